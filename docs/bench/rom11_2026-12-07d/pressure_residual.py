#!/usr/bin/python3
"""Is the FE's state an equilibrium of the reduced model when the pressure field is the best of
span(P)? (rom11) At a held-out FE state u: the reduced residual V^T (f_dev + G(u)^T p + f_fib +
f_chambers) with p = kappa theta_FE (the FE's P0 pressure: the verification, ~0 with the FE's
fibres), and with p = P r, r the least-squares best over span(P) (the mixed model's pressure can
take any such field by a tiny dilatation), for pressure bases of the training's dilatation POD
(rom_basis.py mixed_bases: volume-weighted, every training state and its quarter turns) with K
modes split per segment at the connectors (3 K columns). Relative to |V^T f_chambers|.
Usage: pressure_residual.py SNAP BASIS.h5 LEG.h5 RAY T K1,K2,... [--mf K]"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rom"))
import numpy as np  # noqa: E402
from rom11_energy import Energy  # noqa: E402
from rom11_iso_diag import volume_grads  # noqa: E402
from rom_basis import (dilatations, read_rays, split_pressure_modes,  # noqa: E402
                       turn_maps, turn_snapshots)

snap, basis, leg, ray, t = sys.argv[1:6]
ks = [int(k) for k in sys.argv[6].split(",")]
m = Energy(snap, basis, leg)
rays = read_rays(snap)
r = [r for r in rays if r["name"] == ray][0]
k = int(np.argmin(np.abs(r["t"] - float(t))))
u = r["u"][k].copy()
u[m.fixed] = 0.0
p = r["p"][k].ravel()
V = m.V
fd = m.dev(u)[1]
ff_fe = m.fibres_e(u, mixed=False)[1]
ff_mx = m.fibres_e(u, mixed=True)[1]
vol, Gc = m.chambers(u)
fp = -(p @ Gc)
fp[m.fixed] = 0
v, g = volume_grads(u, m.tet, m.dNdX, m.wq)
th = v / m.Ve - 1
pfe = m.kappa * th
Vp = np.linalg.norm(V.T @ fp)


def GT(pe):
    f = np.zeros((m.nn, 3))
    np.add.at(f, m.tet, pe[:, None, None] * g)
    f = f.ravel()
    f[m.fixed] = 0
    return f


def res(f):
    return np.linalg.norm(V.T @ f) / Vp


print(f"{ray} t {r['t'][k]:.2f}: n = {V.shape[1]}; |V^T f_chambers| {Vp:.4g} N (per unit q)")
print(f"  p = the FE's, FE fibres:    {res(fd + GT(pfe) + ff_fe + fp):.2e}  (the verification)")
print(f"  p = the FE's, mixed fibres: {res(fd + GT(pfe) + ff_mx + fp):.3f}  (mf {m.Qf.shape[1]})")
# the training's dilatation POD (every state and its quarter turns)
train = [q for q in rays if q["kind"] == "train"]
X = np.concatenate([q["u"] for q in train], axis=0).T
X[m.fixed] = 0.0
X = turn_snapshots(X, turn_maps(m.x))
X[m.fixed] = 0.0
Th = dilatations(X, m.tet, m.dNdX, m.wq)
vol_e = m.Ve
lam, Phi = np.linalg.eigh(Th.T @ (vol_e[:, None] * Th))
o = np.argsort(lam)[::-1]
lam, Phi = np.clip(lam[o], 0, None), Phi[:, o]
kmax = int((lam > lam[0] * 1e-24).sum())
Pall = Th @ Phi[:, :kmax] / np.sqrt(lam[:kmax])
# the FE pressure field's force split into the part span(P) reaches, per basis
f0m = fd + ff_mx + fp
f0f = fd + ff_fe + fp
for K in ks:
    P = split_pressure_modes(Pall[:, :min(K, kmax)], m.x, m.tet, vol_e, [54.0, 112.0])
    B = np.column_stack([V.T @ GT(P[:, j]) for j in range(P.shape[1])])  # (n, 3K)
    out = []
    for f0 in (f0f, f0m):
        rr = np.linalg.lstsq(B, -(V.T @ f0), rcond=None)[0]
        out.append(np.linalg.norm(V.T @ f0 + B @ rr) / Vp)
    pe = P @ np.linalg.lstsq(np.sqrt(vol_e)[:, None] * P, np.sqrt(vol_e) * pfe, rcond=None)[0]
    perr = np.sqrt((vol_e * (pfe - pe) ** 2).sum() / (vol_e * pfe ** 2).sum())
    print(f"  {K:3d} modes per segment (m = {P.shape[1]:3d}): best residual, FE fibres "
          f"{out[0]:.3f}, mixed fibres {out[1]:.3f}; FE pressure's projection error {perr:.3f}")
    sys.stdout.flush()

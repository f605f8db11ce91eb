#!/usr/bin/python3
"""The mixed fibre field's consistency at held-out FE states (rom11): for candidate fibre bases
Qf, the held-out fibre strain field's projection error (W-norm, W = EA L0) and the reduced
residual at the FE state with the FE's P0 pressure and the mixed fibres
|V^T (f_dev + G^T p_FE + f_fib,mixed + f_chambers)| / |V^T f_chambers| (0 with the FE's fibres: the
verification, pressure_residual.py). Candidates: the basis' Qf truncated to K (FE states' strains
and stresses, rom_basis.py fibre_basis) and the same POD over every training state and its
quarter turns ("turned": the turned states' strains are those of the same deformation carried
by other fibres, as the helices' start does not turn onto itself).
Usage: fibre_consistency.py SNAP BASIS_F.h5 LEG.h5 RAY:T[,RAY:T...] K1,K2,..."""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rom"))
import numpy as np  # noqa: E402
from rom11_energy import Energy  # noqa: E402
from rom_basis import fibre_law, fibre_strains, read_rays, turn_maps, turn_snapshots  # noqa: E402

snap, basis, leg = sys.argv[1:4]
cases = [(c.split(":")[0], float(c.split(":")[1])) for c in sys.argv[4].split(",")]
ks = [int(k) for k in sys.argv[5].split(",")]
m = Energy(snap, basis, leg)
W = m.W
Qb = m.Qf.copy()
rays = read_rays(snap)
train = [q for q in rays if q["kind"] == "train"]
X = np.concatenate([q["u"] for q in train], axis=0).T
X[m.fixed] = 0.0
nfe = X.shape[1]
X = turn_snapshots(X, turn_maps(m.x))
X[m.fixed] = 0.0
node, coef, L0, EA = m.fib
fib = (node, coef, L0, EA, True)
E = fibre_strains(X, m.x, fib)
del X


def pod(Y):
    lam, Phi = np.linalg.eigh(Y.T @ (W[:, None] * Y))
    o = np.argsort(lam)[::-1]
    lam, Phi = np.clip(lam[o], 0, None), Phi[:, o]
    k = int((lam > lam[0] * 1e-24).sum())
    return Y @ Phi[:, :k] / np.sqrt(lam[:k])


Qt = pod(np.concatenate([E, fibre_law(E, True)], axis=1))
if os.environ.get("QF_OUT"):  # the turned POD for a leg file's /Qf (rom11: swapped into a copy)
    import h5py
    with h5py.File(os.environ["QF_OUT"], "w") as fh:
        fh["Qf"] = Qt
print(f"fibre_consistency: {E.shape[0]} fibres; the basis' Qf {Qb.shape[1]} modes, the turned "
      f"POD {Qt.shape[1]} modes ({E.shape[1]} states, {nfe} FE)")
pre = []
for ray, t in cases:
    r = [q for q in rays if q["name"] == ray][0]
    k = int(np.argmin(np.abs(r["t"] - t)))
    u = r["u"][k].copy()
    u[m.fixed] = 0.0
    p = r["p"][k].ravel()
    Et = fibre_strains(u[:, None], m.x, fib)[:, 0]
    m.Qf = None
    parts, f_fe, fp = m.total(u, p, fe=True)
    ff_fe = m.fibres_e(u, mixed=False)[1]
    pre.append((ray, r["t"][k], u, Et, f_fe - ff_fe, fp))
for lab, Q in (("basis' Qf", Qb), ("turned", Qt)):
    for K in ks:
        if K > Q.shape[1]:
            continue
        m.Qf = Q[:, :K]
        m.Gf = (m.Qf * W[:, None]).T @ m.Qf
        out = []
        for ray, t, u, Et, f_rest, fp in pre:
            R = Et - m.Qf @ np.linalg.solve(m.Gf, m.Qf.T @ (W * Et))
            perr = np.sqrt((W * R * R).sum() / (W * Et * Et).sum())
            ff = m.fibres_e(u, mixed=True)[1]
            ff[m.fixed] = 0.0
            res = np.linalg.norm(m.V.T @ (f_rest + ff)) / np.linalg.norm(m.V.T @ fp)
            out.append(f"{ray} t {t:.2f}: strain error {perr:.3f}, residual {res:.3f}")
        print(f"  {lab:10s} K {K:4d}: " + "; ".join(out))
        sys.stdout.flush()

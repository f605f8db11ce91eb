#!/usr/bin/python3
"""The reduced residual at held-out FE states on a (possibly enriched) span (rom12; rom11's
pressure_residual.py and fibre_consistency.py measures without their POD rebuilds): at the FE
state u of each RAY:T, |V^T (f_dev + G^T p + f_fib + f_chambers)| / |V^T f_chambers| with
  - p the FE's P0 pressure and the FE's fibres (the verification: ~0 on any V),
  - p the best of span(P) (the basis' own P: least squares on V^T G^T P) and the FE's fibres
    (mf = 0: the only inconsistency the pressure basis'),
  - p the FE's and the mixed fibres on the basis' first MF fibre modes,
  - p the best of span(P) and the mixed fibres.
Run through enriched.py for an enriched V (ENRICH=E.h5:K).
Usage: consistency.py SNAP BASIS.h5 LEG.h5 RAY:T[,RAY:T...] [MF]"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rom"))
import numpy as np  # noqa: E402
from rom11_energy import Energy  # noqa: E402
from rom11_iso_diag import states, volume_grads  # noqa: E402

snap, basis, leg = sys.argv[1:4]
cases = [c.split(":") for c in sys.argv[4].split(",")]
mf = int(sys.argv[5]) if len(sys.argv) > 5 else 104
m = Energy(snap, basis, leg)
m.Qf = m.Qf[:, :mf]
m.Gf = (m.Qf * m.W[:, None]).T @ m.Qf
V = m.V
print(f"consistency: n = {V.shape[1]}, m = {m.P.shape[1]}, mf = {mf}")
for ray, t, u, p, _, _ in (s for c in cases for s in states(snap, [c[0]], [float(c[1])], m.fixed)):
    fd = m.dev(u)[1]
    ff_fe = m.fibres_e(u, mixed=False)[1]
    ff_mx = m.fibres_e(u, mixed=True)[1]
    _, Gc = m.chambers(u)
    fp = -(p @ Gc)
    fp[m.fixed] = 0
    v, g = volume_grads(u, m.tet, m.dNdX, m.wq)
    pfe = m.kappa * (v / m.Ve - 1)

    def GT(pe):
        f = np.zeros((m.nn, 3))
        np.add.at(f, m.tet, pe[:, None, None] * g)
        f = f.ravel()
        f[m.fixed] = 0
        return f

    Vp = np.linalg.norm(V.T @ fp)
    Bm = np.column_stack([V.T @ GT(m.P[:, j]) for j in range(m.P.shape[1])])
    out = []
    for ff in (ff_fe, ff_mx):
        ff = ff.copy()
        ff[m.fixed] = 0
        f0 = fd + ff + fp
        rf = np.linalg.norm(V.T @ (f0 + GT(pfe))) / Vp
        rr = np.linalg.lstsq(Bm, -(V.T @ f0), rcond=None)[0]
        rb = np.linalg.norm(V.T @ f0 + Bm @ rr) / Vp
        out.append((rf, rb))
    print(f"  {ray} t {t:.2f}: FE fibres: FE pressure {out[0][0]:.2e}, best of span(P) "
          f"{out[0][1]:.3f}; mixed fibres (mf {mf}): FE pressure {out[1][0]:.3f}, best of span(P) "
          f"{out[1][1]:.3f}")
    sys.stdout.flush()

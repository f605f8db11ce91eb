#!/usr/bin/python3
"""Does span(V) hold a state near the FE's that neither dilates nor stretches the fibres? (rom11)
From the isochoric projection q_I (rom11_iso_diag.py) of a held-out FE state u: Gauss-Newton on
  min_q  s |G^T (q - q_M)|^2 + sum_f W_f (max(E_f(Vq), 0) - max(E_f(u), 0))^2
  s.t.  P^T (v(Vq) - V_e) = P^T (v(u) - V_e)
(G^T G = V^T M V: the M-norm from the M-projection; W = EA L0; the taut fibres' Green strains
against the FE state's; with MATCH=0 in the environment against 0, as first run) for weights s
(1 / t; s |.|^2 in N mm: 1 mm moved over the whole 35 g leg weighs ~3.5e-5 s), and the FE's
(full) fibre energy, tip and volumes of the result: the fibres' price of staying near the FE
state in this span.
Usage: [MATCH=0] fibre_free_projection.py SNAP BASIS.h5 LEG.h5 RAY T S1,S2,..."""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rom"))
import numpy as np  # noqa: E402
from rom11_iso_diag import Model, gV, states  # noqa: E402

snap, basis, leg, ray, t = sys.argv[1:6]
ss = [float(v) for v in sys.argv[6].split(",")]
m = Model(snap, basis, leg)
name, t, u, p, _, _ = next(states(snap, [ray], [float(t)], m.fixed))
qm = m.project_M(u)
qi, _ = m.project_iso(u, qm)
bt, _ = m.bvec(u)
Li = np.linalg.inv(m.G)
sW = np.sqrt(m.W)
Et = np.maximum(m.fibre_strain(u)[0], 0.0)
if os.environ.get("MATCH", "1") == "0":
    Et[:] = 0.0
print("  taut fibres against " + ("0" if not Et.any() else "the FE state's strains"))
print(f"{name} t {t:.2f}: n = {m.V.shape[1]}")
for s in ss:
    q = qi.copy()
    for it in range(8):
        b, g = m.bvec(m.V @ q)
        c = m.Ainv_half @ (b - bt)
        C = (m.Ainv_half @ (m.P.T @ gV(g, m.tet, m.V))) @ Li.T
        E, D = m.fibre_strain(m.V @ q, jac=True)
        taut = E > 0
        rf = sW * (np.maximum(E, 0) - Et)
        Jf = (sW * taut)[:, None] * (D @ Li.T)
        y0 = m.G.T @ (q - qm)
        # min s |y0 + dy|^2 + |rf + Jf dy|^2  s.t. c + C dy = 0  (KKT)
        H = s * np.eye(len(q)) + Jf.T @ Jf
        gr = s * y0 + Jf.T @ rf
        K = np.block([[H, C.T], [C, np.zeros((C.shape[0], C.shape[0]))]])
        sol = np.linalg.solve(K, -np.concatenate([gr, c]))
        q = q + Li.T @ sol[:len(q)]
    o = m.report(u, p, dict(F=q))["F"]
    print(f"  s {s:.0e}: M-norm {100 * o['rel']:.3f} %, tip {o['tip']:.3f} mm, volumes worst "
          f"{100 * o['vol']:+.2f} % (chamber {o['ch'] // 4 + 1}.{o['ch'] % 4 + 1}); bulk in "
          f"span(P) {o['bulk']:.3g}, fibres (FE's, full) {o['fibfull']:.4g}, mixed {o['fib']:.4g}, "
          f"largest strain {o['emax']:.3f}")
    sys.stdout.flush()

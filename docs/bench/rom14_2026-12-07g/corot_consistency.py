#!/usr/bin/python3
"""The corotated model's consistency at held-out FE states (rom14; rom11/rom13's measure).

    corot_consistency.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 RAY:T,... [--r 12 --k 176]
        [--mf 0,104]

At the FE state u the FE's residual vanishes; the reduced model's residual there, its terms
evaluated at u (the mixed bulk in span(P) from u's own dilatation; the fibres the FE's (mf = 0)
or the basis' first MF mixed modes) and projected on the manifold's tangent at u's
representation z_u (J(z_u), corot_newton.py), relative to the chambers' force projected the
same way: |J^T f(u)| / |J^T f_p(u)|. V's own (the linear span, rom11/rom13: T_H4 t = 1 2.9 %
with mf = 104) beside it. Units as rom11_energy.py.
"""
import os
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import numpy as np  # noqa: E402
from corot import rod_strains  # noqa: E402
from corot_newton import load_manifold, manifold_args  # noqa: E402
from rom11_iso_diag import states  # noqa: E402

ap = manifold_args(["cases"])
ap.add_argument("--mf", default="0,104")
a = ap.parse_args()
m, mf = load_manifold(a)
Qf0 = m.Qf
sl, Vs, Vl = mf.sl, mf.Vs, mf.Vl
for case in a.cases.split(","):
    ray, t = case.split(":")
    (name, tt, u, p, _, _), = list(states(a.snap, [ray], [float(t)], m.fixed))
    s = rod_strains(*sl.fit(u), sl.c0).ravel()
    z = np.concatenate([Vs.T @ s, np.zeros(mf.k)])
    ul = sl.local(u, mf.fld(z[:mf.r]))
    z[mf.r:] = np.linalg.lstsq(Vl.T @ (m.M @ Vl), Vl.T @ (m.M @ ul), rcond=None)[0]
    J, _ = mf.jac(z)
    for k in [int(v) for v in a.mf.split(",")]:
        m.Qf = None if k == 0 else Qf0[:, :k]
        if k:
            m.Gf = (m.Qf * m.W[:, None]).T @ m.Qf
        _, f, fp = m.total(u, p)
        print(f"corot_consistency: {name} t {tt:g}, mf = {k}: corotated (n = {mf.n}) "
              f"{np.linalg.norm(J.T @ f) / np.linalg.norm(J.T @ fp):.4f}; V (n = "
              f"{m.V.shape[1]}) {np.linalg.norm(m.V.T @ f) / np.linalg.norm(m.V.T @ fp):.4f}",
              flush=True)

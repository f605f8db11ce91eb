#!/usr/bin/python3
"""The reduced gradient of the condensed FE potential at the septa-relaxed representation (rom16).

    condensed_grad.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 DIR [--cases T_R:1,T_H4:1] [--band 24
        --rmin 3.66 --rmax 7.66]

With the region's interior nodes condensed (solved by the FE's energy given the rest: septa_relax.py's
states in DIR), the reduced potential Pi_c(z) = min over those nodes of the FE's Pi has the gradient
J_w(z)^T f(u_c) (the envelope theorem: f vanishes on the condensed dofs at their minimum; J_w the
manifold's Jacobian with the condensed rows zero). Printed beside the uncondensed J^T f(u(z)) at the
representation, each against the pressure forces' |J^T f_p|, the FE's potential (the FE's P0 bulk,
every fibre): a condensed model whose start is near its equilibrium has a small ratio (this is the
gradient at the representation, not rom14's consistency at the FE state). Units N mm.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from septa_relax import (load_manifold, manifold_args, represent_z, septa_select,  # noqa: E402
                         states)
import numpy as np  # noqa: E402


def main():
    ap = manifold_args(["dir"])
    ap.add_argument("--cases", default="T_R:1,T_H4:1")
    ap.add_argument("--band", type=float, default=24.0)
    ap.add_argument("--rmin", type=float, default=3.66)
    ap.add_argument("--rmax", type=float, default=7.66)
    a = ap.parse_args()
    m, mf = load_manifold(a)
    m.Qf = None
    _, fnode = septa_select(m, a.band, a.rmin, a.rmax)
    cond = np.repeat(fnode, 3)
    for case in a.cases.split(","):
        ray, t = case.split(":")
        (name, tt, u, p, _, _), = list(states(a.snap, [ray], [float(t)], m.fixed))
        fn = os.path.join(a.dir, f"septa_relaxed_{name}_t{tt:g}_b{a.band:g}_r{a.rmin:g}-{a.rmax:g}.npy")
        if not os.path.exists(fn):
            print(f"{name} t {tt:g}: no {fn}")
            continue
        z = represent_z(m, mf, u)
        J, _ = mf.jac(z)
        w0 = mf.u(z)
        wc = np.load(fn)
        _, f0, fp0 = m.total(w0, p, fe=True)
        _, fc, fpc = m.total(wc, p, fe=True)
        Jw = J.copy()
        Jw[cond] = 0.0
        r0 = np.linalg.norm(J.T @ f0) / np.linalg.norm(J.T @ fp0)
        rc = np.linalg.norm(Jw.T @ fc) / np.linalg.norm(Jw.T @ fpc)
        print(f"{name} t {tt:g}: |J^T f| / |J^T f_p| (FE energy) at the representation {100 * r0:.2f} %, "
              f"condensed at the relaxed state {100 * rc:.2f} % (the condensed dofs' |f| "
              f"{np.linalg.norm(fc[cond]):.2e}); the strain / local parts: "
              f"{np.linalg.norm((J.T @ f0)[:mf.r]):.3g} / {np.linalg.norm((J.T @ f0)[mf.r:]):.3g} -> "
              f"{np.linalg.norm((Jw.T @ fc)[:mf.r]):.3g} / {np.linalg.norm((Jw.T @ fc)[mf.r:]):.3g}",
              flush=True)


if __name__ == "__main__":
    main()

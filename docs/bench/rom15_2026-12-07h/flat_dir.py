#!/usr/bin/python3
"""The flat direction of rom14's T_H4 settle: soft in the FE too, or only in the reduced model?

    flat_dir.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 NPY --ray T_H4 --t 1 --near 6
        [--r 12 --k 176] [--penrich E.h5 --pk K]

NPY: corot_newton.py's saved iterates. d = u(z_last) - u(z_near): the step from the iterate
NEAR the FE state (rom14: iterate 6, tip 0.14 mm) to where the Newton settled (tip 2.47 mm).
Along d, from the FE state u: the FE's own potential (P0 bulk element by element, every fibre)
and the reduced model's (the mixed bulk in span(P), the FE's fibres: mf = 0), at s = -1 .. 1; each's
slope at u, f(u) . d (the FE's vanishes to its Newton tolerance; the reduced model's is its
inconsistency along d) and curvature d^T K d (central differences of the slope, s = +-0.05);
the predicted shift of the minimum along d, -slope / curvature (in units of d: 1 = the 2.3 mm
settle), and where d acts: the per-slab rotation change along z (degrees) and the tip's motion.
With --penrich the reduced model's pressure space is [P, the first K modes of E.h5 /D].
Units mm, N mm.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "rom14_2026-12-07g"))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from corot_newton import load_manifold, manifold_args  # noqa: E402
from rom11_iso_diag import states  # noqa: E402
from scipy.spatial.transform import Rotation  # noqa: E402


def main():
    ap = manifold_args(["npy"])
    ap.add_argument("--ray", default="T_H4")
    ap.add_argument("--t", type=float, default=1.0)
    ap.add_argument("--near", type=int, default=6)
    ap.add_argument("--penrich", default=None)
    ap.add_argument("--pk", type=int, default=0)
    a = ap.parse_args()
    m, mf = load_manifold(a)
    m.Qf = None  # the FE's fibres, fibre by fibre (corot_newton.py --mf 0, rom14's screens)
    if a.penrich and a.pk:
        with h5py.File(a.penrich, "r") as f:
            m.P = np.concatenate([m.P, f["D"][:, :a.pk]], axis=1)
        A = (m.P * (m.Ve / m.kappa)[:, None]).T @ m.P
        m.Ainv_half = np.linalg.inv(np.linalg.cholesky(A))
    (name, t, u, p, _, _), = list(states(a.snap, [a.ray], [a.t], m.fixed))
    Z = np.load(a.npy)
    w0, w1 = mf.u(Z[a.near]), mf.u(Z[-1])
    d = w1 - w0
    tipd = d.reshape(-1, 3)[m.tip].mean(axis=0)
    print(f"{name} t {t:g}: d = iterate {len(Z) - 1} - iterate {a.near}: tip moves "
          f"{np.linalg.norm(tipd):.3f} mm ({tipd[0]:+.3f}, {tipd[1]:+.3f}, {tipd[2]:+.3f}); "
          f"M-norm of d {100 * np.sqrt(d @ (m.M @ d) / (u @ (m.M @ u))):.3f} % of u")
    R0, _ = mf.sl.fit(w0)
    R1, _ = mf.sl.fit(w1)
    ang = np.degrees(Rotation.from_matrix(np.einsum("sji,sjk->sik", R0, R1)).as_rotvec())
    for lo in range(0, mf.sl.nsl, 10):
        print(f"    slabs {lo:2d}-{min(lo + 9, mf.sl.nsl - 1):2d} (z {mf.sl.zc[lo]:5.1f} mm): "
              "rotation change " + " ".join(f"({v[0]:+.2f},{v[1]:+.2f},{v[2]:+.2f})"
                                             for v in ang[lo:lo + 10:3]) + " deg")
    for fe, lab in ((True, "FE potential"), (False, "reduced model's")):
        def pi(s):
            return sum(m.total(u + s * d, p, fe=fe)[0])
        f = m.total(u, p, fe=fe)[1]
        h = 0.05
        slope = float(f @ d)
        curv = float((m.total(u + h * d, p, fe=fe)[1] - m.total(u - h * d, p, fe=fe)[1]) @ d
                     / (2 * h))
        vals = " ".join(f"{s:+.2f}: {pi(s) - pi(0.0):+9.3f}" for s in (-1, -0.5, -0.25, 0.25, 0.5, 1))
        dp = [x1 - x0 for x1, x0 in zip(m.total(u + d, p, fe=fe)[0], m.total(u, p, fe=fe)[0])]
        print(f"  {lab:16s} along d from u: Pi(u + s d) - Pi(u) {vals} N mm; slope "
              f"{slope:+.4f} N mm, curvature {curv:.4f} N mm, minimum at s = "
              f"{-slope / curv:+.3f}; at s = 1 by part: dev {dp[0]:+.3f}, bulk {dp[1]:+.3f}, "
              f"fibres {dp[2]:+.3f}, -work {dp[3]:+.3f}")
        sys.stdout.flush()


if __name__ == "__main__":
    main()

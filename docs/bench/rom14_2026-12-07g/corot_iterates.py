#!/usr/bin/python3
"""The FE's own measures of corot_newton.py's iterates (rom14): per saved iterate z (its --save
file) corot.show's line (M-norm, tip, worst chamber, the FE's P0 bulk beside the mixed bulk in
span(P), every fibre, the pressure work) and the slab chain's strain coordinates a.
    corot_iterates.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 NPY --ray RAY --t T [--r 12 --k 176]"""
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import numpy as np  # noqa: E402
from corot import show  # noqa: E402
from corot_newton import load_manifold, manifold_args  # noqa: E402
from rom11_iso_diag import states  # noqa: E402

ap = manifold_args(["npy"])
ap.add_argument("--ray", default="T_R")
ap.add_argument("--t", type=float, default=1.0)
ap.add_argument("--last", type=int, default=0, help="only the last LAST iterates")
a = ap.parse_args()
m, mf = load_manifold(a)
(name, t, u, p, _, _), = list(states(a.snap, [a.ray], [a.t], m.fixed))
Z = np.load(a.npy)
for i, z in list(enumerate(Z))[-a.last if a.last else 0:]:
    show(m, f"{name} t {t:g} iterate {i}", u, mf.u(z), p)
    print("        strain coordinates a: " + " ".join(f"{v:+.3f}" for v in z[:mf.r]))

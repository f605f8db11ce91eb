#!/usr/bin/python3
"""The FE's own measures of corot_newton.py's iterates (rom14): per saved iterate z (its --save
file) corot.show's line (M-norm, tip, worst chamber, the FE's P0 bulk beside the mixed bulk in
span(P), every fibre, the pressure work) and the slab chain's strain coordinates a.
    corot_iterates.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 NPY --ray RAY --t T [--r 12 --k 176]"""
import argparse
import os
import sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from corot import Slabs, show  # noqa: E402
from corot_newton import Manifold  # noqa: E402
from rom11_energy import Energy  # noqa: E402
from rom11_iso_diag import states  # noqa: E402

ap = argparse.ArgumentParser()
for n in ("snap", "basis", "leg", "rod", "local", "npy"):
    ap.add_argument(n)
ap.add_argument("--r", type=int, default=12)
ap.add_argument("--k", type=int, default=176)
ap.add_argument("--ray", default="T_R")
ap.add_argument("--t", type=float, default=1.0)
ap.add_argument("--last", type=int, default=0, help="only the last LAST iterates")
a = ap.parse_args()
m = Energy(a.snap, a.basis, a.leg)
with h5py.File(a.rod, "r") as f:
    Vs = f["Vs"][:, :a.r]
with h5py.File(a.local, "r") as f:
    Vl = f["Vl"][:, :a.k]
mf = Manifold(m, Slabs(m.x, 2.0), Vs, Vl)
(name, t, u, p, _, _), = list(states(a.snap, [a.ray], [a.t], m.fixed))
Z = np.load(a.npy)
for i, z in list(enumerate(Z))[-a.last if a.last else 0:]:
    show(m, f"{name} t {t:g} iterate {i}", u, mf.u(z), p)
    print("        strain coordinates a: " + " ".join(f"{v:+.3f}" for v in z[:mf.r]))

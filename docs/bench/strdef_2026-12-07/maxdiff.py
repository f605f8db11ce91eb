#!/usr/bin/python3
"""maxdiff.py A.h5 B.h5...: the largest |(dx, dz)| of the support between A and each B at A's
whole seconds (mm, 6 digits: the noise floor's runs differ by less than cmp.py's 0.01)."""
import math, sys
import h5py, numpy as np

def rd(p):
    with h5py.File(p, "r") as f:
        return f["/time"][:], f["/support/position"][:]

ta, pa = rd(sys.argv[1])
for p in sys.argv[2:]:
    t, q = rd(p)
    worst = 0.0
    for s in range(1, int(math.floor(min(t[-1], ta[-1]) + 5e-3)) + 1):
        i, j = int(np.argmin(abs(ta - s))), int(np.argmin(abs(t - s)))
        worst = max(worst, math.hypot(q[j, 0] - pa[i, 0], q[j, 2] - pa[i, 2]))
    print(f"{worst:.6f} mm  {p.split('/')[-1]} against {sys.argv[1].split('/')[-1]}")

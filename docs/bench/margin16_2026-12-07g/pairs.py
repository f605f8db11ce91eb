#!/usr/bin/python3
"""pairs.py A.h5 B.h5 [...]: the support's |(dx, dz)| between run A and each B at every whole
second both reach (mm): the max over 1-5 s and over the whole run, and where."""
import sys

import h5py
import numpy as np


RUNS = {}
for p in sys.argv[1:]:
    with h5py.File(p, "r") as f:
        RUNS[p] = (f["time"][:], f["support/position"][:])
ta, pa = RUNS[sys.argv[1]]
for q in sys.argv[2:]:
    tb, pb = RUNS[q]
    d = []
    for s in range(1, int(min(ta[-1], tb[-1])) + 1):
        dx = np.interp(s, ta, pa[:, 0]) - np.interp(s, tb, pb[:, 0])
        dz = np.interp(s, ta, pa[:, 2]) - np.interp(s, tb, pb[:, 2])
        d.append((float(np.hypot(dx, dz)), s))
    print("%s vs %s: 1-5 s max %.2f mm; whole max %.2f mm at %d s; to 30 s max %.2f mm at %d s" % (
        sys.argv[1], q, max(v for v, s in d if s <= 5), *max(d),
        *max((v, s) for v, s in d if s <= 30)))

#!/usr/bin/python3
"""Chosen feet over a window of several obstacle runs side by side: per run the support's x and
height, then per leg its foot (last centreline point) x, height (mm) and normal force (N; '-'
unloaded). usage: feet2.py LEGS T0 T1 DT RUN.h5...  (LEGS e.g. ACG)"""
import sys

import h5py
import numpy as np

legs, t0, t1, dt = sys.argv[1], float(sys.argv[2]), float(sys.argv[3]), float(sys.argv[4])
fs = [h5py.File(p, "r") for p in sys.argv[5:]]
for k, p in enumerate(sys.argv[5:]):
    print("run %d: %s" % (k, p))
print("   t  " + "".join(" || r  sup x     h | " + " | ".join("%s  x     h    N" % l for l in legs)
                         for _ in fs))
for tt in np.arange(t0, t1 + 1e-9, dt):
    out = "%6.2f" % tt
    for k, f in enumerate(fs):
        t = f["time"][:]
        if tt > t[-1]:
            out += " || %d  (over)" % k
            continue
        i = int(np.searchsorted(t, tt - 1e-9))
        s = f["support/position"][i]
        row = []
        for l in legs:
            j = "ABCDEFGH".index(l)
            b = f["legs/%s/centerline" % l][i, -1]
            n = f["contact/foot_force"][i, j, 1]
            row.append("%5.1f %4.1f %4s" % (b[0], b[1], "%.2f" % n if n > 0.005 else "-"))
        out += " || %d %5.1f %5.1f | %s" % (k, s[0], s[1], " | ".join(row))
    print(out)

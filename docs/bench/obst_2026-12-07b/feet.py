#!/usr/bin/python3
"""Every foot over a time window of an obstacle run: the support's x, height and tilt, then per
leg its foot (last centreline point) x and height (mm) and normal force (N; '-' unloaded).
usage: /usr/bin/python3 feet.py RUN.h5 T0 T1 [DT]  (s; DT default 0.1)"""
import sys

import h5py
import numpy as np

p, t0, t1 = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
dt = float(sys.argv[4]) if len(sys.argv) > 4 else 0.1
with h5py.File(p, "r") as f:
    t = f["time"][:]
    print("   t  | sup x     h  tilt | " + " | ".join("%s  x     h    N" % l for l in "ABCDEFGH"))
    for tt in np.arange(t0, t1 + 1e-9, dt):
        if tt > t[-1]:
            break
        i = int(np.searchsorted(t, tt - 1e-9))
        q = f["support/orientation"][i]
        tilt = np.degrees(np.arccos(np.clip(1 - 2 * (q[1] ** 2 + q[3] ** 2), -1, 1)))
        s = f["support/position"][i]
        row = []
        for k, l in enumerate("ABCDEFGH"):
            b = f["legs/%s/centerline" % l][i, -1]
            n = f["contact/foot_force"][i, k, 1]
            row.append("%5.0f %4.0f %4s" % (b[0], b[1], "%.2f" % n if n > 0.005 else "-"))
        print("%6.2f | %5.1f %5.1f %4.1f | %s" % (t[i], s[0], s[1], tilt, " | ".join(row)))

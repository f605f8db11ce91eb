#!/usr/bin/python3
"""The support's yaw (about y, up; deg) and x, z at run times T for each run file: the lateral
crawl's x drift against its heading. usage: /usr/bin/python3 yaw.py T0 T1 DT RUN.h5..."""
import sys

import h5py
import numpy as np

t0, t1, dt = (float(v) for v in sys.argv[1:4])
for fn in sys.argv[4:]:
    with h5py.File(fn, "r") as f:
        t = f["time"][:]
        q = f["support/orientation"][:]
        p = f["support/position"][:]
    R = np.array([[1 - 2 * (q[:, 2]**2 + q[:, 3]**2)], [2 * (q[:, 1] * q[:, 3] - q[:, 0] * q[:, 2])]])[:, 0]
    # the body's x axis in the world: (R00, R20); yaw of it about y
    yaw = np.degrees(np.arctan2(-R[1], R[0]))
    print(fn.split("/")[-1])
    for tt in np.arange(t0, t1 + 1e-9, dt):
        i = min(np.searchsorted(t, tt), len(t) - 1)
        print("  t %6.2f  x %6.1f  z %6.1f  yaw %6.2f" % (t[i], p[i, 0], p[i, 2], yaw[i]))

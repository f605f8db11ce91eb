#!/usr/bin/python3
"""The second pair's (B, F) landing at the obstacle's step (x = 240 mm, 40 mm up): per run the
support's x and tilt and B's foot (last centreline point: x, height; its normal force, N) at
5.2-5.6 s. usage: /usr/bin/python3 landing.py RUN.h5 ..."""
import sys

import h5py
import numpy as np

for p in sys.argv[1:]:
    with h5py.File(p, "r") as f:
        t = f["time"][:]
        print(p.split("/")[-1])
        for tt in (5.2, 5.3, 5.35, 5.4, 5.45, 5.5, 5.6, 5.8, 6.0):
            if tt > t[-1]:
                break
            i = int(np.searchsorted(t, tt - 1e-9))
            q = f["support/orientation"][i]
            tilt = np.degrees(np.arccos(np.clip(1 - 2 * (q[1] ** 2 + q[3] ** 2), -1, 1)))
            b = f["legs/B/centerline"][i, -1]
            fb = f["contact/foot_force"][i, 1, 1]
            x = f["support/position"][i, 0]
            print(f"  {t[i]:.2f} s: support x {x:6.2f} tilt {tilt:4.1f} | B foot x {b[0]:6.1f}"
                  f" h {b[1]:5.1f} N {fb:4.2f}")

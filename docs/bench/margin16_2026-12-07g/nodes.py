#!/usr/bin/python3
"""nodes.py RUN.h5...: per run, the error of every Table 3 node from 4 s (x, height, z: mm; the
table as docs/bench/gate_2026-12-06f/score.py), the worst, the end point's distance, the run's
end time, penetration (legs) and tilt."""
import sys

import h5py
import numpy as np

T = [4, 5, 7, 11, 12, 14, 24, 29, 32]
X = [26, 26, 52, 130, 170, 230, 492, 646, 646]
H = [22, 48, 20, 50, 40, 40, 13, 0, 0]
Z = [0, 0, 0, 0, 0, 0, 0, 90, 270]
for p in sys.argv[1:]:
    with h5py.File(p, "r") as f:
        t = f["time"][:]
        pos = f["support/position"][:]
        q = f["support/orientation"][:]
        ld = f["contact/leg_max_depth"][:]
    tilt = np.degrees(np.arccos(np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2), -1, 1)))
    out, worst = [], (0, None)
    for k, s in enumerate(T):
        if t[-1] < s - 1e-9:
            out.append("%g:-" % s)
            continue
        x, y, z = (np.interp(s, t, pos[:, j]) for j in range(3))
        e = (abs(x - X[k]), abs(y - H[k]), abs(z - Z[k]))
        out.append("%g:%.1f/%.1f/%.1f" % (s, e[0], e[1], e[2]))
        if max(e) > worst[0]:
            worst = (max(e), s)
    end = pos[-1]
    off = np.hypot(end[0] - 646, end[2] - 270)
    print("%s: end %.2f s (%.1f, %.1f, %.1f) %.1f mm off; depth %.3f mm; tilt %.1f deg; worst node %.1f (%s s)"
          % (p, t[-1], end[0], end[1], end[2], off, ld.max(), tilt.max(), worst[0], worst[1]))
    print("   errors x/h/z: " + " ".join(out))

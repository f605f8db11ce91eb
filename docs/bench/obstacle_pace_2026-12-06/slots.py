#!/usr/bin/python3
"""Support advance per slot of a restart track: usage slots.py RUN.npz T0 TSLOT [N]
(x, z at each slot boundary from T0 and the change over each slot, mm; yaw in deg)."""
import sys
import numpy as np
d = np.load(sys.argv[1])
t, pos, q = d['t'], d['pos'], d['quat']
t0, ts = float(sys.argv[2]), float(sys.argv[3])
n = int(sys.argv[4]) if len(sys.argv) > 4 else int((t[-1] - t0) / ts)
prev = None
for k in range(n + 1):
    i = int(np.argmin(abs(t - (t0 + k * ts))))
    w, x, y, z = q[i]
    yaw = np.degrees(np.arctan2(2 * (w * y + x * z), 1 - 2 * (y * y + z * z)))
    p = pos[i]
    dd = '' if prev is None else ' d %+6.1f %+6.1f' % (p[0] - prev[0], p[2] - prev[2])
    print('%6.2f s: x %6.1f h %5.1f z %6.1f yaw %+5.1f%s' % (t[i], p[0], p[1], p[2], yaw, dd))
    prev = p

#!/usr/bin/python3
"""Score obstacle runs against the paper's Table 3 and print the landing gate's record
(reporting data, not used by any code; docs/bench/obstacle_pace_2026-12-05/table3.py's scoring
with gate2.py's line format, plus the gate's HDF5 attributes, core/sim_run.c).

usage: /usr/bin/python3 score.py RUN.h5 [...]"""
import sys

import h5py
import numpy as np

T = [0, 1, 2, 3, 4, 5, 7, 11, 12, 14, 24, 29, 32]
X = [0, 0, 0, 0, 26, 26, 52, 130, 170, 230, 492, 646, 646]
H = [0, 50, 50, 13, 22, 48, 20, 50, 40, 40, 13, 0, 0]  # = -y of Table 3
Z = [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 90, 270]


def tilt_deg(q):
    x, z = q[:, 1], q[:, 3]
    return np.degrees(np.arccos(np.clip(1 - 2 * (x * x + z * z), -1, 1)))


for p in sys.argv[1:]:
    with h5py.File(p, 'r') as f:
        t = f['time'][:]
        pos = f['support/position'][:]
        tl = tilt_deg(f['support/orientation'][:])
        ld = f['contact/leg_max_depth'][:] if 'contact/leg_max_depth' in f else np.zeros(len(t))
        at = {k: f.attrs[k] for k in f.attrs}
    s = lambda v: v.decode() if isinstance(v, bytes) else v  # noqa: E731
    print('%s: run to %.2f s, status %s; %s' % (p, t[-1], s(at.get('status', '')),
                                                 s(at.get('control', ''))))
    if 'gate_file' in at:
        w = s(at['gate_waits'])
        print('  gate %s: held %.3f s, %d of %d released gates waited; waits (T LEGS s): %s'
              % (s(at['gate_file']), at['gate_held_s'], at['gate_waited'], at['gate_released'],
                 w or '-'))
    worst, where, row = 0.0, '', []
    for k, tn in enumerate(T):
        if tn > t[-1] + 1e-9:
            row.append('%d:-' % tn)
            continue
        i = int(np.argmin(abs(t - tn)))
        x, h, z = pos[i, 0], pos[i, 1], pos[i, 2]
        row.append('%d:%.0f/%.0f/%.0f' % (tn, x, h, z))
        if tn >= 4:
            e = max(abs(x - X[k]), abs(h - H[k]), abs(z - Z[k]))
            if e > worst:
                worst, where = e, '%d s' % tn
    print('  ' + ' '.join(row))
    end = pos[-1]
    d = np.hypot(end[0] - 646, end[2] - 270)
    print('  worst node from 4 s %.1f mm (%s); end (%.1f, %.1f, %.1f) %.1f mm off; tilt max %.1f deg'
          ' (last 1 s %.1f); leg depth max %.3f mm'
          % (worst, where, end[0], end[1], end[2], d, tl.max(), tl[t > t[-1] - 1].max(), ld.max()))

#!/usr/bin/python3
"""Where an obstacle run under a gate tips: the first time the support's tilt passes 10 deg, the
table's clock then (lag.py's table_time), the support's x then and its largest x before, and the
gate's total hold. usage: /usr/bin/python3 tips.py RUN.h5..."""
import os
import sys

import h5py
import numpy as np

sys.argv, files = sys.argv[:1], sys.argv[1:]
exec(open(os.path.join(os.path.dirname(os.path.abspath(__file__)), "lag.py")).read().split("run, ref")[0])
for p in files:
    with h5py.File(p, "r") as f:
        t, tau = table_time(f)
        x = f["support/position"][:, 0]
        th = tilt(f["support/orientation"][:])
        i = np.nonzero(th > 10)[0]
        held = f.attrs.get("gate_held_s", 0.0)
        if len(i):
            k = i[0]
            print("%s: tilt > 10 deg at %.2f s (table %.2f s), x %.1f mm (largest before %.1f); "
                  "held %.2f s" % (os.path.basename(p), t[k], tau[k], x[k], x[:k + 1].max(), held))
        else:
            print("%s: never tilts past 10 deg (to %.2f s, table %.2f s), end x %.1f mm; held %.2f s"
                  % (os.path.basename(p), t[-1], tau[-1], x[-1], held))

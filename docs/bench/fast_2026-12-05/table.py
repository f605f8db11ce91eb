#!/usr/bin/python3
"""table.py [DIR]: support x (mm) at whole seconds of the crawlsim runs DIR/{flat,ob}_TAG_H.h5
(run_driver.sh; default DIR build/fast), each run against its half-step run of the same tag
(max over the whole seconds of |(dx, dz)|) and |dx| against the nodal rod (flat road: 16
elements at 0.25 ms; obstacle: 6 elements at 0.25 ms; their x as printed in
docs/notes/strain_leg.md, "Why the flat road differs" and "Through the driver")."""
import glob
import re
import sys

import h5py
import numpy as np

ROD16 = [-0.19, 34.67, 68.77, 106.95, 144.37, 182.01, 219.58, 257.19, 294.81]
ROD6_OBST = [0.00, 0.99, -1.34, 2.04]


def track(p):
    with h5py.File(p, "r") as f:
        n = int(f.attrs.get("samples", len(f["time"])))
        t, x = f["time"][:n], f["support/position"][:n]
    out = {}
    for s in range(1, 10):
        i = np.where(np.abs(t - s) < 1e-6)[0]
        if len(i):
            out[s] = x[i[0]]
    return out


d = sys.argv[1] if len(sys.argv) > 1 else "build/fast"
for scene, ref in (("flat", ROD16), ("ob", ROD6_OBST)):
    runs = {}
    for p in glob.glob("%s/%s_*_*.h5" % (d, scene)):
        m = re.match(r".*/%s_([A-Za-z0-9]+)_([0-9.e-]+)\.h5" % scene, p)
        if not m:
            continue
        try:
            runs[(m.group(1), float(m.group(2)))] = track(p)
        except (KeyError, OSError):
            continue  # a run that has written nothing yet
    for tag in sorted({k[0] for k in runs}):
        hs = sorted((k[1] for k in runs if k[0] == tag), reverse=True)
        print("%s, %s" % (scene, tag))
        for h in hs:
            tr = runs[(tag, h)]
            secs = sorted(tr)
            dref = max((abs(tr[s][0] - ref[s - 1]) for s in secs if s <= len(ref)), default=np.nan)
            print("  %6.3f ms " % (1e3 * h) + " ".join("%8.2f" % tr[s][0] for s in secs) +
                  "   |dx| vs rod %.2f" % dref)
        for a, b in zip(hs, hs[1:]):
            if b != a / 2:
                continue
            ra, rb = runs[(tag, a)], runs[(tag, b)]
            secs = sorted(set(ra) & set(rb))
            dd = [np.hypot(ra[s][0] - rb[s][0], ra[s][2] - rb[s][2]) for s in secs]
            if not dd:
                continue  # a run that stopped before 1 s
            print("  %g vs %g ms: max |(dx, dz)| %.2f mm (at %s s)" %
                  (1e3 * a, 1e3 * b, max(dd), secs[int(np.argmax(dd))]))

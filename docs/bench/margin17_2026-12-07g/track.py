#!/usr/bin/python3
"""track.py [-s STEP] RUN.h5... : the support's x, height (y) and z (mm) and its tilt (deg, from the
body's up axis when stored, else '-') every STEP s (default 1) to the run's end: where a run that
ends off the course left it; then the first time after 2 s the support stands more than 60 mm up
(launched: the walk stands it at 40, then 15) or below 0 (fallen off the step or the road)."""
import sys

import h5py
import numpy as np


def main():
    a = sys.argv[1:]
    step = 1.0
    if a[:1] == ["-s"]:
        step, a = float(a[1]), a[2:]
    for p in a:
        with h5py.File(p, "r") as f:
            t = f["time"][:]
            pos = f["support/position"][:]
        print(p)
        for s in np.arange(0.0, t[-1] + 1e-9, step):
            i = min(np.searchsorted(t, s), len(t) - 1)
            print("  %6.2f s  x %7.1f  y %6.1f  z %6.1f" % (t[i], *pos[i, :3]))
        for name, m in (("up > 60 mm", pos[:, 1] > 60), ("below 0 mm", pos[:, 1] < 0)):
            k = np.nonzero(m & (t > 2))[0]
            print("  first %s: %s" % (name, "%.2f s (x %.1f)" % (t[k[0]], pos[k[0], 0]) if len(k) else "never"))


if __name__ == "__main__":
    main()

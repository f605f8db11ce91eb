#!/usr/bin/python3
"""compare_interp.py REF.h5 RUN.h5 [RUN2.h5 ...]: as ../strain_driver_2026-12-05/compare.py
(support x at whole seconds, max over t = 1.. s of |(dx, dz)| against REF), the tracks
interpolated linearly to the whole seconds, so runs whose samples miss them (a step of 0.9 or
1.1 ms against the 10 ms output) compare too."""
import sys

import h5py
import numpy as np


def track(p):
    with h5py.File(p, "r") as f:
        n = int(f.attrs.get("samples", len(f["time"])))
        return f["time"][:n], f["support/position"][:n]


def at(t, x, s):
    if s > t[-1] + 1e-9:
        return None
    return np.array([np.interp(s, t, x[:, k]) for k in range(3)])


def main(paths):
    tr, xr = track(paths[0])
    secs = [s for s in range(1, 10) if at(tr, xr, s) is not None]
    print("%-34s" % "t (s)" + "".join("%8d" % s for s in secs) + "   max|d(x,z)|")
    for p in paths:
        t, x = track(p)
        row, d, dx = "", [], ""
        for s in secs:
            a, r = at(t, x, s), at(tr, xr, s)
            if a is None:
                row += "%8s" % "-"
                dx += "%8s" % "-"
                continue
            row += "%8.2f" % a[0]
            dx += "%8.2f" % (a[0] - r[0])
            d.append(np.hypot(a[0] - r[0], a[2] - r[2]))
        print("%-34s" % p.split("/")[-2][:8] + "/" + p.split("/")[-1][10:34] + row +
              "   %8.2f" % (max(d) if d else float("nan")))
        if p != paths[0]:
            print("%-34s" % "  difference" + dx)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

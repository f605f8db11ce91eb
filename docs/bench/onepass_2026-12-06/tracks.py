#!/usr/bin/python3
"""tracks.py [--norod] REF.h5 RUN.h5 [RUN2.h5 ...]: the support's x at whole seconds (mm, the tracks
interpolated linearly to them), each run's max over t = 1..9 s of |(dx, dz)| against REF, and its
max |dx| against the nodal rod at 16 elements and 0.25 ms (x only: its x at 1..9 s from
docs/bench/ghost_2026-12-06/tracks_steps.txt; its file was not kept). Needs h5py and numpy
(/usr/bin/python3 here)."""
import os
import sys

import h5py
import numpy as np

ROD16 = [0.30, 41.47, 79.05, 118.56, 159.23, 199.61, 239.98, 280.34, 320.72]


def track(p):
    with h5py.File(p, "r") as f:
        n = int(f.attrs.get("samples", len(f["time"])))
        return f["time"][:n], f["support/position"][:n]


def at(t, x, s):
    if s > t[-1] + 1e-9:
        return None
    return np.array([np.interp(s, t, x[:, k]) for k in range(3)])


def main(paths):
    rod = True
    if paths and paths[0] == "--norod":
        rod, paths = False, paths[1:]
    tr, xr = track(paths[0])
    secs = [s for s in range(1, 10) if s <= tr[-1] + 1e-9]
    print("%-44s" % "t (s)" + "".join("%8d" % s for s in secs) +
          "  max|d(x,z)| vs first  max|dx| vs rod16")
    for p in paths:
        t, x = track(p)
        row, d, dr = "", [], []
        for s in secs:
            a, r = at(t, x, s), at(tr, xr, s)
            if a is None:
                row += "%8s" % "-"
                continue
            row += "%8.2f" % a[0]
            if r is not None:
                d.append(np.hypot(a[0] - r[0], a[2] - r[2]))
            if rod:
                dr.append(abs(a[0] - ROD16[s - 1]))
        print("%-44s" % os.path.basename(p)[:44] + row + "%12.2f%20.2f   (to %.3f s)" %
              (max(d) if d else float("nan"), max(dr) if dr else float("nan"), t[-1]))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

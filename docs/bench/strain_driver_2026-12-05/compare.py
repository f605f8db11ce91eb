#!/usr/bin/python3
"""compare.py REF.h5 RUN.h5 [RUN2.h5 ...]: support x (mm) at whole seconds of each run and the
distance max over t = 1.. s of |(dx, dz)| against REF (the runs' own times; a run that stopped
is compared up to where it reaches). Reads a file being written up to its last flush."""
import sys

import h5py
import numpy as np


def track(p):
    with h5py.File(p, "r") as f:
        n = int(f.attrs.get("samples", len(f["time"])))
        t = f["time"][:n]
        x = f["support/position"][:n]
        status = f.attrs.get("status", b"")
        status = status.decode() if isinstance(status, bytes) else str(status)
    return t, x, status


def at(t, x, s):
    i = np.where(np.abs(t - s) < 1e-6)[0]
    return x[i[0]] if len(i) else None


def main(paths):
    tr, xr, _ = track(paths[0])
    secs = [s for s in range(1, 10) if at(tr, xr, s) is not None]
    print("%-24s" % "t (s)" + "".join("%8d" % s for s in secs) + "   max|d(x,z)|  status")
    for p in paths:
        t, x, st = track(p)
        row, d = "", []
        for s in secs:
            a, r = at(t, x, s), at(tr, xr, s)
            if a is None:
                row += "%8s" % "-"
                continue
            row += "%8.2f" % a[0]
            d.append(np.hypot(a[0] - r[0], a[2] - r[2]))
        print("%-24s" % p.split("/")[-1][:24] + row + "   %8.2f     %s" %
              (max(d) if d else float("nan"), st[:40]))
        if p != paths[0] and d:
            print("%-24s" % "  difference" + "".join(
                "%8.2f" % (at(t, x, s)[0] - at(tr, xr, s)[0]) if at(t, x, s) is not None else "%8s" % "-"
                for s in secs))


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

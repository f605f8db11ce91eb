#!/usr/bin/python3
"""Print a run's support displacement at whole seconds next to the paper's Table 2.

usage: /usr/bin/python3 tools/track_table.py RUN.h5 [RUN2.h5 ...]
One row per file: x (mm) at t = 0, 1, ..., 9 s (blank after the run stopped), then the
relative error against Table 2 at t >= 2 s. The Table 2 values are plotting/reporting data.
"""
import sys

import h5py
import numpy as np

TABLE2 = [0, 0, 39, 78, 117, 156, 195, 234, 273, 312]  # paper Table 2, x (mm) at t = 0..9 s


def main(paths):
    if not paths:
        print(__doc__.strip(), file=sys.stderr)
        return 2
    print("%-28s" % "t (s)" + "".join("%7d" % t for t in range(10)) + "   max|err| t>=2")
    print("%-28s" % "Table 2 x (mm)" + "".join("%7d" % v for v in TABLE2))
    for p in paths:
        try:
            with h5py.File(p, "r") as f:
                t = f["time"][:]
                x = f["support/position"][:, 0]
        except (OSError, KeyError) as e:
            print("track_table: %s: %s" % (p, e), file=sys.stderr)
            return 1
        row, errs = [], []
        for s in range(10):
            i = np.where(np.abs(t - s) < 1e-6)[0]
            if len(i):
                row.append("%7.1f" % x[i[0]])
                if s >= 2:
                    errs.append(abs(x[i[0]] - TABLE2[s]) / TABLE2[s])
            else:
                row.append("%7s" % "-")
        e = ("%6.0f %%" % (100 * max(errs))) if errs else "     -"
        print("%-28s" % p.split("/")[-1][:28] + "".join(row) + "   " + e)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

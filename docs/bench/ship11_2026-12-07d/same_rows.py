"""same_rows.py A.h5 B.h5: compare two run files row for row over their common rows (every
dataset with a time axis): prints the common rows, the last common time, and the largest
difference of /support/position there (0: bit for bit), and each file's last row."""
import sys

import h5py
import numpy as np

a, b = (h5py.File(p, "r") for p in sys.argv[1:3])
n = min(a["/time"].shape[0], b["/time"].shape[0])
worst = 0.0
same = True
for name in ("/time", "/support/position", "/support/orientation", "/pressure",
             "/contact/foot_force"):
    da, db = a[name][:n], b[name][:n]
    same &= bool(np.array_equal(da, db))
    worst = max(worst, float(np.max(np.abs(da - db))))
pa, pb = a["/support/position"], b["/support/position"]
print("%d common rows to t = %.4f s: %s (max |diff| %.3g); ends: %.4f s (%.1f, %.1f) / %.4f s "
      "(%.1f, %.1f)" % (n, a["/time"][n - 1], "bit for bit" if same else "DIFFER", worst,
                         a["/time"][-1], pa[-1, 0], pa[-1, 2], b["/time"][-1], pb[-1, 0], pb[-1, 2]))

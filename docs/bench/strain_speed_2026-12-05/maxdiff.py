#!/usr/bin/python3
"""maxdiff.py REF.h5 RUN.h5: the largest |Δ support position| (mm, x y z) over every output
sample the two runs share (same times), and where."""
import sys

import h5py
import numpy as np


def track(p):
    with h5py.File(p, "r") as f:
        n = int(f.attrs.get("samples", len(f["time"])))
        return f["time"][:n], f["support/position"][:n]


tr, xr = track(sys.argv[1])
t, x = track(sys.argv[2])
n = min(len(tr), len(t))
assert np.allclose(tr[:n], t[:n]), "the runs' output times differ"
d = np.linalg.norm(x[:n] - xr[:n], axis=1)
i = int(np.argmax(d))
print("%s vs %s: max |d position| %.4f mm at t = %.3f s over %d samples (0-%.2f s)"
      % (sys.argv[2], sys.argv[1], d[i], t[i], n, t[n - 1]))

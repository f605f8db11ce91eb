#!/usr/bin/python3
"""growth.py REF.h5 RUN.h5: the largest |d support position| (mm) of RUN from REF over each
whole second so far (t <= 1, 2, ... s): how a difference grows along the run."""
import sys

import h5py
import numpy as np

with h5py.File(sys.argv[1], "r") as fa, h5py.File(sys.argv[2], "r") as fb:
    t = fa["time"][()]
    n = min(len(t), len(fb["time"]))
    d = np.linalg.norm(fa["support/position"][:n] - fb["support/position"][:n], axis=1)
    print(" ".join("t<=%d s: %.2g" % (s, d[t[:n] <= s + 1e-9].max())
                   for s in range(1, int(t[n - 1] + 1e-9) + 1)))

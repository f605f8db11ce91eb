#!/usr/bin/python3
"""Two run files compared row for row over their common rows: time, support position and
orientation, chamber pressures, foot forces; prints the largest difference of each and whether
every one is bit for bit. usage: same_rows.py A.h5 B.h5"""
import sys

import h5py
import numpy as np

with h5py.File(sys.argv[1], "r") as a, h5py.File(sys.argv[2], "r") as b:
    n = min(a["time"].shape[0], b["time"].shape[0])
    same = True
    for k in ("time", "support/position", "support/orientation", "pressure", "contact/foot_force"):
        d = np.abs(a[k][:n] - b[k][:n]).max()
        same = same and d == 0
        print("%-22s max diff %.3g" % (k, d))
    print("%d common rows (%d, %d): %s" % (n, a["time"].shape[0], b["time"].shape[0],
                                          "bit for bit" if same else "DIFFER"))

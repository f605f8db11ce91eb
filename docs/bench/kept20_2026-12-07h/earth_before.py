#!/usr/bin/python3
"""earth_before.py A B: the support track of B's `earth` run against A's (/tmp/kept20/runs,
k20.sh runs.sh WHO earth) before 0.9, 1.0 and 1.0182 s (the fall), mm"""
import sys

import h5py
import numpy as np

f = "/tmp/kept20/runs/{}.earth.flat-road.h5"
a, b = h5py.File(f.format(sys.argv[1]), "r"), h5py.File(f.format(sys.argv[2]), "r")
t = a["time"][()] if "time" in a else a["support/time"][()]
d = np.abs(a["support/position"][()] - b["support/position"][()])
d = d.reshape(len(t), -1).max(axis=1)
for tc in (0.9, 1.0, 1.0182):
    print(f"{sys.argv[2]}: support track against {sys.argv[1]} for t < {tc} s: "
          f"{d[t < tc].max():.3e} mm")

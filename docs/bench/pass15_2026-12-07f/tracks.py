#!/usr/bin/python3
"""tracks.py BASE.h5 NEW.h5 [...pairs]: tools/bench_levels.py's track measure (the largest
|(dx, dz)| of the support over the whole seconds both runs reach, mm) between each pair, and the
largest |difference| of the support's position over every output sample (mm)."""
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../tools"))
import bench_levels as bl  # noqa: E402

a = sys.argv[1:]
for base, new in zip(a[::2], a[1::2]):
    e = bl.track_error({"h5": new}, {"h5": base})
    pa = np.asarray(h5py.File(base, "r")["support/position"][()])
    pb = np.asarray(h5py.File(new, "r")["support/position"][()])
    n = min(len(pa), len(pb))
    print(f"{new} vs {base}: whole seconds {e:.4f} mm; every sample {np.max(np.abs(pa[:n] - pb[:n])):.4f} mm")

#!/usr/bin/python3
"""diff_all.py BASE.h5 NEW.h5: the largest difference of the support's (x, z) between two runs
over every output sample (mm, tools/bench_levels.py read_track), beside bench_levels' measure
(whole seconds, track_error)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../tools"))
import bench_levels as bl  # noqa: E402

a, b = sys.argv[1], sys.argv[2]
ta, pa, _ = bl.read_track(a)
tb, pb, _ = bl.read_track(b)
n = min(len(ta), len(tb))
d = np.hypot(pa[:n, 0] - pb[:n, 0], pa[:n, 2] - pb[:n, 2])
i = int(np.argmax(d))
print(f"{b} vs {a}: whole seconds {bl.track_error({'h5': b}, {'h5': a}):.4f} mm; every sample "
      f"({n}) max {d[i]:.4f} mm at t = {ta[i]:.2f} s; x(end) {pa[n-1, 0]:.4f} / {pb[n-1, 0]:.4f} mm")

#!/usr/bin/python3
"""The shipped design's runs at 8 elements (search/cases/dKEY[__CASE].h5) against the same runs
at 16 elements (DIR16/dKEY_el16_NAME.h5): x at 1..9 s of both and the largest difference at the
whole seconds. usage: /usr/bin/python3 conv16.py KEY DIR16 NAME=CASE ...  (NAME tab: the nominal)"""
import os
import sys
import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def xs(p):
    with h5py.File(p, "r") as f:
        g = f["run"] if "run" in f else f
        t, x = g["time"][:], g["support/position"][:, 0]
    return [float(np.interp(k, t, x)) for k in range(1, 10)]


key, d16 = sys.argv[1], sys.argv[2]
print("# run: x at 1..9 s (mm) at 8 elements / at 16 elements; max |8 - 16| over 1..9 s and "
      "over 3..9 s (mm)")
for arg in sys.argv[3:]:
    name, case = arg.split("=")
    p8 = os.path.join(HERE, "search", "cases", f"d{key}{'__' + case if case else ''}.h5")
    p16 = os.path.join(d16, f"d{key}_el16_{name}.h5")
    a, b = xs(p8), xs(p16)
    d = [abs(u - v) for u, v in zip(a, b)]
    print(f"{name}: " + " ".join(f"{v:.2f}" for v in a) + " / " + " ".join(f"{v:.2f}" for v in b)
          + f"; max {max(d):.2f} (t = {1 + d.index(max(d))} s), from 3 s {max(d[2:]):.2f}")

#!/usr/bin/python3
"""h5diff.py BASE.h5 NEW.h5: every float dataset of two run files, the largest |difference| and
where; 'identical' when every dataset is bit for bit the same."""
import sys

import h5py
import numpy as np

a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
rows = []


def visit(name, obj):
    if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f" and name in b:
        x, y = np.asarray(obj[()]), np.asarray(b[name][()])
        if x.shape != y.shape:
            rows.append((name, "shape", x.shape, y.shape))
            return
        same = np.array_equal(x, y, equal_nan=True)
        d = float(np.nanmax(np.abs(x - y))) if x.size else 0.0
        rows.append((name, "identical" if same else "differs", d, float(np.nanmax(np.abs(x))) if x.size else 0.0))


a.visititems(visit)
n_same = sum(r[1] == "identical" for r in rows)
print(f"{len(rows)} float datasets, {n_same} bit-identical")
for r in rows:
    if r[1] != "identical":
        print(f"  {r[0]}: max |diff| {r[2]:.3e} (max |value| {r[3]:.3e})")

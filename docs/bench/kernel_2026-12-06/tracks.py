#!/usr/bin/python3
"""tracks.py REF.h5 RUN.h5: how far a run's track is from a reference run of the same scene:
whether every float dataset is bit-identical, the largest |d support position| (mm) over all
output samples and at whole seconds, and the largest |d| of the legs' centrelines and foot
forces (branch `kernel`, docs/notes/strain_leg.md "Kernel and fixed costs")."""
import sys

import h5py
import numpy as np


def series(f):
    out = {}

    def visit(name, obj):
        if isinstance(obj, h5py.Dataset) and obj.dtype.kind == "f":
            out[name] = obj[()]
    f.visititems(visit)
    return out


with h5py.File(sys.argv[1], "r") as fr, h5py.File(sys.argv[2], "r") as fn:
    a, b = series(fr), series(fn)
    t = a["time"]
    n = min(len(t), len(b["time"]))
    same = all(k in b and a[k].shape == b[k].shape and np.array_equal(a[k], b[k]) for k in a)
    dx = np.linalg.norm(a["support/position"][:n] - b["support/position"][:n], axis=1)
    whole = [i for i in range(n) if abs(t[i] - round(t[i])) < 1e-9 and round(t[i]) >= 1]
    cl = max(np.abs(a[k][:n] - b[k][:n]).max() for k in a if k.endswith("centerline"))
    ff = np.abs(a["contact/foot_force"][:n] - b["contact/foot_force"][:n]).max()
    print("%s vs %s: bit-identical %s; support max |d| %.3g mm (at t = %.3f s) over %d samples, "
          "%.3g mm at whole seconds; centrelines max |d| %.3g mm; foot forces max |d| %.3g N; "
          "x(end) %.4f / %.4f mm"
          % (sys.argv[2], sys.argv[1], same, dx.max(), t[int(np.argmax(dx))], n,
             max(dx[i] for i in whole) if whole else float("nan"), cl, ff,
             a["support/position"][n - 1][0], b["support/position"][n - 1][0]))

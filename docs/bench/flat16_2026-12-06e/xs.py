#!/usr/bin/python3
"""Print each run file's support x at 1..9 s, worst node against Table 2 from 2 s, max |z|, max tilt.

usage: /usr/bin/python3 xs.py RUN.h5 ...   (a `crawlsim run` file or a study case file)"""
import os
import sys
import h5py
import numpy as np

for p in sys.argv[1:]:
    with h5py.File(p, "r") as f:
        g = f["run"] if "run" in f else f
        if "time" not in g:
            print(f"{os.path.basename(p)}: no track")
            continue
        t = g["time"][:]
        pos = g["support/position"][:]
        q = g["support/orientation"][:]
        ramp = g.attrs.get("ramp_s", f.attrs.get("ramp_s", float("nan")))
        links = g.attrs.get("links_per_segment", f.attrs.get("links_per_segment", 0))
    x = [float(np.interp(k, t, pos[:, 0])) if t[-1] >= k - 1e-9 else float("nan") for k in range(10)]
    errs = [((x[k] - 39.0 * (k - 1)) / (39.0 * (k - 1)), k) for k in range(2, 10)]
    e, k = max(errs, key=lambda v: abs(v[0]))
    tilt = float(np.degrees(np.max(np.arccos(np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2), -1, 1)))))
    print(f"{os.path.basename(p)} (links {links:g}, ramp {ramp:g}): "
          + " ".join(f"{v:.2f}" for v in x[1:])
          + f" | worst {100 * e:+.2f} % (t={k}) | |z| {np.max(np.abs(pos[:, 2])):.2f} tilt {tilt:.2f}")

#!/usr/bin/python3
"""Each level's track against the converged rod (16 elements per segment, 0.25 ms) and its CPU
from one bench_strain_driver process (run.sh): error = max over t = 1..9 s of |support (dx, dz)|
(mm); the Pareto front = the configurations no other is both cheaper and closer than.
usage: compare.py [DIR=build/levels_one] [RUN_TXT=run.txt beside this file]"""
import os
import re
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
d = sys.argv[1] if len(sys.argv) > 1 else "build/levels_one"
txt = sys.argv[2] if len(sys.argv) > 2 else os.path.join(HERE, "run.txt")
REF = "rod_16_0.00025_0.h5"


def whole(path):
    with h5py.File(path, "r") as f:
        t, p = f["/time"][()], f["/support/position"][()]
    out = []
    for s in range(1, 10):
        i = np.flatnonzero(np.abs(t - s) < 1e-6)
        out.append(p[i[0], [0, 2]] - p[0, [0, 2]] if i.size else [np.nan, np.nan])
    return np.array(out)


cpu = {}
pat = re.compile(r"^(\w+), (\d+) per segment, h ([\d.e-]+) ms( BDF2)?, coupling (\w+): "
                 r"([\d.]+) s simulated(.*?), CPU ([\d.]+) s -> real-time factor ([\d.]+)")
for line in open(txt):
    m = pat.match(line)
    if m:
        lvl, n, h, bdf, coup, tsim, stop, c, rtf = m.groups()
        key = (lvl, int(n), float(h) * 1e-3, 2 if bdf else (1 if lvl == "strain" else 0))
        cpu[key] = (float(c) / float(tsim), float(rtf), coup, stop.strip())
ref = whole(os.path.join(d, REF))
rows = []
for (lvl, n, h, order), (cps, rtf, coup, stop) in cpu.items():
    f = os.path.join(d, "%s_%d_%g_%d.h5" % (lvl, n, h, order))
    if not os.path.exists(f):
        continue
    tr = whole(f)
    err = float(np.nanmax(np.hypot(*(tr - ref).T))) if f != os.path.join(d, REF) else 0.0
    rows.append((lvl, n, h, order, coup, err, cps, rtf, tr[-1, 0], stop))
rows.sort(key=lambda r: r[6])
print("# level, per segment, h (ms), order, coupling: error against rod 16 at 0.25 ms (mm), "
      "CPU s per simulated s, real-time factor, x(9 s) mm, on the front")
for r in rows:
    front = not any(o[6] < r[6] and o[5] <= r[5] or o[6] <= r[6] and o[5] < r[5] for o in rows)
    print("%-6s %2d %6.2f %s %-10s error %7.2f  CPU %6.3f  RTF %6.3f  x9 %7.1f  %s%s" % (
        r[0], r[1], r[2] * 1e3, {0: "- ", 1: "BE", 2: "BDF2"}[r[3]], r[4], r[5], r[6], r[7],
        r[8], "front" if front else "", (" (" + r[9] + ")") if r[9] else ""))

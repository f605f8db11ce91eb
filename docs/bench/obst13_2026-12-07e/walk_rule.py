#!/usr/bin/python3
"""The walk's end read off the measured support x (the crawl statement's rule on x), applied to
run files offline: x at the ends of the two-group walk's slots (table time, gate holds removed:
ramp11's lag.py), and at each boundary j >= 2 of the decision's phase whether the rule ends the
walk: x_j + CARRY >= XEND - (x_j - x_{j-2}) / 2.
Exact for a table that agrees with the run's up to the boundary (the decision reads only the
state before it). usage: walk_rule.py T0 TP N XEND CARRY RUN.h5...
(T0 the first walk slot's start, TP a slot, N the walk's slots before the turn)"""
import sys

import h5py
import numpy as np

sys.path.insert(0, sys.path[0])
from phases import table_time  # noqa: E402

t0, tp, n, xend, carry = float(sys.argv[1]), float(sys.argv[2]), int(sys.argv[3]), float(sys.argv[4]), float(sys.argv[5])
for fn in sys.argv[6:]:
    with h5py.File(fn, "r") as f:
        t, tau = table_time(f)
        x = f["support/position"][:, 0]
    xs = {}
    for j in range(n):
        i = np.nonzero(tau >= t0 + (j + 1) * tp - 1e-9)[0]
        xs[j] = x[i[0]] if len(i) else np.nan
    out = []
    for j in range((n - 1) % 2, n, 2):
        if j < 2 or j == n - 1:
            continue
        a = xs[j] - xs[j - 2]
        lhs, rhs = xs[j] + carry, xend - a / 2
        out.append("j %d (%.2f s): x %.1f a %.1f: %.1f %s %.1f -> %s" % (
            j, t0 + (j + 1) * tp, xs[j], a, lhs, ">=" if lhs >= rhs else "<", rhs,
            "end (skip %d)" % (n - 1 - j) if lhs >= rhs else "walk on"))
    print("%-10s x at slot ends: %s" % (fn.split("/")[-1], " ".join("%.1f" % xs[j] for j in range(n))))
    for o in out:
        print("    " + o)

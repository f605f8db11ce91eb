#!/usr/bin/python3
"""table_harness.py: support x at whole seconds from the harness outputs here
(harness_o{ORDER}_h{H}.txt), each run against its half-step run, the max over 1..8 s, the
observed order log2 of successive differences; BE's numbers for comparison are in
docs/notes/strain_leg.md (the friction's secant table)."""
import glob
import re

runs = {}
for p in glob.glob("harness_o*_h*.txt"):
    m = re.match(r"harness_o(\d)_h([0-9.e-]+)\.txt", p.split("/")[-1])
    xs = [float(v) for v in re.findall(r"^t \d+ s: support x\s+([+-][0-9.]+)", open(p).read(), re.M)]
    runs[(int(m.group(1)), float(m.group(2)))] = xs
for o in sorted({k[0] for k in runs}):
    hs = sorted((k[1] for k in runs if k[0] == o), reverse=True)
    print("step order %d" % o)
    for h in hs:
        print("  %7.3f ms " % (1e3 * h) + " ".join("%8.2f" % x for x in runs[(o, h)]))
    diffs = []
    for a, b in zip(hs, hs[1:]):
        ra, rb = runs[(o, a)], runs[(o, b)]
        n = min(len(ra), len(rb))
        d = [ra[i] - rb[i] for i in range(n)]
        diffs.append(d)
        print("  %g - %g ms: " % (1e3 * a, 1e3 * b) + " ".join("%+6.2f" % v for v in d) +
              "   max %.2f" % max(abs(v) for v in d))

#!/usr/bin/env python3
"""levels_median.py A.csv B.csv C.csv > OUT.csv: robot/levels.csv's rows as the median of three
tools/bench_levels.py tables run one after the other on the same build (this VM's speed drifts by
20-30 % from one run to the next: the median per row of three runs, not one run). Every column but
cpu_s_per_s and wall_s_per_s must be equal in the three (the tracks are deterministic); the
header comments are the first table's."""
import statistics
import sys

tabs = [open(p).read().splitlines() for p in sys.argv[1:4]]
head = [l for l in tabs[0] if l.startswith('#')]
rows = [[l.split(',') for l in t if l and not l.startswith('#')] for t in tabs]
cols = rows[0][0]
ic, iw = cols.index('cpu_s_per_s'), cols.index('wall_s_per_s')
out = head + [','.join(cols)]
for r in zip(*[t[1:] for t in rows]):
    same = [[v for k, v in enumerate(x) if k not in (ic, iw)] for x in r]
    if any(s != same[0] for s in same):
        sys.exit('levels_median.py: rows differ beyond CPU: %s' % r)
    m = list(r[0])
    m[ic] = '%.3f' % statistics.median(float(x[ic]) for x in r)
    m[iw] = '%.3f' % statistics.median(float(x[iw]) for x in r)
    out.append(','.join(m))
print('\n'.join(out))

#!/usr/bin/python3
"""calls.py CG NAME...: the calls to each named function in a callgrind profile (the sum of its
callers' calls= lines) and its inclusive instructions per call (from those lines' costs)."""
import re
import sys

f, names = sys.argv[1], sys.argv[2:]
idname = {}
calls = {n: 0 for n in names}
incl = {n: 0 for n in names}
cur = None
pending = None
for line in open(f):
    m = re.match(r'^c?fn=\((\d+)\)(?: (.*))?$', line.strip())
    if m:
        if m.group(2):
            idname[m.group(1)] = m.group(2)
        if line.startswith('cfn='):
            cur = idname.get(m.group(1))
        continue
    if line.startswith('calls=') and cur in calls:
        calls[cur] += int(line.split('=')[1].split()[0])
        pending = cur
        continue
    if pending:
        w = line.split()
        if len(w) >= 2:
            incl[pending] += int(w[1])
        pending = None
for n in names:
    c = calls[n]
    print(f"{n}: calls {c}, inclusive {incl[n]:.4g}, per call {incl[n] / c if c else 0:.4g}")

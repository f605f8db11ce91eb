#!/usr/bin/python3
"""cgdiff.py A.cg B.cg: self instructions by function (callgrind_annotate), B - A, the largest changes"""
import re, subprocess, sys
def load(p):
    out = subprocess.run(["callgrind_annotate", "--inclusive=no", "--threshold=100", p],
                         capture_output=True, text=True).stdout
    d = {}
    for line in out.splitlines():
        m = re.match(r"\s*([\d,]+) \([^)]*\)\s+(\S+?):(\S+)", line)
        if m:
            fn = m.group(3)
            d[fn] = d.get(fn, 0) + int(m.group(1).replace(",", ""))
    return d
a, b = load(sys.argv[1]), load(sys.argv[2])
rows = sorted(((b.get(k, 0) - a.get(k, 0), k) for k in set(a) | set(b)), key=lambda r: abs(r[0]), reverse=True)
print(f"total {sum(a.values()):,} -> {sum(b.values()):,}: {sum(b.values()) - sum(a.values()):+,}")
for dlt, k in rows[:20]:
    print(f"{dlt:+15,}  {k}  ({a.get(k, 0):,} -> {b.get(k, 0):,})")

#!/usr/bin/python3
"""set_table.py GAIT: issue 33's obstacle set of GAIT at d and b (set.sh's logs): per case the
end's distance from Table 3's end point (mm) or the fall time, the worst node, and the loaded
feet nearest an edge on the step's top over 5-12 s (margin.py's lines in the log)."""
import os
import re
import sys

H = os.path.dirname(os.path.abspath(__file__))
CASES = ("nominal", "ramp0.1", "ramp0.5", "mu0.6", "mu1.0", "m25g", "m75g", "tau0.5x", "tau2x",
         "dt_half")


def cell(g, lev, c):
    p = os.path.join(H, "logs", "%s_%s_%s.log" % (g, lev, c))
    if not os.path.exists(p):
        return "(not run)"
    s = open(p).read()
    v = re.search(r"^verdict \([^)]*\): (\w[\w ]*?):", s, re.M)
    e = re.search(r"end ([\d.]+) s \(.*?\) ([\d.]+) mm off;.*worst node ([\d.]+) \((\d+) s\)", s)
    tops = re.findall(r"^\s+([\d.]+)-\s*([\d.]+) s: on top min (-?[\d.]+) mm", s, re.M)
    top = min((float(m) for a, b, m in tops if float(a) < 12), default=float("nan"))
    if not v or not e:
        return "?"
    if v.group(1) in ("crawls", "walks"):
        return "%s (node %s at %s s; top %.1f)" % (e.group(2), e.group(3), e.group(4), top)
    return "**%s at %s s** (top %.1f)" % (v.group(1), e.group(1), top)


g = sys.argv[1] if len(sys.argv) > 1 else "m6"
print("| case | d (BE 2.5e-4) | b (BDF2 5e-4) |")
print("|---|---|---|")
for c in CASES:
    print("| %s | %s | %s |" % (c, cell(g, "d", c), cell(g, "b", c)))

#!/usr/bin/python3
"""One table row per Newton log of corot_newton.py (rom15): the representation's Pi and mixed
bulk, then the last step's Pi, tip, pressure work against the FE's (%), worst chamber, M-norm
and gradient ratio, and the tips along the way.  summarise.py LOG..."""
import re
import sys

for path in sys.argv[1:]:
    fe = rep = None
    steps = []
    for line in open(path):
        if "FE state" in line:
            fe = float(re.search(r"work +([-\d.]+)", line).group(1))
        elif "representation" in line:
            rep = (re.search(r"Pi +([-\d.]+)", line).group(1), re.search(r"bulk +([-\d.e+]+)", line).group(1))
        elif re.match(r"\s+Newton \d+", line):
            g = {k: re.search(p, line).group(1) for k, p in (
                ("n", r"Newton (\d+)"), ("pi", r"Pi +([-\d.]+)"), ("work", r"work +([-\d.]+)"),
                ("tip", r"tip ([\d.]+)"), ("ch", r"worst chamber ([-+\d.]+ % \(\d\.\d\))"),
                ("mn", r"M-norm ([\d.]+)"), ("gr", r"p force\| ([\d.e+-]+)"))}
            steps.append(g)
    if not steps:
        print(f"{path}: no step yet")
        continue
    s = steps[-1]
    print(f"{path}: rep Pi {rep[0]}, bulk {rep[1]} | step {s['n']}: Pi {s['pi']}, tip {s['tip']} mm, "
          f"work {s['work']} ({100 * (float(s['work']) / fe - 1):+.1f} %), chamber {s['ch']}, "
          f"M-norm {s['mn']} %, grad {s['gr']} | tips " + " / ".join(x["tip"] for x in steps))

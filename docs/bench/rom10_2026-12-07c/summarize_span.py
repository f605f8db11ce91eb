#!/usr/bin/python3
"""summarize_span.py: the worst chamber of the walls' best fit over each held-out ray
(romacc_volume_diag.py's "faces' projection") and the worst tip of the M-projection onto the
whole basis (rom_project.py), one line a basis. Usage: summarize_span.py OUT/b<N>_f104 ..."""
import re
import sys

for stem in sys.argv[1:]:
    walls, tips = {}, {}
    for line in open(stem + "_volume_diag.log"):
        m = re.match(r"(\S+)\s+t ([\d.]+): .*faces' projection worst ([-+\d.]+) % \(chamber (\S+)\)",
                     line)
        if m and abs(float(m[3])) >= walls.get(m[1], (0,))[0]:
            walls[m[1]] = (abs(float(m[3])), m[2], m[4])
    whole = False
    for line in open(stem + "_projection.log"):
        whole = whole or "whole displacement basis" in line
        f = line.split()
        if whole and f and f[0].startswith("T_") and len(f) == 6:
            tips[f[0]] = max(tips.get(f[0], 0.0), float(f[5]))
    print(stem + ": " + "; ".join(f"{r} {w[0]:.2f} % (t {w[1]}, II{w[2]}), tip {tips.get(r, float('nan')):.4f} mm"
                                  for r, w in sorted(walls.items())))

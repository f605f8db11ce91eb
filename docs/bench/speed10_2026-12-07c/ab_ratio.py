#!/usr/bin/python3
"""ab_ratio.py FILE: the pairs of ab_cpu.sh's output (lines "A|B user_s load1", A then B): each
pair's B / A CPU ratio, their median and range, the medians of A and B alone (CPU s of the 9.8 s
run: the 0.3 s settling and 9.5 s of the gait) and the loads seen."""
import statistics
import sys

rows = [line.split() for line in open(sys.argv[1]) if line.strip()]
pairs = [(float(a[1]), float(b[1])) for a, b in zip(rows[0::2], rows[1::2])
         if a[0] == "A" and b[0] == "B"]
r = [b / a for a, b in pairs]
loads = [float(x[2]) for x in rows]
print(f"{len(pairs)} pairs; B/A per pair: " + " ".join(f"{v:.3f}" for v in r))
print(f"median B/A {statistics.median(r):.3f} (range {min(r):.3f}-{max(r):.3f}); median CPU s "
      f"A {statistics.median(a for a, _ in pairs):.2f}, B {statistics.median(b for _, b in pairs):.2f}"
      f" (per simulated s of the 9.5 s gait: A {statistics.median(a for a, _ in pairs) / 9.5:.3f}, "
      f"B {statistics.median(b for _, b in pairs) / 9.5:.3f}); load {min(loads):.1f}-{max(loads):.1f}")

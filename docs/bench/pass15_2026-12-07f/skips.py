#!/usr/bin/python3
"""skips.py TRACE [T0 T1] [TOL]: what the per-pass trace (trace.patch) says about re-passing legs.

A 'P' line is one leg's iterate (its re-linearisation) at the start of pass p of a try (p 2: the
try's first iterate, after the solve on prepare's model): its own move ck at the update before it
(mm), its hip's move (h |dV|, the angular part times 100 mm), the support's move, the touching
shapes before and after, the refactors the iterate made (a slot changed state), and the oracle:
the next solve and back-substitution redone with this one leg's previous linear model in place of
the new one (all others new): es the support's move changes by, eo the leg's own modes, ex every
other leg's (mm). E = max(es, eo, ex): what skipping this leg's iterate alone changes in the
next move. 'T' lines: a try's passes and its last move."""
import sys
from collections import Counter

f = sys.argv[1]
t0 = float(sys.argv[2]) if len(sys.argv) > 2 else -1e9
t1 = float(sys.argv[3]) if len(sys.argv) > 3 else 1e9
tol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-6
P = []
tries = {}
for line in open(f):
    w = line.split()
    if w[0] == 'P':
        t = float(w[2])
        if not (t0 <= t < t1):
            continue
        P.append(dict(tr=int(w[1]), t=t, h=float(w[3]), p=int(w[4]), k=int(w[5]), ck=float(w[6]),
                      hip=float(w[7]), sup=float(w[8]), nb=int(w[9]), na=int(w[10]),
                      df=int(w[11]), plain=int(w[12]), ghost=int(w[13]), reuse=int(w[14]),
                      lag=int(w[15]), es=float(w[16]), eo=float(w[17]), ex=float(w[18])))
    elif w[0] == 'T':
        t = float(w[2])
        if t0 <= t < t1:
            tries[int(w[1])] = (int(w[4]), float(w[5]), w[6])
for r in P:
    r['E'] = max(r['es'], r['eo'], r['ex'])
    r['contact'] = r['na'] > 0 or r['nb'] > 0
    r['cset'] = r['na'] != r['nb'] or r['df'] > 0
n = len(P)
print(f"trace {f}, t in [{t0}, {t1}), tol {tol:g} mm")
print(f"tries {len(tries)}, passes per try {sum(v[0] for v in tries.values()) / max(1, len(tries)):.3f}, "
      f"rejected {sum(1 for v in tries.values() if v[2] != 'OK')}")
print("passes per try:", sorted(Counter(v[0] for v in tries.values()).items()))
print(f"leg iterates (P lines) {n}; leg passes incl. prepare {n + 8 * len(tries)}")


def show(name, sel):
    s = [r for r in P if sel(r)]
    bad = [r for r in s if r['E'] > tol]
    bad01 = [r for r in s if r['E'] > 0.1 * tol]
    print(f"  {name:58s} {len(s):6d} ({100 * len(s) / max(1, n):5.1f} %), E > tol {len(bad):5d}, "
          f"E > tol/10 {len(bad01):5d}")


print("\nleg iterates by kind: how many, and of them how many change the next move by more than tol")
show("all", lambda r: True)
for p in sorted(set(r['p'] for r in P)):
    show(f"at pass {p}", lambda r, p=p: r['p'] == p)
show("in contact (touching before or after)", lambda r: r['contact'])
show("out of contact", lambda r: not r['contact'])
show("out of contact, pass >= 3", lambda r: not r['contact'] and r['p'] >= 3)
show("in contact, pass >= 3", lambda r: r['contact'] and r['p'] >= 3)
show("contact set changed (touching count or a refactor)", lambda r: r['cset'])
print("\noracle: iterates whose skipping changes nothing above tol / tol/10")
show("E <= tol (the oracle would skip)", lambda r: r['E'] <= tol)
show("E <= tol, pass >= 3", lambda r: r['E'] <= tol and r['p'] >= 3)
print("\nrules (skip when ...; pass 2 = the first iterate, never skipped in the rows marked p>=3)")
show("(a) contact set unchanged", lambda r: not r['cset'])
show("(a) contact set unchanged, p>=3", lambda r: not r['cset'] and r['p'] >= 3)
show("(b) own move ck <= tol", lambda r: r['ck'] <= tol)
show("(b) own move ck <= tol, p>=3", lambda r: r['ck'] <= tol and r['p'] >= 3)
show("(b+hip) own move and hip move <= tol", lambda r: max(r['ck'], r['hip']) <= tol)
show("(c) support move <= tol", lambda r: r['sup'] <= tol)
show("(c) hip move <= tol", lambda r: r['hip'] <= tol)
show("(a)+(b) unchanged and ck <= tol", lambda r: not r['cset'] and r['ck'] <= tol)
show("(a)+(b+hip), p>=3", lambda r: not r['cset'] and max(r['ck'], r['hip']) <= tol and r['p'] >= 3)
show("out of contact, p>=3, ck <= 10 tol", lambda r: not r['contact'] and r['p'] >= 3 and r['ck'] <= 10 * tol)
show("out of contact (any p)", lambda r: not r['contact'])

# E against the leg's move: the ratio E / max(ck, hip) (the linear model's error per mm moved)
import math
print("\nE / max(ck, hip): the skipped model's error per unit of the leg's move, by kind (median, 90 %, max)")
for name, sel in [("p=2 out of contact", lambda r: r['p'] == 2 and not r['contact']),
                  ("p=2 in contact", lambda r: r['p'] == 2 and r['contact']),
                  ("p>=3 out of contact", lambda r: r['p'] >= 3 and not r['contact']),
                  ("p>=3 in contact, set unchanged", lambda r: r['p'] >= 3 and r['contact'] and not r['cset']),
                  ("p>=3 contact set changed", lambda r: r['p'] >= 3 and r['cset'])]:
    v = sorted(r['E'] / max(r['ck'], r['hip'], 1e-30) for r in P if sel(r))
    if v:
        print(f"  {name:34s} n {len(v):6d}  median {v[len(v) // 2]:.3g}  90% {v[int(0.9 * (len(v) - 1))]:.3g}  max {v[-1]:.3g}")

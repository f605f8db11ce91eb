#!/usr/bin/python3
"""rules.py TRACE T0 T1 [TOL]: skip rules evaluated on the per-pass trace (see skips.py): for each
rule the leg iterates it would skip, and how many of those the oracle says change the next move
by more than tol (or tol/10). theta: a leg's measured linear-model error per mm moved, E / m, at
its previous iterate in the same try (E the oracle's effect, m = max(ck, hip) the leg's move before
that iterate); predicted = theta * m now."""
import sys
f, t0, t1 = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
tol = float(sys.argv[4]) if len(sys.argv) > 4 else 1e-6
rows = []
for line in open(f):
    w = line.split()
    if w[0] != 'P':
        continue
    t = float(w[2])
    if not (t0 <= t < t1):
        continue
    rows.append(dict(tr=int(w[1]), p=int(w[4]), k=int(w[5]), ck=float(w[6]), hip=float(w[7]),
                     sup=float(w[8]), nb=int(w[9]), na=int(w[10]), df=int(w[11]),
                     E=max(float(w[16]), float(w[17]), float(w[18]))))
prev = {}
prevtry = {}
for r in rows:
    r['m'] = max(r['ck'], r['hip'])
    key = (r['tr'], r['k'])
    q = prev.get(key)
    r['theta'] = q['E'] / max(q['m'], 1e-30) if q else None
    # the previous try's first-iterate theta for this leg
    qt = prevtry.get(r['k'])
    r['theta_prevtry'] = qt if qt is not None else None
    prev[key] = r
    if r['p'] == 2:
        prevtry_key = r['k']
        prevtry[r['k']] = r['E'] / max(r['m'], 1e-30)
n = len(rows)
print(f"{f}: t in [{t0}, {t1}), {n} leg iterates, tol {tol:g} mm")
print(f"out of contact at p>=3 but touching after (a touch-down inside the passes): "
      f"{sum(1 for r in rows if r['p'] >= 3 and r['nb'] == 0 and r['na'] > 0)}; "
      f"touching before, none after: {sum(1 for r in rows if r['p'] >= 3 and r['nb'] > 0 and r['na'] == 0)}")


def show(name, sel):
    s = [r for r in rows if sel(r)]
    bad = sum(1 for r in s if r['E'] > tol)
    bad01 = sum(1 for r in s if r['E'] > 0.1 * tol)
    worst = max((r['E'] for r in s), default=0)
    print(f"  {name:66s} skips {len(s):6d} ({100 * len(s) / n:5.1f} %)  E>tol {bad:4d}  E>tol/10 {bad01:4d}  max E {worst:.2e}")


for sf in (1.0, 0.1, 0.01):
    show(f"theta rule, p>=3: theta*m <= {sf:g} tol",
         lambda r, sf=sf: r['p'] >= 3 and r['theta'] is not None and r['theta'] * r['m'] <= sf * tol)
    show(f"theta rule, p>=3, no touch before: theta*m <= {sf:g} tol",
         lambda r, sf=sf: r['p'] >= 3 and r['nb'] == 0 and r['theta'] is not None and r['theta'] * r['m'] <= sf * tol)
    show(f"theta rule, p=2 from the previous try's p=2 theta: <= {sf:g} tol",
         lambda r, sf=sf: r['p'] == 2 and r['theta_prevtry'] is not None and r['theta_prevtry'] * r['m'] <= sf * tol)
show("no touch before, p>=3", lambda r: r['p'] >= 3 and r['nb'] == 0)
show("no touch before, p>=3, m <= 1e-4 mm", lambda r: r['p'] >= 3 and r['nb'] == 0 and r['m'] <= 1e-4)
show("no touch before, p=2", lambda r: r['p'] == 2 and r['nb'] == 0)

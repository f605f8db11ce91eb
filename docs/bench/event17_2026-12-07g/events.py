#!/usr/bin/python3
"""events.py TRACE T0 T1: what the default's tries, passes and step lengths are spent on, from the
scratch trace of trace.patch (EV17_TRACE=FILE bench_strain_driver ...).

Lines (t in s, h in s):
  T t0 h passes OK|FAIL nref npref last tch dtch lim legs chg [nsh]   one tree solve (a try of the
      stages, or one of its halves): its Newton passes; nref the legs' iterates that refactored
      (a contact slot changed state: stick/slip/open, the leg's factor redone), npref the passes
      with one, last the last pass with one, tch the legs touching at the end, dtch the legs
      whose touching-shape count changed between prepare and the end, lim the passes damped
      by a leg's stepLimit, legs which legs refactored, chg the last move (mm), nsh the shapes
      touching at the end (all legs)
  S t H depth status message       a stage rejected a try of H (halved and retried)
  A t1 h E ACC|REJ imax nstage     the adaptive controller's test of the try ending at t1: E its
      error norm, imax the watched value of the largest term (0-2 the support's centre, 3-5 its
      velocity, 6-8 its angular velocity x 30 mm, 9 + 3k .. foot k), nstage the stages' halvings
A try is the lines up to and including its A line. Window: the A line's t1 in [T0, T1)."""
import sys
from collections import Counter
import statistics as st

f, t0, t1 = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
tries = []
cur = {'T': [], 'S': []}
for line in open(f):
    w = line.split()
    if w[0] == 'T':
        cur['T'].append(dict(t=float(w[1]), h=float(w[2]), p=int(w[3]), ok=w[4] == 'OK',
                             nref=int(w[5]), npref=int(w[6]), last=int(w[7]), tch=int(w[8]),
                             dtch=int(w[9]), lim=int(w[10]), legs=w[11],
                             nsh=int(w[13]) if len(w) > 13 else -1,
                             tmask=w[14] if len(w) > 14 else None))
    elif w[0] == 'S':
        cur['S'].append((float(w[1]), float(w[2]), int(w[3]), ' '.join(w[5:])))
    elif w[0] == 'A':
        cur.update(t1=float(w[1]), h=float(w[2]), E=float(w[3]), acc=w[4] == 'ACC',
                   imax=int(w[5]), nst=int(w[6]))
        if t0 <= cur['t1'] < t1:
            tries.append(cur)
        cur = {'T': [], 'S': []}
T = [x for tr in tries for x in tr['T']]
dur = t1 - t0
print(f"trace {f}, tries ending in [{t0}, {t1}) s ({dur:g} s)")
nacc = sum(tr['acc'] for tr in tries)
nrej = len(tries) - nacc
print(f"adaptive tries {len(tries)} ({len(tries) / dur:.0f} per s): accepted {nacc}, rejected by the "
      f"error {nrej}; tree solves {len(T)} ({len(T) / dur:.0f} per s), of them failed "
      f"{sum(not x['ok'] for x in T)}")
# what forced the rejections
S = [s for tr in tries for s in tr['S']]
kinds = Counter()
for s in S:
    m = s[3]
    k = ('tree Newton did not converge' if 'did not converge in' in m else
         'a leg left its range / sunk foot (finish)' if 'left its valid range' in m else
         'a leg step did not converge (prepare)' if "step of" in m and 'did not converge' in m else
         m[:60])
    kinds[k] += 1
print(f"stage rejections (halvings) {len(S)}: " + '; '.join(f'{k}: {v}' for k, v in kinds.items()))


def wname(i):
    return ('support centre' if i < 3 else 'support velocity' if i < 6 else
            'support angular velocity' if i < 9 else f'foot {"ABCDEFGH"[(i - 9) // 3]}')


def footkind(tr):
    k = (tr['imax'] - 9) // 3
    m = tr['T'][-1].get('tmask') if tr['T'] else None
    return 'a foot' if m is None else ('a touching foot' if m[k] != '.' else 'a swing foot')


def event(x):  # a contact event in this solve: a slot changed state or a shape count changed
    return x['nref'] > 0 or x['dtch'] > 0


rej = [tr for tr in tries if not tr['acc']]
if rej:
    wk = Counter(footkind(tr) if tr['imax'] >= 9 else wname(tr['imax']) for tr in rej)
    ev = sum(any(event(x) for x in tr['T']) for tr in rej)
    print(f"error rejections {len(rej)}: largest term " + ', '.join(f'{k} {v}' for k, v in wk.items())
          + f"; with a contact event in the rejected try {ev}")
    # the try before the rejection
    idx = {id(tr): i for i, tr in enumerate(tries)}
    prev_ev = sum(1 for tr in rej if idx[id(tr)] > 0 and any(event(x) for x in tries[idx[id(tr)] - 1]['T']))
    print(f"  ... with one in the accepted try before it {prev_ev}")
# passes
P = [x['p'] for x in T]
print(f"tree passes {sum(P)} ({sum(P) / len(T):.3f} per solve); leg passes {8 * sum(P)} "
      f"({8 * sum(P) / dur:.0f} per s)")
print("passes per solve:", sorted(Counter(P).items()))
E = [x for x in T if event(x)]
N = [x for x in T if not event(x)]
Eref = [x for x in T if x['nref'] > 0]
mN = st.mean([x['p'] for x in N]) if N else 0
print(f"solves with a contact event {len(E)} ({len(E) / dur:.0f} per s; {len(Eref)} with a refactor "
      f"in an iterate, {sum(x['nref'] for x in T)} leg refactors, {sum(x['nref'] for x in T) / dur:.0f} per s): "
      f"passes {st.mean([x['p'] for x in E]) if E else 0:.3f} per solve; without {len(N)}: {mN:.3f}")
print("  passes per solve, with an event:", sorted(Counter(x['p'] for x in E).items()))
print("  passes per solve, without:", sorted(Counter(x['p'] for x in N).items()))
extra = sum(x['p'] - mN for x in E)
print(f"passes beyond the eventless mean in the event solves: {extra:.0f} of {sum(P)} "
      f"({100 * extra / sum(P):.1f} %); passes up to the last refactor in them: "
      f"{sum(x['last'] for x in Eref)}; passes above 2 (the least a solve takes) in all: "
      f"{sum(p - 2 for p in P)} ({100 * sum(p - 2 for p in P) / sum(P):.1f} %), in event solves "
      f"{sum(x['p'] - 2 for x in E)}; failed solves' passes {sum(x['p'] for x in T if not x['ok'])}")
print(f"damped (stepLimit) passes {sum(x['lim'] for x in T)}")
# legs and shapes touching
print("legs touching at a solve's end:", sorted(Counter(x['tch'] for x in T).items()))
if T and T[0]['nsh'] >= 0:
    print("shapes touching at a solve's end (all legs):", sorted(Counter(x['nsh'] for x in T).items()))
# step lengths
acc = [tr for tr in tries if tr['acc']]
H = sorted(tr['h'] for tr in acc)
q = lambda a, p: a[min(len(a) - 1, int(p * len(a)))]
print(f"accepted steps: h median {1e3 * q(H, .5):.3f} ms, 10 % {1e3 * q(H, .1):.3f}, 90 % "
      f"{1e3 * q(H, .9):.3f}, min {1e3 * H[0]:.4f}, max {1e3 * H[-1]:.3f}; at the longest (>= 4.99 ms) "
      f"{sum(h >= 4.99e-3 for h in H)}")
evt = [tr['t1'] for tr in acc if any(event(x) for x in tr['T'])]
gaps = sorted(b - a for a, b in zip(evt, evt[1:]))
if gaps:
    print(f"accepted steps with an event {len(evt)} ({len(evt) / dur:.0f} per s); time between them: median "
          f"{1e3 * q(gaps, .5):.2f} ms, 10 % {1e3 * q(gaps, .1):.2f}, 90 % {1e3 * q(gaps, .9):.2f}")
    import bisect
    def dist(t):
        i = bisect.bisect_left(evt, t)
        return min(abs(t - evt[j]) for j in (i - 1, i) if 0 <= j < len(evt))
    for lo, hi in ((0, 0), (1e-12, 5e-3), (5e-3, 20e-3), (20e-3, 1e9)):
        s = [tr for tr in acc if (dist(tr['t1']) == 0 if hi == 0 else lo <= dist(tr['t1']) < hi)]
        if s:
            hs = sorted(tr['h'] for tr in s)
            print(f"  accepted steps {'at an event' if hi == 0 else f'{1e3 * lo:.0f}-{1e3 * hi:.0f} ms from one'}: "
                  f"{len(s)} ({100 * len(s) / len(acc):.1f} %), h median {1e3 * q(hs, .5):.3f} ms, "
                  f"time covered {sum(hs):.3f} s")
# which watched value sets the step: the largest term of the accepted steps' error norms
wk = Counter(footkind(tr) if tr['imax'] >= 9 else wname(tr['imax']) for tr in acc)
Es = sorted(tr['E'] for tr in acc)
print("accepted steps' largest error term: " + ', '.join(f'{k} {v}' for k, v in wk.most_common())
      + f"; their E median {q(Es, .5):.3f}, 90 % {q(Es, .9):.3f}")

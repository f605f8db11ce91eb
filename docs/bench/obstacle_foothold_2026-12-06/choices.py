#!/usr/bin/python3
"""choices.py RUN.h5 FILE.foothold: per foothold, the support's x displacement at its lift (from
the run's samples, 10 ms apart: the player reads the state at the step's start), the plan's
xplan, the shift, the candidate the run chose (the file's root attribute foothold_choices) and
where it was to land (its planned landing plus the shift)."""
import sys

import h5py
import numpy as np

run, fh = sys.argv[1], sys.argv[2]
f = h5py.File(run, 'r')
t = f['time'][:]
x = f['support/position'][:, 0] - f['support/position'][0, 0]
ch = f.attrs.get('foothold_choices', b'')
ch = ch.decode() if isinstance(ch, bytes) else str(ch)
chosen = [c.split() for c in ch.split(';') if c.strip()]
feet = []
for ln in open(fh):
    w = ln.split()
    if not w or w[0].startswith('#'):
        continue
    if w[0] == 'foothold':
        feet.append(dict(t=float(w[1]), legs=w[2], xplan=float(w[4]), cand={}, nominal=None))
    elif w[0] == 'candidate':
        feet[-1]['cand'][float(w[1])] = float(w[3])
        if w[-1] == 'nominal':
            feet[-1]['nominal'] = float(w[1])
for k, ft in enumerate(feet):
    if ft['t'] > t[-1]:
        print('%s at %.2f s: not reached' % (ft['legs'], ft['t']))
        continue
    xs = float(np.interp(ft['t'], t, x))
    d = xs - ft['xplan']
    c = chosen[k][2] if k < len(chosen) else '-'
    land = ft['cand'][float(c)] + d if c != '-' else float('nan')
    print('%s at %.2f s: support x %.1f (plan %.1f, shift %+.1f mm); chose offset %s (plan %g), '
          'to land at %.0f (plan\'s %.0f)' % (ft['legs'], ft['t'], xs, ft['xplan'], d, c,
                                              ft['nominal'], land, ft['cand'][ft['nominal']]))

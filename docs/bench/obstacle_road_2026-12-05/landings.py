#!/usr/bin/python3
"""Where each foot lands relative to its hip (x, mm) and how far it slides while standing:
usage: landings.py RUN.h5 [t_end]. A landing: the foot's stance flag goes 0 -> 1 and stays 1
for 0.1 s; its slide: the foot's x range over the next 0.3 s."""
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], 'r')
t = f['time'][:]
te = float(sys.argv[2]) if len(sys.argv) > 2 else t[-1]
st = f['contact/stance'][:]
for k, L in enumerate('ABCDEFGH'):
    cl = f['legs/' + L + '/centerline']
    foot = cl[:, -1, :]
    hip = cl[:, 0, :]
    ev = []
    for i in range(1, len(t) - 10):
        if t[i] > te:
            break
        if st[i - 1, k] == 0 and st[i:i + 10, k].all():
            j = min(i + 30, len(t) - 1)
            ev.append('%.1f:%+.0f(%.0f,y%.0f)' % (t[i], foot[i, 0] - hip[i, 0], foot[i, 0],
                                                 foot[i, 1]))
    print(L, ' '.join(ev))

#!/usr/bin/python3
"""The lateral crawl slot by slot: usage lateral.py RUN.h5 TZ TPZ [NSLOTS].
Per slot (from TZ, TPZ s each): the support's z advance, and the mean slide along z of the feet
that stand (within 3 mm of the road, y < 3) through the whole slot (the run's stance flag stays
0 for most standing feet of the lateral crawl), in world coordinates (mm): a foot that
grips does not move; the support's advance minus the stance feet's mean slide would be the
planned stroke if the legs were stiff."""
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], 'r')
t = f['time'][:]
tz, tp = float(sys.argv[2]), float(sys.argv[3])
n = int(sys.argv[4]) if len(sys.argv) > 4 else int((t[-1] - tz) / tp)
pos = f['support/position'][:]
feet = np.stack([f['legs/' + L + '/centerline'][:, -1, :] for L in 'ABCDEFGH'], axis=1)
tot = []
for s in range(n):
    i0 = int(np.argmin(abs(t - (tz + s * tp))))
    i1 = int(np.argmin(abs(t - (tz + (s + 1) * tp))))
    if i1 >= len(t) - 1:
        break
    dz = pos[i1, 2] - pos[i0, 2]
    dx = pos[i1, 0] - pos[i0, 0]
    standing = [k for k in range(8) if (feet[i0:i1 + 1, k, 1] < 3).all()]
    slide = np.mean([feet[i1, k, 2] - feet[i0, k, 2] for k in standing]) if standing else 0
    zmin = pos[i0:i1 + 1, 2].min() - pos[i0, 2]
    tot.append(dz)
    print('slot %2d %.2f s: dz %+6.1f dx %+5.1f (min %+5.1f) stance feet %s slide %+5.1f mm'
          % (s, t[i0], dz, dx, zmin, ''.join('ABCDEFGH'[k] for k in standing), slide))
tot = np.array(tot)
print('mean per slot %.2f mm, per cycle %.1f mm' % (tot.mean(), 4 * tot.mean()))

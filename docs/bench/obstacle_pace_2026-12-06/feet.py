#!/usr/bin/python3
"""Where each foot stands and what it carries: usage feet.py RUN.h5 T [T ...]
Per time: the support's x, height, pitch (deg, nose up > 0) and, per leg A..H, the foot's x and
height (world = terrain frame, mm; the step spans x 240..460, 40 mm high) and the terrain's
vertical force on it (N) (reporting tool for the robustness failures, not used by any code)."""
import sys
import h5py
import numpy as np
f = h5py.File(sys.argv[1], 'r')
t = f['time'][:]
pos = f['support/position'][:]
q = f['support/orientation'][:]
ff = f['contact/foot_force'][:]
feet = np.stack([f['legs/' + L + '/centerline'][:, -1, :] for L in 'ABCDEFGH'], axis=1)
for tt in map(float, sys.argv[2:]):
    i = int(np.argmin(abs(t - tt)))
    w, x, y, z = q[i]
    pitch = np.degrees(np.arcsin(np.clip(2 * (w * z + x * y), -1, 1)))
    print('%.2f s: support x %.1f h %.1f pitch %+.1f' % (t[i], pos[i, 0], pos[i, 1], pitch))
    for k, L in enumerate('ABCDEFGH'):
        print('   %s foot x %6.1f y %5.1f  Fy %5.2f N' % (L, feet[i, k, 0], feet[i, k, 1], ff[i, k, 1]))

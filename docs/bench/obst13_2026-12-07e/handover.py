#!/usr/bin/python3
"""The hand-over to the lateral crawl: each foot's mean force (x, y, z; N) and its position
relative to the support's centre (x, z; mm) over run times T0..T1, and its moment about the
vertical (y) axis, (dz Fx - dx Fz) (N mm; positive turns +x towards -z), with the support's yaw
change over the window. usage: handover.py T0 T1 RUN.h5..."""
import sys

import h5py
import numpy as np

t0, t1 = float(sys.argv[1]), float(sys.argv[2])
for fn in sys.argv[3:]:
    with h5py.File(fn, "r") as f:
        t = f["time"][:]
        i = (t >= t0) & (t <= t1)
        F = f["contact/foot_force"][i]
        c = f["support/corners"][i].mean(axis=1)  # the support box's centre
        q = f["support/orientation"][i]
        feet = np.stack([f["legs/%s/centerline" % L][:, -1, :][i] for L in "ABCDEFGH"], axis=1)
    yaw = np.degrees(np.arctan2(-(2 * (q[:, 1] * q[:, 3] - q[:, 0] * q[:, 2])),
                                1 - 2 * (q[:, 2] ** 2 + q[:, 3] ** 2)))
    print("%s  %.2f-%.2f s: yaw %+.2f -> %+.2f deg" % (fn.split("/")[-1], t0, t1, yaw[0], yaw[-1]))
    tot = 0
    for k, L in enumerate("ABCDEFGH"):
        dx = feet[:, k, 0] - c[:, 0]
        dz = feet[:, k, 2] - c[:, 2]
        m = np.mean(dz * F[:, k, 0] - dx * F[:, k, 2])
        tot += m
        print("  %s  F (%+.3f %+.3f %+.3f)  at (%+6.1f, %+6.1f)  moment %+7.2f" % (
            L, *F[:, k].mean(axis=0), dx.mean(), dz.mean(), m))
    print("  total %+.2f N mm" % tot)

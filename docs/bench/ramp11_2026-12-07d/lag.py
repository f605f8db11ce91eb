#!/usr/bin/python3
"""The support's x against the table's clock: RUN.h5 (under a gate) beside REF.h5 (a run whose
gate never held: its time is its table time), at the table times T0..T1 step DT.
The table time of a gated run is rebuilt from the run file's gate/waits (T, wait): gate k
freezes the clock at T_k from run time T_k + (waits before k) for its wait.
usage: /usr/bin/python3 lag.py RUN.h5 REF.h5 T0 T1 [DT]  (s; DT default 0.2)"""
import sys

import h5py
import numpy as np


def table_time(f):
    t = f["time"][:]
    w = f["gate/waits"][:] if "gate/waits" in f else np.zeros((0, 2))
    tau = t.copy()
    held = 0.0
    for T, wait in w:
        if not wait > 0:
            continue
        start = T + held  # run time the clock reaches T
        tau = np.where(t >= start + wait, tau - wait, np.where(t > start, T, tau))
        held += wait
    return t, tau


def tilt(q):
    return np.degrees(np.arccos(np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2), -1, 1)))


run, ref, t0, t1 = sys.argv[1], sys.argv[2], float(sys.argv[3]), float(sys.argv[4])
dt = float(sys.argv[5]) if len(sys.argv) > 5 else 0.2
with h5py.File(run, "r") as f, h5py.File(ref, "r") as g:
    t, tau = table_time(f)
    x = f["support/position"][:, 0]
    th = tilt(f["support/orientation"][:])
    tr = g["time"][:]
    xr = g["support/position"][:, 0]
    print(" table s | run s  | x run  x ref  lag (mm) | tilt")
    for tt in np.arange(t0, t1 + 1e-9, dt):
        i = np.nonzero(tau >= tt - 1e-9)[0]
        if not len(i):
            break
        i = i[0]
        print("%7.2f  | %6.2f | %6.1f %6.1f %6.1f | %4.1f" % (tt, t[i], x[i], np.interp(tt, tr, xr),
                                                      np.interp(tt, tr, xr) - x[i], th[i]))

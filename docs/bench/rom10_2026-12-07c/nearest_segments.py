#!/usr/bin/python3
"""nearest_segments.py: for each held-out ray's segment, the training segment load nearest to it
(any training ray, any segment, any quarter turn of the whole ray: rom_basis.py --turns trains
on those), max over the four chambers of |p_train - p_held| (MPa, at t = 1: the rays are
proportional, so a segment pattern that is a multiple of another is compared at its scale
too: the smallest max-difference over the scale s in [0, 1] of the training ray's t).
Usage: nearest_segments.py SNAPDIR [--drop-prefix SQ]"""
import glob
import os
import sys

import h5py
import numpy as np

snap = sys.argv[1]
drop = sys.argv[3] if len(sys.argv) > 3 and sys.argv[2] == "--drop-prefix" else None
train, test = [], []
for p in sorted(glob.glob(os.path.join(snap, "*.h5"))):
    if os.path.basename(p) == "mesh.h5":
        continue
    with h5py.File(p, "r") as f:
        kind = f.attrs["kind"]
        kind = kind.decode() if isinstance(kind, bytes) else str(kind)
        name = os.path.basename(p)[:-3]
        pe = f["pressure_end"][...]
        g, F = f["gravity_end"][...], f["tip_force_end"][...]
    if drop and name.startswith(drop):
        continue
    (train if kind == "train" else test).append((name, pe, g, F))
# a quarter turn (x, y) -> (-y, x) carries chamber Ω1 (+,+) to Ω4's place (-,+): p'[j] = p[(j+1)%4]
turns = [np.roll(np.eye(4), -k, axis=1) for k in range(4)]
scales = np.linspace(0.0, 1.0, 401)
for name, pe, g, F in test:
    for s in range(3):
        best = (np.inf, None)
        for tn, tp, tg, tF in train:
            for k, R in enumerate(turns):
                for s2 in range(3):
                    q = R @ tp[s2]
                    d = np.abs(scales[:, None] * q[None, :] - pe[s][None, :]).max(axis=1)
                    i = int(np.argmin(d))
                    if d[i] < best[0]:
                        best = (d[i], f"{tn} II{s2 + 1} turn {k} at t {scales[i]:.3f}")
        print(f"{name:8s} II{s + 1} {np.array2string(pe[s], precision=3)}: nearest {best[0]:.3f} MPa "
              f"({best[1]})")

#!/usr/bin/python3
"""make_synthetic_h5.py: write small synthetic `run` / `bend` files (DESIGN.md output contract)
for testing tools/plot_track.py and tools/plot_bend.py. Not physics: shapes and units only.

  make_synthetic_h5.py run  OUT.h5 [--n N] [--k K] [--drop /dataset] [--short /dataset]
  make_synthetic_h5.py bend OUT.h5 [--model NAME] [--m M] [--until P] [--scale S] [--drop /dataset]
"""

import argparse
import sys

import h5py
import numpy as np

LEGS = "ABCDEFGH"


def write_run(path, n, k, drop, short):
    t = np.linspace(0.0, 9.0, n)
    # support: still for 1 s, then 39 mm/s with a small step ripple; slight bobbing and attitude
    x = 39.0 * np.clip(t - 1.0, 0.0, 8.0) + 3.0 * np.sin(2 * np.pi * t) * (t > 1)
    y = 2.0 * np.sin(2 * np.pi * t)
    z = 0.5 * np.sin(np.pi * t)
    pos = np.stack([x, y, z], axis=1)
    pitch = np.radians(1.5 * np.sin(2 * np.pi * t))  # about z
    roll = np.radians(0.8 * np.sin(np.pi * t))  # about x
    # q = qz(pitch) * qx(roll), (w, x, y, z)
    cp, sp, cr, sr = np.cos(pitch / 2), np.sin(pitch / 2), np.cos(roll / 2), np.sin(roll / 2)
    quat = np.stack([cp * cr, cp * sr, sp * sr, sp * cr], axis=1)
    pressure = np.zeros((n, 96))
    hip_y = 176.0  # support centre height in the world; legs 166 mm long, feet at y ~ 0..10
    with h5py.File(path, "w") as f:
        f["/time"] = t
        f["/support/position"] = pos
        f["/support/orientation"] = quat
        f["/pressure"] = pressure
        s = np.linspace(0.0, 1.0, k)
        for j, leg in enumerate(LEGS):
            row = j // 4
            hx = 75.0 - 50.0 * (j % 4)
            hz = 65.0 if row == 0 else -65.0
            group_acfh = leg in "ACFH"
            phase = 0.0 if group_acfh else 1.0
            # swing: the foot rises and reaches 39 mm forward of the hip in each inflation second
            u = ((t - phase) % 2.0) / 1.0
            swing = (u < 1.0) & (t >= phase) & (t < 8.0)
            reach = np.where(swing, 39.0 * np.sin(0.5 * np.pi * u), 0.0)
            lift = np.where(swing, 10.0 * np.sin(np.pi * u), 0.0)
            cl = np.empty((n, k, 3))
            for i in range(n):
                hip = np.array([x[i] + hx, y[i] + hip_y, z[i] + hz])
                foot = np.array([hip[0] + reach[i], lift[i], hip[2]])
                mid = 0.5 * (hip + foot) + np.array([-25.0 * reach[i] / 39.0, 0.0, 0.0])
                pts = ((1 - s) ** 2)[:, None] * hip + (2 * (1 - s) * s)[:, None] * mid + (s ** 2)[:, None] * foot
                cl[i] = pts
            f[f"/legs/{leg}/centerline"] = cl
        f.attrs["scene"] = "flat-road"
        f.attrs["leg model"] = "cosserat"
        f.attrs["gait file"] = "gaits/flat_road.csv"
        f.attrs["units"] = "mm, s, MPa"
        f.attrs["wall time"] = 12.5
        f.attrs["version"] = "synthetic"
        for d in drop:
            del f[d]
        for d in short:  # one sample fewer, as a run stopped mid-sample leaves it
            a = f[d][()]
            del f[d]
            f[d] = a[:-1]


def write_bend(path, model, m, until, drop, scale):
    p = np.linspace(0.0, 0.45, m)
    seg = np.stack([scale * w * 360.0 / 3 * (p / 0.403) ** 1.3 for w in (0.95, 1.0, 1.05)], axis=1)
    total = seg.sum(axis=1)
    tip = np.stack([50 * np.sin(np.radians(total)), 162 * np.cos(np.radians(total / 2)), 0 * p], axis=1)
    with h5py.File(path, "w") as f:
        f["/pressure"] = p
        f["/angle_deg"] = seg
        f["/angle_total_deg"] = total
        f["/tip_position"] = tip
        f.attrs["model"] = model
        f.attrs["actuator"] = "baseline"
        f.attrs["mesh size"] = 4.0
        if until is not None:
            f.attrs["p_until_angle_MPa"] = until
        for d in drop:
            del f[d]


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("kind", choices=["run", "bend"])
    ap.add_argument("out")
    ap.add_argument("--n", type=int, default=37)
    ap.add_argument("--k", type=int, default=7)
    ap.add_argument("--m", type=int, default=19)
    ap.add_argument("--model", default="fem")
    ap.add_argument("--until", type=float, default=None)
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--drop", action="append", default=[])
    ap.add_argument("--short", action="append", default=[])
    a = ap.parse_args()
    if a.kind == "run":
        write_run(a.out, a.n, a.k, a.drop, a.short)
    else:
        write_bend(a.out, a.model, a.m, a.until, a.drop, a.scale)
    return 0


if __name__ == "__main__":
    sys.exit(main())

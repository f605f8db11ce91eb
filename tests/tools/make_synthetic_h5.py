#!/usr/bin/python3
"""make_synthetic_h5.py: write small synthetic `run` / `bend` files (docs/design.md output contract)
for testing tools/plot_track.py and tools/plot_bend.py. Not physics: shapes and units only.

  make_synthetic_h5.py run  OUT.h5 [--n N] [--k K] [--drop /dataset] [--short /dataset]
  make_synthetic_h5.py bend OUT.h5 [--model NAME] [--m M] [--until P] [--scale S] [--drop /dataset]
  make_synthetic_h5.py caltable OUT.h5 [--drop /dataset]   (an FE mode calibration table)
  make_synthetic_h5.py calpred OUT.h5                      (its model's predictions file)
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


# the calibration's cases (fem/fem_calibration.c): name, kind, chamber ratios, end pressure, probes
CAL_CASES = [
    ("O12", "mode", (1, 1, 0, 0), 0.5, True), ("O1", "mode", (1, 0, 0, 0), 0.5, False),
    ("O124", "mode", (1, 1, 0, 1), 0.5, False), ("O1234", "mode", (1, 1, 1, 1), 0.5, True),
    ("O13", "mode", (1, 0, 1, 0), 0.5, False), ("O12r05", "mode", (1, 0.5, 0, 0), 0.5, False),
    ("O12O34r3", "mode", (1, 1, 1 / 3, 1 / 3), 0.5, False), ("O1O234r05", "mode", (1, 0.5, 0.5, 0.5), 0.5, False),
    ("O1O234r075", "mode", (1, 0.75, 0.75, 0.75), 0.5, False),
    ("O124O3r05", "mode", (1, 1, 0.5, 1), 0.5, False), ("O1O23r05O4r025", "mode", (1, 0.5, 0.5, 0.25), 0.5, False),
    ("O1O3r05", "mode", (1, 0, 0.5, 0), 0.5, False),
    ("O2", "symmetry", (0, 1, 0, 0), 0.5, False),
    ("H1", "holdout", (1, 1 / 3, 0, 0), 0.3, False), ("H2", "holdout", (1, 1, 0.5, 0), 0.2, False),
    ("H3", "holdout", (1, 5 / 7, 5 / 7, 5 / 7), 0.35, False), ("H4", "holdout", (1, 0.75, 0.375, 0.75), 0.4, False),
    ("H5", "holdout", (1, 0.6, 0.3, 0.3), 0.4, False), ("H6", "holdout", (1, 0.8, 0.6, 0.4), 0.4, False),
    ("H7", "holdout", (1, 0.3, 0.7, 0.2), 0.4, False), ("H8", "holdout", (1, 1 / 3, 0, 0), 0.4, False),
    ("G", "gravity", (0, 0, 0, 0), 0.025, False),
]


def cal_rows(ratio, pmax, scale):
    """Rows of a superposed single-chamber response: bend [M,3,2] rad, stretch [M,3], tip [M,3]."""
    p = np.arange(0.0, pmax + 1e-9, 0.025)
    r = np.asarray(ratio, dtype=float)
    g1, g2 = 1.2 * scale * (r[0] - r[2]) * p, 1.2 * scale * (r[1] - r[3]) * p
    b = np.stack([-(g1 + g2), -(g1 - g2)], axis=1) / np.sqrt(2.0)
    bend = np.repeat(b[:, None, :], 3, axis=1)
    stretch = 1 + 0.02 * r.sum() * np.repeat(p[:, None], 3, axis=1)
    th = np.hypot(b[:, 0], b[:, 1]) * 3
    tip = np.stack([-60 * np.sin(th), 0 * p, 166 * np.cos(th / 2)], axis=1)
    return p, bend, stretch, tip


def write_caltable(path, drop):
    with h5py.File(path, "w") as f:
        f.attrs["format"] = "crawlsim-fe-calibration 1"
        f.attrs["actuator"] = "leg"
        f.attrs["a"] = 7.5
        for name, kind, ratio, pmax, probes in CAL_CASES:
            p, bend, stretch, tip = cal_rows(ratio, pmax, 1.0)
            g = f.create_group(f"/cases/{name}")
            g.attrs["kind"] = kind
            for j in range(4):
                g.attrs[f"ratio{j + 1}"] = float(ratio[j])
            g["pressure"], g["bend"], g["stretch"], g["tip"] = p, bend, stretch, tip
            g["radial_max"] = 0.3 * (stretch - 1)
            if probes:
                pp = np.array([0.0, 0.1, 0.2, 0.3])
                pbar = pp * np.mean(ratio)
                g["probe_pressure"] = pp
                g["EI"] = np.repeat((3000 * (1 + pbar))[:, None, None], 3, 1).repeat(2, 2)
                g["EA"] = np.repeat((200 * (1 + 2 * pbar))[:, None], 3, 1)
        for d in drop:
            del f[d]


def write_calpred(path):
    with h5py.File(path, "w") as f:
        f.attrs["model"] = "FE mode table (synthetic)"
        f.attrs["EI_8C10I_Nmm2"] = 2810.0
        f.attrs["EA_8C10A_N"] = 150.7
        for name, kind, ratio, pmax, _ in CAL_CASES:
            if kind == "gravity":
                continue
            p, bend, stretch, tip = cal_rows(ratio, pmax, 1.02)
            g = f.create_group(f"/cases/{name}")
            g.attrs["kind"] = kind
            g["pressure"], g["bend"], g["stretch"], g["tip"] = p, bend, stretch, tip
            g["radius"] = 7.5 + 0.3 * (stretch - 1)
        for s in range(3):
            x = np.array([0.0, 0.05, 0.1, 0.15, 0.2, 0.3])
            f[f"/stiffness/II{s + 1}/EI_pbar"] = x
            f[f"/stiffness/II{s + 1}/EI"] = 3000 * (1 + x)
            f[f"/stiffness/II{s + 1}/EA_pbar"] = x
            f[f"/stiffness/II{s + 1}/EA"] = 200 * (1 + 2 * x)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("kind", choices=["run", "bend", "caltable", "calpred"])
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
    elif a.kind == "caltable":
        write_caltable(a.out, a.drop)
    elif a.kind == "calpred":
        write_calpred(a.out)
    else:
        write_bend(a.out, a.model, a.m, a.until, a.drop, a.scale)
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""Per-foot stance and swing analysis of `crawlsim run` files (README, flat road, finding 5).

usage: /usr/bin/python3 tools/stance_slip.py RUN.h5 [RUN2.h5 ...] [--first 2.5] [--strides 6]
                                             [--period 1] [--window 0.45,0.65] [--per-foot]

The stance windows are those of gaits/flat_road.gait: the two groups ACFH and BDEG alternate,
each stance lasting one period; BDEG's stances start at --first + 2k periods, ACFH's at
--first + (2k + 1) periods (defaults: 2.5 s, i.e. the strides from 2.5 s to 8.5 s, after the
start). Every quantity is read from /legs/<L>/centerline (hip = first point, foot = last point,
world mm; the road's top is y = 0) and /support/position. Per file and per group of legs
(front ABEF, hips at x = 175 and 225 mm; rear CDGH), averaged over the stances:
  slip      the foot's displacement along x over its stance (mm; negative = backwards)
  mid slip  the part of it inside the mid-stride window [a + w0, a + w1] of each stance starting
            at a (default 0.45..0.65 s: the gait's legs pass their hips there)
  stroke    the change of (hip x - foot x) over the stance: how far the leg moved its hip over
            its foot (mm); hip = how far the hip moved (the support's advance)
  clear     the stance sole's largest clearance inside the window (mm: its lowest edge above
            the road; the sole, half side 7.5 mm, is normal to the tip's tangent); off = how
            long (s) inside the window it is above 0.02 mm, i.e. unloaded (the rod's foundation
            sinks a loaded sole by micrometres; ODE's contacts by about as little)
  swing     the smallest clearance of the other group's (swinging) soles inside the window
Then the support's highest point in the window and its height a quarter period into each
stance (mm).
"""
import argparse
import sys

import h5py
import numpy as np

LEGS = "ABCDEFGH"
GROUP_B, GROUP_A = "BDEG", "ACFH"  # BDEG stands first from --first, ACFH one period later
FRONT, REAR = "ABEF", "CDGH"
SOLE_A = 7.5  # mm: the sole's half side (robot_actuator.c a; the rod's foot block)
UNLOADED = 0.02  # mm: a sole this far above the road carries nothing (loads sink it < 0.01 mm)


def clearance(c):
    """Height (mm) of the lowest edge of the sole above the road (y = 0) at every sample, from a
    centreline c [N, K, 3]: the sole (half side SOLE_A) is centred at the tip, normal to the
    tip's tangent, so a tilt lowers one edge by SOLE_A times the tangent's horizontal part.
    On the rod's foundation (225 N/mm for the whole sole) any load sinks it by micrometres: a
    clearance above ~0.01 mm is an unloaded foot."""
    tip = c[:, -1, :]
    tan = tip - c[:, -2, :]
    tan /= np.linalg.norm(tan, axis=1)[:, None]
    return tip[:, 1] - SOLE_A * np.hypot(tan[:, 0], tan[:, 2])


def at(t, s):
    return int(np.argmin(np.abs(t - s)))


def analyse(path, first, strides, period, w0, w1):
    with h5py.File(path, "r") as f:
        t = f["time"][:]
        sup = f["support/position"][:]
        cl = {L: f["legs/%s/centerline" % L][:] for L in LEGS}
        model = f.attrs.get("leg_model", b"?")
        model = model.decode() if isinstance(model, bytes) else str(model)
    rows = {}
    feet = []  # per foot and stride: (leg, stance start, role, values)
    windows = []
    for k in range(strides):
        a = first + k * period
        stand = GROUP_B if k % 2 == 0 else GROUP_A
        swing = GROUP_A if stand == GROUP_B else GROUP_B
        windows.append((a, stand, swing))
    for name, legs in (("front ABEF", FRONT), ("rear CDGH", REAR)):
        acc = {"slip": [], "mid": [], "stroke": [], "hip": [], "clear": [], "off": []}
        for a, stand, _ in windows:
            i, j = at(t, a), at(t, a + period)
            m0, m1 = at(t, a + w0), at(t, a + w1)
            for L in legs:
                if L not in stand:
                    continue
                fx, hx = cl[L][:, -1, 0], cl[L][:, 0, 0]
                acc["slip"].append(fx[j] - fx[i])
                acc["mid"].append(fx[m1] - fx[m0])
                acc["stroke"].append((hx[j] - fx[j]) - (hx[i] - fx[i]))
                acc["hip"].append(hx[j] - hx[i])
                c = clearance(cl[L][m0:m1 + 1])
                acc["clear"].append(c.max())
                acc["off"].append(np.count_nonzero(c > UNLOADED) / len(c) * (w1 - w0))
                feet.append((L, a, {k: v[-1] for k, v in acc.items()}))
        rows[name] = {k: float(np.mean(v)) for k, v in acc.items()}
    for a, stand, swing in windows:
        m0, m1 = at(t, a + w0), at(t, a + w1)
        for L in swing:
            feet.append((L, a, {"swing": float(clearance(cl[L][m0:m1 + 1]).min())}))
    feet.sort(key=lambda e: (e[0], e[1]))
    swing_min, sup_top, sup_mid = [], [], []
    for a, stand, swing in windows:
        m0, m1 = at(t, a + w0), at(t, a + w1)
        swing_min.append(min(clearance(cl[L][m0:m1 + 1]).min() for L in swing))
        sup_top.append(sup[m0:m1 + 1, 1].max())
        sup_mid.append(sup[at(t, a + 0.25 * period), 1])
    return model, rows, feet, {
        "swing": float(np.mean(swing_min)),
        "sup_top": float(np.mean(sup_top)),
        "sup_mid": float(np.mean(sup_mid)),
        "x_end": float(sup[at(t, first + strides * period), 0] - sup[at(t, first), 0]),
    }


def main(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("runs", nargs="+")
    ap.add_argument("--first", type=float, default=2.5)
    ap.add_argument("--strides", type=int, default=6)
    ap.add_argument("--period", type=float, default=1.0)
    ap.add_argument("--window", default="0.45,0.65")
    ap.add_argument("--per-foot", action="store_true",
                    help="also one line per foot and stride (stance: its values; swing: its "
                    "sole's smallest clearance in the window)")
    args = ap.parse_args(argv)
    w0, w1 = (float(v) for v in args.window.split(","))
    print("%-22s %-5s %-10s %6s %8s %6s %5s %5s %5s %6s %7s %6s" %
          ("run", "legs", "group", "slip", "mid slip", "stroke", "hip", "clear", "off", "swing",
           "sup top", "sup"))
    for p in args.runs:
        try:
            model, rows, feet, w = analyse(p, args.first, args.strides, args.period, w0, w1)
        except (OSError, KeyError) as e:
            print("stance_slip: %s: %s" % (p, e), file=sys.stderr)
            return 1
        for name, r in rows.items():
            print("%-22s %-5s %-10s %6.1f %8.1f %6.1f %5.1f %5.2f %5.2f %6.2f %7.2f %6.2f" %
                  (p.split("/")[-1][:22], model, name, r["slip"], r["mid"], r["stroke"],
                   r["hip"], r["clear"], r["off"], w["swing"], w["sup_top"], w["sup_mid"]))
        print("%-22s support advance over the %d strides: %.1f mm (%.1f mm per stride)" %
              ("", args.strides, w["x_end"], w["x_end"] / args.strides))
        for L, a, v in feet if args.per_foot else ():
            if "slip" in v:
                print("%-22s %-5s %s %4.1f-%4.1f s %6.1f %8.1f %6.1f %5.1f %5.2f %5.2f" %
                      ("", "", L, a, a + args.period, v["slip"], v["mid"], v["stroke"], v["hip"],
                       v["clear"], v["off"]))
            else:
                print("%-22s %-5s %s %4.1f-%4.1f s %s swing %6.2f" %
                      ("", "", L, a, a + args.period, " " * 44, v["swing"]))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

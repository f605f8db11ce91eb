#!/usr/bin/python3
"""check.py: every rule dflt15's brief lists, for the strain level's default step (backward
Euler, adaptive 2.5e-4 mm: tags d_*) and the adaptive BDF2 at 5e-4 mm (b_*), from batch.sh's
run files (no runs); the CPU of each pair beside. Prints one line per rule: the rule, the
default's number, BDF2's, met or missed for each.

Measures: track errors are tools/bench_levels.py's (max over the whole seconds of |(dx, dz)|
of the support, mm), here over a window [T0, T1] of whole seconds both runs reach. Table 3
(the obstacle): ../gate_2026-12-06f/score.py's nodes, end point and depth. Table 2 (the flat
road): x(t) = 39 (t - 1) mm from 2 s. Falls: the run file's status line. CPU: the user s of
/usr/bin/time in logs/TAG.log over the run's simulated s (its last output time; the 0.3 s
settling not counted), the load (1-min average) before; the two runs of a pair ran at the same
time. RUNS: the run files (default /tmp/dflt15/runs), REFS the rod references at 32 elements
(default /tmp/dflt15/refs: bdf13's /tmp/bdf13/runs/rod32_*.h5, made by
../bdf13_2026-12-07e/refs.sh)."""
import math
import os
import re
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
RUNS = os.environ.get("RUNS", "/tmp/dflt15/runs")
REFS = os.environ.get("REFS", "/tmp/dflt15/refs")
T3 = [0, 1, 2, 3, 4, 5, 7, 11, 12, 14, 24, 29, 32]
X3 = [0, 0, 0, 0, 26, 26, 52, 130, 170, 230, 492, 646, 646]
H3 = [0, 50, 50, 13, 22, 48, 20, 50, 40, 40, 13, 0, 0]
Z3 = [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 90, 270]


def path(tag):
    return os.path.join(REFS if tag.startswith("rod32") else RUNS, tag + ".h5")


def done(tag):
    if tag.startswith("rod32"):
        return os.path.exists(path(tag))
    p = os.path.join(HERE, "logs", tag + ".log")
    return os.path.exists(p) and re.search(r"^rc ", open(p).read(), re.M) is not None


def track(tag):
    """time, support position and orientation, the legs' deepest contact, the file's attributes"""
    if not done(tag):
        raise OSError(tag + ": not finished")
    with h5py.File(path(tag), "r") as f:
        out = [f[k][:] for k in ("/time", "/support/position", "/support/orientation")]
        ld = "contact/leg_max_depth"
        out.append(f[ld][:] if ld in f else np.zeros(len(out[0])))
        out.append({k: (v.decode() if isinstance(v, bytes) else v) for k, v in f.attrs.items()})
    return tuple(out)


def err(a, b, t0=1, t1=1e9):
    """max over whole seconds s in [t0, t1] both reach of |(dx, dz)| (mm), and where"""
    try:
        t, p = track(a)[:2]
        tr, pr = track(b)[:2]
    except OSError:
        return float("nan"), 0
    worst, at = float("nan"), 0
    for s in range(max(1, t0), int(math.floor(min(t[-1], tr[-1], t1) + 1e-9)) + 1):
        i, j = int(np.argmin(abs(t - s))), int(np.argmin(abs(tr - s)))
        d = math.hypot(p[i, 0] - pr[j, 0], p[i, 2] - pr[j, 2])
        if not d <= worst:
            worst, at = d, s
    return worst, at


def tilt(q):
    return np.degrees(np.arccos(np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2), -1, 1)))


def fall(tag):
    try:
        st = str(track(tag)[4].get("status", ""))
    except OSError:
        return float("nan")
    m = re.search(r"t = ([\d.]+) s: the support fell", st)
    return float(m.group(1)) if m else float("inf")


def x_at(tag, s):
    t, p = track(tag)[:2]
    return float(np.interp(s, t, p[:, 0])) if t[-1] >= s - 1e-9 else float("nan")


def table2(tag):
    t, p, q = track(tag)[:3]
    devs = [((x_at(tag, k) - 39.0 * (k - 1)) / (39.0 * (k - 1)), k) for k in range(2, 10)]
    w = max(devs, key=lambda v: abs(v[0]) if math.isfinite(v[0]) else 1e9)
    return w, float(np.max(np.abs(p[:, 2]))), float(tilt(q).max())


def table3(tag):
    """worst node from 4 s (mm, where), end point distance, depth max, tilt max, end t, status"""
    t, p, q, ld, at = track(tag)
    worst, where = 0.0, 0
    for k, tn in enumerate(T3):
        if tn < 4 or tn > t[-1] + 1e-9:
            continue
        i = int(np.argmin(abs(t - tn)))
        e = max(abs(p[i, 0] - X3[k]), abs(p[i, 1] - H3[k]), abs(p[i, 2] - Z3[k]))
        if e > worst:
            worst, where = e, tn
    d = math.hypot(p[-1, 0] - 646, p[-1, 2] - 270)
    return worst, where, d, float(ld.max()), float(tilt(q).max()), float(t[-1]), at


def cpu(tag):
    p = os.path.join(HERE, "logs", tag + ".log")
    if not done(tag):
        return float("nan"), "?"
    txt = open(p).read()
    m = re.search(r"([\d.]+) user ([\d.]+) sys", txt)
    ld = re.search(r"load average: ([\d.]+)", txt)
    t = track(tag)[0]
    return (float(m.group(1)) / float(t[-1]) if m else float("nan")), (ld.group(1) if ld else "?")


ROWS = []


def row(rule, dv, bv, dok, bok):
    """a rule's line; a number not there yet (nan, '-': the run not finished) is no verdict"""
    dok = None if "nan" in dv or dv == "-" else dok
    bok = None if "nan" in bv or bv == "-" else bok
    ROWS.append((rule, dv, bv, dok, bok))
    m = lambda ok: "met" if ok else ("MISSED" if ok is not None else "-")  # noqa: E731
    print(f"| {rule} | {dv} | {m(dok)} | {bv} | {m(bok)} |")


def safe(f, *a):
    try:
        return f(*a)
    except (OSError, KeyError, ValueError, IndexError):
        return None


def main():
    print("| rule | default (BE 2.5e-4) | | BDF2 5e-4 | |")
    print("|---|---|---|---|---|")
    # the flat road, designed gait
    v = [err(f"{k}_f_nominal", "rod32_flat")[0] for k in ("d", "b")]
    row("flat road vs rod 32 / 0.25 ms, whole s (<= 3 mm)", f"{v[0]:.2f} mm", f"{v[1]:.2f} mm",
        v[0] <= 3, v[1] <= 3)
    r = [safe(table2, f"{k}_f_nominal") for k in ("d", "b")]
    f2 = lambda r: f"{100 * r[0][0]:+.2f} % ({r[0][1]} s), |z| {r[1]:.2f}, tilt {r[2]:.2f}"  # noqa
    ok2 = lambda r: abs(r[0][0]) <= 0.05 and r[1] <= 5 and r[2] <= 3  # noqa: E731
    row("flat road: Table 2 from 2 s within 5 %, |z| <= 5 mm, tilt <= 3 deg",
        f2(r[0]) if r[0] else "-", f2(r[1]) if r[1] else "-",
        ok2(r[0]) if r[0] else None, ok2(r[1]) if r[1] else None)
    v = [err(f"{k}_f_nominal", f"{k}_f_half") for k in ("d", "b")]
    row("flat road vs its half tolerance, whole s (<= 1 mm)", f"{v[0][0]:.2f} mm ({v[0][1]} s)",
        f"{v[1][0]:.2f} mm ({v[1][1]} s)", v[0][0] <= 1, v[1][0] <= 1)
    # the paper's table
    v = [err(f"{k}_paper", "rod32_paper_0125")[0] for k in ("d", "b")]
    w = [err(f"{k}_paper", "rod32_paper")[0] for k in ("d", "b")]
    row("paper's table vs rod 32 / 0.125 ms (<= 3 mm; vs 0.25 ms)", f"{v[0]:.2f} mm ({w[0]:.2f})",
        f"{v[1]:.2f} mm ({w[1]:.2f})", v[0] <= 3, v[1] <= 3)
    v = [err(f"{k}_paper", f"{k}_paper_half") for k in ("d", "b")]
    row("paper's table vs its half tolerance (<= 1 mm)", f"{v[0][0]:.2f} mm ({v[0][1]} s)",
        f"{v[1][0]:.2f} mm ({v[1][1]} s)", v[0][0] <= 1, v[1][0] <= 1)
    fr = fall("rod32_earth")
    v = [fall(f"{k}_p_earth") for k in ("d", "b")]
    row(f"`earth`, paper's table: falls within 0.1 s of the rod's {fr:.4f} s", f"{v[0]:.4f} s",
        f"{v[1]:.4f} s", abs(v[0] - fr) <= 0.1, abs(v[1] - fr) <= 0.1)
    # `earth` on the scenes' own gaits
    r = [(safe(x_at, f"{k}_f_earth", 9), fall(f"{k}_f_earth")) for k in ("d", "b")]
    fe = lambda r: f"x(9) {r[0]:.1f} mm, falls {r[1]:g}" if r[0] is not None else "-"  # noqa
    row("`earth`, flat road (its Earth gait): >= 250 mm in 9 s, no fall", fe(r[0]), fe(r[1]),
        r[0][0] is not None and r[0][0] >= 250 and math.isinf(r[0][1]),
        r[1][0] is not None and r[1][0] >= 250 and math.isinf(r[1][1]))
    v = [fall(f"{k}_o_earth") for k in ("d", "b")]
    row("`earth`, obstacle: falls (the verdict), BDF2 within 0.1 s of the default",
        f"{v[0]:.3f} s", f"{v[1]:.3f} s", None,
        math.isfinite(v[1]) and abs(v[1] - v[0]) <= 0.1)
    # the obstacle
    v = [err(f"{k}_o_nominal", "rod32_obst4", 1, 4)[0] for k in ("d", "b")]
    row("obstacle 0-4 s vs rod 32 (<= 2 mm)", f"{v[0]:.2f} mm", f"{v[1]:.2f} mm", v[0] <= 2,
        v[1] <= 2)
    r = [safe(table3, f"{k}_o_nominal") for k in ("d", "b")]
    f3 = lambda r: (f"worst node {r[0]:.1f} mm ({r[1]} s); end {r[2]:.1f} mm; depth "  # noqa
                    f"{r[3]:.3f} mm; tilt {r[4]:.1f} deg; over at {r[5]:.2f} s")
    ok3 = lambda r: r[0] <= 20 and r[2] <= 20 and r[3] < 1 and r[4] <= 10 and r[5] <= 35  # noqa
    row("obstacle whole climb: nodes from 4 s <= 20 mm, end <= 20 mm, depth < 1 mm, tilt <= 10 "
        "deg, over by 35 s", f3(r[0]) if r[0] else "-", f3(r[1]) if r[1] else "-",
        ok3(r[0]) if r[0] else None, ok3(r[1]) if r[1] else None)
    v = [err(f"{k}_o_nominal", f"{k}_o_half", 1, 5) for k in ("d", "b")]
    row("obstacle vs its half tolerance, 0-5 s (the crawl start; <= 1 mm)",
        f"{v[0][0]:.2f} mm ({v[0][1]} s)", f"{v[1][0]:.2f} mm ({v[1][1]} s)", v[0][0] <= 1,
        v[1][0] <= 1)
    v = [err(f"{k}_o_nominal", f"{k}_o_half") for k in ("d", "b")]
    row("obstacle vs its half tolerance, every whole s of the climb (<= 1 mm)",
        f"{v[0][0]:.2f} mm ({v[0][1]} s)", f"{v[1][0]:.2f} mm ({v[1][1]} s)", v[0][0] <= 1,
        v[1][0] <= 1)
    # the robustness sets
    for n in ("ramp0.1", "ramp0.5", "mu0.6", "mu1.0", "m25g", "m75g", "tau0.5x", "tau2x", "half"):
        v = [safe(x_at, f"{k}_f_{n}", 9) for k in ("d", "b")]
        fx = lambda x: f"{x:.1f} mm ({100 * (x - 312) / 312:+.1f} %)" if x is not None else "-"  # noqa
        okx = lambda x: abs(x - 312) <= 31.2 if x is not None else None  # noqa: E731
        row(f"flat robustness {n if n != 'half' else 'step tolerance halved'}: x(9) within 10 % "
            "of 312 mm", fx(v[0]), fx(v[1]), okx(v[0]), okx(v[1]))
    v = [safe(x_at, f"{k}_f_mu0", 9) for k in ("d", "b")]
    row("friction 0: no progress (|x(9)| < 39 mm)", f"{v[0]:.1f} mm" if v[0] is not None else "-",
        f"{v[1]:.1f} mm" if v[1] is not None else "-",
        abs(v[0]) < 39 if v[0] is not None else None, abs(v[1]) < 39 if v[1] is not None else None)
    for n in ("ramp0.1", "ramp0.5", "mu0.6", "mu1.0", "m25g", "m75g", "tau0.5x", "tau2x", "half"):
        r = [safe(table3, f"{k}_o_{n}") for k in ("d", "b")]
        fo = lambda r: f"{r[2]:.1f} mm (over at {r[5]:.2f} s)" if r else "-"  # noqa: E731
        row(f"obstacle robustness {n if n != 'half' else 'step tolerance halved'}: end within "
            "40 mm of Table 3's", fo(r[0]), fo(r[1]), r[0][2] <= 40 if r[0] else None,
            r[1][2] <= 40 if r[1] else None)
    print()
    print("| case | default: CPU s per simulated s (load before) | BDF2 | BDF2 / default |")
    print("|---|---|---|---|")
    rat = []
    for lg in sorted(f[2:-4] for f in os.listdir(os.path.join(HERE, "logs"))
                     if f.startswith("d_") and f.endswith(".log")):
        a, b = cpu("d_" + lg), cpu("b_" + lg)
        r = b[0] / a[0]
        if math.isfinite(r):
            rat.append(r)
        print(f"| {lg} | {a[0]:.3f} ({a[1]}) | {b[0]:.3f} ({b[1]}) | {r:.3f} |")
    if rat:
        print(f"\nBDF2 / default CPU: median {np.median(rat):.3f}, range {min(rat):.3f}-"
              f"{max(rat):.3f} over {len(rat)} pairs")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""check.py [STEP...]: every rule of issues 32 and 33 that the flat road's step touches, for the
fixed backward-Euler steps STEP (default 0.005) of strain.sh, from the run files (no runs).

Errors are tools/bench_levels.py's measure (max over the whole seconds both runs reach of
|(dx, dz)| of the support, mm). Table 2: x at t = 39 (t - 1) mm, every whole second from 2 s
within 5 %; |z| <= 5 mm and tilt <= 3 deg over every output sample; the robustness set within
10 % of 312 mm at 9 s; friction 0: no progress (|x(9)| below one stride, 39 mm). The fall time
under `earth` is the run's status line. RUNS: the run files (default /tmp/speed10/runs)."""
import math
import os
import re
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))
import bench_levels as bl  # noqa: E402

RUNS = os.environ.get("RUNS", "/tmp/speed10/runs")


def R(tag):
    return os.path.join(RUNS, tag + ".h5")


def done(tag):
    """the run has finished (crun.sh wrote its rc line): a file being written is no result"""
    p = os.path.join(HERE, "logs", tag + ".log")
    return os.path.exists(p) and re.search(r"^rc ", open(p).read(), re.M) is not None


def err(a, b):
    if not (done(a) and done(b)):
        return float("nan")
    try:
        return bl.track_error({"h5": R(a)}, {"h5": R(b)})
    except (OSError, KeyError, IndexError):
        return float("nan")  # not run (yet)


def track(tag):
    if not done(tag):
        raise OSError(tag + ": not finished")
    with h5py.File(R(tag), "r") as f:
        t = f["/time"][:]
        p = f["/support/position"][:]
        q = f["/support/orientation"][:]
        st = f.attrs.get("status", b"?")
        cpu = {k: f.attrs.get(k) for k in ("steps", "rejected_steps", "real_time_factor")}
    st = st.decode() if isinstance(st, bytes) else str(st)
    return t, p, q, st, cpu


def table2(tag):
    """x at 2..9 s, the worst relative deviation from Table 2 from 2 s, max |z|, max tilt"""
    t, p, q, st, _ = track(tag)
    xs = {k: float(np.interp(k, t, p[:, 0])) for k in range(1, 10) if t[-1] >= k - 1e-9}
    devs = [((xs[k] - 39.0 * (k - 1)) / (39.0 * (k - 1)), k) for k in range(2, 10) if k in xs]
    worst = max(devs, key=lambda v: abs(v[0])) if devs else (float("nan"), 0)
    tilt = float(np.degrees(np.max(np.arccos(np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2),
                                                      -1, 1)))))
    return xs, worst, float(np.max(np.abs(p[:, 2]))), tilt, st


def fall(tag):
    try:
        st = track(tag)[3]
    except (OSError, KeyError):
        return float("nan")
    m = re.search(r"t = ([\d.]+) s: the support fell", st)
    return float(m.group(1)) if m else float("inf")


def cpu_of(tag):
    """user CPU s (crun.sh's /usr/bin/time line) and the load before the run"""
    p = os.path.join(HERE, "logs", tag + ".log")
    if not os.path.exists(p):
        return float("nan"), "?"
    txt = open(p).read()
    m = re.search(r"([\d.]+) user ([\d.]+) sys", txt)
    ld = re.search(r"load average: ([\d.]+)", txt)
    return (float(m.group(1)) if m else float("nan")), (ld.group(1) if ld else "?")


def main(steps):
    ok_all = True

    def rule(name, value, ok):
        nonlocal ok_all
        ok_all &= bool(ok)
        print(f"  {'MET ' if ok else 'MISS'} {name}: {value}")

    for H in steps:
        f = lambda n: f"f{H}_{n}"  # noqa: E731
        print(f"# fixed {H} s backward Euler (flat road, strain legs, scene defaults)")
        e = err(f("flat"), "rod32_flat")
        rule("designed gait vs rod 32 / 0.25 ms (<= 3 mm)", f"{e:.3f} mm", e <= 3)
        e = err(f("flat"), f"h{H}_flat")
        rule("designed gait vs its half step (<= 1 mm)", f"{e:.3f} mm", e <= 1)
        for ref in ("rod32_paper", "rod32_paper_0125"):
            e = err(f("paper"), ref)
            rule(f"paper's table vs {ref} (<= 3 mm)", f"{e:.3f} mm", e <= 3)
        e = err(f("paper"), f"h{H}_paper")
        rule("paper's table vs its half step (<= 1 mm)", f"{e:.3f} mm", e <= 1)
        a, b = fall(f("earth")), fall("rod32_earth")
        rule("earth, paper's table: falls within 0.1 s of the rod", f"{a:.4f} s vs rod {b:.4f} s "
             f"({abs(a - b):.4f} s)", math.isfinite(a) and abs(a - b) <= 0.1)
        try:
            xs, (w, k), z, tilt, st = table2(f("flat"))
            rule("Table 2 from 2 s (within 5 %)", " ".join(f"{xs[s]:.2f}" for s in sorted(xs))
                 + f" | worst {100 * w:+.2f} % at {k} s", abs(w) <= 0.05)
            rule("|z| <= 5 mm", f"{z:.2f} mm", z <= 5)
            rule("tilt <= 3 deg", f"{tilt:.2f} deg", tilt <= 3)
        except (OSError, KeyError):
            rule("Table 2", "not run", False)
        for n in ("ramp0.1", "ramp0.5", "mu0.6", "mu1.0", "m25g", "m75g", "tau0.5x", "tau2x"):
            try:
                xs, _, _, _, st = table2(f(n))
                x9 = xs.get(9, float("nan"))
                rule(f"robust {n}: x(9) within 10 % of 312 mm", f"{x9:.1f} mm "
                     f"({100 * (x9 - 312) / 312:+.1f} %)", abs(x9 - 312) <= 31.2)
            except (OSError, KeyError):
                rule(f"robust {n}", "not run", False)
        xs, _, _, _, _ = table2(f"h{H}_flat") if done(f"h{H}_flat") else ({}, 0, 0, 0, 0)
        x9 = xs.get(9, float("nan"))
        rule("robust: the step halved: x(9) within 10 % of 312 mm",
             f"{x9:.1f} mm ({100 * (x9 - 312) / 312:+.1f} %)", abs(x9 - 312) <= 31.2)
        try:
            xs, _, _, _, _ = table2(f("mu0"))
            x9 = xs.get(9, float("nan"))
            rule("friction 0: no progress (|x(9)| < 39 mm)", f"{x9:.1f} mm", abs(x9) < 39)
        except (OSError, KeyError):
            rule("friction 0", "not run", False)
        print(f"# cost (user CPU s of the run / simulated s, load before; rough, shared machine)")
        for tag, ts in ((f("flat"), 9.5 + 0.3), ("def_flat", 9.8), (f("paper"), 9.3),
                        ("def_paper", 9.3)):
            c, ld = cpu_of(tag)
            print(f"  {tag}: {c:.2f} CPU s, {c / ts:.3f} CPU s per simulated s (load {ld})")
    print("# the old default (adaptive 2.5e-4 mm) on the same runs")
    print(f"  def_flat vs rod32_flat {err('def_flat', 'rod32_flat'):.3f} mm; def_paper vs "
          f"rod32_paper / 0125 {err('def_paper', 'rod32_paper'):.3f} / "
          f"{err('def_paper', 'rod32_paper_0125'):.3f} mm; def_earth falls {fall('def_earth'):.4f} s")
    print(f"  rod32_paper vs rod32_paper_0125 {err('rod32_paper', 'rod32_paper_0125'):.3f} mm")
    print("ALL MET" if ok_all else "NOT ALL MET")


if __name__ == "__main__":
    main(sys.argv[1:] or ["0.005"])

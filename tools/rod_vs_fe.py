#!/usr/bin/python3
"""The rod level against the FE on cases the calibration never fitted (issue 9).

usage: /usr/bin/python3 tools/rod_vs_fe.py TABLE.h5 [--cases H1,H4,O2] [--extra CASE.h5]...
           [--loaded FE.h5] [--tip-load FX,FY,FZ] [--chambers 1,2] [--crawlsim build/tools/crawlsim]
           [--limit-pct 2] [--from-p 0] [--png rod_vs_fe.png]

TABLE.h5 is an FE mode table (`crawlsim calibrate`, format "crawlsim-fe-calibration 1"). For
every case of kind holdout or symmetry in it (or the --cases named), the rod's static bend curve
is computed with that table as its calibration (--extra CASE.h5: the held-out cases of a case
file of `crawlsim calibrate` that is not merged into the table, e.g. one run later) (`crawlsim bend --model rod --calibration TABLE
--pressures r1,r2,r3,r4` at the case's rows), and its tip is compared with the FE's tip at
every FE row: max |tip_rod - tip_FE| in mm and in % of the unloaded leg's length (the tip
distance at p = 0 of the table's first case that is not loaded by gravity). --loaded FE.h5 adds a case under a dead tip load: an FE bend file (`crawlsim
bend --model fe --chambers C --tip-load F`), compared with the rod under the same --chambers
and --tip-load (the FE file does not record them: give the ones it was run with); --from-p P
compares its rows from P on (FE bend files written before 2026-12-02 record the unloaded
reference state as the p = 0 row of a loaded run: the dead load was first applied with the
first pressure step).
Prints a Markdown table (one row per case) and, with --png, draws the tip error against
pressure for every case with the --limit-pct line. A bad file, a missing dataset or a failing
rod run is a one-line error and exit status 1.
"""
import argparse
import os
import subprocess
import sys
import tempfile

PROG = "rod_vs_fe.py"
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)


def fail(msg):
    print(f"{PROG}: {msg}", file=sys.stderr)
    sys.exit(1)


try:
    import h5py
    import numpy as np
except ImportError as e:  # pragma: no cover - the install script provides both
    fail(f"needs h5py and numpy ({e}); run tools/install-deps.sh")


def read(f, path, name):
    if path not in f:
        fail(f"{name}: missing dataset {path}")
    return f[path][()]


def open_h5(name):
    if not os.path.exists(name):
        fail(f"{name}: no such file")
    try:
        return h5py.File(name, "r")
    except OSError:
        fail(f"{name}: not a readable HDF5 file")


def rod_curve(exe, table, pressures, p_max, p_step, extra, work):
    """Tip positions [M, 3] and pressures [M] of the rod's bend curve."""
    out = os.path.join(work, "rod.h5")
    cmd = [exe, "bend", "--model", "rod", "--actuator", "leg", "--chambers", "1,2,3,4",
           "--pressures", ",".join(f"{r:.17g}" for r in pressures), "--p-max", f"{p_max:.17g}",
           "--p-step", f"{p_step:.17g}", "--calibration", table, "--out", out] + extra
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        last = (r.stderr.strip().splitlines() or ["(no message)"])[-1]
        fail(f"rod run failed: {' '.join(cmd[1:])}: {last}")
    with open_h5(out) as f:
        return read(f, "/pressure", out), read(f, "/tip_position", out)


def case_rows(f, fname, n, exe, table, work, leg, rule_args):
    """The rod against the FE case /cases/n of the open file f: (row, curve)."""
    g = "/cases/" + n
    if g not in f:
        fail(f"{fname}: no case {n}")
    attrs = f[g].attrs
    try:
        ratio = [float(attrs[f"ratio{j}"]) for j in range(1, 5)]
    except KeyError:
        fail(f"{fname}: case {n} has no ratio1..ratio4")
    p = read(f, g + "/pressure", fname)
    tip = read(f, g + "/tip", fname)
    if len(p) < 2 or tip.shape != (len(p), 3):
        fail(f"{fname}: case {n}: pressure and tip do not match ({len(p)} rows, tip "
             f"{tip.shape})")
    step = float(p[1] - p[0])
    pr, tr = rod_curve(exe, table, ratio, float(p[-1]), step, rule_args, work)
    d, pct = compare(p, tip, pr, tr, leg)
    label = ":".join(f"{r:g}" for r in ratio)
    return (n, f"chambers at {label} x p", d, pct, p), (n, p, pct)


def compare(p_fe, tip_fe, p_rod, tip_rod, leg_mm):
    """|tip difference| at every FE row (the rod's tip linear between its rows)."""
    d = np.empty(len(p_fe))
    for i, p in enumerate(p_fe):
        t = np.array([np.interp(p, p_rod, tip_rod[:, k]) for k in range(3)])
        d[i] = np.linalg.norm(t - tip_fe[i])
    return d, 100.0 * d / leg_mm


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("table")
    ap.add_argument("--cases", default="", help="comma-separated case names (default: every "
                    "holdout and symmetry case)")
    ap.add_argument("--extra", action="append", default=[],
                    help="a case file of held-out cases not merged into the table")
    ap.add_argument("--loaded", default=None, help="FE bend file under a dead tip load")
    ap.add_argument("--tip-load", default="0.05,0,0")
    ap.add_argument("--chambers", default="1,2")
    ap.add_argument("--crawlsim", default=os.path.join(ROOT, "build", "tools", "crawlsim"))
    ap.add_argument("--limit-pct", type=float, default=2.0)
    ap.add_argument("--from-p", type=float, default=0.0,
                    help="--loaded: compare the FE rows from this pressure on (MPa)")
    ap.add_argument("--png", default=None)
    ap.add_argument("--cal-rule", default=None,
                    help="the mode table's model rule (crawlsim --cal-rule: prism, rbf, rbf-pair)")
    a = ap.parse_args()
    rule_args = ["--cal-rule", a.cal_rule] if a.cal_rule else []
    if not os.access(a.crawlsim, os.X_OK):
        fail(f"{a.crawlsim}: not an executable (build first, or give --crawlsim)")
    rows, curves = [], []
    with tempfile.TemporaryDirectory() as work, open_h5(a.table) as f:
        if f.attrs.get("format", b"") not in (b"crawlsim-fe-calibration 1",
                                              "crawlsim-fe-calibration 1"):
            fail(f"{a.table}: not an FE calibration table of modes")
        if "cases" not in f:
            fail(f"{a.table}: missing group /cases")
        want = [c for c in a.cases.split(",") if c]
        names = want or [n for n in f["cases"]
                         if f["cases"][n].attrs.get("kind", b"") in (b"holdout", b"symmetry",
                                                                      "holdout", "symmetry")]
        if not names:
            fail(f"{a.table}: no holdout or symmetry case")
        leg = None  # mm: the unloaded leg (row 0 of a case without gravity)
        for n in f["cases"]:
            kind = f["cases"][n].attrs.get("kind", b"")
            if kind not in (b"gravity", "gravity") and "tip" in f["cases"][n]:
                leg = float(np.linalg.norm(f["cases"][n]["tip"][0]))
                break
        if not leg:
            fail(f"{a.table}: no case without gravity to measure the leg's length")
        for n in names:
            row, curve = case_rows(f, a.table, n, a.crawlsim, a.table, work, leg, rule_args)
            rows.append(row)
            curves.append(curve)
        for extra in a.extra:
            with open_h5(extra) as e:
                if "cases" not in e:
                    fail(f"{extra}: missing group /cases")
                for n in e["cases"]:
                    if e["cases"][n].attrs.get("kind", b"") not in (b"holdout", "holdout"):
                        continue
                    row, curve = case_rows(e, extra, n, a.crawlsim, a.table, work, leg,
                                           rule_args)
                    rows.append(row)
                    curves.append(curve)
        if a.loaded:
            with open_h5(a.loaded) as g:
                p = read(g, "/pressure", a.loaded)
                tip = read(g, "/tip_position", a.loaded)
            keep = p >= a.from_p - 1e-12
            p, tip = p[keep], tip[keep]
            if len(p) < 1:
                fail(f"{a.loaded}: no row at or above --from-p {a.from_p:g} MPa")
            ch = [int(c) for c in a.chambers.split(",")]
            ratio = [1.0 if j in ch else 0.0 for j in range(1, 5)]
            step = 0.025 if len(p) < 2 else float(min(np.diff(p)))
            pr, tr = rod_curve(a.crawlsim, a.table, ratio, float(p[-1]), step,
                               ["--tip-load", a.tip_load] + rule_args, work)
            d, pct = compare(p, tip, pr, tr, leg)
            name = f"chambers {a.chambers} + tip load {a.tip_load} N" + (
                f" (FE rows from {a.from_p:g} MPa)" if a.from_p > 0 else "")
            rows.append(("loaded", name, d, pct, p))
            curves.append(("loaded", p, pct))
    print(f"rod (calibration {os.path.basename(a.table)}"
          + (f", rule {a.cal_rule}" if a.cal_rule else "") + ") against the FE, tip position, "
          f"target {a.limit_pct:g} % of the leg:")
    print("| case | pattern | p range (MPa) | max tip error (mm) | at p (MPa) | % of the leg | "
          "verdict | within the target up to (MPa) |")
    print("|---|---|---|---|---|---|---|---|")
    for n, what, d, pct, p in rows:
        i = int(np.argmax(d))
        ok = "meets" if pct[i] <= a.limit_pct else "misses"
        bad = np.nonzero(pct > a.limit_pct)[0]
        upto = p[-1] if len(bad) == 0 else (p[bad[0] - 1] if bad[0] > 0 else 0.0)
        print(f"| {n} | {what} | {p[0]:g}-{p[-1]:g} | {d[i]:.2f} | {p[i]:g} | {pct[i]:.2f} | {ok} | "
              f"{upto:g} |")
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(7, 4.2))
        for n, p, pct in curves:
            ax.plot(p, pct, marker="o", ms=3, label=n)
        ax.axhline(a.limit_pct, color="k", ls="--", lw=1, label=f"{a.limit_pct:g} % of the leg")
        ax.set_xlabel("highest chamber pressure p (MPa)")
        ax.set_ylabel("|tip(rod) - tip(FE)| (% of the leg)")
        ax.set_title("rod level against the FE on cases the calibration did not fit")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8, ncol=2)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print(f"wrote {a.png}")


if __name__ == "__main__":
    main()

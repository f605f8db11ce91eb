#!/usr/bin/python3
"""plot_study_earth.py: "what makes it walk on Earth" from a `crawlsim study` file.

Usage:
  /usr/bin/python3 tools/plot_study_earth.py STUDY.h5 [-o OUT.png] [--md OUT.md]

Reads the merged study file of tools/studies/earth.study: per case the design (its `--set` and
`--support-mass` words, from the case's signature), the robot's mass and the stance check that
`crawlsim run` prints (load per standing leg, sway-buckling load pi^2 E'I / L^2, their ratio),
the highest pressure of the gait re-derived for the design, the track (/cases/<case>/run:
support x at 9 s against the paper's Table 2, 312 mm), tilt and verdict. A design "walks" when
the run crawls forward to the gait's end, upright (tilt < 10 deg), with x(9 s) within 25 % of
Table 2's 312 mm; the table also gives when the support first tilts past 30 deg (a robot that
tips over early keeps moving as it rolls: its x is no stride). Prints a Markdown table sorted
by stance ratio and draws (a) the tracks against Table 2, (b) x(9 s) against the stance ratio.

Runs with Debian's Python (python3-matplotlib, python3-h5py). Exit status 0, 1 on a missing or
malformed file (one line on stderr), 2 on bad usage.
"""

import math
import os
import re
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # plot_common.py, from any cwd
from plot_common import attr_text, fail, save_or_fail  # noqa: E402
from plot_study_common import fmt, open_study, parse_args  # noqa: E402

PROG = "plot_study_earth"
TABLE2_T = np.arange(10.0)
TABLE2_X = np.array([0, 0, 39, 78, 117, 156, 195, 234, 273, 312], dtype=float)
WALK_TOL = 0.25   # |x(9 s) / 312 - 1| for "walks"
TILT_MAX = 10.0   # deg

STANCE_RE = re.compile(r"stance check: ([0-9.]+) N per leg on half the legs vs sway-buckling "
                       r"load ([0-9.]+) N per leg \(([0-9.]+) %\)")
MASS_RE = re.compile(r"robot mass ([0-9.]+) g")
TILT_RE = re.compile(r"tilt ([0-9.]+) deg")


def text_of(ds):
    v = ds[()]
    return v.decode("utf-8", "replace") if isinstance(v, bytes) else str(v)


def design_of(signature):
    """The design words of a case: the run step's --set and --support-mass values."""
    run = [line for line in signature.splitlines() if line.startswith("run ")]
    words = run[0].split() if run else []
    out = []
    for k, w in enumerate(words[:-1]):
        if w == "--set":
            out.append(words[k + 1])
        elif w == "--support-mass":
            out.append(f"support {float(words[k + 1]) * 1e3:g} g")
        elif w == "--calibration" and "provisional" not in words[k + 1]:
            out.append("FE calibration")
    if not any(w == "--calibration" for w in words):
        out.append("FE calibration (shipped)")
    return ", ".join(out) if out else "-"


def gait_pmax(csv_text):
    pmax = 0.0
    for line in csv_text.splitlines():
        if not line or line.startswith("#") or line.startswith("time"):
            continue
        try:
            vals = [float(v) for v in line.split(",")[1:]]
        except ValueError:
            continue
        if vals:
            pmax = max(pmax, max(vals))
    return pmax


def read_case(f, name):
    g = f["cases"][name]
    rec = {"name": name, "status": attr_text(g.attrs.get("status", b"?")),
           "design": design_of(attr_text(g.attrs.get("signature", b""))),
           "verdict": attr_text(g.attrs.get("verdict", b"")),
           "message": attr_text(g.attrs.get("message", b"")),
           "load": math.nan, "pcr": math.nan, "ratio": math.nan, "mass": math.nan,
           "pmax": math.nan, "x9": math.nan, "t_end": math.nan, "tilt": math.nan,
           "t": None, "x": None, "t_tip": math.nan}
    if "log/run" in g:
        log = text_of(g["log/run"])
        m = STANCE_RE.search(log)
        if m:
            # the ratio as the run printed it (from the unrounded loads)
            rec["load"], rec["pcr"] = float(m.group(1)), float(m.group(2))
            rec["ratio"] = float(m.group(3)) / 100
        m = MASS_RE.search(log)
        if m:
            rec["mass"] = float(m.group(1))
    if "gait_design/csv" in g:
        rec["pmax"] = gait_pmax(text_of(g["gait_design/csv"]))
    if "run/time" in g and "run/support/position" in g:
        t = g["run/time"][()]
        x = g["run/support/position"][()][:, 0]
        rec["t"], rec["x"] = t, x
        if "run/support/orientation" in g:
            q = g["run/support/orientation"][()]
            tilt = np.degrees(np.arccos(np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2), -1, 1)))
            over = np.nonzero(tilt > 30)[0]
            rec["t_tip"] = float(t[over[0]]) if len(over) else math.nan
        rec["t_end"] = float(t[-1]) if len(t) else math.nan
        if len(t) and t[-1] >= 9 - 1e-6:
            rec["x9"] = float(np.interp(9.0, t, x))
    m = TILT_RE.search(rec["verdict"])
    if m:
        rec["tilt"] = float(m.group(1))
    v = rec["verdict"].split(": ", 1)[1] if ": " in rec["verdict"] else rec["verdict"]
    how = v.split(":")[0] if v else rec["status"]
    rec["how"] = how
    rec["walks"] = (how == "crawls" and math.isfinite(rec["x9"]) and
                    abs(rec["x9"] / 312 - 1) <= WALK_TOL and
                    (not math.isfinite(rec["tilt"]) or rec["tilt"] < TILT_MAX))
    return rec



def main():
    args = parse_args(PROG, __doc__)
    with open_study(args.study, PROG) as f:
        recs = [read_case(f, n) for n in f["cases"]]
    if not recs:
        fail(PROG, f"{args.study}: no case")
    recs.sort(key=lambda r: (r["ratio"] if math.isfinite(r["ratio"]) else 9, r["name"]))
    lines = ["| case | design | robot mass (g) | stance load (N/leg) | sway-buckling load (N/leg) "
             "| ratio | gait p max (MPa) | x(9 s) (mm) | vs 312 mm | tilt > 30 deg at (s) | outcome |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    for r in recs:
        dx = (r["x9"] / 312 - 1) * 100 if math.isfinite(r["x9"]) else math.nan
        outcome = ("**walks**: " if r["walks"] else "") + (
            r["verdict"].split(": ", 1)[1] if ": " in r["verdict"] else
            (r["status"] + (": " + r["message"][:80] if r["message"] else "")))
        lines.append(f"| {r['name']} | {r['design']} | {fmt(r['mass'], '.0f')} | "
                     f"{fmt(r['load'], '.2f')} | {fmt(r['pcr'], '.2f')} | "
                     f"{fmt(r['ratio'] * 100, '.0f')}{' %' if math.isfinite(r['ratio']) else ''} | "
                     f"{fmt(r['pmax'], '.3f')} | {fmt(r['x9'], '.1f')} | "
                     f"{fmt(dx, '+.0f')}{' %' if math.isfinite(dx) else ''} | "
                     f"{fmt(r['t_tip'], '.2f')} | {outcome.replace('|', '/')} |")
    walk = [r["name"] for r in recs if r["walks"]]
    lines += ["", f"Walks (crawls upright to the gait's end, x(9 s) within "
              f"{WALK_TOL * 100:.0f} % of Table 2's 312 mm): " + (", ".join(walk) or "none")]
    text = "\n".join(lines) + "\n"
    sys.stdout.write(text)
    if args.md:
        # the table is regenerated; sections written below it by hand (from the first "## "
        # heading on) are kept, so a rerun of the study does not drop them
        kept = ""
        if os.path.exists(args.md):
            with open(args.md, encoding="utf-8") as fh:
                old = fh.read()
            at = old.find("\n## ")
            kept = old[at:] if at >= 0 else ""
        with open(args.md, "w", encoding="utf-8") as fh:
            fh.write(text + kept)

    fig, ax = plt.subplots(1, 2, figsize=(13, 5.2))
    cmap = plt.get_cmap("tab20")
    for k, r in enumerate(recs):
        if r["t"] is None:
            continue
        ax[0].plot(r["t"], r["x"], color=cmap(k % 20), lw=2.0 if r["walks"] else 1.0,
                   ls="-" if r["walks"] else "--",
                   label=f"{r['name']} ({fmt(r['ratio'] * 100, '.0f')} %)")
    ax[0].plot(TABLE2_T, TABLE2_X, "kx", ms=8, mew=2, label="paper Table 2")
    ax[0].set_xlabel("t (s)")
    ax[0].set_ylabel("support x (mm)")
    ax[0].set_title("flat road under earth: tracks (stance load / sway-buckling load)")
    ax[0].grid(alpha=0.3)
    ax[0].legend(fontsize=7, ncol=2)
    for k, r in enumerate(recs):
        xv = r["x9"] if math.isfinite(r["x9"]) else (
            float(r["x"][-1]) if r["x"] is not None and len(r["x"]) else math.nan)
        if not (math.isfinite(r["ratio"]) and math.isfinite(xv)):
            continue
        mk = "o" if r["walks"] else ("x" if r["how"] in ("falls", "tips over", "stops") else "s")
        ax[1].scatter(r["ratio"] * 100, xv, marker=mk, s=60, color=cmap(k % 20))
        ax[1].annotate(r["name"], (r["ratio"] * 100, xv), fontsize=7, xytext=(4, 3),
                       textcoords="offset points")
    ax[1].axhspan(312 * (1 - WALK_TOL), 312 * (1 + WALK_TOL), color="g", alpha=0.12,
                  label="walks: 312 mm +-25 %")
    ax[1].axhline(312, color="k", lw=0.8)
    ax[1].set_xlabel("stance load / sway-buckling load (%)")
    ax[1].set_ylabel("x at 9 s, or where the run stopped (mm)")
    ax[1].set_title("o walks, s crawls or stands, x falls / tips over / stops")
    ax[1].grid(alpha=0.3)
    ax[1].legend(fontsize=8)
    fig.tight_layout()
    out = args.out or os.path.splitext(args.study)[0] + ".png"
    save_or_fail(PROG, out, lambda: fig.savefig(out, dpi=120))
    return 0


if __name__ == "__main__":
    sys.exit(main())

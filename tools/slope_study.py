#!/usr/bin/python3
"""slope_study.py: the slope scene's verdict (issue 36): how steep a slope the designed flat-road
gait climbs under `paper` and `earth`.

  /usr/bin/python3 tools/slope_study.py [--crawlsim build/tools/crawlsim] [--dir build/slope]
                                        [--report-only]

Runs tools/studies/slope.study through `crawlsim study --resume` (each case a 9 s run of the slope
scene at one angle and conditions; finished cases are kept, so an interrupted study picks up where
it stopped), merges it, and writes docs/studies/slope.csv (angle, conditions, distance crawled
along the slope in 9 s, the run's verdict), docs/studies/slope.png (distance against angle) and
the climb table between the markers of docs/studies/slope.md. --report-only skips the runs and
reports what the case files hold. The distance is the support's x displacement at t = 9 s: x runs
along the slope (the slope turns gravity, not the road: terrains/terrains_terrain.h).
"""

import argparse
import csv
import os
import re
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import h5py  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from plot_study_common import fill_markers, run_study, study_paths  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STUDY = os.path.join(ROOT, "tools", "studies", "slope.study")
DOCS = os.path.join(ROOT, "docs", "studies")
BEGIN, END = "<!-- slope table begin -->", "<!-- slope table end -->"


def text(v):
    return v.decode("utf-8", "replace") if isinstance(v, bytes) else str(v)


TIP_DEG = 30.0  # the support tilted this far from the road's normal: it is going over


def tip_time(run_h5):
    """First time (s) the support's up axis is TIP_DEG from the road's normal, None if never or
    no run file. Quaternion (w, x, y, z): the body's y axis has world y component
    1 - 2 (x^2 + z^2)."""
    if not os.path.exists(run_h5):
        return None
    with h5py.File(run_h5, "r") as f:
        t, q = f["/time"][()], f["/support/orientation"][()]
    n = min(len(t), len(q))
    cos_tilt = 1 - 2 * (q[:n, 1] ** 2 + q[:n, 3] ** 2)
    over = np.flatnonzero(cos_tilt < np.cos(np.radians(TIP_DEG)))
    return float(t[over[0]]) if over.size else None


def read_cases(merged, case_dir):
    rows = []
    with h5py.File(merged, "r") as f:
        s = f["summary"]
        for i, name in enumerate(s["case"][()]):
            name = text(name)
            m = re.fullmatch(r"(paper|earth)_(\d+)", name)
            if not m or text(s["status"][i]) not in ("complete", "stopped"):
                continue
            verdict = text(f[f"cases/{name}"].attrs.get("verdict", b""))
            word = re.search(r"\): (\w+( \w+)?):", verdict)
            tip = tip_time(os.path.join(case_dir, name, "run.h5"))
            rows.append({"conditions": m.group(1), "slope_deg": int(m.group(2)),
                         "x_9s_mm": float(s["x_final_mm"][i][0]), "t_s": float(s["t_final_s"][i]),
                         "verdict": word.group(1) if word else verdict,
                         "tilt30_t_s": "" if tip is None else f"{tip:.2f}"})
    rows.sort(key=lambda r: (r["conditions"] != "paper", r["slope_deg"]))
    return rows


def table(rows):
    angles = sorted({r["slope_deg"] for r in rows})
    by = {(r["conditions"], r["slope_deg"]): r for r in rows}
    out = ["| slope (deg) | paper: x in 9 s (mm) | paper verdict | earth: x in 9 s (mm) | earth verdict |",
           "|---:|---:|---|---:|---|"]
    for a in angles:
        cells = [f"{a}"]
        for c in ("paper", "earth"):
            r = by.get((c, a))
            v = r["verdict"] if r else ""
            if r and r["tilt30_t_s"]:
                v += f" (tilt {TIP_DEG:g}° at {r['tilt30_t_s']} s)"
            cells += [f"{r['x_9s_mm']:.1f}", v] if r else ["(not run yet)", ""]
        out.append("| " + " | ".join(cells) + " |")
    return "\n".join(out)


def steepest(rows, cond):
    """The steepest angle with every gentler one crawling uphill (x > 0 and verdict crawls)."""
    best = None
    for r in sorted((r for r in rows if r["conditions"] == cond), key=lambda r: r["slope_deg"]):
        if r["verdict"] == "crawls" and r["x_9s_mm"] > 0:
            best = r["slope_deg"]
        else:
            break
    return best


def plot(rows, out):
    fig, ax = plt.subplots(figsize=(7.5, 4.2), constrained_layout=True)
    for c, col in (("paper", "C0"), ("earth", "C3")):
        rr = [r for r in rows if r["conditions"] == c]
        ax.plot([r["slope_deg"] for r in rr], [r["x_9s_mm"] for r in rr], "-", color=col, lw=1.2)
        ok = [r for r in rr if r["verdict"] == "crawls"]
        bad = [r for r in rr if r["verdict"] != "crawls"]
        ax.plot([r["slope_deg"] for r in ok], [r["x_9s_mm"] for r in ok], "o", color=col,
                label=f"{c}: crawls")
        ax.plot([r["slope_deg"] for r in bad], [r["x_9s_mm"] for r in bad], "x", color=col, ms=8,
                mew=2, label=f"{c}: stands or tips over (see the table)")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_xlabel("slope (deg, +x uphill)")
    ax.set_ylabel("distance crawled along the slope in 9 s (mm)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("slope scene: flat_road_rod.csv gait, rod legs (8 per segment),\n"
                 "calibration_fe_leg_modes_sym.h5 (rbf-pair), friction 0.8", fontsize=9)
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--crawlsim", default=os.path.join(ROOT, "build", "tools", "crawlsim"))
    ap.add_argument("--dir", default=os.path.join(ROOT, "build", "slope"),
                    help="work folder (case files, merged study file)")
    ap.add_argument("--report-only", action="store_true")
    a = ap.parse_args(argv)
    merged, case_dir = study_paths(a.dir, "slope")
    rc = run_study(a.crawlsim, STUDY, merged, case_dir, a.report_only)
    if not os.path.exists(merged):
        print(f"slope_study.py: {merged} was not written (crawlsim study exit {rc})", file=sys.stderr)
        return 1
    rows = read_cases(merged, case_dir)
    with open(os.path.join(DOCS, "slope.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=["slope_deg", "conditions", "x_9s_mm", "t_s", "verdict",
                                          "tilt30_t_s"])
        w.writeheader()
        w.writerows(rows)
    plot(rows, os.path.join(DOCS, "slope.png"))
    lines = [table(rows), ""]
    for c in ("paper", "earth"):
        s = steepest(rows, c)
        if not any(r["conditions"] == c for r in rows):
            lines.append(f"- **{c}**: not run yet")
        elif s is None:
            lines.append(f"- **{c}**: does not crawl uphill even at the gentlest angle run")
        else:
            lines.append(f"- **{c}**: crawls uphill on every slope up to {s} deg (the steepest "
                         "of the angles run before the first that does not crawl)")
    if not fill_markers(os.path.join(DOCS, "slope.md"), BEGIN, END, lines, "slope_study.py"):
        return 1
    print(f"slope_study.py: {len(rows)} cases in docs/studies/slope.csv, slope.png, slope.md")
    return 0 if rc in (0, 1) else rc


if __name__ == "__main__":
    sys.exit(main())

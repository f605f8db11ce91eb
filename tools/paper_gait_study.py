#!/usr/bin/python3
"""paper_gait_study.py: the paper's printed flat-road gait table on the default model (issue 33):
its track against Table 2 and its fragility under the robustness set, beside the designed gait.

  /usr/bin/python3 tools/paper_gait_study.py [--crawlsim build/tools/crawlsim]
                                             [--dir build/paper_gait] [--report-only]

Runs tools/studies/paper_gait.study through `crawlsim study --resume` (each case a 9 s flat-road
run of gaits/flat_road_paper.csv on the scene's default legs and calibration, one robustness
option each; finished cases are kept, so an interrupted study picks up where it stopped), merges
it, and writes docs/studies/paper_gait.csv (per case: x at whole seconds, the worst relative
error against Table 2 from 2 s, x at 9 s against 312 mm, the largest |z| and tilt, the verdict),
docs/studies/paper_gait.png (the tracks against Table 2; x at 9 s per case) and the table between
the markers of docs/studies/paper_gait.md. --report-only skips the runs. Nothing here is fitted:
the numbers are read from the runs' files.
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
STUDY = os.path.join(ROOT, "tools", "studies", "paper_gait.study")
DOCS = os.path.join(ROOT, "docs", "studies")
BEGIN, END = "<!-- paper gait table begin -->", "<!-- paper gait table end -->"
TABLE2 = [0, 0, 39, 78, 117, 156, 195, 234, 273, 312]  # paper Table 2, x (mm) at t = 0..9 s
ORDER = ["nominal", "ramp0.1", "ramp0.5", "mu0.6", "mu1.0", "m25g", "m75g", "tau0.5x", "tau2x",
         "dt_half", "mu0", "designed"]
WHAT = {"nominal": "the paper's table, nominal", "ramp0.1": "ramp 0.1 s", "ramp0.5": "ramp 0.5 s",
        "mu0.6": "friction 0.6", "mu1.0": "friction 1.0", "m25g": "support 25 g",
        "m75g": "support 75 g", "tau0.5x": "pneumatic lag x0.5 (10 ms)",
        "tau2x": "pneumatic lag x2 (40 ms)", "dt_half": "step halved (tolerance 1.25e-4 mm)",
        "mu0": "friction 0 (no progress expected)",
        "designed": "the designed gait (gaits/flat_road_rod.csv), nominal"}


def text(v):
    return v.decode("utf-8", "replace") if isinstance(v, bytes) else str(v)


def track(run_h5):
    """x (mm) at t = 0..9 s (NaN past the run's end), max |z| (mm), max tilt (deg), the times
    and x, z of the whole track (displacement from the start)"""
    with h5py.File(run_h5, "r") as f:
        t = f["/time"][()]
        p = f["/support/position"][()]
        q = f["/support/orientation"][()]
    n = min(len(t), len(p), len(q))
    t, p, q = t[:n], p[:n], q[:n]
    x, z = p[:, 0] - p[0, 0], p[:, 2] - p[0, 2]
    xs = []
    for s in range(10):
        i = np.flatnonzero(np.abs(t - s) < 1e-6)
        xs.append(float(x[i[0]]) if i.size else float("nan"))
    cos_tilt = np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2), -1, 1)
    return xs, float(np.max(np.abs(z))), float(np.degrees(np.max(np.arccos(cos_tilt)))), t, x


def read_cases(merged, case_dir):
    rows, tracks = [], {}
    with h5py.File(merged, "r") as f:
        s = f["summary"]
        for i, name in enumerate(s["case"][()]):
            name = text(name)
            status = text(s["status"][i])
            run = os.path.join(case_dir, name, "run.h5")
            if status not in ("complete", "stopped") or not os.path.exists(run):
                continue
            verdict = text(f[f"cases/{name}"].attrs.get("verdict", b""))
            word = re.search(r"\): (\w+( \w+)?):", verdict)
            xs, zmax, tilt, t, x = track(run)
            errs = [(abs(xs[k] - TABLE2[k]) / TABLE2[k], k) for k in range(2, 10)
                    if not np.isnan(xs[k])]
            worst, wt = max(errs) if errs else (float("nan"), -1)
            signed = (xs[wt] - TABLE2[wt]) / TABLE2[wt] if wt >= 0 else float("nan")
            rows.append({"case": name, "what": WHAT.get(name, name), "status": status,
                         **{f"x{k}_mm": f"{xs[k]:.1f}" for k in range(10)},
                         "worst_vs_table2_pct": f"{100 * signed:+.1f}", "worst_t_s": wt,
                         "x9_vs_312_pct": f"{100 * (xs[9] - 312) / 312:+.1f}",
                         "max_abs_z_mm": f"{zmax:.1f}", "max_tilt_deg": f"{tilt:.1f}",
                         "verdict": word.group(1) if word else verdict})
            tracks[name] = (t, x)
    rows.sort(key=lambda r: ORDER.index(r["case"]) if r["case"] in ORDER else 99)
    return rows, tracks


def table(rows):
    out = ["| case | x at 2 / 5 / 9 s (mm) | worst against Table 2 from 2 s (at t) | "
           "x at 9 s against 312 mm | max abs z (mm) | max tilt (deg) | verdict |",
           "|---|---|---|---|---|---|---|"]
    for r in rows:
        out.append(f"| {r['what']} | {r['x2_mm']} / {r['x5_mm']} / {r['x9_mm']} | "
                   f"{r['worst_vs_table2_pct']} % ({r['worst_t_s']} s) | {r['x9_vs_312_pct']} % | "
                   f"{r['max_abs_z_mm']} | {r['max_tilt_deg']} | {r['verdict']} |")
    return "\n".join(out)


def plot(rows, tracks, out):
    fig, (a1, a2) = plt.subplots(1, 2, figsize=(11, 4.2), constrained_layout=True,
                                 gridspec_kw={"width_ratios": [1.3, 1]})
    a1.plot(range(10), TABLE2, "ks", label="paper Table 2")
    t5 = np.arange(2, 10)
    a1.fill_between(t5, 0.95 * np.array(TABLE2[2:]), 1.05 * np.array(TABLE2[2:]), color="0.85",
                    label="Table 2 within 5 %")
    for name, col in (("nominal", "C0"), ("designed", "C2")):
        if name in tracks:
            t, x = tracks[name]
            a1.plot(t, x, color=col, lw=1.4, label=WHAT[name])
    for name in ORDER[1:10]:
        if name in tracks:
            t, x = tracks[name]
            a1.plot(t, x, color="C0", lw=0.6, alpha=0.35)
    a1.set_xlabel("t (s)")
    a1.set_ylabel("support x (mm)")
    a1.grid(True, alpha=0.3)
    a1.legend(fontsize=7)
    a1.set_title("flat road, the scene's default legs, 23-mode table (rbf-pair), paper;\n"
                 "thin: the paper's table under the robustness set", fontsize=8)
    names = [r["case"] for r in rows]
    x9 = [float(r["x9_mm"]) for r in rows]
    cols = ["C2" if n == "designed" else "C0" for n in names]
    a2.barh(range(len(names)), x9, color=cols, zorder=2)
    for k, r in enumerate(rows):
        if not np.isfinite(x9[k]):
            a2.text(0, k, f" {r['verdict']} before 9 s", va="center", fontsize=7)
    a2.axvspan(0.9 * 312, 1.1 * 312, color="0.85", label="312 mm within 10 %", zorder=0)
    a2.axvline(312, color="k", lw=0.8)
    a2.set_yticks(range(len(names)))
    a2.set_yticklabels(names, fontsize=7)
    a2.invert_yaxis()
    a2.set_xlabel("x at 9 s (mm)")
    a2.legend(fontsize=7)
    a2.grid(True, axis="x", alpha=0.3)
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--crawlsim", default=os.path.join(ROOT, "build", "tools", "crawlsim"))
    ap.add_argument("--dir", default=os.path.join(ROOT, "build", "paper_gait"),
                    help="work folder (case files, merged study file)")
    ap.add_argument("--report-only", action="store_true")
    a = ap.parse_args(argv)
    merged, case_dir = study_paths(a.dir, "paper_gait")
    rc = run_study(a.crawlsim, STUDY, merged, case_dir, a.report_only)
    if not os.path.exists(merged):
        print(f"paper_gait_study.py: {merged} was not written (crawlsim study exit {rc})",
              file=sys.stderr)
        return 1
    rows, tracks = read_cases(merged, case_dir)
    with open(os.path.join(DOCS, "paper_gait.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()) if rows else ["case"])
        w.writeheader()
        w.writerows(rows)
    if rows:
        plot(rows, tracks, os.path.join(DOCS, "paper_gait.png"))
    missing = [n for n in ORDER if n not in {r["case"] for r in rows}]
    lines = [table(rows)]
    if missing:
        lines += ["", "Not run yet: " + ", ".join(missing) + "."]
    if not fill_markers(os.path.join(DOCS, "paper_gait.md"), BEGIN, END, lines,
                        "paper_gait_study.py"):
        return 1
    print(f"paper_gait_study.py: {len(rows)} cases in docs/studies/paper_gait.csv, "
          "paper_gait.png, paper_gait.md")
    return 0 if rc in (0, 1) else rc


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""plot_study_sec4.py: the paper's Sec. 4 parameter study from a `crawlsim study` file.

Usage:
  /usr/bin/python3 tools/plot_study_sec4.py STUDY.h5 [-o OUT.png] [--md OUT.md] [--csv OUT.csv]
  /usr/bin/python3 tools/plot_study_sec4.py TABLE.md [-o OUT.png]   (redraw from its own table)

Reads the merged study file of tools/studies/sec4.study (or sec4_tiny.study): for every FE case
and its analytic twin (`an_<case>`) the pressure at which the total bending angle reaches the
target (/cases/<case>/bend attribute p_until_angle_MPa, target until_angle_deg), the wall time
and the status. Prints a Markdown table: pressure for 360 deg per case, its ratio to the
baseline's, the analytic model's pressure and ratio, the paper's value where the paper gives
one, and the FE's difference from it; then the paper's qualitative claims checked against the
FE's trend. Draws a PNG: (a) pressure for the target angle per case (FE, paper), (b) ratio to
the baseline (FE, analytic, paper).

The paper's numbers come from its text (Sec. 4; the values used are in docs/reference.md): it
prints 0.403 MPa for the baseline (Sec. 4.2: Lc = 40 mm; Sec. 4.3: r1 = 2 mm, there with b = 3 mm) and withholds the
other pressures ("[withheld]" in the extract): those cells stay empty and are never filled in
from elsewhere. Issue 13 quotes 0.301 MPa for r1 = 2.5 mm; that number is not in the text and
is not used.

Runs with Debian's Python (python3-matplotlib, python3-h5py). Exit status 0, 1 on a missing or
malformed file (one line on stderr), 2 on bad usage.
"""

import math
import re
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # plot_common.py, from any cwd
from plot_common import attr_text, fail, save_or_fail  # noqa: E402
from plot_study_common import fmt, open_study, parse_args  # noqa: E402

PROG = "plot_study_sec4"

# (case, group, what changes against the baseline)
CASES = [
    ("baseline", "baseline", "S 50, n 30/30/30, Lc 40, r1 2, b 4"),
    ("fibres_none", "4.1 fibres", "n 0/0/0"),
    ("fibres_30_20_10", "4.1 fibres", "n 30/20/10"),
    ("Lc35", "4.2 chamber", "Lc 35 (c 7.5)"),
    ("Lc45", "4.2 chamber", "Lc 45 (c 2.5)"),
    ("S45", "4.2 segment", "S 45, n 27"),
    ("S55", "4.2 segment", "S 55, n 33"),
    ("S65", "4.2 segment", "S 65, n 39"),
    ("r1_1.5_b3", "4.3 radius", "r1 1.5, b 3"),
    ("r1_2_b3", "4.3 radius", "r1 2, b 3"),
    ("r1_2.5_b3", "4.3 radius", "r1 2.5, b 3"),
]

# the paper's printed pressures for 360 deg (MPa) and where they are printed
PAPER = {
    "baseline": (0.403, "Sec. 4.2 (Lc = 40) and 4.3"),
    "r1_2_b3": (0.403, "Sec. 4.3 (r1 = 2 at b = 3)"),
}

# the paper's qualitative statements on the 360 deg pressure, as (claim, cases in the order in
# which the pressure must fall)
CLAIMS = [
    ("fibres: 'more air pressure is needed to achieve 360 deg' with fibres (Sec. 4.1)",
     ["baseline", "fibres_none"]),
    ("chamber length: 'the larger the length of the pneumatic chamber, the larger the bending "
     "angle' (Sec. 4.2)", ["Lc35", "baseline", "Lc45"]),
    ("segment length: 'the longer the segment length, the better' (Sec. 4.2)",
     ["S45", "baseline", "S55", "S65"]),
    ("chamber radius: 'the larger the radius r1 ..., the greater the bending ability' (Sec. 4.3)",
     ["r1_1.5_b3", "r1_2_b3", "r1_2.5_b3"]),
]


def end_reason(log):
    """Why an FE sweep ended below its target, from the report lines of `crawlsim bend` (its
    log in the case file): the critical point the tangent's inertia shows, and how the path
    ended. "" when the log has none of them."""
    why = []
    for line in log.splitlines():
        if "tangent indefinite" in line and not any(w.startswith("tangent") for w in why):
            m = re.search(r"p = ([0-9.]+) MPa", line)
            why.append(f"tangent indefinite from {float(m.group(1)):.4f} MPa" if m
                       else "tangent indefinite")
        m = re.search(r"the sweep ends at ([0-9.]+) MPa \(([0-9.]+) deg\): pressure control "
                      r"failed there and the pressure did not fall", line)
        if m:
            tail = line.rsplit("fem: ", 1)[-1]
            cause = ("inverted elements" if "inverted" in tail else
                     "Newton stagnated" if "stagnated" in tail else tail[:60])
            why.append(f"ended at {float(m.group(1)):.4f} MPa ({float(m.group(2)):.1f} deg): "
                       f"no limit point (the pressure still rose), {cause}")
        m = re.search(r"pressure limit point at ([0-9.]+) MPa \(([0-9.]+) deg\).*sweep ends", line)
        if m:
            why.append(f"limit point at {float(m.group(1)):.4f} MPa ({float(m.group(2)):.1f} "
                       f"deg), no stable branch past it")
    return "; ".join(why)


def read_case(f, name):
    """dict of what the study recorded for case `name` (None if the case is not in the file)."""
    path = f"cases/{name}"
    if path not in f:
        return None
    g = f[path]
    rec = {
        "status": attr_text(g.attrs.get("status", b"?")),
        "message": attr_text(g.attrs.get("message", b"")),
        "wall_s": float(g.attrs.get("wall_time_s", math.nan)),
        "p": math.nan, "target": math.nan, "angle_end": math.nan, "p_end": math.nan,
        "p_limit": math.nan, "p_stalled": math.nan, "n_tet": math.nan, "mesh": math.nan, "why": "",
    }
    if "log/bend" in g:
        rec["why"] = end_reason(attr_text(g["log/bend"][()]))
    if "bend" in g:
        b = g["bend"]
        rec["p"] = float(b.attrs.get("p_until_angle_MPa", math.nan))
        rec["target"] = float(b.attrs.get("until_angle_deg", math.nan))
        rec["p_limit"] = float(b.attrs.get("p_limit_MPa", math.nan))
        rec["p_stalled"] = float(b.attrs.get("fe_p_stalled_MPa", math.nan))
        rec["n_tet"] = float(b.attrs.get("n_elements_soft", math.nan))
        rec["mesh"] = float(b.attrs.get("mesh_size_mm", math.nan))
        if "angle_total_deg" in b and b["angle_total_deg"].shape[0] > 0:
            rec["angle_end"] = float(b["angle_total_deg"][-1])
            rec["p_end"] = float(b["pressure"][-1])
    return rec



def num(cell):
    """a table cell as a float (nan when empty)"""
    cell = cell.strip().rstrip("%").strip()
    try:
        return float(cell) if cell else math.nan
    except ValueError:
        return math.nan


def rows_from_md(path):
    """The rows of a Markdown table this script wrote (--md), for redrawing the chart when the
    study file is gone: (target angle text, rows as main() builds them)."""
    try:
        with open(path) as fh:
            text = fh.read()
    except OSError as e:
        fail(PROG, f"{path}: {e.strerror}")
    m = re.search(r"bend the actuator to (.+)$", text, re.M)
    tname = m.group(1).strip() if m else "the target angle"
    groups = {c: (g, ch) for c, g, ch in CASES}
    rows = {}
    for n, line in enumerate(text.splitlines(), 1):
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) != 11 or cells[0] not in groups:
            continue
        if cells[0] in rows:
            fail(PROG, f"{path}:{n}: case {cells[0]} twice")
        rows[cells[0]] = (cells[0], groups[cells[0]][0], cells[1], num(cells[2]), num(cells[3]),
                          num(cells[4]), num(cells[5]), num(cells[6]), num(cells[7]),
                          num(cells[8]), num(cells[9]), cells[10])
    if not rows:
        fail(PROG, f"{path}: no row of the Sec. 4 table (case | change | FE p | ... | FE status)")
    return tname, [rows.get(c, (c, g, ch) + (math.nan,) * 8 + ("not in the table",))
                   for c, g, ch in CASES]


def main():
    args = parse_args(PROG, __doc__,
                      lambda ap: ap.add_argument("--csv", help="also write the numbers as CSV"))
    if args.study.endswith(".md"):
        # redraw from the table (the study's HDF5 is not kept in the repository)
        tname, rows = rows_from_md(args.study)
        chart(rows, tname, "?", args.out or os.path.splitext(args.study)[0] + ".png")
        return 0
    with open_study(args.study, PROG) as f:
        study = attr_text(f.attrs.get("study", b"?"))
        fe = {c: read_case(f, c) for c, _, _ in CASES}
        an = {c: read_case(f, "an_" + c) for c, _, _ in CASES}
    if all(r is None for r in fe.values()) and all(r is None for r in an.values()):
        fail(PROG, f"{args.study}: none of the Sec. 4 cases is in the file (study '{study}')")
    targets = {r["target"] for r in list(fe.values()) + list(an.values())
               if r and math.isfinite(r["target"])}
    target = targets.pop() if len(targets) == 1 else math.nan
    tname = f"{target:g} deg" if math.isfinite(target) else "the target angle"

    def ratio(recs, c):
        b, r = recs.get("baseline"), recs.get(c)
        if not b or not r or not (b["p"] > 0) or not math.isfinite(r["p"]):
            return math.nan
        return r["p"] / b["p"]

    pb = PAPER["baseline"][0]
    lines = [f"Sec. 4 study `{study}`: pressure (MPa) at which chambers 1,2 of all segments bend "
             f"the actuator to {tname}",
             "",
             "| case | change | FE p (MPa) | FE / baseline | analytic p (MPa) | analytic / "
             "baseline | paper p (MPa) | paper / baseline | FE vs paper | FE wall (min) | FE "
             "status |",
             "|---|---|---|---|---|---|---|---|---|---|---|"]
    rows = []
    for c, group, change in CASES:
        r, a = fe[c], an[c]
        p_fe = r["p"] if r else math.nan
        p_an = a["p"] if a else math.nan
        paper = PAPER.get(c)
        p_pa = paper[0] if paper and target == 360 else math.nan
        diff = (p_fe / p_pa - 1) * 100 if math.isfinite(p_fe) and math.isfinite(p_pa) else math.nan
        status = "not run" if r is None else r["status"]
        if r and r["status"] == "complete" and not math.isfinite(p_fe):
            status = (f"not reached: {r['angle_end']:.1f} deg at {r['p_end']:.4f} MPa"
                      if math.isfinite(r["angle_end"]) else "no angle")
            if r["why"]:
                status += "; " + r["why"]
            elif math.isfinite(r["p_limit"]):
                status += f"; limit point at {r['p_limit']:.4f} MPa"
            elif math.isfinite(r["p_stalled"]):
                status += f"; ended at {r['p_stalled']:.4f} MPa: both controls failed"
        elif r and r["status"] == "failed":
            status = "failed: " + r["message"][:90].replace("|", "/")
        rows.append((c, group, change, p_fe, ratio(fe, c), p_an, ratio(an, c), p_pa,
                     p_pa / pb if math.isfinite(p_pa) else math.nan, diff,
                     r["wall_s"] / 60 if r else math.nan, status))
        lines.append(f"| {c} | {change} | {fmt(p_fe, '.4f')} | {fmt(ratio(fe, c), '.3f')} | "
                     f"{fmt(p_an, '.4f')} | {fmt(ratio(an, c), '.3f')} | {fmt(p_pa, '.3f')} | "
                     f"{fmt(p_pa / pb if math.isfinite(p_pa) else math.nan, '.3f')} | "
                     f"{fmt(diff, '+.1f')}{' %' if math.isfinite(diff) else ''} | "
                     f"{fmt(r['wall_s'] / 60 if r else math.nan, '.1f')} | {status} |")
    total = sum(r["wall_s"] for r in fe.values() if r and math.isfinite(r["wall_s"]))
    lines += ["", f"FE wall time of the cases run so far: {total / 3600:.2f} h "
              f"({sum(1 for r in fe.values() if r)} of {len(CASES)} cases)."]
    if target == 360:
        lines += ["", "The paper prints 360 deg pressures only for the baseline (0.403 MPa, "
                  "Sec. 4.2 and 4.3); the others are withheld in the text extract, so only the "
                  "trends below are compared for them."]
    lines += ["", "The paper's claims against the FE trend (pressure must fall along the list):"]
    if target != 360:
        lines.append(f"- (the paper's claims are about 360 deg; at {tname} they are not checked)")
    for claim, order in CLAIMS if target == 360 else []:
        ps = [fe[c]["p"] if fe[c] else math.nan for c in order]
        if all(math.isfinite(p) for p in ps):
            ok = all(ps[k + 1] < ps[k] for k in range(len(ps) - 1))
            verdict = ("holds" if ok else "does not hold") + ": " + ", ".join(
                f"{c} {p:.4f}" for c, p in zip(order, ps))
        else:
            verdict = "not all cases have a pressure yet"
        lines.append(f"- {claim}: {verdict}")
    text = "\n".join(lines) + "\n"
    sys.stdout.write(text)
    if args.md:
        with open(args.md, "w") as fh:
            fh.write(text)
    if args.csv:
        with open(args.csv, "w") as fh:
            fh.write("case,group,change,fe_p_MPa,fe_ratio,analytic_p_MPa,analytic_ratio,"
                     "paper_p_MPa,paper_ratio,fe_vs_paper_percent,fe_wall_min,fe_status\n")
            for row in rows:
                fh.write(",".join(f'"{v}"' if isinstance(v, str) else fmt(v, ".6g")
                                  for v in row) + "\n")

    meshes = sorted({r["mesh"] for r in fe.values() if r and math.isfinite(r["mesh"])})
    mesh = ", ".join(f"{m:g}" for m in meshes) if meshes else "?"
    chart(rows, tname, mesh, args.out or os.path.splitext(args.study)[0] + ".png")
    return 0


def chart(rows, tname, mesh, out):
    """the PNG: (a) pressure for the target angle per case, (b) ratios to the baseline"""
    names = [c for c, _, _ in CASES]
    x = np.arange(len(names))
    fig, ax = plt.subplots(2, 1, figsize=(11, 7.5), sharex=True)
    p_fe = np.array([row[3] for row in rows])
    p_pa = np.array([row[7] for row in rows])
    label = "FE (crawlsim)" if mesh == "?" else f"FE (crawlsim, l_soft {mesh} mm)"
    ax[0].bar(x - 0.2, p_fe, 0.4, label=label, color="tab:blue")
    ax[0].scatter(x[np.isfinite(p_pa)], p_pa[np.isfinite(p_pa)], marker="D", s=60,
                  color="tab:red", zorder=3, label="paper (printed values)")
    for k, row in enumerate(rows):
        if not math.isfinite(row[3]):
            ax[0].text(x[k] - 0.2, 0.005, row[11].split(":")[0], rotation=90, fontsize=7,
                       va="bottom", ha="center")
    ax[0].set_ylabel(f"pressure for {tname} (MPa)")
    ax[0].legend(loc="upper right", fontsize=8)
    ax[0].grid(axis="y", alpha=0.3)
    ax[0].set_title(f"paper Sec. 4: pressure for {tname} (chambers 1,2 of all segments)")
    ax[1].bar(x - 0.2, [row[4] for row in rows], 0.4, label="FE / FE baseline", color="tab:blue")
    ax[1].bar(x + 0.2, [row[6] for row in rows], 0.4, label="analytic / analytic baseline",
              color="tab:gray")
    pr = np.array([row[8] for row in rows])
    ax[1].scatter(x[np.isfinite(pr)], pr[np.isfinite(pr)], marker="D", s=60, color="tab:red",
                  zorder=3, label="paper / paper baseline")
    ax[1].axhline(1.0, color="k", lw=0.8)
    ax[1].set_ylabel("ratio to the baseline")
    ax[1].legend(loc="upper right", fontsize=8)
    ax[1].grid(axis="y", alpha=0.3)
    ax[1].set_xticks(x)
    ax[1].set_xticklabels([f"{c}\n{ch}" for c, _, ch in CASES], fontsize=7, rotation=30,
                          ha="right")
    fig.tight_layout()
    save_or_fail(PROG, out, lambda: fig.savefig(out, dpi=120))


if __name__ == "__main__":
    sys.exit(main())

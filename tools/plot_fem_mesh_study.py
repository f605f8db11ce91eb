#!/usr/bin/python3
"""FE mesh study (paper Table 1): error of the total bending angle against wall time.

Reads the logs of `bench_fem_bend` runs (or the stderr of `crawlsim bend --model fe`; one per mesh
size, same actuator and chambers), takes at each pressure the finest mesh (most Tet10) that
reached it as the reference, and prints a Markdown table
(l_soft, Tet10, nodes, fibre elements, wall time, angle and relative error at each study
pressure) and draws relative error against wall time to a PNG.

Usage:
  /usr/bin/python3 tools/plot_fem_mesh_study.py LOG... [--pressures 0.05,0.1,0.2]
      [--out docs/fem_mesh_study.png]
Run e.g. `bench_fem_bend baseline L 0.2 0.05 nan 1,2 > /tmp/mesh_L.log` for each L first. A log
without the closing summary (a run stopped early, or a crawlsim log) needs LOG.meta holding the
`mesh: ...` line of a bench_fem_bend run of the same mesh; its setup time counts as 0.
"""
import argparse
import re
import sys

MESH_RE = re.compile(r"mesh: (\d+) Tet10, (\d+) nodes, (\d+) dofs, (\d+) fibre elements; "
                     r"l_soft ([\d.]+) mm")
TIME_RE = re.compile(r"time: total ([\d.]+) s = mesh ([\d.]+) \+ setup ([\d.]+)")
STEP_RE = re.compile(r"^step p ([\d.]+) MPa .* wall +([\d.]+) s.* total +(\S+) deg")
# `crawlsim bend --model fe` progress lines (stderr), the same data in the CLI's words
CLI_STEP_RE = re.compile(r"fe: p = ([\d.]+) MPa \(dp [\d.]+\), \d+ Newton iterations, \d+ "
                         r"cut-backs, ([\d.]+) s, total (\S+) deg")
ROW_RE = re.compile(r"^p ([\d.]+) MPa +angles +(\S+) +(\S+) +(\S+) +total +(\S+) deg")


def read_log(path):
    """One run: mesh statistics, total wall time, output rows p -> total angle, and the wall
    time at which each output pressure was reached (mesh + setup + steps so far)."""
    run = {"path": path, "rows": {}, "wall_at": {}}
    steps = []
    with open(path) as f:
        for line in f:
            m = MESH_RE.search(line)
            if m:
                run["ntet"], run["nnode"] = int(m.group(1)), int(m.group(2))
                run["nfib"], run["l_soft"] = int(m.group(4)), float(m.group(5))
            m = TIME_RE.search(line)
            if m:
                run["wall"] = float(m.group(1))
                run["pre"] = float(m.group(2)) + float(m.group(3))
            m = STEP_RE.search(line) or CLI_STEP_RE.search(line)
            if m:
                steps.append((float(m.group(1)), float(m.group(2))))
                # converged steps land exactly on the output pressures: a run stopped before its
                # summary still gives the angles it reached (2 decimals, vs 3 in the rows)
                run["rows"].setdefault(round(float(m.group(1)), 6), float(m.group(3)))
            m = ROW_RE.search(line)
            if m:
                run["rows"][round(float(m.group(1)), 6)] = float(m.group(5))
    if "wall" not in run:
        # an unfinished run: mesh statistics from a side file LOG.meta ("mesh: ..." line of a
        # short run of the same mesh), setup time unknown (taken as 0)
        try:
            with open(path + ".meta") as f:
                m = MESH_RE.search(f.read())
        except OSError:
            m = None
        if not m:
            sys.exit(f"{path}: no mesh/time summary (unfinished run) and no {path}.meta")
        run["ntet"], run["nnode"] = int(m.group(1)), int(m.group(2))
        run["nfib"], run["l_soft"] = int(m.group(4)), float(m.group(5))
        run["pre"], run["wall"], run["partial"] = 0.0, float("nan"), True
    t = run["pre"]
    for p, w in steps:
        t += w
        run["wall_at"][round(p, 6)] = t
    return run


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("logs", nargs="+")
    ap.add_argument("--pressures", default="0.05,0.1,0.2")
    ap.add_argument("--out", default="docs/fem_mesh_study.png")
    a = ap.parse_args()
    ps = [round(float(x), 6) for x in a.pressures.split(",")]
    runs = sorted((read_log(p) for p in a.logs), key=lambda r: r["ntet"])
    # the reference at each pressure: the finest run that reached it
    refs = {}
    for p in ps:
        have = [r for r in runs if p in r["rows"]]
        if len(have) >= 2:
            refs[p] = have[-1]
    ps = [p for p in ps if p in refs]
    if not ps:
        sys.exit("no study pressure was reached by two runs")
    head = "| l_soft (mm) | Tet10 | nodes | fibre el. | wall to %.2f MPa (s) |" % max(ps)
    head += "".join(" angle %.2f (deg) | err %.2f |" % (p, p) for p in ps)
    print(head)
    print("|" + "---|" * (5 + 2 * len(ps)))
    series = {p: ([], [], []) for p in ps}
    for r in runs:
        wall = r["wall_at"].get(max(ps), float("nan"))
        line = "| %g | %d | %d | %d | %s |" % (r["l_soft"], r["ntet"], r["nnode"], r["nfib"],
                                                "-" if wall != wall else "%.0f" % wall)
        for p in ps:
            if p in r["rows"]:
                ref = refs[p]
                err = abs(r["rows"][p] / ref["rows"][p] - 1.0)
                line += " %.2f | %s |" % (r["rows"][p], "ref" if r is ref else "%.2f %%" %
                                          (100 * err))
                if r is not ref:
                    series[p][0].append(r["wall_at"].get(p, float("nan")))
                    series[p][1].append(100 * err)
                    series[p][2].append(r["l_soft"])
            else:
                line += " - | - |"
        print(line)
    print("reference per pressure: " + ", ".join("%.2f MPa: l_soft %g" % (p, refs[p]["l_soft"])
                                                 for p in ps))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4))
    for p in ps:
        ax.plot(series[p][0], series[p][1], "o:",
                label="%.2f MPa (vs l_soft %g)" % (p, refs[p]["l_soft"]))
        for t, e, l in zip(*series[p]):
            ax.annotate("%g" % l, (t, e), textcoords="offset points", xytext=(4, 3), fontsize=7)
    ax.set_xlabel("wall time to reach the pressure (s); labels: l_soft (mm)")
    ax.set_ylabel("total-angle error vs the finest mesh (%)")
    ax.set_yscale("log")
    ax.set_title("FE mesh study: baseline, fibres, chambers 1,2")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend()
    fig.tight_layout()
    fig.savefig(a.out, dpi=120)
    print("wrote", a.out)


if __name__ == "__main__":
    main()

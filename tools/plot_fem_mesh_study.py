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
  /usr/bin/python3 tools/plot_fem_mesh_study.py --study docs/studies/fem_mesh
      [--pressures 0.1,0.2,0.3,0.4,0.5] [--out docs/fem_mesh_study.png]
The second form reads the cases of tools/fem_mesh_study.py (DIR/l*.json and DIR/*/l*.json; per
l_soft the finished case, else the one that got furthest): the convergence chart (angle against
the mesh's element size h = (V / Tet10)^(1/3), with the Richardson estimate of the converged
angle and the observed order from the three finest meshes that reached a pressure) and the
cost (CPU time, factor memory) against Tet10; the Markdown tables on stdout.
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


def richardson(h, f):
    """Observed order and extrapolated value from three solutions f on meshes h (finest first,
    any refinement ratios): the generalised Richardson procedure of Celik et al. (2008, J. Fluids
    Eng. 130, 078001, Eqs. 3-4), fixed-point iteration for p. Returns (p, f_ext, note); p and
    f_ext None when the differences change sign (oscillatory) or do not shrink."""
    import math
    e21, e32 = f[1] - f[0], f[2] - f[1]
    r21, r32 = h[1] / h[0], h[2] / h[1]
    if e21 == 0 or e32 == 0:
        return None, None, "equal angles"
    s = 1.0 if e32 / e21 > 0 else -1.0
    if s < 0:
        return None, None, "oscillatory (differences %+.3g, %+.3g deg)" % (e21, e32)
    p = 1.0
    for _ in range(200):
        q = math.log((r21 ** p - s) / (r32 ** p - s))
        pn = (math.log(abs(e32 / e21)) + q) / math.log(r21)  # Celik's |.| left off: a
        if pn <= 0:                                          # negative order = diverging
            return None, None, "not converging (differences %+.3g, %+.3g deg)" % (e21, e32)
        if abs(pn - p) < 1e-10:
            break
        p = pn
    p = pn
    f_ext = (r21 ** p * f[0] - f[1]) / (r21 ** p - 1.0)
    return p, f_ext, ""


def study(a):
    """Charts and tables of a tools/fem_mesh_study.py directory."""
    import glob
    import json
    recs, by_size = [], {}
    paths = glob.glob(a.study.rstrip("/") + "/l*.json") + glob.glob(a.study.rstrip("/") +
                                                                   "/*/l*.json")
    for path in sorted(paths):
        with open(path) as f:
            r = json.load(f)
        if "tet10" not in r and "tet10_msh" in r:  # stopped before the CLI's summary
            r["tet10"], r["nodes"] = r["tet10_msh"], r["nodes_msh"]
        if "tet10" not in r:
            continue  # stopped before its mesh was reported
        ang = {round(float(p), 6): v for p, v in r.get("angles_progress", {}).items()}
        ang.update({round(float(p), 6): v[1] for p, v in r.get("angles", {}).items()})
        r["ang"] = ang
        # one case per l_soft: a finished one, else the one that got furthest
        key = r["l_soft"]
        best = by_size.get(key)
        rank = (r["status"] == "done", max(ang) if ang else 0.0)
        if best is None or rank > best[0]:
            by_size[key] = (rank, r)
    recs = [v[1] for v in by_size.values()]
    if not recs:
        sys.exit("plot_fem_mesh_study: no case with a mesh in %s" % a.study)
    recs.sort(key=lambda r: r["tet10"])
    ps = [round(float(x), 6) for x in a.pressures.split(",")]
    # the element size of each mesh: the solid volume over the elements, cube root
    vol = a.volume
    for r in recs:
        r["h"] = (vol / r["tet10"]) ** (1.0 / 3.0)
    print("| l_soft (mm) | status | Tet10 | nodes | fibre el. | h (mm) | Newton it. | factor "
          "memory (MB) | peak RSS (MB) | wall (s) | CPU (s) | load (1-min, mean) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in sorted(recs, key=lambda r: -r["l_soft"]):
        print("| %g | %s | %d | %s | %s | %.3f | %s | %s | %.0f | %.0f | %.0f | %.1f |" % (
            r["l_soft"], r["status"], r["tet10"], r.get("nodes", "-"),
            r.get("fibre_elements", "-"), r["h"], r.get("newton", r.get("newton_progress", "-")),
            r.get("factor_mem_mb", "-"), r.get("maxrss_mb", 0), r["wall_s"], r["cpu_s"],
            r["load1_mean"]))
    print()
    print("| l_soft (mm) |" + "".join(" %.2f MPa (deg) | err |" % p for p in ps))
    print("|---|" + "---|---|" * len(ps))
    ref = {}
    for p in ps:
        have = [r for r in recs if p in r["ang"]]
        if have:
            ref[p] = have[-1]
    for r in sorted(recs, key=lambda r: -r["l_soft"]):
        line = "| %g |" % r["l_soft"]
        for p in ps:
            if p in r["ang"]:
                rr = ref[p]
                err = "ref" if rr is r else "%.2f %%" % (100 * (r["ang"][p] / rr["ang"][p] - 1))
                line += " %.2f | %s |" % (r["ang"][p], err)
            else:
                line += " - | - |"
        print(line)
    print("reference per pressure (the finest mesh that reached it): " +
          ", ".join("%.2f MPa: l_soft %g" % (p, ref[p]["l_soft"]) for p in ps if p in ref))
    print()
    print("| p (MPa) | meshes (l_soft) | observed order | Richardson angle (deg) | finest (deg) "
          "| finest vs Richardson |")
    print("|---|---|---|---|---|---|")
    rich = {}
    for p in ps:
        have = [r for r in recs if p in r["ang"]]
        if len(have) < 3:
            print("| %.2f | %s | - | - | - | fewer than three meshes |" % (
                p, ", ".join("%g" % r["l_soft"] for r in have) or "-"))
            continue
        three = have[-3:][::-1]  # finest first
        order, fx, note = richardson([r["h"] for r in three], [r["ang"][p] for r in three])
        names = ", ".join("%g" % r["l_soft"] for r in three)
        if order is None:
            print("| %.2f | %s | - | - | %.2f | %s |" % (p, names, three[0]["ang"][p], note))
            continue
        rich[p] = fx
        print("| %.2f | %s | %.2f | %.2f | %.2f | %+.2f %% |" % (
            p, names, order, fx, three[0]["ang"][p], 100 * (three[0]["ang"][p] / fx - 1)))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (ax, bx) = plt.subplots(1, 2, figsize=(11, 4.3))
    # each pressure relative to its finest mesh, so that all pressures share one axis
    hmax = max(r["h"] for r in recs)
    for k, p in enumerate(ps):
        pts = sorted(((r["h"], r["ang"][p], r) for r in recs if p in r["ang"]),
                     key=lambda q: q[0])
        if not pts:
            continue
        fin = pts[0][1]
        line, = ax.plot([q[0] for q in pts], [100 * (q[1] / fin - 1) for q in pts], "o-",
                        label="%.1f MPa (finest %.2f deg)" % (p, fin))
        for hh, v, r in pts:
            if r["status"] != "done":
                ax.plot([hh], [100 * (v / fin - 1)], "x", color="k", ms=8)
        if p in rich:
            ax.plot([0, pts[0][0]], [100 * (rich[p] / fin - 1), 0], ":", color=line.get_color())
            ax.plot([0], [100 * (rich[p] / fin - 1)], "*", color=line.get_color(), ms=11)
    for r in recs:
        ax.annotate("%g" % r["l_soft"], (r["h"], 0), textcoords="offset points",
                    xytext=(0, -14), fontsize=7, ha="center")
    ax.set_xlim(-0.05, 1.08 * hmax)
    ax.set_ylabel("angle against the finest mesh at that pressure (%)")
    ax.set_xlabel("element size h = (V / Tet10)^(1/3) (mm); labels: l_soft (mm); * Richardson;"
                  " x stopped", fontsize=8)
    ax.set_title(a.title, fontsize=10)
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8)
    done = [r for r in recs if r["status"] == "done"]
    bx.loglog([r["tet10"] for r in done], [r["cpu_s"] for r in done], "o-", label="CPU time (s)")
    bx.loglog([r["tet10"] for r in recs if r.get("factor_mem_mb")],
              [r["factor_mem_mb"] for r in recs if r.get("factor_mem_mb")], "s--",
              label="MUMPS factor memory (MB)")
    bx.loglog([r["tet10"] for r in recs], [r["maxrss_mb"] for r in recs], "^:",
              label="peak RSS (MB)")
    for r in recs:
        bx.annotate("%g" % r["l_soft"], (r["tet10"], r["maxrss_mb"]), textcoords="offset points",
                    xytext=(4, -10), fontsize=7)
    bx.set_xlabel("Tet10 elements")
    bx.set_title("cost of the sweep (1 thread; CPU time: the load-free measure)", fontsize=10)
    bx.grid(True, which="both", alpha=0.3)
    bx.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(a.out, dpi=110)
    print("wrote", a.out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("logs", nargs="*")
    ap.add_argument("--study", help="a tools/fem_mesh_study.py directory (CASE.json files)")
    ap.add_argument("--volume", type=float, default=7354.7,
                    help="solid volume, mm^3, for h (default: fig1's II1 alone)")
    ap.add_argument("--title", default="FE mesh study: single segment (fig1 II1), Ω1&Ω2")
    ap.add_argument("--pressures", default="0.05,0.1,0.2")
    ap.add_argument("--out", default="docs/fem_mesh_study.png")
    a = ap.parse_args()
    if a.study:
        if a.pressures == "0.05,0.1,0.2":
            a.pressures = "0.1,0.2,0.3,0.4,0.5"
        return study(a)
    if not a.logs:
        sys.exit("plot_fem_mesh_study: give LOG files or --study DIR")
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

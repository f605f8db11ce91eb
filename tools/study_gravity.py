#!/usr/bin/python3
"""Where the flat-road walk fails: the track against gravity (a stability study, not a test).

usage: /usr/bin/python3 tools/study_gravity.py [--crawlsim BIN] [--gait CSV]... [--g G,G,...]
                                             [--legs rod,strain] [--outdir DIR] [--png FILE]
                                             [--reuse] [-- EXTRA RUN ARGS]

Runs `crawlsim run --scene flat-road --legs L --gravity G` for every leg level L (default rod;
`--legs rod,strain` puts the two models side by side), every gait and every G (m/s^2), reads each
run's HDF5 file and its stance check (load per standing leg over the legs' sway-buckling load,
printed by `crawlsim run`), and prints one markdown row per run: stance ratio, x (mm) at whole
seconds, the worst error against the paper's Table 2 for t >= 2 s, and how the run ended.
The PNG shows x(t) of every run over Table 2, and the final x (or the time of the fall) against
the stance ratio. Runs are sequential. The results of docs/studies/earth_gravity.md were
measured with prb legs (retired 2026-12-06), whose files kept the bare gait's name.
Table 2 is reporting data here, as in track_table.py.
"""
import argparse
import os
import re
import subprocess
import sys

import h5py
import numpy as np

TABLE2 = [0, 0, 39, 78, 117, 156, 195, 234, 273, 312]  # paper Table 2, x (mm) at t = 0..9 s
ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def run_one(binary, gait, g, out, extra, reuse, legs="rod"):
    cmd = [binary, "run", "--scene", "flat-road", "--legs", legs, "--gait", gait,
           "--gravity", "%g" % g, "--out", out] + extra
    log = os.path.splitext(out)[0] + ".log"
    if reuse and os.path.exists(out) and os.path.exists(log):
        rc, text = 0, open(log).read()
    else:
        p = subprocess.run(cmd, capture_output=True, text=True)
        rc, text = p.returncode, p.stdout + p.stderr
        with open(log, "w") as f:
            f.write(text)
    m = re.search(r"stance check: ([0-9.]+) N per leg .*?\(([0-9.]+) %\)", text)
    ratio = float(m.group(2)) / 100 if m else float("nan")
    stop = re.search(r"crawlsim run: t = ([0-9.]+) s: (.*)", text)
    if not os.path.exists(out):
        raise RuntimeError("%s wrote no output:\n%s" % (" ".join(cmd), text))
    with h5py.File(out, "r") as f:
        t = f["time"][:]
        x = f["support/position"][:, 0]
        q = f["support/orientation"][:]
    # tilt of the support: angle of its body y axis from the world y axis (deg)
    w, qx, qy, qz = q[:, 0], q[:, 1], q[:, 2], q[:, 3]
    ybody_y = 1 - 2 * (qx * qx + qz * qz)
    tilt = np.degrees(np.arccos(np.clip(ybody_y, -1, 1)))
    return {"t": t, "x": x, "ratio": ratio, "rc": rc,
            "stop": (float(stop.group(1)), stop.group(2)) if stop else None,
            "max_tilt": float(np.max(tilt))}


def at_seconds(r):
    vals = []
    for s in range(10):
        i = np.where(np.abs(r["t"] - s) < 1e-6)[0]
        vals.append(float(r["x"][i[0]]) if len(i) else None)
    return vals


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--crawlsim", default=os.path.join(ROOT, "build", "tools", "crawlsim"))
    ap.add_argument("--gait", action="append")
    ap.add_argument("--g", default="1,2,3,4,5,6,8,9.81")
    ap.add_argument("--legs", default="rod", help="leg levels, comma separated (rod,strain)")
    ap.add_argument("--outdir", default=os.path.join(ROOT, "out", "gravity"))
    ap.add_argument("--png", default=None)
    ap.add_argument("--reuse", action="store_true",
                    help="reuse runs already in --outdir (their .h5 and .log) instead of rerunning")
    ap.add_argument("extra", nargs="*")
    a = ap.parse_args()
    gaits = a.gait or [os.path.join(ROOT, "gaits", "flat_road_paper.csv"),
                       os.path.join(ROOT, "gaits", "flat_road_crouch.csv")]
    try:
        gs = [float(v) for v in a.g.split(",")]
    except ValueError:
        print("study_gravity: --g: expected numbers separated by commas, got '%s'" % a.g,
              file=sys.stderr)
        return 1
    os.makedirs(a.outdir, exist_ok=True)
    runs = []
    levels = [v for v in a.legs.split(",") if v]
    print("| legs | gait | g (m/s²) | stance load / buckling | " +
          " | ".join("x(%d)" % s for s in range(1, 10)) + " | max err t≥2 | outcome |")
    print("|---|---|---|---|" + "---|" * 9 + "---|---|")
    cases = [(legs, gait, g) for legs in levels for gait in gaits for g in gs]
    for legs, gait, g in cases:
        name = os.path.splitext(os.path.basename(gait))[0]
        tag = "%s_%s" % (legs, name)
        out = os.path.join(a.outdir, "%s_g%g.h5" % (tag, g))
        r = run_one(a.crawlsim, gait, g, out, a.extra, a.reuse, legs)
        r["gait"], r["g"] = (name if len(levels) == 1 else "%s %s" % (legs, name)), g
        runs.append(r)
        xs = at_seconds(r)
        errs = [abs(xs[s] - TABLE2[s]) / TABLE2[s] for s in range(2, 10) if xs[s] is not None]
        complete = r["stop"] is None and xs[9] is not None
        err = "%.0f %%" % (100 * max(errs)) if complete and errs else "-"
        if r["stop"]:
            outcome = "stopped at %.2f s: %s" % r["stop"]
        else:
            outcome = "completed, max tilt %.1f°" % r["max_tilt"]
        print("| %s | %s | %g | %.0f %% | %s | %s | %s |" % (
            legs, name, g, 100 * r["ratio"],
            " | ".join("%.0f" % v if v is not None else "-" for v in xs[1:]), err, outcome),
            flush=True)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
        ax1.plot(range(10), TABLE2, "ks", label="paper Table 2", zorder=5)
        cmap = plt.get_cmap("viridis")
        styles = {n: ls for n, ls in zip(sorted({r["gait"] for r in runs}),
                                         ["-", "--", ":", "-."])}
        for r in runs:
            c = cmap(min(r["ratio"], 1.0))
            ax1.plot(r["t"], r["x"], styles[r["gait"]], color=c, lw=1.2,
                     label="%s, g = %g" % (r["gait"], r["g"]))
        ax1.set_xlabel("t (s)")
        ax1.set_ylabel("support x (mm)")
        ax1.set_ylim(-100, 400)
        ax1.set_title("flat road: support x against gravity")
        ax1.legend(fontsize=6, ncol=2)
        for k, name in enumerate(styles):
            rr = [r for r in runs if r["gait"] == name]
            ratio = [r["ratio"] for r in rr]
            xend = [r["x"][-1] for r in rr]
            line, = ax2.plot(ratio, xend, styles[name], lw=1, label="%s: x where the run ended" % name)
            for r in rr:
                fell = r["stop"] is not None
                ax2.plot(r["ratio"], r["x"][-1], "x" if fell else "o", color=line.get_color(), ms=7)
                if fell:
                    ax2.annotate("fell at %.1f s" % r["stop"][0], (r["ratio"], r["x"][-1]),
                                 textcoords="offset points", xytext=(4, 4 + 10 * k), fontsize=7,
                                 color=line.get_color())
        ax2.axhline(312, color="k", lw=0.8, ls=":")
        ax2.text(0.02, 318, "Table 2 final, 312 mm", fontsize=7)
        ax2.set_xlabel("stance load per leg / sway-buckling load (g = 9.81: %.2f)" %
                       max(r["ratio"] for r in runs))
        ax2.set_ylabel("support x at the end (mm); o completed at 9 s, x fell")
        ax2.set_title("walk against leg load")
        ax2.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print("study_gravity: wrote %s" % a.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())

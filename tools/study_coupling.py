#!/usr/bin/python3
"""Coupling study: where the staggered scheme fails with rod legs, and how far the stabilised
one stays from a tightly coupled reference, against the macro step (a study, not a test).

usage: /usr/bin/python3 tools/study_coupling.py [--crawlsim BIN] [--t-end S] [--outdir DIR]
                                              [--png FILE] [--reuse] [-- EXTRA RUN ARGS]

Runs `crawlsim run --scene flat-road --legs rod --gait gaits/flat_road_paper.csv --conditions
paper --t-end S --dt H --coupling C` (one ODE step per macro step: H = h) for the staggered
scheme at H = 20 .. 50 us, the stabilised one at H = 50 us .. 10 ms and the Gauss-Seidel one
(the default) at H = 25 us .. 5 ms. The reference is the staggered scheme at H = 20 us
(converged there: 10 and 25 us move x(2 s) of the shipped gait by 0.03 mm). For every run
it prints the outcome and the largest distance of the support's centre from the reference's
over the run's output samples (every 10 ms, the reference interpolated to them), and x at the
end. The PNG plots that distance
against H (diverged runs as crosses at the top) and the tracks x(t). Runs are sequential; the
reference takes ~1 min of CPU per simulated second.
"""
import argparse
import os
import re
import subprocess
import sys

import h5py
import numpy as np

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
STAGGERED = [20e-6, 25e-6, 30e-6, 40e-6, 50e-6]
STABILISED = [50e-6, 100e-6, 250e-6, 500e-6, 1e-3, 2e-3, 5e-3, 10e-3]
GS = [25e-6, 250e-6, 500e-6, 1e-3, 2e-3, 5e-3]
REF = ("staggered", 20e-6)


def run_one(a, coupling, h):
    out = os.path.join(a.outdir, "%s_%gus.h5" % (coupling, h * 1e6))
    log = os.path.splitext(out)[0] + ".log"
    cmd = [a.crawlsim, "run", "--scene", "flat-road", "--legs", "rod", "--gait",
           os.path.join(ROOT, "gaits", "flat_road_paper.csv"), "--conditions", "paper",
           "--t-end", "%g" % a.t_end, "--dt", "%g" % h, "--coupling", coupling,
           "--output-dt", "0.01", "--quiet", "--out", out] + a.extra
    if a.reuse and os.path.exists(out) and os.path.exists(log):
        text = open(log).read()
    else:
        p = subprocess.run(cmd, capture_output=True, text=True)
        text = p.stdout + p.stderr
        with open(log, "w") as f:
            f.write(text)
    # a divergence ("crawlsim run: t = T s: ...") or a leg's failed advance ("crawlsim run: rod
    # advance from t = T s by ...")
    stop = re.search(r"crawlsim run: (.*?\bt = ([-0-9.]+) s.*)", text)
    r = {"coupling": coupling, "h": h, "stop": (float(stop.group(2)), stop.group(1)) if stop
         else None, "t": np.zeros(0), "p": np.zeros((0, 3))}
    if os.path.exists(out):
        with h5py.File(out, "r") as f:
            r["t"] = f["time"][:]
            r["p"] = f["support/position"][:]
    wall = re.search(r"wall time ([0-9.]+) s", text)
    r["wall"] = float(wall.group(1)) if wall else float("nan")
    return r


def distance(r, ref):
    """largest |p - p_ref| over the run's samples, the reference interpolated linearly to them
    (a macro step that does not divide 10 ms samples at its own multiples), and at the last (mm)"""
    if r["stop"] or len(r["t"]) == 0:
        return float("nan"), float("nan")
    t = r["t"][r["t"] <= ref["t"][-1] + 1e-9]
    pr = np.stack([np.interp(t, ref["t"], ref["p"][:, k]) for k in range(3)], axis=1)
    d = np.linalg.norm(r["p"][:len(t)] - pr, axis=1)
    return float(np.max(d)), float(d[-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--crawlsim", default=os.path.join(ROOT, "build", "tools", "crawlsim"))
    ap.add_argument("--t-end", type=float, default=1.0)
    ap.add_argument("--outdir", default=os.path.join(ROOT, "out", "coupling"))
    ap.add_argument("--png", default=None)
    ap.add_argument("--reuse", action="store_true",
                    help="reuse runs already in --outdir (their .h5 and .log) instead of rerunning")
    ap.add_argument("extra", nargs="*")
    a = ap.parse_args()
    os.makedirs(a.outdir, exist_ok=True)
    ref = run_one(a, *REF)
    if ref["stop"]:
        print("study_coupling: the reference stopped: %s" % (ref["stop"],), file=sys.stderr)
        return 1
    runs = []
    print("| coupling | H (µs) | outcome | max \\|Δp\\| (mm) | \\|Δp\\| at %g s (mm) | x at %g s "
          "(mm) | wall (s) |" % (a.t_end, a.t_end))
    print("|---|---|---|---|---|---|---|")
    for coupling, hs in (("staggered", STAGGERED), ("stabilised", STABILISED), ("gs", GS)):
        for h in hs:
            r = ref if (coupling, h) == REF else run_one(a, coupling, h)
            r["dmax"], r["dend"] = distance(r, ref)
            runs.append(r)
            outcome = ("diverged at t = %.3f s" % r["stop"][0]) if r["stop"] else "ran"
            xend = "%.2f" % r["p"][-1, 0] if not r["stop"] and len(r["t"]) else "-"
            print("| %s | %g | %s | %s | %s | %s | %.1f |" % (
                coupling, h * 1e6, outcome, "%.3f" % r["dmax"] if r["dmax"] == r["dmax"] else "-",
                "%.3f" % r["dend"] if r["dend"] == r["dend"] else "-", xend, r["wall"]),
                flush=True)
    if a.png:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
        top = 1e3
        for coupling, mk in (("staggered", "o-"), ("stabilised", "s-"), ("gs", "^-")):
            rr = [r for r in runs if r["coupling"] == coupling]
            ok = [r for r in rr if not r["stop"] and (r["coupling"], r["h"]) != REF]
            line, = ax1.loglog([r["h"] * 1e6 for r in ok], [max(r["dmax"], 1e-3) for r in ok],
                               mk, label="%s: max |Δp| over %g s" % (coupling, a.t_end))
            bad = [r for r in rr if r["stop"]]
            if bad:
                ax1.loglog([r["h"] * 1e6 for r in bad], [top] * len(bad), "x",
                           color=line.get_color(), ms=10, mew=2,
                           label="%s: diverged" % coupling)
        ax1.axhline(1.0, color="k", lw=0.8, ls=":")
        ax1.text(22, 1.15, "1 mm", fontsize=8)
        ax1.set_xlabel("macro step H = h (µs)")
        ax1.set_ylabel("distance of the support from the reference (mm)")
        ax1.set_title("rod legs, flat road (paper's table, paper conditions): "
                      "reference staggered 20 µs", fontsize=9)
        ax1.legend(fontsize=7)
        ax2.plot(ref["t"], ref["p"][:, 0], "k-", lw=2, label="reference (staggered 20 µs)")
        for r in runs:
            if r["stop"] or (r["coupling"], r["h"]) == REF or r["coupling"] == "staggered":
                continue
            if r["h"] not in (250e-6, 1e-3, 2e-3):
                continue
            ax2.plot(r["t"], r["p"][:, 0], lw=1, ls="-" if r["coupling"] == "gs" else "--",
                     label="%s %g µs" % (r["coupling"], r["h"] * 1e6))
        ax2.set_xlabel("t (s)")
        ax2.set_ylabel("support x (mm)")
        ax2.set_title("tracks")
        ax2.legend(fontsize=7)
        fig.tight_layout()
        fig.savefig(a.png, dpi=110)
        print("study_coupling: wrote %s" % a.png)
    return 0


if __name__ == "__main__":
    sys.exit(main())

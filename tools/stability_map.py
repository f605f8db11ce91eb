#!/usr/bin/python3
"""stability_map.py: where the co-simulation stops working, and how it says so (issue 11).

Short `crawlsim run` processes (the flat road, the paper's printed table
gaits/flat_road_paper.csv under `paper`: the gait that walks on both levels) swept over one
setting at a time from the default (rod legs, stabilised coupling, h = H = 1 ms):
  coupling x macro step   staggered at H = 25 us .. 1 ms; stabilised at H = 1 .. 200 ms as
                          macro steps of 1 ms ODE steps, and at h = H = 2 .. 10 ms
  contact stiffness       --contact-scale 1e-4 .. 1e5 (the rod's soft foundation modulus; the
                          committed map also swept prb legs, retired 2026-12-06)
  pressure                --pressure-scale up to 0.5 MPa of the table's 0.1744 MPa, with the
                          FE calibration (its range ends at 0.3 MPa) and with the provisional
                          one (analytic x 3.08, no range limit); and one actuator's bend past
                          360 deg (`crawlsim bend --until-angle 360`)
Each run lasts --t-end s (2) after the 0.3 s settling; staggered runs 0.2 s (25 us steps are
costly and the staggered limit shows while settling). Each run is classified from its exit status and its own one-line error: finishes, diverges
(runaway speed or a non-finite state), integrator failure (CVODE), map out of range, falls,
tips over (a finished run whose support tilted past 30 deg), or hangs (killed after
--timeout s: a hang is a failure mode too). A finished run also gets its distance from the
same level's default run at the common end time (a run can finish and be wrong). The
contact depth column is ODE's (the support; the committed map's prb feet); the rod legs' own
soft contact is not in it.

Writes docs/stability_map.csv and docs/stability_map.png (--out-dir); runs cached in --work.
Usage: /usr/bin/python3 tools/stability_map.py [--crawlsim build/tools/crawlsim]
         [--t-end 1.0] [--timeout 300] [--work DIR] [--out-dir docs]
"""

import argparse
import csv
import json
import math
import os
import re
import resource
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
PROG = "stability_map.py"
GAIT_P_MAX = 0.1744  # MPa: the highest pressure of gaits/flat_road_paper.csv (its header)

OUTCOMES = ["finishes", "finishes, off > 10 mm", "tips over", "diverges", "integrator failure",
            "map out of range", "falls", "hangs (timeout)", "other failure"]
COLOURS = {"finishes": "tab:green", "finishes, off > 10 mm": "gold",
           "tips over": "magenta", "diverges": "tab:red", "integrator failure": "tab:purple",
           "map out of range": "tab:orange", "falls": "tab:brown", "hangs (timeout)": "black",
           "other failure": "tab:gray"}


def cases(a):
    """(axis, label, value, args) of every run"""
    out = []
    for H in [25e-6, 50e-6, 100e-6, 1e-3]:
        out.append(("macro step H (s)", "staggered, h = H", H,
                    ["--legs", "rod", "--coupling", "staggered", "--dt", f"{H:g}",
                     "--t-end", "0.2"]))  # 0.2 s: 25 us steps are costly; the limit shows early
    for n in [1, 2, 5, 10, 50, 200]:
        out.append(("macro step H (s)", "stabilised, h = 1 ms", n * 1e-3,
                    ["--legs", "rod", "--macro-steps", str(n)]))
    for h in [2e-3, 5e-3, 1e-2]:
        out.append(("macro step H (s)", "stabilised, h = H", h, ["--legs", "rod", "--dt", f"{h:g}"]))
    for k in [1e-4, 1e-3, 1e-2, 0.1, 1, 10, 1e3, 1e5]:
        out.append(("contact stiffness scale", "rod", k,
                    ["--legs", "rod", "--contact-scale", f"{k:g}"]))
    prov = os.path.join(ROOT, "robot", "calibration_provisional.txt")
    # 0.29, not 0.3: the FE table ends at 0.3 MPa and a scaled 0.1744 lands a rounding above it
    for p in [0.1744, 0.25, 0.29, 0.35, 0.5]:
        s = p / GAIT_P_MAX
        out.append(("highest gait pressure (MPa)", "rod, FE calibration", p,
                    ["--legs", "rod", "--pressure-scale", f"{s:.6g}"]))
        out.append(("highest gait pressure (MPa)", "rod, provisional calibration", p,
                    ["--legs", "rod", "--pressure-scale", f"{s:.6g}", "--calibration", prov]))
    return out


def classify(rc, last, tilt):
    if rc == -999:
        return "hangs (timeout)"
    if rc == 0:
        return "tips over" if tilt > 30 else "finishes"
    if "CVODE" in last or "integrator" in last:
        return "integrator failure"
    if "diverged" in last or "non-finite" in last or "nan" in last.lower():
        return "diverges"
    if "calibrated range" in last or "range" in last:
        return "map out of range"
    if "fell off" in last:
        return "falls"
    return "other failure"


def run_case(a, key, args):
    path = os.path.join(a.work, key + ".json")
    if os.path.exists(path):
        with open(path) as f:
            return json.load(f)
    out = os.path.join(a.work, key + ".h5")
    cmd = [a.crawlsim, "run", "--gait", os.path.join(ROOT, "gaits", "flat_road_paper.csv"),
           "--conditions", "paper", "--t-end", f"{a.t_end:g}", "--quiet", "--out", out] + args
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE", OMP_NUM_THREADS="1")
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    load = os.getloadavg()[0]
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           env=env, timeout=a.timeout)
        rc, err, so = p.returncode, p.stderr, p.stdout
    except subprocess.TimeoutExpired:
        rc, err, so = -999, f"killed after {a.timeout:g} s", ""
    wall = time.monotonic() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    lines = [ln for ln in err.strip().splitlines() if ln.strip()]
    last = lines[-1] if lines else ""
    m = re.search(r"tilt ([-0-9.]+) deg", so)
    tilt = float(m.group(1)) if m else 0.0
    m = re.search(r"t = (-?[0-9.]+) s", last)
    res = {"cmd": " ".join(cmd[1:]), "rc": rc, "last": last, "tilt": tilt,
           "t_fail": float(m.group(1)) if (m and rc != 0) else None, "wall_s": wall,
           "cpu_s": (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime), "load": load,
           "h5": out, "stderr_lines": len(lines)}
    with open(path, "w") as f:
        json.dump(res, f, indent=1)
    return res


def end_state(path):
    """(t_end, x, z, max contact depth) of a run file, or None"""
    try:
        import h5py
        with h5py.File(path, "r") as f:
            t = f["/time"][:]
            p = f["/support/position"][:]
            d = f["/contact/max_depth"][:]
        if len(t) == 0:
            return None  # stopped before its first sample (while settling)
        return float(t[-1]), float(p[-1, 0]), float(p[-1, 2]), float(max(d.max(), 0))
    except (OSError, KeyError, ValueError):
        return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--crawlsim", default=os.path.join(ROOT, "build", "tools", "crawlsim"))
    # 2 s: the paper's table walks from its first swap at 1 s; a run that only stands still
    # would look right over the first second
    ap.add_argument("--t-end", type=float, default=2.0)
    ap.add_argument("--timeout", type=float, default=300)
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "stability_map"))
    ap.add_argument("--out-dir", default=os.path.join(ROOT, "docs"))
    a = ap.parse_args()
    if not os.access(a.crawlsim, os.X_OK):
        print(f"{PROG}: {a.crawlsim}: not an executable (build first)", file=sys.stderr)
        sys.exit(1)
    os.makedirs(a.work, exist_ok=True)
    # "off": distance at the end from the default run (rod: stabilised, 1 ms); not on the
    # pressure axis, where the gait itself changes
    bases = {"rod": run_case(a, "default-rod", ["--legs", "rod"])}
    rows = []
    for axis, label, value, args in cases(a):
        key = re.sub(r"[^A-Za-z0-9.]+", "_", f"{axis}-{label}-{value:g}")
        r = run_case(a, key, args)
        outcome = classify(r["rc"], r["last"], r["tilt"])
        es = end_state(r["h5"])
        base = bases["rod"]
        base_end = end_state(base["h5"]) if base["rc"] == 0 else None
        off = ""
        if "pressure" in axis:
            base_end = None
        if outcome == "finishes" and es and base_end and abs(es[0] - base_end[0]) < 1e-6:
            off = math.hypot(es[1] - base_end[1], es[2] - base_end[2])
            if off > 10:
                outcome = "finishes, off > 10 mm"
        rows.append({"axis": axis, "case": label, "value": value, "outcome": outcome,
                     "t_fail_s": "" if r["t_fail"] is None else r["t_fail"],
                     "off_default_mm": off, "max_depth_mm": es[3] if es else "",
                     "tilt_deg": r["tilt"], "error_lines": r["stderr_lines"],
                     "message": r["last"] if r["rc"] != 0 else "", "cpu_s": r["cpu_s"],
                     "wall_s": r["wall_s"], "load": r["load"], "command": r["cmd"]})
        print(f"  {axis} | {label} | {value:g}: {outcome} "
              f"{'' if r['t_fail'] is None else 't = %g s ' % r['t_fail']}{r['last'][:90]}",
              file=sys.stderr)
    # one actuator past 360 deg: the analytic model (no range), the rod on the analytic map
    # (no range) and the rod on the FE calibration (range 0.3 MPa)
    for model, p_max, extra in [("analytic", 0.5, []), ("rod", 1.5, ["--calibration", "analytic"]),
                                ("rod", 0.5, [])]:
        tag = model + ("-analytic-map" if extra else "")
        out = os.path.join(a.work, f"bend360-{tag}.h5")
        cmd = [a.crawlsim, "bend", "--model", model, "--actuator", "leg", "--chambers", "1,2",
               "--p-max", f"{p_max:g}", "--p-step", "0.05", "--until-angle", "360",
               "--out", out] + extra
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                           timeout=a.timeout)
        msg = (p.stderr.strip().splitlines() or [""])[-1] if p.returncode else ""
        if p.returncode == 0:
            import h5py
            with h5py.File(out, "r") as f:
                top = float(f["/angle_total_deg"][-1])
                pu = float(f.attrs.get("p_until_angle_MPa", float("nan")))
            msg = f"360 deg at {pu:.4g} MPa; {top:.0f} deg at {p_max:g} MPa"
        label = f"bend --model {model}" + (" --calibration analytic" if extra else "")
        rows.append({"axis": "bend past 360 deg", "case": label, "value": p_max,
                     "outcome": "finishes" if p.returncode == 0 else
                     classify(p.returncode, msg, 0), "t_fail_s": "", "off_default_mm": "",
                     "max_depth_mm": "", "tilt_deg": "", "error_lines": len(
                         p.stderr.strip().splitlines()), "message": msg, "cpu_s": "",
                     "wall_s": "", "load": "", "command": " ".join(cmd[1:])})
        print(f"  {label}: {msg[:120]}", file=sys.stderr)
    os.makedirs(a.out_dir, exist_ok=True)
    cols = list(rows[0].keys())
    with open(os.path.join(a.out_dir, "stability_map.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=cols, lineterminator="\n")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()})
    chart(os.path.join(a.out_dir, "stability_map.png"), [r for r in rows
                                                          if r["axis"] != "bend past 360 deg"])
    print(f"{PROG}: {len(rows)} runs; wrote {a.out_dir}/stability_map.csv, stability_map.png",
          file=sys.stderr)


def chart(path, rows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    axes_names = list(dict.fromkeys(r["axis"] for r in rows))
    fig, axs = plt.subplots(len(axes_names), 1, figsize=(9, 2.3 * len(axes_names)))
    seen = set()
    for ax, name in zip(axs, axes_names):
        sub = [r for r in rows if r["axis"] == name]
        labels = list(dict.fromkeys(r["case"] for r in sub))
        for r in sub:
            y = labels.index(r["case"])
            lab = r["outcome"] if r["outcome"] not in seen else None
            seen.add(r["outcome"])
            ax.scatter(r["value"], y, s=90, color=COLOURS[r["outcome"]], label=lab,
                       edgecolors="k", zorder=3)
            if r["t_fail_s"] != "":
                ax.annotate(f"t={r['t_fail_s']:.2f}", (r["value"], y), fontsize=6.5,
                            xytext=(0, 7), textcoords="offset points", ha="center")
        ax.set_yticks(range(len(labels)))
        ax.set_yticklabels(labels, fontsize=8)
        ax.set_ylim(-0.6, len(labels) - 0.4)
        if "pressure" not in name:
            ax.set_xscale("log")
        ax.set_xlabel(name, fontsize=8)
        ax.grid(True, axis="x", alpha=0.3)
    fig.legend(loc="upper center", ncol=4, fontsize=7.5, frameon=False)
    fig.tight_layout(rect=(0, 0, 1, 0.93))
    fig.savefig(path, dpi=110)


if __name__ == "__main__":
    main()

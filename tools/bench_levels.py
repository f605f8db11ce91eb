#!/usr/bin/python3
"""bench_levels.py: speed against accuracy of the leg levels (issue 11), in one run.

Tasks (each point = one `crawlsim` process, timed as a whole: wall clock and CPU seconds of
the child from getrusage, with the load average beside them because the machine is shared):
  track  (3) flat-road and (4) obstacle track: `crawlsim run --scene S` for rod at several
         elements per segment (`--links`), macro steps
         (`--macro-steps`) and ODE steps (`--dt`); error = max over whole seconds of |(dx, dz)|
         of the support against a rod reference at a fine discretisation and a small step
         (--ref-*: 6 elements per segment, h = H = 0.25 ms); the same rod at 0.5 ms is one of
         the configurations, so the table shows how far the reference itself is from converged.
  bend   (1) one actuator's bend curve (`crawlsim bend --actuator leg`) for the chamber sets
         that have an FE reference at l_soft 4 mm: Omega1&Omega2 from the shipped pair table
         robot/calibration_fe_leg.h5 (an FE sweep), others from FE calibration case files
         (--fe-cases DIR, format "crawlsim-fe-calibration 1", equal-pressure modes only);
         analytic and rod models, and the FE itself at coarser meshes (--fe-meshes 6,5: ~4 min
         each); error = max over the reference's pressures of |tip difference| in mm;
         (2) the same actuator under a dead tip load, against the FE at the finest of
         --tip-meshes (5,6).

Writes (--out-dir, default docs/): levels_bench.csv (every point), levels_pareto.png (log-log
error against CPU time per task), and the `--legs auto` table (--table, default
robot/levels.csv: one row per scene and track configuration that finished). Finished points
are cached in --work (JSON beside each output file), so an interrupted run resumes; --fresh
discards the cache.

Usage: /usr/bin/python3 tools/bench_levels.py [--crawlsim build/tools/crawlsim]
         [--tasks track,bend] [--scenes flat-road,obstacle] [--obstacle-t-end 4]
         [--rod-configs 2x1,4x1,8x1,...,4x1t20,...] [--ref-links 16]
         [--strain-configs 3@1e-3o1,3@5e-3o2,2@5e-3o1a5e-4]
         [--ref-dt 2.5e-4] [--fe-meshes 6,5] [--tip-meshes 5,6]
         [--work DIR] [--out-dir docs] [--table robot/levels.csv]
       /usr/bin/python3 tools/bench_levels.py --plot-only   (redraw the chart from the CSV)
"""

import argparse
import csv
import json
import math
import os
import platform
import re
import resource
import subprocess
import sys
import time

import numpy as np

PROG = "bench_levels.py"
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
# the `--legs auto` table's header (robot/robot_levels.h reads exactly these columns)
# (format 4: step_tol_mm, 0 a fixed step, > 0 the adaptive step at that tolerance, dt_s its
# longest)
# (format 5: whole_run, the scene's whole default run judged against its goal: WHOLE_GOAL)
TABLE_COLUMNS = ["scene", "level", "links", "macro_steps", "dt_s", "rod_tol", "step_order",
                 "step_tol_mm", "error_mm", "whole_run", "cpu_s_per_s", "wall_s_per_s",
                 "machine"]
# What a scene's whole run must reach for whole_run 1: the run's own verdict (core/cs_api.c,
# its verdict line) "crawls": it ends without a stop (a fall, a divergence), upright, having
# moved (|x| or |z| >= 20 mm); on the obstacle also at the
# top: within 20 mm of Table 3's end point (x 646, z 270 mm; tools/obstacle_search.py END,
# issue 32's bound on the whole climb). A track window shorter than the run (the obstacle's
# first 4 s) cannot see a fall at 12 s: the column is why `--legs auto` never picks such a row.
WHOLE_GOAL = {"obstacle": ((646.0, 270.0), 20.0)}


def fail(msg):
    print(f"{PROG}: {msg}", file=sys.stderr)
    sys.exit(1)


def run_timed(cmd, timeout):
    """Run cmd; return (returncode, wall s, child CPU s (user + sys), last stderr line, stdout)."""
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE", OMP_NUM_THREADS="1")
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.monotonic()
    try:
        p = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                           timeout=timeout, text=True)
        rc, err, out = p.returncode, p.stderr, p.stdout
    except subprocess.TimeoutExpired as e:
        rc, err = -999, f"timeout after {timeout} s " + (e.stderr or b"").decode()[-200:]
        out = ""
    wall = time.monotonic() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    lines = [ln for ln in err.strip().splitlines() if ln.strip()]
    return rc, wall, cpu, (lines[-1] if lines else ""), out


def cached(work, key, compute, need=()):
    """The point's result from work/key.json (if it holds every key of need), or compute()
    stored there."""
    path = os.path.join(work, key + ".json")
    if os.path.exists(path):
        with open(path) as f:
            res = json.load(f)
        if all(k in res for k in need):
            return res
    res = compute()
    with open(path, "w") as f:
        json.dump(res, f, indent=1)
    return res


# ---------------------------------------------------------------------------------- tracks
def track_config_name(level, links, macro, dt, k=1.0, order=0, tol=0.0):
    return f"{level}-l{links}-m{macro}-dt{dt:g}" + (f"-k{k:g}" if k != 1 else "") + \
        (f"-o{order}" if order else "") + (f"-a{tol:g}" if tol else "")


def run_track(a, scene, level, links, macro, dt, k=1.0, order=0, tol=0.0, whole=False,
              need=()):
    """tol > 0: the strain level's adaptive step (--strain-step adaptive --step-tol tol, dt
    its longest step); whole: the scene's whole default run (the obstacle's track is otherwise
    its first --obstacle-t-end s); need: keys a cached result must hold (else it runs again)"""
    t_end = a.obstacle_t_end if scene == "obstacle" and not whole else 0
    key = f"track-{scene}-" + track_config_name(level, links, macro, dt, k, order, tol) + \
        (f"-t{t_end:g}" if t_end > 0 else "-whole" if scene == "obstacle" else "")
    out = os.path.join(a.work, key + ".h5")

    def compute():
        cmd = [a.crawlsim, "run", "--scene", scene, "--legs", level, "--links", str(links),
               "--quiet", "--out", out]
        if level == "rod":
            cmd += ["--macro-steps", str(macro)]
        if order:
            cmd += ["--step-order", str(order)]
        # always given: a level's own default step is not the configuration's (the strain
        # level's is 0.5 ms since the sixth session, so "1e-3" left out ran at 0.5 ms)
        cmd += ["--dt", f"{dt:g}"]
        if tol:
            cmd += ["--strain-step", "adaptive", "--step-tol", f"{tol:g}"]
        if k != 1:
            cmd += ["--rod-tol", f"{k:g}"]
        if t_end > 0:
            cmd += ["--t-end", f"{t_end:g}"]
        load = os.getloadavg()[0]
        rc, wall, cpu, last, stdout = run_timed(cmd, a.timeout)
        # the run's own verdict word (core/cs_api.c: falls, stops, tips over, crawls, stands),
        # from its verdict line on stdout
        m = re.search(r"^verdict \([^)]*\): (falls|stops|tips over|crawls|stands)", stdout,
                      re.M)
        res = {"task": scene, "scene": scene, "level": level, "links": links, "macro": macro,
               "dt": dt, "cmd": " ".join(cmd[1:]), "rc": rc, "wall_s": wall, "cpu_s": cpu,
               "load": load, "last": last, "h5": out, "verdict": m.group(1) if m else "none"}
        res.update(step_counts(out))
        return res

    return cached(a.work, key, compute, need)


def run_whole(a, scene, level, links, macro, dt, k=1.0, order=0, tol=0.0):
    """the scene's whole default run of a configuration (no --t-end), with its verdict"""
    return run_track(a, scene, level, links, macro, dt, k, order, tol, whole=True,
                     need=("verdict",))


def whole_verdict(res, scene):
    """(1 or 0, why): the whole run against the scene's goal (WHOLE_GOAL): the run's own
    verdict "crawls", and on the obstacle the end near Table 3's end point"""
    if res["rc"] != 0 or res["verdict"] != "crawls":
        return 0, f"{res['verdict']}: {res['last'][:120]}"
    if scene in WHOLE_GOAL:
        import h5py
        with h5py.File(res["h5"], "r") as f:
            p = f["/support/position"][:]
        (gx, gz), within = WHOLE_GOAL[scene]
        d = math.hypot(p[-1, 0] - gx, p[-1, 2] - gz)
        if d > within:
            return 0, f"ends {d:.1f} mm from the goal ({gx:g}, {gz:g}) mm"
        return 1, f"ends {d:.1f} mm from the goal"
    return 1, "crawls"


def step_counts(path):
    """the run file's step counts: steps and rejected_steps, and with the adaptive step its
    accepted and error-rejected steps and their lengths (s); {} without the file"""
    import h5py
    names = ["steps", "rejected_steps", "adaptive_steps", "adaptive_rejected_steps",
             "adaptive_h_min_s", "adaptive_h_median_s", "adaptive_h_max_s"]
    try:
        with h5py.File(path, "r") as f:
            return {n: float(f.attrs[n]) for n in names if n in f.attrs}
    except OSError:
        return {}


def read_track(path):
    import h5py
    with h5py.File(path, "r") as f:
        t = f["/time"][:]
        p = f["/support/position"][:]
        status = f.attrs.get("status", b"?")
    if isinstance(status, bytes):
        status = status.decode()
    return t, p, status


def track_error(res, ref):
    """max over whole seconds (both runs reached) of |(dx, dz)| in mm; NaN if none."""
    t, p, _ = read_track(res["h5"])
    tr, pr, _ = read_track(ref["h5"])
    worst = float("nan")
    for s in range(1, int(math.floor(min(t[-1], tr[-1]) + 1e-9)) + 1):
        i, j = int(np.argmin(abs(t - s))), int(np.argmin(abs(tr - s)))
        d = math.hypot(p[i, 0] - pr[j, 0], p[i, 2] - pr[j, 2])
        worst = d if math.isnan(worst) else max(worst, d)
    return worst


def sim_seconds(res):
    t, _, _ = read_track(res["h5"])
    return float(t[-1])


def adaptive_setting(res, tol):
    """the adaptive step's words for the bench CSV: tolerance, steps, rejections, lengths"""
    g = res.get
    return (f", adaptive tol {tol:g} mm: {g('adaptive_steps', float('nan')):.0f} steps, "
            f"{g('adaptive_rejected_steps', float('nan')):.0f} rejected by the error, "
            f"{g('rejected_steps', float('nan')):.0f} by the stages, h min/median/max "
            f"{g('adaptive_h_min_s', float('nan')) * 1e3:.3g}/"
            f"{g('adaptive_h_median_s', float('nan')) * 1e3:.3g}/"
            f"{g('adaptive_h_max_s', float('nan')) * 1e3:.3g} ms")


def tracks(a, rows, table):
    # "NxM", "NxM@DT", "NxMtK", "NxM@DTtK": N elements per segment, M macro steps, ODE step DT
    # (default 1 ms), the rod's CVODE tolerances x K (--rod-tol, default 1)
    rod_configs = []
    for c in (c for c in a.rod_configs.split(",") if c):
        c, _, k = c.partition("t")
        nm, _, dt = c.partition("@")
        n, m = (int(v) for v in nm.split("x"))
        rod_configs.append((n, m, float(dt) if dt else 1e-3, float(k) if k else 1.0))
    # "N@DToK[aTOL]": N bending modes per segment, tree step DT, step formula K (1 BE, 2
    # BDF2); with aTOL the adaptive step (--strain-step adaptive --step-tol TOL mm, DT its
    # longest step): a row of the auto table with step_tol_mm TOL
    strain_configs = []
    for c in (c for c in a.strain_configs.split(",") if c):
        c, _, tol = c.partition("a")
        c, _, o = c.partition("o")
        n, _, dt = c.partition("@")
        strain_configs.append((int(n), 1, float(dt) if dt else 1e-3, 1.0, int(o) if o else 0,
                               float(tol) if tol else 0.0))
    for scene in a.scenes.split(","):
        ref = run_track(a, scene, "rod", a.ref_links, 1, a.ref_dt)
        if ref["rc"] != 0:
            fail(f"the {scene} reference run failed: {ref['last']}")
        t_ref = sim_seconds(ref)
        configs = [("rod", n, m, dt, k, 0, 0.0) for n, m, dt, k in rod_configs]
        configs += [("strain",) + c for c in strain_configs]
        points = [(ref, "rod", a.ref_links, 1, a.ref_dt, 1.0, 0, True, 0.0)]
        for level, links, macro, dt, k, order, tol in configs:
            res = run_track(a, scene, level, links, macro, dt, k, order, tol)
            points.append((res, level, links, macro, dt, k, order, False, tol))
            print(f"  {scene} {level} links {links} macro {macro} rod tol {k:g}"
                  + (f" adaptive {tol:g} mm" if tol else "") + f": rc {res['rc']}, "
                  f"{res['cpu_s']:.1f} s CPU, {res['wall_s']:.1f} s wall", file=sys.stderr)
        # the reference's own error: the same rod at half its step (not a choice for auto)
        check = None
        if a.ref_check_dt:
            check = run_track(a, scene, "rod", a.ref_links, 1, a.ref_check_dt)
        for res, level, links, macro, dt, k, order, is_ref, tol in points + \
                ([(check, "rod", a.ref_links, 1, a.ref_check_dt, 1.0, 0, False, 0.0)] if check
                 else []):
            ok = res["rc"] == 0
            is_check = check is not None and res is check
            t_sim = sim_seconds(res) if os.path.exists(res["h5"]) else float("nan")
            err = 0.0 if is_ref else (track_error(res, ref) if ok else float("nan"))
            setting = f"links {links}" + (f", macro {macro} x {dt * 1e3:g} ms" if level == "rod"
                                         else f", dt {dt * 1e3:g} ms") + \
                (f", rod tol {k:g}" if k != 1 else "") + \
                ({1: ", BE", 2: ", BDF2"}.get(order, "") if level == "strain" else "") + \
                (adaptive_setting(res, tol) if tol else "")
            rows.append({"task": scene, "model": level, "setting": setting,
                         "error_mm": err, "wall_s": res["wall_s"], "cpu_s": res["cpu_s"],
                         "sim_s": t_sim, "load": res["load"], "status": "ok" if ok else
                         res["last"], "reference": "yes" if is_ref else
                         ("check of the reference" if is_check else ""),
                         "command": res["cmd"]})
            if ok and not is_ref and not is_check:
                whole = -1
                if a.whole:
                    whole, why = whole_verdict(run_whole(a, scene, level, links, macro, dt, k,
                                                         order, tol), scene)
                    print(f"  {scene} {level} links {links} {setting}: whole run {whole} "
                          f"({why})", file=sys.stderr)
                table.append({"scene": scene, "level": level, "links": links,
                              "macro_steps": macro, "dt_s": f"{dt:g}", "rod_tol": f"{k:g}",
                              "step_order": order, "step_tol_mm": f"{tol:g}",
                              "error_mm": f"{err:.2f}", "whole_run": whole,
                              "cpu_s_per_s": f"{res['cpu_s'] / t_ref:.3f}",
                              "wall_s_per_s": f"{res['wall_s'] / t_ref:.3f}",
                              "machine": a.machine})
        print(f"  {scene}: reference {t_ref:g} s simulated", file=sys.stderr)


# ---------------------------------------------------------------------------------- bends
def fe_references(a):
    """[(name, ratios R1..R4, pressure [M], tip [M,3], wall s)] of the FE at l_soft 4 mm."""
    import h5py
    refs = []
    with h5py.File(os.path.join(ROOT, "robot", "calibration_fe_leg.h5"), "r") as f:
        refs.append(("O12", (1.0, 1.0, 0.0, 0.0), f["/pressure"][:], f["/tip_position"][:],
                     float(f.attrs.get("wall_time_s", float("nan")))))
    # the calibration's modes and held-out cases (O1, O12r05, O12O34r3, H1 ...), as they exist
    if a.fe_cases and os.path.isdir(a.fe_cases):
        for fn in sorted(os.listdir(a.fe_cases)):
            if not fn.endswith(".h5"):
                continue
            try:
                with h5py.File(os.path.join(a.fe_cases, fn), "r") as f:
                    if f.attrs.get("format", b"") != b"crawlsim-fe-calibration 1":
                        continue
                    for name, g in f["cases"].items():
                        r = tuple(float(g.attrs[f"ratio{k}"]) for k in range(1, 5))
                        if g.attrs.get("status", b"") != b"complete" or name == "O12" or \
                                g.attrs.get("kind", b"") == b"gravity" or max(r) <= 0:
                            continue
                        refs.append((name, r, g["pressure"][:], g["tip"][:],
                                     float(g.attrs.get("wall_time_s", float("nan")))))
            except (OSError, KeyError):
                continue
    return refs


def run_bend(a, name, ratios, model, p_max, p_step, mesh=None, tip=None, calib=None):
    key = f"bend-{name}-{model}" + (f"-h{mesh:g}" if mesh else "") + \
        (f"-tip{tip}" if tip else "") + (f"-cal{calib}" if calib else "")
    out = os.path.join(a.work, key + ".h5")

    def compute():
        cmd = [a.crawlsim, "bend", "--model", model, "--actuator", "leg", "--pressures",
               ",".join(f"{v:.6g}" for v in ratios), "--p-max", f"{p_max:g}", "--p-step",
               f"{p_step:g}", "--out", out]
        if mesh:
            cmd += ["--mesh-size", f"{mesh:g}"]
        if tip:
            cmd += ["--tip-load", tip]
        if calib:
            cmd += ["--calibration", calib]
        load = os.getloadavg()[0]
        rc, wall, cpu, last, _ = run_timed(cmd, a.fe_timeout if model == "fe" else a.timeout)
        return {"rc": rc, "wall_s": wall, "cpu_s": cpu, "load": load, "last": last, "h5": out,
                "cmd": " ".join(cmd[1:])}

    return cached(a.work, key, compute)


def bend_error(res, p_ref, tip_ref):
    """max over the reference's pressures of |tip difference| (mm); NaN if the run failed."""
    import h5py
    if res["rc"] != 0:
        return float("nan")
    with h5py.File(res["h5"], "r") as f:
        p, tip = f["/pressure"][:], f["/tip_position"][:]
    worst = 0.0
    for i, pv in enumerate(p):
        j = int(np.argmin(abs(p_ref - pv)))
        if abs(p_ref[j] - pv) < 1e-9:
            worst = max(worst, float(np.linalg.norm(tip[i] - tip_ref[j])))
    return worst


def bend_row(task, model, setting, res, err):
    return {"task": task, "model": model, "setting": setting, "error_mm": err,
            "wall_s": res["wall_s"], "cpu_s": res["cpu_s"], "sim_s": "", "load": res["load"],
            "status": "ok" if res["rc"] == 0 else res["last"], "reference": "",
            "command": res["cmd"]}


def bends(a, rows):
    """(1) bend curves against the FE at l_soft 4 mm; (2) under a tip load against the FE at
    the finest mesh run here (--tip-meshes, the first is the reference)."""
    import h5py
    for name, ratios, p_ref, tip_ref, fe_wall in fe_references(a):
        # the calibrated levels hold only up to the pair table's end (0.3 MPa): compare there
        p_max = min(float(p_ref[-1]), a.bend_p_max)
        step = float(p_ref[1] - p_ref[0])
        rs = ",".join(f"{v:g}" for v in ratios)
        task = f"(1) bend {name} (p x {rs}), 0-{p_max:g} MPa"
        # the reference itself, at the wall time its file records (not re-run; shared machine)
        rows.append({"task": task, "model": "fe", "setting": "l_soft 4 mm (reference, wall "
                     "time from the file)", "error_mm": 0.0, "wall_s": fe_wall, "cpu_s": float("nan"),
                     "sim_s": "", "load": "", "status": "ok", "reference": "yes",
                     "command": "crawlsim calibrate (FE case file)"})
        # rod: --mesh-size is its element length (12.5 mm = 4 per segment, the default)
        models = [("analytic", None, None), ("rod", 25.0, None), ("rod", 12.5, None),
                  ("rod", 6.25, None), ("rod", 12.5, "analytic")]
        models += [("fe", h, None) for h in a.fe_meshes] if name == "O12" else []
        for model, mesh, calib in models:
            res = run_bend(a, name, ratios, model, p_max, step, mesh, calib=calib)
            err = bend_error(res, p_ref, tip_ref)
            setting = (f"{'elements' if model == 'rod' else 'mesh'} {mesh:g} mm" if mesh
                       else "") + (", calibration analytic" if calib else "")
            rows.append(bend_row(task, model, setting, res, err))
            print(f"  bend {name} {model} {setting}: error {err:.3g} mm, "
                  f"{res['cpu_s']:.2f} s CPU", file=sys.stderr)
    # (2) the same actuator (Omega1&Omega2) under a dead tip load. Reference: the FE at the
    # finest --tip-meshes when given (no l_soft 4 mm FE run under a tip load exists), else the
    # rod at 3.125 mm elements (then the error is the rod's discretisation error only)
    meshes = sorted(a.tip_meshes)
    p_max, step = a.tip_p_max, 0.025
    if meshes:
        task = f"(2) bend O12 + tip load {a.tip_load} N vs FE {meshes[0]:g} mm"
        ref = run_bend(a, "O12", (1, 1, 0, 0), "fe", p_max, step, meshes[0], tip=a.tip_load)
        ref_label = ("fe", f"mesh {meshes[0]:g} mm")
    else:
        task = f"(2) bend O12 + tip load {a.tip_load} N vs rod 3.125 mm"
        ref = run_bend(a, "O12", (1, 1, 0, 0), "rod", p_max, step, 3.125, tip=a.tip_load)
        ref_label = ("rod", "elements 3.125 mm")
    if ref["rc"] != 0:
        print(f"  tip-load reference failed: {ref['last']}", file=sys.stderr)
        return
    with h5py.File(ref["h5"], "r") as f:
        p_ref, tip_ref = f["/pressure"][:], f["/tip_position"][:]
    rows.append(dict(bend_row(task, ref_label[0], ref_label[1], ref, 0.0), reference="yes"))
    for model, mesh, calib in [("rod", 50.0, None), ("rod", 25.0, None), ("rod", 12.5, None),
                               ("rod", 6.25, None)] + [("fe", h, None) for h in meshes[1:]]:
        res = run_bend(a, "O12", (1, 1, 0, 0), model, p_max, step, mesh, tip=a.tip_load,
                       calib=calib)
        err = bend_error(res, p_ref, tip_ref)
        setting = (f"{'elements' if model == 'rod' else 'mesh'} {mesh:g} mm" if mesh else "") \
            + (", calibration analytic" if calib else "")
        rows.append(bend_row(task, model, setting, res, err))
        print(f"  tip load {model} {setting}: error {err:.3g} mm", file=sys.stderr)


# ---------------------------------------------------------------------------------- output
def write_csv(path, rows, columns):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=columns, lineterminator="\n")
        w.writeheader()
        for r in rows:
            w.writerow({k: (f"{v:.4g}" if isinstance(v, float) else v) for k, v in r.items()
                        if k in columns})


# issue 32's targets drawn on the track charts: the error bound against the converged
# reference (the flat road 3 mm, the obstacle's first 4 s 2 mm) and 100x real time
TRACK_BOUND_MM = {"flat-road": 3.0, "obstacle": 2.0}
TARGET_RT = 100.0


def pareto_front(points):
    """the points no other point beats in both cost and error (lower-left), sorted by cost"""
    front, best = [], float("inf")
    for x, e, lab in sorted(points):
        if e < best:
            front.append((x, e, lab))
            best = e
    return front


def pareto_png(path, rows, machine):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    tasks = list(dict.fromkeys(r["task"] for r in rows))
    ncol = min(3, len(tasks))
    nrow = (len(tasks) + ncol - 1) // ncol
    fig, axes = plt.subplots(nrow, ncol, figsize=(6.2 * ncol, 4.8 * nrow), squeeze=False)
    for ax in axes.flat[len(tasks):]:
        ax.axis("off")
    colours = {"prb": "tab:blue", "rod": "tab:orange", "strain": "tab:purple", "analytic": "tab:green",
               "fe": "tab:red"}
    for ax, task in zip(axes.flat, tasks):
        track = "bend" not in task
        pts, seen = [], set()
        for r in (r for r in rows if r["task"] == task and r["status"] == "ok"):
            # the l_soft 4 mm FE references record their wall time only (shared machine)
            x = r["cpu_s"] if math.isfinite(r["cpu_s"]) else r["wall_s"]
            sim_s = float(r.get("sim_s") or "nan") if track else float("nan")
            if track and math.isfinite(sim_s) and sim_s > 0:
                x /= sim_s  # CPU s per simulated s: the real-time factor's inverse
            label = f"{r['model']} {r['setting']}".replace("links ", "n").replace(
                "elements ", "").replace("calibration analytic", "analytic map").replace(
                " (reference, wall time from the file)", " ref").replace(
                "macro 1 x ", "").replace(", rod tol", " tol").strip()
            # an adaptive point's setting carries its step statistics after ":" (kept in the csv)
            label = label.split(":")[0].replace("dt 5 ms, BE, adaptive tol ", "adaptive ")
            if r["reference"] == "yes":
                # the reference has no error against itself: a vertical line at its cost
                ax.axvline(x, color=colours.get(r["model"], "k"), ls=":", lw=1)
                ax.annotate("reference: " + label, (x, 0.02), xycoords=("data", "axes fraction"),
                            fontsize=6.5, rotation=90, ha="right", va="bottom")
                continue
            e = max(r["error_mm"], 1e-3)
            mk = "s" if r["reference"] else "o"
            ax.loglog(x, e, mk, color=colours.get(r["model"], "k"), ms=6,
                      label=r["model"] if r["model"] not in seen else None)
            seen.add(r["model"])
            pts.append((x, e, label))
        front = pareto_front(pts)
        if front:
            ax.loglog([p[0] for p in front], [p[1] for p in front], "-", color="0.5", lw=0.8,
                      zorder=0, label="front")
        for x, e, lab in front:  # label the front only: the rest is in levels_bench.csv
            ax.annotate(lab, (x, e), fontsize=6.5, xytext=(4, 3), textcoords="offset points")
        if track:
            if task in TRACK_BOUND_MM:
                ax.axhline(TRACK_BOUND_MM[task], color="tab:green", ls="--", lw=0.8)
                ax.annotate(f"bound {TRACK_BOUND_MM[task]:g} mm", (0.01, TRACK_BOUND_MM[task]),
                            xycoords=("axes fraction", "data"), fontsize=6.5, va="bottom",
                            color="tab:green")
            ax.axvline(1.0 / TARGET_RT, color="tab:red", ls="--", lw=0.8)
            ax.annotate(f"{TARGET_RT:g}x real time", (1.0 / TARGET_RT, 0.98),
                        xycoords=("data", "axes fraction"), fontsize=6.5, rotation=90,
                        ha="left", va="top", color="tab:red")
            ax.axvline(1.0, color="0.4", ls="--", lw=0.6)
            ax.annotate("real time", (1.0, 0.98), xycoords=("data", "axes fraction"),
                        fontsize=6.5, rotation=90, ha="left", va="top", color="0.4")
            lo = min([p[0] for p in pts] + [1.0 / TARGET_RT])
            hi = max([p[0] for p in pts] + [1.0])
            ax.set_xlim(lo / 2, hi * 6)
        ax.set_title(task, fontsize=9)
        ax.set_xlabel("CPU s (whole process; FE reference: its recorded wall s)" if not track
                      else "CPU s per simulated s (whole process)")
        ax.set_ylabel("error (mm)")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, loc="best")
    fig.suptitle(f"speed against accuracy of the leg levels ({machine})", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def replot(a):
    """levels_pareto.png again from the points of levels_bench.csv (a corrected or re-measured
    row), without running anything; the machine is the table's (robot/levels.csv) if it names
    one"""
    path = os.path.join(a.out_dir, "levels_bench.csv")
    try:
        with open(path, newline="") as f:
            rows = list(csv.DictReader(f))
    except OSError as e:
        fail(f"{path}: cannot read ({e.strerror})")
    need = ("task", "model", "setting", "error_mm", "cpu_s", "wall_s", "status", "reference")
    for n, r in enumerate(rows, start=2):
        if any(r.get(k) is None for k in need):
            fail(f"{path}:{n}: not a levels_bench.csv row (needs {', '.join(need)})")
        try:
            for k in ("error_mm", "cpu_s", "wall_s"):
                r[k] = float(r[k]) if r[k] not in ("", None) else float("nan")
        except ValueError:
            fail(f"{path}:{n}: error_mm, cpu_s or wall_s is not a number")
    machine = a.machine
    try:
        with open(a.table, newline="") as f:
            for r in csv.DictReader(line for line in f if not line.startswith("#")):
                machine = r.get("machine") or machine
                break
    except OSError:
        pass
    pareto_png(os.path.join(a.out_dir, "levels_pareto.png"), rows, machine)
    print(f"{PROG}: redrew {a.out_dir}/levels_pareto.png from {len(rows)} points",
          file=sys.stderr)


def machine_name():
    """'<n>-core <CPU model>' from /proc/cpuinfo (Linux), else the platform's name"""
    model = platform.processor() or platform.machine()
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{os.cpu_count()}-core {model}"


def whole_fill(a):
    """--whole-fill: the whole_run column of an existing table, from one whole run per row"""
    with open(a.whole_fill) as f:
        lines = f.read().splitlines()
    out, header = [], None
    for n, line in enumerate(lines, 1):
        if not line.strip() or line.lstrip().startswith("#"):
            out.append(line)
            continue
        if header is None:
            header = line.split(",")
            for c in ("scene", "level", "links", "dt_s", "error_mm"):
                if c not in header:
                    fail(f"{a.whole_fill}:{n}: the header has no column {c}")
            out.append(",".join(TABLE_COLUMNS))
            continue
        fields = line.split(",")
        if len(fields) != len(header):
            fail(f"{a.whole_fill}:{n}: {len(fields)} fields, expected {len(header)}")
        r = dict(zip(header, fields))
        r.setdefault("rod_tol", "1")
        r.setdefault("step_order", "0")
        r.setdefault("step_tol_mm", "0")
        res = run_whole(a, r["scene"], r["level"], int(r["links"]), int(r["macro_steps"]),
                        float(r["dt_s"]), float(r["rod_tol"]), int(r["step_order"]),
                        float(r["step_tol_mm"]))
        r["whole_run"], why = whole_verdict(res, r["scene"])
        print(f"  {a.whole_fill}:{n}: {r['scene']} {r['level']} links {r['links']} dt "
              f"{r['dt_s']} order {r['step_order']} tol {r['step_tol_mm']}: whole run "
              f"{r['whole_run']} ({why})", file=sys.stderr)
        out.append(",".join(str(r[c]) for c in TABLE_COLUMNS))
    if header is None:
        fail(f"{a.whole_fill}: no header line")
    with open(a.whole_fill, "w") as f:
        f.write("\n".join(out) + "\n")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--crawlsim", default=os.path.join(ROOT, "build", "tools", "crawlsim"))
    ap.add_argument("--tasks", default="track,bend")
    ap.add_argument("--scenes", default="flat-road,obstacle")
    # 4 s: the raise and the first pair steps (the gait before 2026-12-03 headed off the road
    # backwards from 3 s; the whole run is the README's "Obstacle road")
    ap.add_argument("--obstacle-t-end", type=float, default=4.0)
    ap.add_argument("--rod-configs",
                    default="2x1,4x1,8x1,12x1,4x2,8x2,8x1@5e-4,16x1@5e-4,2x1t20,4x1t20,"
                    "8x1t20",
                    help="rod elements per segment x macro steps [@ ODE step s] [t --rod-tol K], comma "
                    "separated")
    ap.add_argument("--strain-configs", default="3@1e-3o1,3@5e-3o2",
                    help="strain bending modes per segment [@ tree step s] [o step order: 1 BE, "
                    "2 BDF2] [a TOL: the adaptive step at --step-tol TOL mm, the tree step its "
                    "longest; a row of --table with step_tol_mm TOL], comma separated")
    # the reference the issues name (32, 33): the nodal rod converged in its elements and step,
    # 16 elements per segment at 0.25 ms; the same rod at twice its step (16x1@5e-4 in
    # --rod-configs) measures how far the reference itself may be from converged
    ap.add_argument("--ref-links", type=int, default=16)
    ap.add_argument("--ref-dt", type=float, default=2.5e-4)
    ap.add_argument("--ref-check-dt", type=float, default=0,
                    help="also run the reference at this step, not as a choice (0: skip)")
    ap.add_argument("--fe-meshes", default="6,5",
                    help="FE mesh sizes (mm) of task (1), against the l_soft 4 mm FE ('': none)")
    ap.add_argument("--fe-cases", default="docs/bench/calibration_cases_2026-12-03",
                    help="folder of FE case files (crawlsim calibrate --dir); a missing folder skips task (1)'s FE rows")
    ap.add_argument("--tip-meshes", default="5,6", help="FE mesh sizes (mm) of task (2), the "
                    "finest the reference ('': the rod at 3.125 mm elements instead)")
    ap.add_argument("--tip-load", default="0.05,0,0", help="task (2)'s tip force (N), base frame")
    ap.add_argument("--tip-p-max", type=float, default=0.3)
    # the FE-calibrated levels end at the shipped table's 0.3 MPa (they refuse to extrapolate)
    ap.add_argument("--bend-p-max", type=float, default=0.3)
    ap.add_argument("--timeout", type=float, default=1800)
    ap.add_argument("--fe-timeout", type=float, default=3600)
    ap.add_argument("--work", default=os.path.join(ROOT, "build", "bench_levels"))
    ap.add_argument("--out-dir", default=os.path.join(ROOT, "docs"))
    ap.add_argument("--table", default=os.path.join(ROOT, "robot", "levels.csv"))
    ap.add_argument("--machine", default=machine_name(),
                    help="where it ran (default: the CPU count and model; say if it was shared)")
    ap.add_argument("--no-whole", dest="whole", action="store_false",
                    help="do not run each configuration's whole scene (the obstacle's ~34 s "
                    "climb): whole_run -1 in the table")
    ap.add_argument("--whole-fill", metavar="TABLE",
                    help="only judge the whole runs of the rows of an existing table (any "
                    "format) and write it back as format 5, every other column and comment "
                    "kept (no track or bend runs)")
    ap.add_argument("--fresh", action="store_true")
    ap.add_argument("--plot-only", action="store_true",
                    help="redraw levels_pareto.png from --out-dir's levels_bench.csv (no runs)")
    a = ap.parse_args()
    if a.plot_only:
        replot(a)
        return
    a.machine = a.machine.replace(",", ";")  # the table has no quoting
    a.fe_meshes = [float(v) for v in a.fe_meshes.split(",") if v]
    a.tip_meshes = [float(v) for v in a.tip_meshes.split(",") if v]
    if not os.access(a.crawlsim, os.X_OK):
        fail(f"{a.crawlsim}: not an executable (build first, or give --crawlsim)")
    os.makedirs(a.work, exist_ok=True)
    if a.fresh:
        for fn in os.listdir(a.work):
            if fn.endswith(".json"):
                os.remove(os.path.join(a.work, fn))
    if a.whole_fill:
        whole_fill(a)
        return
    rows, table = [], []
    tasks = a.tasks.split(",")
    if "track" in tasks:
        tracks(a, rows, table)
    if "bend" in tasks:
        bends(a, rows)
    os.makedirs(a.out_dir, exist_ok=True)
    cols = ["task", "model", "setting", "error_mm", "cpu_s", "wall_s", "sim_s", "load",
            "status", "reference", "command"]
    write_csv(os.path.join(a.out_dir, "levels_bench.csv"), rows, cols)
    pareto_png(os.path.join(a.out_dir, "levels_pareto.png"), rows, a.machine)
    if table:
        with open(a.table, "w", newline="") as f:
            f.write("# crawlsim leg levels 5: written by tools/bench_levels.py; error_mm = max "
                    "over whole seconds of |support (dx, dz)| against a rod reference "
                    f"(links {a.ref_links}, dt {a.ref_dt:g} s); cpu_s_per_s = CPU seconds of "
                    "the whole process per simulated second; step_tol_mm 0: a fixed step, > 0: "
                    "the adaptive step at that tolerance, dt_s its longest; whole_run 1: "
                    "the scene's whole default run reaches its goal, 0: it does not, -1: not "
                    "judged (tools/bench_levels.py WHOLE_GOAL)\n")
            w = csv.DictWriter(f, fieldnames=TABLE_COLUMNS, lineterminator="\n")
            w.writeheader()
            for r in table:
                w.writerow(r)
    print(f"{PROG}: {len(rows)} points; wrote {a.out_dir}/levels_bench.csv, levels_pareto.png"
          + (f", {a.table}" if table else "") + f" ({platform.node()})", file=sys.stderr)


if __name__ == "__main__":
    main()

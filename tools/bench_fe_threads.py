#!/usr/bin/python3
"""The FE under load (issue 38): the same small FE command with one other busy process on the
machine, run by the default thread plan and pinned to one thread, alternately, and the ratio; and
optionally a study of two FE cases under `mpirun -n 2` against the same study run sequentially.

Usage: /usr/bin/python3 tools/bench_fe_threads.py --crawlsim build/tools/crawlsim
           [--repeat 3] [--configs default,pinned] [--mesh-size 4] [--p-max 0.1]
           [--busy 1] [--study] [--mpirun mpirun] [--out DIR] [--csv OUT.csv]
(--repeat 0 --study: the study comparison alone)

Configurations (each a separate process, in this order within a repetition, so that a slow spell
of the shared machine hits all of them):
  default    the command as a user types it (the thread plan, passive OpenMP waits);
  pinned     OMP_NUM_THREADS=1 (the reference of the target: default <= 1.10 x pinned);
  two        --threads 2 with passive waits (what the load-aware count avoids);
  spin2      --threads 2 with libgomp's spinning waits (GOMP_SPINCOUNT=300000, libgomp's own
             default before this change: what issue 38 measured, 3.3x slower).
The busy process is a CPU-bound Python loop started before and killed after each repetition.
Every row prints the 1-min load average before the run and the thread line of the banner. The
machine is shared: compare the ratios within a repetition, and the spread between repetitions.
The FE command is the issue's: baseline without fibres, chambers 1,2, 0 -> P-MAX MPa in steps
of 0.05, l_soft MESH-SIZE.
"""
import argparse
import csv
import os
import re
import subprocess
import sys
import tempfile
import time

CONFIGS = {
    "default": ({}, []),
    "pinned": ({"OMP_NUM_THREADS": "1"}, []),
    "two": ({}, ["--threads", "2"]),
    "spin2": ({"GOMP_SPINCOUNT": "300000"}, ["--threads", "2"]),
}


def fe_args(a, out):
    return ["bend", "--model", "fe", "--actuator", "baseline", "--set", "n1=0", "--set", "n2=0",
            "--set", "n3=0", "--chambers", "1,2", "--p-max", str(a.p_max), "--p-step", "0.05",
            "--mesh-size", str(a.mesh_size), "--out", out]


def clean_env():
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    for k in ("OMP_NUM_THREADS", "OMP_WAIT_POLICY", "GOMP_SPINCOUNT"):
        env.pop(k, None)
    return env


def run_fe(a, name, work):
    extra_env, extra_args = CONFIGS[name]
    env = clean_env()
    env.update(extra_env)
    out = os.path.join(work, f"{name}.h5")
    load = os.getloadavg()[0]
    t0 = time.time()
    p = subprocess.run([a.crawlsim] + fe_args(a, out) + extra_args, env=env,
                       capture_output=True, text=True)
    wall = time.time() - t0
    if p.returncode != 0:
        sys.exit(f"{name}: exit {p.returncode}:\n{p.stderr[-2000:]}")
    plan = re.search(r"fe: (\d+) threads? \(([^)]*)\)", p.stderr)
    fac = re.search(r"factorisation \(\S+, ([\d.e+]+) flops\) ran on (\d+)", p.stderr)
    total = re.findall(r"^\s+([\d.]+)\s+\S+\s+\S+\s+\S+\s+([-\d.]+)$", p.stdout, re.M)
    return {"config": name, "wall_s": round(wall, 2), "load1": round(load, 2),
            "threads": int(plan.group(1)) if plan else -1, "why": plan.group(2) if plan else "",
            "factor_threads": int(fac.group(2)) if fac else -1,
            "angle_deg": total[-1][1] if total else "?"}


def busy_start(n):
    return [subprocess.Popen([sys.executable, "-c", "while True: pass"]) for _ in range(n)]


def busy_stop(procs):
    for q in procs:
        q.kill()
        q.wait()


def study(a, work):
    """two FE cases: sequential study, then the same under mpirun -n 2"""
    text = ("study fe_pair\n"
            "defaults bend --model fe --actuator baseline --set n1=0 --set n2=0 --set n3=0"
            f" --chambers 1,2 --p-step 0.05 --mesh-size {a.mesh_size}\n"
            f"case a bend --p-max {a.p_max}\n"
            f"case b bend --p-max {a.p_max} --chambers 1\n")
    rows = []
    for mode in ("sequential", "mpirun -n 2"):
        d = tempfile.mkdtemp(dir=work, prefix="study_")
        f = os.path.join(d, "pair.study")
        with open(f, "w") as fh:
            fh.write(text)
        cmd = [a.crawlsim, "study", f, "--out", os.path.join(d, "pair.h5")]
        if mode != "sequential":
            cmd = [a.mpirun, "-n", "2"] + cmd
        load = os.getloadavg()[0]
        t0 = time.time()
        p = subprocess.run(cmd, env=clean_env(), capture_output=True, text=True, cwd=d)
        wall = time.time() - t0
        if p.returncode != 0:
            sys.exit(f"study ({mode}): exit {p.returncode}:\n{p.stderr[-2000:]}")
        rows.append({"config": "study " + mode, "wall_s": round(wall, 2), "load1": round(load, 2),
                     "threads": "", "why": "", "factor_threads": "", "angle_deg": ""})
        print(f"  study {mode:12s} {wall:8.1f} s (load {load:.2f})", flush=True)
    return rows


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--crawlsim", required=True)
    ap.add_argument("--repeat", type=int, default=3)
    ap.add_argument("--configs", default="default,pinned")
    ap.add_argument("--mesh-size", type=float, default=4)
    ap.add_argument("--p-max", type=float, default=0.1)
    ap.add_argument("--busy", type=int, default=1, help="other busy processes during FE runs")
    ap.add_argument("--study", action="store_true")
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--out", default=None, help="work directory (default: a temporary one)")
    ap.add_argument("--csv", default=None)
    a = ap.parse_args()
    a.crawlsim = os.path.abspath(a.crawlsim)
    work = a.out or tempfile.mkdtemp(prefix="bench_fe_threads_")
    os.makedirs(work, exist_ok=True)
    names = a.configs.split(",")
    for n in names:
        if n not in CONFIGS:
            sys.exit(f"unknown configuration {n} (expected {', '.join(CONFIGS)})")
    print(f"bench_fe_threads: {os.cpu_count()} CPUs, {a.busy} busy process(es) beside the FE; "
          f"work {work}", flush=True)
    rows = []
    for rep in range(a.repeat):
        procs = busy_start(a.busy)
        time.sleep(1.0)  # let the load sampling see it
        try:
            got = {}
            for n in names:
                r = run_fe(a, n, work)
                r["rep"] = rep + 1
                got[n] = r
                rows.append(r)
                print(f"  rep {rep + 1} {n:8s} {r['wall_s']:8.1f} s  load {r['load1']:5.2f}  "
                      f"{r['threads']} thread(s) ({r['why']}), factorisation on "
                      f"{r['factor_threads']}; total {r['angle_deg']} deg", flush=True)
        finally:
            busy_stop(procs)
        if "default" in got and "pinned" in got:
            print(f"  rep {rep + 1} ratio default / pinned = "
                  f"{got['default']['wall_s'] / got['pinned']['wall_s']:.3f}", flush=True)
    ratios = []
    for rep in range(1, a.repeat + 1):
        d = [r for r in rows if r["rep"] == rep and r["config"] == "default"]
        p = [r for r in rows if r["rep"] == rep and r["config"] == "pinned"]
        if d and p:
            ratios.append(d[0]["wall_s"] / p[0]["wall_s"])
    if ratios:
        ratios.sort()
        print(f"default / pinned: median {ratios[len(ratios) // 2]:.3f}, range "
              f"{ratios[0]:.3f}-{ratios[-1]:.3f} over {len(ratios)} repetitions (target <= 1.10)")
    if a.study:
        rows += study(a, work)
    if a.csv:
        with open(a.csv, "w", newline="") as fh:
            w = csv.DictWriter(fh, fieldnames=["rep", "config", "wall_s", "load1", "threads",
                                               "factor_threads", "why", "angle_deg"])
            w.writeheader()
            for r in rows:
                w.writerow({k: r.get(k, "") for k in w.fieldnames})


if __name__ == "__main__":
    main()

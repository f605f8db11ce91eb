#!/usr/bin/python3
"""FE speed before and after: runs the FE benchmark command (bench_fem_bend) of two builds on the
same sweeps and prints one table row per build and mesh: time per Newton iteration (assembly and
factorisation apart), per load step and per sweep.

Usage: /usr/bin/python3 tools/bench_fem_speed.py --after BUILD/tests/fem/bench_fem_bend
           [--before OLD/bench_fem_bend] [--meshes 5,4,3] [--p-max 0.1] [--p-step 0.05]
           [--actuator baseline] [--threads N] [--extra "ARGS"] [--csv OUT.csv]

The "before" binary is a build of an older commit (e.g. `git worktree add /tmp/old 21390b1`,
then cmake and build bench_fem_bend there). Each run is a separate process (OMP_NUM_THREADS and
OMP_WAIT_POLICY=PASSIVE set for both); wall times are only comparable on a quiet machine, so the
script prints the load average before each run, and the CPU seconds of the process beside the
wall time.
"""
import argparse
import os
import re
import resource
import subprocess
import sys
import tempfile
import time


def run(binary, actuator, mesh, p_max, p_step, extra, threads, work):
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
    if threads:
        env["OMP_NUM_THREADS"] = str(threads)
    cmd = [binary, actuator, str(mesh), str(p_max), str(p_step), "nan", "1,2", "--stem",
           os.path.join(work, f"m{mesh}")] + extra
    load = os.getloadavg()[0]
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    out = subprocess.run(cmd, env=env, capture_output=True, text=True)
    wall = time.time() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    text = out.stdout
    m = re.search(r"time: total ([\d.]+) s = mesh ([\d.]+) \+ setup ([\d.]+) \+ assembly ([\d.]+)"
                  r" \+ factorisation ([\d.]+) \+ solves ([\d.]+) .*?; (\d+) steps, (\d+) Newton "
                  r"iterations, (\d+) cutbacks; factor nnz ([\d.e+]+)", text)
    if not m:
        sys.exit(f"{binary}: no summary line (exit {out.returncode}):\n{out.stderr[-2000:]}")
    g = [float(x) for x in m.groups()]
    nfac = re.search(r"linear solves: (\S+), (\d+) factorisations", text)
    mesh_line = re.search(r"mesh: (\d+) Tet10, \d+ nodes, (\d+) dofs, (\d+) fibre elements", text)
    angles = re.findall(r"^p ([\d.]+) MPa .* total +([-\d.]+) deg", text, re.M)
    return {
        "total": g[0], "assembly": g[3], "factor": g[4], "solve": g[5], "steps": int(g[6]),
        "newton": int(g[7]), "cutbacks": int(g[8]), "factor_nnz": g[9],
        "nfactor": int(nfac.group(2)) if nfac else int(g[7]),
        "solver": nfac.group(1) if nfac else "mumps-lu",
        "tets": int(mesh_line.group(1)), "dofs": int(mesh_line.group(2)),
        "fibres": int(mesh_line.group(3)), "angle": angles[-1][1] if angles else "?",
        "wall": wall, "cpu": cpu, "load": load,
    }


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--after", required=True)
    ap.add_argument("--before")
    ap.add_argument("--meshes", default="5,4,3")
    ap.add_argument("--p-max", type=float, default=0.1)
    ap.add_argument("--p-step", type=float, default=0.05)
    ap.add_argument("--actuator", default="baseline")
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--extra", default="", help="extra arguments for the 'after' build")
    ap.add_argument("--csv")
    a = ap.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for mesh in [float(x) for x in a.meshes.split(",")]:
            for label, binary, extra in (("before", a.before, []),
                                         ("after", a.after, a.extra.split())):
                if not binary:
                    continue
                r = run(binary, a.actuator, mesh, a.p_max, a.p_step, extra, a.threads, work)
                r.update(build=label, mesh=mesh)
                rows.append(r)
                print(f"{label:6s} l_soft {mesh:g}: {r['tets']} Tet10, {r['dofs']} dofs, "
                      f"{r['fibres']} fibre el.; {r['solver']}; sweep {r['total']:.1f} s wall "
                      f"({r['cpu']:.1f} s CPU, load {r['load']:.2f}); {r['steps']} steps, "
                      f"{r['newton']} Newton it., {r['cutbacks']} cut-backs; per iteration "
                      f"assembly {r['assembly'] / r['newton']:.2f} s, factorisation "
                      f"{r['factor'] / max(r['nfactor'], 1):.2f} s; per step "
                      f"{r['total'] / r['steps']:.1f} s; total angle {r['angle']} deg",
                      flush=True)
    print("\n| build | l_soft | Tet10 | fibre el. | solver | factor entries | Newton it. | "
          "assembly / it. (s) | factorisation / it. (s) | per step (s) | sweep (s) | CPU (s) | "
          "angle at p_max (deg) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|")
    for r in rows:
        print(f"| {r['build']} | {r['mesh']:g} | {r['tets']} | {r['fibres']} | {r['solver']} | "
              f"{r['factor_nnz']:.3g} | {r['newton']} | {r['assembly'] / r['newton']:.2f} | "
              f"{r['factor'] / max(r['nfactor'], 1):.2f} | {r['total'] / r['steps']:.1f} | "
              f"{r['total']:.0f} | {r['cpu']:.0f} | {r['angle']} |")
    if a.csv:
        keys = ["build", "mesh", "tets", "dofs", "fibres", "solver", "factor_nnz", "steps",
                "newton", "cutbacks", "nfactor", "assembly", "factor", "solve", "total", "cpu",
                "load", "angle"]
        with open(a.csv, "w") as f:
            f.write(",".join(keys) + "\n")
            for r in rows:
                f.write(",".join(str(r[k]) for k in keys) + "\n")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""The FE's MUMPS over MPI ranks (issue 38): the same FE command by crawlsim-mpi on 1 rank and
under `mpirun -n N`, alternately, with the factorisation's time and MUMPS's memory per rank, and
the answer (total angle of the last row) of each; a markdown table at the end.

Usage: /usr/bin/python3 tools/bench_fe_mpi.py --crawlsim-mpi build/tools/crawlsim-mpi
           [--ranks 1,2] [--repeat 2] [--threads 1] [--mesh-size 4] [--p-max 0.1]
           [--fibres] [--mpirun mpirun] [--out DIR] [--csv OUT.csv]

The FE command is the issue's small one (baseline, chambers 1,2, 0 -> P-MAX in steps of 0.05,
l_soft MESH-SIZE, without fibres unless --fibres). Every run gets --threads THREADS per rank
(default 1: one core per rank on the 2-core machine, so the ranks, not the threads, are
measured). Wall times on a shared machine: the 1-min load average is printed before each run;
compare within a repetition.
"""
import argparse
import csv
import os
import re
import resource
import subprocess
import sys
import tempfile
import time


def run(a, ranks, work, rep):
    out = os.path.join(work, f"r{ranks}_{rep}.h5")
    fe = [a.crawlsim_mpi, "bend", "--model", "fe", "--actuator", "baseline", "--chambers", "1,2",
          "--p-max", str(a.p_max), "--p-step", "0.05", "--mesh-size", str(a.mesh_size),
          "--threads", str(a.threads), "--out", out]
    if not a.fibres:
        fe += ["--set", "n1=0", "--set", "n2=0", "--set", "n3=0"]
    cmd = fe if ranks == 1 else [a.mpirun, "-n", str(ranks)] + fe
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    for k in ("OMP_NUM_THREADS", "OMP_WAIT_POLICY", "GOMP_SPINCOUNT"):
        env.pop(k, None)
    load = os.getloadavg()[0]
    r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
    t0 = time.time()
    p = subprocess.run(cmd, env=env, capture_output=True, text=True)
    wall = time.time() - t0
    r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
    if p.returncode != 0:
        sys.exit(f"{ranks} ranks: exit {p.returncode}:\n{p.stderr[-3000:]}")
    s = re.search(r"fe: (\d+) tets, (\d+) nodes, \d+ fibre elements, \d+ steps, (\d+) Newton "
                  r"iterations; assembly ([\d.]+) s, factorisation ([\d.]+) s, solves ([\d.]+) s",
                  p.stderr)
    m = re.search(r"\(\S+, ([\d.e+]+) flops\) ran on (\d+) threads?.*?; its memory (\d+) MB "
                  r"\(the most on one rank: (\d+) MB\)", p.stderr)
    rows = re.findall(r"^\s+([\d.]+)\s+\S+\s+\S+\s+\S+\s+([-\d.]+)$", p.stdout, re.M)
    if not s or not m:
        sys.exit(f"{ranks} ranks: no summary lines:\n{p.stderr[-3000:]}")
    it = int(s.group(3))
    return {"ranks": ranks, "rep": rep, "wall_s": round(wall, 1), "load1": round(load, 2),
            "cpu_s": round(cpu, 1),
            "tets": int(s.group(1)), "dofs": 3 * int(s.group(2)), "newton": it,
            "assembly_s": float(s.group(4)), "factor_s": float(s.group(5)),
            "factor_per_it_s": round(float(s.group(5)) / max(it, 1), 3),
            "solve_s": float(s.group(6)), "flops": float(m.group(1)),
            "threads": int(m.group(2)), "mem_total_MB": int(m.group(3)),
            "mem_rank_MB": int(m.group(4)), "angle_deg": rows[-1][1] if rows else "?"}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--crawlsim-mpi", required=True)
    ap.add_argument("--ranks", default="1,2")
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--mesh-size", type=float, default=4)
    ap.add_argument("--p-max", type=float, default=0.1)
    ap.add_argument("--fibres", action="store_true")
    ap.add_argument("--mpirun", default="mpirun")
    ap.add_argument("--out", default=None)
    ap.add_argument("--csv", default=None)
    a = ap.parse_args()
    a.crawlsim_mpi = os.path.abspath(a.crawlsim_mpi)
    work = a.out or tempfile.mkdtemp(prefix="bench_fe_mpi_")
    os.makedirs(work, exist_ok=True)
    rows = []
    for rep in range(1, a.repeat + 1):
        for r in [int(x) for x in a.ranks.split(",")]:
            row = run(a, r, work, rep)
            rows.append(row)
            print(f"  rep {rep} {r} rank(s): wall {row['wall_s']} s (load {row['load1']}), "
                  f"{row['newton']} Newton it., factorisation {row['factor_s']} s "
                  f"({row['factor_per_it_s']} s/it.), MUMPS memory {row['mem_total_MB']} MB, "
                  f"most on one rank {row['mem_rank_MB']} MB; total {row['angle_deg']} deg",
                  flush=True)
    print("\n| ranks | rep | load (1 min) | wall (s) | CPU, all ranks (s) | Newton it. | factorisation (s) | per it. (s) "
          "| MUMPS memory, sum (MB) | most on one rank (MB) | total angle (deg) |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for w in rows:
        print(f"| {w['ranks']} | {w['rep']} | {w['load1']} | {w['wall_s']} | {w['cpu_s']} | "
              f"{w['newton']} | "
              f"{w['factor_s']} | {w['factor_per_it_s']} | {w['mem_total_MB']} | "
              f"{w['mem_rank_MB']} | {w['angle_deg']} |")
    if a.csv:
        with open(a.csv, "w", newline="") as fh:
            wr = csv.DictWriter(fh, fieldnames=list(rows[0].keys()))
            wr.writeheader()
            wr.writerows(rows)


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""FE mesh study (paper Table 1, issue 38): the same pressure sweep at each mesh size, one case
per l_soft, coarse to fine, with the cost of each.

Each case runs `crawlsim bend --model fe` (default: the paper's single segment, II1 of the fig1
actuator alone, Omega1 & Omega2, 0 -> 0.5 MPa in steps of 0.05 MPa, its Sec. 3.3 / Fig. 3a)
at one l_soft, and records, as soon as it ends, CASE.json and CASE.log in --out: the bending
angle (II1 and total) at every output pressure, Tet10, nodes, fibre elements, Newton
iterations, MUMPS's factor memory, the factorisation's flops and threads, the peak RSS, wall
time, CPU time (user + system of the process, getrusage: the honest cost on a shared machine)
and the 1-min load average sampled during the run. results.csv is rewritten from all CASE.json
after each case. --resume skips the cases whose CASE.json says "done". A case whose resident
memory passes --mem-limit-gb is stopped (status "memory"); one still running at --deadline
(UTC, HH:MM) is stopped (status "stopped") with the pressures it reached; both are rerun by
--resume. Cases run one after the other, each on --threads threads (default 1).

Usage:
  /usr/bin/python3 tools/fem_mesh_study.py [--crawlsim build/tools/crawlsim]
      [--sizes 4,3,2,1.5,1] [--segments 1|3] [--actuator fig1] [--chambers 1,2]
      [--p-max 0.5] [--p-step 0.05] [--threads 1] [--mem-limit-gb 12] [--deadline HH:MM]
      [--out docs/studies/fem_mesh] [--work out/fem_mesh] [--resume] [--refresh]
The chart and table: tools/plot_fem_mesh_study.py --study DIR.
"""
import argparse
import csv
import datetime
import glob
import json
import os
import re
import signal
import subprocess
import sys
import time

ROW_RE = re.compile(r"^\s+([\d.]+)\s+(-?[\d.]+|nan)\s+(-?[\d.]+|nan)\s+(-?[\d.]+|nan)\s+"
                    r"(-?[\d.]+|nan)\s*$")
PROG_RE = re.compile(r"fe: p = ([\d.]+) MPa \(dp [\d.]+\), (\d+) Newton iterations, (\d+) "
                     r"cut-backs, ([\d.]+) s, total (\S+) deg")
SUM_RE = re.compile(r"fe: (\d+) tets, (\d+) nodes, (\d+) fibre elements, (\d+) steps, (\d+) "
                    r"Newton iterations; assembly ([\d.]+) s, factorisation ([\d.]+) s, solves "
                    r"([\d.]+) s, total ([\d.]+) s")
MEM_RE = re.compile(r"factorisation \((\S+), ([\d.e+]+) flops\) ran on (\d+) thread.*its memory "
                    r"(\d+) MB")
THREAD_RE = re.compile(r"crawlsim bend: fe: (\d+ threads? \(.*?\));")


def case_name(l_soft):
    return "l%s" % ("%g" % l_soft).replace(".", "p")


def rss_mb(pid):
    """Resident memory of the process, MB (0 when it is gone)."""
    try:
        with open("/proc/%d/status" % pid) as f:
            for line in f:
                if line.startswith("VmRSS:"):
                    return int(line.split()[1]) / 1024.0
    except OSError:
        pass
    return 0.0


def msh_counts(path):
    """Tet10 elements and nodes of gmsh's mesh file (format 2.2, as fem_mesh writes it): the
    mesh of a case stopped before the CLI's summary. The FE may drop nothing from it (it fixes
    folded elements in place), so these are the counts it ran on."""
    tets = nodes = 0
    try:
        with open(path) as f:
            sect = None
            for line in f:
                if line.startswith("$"):
                    sect = line.strip()
                    first = True
                    continue
                if sect == "$Nodes" and first:
                    nodes, first = int(line), False
                elif sect == "$Elements":
                    if first:
                        first = False
                        continue
                    parts = line.split(None, 2)
                    if len(parts) > 1 and parts[1] == "11":
                        tets += 1
    except OSError:
        return None
    return tets, nodes


def parse_log(path, rec):
    """Angles and costs from the CLI's stderr/stdout (the same numbers as its HDF5 file)."""
    rows, prog = {}, {}
    with open(path, errors="replace") as f:
        for line in f:
            m = PROG_RE.search(line)
            if m:
                prog[round(float(m.group(1)), 6)] = float(m.group(5))
                rec["newton_progress"] = rec.get("newton_progress", 0) + int(m.group(2))
                continue
            m = SUM_RE.search(line)
            if m:
                keys = ("tet10", "nodes", "fibre_elements", "steps", "newton")
                for k, v in zip(keys, m.groups()[:5]):
                    rec[k] = int(v)
                for k, v in zip(("t_assembly_s", "t_factor_s", "t_solve_s", "t_fe_s"),
                                m.groups()[5:]):
                    rec[k] = float(v)
                continue
            m = MEM_RE.search(line)
            if m:
                rec["factor"], rec["factor_flops"] = m.group(1), float(m.group(2))
                rec["factor_threads"], rec["factor_mem_mb"] = int(m.group(3)), int(m.group(4))
                continue
            m = THREAD_RE.search(line)
            if m:
                rec["threads_why"] = m.group(1)
                continue
            m = ROW_RE.match(line)
            if m:
                rows[round(float(m.group(1)), 6)] = [float(m.group(2)), float(m.group(5))]
    # rows of the final table (3 decimals) where the run finished; otherwise the progress lines
    # (2 decimals, total only: II1 = total for a single segment)
    rec["angles"] = {("%.4f" % p): v for p, v in sorted(rows.items())}
    rec["angles_progress"] = {("%.4f" % p): v for p, v in sorted(prog.items())}


def run_case(a, l_soft):
    name = case_name(l_soft)
    log = os.path.join(a.out, name + ".log")
    h5 = os.path.join(a.work, name + ".h5")
    cmd = [a.crawlsim, "bend", "--model", "fe", "--actuator", a.actuator, "--chambers",
           a.chambers, "--p-max", str(a.p_max), "--p-step", str(a.p_step), "--mesh-size",
           "%g" % l_soft, "--threads", str(a.threads), "--out", h5]
    if a.segments == 1:
        cmd += ["--segments", "1"]
    rec = {"case": name, "l_soft": l_soft, "segments": a.segments, "actuator": a.actuator,
           "chambers": a.chambers, "p_max": a.p_max, "p_step": a.p_step, "threads": a.threads,
           "command": " ".join(cmd), "host_cpus": os.cpu_count(),
           "start_utc": datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M:%S")}
    env = dict(os.environ)
    for k in ("OMP_NUM_THREADS", "OMP_WAIT_POLICY", "GOMP_SPINCOUNT"):
        env.pop(k, None)
    loads, peak_rss, status = [], 0.0, "done"
    t0 = time.time()
    with open(log, "w") as lf:
        lf.write("# " + rec["command"] + "\n")
        lf.flush()
        p = subprocess.Popen(cmd, stdout=lf, stderr=subprocess.STDOUT, env=env)
        while True:
            pid, wst, ru = os.wait4(p.pid, os.WNOHANG)
            if pid == p.pid:
                break
            loads.append(os.getloadavg()[0])
            peak_rss = max(peak_rss, rss_mb(p.pid))
            if a.mem_limit_gb > 0 and peak_rss > 1024 * a.mem_limit_gb and status == "done":
                status = "memory"
                p.send_signal(signal.SIGINT)
            if a.deadline_ts and time.time() > a.deadline_ts and status == "done":
                status = "stopped"
                p.send_signal(signal.SIGINT)  # the CLI closes its file with the rows it has
            time.sleep(a.sample)
    rec["wall_s"] = time.time() - t0
    rec["cpu_s"] = ru.ru_utime + ru.ru_stime
    rec["cpu_user_s"], rec["cpu_sys_s"] = ru.ru_utime, ru.ru_stime
    rec["maxrss_mb"] = ru.ru_maxrss / 1024.0
    rec["exit"] = os.waitstatus_to_exitcode(wst)
    rec["load1_mean"] = sum(loads) / len(loads) if loads else os.getloadavg()[0]
    rec["load1_max"] = max(loads) if loads else rec["load1_mean"]
    rec["load_samples"] = len(loads)
    rec["end_utc"] = datetime.datetime.utcnow().strftime("%Y-%m-%d %H:%M:%S")
    if status == "done" and rec["exit"] != 0:
        status = "failed"
    rec["status"] = status
    parse_log(log, rec)
    counts = msh_counts(os.path.join(a.work, name + ".msh"))
    if counts:
        rec["tet10_msh"], rec["nodes_msh"] = counts
    with open(os.path.join(a.out, name + ".json"), "w") as f:
        json.dump(rec, f, indent=1, sort_keys=True)
    return rec


def write_csv(out):
    recs = []
    for path in glob.glob(os.path.join(out, "l*.json")):
        with open(path) as f:
            recs.append(json.load(f))
    recs.sort(key=lambda r: -r["l_soft"])
    ps = sorted({p for r in recs for p in list(r["angles"]) + list(r["angles_progress"])},
                key=float)
    cols = ["l_soft", "status", "tet10", "nodes", "fibre_elements", "newton", "factor_mem_mb",
            "maxrss_mb", "wall_s", "cpu_s", "threads", "load1_mean", "load1_max"]
    with open(os.path.join(out, "results.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(cols + ["total_deg_%s" % p for p in ps])
        for r in recs:
            ang = dict(r["angles_progress"])
            ang.update({p: v[1] for p, v in r["angles"].items()})
            w.writerow([r.get(c, "") for c in cols] + [ang.get(p, "") for p in ps])


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--crawlsim", default="build/tools/crawlsim")
    ap.add_argument("--sizes", default="4,3,2,1.5,1")
    ap.add_argument("--segments", type=int, choices=(1, 3), default=1)
    ap.add_argument("--actuator", default="fig1")
    ap.add_argument("--chambers", default="1,2")
    ap.add_argument("--p-max", type=float, default=0.5)
    ap.add_argument("--p-step", type=float, default=0.05)
    ap.add_argument("--threads", type=int, default=1)
    ap.add_argument("--mem-limit-gb", type=float, default=12.0)
    ap.add_argument("--deadline", default="", help="HH:MM UTC: stop the running case then")
    ap.add_argument("--sample", type=float, default=10.0, help="s between load/RSS samples")
    ap.add_argument("--out", default="docs/studies/fem_mesh")
    ap.add_argument("--work", default="out/fem_mesh")
    ap.add_argument("--resume", action="store_true")
    ap.add_argument("--refresh", action="store_true",
                    help="re-read the logs and meshes of the cases in --out (no runs)")
    a = ap.parse_args()
    if a.refresh:
        for path in glob.glob(os.path.join(a.out, "l*.json")):
            with open(path) as f:
                rec = json.load(f)
            parse_log(os.path.join(a.out, rec["case"] + ".log"), rec)
            counts = msh_counts(os.path.join(a.work, rec["case"] + ".msh"))
            if counts:
                rec["tet10_msh"], rec["nodes_msh"] = counts
            with open(path, "w") as f:
                json.dump(rec, f, indent=1, sort_keys=True)
        write_csv(a.out)
        return 0
    a.deadline_ts = 0
    if a.deadline:
        h, m = (int(x) for x in a.deadline.split(":"))
        now = datetime.datetime.utcnow()
        d = now.replace(hour=h, minute=m, second=0, microsecond=0)
        if d < now:
            d += datetime.timedelta(days=1)
        a.deadline_ts = time.time() + (d - now).total_seconds()
    os.makedirs(a.out, exist_ok=True)
    os.makedirs(a.work, exist_ok=True)
    for s in a.sizes.split(","):
        l_soft = float(s)
        done = os.path.join(a.out, case_name(l_soft) + ".json")
        if a.resume and os.path.exists(done):
            with open(done) as f:
                if json.load(f).get("status") == "done":
                    print("fem_mesh_study: %s done, skipped" % case_name(l_soft), flush=True)
                    continue
        if a.deadline_ts and time.time() > a.deadline_ts:
            print("fem_mesh_study: deadline passed, %s not started" % case_name(l_soft))
            break
        print("fem_mesh_study: %s (l_soft %g mm) started %s UTC, load %.2f" %
              (case_name(l_soft), l_soft, datetime.datetime.utcnow().strftime("%H:%M:%S"),
               os.getloadavg()[0]), flush=True)
        r = run_case(a, l_soft)
        write_csv(a.out)
        print("fem_mesh_study: %s %s: %s Tet10, wall %.0f s, CPU %.0f s, load %.1f, factor %s MB"
              % (r["case"], r["status"], r.get("tet10", "?"), r["wall_s"], r["cpu_s"],
                 r["load1_mean"], r.get("factor_mem_mb", "?")), flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())

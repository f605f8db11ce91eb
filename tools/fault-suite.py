#!/usr/bin/env python3
"""Fault-injection suite for crawlsim's outputs (docs/notes/faults.md), in the manner of
SQLite's I/O-error, malloc-failure and crash tests.

For each target (a rod-leg run, a small-mesh FE bend sweep) and each scenario (disk full,
read-only file system, allocation failure, SIGINT, SIGTERM, kill -9) the suite runs `crawlsim`
once per fault point and checks:
  * no crash: no exit by a signal we did not send, no sanitizer report;
  * a non-zero exit and, last on stderr, one line "crawlsim <cmd>: ..." naming the cause
    (No space left on device / Read-only file system / out of memory / interrupted);
  * every output file opens (HDF5 C API, tests/faults/h5_check), holds as many rows as its
    `samples` attribute says were flushed (every sample before its last flush), and its
    `status` says what happened ("running" only after kill -9, or on a read-only file system,
    where the status cannot be rewritten either); no "<file>.part" is left
    behind except after kill -9; an .xdmf beside a run is complete.
Fault points: write faults at the N-th write event of the shim (tests/faults/fault_shim.c),
every event of the HDF5 image writes and log-spaced ones over the rest (XDMF, VTU, .inp, the
gmsh files); allocation failure at the N-th allocation made by crawlsim's own code; signals at
seeded random times over the baseline's wall time.

Usage:
  tools/fault-suite.py --crawlsim BUILD/tools/crawlsim --shim BUILD/tests/faults/libcs_fault_shim.so
      --check BUILD/tests/faults/h5_check [--short] [--points N] [--targets run,fe]
      [--scenarios enospc,erofs,enomem,sigint,sigterm,sigkill,tmpfs] [--work DIR] [--seed S]
      [--jobs J]
  --shim none: against a sanitizer build, the signal (and, as root, tmpfs) scenarios only.
Results go to WORK/results.jsonl, one line per trial; a second call with the same WORK resumes
(trials already there are not run again). Exit status 0 only when every trial passed.
"""
import argparse
import json
import math
import os
import random
import signal
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

HERE = os.path.dirname(os.path.abspath(__file__))
SRC = os.path.dirname(HERE)

# the small FE sweep: test_study_cli's 12 mm segment actuator without fibres on a 5 mm mesh to
# 0.02 MPa (four load steps, two output rows; ~10 s on an idle machine): every write path of an
# FE bend (gmsh script, gmsh's mesh, rows flushed per step, VTU, .inp) at an affordable cost
FE_ARGS = ["bend", "--model", "fe", "--set", "S1=12", "--set", "S2=12", "--set", "S3=12",
           "--set", "c=3", "--set", "LS12=4", "--set", "LS23=4", "--set", "n1=0", "--set",
           "n2=0", "--set", "n3=0", "--mesh-size", "5", "--p-max", "0.02", "--p-step", "0.02"]

CAUSE = {"enospc": "No space left on device", "tmpfs": "No space left on device",
         "erofs": "Read-only file system",
         "enomem": "out of memory", "sigint": "interrupted", "sigterm": "interrupted",
         "sigkill": None}
SIGNALS = {"sigint": signal.SIGINT, "sigterm": signal.SIGTERM, "sigkill": signal.SIGKILL}
ALL_SCENARIOS = ["enospc", "erofs", "enomem", "sigint", "sigterm", "sigkill", "tmpfs"]


def target_cmd(target, out, t_end):
    if target == "run":
        return ["run", "--scene", "flat-road", "--conditions", "paper", "--legs", "rod",
                "--t-end", str(t_end), "--out", out]
    return FE_ARGS + ["--out", out]


def run_once(a, target, out, env_extra, sig=None, at_s=None):
    """Run crawlsim; send `sig` to its process group at_s seconds after start. Returns a dict."""
    env = dict(os.environ)
    env.update(env_extra)
    env.setdefault("OMP_NUM_THREADS", "1")
    cmd = [a.crawlsim] + target_cmd(target, out, a.t_end)
    t0 = time.monotonic()
    # SIGINT/SIGTERM at their default as in a terminal (a background job of a non-interactive
    # shell, such as this suite under nohup, inherits SIGINT ignored: crawlsim keeps that)
    p = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, env=env,
                         cwd=os.path.dirname(out), start_new_session=True,
                         preexec_fn=lambda: [signal.signal(s, signal.SIG_DFL)
                                             for s in (signal.SIGINT, signal.SIGTERM)])
    sent = False
    if sig is not None:
        try:
            p.wait(timeout=at_s)
        except subprocess.TimeoutExpired:
            try:
                # Ctrl-C reaches the whole process group (gmsh too); kill -9 only crawlsim
                if sig == signal.SIGKILL:
                    os.kill(p.pid, sig)
                else:
                    os.killpg(p.pid, sig)
                sent = True
            except ProcessLookupError:
                pass
    try:
        so, se = p.communicate(timeout=a.timeout)
    except subprocess.TimeoutExpired:
        os.killpg(p.pid, signal.SIGKILL)
        so, se = p.communicate()
        return {"rc": "timeout", "stderr": se.decode(errors="replace")[-400:], "wall": a.timeout}
    if sig == signal.SIGKILL and sent:
        # gmsh may outlive a killed parent: end the group so the next trial starts clean
        try:
            os.killpg(p.pid, signal.SIGKILL)
        except ProcessLookupError:
            pass
    return {"rc": p.returncode, "stderr": se.decode(errors="replace"),
            "stdout": so.decode(errors="replace"), "wall": time.monotonic() - t0, "sent": sent}


def h5_check(a, path):
    r = subprocess.run([a.check, path], stdout=subprocess.PIPE, stderr=subprocess.PIPE)
    d = {}
    for line in r.stdout.decode(errors="replace").splitlines():
        k, _, v = line.partition("=")
        d[k] = v
    return d


def parse_log(path):
    """the shim's counts of the crawlsim process (its last line)"""
    if not os.path.exists(path):
        return None
    lines = [l.split() for l in open(path) if len(l.split()) == 7]
    rows = [w for w in lines if w[0] == "crawlsim"]
    if not rows:
        return None
    w = rows[-1]
    # fired: in crawlsim or in a program it ran (gmsh, under the same shim and fault point)
    return {"writes": int(w[2]), "mallocs": int(w[4]),
            "fired": int(any(int(x[6]) for x in lines))}


def baseline(a, target, work):
    """one run without faults: wall time, write events (and those of the HDF5 images),
    allocations"""
    d = os.path.join(work, f"{target}-baseline")
    os.makedirs(d, exist_ok=True)
    out = os.path.join(d, "out.h5")
    log = os.path.join(d, "shim.log")
    if os.path.exists(log):
        os.remove(log)
    r = run_once(a, target, out, {"LD_PRELOAD": a.shim, "CS_FAULT_LOG": log} if a.shim else {})
    c = parse_log(log) if a.shim else {"writes": 0, "mallocs": 0, "fired": 0}
    if r["rc"] != 0 or c is None:
        sys.exit(f"fault-suite: the baseline {target} failed (exit {r['rc']}): "
                 f"{r['stderr'].strip().splitlines()[-1:]}")
    chk = h5_check(a, out)
    nbytes = sum(os.path.getsize(os.path.join(d, f)) for f in os.listdir(d)
                 if f.startswith("out"))
    return {"wall": r["wall"], "writes": c["writes"], "mallocs": c["mallocs"],
            "rows": int(chk.get("rows", -1)), "bytes": nbytes}


def points(a, scen, base, n, rng):
    """the fault points of one scenario"""
    if scen in ("enospc", "erofs"):
        total = base["writes"]
        pts = set(range(1, min(total, n // 2) + 1))  # every early event: creates and flushes
        k = 0
        while len(pts) < min(n, total) and k < 10 * n:
            # log-spaced over the rest, then filled at random
            f = (k + 0.5) / n
            pts.add(max(1, min(total, int(round(math.exp(f * math.log(total)))))))
            if k >= n:
                pts.add(rng.randint(1, total))
            k += 1
        return sorted(pts)[:n]
    if scen == "tmpfs":
        # KiB: log-spaced from 8 KiB to twice the baseline's outputs (a flush needs room for the
        # new image beside the old one)
        top = max(16, 2 * base["bytes"] // 1024)
        return sorted(set(int(round(8 * (top / 8) ** (i / (n - 1)))) for i in range(n)))
    if scen == "enomem":
        total = base["mallocs"]
        if total <= n:
            return list(range(1, total + 1))
        return sorted(set(int(round(1 + i * (total - 1) / (n - 1))) for i in range(n)))
    # signals: seeded times over (2 %, 98 %) of the baseline's wall time
    return sorted(round(rng.uniform(0.02, 0.98) * base["wall"], 3) for _ in range(n))


def trial(a, target, scen, pt, work, base):
    d = os.path.join(work, f"{target}-{scen}-{pt}")
    if scen == "tmpfs":
        # a real full disk: a tmpfs of pt KiB holds the outputs (root only)
        os.makedirs(d, exist_ok=True)
        subprocess.run(["umount", d], stderr=subprocess.DEVNULL)
        if subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={pt}k", "tmpfs", d]).returncode:
            return {"target": target, "scenario": scen, "point": pt, "rc": None, "wall": 0,
                    "problems": ["cannot mount a tmpfs"], "message": ""}
        try:
            return trial_in(a, target, scen, pt, d, base)
        finally:
            subprocess.run(["umount", "-l", d])
    os.makedirs(d, exist_ok=True)
    for f in os.listdir(d):
        os.remove(os.path.join(d, f))
    return trial_in(a, target, scen, pt, d, base)


def trial_in(a, target, scen, pt, d, base):
    out = os.path.join(d, "out.h5")
    log = os.path.join(d, "shim.log")
    env, sig, at_s = {}, None, None
    if scen in ("enospc", "erofs"):
        env = {"LD_PRELOAD": a.shim, "CS_FAULT_WRITE_AT": str(pt), "CS_FAULT_LOG": log,
               "CS_FAULT_ERRNO": scen.upper()}
    elif scen == "enomem":
        env = {"LD_PRELOAD": a.shim, "CS_FAULT_MALLOC_AT": str(pt), "CS_FAULT_LOG": log}
    elif scen != "tmpfs":
        sig, at_s = SIGNALS[scen], pt
    r = run_once(a, target, out, env, sig, at_s)
    res = {"target": target, "scenario": scen, "point": pt, "rc": r["rc"],
           "wall": round(r["wall"], 2), "problems": []}
    prob = res["problems"]
    err_lines = [l for l in r["stderr"].splitlines() if l.strip()]
    last = err_lines[-1] if err_lines else ""
    res["message"] = last[:300]
    fired = True
    if scen == "tmpfs":
        fired = r["rc"] != 0  # a tmpfs as large as all outputs is no fault
    elif env:
        c = parse_log(log)
        fired = bool(c and c["fired"])
    elif sig is not None:
        fired = r.get("sent", False)
    res["fired"] = fired
    # crashes and sanitizer reports
    if r["rc"] == "timeout":
        prob.append("timeout")
        return res
    if "Sanitizer" in r["stderr"] or "runtime error:" in r["stderr"]:
        prob.append("sanitizer report")
    expected_sig = -int(sig) if sig == signal.SIGKILL and fired else None
    if (sig is not None and r["rc"] == -int(sig) and not os.path.exists(out)
            and not os.path.exists(out + ".part")):
        # the signal came before crawlsim installed its handler (while the dynamic loader
        # was still at work): the default action, before any output existed
        res["before_start"] = True
        return res
    if isinstance(r["rc"], int) and r["rc"] < 0 and r["rc"] != expected_sig:
        prob.append(f"crash (signal {-r['rc']})")
    if r["rc"] in (134, 139):
        prob.append(f"crash (exit {r['rc']})")
    if prob:
        return res
    if not fired:
        # the process finished before the fault point: nothing to check but a clean exit
        if r["rc"] != 0:
            prob.append("failed without a fault")
        return res
    # exit status and message
    cause = CAUSE[scen]
    gmsh = False
    if scen != "sigkill":
        if r["rc"] == 0:
            # a fault that hit nothing the command needed (e.g. an allocation whose failure
            # has a fallback) is fine only if the outputs are complete and say ok
            res["survived"] = True
        else:
            cmdname = "run" if target == "run" else "bend"
            if not last.startswith(f"crawlsim {cmdname}: "):
                prob.append("last stderr line is not the command's one-line error")
            # gmsh does not report its errno: its truncated output is named, with the free space
            gmsh = "gmsh could not write" in last or "see " in last and "gmsh.log" in last
            if cause and cause not in last and not gmsh and not (
                    scen == "enomem" and ("memory" in last or "allocate" in last)):
                prob.append(f"message does not name the cause ({cause})")
    # the output file
    chk = h5_check(a, out) if os.path.exists(out) else {"open": "absent"}
    res["file"] = {k: chk.get(k) for k in ("open", "status", "samples", "rows", "kind")}
    if chk.get("open") == "0":
        prob.append("output file does not open")
    elif chk.get("open") == "1":
        rows, samples = int(chk.get("rows", -1)), float(chk.get("samples", -1))
        status = chk.get("status", "")
        if chk.get("consistent") != "1" or chk.get("monotone") != "1":
            prob.append("series inconsistent or unreadable")
        if chk.get("missing", "0") != "0" and status in ("ok", "running"):
            prob.append("series missing from a file that does not say why")
        if samples >= 0 and rows != samples:
            prob.append(f"rows {rows} != samples {samples:.0f}")
        if rows > base["rows"]:
            prob.append("more rows than a complete run")
        if scen == "sigkill":
            if status not in ("running", "ok"):
                prob.append(f"status after kill -9: {status!r}")
        elif r["rc"] != 0:
            other_file = any(s in last for s in (".xdmf", ".vtu", ".inp", ".msh", ".geo"))
            # on a read-only file system not even the status can change: the file stays as
            # it was at its last flush ("running") and the message says why
            readonly_kept = scen == "erofs" and status == "running"
            if not readonly_kept and (status == "running" or (status == "ok" and not other_file)):
                prob.append(f"status does not say what happened: {status!r}")
            if (cause and status not in ("ok", "running") and cause not in status
                    and scen != "enomem" and not gmsh):
                prob.append(f"status does not name the cause: {status!r}")
    # leftovers
    for f in os.listdir(d):
        if f.endswith(".part") and scen != "sigkill":
            prob.append(f"left {f}")
        if f.endswith(".xdmf"):
            with open(os.path.join(d, f), "rb") as x:
                x.seek(0, 2)
                x.seek(max(0, x.tell() - 64))
                if b"</Xdmf>" not in x.read():
                    prob.append("incomplete .xdmf")
    return res


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--crawlsim", required=True)
    ap.add_argument("--shim", required=True)
    ap.add_argument("--check", required=True)
    ap.add_argument("--work", default="fault-suite")
    ap.add_argument("--short", action="store_true",
                    help="the CI version: the run target, 4 points per scenario, t_end 1 s, "
                    "never resumed")
    ap.add_argument("--points", type=int, default=50)
    ap.add_argument("--targets", default="run,fe")
    ap.add_argument("--scenarios", default=",".join(ALL_SCENARIOS))
    ap.add_argument("--t-end", type=float, default=2.0)
    ap.add_argument("--seed", type=int, default=37)
    ap.add_argument("--jobs", type=int, default=1)
    ap.add_argument("--timeout", type=float, default=600)
    a = ap.parse_args()
    if a.short:
        a.points, a.targets, a.t_end = 4, "run", 1.0
    scen_list = a.scenarios.split(",")
    if "tmpfs" in scen_list and (os.geteuid() != 0 or a.short):
        # mounting needs root; the short (CI) version keeps to the shim, which needs nothing
        scen_list.remove("tmpfs")
        if not a.short:
            print("fault-suite: not root: the tmpfs scenario (a real full disk) is left out",
                  flush=True)
    a.scenarios = ",".join(scen_list)
    if a.shim == "none":
        # a sanitizer build (ASan must be first in the preload list and owns malloc): the
        # signal and tmpfs scenarios need no shim
        a.shim = ""
        if any(s in ("enospc", "erofs", "enomem") for s in a.scenarios.split(",")):
            sys.exit("fault-suite: --shim none runs only sigint,sigterm,sigkill,tmpfs")
    for p in (a.crawlsim, a.shim or a.crawlsim, a.check):
        if not os.path.exists(p):
            sys.exit(f"fault-suite: {p}: not found (build the project first)")
    a.crawlsim, a.check = map(os.path.abspath, (a.crawlsim, a.check))
    a.shim = os.path.abspath(a.shim) if a.shim else ""
    work = os.path.abspath(a.work)
    os.makedirs(work, exist_ok=True)
    results_path = os.path.join(work, "results.jsonl")
    if a.short and os.path.exists(results_path):
        os.remove(results_path)  # the CI version always runs afresh
    done = {}
    if os.path.exists(results_path):
        for line in open(results_path):
            try:
                r = json.loads(line)
            except ValueError:
                continue  # a line cut by a kill
            done[(r["target"], r["scenario"], str(r["point"]))] = r
    rng = random.Random(a.seed)
    results = []
    for target in a.targets.split(","):
        base = baseline(a, target, work)
        print(f"fault-suite: {target}: baseline {base['wall']:.1f} s wall, {base['writes']} write "
              f"events, {base['mallocs']} allocations by crawlsim's code, {base['rows']} rows",
              flush=True)
        todo = []
        for scen in a.scenarios.split(","):
            for pt in points(a, scen, base, a.points, rng):
                key = (target, scen, str(pt))
                if key in done:
                    results.append(done[key])
                else:
                    todo.append((scen, pt))
        with ThreadPoolExecutor(max_workers=max(1, a.jobs)) as ex:
            futs = [ex.submit(trial, a, target, s, p, work, base) for s, p in todo]
            for fu in futs:
                r = fu.result()
                results.append(r)
                with open(results_path, "a") as f:
                    f.write(json.dumps(r) + "\n")
                if r["problems"]:
                    print(f"  FAIL {r['target']} {r['scenario']} @{r['point']}: "
                          f"{'; '.join(r['problems'])} (exit {r['rc']}: {r['message']})",
                          flush=True)
    # summary
    print(f"{'target':7} {'scenario':8} {'points':>6} {'fired':>5} {'crash':>5} "
          f"{'failed':>6} {'no file':>7} {'exit 0':>6}")
    bad = 0
    for target in a.targets.split(","):
        for scen in a.scenarios.split(","):
            rs = [r for r in results if r["target"] == target and r["scenario"] == scen]
            if not rs:
                continue
            fired = sum(1 for r in rs if r.get("fired"))
            crash = sum(1 for r in rs if any(p.startswith(("crash", "sanitizer", "timeout"))
                                             for p in r["problems"]))
            failed = sum(1 for r in rs if r["problems"])
            nofile = sum(1 for r in rs if (r.get("file") or {}).get("open") == "absent")
            survived = sum(1 for r in rs if r.get("survived"))
            bad += failed
            print(f"{target:7} {scen:8} {len(rs):6d} {fired:5d} {crash:5d} {failed:6d} "
                  f"{nofile:7d} {survived:6d}")
    print(f"fault-suite: {len(results)} trials, {bad} failed; results in {results_path}")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())

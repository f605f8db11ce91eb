#!/usr/bin/env python3
"""stages.py LABEL:LOG:CG [LABEL:LOG:CG ...]: per measured window of cg.sh (one callgrind profile
each, in window order, and the bench's log with its "window [t0, t1] s" lines in the same order;
LOG:CG:K takes the log's K-th window line, 1-based, default 1) the instructions per simulated
second by stage (inclusive counts, callgrind_annotate --inclusive=yes; the "across" rows are
parts of the legs' stages above them), the tree tries and passes, and the instructions per leg
pass (the legs' first passes and iterates over the calls that make them). Stages as
../strainspeed_2026-12-06f/stages.py, with the calibration's RBF field apart (and, branch
speed9, the articulated condensation; branch speed12, its kept iterates' solve, the contact's
dense blocks and the inertia's assembly by name). Source annotation off (--auto=no, branch speed11): with
the profile's sources present its call lines entered the by-name sums (the inertia and the
recursion rows read half)."""
import re, subprocess, sys

ROWS = [
    ("the run (cs_runWrite)", ["cs_runWrite"]),
    ("legs: calibration (csr_strainActuate)", ["csr_strainActuate"]),
    ("  of which the RBF field (csr_rodActuationEval_)", ["csr_rodActuationEval_"]),
    ("legs: first pass (cs_couplingTreePrepare)", ["cs_couplingTreePrepare"]),
    ("later passes + tree solve (cs_couplingApplyTree)", ["cs_couplingApplyTree"]),
    ("  of which the legs' iterates (csr_strainIterate)", ["csr_strainIterate"]),
    ("legs: finish (cs_couplingTreeFinish)", ["cs_couplingTreeFinish"]),
    ("pneumatics (CVode)", ["CVode"]),
    ("output (writeSample)", ["writeSample"]),
    ("support (dWorldQuickStep + dWorldStep)", ["dWorldQuickStep", "dWorldStep"]),
    ("across: kinematics (csr_strainKinematics_)", ["csr_strainKinematics_"]),
    ("across: inertia (csr_strainInertiaFrom_)", ["csr_strainInertiaFrom_"]),
    ("across: velocity products (csr_strainTwists_)", ["csr_strainTwists_"]),
    ("across: factorisations (LU, Cholesky)", ["csr_strainLuFactor_", "csr_strainCholFactor_"]),
    ("across: solves", ["csr_strainLuSolveMulti_", "csr_strainLuSolve_", "csr_strainCholSolve6_",
                        "csr_strainCholSolve_"]),
    ("across: contact linearisation (csr_strainContactAssemble_)", ["csr_strainContactAssemble_"]),
    ("across: contact law (csc_softComputeShape, csc_softShapeJacobian, csc_softUpdateShapeLoad)",
     ["csc_softComputeShape", "csc_softShapeJacobian", "csc_softUpdateShapeLoad"]),
    ("across: the articulated condensation (csr_strainCondenseArtic_)",
     ["csr_strainCondenseArtic_"]),
    ("across: the recursion's kept solve (csr_strainArticSolve_)", ["csr_strainArticSolve_"]),
    ("across: the contact's W blocks (csr_strainShapeW_)", ["csr_strainShapeW_"]),
    ("across: memcpy + memset", ["__memcpy_avx_unaligned_erms", "__memset_avx2_unaligned_erms"]),
]
WIN = re.compile(r"window \[([\d.e+-]+), ([\d.e+-]+)\] s: (\d+) macro steps \((\d+) rejected\), "
                 r"(\d+) leg steps prepared \((\d+) tries of the tree step\), (\d+) tree passes "
                 r"\(([\d.]+) per try\), leg calls: prepare (\d+), iterate (\d+), finish (\d+), "
                 r"actuate (\d+); adaptive (\d): (\d+) accepted, (\d+) rejected")


def load(path):
    out = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", "--auto=no", path],
                         capture_output=True, text=True).stdout
    inc = {}
    for line in out.splitlines():
        m = re.match(r"\s*([\d,]+) \([ \d.]+%\)\s+\S*:(\S+) \[", line)
        if m:
            inc[m.group(2)] = max(inc.get(m.group(2), 0), int(m.group(1).replace(",", "")))
    return inc


def main():
    cols = []
    for arg in sys.argv[1:]:
        parts = arg.split(":")
        label, log, cg = parts[0], parts[1], parts[2]
        k = int(parts[3]) if len(parts) > 3 else 1
        wins = [m for m in map(WIN.search, open(log).read().splitlines()) if m]
        w = wins[k - 1]
        cols.append((label, w, load(cg)))
    print("| per simulated second | " + " | ".join(c[0] for c in cols) + " |")
    print("|---|" + "---|" * len(cols))
    for name, fns in ROWS:
        cells = []
        for _, w, inc in cols:
            T = float(w.group(2)) - float(w.group(1))
            cells.append("%.3g" % (sum(inc.get(f, 0) for f in fns) / T))
        print("| %s | %s |" % (name, " | ".join(cells)))
    def row(name, f):
        print("| %s | %s |" % (name, " | ".join(f(w, inc) for _, w, inc in cols)))
    row("tries of the tree step (accepted + rejected)", lambda w, i: w.group(6))
    row("adaptive: accepted / rejected by the error", lambda w, i: "%s / %s" % (w.group(14), w.group(15)) if w.group(13) == "1" else "-")
    row("tree passes per try", lambda w, i: w.group(8))
    row("leg passes (prepare + iterate calls)", lambda w, i: str(int(w.group(9)) + int(w.group(10))))
    row("instructions per leg first pass (prepare)", lambda w, i: "%.0f k" % (i.get("cs_couplingTreePrepare", 0) / int(w.group(9)) / 1e3))
    row("instructions per leg iterate (csr_strainIterate)", lambda w, i: "%.0f k" % (i.get("csr_strainIterate", 0) / max(1, int(w.group(10))) / 1e3))
    row("instructions per leg finish (cs_couplingTreeFinish / leg steps)", lambda w, i: "%.0f k" % (i.get("cs_couplingTreeFinish", 0) / max(1, int(w.group(11))) / 1e3))
    row("instructions per leg pass (first + iterates, their calls)", lambda w, i: "%.0f k" % ((i.get("cs_couplingTreePrepare", 0) + i.get("csr_strainIterate", 0)) / (int(w.group(9)) + int(w.group(10))) / 1e3))
    row("instructions per leg step, all the legs' stages (calibration, passes, finish)", lambda w, i: "%.0f k" % ((i.get("csr_strainActuate", 0) + i.get("cs_couplingTreePrepare", 0) + i.get("csr_strainIterate", 0) + i.get("cs_couplingTreeFinish", 0)) / int(w.group(9)) / 1e3))


main()

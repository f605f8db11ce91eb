#!/usr/bin/env python3
"""stages.py CG [CG...]: instructions per simulated second by stage from callgrind files of
bench_strain_driver (--toggle-collect=cs_runWrite, T seconds; T read from the file's command).
Inclusive counts of the functions named below (callgrind_annotate --inclusive=yes); stages
overlap where one calls another (the law inside the legs' passes): each line says what it is."""
import re, subprocess, sys

ROWS = [
    ("run (cs_runWrite)", ["cs_runWrite"]),
    ("legs: calibration (csr_strainActuate)", ["csr_strainActuate"]),
    ("  of which the RBF field (csr_rodActuationEval_)", ["csr_rodActuationEval_"]),
    ("legs: first pass (cs_couplingTreePrepare)", ["cs_couplingTreePrepare"]),
    ("later passes + tree solve (cs_couplingApplyTree)", ["cs_couplingApplyTree"]),
    ("  of which the legs' iterates (csr_strainIterate)", ["csr_strainIterate"]),
    ("legs: finish (cs_couplingTreeFinish)", ["cs_couplingTreeFinish"]),
    ("pneumatics (CVode)", ["CVode"]),
    ("output (writeSample)", ["writeSample"]),
    ("support (dWorldQuickStep + dWorldStep)", ["dWorldQuickStep", "dWorldStep"]),
    ("across stages: kinematics (csr_strainKinematics_)", ["csr_strainKinematics_"]),
    ("across stages: inertia (csr_strainInertiaFrom_)", ["csr_strainInertiaFrom_"]),
    ("across stages: velocity products (csr_strainTwists_)", ["csr_strainTwists_"]),
    ("across stages: factorisations (LU, Cholesky)", ["csr_strainLuFactor_", "csr_strainCholFactor_"]),
    ("across stages: solves", ["csr_strainLuSolveMulti_", "csr_strainLuSolve_", "csr_strainCholSolve6_", "csr_strainCholSolve_"]),
    ("across stages: contact linearisation (csr_strainContactAssemble_)", ["csr_strainContactAssemble_"]),
    ("across stages: contact law (csc_softComputeShape, csc_softShapeJacobian, csc_softUpdateShapeLoad)", ["csc_softComputeShape", "csc_softShapeJacobian", "csc_softUpdateShapeLoad"]),
]


def load(path):
    out = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", path],
                         capture_output=True, text=True).stdout
    inc, t = {}, 1.0
    for line in out.splitlines():
        m = re.match(r"\s*([\d,]+) \([ \d.]+%\)\s+\S*:(\S+) \[", line)
        if m:
            name = m.group(2)
            inc[name] = max(inc.get(name, 0), int(m.group(1).replace(",", "")))
        m = re.match(r"Profiled target:\s+\S+ (\S+) ", line)
        if m:
            t = float(m.group(1))
    return inc, t


def main():
    files = sys.argv[1:]
    data = [load(f) for f in files]
    print("| stage (instructions per simulated second) | " + " | ".join(f.split("/")[-1] for f in files) + " |")
    print("|---|" + "---|" * len(files))
    for label, names in ROWS:
        cells = []
        for inc, t in data:
            v = sum(inc.get(n, 0) for n in names) / t
            cells.append("%.3g" % v)
        print("| %s | %s |" % (label, " | ".join(cells)))


main()

#!/usr/bin/env python3
"""cgcalls.py CG [FUNC ...]: from a callgrind profile, per function (FUNC: a substring of its
name; default the condensation paths) the calls made to it (the sum of its callers' "calls="
lines) and its inclusive instructions (the sum over its callers' call costs, recursion not
double counted as callgrind_annotate's --inclusive: it is read from there)."""
import re, subprocess, sys

DEFAULT = ["condenseUpdate", "factorAndCondense", "wmFrom", "denseStart", "condenseKeptArtic",
           "condenseKept", "condensePlain", "condenseStance", "condenseStart", "condense",
           "csr_strainInertiaFrom_", "csr_strainInertiaApply_", "csr_strainCondenseWoodbury_",
           "csr_strainWoodburySolve_", "csr_strainCondenseArtic_", "csr_strainArticSolve_",
           "csr_strainLuFactor_", "csr_strainCholFactor_", "csr_strainKinematics_",
           "csr_strainContactAssemble_", "csr_strainContactLoads_", "assemble", "momentumRows",
           "startKinematics", "keepKinematics", "csr_strainPrepare", "csr_strainIterate",
           "prepareBdf", "iterateAt", "csr_strainTwists_", "csr_strainPointTwistsChain_"]


def calls(path):
    names = {}
    out = {}
    cfn = None
    with open(path) as f:
        for line in f:
            m = re.match(r"(c?fn)=\((\d+)\)(?: (.*))?", line)
            if m:
                if m.group(3):
                    names[m.group(2)] = m.group(3).strip()
                if m.group(1) == "cfn":
                    cfn = names.get(m.group(2))
                continue
            m = re.match(r"calls=(\d+)", line)
            if m and cfn:
                out[cfn] = out.get(cfn, 0) + int(m.group(1))
    return out


def inclusive(path):
    txt = subprocess.run(["callgrind_annotate", "--inclusive=yes", "--threshold=100", path],
                         capture_output=True, text=True).stdout
    inc = {}
    for line in txt.splitlines():
        m = re.match(r"\s*([\d,]+) \([ \d.]+%\)\s+\S*:(\S+) \[", line)
        if m:
            inc[m.group(2)] = max(inc.get(m.group(2), 0), int(m.group(1).replace(",", "")))
    return inc


def main():
    path = sys.argv[1]
    funcs = sys.argv[2:] or DEFAULT
    c = calls(path)
    inc = inclusive(path)
    tot = inc.get("cs_runWrite", 0)
    print(f"| function | calls | inclusive Ir | % of the run |")
    print("|---|---|---|---|")
    for fn in funcs:
        n = sum(v for k, v in c.items() if k == fn)
        i = inc.get(fn, 0)
        print(f"| {fn} | {n} | {i:,} | {100.0 * i / tot if tot else 0:.1f} |")
    print(f"| (the run, cs_runWrite) | | {tot:,} | 100 |")


main()

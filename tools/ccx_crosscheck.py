#!/usr/bin/python3
"""Cross-check an exported FE deck in CalculiX: run ccx on it and print the tip-face centroid.

`crawlsim bend --model fe` (and `bench_fem_bend --inp F`) write the model - mesh, Yeoh material,
fibres, chamber pressures as follower loads, base clamp - as an ABAQUS/CalculiX deck at the
sweep's last pressure. This script adapts the deck to CalculiX (C3D10H -> C3D10: CalculiX has no
hybrid tetrahedra, so compare with crawlsim's plain-P2 formulation, `bench_fem_bend ... --p2`),
adds a node set on the tip face z = L and a displacement print, runs `ccx`, and prints the
centroid of the tip-face nodes before and after, to compare with the `tip` column of
bench_fem_bend / the /tip_position of the bend file (same nodes, same centroid definition).

Usage: /usr/bin/python3 tools/ccx_crosscheck.py DECK.inp L_MM [--work DIR]
CalculiX is optional (Debian package calculix-ccx, GPL, run as a separate program). Fibres are
written with *EMBEDDED ELEMENT (ABAQUS); CalculiX does not read it, so cross-check fibre-free
models (`--no-fibres`).
"""
import argparse
import os
import shutil
import subprocess
import sys


def adapt(src, dst, z_tip):
    """C3D10H -> C3D10, NSET TIP (nodes at z = z_tip), *NODE PRINT of U on it."""
    out, tip, mode = [], [], ""
    with open(src) as f:
        lines = f.read().split("\n")
    for ln in lines:
        if ln.startswith("*"):
            mode = ln.upper()
        elif mode.startswith("*NODE, NSET=NBODY") and ln.strip():
            p = ln.split(",")
            if abs(float(p[3]) - z_tip) < 1e-6:
                tip.append(int(p[0]))
        if ln.startswith("*ELEMENT, TYPE=C3D10H"):
            ln = ln.replace("C3D10H", "C3D10")
        if ln.startswith("*EMBEDDED ELEMENT"):
            sys.exit(f"{src}: has fibres (*EMBEDDED ELEMENT), which CalculiX does not read")
        if ln.startswith("*NODE FILE"):
            out.append("*NODE PRINT, NSET=TIP\nU")
        out.append(ln)
    if not tip:
        sys.exit(f"{src}: no node on the plane z = {z_tip} mm")
    text = "\n".join(out)
    nset = "*NSET, NSET=TIP\n" + "\n".join(
        ", ".join(str(t) for t in tip[i:i + 10]) for i in range(0, len(tip), 10)) + "\n"
    text = text.replace("*BOUNDARY", nset + "*BOUNDARY", 1)
    with open(dst, "w") as f:
        f.write(text)
    return tip


def read_nodes(path):
    X, mode = {}, ""
    with open(path) as f:
        for ln in f:
            if ln.startswith("*"):
                mode = ln.upper()
                continue
            if mode.startswith("*NODE, NSET=NBODY") and ln.strip():
                p = ln.split(",")
                X[int(p[0])] = [float(v) for v in p[1:4]]
    return X


def last_displacements(dat):
    blocks, cur = [], None
    with open(dat) as f:
        for ln in f:
            if "displacements" in ln:
                cur = {}
                blocks.append(cur)
                continue
            p = ln.split()
            if cur is not None and len(p) == 4:
                try:
                    cur[int(p[0])] = [float(v) for v in p[1:]]
                except ValueError:
                    pass
    return blocks


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("deck")
    ap.add_argument("length", type=float, help="actuator length L (mm): the tip face is z = L")
    ap.add_argument("--work", default=None, help="folder for the CalculiX files (default: next "
                    "to the deck)")
    a = ap.parse_args()
    if not shutil.which("ccx"):
        sys.exit("ccx not found: install Debian's calculix-ccx (apt-get install calculix-ccx)")
    if not os.path.isfile(a.deck):
        sys.exit(f"{a.deck}: no such file")
    work = a.work or os.path.dirname(os.path.abspath(a.deck))
    os.makedirs(work, exist_ok=True)
    stem = os.path.join(work, os.path.splitext(os.path.basename(a.deck))[0] + "_ccx")
    tip = adapt(a.deck, stem + ".inp", a.length)
    r = subprocess.run(["ccx", "-i", os.path.basename(stem)], cwd=work, capture_output=True,
                       text=True)
    blocks = last_displacements(stem + ".dat") if os.path.isfile(stem + ".dat") else []
    if r.returncode != 0 or not blocks:
        sys.exit(f"ccx failed on {stem}.inp (see its output in {work})")
    U, X = blocks[-1], read_nodes(stem + ".inp")
    n = len(U)
    c0 = [sum(X[k][i] for k in U) / n for i in range(3)]
    c = [sum(X[k][i] + U[k][i] for k in U) / n for i in range(3)]
    print(f"CalculiX {stem}.inp: {len(tip)} tip nodes, {len(blocks)} increments")
    print("tip centroid reference  %.4f %.4f %.4f mm" % tuple(c0))
    print("tip centroid deformed   %.4f %.4f %.4f mm" % tuple(c))


if __name__ == "__main__":
    main()

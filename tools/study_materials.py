#!/usr/bin/python3
"""study_materials.py: second-order Yeoh constants of real silicones for the Earth design study.

Usage:
  git clone https://github.com/LucMarechal/Soft-Robotics-Materials-Database SRMD
  /usr/bin/python3 tools/study_materials.py SRMD/Tensile-Tests-Data [--strain-max 1.0]

Source: the raw uniaxial tensile tests (ASTM D412, engineering strain and stress) of the Soft
Robotics Materials Database, L. Marechal, P. Balland, L. Lindenroth, F. Petrou,
C. Kontovounisios, F. Bello, "Toward a Common Framework and Database of Materials for Soft
Robotics", Soft Robotics 8(3), 2021, doi:10.1089/soro.2019.0115 (data under the ODbL; only the
constants derived here are used by crawlsim, the data is not copied).

The paper's material law is the incompressible second-order Yeoh form W = C10 (I1 - 3) +
C20 (I1 - 3)^2 (docs/reference.md). Under uniaxial tension with stretch l = 1 + e, I1 = l^2 + 2/l and
the nominal stress is P = 2 (l - l^-2) (C10 + 2 C20 (I1 - 3)): linear in (C10, C20), fitted here
by least squares to the points with 0 < e <= strain-max (default 1.0: the actuators' walls
stretch up to ~50 %, the legs' bending stiffness depends on the small-strain modulus 8 C10 with
the fibres holding the circumference). Prints, per material, C10, C20, the fit's RMS error
relative to the largest stress fitted, and the `--set` words of a study file.
"""

import argparse
import glob
import os
import sys

import numpy as np

PROG = "study_materials"


def read_test(path):
    """(engineering strain, engineering stress MPa, material name) of one database CSV."""
    rows = open(path, encoding="latin-1").read().splitlines()
    name = os.path.splitext(os.path.basename(path))[0]
    head = None
    for k, r in enumerate(rows):
        cells = r.split(";")
        if cells[0] == "Material" and len(cells) > 1 and cells[1]:
            name = cells[1]
        if r.startswith("Time (s)"):
            head = k
            break
    if head is None:
        raise ValueError(f"{path}: no 'Time (s)' header row")
    cols = rows[head].split(";")
    ie, isig = cols.index("Engineering Strain"), cols.index("Engineering Stress (MPa)")
    data = []
    for r in rows[head + 1:]:
        c = r.split(";")
        try:
            data.append((float(c[ie]), float(c[isig])))
        except (ValueError, IndexError):
            continue
    d = np.array(data)
    return d[:, 0], d[:, 1], name


def fit_yeoh(e, s, e_max):
    """C10, C20 (MPa) and the RMS error / max stress of the fit on 0 < e <= e_max."""
    m = (e > 0) & (e <= e_max)
    lam = 1 + e[m]
    i1 = lam**2 + 2 / lam
    a = np.c_[2 * (lam - lam**-2), 4 * (lam - lam**-2) * (i1 - 3)]
    c, *_ = np.linalg.lstsq(a, s[m], rcond=None)
    rms = np.sqrt(np.mean((a @ c - s[m]) ** 2)) / np.max(s[m])
    return c[0], c[1], rms, int(m.sum())


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n")[0])
    ap.add_argument("data_dir", help="Tensile-Tests-Data folder of the database")
    ap.add_argument("--strain-max", type=float, default=1.0, help="largest engineering strain")
    args = ap.parse_args()
    files = sorted(glob.glob(os.path.join(args.data_dir, "*.csv")))
    if not files:
        print(f"{PROG}: {args.data_dir}: no CSV files", file=sys.stderr)
        return 1
    print(f"| material (file) | C10 (MPa) | C20 (MPa) | 8 C10 (MPa) | fit RMS / max | points "
          f"| study words |")
    print("|---|---|---|---|---|---|---|")
    print("| Elastosil M4601 (the paper's, Sec. 3.3) | 0.11 | 0.02 | 0.88 | | | (default) |")
    for p in files:
        try:
            e, s, name = read_test(p)
        except ValueError as err:
            print(f"{PROG}: {err}", file=sys.stderr)
            continue
        c10, c20, rms, n = fit_yeoh(e, s, args.strain_max)
        print(f"| {name} ({os.path.basename(p)}) | {c10:.4f} | {c20:.4f} | {8 * c10:.3f} | "
              f"{rms:.3f} | {n} | --set C10={c10:.4f} --set C20={c20:.4f} |")
    return 0


if __name__ == "__main__":
    sys.exit(main())

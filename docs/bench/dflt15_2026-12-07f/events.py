#!/usr/bin/python3
"""events.py -> events.txt: where the adaptive BDF2 leaves the default on the obstacle (no runs).

1. The support's x minus the nodal rod's at 32 elements (rod.sh's rod32_obst10, 0.25 ms) at
   3.5..10 s for the default (d_o_nominal), its half tolerance (d_o_half), BDF2 at 5e-4 and
   2.5e-4 (b_o_nominal, b_o_half), BDF2 at the longest step 2.5 and 1 ms (diag.sh) and the
   noise floor's grids 1/220 and 1/180 s (noise.sh).
2. Backward Euler's tracks at 5e-4 ... 3.125e-5 mm (more.sh, more2.sh), the ratios of their
   successive differences, and its limit as the tolerance goes to 0 extrapolated from the two
   finest (Richardson, the global error taken ~ tol^(1/2): local error ~ h^2 held at tol by
   the controller, so h ~ tol^(1/2) and the first-order global error ~ h), against BDF2's.
3. Leg C's touchdowns after 8.6 s (time @ foot x, mm; the step's edge is at x = 240 mm; G, its
   mirror, lands with it) and the support's x at whole seconds 7..20 s, for every obstacle run.
RUNS as check.py (default /tmp/dflt15/runs)."""
import os
import sys

import h5py
import numpy as np

RUNS = os.environ.get("RUNS", "/tmp/dflt15/runs")
S = (3.5, 4, 5, 6, 7, 7.5, 8, 8.5, 9, 9.5, 10)


def load(tag):
    with h5py.File(os.path.join(RUNS, tag + ".h5"), "r") as f:
        return (f["time"][:], f["support/position"][:], f["contact/stance"][:],
                f["legs/C/centerline"][:, -1])


def x(tr, s):
    return float(np.interp(s, tr[0], tr[1][:, 0])) if tr[0][-1] >= s - 1e-9 else float("nan")


def main():
    def have(t):  # finished: its log (logs/TAG.log) has its rc line
        lg = os.path.join(os.path.dirname(os.path.abspath(__file__)), "logs", t + ".log")
        return os.path.exists(lg) and "\nrc " in open(lg).read()
    rod = load("rod32_obst10")
    print("# 1. support x minus the rod at 32 elements (mm); the rod's x on its line")
    print("%-16s" % "t (s)" + "".join("%8.1f" % s for s in S))
    print("%-16s" % "rod32 x" + "".join("%8.2f" % x(rod, s) for s in S))
    tags = ("d_o_nominal", "d_o_half", "nd_220", "nd_180", "b_o_nominal", "b_o_half",
            "bdt0.0025_o10", "bdt0.001_o10", "nb_220", "nb_180")
    for t in (t for t in tags if have(t)):
        tr = load(t)
        print("%-16s" % t + "".join("%8.2f" % (x(tr, s) - x(rod, s)) for s in S))
    print("\n# 2. backward Euler's tolerance sequence (more.sh, more2.sh) against BDF2: x (mm);")
    print("#    ratio: successive differences (sqrt 2 = 1.41 for an error ~ tol^(1/2), 2 for ~ tol);")
    print("#    limit: Richardson from the two finest, the error taken ~ tol^(1/2)")
    seq = [("5e-4", "be_5e-4_o8"), ("2.5e-4", "d_o_nominal"), ("1.25e-4", "d_o_half"),
           ("6.25e-5", "be_6.25e-5_o12" if have("be_6.25e-5_o12") else "be_6.25e-5_o8"),
           ("3.125e-5", "be_3.125e-5_o12")]
    seq = [(n, load(t)) for n, t in seq if have(t)]
    S2 = S[:7]
    print("%-16s" % "t (s)" + "".join("%8.1f" % s for s in S2))
    for n, tr in seq:
        print("%-16s" % ("BE " + n) + "".join("%8.2f" % x(tr, s) for s in S2))
    b = load("b_o_nominal")
    print("%-16s" % "BDF2 5e-4" + "".join("%8.2f" % x(b, s) for s in S2))
    print("%-16s" % "rod32" + "".join("%8.2f" % x(rod, s) for s in S2))
    for i in range(len(seq) - 2):
        (n0, a0), (n1, a1), (n2, a2) = seq[i:i + 3]
        print("%-16s" % ("ratio " + n1) + "".join(
            "%8.2f" % ((x(a0, s) - x(a1, s)) / (x(a1, s) - x(a2, s))) for s in S2))
    k = 2 ** -0.5 / (1 - 2 ** -0.5)  # x_lim = x_h + k (x_h - x_2h)
    (_, c), (_, f) = seq[-2:]
    print("%-16s" % "BE limit" + "".join("%8.2f" % (x(f, s) + k * (x(f, s) - x(c, s)))
                                          for s in S2))
    print("\n# 3. leg C's touchdowns after 8.6 s (t@foot x mm; the edge at 240) and x(7..20 s)")
    runs = sorted(f[:-3] for f in os.listdir(RUNS) if f.endswith(".h5") and have(f[:-3]) and
                  ("_o_" in f or f.startswith(("rod32_", "bdt", "nd_", "nb_", "be_"))))
    for t in runs:
        tr = load(t)
        tt, st, c = tr[0], tr[2], tr[3]
        lands = ["%.2f@%.1f" % (tt[i], c[i, 0]) for i in range(1, len(tt))
                 if tt[i] > 8.6 and st[i, 2] and not st[i - 1, 2]][:4]
        xs = " ".join("%.0f" % x(tr, s) if tt[-1] >= s else "-" for s in range(7, 21))
        print("%-16s end %6.2f s | x %s | C lands %s" % (t, tt[-1], xs, " ".join(lands)))


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""cmp.py REF.h5 RUN.h5...: support (x, z) of each RUN against REF at whole seconds (mm) and the
max of |(dx, dz)| there (the levels table's error); -v adds dx every 0.1 s."""
import sys, math
import h5py, numpy as np

def rd(p):
    with h5py.File(p, "r") as f:
        return f["/time"][:], f["/support/position"][:], f.attrs.get("status", b"?")

args = [a for a in sys.argv[1:] if a != "-v"]
verbose = "-v" in sys.argv
tr, pr, _ = rd(args[0])
for path in args[1:]:
    t, p, st = rd(path)
    # a run whose step does not divide 1 s ends within a step of the whole second: take it
    n = int(math.floor(min(t[-1], tr[-1]) + 5e-3))
    row, worst = [], 0.0
    for s in range(1, n + 1):
        i, j = int(np.argmin(abs(t - s))), int(np.argmin(abs(tr - s)))
        dx, dz = p[i, 0] - pr[j, 0], p[i, 2] - pr[j, 2]
        d = math.hypot(dx, dz); worst = max(worst, d)
        row.append(f"{dx:+6.2f}/{dz:+5.2f}")
    print(f"{worst:6.2f}  x(end) {p[-1,0]:7.2f}  {' '.join(row)}  {path.split('/')[-1]} {st}")
    if verbose:
        out = []
        for k in range(1, int(n * 10) + 1):
            s = k / 10
            i, j = int(np.argmin(abs(t - s))), int(np.argmin(abs(tr - s)))
            out.append(f"{s:.1f}:{p[i,0]-pr[j,0]:+.2f}")
        print("   ", " ".join(out))

#!/usr/bin/python3
"""tracks.py A.h5 B.h5 ... [--from T0 --to T1 --every DT]: support x, y (mm) and pitch, roll
(deg, from the orientation quaternion w x y z) of each run side by side, and the legs in stance
(/contact/stance, 8 legs A..H as a string of 0/1) when the file has it."""
import sys

import h5py
import numpy as np

argv = sys.argv[1:]
opt = {argv[i]: argv[i + 1] for i in range(len(argv) - 1) if argv[i].startswith("--")}
args = [a for i, a in enumerate(argv) if not a.startswith("--") and (i == 0 or not argv[i - 1].startswith("--"))]
t0, t1, dt = float(opt.get("--from", 0)), float(opt.get("--to", 9)), float(opt.get("--every", 0.1))


def load(p):
    f = h5py.File(p, "r")
    n = int(f.attrs.get("samples", len(f["time"])))
    d = {"t": f["time"][:n], "x": f["support/position"][:n], "q": f["support/orientation"][:n]}
    d["st"] = f["contact/stance"][:n] if "contact/stance" in f else None
    return d


def angles(q):
    w, x, y, z = q
    # the support's body axes: pitch about z (x up/down), roll about x
    pitch = np.degrees(np.arcsin(np.clip(2 * (w * z + x * y), -1, 1)))
    roll = np.degrees(np.arctan2(2 * (w * x - y * z), 1 - 2 * (x * x + z * z)))
    return pitch, roll


runs = [load(p) for p in args]
print("t    " + "".join(" | %-38s" % p.split("/")[-1][:38] for p in args))
for s in np.arange(t0, t1 + 1e-9, dt):
    row = "%4.1f" % s
    for d in runs:
        i = np.where(np.abs(d["t"] - s) < 1e-6)[0]
        if not len(i):
            row += " | %-38s" % "-"
            continue
        i = i[0]
        p, r = angles(d["q"][i])
        st = "".join("%d" % v for v in d["st"][i]) if d["st"] is not None else "--------"
        row += " | x %7.2f y %6.2f p %5.1f %s" % (d["x"][i][0], d["x"][i][1], p, st)
    print(row)

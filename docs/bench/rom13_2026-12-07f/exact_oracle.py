#!/usr/bin/python3
"""The span's own residuals (rom13). Per FE state u of RAYS at load factors T, r = u - V q_M (the
part of u the span misses, M-orthogonal to V); /d the residuals, /D their POD in M (M-orthonormal
to V; fibre_compat_hold.py's pod_against), /states. With a held-out ray (the exact oracle: a
diagnostic, never a basis) V + r holds u exactly, so whatever a fibre-compatible shape of that
state could add, V + r holds at least as well: the upper bound of item 1's oracles. With
RAYS = train every training ray (the truncation's residuals at those states: a basis candidate).
Usage: exact_oracle.py SNAP BASIS.h5 LEG.h5 OUT.h5 RAYS T[,T...]"""
import os
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # the OpenMP OpenBLAS: one thread, no spin-waiting
os.environ.setdefault("OMP_NUM_THREADS", "1")
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "rom"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))
sys.path.insert(0, HERE)
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from fibre_compat_hold import pod_against  # noqa: E402
from rom11_iso_diag import Model, states  # noqa: E402
from rom_basis import read_rays  # noqa: E402

snap, basis, leg, out, rays, ts = sys.argv[1:7]
m = Model(snap, basis, leg)
names = ([r["name"] for r in read_rays(snap) if r["kind"] == "train"] if rays == "train"
         else rays.split(","))
cols, keys = [], []
for name, tt, u, p, _, _ in states(snap, names, [float(t) for t in ts.split(",")], m.fixed):
    r = u - m.V @ m.project_M(u)
    nr = np.sqrt(r @ (m.M @ r)) / np.sqrt(u @ (m.M @ u))
    print(f"exact_oracle: {name} t {tt:g}: |u - V q_M|_M / |u|_M = {100 * nr:.3f} %, max {np.abs(r).max():.3f} mm")
    cols.append(r)
    keys.append(f"{name}@{tt:g}")
Dr = np.stack(cols, axis=1)
D, sig = pod_against(m.V, m.M, Dr)
with h5py.File(out, "w") as f:
    f["d"], f["D"], f["sig"] = Dr, D, sig
    f["states"] = np.array(keys, dtype="S")
print(f"exact_oracle: {len(keys)} residuals -> {D.shape[1]} POD modes; singular values "
      + " ".join(f"{s:.3g}" for s in sig[:8]))

#!/usr/bin/python3
"""Session rom4 (docs/notes/rom.md): how well the held-out rays' element dilatations (the
pressure field, p_e = kappa theta_e) at full load lie in the pressure basis, global (the first m
POD modes of the 34 training rays' dilatations) against split at the segments' connectors
(tools/rom_basis.py --p-split 19,42), and where along the leg the residual sits.

    /usr/bin/python3 docs/bench/rom/rom4_pressure_split.py SNAPDIR BASIS_ALL_M.h5

BASIS_ALL_M.h5: a basis with every pressure mode (rom_basis.py SNAPDIR --n 48 --m 136 --mixed
--no-supremizers). Relative errors in the volume-weighted norm."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "tools"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from rom_basis import (dilatations, read_mesh, read_rays,  # noqa: E402
                       split_pressure_modes, tet_reference)

snap, basis = sys.argv[1], sys.argv[2]
x, tet, fixed, _, _ = read_mesh(snap)
with h5py.File(basis, "r") as f:
    P = f["P"][...]
dNdX, wq = tet_reference(x, tet)
vol = wq.sum(axis=1)
zc = x[tet[:, :4]].mean(axis=1)[:, 2]
T = {}
for r in read_rays(snap):
    if r["kind"] == "test":
        U = r["u"][-1:].T.copy()
        U[fixed] = 0.0
        T[r["name"]] = dilatations(U, tet, dNdX, wq)[:, 0]


def rel(PP, t):
    R = t - PP @ (PP.T @ (vol * t))
    return np.sqrt(np.sum(R * R * vol) / np.sum(t * t * vol)), R


print("where the residual of the full-load dilatations sits (every global mode, m = "
      f"{P.shape[1]}); x3 slices of the 61 mm leg")
edges = np.linspace(0.0, 61.0, 11)
for name in ("T_H4", "T_S2"):
    e, R = rel(P, T[name])
    tot, nt = np.sum(R * R * vol), np.sum(T[name] ** 2 * vol)
    print(f"  {name}: relative {e:.4f}")
    for a, b in zip(edges[:-1], edges[1:]):
        s = (zc >= a) & (zc < b)
        print(f"    x3 {a:5.1f}-{b:5.1f}: residual share {np.sum(R[s] ** 2 * vol[s]) / tot:6.3f}, "
              f"field share {np.sum(T[name][s] ** 2 * vol[s]) / nt:6.3f}")
print("global against split at x3 = 19, 42 mm (full load, relative)")
print(f"  {'m':>4s} {'modes g/s':>10s} " + " ".join(f"{n:>15s}" for n in sorted(T)))
for m in (16, 24, 32, 48, P.shape[1]):
    Ps = split_pressure_modes(P[:, :m], x, tet, vol, [19.0, 42.0])
    print(f"  {m:4d} {m:4d}/{Ps.shape[1]:4d} " + " ".join(
        f"{rel(P[:, :m], T[n])[0]:7.4f}/{rel(Ps, T[n])[0]:7.4f}" for n in sorted(T)))

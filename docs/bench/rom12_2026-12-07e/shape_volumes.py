#!/usr/bin/python3
"""What a fibre-compatible shape does to the chambers (rom12): for each state of a
fibre_compat_modes.py output (its /d and /states), the worst chamber volume error against the FE
state of the M-projection w = V q_M and of w + d, their tip error and M-norm distance, and the taut fibres' mismatch energy
1/2 sum W (max(E, 0) - max(E_FE, 0))^2 of each (N mm): does the shape return the fibres at the
walls' cost (fibre_free_projection.py's M-norm objective does not see the walls)?
Usage: shape_volumes.py SNAP BASIS.h5 LEG.h5 SHAPES.h5"""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rom"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from rom11_iso_diag import Model  # noqa: E402
from romacc_volume_diag import chamber_volumes  # noqa: E402
from rom_basis import read_rays  # noqa: E402

snap, basis, leg, shapes = sys.argv[1:5]
m = Model(snap, basis, leg)
with h5py.File(shapes, "r") as f:
    d = f["d"][...]
    names = [s.decode() for s in f["states"][...]]
rays = {r["name"]: r for r in read_rays(snap)}


def mismatch(w, Eu):
    E = m.fibre_strain(w)[0]
    return 0.5 * float((m.W * (np.maximum(E, 0) - np.maximum(Eu, 0)) ** 2).sum())


for j, name in enumerate(names):
    ray, t = name.split("/")[0].split("@")
    r = rays[ray]
    k = int(np.argmin(np.abs(r["t"] - float(t))))
    u = r["u"][k].copy()
    u[m.fixed] = 0.0
    vu = chamber_volumes(m.x, m.face, m.cid, u)
    Eu = m.fibre_strain(u)[0]
    w = m.V @ m.project_M(u)
    out = []
    for lab, s in (("V q_M", w), ("V q_M + d", w + d[:, j])):
        ev = chamber_volumes(m.x, m.face, m.cid, s) / vu - 1
        c = int(np.argmax(np.abs(ev)))
        R3 = (u - s).reshape(-1, 3)
        tip = float(np.sqrt((R3[m.tip].mean(axis=0) ** 2).sum()))
        mn = float(np.sqrt((u - s) @ (m.M @ (u - s))) / np.sqrt(u @ (m.M @ u)))
        out.append(f"{lab}: tip {tip:.3f} mm, M-norm {100 * mn:.2f} %, worst volume {100 * ev[c]:+.2f} % (chamber {c // 4 + 1}.{c % 4 + 1}),"
                   f" fibre mismatch {mismatch(s, Eu):.4g} N mm")
    print(f"  {name:16s} " + "; ".join(out))
    sys.stdout.flush()

#!/usr/bin/python3
"""The reduced potential's parts at the FE state and at its isochoric projection (rom11_energy.py)
for fibre bases of mf = the first K of the basis' Qf (every fibre mode: b176_f.h5), and the
gradient's norm there: what the mixed fibre field's size charges a state of span(V) near the
FE's. Usage: mf_energy.py SNAP BASIS_F.h5 LEG.h5 RAY T K1,K2,..."""
import os
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rom"))
import numpy as np  # noqa: E402
from rom11_energy import Energy  # noqa: E402
from rom_basis import read_rays  # noqa: E402

snap, basis, leg, ray, t = sys.argv[1:6]
ks = [int(k) for k in sys.argv[6].split(",")]
m = Energy(snap, basis, leg)
Qall = m.Qf.copy()
r = [r for r in read_rays(snap) if r["name"] == ray][0]
k = int(np.argmin(np.abs(r["t"] - float(t))))
u = r["u"][k].copy()
u[m.fixed] = 0.0
p = r["p"][k].ravel()
qm = m.project_M(u)
qi, _ = m.project_iso(u, qm)
print(f"{ray} t {r['t'][k]:.2f}, n = {m.V.shape[1]}, of {Qall.shape[1]} fibre modes")
for K in ks:
    m.Qf = Qall[:, :K]
    m.Gf = (m.Qf * m.W[:, None]).T @ m.Qf
    for lab, w in (("FE state", u), ("isochoric projection", m.V @ qi)):
        parts, f, fp = m.total(w, p)
        print(f"  mf {K:3d} {lab:22s} Pi {sum(parts):9.2f} = dev {parts[0]:8.2f} + bulk "
              f"{parts[1]:8.3g} + fibres {parts[2]:8.3g} - work {-parts[3]:8.2f}; |V^T grad| / "
              f"|V^T f_p| {np.linalg.norm(m.V.T @ f) / np.linalg.norm(m.V.T @ fp):.3g}")
    sys.stdout.flush()

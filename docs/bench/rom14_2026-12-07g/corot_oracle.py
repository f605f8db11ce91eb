#!/usr/bin/python3
"""The corotated representation's oracle screen (rom14, issue 34).

    corot_oracle.py SNAP BASIS.h5 LEG.h5 OUT.h5 [--width 2] [--sizes 176,300,all]
        [--rays T_R,T_H4,T_S2,T_H7] [--t 0.5,1]

Local shapes (corot.py) of every training FE state and its three quarter turns, their POD in
the M inner product (OUT.h5 /Vl, /sig, /zc). For each held-out FE state, with the rotation and
centroid field taken from that state itself (the oracle: what the rotation dofs could do at
best), its local shape projected onto the first K local modes (M-orthogonal) and turned back:
the state the corotated model can represent, against the linear span V's M-projection. Each
reported by the M-norm distance from the FE state, the tip, the worst chamber volume, and
the FE's own energies there (rom11_energy.Energy: Yeoh, P0 bulk, every fibre psi(E_f), the
pressure work) and the largest fibre strain: a state near the FE's that leaves its fibres
near the FE's few N mm is what span(V) lacks (rom11: q_I carries 651 N mm, the FE 6.6).
The held-out states are never in the local basis. Units mm, N mm.
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from corot import Slabs, mpod, show, train_states  # noqa: E402
from rom11_energy import Energy  # noqa: E402
from rom11_iso_diag import states  # noqa: E402
from rom_basis import turn_maps, turn_snapshots  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    for n in ("snap", "basis", "leg", "out"):
        ap.add_argument(n)
    ap.add_argument("--width", type=float, default=2.0)
    ap.add_argument("--sizes", default="176,300,all")
    ap.add_argument("--rays", default="T_R,T_H4,T_S2,T_H7")
    ap.add_argument("--t", type=lambda v: [float(c) for c in v.split(",")], default=[0.5, 1.0])
    a = ap.parse_args()
    t0 = time.process_time()
    m = Energy(a.snap, a.basis, a.leg)
    sl = Slabs(m.x, a.width)
    print(f"corot_oracle: {sl.nsl} slabs of {a.width} mm; V n = {m.V.shape[1]}, m = "
          f"{m.P.shape[1]}")
    if os.path.exists(a.out):
        with h5py.File(a.out, "r") as f:
            Vl, sig = f["Vl"][...], f["sig"][...]
        print(f"corot_oracle: local basis read from {a.out}")
    else:
        cols = []
        for u in train_states(a.snap, m.fixed):
            fld = sl.field(*sl.fit(u))
            ul = sl.local(u, fld)
            assert np.abs(sl.glob(ul, fld) - u).max() < 1e-9, "the split must invert exactly"
            cols.append(ul)
        UL = turn_snapshots(np.stack(cols, axis=1), turn_maps(m.x))
        Vl, sig = mpod(UL, m.M, m.fixed)
        with h5py.File(a.out, "w") as f:
            f["Vl"], f["sig"], f["zc"] = Vl, sig, sl.zc
        print(f"corot_oracle: {UL.shape[1]} local training shapes -> {Vl.shape[1]} modes "
              f"({time.process_time() - t0:.0f} s CPU)")
    sizes = [Vl.shape[1] if s == "all" else int(s) for s in a.sizes.split(",")]
    for name, t, u, p, _, _ in states(a.snap, a.rays.split(","), a.t, m.fixed):
        print(f"{name} t {t:.2f}:")
        show(m, "FE state", u, u, p)
        show(m, "V's M-projection (linear span)", u, m.V @ m.project_M(u), p)
        fld = sl.field(*sl.fit(u))
        ul = sl.local(u, fld)
        show(m, "oracle rotations, no local shape", u, sl.glob(np.zeros_like(ul), fld), p)
        for k in sizes:
            Vk = Vl[:, :k]
            w = sl.glob(Vk @ (Vk.T @ (m.M @ ul)), fld)
            show(m, f"oracle rotations + {k} local modes", u, w, p)
        # the same rotations with V's linear span as the local space (is the frame the gain?)
        show(m, "oracle rotations + V (224) as local", u,
             sl.glob(m.V @ m.project_M(ul), fld), p)
    print(f"corot_oracle: {time.process_time() - t0:.0f} s CPU")


if __name__ == "__main__":
    main()

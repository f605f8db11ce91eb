#!/usr/bin/python3
"""The corotated model's representation of held-out states without the oracle (rom14).

    corot_rep.py SNAP BASIS.h5 LEG.h5 LOCAL.h5 RODOUT.h5 [--r 6,12,24,all] [--k 176]
        [--rays T_R,T_H4,T_S2,T_H7] [--t 0.5,1] [--width 2]

The slab chain's strains (corot.rod_strains: relative rotation and offset per slab) of every
training FE state and its quarter turns, their POD (RODOUT.h5 /Vs, /sig, Euclidean, rotations
scaled by the section's half-width), and the local shapes' POD of corot_oracle.py (LOCAL.h5
/Vl). A held-out FE state is represented by its strains projected onto the first R strain
modes (the chain rebuilt from them: corot.rod_frames) and its local shape in that chain's
frames projected (M) onto the first K local modes: the nearest state the corotated model
u(a, ql) = R(a) (X - c0 + Vl ql) + c(a) - X can take without knowing the held-out rotations
(the linear span's M-projection is the comparison). Units mm, N mm.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from corot import Slabs, mpod, rod_frames, rod_strains, show, train_states, turn_strains  # noqa: E402
from rom11_energy import Energy  # noqa: E402
from rom11_iso_diag import states  # noqa: E402
from rom_basis import turn_maps, turn_snapshots  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    for n in ("snap", "basis", "leg", "local", "rodout"):
        ap.add_argument(n)
    ap.add_argument("--width", type=float, default=2.0)
    ap.add_argument("--r", default="6,12,24,all")
    ap.add_argument("--k", type=int, default=176)
    ap.add_argument("--consistent", action="store_true")
    ap.add_argument("--rays", default="T_R,T_H4,T_S2,T_H7")
    ap.add_argument("--t", type=lambda v: [float(c) for c in v.split(",")], default=[0.5, 1.0])
    a = ap.parse_args()
    m = Energy(a.snap, a.basis, a.leg)
    sl = Slabs(m.x, a.width)
    with h5py.File(a.local, "r") as f:
        Vl = f["Vl"][:, :a.k]
    cols = []
    for u in train_states(a.snap, m.fixed):
        R, c = sl.fit(u)
        s = rod_strains(R, c, sl.c0)
        R2, c2 = rod_frames(s, sl.c0)
        assert np.abs(R2 - R).max() < 1e-9 and np.abs(c2 - c).max() < 1e-9
        cols.append(s.ravel())
    S = turn_strains(np.stack(cols, axis=1), turn_maps(m.x))
    U, sig, _ = np.linalg.svd(S, full_matrices=False)
    keep = sig > 1e-10 * sig[0]
    Vs = U[:, keep]
    with h5py.File(a.rodout, "w") as f:
        f["Vs"], f["sig"] = Vs, sig[keep]
    print(f"corot_rep: {S.shape[1]} training strain fields ({sl.nsl} slabs x 6) -> "
          f"{Vs.shape[1]} modes; singular values " + " ".join(f"{v:.3g}" for v in sig[:12]))
    rs = [Vs.shape[1] if v == "all" else int(v) for v in a.r.split(",")]
    # local bases in the truncated chains' frames (--consistent): the training states' local
    # shapes measured in the frames the model itself can take (their strains on the first R
    # modes), so the frames' truncation error is a local shape the basis holds
    Vls = {}
    if a.consistent:
        for r in rs:
            P = Vs[:, :r]
            cl = []
            for j, u in enumerate(train_states(a.snap, m.fixed)):
                sr = P @ (P.T @ S[:, j])
                cl.append(sl.local(u, sl.field(*rod_frames(sr.reshape(-1, 6), sl.c0))))
            Vr, sg = mpod(turn_snapshots(np.stack(cl, axis=1), turn_maps(m.x)), m.M, m.fixed)
            Vls[r] = Vr[:, :a.k]
            with h5py.File(f"{a.rodout[:-3]}_local_r{r}.h5", "w") as f:
                f["Vl"], f["sig"] = Vr, sg
            print(f"corot_rep: r = {r}: local shapes in the truncated frames -> {Vr.shape[1]} "
                  f"modes; the {a.k}th singular value {sg[min(a.k, len(sg)) - 1]:.3g} of {sg[0]:.3g}")
    for name, t, u, p, _, _ in states(a.snap, a.rays.split(","), a.t, m.fixed):
        print(f"{name} t {t:.2f}: pressure work FE")
        show(m, "FE state", u, u, p)
        show(m, "V's M-projection (n = 224)", u, m.V @ m.project_M(u), p)
        s = rod_strains(*sl.fit(u), sl.c0).ravel()
        for r in rs:
            sr = Vs[:, :r] @ (Vs[:, :r].T @ s)
            fld = sl.field(*rod_frames(sr.reshape(-1, 6), sl.c0))
            ul = sl.local(u, fld)
            L = Vls.get(r, Vl)
            w = sl.glob(L @ (L.T @ (m.M @ ul)), fld)
            err = np.linalg.norm(s - sr) / np.linalg.norm(s)
            show(m, f"{r} strain + {a.k} local modes", u, w, p)
            print(f"        (strain field's relative error {err:.4f})")


if __name__ == "__main__":
    main()

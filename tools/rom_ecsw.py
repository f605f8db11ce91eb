#!/usr/bin/python3
"""rom_ecsw.py: hyper-reduction of the reduced-order FE leg by ECSW (issue 34, stage 4).

    /usr/bin/python3 tools/rom_ecsw.py A.h5 [--out WEIGHTS.h5] [--tol 1e-3 [--tol 1e-4 ...]]

A.h5 is `crawlsim rom ecsw-matrix`'s output: for each element set (Tet10 bodies, fibres,
pressure faces) the matrix A whose column e holds element e's reduced force V_e^T f_e at every
training snapshot (rows: snapshot x reduced coordinate; the chambers' pressure faces are not
fitted: their loads are exact in closed form, fem/fem_rom.h). Energy-conserving sampling and
weighting (Farhat, Avery, Chapman and Cortial 2014): non-negative weights w with A w ~ A 1,
found by non-negative least squares, one set at a time, each snapshot's block of rows scaled to
unit norm so that every snapshot counts alike. Non-negative weights of whole elements keep the
reduced forces a gradient (conservative) and the reduced tangent symmetric; weighting whole
Tet10s (not quadrature points) keeps each element's mixed pressure. Lawson-Hanson's active set
(scipy.optimize.nnls's algorithm, tools/rom_nnls.py: an incremental Cholesky factor of the kept
columns) is stopped once ||A w - A 1|| <= tol ||A 1||. Several --tol: one pass to the smallest,
the weights of each larger tolerance taken where the pass first reaches it (what a separate
run stopped there returns), each written to WEIGHTS_tol<tol>.h5. Writes WEIGHTS.h5
(fem/fem_rom_act.h): tet_id, tet_w, fibre_id, fibre_w and per set the kept count and residual.
A fibre that is slack in every training state has no force there and gets no weight.
A mixed basis (attribute m > 0: pressure modes, fem/fem_rom.h csfRom.m): each snapshot's Tet10
rows also hold the elements' constraint shares P_e (v_e - V_e), and /A_tet_pressure each Tet10's
share of the pressure matrix A; both are fitted with the forces (each its own unit-norm block),
so the hyper-reduced p^ = A_w^-1 b_w stays the unreduced one on the training states.
A fibre strain basis (attribute mf > 0, fem/fem_rom_fibre.h): each snapshot's fibre rows also
hold the fibres' shares W_f Q_f E_f and W_f Q_f S(Ebar_f) of the projections and of G's action
on that state's E^ and s^, and /A_fibre_projection each fibre's share of G = sum W Q Q^T;
fitted the same way (forces, the four shares per snapshot and G once, each its own unit-norm
block), so the weighted E^ and S* stay the unreduced ones on the training states. G's
mf (mf + 1) / 2 rows (7 260 at mf = 120) can outnumber the snapshots' rows and set the fit's
cost: --no-projection leaves them out and relies on G's action at the training states.
With several --tol, each weights file is written as soon as every set has reached its
tolerance (the larger tolerances' files exist while the pass goes on to the smallest).
"""
import argparse
import os
import sys
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # the shared two-core machine
os.environ.setdefault("OMP_NUM_THREADS", "1")

import h5py  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rom_nnls import nnls_chol  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("matrix")
    ap.add_argument("--out", default=None)
    ap.add_argument("--tol", type=float, action="append", default=None,
                    help="relative residual of the fit, each snapshot block at unit norm "
                    "(default 1e-3; repeat for several: one pass, one weights file each)")
    ap.add_argument("--set", action="append", choices=["tet", "fibre", "face"], default=None,
                    help="fit only these element sets (repeatable; default every set in the "
                    "matrix): a set left out is absent from the weights file, every element "
                    "of it kept at weight 1 (fem/fem_rom_act.h)")
    ap.add_argument("--no-projection", action="store_true",
                    help="leave /A_fibre_projection (G's entries) out of the fibre fit: the "
                    "snapshots' rows of G's action on their E^ and s^ remain")
    a = ap.parse_args()
    tols = sorted(set(a.tol or [1e-3]), reverse=True)
    out = a.out or os.path.join(os.path.dirname(a.matrix) or ".", "weights.h5")
    outs = {tols[0]: out} if len(tols) == 1 else {
        t: f"{os.path.splitext(out)[0]}_tol{t:g}.h5" for t in tols}
    res = {t: {} for t in tols}

    def write(t):
        with h5py.File(outs[t], "w") as f:
            f.attrs["format"] = "crawlsim-rom-weights 1"
            f.attrs["tol"] = t
            f.attrs["matrix"] = os.path.abspath(a.matrix)
            for key, (idx, w, rel, ncol) in res[t].items():
                f[f"{key}_id"] = idx.astype(float)
                f[f"{key}_w"] = w
                f.attrs[f"{key}_kept"] = len(idx)
                f.attrs[f"{key}_candidates"] = ncol
                f.attrs[f"{key}_residual"] = rel
        print(f"rom_ecsw: {outs[t]}", flush=True)

    with h5py.File(a.matrix, "r") as f:
        n = int(f.attrs["n"])
        ns = int(f.attrs["nsnap"])
        mp = int(f.attrs["m"]) if "m" in f.attrs else 0
        mfib = int(f.attrs["mf"]) if "mf" in f.attrs else 0
        todo = [(key, name) for key, name in (("tet", "A_tet"), ("fibre", "A_fibre"),
                                              ("face", "A_face"))
                if name in f and not (a.set and key not in a.set)]
        for key, name in todo:
            # the chambers' faces are in closed form on the C side, not fitted
            # a mixed basis: each snapshot's Tet10 rows are n forces and m constraint shares,
            # with a fibre strain basis its fibre rows n forces and four blocks of mf shares
            blocks = ([n, mp] if key == "tet" and mp > 0 else
                      [n, mfib, mfib, mfib, mfib] if key == "fibre" and mfib > 0 else [n])
            wd = sum(blocks)
            # and the constant matrix, once: the pressure matrix A = sum_e (V_e/kappa) P_e P_e^T
            # or the fibre projection G = sum_f W_f Q_f Q_f^T
            extra = ("A_tet_pressure" if key == "tet" and mp > 0 else
                     "A_fibre_projection" if key == "fibre" and mfib > 0 and
                     not a.no_projection else None)
            r0, nc = f[name].shape
            blocks_extra = f[extra].shape[0] if extra else 0
            A = np.empty((r0 + blocks_extra, nc))  # one copy in memory (GB for the fibres)
            f[name].read_direct(A, dest_sel=np.s_[:r0])
            if extra:
                f[extra].read_direct(A, dest_sel=np.s_[r0:])
            cols = np.flatnonzero(np.abs(A).sum(axis=0) > 0)  # faces never loaded drop out
            if len(cols) < nc:
                A = A[:, cols]
            b = A.sum(axis=1)
            # each snapshot's block of forces (and of constraint shares) at unit norm, so every
            # snapshot counts alike and forces (N) and volumes (mm^3) are commensurate; the
            # pressure matrix as one block
            spans = []
            for k in range(ns):
                o = k * wd
                for nb in blocks:
                    spans.append((o, o + nb))
                    o += nb
            if blocks_extra:
                spans.append((ns * wd, ns * wd + blocks_extra))
            for lo, hi in spans:
                s = np.linalg.norm(b[lo:hi])
                if s > 0:
                    A[lo:hi] /= s
                    b[lo:hi] /= s
            t0, c0 = time.time(), time.process_time()
            last = key == todo[-1][0]

            def reached(t, e, key=key, cols=cols, ncol=A.shape[1], last=last):
                sel = np.flatnonzero(e[0] > 0)
                res[t][key] = (cols[sel], e[0][sel], e[1], ncol)
                print(f"rom_ecsw: {key}: reached tol {t:g}: {e[2]} kept, {e[3]:.1f} s "
                      f"({e[4]:.1f} s of CPU)", flush=True)
                if last and t != tols[-1]:
                    write(t)  # every set has its weights at t: the file exists from now on

            w, rel, path = nnls_chol(A, b, tols[-1], record=tols, on_record=reached)
            for t in tols:
                wt, relt, _, sec, cpu = path.get(
                    t, (w, rel, 0, time.time() - t0, time.process_time() - c0))
                sel = np.flatnonzero(wt > 0)
                res[t][key] = (cols[sel], wt[sel], relt, A.shape[1])
                print(f"rom_ecsw: {key} ({A.shape[0]} rows): tol {t:g}: {len(sel)} of "
                      f"{A.shape[1]} elements kept, relative residual {relt:.2e}, {sec:.1f} s "
                      f"({cpu:.1f} s of CPU)", flush=True)
            del A
    for t in tols:
        if t == tols[-1] or len(tols) == 1 or t not in path:
            write(t)  # the smallest, and any the pass ended before reaching


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""rom_ecsw.py: hyper-reduction of the reduced-order FE leg by ECSW (issue 34, stage 4).

    /usr/bin/python3 tools/rom_ecsw.py A.h5 [--out WEIGHTS.h5] [--tol 1e-3]

A.h5 is `crawlsim rom ecsw-matrix`'s output: for each element set (Tet10 bodies, fibres,
pressure faces) the matrix A whose column e holds element e's reduced force V_e^T f_e at every
training snapshot (rows: snapshot x reduced coordinate; the chambers' pressure faces are not
fitted: their loads are exact in closed form, fem/fem_rom.h). Energy-conserving sampling and
weighting (Farhat, Avery, Chapman and Cortial 2014): non-negative weights w with A w ~ A 1,
found by non-negative least squares, one set at a time, each snapshot's block of rows scaled to
unit norm so that every snapshot counts alike. Non-negative weights of whole elements keep the
reduced forces a gradient (conservative) and the reduced tangent symmetric; weighting whole
Tet10s (not quadrature points) keeps each element's mixed pressure. Lawson-Hanson's active set
(scipy.optimize.nnls) is stopped once ||A w - A 1|| <= tol ||A 1||, or after 3 min(rows, columns)
additions, or when the element just added cannot enter (the greedy loop below adds
the element of the largest gradient, then solves the least squares on the kept set and steps
back into the feasible region, as Lawson-Hanson does). Writes WEIGHTS.h5 (fem/fem_rom_act.h):
tet_id, tet_w, fibre_id, fibre_w and per set the kept count and residual. A fibre that is
slack in every training state has no force there and gets no weight.
"""
import argparse
import os
import sys
import time

import h5py
import numpy as np


def nnls_tol(A, b, tol, max_keep=None):
    """Lawson-Hanson NNLS stopped at ||A w - b|| <= tol ||b||. Returns (w, rel. residual)."""
    m, n = A.shape
    w = np.zeros(n)
    keep = np.zeros(n, bool)
    nb = np.linalg.norm(b)
    r = b.copy()
    max_keep = max_keep or min(m, n)
    it = 0
    outer = 0
    while np.linalg.norm(r) > tol * nb and keep.sum() < max_keep and outer < 3 * max_keep:
        outer += 1
        g = A.T @ r
        g[keep] = -np.inf
        j = int(np.argmax(g))
        if g[j] <= 1e-14 * np.abs(g[np.isfinite(g)]).max():
            break
        keep[j] = True
        while True:
            it += 1
            idx = np.flatnonzero(keep)
            z, *_ = np.linalg.lstsq(A[:, idx], b, rcond=None)
            if np.all(z > 0):
                w[:] = 0
                w[idx] = z
                break
            # step back into the feasible region (Lawson-Hanson's inner loop)
            neg = z <= 0
            alpha = np.min(w[idx][neg] / (w[idx][neg] - z[neg]))
            w[idx] = w[idx] + alpha * (z - w[idx])
            drop = idx[w[idx] <= 1e-14 * max(1.0, w[idx].max())]
            keep[drop] = False
            w[drop] = 0
            if j in drop:
                break  # the element just added cannot enter: Lawson-Hanson's stagnation
        r = b - A @ w
    return w, np.linalg.norm(r) / nb


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("matrix")
    ap.add_argument("--out", default=None)
    ap.add_argument("--tol", type=float, default=1e-3,
                    help="relative residual of the fit, each snapshot block at unit norm")
    a = ap.parse_args()
    out = a.out or os.path.join(os.path.dirname(a.matrix) or ".", "weights.h5")
    res = {}
    with h5py.File(a.matrix, "r") as f:
        n = int(f.attrs["n"])
        ns = int(f.attrs["nsnap"])
        for key, name in (("tet", "A_tet"), ("fibre", "A_fibre"), ("face", "A_face")):
            if name not in f:
                continue  # the chambers' faces: in closed form on the C side, not fitted
            A = f[name][...]
            cols = np.flatnonzero(np.abs(A).sum(axis=0) > 0)  # faces never loaded drop out
            A = A[:, cols]
            b = A.sum(axis=1)
            # each snapshot's block of n rows at unit norm
            for k in range(ns):
                s = np.linalg.norm(b[k * n:(k + 1) * n])
                if s > 0:
                    A[k * n:(k + 1) * n] /= s
                    b[k * n:(k + 1) * n] /= s
            t0 = time.time()
            w, rel = nnls_tol(A, b, a.tol)
            sel = np.flatnonzero(w > 0)
            res[key] = (cols[sel], w[sel], rel, A.shape[1])
            print(f"rom_ecsw: {key}: {len(sel)} of {A.shape[1]} elements kept, relative residual "
                  f"{rel:.2e} (tol {a.tol:g}), {time.time() - t0:.1f} s")
    with h5py.File(out, "w") as f:
        f.attrs["format"] = "crawlsim-rom-weights 1"
        f.attrs["tol"] = a.tol
        f.attrs["matrix"] = os.path.abspath(a.matrix)
        for key, (idx, w, rel, ncol) in res.items():
            f[f"{key}_id"] = idx.astype(float)
            f[f"{key}_w"] = w
            f.attrs[f"{key}_kept"] = len(idx)
            f.attrs[f"{key}_candidates"] = ncol
            f.attrs[f"{key}_residual"] = rel
    print(f"rom_ecsw: {out}")


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""rom_nnls.py: Lawson-Hanson non-negative least squares with an incremental Cholesky factor of
the active columns, stopped at a relative residual (the ECSW fit of tools/rom_ecsw.py, issue 34).

    w, rel, path = nnls_chol(A, b, tol, max_keep=None, record=(1e-2, 1e-3))

min ||A w - b|| subject to w >= 0 by Lawson and Hanson's active set (Solving Least Squares
Problems, 1974, ch. 23, algorithm NNLS; the algorithm of scipy.optimize.nnls): add the free
column of the largest gradient A^T (b - A w), solve the least squares on the kept (passive) set,
step back into w >= 0 when a kept weight would turn negative and drop the columns that reach
zero. What makes it fast: the kept set's least squares is solved through the upper-triangular
factor R of its Gram matrix, R^T R = A_P^T A_P, which grows by one row and column per added
column (R^T s = A_P^T a_j, rho^2 = a_j.a_j - s.s: O(m k + k^2) for k kept columns of m rows,
instead of a fresh O(m k^2) QR per step); a drop deletes its column from R by Givens rotations
(O(k^2)). The residual and gradient are updated with one product by A per step.
The normal equations square the kept columns' condition number: a column whose new pivot
rho^2 falls below 1e-12 a_j.a_j (numerically in the span of the kept ones) is not added, as
Lawson-Hanson's own test of a new column's independence does; the stopping tolerances of an
ECSW fit (1e-2 ... 1e-6 of ||b||) are far above the resulting round-off.

It stops at ||A w - b|| <= tol ||b||, at max_keep kept columns, after 3 n outer steps, or when no
free column has a positive gradient (the exact NNLS solution: then w and the kept set are
scipy.optimize.nnls's, tests/tools/test_rom_tools.py). `record`: relative residuals at which the
weights are also returned (the first step at or below each, as separate runs stopped there would
return them): `path` maps each to (w, rel, kept, wall seconds, CPU seconds).
"""
import time

import numpy as np
import scipy.linalg as sla


def nnls_chol(A, b, tol=0.0, max_keep=None, record=(), on_record=None):
    """Lawson-Hanson NNLS of A (m x n), b (m) stopped at ||A w - b|| <= tol ||b||.
    Returns (w (n), relative residual, {tol_k: (w, rel, kept, wall s, CPU s)} per tol_k of
    record); on_record(tol_k, that tuple) is called as each is reached."""
    A = np.asarray(A, dtype=float)
    b = np.asarray(b, dtype=float)
    m, n = A.shape
    At = np.ascontiguousarray(A.T)  # rows are columns of A: a_j contiguous, A^T r one gemv
    nb = float(np.linalg.norm(b))
    max_keep = min(max_keep or min(m, n), min(m, n))
    w = np.zeros(n)
    c = At @ b  # A^T b
    kept = []  # the passive set, in the order of R's rows
    cap = max(16, min(max_keep, 256))
    R = np.zeros((cap, cap))  # upper triangular, R^T R = A_P^T A_P
    AP = np.empty((cap, m))  # the kept columns of A as rows, in the order of R
    r = b.copy()
    t0 = time.time()
    c0 = time.process_time()
    path = {}
    pending = sorted(set(float(t) for t in record), reverse=True)
    eps_g = None

    def rel_now():
        return float(np.linalg.norm(r)) / nb if nb > 0 else 0.0

    def note(rel):
        while pending and rel <= pending[0]:
            t = pending.pop(0)
            path[t] = (w.copy(), rel, len(kept), time.time() - t0, time.process_time() - c0)
            if on_record:
                on_record(t, path[t])

    def grow(k):
        nonlocal R, AP
        if k > R.shape[0]:
            c2 = max(k, 2 * R.shape[0])
            R2 = np.zeros((c2, c2))
            R2[:R.shape[0], :R.shape[0]] = R
            AP2 = np.empty((c2, m))
            AP2[:AP.shape[0]] = AP
            R, AP = R2, AP2

    def solve(k):
        """z_P = (A_P^T A_P)^-1 A_P^T b through R."""
        cp = c[kept]
        y = sla.solve_triangular(R[:k, :k], cp, trans="T", lower=False, check_finite=False)
        return sla.solve_triangular(R[:k, :k], y, lower=False, check_finite=False)

    def delete(i, k):
        """R (k x k) without column i: the Hessenberg rest back to triangular by Givens
        rotations of rows (i, i+1), ..., (k-2, k-1) (Golub and Van Loan, 6.5.2); O(k^2)."""
        R[:k, i:k - 1] = R[:k, i + 1:k].copy()
        for l in range(i, k - 1):
            x, y = R[l, l], R[l + 1, l]
            h = np.hypot(x, y)
            if h == 0.0:
                continue
            cs, sn = x / h, y / h
            rl = R[l, l:k - 1].copy()
            rl1 = R[l + 1, l:k - 1]
            R[l, l:k - 1] = cs * rl + sn * rl1
            R[l + 1, l:k - 1] = -sn * rl + cs * rl1
            R[l + 1, l] = 0.0
        R[k - 1, :k] = 0.0
        R[:k, k - 1] = 0.0
        AP[i:k - 1] = AP[i + 1:k].copy()

    if nb == 0.0:
        return w, 0.0, path
    rel = rel_now()
    note(rel)
    outer = 0
    banned = np.zeros(n, bool)  # columns refused this step (dependent, or cannot enter)
    while rel > tol and len(kept) < max_keep and outer < 3 * n:
        outer += 1
        g = At @ r
        if eps_g is None:
            eps_g = 1e-14 * max(float(np.abs(g).max()), 1e-300)
        g[kept] = -np.inf
        g[banned] = -np.inf
        j = int(np.argmax(g))
        if not g[j] > eps_g:
            break  # Kuhn-Tucker conditions hold: the exact NNLS solution
        k = len(kept)
        aj = At[j]
        v = AP[:k] @ aj
        d = float(aj @ aj)
        s = sla.solve_triangular(R[:k, :k], v, trans="T", lower=False,
                                 check_finite=False) if k else np.zeros(0)
        rho2 = d - float(s @ s)
        if rho2 <= 1e-12 * d:
            banned[j] = True  # numerically dependent on the kept columns
            continue
        grow(k + 1)
        R[:k, k] = s
        R[k, k] = np.sqrt(rho2)
        AP[k] = aj
        kept.append(j)
        while True:
            k = len(kept)
            z = solve(k)
            if np.all(z > 0):
                w[:] = 0.0
                w[kept] = z
                break
            wp = w[kept]
            neg = z <= 0
            alpha = float(np.min(wp[neg] / (wp[neg] - z[neg])))
            wp = wp + alpha * (z - wp)
            drop = wp <= 1e-14 * max(1.0, float(wp.max()))
            # the column just added enters with weight 0 when alpha = 0: Lawson-Hanson's
            # "cannot enter" (its z_j <= 0); refuse it for this step instead of cycling
            w[kept] = wp
            for i in np.flatnonzero(drop)[::-1]:
                delete(int(i), len(kept))
                w[kept[i]] = 0.0
                if kept[i] == j:
                    banned[j] = True
                del kept[i]
            if not kept:
                break
        k = len(kept)
        r = b - AP[:k].T @ w[kept] if k else b.copy()
        if not banned[j]:
            banned[:] = False  # the kept set changed: every column may be tried again
        rel = rel_now()
        note(rel)
    return w, rel, path

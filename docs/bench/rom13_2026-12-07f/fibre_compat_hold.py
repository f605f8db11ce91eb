#!/usr/bin/python3
"""Fibre-compatible wall shapes with the bend held (rom13; rom12's fibre_compat_modes.py with
further constraints). Per FE state u (a training state, or with --oracle a held-out one: a
diagnostic, never a basis) and its M-projection w0 = V q_M: Newton steps d of
    min 1/2 d^T A d + 1/2 sum_taut W (E_f(w + d) - max(E_f(u), 0))^2   (linearised in d)
    s.t.  V_c(w + d) = V_c(u)              (the twelve chamber volumes; --keep-volumes)
          H (w + d) = H u                  (--hold: the bend, below)
A = K(w) the rubber's linear elastic stiffness in w's configuration (rom12's, mu = 2 C10, the
FE's P0 bulk) or, --norm M, the consistent mass matrix scaled to K's trace (the M-norm of rom12's
Next 1(a)); W = EA L0; w = w0 + the shape so far. Lagrange multipliers by the Schur complement
(one sparse factor per step, one solve per constraint). --hold:
  tip    the tip face's mean displacement (3 rows),
  ends   the mean displacement and the mean (X - Xc) x u (a rotation measure, 6 rows) of the
         cross-section slabs |z - z_j| < 1.5 mm at the connectors (z = 54, 112 mm) and the tip face,
  axis   the same at z = 27, 54, 83, 112, 139 mm and the tip (36 rows).
Printed per step: the taut fibres' mismatch energy (N mm), the tip's distance from the FE's,
the M-norm distance |u - w|_M / |u|_M and the worst chamber volume against the FE's.
Writes OUT.h5: /d (ndof, K) the shapes w - w0, /D their POD M-orthogonal to V (rom12's format:
enriched.py, shape_volumes.py read it), /states. Resumable: OUT.h5.part.
Usage: fibre_compat_hold.py SNAP BASIS.h5 LEG.h5 OUT.h5 --only RAYS [--oracle] [--t 1]
       [--keep-volumes] [--hold tip|ends|axis] [--norm K|M] [--iterate N]"""
import argparse
import os
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # the OpenMP OpenBLAS: one thread, no spin-waiting
os.environ.setdefault("OMP_NUM_THREADS", "1")
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "rom"))
sys.path.insert(0, os.path.join(HERE, "..", "rom12_2026-12-07e"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402
import scipy.sparse.linalg as spl  # noqa: E402
from fibre_compat_modes import stiffness  # noqa: E402
from rom11_energy import Energy  # noqa: E402
from rom11_iso_diag import states  # noqa: E402

LEVELS = {"tip": [], "ends": [54.0, 112.0], "axis": [27.0, 54.0, 83.0, 112.0, 139.0]}


def hold_rows(x, tip, kind):
    """(nrow, ndof) sparse rows H of the bend's hold (above)."""
    rows = []
    sets = [np.flatnonzero(np.abs(x[:, 2] - z) < 1.5) for z in LEVELS[kind]] + [np.flatnonzero(tip)]
    nn = x.shape[0]
    for j, s in enumerate(sets):
        for i in range(3):  # mean displacement
            r = np.zeros((nn, 3))
            r[s, i] = 1.0 / s.size
            rows.append(r.ravel())
        if kind == "tip":
            continue
        X = x[s] - x[s].mean(axis=0)
        for i in range(3):  # mean (X - Xc) x u, component i: e_i . (X x u) = u . (e_i x X)
            r = np.zeros((nn, 3))
            r[s] = np.cross(np.eye(3)[i], X) / s.size
            rows.append(r.ravel())
    return np.array(rows)


def pod_against(V, M, Dr):
    """Dr's columns M-orthogonalised against V (twice), then their POD in M (decreasing)."""
    Y = Dr.copy()
    Gi = np.linalg.inv(V.T @ (M @ V))
    for _ in range(2):
        Y -= V @ (Gi @ (V.T @ (M @ Y)))
    lam, Phi = np.linalg.eigh(Y.T @ (M @ Y))
    o = np.argsort(lam)[::-1]
    lam, Phi = np.clip(lam[o], 0, None), Phi[:, o]
    k = int((lam > lam[0] * 1e-14).sum())
    return Y @ Phi[:, :k] / np.sqrt(lam[:k]), np.sqrt(lam)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    for name in ("snapdir", "basis", "legfile", "out"):
        ap.add_argument(name)
    ap.add_argument("--t", type=lambda v: [float(c) for c in v.split(",")], default=[1.0])
    ap.add_argument("--only", required=True)
    ap.add_argument("--oracle", action="store_true")
    ap.add_argument("--keep-volumes", action="store_true")
    ap.add_argument("--hold", choices=("none", "tip", "ends", "axis"), default="none")
    ap.add_argument("--norm", choices=("K", "M"), default="K")
    ap.add_argument("--iterate", type=int, default=1)
    a = ap.parse_args()
    m = Energy(a.snapdir, a.basis, a.legfile)
    x, V, M, fixed = m.x, m.V, m.M, m.fixed
    ndof = x.size
    node, coef, L0, EA = m.fib
    assert (node[:, :10] == node[:, 10:]).all()  # each chord in one Tet10 (rom12)
    node, coef = node[:, :10], coef[:, :10] + coef[:, 10:]
    W = EA * L0
    nf = node.shape[0]
    fdof = (3 * node[:, :, None] + np.arange(3)).reshape(nf, 30)
    frows = np.broadcast_to(fdof[:, :, None], (nf, 30, 30)).ravel()
    fcols = np.broadcast_to(fdof[:, None, :], (nf, 30, 30)).ravel()
    free = np.flatnonzero(~fixed)
    H = hold_rows(x, m.tip, a.hold) if a.hold != "none" else np.zeros((0, ndof))
    rays = set(a.only.split(","))
    part = a.out + ".part"
    done = {}
    if os.path.exists(part):
        with h5py.File(part, "r") as f:
            done = {f[k].attrs["state"]: f[k][...] for k in f}
    print(f"fibre_compat_hold: n = {V.shape[1]}, norm {a.norm}, volumes {'kept' if a.keep_volumes else 'free'},"
          f" hold {a.hold} ({H.shape[0]} rows), {a.iterate} steps; {len(done)} done")
    names = []
    for name, t, u, p, _, _ in states(a.snapdir, rays, a.t, fixed):
        key = f"{name}@{t:g}"
        names.append(key)
        if key in done:
            continue
        t0 = time.process_time()
        w0 = V @ m.project_M(u)
        vu = m.chambers(u)[0]
        du = np.einsum("fa,fai->fi", coef, (x + u.reshape(-1, 3))[node])
        Eu = np.maximum(0.5 * ((du ** 2).sum(1) / L0 ** 2 - 1.0), 0.0)
        nu = np.sqrt(u @ (M @ u))
        dtot = np.zeros(ndof)

        def report(lab, w):
            dw = np.einsum("fa,fai->fi", coef, (x + w.reshape(-1, 3))[node])
            Ew = 0.5 * ((dw ** 2).sum(1) / L0 ** 2 - 1.0)
            mis = 0.5 * float((W * (np.maximum(Ew, 0) - Eu) ** 2).sum())
            R3 = (u - w).reshape(-1, 3)
            tip = float(np.sqrt((R3[m.tip].mean(axis=0) ** 2).sum()))
            ev = m.chambers(w)[0] / vu - 1
            c = int(np.argmax(np.abs(ev)))
            print(f"    {key} {lab:8s}: mismatch {mis:9.4g} N mm (largest strain {Ew.max():.3f}, FE {Eu.max():.3f});"
                  f" tip {tip:.3f} mm; |u - w|_M {100 * np.sqrt((u - w) @ (M @ (u - w))) / nu:.3f} %;"
                  f" worst volume {100 * ev[c]:+.2f} % ({c // 4 + 1}.{c % 4 + 1}); hold gap"
                  f" {np.abs(H @ (u - w)).max() if H.shape[0] else 0:.2e}")
            sys.stdout.flush()
            return dw, Ew
        dw, Ew = report("V q_M", w0)
        for it in range(a.iterate):
            w = w0 + dtot
            taut = Ew > 0
            r = np.where(taut, Ew - Eu, 0.0)
            Df = (coef[:, :, None] * (dw / L0[:, None] ** 2)[:, None, :]).reshape(nf, 30)
            wt = W * taut
            Kf = (wt[:, None, None] * Df[:, :, None] * Df[:, None, :]).ravel()
            if a.norm == "K":
                rk, ck, vk = stiffness(x, m.tet, m.dNdX, m.wq, w, 2 * m.C10, m.kappa)
                A = sp.csr_matrix((vk, (rk, ck)), shape=(ndof, ndof))
            else:
                if it == 0:
                    Kref = sp.csr_matrix((lambda r_: (r_[2], (r_[0], r_[1])))(
                        stiffness(x, m.tet, m.dNdX, m.wq, np.zeros(ndof), 2 * m.C10, m.kappa)),
                        shape=(ndof, ndof))
                    sM = Kref.diagonal().sum() / M.diagonal().sum()
                A = sM * M
            A = A + sp.csr_matrix((Kf, (frows, fcols)), shape=(ndof, ndof))
            lu = spl.splu(A[free][:, free].tocsc(), permc_spec="COLAMD")
            b = np.zeros(ndof)
            np.add.at(b, fdof.ravel(), (-(wt * r)[:, None] * Df).ravel())
            d = np.zeros(ndof)
            d[free] = lu.solve(b[free])
            C, g = [], []
            if a.keep_volumes:
                vw, Gc = m.chambers(w)
                C.append(Gc)
                g.append(vu - vw)
            if H.shape[0]:
                C.append(H)
                g.append(H @ (u - w))
            if C:
                C, g = np.concatenate(C), np.concatenate(g)
                Z = lu.solve(np.ascontiguousarray(C[:, free].T))
                lam = np.linalg.solve(C[:, free] @ Z, C[:, free] @ d[free] - g)
                d[free] -= Z @ lam
            dtot += d
            dw, Ew = report(f"step {it + 1}", w0 + dtot)
        print(f"  {key}: {time.process_time() - t0:.0f} s CPU")
        with h5py.File(part, "a") as f:
            k = f"s{len(f)}"
            f[k] = dtot
            f[k].attrs["state"] = key
        done[key] = dtot
    Dr = np.stack([done[k] for k in names], axis=1)
    D, sig = pod_against(V, M, Dr)
    with h5py.File(a.out, "w") as f:
        f["d"], f["D"], f["sig"] = Dr, D, sig
        f["states"] = np.array(names, dtype="S")
    print(f"fibre_compat_hold: {len(names)} shapes -> {D.shape[1]} POD modes")


if __name__ == "__main__":
    main()

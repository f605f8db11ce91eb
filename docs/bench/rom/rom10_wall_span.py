#!/usr/bin/python3
"""rom10_wall_span.py: the chamber walls' best fit against the POD's size and training (issue 34,
session rom10).

    /usr/bin/python3 docs/bench/rom/rom10_wall_span.py SNAPDIR [--n 96,128,192,256]
        [--ray T_S2 ...] [--drop RAY ...] [--wall-weight W]

The question it answers: when no span holds a held-out ray's chamber walls within 1 %
(romacc_volume_diag.py's "faces' projection"), is it the POD's truncation (more modes of the
same training would) or the training (no size would)? One POD of SNAPDIR's training rays (every
state and its three quarter turns, rom_basis.py's --turns; --drop leaves rays out, to measure
what a family adds), in the M inner product (rom_basis.py's, without supremizers), then for
each size n of --n (nested: the first n modes) and each state of the held-out rays:
  - walls: the least-squares fit of the FE state's chamber-face nodes by the first n modes
    (romacc_volume_diag.py's fit) and the twelve chambers' volumes of that fit, the worst
    relative error against the FE state's volumes;
  - tip: the error of the M-projection's tip (the mean of the free end's nodes, rom_project.py).
With --wall-weight W the POD's inner product is M + W (m_bar / n_wall) D, D the identity on the
chamber faces' dofs and m_bar the mean diagonal of M there: the walls weighted W times their
share of the mass, a basis that enriches the walls' shapes directly (W = 0: rom_basis.py's).
The size nmax of the span (every mode with sigma_i > 1e-12 sigma_1) is printed, and n above it
is clipped. Units mm; volumes relative (%).
"""
import argparse
import os
import sys

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))
sys.path.insert(0, HERE)
from rom_basis import mass_matrix, read_mesh, read_rays, turn_maps, turn_snapshots  # noqa: E402
from romacc_volume_diag import chamber_faces, chamber_volumes  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("snapdir")
    ap.add_argument("--n", default="96,128,192,256",
                    type=lambda v: [int(c) for c in v.split(",") if c])
    ap.add_argument("--ray", action="append", default=None)
    ap.add_argument("--drop", action="append", default=[])
    ap.add_argument("--wall-weight", type=float, default=0.0)
    a = ap.parse_args()
    x, tet, fixed, rho, _ = read_mesh(a.snapdir)
    face, cid = chamber_faces(a.snapdir)
    fn = np.unique(face.ravel())
    fd = (3 * fn[:, None] + np.arange(3)).ravel()
    Ms, _ = mass_matrix(x, tet, rho)
    M = sp.kron(Ms, sp.identity(3), format="csr")
    rays = read_rays(a.snapdir)
    unknown = [r for r in a.drop if r not in [q["name"] for q in rays]]
    if unknown:
        sys.exit(f"rom10_wall_span: --drop {','.join(unknown)}: no such ray in {a.snapdir}")
    train = [r for r in rays if r["kind"] == "train" and r["name"] not in a.drop]
    test = [r for r in rays if r["kind"] == "test" and (not a.ray or r["name"] in a.ray)]
    if not train or not test:
        sys.exit(f"rom10_wall_span: {a.snapdir}: {len(train)} training, {len(test)} held-out rays")
    X = np.concatenate([r["u"] for r in train], axis=0).T
    X[fixed] = 0.0
    maps = turn_maps(x)
    if maps is None:
        sys.exit("rom10_wall_span: the mesh is not symmetric under quarter turns")
    X = turn_snapshots(X, maps)
    X[fixed] = 0.0
    W = M
    if a.wall_weight > 0:
        mbar = M.diagonal()[fd].mean()
        d = np.zeros(M.shape[0])
        d[fd] = a.wall_weight * mbar * M.shape[0] / fd.size
        W = (M + sp.diags(d)).tocsr()
    C = X.T @ (W @ X)
    lam, Phi = np.linalg.eigh(C)
    order = np.argsort(lam)[::-1]
    lam, Phi = np.clip(lam[order], 0, None), Phi[:, order]
    nmax = int((lam > lam[0] * 1e-24).sum())
    V = X @ (Phi[:, :nmax] / np.sqrt(lam[:nmax]))
    V[fixed] = 0.0
    del X
    # M-orthonormal nested columns for the M-projection (Gram-Schmidt in M keeps the nesting)
    Gm = np.linalg.cholesky(V.T @ (M @ V))
    Vm = np.linalg.solve(Gm, V.T).T
    # the walls' fit: QR of the faces' rows keeps the nesting too
    Qf, Rf = np.linalg.qr(V[fd])
    xc = x[fixed.reshape(-1, 3).any(axis=1)].mean(axis=0)
    ax = np.argmax(np.abs(x - xc).max(axis=0))
    far = np.abs(x[:, ax] - xc[ax])
    tipn = far > far.max() - 1e-9 * max(far.max(), 1.0)
    print(f"rom10_wall_span: {len(train)} training rays ({','.join(r['name'] for r in train)}),"
          f" {V.shape[1]} modes in the span (nmax), wall weight {a.wall_weight:g}; "
          f"{face.shape[0]} chamber faces, {fn.size} nodes")
    ns = [min(n, nmax) for n in a.n]
    v0 = chamber_volumes(x, face, cid, np.zeros(x.size))
    print(f"{'ray':8s} {'t':>5s} " + " ".join(f"{'n=' + str(n) + ' walls %':>16s} {'tip mm':>7s}"
                                            for n in ns))
    worst = {n: {} for n in ns}
    for r in test:
        U = r["u"].T.copy()
        U[fixed] = 0.0
        for k in range(U.shape[1]):
            u = U[:, k]
            v = chamber_volumes(x, face, cid, u)
            qm = Vm.T @ (M @ u)
            cf = Qf.T @ u[fd]
            cells = []
            for n in ns:
                qf = np.linalg.solve(Rf[:n, :n], cf[:n])
                e = chamber_volumes(x, face, cid, V[:, :n] @ qf) / v - 1
                c = int(np.argmax(np.abs(e)))
                um = Vm[:, :n] @ qm[:n]
                et = np.linalg.norm((u - um).reshape(-1, 3)[tipn].mean(axis=0))
                cells.append(f"{100 * e[c]:+7.2f} ({c // 4 + 1}.{c % 4 + 1} {v[c] / v0[c]:.2f})"
                             f" {et:7.4f}")
                w = worst[n].setdefault(r["name"], [0.0, 0.0])
                w[0], w[1] = max(w[0], abs(100 * e[c])), max(w[1], et)
            print(f"{r['name']:8s} {r['t'][k]:5.2f} " + " ".join(cells))
    print("worst over each ray (walls %, tip mm):")
    for n in ns:
        print(f"  n = {n:4d}: " + "; ".join(f"{name} {w[0]:.2f} % {w[1]:.4f} mm"
                                            for name, w in worst[n].items()))


if __name__ == "__main__":
    main()

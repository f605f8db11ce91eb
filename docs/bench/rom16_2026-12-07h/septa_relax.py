#!/usr/bin/python3
"""The septa's nodes relaxed by the FE's own energy, the walls held (rom16, issue 34; rom15's Next 1).

    septa_relax.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 [--r 12 --k 176] [--cases T_R:1,T_H4:1]
        [--newton 8] [--band 24] [--npy ITERATES.npy]

For each held-out FE state: its representation w on the corotated manifold (corot_rep.py's,
bad_fibres.represent_z), then a static condensation of the septa: the dofs of the septum
elements' interior nodes (iso_local.py --septa's geometry: centroid within BAND degrees of a
septum plane at 0/90/180/270 deg, radius within the chambers' 3.66-7.66 mm, z within a
chamber's span; the nodes touched only by those elements) are solved for the minimum of the
FE's own potential (rom11_energy.Energy.total(fe=True): Yeoh + the P0 bulk kappa V_e th_e^2 / 2
element by element + every fibre by the FE's law - the chambers' constant-pressure work) with
every other dof held at w. Newton on those dofs (Levenberg-Marquardt: the septa's Hessian is indefinite there): the Hessian by forward differences of the FE
force, columns grouped by a distance-2 colouring of the node graph (tets, fibres' host nodes),
evaluated on the elements, fibres and chamber faces touching the free nodes only (the energy's
other terms do not depend on them); a line search on the FE's Pi. Printed: the FE state's,
the representation's and each iterate's FE energies by part, M-norm from the FE state, tip,
worst chamber (corot.show), the P0 bulk inside and outside the septa. With --npy the last
iterate of a Newton run instead of the representation. Units mm, N mm.
"""
import copy
import os
import sys
import time
import warnings

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "rom14_2026-12-07g"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "rom15_2026-12-07h"))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402
from scipy.sparse.linalg import splu, spsolve  # noqa: E402
from corot import show  # noqa: E402
from bad_fibres import represent_z  # noqa: E402
from iso_local import septa_select  # noqa: E402
from corot_newton import load_manifold, manifold_args  # noqa: E402
from rom11_iso_diag import states, volume_grads  # noqa: E402


def local_model(m, fnode):
    """a shallow copy of m restricted to the elements, fibres and chamber faces that touch a
    node in fnode: its forces on fnode's dofs are m's (every other term is constant there)"""
    s = copy.copy(m)
    et = fnode[m.tet].any(axis=1)
    s.tet, s.dNdX, s.wq, s.Ve = m.tet[et], m.dNdX[et], m.wq[et], m.Ve[et]
    node, coef, L0, EA = m.fib
    ft = fnode[node].any(axis=1)
    s.fib = (node[ft], coef[ft], L0[ft], EA[ft])
    s.W = m.W[ft]
    s.Qf = None
    ff = fnode[m.face].any(axis=1)
    s.face, s.cid = m.face[ff], m.cid[ff]
    s.v0 = np.zeros(12)  # the work's constant: the gradient does not see it
    return s


def colouring(m, fnode):
    """a distance-2 colouring of the free nodes on the graph of tets and fibres (two nodes of one
    colour share no neighbour): one force difference gives every column of that colour"""
    rows, cols = [], []
    for conn in (m.tet, m.fib[0]):
        k = conn.shape[1]
        rows.append(np.repeat(conn, k, axis=1).ravel())
        cols.append(np.tile(conn, (1, k)).ravel())
    r, c = np.concatenate(rows), np.concatenate(cols)
    A = sp.coo_matrix((np.ones(r.size), (r, c)), shape=(m.nn, m.nn)).tocsr()
    A.data[:] = 1.0
    fi = np.flatnonzero(fnode)
    A2 = (A[fi] @ A[:, fi]).tocsr()  # free i, j conflict when they share any neighbour
    col = -np.ones(len(fi), np.int64)
    for i in range(len(fi)):
        used = set(col[A2.indices[A2.indptr[i]:A2.indptr[i + 1]]].tolist())
        c = 0
        while c in used:
            c += 1
        col[i] = c
    return fi, col, A


def fe_parts(m, w, p):
    return m.total(w, p, fe=True)


def relax(m, s, w0, p, fi, col, A, newton, h=1e-6, log=None):
    """Newton on the free nodes' dofs of the FE potential, the rest held at w0"""
    dofs = (3 * fi[:, None] + np.arange(3)).ravel()
    dofs = dofs[~m.fixed[dofs]]
    pos = -np.ones(3 * m.nn, np.int64)
    pos[dofs] = np.arange(dofs.size)
    w = w0.copy()
    ncol = col.max() + 1
    mu = 30.0
    Af = A[fi].tocoo()  # (free node i, neighbour k)
    for it in range(newton):
        t0 = time.process_time()
        _, f, _ = s.total(w, p, fe=True)
        g = f[dofs]
        rr, cc, vv = [], [], []
        for c in range(ncol):
            nodes_c = fi[col == c]
            msk = col[Af.row] == c
            ki, kk = Af.row[msk], Af.col[msk]  # free node index, neighbour node
            for d in range(3):
                e = np.zeros(3 * m.nn)
                e[3 * nodes_c + d] = h
                e[m.fixed] = 0.0
                df = (s.total(w + e, p, fe=True)[1] - f) / h
                jcol = pos[3 * fi[ki] + d]
                for dd in range(3):
                    irow = pos[3 * kk + dd]
                    ok = (irow >= 0) & (jcol >= 0)
                    rr.append(irow[ok])
                    cc.append(jcol[ok])
                    vv.append(df[3 * kk[ok] + dd])
        H = sp.coo_matrix((np.concatenate(vv), (np.concatenate(rr), np.concatenate(cc))),
                          shape=(dofs.size, dofs.size)).tocsr()
        H = (0.5 * (H + H.T)).tocsc()
        # the septa's Hessian at the representation is indefinite (eigenvalues down to ~ -23
        # N/mm at T_R's: the compressed septa): Levenberg-Marquardt, H + mu I, mu raised
        # until the full step lowers the FE's Pi, lowered after a full step
        e0 = sum(fe_parts(m, w, p)[0])
        Id = sp.identity(dofs.size, format="csc")
        while True:
            dx = -splu((H + mu * Id).tocsc()).solve(g) if mu > 0 else -spsolve(H, g)
            wt = w.copy()
            wt[dofs] += dx
            e1 = sum(fe_parts(m, wt, p)[0])
            if g @ dx < 0 and e1 < e0 and np.isfinite(e1):
                mu = mu / 3.0
                break
            mu = max(4.0 * mu, 1.0)
            if mu > 1e8:
                wt, e1 = w, e0
                break
        w = wt
        gn = np.linalg.norm(s.total(w, p, fe=True)[1][dofs])
        print(f"      Newton {it + 1}: mu {mu:.3g}, Pi {e1:.2f} (from {e0:.2f}), |g| free "
              f"{np.linalg.norm(g):.3e} -> {gn:.3e}, {ncol} colours, "
              f"{time.process_time() - t0:.0f} s CPU", flush=True)
        if gn < 1e-8 * max(1.0, np.linalg.norm(f)):
            break
    return w


def bulk_split(m, w, sel):
    v, _ = volume_grads(w, m.tet, m.dNdX, m.wq)
    eb = 0.5 * m.kappa * m.Ve * (v / m.Ve - 1) ** 2
    return eb[sel].sum(), eb[~sel].sum()


def bulk_where(m, w, sel):
    """the P0 bulk outside the septa per radius band (mm): the core, the septa's radii, the
    outer wall"""
    v, _ = volume_grads(w, m.tet, m.dNdX, m.wq)
    eb = 0.5 * m.kappa * m.Ve * (v / m.Ve - 1) ** 2
    cen = m.x[m.tet[:, :4]].mean(axis=1)
    rad = np.hypot(cen[:, 0], cen[:, 1])
    out = ~sel
    bands = [(0, 3.66), (3.66, 7.66), (7.66, 1e9)]
    return " / ".join(f"{eb[out & (rad >= a) & (rad < b)].sum():.1f}" for a, b in bands)


def main():
    ap = manifold_args([])
    ap.add_argument("--cases", default="T_R:1,T_H4:1")
    ap.add_argument("--newton", type=int, default=8)
    ap.add_argument("--band", type=float, default=24.0)
    ap.add_argument("--npy", default=None)
    ap.add_argument("--rmin", type=float, default=3.66,
                    help="the relaxed elements' radii (mm): 3.66-7.66 the chambers' (the septa); "
                    "--band 45 --rmin 0 every element inside the chambers' outer radius (septa "
                    "and core)")
    ap.add_argument("--rmax", type=float, default=7.66)
    ap.add_argument("--out", default=None, help="a directory for the relaxed states (.npy)")
    a = ap.parse_args()
    # a trial step of the line search may invert an element (J < 0: NaN energy, rejected)
    warnings.filterwarnings("ignore", category=RuntimeWarning)
    m, mf = load_manifold(a)
    m.Qf = None
    sel, fnode = septa_select(m, a.band, a.rmin, a.rmax)
    s = local_model(m, fnode)
    fi, col, A = colouring(m, fnode)
    print(f"septa (band {a.band:g} deg, radius {a.rmin:g}-{a.rmax:g} mm): {sel.sum()} elements, {fnode.sum()} interior nodes; local "
          f"model {len(s.tet)} elements, {len(s.fib[0])} fibres, {len(s.face)} faces; "
          f"{col.max() + 1} colours", flush=True)
    for case in a.cases.split(","):
        ray, t = case.split(":")
        (name, tt, u, p, _, _), = list(states(a.snap, [ray], [float(t)], m.fixed))
        if a.npy:
            w0 = mf.u(np.load(a.npy)[-1])
        else:
            w0 = mf.u(represent_z(m, mf, u))
        print(f"{name} t {tt:g}:")
        for lab, w in (("FE state", u), ("representation" if not a.npy else "iterate", w0)):
            show(m, lab, u, w, p)
            print(f"      Pi(FE) {sum(fe_parts(m, w, p)[0]):.2f}; P0 bulk septa / rest "
                  "%.1f / %.1f" % bulk_split(m, w, sel) + "; rest by radius (core r < 3.66 / "
                  "3.66-7.66 / outer wall) " + bulk_where(m, w, sel), flush=True)
        w = relax(m, s, w0, p, fi, col, A, a.newton)
        show(m, "septa relaxed", u, w, p)
        print(f"      Pi(FE) {sum(fe_parts(m, w, p)[0]):.2f}; P0 bulk septa / rest "
              "%.1f / %.1f" % bulk_split(m, w, sel) + "; rest by radius (core r < 3.66 / "
              "3.66-7.66 / outer wall) " + bulk_where(m, w, sel), flush=True)
        np.save(os.path.join(a.out, f"septa_relaxed_{name}_t{tt:g}_b{a.band:g}_r{a.rmin:g}-{a.rmax:g}.npy"), w) \
            if a.out else None
        # the FE state's own septa: how far the relaxed septa sit from the FE's
        d = (w - u).reshape(-1, 3)[fnode]
        print(f"      septa nodes' distance from the FE state: max {np.sqrt((d ** 2).sum(1)).max():.4f}"
              f" mm, rms {np.sqrt((d ** 2).sum(1).mean()):.4f} mm", flush=True)


if __name__ == "__main__":
    main()

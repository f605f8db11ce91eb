#!/usr/bin/python3
"""Local modes made linearly isochoric where the manifold dilates (rom15's Next 1, a first screen).

    iso_local.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 [--r 12 --k 176] [--pairs 150]
        [--nsel 100,400] [--cases T_R:1,T_H4:1] [--out LOCAL_ISO.h5]

The held-out representations' spurious P0 bulk sits in the septa (bad_fibres.py). From
training data only: the element dilatations of the training representations and PAIRS
corotated combinations (pressure_enrich.py's), the NSEL elements with the largest RMS
dilatation over them, closed under the quarter turns, form the set C. Each local mode phi is
corrected by supremizers of C's element indicators so that its linear dilatation vanishes on C:
    phi' = phi - S (B S)^-1 B phi,  B_e phi = g0_e . phi_e / V_e (e in C),  S = X^-1 B^T
(g0 the reference volume derivative, X the vector Laplacian on the free dofs: rom_basis.py's
supremizer), then the corrected modes are M-orthonormalised. The screen before any Newton:
the held-out states' representations (corot_rep.py's) on the corrected modes, the FE's P0
bulk, fibres, M-norm, tip and worst chamber (corot.show), beside the uncorrected modes'.
Units mm, N mm.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "rom14_2026-12-07g"))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402
from corot import show, train_states  # noqa: E402
from bad_fibres import represent_z as represent  # noqa: E402
from corot_newton import Manifold, load_manifold, manifold_args  # noqa: E402
from pressure_enrich import element_turns  # noqa: E402
from rom11_iso_diag import states  # noqa: E402
from rom_basis import dilatations, turn_maps  # noqa: E402
from scipy.sparse.linalg import splu  # noqa: E402


def septa_select(m, band=24.0, rmin=3.66, rmax=7.66):
    """the septum elements by geometry (centroid within BAND deg of a multiple of 90 deg, radius
    within RMIN-RMAX mm: the chambers' 3.66-7.66, z within a chamber's span) and the nodes touched
    only by them (bool over elements, bool over nodes); rom16's septa_relax.py uses it too"""
    cen = m.x[m.tet[:, :4]].mean(axis=1)
    ang = np.degrees(np.arctan2(cen[:, 1], cen[:, 0]))
    dist90 = np.abs((ang + 45.0) % 90.0 - 45.0)
    rad = np.hypot(cen[:, 0], cen[:, 1])
    inz = np.zeros(len(cen), bool)
    for c in range(12):
        zc = m.x[m.face[m.cid == c]].reshape(-1, 3)[:, 2]
        inz |= (cen[:, 2] >= zc.min()) & (cen[:, 2] <= zc.max())
    sel = (dist90 < band) & (rad > rmin) & (rad < rmax) & inz
    inside = np.zeros(m.x.shape[0], bool)
    inside[np.unique(m.tet[sel])] = True
    outside = np.zeros(m.x.shape[0], bool)
    outside[np.unique(m.tet[~sel])] = True
    return sel, inside & ~outside


def main():
    ap = manifold_args([])
    ap.add_argument("--pairs", type=int, default=150)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--nsel", default="100,400")
    ap.add_argument("--cases", default="T_R:1,T_H4:1")
    ap.add_argument("--out", default=None)
    ap.add_argument("--septa", action="store_true",
                    help="C = the elements in the septa by geometry (centroid within 24 deg of a "
                    "multiple of 90 deg, radius within the chambers' 3.66-7.66 mm, z within the "
                    "chambers' span), the correction solved on C's nodes only (the nodes shared "
                    "with other elements held): a local correction; --nsel then unused")
    a = ap.parse_args()
    m, mf = load_manifold(a)
    rng = np.random.default_rng(a.seed)
    Z = np.array([represent(m, mf, u) for u in train_states(a.snap, m.fixed)])
    zs = list(Z)
    for _ in range(a.pairs):
        i, j = rng.integers(len(Z)), rng.integers(len(Z))
        zs.append(np.concatenate([Z[i, :mf.r], Z[j, mf.r:]]))
        zs.append(0.5 * (Z[i] + Z[j]))
    Th = np.concatenate([dilatations(np.stack([mf.u(z) for z in zs[c:c + 50]], axis=1), m.tet,
                                     m.dNdX, m.wq) for c in range(0, len(zs), 50)], axis=1)
    perms = element_turns(m.x, m.tet, turn_maps(m.x))
    rms0 = np.sqrt((Th ** 2).mean(axis=1))
    rms = rms0.copy()
    for pe in perms:  # the turned states' dilatations: the selection is turn-symmetric
        rk = np.empty_like(rms0)
        rk[pe] = rms0
        rms = np.maximum(rms, rk)
    order = np.argsort(rms)[::-1]
    nn = m.x.shape[0]
    g0 = np.einsum("eg,egai->eai", m.wq, m.dNdX)
    Ke = np.einsum("eg,egai,egbi->eab", m.wq, m.dNdX, m.dNdX)
    rows = np.repeat(m.tet, 10, axis=1).ravel()
    cols = np.tile(m.tet, (1, 10)).ravel()
    Lap = sp.coo_matrix((Ke.ravel(), (rows, cols)), shape=(nn, nn)).tocsr()
    Xh = sp.kron(Lap, sp.identity(3), format="csc")
    free = np.flatnonzero(~m.fixed)
    lu = splu(Xh[free][:, free].tocsc())
    cases = []
    for case in a.cases.split(","):
        ray, t = case.split(":")
        cases.append(list(states(a.snap, [ray], [float(t)], m.fixed))[0])
    for name, t, u, p, _, _ in cases:
        print(f"{name} t {t:g}, the uncorrected local modes (k = {mf.k}):")
        show(m, "representation", u, mf.u(represent(m, mf, u)), p)
    if a.septa:
        sel, interior = septa_select(m)
        Cs = np.flatnonzero(sel)
        freel = np.flatnonzero(np.repeat(interior, 3) & ~m.fixed)
        lu = splu(Xh[freel][:, freel].tocsc())
        free = freel
        print(f"septa: {len(Cs)} elements, {interior.sum()} interior nodes", flush=True)
    sets = [("septa", None)] if a.septa else [(v, int(v)) for v in a.nsel.split(",")]
    for lab, nsel in sets:
        if nsel is None:
            C = Cs
        else:
            C = set(order[:nsel].tolist())
            for pe in perms:  # closed under the quarter turns
                C |= set(pe[list(C)].tolist())
            C = np.array(sorted(C))
        # B (|C|, ndof): the linear dilatation of the elements in C
        r_ = np.repeat(np.arange(len(C)), 30)
        c_ = (3 * m.tet[C][:, :, None] + np.arange(3)).reshape(len(C), 30).ravel()
        v_ = (g0[C] / m.Ve[C][:, None, None]).reshape(len(C), 30).ravel()
        B = sp.csr_matrix((v_, (r_, c_)), shape=(len(C), 3 * nn))
        S = np.zeros((3 * nn, len(C)))
        BT = B.T.tocsc()
        for j in range(len(C)):
            S[free, j] = lu.solve(BT[:, j].toarray().ravel()[free])
        BS = B @ S
        Vl = mf.Vl - S @ np.linalg.lstsq(BS, B @ mf.Vl, rcond=1e-10)[0]
        Vl[m.fixed] = 0.0
        G = Vl.T @ (m.M @ Vl)
        w, Q = np.linalg.eigh(G)
        keep = w > 1e-10 * w.max()
        Vl = Vl @ (Q[:, keep] / np.sqrt(w[keep]))
        mi = Manifold(m, mf.sl, mf.Vs, Vl)
        cen = m.x[m.tet[C, :4]].mean(axis=1)
        print(f"{lab}: {len(C)} elements (turn-closed; mean radius "
              f"{np.hypot(cen[:, 0], cen[:, 1]).mean():.2f} mm, z {cen[:, 2].min():.0f} .. "
              f"{cen[:, 2].max():.0f} mm), {Vl.shape[1]} corrected local modes", flush=True)
        for name, t, u, p, _, _ in cases:
            show(m, f"{name} t {t:g} representation", u, mi.u(represent(m, mi, u)), p)
        if a.out:
            with h5py.File(f"{a.out[:-3]}_{lab}.h5", "w") as f:
                f["Vl"], f["C"] = Vl, C


if __name__ == "__main__":
    main()

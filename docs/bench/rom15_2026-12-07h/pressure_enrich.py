#!/usr/bin/python3
"""Dilatation patterns of the corotated manifold's own states (rom15, issue 34; rom14 Next 1).

    pressure_enrich.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 OUT.h5 [--r 12 --k 176]
        [--pairs 400] [--seed 1] [--kmax 192]

rom14's reduced Newton on the corotated manifold u(a, ql) leaks volume at T_R, t = 1: the
iterates' element dilatations grow in patterns the mixed bulk's pressure space span(P) does not
see (P0 bulk 554 N mm against span(P)'s 1.35 at the end state). This builds the candidate
pressure enrichment from training data only: the element P0 dilatations
theta_e = v_e / V_e - 1 (rom_basis.dilatations, the FE's condensed field) of
  - every training FE state's representation on the manifold (its chain strains on the first R
    modes, its local shape in those frames on the first K local modes: corot_rep.py's), and
  - PAIRS corotated combinations of two training states i, j (a random pair, both at the same
    load factor): the local coordinates of j in the chain of i, (a_i, ql_j), and the midpoint
    of the two representations ((a_i + a_j) / 2, (ql_i + ql_j) / 2): the states the Newton's
    steps reach by mixing coordinates,
and their quarter turns (the element map of the turned mesh), with the part in span(P) removed
(P is volume-orthonormal: P^T diag(V_e) P = I), then a volume-weighted POD (method of
snapshots). OUT.h5 /D (ntet, kmax): the enrichment modes, volume-orthonormal and orthogonal
to P; /sig their singular values; /Ds (ndof, kmax): their supremizers (rom_basis.supremizers,
the reduced Stokes supremizer on the reference mesh), to join the local modes. Units: theta
dimensionless, V_e mm^3.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "rom14_2026-12-07g"))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from bad_fibres import represent_z  # noqa: E402
from corot import train_states  # noqa: E402
from corot_newton import load_manifold, manifold_args  # noqa: E402
from rom_basis import dilatations, read_rays, supremizers, turn_maps  # noqa: E402


def element_turns(x, tet, maps):
    """per quarter turn the element permutation: element e goes to element perm[e] (the
    turned mesh is the mesh: the node map turns each element's vertex set into another's)"""
    key = {tuple(sorted(t)): e for e, t in enumerate(tet[:, :4])}
    out = []
    for _, j in maps:
        out.append(np.array([key[tuple(sorted(j[t]))] for t in tet[:, :4]]))
    return out


def main():
    ap = manifold_args(["out"])
    ap.add_argument("--pairs", type=int, default=400)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--kmax", type=int, default=192)
    a = ap.parse_args()
    m, mf = load_manifold(a)
    vol = m.Ve
    dNdX, wq = m.dNdX, m.wq
    tloads = [float(t) for r in read_rays(a.snap) if r["kind"] == "train" for t in r["t"]]
    Z = np.array([represent_z(m, mf, u) for u in train_states(a.snap, m.fixed)])
    tl = np.array(tloads)
    assert len(tl) == len(Z)
    rng = np.random.default_rng(a.seed)
    zs = list(Z)
    for _ in range(a.pairs):
        i = rng.integers(len(Z))
        same = np.flatnonzero(np.abs(tl - tl[i]) < 1e-9)
        j = same[rng.integers(len(same))]
        zs.append(np.concatenate([Z[i, :mf.r], Z[j, mf.r:]]))
        zs.append(0.5 * (Z[i] + Z[j]))
    print(f"pressure_enrich: {len(Z)} training representations + {2 * a.pairs} combinations "
          f"(r = {mf.r}, k = {mf.k})", flush=True)
    Th = np.empty((m.tet.shape[0], len(zs)))
    for c in range(0, len(zs), 50):
        U = np.stack([mf.u(z) for z in zs[c:c + 50]], axis=1)
        Th[:, c:c + U.shape[1]] = dilatations(U, m.tet, dNdX, wq)
    maps = turn_maps(m.x)
    perms = element_turns(m.x, m.tet, maps)
    # the turned state's dilatation of element perm[e] is the state's of element e
    T = [Th]
    for pe in perms:
        Tk = np.empty_like(Th)
        Tk[pe] = Th
        T.append(Tk)
    Th = np.concatenate(T, axis=1)
    P = m.P
    inP = np.einsum("ej,ej,e->j", Th, Th, vol)
    R = Th - P @ (P.T @ (vol[:, None] * Th))
    outP = np.einsum("ej,ej,e->j", R, R, vol)
    print(f"pressure_enrich: {Th.shape[1]} dilatation fields; the part outside span(P) "
          f"(volume norm): median {np.median(np.sqrt(outP / inP)):.3f}, max "
          f"{np.sqrt(outP / inP).max():.3f}", flush=True)
    C = R.T @ (vol[:, None] * R)
    lam, Y = np.linalg.eigh(C)
    order = np.argsort(lam)[::-1]
    lam, Y = np.clip(lam[order], 0, None), Y[:, order]
    kk = min(a.kmax, int((lam > 1e-14 * lam[0]).sum()))
    D = R @ Y[:, :kk] / np.sqrt(lam[:kk])
    D -= P @ (P.T @ (vol[:, None] * D))  # once more against P for round-off
    frac = np.cumsum(lam) / lam.sum()
    print("pressure_enrich: POD of the outside parts: energy fraction at 12/24/48/96/192 modes "
          + " ".join(f"{frac[min(n, len(frac)) - 1]:.4f}" for n in (12, 24, 48, 96, 192)),
          flush=True)
    Ds = supremizers(D, m.x, m.tet, dNdX, wq, m.fixed)
    Ds[m.fixed] = 0.0
    with h5py.File(a.out, "w") as f:
        f["D"], f["sig"], f["Ds"] = D, np.sqrt(lam[:kk]), Ds
    print(f"pressure_enrich: wrote {a.out}: {kk} modes and their supremizers", flush=True)


if __name__ == "__main__":
    main()

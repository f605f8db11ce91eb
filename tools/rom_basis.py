#!/usr/bin/python3
"""rom_basis.py: the mass-weighted POD basis of the reduced-order FE leg (issue 34, stage 2).

    /usr/bin/python3 tools/rom_basis.py SNAPDIR [--out BASIS.h5] [--tol 1e-3] [--n N]

Reads SNAPDIR/mesh.h5 and the ray files of `crawlsim rom snapshots` (fem/fem_rom_snap.h),
assembles the Tet10 consistent mass matrix M (rho of the mesh file; a collapsed Gauss rule of
4^3 points, exact for the degree-4 integrand N_a N_b det J of a straight element and of high
order on the curved ones), and takes the POD of the training snapshots in the hip frame (the
base clamped: the snapshots' displacements relative to the clamped base face, which is their
frame already) in the M inner product, by the method of snapshots: C = X^T M X = Phi Lambda
Phi^T, V = X Phi Lambda^(-1/2), so V^T M V = I. The basis size n is the smallest whose largest
relative projection error over the training snapshots, |u - V V^T M u|_M / |u|_M, is at most
--tol (or --n). Prints the singular value decay, the projection errors (M-norm and the largest
nodal displacement error, mm) of the training snapshots and of the held-out rays (the best any
reduced model on this basis can do there), and writes BASIS.h5:
  V [ndof, n] (zero rows at clamped dofs), sigma [nsnap] (sqrt of C's eigenvalues, decreasing),
  Mr [n, n] (V^T M V), q_snap [nsnap, n] (the training snapshots' reduced coordinates) with
  their loads p_snap [nsnap,3,4] (MPa), g_snap [nsnap,3] (mm/s^2), F_snap [nsnap,3] (N),
  attributes n, tol, mass_total_t, rho, nsnap, the rays used, the mesh signature.
With --fibre-modes K --fibres LEG.h5 (a `crawlsim rom leg-file` of the same mesh, for its fibre
elements) also the fibre strain basis of the mixed fibre field (fem/fem_rom.h csfRom.mf): the
POD, weighted by W_f = EA_f L0_f, of the training states' fibre Green strains E_f and of their
stresses S(E_f) (the tension-only law is not linear: S* = S(E) at a training state needs both
in the span), written as Qf [nfib, mf] with attribute mf.
With --v-rays A,B,... the displacement POD takes the states of those training rays only (the
span V of a smaller training); the pressure and fibre bases and the errors printed stay those of
every training ray, so one training's V can be paired with another's P and Qf.
Units: mm, t (tonnes), N.
"""
import argparse
import glob
import os
import sys

# one BLAS thread: numpy's batched 3x3 inverses and determinants (tet_reference, dilatations)
# stalled for minutes in OpenBLAS's thread hand-offs on the loaded two-core machine
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402


def tet10_shape(xi):
    """Tet10 shape values (10) and derivatives (10 x 3) at xi (3,), VTK order (fem_mesh.c)."""
    L = np.array([1.0 - xi[0] - xi[1] - xi[2], xi[0], xi[1], xi[2]])
    dL = np.array([[-1, -1, -1], [1, 0, 0], [0, 1, 0], [0, 0, 1]], float)
    ed = [(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)]
    N = np.empty(10)
    dN = np.empty((10, 3))
    for k in range(4):
        N[k] = L[k] * (2 * L[k] - 1)
        dN[k] = (4 * L[k] - 1) * dL[k]
    for e, (i, j) in enumerate(ed):
        N[4 + e] = 4 * L[i] * L[j]
        dN[4 + e] = 4 * (dL[i] * L[j] + L[i] * dL[j])
    return N, dN


def tet_rule(npt=4):
    """Collapsed (Duffy) Gauss rule on the unit tetrahedron: points (m x 3), weights (m)."""
    g, w = np.polynomial.legendre.leggauss(npt)
    g = 0.5 * (g + 1)
    w = 0.5 * w
    pts, wts = [], []
    for a, wa in zip(g, w):
        for b, wb in zip(g, w):
            for c, wc in zip(g, w):
                x = a
                y = b * (1 - a)
                z = c * (1 - a) * (1 - b)
                pts.append((x, y, z))
                wts.append(wa * wb * wc * (1 - a) ** 2 * (1 - b))
    return np.array(pts), np.array(wts)


def mass_matrix(x, tet, rho):
    """Consistent mass of the scalar Tet10 field (nnode x nnode, sparse) and the volume."""
    pts, wts = tet_rule(4)
    ne = tet.shape[0]
    Me = np.zeros((ne, 10, 10))
    vol = np.zeros(ne)
    X = x[tet]  # (ne, 10, 3)
    for p, w in zip(pts, wts):
        N, dN = tet10_shape(p)
        J = np.einsum("eai,ad->eid", X, dN)  # dx_i/dxi_d
        det = np.linalg.det(J)
        if np.any(det <= 0):
            raise ValueError("an inverted Tet10 in the mesh")
        Me += (w * det)[:, None, None] * np.outer(N, N)[None]
        vol += w * det
    rows = np.repeat(tet, 10, axis=1).ravel()
    cols = np.tile(tet, (1, 10)).ravel()
    M = sp.coo_matrix((rho * Me.ravel(), (rows, cols)), shape=(x.shape[0],) * 2).tocsr()
    return M, vol.sum()


# the FE's Tet10 rule (fem/fem_element.c kTetQ, kTetW): 4 points, degree 2, weights 1/24
QA, QB = 0.5854101966249685, 0.1381966011250105
FE_RULE = np.array([[QB, QB, QB], [QA, QB, QB], [QB, QA, QB], [QB, QB, QA]])


def tet_reference(x, tet):
    """The FE's reference geometry (csf_tetReference): dN/dX at the 4 points (ne, 4, 10, 3) and
    weights times det J (ne, 4), mm^3."""
    X = x[tet]
    ne = tet.shape[0]
    dNdX = np.empty((ne, 4, 10, 3))
    wq = np.empty((ne, 4))
    for g, p in enumerate(FE_RULE):
        _, dN = tet10_shape(p)
        J = np.einsum("eai,ad->eid", X, dN)
        det = np.linalg.det(J)
        dNdX[:, g] = np.einsum("ad,edi->eai", dN, np.linalg.inv(J))
        wq[:, g] = det / 24.0
    return dNdX, wq


def dilatations(U, tet, dNdX, wq):
    """Element dilatations v_e / V_e - 1 (ne, ns) of displacements U (ndof, ns): the FE's
    condensed P0 field, p_e = kappa (v_e / V_e - 1) (fem_element.c csf_tetKernel)."""
    nn = U.shape[0] // 3
    vol = wq.sum(axis=1)
    out = np.empty((tet.shape[0], U.shape[1]))
    for k in range(U.shape[1]):
        ue = U[:, k].reshape(nn, 3)[tet]  # (ne, 10, 3)
        F = np.einsum("eai,egaj->egij", ue, dNdX) + np.eye(3)
        out[:, k] = (wq * np.linalg.det(F)).sum(axis=1) / vol - 1.0
    return out


def supremizers(P, x, tet, dNdX, wq, fixed):
    """s_k = X^-1 B^T P_k (ndof, m): B^T p = sum_e p_e g_e with g_e = dv_e/du at rest (the
    discrete divergence of the P2/P0 element), X the H1 product of the displacement (the vector
    Laplacian over the free dofs; the supremizer of reduced Stokes, Rozza & Veroy 2007, Ballarin
    et al. 2015)."""
    from scipy.sparse.linalg import splu
    nn = x.shape[0]
    g0 = np.einsum("eg,egai->eai", wq, dNdX)  # (ne, 10, 3)
    Ke = np.einsum("eg,egai,egbi->eab", wq, dNdX, dNdX)
    rows = np.repeat(tet, 10, axis=1).ravel()
    cols = np.tile(tet, (1, 10)).ravel()
    L = sp.coo_matrix((Ke.ravel(), (rows, cols)), shape=(nn, nn)).tocsr()
    Xh = sp.kron(L, sp.identity(3), format="csc")
    free = np.flatnonzero(~fixed)
    lu = splu(Xh[free][:, free].tocsc())
    S = np.zeros((3 * nn, P.shape[1]))
    for k in range(P.shape[1]):
        rhs = np.zeros(3 * nn)
        np.add.at(rhs.reshape(nn, 3), tet, P[:, k][:, None, None] * g0)
        S[free, k] = lu.solve(rhs[free])
    return S


def turn_maps(x):
    """Node maps of the quarter turns about the leg axis (x, y) -> (-y, x), k = 1, 2, 3: node
    i goes to node perm[k][i]; None when the mesh lacks the symmetry (not the symmetric mesh)."""
    from scipy.spatial import cKDTree
    tree = cKDTree(x)
    maps = []
    R = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    Rk = np.eye(3)
    for _ in range(3):
        Rk = R @ Rk
        d, j = tree.query(x @ Rk.T)
        if d.max() > 1e-6 * np.abs(x).max():
            return None
        maps.append((Rk.copy(), j))
    return maps


def turn_snapshots(U, maps):
    """The snapshots U (ndof, m) turned by each quarter turn: u'_{perm(i)} = R u_i."""
    out = [U]
    nn = U.shape[0] // 3
    for Rk, j in maps:
        V = np.empty_like(U)
        Ui = U.reshape(nn, 3, -1)
        V.reshape(nn, 3, -1)[j] = np.einsum("ab,nbm->nam", Rk, Ui)
        out.append(V)
    return np.concatenate(out, axis=1)


def mixed_bases(a, V, X, Ut, x, tet, fixed, M):
    """The pressure basis P (ntet, m; volume-orthonormal, POD of the training dilatations) and
    V enriched by P's supremizers, M-orthonormalised against V (twice); prints the sizes and the
    held-out pressure fields' projection errors."""
    dNdX, wq = tet_reference(x, tet)
    vol = wq.sum(axis=1)
    Th = dilatations(X, tet, dNdX, wq)
    Cp = Th.T @ (vol[:, None] * Th)
    lam, Phi = np.linalg.eigh(Cp)
    order = np.argsort(lam)[::-1]
    lam, Phi = np.clip(lam[order], 0, None), Phi[:, order]
    mmax = int((lam > lam[0] * 1e-24).sum())
    Pall = Th @ Phi[:, :mmax] / np.sqrt(lam[:mmax])
    tn = np.sqrt(np.einsum("ej,ej,e->j", Th, Th, vol))

    def perr(Pk, T):
        R = T - Pk @ (Pk.T @ (vol[:, None] * T))
        return np.sqrt(np.einsum("ej,ej,e->j", R, R, vol)) / np.maximum(
            np.sqrt(np.einsum("ej,ej,e->j", T, T, vol)), 1e-300)

    m = a.m if a.m > 0 else mmax
    if a.m <= 0:
        for k in range(1, mmax + 1):
            if perr(Pall[:, :k], Th).max() <= a.ptol:
                m = k
                break
    m = min(m, mmax)
    P = Pall[:, :m]
    if a.p_split:
        P = split_pressure_modes(P, x, tet, vol, a.p_split)
        print(f"rom_basis: mixed: {m} pressure modes split at x3 = {a.p_split} mm: "
              f"{P.shape[1]} modes")
        m = P.shape[1]
    line = (f"rom_basis: mixed: m = {m} pressure modes of {mmax} (ptol {a.ptol:g}): training "
            f"pressure projection error max {perr(P, Th).max():.3e} (|dilatation| up to "
            f"{np.abs(Th).max():.2e})")
    if Ut is not None:
        line += f"; held-out {perr(P, dilatations(Ut, tet, dNdX, wq)).max():.3e}"
    print(line)
    if a.no_supremizers:
        return V, P, m
    S = supremizers(P, x, tet, dNdX, wq, fixed)
    S[fixed] = 0.0
    cols = [V]
    Q = V.copy()
    kept = 0
    for k in range(S.shape[1]):
        s = S[:, k].copy()
        n0 = np.sqrt(s @ (M @ s))
        for _ in range(2):
            s -= Q @ (Q.T @ (M @ s))
        n1 = np.sqrt(max(s @ (M @ s), 0.0))
        if n1 <= 1e-8 * n0:
            continue
        s /= n1
        Q = np.concatenate([Q, s[:, None]], axis=1)
        kept += 1
    print(f"rom_basis: mixed: {kept} supremizers added: n = {V.shape[1]} + {kept}")
    del tn, cols
    return Q, P, m


def split_pressure_modes(P, x, tet, vol, cuts):
    """Each pressure mode restricted to each zone of the leg between the cuts (x3 of the
    element's vertex centroid, mm; cuts in the connectors between segments make each segment a
    zone), volume-orthonormalised again (an SVD of the volume-weighted columns; columns below
    1e-10 of the zone's largest singular value dropped): the segments' pressure fields combine
    independently, as the chambers' pressures of the segments do. Returns (ntet, <= zones x m)."""
    z = x[tet[:, :4]].mean(axis=1)[:, 2]
    edges = [-np.inf] + sorted(cuts) + [np.inf]
    sv = np.sqrt(vol)[:, None]
    out = []
    for lo, hi in zip(edges[:-1], edges[1:]):  # zone by zone: the modes keep their zone
        u, sig, _ = np.linalg.svd(sv * P * ((z >= lo) & (z < hi))[:, None], full_matrices=False)
        if sig.size and sig[0] > 0:
            out.append(u[:, sig > sig[0] * 1e-10] / sv)
    return np.concatenate(out, axis=1)


# the FE's smoothed tension-only fibre law (fem/fem_material.h CSF_FIBRE_SLACK, csf_fibreLaw)
FIBRE_SLACK = 5e-4


def fibre_law(E, tension_only=True):
    """S(E) of csf_fibreLaw (strain units)."""
    if not tension_only:
        return E.copy()
    dl = FIBRE_SLACK
    return np.where(E <= -dl, 0.0, np.where(E < dl, (E + dl) ** 2 / (4 * dl), E))


def read_fibres(path, x):
    """The fibre elements of a leg file (robot/rom/robot_rom_file.h): host nodes (nfib, 20),
    chord coefficients (nfib, 20), L0 (mm), EA (N), the tension-only flag."""
    with h5py.File(path, "r") as f:
        if f["mesh/x"].shape != x.shape or not np.allclose(f["mesh/x"][...], x):
            sys.exit(f"rom_basis: --fibres {path}: another mesh")
        return (f["fibre/node"][...].astype(np.int64), f["fibre/coef"][...], f["fibre/L0"][...],
                f["fibre/EA"][...], bool(f.attrs.get("fib_tension_only", 1)))


def fibre_strains(U, x, fib):
    """Green strains (nfib, ns) of the fibres' chords at displacements U (ndof, ns)."""
    node, coef, L0 = fib[0], fib[1], fib[2]
    out = np.empty((node.shape[0], U.shape[1]))
    for k in range(U.shape[1]):
        xc = (x + U[:, k].reshape(-1, 3))[node]  # (nf, 20, 3)
        d = np.einsum("fa,fai->fi", coef, xc)
        out[:, k] = 0.5 * ((d ** 2).sum(1) / L0 ** 2 - 1.0)
    return out


def fibre_basis(a, X, Ut, x, fib):
    """Qf (nfib, mf): the W-orthonormal POD (W = EA L0) of the training fibre strains and their
    stresses S(E); with --f-split each mode split per zone as --p-split does. Prints the
    held-out strain fields' projection error."""
    W = fib[3] * fib[2]
    E = fibre_strains(X, x, fib)
    Y = np.concatenate([E, fibre_law(E, fib[4])], axis=1)
    C = Y.T @ (W[:, None] * Y)
    lam, Phi = np.linalg.eigh(C)
    order = np.argsort(lam)[::-1]
    lam, Phi = np.clip(lam[order], 0, None), Phi[:, order]
    kmax = int((lam > lam[0] * 1e-24).sum())
    mf = min(a.fibre_modes, kmax)
    Q = Y @ Phi[:, :mf] / np.sqrt(lam[:mf])
    if a.f_split:
        z = (x[fib[0]][:, :, 2]).mean(axis=1)
        edges = [-np.inf] + sorted(a.f_split) + [np.inf]
        sw = np.sqrt(W)[:, None]
        out = []
        for lo, hi in zip(edges[:-1], edges[1:]):
            u, sig, _ = np.linalg.svd(sw * Q * ((z >= lo) & (z < hi))[:, None],
                                      full_matrices=False)
            if sig.size and sig[0] > 0:
                out.append(u[:, sig > sig[0] * 1e-10] / sw)
        Q = np.concatenate(out, axis=1)

    def perr(T):
        R = T - Q @ (Q.T @ (W[:, None] * T))
        return (np.sqrt(np.einsum("fj,fj,f->j", R, R, W)) /
                np.maximum(np.sqrt(np.einsum("fj,fj,f->j", T, T, W)), 1e-300))

    line = (f"rom_basis: fibres: {Q.shape[1]} strain modes ({mf} of {kmax}"
            f"{', split' if a.f_split else ''}; {fib[0].shape[0]} fibres): training strain "
            f"projection error max {perr(E).max():.3e}, stress {perr(Y[:, E.shape[1]:]).max():.3e}")
    if Ut is not None:
        Et = fibre_strains(Ut, x, fib)
        line += f"; held-out strain {perr(Et).max():.3e}"
    print(line)
    return Q


def fibre_vib_enrich(Q, raw, x, fib):
    """Qf with the fibre strain increments of the vibration modes at their loaded states (the
    linearised Green strains dE_f = d_f . (D_f phi) / L0^2, d_f the chord at the FE's equilibrium
    u of the mode's level) W-orthonormalised against Qf and each other (twice): the mixed fibre
    field's projection then keeps the fibres' stiffness along the enrichment's modes instead of
    relaxing what span(Qf) does not hold."""
    node, coef, L0, W = fib[0], fib[1], fib[2], fib[3] * fib[2]
    kept = 0
    for u, phi in raw:
        d = np.einsum("fa,fai->fi", coef, (x + u.reshape(-1, 3))[node])
        dd = np.einsum("fa,fai->fi", coef, phi.reshape(-1, 3)[node])
        t = (d * dd).sum(1) / L0 ** 2
        n0 = np.sqrt(t @ (W * t))
        for _ in range(2):
            t = t - Q @ (Q.T @ (W * t))
        n1 = np.sqrt(max(t @ (W * t), 0.0))
        if n0 == 0 or n1 <= 1e-8 * n0:
            continue
        Q = np.concatenate([Q, (t / n1)[:, None]], axis=1)
        kept += 1
    print(f"rom_basis: fibres: {kept} strain increments of the {len(raw)} vibration modes added "
          f"(--fibre-vib): mf = {Q.shape[1]}")
    return Q


def enrich_vibration(V, path, k, fixed, M, levels=(0.0,), raw=None):
    """V with the FE's k lowest vibration modes at each pressure level of `levels` (MPa; K phi =
    omega^2 M phi over the free dofs, K the FE's tangent at that level's equilibrium in a
    `crawlsim rom modes` file), M-orthonormalised against V and each other (twice): the
    small-amplitude shapes a basis of load snapshots lacks (the tip-loaded cantilever's bending,
    torsion), as nonlinear reduced models of structures add vibration modes to static snapshots;
    at loaded levels, the modes of the ballooned, prestressed leg (its load stiffness). With a
    list `raw`, each added mode's (FE equilibrium u at its level, the FE's mode) is appended to
    it (for --fibre-vib)."""
    import scipy.sparse.linalg as spla
    free = np.flatnonzero(~fixed)
    nd = V.shape[0]
    Q = V.copy()
    Mff = M[free][:, free].tocsc()
    with h5py.File(path, "r") as f:
        for lev in levels:
            g = None
            for key in f:
                if key.startswith("p") and abs(float(f[key].attrs["p_MPa"]) - lev) <= 1e-9:
                    g = f[key]
            if g is None or "K_fe_val" not in g:
                sys.exit(f"rom_basis: --vib {path}: no FE tangent at {lev:g} MPa")
            K = sp.csr_matrix((g["K_fe_val"][...], g["K_fe_col"][...].astype(np.int64),
                               g["K_fe_row_ptr"][...].astype(np.int64)), shape=(nd, nd))
            Kff = K[free][:, free]
            Kff = 0.5 * (Kff + Kff.T)
            lam, Phi = spla.eigsh(Kff.tocsc(), k=k, M=Mff, sigma=0, which="LM")
            kept = 0
            for j in np.argsort(lam):
                s = np.zeros(nd)
                s[free] = Phi[:, j]
                n0 = np.sqrt(s @ (M @ s))
                for _ in range(2):
                    s -= Q @ (Q.T @ (M @ s))
                n1 = np.sqrt(max(s @ (M @ s), 0.0))
                if n1 <= 1e-8 * n0:
                    continue
                Q = np.concatenate([Q, (s / n1)[:, None]], axis=1)
                kept += 1
                if raw is not None:
                    phi = np.zeros(nd)
                    phi[free] = Phi[:, j]
                    raw.append((g["u_fe"][...], phi))
            f_hz = np.sqrt(np.maximum(np.sort(lam), 0)) / (2 * np.pi)
            print(f"rom_basis: vibration enrichment: {kept} of the FE's {k} lowest modes at "
                  f"{lev:g} MPa ({', '.join(f'{x:.1f}' for x in f_hz)} Hz) added: n = "
                  f"{Q.shape[1]}")
    return Q


def text(v):
    """An HDF5 string attribute as str (h5py gives bytes for fixed-length strings)."""
    return v.decode() if isinstance(v, bytes) else str(v)


def read_mesh(snapdir):
    """SNAPDIR/mesh.h5 (crawlsim rom snapshots): node coordinates x (nnode, 3) mm, Tet10
    connectivity tet (ntet, 10), the clamped dofs fixed (3 nnode,) bool, rho t/mm^3 and the
    file's attributes."""
    with h5py.File(os.path.join(snapdir, "mesh.h5"), "r") as f:
        return (f["x"][...], f["tet"][...].astype(np.int64), f["fixed"][...] > 0.5,
                float(f.attrs["rho"]), dict(f.attrs))


def read_rays(snapdir):
    rays = []
    for p in sorted(glob.glob(os.path.join(snapdir, "*.h5"))):
        if os.path.basename(p) in ("mesh.h5",) or p.endswith(".part"):
            continue
        with h5py.File(p, "r") as f:
            if f.attrs.get("format", b"") not in ("crawlsim-rom-snapshots 1",
                                                   b"crawlsim-rom-snapshots 1"):
                continue
            if "u" not in f:
                continue
            rays.append(dict(name=text(f.attrs["name"]), kind=text(f.attrs["kind"]),
                             u=f["u"][...], t=f["t"][...], status=text(f.attrs["status"]),
                             p=f["pressure"][...], g=f["gravity"][...], F=f["tip_force"][...]))
    return rays


def ray_columns(train, names, reps):
    """The snapshot columns of the training rays named in names: a bool mask over the training
    matrix X (the rays' states in file order, repeated reps times for the quarter turns, as
    turn_snapshots lays them out). A name that is no training ray is refused (SystemExit)."""
    known = [r["name"] for r in train]
    unknown = [v for v in names if v not in known]
    if unknown:
        sys.exit(f"rom_basis: --v-rays: {','.join(unknown)}: not a training ray (training: "
                 f"{','.join(known)})")
    sel = np.concatenate([np.full(r["u"].shape[0], r["name"] in names) for r in train])
    return np.tile(sel, reps)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("snapdir")
    ap.add_argument("--out", default=None)
    ap.add_argument("--tol", type=float, default=1e-3,
                    help="largest relative M-norm projection error of a training snapshot")
    ap.add_argument("--n", type=int, default=0, help="basis size (overrides --tol)")
    ap.add_argument("--vib", default=None,
                    help="enrich the basis with the FE's lowest vibration modes at rest (or at "
                    "--vib-level): a `crawlsim rom modes` file's FE tangents (M consistent)")
    ap.add_argument("--nvib", type=int, default=8, help="--vib: how many modes per level")
    ap.add_argument("--vib-level", type=float, action="append", default=None,
                    help="--vib: a pressure level (MPa) of the modes file whose FE modes are "
                    "added (repeatable; default 0, the rest state)")
    ap.add_argument("--turns", action="store_true",
                    help="add every training snapshot turned by the section's quarter turns (the "
                         "symmetric mesh maps onto itself; the fibre helices' start does not, so "
                         "the turned states are near-equilibria, not equilibria)")
    ap.add_argument("--mixed", action="store_true",
                    help="the mixed reduced model: a POD basis P of the training states' element "
                         "pressures (their dilatations; volume-weighted) and the displacement "
                         "basis enriched by P's supremizers (written as P, attribute m)")
    ap.add_argument("--ptol", type=float, default=1e-3,
                    help="--mixed: largest relative projection error of a training pressure field")
    ap.add_argument("--p-split", type=lambda v: [float(c) for c in v.split(",")], default=None,
                    help="--mixed: split every pressure mode at these x3 (mm, comma-separated; "
                    "the connectors between the segments): the segments' pressure fields "
                    "combine independently (m becomes up to zones x m)")
    ap.add_argument("--m", type=int, default=0, help="--mixed: pressure basis size (overrides "
                    "--ptol)")
    ap.add_argument("--fibre-modes", type=int, default=0,
                    help="the mixed fibre field: this many POD modes of the training fibre "
                    "strains and stresses, written as Qf, attribute mf; needs --fibres")
    ap.add_argument("--f-split", type=lambda v: [float(c) for c in v.split(",")], default=None,
                    help="--fibre-modes: split every fibre strain mode at these x3 (mm; as "
                    "--p-split, by the mean x3 of the fibre's host nodes)")
    ap.add_argument("--fibres", default=None,
                    help="--fibre-modes: a `crawlsim rom leg-file` of the same mesh (its fibre "
                    "elements)")
    ap.add_argument("--fibre-vib", action="store_true",
                    help="--fibre-modes with --vib: add to Qf the fibre strain increments of the "
                    "added vibration modes at their levels' FE equilibria")
    ap.add_argument("--v-rays", type=lambda v: [c for c in v.split(",") if c], default=None,
                    help="the displacement POD of these training rays only (comma-separated "
                    "names); the pressure and fibre bases, the supremizers' pressures, the "
                    "projection errors and q_snap of every training ray: separates the span "
                    "V from the training's other bases")
    ap.add_argument("--no-supremizers", action="store_true",
                    help="--mixed: no supremizer enrichment (to measure what it does)")
    a = ap.parse_args()
    if a.fibre_modes > 0 and not a.fibres:
        sys.exit("rom_basis: --fibre-modes needs --fibres LEG.h5 (the fibre elements)")
    if a.fibre_vib and not (a.vib and a.fibre_modes > 0):
        sys.exit("rom_basis: --fibre-vib needs --vib and --fibre-modes")
    out = a.out or os.path.join(a.snapdir, "basis.h5")
    x, tet, fixed, rho, attrs = read_mesh(a.snapdir)
    l_soft = float(attrs["fe_mesh_size_mm"])
    Ms, vol = mass_matrix(x, tet, rho)
    M = sp.kron(Ms, sp.identity(3), format="csr")
    mass_total = Ms.sum()
    print(f"rom_basis: mesh l_soft {l_soft:g} mm: {tet.shape[0]} Tet10, {3 * x.shape[0]} dofs, "
          f"{fixed.sum()} clamped; mass {mass_total * 1e6:.4f} g = rho V "
          f"({rho * vol * 1e6:.4f} g, rel. {mass_total / (rho * vol) - 1:.1e})")
    rays = read_rays(a.snapdir)
    train = [r for r in rays if r["kind"] == "train"]
    test = [r for r in rays if r["kind"] == "test"]
    if not train:
        sys.exit(f"rom_basis: {a.snapdir}: no training ray file")
    X = np.concatenate([r["u"] for r in train], axis=0).T  # (ndof, ns)
    X[fixed] = 0.0
    ns_fe = X.shape[1]
    if a.turns:
        maps = turn_maps(x)
        if maps is None:
            sys.exit("rom_basis: --turns: the mesh is not symmetric under quarter turns")
        X = turn_snapshots(X, maps)
        X[fixed] = 0.0
    ns = X.shape[1]
    MX = M @ X
    # the POD's snapshots: every training state, or those of --v-rays (Xv a copy of X's columns)
    Xv, MXv = X, MX
    if a.v_rays:
        cols = ray_columns(train, a.v_rays, ns // ns_fe)
        Xv, MXv = X[:, cols], MX[:, cols]
        print(f"rom_basis: --v-rays: the displacement POD of {len(a.v_rays)} of {len(train)} "
              f"training rays ({Xv.shape[1]} of {ns} snapshots)")
    C = Xv.T @ MXv
    lam, Phi = np.linalg.eigh(C)
    order = np.argsort(lam)[::-1]
    lam, Phi = np.clip(lam[order], 0, None), Phi[:, order]
    sigma = np.sqrt(lam)
    print(f"rom_basis: {len(train)} training rays, {ns_fe} FE snapshots"
          f"{f' ({ns} with the quarter turns)' if a.turns else ''}; {len(test)} held-out rays")
    print("rom_basis: singular values sigma_i / sigma_1 (M-norm):")
    for i in range(0, Xv.shape[1], 8):
        print("  " + " ".join(f"{s / sigma[0]:.2e}" for s in sigma[i:i + 8]))
    # largest projection error over the training snapshots for each size
    keep = lam > lam[0] * 1e-24
    nmax = int(keep.sum())
    Vall = Xv @ Phi[:, :nmax] / sigma[:nmax]
    del Xv, MXv

    def proj_err(V, U):
        MU = M @ U
        Q = V.T @ MU
        R = U - V @ Q
        e_m = np.sqrt(np.maximum(np.einsum("ij,ij->j", R, M @ R), 0))
        nrm = np.sqrt(np.einsum("ij,ij->j", U, MU))
        e_max = np.abs(R).reshape(-1, 3, R.shape[1])
        e_max = np.sqrt((e_max ** 2).sum(axis=1)).max(axis=0)
        return e_m / np.maximum(nrm, 1e-300), e_max

    sizes = sorted(set([k for k in (1, 2, 4, 6, 8, 10, 12, 16, 20, 24, 30, 40, 50, 60, 80, 100,
                                     120, 160) if k <= nmax] + [nmax]))
    Ut = np.concatenate([r["u"] for r in test], axis=0).T if test else None
    if Ut is not None:
        Ut[fixed] = 0.0
    n_pick = a.n
    print("rom_basis: projection error by basis size (relative M-norm, largest nodal mm):")
    print("     n   train max rel   train max mm   held-out max rel   held-out max mm")
    for k in sizes:
        er, em = proj_err(Vall[:, :k], X)
        line = f"  {k:4d}   {er.max():12.3e}   {em.max():12.4f}"
        if Ut is not None:
            tr, tm = proj_err(Vall[:, :k], Ut)
            line += f"   {tr.max():16.3e}   {tm.max():15.4f}"
        print(line)
    if n_pick <= 0:
        n_pick = nmax
        for k in range(1, nmax + 1):
            er, _ = proj_err(Vall[:, :k], X)
            if er.max() <= a.tol:
                n_pick = k
                break
    n_pick = min(n_pick, nmax)
    V = Vall[:, :n_pick]
    V[fixed] = 0.0
    n_pod, P, m_pick = n_pick, None, 0
    if a.vib:
        raw = [] if a.fibre_vib else None
        V = enrich_vibration(V, a.vib, a.nvib, fixed, M, a.vib_level or [0.0], raw)
        n_pick = V.shape[1]
    if a.mixed:
        V, P, m_pick = mixed_bases(a, V, X, Ut, x, tet, fixed, M)
        n_pick = V.shape[1]
    Qf = None
    if a.fibre_modes > 0:
        # the FE states' only: with --turns the turned states are near-equilibria whose fibre
        # strains are no FE's (the helices' start does not turn onto itself)
        fib = read_fibres(a.fibres, x)
        Qf = fibre_basis(a, X[:, :ns_fe], Ut, x, fib)
        if a.fibre_vib:
            Qf = fibre_vib_enrich(Qf, raw, x, fib)
    Mr = V.T @ (M @ V)
    er, em = proj_err(V, X)
    print(f"rom_basis: n = {n_pick} (tol {a.tol:g}): training projection error max {er.max():.3e} "
          f"(M-norm), {em.max():.4f} mm; |V^T M V - I| = {np.abs(Mr - np.eye(n_pick)).max():.1e}")
    with h5py.File(out, "w") as f:
        f.attrs["format"] = "crawlsim-rom-basis 1"
        f.attrs["n"] = n_pick
        f.attrs["tol"] = a.tol
        f.attrs["rho"] = rho
        f.attrs["mass_total_t"] = mass_total
        f.attrs["nsnap"] = ns
        f.attrs["nsnap_fe"] = ns_fe
        f.attrs["turns"] = int(a.turns)
        f.attrs["fe_mesh_size_mm"] = l_soft
        # the mesh signature the C side checks (fem/fem_rom_act.h)
        f.attrs["mesh_nnode"] = x.shape[0]
        f.attrs["mesh_ntet"] = tet.shape[0]
        f.attrs["mesh_x_sum"] = float(x.sum())
        f.attrs["mesh_x_sq"] = float((x * x).sum())
        f.attrs["snapshots"] = os.path.abspath(a.snapdir)
        f.attrs["train_rays"] = ",".join(r["name"] for r in train)
        f.attrs["test_rays"] = ",".join(r["name"] for r in test)
        if a.v_rays:
            f.attrs["v_rays"] = ",".join(a.v_rays)
        f.attrs["units"] = ("V: mm per unit reduced coordinate (M-orthonormal, M in t); "
                            "sigma: t^0.5 mm")
        f["V"] = V
        f.attrs["n_pod"] = n_pod
        if P is not None:
            f.attrs["m"] = m_pick
            f.attrs["supremizers"] = int(not a.no_supremizers)
            if a.p_split:
                f.attrs["p_split_x3_mm"] = np.array(a.p_split)
            f["P"] = P
        if Qf is not None:
            f.attrs["mf"] = Qf.shape[1]
            f["Qf"] = Qf
        f["sigma"] = sigma
        f["Mr"] = Mr
        # the training snapshots in reduced coordinates (q = V^T M u) with their loads: what
        # the hyper-reduction is fitted on (crawlsim rom ecsw-matrix, tools/rom_ecsw.py)
        # (with --turns every turned state too, with the loads of the FE state it was turned
        # from: the bodies' and fibres' element forces, all ECSW fits, do not depend on loads)
        reps = ns // ns_fe
        f["q_snap"] = (V.T @ MX).T
        f["p_snap"] = np.tile(np.concatenate([r["p"] for r in train], axis=0), (reps, 1, 1))
        f["g_snap"] = np.tile(np.concatenate([r["g"] for r in train], axis=0), (reps, 1))
        f["F_snap"] = np.tile(np.concatenate([r["F"] for r in train], axis=0), (reps, 1))
    print(f"rom_basis: {out}")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""Fibre-compatible wall shapes (issue 34, rom12): per training FE state u_k, the displacement d_k
that returns the taut fibres' strains of its projection w_k = V q_k onto the basis to the FE's,
of least elastic energy:

    (K_k + D_k^T W D_k) d_k = -D_k^T W r_k,   r_f = E_f(w_k) - max(E_f(u_k), 0) on the fibres
                                               taut at w_k (E_f(w_k) > 0), 0 elsewhere

D_k = dE/du at w_k (a fibre's chord lies in one Tet10: its 10 nodes, 30 dofs), W = EA L0 (N mm;
the tension-only law's psi'' = 1 per unit strain above its smoothing, so 1/2 D^T W D is the taut
fibres' energy to second order: w = 1 is the fibres' own stiffness, no free weight), K_k the
rubber's linear elastic stiffness in w_k's configuration (updated Lagrangian: dN/dx = dN/dX F^-1,
weights w det F; deviatoric mu = 2 C10, the Yeoh law's initial shear modulus, and the FE's P0
bulk kappa / v_e g_e g_e^T element by element; no initial-stress term). This is one Newton step
of the linearised rubber + fibres against the fibres' strain mismatch: the rubber's cheapest
response that relieves the stretch the truncated span puts in the fibres. The clamped dofs are
held. Writes OUT.h5: /d (ndof, K) the raw shapes, /D (ndof, k) their POD in the M inner product
after M-orthogonalising against V (decreasing order; rom11_iso_diag.py's --enrich reads /D), /sig
the POD's singular values, /states the (ray, t) of each column.
Usage: fibre_compat_modes.py SNAP BASIS.h5 LEG.h5 OUT.h5 [--t 1,0.75] [--turns]
(resumable: the raw shapes are kept in OUT.h5.part and skipped on a rerun)."""
import argparse
import os
import sys
import time

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))
sys.path.insert(0, os.path.join(HERE, "..", "rom"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402
import scipy.sparse.linalg as spl  # noqa: E402
from rom11_energy import Energy  # noqa: E402  (its chambers(): volumes and their gradients)
from rom_basis import mass_matrix, read_mesh, read_rays, tet_reference, turn_maps  # noqa: E402


def stiffness(x, tet, dNdX, wq, u, mu, kappa):
    """K (ndof, ndof) csr: linear elasticity in u's configuration (deviatoric mu, P0 bulk)."""
    ue = u.reshape(-1, 3)[tet]
    F = np.einsum("eai,egaj->egij", ue, dNdX) + np.eye(3)
    det = np.linalg.det(F)
    dNdx = np.einsum("egaj,egji->egai", dNdX, np.linalg.inv(F))
    w = wq * det
    # mu [delta_ik dN_a . dN_b + dN_ak dN_bi - 2/3 dN_ai dN_bk] (the energy mu |dev eps|^2)
    wd = w[:, :, None, None] * dNdx
    Ke = mu * (np.einsum("egaj,egbj,ik->eaibk", wd, dNdx, np.eye(3), optimize=True)
               + np.einsum("egak,egbi->eaibk", wd, dNdx, optimize=True)
               - (2.0 / 3.0) * np.einsum("egai,egbk->eaibk", wd, dNdx, optimize=True))
    g = np.einsum("eg,egai->eai", w, dNdx)  # d v_e / du
    ve = w.sum(axis=1)
    Ke += np.einsum("e,eai,ebk->eaibk", kappa / ve, g, g)
    dof = (3 * tet[:, :, None] + np.arange(3)).reshape(tet.shape[0], 30)
    ne = tet.shape[0]
    rows = np.broadcast_to(dof[:, :, None], (ne, 30, 30)).ravel()
    cols = np.broadcast_to(dof[:, None, :], (ne, 30, 30)).ravel()
    return rows, cols, Ke.reshape(ne, 30, 30).ravel()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    for name in ("snapdir", "basis", "legfile", "out"):
        ap.add_argument(name)
    ap.add_argument("--t", type=lambda v: [float(c) for c in v.split(",")], default=[1.0])
    ap.add_argument("--turns", action="store_true", help="also every quarter-turned state")
    ap.add_argument("--operator", choices=("state", "ref"), default="state",
                    help="state: K_k + D_k^T W D_k factored per state (as above); ref: one factor "
                    "of the reference configuration's K_0 + D_0^T W D_0 (every fibre, W) for every "
                    "state's right-hand side -D_k^T W r_k (the shapes then fix the mismatch only "
                    "as far as the reference operator is the state's: printed per state)")
    ap.add_argument("--only", default=None,
                    help="comma-separated training rays: only their states")
    ap.add_argument("--extra-part", action="append", default=[],
                    help="another run's OUT.h5.part: its shapes count as done (parallel runs)")
    ap.add_argument("--oracle", action="store_true",
                    help="a diagnostic, never a basis: --only's rays may be held-out ones (the "
                    "shape of a held-out state itself: does the construction fix that state when "
                    "the state is its own?)")
    ap.add_argument("--keep-volumes", action="store_true",
                    help="the shape also returns the twelve chamber volumes of w_k to the FE "
                    "state's (linearised: G_c d = V_c(u_k) - V_c(w_k), G_c the volumes' gradients "
                    "at w_k; Lagrange multipliers by the Schur complement, 13 solves with the one "
                    "factor): without it the rubber's response to the fibres moves the walls "
                    "(T_R's own shape: a chamber -3.45 %), as no pressure holds them")
    ap.add_argument("--iterate", type=int, default=1,
                    help="Newton steps of the shape: each recomputes D, K and the mismatch at "
                    "w_k + d (the fibres' constraint is curved on the shape's scale); 1: the "
                    "linearised shape")
    ap.add_argument("--limit", type=int, default=0, help="stop after this many new shapes")
    a = ap.parse_args()
    x, tet, fixed, rho, _ = read_mesh(a.snapdir)
    ndof = x.size
    with h5py.File(a.basis, "r") as f:
        V = f["V"][...]
    with h5py.File(a.legfile, "r") as f:
        node = f["fibre/node"][...].astype(np.int64)
        coef = f["fibre/coef"][...]
        L0, EA = f["fibre/L0"][...], f["fibre/EA"][...]
        C10, kappa = float(f.attrs["C10"]), float(f.attrs["kappa"])
    # each chord's two ends lie in one Tet10: the node list repeats its 10 nodes (checked)
    assert (node[:, :10] == node[:, 10:]).all()
    node, coef = node[:, :10], coef[:, :10] + coef[:, 10:]
    W = EA * L0
    Ms, _ = mass_matrix(x, tet, rho)
    M = sp.kron(Ms, sp.identity(3), format="csr")
    dNdX, wq = tet_reference(x, tet)
    G = V.T @ (M @ V)
    free = np.flatnonzero(~fixed)
    fdof = (3 * node[:, :, None] + np.arange(3)).reshape(node.shape[0], 30)
    nf = node.shape[0]
    frows = np.broadcast_to(fdof[:, :, None], (nf, 30, 30)).ravel()
    fcols = np.broadcast_to(fdof[:, None, :], (nf, 30, 30)).ravel()

    states = []
    for r in read_rays(a.snapdir):
        if (r["kind"] != "train" and not a.oracle) or (a.only and r["name"] not in a.only.split(",")):
            continue
        for k in range(r["u"].shape[0]):
            if any(abs(r["t"][k] - t) < 1e-9 for t in a.t):
                u = r["u"][k].copy()
                u[fixed] = 0.0
                states.append((f"{r['name']}@{r['t'][k]:g}", u))
    if a.turns:
        maps = turn_maps(x)
        nn = x.shape[0]
        for name, u in list(states):
            for j, (Rk, perm) in enumerate(maps):
                v = np.empty_like(u)
                v.reshape(nn, 3)[perm] = u.reshape(nn, 3) @ Rk.T
                v[fixed] = 0.0
                states.append((f"{name}/turn{j + 1}", v))
    lu0 = None
    if a.operator == "ref":
        t0 = time.process_time()
        d0 = np.einsum("fa,fai->fi", coef, x[node])
        D0 = (coef[:, :, None] * (d0 / L0[:, None] ** 2)[:, None, :]).reshape(nf, 30)
        rk, ck, vk = stiffness(x, tet, dNdX, wq, np.zeros(ndof), 2 * C10, kappa)
        A0 = sp.csr_matrix((np.concatenate([vk, (W[:, None, None] * D0[:, :, None] * D0[:, None, :]).ravel()]),
                            (np.concatenate([rk, frows]), np.concatenate([ck, fcols]))), shape=(ndof, ndof))
        lu0 = spl.splu(A0[free][:, free].tocsc(), permc_spec="COLAMD")
        print(f"fibre_compat_modes: the reference operator factored, {time.process_time() - t0:.0f} s CPU")
    chambers = Energy(a.snapdir, a.basis, a.legfile) if a.keep_volumes else None
    part = a.out + ".part"
    done = {}
    for pth in [part] + a.extra_part:
        if os.path.exists(pth):
            with h5py.File(pth, "r") as f:
                for key in f:
                    done[f[key].attrs["state"]] = f[key][...]
    print(f"fibre_compat_modes: {len(states)} training states (t in {a.t}{', turned' if a.turns else ''}),"
          f" {len(done)} done; n = {V.shape[1]}, ndof {ndof}, {nf} fibres, mu {2 * C10:g}, kappa {kappa:g} MPa")
    sys.stdout.flush()
    new = 0
    for name, u in states:
        if name in done:
            continue
        if a.limit and new >= a.limit:
            break
        t0 = time.process_time()
        q = np.linalg.solve(G, V.T @ (M @ u))
        w0 = V @ q
        dtot = np.zeros(ndof)
        for it in range(a.iterate):
            w = w0 + dtot
            xw = (x + w.reshape(-1, 3))[node]
            dw = np.einsum("fa,fai->fi", coef, xw)
            Ew = 0.5 * ((dw ** 2).sum(1) / L0 ** 2 - 1.0)
            du = np.einsum("fa,fai->fi", coef, (x + u.reshape(-1, 3))[node])
            Eu = 0.5 * ((du ** 2).sum(1) / L0 ** 2 - 1.0)
            taut = Ew > 0
            r = np.where(taut, Ew - np.maximum(Eu, 0.0), 0.0)
            # D_f = c_f (x) d_f / L0^2 on the chord's 30 dofs
            Df = (coef[:, :, None] * (dw / L0[:, None] ** 2)[:, None, :]).reshape(nf, 30)
            wt = W * taut
            if lu0 is None:
                Kf = (wt[:, None, None] * Df[:, :, None] * Df[:, None, :]).ravel()
                rk, ck, vk = stiffness(x, tet, dNdX, wq, w, 2 * C10, kappa)
                A = sp.csr_matrix((np.concatenate([vk, Kf]), (np.concatenate([rk, frows]),
                                                           np.concatenate([ck, fcols]))),
                                  shape=(ndof, ndof))
                lu = spl.splu(A[free][:, free].tocsc(), permc_spec="COLAMD")
            else:
                lu = lu0
            b = np.zeros(ndof)
            np.add.at(b, fdof.ravel(), (-(wt * r)[:, None] * Df).ravel())
            d = np.zeros(ndof)
            d[free] = lu.solve(b[free])
            if a.keep_volumes:
                vw, Gc = chambers.chambers(w)
                vu = chambers.chambers(u)[0]
                Z = lu.solve(np.ascontiguousarray(Gc[:, free].T))  # A^-1 G_c^T (nfree, 12)
                lam = np.linalg.solve(Gc[:, free] @ Z, Gc[:, free] @ d[free] - (vu - vw))
                d[free] -= Z @ lam
            dtot += d
            if a.iterate > 1:
                di = np.einsum("fa,fai->fi", coef, (x + (w0 + dtot).reshape(-1, 3))[node])
                Ei = 0.5 * ((di ** 2).sum(1) / L0 ** 2 - 1.0)
                mis = 0.5 * float((W * (np.maximum(Ei, 0) - np.maximum(Eu, 0)) ** 2).sum())
                print(f"    step {it + 1}: mismatch {mis:.4g} N mm, largest strain {Ei.max():.3f}")
                sys.stdout.flush()
            if it == 0:
                Ew0, taut0 = Ew, taut
        d, w, Ew, taut = dtot, w0, Ew0, taut0
        dd = np.einsum("fa,fai->fi", coef, (x + (w + d).reshape(-1, 3))[node])
        Ed = 0.5 * ((dd ** 2).sum(1) / L0 ** 2 - 1.0)

        def fe(E):  # the taut fibres' full energy against the FE's strains (N mm)
            return 0.5 * float((W * (np.maximum(E, 0) - np.maximum(Eu, 0)) ** 2).sum())
        dm = np.sqrt(d @ (M @ d)) / np.sqrt(u @ (M @ u))
        print(f"  {name:22s}: {taut.sum():5d} taut, largest strain {Ew.max():.3f} (FE {Eu.max():.3f});"
              f" mismatch energy {fe(Ew):.4g} -> {fe(Ed):.4g} N mm (largest {Ed.max():.3f});"
              f" |d|_M / |u|_M {dm:.2e}, max |d| {np.abs(d).max():.3f} mm; {time.process_time() - t0:.0f} s CPU")
        sys.stdout.flush()
        with h5py.File(part, "a") as f:
            key = f"s{len(f)}"
            f[key] = d
            f[key].attrs["state"] = name
        done[name] = d
        new += 1
    names = [s[0] for s in states if s[0] in done]
    Dr = np.stack([done[s] for s in names], axis=1)
    # M-orthogonal to V (twice), then the POD in the M inner product
    Y = Dr.copy()
    Gi = np.linalg.inv(G)
    for _ in range(2):
        Y -= V @ (Gi @ (V.T @ (M @ Y)))
    C = Y.T @ (M @ Y)
    lam, Phi = np.linalg.eigh(C)
    o = np.argsort(lam)[::-1]
    lam, Phi = np.clip(lam[o], 0, None), Phi[:, o]
    k = int((lam > lam[0] * 1e-14).sum())
    D = Y @ Phi[:, :k] / np.sqrt(lam[:k])
    with h5py.File(a.out, "w") as f:
        f["d"] = Dr
        f["D"] = D
        f["sig"] = np.sqrt(lam)
        f["states"] = np.array(names, dtype="S")
    print(f"fibre_compat_modes: {len(names)} shapes -> {k} POD modes; singular values "
          + " ".join(f"{s:.3g}" for s in np.sqrt(lam[:min(k, 12)])) + " ...")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""rom_project.py: the best a reduced basis can do on the held-out rays (issue 34).

    /usr/bin/python3 tools/rom_project.py SNAPDIR BASIS.h5 [--ray NAME ...]

For every state of the held-out rays of SNAPDIR (`crawlsim rom snapshots` files, kind "test"),
the M-orthogonal projection of the FE displacement u onto the basis' displacement space V
(tools/rom_basis.py: POD modes and, for a mixed basis, their supremizers; V^T M V = I), and
the projection's error: relative M-norm |u - V V^T M u|_M / |u|_M, the largest nodal error
(mm) and the error of the tip (the mean displacement of the nodes of the free end face, mm);
for a mixed basis also the element dilatations' (the pressure field's, p_e = kappa theta_e)
projection onto the pressure basis P, relative in the volume-weighted norm.
Set beside `crawlsim rom check`'s errors of the reduced model on the same states it separates
a basis-span problem (the projection already misses) from a reduced-model one (the projection
is close and the Galerkin solution is not). Units: mm, t.
"""
import argparse
import os
import sys

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rom_basis import (dilatations, mass_matrix, read_mesh, read_rays,  # noqa: E402
                       tet_reference)


def project(V, M, U, tip):
    """The M-orthogonal projection of the states U (ndof, k) onto span(V) (ndof, n; any basis:
    solved with its Gram matrix V^T M V), M (ndof, ndof). Returns per state the relative
    M-norm error, the largest nodal error, the error of the mean displacement of the nodes
    flagged in tip (nnode,), and the largest nodal displacement (mm)."""
    MU = M @ U
    Q = np.linalg.solve(V.T @ (M @ V), V.T @ MU)
    R = U - V @ Q
    e_m = np.sqrt(np.maximum(np.einsum("ij,ij->j", R, M @ R), 0))
    nrm = np.sqrt(np.einsum("ij,ij->j", U, MU))
    R3 = R.reshape(-1, 3, R.shape[1])
    e_max = np.sqrt((R3 ** 2).sum(axis=1)).max(axis=0)
    e_tip = np.sqrt((R3[tip].mean(axis=0) ** 2).sum(axis=0))
    U3 = U.reshape(-1, 3, U.shape[1])
    u_max = np.sqrt((U3 ** 2).sum(axis=1)).max(axis=0)
    return e_m / np.maximum(nrm, 1e-300), e_max, e_tip, u_max


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("snapdir")
    ap.add_argument("basis")
    ap.add_argument("--ray", action="append", help="a held-out ray (repeatable; default all)")
    a = ap.parse_args()
    try:
        x, tet, fixed, rho, _ = read_mesh(a.snapdir)
        with h5py.File(a.basis, "r") as f:
            V = f["V"][...]
            n_pod = int(f.attrs.get("n_pod", V.shape[1]))
            P = f["P"][...] if "P" in f else None
    except (OSError, KeyError) as e:
        sys.exit(f"rom_project: {e}")
    if V.shape[0] != 3 * x.shape[0]:
        sys.exit(f"rom_project: {a.basis}: {V.shape[0]} rows, the mesh has {3 * x.shape[0]} dofs")
    Ms, _ = mass_matrix(x, tet, rho)
    M = sp.kron(Ms, sp.identity(3), format="csr")
    # the free end: the nodes farthest from the clamped face along the leg's axis
    xc = x[fixed.reshape(-1, 3).any(axis=1)].mean(axis=0)
    ax = np.argmax(np.abs(x - xc).max(axis=0))
    far = np.abs(x[:, ax] - xc[ax])
    tip = far > far.max() - 1e-9 * max(far.max(), 1.0)
    rays = [r for r in read_rays(a.snapdir) if r["kind"] == "test"
            and (not a.ray or r["name"] in a.ray)]
    if not rays:
        sys.exit(f"rom_project: {a.snapdir}: no held-out ray"
                 + (f" named {a.ray}" if a.ray else ""))
    print(f"rom_project: basis {os.path.basename(a.basis)}: n = {V.shape[1]} ({n_pod} POD), "
          f"tip: {tip.sum()} nodes at the free end (axis e{ax + 1})")
    for V_use, label in ((V[:, :n_pod], "POD modes only"), (V, "the whole displacement basis")):
        if label == "POD modes only" and n_pod == V.shape[1]:
            continue
        print(f"rom_project: projection onto {label} ({V_use.shape[1]} vectors)")
        print(f"  {'ray':10s} {'t':>6s} {'|u|max mm':>10s} {'rel M-norm':>11s} "
              f"{'max nodal mm':>13s} {'tip mm':>8s}")
        for r in rays:
            U = r["u"].T.copy()
            U[fixed] = 0.0
            e_rel, e_max, e_tip, u_max = project(V_use, M, U, tip)
            for k in range(U.shape[1]):
                print(f"  {r['name']:10s} {r['t'][k]:6.3f} {u_max[k]:10.3f} "
                      f"{e_rel[k]:11.3e} {e_max[k]:13.4f} {e_tip[k]:8.4f}")
    if P is None:
        return
    dNdX, wq = tet_reference(x, tet)
    vol = wq.sum(axis=1)
    print(f"rom_project: the dilatations' projection onto P ({P.shape[1]} pressure modes)")
    print(f"  {'ray':10s} {'t':>6s} {'|theta|max':>11s} {'rel error':>10s}")
    for r in rays:
        U = r["u"].T.copy()
        U[fixed] = 0.0
        T = dilatations(U, tet, dNdX, wq)
        R = T - P @ (P.T @ (vol[:, None] * T))
        e = np.sqrt(np.einsum("ej,ej,e->j", R, R, vol)) / np.maximum(
            np.sqrt(np.einsum("ej,ej,e->j", T, T, vol)), 1e-300)
        for k in range(U.shape[1]):
            print(f"  {r['name']:10s} {r['t'][k]:6.3f} {np.abs(T[:, k]).max():11.3e} {e[k]:10.3e}")


if __name__ == "__main__":
    main()

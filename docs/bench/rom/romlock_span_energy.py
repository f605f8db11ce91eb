#!/usr/bin/python3
"""romlock_span_energy.py: what the span charges a held-out state, with and without the mixed
fibre field (docs/notes/rom.md, "Locking (branch romlock)").

    /usr/bin/python3 docs/bench/rom/romlock_span_energy.py SNAPDIR BASIS.h5 LEG.h5 [--ray NAME]

For each state of the rays: the FE state u and its M-orthogonal projection onto span(V); their
bulk energy in span(P) (b^T A^-1 b / 2, fem/fem_rom_mixed.h) and their fibre energy
sum_f W_f psi(E_f) (W = EA L0, psi the integral of the smoothed tension-only law) and, when the
basis has a fibre strain basis Qf, the mixed fibre energy sum_f W_f psi(Ebar_f), Ebar the
W-projection of E onto span(Qf) (fem/fem_rom.h csfRom.mf). N mm. The ratio projection / FE is
what a Galerkin solution near the projection would pay beyond the FE: the locking.
"""
import argparse
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "tools"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402
from rom_basis import (FIBRE_SLACK, dilatations, fibre_strains, mass_matrix, read_fibres,  # noqa: E402
                       read_mesh, read_rays, tet_reference)


def psi(E, tension_only=True):
    """the energy density (strain^2) of csf_fibreLaw: psi' = S"""
    if not tension_only:
        return 0.5 * E ** 2
    dl = FIBRE_SLACK
    return np.where(E <= -dl, 0.0, np.where(E < dl, (E + dl) ** 3 / (12 * dl),
                                             0.5 * E ** 2 + dl ** 2 / 6))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("snapdir")
    ap.add_argument("basis")
    ap.add_argument("legfile")
    ap.add_argument("--ray", action="append")
    a = ap.parse_args()
    x, tet, fixed, rho, _ = read_mesh(a.snapdir)
    with h5py.File(a.basis, "r") as f:
        V = f["V"][...]
        P = f["P"][...] if "P" in f else None
        Q = f["Qf"][...] if "Qf" in f else None
    with h5py.File(a.legfile, "r") as f:
        kappa = float(f.attrs["kappa"])
    fib = read_fibres(a.legfile, x)
    W = fib[3] * fib[2]
    Ms, _ = mass_matrix(x, tet, rho)
    M = sp.kron(Ms, sp.identity(3), format="csr")
    Gm = np.linalg.cholesky(V.T @ (M @ V))
    dNdX, wq = tet_reference(x, tet)
    Ve = wq.sum(axis=1)
    if Q is not None:
        GQ = Q.T @ (W[:, None] * Q)
    print(f"romlock_span_energy: {a.basis}: n = {V.shape[1]}, m = "
          f"{0 if P is None else P.shape[1]}, mf = {0 if Q is None else Q.shape[1]}")

    def energies(u):
        th = dilatations(u[:, None], tet, dNdX, wq)[:, 0]
        bulk = 0.5 * kappa * (Ve * th ** 2).sum()
        if P is not None:
            A = (P * (Ve / kappa)[:, None]).T @ P
            b = P.T @ (Ve * th)
            bulk = 0.5 * float(b @ np.linalg.solve(A, b))
        E = fibre_strains(u[:, None], x, fib)[:, 0]
        fe = float((W * psi(E, fib[4])).sum())
        fm = float("nan")
        if Q is not None:
            Eb = Q @ np.linalg.solve(GQ, Q.T @ (W * E))
            fm = float((W * psi(Eb, fib[4])).sum())
        return bulk, fe, fm, E.max()

    for r in read_rays(a.snapdir):
        if a.ray and r["name"] not in a.ray:
            continue
        for k in range(r["u"].shape[0]):
            u = r["u"][k].copy()
            u[fixed] = 0.0
            qm = np.linalg.solve(Gm.T, np.linalg.solve(Gm, V.T @ (M @ u)))
            um = V @ qm
            b0, f0, fm0, e0 = energies(u)
            b1, f1, fm1, e1 = energies(um)
            print(f"{r['name']:8s} t {r['t'][k]:.2f}: bulk{' in span(P)' if P is not None else ''}"
                  f" FE {b0:.3g}, projection {b1:.3g} ({b1 / max(b0, 1e-300):.0f}x); fibres FE "
                  f"{f0:.3g}, projection {f1:.3g} ({f1 / max(f0, 1e-300):.1f}x); mixed fibres FE "
                  f"{fm0:.3g}, projection {fm1:.3g} ({fm1 / max(f0, 1e-300):.1f}x the FE's); "
                  f"largest strain {e0:.3g} / {e1:.3g}")


if __name__ == "__main__":
    main()

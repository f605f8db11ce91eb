#!/usr/bin/python3
"""Session rom4 (docs/notes/rom.md): the held-out states' best projection onto a basis' POD
modes measured by what the near-incompressible material feels, the element dilatations of the
projected displacement against the FE's (relative, volume-weighted), beside the M-norm error.

    /usr/bin/python3 docs/bench/rom/rom4_projection_dilatation.py SNAPDIR BASIS.h5 ..."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "tools"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402
from rom_basis import (dilatations, mass_matrix, read_mesh, read_rays,  # noqa: E402
                       tet_reference)

snap = sys.argv[1]
x, tet, fixed, rho, _ = read_mesh(snap)
M = sp.kron(mass_matrix(x, tet, rho)[0], sp.identity(3), format="csr")
dNdX, wq = tet_reference(x, tet)
vol = wq.sum(axis=1)
rays = [r for r in read_rays(snap) if r["name"] in ("T_H4", "T_S2")]
print(f"  {'basis':24s} {'ray':6s} {'t':>5s} {'M-norm':>8s} {'dilatation':>10s}")
for b in sys.argv[2:]:
    with h5py.File(b, "r") as f:
        V = f["V"][...][:, :int(f.attrs["n_pod"])]
    for r in rays:
        U = r["u"].T.copy()
        U[fixed] = 0.0
        Up = V @ (V.T @ (M @ U))  # V^T M V = I for the POD modes
        R = U - Up
        em = np.sqrt(np.einsum("ij,ij->j", R, M @ R) / np.einsum("ij,ij->j", U, M @ U))
        T, Tp = dilatations(U, tet, dNdX, wq), dilatations(Up, tet, dNdX, wq)
        ed = np.sqrt(((T - Tp) ** 2 * vol[:, None]).sum(0) / (T ** 2 * vol[:, None]).sum(0))
        for k in range(U.shape[1]):
            print(f"  {os.path.basename(os.path.dirname(b)) + ' (' + str(V.shape[1]) + ' POD)':24s} "
                  f"{r['name']:6s} {r['t'][k]:5.2f} {em[k]:8.2e} {ed[k]:10.3e}")

#!/usr/bin/python3
"""rom_modes.py: the first eigenfrequencies of the reduced-order FE leg against the full FE's
(issue 34: the first four within 3 % at 0 and 0.15 MPa).

    /usr/bin/python3 tools/rom_modes.py MODES.h5 SNAPDIR BASIS.h5 [--k 4]

MODES.h5 is `crawlsim rom modes`'s output (tools/cmd_rom_modes.c): at each pressure level the FE's
static tangent K (CSR, Dirichlet rows and columns identity) and the reduced one K_r = dK/dq at
their own equilibria. The mass is the FE's consistent Tet10 mass M (tools/rom_basis.py's
mass_matrix on SNAPDIR/mesh.h5; the fibres' and the air's masses are not in the FE model either),
the reduced one V^T M V of BASIS.h5 (Mr). Small vibrations about the loaded equilibrium:
K phi = omega^2 M phi over the free dofs (scipy's shift-invert Lanczos about 0 for the FE, a
dense generalised eigenproblem for the reduced model). Units: K N/mm, M t, so omega^2 is in
1/s^2 and f = omega / (2 pi) in Hz. Each reduced mode is paired with the FE mode it resembles
most (the MAC in the M inner product of V phi_r and the FE's modes), so a near-degenerate pair
of bending modes ordered differently is not counted as an error; the sorted frequencies are
compared as well.
"""
import argparse
import os
import sys

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.linalg as sla  # noqa: E402
import scipy.sparse as sp  # noqa: E402
import scipy.sparse.linalg as spla  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from rom_basis import mass_matrix, read_mesh  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("modes")
    ap.add_argument("snapdir")
    ap.add_argument("basis")
    ap.add_argument("--k", type=int, default=4, help="how many frequencies to compare")
    ap.add_argument("--fe", default=None, help="take the FE's tangents from this modes file "
                    "(same mesh; each level of MODES.h5, from `crawlsim rom modes --rom-only`, "
                    "paired with the FE's level of the same pressure)")
    a = ap.parse_args()
    x, tet, fixed, rho, _ = read_mesh(a.snapdir)
    with h5py.File(a.basis, "r") as f:
        V = f["V"][...]
        Mr = f["Mr"][...]
    Ms, _ = mass_matrix(x, tet, rho)
    M = sp.kron(Ms, sp.identity(3), format="csr")
    free = np.flatnonzero(~fixed)
    Mff = M[free][:, free]
    k = a.k
    worst = 0.0
    fe_file = h5py.File(a.fe or a.modes, "r")
    with h5py.File(a.modes, "r") as f:
        nlev = int(f.attrs["nlevel"])
        ray = f.attrs["ray"]
        ray = ray.decode() if isinstance(ray, bytes) else ray
        print(f"rom_modes: basis {a.basis}: n = {V.shape[1]}, m = {int(f.attrs['m'])}; FE "
              f"{len(free)} free dofs; ray {ray}")
        for lev in range(nlev):
            gr = f[f"p{lev}"]
            p = float(gr.attrs["p_MPa"])
            g = None
            for key in fe_file:
                if (key.startswith("p") and "K_fe_val" in fe_file[key]
                        and abs(float(fe_file[key].attrs["p_MPa"]) - p) <= 1e-12):
                    g = fe_file[key]
            if g is None:
                sys.exit(f"rom_modes: {a.fe or a.modes}: no FE tangent at {p:g} MPa (level {lev} "
                         f"of {a.modes})")
            nd = V.shape[0]
            K = sp.csr_matrix((g["K_fe_val"][...], g["K_fe_col"][...].astype(np.int64),
                               g["K_fe_row_ptr"][...].astype(np.int64)), shape=(nd, nd))
            Kff = K[free][:, free]
            asym = abs(Kff - Kff.T).max() / abs(Kff).max()
            Kff = 0.5 * (Kff + Kff.T)
            lam, Phi = spla.eigsh(Kff.tocsc(), k=k + 4, M=Mff.tocsc(), sigma=0, which="LM")
            order = np.argsort(lam)
            lam, Phi = lam[order], Phi[:, order]
            Kr = gr["K_rom"][...]
            asym_r = np.abs(Kr - Kr.T).max() / np.abs(Kr).max()
            lr, Pr = sla.eigh(0.5 * (Kr + Kr.T), Mr)
            f_fe = np.sqrt(np.maximum(lam, 0)) / (2 * np.pi)
            f_r = np.sqrt(np.maximum(lr, 0)) / (2 * np.pi)
            # MAC in the M inner product between expanded reduced modes and the FE modes
            Ur = (V[free] @ Pr[:, :k + 4])
            MPhi = Mff @ Phi
            num = (Ur.T @ MPhi) ** 2
            den = np.outer(np.einsum("ij,ij->j", Ur, Mff @ Ur), np.einsum("ij,ij->j", Phi, MPhi))
            mac = num / den
            fd = (f"; rom tangent against central differences {float(gr.attrs['fd_rel_err']):.1e}"
                  if "fd_rel_err" in gr.attrs else "")
            print(f"rom_modes: {p:g} MPa (FE {float(g.attrs['fe_wall_s']):.0f} s, "
                  f"{int(g.attrs['fe_newton'])} Newton iterations; tangent asymmetry FE "
                  f"{asym:.1e}, rom {asym_r:.1e}{fd})")
            print("   mode   FE Hz      rom Hz     error     paired FE mode (MAC)")
            for i in range(k):
                j = int(np.argmax(mac[i]))
                e_sorted = f_r[i] / f_fe[i] - 1
                worst = max(worst, abs(e_sorted))
                print(f"   {i + 1:4d}   {f_fe[i]:8.3f}   {f_r[i]:8.3f}   {100 * e_sorted:+7.2f} %"
                      f"   {j + 1} ({mac[i, j]:.3f}; {100 * (f_r[i] / f_fe[j] - 1):+.2f} %)")
    print(f"rom_modes: worst of the first {k} (sorted) {100 * worst:.2f} % (target 3 %)")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""romacc_volume_diag.py: where a chamber volume's error comes from (issue 34, session romacc).

    /usr/bin/python3 docs/bench/rom/romacc_volume_diag.py SNAPDIR BASIS.h5 [--ray T_S2 ...]

For every state of the named held-out rays: the twelve chambers' volumes of the FE state
(recomputed from its displacement with the FE's own face rule: it must reproduce the file's
/chamber_volume, csf_romChamberVolumes) and of two projections of it onto span(V):
  - the M-orthogonal projection (rom_project.py's: what rom_basis.py sizes the basis by);
  - the projection in the chamber faces' nodes alone (least squares on their displacements):
    the best a basis can do for the volumes' geometry.
With --legfile LEG.h5 (`crawlsim rom leg-file` of the same mesh: it holds the fibre elements)
also the energies a near-incompressible, fibre-reinforced leg weighs, of the FE state and of
its M-projection: the bulk energy sum_e kappa V_e theta_e^2 / 2 (theta_e = v_e / V_e - 1, the
FE's P0 dilatation; kappa from the file) and the fibres' sum_f EA L0 E_f^2 / 2 over the
stretched ones (E_f the Green strain of the chord, fem_element.c csf_fibreKernel; tension
only), against the chambers' pressure work sum_c p_c (V_c - V0_c) as the scale. A projection
that pays many times the FE's bulk or fibre energy is what the Galerkin solution cannot take:
it settles on a stiffer state (locking). With --rom-states DIR (`crawlsim rom check --states
DIR`) the same volumes and energies of the reduced model's own solution (its bulk energy here is
the full P0 dilatation's, not the mixed model's projected one).
The volumes are those of `crawlsim rom check` (the full reconstruction u = V q of the
chambers' quadratic faces; the FE computes its own the same way); relative error, worst
chamber, and the chamber's inflation V / V0 to read the error against the volume change.
Units mm, mm^3.
"""
import argparse
import os
import sys

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..",
                                "tools"))
from rom_basis import dilatations, mass_matrix, read_mesh, read_rays, tet_reference  # noqa: E402

# fem_element.c kTriQ: Dunavant degree 4 (s, t, weight incl. the 1/2 of the reference triangle)
TRIQ = np.array([[0.445948490915965, 0.445948490915965, 0.223381589678011 / 2],
                 [0.108103018168070, 0.445948490915965, 0.223381589678011 / 2],
                 [0.445948490915965, 0.108103018168070, 0.223381589678011 / 2],
                 [0.091576213509771, 0.091576213509771, 0.109951743655322 / 2],
                 [0.816847572980459, 0.091576213509771, 0.109951743655322 / 2],
                 [0.091576213509771, 0.816847572980459, 0.109951743655322 / 2]])


def tri6(s, t):
    l0 = 1 - s - t
    N = np.array([l0 * (2 * l0 - 1), s * (2 * s - 1), t * (2 * t - 1), 4 * l0 * s, 4 * s * t,
                  4 * t * l0])
    dN = np.array([[-(4 * l0 - 1), -(4 * l0 - 1)], [4 * s - 1, 0], [0, 4 * t - 1],
                   [4 * (l0 - s), -4 * s], [4 * t, 4 * s], [-4 * t, 4 * (l0 - t)]])
    return N, dN


def chamber_volumes(x, face, cid, u):
    """The twelve chambers' volumes at nodal displacement u (nnode*3,): csf_faceKernel's
    v = -sum_q w (x_q . (x_s x x_t)) / 3 summed over each chamber's faces."""
    xf = (x + u.reshape(-1, 3))[face]  # (nf, 6, 3)
    v = np.zeros(face.shape[0])
    for s, t, w in TRIQ:
        N, dN = tri6(s, t)
        xs = np.einsum("a,fai->fi", dN[:, 0], xf)
        xt = np.einsum("a,fai->fi", dN[:, 1], xf)
        xq = np.einsum("a,fai->fi", N, xf)
        v -= w * np.einsum("fi,fi->f", xq, np.cross(xs, xt)) / 3.0
    return np.bincount(cid, weights=v, minlength=12)


def chamber_faces(snapdir):
    """The chambers' quadratic faces of SNAPDIR/mesh.h5 (nface, 6) and each one's chamber
    4 s + j (segment s, chamber j, 0-based) from its tag."""
    with h5py.File(os.path.join(snapdir, "mesh.h5"), "r") as f:
        face = f["face"][...].astype(np.int64)
        tag = f["face_tag"][...].astype(np.int64)
    seg, ch = tag // 10 - 11, tag % 10 - 1
    inch = (seg >= 0) & (seg < 3) & (ch >= 0) & (ch < 4) & (tag >= 111)
    return face[inch], (4 * seg + ch)[inch]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("snapdir")
    ap.add_argument("basis")
    ap.add_argument("--ray", action="append")
    ap.add_argument("--legfile", default=None)
    ap.add_argument("--rom-states", default=None)
    a = ap.parse_args()
    x, tet, fixed, rho, _ = read_mesh(a.snapdir)
    face, cid = chamber_faces(a.snapdir)
    with h5py.File(a.basis, "r") as f:
        V = f["V"][...]
        P = f["P"][...] if "P" in f else None
    Ms, _ = mass_matrix(x, tet, rho)
    M = sp.kron(Ms, sp.identity(3), format="csr")
    G = np.linalg.cholesky(V.T @ (M @ V))
    # the chamber faces' dofs
    fn = np.unique(face.ravel())
    fd = (3 * fn[:, None] + np.arange(3)).ravel()
    Vf = V[fd]
    print(f"romacc_volume_diag: basis {a.basis}: n = {V.shape[1]}; {face.shape[0]} chamber "
          f"faces, {fn.size} nodes")
    fib = None
    if a.legfile:
        with h5py.File(a.legfile, "r") as f:
            if np.abs(f["mesh/x"][...] - x).max() > 1e-9:
                sys.exit(f"romacc_volume_diag: {a.legfile}: another mesh")
            fib = (f["fibre/node"][...].astype(np.int64), f["fibre/coef"][...],
                   f["fibre/L0"][...], f["fibre/EA"][...])
            kappa = float(f.attrs["kappa"])
        dNdX, wq = tet_reference(x, tet)[:2]
        Ve = wq.sum(axis=1)

    def energies(u):
        """bulk energy of the full P0 dilatation, the mixed model's bulk energy b^T A^-1 b / 2
        (only the dilatation's part in span(P): A = sum_e V_e / kappa P_e P_e^T, b = sum_e P_e
        V_e theta_e; fem/fem_rom_mixed.h), the stretched fibres' energy, the largest strain"""
        th = dilatations(u[:, None], tet, dNdX, wq)[:, 0]
        if P is not None:
            A = (P * (Ve / kappa)[:, None]).T @ P
            b = P.T @ (Ve * th)
            bulk_p = 0.5 * float(b @ np.linalg.solve(A, b))
        else:
            bulk_p = float("nan")
        xc = (x + u.reshape(-1, 3))[fib[0]]  # (nf, 20, 3)
        d = np.einsum("fa,fai->fi", fib[1], xc)
        E = 0.5 * ((d ** 2).sum(1) / fib[2] ** 2 - 1.0)
        return (0.5 * kappa * (Ve * th ** 2).sum(), bulk_p,
                0.5 * (fib[3] * fib[2] * np.maximum(E, 0) ** 2).sum(), E.max())
    for r in read_rays(a.snapdir):
        if a.ray and r["name"] not in a.ray:
            continue
        with h5py.File(os.path.join(a.snapdir, r["name"] + ".h5"), "r") as f:
            vfe = f["chamber_volume"][...].reshape(-1, 12)
        v0 = chamber_volumes(x, face, cid, np.zeros(x.size))
        for k in range(r["u"].shape[0]):
            u = r["u"][k]
            v = chamber_volumes(x, face, cid, u)
            qm = np.linalg.solve(G.T, np.linalg.solve(G, V.T @ (M @ u)))
            um = V @ qm
            qf, *_ = np.linalg.lstsq(Vf, u[fd], rcond=None)
            uf = V @ qf
            vm = chamber_volumes(x, face, cid, um)
            vf = chamber_volumes(x, face, cid, uf)
            em, ef = vm / v - 1, vf / v - 1
            cm, cf = np.argmax(np.abs(em)), np.argmax(np.abs(ef))
            rel = np.sqrt(((u - um) @ (M @ (u - um))) / (u @ (M @ u)))
            fmax = np.abs(u[fd] - um[fd]).reshape(-1, 3)
            print(f"{r['name']:8s} t {r['t'][k]:.2f}: FE volume recomputed {np.abs(v / vfe[k] - 1).max():.1e}; "
                  f"M-projection (M-norm {100 * rel:.2f} %, faces' largest nodal "
                  f"{np.sqrt((fmax ** 2).sum(1)).max():.3f} mm) volumes worst {100 * em[cm]:+.2f} % "
                  f"(chamber {cm // 4 + 1}.{cm % 4 + 1}, V/V0 {v[cm] / v0[cm]:.2f}); "
                  f"faces' projection worst {100 * ef[cf]:+.2f} % (chamber {cf // 4 + 1}.{cf % 4 + 1})")
            if fib is not None:
                pr = r["p"][k].ravel() if r["p"].ndim == 3 else r["p"].ravel() * r["t"][k]
                work = float((pr * (v - v0)).sum())
                b_fe, bp_fe, f_fe, e_fe = energies(u)
                b_pm, bp_pm, f_pm, e_pm = energies(um)
                print(f"    energies (N mm): pressure work {work:.3g}; bulk FE {b_fe:.3g}, "
                      f"M-projection {b_pm:.3g} ({b_pm / max(b_fe, 1e-300):.0f}x; in span(P): FE "
                      f"{bp_fe:.3g}, M-projection {bp_pm:.3g}); fibres FE "
                      f"{f_fe:.3g}, M-projection {f_pm:.3g} ({f_pm / max(f_fe, 1e-300):.1f}x); "
                      f"largest fibre strain {e_fe:.3g} / {e_pm:.3g}")
            rp = a.rom_states and os.path.join(a.rom_states, r["name"] + ".h5")
            if rp and os.path.exists(rp):
                with h5py.File(rp, "r") as f:
                    ur = f["u"][k]
                vr = chamber_volumes(x, face, cid, ur)
                er = vr / v - 1
                cr = np.argmax(np.abs(er))
                line = (f"    reduced model's state: volumes worst {100 * er[cr]:+.2f} % (chamber "
                        f"{cr // 4 + 1}.{cr % 4 + 1})")
                if fib is not None:
                    b_r, bp_r, f_r, e_r = energies(ur)
                    line += (f"; bulk (full P0) {b_r:.3g} ({b_r / max(b_fe, 1e-300):.0f}x the FE's),"
                             f" in span(P) {bp_r:.3g},"
                             f" fibres {f_r:.3g} ({f_r / max(f_fe, 1e-300):.1f}x), largest fibre "
                             f"strain {e_r:.3g}")
                print(line)
            print("    V/V0 FE: " + " ".join(f"{z:.2f}" for z in v / v0))
            print("    M-proj err %: " + " ".join(f"{100 * z:+.2f}" for z in em))


if __name__ == "__main__":
    main()

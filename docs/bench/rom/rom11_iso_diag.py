#!/usr/bin/python3
"""rom11_iso_diag.py: does a span hold a nearly isochoric state near the FE's? (issue 34, rom11)

    /usr/bin/python3 docs/bench/rom/rom11_iso_diag.py SNAPDIR BASIS.h5 LEG.h5 [--ray T_R ...]
        [--t 0.75,1] [--enrich E.h5 --k K]

For every named held-out state u (FE) and the basis' V, P (mixed pressure modes), Qf (mixed
fibre strain modes): what the mixed reduced model charges two states of span(V), against the
chambers' pressure work sum_c p_c (V_c - V0_c) (the scale the pressures can pay):
  - the M-projection q_M (romacc_volume_diag.py's);
  - the isochoric projection q_I: the state of span(V) nearest the FE's in the M-norm whose
    dilatation in span(P) is the FE's, b(q) = P^T (V_e theta_e(Vq)) = b(u) (m equations; a
    Gauss-Newton with the minimum-norm step onto the linearised constraint, dtheta_e/du =
    g_e(u) / V_e, g_e = sum_g w_g det F F^-T grad N the derivative of the element volume).
    Its distance from the FE (M-norm, tip, chamber volumes) says whether span(V) holds a state
    the bulk energy does not penalise near the FE's; the M-projection's bulk energy alone says
    only that the nearest state is not one;
  - with --fibres the same with the mixed fibre strains also the FE's, Q^T W E(Vq) = Q^T W E(u)
    (m + mf equations): a state of span(V) the reduced model charges the FE's bulk and fibre
    energies.
Energies (N mm): the mixed bulk b^T A^-1 b / 2 (A = sum_e V_e / kappa P_e P_e^T,
fem/fem_rom_mixed.h) and the mixed fibres sum_f W_f psi(Q_f . E^), E^ = G^-1 sum_f W_f Q_f E_f
(W = EA L0, psi the tension-only law's energy, fem/fem_rom_fibre.h), both as the reduced model
charges them. With --enrich E.h5 (dataset D [ndof, k], any columns) V is first extended by the
first K columns of D, M-orthonormalised against V (twice; columns below 1e-8 dropped): a
candidate enrichment measured before any leg file is built. Units mm, N, MPa.
"""
import argparse
import os
import sys

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import h5py  # noqa: E402
import numpy as np  # noqa: E402
import scipy.sparse as sp  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))
sys.path.insert(0, HERE)
from rom_basis import mass_matrix, read_mesh, read_rays, tet_reference  # noqa: E402
from romacc_volume_diag import chamber_faces, chamber_volumes  # noqa: E402
from romlock_span_energy import psi  # noqa: E402  (the tension-only law's energy density)


def volume_grads(u, tet, dNdX, wq):
    """Element volumes v_e (ne,) and their derivatives g_e = dv_e/du_e (ne, 10, 3) at u."""
    ue = u.reshape(-1, 3)[tet]
    F = np.einsum("eai,egaj->egij", ue, dNdX) + np.eye(3)
    det = np.linalg.det(F)
    Finv = np.linalg.inv(F)
    # d det F / dF = det F F^-T; dF_ij/du_ai = dN_a/dX_j
    g = np.einsum("eg,eg,egji,egaj->eai", wq, det, Finv, dNdX)
    return (wq * det).sum(axis=1), g


def assemble_g(w, g, tet, nn):
    """sum_e w_e g_e assembled into a nodal vector (3 nn,) (w (ne,))."""
    out = np.zeros((nn, 3))
    np.add.at(out, tet, w[:, None, None] * g)
    return out.ravel()


def gV(g, tet, V, chunk=800):
    """(ne, n): g_e . V restricted to the element's dofs, for every element."""
    ne, n = tet.shape[0], V.shape[1]
    V3 = V.reshape(-1, 3, n)
    out = np.empty((ne, n))
    for s in range(0, ne, chunk):
        e = slice(s, min(s + chunk, ne))
        out[e] = np.einsum("eai,eain->en", g[e], V3[tet[e]])
    return out


def states(snapdir, names, ts, fixed):
    """The states (ray, t, u with the clamped dofs zeroed, chamber pressures (12,), gravity,
    tip force) of the named rays (all when None) at the load factors ts."""
    for r in read_rays(snapdir):
        if names and r["name"] not in names:
            continue
        for k in range(r["u"].shape[0]):
            if any(abs(r["t"][k] - t) < 1e-9 for t in ts):
                u = r["u"][k].copy()
                u[fixed] = 0.0
                p = r["p"][k].ravel() if r["p"].ndim == 3 else r["p"].ravel() * r["t"][k]
                yield r["name"], float(r["t"][k]), u, p, r["g"][k], r["F"][k]


def common_args(doc):
    """The arguments rom11_iso_diag.py and rom11_energy.py share."""
    ap = argparse.ArgumentParser(description=doc.split("\n\n")[0])
    for name in ("snapdir", "basis", "legfile"):
        ap.add_argument(name)
    ap.add_argument("--ray", action="append")
    ap.add_argument("--t", type=lambda v: [float(c) for c in v.split(",")], default=[0.75, 1.0])
    ap.add_argument("--enrich", default=None)
    ap.add_argument("--k", type=int, default=0)
    return ap


class Model:
    def __init__(self, snapdir, basis, legfile, enrich=None, k=0):
        self.x, self.tet, self.fixed, rho, _ = read_mesh(snapdir)
        self.nn = self.x.shape[0]
        self.face, self.cid = chamber_faces(snapdir)
        with h5py.File(basis, "r") as f:
            V = f["V"][...]
            self.P = f["P"][...]
            self.Qf = f["Qf"][...] if "Qf" in f else None
        Ms, _ = mass_matrix(self.x, self.tet, rho)
        self.M = sp.kron(Ms, sp.identity(3), format="csr")
        self.n0 = V.shape[1]
        if enrich:
            with h5py.File(enrich, "r") as f:
                D = f["D"][:, :k]
            V = self.orth(V, D)
        self.V = V
        self.G = np.linalg.cholesky(V.T @ (self.M @ V))
        with h5py.File(legfile, "r") as f:
            self.fib = (f["fibre/node"][...].astype(np.int64), f["fibre/coef"][...],
                        f["fibre/L0"][...], f["fibre/EA"][...])
            self.kappa = float(f.attrs["kappa"])
        self.dNdX, self.wq = tet_reference(self.x, self.tet)[:2]
        self.Ve = self.wq.sum(axis=1)
        A = (self.P * (self.Ve / self.kappa)[:, None]).T @ self.P
        self.Ainv_half = np.linalg.inv(np.linalg.cholesky(A))  # L^-1: b^T A^-1 b = |L^-1 b|^2
        self.W = self.fib[3] * self.fib[2]  # W_f = EA L0 (N mm)
        if self.Qf is not None:
            self.Gf = (self.Qf * self.W[:, None]).T @ self.Qf
        xc = self.x[self.fixed.reshape(-1, 3).any(axis=1)].mean(axis=0)
        ax = np.argmax(np.abs(self.x - xc).max(axis=0))
        far = np.abs(self.x[:, ax] - xc[ax])
        self.tip = far > far.max() - 1e-9 * max(far.max(), 1.0)
        self.v0 = chamber_volumes(self.x, self.face, self.cid, np.zeros(self.x.size))

    def orth(self, V, D):
        M = self.M
        Q = V
        kept = 0
        for j in range(D.shape[1]):
            s = D[:, j].copy()
            s[self.fixed] = 0.0
            n0 = np.sqrt(s @ (M @ s))
            for _ in range(2):  # V^T M V = I (rom_basis.py), so Q stays M-orthonormal
                s -= Q @ (Q.T @ (M @ s))
            n1 = np.sqrt(max(s @ (M @ s), 0.0))
            if n0 == 0 or n1 <= 1e-8 * n0:
                continue
            Q = np.concatenate([Q, (s / n1)[:, None]], axis=1)
            kept += 1
        return Q

    def bvec(self, u):
        v, g = volume_grads(u, self.tet, self.dNdX, self.wq)
        return self.P.T @ (v - self.Ve), g

    def bulk(self, b):
        z = self.Ainv_half @ b
        return 0.5 * float(z @ z)

    def fibres(self, u):
        node, coef, L0, EA = self.fib
        d = np.einsum("fa,fai->fi", coef, (self.x + u.reshape(-1, 3))[node])
        E = 0.5 * ((d ** 2).sum(1) / L0 ** 2 - 1.0)
        full = float((EA * L0 * psi(E)).sum())
        if self.Qf is None:
            return full, full, E.max()
        Eh = np.linalg.solve(self.Gf, self.Qf.T @ (self.W * E))
        return full, float((self.W * psi(self.Qf @ Eh)).sum()), E.max()

    def project_M(self, u):
        return np.linalg.solve(self.G.T, np.linalg.solve(self.G, self.V.T @ (self.M @ u)))

    def fibre_strain(self, u, jac=False, chunk=2000):
        """the fibres' Green strains E (nfib,) at u and with jac dE/dq (nfib, n) on span(V)"""
        node, coef, L0, _ = self.fib
        d = np.einsum("fa,fai->fi", coef, (self.x + u.reshape(-1, 3))[node])
        E = 0.5 * ((d ** 2).sum(1) / L0 ** 2 - 1.0)
        if not jac:
            return E, None
        n = self.V.shape[1]
        V3 = self.V.reshape(-1, 3, n)
        D = np.empty((node.shape[0], n))
        for s in range(0, node.shape[0], chunk):
            f = slice(s, min(s + chunk, node.shape[0]))
            D[f] = np.einsum("fa,fi,fain->fn", coef[f], d[f] / L0[f, None] ** 2, V3[node[f]])
        return E, D

    def project_iso(self, u, q0, iters=12, fibres=False):
        """q nearest q0 in the Gram metric (the M-norm of V (q - q0)) with b(Vq) = b(u), and
        with fibres also the mixed fibre strains Q^T W E(Vq) = Q^T W E(u) (then the mixed
        fibres' energy is the FE state's)."""
        bt, _ = self.bvec(u)
        if fibres:
            Lf = np.linalg.inv(np.linalg.cholesky(self.Gf))
            et = Lf @ (self.Qf.T @ (self.W * self.fibre_strain(u)[0]))
        Li = np.linalg.inv(self.G)  # metric: |G^T dq|
        q = q0.copy()
        hist = []
        for _ in range(iters):
            b, g = self.bvec(self.V @ q)
            c = self.Ainv_half @ (b - bt)  # scaled so |c|^2 / 2 is the bulk energy gap (N mm)
            hist.append(0.5 * float(c @ c))
            C = self.Ainv_half @ (self.P.T @ gV(g, self.tet, self.V))  # (m, n)
            if fibres:
                E, D = self.fibre_strain(self.V @ q, jac=True)
                cf = Lf @ (self.Qf.T @ (self.W * E)) - et
                hist[-1] += float(cf @ cf)
                c = np.concatenate([c, cf])
                C = np.concatenate([C, Lf @ (self.Qf.T @ (self.W[:, None] * D))])
            # min |G^T (q + dq - q0)|^2 s.t. c + C dq = 0; y = G^T dq: C Li^T y
            Cy = C @ Li.T
            r0 = self.G.T @ (q0 - q)
            lam = np.linalg.lstsq(Cy @ Cy.T, c + Cy @ r0, rcond=1e-12)[0]
            y = r0 - Cy.T @ lam
            q = q + Li.T @ y
        b, _ = self.bvec(self.V @ q)
        c = self.Ainv_half @ (b - bt)
        hist.append(0.5 * float(c @ c))
        if fibres:
            cf = Lf @ (self.Qf.T @ (self.W * self.fibre_strain(self.V @ q)[0])) - et
            hist[-1] += float(cf @ cf)
        return q, hist

    def report(self, u, p, qs):
        v = chamber_volumes(self.x, self.face, self.cid, u)
        work = float((p * (v - self.v0)).sum())
        bfe, _ = self.bvec(u)
        ffe, fmfe, efe = self.fibres(u)
        out = dict(work=work, bulk_fe=self.bulk(bfe), fib_fe=fmfe, fibfull_fe=ffe, emax_fe=efe)
        nrm = np.sqrt(u @ (self.M @ u))
        for name, q in qs.items():
            w = self.V @ q
            r = u - w
            vv = chamber_volumes(self.x, self.face, self.cid, w)
            ev = vv / v - 1
            cw = int(np.argmax(np.abs(ev)))
            bw, _ = self.bvec(w)
            fw, fmw, ew = self.fibres(w)
            R3 = r.reshape(-1, 3)
            out[name] = dict(rel=float(np.sqrt(r @ (self.M @ r)) / nrm),
                             tip=float(np.sqrt((R3[self.tip].mean(axis=0) ** 2).sum())),
                             vol=float(ev[cw]), ch=cw, bulk=self.bulk(bw), fib=fmw, fibfull=fw,
                             emax=ew)
        return out


def main():
    ap = common_args(__doc__)
    ap.add_argument("--fibres", action="store_true",
                    help="also the projection that keeps the mixed fibre strains the FE's")
    a = ap.parse_args()
    m = Model(a.snapdir, a.basis, a.legfile, a.enrich, a.k)
    print(f"rom11_iso_diag: {os.path.basename(a.basis)}: n = {m.n0}"
          f"{f' + {m.V.shape[1] - m.n0} of {a.enrich} (first {a.k})' if a.enrich else ''}"
          f" = {m.V.shape[1]}, m = {m.P.shape[1]}, mf = {0 if m.Qf is None else m.Qf.shape[1]}, "
          f"kappa {m.kappa:g} MPa")
    for name, t, u, p, _, _ in states(a.snapdir, a.ray, a.t, m.fixed):
        qm = m.project_M(u)
        qi, hist = m.project_iso(u, qm)
        qs = dict(M=qm, I=qi)
        if a.fibres:
            qs["F"], hist_f = m.project_iso(u, qm, fibres=True)
        o = m.report(u, p, qs)
        print(f"{name:8s} t {t:.2f}: pressure work {o['work']:.4g} N mm; FE bulk "
              f"{o['bulk_fe']:.3g}, mixed fibres {o['fib_fe']:.3g} (full {o['fibfull_fe']:.3g},"
              f" largest strain {o['emax_fe']:.3f})")
        for key, lab in (("M", "M-projection"), ("I", "isochoric projection"),
                         ("F", "+ fibres' projection")):
            if key not in o:
                continue
            s = o[key]
            print(f"    {lab:21s}: M-norm {100 * s['rel']:.3f} %, tip {s['tip']:.3f} mm, "
                  f"volumes worst {100 * s['vol']:+.2f} % (chamber {s['ch'] // 4 + 1}."
                  f"{s['ch'] % 4 + 1}); bulk in span(P) {s['bulk']:.4g}, mixed fibres "
                  f"{s['fib']:.4g} (full {s['fibfull']:.4g}, largest strain {s['emax']:.3f})")
        print("    isochoric projection's bulk gap by Gauss-Newton iteration: "
              + " ".join(f"{h:.3g}" for h in hist))
        if a.fibres:
            print("    with the fibres' strains (their scaled gap added): "
                  + " ".join(f"{h:.3g}" for h in hist_f))
        sys.stdout.flush()


if __name__ == "__main__":
    main()

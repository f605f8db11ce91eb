#!/usr/bin/python3
"""rom11_energy.py: the reduced model's potential energy and its gradient on span(V) (issue 34, rom11).

    /usr/bin/python3 docs/bench/rom/rom11_energy.py SNAPDIR BASIS.h5 LEG.h5 [--ray T_R]
        [--t 0.75,1] [--rom-states DIR] [--enrich E.h5 --k K] [--newton N]

The total potential the every-element mixed reduced model minimises (fem/fem_rom.h; its
Galerkin residual is this energy's gradient), evaluated in numpy on u = V q:
  Pi(q) = sum_e sum_g w_g W_dev(F_g)                   Yeoh, I1b = J^-2/3 tr F^T F (fem_material.h)
        + b^T A^-1 b / 2,  b = P^T (v_e - V_e)          the mixed P0 bulk in span(P) (fem_rom_mixed.h)
        + sum_f W_f psi(Q_f . E^)                        the mixed fibres (fem_rom_fibre.h)
        - sum_c p_c (V_c(u) - V0_c)                      the chambers' pressures (constant p)
and the FE's own potential (P0 bulk kappa V_e theta_e^2 / 2 element by element, every fibre's
psi(E_f)) for the verification: its gradient at the FE's equilibrium must vanish to the FE's
Newton tolerance against the pressure forces (printed as a ratio). For each held-out state:
Pi and its parts at the FE state (FE potential), at the M-projection and at the isochoric
projection (rom11_iso_diag.py), the reduced gradient's norm there against the pressure forces'
(|V^T f_p|), and with --rom-states DIR (`crawlsim rom check --states DIR`) the same at the
reduced model's own solution: the Galerkin model locks energetically when its solution's Pi is
below the isochoric projection's; when it is above, the reduced Newton stopped on another branch.
With --newton N: N damped Newton steps on Pi from the isochoric projection (the Hessian by
central differences of the gradient along the n coordinates: 2 n gradients a step), to where
the reduced model settles when started at the FE's state. Units mm, N, MPa, N mm.
"""
import os
import sys

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")
os.environ.setdefault("OMP_NUM_THREADS", "1")

import h5py  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
from rom11_iso_diag import Model, common_args, psi, states, volume_grads  # noqa: E402
from rom_basis import fibre_law  # noqa: E402
from romacc_volume_diag import TRIQ, tri6  # noqa: E402


def dpsi(E):
    return fibre_law(E, True)


class Energy(Model):
    def __init__(self, *args, **kw):
        super().__init__(*args, **kw)
        with h5py.File(args[2], "r") as f:
            self.C10, self.C20 = float(f.attrs["C10"]), float(f.attrs["C20"])

    def dev(self, u, grad=True):
        ue = u.reshape(-1, 3)[self.tet]
        F = np.einsum("eai,egaj->egij", ue, self.dNdX) + np.eye(3)
        J = np.linalg.det(F)
        I1 = np.einsum("egij,egij->eg", F, F)
        Jm = J ** (-2.0 / 3.0)
        I1b = Jm * I1
        W = self.C10 * (I1b - 3) + self.C20 * (I1b - 3) ** 2
        e = float((self.wq * W).sum())
        if not grad:
            return e, None
        dW = self.C10 + 2 * self.C20 * (I1b - 3)
        FinvT = np.transpose(np.linalg.inv(F), (0, 1, 3, 2))
        Pk = (dW * Jm)[..., None, None] * (2 * F - (2.0 / 3.0) * I1[..., None, None] * FinvT)
        fe = np.einsum("eg,egij,egaj->eai", self.wq, Pk, self.dNdX)
        f = np.zeros((self.nn, 3))
        np.add.at(f, self.tet, fe)
        return e, f.ravel()

    def bulk_mixed(self, u):
        v, g = volume_grads(u, self.tet, self.dNdX, self.wq)
        b = self.P.T @ (v - self.Ve)
        z = self.Ainv_half @ b
        lam = self.Ainv_half.T @ z  # A^-1 b
        pe = self.P @ lam
        f = np.zeros((self.nn, 3))
        np.add.at(f, self.tet, pe[:, None, None] * g)
        return 0.5 * float(z @ z), f.ravel()

    def bulk_fe(self, u):
        v, g = volume_grads(u, self.tet, self.dNdX, self.wq)
        th = v / self.Ve - 1
        f = np.zeros((self.nn, 3))
        np.add.at(f, self.tet, (self.kappa * th)[:, None, None] * g)
        return 0.5 * self.kappa * float((self.Ve * th ** 2).sum()), f.ravel()

    def fibres_e(self, u, mixed=True):
        node, coef, L0, EA = self.fib
        d = np.einsum("fa,fai->fi", coef, (self.x + u.reshape(-1, 3))[node])
        E = 0.5 * ((d ** 2).sum(1) / L0 ** 2 - 1.0)
        W = EA * L0
        if mixed and self.Qf is not None:
            Eh = np.linalg.solve(self.Gf, self.Qf.T @ (W * E))
            Eb = self.Qf @ Eh
            e = float((W * psi(Eb)).sum())
            Ss = self.Qf @ np.linalg.solve(self.Gf, self.Qf.T @ (W * dpsi(Eb)))
        else:
            e = float((W * psi(E)).sum())
            Ss = dpsi(E)
        # dE_f/dx_a = coef_a d_f / L0^2
        fa = (W * Ss / L0 ** 2)[:, None, None] * coef[:, :, None] * d[:, None, :]
        f = np.zeros((self.nn, 3))
        np.add.at(f, node, fa)
        return e, f.ravel()

    def chambers(self, u):
        """chamber volumes (12) and their gradients (12, ndof)."""
        xf = (self.x + u.reshape(-1, 3))[self.face]
        v = np.zeros(self.face.shape[0])
        gf = np.zeros(xf.shape)
        for s, t, w in TRIQ:
            N, dN = tri6(s, t)
            xs = np.einsum("a,fai->fi", dN[:, 0], xf)
            xt = np.einsum("a,fai->fi", dN[:, 1], xf)
            xq = np.einsum("a,fai->fi", N, xf)
            c = np.cross(xs, xt)
            v -= w * np.einsum("fi,fi->f", xq, c) / 3.0
            gf -= (w / 3.0) * (N[None, :, None] * c[:, None, :]
                               + dN[None, :, 0, None] * np.cross(xt, xq)[:, None, :]
                               + dN[None, :, 1, None] * np.cross(xq, xs)[:, None, :])
        vol = np.bincount(self.cid, weights=v, minlength=12)
        G = np.zeros((12, self.nn, 3))
        for c in range(12):
            sel = self.cid == c
            np.add.at(G[c], self.face[sel], gf[sel])
        return vol, G.reshape(12, -1)

    def total(self, u, p, fe=False):
        """parts (dev, bulk, fibres, -pressure work) and the gradient (ndof,)."""
        ed, fd = self.dev(u)
        eb, fb = self.bulk_fe(u) if fe else self.bulk_mixed(u)
        ef, ff = self.fibres_e(u, mixed=not fe)
        vol, G = self.chambers(u)
        ep = -float(p @ (vol - self.v0))
        fp = -(p @ G)
        f = fd + fb + ff + fp
        f[self.fixed] = 0.0
        fp[self.fixed] = 0.0
        return (ed, eb, ef, ep), f, fp


def main():
    ap = common_args(__doc__)
    ap.add_argument("--rom-states", default=None)
    ap.add_argument("--newton", type=int, default=0)
    ap.add_argument("--mf", type=int, default=-1,
                    help="the first MF fibre modes of the basis' Qf only (0: no fibre basis, the "
                    "FE's fibres fibre by fibre, as `run_romreal4.sh base`)")
    ap.add_argument("--qf", default=None,
                    help="the fibre basis of this file's /Qf instead of the basis' (with --mf: "
                    "its first MF columns)")
    a = ap.parse_args()
    m = Energy(a.snapdir, a.basis, a.legfile, enrich=a.enrich, k=a.k)
    if a.qf:
        with h5py.File(a.qf, "r") as fh:
            m.Qf = fh["Qf"][:, :a.mf] if a.mf > 0 else fh["Qf"][...]
        m.Gf = (m.Qf * m.W[:, None]).T @ m.Qf
    elif a.mf == 0:
        m.Qf = None
    elif a.mf > 0:
        m.Qf = m.Qf[:, :a.mf]
        m.Gf = (m.Qf * m.W[:, None]).T @ m.Qf
    V = m.V
    print(f"rom11_energy: {os.path.basename(a.basis)}: n = {V.shape[1]}, m = {m.P.shape[1]}, "
          f"mf = {0 if m.Qf is None else m.Qf.shape[1]}; Yeoh C10 {m.C10:g}, C20 {m.C20:g}, "
          f"kappa {m.kappa:g} MPa")

    def line(lab, parts, g, gp, extra=""):
        tot = sum(parts)
        print(f"    {lab:22s} Pi {tot:10.2f} = dev {parts[0]:9.2f} + bulk {parts[1]:9.3g} + "
              f"fibres {parts[2]:8.3g} - work {-parts[3]:9.2f}; |grad| / |pressure force| "
              f"{np.linalg.norm(g) / np.linalg.norm(gp):.2e}{extra}")
        return tot

    for name, t, u, p, grav, tipf in states(a.snapdir, a.ray, a.t, m.fixed):
        if np.abs(grav).max() > 0 or np.abs(tipf).max() > 0:
            print(f"{name} t {t:.2f}: gravity or a tip force: not modelled here")
            continue
        print(f"{name:8s} t {t:.2f}:")
        parts, f, fp = m.total(u, p, fe=True)
        line("FE state, FE potential", parts, f, fp, "  (full ndof: the verification)")
        qm = m.project_M(u)
        qi, _ = m.project_iso(u, qm)
        cands = [("M-projection", qm), ("isochoric projection", qi)]
        rp = a.rom_states and os.path.join(a.rom_states, name + ".h5")
        if rp and os.path.exists(rp):
            with h5py.File(rp, "r") as fh:
                ur = fh["u"][int(np.argmin(np.abs(fh["t"][...] - t)))]
            cands.append(("reduced solution", m.project_M(ur)))
        for lab, q in cands:
            w = V @ q
            parts, f, fp = m.total(w, p)
            R3 = (u - w).reshape(-1, 3)
            tip = np.sqrt((R3[m.tip].mean(axis=0) ** 2).sum())
            line(lab, parts, V.T @ f, V.T @ fp, f"; tip {tip:.3f} mm")
        q = qi.copy()
        for it in range(a.newton):
            w = V @ q
            parts, f, fp = m.total(w, p)
            g = V.T @ f
            # forward differences of the gradient along each coordinate: q ~ 0.1-1 and a
            # unit q moves the leg by ~1 / sqrt(mass) ~ 170 mm, so h = 1e-6 moves it by
            # ~2e-4 mm (strains ~1e-5: far above round-off, far inside the nonlinearity)
            h = 1e-6
            n = V.shape[1]
            H = np.empty((n, n))
            for j in range(n):
                H[:, j] = (V.T @ m.total(w + h * V[:, j], p)[1] - g) / h
            H = 0.5 * (H + H.T)
            ev = np.linalg.eigvalsh(H)
            # an indefinite Hessian (away from a minimum): shift it to a descent direction
            shift = 0.0 if ev[0] > 0 else 1.1 * abs(ev[0]) + 1e-9 * abs(ev[-1])
            dq = -np.linalg.solve(H + shift * np.eye(n), g)
            e0 = sum(parts)
            alpha = 1.0
            while alpha > 1e-3:
                e1 = sum(m.total(V @ (q + alpha * dq), p)[0])
                if e1 < e0:
                    break
                alpha *= 0.5
            q = q + alpha * dq
            w = V @ q
            parts, f, fp = m.total(w, p)
            R3 = (u - w).reshape(-1, 3)
            tip = np.sqrt((R3[m.tip].mean(axis=0) ** 2).sum())
            line(f"Newton {it + 1} (a {alpha:.3g})", parts, V.T @ f, V.T @ fp,
                 f"; tip {tip:.3f} mm; Hessian eig {ev[0]:.3g} .. {ev[-1]:.3g}")
            sys.stdout.flush()
        sys.stdout.flush()


if __name__ == "__main__":
    main()

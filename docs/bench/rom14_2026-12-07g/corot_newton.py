#!/usr/bin/python3
"""The reduced Newton on the corotated manifold (rom14, issue 34): the exact oracle's screen.

    corot_newton.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 --r 12 --k 176 --ray T_R --t 1
        [--newton 3] [--mf 0] [--width 2] [--sup 0]

The reduced state z = (a, ql): a the first R strain modes of the slab chain (ROD.h5 /Vs,
corot_rep.py), ql the first K local modes (LOCAL.h5 /Vl, corot_rep.py --consistent: the
training states' local shapes in the truncated chains' frames); the map
    u(z) = R(a) (X - c0 + Vl ql) + c(a) - X,   u = 0 on the clamped dofs
(corot.py: the chain's rotations by slerp along z, its centroids linear) is a nonlinear
manifold: a bend carries the walls' shapes with it instead of adding a linearised rotation.
With --sup S the basis' last S columns of V (the supremizers of the mixed pressure modes,
rom_basis.py) join Vl as local modes. The reduced potential is rom11_energy.py's (Yeoh +
the mixed bulk in span(P) + the fibres, every fibre by the FE's law with --mf 0 or the
basis' first MF mixed fibre modes, - the constant-pressure work); its gradient J(z)^T f(u(z))
with J = du/dz (the local columns exactly, R(a) Vl; the strain columns by central
differences of the map), the Hessian J^T K J (K J by forward differences of the full
force along J's columns) plus the manifold's curvature f . d2u/dz2 (differences of J at fixed
f; Manifold.hessian), damped Newton with a line search on Pi as
rom11_energy.py's. Started at the held-out FE state's representation (its strains and local
shape projected: corot_rep.py's state), it says whether the reduced model stays at the FE
state (rom13's exact oracle on V + r: 0.17 mm, the FE's pressure work) or drifts (V: 2.4 /
3.6 mm, -6 % work). Units mm, N mm.
"""
import argparse
import os
import sys
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from corot import Slabs, rod_frames, rod_strains  # noqa: E402
from rom11_energy import Energy  # noqa: E402
from rom11_iso_diag import states  # noqa: E402


class Manifold:
    def __init__(self, m, sl, Vs, Vl):
        self.m, self.sl, self.Vs, self.Vl = m, sl, Vs, Vl
        self.r, self.k = Vs.shape[1], Vl.shape[1]
        self.n = self.r + self.k

    def fld(self, a):
        return self.sl.field(*rod_frames((self.Vs @ a).reshape(-1, 6), self.sl.c0))

    def u(self, z, fld=None):
        a, ql = z[:self.r], z[self.r:]
        w = self.sl.glob(self.Vl @ ql, self.fld(a) if fld is None else fld)
        w[self.m.fixed] = 0.0
        return w

    def rot_local(self, Rn):
        """R(z) Vl node by node (ndof, k), the clamped rows zero"""
        J = np.matmul(Rn, self.Vl.reshape(-1, 3, self.k)).reshape(-1, self.k)
        J[self.m.fixed] = 0.0
        return J

    def jac_strain(self, z, h=1e-5):
        """du/da by central differences of the map (the chain's rotations are not linear in a)"""
        Ja = np.empty((self.m.x.size, self.r))
        for j in range(self.r):
            e = np.zeros(self.n)
            e[j] = h
            Ja[:, j] = (self.u(z + e) - self.u(z - e)) / (2 * h)
        return Ja

    def jac(self, z):
        fld = self.fld(z[:self.r])
        return np.concatenate([self.jac_strain(z), self.rot_local(fld[0])], axis=1), fld

    def hessian(self, z, p, J, f, h=1e-6, hc=1e-5):
        """d(J^T f)/dz = J^T K J + f . d2u/dz2: K J by differences of the full force along
        each column of J (one force a column), the manifold's curvature term by differences of
        J^T f at fixed f (zero between local coordinates: u is linear in ql at fixed a)."""
        w = self.u(z)
        H = np.empty((self.n, self.n))
        for j in range(self.n):
            H[:, j] = J.T @ ((self.m.total(w + h * J[:, j], p)[1] - f) / h)
        C = np.zeros((self.n, self.n))
        for j in range(self.r):
            e = np.zeros(self.n)
            e[j] = hc
            gp = np.concatenate([self.jac_strain(z + e).T @ f,
                                 self.rot_local(self.fld((z + e)[:self.r])[0]).T @ f])
            gm = np.concatenate([self.jac_strain(z - e).T @ f,
                                 self.rot_local(self.fld((z - e)[:self.r])[0]).T @ f])
            C[:, j] = (gp - gm) / (2 * hc)
        C[:self.r, self.r:] = C[self.r:, :self.r].T
        return 0.5 * (H + H.T) + C

    def grad(self, z, p):
        J, fld = self.jac(z)
        w = self.u(z, fld)
        parts, f, fp = self.m.total(w, p)
        return parts, J.T @ f, J.T @ fp, w, J, f


def manifold_args(extra):
    """the arguments the manifold's scripts share (positional SNAP BASIS LEG ROD LOCAL, then
    EXTRA), --r, --k"""
    ap = argparse.ArgumentParser()
    for name in ("snap", "basis", "leg", "rod", "local") + tuple(extra):
        ap.add_argument(name)
    ap.add_argument("--r", type=int, default=12)
    ap.add_argument("--k", type=int, default=176)
    return ap


def load_manifold(a):
    """rom11_energy.Energy of the basis and leg file, and the Manifold of a's ROD / LOCAL"""
    m = Energy(a.snap, a.basis, a.leg)
    with h5py.File(a.rod, "r") as f:
        Vs = f["Vs"][:, :a.r]
    with h5py.File(a.local, "r") as f:
        Vl = f["Vl"][:, :a.k]
    return m, Manifold(m, Slabs(m.x, 2.0), Vs, Vl)


def main():
    ap = argparse.ArgumentParser()
    for n in ("snap", "basis", "leg", "rod", "local"):
        ap.add_argument(n)
    ap.add_argument("--r", type=int, default=12)
    ap.add_argument("--k", type=int, default=176)
    ap.add_argument("--sup", type=int, default=0)
    ap.add_argument("--ray", default="T_R")
    ap.add_argument("--t", type=float, default=1.0)
    ap.add_argument("--newton", type=int, default=3)
    ap.add_argument("--mf", type=int, default=0)
    ap.add_argument("--width", type=float, default=2.0)
    ap.add_argument("--bulk", choices=("mixed", "fe"), default="mixed",
                    help="the bulk energy: the mixed P0 bulk in span(P) (rom11_energy.py's) or the "
                    "FE's own, element by element (kappa V_e theta_e^2 / 2)")
    ap.add_argument("--bfgs", action="store_true",
                    help="the differenced Hessian at the first step only, BFGS updates after (each "
                    "later step costs a gradient, not n forces)")
    ap.add_argument("--resume", default=None,
                    help="start from the last iterate of this --save file instead of the "
                    "representation (a fresh Hessian)")
    ap.add_argument("--save", default=None, help="the iterates z (one row a step) to this .npy")
    a = ap.parse_args()
    t0 = time.process_time()
    m = Energy(a.snap, a.basis, a.leg)
    if a.mf == 0:
        m.Qf = None
    else:
        m.Qf = m.Qf[:, :a.mf]
        m.Gf = (m.Qf * m.W[:, None]).T @ m.Qf
    sl = Slabs(m.x, a.width)
    with h5py.File(a.rod, "r") as f:
        Vs = f["Vs"][:, :a.r]
    with h5py.File(a.local, "r") as f:
        Vl = f["Vl"][:, :a.k]
    if a.sup:
        # supremizers in the local frame: M-orthonormalised against the local modes
        Vl = m.orth(Vl, m.V[:, -a.sup:])
    if a.bulk == "fe":
        m.bulk_mixed = m.bulk_fe  # Energy.total charges bulk_mixed on the reduced states
    mf = Manifold(m, sl, Vs, Vl)
    print(f"corot_newton: {a.ray} t {a.t:g}: r = {mf.r} strain + {mf.k} local modes (n = "
          f"{mf.n}), {sl.nsl} slabs; bulk {a.bulk}; fibres {'FE (mf = 0)' if m.Qf is None else m.Qf.shape[1]}")
    (name, t, u, p, _, _), = list(states(a.snap, [a.ray], [a.t], m.fixed))
    nu = np.sqrt(u @ (m.M @ u))
    vfe = m.chambers(u)[0]
    s = rod_strains(*sl.fit(u), sl.c0).ravel()
    z = np.concatenate([Vs.T @ s, np.zeros(mf.k)])
    fld = mf.fld(z[:mf.r])
    ul = sl.local(u, fld)
    z[mf.r:] = np.linalg.lstsq(Vl.T @ (m.M @ Vl), Vl.T @ (m.M @ ul), rcond=None)[0]

    def line(lab, parts, g, gp, w, extra=""):
        r = u - w
        R3 = r.reshape(-1, 3)
        tip = np.sqrt((R3[m.tip].mean(axis=0) ** 2).sum())
        vol = m.chambers(w)[0] / vfe - 1
        c = int(np.argmax(np.abs(vol)))
        print(f"    {lab:18s} Pi {sum(parts):9.2f} = dev {parts[0]:8.2f} + bulk {parts[1]:8.3g} + "
              f"fibres {parts[2]:8.3g} - work {-parts[3]:8.2f}; |grad|/|p force| "
              f"{np.linalg.norm(g) / np.linalg.norm(gp):.2e}; tip {tip:.3f} mm, M-norm "
              f"{100 * np.sqrt(r @ (m.M @ r)) / nu:.3f} %, worst chamber {100 * vol[c]:+.2f} % "
              f"({c // 4 + 1}.{c % 4 + 1}){extra}")
        sys.stdout.flush()

    parts, f, fp = m.total(u, p)
    line("FE state", parts, f, fp, u, " (full ndof, the reduced model's terms)")
    parts, g, gp, w, J, f = mf.grad(z, p)
    line("representation", parts, g, gp, w)
    hist = [z.copy()]
    if a.resume:
        hist = list(np.load(a.resume))
        z = hist[-1].copy()
        parts, g, gp, w, J, f = mf.grad(z, p)
        line(f"resumed ({len(hist) - 1})", parts, g, gp, w)
    B, sv, yv, sy = None, None, None, 0.0
    for it in range(a.newton):
        if it == 0 or not a.bfgs:
            H = mf.hessian(z, p, J, f)
            ev = np.linalg.eigvalsh(H)
            shift = 0.0 if ev[0] > 0 else 1.1 * abs(ev[0]) + 1e-9 * abs(ev[-1])
            B = H + shift * np.eye(mf.n)
        elif sy > 1e-12 * np.linalg.norm(sv) * np.linalg.norm(yv):
            Bs = B @ sv
            B = B - np.outer(Bs, Bs) / (sv @ Bs) + np.outer(yv, yv) / sy
        dz = -np.linalg.solve(B, g)
        g_old = g
        e0 = sum(parts)
        alpha = 1.0
        while alpha > 1e-3:
            e1 = sum(m.total(mf.u(z + alpha * dz), p)[0])
            if e1 < e0:
                break
            alpha *= 0.5
        z = z + alpha * dz
        parts, g, gp, w, J, f = mf.grad(z, p)
        sv, yv = alpha * dz, g - g_old
        sy = float(sv @ yv)
        line(f"Newton {it + 1} (a {alpha:.3g})", parts, g, gp, w,
             f"; Hessian eig {ev[0]:.3g} .. {ev[-1]:.3g}; {time.process_time() - t0:.0f} s CPU")
        hist.append(z.copy())
        if a.save:
            np.save(a.save, np.array(hist))


if __name__ == "__main__":
    main()

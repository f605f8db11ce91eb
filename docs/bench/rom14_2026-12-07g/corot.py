#!/usr/bin/python3
"""Corotated per-slab kinematics of the leg (rom14, issue 34): the shared pieces.

The leg's axis is z (0 at the clamp, 166 mm at the tip). A state u is split into a rigid
motion per cross-section slab (nodes binned by reference z; per slab the best-fit rotation R_s
and the centroid c_s of its nodes, Kabsch: the least-squares rigid map of X - c0_s onto
x - c_s) interpolated along z (rotations by slerp between slab centres, centroids linearly,
both held constant beyond the first and last centres), and a local displacement in the
slab's rotated frame:
    u_loc(X) = R(z)^T (X + u(X) - c(z)) - (X - c0(z))
    u(X)     = R(z) (X - c0(z) + u_loc(X)) + c(z) - X          (the inverse: exact)
Green strains are rotation-invariant, so a linear combination of local shapes measured in a
frame that carries the segment's bend stretches the fibres only by the local shapes' own
nonlinearity, not by the linearised rotation of the bend (why span(V) stretches them: rom11).
The quarter turns about z commute with the split (c0 on the axis), so the local shapes of the
turned training states are the turned local shapes. Units mm.
"""
import os
import sys

os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # one thread: the machine is shared
os.environ.setdefault("OMP_NUM_THREADS", "1")
_HERE = os.path.dirname(os.path.abspath(__file__))
for _p in (os.path.join(_HERE, "..", "..", "..", "tools"), os.path.join(_HERE, "..", "rom")):
    if _p not in sys.path:
        sys.path.insert(0, _p)

import numpy as np  # noqa: E402
from scipy.spatial.transform import Rotation, Slerp  # noqa: E402


class Slabs:
    def __init__(self, x, width=2.0, weights=None):
        self.x = x
        z = x[:, 2]
        nsl = max(1, int(round((z.max() - z.min()) / width)))
        edges = np.linspace(z.min(), z.max(), nsl + 1)
        self.sid = np.clip(np.searchsorted(edges, z, side="right") - 1, 0, nsl - 1)
        self.nsl = nsl
        self.w = np.ones(x.shape[0]) if weights is None else weights
        ws = np.bincount(self.sid, weights=self.w, minlength=nsl)
        self.ws = ws
        self.c0 = np.stack([np.bincount(self.sid, weights=self.w * x[:, i], minlength=nsl)
                            for i in range(3)], axis=1) / ws[:, None]
        self.zc = self.c0[:, 2].copy()
        self.zn = np.clip(z, self.zc[0], self.zc[-1])

    def fit(self, u):
        """per slab rotation (nsl, 3, 3) and centroid (nsl, 3) of the state u (ndof,)"""
        xx = self.x + u.reshape(-1, 3)
        c = np.stack([np.bincount(self.sid, weights=self.w * xx[:, i], minlength=self.nsl)
                      for i in range(3)], axis=1) / self.ws[:, None]
        P = self.x - self.c0[self.sid]
        Q = xx - c[self.sid]
        H = np.zeros((self.nsl, 3, 3))
        np.add.at(H, self.sid, self.w[:, None, None] * P[:, :, None] * Q[:, None, :])
        U, _, Vt = np.linalg.svd(H)
        d = np.sign(np.linalg.det(np.einsum("sji,skj->sik", Vt, U)))
        D = np.zeros((self.nsl, 3, 3))
        D[:, 0, 0] = 1
        D[:, 1, 1] = 1
        D[:, 2, 2] = d
        R = np.einsum("sji,sjk,slk->sil", Vt, D, U)  # V D U^T: maps P onto Q
        return R, c

    def field(self, R, c):
        """per node rotation (nn, 3, 3), centroid (nn, 3), reference centroid (nn, 3)"""
        Rn = Slerp(self.zc, Rotation.from_matrix(R))(self.zn).as_matrix()
        cn = np.stack([np.interp(self.zn, self.zc, c[:, i]) for i in range(3)], axis=1)
        c0n = np.stack([np.interp(self.zn, self.zc, self.c0[:, i]) for i in range(3)], axis=1)
        return Rn, cn, c0n

    def local(self, u, fld):
        Rn, cn, c0n = fld
        xx = self.x + u.reshape(-1, 3)
        return (np.einsum("nji,nj->ni", Rn, xx - cn) - (self.x - c0n)).ravel()

    def glob(self, ul, fld):
        Rn, cn, c0n = fld
        y = self.x - c0n + ul.reshape(-1, 3)
        return (np.einsum("nij,nj->ni", Rn, y) + cn - self.x).ravel()


def rod_strains(R, c, c0, lever=7.5):
    """the slab chain's strains (nsl, 6): per slab the rotation vector relative to the slab
    below (the first: to the identity) times LEVER (mm: the section's half-width, so radians
    and mm weigh alike in a POD), and the offset from the slab below in that slab's frame
    minus the reference offset (mm). rod_frames inverts it exactly."""
    nsl = R.shape[0]
    Rp = np.concatenate([np.eye(3)[None], R[:-1]], axis=0)
    kap = Rotation.from_matrix(np.einsum("sji,sjk->sik", Rp, R)).as_rotvec()
    cp = np.concatenate([c0[:1], c[:-1]], axis=0)
    c0p = np.concatenate([c0[:1], c0[:-1]], axis=0)
    gam = np.einsum("sji,sj->si", Rp, c - cp) - (c0 - c0p)
    assert nsl == kap.shape[0]
    return np.concatenate([lever * kap, gam], axis=1)


def rod_frames(s, c0, lever=7.5):
    """the slab rotations and centroids of the strains s (nsl, 6) (rod_strains' inverse)"""
    nsl = s.shape[0]
    dR = Rotation.from_rotvec(s[:, :3] / lever).as_matrix()
    R = np.empty((nsl, 3, 3))
    c = np.empty((nsl, 3))
    Rp, cp, c0p = np.eye(3), c0[0], c0[0]
    for i in range(nsl):
        c[i] = cp + Rp @ (c0[i] - c0p + s[i, 3:])
        R[i] = Rp @ dR[i]
        Rp, cp, c0p = R[i], c[i], c0[i]
    return R, c


def turn_strains(S, maps):
    """strain fields (nsl*6, m) and their quarter turns (both halves turn with the section)"""
    out = [S]
    for Rk, _ in maps:
        T = S.reshape(-1, 2, 3, S.shape[1])
        out.append(np.einsum("ab,sibm->siam", Rk, T).reshape(S.shape))
    return np.concatenate(out, axis=1)


def train_states(snap, fixed):
    """every training FE state (ray by ray, load factor by load factor), clamped dofs zeroed"""
    from rom_basis import read_rays
    for r in read_rays(snap):
        if r["kind"] != "train":
            continue
        for k in range(r["u"].shape[0]):
            u = r["u"][k].copy()
            u[fixed] = 0.0
            yield u


def mpod(U, M, fixed):
    """POD of the columns of U in the M inner product (method of snapshots)."""
    U = U.copy()
    U[fixed] = 0.0
    C = U.T @ (M @ U)
    lam, Y = np.linalg.eigh(C)
    order = np.argsort(lam)[::-1]
    lam, Y = lam[order], Y[:, order]
    keep = lam > 1e-12 * lam[0]
    lam, Y = lam[keep], Y[:, keep]
    return U @ (Y / np.sqrt(lam)), np.sqrt(lam)


def show(m, lab, u, w, p):
    """one line: w against the FE state u (M-norm, tip, worst chamber) and the FE's energies
    at w (rom11_energy.Energy m: Yeoh, P0 bulk and the mixed bulk in span(P), every fibre)"""
    nu = np.sqrt(u @ (m.M @ u))
    r = u - w
    R3 = r.reshape(-1, 3)
    tip = np.sqrt((R3[m.tip].mean(axis=0) ** 2).sum())
    (ed, eb, ef, ep), _, _ = m.total(w, p, fe=True)
    ebm = m.bulk_mixed(w)[0]
    E, _ = m.fibre_strain(w)
    vol = m.chambers(w)[0] / m.chambers(u)[0] - 1
    c = int(np.argmax(np.abs(vol)))
    print(f"    {lab:34s} M-norm {100 * np.sqrt(r @ (m.M @ r)) / nu:6.3f} %, tip {tip:6.3f} mm, "
          f"worst chamber {100 * vol[c]:+6.2f} % ({c // 4 + 1}.{c % 4 + 1}); dev {ed:7.1f}, "
          f"bulk P0 {eb:8.3g} / span(P) {ebm:8.3g}, fibres {ef:8.3g} (largest {E.max():.3f}), "
          f"work {-ep:7.1f}", flush=True)

#!/usr/bin/python3
"""Candidate fibre bases Qf for the mixed fibre field's consistency (rom13, item 2), each written
as OUT_<name>.h5 /Qf (W-orthonormal, W = EA L0) for consistency_parts.py:
  all       the W-POD of every training FE state's fibre strains E and stresses S(E) (rom_basis.py
            fibre_basis without truncation: 2 per state),
  split     `all` split per segment at the connectors (z = 54, 112 mm; rom_basis.py --f-split's
            construction): a segment's strains from any training state's same segment,
  split104  the basis' own Qf (mf = 104) split the same way,
  sect104   the basis' Qf split per segment and per chamber quadrant (sign of x and y at the
            fibre's host element; the chambers sit on the diagonals): 12 zones, a chamber wall's
            strains from any training state's same chamber,
  sect      every training mode (`all`) split the same way (12 zones),
  sect104z6 the basis' Qf split per half segment (z cuts 27, 54, 83, 112, 139 mm) and quadrant
            (24 zones),
  lin0      the basis' Qf plus the span's linearised strain modes at the reference, D_0 V (n columns:
            the strain rates every reduced state starts from),
  oracle    the basis' Qf plus the held-out state's own E and S(E) (--oracle RAY:T; a diagnostic,
            never a basis: what a strain span holding that state would leave).
Usage: qf_candidates.py SNAP BASIS.h5 LEG.h5 OUT_PREFIX NAMES [--oracle RAY:T]"""
import argparse
import os
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # the OpenMP OpenBLAS: one thread, no spin-waiting
os.environ.setdefault("OMP_NUM_THREADS", "1")
import sys
HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "rom"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from rom11_iso_diag import Model, states  # noqa: E402
from rom_basis import fibre_law, fibre_strains, read_rays  # noqa: E402

ap = argparse.ArgumentParser()
for k in ("snap", "basis", "leg", "prefix", "names"):
    ap.add_argument(k)
ap.add_argument("--oracle", default=None)
a = ap.parse_args()
m = Model(a.snap, a.basis, a.leg)
W = m.W
sw = np.sqrt(W)[:, None]
node, coef, L0, EA = m.fib
zf = m.x[node][:, :, 2].mean(axis=1)
zones = [(zf < 54), (zf >= 54) & (zf < 112), (zf >= 112)]
xf = m.x[node][:, :, 0].mean(axis=1)
yf = m.x[node][:, :, 1].mean(axis=1)


def quadrants(zs):
    return [z & (sx * xf >= 0) & (sy * yf >= 0) & ~((sx < 0) & (xf == 0)) & ~((sy < 0) & (yf == 0))
            for z in zs for sx in (1, -1) for sy in (1, -1)]


sectors = quadrants(zones)
cuts = [-np.inf, 27, 54, 83, 112, 139, np.inf]
sectors6 = quadrants([(zf >= lo) & (zf < hi) for lo, hi in zip(cuts[:-1], cuts[1:])])


def orthw(Y, tol=1e-10):
    """W-orthonormal basis of Y's columns (SVD of sqrt(W) Y)."""
    U, s, _ = np.linalg.svd(sw * Y, full_matrices=False)
    return U[:, s > s[0] * tol] / sw


def extend(Q, Y):
    """Q plus Y's columns W-orthogonalised against Q (twice)."""
    for _ in range(2):
        Y = Y - Q @ (Q.T @ (W[:, None] * Y))
    return np.concatenate([Q, orthw(Y, 1e-8)], axis=1)


def split(Q, parts=None):
    return np.concatenate([orthw(Q * z[:, None]) for z in (parts or zones)], axis=1)


X = np.concatenate([r["u"].T for r in read_rays(a.snap) if r["kind"] == "train"], axis=1)
X[m.fixed] = 0.0
fib = (node, coef, L0, EA)
for name in a.names.split(","):
    if name in ("all", "split", "sect"):
        E = fibre_strains(X, m.x, fib)
        Q = orthw(np.concatenate([E, fibre_law(E, True)], axis=1), 1e-12)
        if name != "all":
            Q = split(Q, sectors if name == "sect" else None)
    elif name == "split104":
        Q = split(m.Qf)
    elif name == "sect104":
        assert sum(z.sum() for z in sectors) == W.size  # a partition
        Q = split(m.Qf, sectors)
    elif name == "sect104z6":
        assert sum(z.sum() for z in sectors6) == W.size
        Q = split(m.Qf, sectors6)
    elif name == "lin0":
        n = m.V.shape[1]
        d0 = np.einsum("fa,fai->fi", coef, m.x[node])
        V3 = m.V.reshape(-1, 3, n)
        D0V = np.einsum("fa,fi,fain->fn", coef, d0 / L0[:, None] ** 2, V3[node])
        Q = extend(m.Qf, D0V)
    elif name == "oracle":
        ray, t = a.oracle.split(":")
        u = next(states(a.snap, [ray], [float(t)], m.fixed))[2]
        E = fibre_strains(u[:, None], m.x, fib)
        Q = extend(m.Qf, np.concatenate([E, fibre_law(E, True)], axis=1))
    else:
        sys.exit(f"qf_candidates: unknown candidate {name}")
    with h5py.File(f"{a.prefix}_{name}.h5", "w") as f:
        f["Qf"] = Q
    print(f"qf_candidates: {name}: {Q.shape[1]} modes ({X.shape[1]} training states)")
    sys.stdout.flush()

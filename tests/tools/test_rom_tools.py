#!/usr/bin/python3
"""test_rom_tools.py: the offline tools of the reduced-order leg (tools/rom_basis.py,
tools/rom_nnls.py) on closed forms.

Proves: (1) the consistent Tet10 mass of a straight element totals rho V and its row sums are
rho int N_a dV = -rho V / 20 at the vertices and rho V / 5 at the edge nodes (the quadratic
tetrahedron's closed form); (2) the quarter-turn node maps of a
point cloud with the symmetry map it onto itself and are refused without it; (3) the
Lawson-Hanson NNLS of tools/rom_nnls.py (incremental Cholesky) finds scipy's kept set and weights
with tol 0, stops early with a looser tol, keeps every weight non-negative, and the weights it
records at a larger tolerance are those of a run stopped there; (4) tools/rom_project.py's
M-orthogonal projection reproduces a state in the basis' span (error at round-off, on a
non-orthonormal basis) and leaves a state M-orthogonal to it whole (relative error 1, the tip
error its mean tip displacement); (5) rom_basis.py's segment-split pressure modes are
volume-orthonormal, vanish outside their zone and reproduce each zone's share of a mode;
(8) --v-rays picks the named rays' columns of the training matrix, turned copies included, and
refuses a name that is no training ray.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import rom_basis  # noqa: E402
import rom_nnls  # noqa: E402
import rom_project  # noqa: E402

failed = 0


def expect(cond, what):
    global failed
    print(("ok   " if cond else "FAIL ") + what)
    failed += 0 if cond else 1


def tet10(X4):
    ed = [(0, 1), (1, 2), (0, 2), (0, 3), (1, 3), (2, 3)]
    return np.vstack([X4] + [0.5 * (X4[i] + X4[j]) for i, j in ed])


# (1) mass of one straight Tet10
X4 = np.array([[0, 0, 0], [2.0, 0.1, 0], [0.3, 1.5, 0.2], [0.1, 0.4, 3.0]])
x = tet10(X4)
V = abs(np.linalg.det(np.array([X4[1] - X4[0], X4[2] - X4[0], X4[3] - X4[0]]))) / 6
rho = 1.1e-9
M, vol = rom_basis.mass_matrix(x, np.arange(10)[None, :], rho)
rows = np.asarray(M.sum(axis=1)).ravel()
expect(abs(vol / V - 1) < 1e-13, f"volume {vol:.12g} = {V:.12g}")
expect(abs(M.sum() / (rho * V) - 1) < 1e-13, "mass total = rho V")
expect(np.allclose(rows[:4], -rho * V / 20, rtol=1e-12) and
       np.allclose(rows[4:], rho * V / 5, rtol=1e-12), "row sums -V/20 (vertices), V/5 (edges)")
expect(np.all(np.linalg.eigvalsh(M.toarray()) > 0), "positive definite")

# (2) quarter-turn maps
rng = np.random.default_rng(3)
p = rng.normal(size=(20, 3))
sym = np.vstack([p, p @ np.array([[0, -1, 0], [1, 0, 0], [0, 0, 1.0]]).T,
                 p * [-1, -1, 1], p @ np.array([[0, 1, 0], [-1, 0, 0], [0, 0, 1.0]]).T])
maps = rom_basis.turn_maps(sym)
expect(maps is not None and all(sorted(j) == list(range(len(sym))) for _, j in maps),
       "quarter-turn maps are permutations of a symmetric cloud")
expect(rom_basis.turn_maps(p) is None, "a cloud without the symmetry is refused")
U = rng.normal(size=(3 * len(sym), 2))
T = rom_basis.turn_snapshots(U, maps)
R, j = maps[0]
expect(np.allclose(T[:, 2:4].reshape(-1, 3, 2)[j[5]], R @ U.reshape(-1, 3, 2)[5]),
       "a turned snapshot moves node i's displacement, turned, to its image")

# (3) NNLS (tools/rom_nnls.py): the exact problem gives scipy's active set and weights (its
# Fortran Lawson-Hanson, a Householder QR of the kept columns) to round-off, on wide ECSW-like
# problems (b = A 1, A >= 0: a zero residual) and on tall ones with a residual and zero weights;
# stopped at a tolerance it keeps fewer columns, the residual at or below it, the weights >= 0
from scipy.optimize import nnls  # noqa: E402
for m, n, kind in ((40, 200, "ecsw"), (30, 500, "ecsw"), (60, 30, "tall"), (200, 80, "tall"),
                   (100, 100, "tall")):
    worst_w, same, worst_r = 0.0, True, 0.0
    for trial in range(4):
        if kind == "ecsw":
            A = np.abs(rng.normal(size=(m, n)))
            b = A @ np.ones(n)
        else:
            A = rng.normal(size=(m, n))
            b = rng.normal(size=m)
        w0, r0 = nnls(A, b, maxiter=50 * n)
        w, rel, _ = rom_nnls.nnls_chol(A, b, 0.0)
        same &= set(np.flatnonzero(w0 > 0)) == set(np.flatnonzero(w > 0))
        worst_w = max(worst_w, np.abs(w - w0).max() / np.abs(w0).max())
        worst_r = max(worst_r, abs(rel - r0 / np.linalg.norm(b)))
    # round-off: the weights are O(1), kappa(A_P) of these random problems O(10-100), and the
    # normal equations square it: 1e-10 leaves a margin of 1e3 over what is measured (1e-13)
    expect(same and worst_w < 1e-10 and worst_r < 1e-10,
           f"{m} x {n} {kind}: scipy's kept set, weights within {worst_w:.1e}, residual within "
           f"{worst_r:.1e}")
A = np.abs(rng.normal(size=(40, 200)))
b = A @ np.ones(200)
w, rel, _ = rom_nnls.nnls_chol(A, b, 0.0)
w2, rel2, path = rom_nnls.nnls_chol(A, b, 1e-2, record=(1e-1, 1e-2))
expect(rel2 <= 1e-2 and (w2 > 0).sum() < (w > 0).sum() and np.all(w2 >= 0),
       f"tol 1e-2: residual {rel2:.2e} with {(w2 > 0).sum()} of 200 elements "
       f"(exact: {(w > 0).sum()}), weights >= 0")
w1, rel1, _ = rom_nnls.nnls_chol(A, b, 1e-1)
expect(np.array_equal(path[1e-1][0], w1) and path[1e-1][1] == rel1 and rel1 <= 1e-1,
       f"a recorded tolerance (1e-1: {path[1e-1][2]} kept) = a run stopped there")

# (4) projection onto a span in a mass inner product (SPD, banded, 12 nodes x 3 dofs)
nd = 36
Mp = np.diag(np.linspace(1.0, 3.0, nd)) + 0.2 * (np.eye(nd, k=1) + np.eye(nd, k=-1))
Vb = rng.normal(size=(nd, 5))  # not M-orthonormal: project() solves with the Gram matrix
tipn = np.zeros(nd // 3, bool)
tipn[-3:] = True
Uin = Vb @ rng.normal(size=(5, 2))
e_rel, e_max, e_tip, _ = rom_project.project(Vb, Mp, Uin, tipn)
expect(e_rel.max() < 1e-12 and e_max.max() < 1e-12 * np.abs(Uin).max(),
       f"a state in the span projects exactly (relative {e_rel.max():.1e})")
w = rng.normal(size=nd)
w -= Vb @ np.linalg.solve(Vb.T @ Mp @ Vb, Vb.T @ Mp @ w)  # M-orthogonal to span(Vb)
e_rel, e_max, e_tip, u_max = rom_project.project(Vb, Mp, w[:, None], tipn)
tip_mean = np.linalg.norm(w.reshape(-1, 3)[tipn].mean(axis=0))
expect(abs(e_rel[0] - 1) < 1e-12 and abs(e_tip[0] - tip_mean) < 1e-12 * tip_mean
       and abs(e_max[0] - u_max[0]) < 1e-12 * u_max[0],
       f"a state M-orthogonal to the span is left whole (relative {e_rel[0]:.15f})")

# (5) the pressure modes split at the segments' connectors (--p-split)
ne = 60
xs = np.zeros((4 * ne, 3))
xs[:, 2] = np.repeat(np.linspace(0.0, 59.0, ne), 4)  # element e's vertices all at x3 = e
tets = np.arange(4 * ne).reshape(ne, 4)
tets = np.concatenate([tets, np.repeat(tets[:, :1], 6, axis=1)], axis=1)  # (ne, 10)
vols = rng.uniform(0.5, 2.0, ne)
Pg = rng.normal(size=(ne, 3))
Ps = rom_basis.split_pressure_modes(Pg, xs, tets, vols, [19.0, 42.0])
z = xs[tets[:, 0], 2]
zone = (z >= 19.0).astype(int) + (z >= 42.0)
gram = Ps.T @ (vols[:, None] * Ps)
outside = max(np.abs(Ps[zone != zone[np.argmax(np.abs(Ps[:, k]))], k]).max()
              for k in range(Ps.shape[1]))
share = Pg * (zone == 1)[:, None]  # a mode's middle-zone share lies in the span
res = share - Ps @ (Ps.T @ (vols[:, None] * share))
expect(Ps.shape[1] == 9 and np.abs(gram - np.eye(9)).max() < 1e-12 and outside < 1e-12
       and np.abs(res).max() < 1e-12 * np.abs(share).max(),
       f"split pressure modes: 9 of 3 x 3, volume-orthonormal "
       f"({np.abs(gram - np.eye(9)).max():.1e}),"
       f" zero outside their zone, a zone's share reproduced ({np.abs(res).max():.1e})")

# (6) the fibre strain basis (--fibre-modes): Green strains of chords, the smoothed tension-only
# law, a W-orthonormal basis that holds the training strains and stresses
nf = 40
xf = rng.normal(size=(2 * nf, 3))
node = np.zeros((nf, 20), dtype=np.int64)
coef = np.zeros((nf, 20))
node[:, 0], node[:, 1] = np.arange(0, 2 * nf, 2), np.arange(1, 2 * nf, 2)
coef[:, 0], coef[:, 1] = -1.0, 1.0  # d = x_b - x_a
L0 = np.linalg.norm(xf[1::2] - xf[0::2], axis=1)
EA = rng.uniform(1e3, 3e4, nf)
fib = (node, coef, L0, EA, True)
stretch = rng.uniform(0.98, 1.05, (nf, 3))
U = np.zeros((xf.size, 3))
for k in range(3):  # each fibre's end b moved along the chord: |d| = stretch L0
    u = np.zeros_like(xf)
    u[1::2] = (stretch[:, k] - 1.0)[:, None] * (xf[1::2] - xf[0::2])
    U[:, k] = u.ravel()
E = rom_basis.fibre_strains(U, xf, fib)
dl = rom_basis.FIBRE_SLACK
Sl = rom_basis.fibre_law(np.array([-dl, dl, 2 * dl, -2 * dl, 0.0]))
expect(np.abs(E - 0.5 * (stretch ** 2 - 1)).max() < 1e-12
       and np.abs(Sl - [0.0, dl, 2 * dl, 0.0, dl / 4]).max() < 1e-15,
       f"fibre Green strains of stretched chords ({np.abs(E - 0.5 * (stretch ** 2 - 1)).max():.1e})"
       f" and the tension-only law at its joints")


class _A:
    fibre_modes, f_split = 6, None


Qf = rom_basis.fibre_basis(_A, U, None, xf, fib)
W = EA * L0
St = rom_basis.fibre_law(E)
res = np.concatenate([E, St], 1)
res = res - Qf @ (Qf.T @ (W[:, None] * res))
expect(Qf.shape[1] == 6 and np.abs(Qf.T @ (W[:, None] * Qf) - np.eye(6)).max() < 1e-10
       and np.abs(res).max() < 1e-10 * np.abs(E).max(),
       f"fibre strain basis: W-orthonormal, training strains and stresses reproduced "
       f"({np.abs(res).max():.1e})")
zf = xf[node][:, :, 2].mean(axis=1)  # the zone's measure: the host nodes' mean x3
_A.f_split = [float(np.median(zf))]
Qs = rom_basis.fibre_basis(_A, U, None, xf, fib)
side = zf >= _A.f_split[0]
mixed_zone = max(min(np.abs(Qs[side, k]).max(), np.abs(Qs[~side, k]).max())
                 for k in range(Qs.shape[1]))
res = np.concatenate([E, St], 1)
res = res - Qs @ (Qs.T @ (W[:, None] * res))
expect(Qs.shape[1] == 12 and np.abs(Qs.T @ (W[:, None] * Qs) - np.eye(12)).max() < 1e-10
       and mixed_zone < 1e-12 and np.abs(res).max() < 1e-10 * np.abs(E).max(),
       f"split fibre strain modes: 12 of 2 x 6, W-orthonormal, each in one zone "
       f"({mixed_zone:.1e}), the training fields reproduced ({np.abs(res).max():.1e})")

# (7) --fibre-vib: the fibre strain increments of vibration modes at a loaded state join Qf,
# W-orthonormal; an increment is the derivative of the fibres' Green strains along the mode
# (central differences), and a mode parallel to one already added adds nothing
phi = rng.normal(size=xf.size)
u0 = U[:, 1]
Qv = rom_basis.fibre_vib_enrich(Qf, [(u0, phi), (u0, 2.0 * phi)], xf, fib)
h = 1e-6
dE = (rom_basis.fibre_strains((u0 + h * phi)[:, None], xf, fib)[:, 0]
      - rom_basis.fibre_strains((u0 - h * phi)[:, None], xf, fib)[:, 0]) / (2 * h)
res = dE - Qv @ (Qv.T @ (W * dE))
resf = dE - Qf @ (Qf.T @ (W * dE))
expect(Qv.shape[1] == 7 and np.abs(Qv.T @ (W[:, None] * Qv) - np.eye(7)).max() < 1e-10
       and np.abs(res).max() < 1e-8 * np.abs(dE).max()
       and np.abs(resf).max() > 1e-3 * np.abs(dE).max(),
       f"--fibre-vib: one increment added of two parallel modes, W-orthonormal, the strains' "
       f"derivative along the mode in the span ({np.abs(res).max() / np.abs(dE).max():.1e}; "
       f"outside Qf alone: {np.abs(resf).max() / np.abs(dE).max():.1e})")
# (8) --v-rays: the columns of the named rays in X's layout (rays in file order, the block of
# FE states repeated once per quarter turn)
train = [dict(name="A", u=np.zeros((4, 3))), dict(name="B", u=np.zeros((2, 3))),
         dict(name="C", u=np.zeros((3, 3)))]
cols = rom_basis.ray_columns(train, ["C", "A"], 2)
want = np.array([1, 1, 1, 1, 0, 0, 1, 1, 1] * 2, dtype=bool)
expect(cols.shape == want.shape and (cols == want).all(),
       "--v-rays: the named rays' states in each turned block, the others left out")
try:
    rom_basis.ray_columns(train, ["A", "T_H4"], 1)
    refused = ""
except SystemExit as e:
    refused = str(e)
expect("T_H4" in refused and "not a training ray" in refused and "\n" not in refused,
       f"--v-rays: a name that is no training ray refused in one line ({refused[:60]})")
print(f"{failed} failed")
sys.exit(1 if failed else 0)

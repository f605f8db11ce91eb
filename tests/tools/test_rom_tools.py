#!/usr/bin/python3
"""test_rom_tools.py: the offline tools of the reduced-order leg (tools/rom_basis.py,
tools/rom_ecsw.py) on closed forms.

Proves: (1) the consistent Tet10 mass of a straight element totals rho V and its row sums are
rho int N_a dV = -rho V / 20 at the vertices and rho V / 5 at the edge nodes (the quadratic
tetrahedron's closed form); (2) the quarter-turn node maps of a
point cloud with the symmetry map it onto itself and are refused without it; (3) the
tolerance-stopped Lawson-Hanson NNLS reaches scipy's NNLS residual with tol 0, stops early
with a looser tol, and keeps every weight non-negative.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import rom_basis  # noqa: E402
import rom_ecsw  # noqa: E402

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

# (3) NNLS stopped at a tolerance
from scipy.optimize import nnls  # noqa: E402
A = np.abs(rng.normal(size=(40, 200)))
b = A @ np.ones(200)
w0, r0 = nnls(A, b)
w, rel = rom_ecsw.nnls_tol(A, b, 0.0)
expect(abs(rel - r0 / np.linalg.norm(b)) < 1e-8, f"tol 0: residual {rel:.2e} = scipy's "
       f"{r0 / np.linalg.norm(b):.2e}")
w2, rel2 = rom_ecsw.nnls_tol(A, b, 1e-2)
expect(rel2 <= 1e-2 and (w2 > 0).sum() <= (w > 0).sum() and np.all(w2 >= 0),
       f"tol 1e-2: residual {rel2:.2e} with {(w2 > 0).sum()} of 200 elements, weights >= 0")
print(f"{failed} failed")
sys.exit(1 if failed else 0)

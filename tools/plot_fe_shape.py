#!/usr/bin/python3
"""plot_fe_shape.py: the FE's deformed actuator beside its bend curve, from the files of one
`crawlsim bend --model fe` run.

Usage:
  /usr/bin/python3 tools/plot_fe_shape.py BEND.h5 [--vtu BEND.vtu[.gz]] [-o OUT.png]
                                          [--all-surfaces] [--elev DEG] [--azim DEG]

BEND.h5 is the bend file (/pressure [M] MPa, /angle_total_deg [M], /angle_deg [M,3]; the
contract of docs/design.md); the run writes the deformed mesh at its last converged state beside
it (FILE.h5 -> FILE.vtu, tools/cmd_bend_fe.c): ASCII VTK XML, quadratic tetrahedra (VTK type
24, ten nodes: corners 0-3, then the edge midpoints 01, 12, 02, 03, 13, 23), Points at the
deformed positions X + u in mm and the point data `displacement` u in mm (read gzip-compressed
when the name ends in .gz; without --vtu, BEND.vtu or else BEND.vtu.gz).

Draws one PNG: (a) the total bending angle against pressure with the state the mesh shows
marked (the last row); (b) the deformed actuator in 3D: the mesh's boundary faces (faces of one
tetrahedron only), each split into four flat triangles through its edge midpoints so the
quadratic elements' curvature shows, coloured by |u|. By default only the outer skin is drawn:
the connected closed surface of boundary faces that holds the undeformed point farthest from the
mesh's centre; the sealed chambers' walls, separate surfaces inside it, are left out
(--all-surfaces draws them too). Needs python3-scipy (connected components).

Runs with Debian's Python (python3-matplotlib, python3-h5py, python3-numpy), Agg backend.
Exit status: 0 on success, 1 on a missing/unreadable file or a mesh it cannot read (one line on
stderr), 2 on bad usage.
"""

import argparse
import gzip
import os
import sys
import xml.etree.ElementTree as ET

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from mpl_toolkits.mplot3d.art3d import Poly3DCollection  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # plot_common.py, from any cwd
from plot_common import InputError, default_out, load_or_fail, save_or_fail  # noqa: E402
from plot_bend import load_bend  # noqa: E402

PROG = "plot_fe_shape"
VTK_QUADRATIC_TETRA = 24
VTK_TETRA = 10
# the faces of a tetrahedron (corner indices) and, for the quadratic one, the midpoint node of
# each edge (VTK's order: 01, 12, 02, 03, 13, 23 -> nodes 4..9)
TET_FACES = ((0, 1, 2), (0, 1, 3), (0, 2, 3), (1, 2, 3))
EDGE_MID = {(0, 1): 4, (1, 2): 5, (0, 2): 6, (0, 3): 7, (1, 3): 8, (2, 3): 9}


def _array(piece, path, where, name=None):
    """The text of one DataArray (the first, or the one called `name`) of a VTU piece's section
    `where` (Points, Cells, PointData) as a flat float array."""
    sec = piece.find(where)
    for da in ([] if sec is None else sec.iter("DataArray")):
        if name is None or da.get("Name") == name:
            if da.get("format", "ascii") != "ascii":
                raise InputError(f"{path}: DataArray {name or where} is not ASCII")
            try:
                return np.array((da.text or "").split(), dtype=float)
            except ValueError:
                raise InputError(f"{path}: DataArray {name or where} holds a non-number") from None
    raise InputError(f"{path}: no DataArray {name or where}")


def load_vtu(path):
    """Deformed points [N,3] mm, displacement [N,3] mm (zeros when absent) and the cells [C,k]
    (k = 10 for quadratic tetrahedra, 4 for linear ones)."""
    try:
        if path.endswith(".gz"):  # a committed mesh is kept compressed (docs/bench)
            with gzip.open(path, "rb") as f:
                root = ET.parse(f).getroot()
        else:
            root = ET.parse(path).getroot()
    except OSError as e:
        raise InputError(f"{path}: cannot open ({e.strerror or e})") from None
    except ET.ParseError as e:
        raise InputError(f"{path}: not XML ({e})") from None
    piece = root.find("UnstructuredGrid/Piece")
    if piece is None:
        raise InputError(f"{path}: not a VTK UnstructuredGrid file")
    n = int(piece.get("NumberOfPoints", "0"))
    x = _array(piece, path, "Points")
    if n < 4 or x.size != 3 * n:
        raise InputError(f"{path}: {x.size} point coordinates for {n} points")
    x = x.reshape(n, 3)
    conn = _array(piece, path, "Cells", "connectivity").astype(int)
    offs = _array(piece, path, "Cells", "offsets").astype(int)
    types = _array(piece, path, "Cells", "types").astype(int)
    if len(types) == 0 or len(offs) != len(types):
        raise InputError(f"{path}: {len(offs)} offsets for {len(types)} cells")
    if np.all(types == VTK_QUADRATIC_TETRA):
        k = 10
    elif np.all(types == VTK_TETRA):
        k = 4
    else:
        raise InputError(f"{path}: cells other than (quadratic) tetrahedra "
                         f"(types {sorted(set(types))})")
    if not np.array_equal(offs, k * np.arange(1, len(types) + 1)) or conn.size != k * len(types):
        raise InputError(f"{path}: the connectivity is not {k} nodes a cell")
    cells = conn.reshape(-1, k)
    if cells.min() < 0 or cells.max() >= n:
        raise InputError(f"{path}: a cell names a point outside 0..{n - 1}")
    try:
        u = _array(piece, path, "PointData", "displacement").reshape(n, 3)
    except (InputError, ValueError):
        u = np.zeros_like(x)
    return {"path": path, "x": x, "u": u, "cells": cells}


def boundary_faces(cells):
    """The faces that belong to one cell only: [F,3] corner nodes and [F,6] the nodes of each
    face's corners and edge midpoints (corner i, j, k, mid ij, jk, ik; -1 for linear cells)."""
    tri, full = [], []
    for a, b, c in TET_FACES:
        tri.append(cells[:, [a, b, c]])
        if cells.shape[1] == 10:
            full.append(cells[:, [a, b, c, EDGE_MID[(a, b)], EDGE_MID[(b, c)], EDGE_MID[(a, c)]]])
        else:
            none = -np.ones((len(cells), 3), int)
            full.append(np.concatenate([cells[:, [a, b, c]], none], axis=1))
    tri, full = np.concatenate(tri), np.concatenate(full)
    key = np.sort(tri, axis=1)
    _, inv, count = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    once = count[inv.reshape(-1)] == 1
    return tri[once], full[once]


def outer_skin(x, tri):
    """Which boundary faces are the outer skin: the boundary splits into closed surfaces, the skin
    (with the end caps) and one wall per sealed chamber inside it; the skin is the one that holds
    the point farthest from the mesh's centre (the chambers lie inside the skin). A mesh whose
    chambers open through a cap is one surface, drawn whole."""
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    n = x.shape[0]
    rows = np.concatenate([tri[:, 0], tri[:, 1], tri[:, 2]])
    cols = np.concatenate([tri[:, 1], tri[:, 2], tri[:, 0]])
    graph = coo_matrix((np.ones(rows.size), (rows, cols)), shape=(n, n))
    _, label = connected_components(graph, directed=False)
    used = np.unique(tri)
    far = used[np.argmax(np.linalg.norm(x[used] - x[used].mean(axis=0), axis=1))]
    return label[tri[:, 0]] == label[far]


def surface_triangles(mesh, all_surfaces):
    """The triangles to draw [T,3,3] (mm, deformed) and |u| at each [T] (mm)."""
    x, u = mesh["x"], mesh["u"]
    tri, full = boundary_faces(mesh["cells"])
    if not all_surfaces:
        keep = outer_skin(x - u, tri)
        if keep.any():  # a mesh with no recognisable skin is drawn whole
            tri, full = tri[keep], full[keep]
    if full[0, 3] >= 0:
        # four flat triangles a quadratic face: (i, ij, ik), (j, jk, ij), (k, ik, jk), (ij, jk, ik)
        sub = np.concatenate([full[:, [0, 3, 5]], full[:, [1, 4, 3]], full[:, [2, 5, 4]],
                              full[:, [3, 4, 5]]])
    else:
        sub = tri
    mag = np.linalg.norm(u, axis=1)
    return x[sub], mag[sub].mean(axis=1), len(tri)


def plot_shape(bend, mesh, out, all_surfaces, elev, azim):
    verts, mag, nfaces = surface_triangles(mesh, all_surfaces)
    fig = plt.figure(figsize=(12, 5.4), constrained_layout=True)
    gs = fig.add_gridspec(1, 2, width_ratios=(1, 1.15))
    ax = fig.add_subplot(gs[0])
    order = np.argsort(bend["p"], kind="stable")
    p, tot = bend["p"][order], bend["total"][order]
    ax.plot(p, tot, "k-o", ms=3.5, lw=1.6, label="FE, total bend")
    last = len(bend["p"]) - 1  # the mesh is the sweep's last converged state: its last row
    ax.plot([bend["p"][last]], [bend["total"][last]], "r*", ms=16, mec="k",
            label=f"shape on the right: p = {bend['p'][last]:.3g} MPa, "
                  f"{bend['total'][last]:.1f} deg")
    ax.set_xlabel("pressure p (MPa)")
    ax.set_ylabel("total bending angle \u0398 (deg)")
    ax.set_title("(a) bend curve")
    ax.grid(True, alpha=0.3)
    ax.legend(loc="upper left", fontsize=9)

    ax3 = fig.add_subplot(gs[1], projection="3d")
    norm = plt.Normalize(vmin=0.0, vmax=max(float(mag.max()), 1e-12))
    cmap = plt.get_cmap("viridis")
    coll = Poly3DCollection(verts, facecolors=cmap(norm(mag)), edgecolors="none", linewidths=0)
    ax3.add_collection3d(coll)
    pts = verts.reshape(-1, 3)
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    mid, half = 0.5 * (lo + hi), 0.5 * float((hi - lo).max())
    ax3.set_xlim(mid[0] - half, mid[0] + half)
    ax3.set_ylim(mid[1] - half, mid[1] + half)
    ax3.set_zlim(mid[2] - half, mid[2] + half)
    ax3.set_box_aspect((1, 1, 1))
    ax3.view_init(elev=elev, azim=azim)
    ax3.set_xlabel("x (mm)")
    ax3.set_ylabel("y (mm)")
    ax3.set_zlabel("z (mm)")
    what = "every boundary face" if all_surfaces else "outer skin"
    ax3.set_title(f"(b) deformed FE mesh at p = {bend['p'][last]:.3g} MPa ({what}, {nfaces} faces)",
                  fontsize=10)
    sm = plt.cm.ScalarMappable(norm=norm, cmap=cmap)
    fig.colorbar(sm, ax=ax3, shrink=0.7, label="|displacement| (mm)")
    name = bend["actuator"] or os.path.basename(bend["path"])
    fig.suptitle(f"FE bend of {name}: the curve and the deformed shape "
                 f"({os.path.basename(mesh['path'])})", fontsize=11)
    fig.savefig(out, dpi=100)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description="The FE's deformed shape beside its bend curve.")
    ap.add_argument("bend", metavar="BEND.h5", help="output of `crawlsim bend --model fe`")
    ap.add_argument("--vtu", metavar="BEND.vtu",
                    help="the deformed mesh (default: BEND.h5's stem + .vtu, or .vtu.gz)")
    ap.add_argument("-o", "--output", metavar="OUT.png",
                    help="output PNG (default: BEND_shape.png)")
    ap.add_argument("--all-surfaces", action="store_true", help="draw the chambers' walls too")
    ap.add_argument("--elev", type=float, default=20.0, help="view elevation, deg (default 20)")
    ap.add_argument("--azim", type=float, default=-60.0, help="view azimuth, deg (default -60)")
    args = ap.parse_args(argv)
    vtu = args.vtu or os.path.splitext(args.bend)[0] + ".vtu"
    if not args.vtu and not os.path.exists(vtu) and os.path.exists(vtu + ".gz"):
        vtu += ".gz"
    bend = load_or_fail(PROG, load_bend, args.bend)
    mesh = load_or_fail(PROG, load_vtu, vtu)
    out = args.output or default_out(args.bend, "_shape.png")
    save_or_fail(PROG, out, lambda: plot_shape(bend, mesh, out, args.all_surfaces, args.elev,
                                               args.azim))
    return 0


if __name__ == "__main__":
    sys.exit(main())

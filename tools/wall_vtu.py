#!/usr/bin/python3
"""wall_vtu.py: the free surfaces of a deformed actuator from the VTU that `crawlsim bend --model
fe` writes beside its HDF5 (fem_output.c: ASCII, deformed points and displacement, Tet10).

What it measures (the field behind the one-number report of fem_wall.c, issue 13's b = 3
stalls):
- on every vented chamber's wall (chambers given by --vented, of every segment): the principal
  in-surface stretches lam_c <= lam_t at the six points of each Tri6 face (the surface's own
  deformation gradient, as fem_wall.c), the plane-strain-equivalent stretch lam_eq = lam_c
  sqrt(lam_t), and the area of wall past the crease onset lam_eq < 0.65 (Hong, Zhao & Suo 2009);
  where on the chamber (segment, angle around the chamber axis, z) and along which direction
  (axial / hoop) the wall is compressed;
- in the volume: the pointwise J = det F at each Tet10's four quadrature points; the most
  distorted elements, and for each its distance to the nearest vented-wall point past the onset
  and whether it owns a vented-wall face.
Chamber faces are found from the reference geometry (fem_mesh.c's .geo: chamber j at (sx b,
sy b), sx = (1, 1, -1, -1), sy = (1, -1, -1, 1), radius r1, from z0 + c to z0 + S - c).

Usage: /usr/bin/python3 tools/wall_vtu.py FILE.vtu --b 3 --r1 2 [--a 7.5 --c 5 --S 50 --LS 6]
       [--vented 3,4] [--worst 10]
"""
import argparse
import re
import sys

import numpy as np

CREASE = 0.65  # Hong, Zhao & Suo 2009, plane strain, neo-Hookean
SX = (1, 1, -1, -1)
SY = (1, -1, -1, 1)
# Tet10 (VTK) faces as (corner, corner, corner) with their edge nodes (c0-c1, c1-c2, c2-c0)
EDGE = {(0, 1): 4, (1, 2): 5, (0, 2): 6, (0, 3): 7, (1, 3): 8, (2, 3): 9}
FACES = [(0, 1, 2), (0, 1, 3), (1, 2, 3), (0, 2, 3)]
TA, TB = 0.445948490915965, 0.091576213509771
TRI_PTS = [(TA, TA), (1 - 2 * TA, TA), (TA, 1 - 2 * TA), (TB, TB), (1 - 2 * TB, TB),
           (TB, 1 - 2 * TB)]


def edge(a, b):
    return EDGE[(min(a, b), max(a, b))]


def read_vtu(path):
    text = open(path).read()

    def array(name):
        m = re.search(r'Name="%s"[^>]*>(.*?)</DataArray>' % name, text, re.S)
        return np.array(m.group(1).split(), dtype=float)
    m = re.search(r"<Points><DataArray[^>]*>(.*?)</DataArray>", text, re.S)
    x = np.array(m.group(1).split(), dtype=float).reshape(-1, 3)
    u = array("displacement").reshape(-1, 3)
    tet = array("connectivity").astype(int).reshape(-1, 10)
    return x - u, x, tet


def tri6_deriv(s, t):
    l0 = 1 - s - t
    return np.array([[-(4 * l0 - 1), -(4 * l0 - 1)], [4 * s - 1, 0], [0, 4 * t - 1],
                     [4 * (l0 - s), -4 * s], [4 * t, 4 * s], [-4 * t, 4 * (l0 - t)]])


def tri6_shape(s, t):
    l0 = 1 - s - t
    return np.array([l0 * (2 * l0 - 1), s * (2 * s - 1), t * (2 * t - 1), 4 * l0 * s, 4 * s * t,
                     4 * t * l0])


def tet10_deriv(l1, l2, l3):
    """dN/d(l1, l2, l3) (10 x 3), l0 = 1 - l1 - l2 - l3"""
    l = [1 - l1 - l2 - l3, l1, l2, l3]
    dl = np.array([[-1, -1, -1], [1, 0, 0], [0, 1, 0], [0, 0, 1]], dtype=float)
    dN = np.zeros((10, 3))
    for i in range(4):
        dN[i] = (4 * l[i] - 1) * dl[i]
    for (i, j), k in EDGE.items():
        dN[k] = 4 * (l[i] * dl[j] + l[j] * dl[i])
    return dN


def boundary_faces(tet):
    count = {}
    for e, t in enumerate(tet):
        for f in FACES:
            key = tuple(sorted(t[list(f)]))
            count.setdefault(key, []).append((e, f))
    out = []
    for key, lst in count.items():
        if len(lst) == 1:
            e, f = lst[0]
            t = tet[e]
            c = [t[f[0]], t[f[1]], t[f[2]]]
            mids = [t[edge(f[0], f[1])], t[edge(f[1], f[2])], t[edge(f[2], f[0])]]
            out.append((e, np.array(c + mids)))
    return out


def chamber_of(X, o):
    """(segment, chamber 1..4, "wall" or "cap") of a reference boundary face whose six nodes lie
    within a chamber's closed cylinder (no material there, so such a face bounds the chamber;
    straightened edge nodes of csf_meshFixInverted sit inside the circle, up to 0.25 r1)"""
    z0 = 0.0
    tol = 1e-3 + 0.01 * o.r1
    for s in range(3):
        zlo, zhi = z0 + o.c, z0 + o.S - o.c
        if X[:, 2].min() >= zlo - tol and X[:, 2].max() <= zhi + tol:
            for j in range(4):
                rho = np.hypot(X[:, 0] - SX[j] * o.b, X[:, 1] - SY[j] * o.b)
                if np.all(rho < o.r1 + tol):
                    cap = (np.all(np.abs(X[:, 2] - zlo) < tol) or
                           np.all(np.abs(X[:, 2] - zhi) < tol))
                    return s, j + 1, "cap" if cap else "wall"
        z0 += o.S + o.LS
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("vtu")
    ap.add_argument("--a", type=float, default=7.5)
    ap.add_argument("--b", type=float, default=4.0)
    ap.add_argument("--c", type=float, default=5.0)
    ap.add_argument("--r1", type=float, default=2.0)
    ap.add_argument("--S", type=float, default=50.0)
    ap.add_argument("--LS", type=float, default=6.0)
    ap.add_argument("--vented", default="3,4")
    ap.add_argument("--worst", type=int, default=10)
    o = ap.parse_args()
    vented = [int(v) for v in o.vented.split(",")]
    X, x, tet = read_vtu(o.vtu)
    print(f"{o.vtu}: {len(X)} nodes, {len(tet)} Tet10")

    # pointwise J at the four quadrature points of every element
    qa, qb = 0.5854101966249685, 0.1381966011250105
    qpts = [(qb, qb, qb), (qa, qb, qb), (qb, qa, qb), (qb, qb, qa)]
    dNq = np.array([tet10_deriv(*q) for q in qpts])  # (4, 10, 3)
    Xe, xe = X[tet], x[tet]  # (ne, 10, 3)
    jmin = np.full(len(tet), np.inf)
    for q in range(4):
        Jr = np.einsum("eai,aj->eij", Xe, dNq[q])
        Jd = np.einsum("eai,aj->eij", xe, dNq[q])
        jmin = np.minimum(jmin, np.linalg.det(Jd) / np.linalg.det(Jr))

    # the vented chambers' faces: stretches at the six points
    rows = []  # (lam_eq, lam_c, lam_t, X(3), dir(3), seg, chamber, kind, tet, area)
    for e, fn in boundary_faces(tet):
        hit = chamber_of(X[fn], o)
        if not hit or hit[1] not in vented:
            continue
        s, j, kind = hit
        for (ps, pt) in TRI_PTS:
            dN = tri6_deriv(ps, pt)
            A = X[fn].T @ dN
            a = x[fn].T @ dN
            G, g = A.T @ A, a.T @ a
            mu, V = np.linalg.eig(np.linalg.solve(G, g))
            order = np.argsort(mu.real)
            mu, V = mu.real[order], V.real[:, order]
            lc, lt = np.sqrt(max(mu[0], 0)), np.sqrt(mu[1])
            d = A @ V[:, 0]
            d /= np.linalg.norm(d)
            area = 0.5 * np.sqrt(np.linalg.det(G)) / 6
            rows.append((lc * np.sqrt(lt), lc, lt, *(tri6_shape(ps, pt) @ X[fn]), *d, s, j,
                         kind, e, area))
    if not rows:
        print("no vented chamber faces found (check --b --r1 --c --S --LS)")
        return 1
    leq = np.array([r[0] for r in rows])
    P = np.array([r[3:6] for r in rows])
    D = np.array([r[6:9] for r in rows])
    area = np.array([r[13] for r in rows])
    k = int(np.argmin(leq))
    r = rows[k]
    print(f"vented walls: {len(rows)} points; smallest lam_eq {r[0]:.3f} (lam_c {r[1]:.3f}, "
          f"lam_t {r[2]:.3f}) at ({r[3]:.2f}, {r[4]:.2f}, {r[5]:.2f}) mm, II{r[9] + 1} chamber "
          f"{r[10]} {r[11]}, compressed along ({r[6]:.2f}, {r[7]:.2f}, {r[8]:.2f})")
    for s in range(3):
        for j in vented:
            sel = np.array([(rr[9] == s and rr[10] == j) for rr in rows])
            if not sel.any():
                continue
            past = sel & (leq < CREASE)
            tot = area[sel].sum()
            # angle around the chamber axis (deg; 0 = +x) and axial / hoop share of compression
            th = np.degrees(np.arctan2(P[past, 1] - SY[j - 1] * o.b, P[past, 0] - SX[j - 1] * o.b))
            ax = np.abs(D[past, 2])
            desc = ""
            if past.any():
                desc = (f"; past it at angles {th.min():.0f}..{th.max():.0f} deg around the axis,"
                        f" z {P[past, 2].min():.1f}..{P[past, 2].max():.1f} mm, compression "
                        f"axial (|dir_z| > 0.7) at {np.mean(ax > 0.7) * 100:.0f} % of those "
                        f"points, hoop (< 0.3) at {np.mean(ax < 0.3) * 100:.0f} %")
            print(f"  II{s + 1} chamber {j}: min lam_eq {leq[sel].min():.3f}, "
                  f"{area[past].sum() / tot * 100:.1f} % of its wall area past {CREASE}{desc}")
    # the most distorted elements against the creased wall
    order = np.argsort(jmin)[:o.worst]
    owners = {rr[12] for rr in rows}
    pastP = P[leq < CREASE]
    print(f"most distorted elements (pointwise J at the quadrature points):")
    for e in order:
        c = X[tet[e][:4]].mean(axis=0)
        dist = np.min(np.linalg.norm(pastP - c, axis=1)) if len(pastP) else float("nan")
        near = np.argmin(np.linalg.norm(P - c, axis=1))
        print(f"  tet {e}: J {jmin[e]:.3f} at ({c[0]:.2f}, {c[1]:.2f}, {c[2]:.2f}) mm; "
              f"{'owns a vented-wall face; ' if e in owners else ''}nearest vented-wall point "
              f"{np.linalg.norm(P[near] - c):.2f} mm (lam_eq {leq[near]:.3f}), nearest point "
              f"past the onset {dist:.2f} mm")
    print(f"elements with J < 0.6: {int(np.sum(jmin < 0.6))}, < 0.5: {int(np.sum(jmin < 0.5))}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

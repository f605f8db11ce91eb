#!/usr/bin/python3
"""Where the corotated representation over-stretches fibres and dilates elements (rom15;
rom14 Next 3).

    bad_fibres.py SNAP BASIS.h5 LEG.h5 ROD.h5 LOCAL.h5 [--r 12 --k 176] [--cases T_R:1,T_H4:1]
        [--train 8] [--emin 0.1] [--npy ITERATES.npy]

For each named held-out FE state and the last load factor of the first TRAIN training rays: the state's
representation on the manifold (corot_rep.py's: chain strains on R modes, local shape on K
modes), its fibres' Green strains against the FE state's, and the fibres with E above EMIN (the
FE's largest at T_R t = 1 is 0.058): their number, the fibre energy they carry, where they sit
(the host nodes' mean position: z, the angle about the axis, the radius; the slab index of
corot.Slabs), and the same for the elements' P0 bulk energy kappa V_e theta_e^2 / 2 (the 10
worst elements' z, angle, radius, share of the total). With --npy the same for the last iterate
of a Newton run instead of the representation. Units mm, N mm, degrees.
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..",
                                "rom14_2026-12-07g"))
import corot  # noqa: E402,F401  (first: it sets the one-thread BLAS before numpy loads)
import numpy as np  # noqa: E402
from corot import rod_strains, train_states  # noqa: E402
from corot_newton import load_manifold, manifold_args  # noqa: E402
from rom11_iso_diag import states, volume_grads  # noqa: E402
from romlock_span_energy import psi  # noqa: E402


def represent_z(m, mf, u):
    """corot_rep.py's representation of the state u on the manifold mf: its chain strains on
    the strain modes, its local shape in those frames M-projected on the local modes"""
    s = rod_strains(*mf.sl.fit(u), mf.sl.c0).ravel()
    z = np.concatenate([mf.Vs.T @ s, np.zeros(mf.k)])
    ul = mf.sl.local(u, mf.fld(z[:mf.r]))
    z[mf.r:] = np.linalg.lstsq(mf.Vl.T @ (m.M @ mf.Vl), mf.Vl.T @ (m.M @ ul), rcond=None)[0]
    return z


def represent(m, mf, u):
    return mf.u(represent_z(m, mf, u))


def where(xyz):
    ang = np.degrees(np.arctan2(xyz[:, 1], xyz[:, 0]))
    rad = np.hypot(xyz[:, 0], xyz[:, 1])
    return xyz[:, 2], ang, rad


def report(m, mf, lab, u, w, emin, fpos, epos):
    node, coef, L0, EA = m.fib
    Eu = m.fibre_strain(u)[0]
    Ew = m.fibre_strain(w)[0]
    en = EA * L0 * psi(Ew)
    bad = np.flatnonzero(Ew > emin)
    print(f"{lab}: fibres: largest E {Ew.max():.3f} (FE {Eu.max():.3f}); {bad.size} above "
          f"{emin:g} carry {en[bad].sum():.1f} of {en.sum():.1f} N mm (FE state's total "
          f"{(EA * L0 * psi(Eu)).sum():.1f})")
    if bad.size:
        z, ang, rad = where(fpos[bad])
        sid = mf.sl.sid[node[bad, 0]]
        print(f"    bad fibres: z {z.min():.1f} .. {z.max():.1f} mm (slabs "
              f"{np.unique(sid).tolist()[:12]}), angle {ang.min():.0f} .. {ang.max():.0f} deg, "
              f"radius {rad.min():.2f} .. {rad.max():.2f} mm; FE strains there "
              f"{Eu[bad].min():.3f} .. {Eu[bad].max():.3f}")
        top = bad[np.argsort(Ew[bad])[::-1][:6]]
        for f in top:
            zz, aa, rr = where(fpos[f:f + 1])
            print(f"      fibre {f}: E {Ew[f]:.3f} (FE {Eu[f]:.3f}), z {zz[0]:.2f}, angle "
                  f"{aa[0]:.0f}, radius {rr[0]:.2f}, slab {mf.sl.sid[node[f, 0]]}")
    v, _ = volume_grads(w, m.tet, m.dNdX, m.wq)
    th = v / m.Ve - 1
    eb = 0.5 * m.kappa * m.Ve * th ** 2
    order = np.argsort(eb)[::-1]
    z, ang, rad = where(epos[order[:10]])
    print(f"    P0 bulk {eb.sum():.1f} N mm; the 10 worst elements {eb[order[:10]].sum():.1f}, "
          f"the worst 1 % ({len(eb) // 100}) {eb[order[:len(eb) // 100]].sum():.1f}; worst: "
          + "; ".join(f"z {a:.1f} ang {b:.0f} r {c:.2f} th {th[e]:+.4f}"
                      for a, b, c, e in zip(z[:5], ang[:5], rad[:5], order[:5])))
    zb = np.histogram(epos[:, 2], bins=np.arange(0, 170, 10), weights=eb)[0]
    print("    P0 bulk per 10 mm of z: " + " ".join(f"{v:.0f}" for v in zb))


def main():
    ap = manifold_args([])
    ap.add_argument("--cases", default="T_R:1,T_H4:1")
    ap.add_argument("--train", type=int, default=8)
    ap.add_argument("--emin", type=float, default=0.1)
    ap.add_argument("--npy", default=None,
                    help="instead of the representation: the last iterate of this corot_newton.py "
                    "--save file (the first case's run)")
    a = ap.parse_args()
    m, mf = load_manifold(a)
    node = m.fib[0]
    fpos = m.x[node].mean(axis=1)
    epos = m.x[m.tet[:, :4]].mean(axis=1)
    for case in a.cases.split(","):
        ray, t = case.split(":")
        (name, tt, u, p, _, _), = list(states(a.snap, [ray], [float(t)], m.fixed))
        if a.npy:
            Z = np.load(a.npy)
            report(m, mf, f"{name} t {tt:g}, iterate {len(Z) - 1} of {os.path.basename(a.npy)}",
                   u, mf.u(Z[-1]), a.emin, fpos, epos)
            return
        report(m, mf, f"{name} t {tt:g}", u, represent(m, mf, u), a.emin, fpos, epos)
    # every fourth training state: each ray's last load factor (t = 1), the first TRAIN rays
    for i, u in enumerate(train_states(a.snap, m.fixed)):
        if i >= 4 * a.train:
            break
        if i % 4 == 3:
            report(m, mf, f"training state {i}", u, represent(m, mf, u), a.emin, fpos, epos)


if __name__ == "__main__":
    main()

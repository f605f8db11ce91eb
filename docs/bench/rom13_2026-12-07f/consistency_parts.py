#!/usr/bin/python3
"""Which part of the mixed fibre field makes the reduced residual at a held-out FE state (rom13;
rom12's consistency.py split). At the FE state u the FE's fibre forces are D(u)^T W S(E(u))
(S the tension-only law, W = EA L0); the mixed field (fem/fem_rom_fibre.h) replaces S(E) by
S* = Pi S(Ebar), Ebar = Pi E, Pi = Q G^-1 Q^T W the W-orthogonal projection onto span(Qf).
Residual |V^T (f_dev + G^T p + f_fib + f_chambers)| / |V^T f_chambers| (FE pressure; best of
span(P)) for the fibre stress
  S(E)        the FE's (the verification),
  S(Ebar)     the strain projection through the law, no stress projection,
  Pi S(E)     the stress projection of the FE's stress, no strain projection,
  Pi S(Ebar)  the mixed field (the checked model),
and the split of the last: (DV)^T W (Pi S(E) - S(E)) (the stress projection's error seen by
the span's strain rates DV) + (DV)^T W Pi (S(Ebar) - S(E)) (the strain projection's, through
the law). Also the taut/slack bookkeeping: fibres slack in the FE (E < -slack) whose Ebar
puts them in tension, and the W-norm of S(Ebar) - S(E) on them.
Usage: consistency_parts.py SNAP BASIS.h5 LEG.h5 RAY:T[,RAY:T...] [MF] [QF.h5]"""
import os
os.environ.setdefault("OPENBLAS_NUM_THREADS", "1")  # the OpenMP OpenBLAS: one thread, no spin-waiting
os.environ.setdefault("OMP_NUM_THREADS", "1")
import sys
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "rom"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "tools"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402
from rom11_energy import Energy, dpsi  # noqa: E402
from rom11_iso_diag import gV, states, volume_grads  # noqa: E402
from rom_basis import FIBRE_SLACK  # noqa: E402

snap, basis, leg = sys.argv[1:4]
cases = [c.split(":") for c in sys.argv[4].split(",")]
mf = int(sys.argv[5]) if len(sys.argv) > 5 else 104
m = Energy(snap, basis, leg)
if len(sys.argv) > 6:
    with h5py.File(sys.argv[6], "r") as fh:
        m.Qf = fh["Qf"][...]
Q = m.Qf[:, :mf]
W = m.W
Gf = (Q * W[:, None]).T @ Q
V = m.V
node, coef, L0, EA = m.fib


def Pi(s):
    return Q @ np.linalg.solve(Gf, Q.T @ (W * s))


def fforce(u, S):
    d = np.einsum("fa,fai->fi", coef, (m.x + u.reshape(-1, 3))[node])
    fa = (W * S / L0 ** 2)[:, None, None] * coef[:, :, None] * d[:, None, :]
    f = np.zeros((m.nn, 3))
    np.add.at(f, node, fa)
    f = f.ravel()
    f[m.fixed] = 0
    return f


print(f"consistency_parts: n = {V.shape[1]}, m = {m.P.shape[1]}, mf = {mf}"
      f"{' (Qf of ' + sys.argv[6] + ')' if len(sys.argv) > 6 else ''}")
for ray, t, u, p, _, _ in (s for c in cases for s in states(snap, [c[0]], [float(c[1])], m.fixed)):
    fd = m.dev(u)[1]
    fp = -(p @ m.chambers(u)[1])
    fp[m.fixed] = 0
    v, g = volume_grads(u, m.tet, m.dNdX, m.wq)
    gv = gV(g, m.tet, V)  # (ne, n): V^T G^T p = gv^T p (V's clamped rows are zero)
    Vp = np.linalg.norm(V.T @ fp)
    Bm = gv.T @ m.P
    Vpfe = gv.T @ (m.kappa * (v / m.Ve - 1))
    d = np.einsum("fa,fai->fi", coef, (m.x + u.reshape(-1, 3))[node])
    E = 0.5 * ((d ** 2).sum(1) / L0 ** 2 - 1.0)
    Eb = Pi(E)
    SE, SEb = dpsi(E), dpsi(Eb)
    base = fd + fp
    rows = []
    for lab, S in (("S(E)", SE), ("S(Ebar)", SEb), ("Pi S(E)", Pi(SE)), ("Pi S(Ebar)", Pi(SEb))):
        r0 = V.T @ (base + fforce(u, S))
        rf = np.linalg.norm(r0 + Vpfe) / Vp
        rb = np.linalg.norm(r0 + Bm @ np.linalg.lstsq(Bm, -r0, rcond=None)[0]) / Vp
        rows.append(f"{lab} {rf:.4f} / {rb:.4f}")
    e_stress = np.linalg.norm(V.T @ fforce(u, Pi(SE) - SE)) / Vp
    e_strain = np.linalg.norm(V.T @ fforce(u, Pi(SEb - SE))) / Vp
    slack = E < -FIBRE_SLACK
    spur = slack & (Eb > -FIBRE_SLACK)
    wn = np.sqrt((W * SE ** 2).sum())
    taut = E > FIBRE_SLACK

    def rel(s, sel=slice(None)):
        return np.sqrt((W[sel] * s[sel] ** 2).sum()) / wn
    print(f"  {ray} t {t:.2f}: residual (FE pressure / best of span(P)): " + "; ".join(rows))
    print(f"      the mixed residual's parts (FE pressure): stress projection {e_stress:.4f}, strain projection"
          f" through the law {e_strain:.4f}")
    print(f"      fibres: {taut.sum()} taut, {slack.sum()} slack in the FE; {spur.sum()} of the slack put in"
          f" tension by Ebar; |S(Ebar) - S(E)|_W / |S(E)|_W {rel(SEb - SE):.3f} (on the FE's slack fibres"
          f" {rel(SEb - SE, slack):.3f}, taut {rel(SEb - SE, taut):.3f}); |Pi S(E) - S(E)|_W {rel(Pi(SE) - SE):.3f};"
          f" |Ebar - E|_W / |E|_W {np.sqrt((W * (Eb - E) ** 2).sum() / (W * E ** 2).sum()):.3f}")
    sys.stdout.flush()

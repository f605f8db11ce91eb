#!/usr/bin/python3
"""The obstacle's lateral crawl, slot by slot: per run file and per slot of the crawl (and of the
two-group walk before it, rule 11), the support's advance, the standing group's feet (their slip
on the road, mean normal and tangential force, the share of the slot they slide at the friction
limit) and the swinging group's. The slots are read from the run's gait description (the
comments tools/obstacle_gait.py writes: "two groups, ..." and "the lateral crawl: N slots of T s
from T0 s, groups ACFH / BDEG").

usage: /usr/bin/python3 lateral.py GAIT.gait RUN.h5 [RUN2.h5 ...] [--mu 0.8]
"""
import argparse
import re

import h5py
import numpy as np

LEGS = "ABCDEFGH"
ap = argparse.ArgumentParser()
ap.add_argument("gait")
ap.add_argument("runs", nargs="+")
ap.add_argument("--mu", type=float, default=None, help="friction (default: the run's)")
a = ap.parse_args()

text = open(a.gait).read()
m = re.search(r"# the lateral crawl: (\d+) slots of ([0-9.]+) s from ([0-9.]+) s", text)
if not m:
    raise SystemExit("lateral.py: %s: no lateral crawl of two groups" % a.gait)
NZ, TPZ, TZ = int(m.group(1)), float(m.group(2)), float(m.group(3))
m2 = re.search(r"# from ([0-9.]+) s \(support planned at x \+ \d+ mm\): two groups", text)
TX = float(m2.group(1)) if m2 else None
NX = int(round((TZ - TX) / TPZ)) if TX is not None else 0
# the group that stands in lateral slot 0: the one that stepped aside last (tools/obstacle_gait.py
# rule 11: g0 = xslots % 2, xslots = NX - 1)
G = ("ACFH", "BDEG")
g0 = (NX - 1) % 2 if NX else 0
R18 = "At the end the group that stood last steps under its hips first" in text


def idx(t, s):
    return int(np.argmin(np.abs(t - s)))


for p in a.runs:
    with h5py.File(p, "r") as f:
        t = f["time"][:]
        pos = f["support/position"][:]
        ff = f["contact/foot_force"][:]
        foot = np.stack([f["legs/%s/centerline" % L][:, -1, :] for L in LEGS], axis=1)
        mu = a.mu
        if mu is None:
            v = f.attrs.get("friction", 0.8)
            mu = float(v.decode() if isinstance(v, bytes) else v)
        mass = f.attrs.get("support_mass_kg", b"?")
    print("%s (mu %g; lateral crawl %d slots of %g s from %g s; two-group walk from %s s)"
          % (p.split("/")[-1], mu, NZ, TPZ, TZ, TX))
    print("  slot  t0     stand  d_sup(x,z)    stance slip z (x) mm  N/foot  |Ft|/N  "
          "slide%  swing N  aloft s  y range mm")
    rows = []
    for k in range(-NX, NZ + 1):
        t0 = TZ + k * TPZ
        t1 = t0 + TPZ
        if t1 > t[-1] + 1e-9:
            break
        if k < 0:         # the two-group walk: slot -NX is ACFH's step (BDEG stand)
            j = k + NX
            st = G[1] if j == 0 else G[(j - 1) % 2]
            kind = "x"
        elif k == NZ:     # the release's first slot: ACFH step under the hips (rule 18: the
            # group that stood in the last slot steps first, the other stands)
            st, kind = (G[(g0 + NZ) % 2] if R18 else G[1]), "rel"
        else:
            st, kind = G[(g0 + k) % 2], "z"
        sw = G[0] if st == G[1] else G[1]
        i0, i1 = idx(t, t0), idx(t, t1)
        # the stance: from the slot's start plus the landing's settle (0.02 s) to its end
        ii = slice(idx(t, t0 + 0.02), i1 + 1)
        si = [LEGS.index(L) for L in st]
        wi = [LEGS.index(L) for L in sw]
        N = ff[ii][:, si, 1]
        Ft = np.hypot(ff[ii][:, si, 0], ff[ii][:, si, 2])
        slide = np.mean(Ft > 0.95 * mu * np.maximum(N, 1e-9)) * 100
        slz = np.mean(foot[i1, si, 2] - foot[idx(t, t0 + 0.02), si, 2])
        slx = np.mean(foot[i1, si, 0] - foot[idx(t, t0 + 0.02), si, 0])
        dsx, dsz = pos[i1, 0] - pos[i0, 0], pos[i1, 2] - pos[i0, 2]
        nsw = np.mean(np.sum(ff[ii][:, wi, 1], axis=1))
        # aloft: no foot of either group loaded (the support in the air); the slot's samples
        jj = slice(i0, i1)
        aloft = np.sum(np.all(ff[jj][:, :, 1] < 1e-4, axis=1)) * (t[1] - t[0])
        yr = np.ptp(pos[jj, 1])
        rows.append((kind, dsx, dsz, slz, slx, np.mean(N), np.mean(Ft) / max(np.mean(N), 1e-9),
                     slide, aloft, yr))
        print("  %-4s %6.2f %s  %6.1f %6.1f   %6.1f (%5.1f)        %5.3f   %4.2f   %5.1f   %5.3f"
              "    %5.3f    %4.1f"
              % ("%s%d" % (kind, k), t0, st, dsx, dsz, slz, slx, np.mean(N),
                 np.mean(Ft) / max(np.mean(N), 1e-9), slide, nsw, aloft, yr))
    z = [r for r in rows if r[0] == "z"]
    if z:
        dz = np.array([r[2] for r in z])
        print("  lateral: %d slots, %.1f mm per slot (%.1f per cycle of two; the paper: 65 per "
              "gait cycle at 0.25 MPa), slots 2..: %.1f per slot; stance slip z %.1f mm per slot, "
              "N %.3f N per foot, sliding %.0f %% of the stance; aloft %.3f s per slot (slots 2..)"
              % (len(z), dz.mean(), 2 * dz.mean(), dz[2:].mean() if len(dz) > 2 else float("nan"),
                 np.mean([r[3] for r in z]), np.mean([r[5] for r in z]),
                 np.mean([r[7] for r in z]), np.mean([r[8] for r in z[2:]]) if len(z) > 2 else 0))
    x = [r for r in rows if r[0] == "x"]
    if x:
        print("  two-group walk: %d slots, %.1f mm per slot along x, stance slip x %.1f mm, "
              "sliding %.0f %%" % (len(x), np.mean([r[1] for r in x]),
                                   np.mean([r[4] for r in x]), np.mean([r[7] for r in x])))
    print("  end: support (%.1f, %.1f, %.1f) mm at %.2f s" % (pos[-1, 0], pos[-1, 1], pos[-1, 2],
                                                          t[-1]))

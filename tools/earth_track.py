#!/usr/bin/python3
"""Summarise flat-road runs under `earth`: the track and how the legs carry the robot.

usage: /usr/bin/python3 tools/earth_track.py RUN.h5 [RUN.h5 ...] [--legs T1,T2,...]
           [--pcr N]

Per run (docs/reference/output.md datasets): the support's x at the whole seconds 1..9 (mm),
the largest |z| (mm), the support's height range (mm, y from its start), the largest tilt
(deg, the support's up axis from world up), the fewest feet down (contact/stance) and the
share of samples with fewer than six, and the largest stance-foot normal force against --pcr
(the legs' sway-buckling load pi^2 EI / L^2, N; default the rod's 1.07 N: EI 3000 N mm^2,
the FE-probed unpressurised section, docs/notes/calibration.md, and L 166 mm).

--legs prints, at each time given (s), per leg A..H: in stance (*) or not, the foot's normal
force (N), the foot's offset from its hip along x (dx, mm) and below it (h, mm), and the
largest distance of the centreline from the hip-foot chord (b, mm: how bent the leg stands).
Used by docs/studies/earth_gait.md.
"""
import argparse
import sys

try:
    import h5py
    import numpy as np
except ImportError as e:  # Debian: python3-h5py python3-numpy
    sys.exit(f"earth_track.py: needs h5py and numpy ({e})")

ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
ap.add_argument("runs", nargs="+")
ap.add_argument("--legs", default="", help="times (s) for the per-leg table, comma separated")
ap.add_argument("--pcr", type=float, default=1.07, help="sway-buckling load per leg, N")
a = ap.parse_args()
LEGS = "ABCDEFGH"


def tilt_deg(q):
    """angle of the support's up axis (body y) from world up, q = (w, x, y, z) body to world"""
    w, x, y, z = q.T
    return np.degrees(np.arccos(np.clip(1 - 2 * (x * x + z * z), -1, 1)))


for fn in a.runs:
    try:
        f = h5py.File(fn, "r")
        t = f["time"][:]
        P = f["support/position"][:]
        q = f["support/orientation"][:]
        st = f["contact/stance"][:]
        F = f["contact/foot_force"][:]
    except (OSError, KeyError) as e:
        sys.exit(f"earth_track.py: {fn}: not a run file ({e})")
    status = f.attrs.get("status", b"")
    status = status.decode() if isinstance(status, bytes) else str(status)
    tilt = tilt_deg(q)
    xs = []
    for k in range(1, 10):
        i = np.where(np.abs(t - k) < 1e-6)[0]
        xs.append("%.1f" % P[i[0], 0] if len(i) else "-")
    down = st.sum(axis=1)
    N = F[:, :, 1]
    print(f"{fn}: status {status}, t = {t[-1]:.2f} s, conditions "
          f"{f.attrs.get('conditions', b'?').decode()}, support {1e3 * f.attrs['support_mass_kg']:.0f} g")
    print("  x at 1..9 s (mm): " + " ".join(xs))
    i10 = np.where(tilt > 10)[0]
    print(f"  |z| <= {np.abs(P[:, 2]).max():.2f} mm; y {P[:, 1].min():.1f} .. {P[:, 1].max():.1f} mm;"
          f" tilt <= {tilt.max():.2f} deg" + (f" (past 10 deg at {t[i10[0]]:.2f} s)" if len(i10) else ""))
    stance_N = N[st > 0]
    print(f"  feet down: fewest {down.min()}, fewer than six {100 * (down < 6).mean():.1f} % of samples;"
          f" stance foot normal force: median {np.median(stance_N):.2f} N, 95th percentile"
          f" {np.percentile(stance_N, 95):.2f} N = {np.percentile(stance_N, 95) / a.pcr:.0%} of"
          f" {a.pcr:.2f} N")
    # how bent the stance legs stand: the centreline's largest distance from the hip-foot chord
    bs = []
    for k, l in enumerate(LEGS):
        c = f[f"legs/{l}/centerline"][:]
        rel = c - c[:, :1, :]
        d = rel[:, -1, :]
        chord = d / np.linalg.norm(d, axis=1)[:, None]
        along = np.einsum("ijk,ik->ij", rel, chord)
        perp = rel - along[:, :, None] * chord[:, None, :]
        b = np.linalg.norm(perp, axis=2).max(axis=1)
        bs.append(b[st[:, k] > 0])
    bs = np.concatenate(bs)
    print(f"  stance legs' bend (centreline from the hip-foot chord): median {np.median(bs):.1f} mm,"
          f" 95th percentile {np.percentile(bs, 95):.1f} mm")
    if a.legs:
        for tt in (float(v) for v in a.legs.split(",")):
            i = int(np.argmin(np.abs(t - tt)))
            s = f"  t {t[i]:.2f}: x {P[i, 0]:6.1f} y {P[i, 1]:6.1f} tilt {tilt[i]:4.1f} |"
            for k, l in enumerate(LEGS):
                c = f[f"legs/{l}/centerline"][i]
                d = c[-1] - c[0]
                chord = d / np.linalg.norm(d)
                rel = c - c[0]
                b = np.max(np.linalg.norm(rel - np.outer(rel @ chord, chord), axis=1))
                s += f" {l}{'*' if st[i, k] else ' '}{N[i, k]:.2f} {d[0]:4.0f} {-d[1]:3.0f} {b:2.0f}|"
            print(s)

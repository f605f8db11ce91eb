#!/usr/bin/env python3
"""animate_run.py: an animation of a crawlsim run: side view (x, height) and top view (x, z) of
the terrain, the support and the eight legs' centrelines, with the paper's table nodes.

    /usr/bin/python3 tools/animate_run.py RUN.h5 [-o OUT.gif|OUT.mp4] [--fps N] [--speed K]
                                         [--reference flat-road|obstacle|none]

Reads the run file's /time, /support/corners (N x 8 x 3), /legs/<A..H>/centerline (N x K x 3),
/support/position (displacement of the support's centre) and /terrain/corners (8 nbox x 3).
The paper's nodes (Table 2 for flat-road, Table 3 for obstacle, chosen by the file's `scene`
attribute unless --reference says otherwise) are drawn where the support's centre would be
at each listed time (its start plus the table's displacement; Table 3's y is the paper's
downward axis: height = -y), and the current displacement is printed against the node of
the last listed time passed. GIF through Pillow (Debian's python3-pil, a matplotlib
dependency); MP4 needs ffmpeg. --speed: simulated seconds per second of video (default 1).
A bad input is one line "animate_run.py: <cause>" and exit status 1.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_common import InputError, fail, find_attr_text  # noqa: E402

PROG = "animate_run.py"
# paper Table 2 (flat road) and Table 3 (obstacle): t, x, y_paper (down), z (mm)
TABLE2 = [(t, 39.0 * max(0, t - 1), 0.0, 0.0) for t in range(10)]
TABLE3 = [(0, 0, 0, 0), (1, 0, -50, 0), (2, 0, -50, 0), (3, 0, -13, 0), (4, 26, -22, 0),
          (5, 26, -48, 0), (7, 52, -20, 0), (11, 130, -50, 0), (12, 170, -40, 0),
          (14, 230, -40, 0), (24, 492, -13, 0), (29, 646, 0, 90), (32, 646, 0, 270)]


def load(path):
    import h5py
    import numpy as np
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise InputError(f"{path}: cannot open run file ({e})")
    with f:
        need = ["/time", "/support/corners", "/support/position"] + \
               [f"/legs/{k}/centerline" for k in "ABCDEFGH"]
        for p in need:
            if p not in f:
                raise InputError(f"{path}: no dataset {p} (not a crawlsim run file?)")
        t = np.asarray(f["/time"][:], dtype=float)
        n = len(t)
        corners = np.asarray(f["/support/corners"][:n], dtype=float)
        pos = np.asarray(f["/support/position"][:n], dtype=float)
        legs = [np.asarray(f[f"/legs/{k}/centerline"][:n], dtype=float) for k in "ABCDEFGH"]
        n = min([n, len(corners), len(pos)] + [len(l) for l in legs])
        terrain = np.asarray(f["/terrain/corners"][:], dtype=float).reshape(-1, 8, 3) \
            if "/terrain/corners" in f else np.zeros((0, 8, 3))
        scene = find_attr_text(f.attrs, ["scene"]) or ""
        cond = find_attr_text(f.attrs, ["conditions"]) or ""
        legm = find_attr_text(f.attrs, ["leg_model"]) or ""
        status = find_attr_text(f.attrs, ["status"]) or ""
    if n < 1:
        raise InputError(f"{path}: the run has no samples")
    return dict(t=t[:n], corners=corners[:n], pos=pos[:n], legs=[l[:n] for l in legs],
                terrain=terrain, scene=scene, cond=cond, legm=legm, status=status)


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("run")
    ap.add_argument("-o", "--out")
    ap.add_argument("--fps", type=int, default=10)
    ap.add_argument("--speed", type=float, default=1.0)
    ap.add_argument("--reference", choices=["flat-road", "obstacle", "none"], default=None)
    a = ap.parse_args()
    if a.fps < 1 or a.fps > 60 or not a.speed > 0:
        fail(PROG, "--fps must be 1..60 and --speed > 0")
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib import animation
    try:
        r = load(a.run)
    except InputError as e:
        fail(PROG, str(e))
    ref = a.reference or (r["scene"] if r["scene"] in ("flat-road", "obstacle") else "none")
    table = TABLE2 if ref == "flat-road" else TABLE3 if ref == "obstacle" else []
    t, C, legs = r["t"], r["corners"], r["legs"]
    c0 = C[0].mean(axis=0)  # support centre at t = 0 (world)
    nodes = np.array([[c0[0] + x, c0[1] - y, c0[2] + z] for (_, x, y, z) in table]) \
        if table else np.zeros((0, 3))
    pts = np.concatenate([C.reshape(-1, 3)] + [l.reshape(-1, 3) for l in legs])
    lo, hi = pts.min(axis=0) - 20, pts.max(axis=0) + 20
    if len(r["terrain"]):
        tl = r["terrain"].reshape(-1, 3)
        lo = np.minimum(lo, tl.min(axis=0))
        hi = np.maximum(hi, tl.max(axis=0))
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(9, 7.5))
    for ax in (ax1, ax2):
        ax.set_aspect("equal")
        ax.set_xlabel("x (mm)")
    ax1.set_ylabel("height y (mm)")
    ax2.set_ylabel("lateral z (mm)")
    ax1.set_xlim(lo[0], hi[0]); ax1.set_ylim(lo[1], hi[1])
    ax2.set_xlim(lo[0], hi[0]); ax2.set_ylim(lo[2], hi[2])
    for b in r["terrain"]:
        x0, y0, z0 = b.min(axis=0); x1, y1, z1 = b.max(axis=0)
        ax1.add_patch(plt.Rectangle((x0, y0), x1 - x0, y1 - y0, color="0.85", zorder=0))
        ax2.add_patch(plt.Rectangle((x0, z0), x1 - x0, z1 - z0, fill=False, ec="0.5", zorder=0))
    if len(nodes):
        ax1.plot(nodes[:, 0], nodes[:, 1], "r+", ms=8, label=f"paper table ({ref})")
        ax2.plot(nodes[:, 0], nodes[:, 2], "r+", ms=8)
        ax1.legend(loc="upper right", fontsize=8)
    colors = ["tab:blue" if k in "ACFH" else "tab:orange" for k in "ABCDEFGH"]
    side_legs = [ax1.plot([], [], "-", color=c, lw=1.5)[0] for c in colors]
    top_legs = [ax2.plot([], [], "-", color=c, lw=1.5)[0] for c in colors]
    side_sup, = ax1.plot([], [], "k-", lw=2)
    top_sup, = ax2.plot([], [], "k-", lw=2)
    track, = ax2.plot([], [], "k:", lw=1)
    text = ax1.text(0.01, 0.97, "", transform=ax1.transAxes, va="top", fontsize=9,
                    family="monospace")
    title = f"{os.path.basename(a.run)}: scene {r['scene']}, conditions {r['cond']}, legs {r['legm']}"
    fig.suptitle(title, fontsize=10)
    # frames: every `step` sample so the video plays at --speed
    dt = (t[-1] - t[0]) / max(1, len(t) - 1) if len(t) > 1 else 1.0
    step = max(1, int(round(a.speed / (a.fps * dt)))) if dt > 0 else 1
    frames = list(range(0, len(t), step))
    centre = C.mean(axis=1)
    side_idx = [0, 1, 5, 4, 0]   # bottom -z edge then top: the x-y outline (corner order of
    top_idx = [0, 1, 2, 3, 0]    # cs_supportCorners: VTK hexahedron)

    def draw(i):
        for k in range(8):
            side_legs[k].set_data(legs[k][i, :, 0], legs[k][i, :, 1])
            top_legs[k].set_data(legs[k][i, :, 0], legs[k][i, :, 2])
        side_sup.set_data(C[i, side_idx, 0], C[i, side_idx, 1])
        top_sup.set_data(C[i, top_idx, 0], C[i, top_idx, 2])
        track.set_data(centre[: i + 1, 0], centre[: i + 1, 2])
        d = r["pos"][i]
        s = f"t = {t[i]:5.2f} s  x {d[0]:7.1f}  h {d[1]:6.1f}  z {d[2]:6.1f} mm"
        past = [row for row in table if row[0] <= t[i] + 1e-9]
        if past:
            tt, x, y, z = past[-1]
            s += f"\npaper at {tt} s: x {x:.0f}  h {-y:.0f}  z {z:.0f} mm"
        text.set_text(s)
        return side_legs + top_legs + [side_sup, top_sup, track, text]

    out = a.out or os.path.splitext(a.run)[0] + ".gif"
    anim = animation.FuncAnimation(fig, draw, frames=frames, blit=False)
    try:
        if out.lower().endswith(".mp4"):
            if not animation.writers.is_available("ffmpeg"):
                fail(PROG, "MP4 needs ffmpeg (apt-get install ffmpeg); write a .gif instead")
            anim.save(out, writer=animation.FFMpegWriter(fps=a.fps))
        else:
            anim.save(out, writer=animation.PillowWriter(fps=a.fps))
    except OSError as e:
        fail(PROG, f"{out}: cannot write: {e}")
    print(f"{out}: {len(frames)} frames at {a.fps} fps ({a.speed:g} simulated s per s)")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""plot_run.py: pictures of one `crawlsim run` file beyond the track (issue 36).

  /usr/bin/python3 tools/plot_run.py RUN.h5 [--kind footfall,pressures,feet,forces]
                                     [--chambers 1,2,3,4] [--out-prefix PREFIX]

writes PREFIX_<kind>.png (PREFIX defaults to RUN without .h5):
  footfall   which foot stands when: one row per leg A..H, a bar where the foot is in stance.
             Stance comes from the run's /contact/stance [N,8] when the file has it; else it is
             measured from the geometry: the foot (the centreline's last point) within --touch
             mm (default 1) of the top of the terrain box under it (/terrain/corners, boxes taken
             by their extent; an oriented box by its bounding box, which overstates its top
             where it is inclined), and the title says which.
  pressures  the chosen chambers' pressures over time (/pressure, MPa; labels 1..96, label =
             12 k + 4 (s - 1) + j for leg k = 0..7 (A..H), segment s, chamber j; docs/reference.md).
  feet       each foot's path relative to its hip in the support's frame (side view: forward x
             against up y), coloured by stance and swing as in the footfall diagram.
  forces     ground forces per foot over time (/contact/foot_force [N,8,3], N): the vertical
             component and the tangential magnitude; only when the file has them.
Titles name scene, slope, conditions, legs, calibration and gait (root attributes,
plot_common.run_title). A missing or malformed input is one line on stderr and exit status 1.
"""

import argparse
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))

import matplotlib  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from plot_common import (InputError, fail, load_or_fail, open_h5, read_dataset,  # noqa: E402
                         run_title, run_title_attrs, save_or_fail)

PROG = "plot_run"
LEGS = "ABCDEFGH"
KINDS = ("footfall", "pressures", "feet", "forces")


def load_run(path):
    with open_h5(path) as f:
        r = {"path": path, "t": read_dataset(f, "/time", path, ())}
        n = r["t"].shape[0]
        if n == 0:
            raise InputError(f"{path}: no samples (/time is empty)")
        r["pressure"] = read_dataset(f, "/pressure", path, (96,))
        r["quat"] = read_dataset(f, "/support/orientation", path, (4,))
        r["legs"] = np.stack([read_dataset(f, f"/legs/{k}/centerline", path, (None, 3))
                              for k in LEGS], axis=1)  # [N, 8, K, 3]
        r["terrain"] = (read_dataset(f, "/terrain/corners", path, (3,))
                        if "/terrain/corners" in f else np.zeros((0, 3)))
        r["stance"] = read_dataset(f, "/contact/stance", path, (8,)) if "/contact/stance" in f else None
        r["foot_force"] = (read_dataset(f, "/contact/foot_force", path, (8, 3))
                           if "/contact/foot_force" in f else None)
        r["title"] = run_title(run_title_attrs(f))
    # series appended as the run goes may end one sample apart: keep the common prefix
    m = min(a.shape[0] for a in (r["t"], r["pressure"], r["quat"], r["legs"])
            if a is not None)
    for k in ("t", "pressure", "quat", "legs", "stance", "foot_force"):
        if r[k] is not None:
            r[k] = r[k][:m]
    return r


def terrain_top(corners, x, z):
    """Top (y, mm) of the highest terrain box whose x-z extent holds (x, z); -inf if none.
    corners: [8 nbox, 3] mm. x, z: arrays of one shape."""
    top = np.full(np.shape(x), -np.inf)
    for b in range(corners.shape[0] // 8):
        c = corners[8 * b:8 * b + 8]
        lo, hi = c.min(axis=0), c.max(axis=0)
        inside = (x >= lo[0]) & (x <= hi[0]) & (z >= lo[2]) & (z <= hi[2])
        top = np.where(inside, np.maximum(top, hi[1]), top)
    return top


def stance_of(r, touch):
    """[N, 8] booleans and a phrase saying where they come from."""
    if r["stance"] is not None:
        return r["stance"] > 0.5, "stance from the run's /contact/stance"
    foot = r["legs"][:, :, -1, :]  # [N, 8, 3]
    top = terrain_top(r["terrain"], foot[..., 0], foot[..., 2])
    return (foot[..., 1] - top) <= touch, (f"stance measured: foot within {touch:g} mm of the "
                                          f"terrain top (no /contact/stance in the file)")


def quat_rotate_inv(q, v):
    """v (.., 3) into the frame of unit quaternions q (.., 4) = (w, x, y, z): R(q)^T v."""
    w, u = q[..., :1], -q[..., 1:]
    t = 2 * np.cross(u, v)
    return v + w * t + np.cross(u, t)


def suptitle(fig, r, what):
    fig.suptitle(f"{what}: {os.path.basename(r['path'])}\n{r['title']}", fontsize=10)


def plot_footfall(r, out, touch):
    st, source = stance_of(r, touch)
    t = r["t"]
    fig, ax = plt.subplots(figsize=(11, 4.2), constrained_layout=True)
    for k in range(8):
        on = st[:, k].astype(int)
        edges = np.flatnonzero(np.diff(np.r_[0, on, 0]))
        starts, ends = edges[0::2], edges[1::2] - 1
        spans = [(t[a], max(t[b] - t[a], t[1] - t[0] if len(t) > 1 else 0)) for a, b in zip(starts, ends)]
        ax.broken_barh(spans, (7 - k - 0.4, 0.8), color="C0" if k < 4 else "C1")
    ax.set_yticks(range(8))
    ax.set_yticklabels([f"leg {k}" for k in reversed(LEGS)])
    ax.set_xlabel("time t (s)")
    ax.set_xlim(t[0], t[-1])
    ax.grid(True, axis="x", alpha=0.3)
    frac = st.mean(axis=0)
    ax.set_title(f"{source}; stance fraction A..H: " + " ".join(f"{v:.2f}" for v in frac),
                 fontsize=9)
    suptitle(fig, r, "footfall diagram (bars: foot in stance)")
    fig.savefig(out, dpi=110)
    plt.close(fig)


def chamber_name(label):
    k, rest = divmod(label - 1, 12)
    s, j = divmod(rest, 4)
    return f"{label} = {LEGS[k]}_II{s + 1}_\u03a9{j + 1}"


def plot_pressures(r, out, chambers):
    t = r["t"]
    fig, ax = plt.subplots(figsize=(11, 4.2), constrained_layout=True)
    for c in chambers:
        ax.plot(t, r["pressure"][:, c - 1], lw=1.4, label=chamber_name(c))
    ax.set_xlabel("time t (s)")
    ax.set_ylabel("pressure (MPa)")
    ax.grid(True, alpha=0.3)
    ax.legend(fontsize=8, ncol=min(4, len(chambers)))
    suptitle(fig, r, "chamber pressures")
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_feet(r, out, touch):
    st, source = stance_of(r, touch)
    cl = r["legs"]
    rel = quat_rotate_inv(r["quat"][:, None, :], cl[:, :, -1, :] - cl[:, :, 0, :])  # [N, 8, 3]
    fig, axes = plt.subplots(2, 4, figsize=(13, 4.8), sharex=True, sharey=True,
                             constrained_layout=True)
    for k in range(8):
        ax = axes[k // 4, k % 4]
        x, y = rel[:, k, 0], rel[:, k, 1]
        ax.plot(x, y, color="0.7", lw=0.8)
        ax.plot(x[st[:, k]], y[st[:, k]], ".", color="C0", ms=2, label="stance")
        ax.plot(x[~st[:, k]], y[~st[:, k]], ".", color="C3", ms=2, label="swing")
        ax.set_title(f"leg {LEGS[k]}", fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.set_aspect("equal", adjustable="box")
        if k // 4 == 1:
            ax.set_xlabel("forward x (mm)")
        if k % 4 == 0:
            ax.set_ylabel("up y (mm)")
    axes[0, 0].legend(fontsize=8, markerscale=4)
    fig.text(0.5, 0.005, f"foot minus hip in the support's frame; {source}", ha="center",
             fontsize=8)
    suptitle(fig, r, "foot paths relative to the hips (side view)")
    fig.savefig(out, dpi=110)
    plt.close(fig)


def plot_forces(r, out):
    F = r["foot_force"]
    if F is None:
        raise InputError(f"{r['path']}: no /contact/foot_force (a run file written before "
                         "per-foot contact was recorded)")
    t = r["t"]
    fig, (a1, a2) = plt.subplots(2, 1, figsize=(11, 6), sharex=True, constrained_layout=True)
    for k in range(8):
        ls = "-" if k < 4 else "--"
        a1.plot(t, F[:, k, 1], ls=ls, lw=1, label=f"leg {LEGS[k]}")
        a2.plot(t, np.hypot(F[:, k, 0], F[:, k, 2]), ls=ls, lw=1)
    a1.set_ylabel("vertical force Fy (N)")
    a2.set_ylabel("tangential |(Fx, Fz)| (N)")
    a2.set_xlabel("time t (s)")
    for a in (a1, a2):
        a.grid(True, alpha=0.3)
    a1.legend(fontsize=8, ncol=8)
    suptitle(fig, r, "ground forces per foot")
    fig.savefig(out, dpi=110)
    plt.close(fig)


def parse_list(text, what, lo, hi):
    try:
        v = [int(s) for s in text.split(",") if s.strip()]
    except ValueError:
        raise argparse.ArgumentTypeError(f"{what} '{text}' is not a comma-separated list of integers")
    if not v or any(not lo <= c <= hi for c in v):
        raise argparse.ArgumentTypeError(f"{what} must be in {lo}..{hi}")
    return v


def main(argv=None):
    ap = argparse.ArgumentParser(description="Footfall diagram, chamber pressures, foot paths "
                                 "and ground forces of a crawlsim run file.")
    ap.add_argument("run", metavar="RUN.h5")
    ap.add_argument("--kind", default="footfall,pressures,feet",
                    help="comma-separated: footfall, pressures, feet, forces (default the first "
                    "three; forces needs /contact/foot_force)")
    ap.add_argument("--chambers", type=lambda s: parse_list(s, "--chambers", 1, 96),
                    default=[1, 2, 3, 4], help="chamber labels 1..96 (default 1,2,3,4: leg A, II1)")
    ap.add_argument("--touch", type=float, default=1.0,
                    help="mm: a foot this close to the terrain top stands (geometric stance only)")
    ap.add_argument("--out-prefix", help="output prefix (default RUN without .h5)")
    args = ap.parse_args(argv)
    kinds = [k for k in args.kind.split(",") if k]
    bad = [k for k in kinds if k not in KINDS]
    if bad:
        fail(PROG, f"unknown --kind '{bad[0]}' (expected {', '.join(KINDS)})")
    r = load_or_fail(PROG, load_run, args.run)
    prefix = args.out_prefix or (args.run[:-3] if args.run.endswith(".h5") else args.run)
    draw = {
        "footfall": lambda out: plot_footfall(r, out, args.touch),
        "pressures": lambda out: plot_pressures(r, out, args.chambers),
        "feet": lambda out: plot_feet(r, out, args.touch),
        "forces": lambda out: plot_forces(r, out),
    }
    for k in kinds:
        out = f"{prefix}_{k}.png"
        if k == "forces" and r["foot_force"] is None:
            fail(PROG, f"{args.run}: no /contact/foot_force (a run file written before per-foot "
                 "contact was recorded)")
        save_or_fail(PROG, out, lambda o=out, k=k: draw[k](o))
    return 0


if __name__ == "__main__":
    sys.exit(main())

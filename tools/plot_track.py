#!/usr/bin/python3
"""plot_track.py: plot the support track and the legs' side view of one `crawlsim run` file.

Usage:
  /usr/bin/python3 tools/plot_track.py RUN.h5 [-o OUT.png] [--times 0,0.5,1,1.5,2]
                                       [--reference flat-road|obstacle|none]

Reads the `run` output contract of docs/design.md ("Output contract (HDF5)"):
  /time [N] s, /support/position [N,3] mm (x, y, z displacement of the support's centre
  from t = 0; x crawl direction, y up, z lateral), /support/orientation [N,4] (w, x, y, z),
  /legs/<A..H>/centerline [N,K,3] mm (world frame), root attributes (scene, leg model,
  gait file, wall time, ...). /pressure is part of the contract but is not plotted here.

Draws one PNG with four panels:
  (a) support x vs t, with the paper's Table 2 (docs/reference.md) and a +-10 % band after 2 s
      (--reference flat-road), or Table 3's x nodes with a +-20 mm band (--reference obstacle);
  (b) support height y and lateral z vs t (with Table 3's height = -y_paper and z nodes);
  (c) pitch and roll of the support in degrees;
  (d) side view (x-y plane) of the legs at the chosen times (nearest samples):
      legs A-D solid, E-H dashed, one colour per time, ground line at the lowest foot at t = 0.

Runs with Debian's Python (python3-matplotlib, python3-h5py), Agg backend, no display.
Exit status: 0 on success, 1 on a missing/unreadable file or dataset (one-line message on
stderr), 2 on bad command-line usage.
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402
from matplotlib.patches import Patch  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # plot_common.py, from any cwd
from plot_common import InputError, default_out, find_attr_text, load_or_fail, open_h5  # noqa: E402
from plot_common import read_dataset, run_title, run_title_attrs, save_or_fail  # noqa: E402

PROG = "plot_track"

LEGS = "ABCDEFGH"

# Paper Table 2 (docs/reference.md): flat road, support displacement x (mm) at t = 0..9 s; y = z = 0.
TABLE2_T = np.arange(10.0)
TABLE2_X = np.array([0, 0, 39, 78, 117, 156, 195, 234, 273, 312], dtype=float)
TABLE2_BAND = 0.10  # +-10 % band, drawn from t = 2 s on (before that x is 0 and a relative band is empty)
TABLE2_BAND_FROM = 2.0
# Paper Table 3 (docs/reference.md): obstacle road, support displacement at its listed times (s):
# x, height (= -y of the paper's table: up positive) and z (mm); the tolerance 20 mm
TABLE3_T = np.array([0, 1, 2, 3, 4, 5, 7, 11, 12, 14, 24, 29, 32], dtype=float)
TABLE3_X = np.array([0, 0, 0, 0, 26, 26, 52, 130, 170, 230, 492, 646, 646], dtype=float)
TABLE3_H = np.array([0, 50, 50, 13, 22, 48, 20, 50, 40, 40, 13, 0, 0], dtype=float)
TABLE3_Z = np.array([0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 90, 270], dtype=float)
TABLE3_TOL = 20.0

# Root attribute names are not fixed by the contract's wording ("scene, leg model, gait file,
# wall time"): accept the usual spellings, compared after lower-casing and mapping ' ' and '-' to '_'.
ATTR_ALIASES = {
    "scene": ("scene", "scene_name", "road", "terrain"),
    "leg_model": ("leg_model", "legmodel", "leg", "leg_surrogate", "surrogate", "model"),
    "gait": ("gait_file", "gait", "gait_path", "gaitfile"),
    "wall_time": ("wall_time_s", "wall_time", "walltime", "wall_clock_s", "wall_clock"),
    "status": ("status",),
}


def load_run(path):
    with open_h5(path) as f:
        series = {
            "t": read_dataset(f, "/time", path, ()),
            "pos": read_dataset(f, "/support/position", path, (3,)),
            "quat": read_dataset(f, "/support/orientation", path, (4,)),
        }
        legs = {leg: read_dataset(f, f"/legs/{leg}/centerline", path, (None, 3)) for leg in LEGS}
        attrs = {k: find_attr_text(f.attrs, aliases) for k, aliases in ATTR_ALIASES.items()}
        title = run_title(run_title_attrs(f))
        terrain = (read_dataset(f, "/terrain/corners", path, (3,)) if "/terrain/corners" in f
                   else np.zeros((0, 3)))
    # The writer appends samples as the run goes, so a run that stopped mid-sample can leave
    # series one sample apart: plot the common prefix and say so.
    lengths = [a.shape[0] for a in series.values()] + [a.shape[0] for a in legs.values()]
    n = min(lengths)
    if n == 0:
        raise InputError(f"{path}: no samples (/time or another series is empty)")
    if max(lengths) != n:
        print(f"plot_track: warning: {path}: series lengths differ ({min(lengths)}..{max(lengths)}), "
              f"plotting the first {n} samples", file=sys.stderr)
    run = {k: a[:n] for k, a in series.items()}
    run["legs"] = {k: a[:n] for k, a in legs.items()}
    run["path"] = path
    run["attrs"] = attrs
    run["title"] = title
    run["terrain"] = terrain
    return run


def draw_terrain_side(ax, corners):
    """The terrain boxes in the side view: each box's outline projected on the x-y plane (the
    hull of its 8 corners: a rectangle for an axis-aligned box, the turned one for an oriented
    box), filled; returns the number drawn."""
    n = corners.shape[0] // 8
    for b in range(n):
        p = corners[8 * b:8 * b + 8, :2]
        c = p.mean(axis=0)
        ang = np.arctan2(p[:, 1] - c[1], p[:, 0] - c[0])
        hull = p[np.argsort(ang)]  # the projected corners around their centre (a convex shape)
        ax.fill(hull[:, 0], hull[:, 1], color="tan", alpha=0.45, lw=0.8, ec="saddlebrown",
                zorder=0)
    return n


def pitch_roll_deg(q):
    """Pitch (about lateral z, nose up > 0) and roll (about crawl axis x) in degrees.

    Frames of docs/reference.md: x crawl direction, y up, z lateral. The attitude is read as
    R = Ry(yaw) Rz(pitch) Rx(roll); then R[1,0] = sin(pitch) (the body x axis' height) and
    roll = atan2(-R[1,2], R[1,1]). Quaternions are normalised first (w, x, y, z order).
    """
    q = np.array(q, dtype=float)
    norm = np.linalg.norm(q, axis=1)
    norm[norm == 0] = np.nan
    w, x, y, z = (q / norm[:, None]).T
    r10 = 2.0 * (x * y + w * z)
    r11 = 1.0 - 2.0 * (x * x + z * z)
    r12 = 2.0 * (y * z - w * x)
    pitch = np.degrees(np.arcsin(np.clip(r10, -1.0, 1.0)))
    roll = np.degrees(np.arctan2(-r12, r11))
    return pitch, roll


def parse_times(text):
    try:
        times = [float(s) for s in text.split(",") if s.strip() != ""]
    except ValueError:
        raise argparse.ArgumentTypeError(f"bad time list '{text}' (expected e.g. 0,0.5,1)") from None
    if not times:
        raise argparse.ArgumentTypeError("empty time list")
    return times


def nearest_samples(t, times):
    """Indices of the samples nearest to each requested time, duplicates removed, in time order."""
    idx = []
    dt = float(np.nanmedian(np.diff(t))) if len(t) > 1 else 0.0
    for tq in times:
        i = int(np.nanargmin(np.abs(t - tq)))
        if abs(t[i] - tq) > max(dt, 1e-12):
            print(f"plot_track: warning: no sample near t = {tq:g} s, using t = {t[i]:.4g} s", file=sys.stderr)
        if i not in idx:
            idx.append(i)
    return sorted(idx, key=lambda i: t[i])


def plot_track(run, out, times, reference):
    t = run["t"]
    x, y, z = run["pos"].T
    pitch, roll = pitch_roll_deg(run["quat"])
    a = run["attrs"]

    fig = plt.figure(figsize=(16, 10.5), constrained_layout=True)
    gs = fig.add_gridspec(2, 3, height_ratios=[1.0, 1.25])
    ax_x = fig.add_subplot(gs[0, 0])
    ax_yz = fig.add_subplot(gs[0, 1], sharex=ax_x)
    ax_pr = fig.add_subplot(gs[0, 2], sharex=ax_x)
    ax_side = fig.add_subplot(gs[1, :])

    # (a) support x vs t
    ax_x.plot(t, x, color="C0", lw=1.8, label="simulation")
    if reference == "flat-road":
        tb = np.linspace(TABLE2_BAND_FROM, TABLE2_T[-1], 50)
        xb = np.interp(tb, TABLE2_T, TABLE2_X)
        ax_x.fill_between(tb, (1 - TABLE2_BAND) * xb, (1 + TABLE2_BAND) * xb, color="0.6", alpha=0.35,
                          lw=0, label=f"Table 2 \u00b1{TABLE2_BAND * 100:.0f} % (t \u2265 {TABLE2_BAND_FROM:g} s)")
        ax_x.plot(TABLE2_T, TABLE2_X, "ks", ms=5, mfc="none", label="paper Table 2 (flat road)")
    elif reference == "obstacle":
        ax_x.errorbar(TABLE3_T, TABLE3_X, yerr=TABLE3_TOL, fmt="ks", ms=5, mfc="none", capsize=3,
                      lw=0.8, label=f"paper Table 3 (obstacle), ±{TABLE3_TOL:g} mm")
        ax_x.axhline(TABLE3_X[-1], color="k", lw=0.6, ls=":", label="Table 3's end x")
    ax_x.set_xlabel("time t (s)")
    ax_x.set_ylabel("support displacement x (mm)")
    ax_x.set_title("(a) crawl direction x")
    ax_x.legend(loc="upper left", fontsize=8)

    # (b) height and lateral
    ax_yz.plot(t, y, color="C2", lw=1.6, label="height y (up)")
    ax_yz.plot(t, z, color="C3", lw=1.6, label="lateral z")
    if reference == "flat-road":
        ax_yz.axhline(0.0, color="k", lw=0.8, ls=":", label="Table 2: y = z = 0")
    elif reference == "obstacle":
        ax_yz.plot(TABLE3_T, TABLE3_H, "s", color="C2", ms=5, mfc="none",
                   label="Table 3: height (-y_paper)")
        ax_yz.plot(TABLE3_T, TABLE3_Z, "o", color="C3", ms=5, mfc="none", label="Table 3: z")
        ax_yz.axhline(TABLE3_Z[-1], color="C3", lw=0.6, ls=":", label="Table 3's end z")
    ax_yz.set_xlabel("time t (s)")
    ax_yz.set_ylabel("support displacement (mm)")
    ax_yz.set_title("(b) height y and lateral z")
    ax_yz.legend(loc="best", fontsize=8)

    # (c) attitude
    ax_pr.plot(t, pitch, color="C4", lw=1.6, label="pitch (about z, nose up > 0)")
    ax_pr.plot(t, roll, color="C5", lw=1.6, label="roll (about x)")
    ax_pr.axhline(0.0, color="k", lw=0.6, ls=":")
    ax_pr.set_xlabel("time t (s)")
    ax_pr.set_ylabel("angle (deg)")
    ax_pr.set_title("(c) support pitch and roll")
    ax_pr.legend(loc="best", fontsize=8)

    for ax in (ax_x, ax_yz, ax_pr):
        ax.grid(True, alpha=0.3)

    # (d) side view of the legs
    idx = nearest_samples(t, times)
    cmap = plt.get_cmap("viridis")
    colors = [cmap(0.9 * k / max(len(idx) - 1, 1)) for k in range(len(idx))]
    handles = []
    for i, c in zip(idx, colors):
        for leg in LEGS:
            cl = run["legs"][leg][i]
            ls = "-" if leg in "ABCD" else "--"
            ax_side.plot(cl[:, 0], cl[:, 1], ls=ls, color=c, lw=1.5)
            ax_side.plot(cl[-1, 0], cl[-1, 1], "o", color=c, ms=3)
        handles.append(Line2D([], [], color=c, lw=2, label=f"t = {t[i]:.3g} s"))
    feet0 = np.array([run["legs"][leg][0][-1, 1] for leg in LEGS])
    ground = np.nanmin(feet0)
    pts = np.concatenate([run["legs"][leg][i] for i in idx for leg in LEGS])
    if draw_terrain_side(ax_side, run["terrain"]):
        # the terrain as it is (the obstacle's step, a ramp), the view held on the legs
        ax_side.set_xlim(pts[:, 0].min() - 30, pts[:, 0].max() + 30)
        ax_side.set_ylim(min(pts[:, 1].min(), ground) - 30, pts[:, 1].max() + 20)
        handles.append(Patch(color="tan", alpha=0.45, label="terrain (boxes, side view)"))
    elif np.isfinite(ground):
        ax_side.axhline(ground, color="saddlebrown", lw=1.2)
        handles.append(Line2D([], [], color="saddlebrown", lw=1.2,
                              label=f"ground (lowest foot at t = 0: y = {ground:.1f} mm)"))
    handles.append(Line2D([], [], color="k", ls="-", label="legs A\u2013D"))
    handles.append(Line2D([], [], color="k", ls="--", label="legs E\u2013H"))
    handles.append(Line2D([], [], color="k", ls="none", marker="o", ms=3, label="foot (last centreline point)"))
    ax_side.set_aspect("equal", adjustable="box" if len(run["terrain"]) else "datalim")
    ax_side.set_xlabel("x, crawl direction (mm)")
    ax_side.set_ylabel("y, up (mm)")
    ax_side.set_title("(d) legs, side view (x\u2013y plane, world frame)")
    ax_side.grid(True, alpha=0.3)
    ax_side.legend(handles=handles, loc="center left", bbox_to_anchor=(1.01, 0.5), fontsize=9)

    def show(v):
        return v if v else "?"

    gait = a["gait"]
    if gait:
        gait = os.path.basename(gait)
    title = run["title"] or (f"scene: {show(a['scene'])}   leg model: {show(a['leg_model'])}   "
                             f"gait: {show(gait)}")
    sub = f"{os.path.basename(run['path'])}   final x = {x[-1]:.1f} mm at t = {t[-1]:.3g} s"
    if a["wall_time"]:
        sub += f"   wall time {a['wall_time']} s"
    if a["status"] and a["status"] != "ok":
        sub += f"   status: {a['status']}"
    fig.suptitle(f"{title}\n{sub}", fontsize=12)

    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Plot the support track and leg side view of a crawlsim run file.")
    ap.add_argument("run", metavar="RUN.h5", help="output of `crawlsim run`")
    ap.add_argument("-o", "--output", metavar="OUT.png", help="output PNG (default: RUN_track.png)")
    ap.add_argument("--times", type=parse_times, default=[0, 0.5, 1, 1.5, 2],
                    help="comma-separated times (s) for the side view, nearest samples (default 0,0.5,1,1.5,2)")
    ap.add_argument("--reference", choices=["flat-road", "obstacle", "none"], default="flat-road",
                    help="reference track: paper Table 2 flat road (default), Table 3 obstacle "
                    "road, or none")
    args = ap.parse_args(argv)

    run = load_or_fail(PROG, load_run, args.run)
    out = args.output or default_out(args.run, "_track.png")
    save_or_fail(PROG, out, lambda: plot_track(run, out, args.times, args.reference))
    return 0


if __name__ == "__main__":
    sys.exit(main())

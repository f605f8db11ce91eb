#!/usr/bin/python3
"""plot_bend.py: plot bending angle vs pressure of one or more `crawlsim bend` files.

Usage:
  /usr/bin/python3 tools/plot_bend.py BEND.h5 [more.h5 ...] [-o OUT.png]

Reads the `bend` output contract of docs/design.md ("Output contract (HDF5)"):
  /pressure [M] MPa, /angle_deg [M,3] per segment (II1, II2, II3), /angle_total_deg [M],
  /tip_position [M,3] mm (checked, not plotted); attributes `model`, the actuator's name,
  and `p_until_angle_MPa` when `--until-angle` was given.

Draws one PNG with two panels: (a) total bending angle vs pressure, one colour and line style
per file, with a marker at p_until_angle_MPa when present; (b) per-segment angles vs pressure,
one colour per segment and the file's line style. Legend entries come from the `model`
attribute (plus the actuator name, or the file name, when needed to tell files apart).

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

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # plot_common.py, from any cwd
from plot_common import InputError, default_out, find_attr, find_attr_text, load_or_fail  # noqa: E402
from plot_common import open_h5, read_dataset, save_or_fail  # noqa: E402

PROG = "plot_bend"

LINESTYLES = ["-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1)), (0, (8, 2)), (0, (1, 3))]
SEGMENTS = ("II1", "II2", "II3")
SEGMENT_COLORS = ("C0", "C1", "C2")

# The actuator's name has no fixed attribute name in the contract; accept the usual spellings
# (compared after lower-casing and mapping ' ' and '-' to '_').
ACTUATOR_KEYS = ("actuator", "actuator_name", "geometry", "actuator_geometry", "name")


def load_bend(path):
    with open_h5(path) as f:
        p = read_dataset(f, "/pressure", path, (), rows="M")
        m = p.shape[0]
        if m == 0:
            raise InputError(f"{path}: /pressure is empty")
        d = {
            "path": path,
            "p": p,
            "seg": read_dataset(f, "/angle_deg", path, (3,), m),
            "total": read_dataset(f, "/angle_total_deg", path, (), m),
            "tip": read_dataset(f, "/tip_position", path, (3,), m),
        }
        d["model"] = find_attr_text(f.attrs, ("model",))
        d["actuator"] = find_attr_text(f.attrs, ACTUATOR_KEYS)
        pu = find_attr(f.attrs, ("p_until_angle_mpa", "p_until_angle"))
        d["p_until"] = None
        if pu is not None:
            try:
                v = float(np.asarray(pu, dtype=float).reshape(-1)[0])
                d["p_until"] = v if np.isfinite(v) else None
            except (TypeError, ValueError, IndexError):
                raise InputError(f"{path}: attribute p_until_angle_MPa is not a number") from None
    return d


def labels_for(runs):
    """Legend labels: the model attribute (or the file name when it is missing). Files that share
    a model are told apart by their actuator name when that differs, else by their file name."""
    base = [r["model"] or os.path.splitext(os.path.basename(r["path"]))[0] for r in runs]
    labels = list(base)
    for name in set(base):
        group = [i for i, b in enumerate(base) if b == name]
        if len(group) < 2:
            continue
        acts = [runs[i]["actuator"] for i in group]
        if all(acts) and len(set(acts)) == len(acts):
            for i in group:
                labels[i] = f"{name} ({runs[i]['actuator']})"
        else:
            for i in group:
                labels[i] = f"{name} [{os.path.basename(runs[i]['path'])}]"
    return labels


def plot_bend(runs, out):
    labels = labels_for(runs)
    fig, (ax_t, ax_s) = plt.subplots(1, 2, figsize=(14, 6), constrained_layout=True)
    file_handles = []
    for k, (r, lab) in enumerate(zip(runs, labels)):
        ls = LINESTYLES[k % len(LINESTYLES)]
        col = f"C{k % 10}" if len(runs) > 1 else "k"
        order = np.argsort(r["p"], kind="stable")
        p, tot, seg = r["p"][order], r["total"][order], r["seg"][order]
        ax_t.plot(p, tot, ls=ls, color=col, lw=1.8, label=lab)
        if r["p_until"] is not None:
            pu = r["p_until"]
            au = float(np.interp(pu, p, tot)) if p[0] <= pu <= p[-1] else np.nan
            if not np.isfinite(au):  # outside the sampled range: mark at the last angle
                au = tot[-1]
            ax_t.plot([pu], [au], marker="*", ms=15, color=col, mec="k", ls="none",
                      label=f"{lab}: p_until_angle = {pu:.4g} MPa")
            ax_t.axvline(pu, color=col, lw=0.8, ls=":")
        for j in range(3):
            ax_s.plot(p, seg[:, j], ls=ls, color=SEGMENT_COLORS[j], lw=1.6)
        file_handles.append(Line2D([], [], color="k", ls=ls, lw=1.6, label=lab))

    ax_t.set_xlabel("pressure p (MPa)")
    ax_t.set_ylabel("total bending angle \u0398 (deg)")
    ax_t.set_title("(a) total bending angle")
    ax_t.grid(True, alpha=0.3)
    ax_t.legend(loc="upper left", fontsize=9)

    seg_handles = [Line2D([], [], color=c, lw=2, label=f"segment {s}") for s, c in zip(SEGMENTS, SEGMENT_COLORS)]
    ax_s.set_xlabel("pressure p (MPa)")
    ax_s.set_ylabel("segment bending angle \u03b8 (deg)")
    ax_s.set_title("(b) per-segment bending angle")
    ax_s.grid(True, alpha=0.3)
    ax_s.legend(handles=seg_handles + file_handles, loc="upper left", fontsize=9)

    acts = sorted({r["actuator"] for r in runs if r["actuator"]})
    title = "Bending angle vs pressure"
    if acts:
        title += f"   actuator: {', '.join(acts)}"
    fig.suptitle(title, fontsize=12)
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Plot bending angle vs pressure of crawlsim bend files.")
    ap.add_argument("files", metavar="BEND.h5", nargs="+", help="outputs of `crawlsim bend`")
    ap.add_argument("-o", "--output", metavar="OUT.png", help="output PNG (default: first file's name + _bend.png)")
    args = ap.parse_args(argv)

    runs = [load_or_fail(PROG, load_bend, path) for path in args.files]
    out = args.output or default_out(args.files[0], "_bend.png")
    save_or_fail(PROG, out, lambda: plot_bend(runs, out))
    return 0


if __name__ == "__main__":
    sys.exit(main())

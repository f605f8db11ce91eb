#!/usr/bin/python3
"""plot_calibration.py: pictures of an FE calibration table of chamber modes and of the model
the legs read from it.

Usage:
  /usr/bin/python3 tools/plot_calibration.py TABLE.h5 [--model PRED.h5] -o DIR
        [--holdout-cols N] [--only bend|stretch|holdout|stiffness]

TABLE.h5 is a mode table of `crawlsim calibrate` (root attribute format
"crawlsim-fe-calibration 1"; /cases/<name>/ with kind, ratio1..ratio4 and the datasets pressure
[M] MPa, bend [M,3,2] rad, stretch [M,3], radial_max [M,3] mm, tip [M,3] mm, and the probes'
probe_pressure [K], EI [K,3,2] N mm^2, EA [K,3] N). PRED.h5 is what `crawlsim calibrate
--model-out PRED.h5` writes (robot_calibration_model.h, csr_calReportWrite): the model's bend,
stretch, radius and tip at every row of every case, the merged stiffness points, and the
small-strain references 8 C10 I and 8 C10 A.

Writes into DIR:
  calibration_bend.png      each fitted mode's segment bend angle against pressure (the manner of
                            the paper's Figs. 3 and 6): FE points, the model as lines;
  calibration_stretch.png   each fitted mode's centreline stretch and largest radial growth;
  calibration_holdout.png   the held-out and symmetry cases: FE points against the model (bend
                            per segment, and the tip's path in the base frame), a grid of
                            --holdout-cols cases to a row (default 2: ~1040 px wide);
  calibration_stiffness.png EI and EA of each segment against the mean chamber pressure: the
                            probes of each probed mode, the model's merged points, 8 C10 I and
                            8 C10 A.
Runs with Debian's Python (python3-matplotlib, python3-h5py), Agg backend, no display.
Exit status: 0 on success, 1 on a missing/unreadable file or dataset (one line on stderr), 2 on
bad usage.
"""

import argparse
import os
import re
import sys
import textwrap

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.lines import Line2D  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))  # plot_common.py, from any cwd
from plot_common import InputError, attr_text, fail, load_or_fail, open_h5  # noqa: E402
from plot_common import read_dataset, save_or_fail  # noqa: E402

PROG = "plot_calibration"
FORMAT_PREFIX = "crawlsim-fe-calibration "
SEGMENTS = ("II1", "II2", "II3")
SEG_COLORS = ("C0", "C1", "C2")
KINDS = ("mode", "holdout", "symmetry", "gravity")


def load_cases(f, path, want_ratio):
    """The cases of an open table or predictions file: {name: dict of arrays and attributes}."""
    if "cases" not in f:
        raise InputError(f"{path}: no /cases group")
    cases = {}
    for name in sorted(f["cases"]):
        g = f["cases"][name]
        kind = attr_text(g.attrs["kind"]) if "kind" in g.attrs else None
        if kind not in KINDS:
            raise InputError(f"{path}: case {name} has no valid 'kind' attribute")
        c = {"name": name, "kind": kind}
        if kind == "gravity":
            cases[name] = c
            continue
        if want_ratio:
            try:
                c["ratio"] = [float(g.attrs[f"ratio{j}"]) for j in range(1, 5)]
            except KeyError as e:
                raise InputError(f"{path}: case {name} has no attribute {e}") from None
        base = f"/cases/{name}"
        c["p"] = read_dataset(f, f"{base}/pressure", path, (), rows="M")
        m = c["p"].shape[0]
        c["bend"] = read_dataset(f, f"{base}/bend", path, (3, 2), m)
        c["stretch"] = read_dataset(f, f"{base}/stretch", path, (3,), m)
        c["tip"] = read_dataset(f, f"{base}/tip", path, (3,), m)
        if want_ratio:
            c["radial_max"] = read_dataset(f, f"{base}/radial_max", path, (3,), m)
            if f"{base}/probe_pressure" in f:
                c["probe_p"] = read_dataset(f, f"{base}/probe_pressure", path, (), rows="K")
                k = c["probe_p"].shape[0]
                c["EI"] = read_dataset(f, f"{base}/EI", path, (3, 2), k)
                c["EA"] = read_dataset(f, f"{base}/EA", path, (3,), k)
        else:
            c["radius"] = read_dataset(f, f"{base}/radius", path, (3,), m)
        cases[name] = c
    return cases


def load_table(path):
    with open_h5(path) as f:
        fmt = attr_text(f.attrs["format"]) if "format" in f.attrs else ""
        if not fmt.startswith(FORMAT_PREFIX):
            raise InputError(f"{path}: not an FE calibration table of modes (format '{fmt}')")
        t = {"path": path, "cases": load_cases(f, path, True)}
        t["a"] = float(f.attrs["a"]) if "a" in f.attrs else np.nan
        t["actuator"] = attr_text(f.attrs["actuator"]) if "actuator" in f.attrs else "?"
        return t


def load_model(path):
    with open_h5(path) as f:
        if "model" not in f.attrs:
            raise InputError(f"{path}: not a calibration model's predictions (no 'model' attribute)")
        d = {"path": path, "name": attr_text(f.attrs["model"]), "cases": load_cases(f, path, False)}
        d["EI0"] = float(f.attrs["EI_8C10I_Nmm2"]) if "EI_8C10I_Nmm2" in f.attrs else None
        d["EA0"] = float(f.attrs["EA_8C10A_N"]) if "EA_8C10A_N" in f.attrs else None
        d["stiff"] = {}
        for s in range(3):
            for q in ("EI", "EA"):
                key = f"/stiffness/II{s + 1}/{q}"
                if key in f:
                    x = read_dataset(f, key + "_pbar", path, (), rows="n")
                    d["stiff"][(s, q)] = (x, read_dataset(f, key, path, (), x.shape[0]))
        return d


def angle_deg(bend):
    """|bend| per segment in degrees: bend is [M,3,2] rad."""
    return np.degrees(np.hypot(bend[..., 0], bend[..., 1]))


def pattern(c):
    r = c["ratio"]
    return ":".join(f"{x:.3g}" for x in r)


def grid(n, w=4.2, h=3.2):
    cols = min(4, max(1, n))
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(w * cols, h * rows), squeeze=False,
                             constrained_layout=True)
    for ax in axes.flat[n:]:
        ax.set_visible(False)
    return fig, list(axes.flat[:n])


def fe_and_model(ax, p, y_fe, mp, y_mod, color, label=None):
    ax.plot(p, y_fe, "o", ms=3.5, color=color, label=label)
    if mp is not None:
        ax.plot(mp, y_mod, "-", lw=1.4, color=color)
    else:
        ax.plot(p, y_fe, "-", lw=0.6, color=color, alpha=0.5)


def legend_handles(model):
    h = [Line2D([], [], color=c, lw=2, label=s) for s, c in zip(SEGMENTS, SEG_COLORS)]
    h.append(Line2D([], [], color="k", marker="o", ls="none", ms=4, label="FE"))
    if model is not None:
        h.append(Line2D([], [], color="k", lw=1.4, label="model"))
    return h


def plot_bend(t, model, out):
    modes = [c for c in t["cases"].values() if c["kind"] == "mode"]
    fig, axes = grid(len(modes))
    for ax, c in zip(axes, modes):
        mc = model["cases"].get(c["name"]) if model else None
        for s in range(3):
            fe_and_model(ax, c["p"], angle_deg(c["bend"])[:, s], mc["p"] if mc else None,
                         angle_deg(mc["bend"])[:, s] if mc else None, SEG_COLORS[s])
        ax.set_title(f"{c['name']} ({pattern(c)})", fontsize=10)
        ax.set_xlabel("pressure p (MPa)")
        ax.set_ylabel("segment bend angle (deg)")
        ax.grid(True, alpha=0.3)
    if axes:
        axes[0].legend(handles=legend_handles(model), fontsize=8, loc="upper left")
    fig.suptitle(f"Fitted modes: bend of each segment against pressure ({t['actuator']}; "
                 f"{os.path.basename(t['path'])})", fontsize=11)
    fig.savefig(out, dpi=100)
    plt.close(fig)


def plot_stretch(t, model, out):
    modes = [c for c in t["cases"].values() if c["kind"] == "mode"]
    fig, axes = grid(len(modes))
    for ax, c in zip(axes, modes):
        mc = model["cases"].get(c["name"]) if model else None
        ax2 = ax.twinx()
        for s in range(3):
            fe_and_model(ax, c["p"], c["stretch"][:, s] - 1, mc["p"] if mc else None,
                         mc["stretch"][:, s] - 1 if mc else None, SEG_COLORS[s])
            growth = c["radial_max"][:, s] - c["radial_max"][0, s]
            ax2.plot(c["p"], growth, "x", ms=3, color=SEG_COLORS[s], alpha=0.6)
            if mc is not None and np.isfinite(t["a"]):
                ax2.plot(mc["p"], mc["radius"][:, s] - t["a"], ":", lw=1, color=SEG_COLORS[s])
        ax.set_title(f"{c['name']} ({pattern(c)})", fontsize=10)
        ax.set_xlabel("pressure p (MPa)")
        ax.set_ylabel("stretch - 1 (o)")
        ax2.set_ylabel("largest radial growth, mm (x)")
        ax.grid(True, alpha=0.3)
    if axes:
        axes[0].legend(handles=legend_handles(model), fontsize=8, loc="upper left")
    fig.suptitle("Fitted modes: centreline stretch (o, left) and largest radial growth (x, right)",
                 fontsize=11)
    fig.savefig(out, dpi=100)
    plt.close(fig)


def holdout_layout(n, cols):
    """Rows and case columns of the held-out grid: each case is a cell of two panels side by side
    (bend, tip path), `cols` cells to a row (fewer when there are fewer cases)."""
    cols = max(1, min(cols, n))
    return (n + cols - 1) // cols, cols


def plot_holdout(t, model, out, cols=2):
    held = [c for c in t["cases"].values() if c["kind"] in ("holdout", "symmetry")]
    if not held:
        raise InputError(f"{t['path']}: no held-out or symmetry case to plot")
    # H2 before H10: the names' numbers in numeric order
    held.sort(key=lambda c: [(0, int(w), "") if w.isdigit() else (1, 0, w)
                             for w in re.split(r"(\d+)", c["name"]) if w])
    rows, cols = holdout_layout(len(held), cols)
    # 2.6 x 2.3 in a panel at 100 dpi: two cases a row are 1040 px wide, readable when the page
    # shows it at ~900 px (the README's width); the rows grow downwards instead of the strip
    fig, axes = plt.subplots(rows, 2 * cols, figsize=(2.6 * 2 * cols, 2.3 * rows + 0.7),
                             squeeze=False, constrained_layout=True)
    for k in range(len(held), rows * cols):
        axes[k // cols][2 * (k % cols)].set_visible(False)
        axes[k // cols][2 * (k % cols) + 1].set_visible(False)
    for k, c in enumerate(held):
        ax, axt = axes[k // cols][2 * (k % cols)], axes[k // cols][2 * (k % cols) + 1]
        mc = model["cases"].get(c["name"]) if model else None
        for s in range(3):
            fe_and_model(ax, c["p"], angle_deg(c["bend"])[:, s], mc["p"] if mc else None,
                         angle_deg(mc["bend"])[:, s] if mc else None, SEG_COLORS[s])
        ax.set_title(f"{c['name']} ({c['kind']}; {pattern(c)})", fontsize=9)
        ax.set_xlabel("pressure p (MPa)", fontsize=8)
        ax.set_ylabel("segment bend (deg)", fontsize=8)
        ax.tick_params(labelsize=7)
        ax.grid(True, alpha=0.3)
        # the tip's path in the base frame: e1 (towards Omega1&Omega2) across, e3 down the leg
        axt.plot(c["tip"][:, 0], c["tip"][:, 2], "ko", ms=2.5)
        if mc is not None:
            axt.plot(mc["tip"][:, 0], mc["tip"][:, 2], "r-", lw=1.3)
            n = min(len(mc["p"]), len(c["p"]))
            err = np.linalg.norm(mc["tip"][:n] - c["tip"][:n], axis=1).max()
            axt.set_title(f"{c['name']} tip path, worst {err:.2f} mm", fontsize=9)
        else:
            axt.set_title(f"{c['name']} tip path", fontsize=9)
        axt.set_xlabel("tip e1 (mm)", fontsize=8)
        axt.set_ylabel("tip e3 (mm)", fontsize=8)
        axt.tick_params(labelsize=7)
        axt.set_aspect("equal", adjustable="datalim")
        axt.grid(True, alpha=0.3)
    handles = legend_handles(model)
    handles.append(Line2D([], [], color="k", marker="o", ls="none", ms=3, label="FE tip"))
    if model is not None:
        handles.append(Line2D([], [], color="r", lw=1.3, label="model tip"))
    axes[0][0].legend(handles=handles, fontsize=7, loc="upper left")
    rule = f" ({model['name']})" if model is not None else ""
    # the model's name is a long sentence (rule, modes, ranges): wrapped to the figure's width
    title = (f"Held-out and symmetry cases of {os.path.basename(t['path'])}: "
             f"FE against the model{rule}")
    fig.suptitle(textwrap.fill(title, width=75 * cols), fontsize=9)
    fig.savefig(out, dpi=100)
    plt.close(fig)


def plot_stiffness(t, model, out):
    probed = [c for c in t["cases"].values() if "probe_p" in c]
    if not probed:
        raise InputError(f"{t['path']}: no stiffness probes to plot")
    fig, (ax_i, ax_a) = plt.subplots(1, 2, figsize=(12, 4.8), constrained_layout=True)
    markers = ("o", "s", "^", "D")
    for k, c in enumerate(probed):
        pbar = c["probe_p"] * np.mean(c["ratio"])
        for s in range(3):
            ax_i.plot(pbar, np.nanmean(c["EI"][:, s, :], axis=1), markers[k % 4], color=SEG_COLORS[s],
                      ms=5, mfc="none")
            ax_a.plot(pbar, c["EA"][:, s], markers[k % 4], color=SEG_COLORS[s], ms=5, mfc="none")
    if model is not None:
        for (s, q), (x, y) in sorted(model["stiff"].items()):
            (ax_i if q == "EI" else ax_a).plot(x, y, "-", lw=1.3, color=SEG_COLORS[s])
        if model["EI0"]:
            ax_i.axhline(model["EI0"], color="k", ls="--", lw=1, label="8 C10 I")
        if model["EA0"]:
            ax_a.axhline(model["EA0"], color="k", ls="--", lw=1, label="8 C10 A")
    handles = [Line2D([], [], color=c, lw=2, label=s) for s, c in zip(SEGMENTS, SEG_COLORS)]
    handles += [Line2D([], [], color="k", marker=markers[k % 4], mfc="none", ls="none",
                       label=f"probes of {c['name']}") for k, c in enumerate(probed)]
    for ax, q, unit in ((ax_i, "EI", "N mm$^2$"), (ax_a, "EA", "N")):
        ax.set_xlabel("mean chamber pressure (MPa)")
        ax.set_ylabel(f"{q} ({unit})")
        ax.grid(True, alpha=0.3)
        extra = [h for h in ax.get_legend_handles_labels()[0]]
        ax.legend(handles=handles + extra, fontsize=8)
    ax_i.set_title("bending stiffness (mean of the e1 and e2 probes)")
    ax_a.set_title("axial stiffness")
    fig.suptitle("Stiffness against pressure", fontsize=11)
    fig.savefig(out, dpi=100)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(description="Plot an FE calibration table and its model.")
    ap.add_argument("table", metavar="TABLE.h5", help="mode table of `crawlsim calibrate`")
    ap.add_argument("--model", metavar="PRED.h5", help="`crawlsim calibrate --model-out` file")
    ap.add_argument("-o", "--outdir", metavar="DIR", required=True, help="directory for the PNGs")
    ap.add_argument("--holdout-cols", metavar="N", type=int, default=2,
                    help="held-out cases to a row of calibration_holdout.png (default 2)")
    ap.add_argument("--only", metavar="KIND", choices=("bend", "stretch", "holdout", "stiffness"),
                    help="write this picture alone")
    args = ap.parse_args(argv)
    if args.holdout_cols < 1:
        ap.error("--holdout-cols must be at least 1")

    t = load_or_fail(PROG, load_table, args.table)
    model = load_or_fail(PROG, load_model, args.model) if args.model else None
    if not os.path.isdir(args.outdir):
        try:
            os.makedirs(args.outdir)
        except OSError as e:
            fail(PROG, f"{args.outdir}: cannot create ({e.strerror or e})")
    def holdout(t, model, out):
        plot_holdout(t, model, out, args.holdout_cols)

    for name, fn in (("bend", plot_bend), ("stretch", plot_stretch), ("holdout", holdout),
                     ("stiffness", plot_stiffness)):
        if args.only and name != args.only:
            continue
        out = os.path.join(args.outdir, f"calibration_{name}.png")
        try:
            save_or_fail(PROG, out, lambda fn=fn, out=out: fn(t, model, out))
        except InputError as e:
            print(f"{PROG}: {e}: {out} not written")
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/python3
"""plot_bend.py: plot bending angle vs pressure of one or more `crawlsim bend` files.

Usage:
  /usr/bin/python3 tools/plot_bend.py BEND.h5 [more.h5 ...] [-o OUT.png]

Reads the `bend` output contract of DESIGN.md ("Output contract (HDF5)"):
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

LINESTYLES = ["-", "--", "-.", ":", (0, (5, 1, 1, 1, 1, 1)), (0, (8, 2)), (0, (1, 3))]
SEGMENTS = ("II1", "II2", "II3")
SEGMENT_COLORS = ("C0", "C1", "C2")

# The actuator's name has no fixed attribute name in the contract; accept the usual spellings
# (compared after lower-casing and mapping ' ' and '-' to '_').
ACTUATOR_KEYS = ("actuator", "actuator_name", "geometry", "actuator_geometry", "name")


class InputError(Exception):
    """A missing or malformed input; reported as one line, exit status 1."""


def fail(msg):
    print(f"plot_bend: {msg}", file=sys.stderr)
    sys.exit(1)


def attr_text(value):
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    if isinstance(value, np.ndarray):
        if value.size == 1:
            return attr_text(value.reshape(-1)[0])
        return " ".join(attr_text(v) for v in value.reshape(-1))
    if isinstance(value, (np.floating, float)):
        return f"{float(value):g}"
    return str(value)


def find_attr(attrs, keys):
    norm = {k.lower().replace(" ", "_").replace("-", "_"): k for k in attrs}
    for key in keys:
        if key in norm:
            return attrs[norm[key]]
    return None


def read_dataset(f, path, fname, shape_tail, m=None):
    if path not in f:
        raise InputError(f"{fname}: missing dataset {path}")
    obj = f[path]
    if not hasattr(obj, "shape") or not hasattr(obj, "dtype"):
        raise InputError(f"{fname}: {path} is not a dataset")
    try:
        a = np.asarray(obj[()], dtype=float)
    except (TypeError, ValueError) as e:
        raise InputError(f"{fname}: {path} is not numeric ({e})") from None
    bad = a.ndim != len(shape_tail) + 1 or (m is not None and a.shape[0] != m)
    bad = bad or any(a.shape[1 + i] != s for i, s in enumerate(shape_tail))
    if bad:
        dims = ",".join(["M" if m is None else str(m)] + [str(s) for s in shape_tail])
        raise InputError(f"{fname}: {path} has shape {list(a.shape)}, expected [{dims}]")
    return a


def load_bend(path):
    import h5py

    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    try:
        f = h5py.File(path, "r")
    except OSError as e:
        raise InputError(f"{path}: not a readable HDF5 file ({str(e).splitlines()[0]})") from None
    with f:
        p = read_dataset(f, "/pressure", path, ())
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
        model = find_attr(f.attrs, ("model",))
        d["model"] = attr_text(model) if model is not None else None
        act = find_attr(f.attrs, ACTUATOR_KEYS)
        d["actuator"] = attr_text(act) if act is not None else None
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


def default_out(path):
    stem, _ = os.path.splitext(path)
    return stem + "_bend.png"


def main(argv=None):
    ap = argparse.ArgumentParser(description="Plot bending angle vs pressure of crawlsim bend files.")
    ap.add_argument("files", metavar="BEND.h5", nargs="+", help="outputs of `crawlsim bend`")
    ap.add_argument("-o", "--output", metavar="OUT.png", help="output PNG (default: first file's name + _bend.png)")
    args = ap.parse_args(argv)

    runs = []
    for path in args.files:
        try:
            runs.append(load_bend(path))
        except InputError as e:
            fail(str(e))
        except (OSError, KeyError, ImportError) as e:
            fail(f"{path}: {str(e).splitlines()[0] if str(e) else type(e).__name__}")
    out = args.output or default_out(args.files[0])
    try:
        plot_bend(runs, out)
    except OSError as e:
        fail(f"{out}: cannot write ({e.strerror or e})")
    print(f"plot_bend: wrote {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

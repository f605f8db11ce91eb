"""plot_common.py: HDF5 input helpers shared by tools/plot_track.py and tools/plot_bend.py.

Opening and checking a `crawlsim` output file, reading a dataset with a checked shape, reading
root attributes under their usual spellings, and the scripts' error reporting: a missing or
malformed input is one line "<script>: <message>" on stderr and exit status 1.

The scripts import this module from their own directory (they insert os.path.dirname(__file__)
into sys.path), so they run from any working directory.
"""

import os
import sys

import numpy as np


class InputError(Exception):
    """A missing or malformed input; reported as one line, exit status 1."""


def fail(prog, msg):
    """Print "<prog>: <msg>" on stderr and exit with status 1."""
    print(f"{prog}: {msg}", file=sys.stderr)
    sys.exit(1)


def attr_text(value):
    """An HDF5 attribute value as a short string (bytes, numpy scalars and 1-element arrays)."""
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
    """The raw value of the first attribute named by one of `keys` (None if there is none); names
    are compared after lower-casing and mapping ' ' and '-' to '_'."""
    norm = {k.lower().replace(" ", "_").replace("-", "_"): k for k in attrs}
    for key in keys:
        if key in norm:
            return attrs[norm[key]]
    return None


def find_attr_text(attrs, keys):
    """find_attr as a string (attr_text), None if there is no such attribute."""
    value = find_attr(attrs, keys)
    return attr_text(value) if value is not None else None


def read_dataset(f, path, fname, shape_tail, m=None, rows="N"):
    """Read dataset `path` of the open file `f` (named `fname` in messages) as float64 and check
    its shape: [m] + shape_tail, where m=None allows any number of rows (called `rows` in the
    message) and a None in shape_tail allows any size (called K)."""
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
    bad = bad or any(s is not None and a.shape[1 + i] != s for i, s in enumerate(shape_tail))
    if bad:
        dims = ",".join([rows if m is None else str(m)] + ["K" if s is None else str(s) for s in shape_tail])
        raise InputError(f"{fname}: {path} has shape {list(a.shape)}, expected [{dims}]")
    return a


def open_h5(path):
    """Open an HDF5 file for reading (use it in a `with`); InputError if it is missing or not
    HDF5. h5py is imported here so that a missing h5py is reported like other input errors."""
    import h5py

    if not os.path.isfile(path):
        raise InputError(f"{path}: no such file")
    try:
        return h5py.File(path, "r")
    except OSError as e:
        raise InputError(f"{path}: not a readable HDF5 file ({str(e).splitlines()[0]})") from None


def load_or_fail(prog, load, path):
    """load(path), or exit 1 with one line on stderr when the input is missing or malformed."""
    try:
        return load(path)
    except InputError as e:
        fail(prog, str(e))
    except (OSError, KeyError, ImportError) as e:
        fail(prog, f"{path}: {str(e).splitlines()[0] if str(e) else type(e).__name__}")


def save_or_fail(prog, out, draw):
    """draw() writes the PNG `out`; then "<prog>: wrote <out>" on stdout, or exit 1 with one
    line on stderr if the file cannot be written."""
    try:
        draw()
    except OSError as e:
        fail(prog, f"{out}: cannot write ({e.strerror or e})")
    print(f"{prog}: wrote {out}")


def default_out(path, suffix):
    """The input's path without its extension, plus `suffix` (e.g. "_track.png")."""
    stem, _ = os.path.splitext(path)
    return stem + suffix


# What a run's picture title names (issue 36): scene, conditions, legs, calibration and the
# terrain's slope, from the run file's root attributes (core/sim_run.c).
RUN_TITLE_ATTRS = {
    "scene": ("scene",),
    "conditions": ("conditions",),
    "legs": ("leg_model",),
    "links": ("links_per_segment",),
    "calibration": ("calibration",),
    "rule": ("calibration_rule",),
    "slope": ("slope_deg",),
    "gait": ("gait_file",),
}


def run_title_attrs(f):
    """The root attributes a run title uses, as strings (None where the file has none)."""
    return {k: find_attr_text(f.attrs, keys) for k, keys in RUN_TITLE_ATTRS.items()}


def run_title(a):
    """One line: "scene S (slope A deg), conditions C, legs L (n per segment), calibration CAL
    (rule R), gait G" from run_title_attrs; unknown parts are left out."""
    parts = []
    if a.get("scene"):
        s = f"scene {a['scene']}"
        try:
            if a.get("slope") and float(a["slope"]) != 0:
                s += f" (slope {float(a['slope']):g} deg)"
        except ValueError:
            pass
        parts.append(s)
    if a.get("conditions"):
        parts.append(f"conditions {a['conditions']}")
    if a.get("legs"):
        s = f"legs {a['legs']}"
        if a.get("links") and a["legs"] == "rod":
            s += f" ({a['links']} per segment)"
        parts.append(s)
    if a.get("calibration"):
        s = f"calibration {os.path.basename(a['calibration'])}"
        if a.get("rule") and a["rule"] != "none":
            s += f" ({a['rule']})"
        parts.append(s)
    if a.get("gait"):
        parts.append(f"gait {os.path.basename(a['gait'])}")
    return ", ".join(parts)

"""plot_study_common.py: what the study table scripts share (tools/plot_study_sec4.py,
tools/plot_study_earth.py): their command line (STUDY.h5 [-o OUT.png] [--md OUT.md]), opening a
merged `crawlsim study` file with the one-line error of plot_common.py, and number formatting
that leaves a missing value (NaN) as an empty table cell."""

import argparse
import math

from plot_common import InputError, fail, open_h5


def parse_args(prog, doc, extra=None):
    """The scripts' arguments; `extra(ap)` may add more."""
    ap = argparse.ArgumentParser(prog=prog, description=doc.split("\n")[0])
    ap.add_argument("study", help="merged study file (crawlsim study ... --out STUDY.h5)")
    ap.add_argument("-o", "--out", help="PNG (default: STUDY.png)")
    ap.add_argument("--md", help="also write the Markdown table here")
    if extra:
        extra(ap)
    return ap.parse_args()


def open_study(path, prog):
    """The open study file (use it in a `with`), or exit 1 with one line on stderr."""
    try:
        f = open_h5(path)
    except InputError as e:
        fail(prog, str(e))
    if "cases" not in f:
        f.close()
        fail(prog, f"{path}: not a crawlsim study file (no /cases)")
    return f


def fmt(v, spec):
    """format(v, spec), or "" for None and non-finite values."""
    return "" if v is None or not math.isfinite(v) else format(v, spec)

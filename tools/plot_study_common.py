"""plot_study_common.py: what the study table scripts share (tools/plot_study_sec4.py,
tools/plot_study_earth.py): their command line (STUDY.h5 [-o OUT.png] [--md OUT.md]), opening a
merged `crawlsim study` file with the one-line error of plot_common.py, and number formatting
that leaves a missing value (NaN) as an empty table cell; and what the study drivers share
(tools/slope_study.py, tools/paper_gait_study.py): running a study resumably and writing a table
between two markers of a Markdown page."""

import argparse
import math
import os
import subprocess
import sys

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


def run_study(crawlsim, study, merged, case_dir, report_only):
    """`crawlsim study STUDY --out MERGED --dir CASE_DIR --resume` (or --merge-only when
    report_only: nothing runs); returns crawlsim's exit code."""
    args = [crawlsim, "study", study, "--out", merged, "--dir", case_dir]
    args += ["--merge-only"] if report_only else ["--resume"]
    return subprocess.run(args).returncode


def fill_markers(md, begin, end, lines, prog):
    """Replace what stands between the markers `begin` and `end` of the page md by lines (a
    list of str); False (with one line on stderr) when the page lacks the markers."""
    with open(md) as f:
        body = f.read()
    i, j = body.find(begin), body.find(end)
    if i < 0 or j < i:
        print(f"{prog}: {md} has no table markers", file=sys.stderr)
        return False
    body = body[:i + len(begin)] + "\n" + "\n".join(lines) + "\n" + body[j:]
    with open(md, "w") as f:
        f.write(body)
    return True


def study_paths(work, name):
    """(merged study file, case folder) of a study driven from the work folder"""
    os.makedirs(work, exist_ok=True)
    return os.path.join(work, name + ".h5"), os.path.join(work, "cases")

#!/usr/bin/env python3
"""plot_gait.py: heat map of a gait table, the 96 chamber labels against time (as the paper's
Figs. 11 and 13: "minimum P_in required", one column per time).

    /usr/bin/python3 tools/plot_gait.py GAIT.csv [-o OUT.png] [--dt S] [--t-end S]

GAIT.csv is a crawlsim gait table (gaits/gaits_csv.h: `time`, then chamber columns by name
<leg>_II<s>_O<j> or by label 1..96; missing chambers are 0 MPa). The table is drawn as its
rows hold (each row's pressures from its time to the next row's: the run's ramp is not drawn),
sampled every --dt s (default: 0.01 s or finer so no row is skipped), labels 1..96 upwards
(label = 12 k + 4 (s - 1) + j, k = 0..7 for A..H), with the legs' bands marked. A bad file is
one line "plot_gait.py: <file>:<line>: <cause>" on stderr and exit status 1.
Uses Debian's /usr/bin/python3 (python3-matplotlib).
"""

import argparse
import os
import re
import sys

PROG = "plot_gait.py"
LEGS = "ABCDEFGH"


def fail(msg):
    print(f"{PROG}: {msg}", file=sys.stderr)
    sys.exit(1)


def label_of(name, path, line):
    """Chamber label 1..96 of a header field (A_II1_O3 or a number)."""
    if re.fullmatch(r"[0-9]+", name):
        lab = int(name)
        if 1 <= lab <= 96:
            return lab
        fail(f"{path}:{line}: label {name} is outside 1..96")
    m = re.fullmatch(r"([A-H])_II([1-3])_O([1-4])", name)
    if not m:
        fail(f"{path}:{line}: column '{name[:40]}' is not a chamber (A_II1_O1 .. H_II3_O4 or 1..96)")
    k = LEGS.index(m.group(1))
    return 12 * k + 4 * (int(m.group(2)) - 1) + int(m.group(3))


def read_gait(path):
    """(times, rows of 96 pressures) of a gait CSV; the reader's main checks, with line numbers."""
    try:
        with open(path, "r", encoding="utf-8-sig") as f:
            lines = f.read().splitlines()
    except OSError as e:
        fail(f"{path}: cannot open gait table: {e.strerror}")
    header, labels, times, rows = None, None, [], []
    for no, text in enumerate(lines, 1):
        s = text.strip()
        if not s or s.startswith("#"):
            continue
        fields = [x.strip() for x in s.split(",")]
        if header is None:
            if fields[0] != "time":
                fail(f"{path}:{no}: header must start with 'time', got '{fields[0][:30]}'")
            header = fields
            labels = [label_of(x, path, no) for x in fields[1:]]
            if len(set(labels)) != len(labels):
                fail(f"{path}:{no}: a chamber is given twice")
            continue
        if len(fields) != len(header):
            fail(f"{path}:{no}: {len(fields)} fields, the header has {len(header)}")
        try:
            vals = [float(x) for x in fields]
        except ValueError:
            fail(f"{path}:{no}: a field is not a number")
        if times and not vals[0] > times[-1]:
            fail(f"{path}:{no}: time {vals[0]} s is not after {times[-1]} s")
        row = [0.0] * 96
        for lab, v in zip(labels, vals[1:]):
            if not 0 <= v <= 1:
                fail(f"{path}:{no}: pressure {v} MPa is outside 0..1")
            row[lab - 1] = v
        times.append(vals[0])
        rows.append(row)
    if not rows:
        fail(f"{path}:{len(lines) or 1}: no data rows")
    return times, rows


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("gait")
    ap.add_argument("-o", "--out", help="PNG to write (default: GAIT.png)")
    ap.add_argument("--dt", type=float, default=None, help="sampling interval (s)")
    ap.add_argument("--t-end", type=float, default=None, help="end of the time axis (s)")
    a = ap.parse_args()
    import numpy as np
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    times, rows = read_gait(a.gait)
    t_end = a.t_end if a.t_end is not None else max(times[-1], times[0] + 1e-3)
    gaps = [b - c for b, c in zip(times[1:], times[:-1])]
    dt = a.dt if a.dt else min([0.01] + [g / 2 for g in gaps])
    if not (dt > 0 and t_end > 0):
        fail("--dt and --t-end must be > 0")
    n = int(np.ceil(t_end / dt)) + 1
    if n > 20000:
        dt = t_end / 20000
        n = 20001
    ts = np.arange(n) * dt
    idx = np.searchsorted(np.array(times), ts, side="right") - 1
    P = np.zeros((96, n))
    R = np.array(rows)
    ok = idx >= 0
    P[:, ok] = R[idx[ok]].T
    fig, ax = plt.subplots(figsize=(10, 7))
    im = ax.imshow(P, aspect="auto", origin="lower", interpolation="nearest", cmap="viridis",
                   extent=[ts[0] - dt / 2, ts[-1] + dt / 2, 0.5, 96.5], vmin=0,
                   vmax=max(1e-6, P.max()))
    for k in range(1, 8):
        ax.axhline(12 * k + 0.5, color="w", lw=0.6, alpha=0.6)
    ax.set_yticks([12 * k + 6.5 for k in range(8)])
    ax.set_yticklabels([f"{LEGS[k]}  {12 * k + 1}-{12 * k + 12}" for k in range(8)])
    ax.set_xlabel("time (s)")
    ax.set_ylabel("chamber label (leg, labels)")
    ax.set_xticks(np.arange(0, np.floor(t_end) + 1, 1.0 if t_end <= 40 else 5.0))
    ax.set_title(f"gait {os.path.basename(a.gait)}: chamber pressure (MPa)")
    fig.colorbar(im, ax=ax, label="P_in (MPa)")
    out = a.out or os.path.splitext(a.gait)[0] + ".png"
    try:
        fig.savefig(out, dpi=90, bbox_inches="tight")
    except OSError as e:
        fail(f"{out}: cannot write: {e.strerror}")
    print(f"{out}: heat map of {len(rows)} rows, 0..{t_end:g} s")


if __name__ == "__main__":
    main()

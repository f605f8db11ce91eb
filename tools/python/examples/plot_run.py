#!/usr/bin/python3
"""plot_run.py: read a run's HDF5 file with the crawlsim package and plot it (issue 35's second
example; docs/reference/python.md).

Usage:
  /usr/bin/python3 tools/python/examples/plot_run.py RUN.h5 [-o OUT.png]

Any file `crawlsim run --out RUN.h5` or `crawlsim.run(out="RUN.h5")` wrote. Three panels:
  (a) top view of the support's track (x crawl, z lateral, mm) with its heading every second;
  (b) the support's displacement x, y, z (mm) and its heading (deg, right axis) against time;
  (c) the footfall: one row per leg A..H, dark while the leg stands (/contact/stance).
Needs python3-matplotlib and python3-h5py. Exit status 0, or 1 with one line on stderr when the
file cannot be read or the picture cannot be written.
"""

import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import crawlsim  # noqa: E402


def draw(run, out):
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6))
    x, y, z = run.position.T
    psi = run.heading
    # (a) top view: x along the page, z down the page as seen from above (+y): the legs A-D side
    # (-z) on top
    a = ax[0]
    a.plot(x, z, color="C0")
    every = max(1, int(round(1.0 / max(np.median(np.diff(run.t)), 1e-9)))) if len(run.t) > 1 else 1
    for k in range(0, len(run.t), every):
        r = np.radians(psi[k])
        a.annotate("", xy=(x[k] + 15 * np.cos(r), z[k] - 15 * np.sin(r)), xytext=(x[k], z[k]),
                   arrowprops=dict(arrowstyle="->", color="C3", lw=1))
    a.set_xlabel("x (mm)")
    a.set_ylabel("z (mm)")
    a.invert_yaxis()
    a.set_aspect("equal", adjustable="datalim")
    a.set_title("(a) support track from above, heading every 1 s")
    # (b) displacement and heading against time
    b = ax[1]
    for k, (v, name) in enumerate(((x, "x"), (y, "y"), (z, "z"))):
        b.plot(run.t, v, color=f"C{k}", label=name)
    b.set_xlabel("t (s)")
    b.set_ylabel("displacement (mm)")
    b2 = b.twinx()
    b2.plot(run.t, psi, color="C3", ls="--", label="heading")
    b2.set_ylabel("heading (deg)")
    h1, l1 = b.get_legend_handles_labels()
    h2, l2 = b2.get_legend_handles_labels()
    b.legend(h1 + h2, l1 + l2, loc="upper left", fontsize=8)
    b.set_title("(b) support displacement and heading")
    # (c) footfall
    c = ax[2]
    if run.stance is not None and len(run.t) > 1:
        c.imshow(run.stance.T, aspect="auto", cmap="Greys", vmin=0, vmax=1, interpolation="nearest",
                 extent=(run.t[0], run.t[-1], 7.5, -0.5))
        c.set_yticks(range(8), list(crawlsim.LEGS))
        c.set_xlabel("t (s)")
        c.set_title("(c) stance (dark) per leg")
    else:
        c.text(0.5, 0.5, "no /contact/stance in this file", ha="center", transform=c.transAxes)
        c.set_axis_off()
    a_ = run.attrs
    fig.suptitle(f"{os.path.basename(run.path)}: scene {a_.get('scene')}, legs "
                 f"{a_.get('leg_model')}, conditions {a_.get('conditions')}, status {run.status}",
                 fontsize=10)
    fig.tight_layout()
    fig.savefig(out, dpi=110)
    plt.close(fig)


def main(argv=None):
    ap = argparse.ArgumentParser(prog="plot_run", description=__doc__.split("\n")[0])
    ap.add_argument("run", help="a run's HDF5 file")
    ap.add_argument("-o", "--out", help="the PNG (default: RUN without .h5 + _run.png)")
    args = ap.parse_args(argv)
    out = args.out or os.path.splitext(args.run)[0] + "_run.png"
    try:
        run = crawlsim.read_run(args.run)
    except crawlsim.Error as e:
        print(f"plot_run: {e}", file=sys.stderr)
        return 1
    try:
        draw(run, out)
    except OSError as e:
        print(f"plot_run: {out}: cannot write ({e.strerror or e})", file=sys.stderr)
        return 1
    print(f"plot_run: {run!r} -> {out}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

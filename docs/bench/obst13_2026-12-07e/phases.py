#!/usr/bin/python3
"""The support's x, z at the table's phase boundaries for each run file, beside the nominal.
Table time rebuilt from gate/waits (ramp11's lag.py); the crawl's skip is not added, so the
times are read up to the crawl's start (27.39 s) and the run's end.
usage: /usr/bin/python3 phases.py NOMINAL.h5 RUN.h5..."""
import sys

import h5py
import numpy as np

T = [4.0, 5.8, 9.4, 11.76, 13.84, 16.24, 19.24, 21.04, 24.64, 25.74, 26.84, 27.39]


def table_time(f):
    t = f["time"][:]
    w = f["gate/waits"][:] if "gate/waits" in f else np.zeros((0, 2))
    tau = t.copy()
    held = 0.0
    for Tk, wait in w:
        if not wait > 0:
            continue
        start = Tk + held
        tau = np.where(t >= start + wait, tau - wait, np.where(t > start, Tk, tau))
        held += wait
    return t, tau


def at(fn):
    with h5py.File(fn, "r") as f:
        t, tau = table_time(f)
        p = f["support/position"][:]
        out = []
        for tt in T:
            i = np.nonzero(tau >= tt - 1e-9)[0]
            out.append(p[i[0]] if len(i) else np.array([np.nan] * 3))
        out.append(p[-1])
    return np.array(out)


def main():
    ref = at(sys.argv[1])
    print("table s  " + " ".join("%7.2f" % x for x in T) + "    end")
    for fn in sys.argv[1:]:
        a = at(fn)
        name = fn.split("/")[-1].replace(".h5", "")
        print("%-8s x " % name + " ".join("%7.1f" % v for v in a[:, 0]))
        if fn != sys.argv[1]:
            print("%-8s dx" % "" + " ".join("%7.1f" % v for v in a[:, 0] - ref[:, 0]))
        print("%-8s z " % "" + " ".join("%7.1f" % v for v in a[:, 2]))


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""compare.py A B [long|earth]: runs.sh's runs of builds A and B (/tmp/legpass19/runs): the
largest difference over the run of the support's track and of every leg's centre line (mm), of
the foot forces (N), and how many datasets are identical bit for bit (bytes; NaN fills compare
equal). The measure of ../bdf15_2026-12-07f/compare.py, for the default's runs."""
import sys

import h5py
import numpy as np


def datasets(f):
    out = {}
    f.visititems(lambda n, o: out.__setitem__(n, o[()]) if isinstance(o, h5py.Dataset) else None)
    return out


def report(path_a, path_b):
    a, b = datasets(h5py.File(path_a, "r")), datasets(h5py.File(path_b, "r"))
    same = [n for n in a if np.asarray(a[n]).tobytes() == np.asarray(b[n]).tobytes()]
    track = np.abs(a["support/position"] - b["support/position"]).max()
    legs = max(np.abs(a[f"legs/{k}/centerline"] - b[f"legs/{k}/centerline"]).max()
               for k in "ABCDEFGH")
    feet = np.nanmax(np.abs(a["contact/foot_force"] - b["contact/foot_force"]))
    return (f"support track {track:.3e} mm, leg centre lines {legs:.3e} mm, foot forces "
            f"{feet:.3e} N, datasets bit for bit: {len(same)} of {len(a)}")


mode = sys.argv[3] if len(sys.argv) > 3 else "o1"
scenes = ["flat-road"] if mode == "earth" else ["flat-road", "obstacle"]
for s in scenes:
    f = "/tmp/legpass19/runs/{}." + f"{mode}.{s}.h5"
    print(f"{mode} {s}: {report(f.format(sys.argv[1]), f.format(sys.argv[2]))}")

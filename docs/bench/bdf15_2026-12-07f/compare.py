"""compare.py A B [long|paper]: runs.sh's runs of A and B (/tmp/bdf15/runs,
or $BDF_SCRATCH/runs): the support's track and
every leg's centre line, the largest difference (mm) over the run, and whether every dataset is
identical bit for bit (bytes: NaN fills compare equal). /usr/bin/python3 compare.py base new"""
import os
import sys

import h5py
import numpy as np

A, B = sys.argv[1], sys.argv[2]
RUNS = os.environ.get("BDF_SCRATCH", "/tmp/bdf15") + "/runs"
mode = sys.argv[3] if len(sys.argv) > 3 else ""
cases = [("long", "flat-road"), ("long", "obstacle")] if mode == "long" else \
    [("paper", "flat-road"), ("earth", "flat-road")] if mode == "paper" else \
    [(t, s) for t in ("o1", "o2") for s in ("flat-road", "obstacle")]
for t, s in cases:
    a = h5py.File(f"{RUNS}/{A}.{t}.{s}.h5", "r")
    b = h5py.File(f"{RUNS}/{B}.{t}.{s}.h5", "r")
    names = []
    a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
    diff = [n for n in names if np.asarray(a[n][()]).tobytes() != np.asarray(b[n][()]).tobytes()]
    dtrack = np.abs(a["support/position"][()] - b["support/position"][()]).max()
    dleg = max(np.abs(a[f"legs/{k}/centerline"][()] - b[f"legs/{k}/centerline"][()]).max()
               for k in "ABCDEFGH")
    dff = np.nanmax(np.abs(a["contact/foot_force"][()] - b["contact/foot_force"][()]))
    print(f"{t} {s}: support track {dtrack:.3e} mm, leg centre lines {dleg:.3e} mm, "
          f"foot forces {dff:.3e} N, "
          f"datasets bit for bit: {len(names) - len(diff)} of {len(names)}"
          + (f" (differ: {', '.join(diff[:6])}{' ...' if len(diff) > 6 else ''})" if diff else ""))

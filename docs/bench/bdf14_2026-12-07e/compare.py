"""compare.py: main's (base) and this branch's (new) runs of runs.sh, /tmp/bdf14/runs: the
support's track and every leg's centre line, the largest difference (mm) over the 2 s, and
whether every dataset is identical bit for bit (bytes: NaN fills compare equal). /usr/bin/python3 compare.py"""
import h5py
import numpy as np

import sys
NEW = sys.argv[1] if len(sys.argv) > 1 else "new"
for t in ("o1", "o2"):
    for s in ("flat-road", "obstacle"):
        a = h5py.File(f"/tmp/bdf14/runs/base.{t}.{s}.h5", "r")
        b = h5py.File(f"/tmp/bdf14/runs/{NEW}.{t}.{s}.h5", "r")
        names = []
        a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        same = all(np.asarray(a[n][()]).tobytes() == np.asarray(b[n][()]).tobytes() for n in names)
        dtrack = np.abs(a["support/position"][()] - b["support/position"][()]).max()
        dleg = max(np.abs(a[f"legs/{k}/centerline"][()] - b[f"legs/{k}/centerline"][()]).max()
                   for k in "ABCDEFGH")
        print(f"{t} {s}: support track {dtrack:.3e} mm, leg centre lines {dleg:.3e} mm, "
              f"all datasets bit for bit: {same}")

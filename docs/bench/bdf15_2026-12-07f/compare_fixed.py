"""compare_fixed.py: main's (base) and the final's (kin) extra BDF2 runs in /tmp/bdf15/runs
(runs.sh's note: fixed 0.5 ms and 5 ms on the flat road's 2 s; the obstacle's whole climb at
adaptive 5e-4 mm): support track, leg centre lines, datasets bit for bit, the end point."""
import h5py
import numpy as np

for tag, what in (("f2.flat-road", "BDF2 fixed 0.5 ms, flat road 2 s"),
                  ("f2_5ms.flat-road", "BDF2 fixed 5 ms, flat road 2 s"),
                  ("climb.obstacle", "BDF2 adaptive 5e-4, the obstacle's whole climb")):
    try:
        a = h5py.File(f"/tmp/bdf15/runs/base.{tag}.h5", "r")
        b = h5py.File(f"/tmp/bdf15/runs/kin.{tag}.h5", "r")
    except OSError:
        print(f"{what}: not run")
        continue
    names = []
    a.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
    diff = [n for n in names if np.asarray(a[n][()]).tobytes() != np.asarray(b[n][()]).tobytes()]
    pa, pb = a["support/position"][()], b["support/position"][()]
    dleg = max(np.abs(a[f"legs/{k}/centerline"][()] - b[f"legs/{k}/centerline"][()]).max()
               for k in "ABCDEFGH")
    print(f"{what}: support {np.abs(pa - pb).max():.3e} mm, centre lines {dleg:.3e} mm, "
          f"bit for bit {len(names) - len(diff)} of {len(names)}; end {pa[-1]} / {pb[-1]} mm")

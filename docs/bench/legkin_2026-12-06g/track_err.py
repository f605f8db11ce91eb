#!/usr/bin/python3
"""track_err.py REF_DIR RUN.h5...: each run's support track against the rod-32 reference of its
scene (flat road 9 s, obstacle first 4 s; the files tools/bench_levels.py names
track-flat-road-rod-l32-m1-dt0.00025.h5 and track-obstacle-rod-l32-m1-dt0.00025-t4.h5 in
REF_DIR), by bench_levels.py's own measure (track_error: max over whole seconds of |(dx, dz)|,
mm); prints the error, x at the end and the largest difference from the first run of the same
scene given (mm, max over whole seconds)."""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "../../../tools"))
import bench_levels as bl  # noqa: E402

ref_dir, runs = sys.argv[1], sys.argv[2:]
refs = {"flat-road": os.path.join(ref_dir, "track-flat-road-rod-l32-m1-dt0.00025.h5"),
        "obstacle": os.path.join(ref_dir, "track-obstacle-rod-l32-m1-dt0.00025-t4.h5")}
first = {}
for r in runs:
    scene = "obstacle" if os.path.basename(r).startswith("obstacle") else "flat-road"
    err = bl.track_error({"h5": r}, {"h5": refs[scene]})
    t, p, status = bl.read_track(r)
    base = first.setdefault(scene, r)
    d0 = bl.track_error({"h5": r}, {"h5": base})
    print(f"{os.path.basename(r)}: {scene} vs rod-32 {err:.3f} mm, x(end {t[-1]:g} s) "
          f"{p[-1, 0]:.3f} mm, vs {os.path.basename(base)} {d0:.3f} mm, status {status}")

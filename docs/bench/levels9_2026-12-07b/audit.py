#!/usr/bin/python3
"""audit.py: the numbers of docs/notes/issue32_status.md from the run files (no runs).

Errors are tools/bench_levels.py's measure (max over the whole seconds both runs reach of
|(dx, dz)| of the support, mm). Inputs: the runs of queue.sh (RUNS, default
/work/rom_data/levels9/runs), the quiet run's cache of 2026-12-07 04:46 UTC (Q, default
/work/rom_data/levels9/quiet8_W: docs/bench/quiet8_2026-12-07's points, its rod references =
/work/rom_data/levels_ref9). Prints one line per number."""
import math
import os
import sys

import h5py
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "..", "tools"))
import bench_levels as bl  # noqa: E402

RUNS = os.environ.get("RUNS", "/work/rom_data/levels9/runs")
Q = os.environ.get("Q", "/work/rom_data/levels9/quiet8_W")


def h(path):
    return {"h5": path}


def err(a, b):
    try:
        return bl.track_error(h(a), h(b))
    except (OSError, KeyError, IndexError):
        return float("nan")  # not run (yet)


def per_second(a, b):
    t, p, _ = bl.read_track(a)
    tr, pr, _ = bl.read_track(b)
    out = []
    for s in range(1, int(math.floor(min(t[-1], tr[-1]) + 1e-9)) + 1):
        i, j = int(np.argmin(abs(t - s))), int(np.argmin(abs(tr - s)))
        out.append((s, p[i, 0] - pr[j, 0], p[i, 2] - pr[j, 2]))
    return out


def same(a, b):
    """every dataset of two run files equal bit for bit (the timers and wall-time attributes
    differ by nature and are not datasets)"""
    with h5py.File(a, "r") as fa, h5py.File(b, "r") as fb:
        names = []
        fa.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
        diff = [n for n in names if n not in fb or fa[n].shape != fb[n].shape or
                not np.array_equal(fa[n][()], fb[n][()])]
        return len(names), diff


def attrs(path, names):
    with h5py.File(path, "r") as f:
        return {n: f.attrs.get(n) for n in names}


def R(tag):
    return os.path.join(RUNS, tag + ".h5")


def main():
    flat_ref = os.path.join(Q, "track-flat-road-rod-l32-m1-dt0.00025.h5")
    obst_ref = os.path.join(Q, "track-obstacle-rod-l32-m1-dt0.00025-t4.h5")
    print("# accuracy on today's default (strain 2 modes, adaptive 2.5e-4 mm, sub 2)")
    print(f"flat road (designed gait, 9.5 s) vs rod 32 / 0.25 ms: {err(R('def_flat'), flat_ref):.3f} mm")
    print(f"obstacle first 4 s vs rod 32 / 0.25 ms: {err(R('def_obst4'), obst_ref):.3f} mm")
    print(f"paper table (9 s) vs rod 32 / 0.25 ms: {err(R('def_paper'), R('rod32_paper')):.3f} mm")
    if os.path.exists(R("def_paper")) and os.path.exists(R("rod32_paper")):
        for s, dx, dz in per_second(R("def_paper"), R("rod32_paper")):
            print(f"  paper {s} s: dx {dx:+.3f} dz {dz:+.3f} mm")
    print("# the paper table's reference against the same rod at 0.5 ms (branch strainacc, sixth "
          "session: /work/rom_data/strainacc/p_rod32_05ms.h5) and the default against the eighth "
          "session's run of it (/work/rom_data/strdef/def_paper.h5)")
    print(f"rod 32: 0.25 vs 0.5 ms: {err(R('rod32_paper'), '/work/rom_data/strainacc/p_rod32_05ms.h5'):.3f} mm; "
          f"default vs rod 32 at 0.5 ms: {err(R('def_paper'), '/work/rom_data/strainacc/p_rod32_05ms.h5'):.3f} mm; "
          f"default now vs strdef's: {err(R('def_paper'), '/work/rom_data/strdef/def_paper.h5'):.2e} mm")
    print(f"rod 32 at 0.125 ms (rod32_paper_0125): default {err(R('def_paper'), R('rod32_paper_0125')):.3f} mm, "
          f"rod 32 0.25 ms {err(R('rod32_paper'), R('rod32_paper_0125')):.3f} mm, half tolerance "
          f"{err(R('half_paper'), R('rod32_paper_0125')):.3f} mm, grid 4.5 / 5.5 ms "
          f"{err(R('grid45_paper'), R('rod32_paper_0125')):.3f} / {err(R('grid55_paper'), R('rod32_paper_0125')):.3f} mm")
    print("# the quiet run's adaptive points (its own files) against the same references")
    for tol in ("0.00025", "0.0005"):
        a = os.path.join(Q, f"track-flat-road-strain-l2-m1-dt0.005-o1-a{tol}.h5")
        b = os.path.join(Q, f"track-obstacle-strain-l2-m1-dt0.005-o1-a{tol}-t4.h5")
        print(f"quiet adaptive {tol}: flat {err(a, flat_ref):.3f}, obstacle 4 s {err(b, obst_ref):.3f} mm")
    print(f"this session's default flat vs the quiet run's 2.5e-4 point: "
          f"{err(R('def_flat'), os.path.join(Q, 'track-flat-road-strain-l2-m1-dt0.005-o1-a0.00025.h5')):.2e} mm")
    print("# convergence in the step (fixed steps, backward Euler, quiet cache): half-step distances")
    for scene, suf in (("flat-road", ""), ("obstacle", "-t4")):
        f = {dt: os.path.join(Q, f"track-{scene}-strain-l2-m1-dt{dt}-o1{suf}.h5")
             for dt in ("0.005", "0.002", "0.001", "0.0005")}
        d52 = err(f["0.005"], f["0.002"])
        d21 = err(f["0.002"], f["0.001"])
        d105 = err(f["0.001"], f["0.0005"])
        # order from d(h, h/2) ~ C h^p (2 -> 1 -> 0.5 ms: halvings)
        p = math.log(d21 / d105, 2) if d105 > 0 and d21 > 0 else float("nan")
        print(f"{scene}: |5-2| {d52:.3f}, |2-1| {d21:.3f}, |1-0.5| {d105:.3f} mm; order from "
              f"2/1/0.5 ms {p:.2f}; vs rod 32: 5/2/1/0.5 ms "
              + ", ".join(f"{err(f[d], flat_ref if scene == 'flat-road' else obst_ref):.2f}"
                          for d in ("0.005", "0.002", "0.001", "0.0005")))
    print("# the tolerance halved (the convergence rule on the adaptive step)")
    print(f"flat: 2.5e-4 vs 1.25e-4: {err(R('def_flat'), R('half_flat')):.3f} mm")
    print(f"obstacle 4 s: 2.5e-4 vs 1.25e-4: {err(R('def_obst4'), R('half_obst4')):.3f} mm")
    print(f"paper: 2.5e-4 vs 1.25e-4: {err(R('def_paper'), R('half_paper')):.3f} mm")
    print("# noise floor (paper table): the longest step 4.5 / 5.5 ms against 5 ms")
    print(f"paper: {err(R('grid45_paper'), R('def_paper')):.3f} / {err(R('grid55_paper'), R('def_paper')):.3f} mm")
    print(f"paper rod 32 vs grid runs: {err(R('grid45_paper'), R('rod32_paper')):.3f} / "
          f"{err(R('grid55_paper'), R('rod32_paper')):.3f} mm; half tolerance {err(R('half_paper'), R('rod32_paper')):.3f} mm")
    print("# determinism: the default flat road twice")
    if os.path.exists(R("def_flat")) and os.path.exists(R("def_flat_again")):
        n, diff = same(R("def_flat"), R("def_flat_again"))
        print(f"{n} datasets, {len(diff)} differ {diff[:5]}")
    names = ["status", "steps", "rejected_steps", "adaptive_steps", "adaptive_rejected_steps",
             "leg_step_adaptive", "leg_step_tol_mm", "leg_step_s", "leg_model",
             "links_per_segment", "strain_sub_intervals", "track_error_mm", "real_time_factor"]
    for tag in ("def_flat", "def_obst4", "def_paper", "def_earth", "rod32_paper", "rod32_earth",
                "rod32_paper_0125",
                "half_flat", "half_obst4", "half_paper", "grid45_paper", "grid55_paper"):
        if os.path.exists(R(tag)):
            try:
                a = attrs(R(tag), names)
                with h5py.File(R(tag), "r") as f:
                    t = f["/time"][-1]
            except (OSError, KeyError, IndexError):
                print(f"{tag}: not complete")
                continue
            print(f"{tag}: t_end {t:.4f} s; " + ", ".join(
                f"{k} {v.decode() if isinstance(v, bytes) else v}" for k, v in a.items()
                if v is not None))


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""test_output_units.py: a run's output a user can read without the code (issue 36).

Proves, on a 0.2 s flat-road run: every dataset of RUN.h5 carries a non-empty "units" and a
"description" attribute, and every string attribute is UTF-8 text (HDF5 cset); `crawlsim
export RUN.h5 --csv --out DIR` writes RUN_tracks.csv with one row per /time sample whose columns
equal the HDF5 series (time, support position and orientation, contact force) and
RUN_pressure.csv with the 96 named chambers; bad input (a missing file, a file that is not
HDF5, an HDF5 file that is not a run, an unwritable --out, a second file) is one error line and
exit 1. Per-foot force against a closed form, on a 1 s flat-road run of the default (rod) legs:
the time mean of the feet's vertical forces is the support's weight m g under `paper` (legs
weightless) within 5 %: the mean differs from m g by the support's vertical momentum change
over the second divided by 1 s (measured 0.4 % over 2 s). Prints "N passed, N failed"; exit 1 on any failure.
Usage: /usr/bin/python3 test_output_units.py PATH_TO_CRAWLSIM
"""
import csv
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

passed = failed = 0


def check(cond, what):
    global passed, failed
    if cond:
        passed += 1
        print(f"ok   {what}")
    else:
        failed += 1
        print(f"FAIL {what}")


def main():
    exe = sys.argv[1]
    tmp = tempfile.mkdtemp(prefix="out_units_")
    env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
    try:
        h5 = os.path.join(tmp, "r.h5")
        p = subprocess.run([exe, "run", "--t-end", "0.2", "--out", h5, "--quiet"], env=env,
                           capture_output=True, text=True)
        check(p.returncode == 0, f"0.2 s run: {p.stderr[-300:]!r}")
        with h5py.File(h5, "r") as f:
            names = []
            f.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
            check(len(names) >= 17, f"{len(names)} datasets")
            for n in names:
                u = f[n].attrs.get("units")
                check(u is not None and len(u) > 0 and len(f[n].attrs.get("description", b"")) > 0,
                      f"/{n} has units ({u!r}) and a description")
            for obj in [f] + [f[n] for n in names]:
                for k in obj.attrs:
                    tid = obj.attrs.get_id(k).get_type()
                    if isinstance(tid, h5py.h5t.TypeStringID):
                        check(tid.get_cset() == h5py.h5t.CSET_UTF8,
                              f"{obj.name} attribute {k} is UTF-8 text")
            t = f["/time"][:]
            x = f["/support/position"][:]
            q = f["/support/orientation"][:]
            F = f["/contact/force"][:]
            P = f["/pressure"][:]
            FF = f["/contact/foot_force"][:]
            ST = f["/contact/stance"][:]
        out = os.path.join(tmp, "csv")
        os.mkdir(out)
        p = subprocess.run([exe, "export", h5, "--csv", "--out", out], env=env,
                           capture_output=True, text=True)
        check(p.returncode == 0 and p.stderr == "", f"export: {p.stderr!r}")
        with open(os.path.join(out, "r_tracks.csv"), newline="") as fh:
            rows = list(csv.reader(fh))
        head = rows[0]
        feet = [f"{c}_F{a}_N" for c in "ABCDEFGH" for a in "xyz"] + \
            [f"{c}_stance" for c in "ABCDEFGH"]
        check(head[11:] == feet, f"tracks header has the per-foot columns {head[11:14]}")
        check(head[:11] == ["time_s", "x_mm", "y_mm", "z_mm", "qw", "qx", "qy", "qz", "Fx_N",
                            "Fy_N", "Fz_N"], f"tracks header {head[:11]}")
        data = np.array(rows[1:], dtype=float)
        check(data.shape[0] == len(t), f"{data.shape[0]} rows for {len(t)} samples")
        ref = np.column_stack([t, x, q, F, FF.reshape(len(t), 24), ST])
        check(data.shape[1] == 43 and np.allclose(data, ref, rtol=1e-8, atol=1e-12),
              "tracks equal the series")
        with open(os.path.join(out, "r_pressure.csv"), newline="") as fh:
            prow = list(csv.reader(fh))
        check(prow[0][1] == "A_II1_O1_MPa" and prow[0][-1] == "H_II3_O4_MPa" and
              len(prow[0]) == 97, "pressure header names the 96 chambers")
        pd = np.array(prow[1:], dtype=float)
        check(np.allclose(pd[:, 1:], P, rtol=1e-8, atol=1e-12), "pressures equal /pressure")
        for legs in ("rod",):
            h = os.path.join(tmp, f"{legs}.h5")
            p = subprocess.run([exe, "run", "--t-end", "1", "--legs", legs, "--out", h,
                                "--quiet"], env=env, capture_output=True, text=True)
            check(p.returncode == 0, f"1 s run with {legs} legs")
            with h5py.File(h, "r") as f:
                ff = f["/contact/foot_force"][:]
                mg = f.attrs["support_mass_kg"] * 9.81
                check(f.attrs["legs_weightless"] == 1, "paper conditions")
                mean = ff[:, :, 1].sum(axis=1).mean()
                check(abs(mean / mg - 1) < 0.05,
                      f"{legs}: mean of the feet's vertical forces {mean:.4f} N = m g {mg:.4f} N")
                st = f["/contact/stance"][:]
                check(st.shape == ff.shape[:2] and set(np.unique(st)) <= {0.0, 1.0} and
                      st[len(st) // 2:].sum(axis=1).mean() >= 3,
                      f"{legs}: stance is 0/1 and on average at least three feet stand after "
                      "0.5 s")
        bend = os.path.join(tmp, "b.h5")
        p = subprocess.run([exe, "bend", "--out", bend], env=env, capture_output=True, text=True)
        check(p.returncode == 0, "analytic bend sweep")
        with h5py.File(bend, "r") as f:
            names = []
            f.visititems(lambda n, o: names.append(n) if isinstance(o, h5py.Dataset) else None)
            check(len(names) == 4 and all(len(f[n].attrs.get("units", b"")) > 0 for n in names),
                  f"every bend dataset has units ({names})")
        bad_h5 = os.path.join(tmp, "bend.h5")
        with h5py.File(bad_h5, "w") as f:
            f["x"] = [1.0]
        txt = os.path.join(tmp, "t.txt")
        open(txt, "w").write("not hdf5\n")
        for args, what in ((["export", os.path.join(tmp, "none.h5")], "missing file"),
                           (["export", txt], "not HDF5"), (["export", bad_h5], "not a run"),
                           (["export", h5, "--out", os.path.join(tmp, "no", "dir")],
                            "unwritable --out"),
                           (["export", h5, h5], "two files"), (["export", h5, "--cvs"], "typo")):
            p = subprocess.run([exe] + args, env=env, capture_output=True, text=True)
            check(p.returncode == 1 and p.stderr.count("\n") == 1 and
                  p.stderr.startswith("crawlsim export: "), f"{what}: {p.stderr!r}")
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print(f"{passed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    sys.exit(main())

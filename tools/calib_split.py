#!/usr/bin/python3
"""calib_split.py: split a merged FE mode table back into one case file per case, so that a table
can be extended with new cases and merged again by the product's own command:

  /usr/bin/python3 tools/calib_split.py TABLE.h5 DIR        (writes DIR/<case>.h5)
  crawlsim calibrate --actuator leg --p-max 0.4 --newton-rtol 1e-8 --dir DIR --case NEW ...
  crawlsim calibrate --merge-only --dir DIR --out NEW_TABLE.h5

Each written file holds the table's root attributes (the actuator, the FE settings, the format)
and one /cases/<name> group, exactly as `crawlsim calibrate` writes a case file; the merge then
checks them as it checks any case file (same actuator, FE settings and Newton tolerance). An
existing file in DIR is not overwritten (the finished case there wins, as the merge's resume).

Runs with Debian's Python (python3-h5py). Exit status 0; 1 on a missing or malformed table (one
line on stderr); 2 on bad usage.
"""
import os
import sys

import h5py

PROG = "calib_split"


def fail(msg, code=1):
    sys.stderr.write(f"{PROG}: {msg}\n")
    sys.exit(code)


def main(argv):
    if len(argv) != 3 or argv[1] in ("-h", "--help"):
        sys.stdout.write(__doc__) if len(argv) == 2 else None
        sys.exit(0 if len(argv) == 2 else 2)
    table, out = argv[1], argv[2]
    try:
        src = h5py.File(table, "r")
    except OSError as e:
        fail(f"{table}: cannot open as HDF5 ({e})")
    with src:
        fmt = src.attrs.get("format", b"")
        fmt = fmt.decode() if isinstance(fmt, bytes) else str(fmt)
        if not fmt.startswith("crawlsim-fe-calibration ") or "cases" not in src:
            fail(f"{table}: not an FE mode table (format '{fmt}', no /cases)")
        os.makedirs(out, exist_ok=True)
        wrote = kept = 0
        for name in src["cases"]:
            path = os.path.join(out, name + ".h5")
            if os.path.exists(path):
                kept += 1
                continue
            with h5py.File(path, "w") as dst:
                for k, v in src.attrs.items():
                    # the stored type as it is (fixed-length strings keep their NUL byte,
                    # which the C reader counts on)
                    dst.attrs.create(k, v, dtype=src.attrs.get_id(k).dtype)
                dst.create_group("cases")
                src.copy(src["cases"][name], dst["cases"], name)
            wrote += 1
    print(f"{PROG}: {table}: wrote {wrote} case files to {out} ({kept} already there)")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))

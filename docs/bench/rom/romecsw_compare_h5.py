#!/usr/bin/python3
"""romecsw_compare_h5.py: two HDF5 files dataset by dataset (docs/notes/rom.md, "ECSW on the real
leg's fibre basis"): for each dataset of B, bit-identical or the largest difference (absolute and
relative to B's largest entry); attributes that differ are listed. Used to verify that a leg file
or an ECSW matrix made from an every-element leg file (`rom leg-file --leg-file`, `rom ecsw-matrix
--leg-file`) is the one made from the basis with gmsh.

    /usr/bin/python3 romecsw_compare_h5.py A.h5 B.h5
"""
import sys

import h5py
import numpy as np


def walk(g, prefix=""):
    for k, v in g.items():
        if isinstance(v, h5py.Group):
            yield from walk(v, prefix + k + "/")
        else:
            yield prefix + k


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    with h5py.File(sys.argv[1], "r") as a, h5py.File(sys.argv[2], "r") as b:
        for k in sorted(walk(b)):
            if k not in a:
                print(f"{k}: only in {sys.argv[2]}")
                continue
            x, y = a[k][...], b[k][...]
            if x.shape != y.shape:
                print(f"{k}: shapes {x.shape} and {y.shape}")
            elif x.dtype.kind in "fiu" and not np.array_equal(x, y):
                d = float(np.abs(x.astype(float) - y.astype(float)).max())
                s = float(np.abs(y.astype(float)).max()) or 1.0
                print(f"{k} {y.shape}: max difference {d:.3g} (relative {d / s:.3g})")
            elif x.dtype.kind not in "fiu" and not np.array_equal(x, y):
                print(f"{k}: differs")
            else:
                print(f"{k} {y.shape}: bit-identical")
        for k in sorted(set(walk(a)) - set(walk(b))):
            print(f"{k}: only in {sys.argv[1]}")
        for k in sorted(set(a.attrs) | set(b.attrs)):
            va, vb = a.attrs.get(k), b.attrs.get(k)
            if not np.array_equal(np.asarray(va), np.asarray(vb)):
                print(f"attribute {k}: {va!r} against {vb!r}")


if __name__ == "__main__":
    main()

#!/usr/bin/python3
"""romsweep_compare.py: the bend files of one timed run side by side (docs/notes/rom.md, "The
sweep at 300x"): per file the rom's size, kept elements, iterations and CPU times (its
attributes), and the largest difference of the segment bends and of the total from the
reference file's (REF, the every-element reduced model) and from the FE's (FE), row by row.

    /usr/bin/python3 romsweep_compare.py FE.h5 REF.h5 ROM.h5 ...
"""
import sys

import h5py
import numpy as np


def load(path):
    with h5py.File(path, "r") as f:
        a = {k: f.attrs[k] for k in f.attrs}
        return (f["/pressure"][...], f["/angle_deg"][...], f["/angle_total_deg"][...], a)


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    fe = load(sys.argv[1])
    ref = load(sys.argv[2])
    print("file | n | Tet10 kept | fibres kept | iterations | tangents | sweep CPU (s) | "
          "max |bend - ref| (deg) | max |total - ref| (deg) | max |bend - FE| (deg) | "
          "total at p_max, FE (deg)")
    for path in sys.argv[2:]:
        p, ang, tot, a = load(path)
        row = [path]
        for k in ("rom_n", "rom_tet_kept", "rom_fibre_kept", "rom_newton_iterations",
                  "rom_tangents", "rom_sweep_cpu_s"):
            v = a.get(k, np.nan)
            row.append(f"{float(v):.4g}")
        m = min(len(p), len(ref[0]), len(fe[0]))
        if not (np.allclose(p[:m], ref[0][:m]) and np.allclose(p[:m], fe[0][:m])):
            sys.exit(f"romsweep_compare: {path}: other pressure rows than the reference's")
        row.append(f"{np.abs(ang[:m] - ref[1][:m]).max():.2e}")
        row.append(f"{np.abs(tot[:m] - ref[2][:m]).max():.2e}")
        row.append(f"{np.abs(ang[:m] - fe[1][:m]).max():.3f}")
        row.append(f"{tot[m - 1]:.3f}, {fe[2][m - 1]:.3f}")
        print(" | ".join(row))


if __name__ == "__main__":
    main()

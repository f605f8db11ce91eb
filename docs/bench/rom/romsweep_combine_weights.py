#!/usr/bin/python3
"""romsweep_combine_weights.py: one weights file (fem/fem_rom_act.h, "crawlsim-rom-weights 1")
from the Tet10 set of one tools/rom_ecsw.py file and the fibre set of another (session romsweep:
the Tet10s fitted tighter than the fibres, `rom_ecsw.py --set tet`).

    /usr/bin/python3 romsweep_combine_weights.py TET.h5 FIBRE.h5 OUT.h5
"""
import sys

import h5py


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    with h5py.File(sys.argv[1], "r") as ft, h5py.File(sys.argv[2], "r") as ff, \
            h5py.File(sys.argv[3], "w") as fo:
        fo.attrs["format"] = "crawlsim-rom-weights 1"
        for key, src in (("tet", ft), ("fibre", ff)):
            if f"{key}_id" not in src:
                sys.exit(f"romsweep_combine_weights: {src.filename}: no {key}_id")
            fo[f"{key}_id"] = src[f"{key}_id"][...]
            fo[f"{key}_w"] = src[f"{key}_w"][...]
            fo.attrs[f"{key}_from"] = src.filename
            fo.attrs[f"{key}_tol"] = src.attrs.get("tol", -1.0)
            fo.attrs[f"{key}_kept"] = len(src[f"{key}_id"])
        print(f"romsweep_combine_weights: {fo.attrs['tet_kept']} Tet10 (tol "
              f"{fo.attrs['tet_tol']:g}), {fo.attrs['fibre_kept']} fibres (tol "
              f"{fo.attrs['fibre_tol']:g}) -> {sys.argv[3]}")


if __name__ == "__main__":
    main()

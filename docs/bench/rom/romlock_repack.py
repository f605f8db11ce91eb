#!/usr/bin/python3
"""romlock_repack.py: copy HDF5 files (the short leg's snapshot rays) with every dataset
gzip-compressed (level 9, byte shuffle) and every attribute kept, for data/rom/short/.

    /usr/bin/python3 docs/bench/rom/romlock_repack.py OUTDIR FILE.h5 ...
"""
import os
import sys

import h5py


def copy(src, dst):
    for k, v in src.attrs.items():
        dst.attrs[k] = v
    for name, obj in src.items():
        if isinstance(obj, h5py.Group):
            copy(obj, dst.create_group(name))
        elif obj.shape == () or obj.size < 16:
            d = dst.create_dataset(name, data=obj[()])
            for k, v in obj.attrs.items():
                d.attrs[k] = v
        else:
            d = dst.create_dataset(name, data=obj[...], compression="gzip", compression_opts=9,
                                   shuffle=True)
            for k, v in obj.attrs.items():
                d.attrs[k] = v


def main():
    out = sys.argv[1]
    os.makedirs(out, exist_ok=True)
    for p in sys.argv[2:]:
        q = os.path.join(out, os.path.basename(p))
        with h5py.File(p, "r") as s, h5py.File(q, "w") as d:
            copy(s, d)
        print(f"{p}: {os.path.getsize(p)} -> {os.path.getsize(q)} bytes")


if __name__ == "__main__":
    main()

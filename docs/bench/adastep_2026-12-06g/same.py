#!/usr/bin/python3
"""same.py A.h5 B.h5: every dataset of two run files compared bit for bit (the output contract);
prints the datasets that differ and 'identical' when none does."""
import sys
import h5py
import numpy as np

def walk(f, out, prefix=""):
    for k, v in f.items():
        if isinstance(v, h5py.Dataset):
            out[prefix + "/" + k] = v[()]
        else:
            walk(v, out, prefix + "/" + k)

a, b = {}, {}
with h5py.File(sys.argv[1], "r") as fa, h5py.File(sys.argv[2], "r") as fb:
    walk(fa, a)
    walk(fb, b)
diff = [k for k in sorted(set(a) | set(b)) if k not in a or k not in b or
        a[k].shape != b[k].shape or a[k].tobytes() != b[k].tobytes()]
print(f"{len(a)} / {len(b)} datasets; " + ("identical" if not diff else "differ: " + ", ".join(diff)))

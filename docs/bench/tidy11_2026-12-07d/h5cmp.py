"""Compare two HDF5 files dataset by dataset (bytes) and attribute by attribute; print the
differences; exit 0 when every dataset is identical."""
import sys
import h5py
import numpy as np

def walk(f):
    out = {}
    f.visititems(lambda n, o: out.__setitem__(n, o) if isinstance(o, h5py.Dataset) else None)
    return out

a, b = h5py.File(sys.argv[1], "r"), h5py.File(sys.argv[2], "r")
da, db = walk(a), walk(b)
bad = 0
print(f"{len(da)} datasets in {sys.argv[1]}, {len(db)} in {sys.argv[2]}")
for n in sorted(set(da) | set(db)):
    if n not in da or n not in db:
        print("only in one:", n); bad += 1; continue
    x, y = da[n][()], db[n][()]
    same = np.asarray(x).tobytes() == np.asarray(y).tobytes() and np.shape(x) == np.shape(y)
    if not same:
        print("DIFFERS:", n); bad += 1
def attrs(o, path):
    for k in sorted(set(o.attrs) | set(b[path].attrs if path in b else [])):
        va, vb = o.attrs.get(k), b[path].attrs.get(k)
        if np.asarray(va).tobytes() != np.asarray(vb).tobytes():
            print(f"attribute {path}:{k}: {va!r} vs {vb!r}")
attrs(a, "/")
print("datasets identical" if bad == 0 else f"{bad} datasets differ")
sys.exit(1 if bad else 0)

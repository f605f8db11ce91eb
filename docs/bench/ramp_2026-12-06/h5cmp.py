import sys, h5py, numpy as np
a, b = h5py.File(sys.argv[1], 'r'), h5py.File(sys.argv[2], 'r')
nd = 0; n = 0
def visit(name, obj):
    global nd, n
    if isinstance(obj, h5py.Dataset):
        n += 1
        if name not in b: print('missing', name); nd += 1; return
        x, y = obj[()], b[name][()]
        if x.shape != y.shape or (x.dtype.kind in 'fiu' and not np.array_equal(x, y, equal_nan=x.dtype.kind == 'f')) or (x.dtype.kind not in 'fiu' and not np.array_equal(x, y)):
            nd += 1
            if x.dtype.kind == 'f' and x.shape == y.shape:
                print('differs', name, 'max abs', np.nanmax(np.abs(x - y)))
            else:
                print('differs', name)
a.visititems(visit)
for k in a.attrs:
    if k not in b.attrs or str(a.attrs[k]) != str(b.attrs[k]): print('attr', k, a.attrs[k], b.attrs.get(k))
print(f'{n} datasets, {nd} differ')

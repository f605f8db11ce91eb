import sys, h5py, numpy as np
rod = [0.30, 41.47, 79.05, 118.56, 159.23, 199.61, 239.98, 280.34, 320.72]
rows = {}
for fn in sys.argv[1:]:
    f = h5py.File(fn, "r"); t = f["/time"][:]; p = f["/support/position"][:]; p = p - p[0]
    xs = []; zs = []
    for s in range(1, 10):
        i = np.argmin(abs(t - s))
        if abs(t[i] - s) > 1e-6: xs.append(np.nan); zs.append(np.nan); continue
        xs.append(p[i, 0]); zs.append(p[i, 2])
    rows[fn] = (np.array(xs), np.array(zs))
    print("%-45s " % fn.split('/')[-1] + " ".join("%7.2f" % x for x in xs), " |dx| vs rod16 %.2f" % np.nanmax(abs(np.array(xs) - rod)))
names = list(rows)
for a in range(len(names) - 1):
    xa, za = rows[names[a]]; xb, zb = rows[names[a + 1]]
    print("%s vs %s: max |d(x,z)| %.2f mm" % (names[a].split('/')[-1], names[a+1].split('/')[-1], np.nanmax(np.hypot(xa - xb, za - zb))))

import sys, h5py, numpy as np
f = h5py.File(sys.argv[1], "r")
t = f["/time"][:]; p = f["/support/position"][:]; p = p - p[0]
lm = f["/contact/leg_max_depth"][:]; md = f["/contact/max_depth"][:]
nodes = [1,2,3,4,5,7,11,12,14,24,29,32]
for tt in nodes + [t[-1]]:
    i = np.argmin(abs(t - tt))
    print("t %6.2f x %7.2f y %6.2f z %7.2f" % (t[i], *p[i]))
print("end t %.3f; leg max depth %.4f mm; support max depth %.4f mm" % (t[-1], lm.max(), md.max()))
print("rejected", f.attrs.get("rejected_steps"), "attrs:", {k: f.attrs[k] for k in f.attrs if 'step' in k or 'order' in k or 'dt' in k})

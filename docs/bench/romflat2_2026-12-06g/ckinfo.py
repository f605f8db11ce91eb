# one line per checkpoint of the flat road on rom legs: the support's state and the legs' wrenches
# (state layout: core/sim_state.c; t, seed, 96 pressures, the support body (13: x, q, v, w), the
# legs, the coupling block (169: the eight legs' step-average base wrenches first), no footholds)
#   /usr/bin/python3 ckinfo.py CHECKPOINT...  (a python with h5py)
import sys, h5py, numpy as np
print("steps t_s | support x y z (mm, world) | v (mm/s) | w (rad/s) | sum of the legs' wrenches f (N) | largest leg |f| (N)")
for p in sys.argv[1:]:
    f = h5py.File(p, "r"); x = f["/state"][:]
    s = x[98:111]; w = x[-169:-169 + 48].reshape(8, 6)
    print("%d %.3f | %.4f %.4f %.4f | %.2f %.2f %.2f | %.4f %.4f %.4f | %.3f %.3f %.3f | %.2f" % (
        f.attrs["steps"], x[0], *s[0:3], *s[7:10], *s[10:13], *w[:, :3].sum(0),
        np.linalg.norm(w[:, :3], axis=1).max()))

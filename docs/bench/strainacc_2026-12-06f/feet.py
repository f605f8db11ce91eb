#!/usr/bin/python3
"""feet.py REF.h5 RUN.h5... [--t0 A --t1 B]: per stance of each foot (the reference's stance
windows from /contact/stance, stretches of at least 0.1 s starting in [A, B)), the foot's slip
along x (last centerline point, world mm), its mean normal force (y) and tangential force (x)
and the support's advance over the window, REF then each RUN (mm, N); and the sums over the
window per run."""
import sys
import h5py, numpy as np

args = [a for a in sys.argv[1:]]
t0, t1 = 0.0, 99.0
if "--t0" in args:
    i = args.index("--t0"); t0 = float(args[i + 1]); del args[i:i + 2]
if "--t1" in args:
    i = args.index("--t1"); t1 = float(args[i + 1]); del args[i:i + 2]

def rd(p):
    f = h5py.File(p, "r")
    d = {"t": f["time"][:], "x": f["support/position"][:, 0], "st": f["contact/stance"][:],
         "ff": f["contact/foot_force"][:],
         "foot": np.stack([f[f"legs/{L}/centerline"][:, -1, :] for L in "ABCDEFGH"], axis=1)}
    return d

R = rd(args[0]); runs = [rd(p) for p in args[1:]]
names = ["ref"] + [p.split("/")[-1][:40] for p in args[1:]]
tot = np.zeros((len(runs) + 1, 2))
for L in range(8):
    s = R["st"][:, L] > 0
    k = 0
    n = len(s)
    while k < n:
        if not s[k]:
            k += 1; continue
        e = k
        while e < n and s[e]:
            e += 1
        a, b = k, e - 1
        if R["t"][b] - R["t"][a] >= 0.1 and t0 <= R["t"][a] < t1:
            out = []
            for r, D in enumerate([R] + runs):
                i = int(np.argmin(abs(D["t"] - R["t"][a]))); j = int(np.argmin(abs(D["t"] - R["t"][b])))
                slip = D["foot"][j, L, 0] - D["foot"][i, L, 0]
                fn = D["ff"][i:j + 1, L, 1].mean(); ft = D["ff"][i:j + 1, L, 0].mean()
                tot[r] += (slip, 0)
                out.append(f"{slip:+6.2f} N{fn:5.3f} T{ft:+6.3f}")
            print(f"{'ABCDEFGH'[L]} {R['t'][a]:5.2f}-{R['t'][b]:5.2f}  " + " | ".join(out))
        k = e
print("sum of slips:", " ".join(f"{names[r]} {tot[r,0]:+.2f}" for r in range(len(names))))

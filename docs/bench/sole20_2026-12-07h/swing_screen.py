#!/usr/bin/python3
"""swing_screen.py H5 [M...]: legpass19's item 5 as a screen on a run file's output frames: the
share of leg-frames whose swing leg (contact/stance 0) has nothing within M mm below it: every
centre-line point higher than M above the highest terrain box top whose x-z footprint meets the
leg's x-z bounding box grown by M (a conservative bound: the terrain's top under the leg). M
covers the sole's tilted corner (7.5 sqrt 2 = 10.6 mm from the centre line's end), its 1 mm rim
and the law's onset; 12 mm and a looser 20 mm. Output frames (5 ms) stand for the iterates:
a screen of the share, not a count of the skipped tests."""
import sys
import h5py
import numpy as np

f = h5py.File(sys.argv[1], "r")
margins = [float(a) for a in sys.argv[2:]] or [12.0, 20.0]
tc = f["terrain/corners"][()].reshape(-1, 8, 3)
blo, bhi = tc.min(axis=1), tc.max(axis=1)
stance = f["contact/stance"][()]
legs = sorted(f["legs"].keys())
for M in margins:
    swing = skip = 0
    for i, k in enumerate(legs):
        cl = f[f"legs/{k}/centerline"][()]
        for t in range(cl.shape[0]):
            if stance[t, i]:
                continue
            swing += 1
            p = cl[t]
            lo, hi = p.min(axis=0) - M, p.max(axis=0) + M
            near = (blo[:, 0] <= hi[0]) & (bhi[:, 0] >= lo[0]) & (blo[:, 2] <= hi[2]) & (bhi[:, 2] >= lo[2])
            top = bhi[near, 1].max() if near.any() else -np.inf
            if p[:, 1].min() - top > M:
                skip += 1
    n = stance.size
    print(f"{sys.argv[1]}: M {M:g} mm: swing leg-frames {swing} of {n}, nothing near {skip} "
          f"({100 * skip / max(swing, 1):.1f} % of swing)")

# per shape: the 8 chord capsules as 8 equal arc-length ranges of the centre line (its 25
# points: range j = points 3j..3j+3), clear when its lowest point is higher than R above the
# top (R: the capsule's radius, taken as the sole's half side 7.5 mm, plus the 1 mm rim and
# the onset: 9 mm); the foot as above with M = 12 mm
R, MF = 9.0, 12.0
caps = clear = feet = feet_clear = 0
for i, k in enumerate(legs):
    cl = f[f"legs/{k}/centerline"][()]
    for t in range(cl.shape[0]):
        if stance[t, i]:
            continue
        for j in range(8):
            p = cl[t, 3 * j:3 * j + 4]
            lo, hi = p.min(axis=0) - R, p.max(axis=0) + R
            near = (blo[:, 0] <= hi[0]) & (bhi[:, 0] >= lo[0]) & (blo[:, 2] <= hi[2]) & (bhi[:, 2] >= lo[2])
            top = bhi[near, 1].max() if near.any() else -np.inf
            caps += 1
            clear += p[:, 1].min() - top > R
print(f"{sys.argv[1]}: swing legs' capsules with nothing within {R:g} mm below: {clear} of {caps} "
      f"({100 * clear / max(caps, 1):.1f} %)")

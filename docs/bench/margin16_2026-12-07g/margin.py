#!/usr/bin/python3
"""margin.py RUN.h5... : how far the loaded feet stand from the step's edges (x = 240, 460 mm,
top 40 mm up; terrains/obstacle.terrain), per run:
  - the support's x at 7, 9, 10, 11, 12, 14, 17, 20 s and the run's end (time, status);
  - per window (5-8 s, 8-12 s, 12-16 s, 16-20 s): the loaded foot (normal force > 0.02 N) nearest
    an edge on the step's top (h > 35 mm: min(x - 240, 460 - x)) and on the road within 60 mm of
    the riser or the far edge (h < 5 mm: 240 - x or x - 460), with its leg, time and x;
  - leg C's (and G's, the mirror) touchdowns 8.6-10 s and 16.8-18 s (time @ foot x, height).
Negative step-top distances are feet on the corner past the edge."""
import sys

import h5py
import numpy as np

WIN = ((5, 8), (8, 12), (12, 16), (16, 20))


def main():
    for p in sys.argv[1:]:
        with h5py.File(p, "r") as f:
            t = f["time"][:]
            sx = f["support/position"][:, 0]
            ff = f["contact/foot_force"][:, :, 1]
            st = f["contact/stance"][:]
            feet = np.stack([f["legs/%s/centerline" % l][:, -1] for l in "ABCDEFGH"], axis=1)
            status = f.attrs.get("status", b"?")
            status = status.decode() if isinstance(status, bytes) else status
        xs = " ".join("%g:%.1f" % (s, np.interp(s, t, sx)) if t[-1] >= s else "%g:-" % s
                      for s in (7, 9, 10, 11, 12, 14, 17, 20))
        print("%s\n  end %.2f s %s | x %s" % (p, t[-1], status, xs))
        for a, b in WIN:
            m = (t >= a) & (t <= b)
            if not m.any():
                continue
            best_top = (1e9, None)
            best_road = (1e9, None)
            for i in np.nonzero(m)[0]:
                for k in range(8):
                    if ff[i, k] <= 0.02:
                        continue
                    x, h = feet[i, k, 0], feet[i, k, 1]
                    if h > 35:
                        d = min(x - 240, 460 - x)
                        if d < best_top[0]:
                            best_top = (d, (t[i], "ABCDEFGH"[k], x, h))
                    elif h < 5:
                        d = 240 - x if x < 240 else x - 460
                        if 0 <= d < best_road[0] and (x < 240 or x > 460):
                            best_road = (d, (t[i], "ABCDEFGH"[k], x, h))
            s = "  %4.1f-%4.1f s: on top min %s" % (a, b, "%.1f mm (%s %.2f s, x %.1f h %.1f)" % (
                best_top[0], best_top[1][1], best_top[1][0], best_top[1][2], best_top[1][3])
                if best_top[1] else "-")
            s += "; road min %s" % ("%.1f mm (%s %.2f s, x %.1f)" % (
                best_road[0], best_road[1][1], best_road[1][0], best_road[1][2])
                if best_road[1] else "-")
            print(s)
        for leg in "CG":
            k = "ABCDEFGH".index(leg)
            ev = ["%.2f@%.1f/h%.1f" % (t[i], feet[i, k, 0], feet[i, k, 1]) for i in range(1, len(t))
                  if ((8.6 < t[i] < 10) or (16.8 < t[i] < 18)) and st[i, k] and not st[i - 1, k]]
            print("  %s touchdowns 8.6-10, 16.8-18 s: %s" % (leg, " ".join(ev[:6])))


if __name__ == "__main__":
    sys.exit(main())

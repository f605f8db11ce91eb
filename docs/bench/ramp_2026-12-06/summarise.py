"""Summarise the flat-road set's logs of one leg level (robust.sh): per run, x at every whole
second from 2 s against Table 2 (39 (t - 1) mm), x at 9 s against 312 mm, max |z|, the final
tilt and the verdict, read from the run's progress lines. Usage: summarise.py DIR."""
import glob
import os
import re
import sys

TABLE2 = {t: 39.0 * (t - 1) for t in range(2, 10)}  # paper Table 2, x (mm) at t (s)


def main(d):
    print("# run: options | x at 2..9 s (mm) | worst vs Table 2 from 2 s | x9 vs 312 mm | "
          "max |z| (mm, whole s) | final tilt | verdict")
    order = ["nominal", "ramp0.1", "ramp0.2", "ramp0.3", "ramp0.5", "mu0.6", "mu1.0", "m25g", "m75g",
             "tau0.5x", "tau2x", "dt_half", "mu0"]
    logs = {os.path.basename(p)[2:-4]: p for p in glob.glob(os.path.join(d, "r_*.log"))}
    for n in [k for k in order if k in logs] + sorted(k for k in logs if k not in order):
        text = open(logs[n]).read()
        opt = ""
        op = os.path.join(d, "o_%s.txt" % n)
        if os.path.exists(op):
            opt = open(op).read().strip().split(":", 1)[1].strip()
        xs, zs = {}, []
        for m in re.finditer(r"t =\s+([\d.]+) s\s+x =\s+(-?[\d.]+)\s+y =\s+(-?[\d.]+)\s+z =\s+(-?[\d.]+)", text):
            t = float(m.group(1))
            if abs(t - round(t)) < 1e-9:
                xs[int(round(t))] = float(m.group(2))
                zs.append(abs(float(m.group(4))))
        v = re.search(r"^verdict.*$", text, re.M)
        tilt = re.search(r"tilt ([\d.]+) deg", text)
        devs = [((xs[t] - TABLE2[t]) / TABLE2[t] * 100, t) for t in TABLE2 if t in xs]
        worst = max(devs, key=lambda e: abs(e[0])) if devs else None
        x9 = "%.1f (%+.1f %%)" % (xs[9], (xs[9] - 312) / 312 * 100) if 9 in xs else "-"
        print("%s: %s | %s | %s | %s | %.2f | %s | %s" % (
            n, opt or "(defaults)", " ".join("%.1f" % xs[t] for t in range(2, 10) if t in xs),
            "%+.1f %% at %d s" % worst if worst else "-", x9, max(zs) if zs else float("nan"),
            tilt.group(1) + " deg" if tilt else "-", v.group(0) if v else "no verdict (unfinished)"))


if __name__ == "__main__":
    main(sys.argv[1])

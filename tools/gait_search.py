#!/usr/bin/python3
"""Search the flat-road gait design's few parameters by simulation (issue 33).

usage: /usr/bin/python3 tools/gait_search.py [--dir DIR] [--evals N] [--robust] [--x0 S,H,U,TL]
           [--crawlsim build/tools/crawlsim] [--mpirun N] [--write-gait P.gait --params S,H,U,TL]

A design is the shipped flat-road gait's structure (gaits/flat_road.gait: a level-sole stance
stroke centred on the hip at constant speed, an overlapped load transfer, a level-sole swing, a
first extra step) with four parameters:
  S   stroke at the hips (mm): the stance feet go +S/2 -> -S/2 in each 1 s stride
  H   stance height (mm): the stance feet's lift above the straight leg's foot
  U   swing height (mm): the swing top's lift (the lift-off pose is U - 2 mm)
  TL  overlap / landing time (s): the lift-off and the landing each take TL at the stance's foot
      speed, the swing 1 - 2 TL
Each design is written as a description (`crawlsim gait design --stretch` on the mission's
table: robot/calibration_fe_leg_modes_sym.h5 under rbf-pair, the map the default rod legs use)
and run on the default model (`crawlsim run --scene flat-road --gait ...`, paper conditions).
Every simulation is a case of a study file run by `crawlsim study --resume` (one case per MPI
rank with --mpirun N), so an interrupted search resumes where it stopped: the cases already
finished are read back, not rerun, and the optimiser (scipy.optimize's Nelder-Mead, deterministic)
replays its path from them.

Objective (never per time node): the worst relative error of the support's x against Table 2
at the whole seconds 2..9 s (x(k) = 39 (k - 1) mm), plus penalties for |z| > 5 mm, tilt > 3 deg
and a failed run. --robust adds, for the best design, the robustness set (ramps 0.1/0.5 s,
friction 0.6/1.0, support 25/75 g, pneumatic lag x0.5/x2, the step halved) and friction 0,
and prints each run's x(9 s) against the nominal one.

Results: DIR/results.csv (one row per evaluated design, in evaluation order) and, with
--robust, DIR/robust.csv.
"""
import argparse
import hashlib
import math
import os
import subprocess
import sys

PROG = "gait_search.py"
HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
CAL = "robot/calibration_fe_leg_modes_sym.h5"
RULE = "rbf-pair"
P_MAX = 0.4          # MPa, the table's range
T_NODES = range(2, 10)
PACE = 39.0          # mm per second, Table 2
NAMES = ("S", "H", "U", "TL")
# start: the shipped design's H, U, TL; S scaled by its measured one-branch stride (a first run
# of S 40.6 strode ~63 mm per second, 1.55 S)
X0 = (25.0, 3.0, 11.0, 1.0 / 6.0)
LO = (12.0, 1.0, 6.0, 0.08)
HI = (45.0, 8.0, 16.0, 0.25)


def fail(msg):
    print(f"{PROG}: {msg}", file=sys.stderr)
    sys.exit(1)


try:
    import h5py
    import numpy as np
    from scipy.optimize import minimize
except ImportError as e:  # Debian: python3-h5py python3-numpy python3-scipy
    fail(f"needs h5py, numpy and scipy ({e})")


def gait_text(S, H, U, TL):
    """The description of one design (the structure of gaits/flat_road.gait)."""
    TL = round(TL, 4)    # times on a 1e-4 s grid, so that consecutive moves abut exactly
    ulo = U - 2.0
    back = S * TL        # the foot's travel at the stance speed S mm/s during TL
    sw = 1.0 - 2.0 * TL  # the swing's duration
    f = lambda v: f"{v:.4f}".rstrip("0").rstrip(".")
    return f"""# flat-road design searched by tools/gait_search.py: S {f(S)} mm, H {f(H)} mm, U {f(U)} mm,
# TL {f(TL)} s (the structure of gaits/flat_road.gait; its rules hold with these values).
# params: {f(S)},{f(H)},{f(U)},{f(TL)}
# Poses on the mission's map with the FE's stretch:
#   crawlsim gait design THIS --stretch --calibration {CAL} --cal-rule {RULE} --p-max {P_MAX}
name flat-road
sample 0.05
# stance at a constant crouch H; the swing U up. Every pose on one branch (`plus`: II1 and II3
# on Omega3&4, II2 on Omega1&2), so that no move passes a straight leg: on two branches the
# cross-fade between them inflates all four chambers of a segment for a sample, which on the
# FE's stretch lengthens the stance legs (the support rose 13 mm at every mid-stride, measured)
pose M0  foot 0 {f(H)} plus
pose Hp  foot {f(S / 2)} {f(H)} plus
pose Hm  foot {f(-S / 2)} {f(H)} plus
pose HmU foot {f(-S / 2 - back)} {f(ulo)} plus
pose FU  foot {f(S / 2 + back)} {f(U)} plus
pose M0U foot {f(-back)} {f(ulo)} plus
# 0..1 s: BDEG lift, reach forward and land at Hp (the support stands); ACFH crouch to M0
move 0    0.6  BDEG FU
move 0.6  0.3  ACFH M0
move 0.6  0.4  BDEG Hp
# 1..2 s: BDEG carry the support a whole stroke; ACFH lift off, swing and land at Hp at 2 s
move 1.0    1.0    BDEG Hm linear
move 1.0    {f(TL)} ACFH M0U linear
move {f(1 + TL)} {f(sw)} ACFH FU
move {f(1 + TL + sw)} {f(TL)} ACFH Hp linear
# strides 2..9 s
stride 7 1 2.0 ACFH BDEG
phase 0      1.0    swing Hm linear
phase 0      {f(TL)} stand HmU linear
phase {f(TL)} {f(sw)} stand FU
phase {f(TL + sw)} {f(TL)} stand Hp linear
# 9..9.5 s: every leg under its hip, then vented
move 9.0    0.3    ABCDEFGH M0
move 9.3    0.2    ABCDEFGH straight
"""


def key(x):
    return hashlib.sha1(",".join(f"{v:.4f}" for v in x).encode()).hexdigest()[:10]


# the robustness set (issue 33): one run option each
ROBUST = [
    ("ramp0.1", "--ramp 0.1"), ("ramp0.5", "--ramp 0.5"),
    ("mu0.6", "--friction 0.6"), ("mu1.0", "--friction 1.0"),
    ("m25g", "--support-mass 0.025"), ("m75g", "--support-mass 0.075"),
    ("tau0.5x", "--tau 0.01"), ("tau2x", "--tau 0.04"),
    ("dt_half", "--dt 0.0005"), ("mu0", "--friction 0"),
]


class Search:
    def __init__(self, a):
        self.a = a
        self.dir = os.path.abspath(a.dir)
        os.makedirs(self.dir, exist_ok=True)
        self.results = os.path.join(self.dir, "results.csv")
        self.seen = {}
        if os.path.exists(self.results):
            for line in open(self.results):
                if line.startswith("#") or line.startswith("key"):
                    continue
                w = line.strip().split(",")
                self.seen[w[0]] = float(w[5])

    def study(self, name, cases):
        """Write and run a study of cases [(case, gait_path_or_None, run_words)]; resumable."""
        path = os.path.join(self.dir, name + ".study")
        lines = [f"study {name}", ""]
        for c, gait, words in cases:
            gd = os.path.join(self.dir, f"{c.split('__')[0]}.gait")
            lines.append(f"case {c} gait-design {gd} --stretch --calibration @data/{CAL} "
                         f"--cal-rule {RULE} --p-max {P_MAX}")
            lines.append(f"then run --scene flat-road --conditions paper --gait @case/gait.csv "
                         f"{words}".rstrip())
        text = "\n".join(lines) + "\n"
        if not os.path.exists(path) or open(path).read() != text:
            open(path, "w").write(text)
        cmd = [self.a.crawlsim, "study", path, "--resume", "--out",
               os.path.join(self.dir, name + ".h5"), "--dir", os.path.join(self.dir, "cases")]
        if self.a.mpirun > 1:
            cmd = ["mpirun", "-n", str(self.a.mpirun), "--bind-to", "none"] + cmd
        subprocess.run(cmd, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        out = {}
        for c, _, _ in cases:
            out[c] = self.track(os.path.join(self.dir, "cases", c + ".h5"))
        return out

    @staticmethod
    def track(case_file):
        """x at the whole seconds 0..9, max |z|, max tilt (deg), status; None if no result."""
        if not os.path.exists(case_file):
            return None
        with h5py.File(case_file, "r") as f:
            st = f.attrs.get("status", b"")
            st = st.decode() if isinstance(st, bytes) else str(st)
            if "run" not in f or "time" not in f["run"]:
                return {"status": st or "failed"}
            t = f["run/time"][:]
            x = f["run/support/position"][:]
            q = f["run/support/orientation"][:]
        xs = [float(np.interp(k, t, x[:, 0])) if t[-1] >= k - 1e-9 else float("nan")
              for k in range(10)]
        zmax = float(np.max(np.abs(x[:, 2]))) if len(t) else float("nan")
        cosang = np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2), -1, 1)
        tilt = float(np.degrees(np.max(np.arccos(cosang)))) if len(t) else float("nan")
        return {"status": st, "x": xs, "z": zmax, "tilt": tilt, "t_end": float(t[-1])}

    @staticmethod
    def score(r):
        if r is None or "x" not in r:
            return 10.0
        errs = [abs(r["x"][k] - PACE * (k - 1)) / (PACE * (k - 1)) for k in T_NODES]
        if any(math.isnan(e) for e in errs):
            return 5.0
        return max(errs) + 0.05 * max(0.0, r["z"] - 5.0) + 0.05 * max(0.0, r["tilt"] - 3.0)

    def evaluate(self, v):
        x = [min(max(vi, lo), hi) for vi, lo, hi in zip(v, LO, HI)]
        k = key(x)
        if k in self.seen:
            return self.seen[k]
        c = f"d{k}"
        open(os.path.join(self.dir, c + ".gait"), "w").write(gait_text(*x))
        r = self.study(f"eval_{k}", [(c, None, "")])[c]
        s = self.score(r)
        # out-of-box candidates pay for the distance (Nelder-Mead has no bounds)
        s += sum(abs(vi - xi) for vi, xi in zip(v, x)) * 0.05
        new = not os.path.exists(self.results)
        with open(self.results, "a") as f:
            if new:
                f.write("key,S_mm,H_mm,U_mm,TL_s,score,x2,x3,x4,x5,x6,x7,x8,x9,zmax_mm,tilt_deg\n")
            xs = r["x"] if r and "x" in r else [float("nan")] * 10
            f.write(f"{k},{x[0]:.4f},{x[1]:.4f},{x[2]:.4f},{x[3]:.4f},{s:.6f},"
                    + ",".join(f"{xs[j]:.2f}" for j in T_NODES)
                    + f",{(r or {}).get('z', float('nan')):.2f},"
                    f"{(r or {}).get('tilt', float('nan')):.2f}\n")
        self.seen[k] = s
        print(f"{PROG}: {k} S {x[0]:.2f} H {x[1]:.2f} U {x[2]:.2f} TL {x[3]:.3f}: score "
              f"{s:.4f} x(9) {xs[9]:.1f} mm", flush=True)
        return s

    def robust(self, x):
        k = key(x)
        c = f"d{k}"
        open(os.path.join(self.dir, c + ".gait"), "w").write(gait_text(*x))
        cases = [(c, None, "")] + [(f"{c}__{n}", None, w) for n, w in ROBUST]
        res = self.study(f"robust_{k}", cases)
        nom = res[c]
        x9 = nom["x"][9] if nom and "x" in nom else float("nan")
        path = os.path.join(self.dir, "robust.csv")
        with open(path, "w") as f:
            f.write(f"# design {k}: S {x[0]:.4f} H {x[1]:.4f} U {x[2]:.4f} TL {x[3]:.4f}\n")
            f.write("case,options,x9_mm,vs_nominal_pct,vs_table2_pct,zmax_mm,tilt_deg,status\n")
            for cname, w in [(c, "")] + [(f"{c}__{n}", w) for n, w in ROBUST]:
                r = res[cname]
                xi = r["x"][9] if r and "x" in r else float("nan")
                f.write(f"{cname},{w},{xi:.2f},{100 * (xi - x9) / x9:+.2f},"
                        f"{100 * (xi - 312) / 312:+.2f},{(r or {}).get('z', float('nan')):.2f},"
                        f"{(r or {}).get('tilt', float('nan')):.2f},{(r or {}).get('status', '?')}\n")
        print(open(path).read(), end="")


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("--dir", default="gait_search")
    ap.add_argument("--evals", type=int, default=40, help="Nelder-Mead's budget of designs")
    ap.add_argument("--robust", action="store_true")
    ap.add_argument("--x0", default=",".join(str(v) for v in X0))
    ap.add_argument("--crawlsim", default=os.path.join(ROOT, "build", "tools", "crawlsim"))
    ap.add_argument("--mpirun", type=int, default=1)
    ap.add_argument("--write-gait", default=None)
    ap.add_argument("--params", default=None)
    a = ap.parse_args()
    if a.write_gait:
        try:
            p = [float(v) for v in (a.params or a.x0).split(",")]
        except ValueError:
            p = []
        if len(p) != 4 or not all(math.isfinite(v) for v in p):
            fail(f"--params '{a.params}': expected four numbers S,H,U,TL")
        if not all(lo <= v <= hi for v, lo, hi in zip(p, LO, HI)):
            fail(f"--params '{a.params}': outside the search's box "
                 + ", ".join(f"{n} {lo:g}..{hi:g}" for n, lo, hi in zip(NAMES, LO, HI)))
        open(a.write_gait, "w").write(gait_text(*p))
        return
    if not os.access(a.crawlsim, os.X_OK):
        fail(f"{a.crawlsim}: not an executable (build first, or give --crawlsim)")
    x0 = [float(v) for v in a.x0.split(",")]
    if len(x0) != 4:
        fail("--x0 needs S,H,U,TL")
    s = Search(a)
    if a.evals > 0:
        # initial simplex: steps of about a tenth of each box
        simplex = [x0] + [[x0[j] + (0.1 * (HI[j] - LO[j]) if j == i else 0) for j in range(4)]
                          for i in range(4)]
        res = minimize(s.evaluate, x0, method="Nelder-Mead",
                       options={"maxfev": a.evals, "initial_simplex": simplex,
                                "xatol": 0.05, "fatol": 1e-3})
        best = [min(max(v, lo), hi) for v, lo, hi in zip(res.x, LO, HI)]
        print(f"{PROG}: best S {best[0]:.3f} H {best[1]:.3f} U {best[2]:.3f} TL {best[3]:.4f}: "
              f"score {res.fun:.4f} ({res.nfev} designs)")
    else:
        best = x0
    if a.robust:
        s.robust(best)


if __name__ == "__main__":
    main()

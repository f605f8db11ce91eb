#!/usr/bin/python3
"""Search a few design parameters of the obstacle gait's rules by simulation (issue 33, item 2).

usage: /usr/bin/python3 tools/obstacle_search.py [--dir DIR] [--base "OPTIONS"]
           [--free settle,Tclimb,Tcross,Dcross] [--x0 V,..] [--sweep N] [--evals N] [--seed S]
           [--screen ramp0.5,m25g] [--full K] [--crawlsim build/tools/crawlsim] [--mpirun N]
           [--report-only] [--write-gait FILE]
           [--legs rod|strain] [--links N] [--strain-step fixed|adaptive] [--step-tol MM] [--dt S]

A design is tools/obstacle_gait.py's output with the fixed options --base (the rules switched on,
e.g. "--over-step -3 --reach 55 --clear-down": the sixth session's rule 16 and 12b) and the
free parameters --free, each one of the script's options within a box (PARAMS below; the
others keep the script's defaults). Each design is written as DIR/dKEY.gait, its landing gate
as DIR/dKEY.gate (`obstacle_gait.py --gate-from`, as gaits/obstacle.gate is made), designed by
`crawlsim gait design --stretch` on the mission's table (as gaits/obstacle.csv) and run on the
scene's default model (`paper`, under its gate; the legs: strain at the adaptive step since
2026-12-07, branch obst10, the rod at 4 elements before: a folder searched before then resumes
its rod runs only with --legs rod, which keys its cases anew). KEY is a hash of
the description's statements (comments left out), so two parameter vectors that give the same
table are one evaluation. Every simulation is a case of a study file run by
`crawlsim study --resume` (tools/gait_search.py's run_study; `--mpirun N` spreads a stage's
cases over N ranks), so an interrupted search resumes where it stopped: DIR/results.csv holds
every evaluated design and a rerun reads it back (the optimiser replays its path from it).

Objective (mm; never per run or per time node; lower is better):
  J = max(worst Table 3 node from 4 s, end point's distance) of the nominal (35 s)
      + 2 (tilt - 10 deg) where the nominal tilts past 10 deg
      + sum over the screening runs (--screen; default the two the shipped table loses,
        ramp 0.5 s and a 25 g support) of: 0 within 40 mm of the end point (x 646, z 270 mm),
        (distance - 40) capped at 100 beyond it, 100 for a run that tips over (tilt > 30 deg) or
        stops early.
A nominal that falls scores 1000 and its screening runs are not run (they count as falls:
1200). The screening runs end at 36 s (the gate's holds make the table longer), ramp 0.5 at
47 s, as the gate's set records (docs/bench/gate_2026-12-06f/gate_set.sh).

Optimiser: a designed sweep (the start --x0 and N-1 points of a Latin hypercube over the free
parameters' box, seeded: scipy.stats.qmc), then scipy.optimize's bounded Nelder-Mead from the
sweep's best design (--evals designs at most, read back ones included; simplex steps a fifth
of each box). Both are deterministic, so a rerun replays them from results.csv. --full K: the
rest of issue 33's robustness set (friction 0.6/1.0, support 75 g, pneumatic lag x0.5/x2, ramp
0.1 s, the step halved) for the K best designs: DIR/full.csv, one row per run, and each
design's count of runs within 40 mm of the end point. --report-only runs nothing: it replays
the search from the finished cases as far as they go and writes full.csv with the runs not
finished as missing (a search cut by a deadline reports what stands; the same command without
it goes on).
"""
import argparse
import hashlib
import math
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(HERE)
sys.path.insert(0, HERE)
PROG = "obstacle_search.py"


def fail(msg):
    print(f"{PROG}: {msg}", file=sys.stderr)
    sys.exit(1)


try:
    import numpy as np
    from scipy.optimize import minimize
    from scipy.stats import qmc
    # the study runner's plumbing and the mission's table, the robustness set's run options
    import gait_search
    from gait_search import CAL, LINKS, MODEL, P_MAX, RULE, model_name, model_words, read_case, \
        robust_set, run_study
    # Table 3 (the paper's obstacle track: support x, height, lateral z at its time nodes)
    from plot_track import TABLE3_H, TABLE3_T, TABLE3_X, TABLE3_Z
except ImportError as e:  # Debian: python3-h5py python3-numpy python3-scipy python3-matplotlib
    fail(f"needs h5py, numpy, scipy and matplotlib ({e})")

# the free parameters: obstacle_gait.py's option, box, grid (a design is rounded to it, so
# that the optimiser's near-equal points are one design), the start (the script's default;
# reach, whose rule is off by default, 45 mm: rule 12's longest offset)
PARAMS = {
    "settle": ("--settle", 0.0, 1.2, 0.01, 0.4),       # s: rule 13's stand before the rear climb
    "Tclimb": ("--Tclimb", 0.7, 1.0, 0.01, 0.8),       # s: the climb's slot
    "Tcross": ("--Tcross", 0.44, 0.6, 0.01, 0.52),     # s: rule 14's crossing slot
    "Tp": ("--Tp", 0.5, 0.7, 0.01, 0.6),               # s: the walk's slot
    "Dcross": ("--Dcross", 44.0, 62.0, 1.0, 59.0),     # mm: rule 16b's advance per cycle (D 59)
    "x2": ("--x2", 460.0, 540.0, 1.0, 500.0),          # mm: where the wave ends (rule 11)
    "xcross": ("--xcross", 200.0, 260.0, 1.0, 235.0),  # mm: the crossing's end (rule 14)
    "rise": ("--rise", 36.0, 40.0, 0.5, 40.0),         # mm: the walk's stance height (rule 2)
    "over_step": ("--over-step", -6.0, 10.0, 1.0, 10.0),  # mm: rule 16's step overshoot
    "reach": ("--reach", 35.0, 60.0, 5.0, 45.0),       # mm: rule 16's longest offset
    "clear": ("--clear", 0.0, 20.0, 1.0, 10.0),        # mm: rule 12's clearance
}
T_NOM, T_SET, T_RAMP05 = 35.0, 36.0, 47.0
END = (646.0, 270.0)      # Table 3's end point (x, z), mm
SET_TOL = 40.0            # the set's allowance from the end point, mm
FALL = 100.0              # penalty of a set run that falls (mm)
NOMINAL_FALLS = 1000.0
SCENE_LEGS = "rod"   # the obstacle's default legs (core/sim_scene.c; crawlsim run --help)
gait_search.SCENE_LEGS = SCENE_LEGS   # the step halved of the scene's own legs (step_halved())


def robust_nine():
    """issue 33's robustness set of nine, the step halved the model's (gait_search.step_halved:
    before 2026-12-07 this passed the set's placeholder word `step` to the run)"""
    return [(n, w) for n, w in robust_set() if n != "mu0"]


def model_run_words(words):
    """the model's run options for a case whose own options are WORDS: --links and the model's
    words, a case's own --dt or --step-tol (the step halved) replacing the model's"""
    own = words.split()
    mw = model_words()
    for opt in ("--dt", "--step-tol"):
        if opt in own and opt in mw:
            i = mw.index(opt)
            del mw[i:i + 2]
    return ([] if LINKS[0] is None else ["--links", str(LINKS[0])]) + mw


class Budget(Exception):
    """the local search's budget of new designs is spent"""


def track(case_file):
    """A run's Table 3 record from its study case file, or None (no result)."""
    case = read_case(case_file, ("time", "support/position", "support/orientation",
                                 "contact/leg_max_depth"))
    if case is None:
        return None
    st, d, at = case
    if d is None:
        return {"status": st, "fell": True}
    t, pos, q = d["time"], d["support/position"], d["support/orientation"]
    depth = d["contact/leg_max_depth"]
    held = at.get("gate_held_s", float("nan"))
    tilt = np.degrees(np.arccos(np.clip(1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2), -1, 1)))
    worst, where, nodes = 0.0, 0.0, []
    for tn, X, H, Z in zip(TABLE3_T, TABLE3_X, TABLE3_H, TABLE3_Z):
        if tn > t[-1] + 1e-9:
            nodes.append(None)
            e = float("inf") if tn >= 4 else 0.0
        else:
            i = int(np.argmin(abs(t - tn)))
            nodes.append((pos[i, 0], pos[i, 1], pos[i, 2]))
            e = max(abs(pos[i, 0] - X), abs(pos[i, 1] - H), abs(pos[i, 2] - Z)) if tn >= 4 else 0
        if e > worst:
            worst, where = e, tn
    end = pos[-1]
    off = float(math.hypot(end[0] - END[0], end[2] - END[1]))
    fell = bool(np.nanmax(tilt) > 30 or not np.isfinite(off)) or st != "complete"
    return {"status": st, "fell": fell, "worst": float(worst), "worst_t": float(where),
            "nodes": nodes, "end": (float(end[0]), float(end[1]), float(end[2])), "off": off,
            "tilt": float(np.nanmax(tilt)), "t_end": float(t[-1]), "held": float(held),
            "depth": float(np.max(depth)) if depth is not None and len(depth) else float("nan")}


def set_penalty(r):
    if r is None or r["fell"]:
        return FALL
    return min(max(0.0, r["off"] - SET_TOL), FALL)


def verdict(r):
    """a set run's short verdict for the tables"""
    if r is None:
        return "-"
    if r["fell"]:
        return "falls"
    return f"{r['off']:.1f}"


class Search:
    def __init__(self, a):
        self.a = a
        self.dir = os.path.abspath(a.dir)
        os.makedirs(self.dir, exist_ok=True)
        self.results = os.path.join(self.dir, "results.csv")
        self.seen = {}        # key -> J
        self.order = []
        self.local = None     # the local search's designs (a set) once it has started
        self.model_col = True  # a table written before the column keeps its columns
        if os.path.exists(self.results):
            for line in open(self.results):
                w = line.rstrip("\n").split(",")
                if line.startswith("#"):
                    continue
                if w[0] == "key":
                    self.model_col = "model" in w
                    continue
                self.seen[w[0]] = float(w[2])

    @staticmethod
    def words(a, x):
        """obstacle_gait.py's options for the free parameters' values x"""
        out = []
        for n, v in zip(a.free, x):
            out.append(f"{PARAMS[n][0]}={v:.6g}")   # `=`: a negative value is not an option
        return out

    @staticmethod
    def design(a, x):
        """Write the description of x into a temporary file; its key (the statements' hash,
        with --base and the run's words) and its text."""
        cmd = [sys.executable, os.path.join(HERE, "obstacle_gait.py")] + a.base.split() \
            + Search.words(a, x)
        p = subprocess.run(cmd, capture_output=True, text=True)
        if p.returncode != 0:
            fail(f"{' '.join(cmd[1:])}: {p.stderr.strip()}")
        stmts = "\n".join(ln for ln in p.stdout.splitlines()
                          if ln.strip() and not ln.lstrip().startswith("#"))
        text = stmts + "\n" + " ".join(a.screen)
        model = model_run_words("")
        if model:   # another model: other cases (the key as before without the options)
            text += "\n" + " ".join(model)
        key = hashlib.sha1(text.encode()).hexdigest()[:10]
        return key, p.stdout, cmd

    def study(self, name, cases):
        """cases [(case, table_or_None, run words, t_end)]; a case without a table designs
        DIR/dKEY.gait first. Returns each case's track."""
        lines = [f"study {name}", ""]
        for c, table, words, t_end in cases:
            k = c.split("__")[0]
            gate = os.path.join(self.dir, k + ".gate")
            run = " ".join([f"run --scene obstacle --conditions paper --gate {gate} --t-end {t_end:g}"]
                           + model_run_words(words) + [words]).rstrip()
            if table is None:
                lines.append(f"case {c} gait-design {os.path.join(self.dir, k + '.gait')} "
                             f"--stretch --calibration @data/{CAL} --cal-rule {RULE} "
                             f"--p-max {P_MAX}")
                lines.append(f"then {run} --gait @case/gait.csv")
            else:
                lines.append(f"case {c} {run} --gait {table}")
        if not self.a.report_only:
            run_study(self.dir, name, lines, self.a.crawlsim, self.a.mpirun)
        return {c: track(os.path.join(self.dir, "cases", c + ".h5")) for c, _, _, _ in cases}

    def snap(self, v):
        """clip to the box and round to the grid"""
        out = []
        for n, vi in zip(self.a.free, v):
            _, lo, hi, grid, _ = PARAMS[n]
            out.append(round(min(max(vi, lo), hi) / grid) * grid)
        return out

    def evaluate(self, v):
        x = self.snap(v)
        key, text, cmd = Search.design(self.a, x)
        self.order.append((key, x))
        if self.local is not None and key not in self.local:
            # the local search's budget counts its distinct designs, run now or read back, so
            # that a rerun with a larger --evals continues the same path
            if len(self.local) >= self.a.evals:
                raise Budget
            self.local.add(key)
        if key in self.seen:
            return self.seen[key]
        if self.a.report_only:
            raise Budget    # a design not yet evaluated: nothing is run
        c = f"d{key}"
        gait = os.path.join(self.dir, c + ".gait")
        open(gait, "w").write(text)
        g = subprocess.run([sys.executable, os.path.join(HERE, "obstacle_gait.py"),
                            "--gate-from", gait, "--gate-out",
                            os.path.join(self.dir, c + ".gate")], capture_output=True, text=True)
        if g.returncode != 0:
            fail(f"{gait}: the gate: {g.stderr.strip()}")
        nom = self.study(f"nom_{key}", [(c, None, "", T_NOM)])[c]
        table = os.path.join(self.dir, "cases", c, "gait.csv")
        scr = {}
        if nom is not None and not nom["fell"] and os.path.exists(table):
            opts = dict(robust_nine())
            scr = self.study(f"screen_{key}", [
                (f"{c}__{n}", table, opts[n], T_RAMP05 if n == "ramp0.5" else T_SET)
                for n in self.a.screen])
        if nom is None or nom["fell"]:
            s = NOMINAL_FALLS
        else:
            s = max(nom["worst"], nom["off"]) + 2.0 * max(0.0, nom["tilt"] - 10.0)
        s += sum(set_penalty(scr.get(f"{c}__{n}")) for n in self.a.screen)
        t_table = float("nan")   # the table's length (its last row's time), s
        if os.path.exists(table):
            last = [ln for ln in open(table) if ln.strip() and not ln.startswith("#")][-1]
            t_table = float(last.split(",")[0])
        new = not os.path.exists(self.results)
        with open(self.results, "a") as f:
            if new:
                f.write(f"# {PROG}: base '{self.a.base}'; objective J (mm), the nominal's "
                        "worst node from 4 s and end, the screening runs' end offsets (mm; "
                        "nan: fell or not run)\n")
                f.write("key,params,J,table_end_s,nom_worst_mm,nom_worst_t_s,nom_end_off_mm,"
                        "nom_tilt_deg,"
                        "nom_depth_mm,nom_x7,nom_h7,nom_x11,nom_x14,nom_x24,nom_z29,nom_z32,"
                        + ",".join(f"{n}_off_mm" for n in self.a.screen) + ",model\n")
            nd = (nom or {}).get("nodes") or [None] * len(TABLE3_T)
            at = {tn: nd[i] for i, tn in enumerate(TABLE3_T)}
            gv = lambda tn, j: f"{at[tn][j]:.1f}" if at.get(tn) else "nan"  # noqa: E731
            ok = nom is not None and not nom["fell"]
            f.write(f"{key}," + " ".join(f"{n}={xi:g}" for n, xi in zip(self.a.free, x))
                    + f",{s:.2f},{t_table:.2f},"
                    + (f"{nom['worst']:.1f},{nom['worst_t']:g},{nom['off']:.1f},{nom['tilt']:.1f},"
                       f"{nom['depth']:.3f}," if ok else "nan,nan,nan,nan,nan,")
                    + ",".join([gv(7, 0), gv(7, 1), gv(11, 0), gv(14, 0), gv(24, 0), gv(29, 2),
                                gv(32, 2)]) + ","
                    + ",".join(f"{r['off']:.1f}" if r and not r["fell"] else "nan"
                               for r in (scr.get(f"{c}__{n}") for n in self.a.screen))
                    + (f",{model_name()}" if self.model_col else "") + "\n")
        self.seen[key] = s
        print(f"{PROG}: d{key} " + " ".join(f"{n} {xi:g}" for n, xi in zip(self.a.free, x))
              + f": J {s:.1f} (nominal " + (f"worst {nom['worst']:.1f} mm at {nom['worst_t']:g} s,"
                                             f" end {nom['off']:.1f}" if ok else "falls")
              + "; " + ", ".join(f"{n} {verdict(scr.get(f'{c}__{n}'))}" for n in self.a.screen)
              + ")", flush=True)
        return s

    def full(self, k):
        """the rest of the set for the k best designs evaluated: DIR/full.csv"""
        best = sorted(self.seen.items(), key=lambda kv: kv[1])[:k]
        rows = []
        for key, s in best:
            c = f"d{key}"
            table = os.path.join(self.dir, "cases", c, "gait.csv")
            if not os.path.exists(table):
                continue
            res = self.study(f"full_{key}", [
                (f"{c}__{n}", table, w, T_RAMP05 if n == "ramp0.5" else T_SET)
                for n, w in robust_nine()])
            res[c] = track(os.path.join(self.dir, "cases", c + ".h5"))
            n40 = sum(1 for n, _ in robust_nine() if res[f"{c}__{n}"] and not res[f"{c}__{n}"]["fell"]
                      and res[f"{c}__{n}"]["off"] <= SET_TOL)
            for n, w in [("nominal", "")] + robust_nine():
                r = res[c if n == "nominal" else f"{c}__{n}"]
                rows.append((key, s, n, w, r, n40))
        path = os.path.join(self.dir, "full.csv")
        with open(path, "w") as f:
            f.write("key,J,run,options,status,fell,end_off_mm,worst_node_mm,worst_t_s,"
                    "tilt_max_deg,leg_depth_mm,gate_held_s,t_end_s,set_within_40mm\n")
            for key, s, n, w, r, n40 in rows:
                r = r or {"status": "missing", "fell": True}
                f.write(f"{key},{s:.2f},{n},{w},{r['status']},{int(r['fell'])},"
                        + ",".join(f"{r.get(q, float('nan')):.{d}f}" for q, d in
                                   (("off", 1), ("worst", 1), ("worst_t", 0), ("tilt", 1),
                                    ("depth", 3), ("held", 3), ("t_end", 2)))
                        + f",{n40}\n")
        print(open(path).read(), end="")


def main():
    ap = argparse.ArgumentParser(prog=PROG, description=__doc__.split("\n\n")[0])
    ap.add_argument("--dir", default="obstacle_search")
    ap.add_argument("--base", default="--up-short -1 --over-step -3 --reach 55 --clear-down",
                    help="obstacle_gait.py's fixed options of every design (default: rule 16 "
                    "and 12b, the sixth session's r55d; rule 17, the script's default since "
                    "2026-12-07, off as it was for that design)")
    ap.add_argument("--free", default="settle,Tclimb,Tcross,Dcross",
                    help="the free parameters, among " + ",".join(PARAMS))
    ap.add_argument("--x0", default=None, help="their start (default: the script's defaults)")
    ap.add_argument("--sweep", type=int, default=6, help="designs of the sweep, the start "
                    "included (default 6)")
    ap.add_argument("--evals", type=int, default=6, help="designs of the local search at most "
                    "(those read back from results.csv included; default 6)")
    ap.add_argument("--seed", type=int, default=1, help="the sweep's seed")
    ap.add_argument("--screen", default="ramp0.5,m25g", help="the set's runs in the objective")
    ap.add_argument("--full", type=int, default=0, help="the rest of the set for the K best")
    ap.add_argument("--crawlsim", default=os.path.join(ROOT, "build", "tools", "crawlsim"))
    ap.add_argument("--mpirun", type=int, default=1)
    ap.add_argument("--report-only", action="store_true",
                    help="run nothing: replay the search from the finished cases as far as they "
                    "go and write --full's table with the runs not finished as missing")
    ap.add_argument("--write-gait", default=None, metavar="FILE",
                    help="write the description of the design --x0 (with --base) to FILE, print "
                    "its key, its obstacle_gait.py command, the model's run options and the "
                    "set's step halved, and run nothing")
    ap.add_argument("--legs", choices=("rod", "strain"), default=None, help="the leg level "
                    "of every run (default: the scene's)")
    ap.add_argument("--links", type=int, default=None, help="rod elements or strain bending "
                    "modes per leg segment of every run (default: the level's)")
    ap.add_argument("--strain-step", choices=("fixed", "adaptive"), default=None,
                    help="strain legs: crawlsim run's --strain-step (default: the level's)")
    ap.add_argument("--step-tol", type=float, default=None, help="with --strain-step "
                    "adaptive: the local error allowed per step, mm (default: the level's)")
    ap.add_argument("--dt", type=float, default=None, help="the run's step, s (default: the "
                    "level's)")
    a = ap.parse_args()
    a.free = a.free.split(",")
    if not a.free or any(n not in PARAMS for n in a.free) or len(set(a.free)) != len(a.free):
        fail(f"--free '{','.join(a.free)}': names among {','.join(PARAMS)}")
    for n in a.free:
        if PARAMS[n][0] in a.base.split():
            fail(f"--free {n}: {PARAMS[n][0]} is also in --base")
    if a.links is not None:
        if not 1 <= a.links <= 64:
            fail(f"--links {a.links}: elements per segment in 1..64")
        LINKS[0] = a.links
    if (a.strain_step is not None or a.step_tol is not None) and a.legs != "strain":
        fail("--strain-step, --step-tol: strain legs only (give --legs strain)")
    if a.step_tol is not None and a.strain_step != "adaptive":
        fail("--step-tol: with --strain-step adaptive only")
    if a.step_tol is not None and not (math.isfinite(a.step_tol) and 0 < a.step_tol <= 100):
        fail(f"--step-tol {a.step_tol}: a local error in (0, 100] mm")
    if a.dt is not None and not (math.isfinite(a.dt) and 0 < a.dt <= 0.01):
        fail(f"--dt {a.dt}: a step in (0, 0.01] s")
    MODEL.update(legs=a.legs, strain_step=a.strain_step, step_tol=a.step_tol, dt=a.dt)
    names = dict(robust_nine())
    a.screen = [n for n in a.screen.split(",") if n]
    if any(n not in names for n in a.screen):
        fail(f"--screen: runs among {','.join(names)}")
    try:
        x0 = ([float(v) for v in a.x0.split(",")] if a.x0
              else [PARAMS[n][4] for n in a.free])
    except ValueError:
        x0 = []
    if len(x0) != len(a.free) or not all(
            math.isfinite(v) and PARAMS[n][1] <= v <= PARAMS[n][2] for n, v in zip(a.free, x0)):
        fail(f"--x0 '{a.x0}': one number per free parameter within its box: "
             + ", ".join(f"{n} {PARAMS[n][1]:g}..{PARAMS[n][2]:g}" for n in a.free))
    if a.sweep < 1 or a.evals < 0 or a.full < 0 or a.mpirun < 1:
        fail("--sweep >= 1, --evals >= 0, --full >= 0, --mpirun >= 1")
    if a.write_gait:
        key, text, cmd = Search.design(a, x0)
        open(a.write_gait, "w").write(text)
        print(f"d{key}: /usr/bin/python3 tools/obstacle_gait.py "
              + " ".join(cmd[2:]) + f" -o {a.write_gait}"
              + (f"; runs: {' '.join(model_run_words(''))}" if model_run_words("") else "")
              + f"; the set's step halved: {dict(robust_nine())['dt_half']}")
        return
    if not os.access(a.crawlsim, os.X_OK):
        fail(f"{a.crawlsim}: not an executable (build first, or give --crawlsim)")
    lo = np.array([PARAMS[n][1] for n in a.free])
    hi = np.array([PARAMS[n][2] for n in a.free])
    s = Search(a)
    pts = [x0]
    if a.sweep > 1:
        u = qmc.LatinHypercube(d=len(a.free), seed=a.seed).random(a.sweep - 1)
        pts += list(qmc.scale(u, lo, hi))
    try:
        scores = [s.evaluate(p) for p in pts]
    except Budget:      # --report-only before the sweep's end
        scores = []
    best = s.snap(pts[int(np.argmin(scores))]) if scores else None
    if a.evals > 0 and best is not None:
        s.local = set()
        step = 0.2 * (hi - lo)
        simplex = [best] + [[best[j] + (step[j] if j == i else 0) * (1 if best[j] + step[j] <= hi[j]
                                                                     else -1)
                             for j in range(len(best))] for i in range(len(best))]
        try:
            minimize(s.evaluate, best, method="Nelder-Mead", bounds=list(zip(lo, hi)),
                     options={"initial_simplex": simplex, "maxfev": 4 * a.evals + 10,
                              "xatol": 0.5, "fatol": 1.0})
        except Budget:
            pass
    if not s.seen:
        fail(f"{a.dir}: no design evaluated yet")
    key = min(s.seen, key=s.seen.get)
    x = [x for k, x in s.order if k == key]
    print(f"{PROG}: best d{key}: J {s.seen[key]:.1f}"
          + (": " + " ".join(f"{n} {v:g}" for n, v in zip(a.free, x[0])) if x else "")
          + f"; its description {os.path.join(a.dir, 'd' + key + '.gait')}", flush=True)
    if a.full:
        s.full(a.full)


if __name__ == "__main__":
    main()

/* cmd_run.c: `crawlsim run`: simulate a gait on a terrain and write the run HDF5 file.
 * Contract (docs/design.md): crawlsim run [--scene flat-road|obstacle] [--gait FILE.csv]
 *   [--legs auto|rod|strain|rom] [--friction MU] [--pressure-scale K] [--t-end S] [--out FILE.h5]
 * Extra options: --terrain FILE, --dt S, --output-dt S, --ramp S, --tau S, --support-mass KG,
 *   --links N, --iterations N, --gravity M/S2, --calibration FILE, --macro-steps N,
 *   --coupling staggered|stabilised|gs|tree, --set NAME=VALUE (the legs' actuator, repeatable), --quiet,
 *   --contact-scale K, --rod-tol K (rod legs' CVODE tolerances x K), --step-order 1|2 (strain
 *   legs' tree step: backward Euler or BDF2), --cal-rule prism|rbf|rbf-pair
 *   (the FE mode table's rule), --checkpoint FILE, --checkpoint-every S, --resume FILE
 *   (resumable runs: docs/notes/cli_output.md),
 *   --tol MM and --levels FILE (with --legs auto: the cheapest measured configuration of the
 *   scene whose track error is within MM, from the table robot/levels.csv, robot_levels.h).
 * Options take "--name VALUE" or "--name=VALUE". Each option fills the field of the run
 * definition it names (crawlsim.h csRunDef); the library validates it, runs and returns the
 * result this command prints. Bad input (flags, files, an unwritable --out) is found before
 * the robot is built or settled, and every failure prints exactly one line
 * "crawlsim run: <cause>" on stderr (file:line for file errors) and exits 1. */
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crawlsim.h"
#include "cs_commands.h"
#include "cs_opts.h"
#include "cs_signal.h"

/* the options of `crawlsim run`, for parsing and --help (cs_opts.h) */
static const csxOpt kRunOpts[] = {
    {"--scene", "flat-road|obstacle|slope", "flat-road",
     "the scene: terrain, gait, calibration and conditions of the paper's Sec. 5.1 (flat-road) "
     "or 5.2 (obstacle); slope: the flat road inclined by --slope-deg"},
    {"--scene-file", "FILE", NULL,
     "terrain, gait, conditions, start, heading, slope and t-end from a scene file "
     "(docs/reference/formats.md \"Scene files\"); options given here win"},
    {"--slope-deg", "A", "the terrain's (the slope scene: 10)",
     "incline the terrain by A deg about z, +x uphill (gravity turns; x stays the distance along "
     "the slope), within +-45"},
    {"--gait", "FILE.csv",
     "the scene's (gaits/flat_road_rod.csv, under earth gaits/flat_road_earth.csv; "
     "gaits/obstacle.csv)",
     "the gait table (docs/reference/formats.md); a gait of your own makes the default "
     "conditions earth"},
    {"--foothold", "FILE|none", "none",
     "the gait's companion .foothold file: the landings it lists are chosen during the run "
     "from where the support stands (docs/reference/formats.md \"Foothold files\")"},
    {"--gate", "FILE|none", "the scene's own gait's (gaits/obstacle.gate; none on the flat road)",
     "the gait's companion .gate file: each lift waits until the pair before it is down, read "
     "from the chamber pressures against the design's (a sensing controller: the run is "
     "closed-loop); none plays the table on time (docs/reference/formats.md \"Gate files\")"},
    {"--terrain", "FILE", "the scene's (terrains/flat_road.terrain, terrains/obstacle.terrain)",
     "the terrain file; a terrain of your own makes the default conditions earth"},
    {"--legs", "auto|rod|strain|rom", "the scene's: strain (flat-road, slope), rod (obstacle)",
     "the leg level; auto picks the scene's cheapest measured configuration within --tol; "
     "strain: the strain-coordinate Cosserat rod (docs/notes/strain_leg.md), coupled tree, its "
     "step adaptive (--strain-step; a fixed --dt when given) and --links bending modes per "
     "segment (default 2); rom: the reduced FE leg of --rom-file (docs/notes/rom.md), contact at its sole only; prb "
     "was retired (refused naming rod or strain)"},
    {"--rom-file", "LEG.h5", NULL,
     "with --legs rom: the reduced leg's file (crawlsim rom leg-file), built for the legs' "
     "actuator (--set)"},
    {"--friction", "MU", "0.8", "Coulomb friction coefficient of every contact (dimensionless)"},
    {"--pressure-scale", "K", "1",
     "multiplies every pressure of the gait (refused if it pushes a gait above 1 MPa)"},
    {"--t-end", "S", "0 = the gait's length",
     "simulated time in s; 0 runs until the last row's change has finished (with a gate: on "
     "the table's clock, which the gate holds and a crawl statement skips)"},
    {"--out", "FILE.h5", "run.h5", "the run file; FILE.xdmf is written beside it"},
    {"--checkpoint", "FILE", NULL,
     "write the run's state to FILE every --checkpoint-every s, at the end and on SIGINT/SIGTERM "
     "(atomically), so --resume FILE can continue it (docs/notes/cli_output.md)"},
    {"--checkpoint-every", "S", "1 (resumed: the checkpoint's)",
     "simulated seconds between checkpoints; the integrators restart at each, so it is part of "
     "the run"},
    {"--resume", "FILE", NULL,
     "continue the run of checkpoint FILE (the same options; --t-end may be later) instead of "
     "settling, appending to its --out; checkpoints go on into FILE unless --checkpoint says"},
    {"--calibration", "FILE", "the scene's (robot/calibration_fe_leg_modes_sym.h5)",
     "the legs' pressure -> shape calibration table"},
    {"--cal-rule", "prism|rbf|rbf-pair", "the scene's (rbf-pair); the table's own (prism) with "
     "--calibration",
     "the FE mode table's model rule; refused for other calibration kinds; recorded as "
     "calibration_rule"},
    {"--cal-drop", "stretch[,stiffness]", "none",
     "rod legs leave that part of the calibration out (the segments' axial stretch; a mode "
     "table's probed EI, EA); recorded as calibration_dropped"},
    {"--conditions", "earth|paper", "the scene's: paper with its own terrain and gait, earth "
     "when --terrain or --gait is given",
     "earth: gravity on every body; paper: the legs keep mass and inertia but feel no gravity "
     "(the paper's assumption)"},
    {"--dt", "S", "1e-3 (strain: the adaptive step's longest, 5e-3)",
     "ODE time step in s (at most 0.01); with strain legs and no --strain-step it fixes their "
     "step (0.5 ms is the level's fixed step)"},
    {"--output-dt", "S", "0.01", "sampling interval of the output in s (>= --dt)"},
    {"--ramp", "S", "the gait's '# @ramp', else 0.2",
     "pressure ramp in s: each gait row's change takes S to arrive (overlapping when the rows "
     "come faster)"},
    {"--tau", "S", "0.02", "pneumatic lag time constant in s (0: none)"},
    {"--gravity", "M/S2", "9.81", "gravitational acceleration in m/s^2"},
    {"--support-mass", "KG", "0.05", "mass of the support (body) in kg"},
    {"--links", "N", "the scene's for rod legs (8 on flat-road, 4 on obstacle), strain 2, else 4",
     "elements (rod) or bending modes (strain) per leg segment, 1..64"},
    {"--iterations", "N", "240", "ODE QuickStep iterations per step, 1..10000"},
    {"--macro-steps", "N", "1", "ODE steps per exchange with co-simulated legs (H = N dt)"},
    {"--coupling", "staggered|stabilised|gs|tree", "gs (rod), tree (strain), stabilised (rom)",
     "how co-simulated legs hand their wrench to the support: gs (Gauss-Seidel: the support "
     "steps first, momentum exact), stabilised (the legs first along a predicted motion), "
     "staggered (explicit: needs --dt 3.5e-5 or less), tree (the support and the legs in one "
     "implicit step solved as a tree with Newton passes, strain legs only; a rejected step is "
     "retried in halves)"},
    {"--contact-scale", "K", "1",
     "multiplies the normal stiffness of every contact law (ODE's 100 N/mm of the support, the "
     "legs' soft foundation modulus), 0 < K <= 1e6"},
    {"--rod-tol", "K", "1",
     "multiplies every CVODE tolerance of rod and rom legs, 0 < K <= 1000; recorded as "
     "rod_tolerance_scale"},
    {"--step-order", "1|2", "the level's (strain: 1)",
     "strain legs: the tree step's formula, 1 backward Euler, 2 BDF2 (support and legs)"},
    {"--strain-step", "fixed|adaptive",
     "adaptive, unless --dt or --step-order 2 (their steps are fixed); --legs auto: its row's",
     "strain legs: fixed (every step --dt, default then 5e-4) or adaptive (each --dt, default "
     "then 5e-3, crossed in steps chosen by a local error estimate of --step-order's formula); "
     "beside --legs auto: pick among the table's rows of that kind"},
    {"--step-tol", "MM", "2.5e-4",
     "with the adaptive step: the local error allowed per step in mm (velocities: mm per 10 ms)"},
    {"--strain-sub", "N", "0",
     "strain legs: Magnus sub-intervals per flexible piece (the points of their kinematics, "
     "inertia and contact: 2 N + 1 per segment), 1..16; 0 by the basis: 2 at --links <= 2, "
     "4 above"},
    {"--tol", "MM", NULL,
     "with --legs auto: the track error allowed against the rod reference, in mm"},
    {"--levels", "FILE", "robot/levels.csv",
     "with --legs auto: the table of measured configurations (tools/bench_levels.py)"},
    {"--set", "NAME=VALUE", NULL,
     "a parameter of the legs' actuator, repeatable (as crawlsim bend: S1 a C10 ...); the "
     "calibration must be of that actuator"},
    {"--quiet", NULL, "off",
     "no banner and no progress lines on stderr (the summary, the verdict and errors are still "
     "printed)"},
};

static const csxOptTable kRunTable = {
    "run", "",
    "Simulate a gait on a terrain and write the run's HDF5 file and its XDMF "
    "(docs/reference/output.md). Prints the conditions, a progress line per simulated second, a "
    "stance check, a summary and a verdict line.",
    kRunOpts, CSX_NOPT(kRunOpts),
    "Exit status 0 on success, 1 with one error line on bad input or a failed run "
    "(docs/reference/commands.md)."};


/* the options that fill a number or a string of the run definition */
static const struct {
  const char* flag;
  size_t off;
  int is_num;
} kRunFields[] = {
    {"--scene", offsetof(csRunDef, scene), 0},
    {"--scene-file", offsetof(csRunDef, scene_file), 0},
    {"--gait", offsetof(csRunDef, gait), 0},
    {"--foothold", offsetof(csRunDef, foothold), 0},
    {"--gate", offsetof(csRunDef, gate), 0},
    {"--terrain", offsetof(csRunDef, terrain), 0},
    {"--legs", offsetof(csRunDef, legs), 0},
    {"--rom-file", offsetof(csRunDef, rom_file), 0},
    {"--out", offsetof(csRunDef, out), 0},
    {"--checkpoint", offsetof(csRunDef, checkpoint), 0},
    {"--resume", offsetof(csRunDef, resume), 0},
    {"--checkpoint-every", offsetof(csRunDef, checkpoint_every), 1},
    {"--calibration", offsetof(csRunDef, calibration), 0},
    {"--cal-rule", offsetof(csRunDef, cal_rule), 0},
    {"--cal-drop", offsetof(csRunDef, cal_drop), 0},
    {"--conditions", offsetof(csRunDef, conditions), 0},
    {"--coupling", offsetof(csRunDef, coupling), 0},
    {"--levels", offsetof(csRunDef, levels), 0},
    {"--slope-deg", offsetof(csRunDef, slope_deg), 1},
    {"--friction", offsetof(csRunDef, friction), 1},
    {"--pressure-scale", offsetof(csRunDef, pressure_scale), 1},
    {"--t-end", offsetof(csRunDef, t_end), 1},
    {"--dt", offsetof(csRunDef, dt), 1},
    {"--output-dt", offsetof(csRunDef, output_dt), 1},
    {"--ramp", offsetof(csRunDef, ramp), 1},
    {"--tau", offsetof(csRunDef, tau), 1},
    {"--support-mass", offsetof(csRunDef, support_mass_kg), 1},
    {"--links", offsetof(csRunDef, links), 1},
    {"--gravity", offsetof(csRunDef, gravity), 1},
    {"--macro-steps", offsetof(csRunDef, macro_steps), 1},
    {"--tol", offsetof(csRunDef, legs_tol_mm), 1},
    {"--contact-scale", offsetof(csRunDef, contact_scale), 1},
    {"--rod-tol", offsetof(csRunDef, rod_tol), 1},
    {"--step-order", offsetof(csRunDef, step_order), 1},
    {"--strain-step", offsetof(csRunDef, strain_step), 0},
    {"--step-tol", offsetof(csRunDef, step_tol), 1},
    {"--strain-sub", offsetof(csRunDef, strain_sub), 1},
    {"--iterations", offsetof(csRunDef, iterations), 1},
};


/* the library's lines of what the run is (csRunDef.log), as the banner on the stream `user`
 * (the command: stderr; a study's step: the case's log) */
static void printBanner(void* user, const char* line) {
  fprintf((FILE*)user, "crawlsim run: %s\n", line);
}


/* the progress line per simulated second (csRunDef.progress) on the stream `user` */
static void printProgress(void* user, double t, const double x[3], double wall_s) {
  fprintf((FILE*)user, "  t = %5.2f s  x = %7.2f  y = %6.2f  z = %6.2f mm  (%.1f s wall)\n", t,
          x[0], x[1], x[2], wall_s);
}


/* the option `flag` with value v into the definition; 0 and err filled if v is not a number
 * where one is needed */
static int setField(csRunDef* def, const char* flag, const char* v, csError* err) {
  for (size_t k = 0; k < sizeof kRunFields / sizeof kRunFields[0]; k++) {
    if (strcmp(flag, kRunFields[k].flag)) continue;
    char* field = (char*)def + kRunFields[k].off;
    if (!kRunFields[k].is_num) {
      memcpy(field, &v, sizeof v);
      return 1;
    }
    char* end;
    double x = strtod(v, &end);
    if (end == v || *end != '\0' || !isfinite(x)) {
      cs_errorSet(err, CS_ERR_PARSE, "%s '%.60s' is not a finite number", flag, v);
      return 0;
    }
    memcpy(field, &x, sizeof x);
    return 1;
  }
  return 1;
}


/* the verdict line of a run that started stepping (r->verdict set) into out */
static void verdictLine(const csRunResult* r, csStatus st, char* out, size_t size) {
  if (st != CS_OK) {
    snprintf(out, size, "verdict (%s, %s legs): %s: %s", r->conditions, r->legs, r->verdict,
             r->message);
  } else {
    snprintf(out, size, "verdict (%s, %s legs): %s: x = %.1f mm, z = %.1f mm in %.2f s, tilt "
             "%.1f deg", r->conditions, r->legs, r->verdict, r->position[0], r->position[2],
             r->t_end, r->tilt_deg);
  }
}


/* the summary of a run that started stepping, ending with its verdict line, on out */
static void printSummary(FILE* out, const csRunDef* def, const csRunResult* r, csStatus st) {
  fprintf(out, "final t = %.3f s: support displacement x = %.2f mm, y = %.2f mm, z = %.2f mm, "
          "tilt %.2f deg\n", r->t_end, r->position[0], r->position[1], r->position[2],
          r->tilt_deg);
  fprintf(out, "wall time %.2f s, real-time factor %.2f (simulated s per wall s), output %s\n",
          r->wall_s, r->real_time_factor, def->out);
  /* where the time went: one entry per stage timer, as in the HDF5 attributes */
  fprintf(out, "time split (s):");
  for (int k = 0; k < r->ntimer; k++) {
    fprintf(out, " %s %.3f%s", r->timer_name[k], r->timer_s[k], k + 1 < r->ntimer ? "," : "\n");
  }
  if (r->gain_projections > 0) {
    fprintf(out, "coupling: the legs' interface gains were not passive in %ld macro step(s); "
            "their implicit part was projected onto passive gains there (README \"Rod legs\")\n",
            r->gain_projections);
  }
  char line[CS_ERROR_MSG_SIZE + 128];
  verdictLine(r, st, line, sizeof line);
  fprintf(out, "%s\n", line);
}


/* argv into def (the --set values kept in sets[32]): 0; 1 with err filled; 2 when `it` holds
 * --help or an option error (csx_optReport's kinds, *kind) */
static int parseRun(int argc, char** argv, csRunDef* def, const char** sets, csxOptIter* it,
                    csxOptKind* kind, csError* err) {
  csx_optBegin(it);
  while ((*kind = csx_optNext(&kRunTable, argc, argv, it)) != CSX_OPT_END) {
    if (*kind == CSX_OPT_HELP || *kind == CSX_OPT_ERROR) return 2;
    if (*kind == CSX_OPT_OPERAND) {
      cs_errorSet(err, CS_ERR_ARG, "unexpected argument '%.60s' (see crawlsim run --help)",
                  it->value);
      return 1;
    }
    const char* flag = it->opt->name;
    if (!strcmp(flag, "--quiet")) {
      def->progress = NULL;
      def->log = NULL;
    } else if (!strcmp(flag, "--set")) {
      if (def->n_actuator_set == 32) {
        cs_errorSet(err, CS_ERR_ARG, "more than 32 --set options");
        return 1;
      }
      sets[def->n_actuator_set++] = it->value;
      def->actuator_set = sets;
    } else if (!setField(def, flag, it->value, err)) {
      return 1;
    }
  }
  return 0;
}


/* the definition the command starts from, its lines going to `lines` */
static csRunDef commandDef(FILE* lines) {
  csRunDef def = cs_defaultRunDef();
  def.out = "run.h5";
  def.progress = printProgress;
  def.progress_user = lines;
  def.log = printBanner;
  def.log_user = lines;
  def.cancel = csx_signalFlag();
  return def;
}


/* `crawlsim run` with its banner and progress on `notes`, its summary on `table` and its
 * results in *res (NULL: the command line; else a study's step, both streams its log) */
static int runCommand(int argc, char** argv, FILE* table, FILE* notes, csxStepResult* res) {
  /* SIGINT/SIGTERM end the run after the step in progress (cs_signal.h): exit 128 + signal */
  csx_signalInstall();
  csRunDef def = commandDef(notes);
  const char* sets[32];
  csError err;
  cs_errorClear(&err);
  csxOptIter it;
  csxOptKind kind;
  int p = parseRun(argc, argv, &def, sets, &it, &kind, &err);
  p = csx_parseEnd(&kRunTable, p, kind, &it, &err, notes, res);
  if (p >= 0) return p;
  csRunResult r;
  csStatus st = cs_run(&def, &r, &err);
  if (r.verdict[0]) {
    /* it stepped: the file holds its samples, the result where it got */
    printSummary(table, &def, &r, st);
    if (res) {
      res->t_final = r.t_end;
      memcpy(res->x_final, r.position, sizeof res->x_final);
      res->wrote_samples = def.out != NULL;
      char line[CS_ERROR_MSG_SIZE + 128];
      verdictLine(&r, st, line, sizeof line);
      /* the case file keeps its first 255 characters, as it kept the log's verdict line */
      snprintf(res->verdict, sizeof res->verdict, "%.*s", (int)sizeof res->verdict - 1, line);
      snprintf(res->summary, sizeof res->summary, "%.*s", (int)sizeof res->summary - 1, line);
    }
  }
  if (st == CS_OK) return 0;
  csx_stepFailed(res, notes, "run", err.msg);
  return st == CS_ERR_INTERRUPTED && csx_signalExitCode() ? csx_signalExitCode() : 1;
}


int csx_cmdRun(int argc, char** argv) {
  return runCommand(argc, argv, stdout, stderr, NULL);
}


int csx_stepRun(int argc, char** argv, FILE* log, csxStepResult* res) {
  return runCommand(argc, argv, log, log, res);
}

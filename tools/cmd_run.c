/* cmd_run.c: `crawlsim run`: simulate a gait on a terrain and write the run HDF5 file.
 * Contract (docs/design.md): crawlsim run [--scene flat-road|obstacle] [--gait FILE.csv]
 *   [--legs auto|prb|rod|strain|rom] [--friction MU] [--pressure-scale K] [--t-end S] [--out FILE.h5]
 * Extra options: --terrain FILE, --dt S, --output-dt S, --ramp S, --tau S, --support-mass KG,
 *   --links N, --iterations N, --gravity M/S2, --calibration FILE, --macro-steps N,
 *   --coupling staggered|stabilised|gs|tree, --set NAME=VALUE (the legs' actuator, repeatable), --quiet,
 *   --contact-scale K, --rod-tol K (rod legs' CVODE tolerances x K), --step-order 1|2 (strain
 *   legs' tree step: backward Euler or BDF2), --cal-rule prism|rbf|rbf-pair
 *   (the FE mode table's rule),
 *   --tol MM and --levels FILE (with --legs auto: the cheapest measured configuration of the
 *   scene whose track error is within MM, from the table robot/levels.csv, robot_levels.h).
 * Options take "--name VALUE" or "--name=VALUE". Bad input (flags, files, an unwritable
 * --out) is found before the robot is built or settled, and every failure prints exactly one
 * line "crawlsim run: <cause>" on stderr (file:line for file errors) and exits 1. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_commands.h"
#include "cs_opts.h"
#include "cs_paths.h"
#include "terrains_scenefile.h"
#include "cs_signal.h"
#include "robot_calibration.h"
#include "robot_levels.h"
#include "robot_strain.h"
#include "sim_model.h"

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
    {"--gait", "FILE.csv", "the scene's (gaits/flat_road_rod.csv, gaits/obstacle.csv)",
     "the gait table (docs/reference/formats.md); a gait of your own makes the default "
     "conditions earth"},
    {"--terrain", "FILE", "the scene's (terrains/flat_road.terrain, terrains/obstacle.terrain)",
     "the terrain file; a terrain of your own makes the default conditions earth"},
    {"--legs", "auto|prb|rod|strain|rom", "rod",
     "the leg level; auto picks the scene's cheapest measured configuration within --tol; "
     "strain: the strain-coordinate Cosserat rod (docs/notes/strain_leg.md), coupled tree, its "
     "step --dt (default 1 ms, the level's own) and --links bending modes per segment (default "
     "3); rom is not available yet"},
    {"--friction", "MU", "0.8", "Coulomb friction coefficient of every contact (dimensionless)"},
    {"--pressure-scale", "K", "1",
     "multiplies every pressure of the gait (refused if it pushes a gait above 1 MPa)"},
    {"--t-end", "S", "0 = the gait's length",
     "simulated time in s; 0 runs until the last row's change has finished"},
    {"--out", "FILE.h5", "run.h5", "the run file; FILE.xdmf is written beside it"},
    {"--calibration", "FILE", "the scene's (flat-road: robot/calibration_fe_leg_modes_sym.h5, "
     "obstacle: robot/calibration_fe_leg_modes.h5)",
     "the legs' pressure -> shape calibration table"},
    {"--cal-rule", "prism|rbf|rbf-pair", "the scene's: rbf-pair on flat-road, the table's own "
     "(prism) on obstacle or with --calibration",
     "the FE mode table's model rule; refused for other calibration kinds; recorded as "
     "calibration_rule"},
    {"--cal-drop", "stretch[,stiffness]", "none",
     "rod legs leave that part of the calibration out (the segments' axial stretch; a mode "
     "table's probed EI, EA); recorded as calibration_dropped"},
    {"--conditions", "earth|paper", "the scene's: paper with its own terrain and gait, earth "
     "when --terrain or --gait is given",
     "earth: gravity on every body; paper: the legs keep mass and inertia but feel no gravity "
     "(the paper's assumption)"},
    {"--dt", "S", "1e-3 (strain: the level's own step, 1e-3)", "ODE time step in s (at most 0.01)"},
    {"--output-dt", "S", "0.01", "sampling interval of the output in s (>= --dt)"},
    {"--ramp", "S", "0.2", "pressure ramp between gait rows in s"},
    {"--tau", "S", "0.02", "pneumatic lag time constant in s (0: none)"},
    {"--gravity", "M/S2", "9.81", "gravitational acceleration in m/s^2"},
    {"--support-mass", "KG", "0.05", "mass of the support (body) in kg"},
    {"--links", "N", "the scene's for rod legs (8 on flat-road, 4 on obstacle), strain 3, else 4",
     "links (prb) or elements (rod) per leg segment, 1..64"},
    {"--iterations", "N", "240", "ODE QuickStep iterations per step, 1..10000"},
    {"--macro-steps", "N", "1", "ODE steps per exchange with co-simulated legs (H = N dt)"},
    {"--coupling", "staggered|stabilised|gs|tree", "gs (rod), tree (strain)",
     "how co-simulated legs hand their wrench to the support: gs (Gauss-Seidel: the support "
     "steps first, momentum exact), stabilised (the legs first along a predicted motion), "
     "staggered (explicit: needs --dt 3.5e-5 or less), tree (the support and the legs in one "
     "implicit step solved as a tree with Newton passes, strain legs only; a rejected step is "
     "retried in halves); prb ignores it"},
    {"--contact-scale", "K", "1",
     "multiplies the normal stiffness of every contact law (ODE's 100 N/mm of prb legs and the "
     "support, the rod legs' soft foundation modulus), 0 < K <= 1e6"},
    {"--rod-tol", "K", "1",
     "multiplies every CVODE tolerance of rod legs, 0 < K <= 1000; recorded as "
     "rod_tolerance_scale"},
    {"--step-order", "1|2", "the level's (strain: 1)",
     "strain legs: the tree step's formula, 1 backward Euler, 2 BDF2 (support and legs)"},
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


/* the longest run one command may ask for: beyond this --t-end / --dt is a typo, and the step
 * count would overflow the driver's step counter on 32-bit longs */
#define MAX_STEPS 1e9
/* the longest step the driver accepts (sim_driver.c validateOptions) */
#define MAX_DT_S 0.01


/* parse a finite number given to `flag`; 0 and err filled if it is not one */
static int parseNum(const char* flag, const char* s, double* v, csError* err) {
  char* end;
  *v = strtod(s, &end);
  if (end == s || *end != '\0' || !isfinite(*v)) {
    cs_errorSet(err, CS_ERR_PARSE, "%s '%.60s' is not a finite number", flag, s);
    return 0;
  }
  return 1;
}


/* fail now, not after settling, if the output file cannot be written: open it for appending
 * (which neither truncates an existing file nor needs HDF5) and remove it again if it is new */
static csStatus checkWritable(const char* path, csError* err) {
  FILE* f = fopen(path, "rb");
  int existed = f != NULL;
  if (f) {
    fclose(f);
  }
  errno = 0;
  f = fopen(path, "ab");
  if (!f) {
    return cs_errorSet(err, CS_ERR_IO, "--out %s: cannot create output file: %s", path,
                       strerror(errno));
  }
  fclose(f);
  if (!existed) {
    remove(path);
  }
  return CS_OK;
}


int csx_cmdRun(int argc, char** argv) {
  /* SIGINT/SIGTERM end the work after the step in progress (cs_signal.h); this command
   * polls the flag */
  csx_signalInstall();
  const char* scene = "flat-road";
  const char* gait = NULL;
  const char* terrain = NULL;
  const char* legs = NULL; /* the scene's (sim_scene.c) */
  const char* out = "run.h5";
  const char* calib = NULL;
  double friction = NAN, scale = 1.0, t_end = 0, dt = NAN, out_dt = NAN, ramp = NAN, tau = NAN;
  double support_kg = NAN, links = NAN, iters = NAN, gravity = NAN, macro = NAN;
  double step_order = NAN;
  const char* coupling = NULL;
  const char* conditions = NULL;
  const char* levels = NULL;
  const char* scene_file = NULL;
  double slope_deg = NAN;
  static cstSceneFile sf; /* ~1.5 KB of paths: not on the stack */
  double tol = NAN, kscale = NAN, rodtol = NAN;
  unsigned cal_drop = 0;
  const char* sets[32];
  int quiet = 0, nset = 0;
  csError err;
  cs_errorClear(&err);
  csModel m;
  cs_modelInit(&m);
  int rc = 1;
  csData* d = NULL;
  char terrain_buf[512], gait_buf[512], calib_buf[512], levels_buf[512];
  static csrLevelTable table; /* ~40 KB: not on the stack */

  /* options: --name VALUE or --name=VALUE; every failure is one line at done: */
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind kind; (kind = csx_optNext(&kRunTable, argc, argv, &it)) != CSX_OPT_END;) {
    if (kind == CSX_OPT_HELP) {
      csx_optHelp(&kRunTable, stdout);
      rc = 0;
      goto done;
    }
    if (kind == CSX_OPT_ERROR) {
      cs_errorSet(&err, CS_ERR_ARG, "%s", it.error);
      goto done;
    }
    if (kind == CSX_OPT_OPERAND) {
      cs_errorSet(&err, CS_ERR_ARG, "unexpected argument '%.60s' (see crawlsim run --help)",
                  it.value);
      goto done;
    }
    const char* flag = it.opt->name;
    const char* v = it.value;
    if (!strcmp(flag, "--quiet")) {
      quiet = 1;
      continue;
    }
    int ok = 1;
    if (!strcmp(flag, "--scene")) {
      scene = v;
    } else if (!strcmp(flag, "--gait")) {
      gait = v;
    } else if (!strcmp(flag, "--terrain")) {
      terrain = v;
    } else if (!strcmp(flag, "--scene-file")) {
      scene_file = v;
    } else if (!strcmp(flag, "--slope-deg")) {
      ok = parseNum(flag, v, &slope_deg, &err);
    } else if (!strcmp(flag, "--legs")) {
      legs = v;
    } else if (!strcmp(flag, "--out")) {
      out = v;
    } else if (!strcmp(flag, "--calibration")) {
      calib = v;
    } else if (!strcmp(flag, "--friction")) {
      ok = parseNum(flag, v, &friction, &err);
    } else if (!strcmp(flag, "--pressure-scale")) {
      ok = parseNum(flag, v, &scale, &err);
    } else if (!strcmp(flag, "--t-end")) {
      ok = parseNum(flag, v, &t_end, &err);
    } else if (!strcmp(flag, "--dt")) {
      ok = parseNum(flag, v, &dt, &err);
    } else if (!strcmp(flag, "--output-dt")) {
      ok = parseNum(flag, v, &out_dt, &err);
    } else if (!strcmp(flag, "--ramp")) {
      ok = parseNum(flag, v, &ramp, &err);
    } else if (!strcmp(flag, "--tau")) {
      ok = parseNum(flag, v, &tau, &err);
    } else if (!strcmp(flag, "--support-mass")) {
      ok = parseNum(flag, v, &support_kg, &err);
    } else if (!strcmp(flag, "--links")) {
      ok = parseNum(flag, v, &links, &err);
    } else if (!strcmp(flag, "--gravity")) {
      ok = parseNum(flag, v, &gravity, &err);
    } else if (!strcmp(flag, "--macro-steps")) {
      ok = parseNum(flag, v, &macro, &err);
    } else if (!strcmp(flag, "--coupling")) {
      coupling = v;
    } else if (!strcmp(flag, "--conditions")) {
      conditions = v;
    } else if (!strcmp(flag, "--tol")) {
      ok = parseNum(flag, v, &tol, &err);
    } else if (!strcmp(flag, "--contact-scale")) {
      ok = parseNum(flag, v, &kscale, &err);
    } else if (!strcmp(flag, "--rod-tol")) {
      ok = parseNum(flag, v, &rodtol, &err);
    } else if (!strcmp(flag, "--step-order")) {
      ok = parseNum(flag, v, &step_order, &err);
    } else if (!strcmp(flag, "--levels")) {
      levels = v;
    } else if (!strcmp(flag, "--cal-rule")) {
      csrCalRule rule;
      if (!csr_calRuleParse(v, &rule)) {
        cs_errorSet(&err, CS_ERR_ARG, "unknown --cal-rule '%.60s' (expected prism, rbf or "
                    "rbf-pair)", v);
        goto done;
      }
      m.cal_rule = (int)rule;
    } else if (!strcmp(flag, "--cal-drop")) {
      if (!csr_calDropParse(v, &cal_drop)) {
        cs_errorSet(&err, CS_ERR_ARG, "bad --cal-drop '%.60s' (expected stretch, stiffness, "
                    "stretch,stiffness or none)", v);
        goto done;
      }
    } else if (!strcmp(flag, "--set")) {
      if (nset == 32) {
        cs_errorSet(&err, CS_ERR_ARG, "more than 32 --set options");
        goto done;
      }
      sets[nset++] = v;
    } else if (!strcmp(flag, "--iterations")) {
      ok = parseNum(flag, v, &iters, &err);
    }
    if (!ok) {
      goto done;
    }
  }

  /* a scene file (terrains_scenefile.h) fills what the command line left out */
  int scene_given = 0;
  for (int i = 1; i < argc; i++) scene_given |= !strncmp(argv[i], "--scene", 7) &&
                                                (argv[i][7] == '\0' || argv[i][7] == '=');
  if (scene_file) {
    if (cst_sceneFileLoad(&sf, scene_file, &err) != CS_OK) goto done;
    if (!scene_given && sf.scene[0]) scene = sf.scene;
    if (!terrain && sf.terrain[0]) terrain = sf.terrain;
    if (!gait && sf.gait[0]) gait = sf.gait;
    if (!conditions && sf.conditions[0]) conditions = sf.conditions;
    if (t_end == 0 && sf.has_t_end) t_end = sf.t_end;
  }
  /* scene -> default terrain, gait and conditions (sim_scene.h) */
  const csScene* sc = cs_sceneFind(scene);
  if (!sc) {
    cs_errorSet(&err, CS_ERR_ARG, "unknown scene '%.60s' (expected flat-road, obstacle or slope)",
                scene);
    goto done;
  }
  int user_files = terrain != NULL || gait != NULL;
  if (!legs) legs = sc->legs;
  if (!terrain) terrain = csx_dataPath(sc->terrain, terrain_buf, sizeof terrain_buf);
  if (!gait) gait = csx_dataPath(sc->gait, gait_buf, sizeof gait_buf);
  int requested = -1;
  if (conditions) {
    csConditions c;
    if (cs_conditionsParse(conditions, &c, &err) != CS_OK) goto done;
    requested = (int)c;
  }
  csConditionsSource cond_src;
  cs_modelSetConditions(&m, cs_sceneConditions(sc, requested, user_files, &cond_src));
  /* the leg level: the table of registered levels is robot_robot.c's (one line per level) */
  const csrLegType* leg_type = NULL;
  if (!strcmp(legs, "auto")) {
    /* the scene's cheapest measured configuration within the tolerance (issue 11) */
    if (isnan(tol)) {
      cs_errorSet(&err, CS_ERR_ARG, "--legs auto needs --tol MM (the track error allowed "
                  "against the reference, see robot/levels.csv)");
      goto done;
    }
    if (!isnan(links) || !isnan(macro) || !isnan(dt) || !isnan(rodtol)) {
      cs_errorSet(&err, CS_ERR_ARG, "--legs auto sets --links, --macro-steps, --dt and --rod-tol "
                  "from its table: give them with --legs prb, rod or strain instead");
      goto done;
    }
    if (!levels) levels = csx_dataPath("robot/levels.csv", levels_buf, sizeof levels_buf);
    if (csr_levelTableRead(levels, &table, &err) != CS_OK) goto done;
    int k = csr_levelTablePick(&table, scene, tol, &err);
    if (k < 0) goto done;
    const csrLevelRow* row = &table.row[k];
    const csrLevelRow* fin = &table.row[csr_levelTableFinest(&table, scene)];
    /* the scene's costliest row: what always running the dearest configuration would cost */
    const csrLevelRow* top = &table.row[csr_levelTableCostliest(&table, scene)];
    leg_type = csr_legTypeFind(row->level, NULL);
    links = row->links;
    macro = row->macro_steps;
    dt = row->dt_s;
    rodtol = row->rod_tol;
    m.legs_auto_tol_mm = tol;
    char tolnote[32] = "";
    if (row->rod_tol != 1) {
      snprintf(tolnote, sizeof tolnote, ", rod tol %g", row->rod_tol);
    }
    snprintf(m.legs_auto_choice, sizeof m.legs_auto_choice,
             "%s, links %d, macro steps %d, dt %g s%s: the cheapest of %d configurations measured "
             "on %.31s within --tol %g mm (error %.3g mm against the reference, %.3g CPU s per "
             "simulated s); the most accurate (%s, links %d, macro steps %d, dt %g s: %.3g mm) "
             "costs %.3g, the costliest (%s, links %d, macro steps %d, dt %g s: %.3g mm) %.3g "
             "CPU s per simulated s, %.2fx; %.200s line %d, measured on %.63s%s",
             row->level, row->links, row->macro_steps, row->dt_s, tolnote,
             csr_levelTableCount(&table, scene), scene, tol, row->error_mm, row->cpu_s_per_s,
             fin->level, fin->links, fin->macro_steps, fin->dt_s, fin->error_mm,
             fin->cpu_s_per_s, top->level, top->links, top->macro_steps, top->dt_s,
             top->error_mm, top->cpu_s_per_s, top->cpu_s_per_s / row->cpu_s_per_s, levels,
             row->line, row->machine,
             user_files || conditions
                 ? " (measured with the scene's own terrain, gait and conditions, not this run's)"
                 : "");
  } else {
    int planned = 0;
    leg_type = csr_legTypeFind(legs, &planned);
    if (!leg_type && planned) {
      char names[128] = "";
      for (int i = 0, n = 0; i < csr_legTypeCount() && n < (int)sizeof names; i++) {
        int w = snprintf(names + n, sizeof names - n, "%s%s", i ? ", " : "",
                         csr_legTypeAt(i)->name);
        n += w > 0 ? w : 0;
      }
      cs_errorSet(&err, CS_ERR_ARG, "leg model '%s' is not available yet (available: %s)", legs,
                  names);
      goto done;
    }
    if (!leg_type) {
      cs_errorSet(&err, CS_ERR_ARG, "unknown leg model '%.60s' (expected auto, prb, rod, strain or "
                  "rom)",
                  legs);
      goto done;
    }
  }
  if (leg_type && !m.legs_auto_choice[0] && (!isnan(tol) || levels)) {
    cs_errorSet(&err, CS_ERR_ARG, "--tol and --levels go with --legs auto");
    goto done;
  }
  /* the scene's calibration (its gait was designed on it) under the scene's rule, overridable
   * with --calibration (which then keeps that table's own default rule) and --cal-rule */
  if (!calib) {
    calib = csx_dataPath(sc->calibration, calib_buf, sizeof calib_buf);
    csrCalRule rule;
    if (m.cal_rule < 0 && sc->cal_rule && csr_calRuleParse(sc->cal_rule, &rule)) {
      m.cal_rule = (int)rule;
    }
  }

  /* numbers: check each against its flag's range before anything is loaded or built */
  if (!isnan(friction) && !(friction >= 0)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--friction %g must be >= 0", friction);
    goto done;
  }
  if (!(scale >= 0)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--pressure-scale %g must be >= 0", scale);
    goto done;
  }
  if (!isnan(step_order) && step_order != 1 && step_order != 2) {
    cs_errorSet(&err, CS_ERR_RANGE, "--step-order %g must be 1 or 2", step_order);
    goto done;
  }
  if (!(t_end >= 0)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--t-end %g s must be >= 0 (0: the gait's length)", t_end);
    goto done;
  }
  if (!isnan(dt) && !(dt > 0 && dt <= MAX_DT_S)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--dt %g s must be > 0 and <= %g s", dt, MAX_DT_S);
    goto done;
  }
  /* a tree-stepped level's step is its own unless --dt says (csrLegType.step) */
  double h = !isnan(dt) ? dt : leg_type && leg_type->prepare && leg_type->step > 0
                                   ? leg_type->step : m.opt.h;
  if (!isnan(out_dt) && !(out_dt >= h)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--output-dt %g s must be >= the step %g s (--dt)", out_dt,
                h);
    goto done;
  }
  if (!isnan(ramp) && !(ramp >= 0)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--ramp %g s must be >= 0", ramp);
    goto done;
  }
  if (!isnan(tau) && !(tau >= 0)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--tau %g s must be >= 0 (0: no pressure lag)", tau);
    goto done;
  }
  if (!isnan(gravity) && !(gravity >= 0)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--gravity %g m/s^2 must be >= 0", gravity);
    goto done;
  }
  if (!isnan(support_kg) && !(support_kg > 0)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--support-mass %g kg must be > 0", support_kg);
    goto done;
  }
  if (!isnan(links) && (links != floor(links) || links < 1 || links > 64)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--links %g must be an integer in 1..64", links);
    goto done;
  }
  /* checked before the conversion to int, which would be undefined for 1e30 */
  if (!isnan(iters) && (iters != floor(iters) || iters < 1 || iters > 10000)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--iterations %g must be an integer in 1..10000", iters);
    goto done;
  }
  if (!isnan(macro) && (macro != floor(macro) || macro < 1 || macro > 100000)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--macro-steps %g must be an integer in 1..100000", macro);
    goto done;
  }
  if (!isnan(macro) && !isnan(out_dt) && !(out_dt >= macro * h)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--output-dt %g s must be >= the macro step %g s "
                "(--macro-steps x --dt)", out_dt, macro * h);
    goto done;
  }
  /* 1e6: a contact a million times stiffer than the default is a typo, not a study */
  if (!isnan(kscale) && !(kscale > 0 && kscale <= 1e6)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--contact-scale %g must be > 0 and <= 1e6", kscale);
    goto done;
  }
  /* 1000: CVODE's relative tolerance (1e-4 shipped) near 0.1, where the steps are bounded by
   * the macro step alone and the track is no longer an integration of anything */
  if (!isnan(rodtol) && !(rodtol > 0 && rodtol <= 1000)) {
    cs_errorSet(&err, CS_ERR_RANGE, "--rod-tol %g must be > 0 and <= 1000", rodtol);
    goto done;
  }
  if (coupling && strcmp(coupling, "staggered") && strcmp(coupling, "stabilised") &&
      strcmp(coupling, "gs") && strcmp(coupling, "tree")) {
    cs_errorSet(&err, CS_ERR_ARG, "unknown coupling '%.60s' (expected staggered, stabilised, "
                "gs or tree)", coupling);
    goto done;
  }
  if (coupling && !strcmp(coupling, "tree") && !(leg_type && leg_type->prepare)) {
    cs_errorSet(&err, CS_ERR_ARG, "--coupling tree needs a tree-stepped leg level (--legs "
                "strain)");
    goto done;
  }
  if (coupling && leg_type && leg_type->prepare && !strcmp(coupling, "tree") && !isnan(macro) &&
      macro != 1) {
    cs_errorSet(&err, CS_ERR_ARG, "--coupling tree takes one ODE step per macro step "
                "(--macro-steps 1)");
    goto done;
  }

  m.opt.progress = !quiet;
  m.opt.cancel = csx_signalFlag(); /* SIGINT/SIGTERM: status "interrupted at t", exit 128+sig */
  /* --set: the legs' actuator of a design study; their stiffness and mass follow from it */
  for (int k = 0; k < nset; k++) {
    if (csr_actuatorSetString(&m.robot.leg, sets[k], &err) != CS_OK) goto done;
  }
  if (nset > 0) {
    if (csr_actuatorValidate(&m.robot.leg, &err) != CS_OK) goto done;
    m.robot.leg_params = csr_defaultLegParams(&m.robot.leg);
  }
  cs_modelSetLegLevel(&m, leg_type); /* the one place the level is stored (and its coupling) */
  if (cal_drop && m.robot.leg_type != &csr_leg_rod) {
    cs_errorSet(&err, CS_ERR_ARG, "--cal-drop: only rod legs take the calibration's stretch and "
                "stiffness (legs %s)", cs_modelLegLevel(&m));
    goto done;
  }
  m.robot.leg_params.cal_drop = cal_drop;
  if (!isnan(friction)) m.contact.mu = friction;
  if (!isnan(kscale)) {
    m.contact.kp *= kscale;
    m.contact.stiffness_scale = kscale;
  }
  m.sched.pressure_scale = scale;
  if (!isnan(ramp)) m.sched.ramp = ramp;
  m.opt.h = h;
  if (!isnan(out_dt)) m.opt.output_dt = out_dt;
  if (!isnan(tau)) m.opt.pneumatic_tau = tau;
  if (!isnan(iters)) m.opt.solver_iterations = (int)iters;
  if (!isnan(macro)) m.opt.macro_steps = (int)macro;
  if (coupling) {
    m.opt.coupling = !strcmp(coupling, "stabilised") ? CS_COUPLING_STABILISED
                     : !strcmp(coupling, "gs")       ? CS_COUPLING_GAUSS_SEIDEL
                     : !strcmp(coupling, "tree")     ? CS_COUPLING_TREE
                                                     : CS_COUPLING_STAGGERED;
  }
  /* the default output interval must hold a whole macro step */
  if (isnan(out_dt) && m.opt.output_dt < cs_modelMacroStep(&m)) {
    m.opt.output_dt = cs_modelMacroStep(&m);
  }
  if (!isnan(gravity)) m.opt.gravity = gravity * 1e3; /* m/s^2 -> mm/s^2 */
  if (!isnan(support_kg)) m.robot.support_mass = support_kg * 1e-3; /* kg -> t */
  if (!isnan(links)) {
    m.robot.leg_params.links_per_segment = (int)links;
  } else if (m.robot.leg_type == &csr_leg_rod && sc->rod_links > 0) {
    m.robot.leg_params.links_per_segment = sc->rod_links; /* converged on the scene's table */
  } else if (m.robot.leg_type == &csr_leg_strain) {
    /* bending modes per segment: the level's own default basis */
    m.robot.leg_params.links_per_segment = csr_strainDefaultParams().bend_order + 1;
  }
  if (!isnan(rodtol)) m.robot.leg_params.rod_tol_scale = rodtol;
  if (!isnan(step_order)) m.robot.leg_params.step_order = (int)step_order;
  m.opt.t_end = t_end;
  if (csc_contactParamsValidate(&m.contact, &err) != CS_OK ||
      csg_scheduleCheckOptions(&m.sched, &err) != CS_OK) {
    goto done;
  }
  if (cs_modelLoad(&m, scene, terrain, gait, calib, &err) != CS_OK) goto done;
  if (scene_file && cs_modelApplySceneFile(&m, &sf, &err) != CS_OK) goto done;
  if (!isnan(slope_deg)) {
    if (!(fabs(slope_deg) <= 45)) { /* the terrain file's limit (terrains_terrain.h) */
      cs_errorSet(&err, CS_ERR_RANGE, "--slope-deg %g must be within +-45 deg", slope_deg);
      goto done;
    }
    m.terrain.slope_deg = slope_deg;
  }
  if (m.gait) {
    csgGaitSummary gs;
    csg_gaitComputeSummary(m.gait, &gs, NULL);
    if (gs.p_max * scale > csg_defaultReadOptions().max_pressure) {
      cs_errorSet(&err, CS_ERR_RANGE, "--pressure-scale %g takes %s to %g MPa, above the %g MPa "
                  "limit of gait pressures", scale, gait, gs.p_max * scale,
                  csg_defaultReadOptions().max_pressure);
      goto done;
    }
  }
  if (cs_modelEndTime(&m) / m.opt.h > MAX_STEPS) {
    cs_errorSet(&err, CS_ERR_RANGE, "a run to t = %g s at --dt %g s takes more than %g steps",
                cs_modelEndTime(&m), m.opt.h, MAX_STEPS);
    goto done;
  }
  if (checkWritable(out, &err) != CS_OK) goto done;

  d = cs_dataCreate(&m, &err);
  if (!d) goto done;
  if (!quiet) {
    fprintf(stderr, "crawlsim run: scene %s, gait %s, legs %s, friction %.3g, t_end %.3g s, "
            "robot mass %.1f g\n", scene, gait, cs_modelLegLevel(&m), m.contact.mu,
            cs_modelEndTime(&m), cs_robotMass(d) * 1e6);
    fprintf(stderr, "crawlsim run: conditions %s (%s): %s\n", cs_conditionsName(m.conditions),
            cs_conditionsSourceName(cond_src), cs_conditionsWhat(m.conditions));
    fprintf(stderr, "crawlsim run: calibration (rule %s): %s\n",
            csr_calibrationRuleName(m.calibration), m.robot.map.name);
    fprintf(stderr, "crawlsim run: legs %s, %d %s per segment\n", cs_modelLegLevel(&m),
            m.robot.leg_params.links_per_segment,
            m.robot.leg_type == &csr_leg_rod      ? "elements"
            : m.robot.leg_type == &csr_leg_strain ? "bending modes"
                                                  : "links");
    if (m.robot.leg_params.cal_drop) {
      char what[32];
      csr_calDropFormat(m.robot.leg_params.cal_drop, what, sizeof what);
      fprintf(stderr, "crawlsim run: calibration parts left out (--cal-drop): %s\n", what);
    }
    if (m.legs_auto_choice[0]) {
      fprintf(stderr, "crawlsim run: --legs auto picked %s\n", m.legs_auto_choice);
    }
    double load, pcr;
    cs_modelStanceCheck(&m, cs_robotMass(d), &load, &pcr);
    fprintf(stderr, "crawlsim run: stance check: %.2f N per leg on half the legs vs sway-buckling "
            "load %.2f N per leg (%.0f %%)%s\n", load, pcr, 100 * load / pcr,
            load > 0.5 * pcr ? ": expect the stance legs to sway and fold" : "");
  }
  if (cs_settle(&m, d, &err) != CS_OK) {
    /* the output file says so too (the contract: what was written stays readable) */
    csError ferr;
    cs_errorClear(&ferr);
    if (cs_runRecordFailure(&m, d, out, &err, &ferr) != CS_OK) {
      char cause[sizeof err.msg];
      memcpy(cause, err.msg, sizeof cause);
      cs_errorSet(&err, err.status, "%.300s (output file not written: %.150s)", cause, ferr.msg);
    }
    goto done;
  }
  double wall = 0;
  csStatus st = cs_run(&m, d, out, &wall, &err);
  double x[3], q[4];
  cs_supportDisplacement(d, x);
  cs_supportOrientation(d, q);
  /* tilt: angle between the support's up axis and world up */
  double tilt = acos(fmin(1.0, 1 - 2 * (q[1] * q[1] + q[3] * q[3]))) * 180 / 3.14159265358979;
  printf("final t = %.3f s: support displacement x = %.2f mm, y = %.2f mm, z = %.2f mm, "
         "tilt %.2f deg\n", cs_time(d), x[0], x[1], x[2], tilt);
  printf("wall time %.2f s, real-time factor %.2f (simulated s per wall s), output %s\n", wall,
         wall > 0 ? cs_time(d) / wall : 0, out);
  /* where the time went: one entry per stage timer (sim_model.h), as in the HDF5 attributes */
  const csuTimer* tm = cs_timers(d);
  printf("time split (s):");
  for (int k = 0; k < CS_NTIMER; k++) {
    printf(" %s %.3f%s", cs_timerName((csTimerId)k), tm[k].wall, k + 1 < CS_NTIMER ? "," : "\n");
  }
  if (cs_gainProjectionCount(d) > 0) {
    printf("coupling: the legs' interface gains were not passive in %ld macro step(s); their "
           "implicit part was projected onto passive gains there (README \"Rod legs\")\n",
           cs_gainProjectionCount(d));
  }
  /* the verdict (issue 10): falls (off the terrain), stops (any other failure: the message
   * says which), tips over, crawls or stands, with when and how far */
  const char* how = st != CS_OK ? (strstr(err.msg, "fell off") ? "falls" : "stops") :
                    tilt > 30 ? "tips over" :
                    fabs(x[0]) >= 20 || fabs(x[2]) >= 20 ? "crawls" : "stands";
  if (st != CS_OK) {
    printf("verdict (%s, %s legs): %s: %s\n", cs_conditionsName(m.conditions),
           cs_modelLegLevel(&m), how, err.msg);
  } else {
    printf("verdict (%s, %s legs): %s: x = %.1f mm, z = %.1f mm in %.2f s, tilt %.1f deg\n",
           cs_conditionsName(m.conditions), cs_modelLegLevel(&m), how, x[0], x[2], cs_time(d),
           tilt);
  }
  if (st == CS_ERR_INTERRUPTED) {
    rc = csx_signalExitCode() ? csx_signalExitCode() : 1;
    goto done;
  }
  if (st != CS_OK) goto done;
  rc = 0;

done:
  if (rc != 0) {
    fprintf(stderr, "crawlsim run: %s\n", err.msg[0] ? err.msg : "failed");
  }
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  return rc;
}

/* cmd_bend.c: `crawlsim bend`, the pressure -> bending characterisation of one actuator
 * (docs/design.md command-line and output contracts; paper Figs. 3, 6-9).
 *
 *   crawlsim bend [--model analytic|fe|rod|rom|strain] [--actuator fig1|baseline|leg]
 *                 [--set NAME=VALUE]... [--chambers 1,2] [--p-max MPA] [--p-step MPA]
 *                 [--until-angle DEG] [--mesh-size MM] [--fibre-size MM] [--fibre-split 0|1]
 *                 [--fibre-law linear|tension-only] [--out FILE.h5]
 *                 [--pressures R1,R2,R3,R4] [--tip-load FX,FY,FZ] [--calibration FILE|analytic]
 *
 * --pressures gives unequal chamber pressures: chamber j of every segment is at R_j p (the
 * ratios replace --chambers; analytic, rod, strain and fe). --tip-load is a dead force (N) on the
 * tip face in the base frame e1, e2, e3 (rod, strain; fe: a uniform traction on the tip face).
 * The strain leg (robot_strain.h, the leg `crawlsim run --legs strain` runs) takes the rod's
 * calibration options and --links (its bending modes per segment). The rod (robot_rod.h) is solved statically at every row,
 * continued from the previous one, gravity off like the other models; its actuation comes from
 * --calibration: an FE table (default: the mission's table, tools/cs_paths.h, under its rule,
 * refused for another actuator) or `analytic` (the analytic model's own bends, so that the
 * unloaded rod reproduces it); a mode table gives the rod its probed section stiffness too,
 * exactly as the rod legs of `crawlsim run` take it (robot_rod_leg.c). --mesh-size is its
 * element length in the segments (default 4 per segment). The rod's default actuator is the
 * default table's (`leg`); the other models' is `baseline` (the paper's Sec. 4).
 *
 * The listed chambers are inflated at the same pressure in all three segments; the sweep runs
 * p = 0, p-step, ... up to p-max (p-max itself is always the last row). --until-angle finds
 * the pressure at which the total angle Θ = Σ θ_i (paper Eq. 11) reaches DEG by bisection on
 * the model itself (Θ grows monotonically with p): inside the sweep when the sweep reaches DEG,
 * otherwise up to max(p-max, kUntilCeilingMPa); if Θ stays below DEG there, the result is NaN
 * and a line says so. Models are dispatched in one place, bendModelEvaluator(); a model level
 * that lands adds its branch there (and fills mesh size / element counts in BendRun). The
 * mesh-free models' points and the sweep's grid are the library's (core/cs_bend.h), the same
 * code as the public cs_bend; this file adds the options, the file, the table and the search. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "core_clock.h"
#include "core_h5.h"
#include "core_text.h"
#include "cs_commands.h"
#include "cmd_bend.h"
#include "cs_bend.h"
#include "cs_opts.h"
#include "cmd_fe_threads.h"
#include "cs_paths.h"
#include "cs_signal.h"
#include "robot_actuator.h"
#include "robot_bend_io.h"
#include "robot_calibration.h"
#include "robot_leg.h"

static const double kDefaultPMax = 0.4;     /* MPa, the paper's multi-segment sweep (Sec. 3.3) */
static const double kDefaultPStep = 0.05;   /* MPa, the paper's increment */
static const double kUntilCeilingMPa = 2.0; /* search ceiling of --until-angle beyond p-max */
static const double kBisectTolMPa = 1e-9;   /* bisection stops when the bracket is this small */
enum { MAX_SETS = 64 };

/* the options of `crawlsim bend`, for parsing and --help (cs_opts.h) */
static const csxOpt kBendOpts[] = {
    {"--model", "analytic|fe|rod|rom|strain", "analytic",
     "the actuator model (rom: the reduced FE of docs/notes/rom.md, needs --rom-basis; strain: "
     "the strain-coordinate leg of run --legs strain)"},
    {"--actuator", "fig1|baseline|leg", "baseline (rod, strain, rom: leg, the calibration's)",
     "the actuator preset"},
    {"--set", "NAME=VALUE", NULL,
     "a parameter of the actuator, repeatable; NAME is S1 S2 S3 n1 n2 n3 LS12 LS23 a b c r1 r2 "
     "(mm, turns) C10 C20 (MPa) rho (t/mm^3) Ef (MPa) nuf rhof rf (mm)"},
    {"--chambers", "1,2", "1,2", "the chambers (1..4) inflated in all three segments"},
    {"--p-max", "MPA", "0.4", "the sweep's last pressure in MPa"},
    {"--p-step", "MPA", "0.05", "the sweep's pressure increment in MPa"},
    {"--until-angle", "DEG", NULL,
     "report the pressure at which the total bending angle reaches DEG degrees (searched up to "
     "max(p-max, 2 MPa))"},
    {"--pressures", "R1,R2,R3,R4", NULL,
     "chamber j at R_j x p (unequal pressures; analytic, rod, strain, fe)"},
    {"--tip-load", "FX,FY,FZ", "0,0,0", "a tip force in N, base frame (rod, strain, fe, rom)"},
    {"--calibration", "FILE|analytic", "robot/calibration_fe_leg_modes_sym.h5 (rod, strain)",
     "the rod's or strain leg's pressure -> bend map and, from an FE mode table, its probed EI, "
     "EA"},
    {"--cal-rule", "prism|rbf|rbf-pair", "rbf-pair on the default table, the table's own "
     "(prism) on a table given by --calibration",
     "that FE mode table's model rule (rod, strain)"},
    {"--cal-drop", "stretch[,stiffness]", "none",
     "the rod or strain leg leaves that part of the calibration out (the axial stretch; a mode "
     "table's probed EI, EA); recorded as calibration_dropped"},
    {"--links", "N", "the strain level's (2)",
     "strain: bending modes per segment (1..7), as run --links on strain legs"},
    {"--mesh-size", "MM", "the FE's default l_soft",
     "fe: the soft elements' size in mm; rod: its element length"},
    {"--fibre-size", "MM", "l_soft / 8", "fe: the fibre element length in mm"},
    {"--fibre-split", "0|1", "1",
     "fe: 1 splits fibre elements at the tets' faces; 0 ties each to the tets holding its two "
     "ends (20 nodes)"},
    {"--fibre-law", "tension-only|linear", "tension-only",
     "fe: tension-only (a thread carries no compression) or linear (compression at full "
     "stiffness)"},
    {"--mesh-symmetric", "0|1", "0",
     "fe: 1 meshes an eighth of the leg, mirrored and turned (the square section's eight "
     "symmetries)"},
    {"--branch-switch", "0|1", "0",
     "fe: 1 at a bifurcation tries to leave the path along the critical mode"},
    {"--segments", "1|3", "3",
     "1: the paper's single segment, II1 of the actuator alone (S2, S3, LS12, LS23 and n2, n3 "
     "taken as 0; its Table 1 and Fig. 3a); 3: the whole actuator (fe)"},
    {"--threads", "N", "this process's cores, less those other processes hold",
     "fe: the FE's threads"},
    {"--out", "FILE.h5", "bend.h5", "the output file (docs/reference/output.md)"},
    {"--rom-basis", "FILE.h5", NULL,
     "rom: the reduced basis (tools/rom_basis.py; its mesh size and the symmetric mesh are the "
     "model's)"},
    {"--rom-weights", "FILE.h5", "every element at weight 1",
     "rom: the hyper-reduction's element weights (tools/rom_ecsw.py)"},
    {"--rom-file", "LEG.h5", NULL,
     "rom: a leg file of `crawlsim rom leg-file` (the basis, its weights and the chambers' "
     "forms, read without meshing); instead of --rom-basis and --rom-weights"},
};

static const csxOptTable kBendTable = {
    "bend", "",
    "Inflate the listed chambers of all three segments of one actuator at equal pressure from 0 "
    "to p-max in steps of p-step and write the bending angles and tip positions to FILE.h5.",
    kBendOpts, CSX_NOPT(kBendOpts), NULL};

static const char* const kModelNames[BEND_NMODEL] = {"analytic", "fe", "rod", "rom", "strain"};

/* Evaluate the model at pressure p (MPa): per-segment angles (deg), tip in the base frame (mm). */
typedef csStatus (*BendPointFn)(BendRun* run, double p, double angle_deg[CSR_NSEG], double tip[3],
                                csError* err);

/* the mesh-free models (analytic, rod, strain) at p: the library's solver (core/cs_bend.h) */
static csStatus solverPoint(BendRun* run, double p, double angle_deg[CSR_NSEG], double tip[3],
                            csError* err);
/* open the solver of run (run->solver): CS_OK or a status with err */
static csStatus solverOpen(BendRun* run, csBendSolver* solver, csError* err);
/* "a,b,c,d" -> n finite numbers; 1 with err naming the flag */
static int parseNumbers(const char* flag, const char* text, int n, double* v, csError* err);
/* the one place that maps a model level to its evaluator; NULL = not available yet */
static BendPointFn bendModelEvaluator(BendModel m);
/* parse and check argv into run (the definition of a bend): 0; 1 with err filled; 2 when `it`
 * holds --help or an option error (*kind, for csx_optReport) */
static int parseArgs(int argc, char** argv, BendRun* run, csxOptIter* it, csxOptKind* kind,
                     csError* err);
static int checkModelOptions(const BendRun* run, csError* err);
/* strict number parser: whole string, finite, > 0; 1 with err naming the unit */
static int parsePositive(const char* flag, const char* text, const char* unit, double* v,
                         csError* err);
/* "1,2" -> inflated[], canonical text (core_text.h's parser); 1 with err */
static int parseChambers(const char* text, BendRun* run, csError* err);
/* Θ(p) for --until-angle */
static csStatus totalAngle(BendRun* run, BendPointFn eval, double p, double* theta_deg,
                           csError* err);
/* pressure at which Θ reaches run->until_angle; NAN when not reached up to the ceiling */
static csStatus findUntilAngle(BendRun* run, BendPointFn eval, const csrBendCurve* bc,
                               double* p_out, double* p_searched, csError* err);


/* the mesh-free models' point: the library's solver (core/cs_bend.h), opened by
 * csx_bendExecute; what the model used (element length, elements) is recorded for the file */
static csStatus solverPoint(BendRun* run, double p, double angle_deg[CSR_NSEG], double tip[3],
                            csError* err) {
  csStatus st = cs_bendSolverPoint(run->solver, p, angle_deg, tip, err);
  run->mesh_size = run->solver->mesh_size; /* NaN: mesh-free */
  run->n_elements_soft = run->solver->n_elements;
  run->n_elements_fibre = 0;
  return st;
}


static csStatus solverOpen(BendRun* run, csBendSolver* solver, csError* err) {
  csBendSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.kind = run->model == BEND_ROD      ? CS_BEND_ROD
            : run->model == BEND_STRAIN ? CS_BEND_STRAIN
                                        : CS_BEND_ANALYTIC;
  sp.links = run->links;
  sp.act = run->act;
  memcpy(sp.ratio, run->ratio, sizeof sp.ratio);
  memcpy(sp.tip_load, run->tip_load, sizeof sp.tip_load);
  sp.p_max = run->p_max;
  sp.calibration = run->calibration;
  char buf[1024];
  sp.default_path = csx_dataPath(CS_MISSION_CALIBRATION, buf, sizeof buf);
  sp.cal_rule = run->cal_rule;
  sp.cal_drop = run->cal_drop;
  sp.mesh_size = sp.kind == CS_BEND_ROD ? run->mesh_size : NAN;
  run->solver = solver;
  csStatus st = cs_bendSolverOpen(solver, &sp, err);
  if (sp.kind == CS_BEND_ROD) {
    run->mesh_size = solver->mesh_size;
    run->n_elements_soft = solver->n_elements;
    run->n_elements_fibre = 0;
  }
  run->p_ceiling = solver->p_ceiling;
  return st;
}


static BendPointFn bendModelEvaluator(BendModel m) {
  switch (m) {
    case BEND_ANALYTIC:
    case BEND_ROD:
    case BEND_STRAIN:
      return solverPoint;
    case BEND_FE:  /* a whole sweep, not point-wise: feSweep() below */
    case BEND_ROM: /* reduced FE */
    case BEND_NMODEL:
      return NULL;
  }
  return NULL;
}


static int parsePositive(const char* flag, const char* text, const char* unit, double* v,
                         csError* err) {
  char* end = NULL;
  double x = strtod(text, &end);
  if (end == text || *end != '\0' || !isfinite(x)) {
    cs_errorSet(err, CS_ERR_ARG, "%s '%s' is not a finite number", flag, text);
    return 1;
  }
  if (!(x > 0)) {
    cs_errorSet(err, CS_ERR_ARG, "%s %s must be > 0 %s", flag, text, unit);
    return 1;
  }
  *v = x;
  return 0;
}


static int parseChambers(const char* text, BendRun* run, csError* err) {
  unsigned mask = 0;
  if (csu_chamberListParse(text, CSR_NCHAMBER, "--chambers", &mask, err) != CS_OK) {
    return 1;
  }
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    run->inflated[j] = (mask >> j) & 1u;
    run->ratio[j] = run->inflated[j] ? 1.0 : 0.0;
  }
  csu_chamberListFormat(mask, run->chambers, sizeof run->chambers);
  run->unequal = 0;
  return 0;
}


static int parseNumbers(const char* flag, const char* text, int n, double* v, csError* err) {
  const char* s = text;
  for (int k = 0; k < n; k++) {
    char* end = NULL;
    v[k] = strtod(s, &end);
    if (end == s || !isfinite(v[k]) || (k < n - 1 ? *end != ',' : *end != '\0')) {
      cs_errorSet(err, CS_ERR_ARG, "%s '%s': expected %d comma-separated finite numbers",
                  flag, text, n);
      return 1;
    }
    s = end + 1;
  }
  return 0;
}


/* --pressures R1,R2,R3,R4: ratios >= 0, one at least > 0; the chambers text lists j:R_j */
static int parsePressures(const char* text, BendRun* run, csError* err) {
  double r[CSR_NCHAMBER];
  if (parseNumbers("--pressures", text, CSR_NCHAMBER, r, err)) {
    return 1;
  }
  double top = 0;
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    if (r[j] < 0) {
      cs_errorSet(err, CS_ERR_ARG, "--pressures '%s': ratio %g of chamber %d is negative",
                  text, r[j], j + 1);
      return 1;
    }
    top = fmax(top, r[j]);
  }
  if (!(top > 0)) {
    cs_errorSet(err, CS_ERR_ARG, "--pressures '%s': every ratio is 0", text);
    return 1;
  }
  char* w = run->chambers;
  size_t room = sizeof run->chambers;
  run->unequal = 0;
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    run->ratio[j] = r[j];
    run->inflated[j] = r[j] > 0;
    run->unequal |= r[j] != 0 && r[j] != 1;
    if (r[j] > 0 && room > 1) {
      int k = snprintf(w, room, "%s%d:%g", w == run->chambers ? "" : ",", j + 1, r[j]);
      k = k < 0 ? 0 : ((size_t)k >= room ? (int)room - 1 : k);
      w += k;
      room -= (size_t)k;
    }
  }
  return 0;
}


static int parseArgs(int argc, char** argv, BendRun* run, csxOptIter* it, csxOptKind* kind,
                     csError* err) {
  const char* actuator = NULL; /* default below, by model */
  const char* sets[MAX_SETS];
  int nset = 0;
  memset(run, 0, sizeof *run);
  run->model = BEND_ANALYTIC;
  run->p_max = kDefaultPMax;
  run->p_step = kDefaultPStep;
  run->until_angle = NAN;
  run->p_ceiling = NAN;
  run->p_limit = run->p_resume = NAN;
  run->mesh_size = NAN;
  run->fibre_size = NAN;
  run->fibre_split = -1;
  run->mesh_symmetric = -1;
  run->segments = -1;
  run->cal_rule = -1;
  run->branch_switch = -1;
  run->fibre_tension_only = -1;
  run->out = "bend.h5";
  run->inflated[0] = run->inflated[1] = 1;
  run->ratio[0] = run->ratio[1] = 1.0;
  snprintf(run->chambers, sizeof run->chambers, "1,2");
  csx_optBegin(it);
  while ((*kind = csx_optNext(&kBendTable, argc, argv, it)) != CSX_OPT_END) {
    if (*kind == CSX_OPT_HELP || *kind == CSX_OPT_ERROR) {
      return 2;
    }
    if (*kind == CSX_OPT_OPERAND) {
      cs_errorSet(err, CS_ERR_ARG, "unexpected argument '%.60s' (see crawlsim bend --help)",
                  it->value);
      return 1;
    }
    const char* name = it->opt->name;
    const char* value = it->value;
    int bad = 0;
    if (!strcmp(name, "--model")) {
      int m = 0;
      while (m < BEND_NMODEL && strcmp(value, kModelNames[m])) {
        m++;
      }
      if (m == BEND_NMODEL && csr_legRetired(value)) {
        cs_errorSet(err, CS_ERR_ARG, "--model %s: %s", value, csr_legRetired(value));
        return 1;
      }
      if (m == BEND_NMODEL) {
        cs_errorSet(err, CS_ERR_ARG, "unknown model '%s' (expected analytic, fe, rod, rom or "
                    "strain)", value);
        return 1;
      }
      run->model = (BendModel)m;
    } else if (!strcmp(name, "--actuator")) {
      actuator = value;
    } else if (!strcmp(name, "--set")) {
      if (nset == MAX_SETS) {
        cs_errorSet(err, CS_ERR_ARG, "more than %d --set options", MAX_SETS);
        return 1;
      }
      sets[nset++] = value;
    } else if (!strcmp(name, "--chambers")) {
      bad = parseChambers(value, run, err);
    } else if (!strcmp(name, "--p-max")) {
      bad = parsePositive(name, value, "MPa", &run->p_max, err);
    } else if (!strcmp(name, "--p-step")) {
      bad = parsePositive(name, value, "MPa", &run->p_step, err);
    } else if (!strcmp(name, "--until-angle")) {
      bad = parsePositive(name, value, "degrees", &run->until_angle, err);
    } else if (!strcmp(name, "--mesh-size")) {
      bad = parsePositive(name, value, "mm", &run->mesh_size, err);
    } else if (!strcmp(name, "--links")) {
      double v;
      bad = parsePositive(name, value, "bending modes per segment", &v, err);
      if (!bad && !(v == floor(v) && v <= CSR_STRAIN_MAX_ORDER + 1)) {
        cs_errorSet(err, CS_ERR_ARG, "--links %s: a whole number 1..%d of bending modes per "
                    "segment", value, CSR_STRAIN_MAX_ORDER + 1);
        return 1;
      }
      run->links = bad ? 0 : (int)v;
    } else if (!strcmp(name, "--fibre-size")) {
      bad = parsePositive(name, value, "mm", &run->fibre_size, err);
    } else if (!strcmp(name, "--fibre-split")) {
      if (strcmp(value, "0") && strcmp(value, "1")) {
        cs_errorSet(err, CS_ERR_ARG, "--fibre-split '%s' must be 0 or 1", value);
        return 1;
      }
      run->fibre_split = value[0] == '1';
    } else if (!strcmp(name, "--mesh-symmetric")) {
      if (strcmp(value, "0") && strcmp(value, "1")) {
        cs_errorSet(err, CS_ERR_ARG, "--mesh-symmetric '%s' must be 0 or 1", value);
        return 1;
      }
      run->mesh_symmetric = value[0] == '1';
    } else if (!strcmp(name, "--segments")) {
      if (strcmp(value, "1") && strcmp(value, "3")) {
        cs_errorSet(err, CS_ERR_ARG, "--segments '%s' must be 1 or 3", value);
        return 1;
      }
      run->segments = value[0] - '0';
    } else if (!strcmp(name, "--branch-switch")) {
      if (strcmp(value, "0") && strcmp(value, "1")) {
        cs_errorSet(err, CS_ERR_ARG, "--branch-switch '%s' must be 0 or 1", value);
        return 1;
      }
      run->branch_switch = value[0] == '1';
    } else if (!strcmp(name, "--threads")) {
      bad = csx_feParseThreads(value, &run->threads, err);
    } else if (!strcmp(name, "--fibre-law")) {
      run->fibre_tension_only = csr_fibreLawParse(value);
      if (run->fibre_tension_only < 0) {
        cs_errorSet(err, CS_ERR_ARG, "--fibre-law '%s' must be linear or tension-only", value);
        return 1;
      }
    } else if (!strcmp(name, "--pressures")) {
      bad = parsePressures(value, run, err);
    } else if (!strcmp(name, "--tip-load")) {
      bad = parseNumbers(name, value, 3, run->tip_load, err);
    } else if (!strcmp(name, "--rom-basis")) {
      run->rom_basis = value;
    } else if (!strcmp(name, "--rom-weights")) {
      run->rom_weights = value;
    } else if (!strcmp(name, "--rom-file")) {
      run->rom_file = value;
    } else if (!strcmp(name, "--cal-rule")) {
      csrCalRule rule;
      if (!csr_calRuleParse(value, &rule)) {
        cs_errorSet(err, CS_ERR_ARG, "unknown --cal-rule '%.60s' (expected prism, rbf or "
                    "rbf-pair)", value);
        return 1;
      }
      run->cal_rule = (int)rule;
    } else if (!strcmp(name, "--cal-drop")) {
      if (!csr_calDropParse(value, &run->cal_drop)) {
        cs_errorSet(err, CS_ERR_ARG, "bad --cal-drop '%.60s' (expected stretch, stiffness, "
                    "stretch,stiffness or none)", value);
        return 1;
      }
    } else if (!strcmp(name, "--calibration")) {
      if (!*value) {
        cs_errorSet(err, CS_ERR_ARG, "--calibration needs a file name or 'analytic'");
        return 1;
      }
      run->calibration = value;
    } else if (!strcmp(name, "--out")) {
      if (!*value) {
        cs_errorSet(err, CS_ERR_ARG, "--out needs a file name");
        return 1;
      }
      run->out = value;
    } else {
      cs_errorSet(err, CS_ERR_ARG, "unknown option '%s' (see crawlsim bend --help)", name);
      return 1;
    }
    if (bad) {
      return 1;
    }
  }
  /* the actuator: preset, then every --set in order, then a consistency check; the rod's
   * default is its default calibration's actuator, so that `bend --model rod` runs as is */
  if (!actuator) {
    actuator = run->model == BEND_ROD || run->model == BEND_ROM || run->model == BEND_STRAIN
                   ? CS_MISSION_ACTUATOR
                   : "baseline";
  }
  if (csr_actuatorPreset(&run->act, actuator, err) != CS_OK) {
    return 1;
  }
  for (int k = 0; k < nset; k++) {
    if (csr_actuatorSetString(&run->act, sets[k], err) != CS_OK) {
      return 1;
    }
  }
  if (csr_actuatorValidate(&run->act, err) != CS_OK) {
    return 1;
  }
  return checkModelOptions(run, err);
}


/* the options only some models take: 0, or 1 with err naming the option */
static int checkModelOptions(const BendRun* run, csError* err) {
  if ((!isnan(run->fibre_size) || run->fibre_split >= 0 || run->fibre_tension_only >= 0) &&
      run->model != BEND_FE) {
    cs_errorSet(err, CS_ERR_ARG, "%s is for --model fe (the %s model has no fibre elements)",
                !isnan(run->fibre_size)  ? "--fibre-size"
                : run->fibre_split >= 0 ? "--fibre-split"
                                        : "--fibre-law",
                kModelNames[run->model]);
    return 1;
  }
  if (run->mesh_symmetric >= 0 && run->model != BEND_FE) {
    cs_errorSet(err, CS_ERR_ARG, "--mesh-symmetric is for --model fe (the %s model has no "
                "mesh)", kModelNames[run->model]);
    return 1;
  }
  if (run->segments >= 0 && run->model != BEND_FE) {
    cs_errorSet(err, CS_ERR_ARG, "--segments is for --model fe (the %s model takes the three "
                "segments)", kModelNames[run->model]);
    return 1;
  }
  if (run->threads > 0 && run->model != BEND_FE) {
    cs_errorSet(err, CS_ERR_ARG, "--threads is for --model fe (the %s model runs on one "
                "thread)", kModelNames[run->model]);
    return 1;
  }
  if (run->branch_switch >= 0 && run->model != BEND_FE) {
    cs_errorSet(err, CS_ERR_ARG, "--branch-switch is for --model fe (the %s model has no "
                "tangent to switch branches on)", kModelNames[run->model]);
    return 1;
  }
  if ((run->rom_basis || run->rom_weights || run->rom_file) && run->model != BEND_ROM) {
    cs_errorSet(err, CS_ERR_ARG, "--rom-basis, --rom-weights and --rom-file are for --model rom");
    return 1;
  }
  if (run->rom_file && (run->rom_basis || run->rom_weights)) {
    cs_errorSet(err, CS_ERR_ARG, "--rom-file holds the basis and the weights: give it without "
                "--rom-basis and --rom-weights");
    return 1;
  }
  int legish = run->model == BEND_ROD || run->model == BEND_STRAIN; /* the calibrated legs */
  int tip = run->tip_load[0] != 0 || run->tip_load[1] != 0 || run->tip_load[2] != 0;
  if ((tip && !legish && run->model != BEND_FE && run->model != BEND_ROM) ||
      ((run->calibration || run->cal_rule >= 0 || run->cal_drop) && !legish)) {
    cs_errorSet(err, CS_ERR_ARG, "%s is for --model %s (the %s model has no %s)",
                tip                  ? "--tip-load"
                : run->calibration   ? "--calibration"
                : run->cal_rule >= 0 ? "--cal-rule"
                                     : "--cal-drop",
                tip ? "rod, strain, fe or rom" : "rod or strain",
                kModelNames[run->model], tip ? "tip load" : "calibration");
    return 1;
  }
  if (run->links > 0 && run->model != BEND_STRAIN) {
    cs_errorSet(err, CS_ERR_ARG, "--links is for --model strain (the %s model has no bending "
                "modes%s)", kModelNames[run->model],
                run->model == BEND_ROD ? "; its element length is --mesh-size" : "");
    return 1;
  }
  if (!isnan(run->mesh_size) && run->model == BEND_STRAIN) {
    cs_errorSet(err, CS_ERR_ARG, "--mesh-size is not for --model strain (its resolution is "
                "--links, the bending modes per segment)");
    return 1;
  }
  return 0;
}


static csStatus totalAngle(BendRun* run, BendPointFn eval, double p, double* theta_deg,
                           csError* err) {
  double ang[CSR_NSEG], tip[3];
  csStatus st = eval(run, p, ang, tip, err);
  *theta_deg = ang[0] + ang[1] + ang[2];
  return st;
}


static csStatus findUntilAngle(BendRun* run, BendPointFn eval, const csrBendCurve* bc,
                               double* p_out, double* p_searched, csError* err) {
  double target = run->until_angle;
  double lo = 0, hi = NAN;
  *p_out = NAN;
  *p_searched = bc->pressure[bc->m - 1];
  /* bracket from the sweep: the first row at or above the target */
  for (size_t i = 0; i < bc->m; i++) {
    if (bc->angle_total[i] >= target) {
      hi = bc->pressure[i];
      break;
    }
    lo = bc->pressure[i];
  }
  if (isnan(hi)) {
    /* beyond the sweep: try the ceiling */
    double ceiling = fmax(run->p_max, isnan(run->p_ceiling) ? kUntilCeilingMPa : run->p_ceiling);
    double th;
    *p_searched = ceiling;
    csStatus st = totalAngle(run, eval, ceiling, &th, err);
    if (st != CS_OK) {
      return st;
    }
    if (th < target) {
      return CS_OK; /* not reached */
    }
    hi = ceiling;
  }
  while (hi - lo > kBisectTolMPa) {
    double mid = 0.5 * (lo + hi), th;
    csStatus st = totalAngle(run, eval, mid, &th, err);
    if (st != CS_OK) {
      return st;
    }
    if (th >= target) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  *p_out = 0.5 * (lo + hi);
  return CS_OK;
}




csStatus csx_bendFileClose(csH5File* f, const char* model, const csrBendCurve* bc, csStatus st,
                           csError* err) {
  if (st != CS_OK) {
    cs_h5AttrString(f, "/", "model", model, NULL);
    csr_bendCurveFlushH5(f, bc, NULL); /* fails at once if the disk refused already */
  }
  cs_h5AttrString(f, "/", "status", st == CS_OK ? "ok" : err->msg, NULL);
  csError cerr;
  csStatus cst = cs_h5CloseChecked(f, &cerr);
  if (st == CS_OK && cst != CS_OK) {
    st = cst;
    *err = cerr;
  }
  return st;
}


int csx_bendExitCode(csStatus st) {
  if (st != CS_ERR_INTERRUPTED) {
    return 1;
  }
  return csx_signalExitCode() ? csx_signalExitCode() : 130;
}


csStatus csx_bendExecute(BendRun* run, csxBendResult* res, csError* err) {
  res->p_until = res->angle_total = res->p_end = NAN;
  res->until_line[0] = '\0';
#ifdef CS_HAVE_FEM
  if (run->model == BEND_FE) {
    return csx_bendFe(run, res, err);
  }
  if (run->model == BEND_ROM) {
    return csx_bendRom(run, res, err);
  }
#endif
  BendPointFn eval = bendModelEvaluator(run->model);
  if (!eval) {
    return cs_errorSet(err, CS_ERR_ARG, "model '%s' is not available yet",
                       kModelNames[run->model]);
  }
  csBendSolver solver;
  csStatus ost = solverOpen(run, &solver, err);
  if (ost != CS_OK) {
    cs_bendSolverClose(&solver);
    return ost;
  }
  if (run->model == BEND_ANALYTIC) {
    for (int s = 0; s < CSR_NSEG; s++) {
      if (run->act.n[s] == 0) {
        fprintf(run->notes,
                "crawlsim bend: note: n%d = 0, but the analytic model assumes fibres that stop "
                "radial growth (lambda2 = 1)\n",
                s + 1);
      }
    }
    if (!isnan(run->mesh_size)) {
      fprintf(run->notes, "crawlsim bend: note: --mesh-size is ignored by the analytic model\n");
    }
  }

  /* open the output first so that an unwritable path fails before any work */
  csH5File* f = cs_h5Create(run->out, err);
  if (!f) {
    cs_bendSolverClose(&solver);
    return err->status;
  }

  /* the sweep: 0, step, ..., and p-max as the last row */
  double t0 = csu_wallSeconds();
  size_t nstep = cs_bendSweepSteps(run->p_max, run->p_step);
  size_t nrow = cs_bendSweepRows(run->p_max, run->p_step);
  csrBendCurve bc;
  csStatus st = csr_bendCurveInit(&bc, nstep + 2, err);
  for (size_t i = 0; st == CS_OK && i < nrow; i++) {
    double p = cs_bendSweepPressure(run->p_max, run->p_step, i);
    if (*csx_signalFlag()) {
      st = cs_errorSet(err, CS_ERR_INTERRUPTED, "interrupted at p = %.6g MPa (%zu rows kept)",
                       bc.m > 0 ? bc.pressure[bc.m - 1] : 0.0, bc.m);
      break;
    }
    double ang[CSR_NSEG], tip[3];
    st = eval(run, p, ang, tip, err);
    if (st != CS_OK) {
      /* where: the pressure, the sweep's step and the discretisation; the rows so far stay */
      char cause[sizeof err->msg];
      memcpy(cause, err->msg, sizeof cause);
      cs_errorSet(err, st, "%s model failed at p = %.6g MPa (sweep step %zu of %zu, from %.6g "
                  "MPa; %d elements; the %zu rows before it are kept): %.300s",
                  kModelNames[run->model], p, i, nstep, bc.m > 0 ? bc.pressure[bc.m - 1] : 0.0,
                  (int)run->n_elements_soft, bc.m, cause);
    }
    if (st == CS_OK) {
      st = csr_bendCurvePush(&bc, p, ang, tip, err);
    }
    if (st == CS_OK) {
      /* the file on disk holds every row so far, whatever stops the sweep */
      st = csr_bendCurveFlushH5(f, &bc, err);
    }
  }
  double p_until = NAN, p_searched = NAN;
  if (st == CS_OK && !isnan(run->until_angle)) {
    st = findUntilAngle(run, eval, &bc, &p_until, &p_searched, err);
    bc.p_until_angle = p_until;
  }
  double wall = csu_wallSeconds() - t0;
  if (st == CS_OK) {
    csrBendMeta meta = {kModelNames[run->model], run->chambers, run->mesh_size,
                        run->n_elements_soft, run->n_elements_fibre, wall, run->until_angle,
                        run->p_limit, run->p_resume, 0, 0, 0, NAN, -1, NAN, 0};
    st = csr_bendCurveWriteH5(f, &run->act, &bc, &meta, err);
  }
  if (st == CS_OK && run->model == BEND_STRAIN) {
    st = cs_h5AttrDouble(f, "/", "strain_links", solver.links, err);
    if (st == CS_OK) {
      st = cs_h5AttrDouble(f, "/", "strain_dofs", solver.n_dofs, err);
    }
  }
  if (st == CS_OK && (run->model == BEND_ROD || run->model == BEND_STRAIN)) {
    char drop[32];
    csr_calDropFormat(run->cal_drop, drop, sizeof drop);
    st = cs_h5AttrString(f, "/", "calibration_dropped", drop, err);
    if (st == CS_OK) {
      st = cs_h5AttrString(f, "/", "calibration", solver.map.name ? solver.map.name : "?", err);
    }
    if (st == CS_OK) {
      st = cs_h5AttrString(f, "/", "calibration_rule",
                           cs_bendSolverRuleName(&solver), err);
    }
    if (st == CS_OK) {
      st = cs_h5AttrString(f, "/", "calibration_stiffness",
                           cs_bendSolverProbedStiffness(&solver) ? "probed" : "default",
                           err);
    }
  }
  st = csx_bendFileClose(f, kModelNames[run->model], &bc, st, err);
  if (st != CS_OK) {
    csr_bendCurveFree(&bc);
    cs_bendSolverClose(&solver);
    return st;
  }
  csx_bendResultFill(run, &bc, res);

  /* the table */
  fprintf(run->table, "crawlsim bend: model %s, actuator %s, chambers %s in II1-II3\n",
          kModelNames[run->model], run->act.name, run->chambers);
  if (run->model == BEND_ROD) {
    fprintf(run->table, "rod: %d elements (%.4g mm in the segments), calibration %s, rule %s, "
            "section stiffness %s, tip load (%g, %g, %g) N in the base frame, gravity off\n",
            (int)run->n_elements_soft, run->mesh_size,
            solver.map.name ? solver.map.name : "?", cs_bendSolverRuleName(&solver),
            cs_bendSolverProbedStiffness(&solver) ? "probed (FE)" : "default (8 C10 I)",
            run->tip_load[0], run->tip_load[1], run->tip_load[2]);
  }
  if (run->model == BEND_STRAIN) {
    fprintf(run->table, "strain leg: %d bending modes per segment (%d unknowns), calibration "
            "%s, rule %s, section stiffness %s, tip load (%g, %g, %g) N in the base frame, "
            "gravity off\n", solver.links, solver.n_dofs,
            solver.map.name ? solver.map.name : "?", cs_bendSolverRuleName(&solver),
            cs_bendSolverProbedStiffness(&solver) ? "probed (FE)" : "default (8 C10 I)",
            run->tip_load[0], run->tip_load[1], run->tip_load[2]);
  }
  fprintf(run->table, "%9s %9s %9s %9s %10s %10s %10s %10s\n", "p (MPa)", "II1 (deg)", "II2 (deg)",
          "II3 (deg)", "total(deg)", "tip e1(mm)", "tip e2(mm)", "tip e3(mm)");
  for (size_t i = 0; i < bc.m; i++) {
    const double* a = &bc.angle_deg[3 * i];
    const double* x = &bc.tip[3 * i];
    fprintf(run->table, "%9.4f %9.3f %9.3f %9.3f %10.3f %10.3f %10.3f %10.3f\n", bc.pressure[i],
            a[0], a[1], a[2], bc.angle_total[i], x[0], x[1], x[2]);
  }
  if (!isnan(run->until_angle)) {
    if (isnan(p_until)) {
      snprintf(res->until_line, sizeof res->until_line,
               "until-angle: total angle %g deg not reached up to %g MPa", run->until_angle,
               p_searched);
    } else {
      snprintf(res->until_line, sizeof res->until_line,
               "until-angle: total angle %g deg at p = %.6f MPa%s", run->until_angle, p_until,
               p_until > run->p_max ? " (above --p-max)" : "");
    }
    fprintf(run->table, "%s\n", res->until_line);
  }
  fprintf(run->table, "wrote %s (%.3f s)\n", run->out, wall);
  csr_bendCurveFree(&bc);
  cs_bendSolverClose(&solver);
  return CS_OK;
}


void csx_bendResultFill(const BendRun* run, const csrBendCurve* bc, csxBendResult* res) {
  (void)run;
  res->p_until = bc->p_until_angle;
  if (bc->m > 0) {
    res->angle_total = bc->angle_total[bc->m - 1];
    res->p_end = bc->pressure[bc->m - 1];
  }
}


/* `crawlsim bend` with its table on `table`, its notes on `notes` and its results in *sres
 * (NULL: the command line; else a study's step, both streams its log) */
static int bendCommand(int argc, char** argv, FILE* table, FILE* notes, csxStepResult* sres) {
  /* SIGINT/SIGTERM end the work after the step in progress (cs_signal.h); this command
   * polls the flag */
  csx_signalInstall();
  BendRun run;
  csxOptIter it;
  csxOptKind kind;
  csError err;
  cs_errorClear(&err);
  int p = parseArgs(argc, argv, &run, &it, &kind, &err);
  p = csx_parseEnd(&kBendTable, p, kind, &it, &err, notes, sres);
  if (p >= 0) {
    return p;
  }
  run.table = table;
  run.notes = notes;
  csxBendResult res;
  csStatus st = csx_bendExecute(&run, &res, &err);
  if (sres) {
    sres->p_until = res.p_until;
    sres->angle_total = res.angle_total;
    sres->p_end = res.p_end;
    /* the case summary's piece: the until-angle line, else the last row */
    if (res.until_line[0]) {
      snprintf(sres->summary, sizeof sres->summary, "%s", res.until_line);
    } else if (!isnan(res.angle_total)) {
      snprintf(sres->summary, sizeof sres->summary, "bend: total %.3f deg at %.4f MPa",
               res.angle_total, res.p_end);
    }
  }
  if (st != CS_OK) {
    csx_stepFailed(sres, notes, "bend", err.msg);
    return csx_bendExitCode(st);
  }
  return 0;
}


int csx_cmdBend(int argc, char** argv) {
  return bendCommand(argc, argv, stdout, stderr, NULL);
}


int csx_stepBend(int argc, char** argv, FILE* log, csxStepResult* res) {
  return bendCommand(argc, argv, log, log, res);
}

/* cmd_calibrate.c: `crawlsim calibrate`: the FE calibration of the legs' chamber modes and
 * stiffness (fem/fem_calibration.h), resumable case by case.
 *
 *   crawlsim calibrate [--out FILE.h5] [--dir DIR] [--case NAME]... [--list] [--merge-only]
 *                      [--actuator leg|baseline|fig1] [--set NAME=VALUE]... [--mesh-size MM]
 *                      [--fibre-size MM] [--fibre-split 0|1] [--fibre-law LAW] [--p-step MPA]
 *                      [--fibre-turn DEG] [--mesh-symmetric 0|1]
 *
 * Every case (all of them, or the --case ones) is an FE pressure sweep written to DIR/NAME.h5
 * (and its deformed leg at the last state to DIR/NAME.vtu for ParaView);
 * a case whose file is already finished for the same actuator and FE settings is skipped, so a
 * calibration stopped after some cases continues where it stopped. A case file is written under
 * a temporary name and renamed when complete, so a killed run never leaves a file that looks
 * finished. Then every finished case file in DIR is merged into FILE.h5 and the table is read
 * back as the legs will read it (robot_calibration.h) to check it. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "core_clock.h"
#include "core_math.h"
#include "cmd_fe_threads.h"
#include "cs_commands.h"
#include "cs_opts.h"
#include "cs_signal.h"
#include "fem_calibration.h"
#include "robot_actuator.h"
#include "robot_bend_io.h"
#include "robot_calibration.h"

/* the options of `crawlsim calibrate`, for parsing and --help (cs_opts.h) */
static const csxOpt kCalOpts[] = {
    {"--out", "FILE.h5", "calibration_fe.h5", "the merged calibration table"},
    {"--dir", "DIR", "calibration_cases", "one file per case (finished cases are skipped)"},
    {"--case", "NAME", "every case", "run only this case, repeatable (--list names them)"},
    {"--list", NULL, "off", "print the cases and exit"},
    {"--merge-only", NULL, "off", "merge the finished case files, run nothing"},
    {"--report", "TABLE.h5", NULL,
     "print the calibration model's report from a merged table alone (no case files)"},
    {"--model-out", "PRED.h5", NULL,
     "write the model's predictions for tools/plot_calibration.py"},
    {"--cal-rule", "prism|rbf|rbf-pair", "prism",
     "the model rule of the report and the predictions"},
    {"--actuator", "leg|baseline|fig1", "leg", "the actuator preset"},
    {"--set", "NAME=VALUE", NULL, "an actuator parameter, repeatable (as crawlsim bend)"},
    {"--mesh-size", "MM", "4", "the soft elements' size l_soft in mm, 0.5..20"},
    {"--fibre-size", "MM", "0.5", "the fibre element length l_fibre in mm, 0.05..20"},
    {"--fibre-split", "0|1", "1",
     "1 splits fibre elements at the tets' faces; 0: 20-node ties"},
    {"--fibre-law", "tension-only|linear", "tension-only",
     "tension-only: a thread carries no compression; linear: compression at full stiffness"},
    {"--fibre-turn", "DEG", "0",
     "the helices' start turned about the leg axis by a multiple of 90 degrees (a check of the "
     "FE's symmetry; recorded, a table's cases must share it)"},
    {"--mesh-symmetric", "0|1", "0",
     "1 meshes an eighth of the leg, mirrored and turned (recorded; a table's cases must share "
     "it)"},
    {"--p-step", "MPA", "0.025", "the rows' pressure increment in MPa, 1e-4..0.5"},
    {"--p-max", "MPA", "each case's own", "caps every case's end pressure in MPa (small tables)"},
    {"--newton-rtol", "R", "1e-6",
     "Newton's test |R| <= R of the force scale, 1e-12..1e-3 (recorded; the shipped table's "
     "cases ran at 1e-8)"},
    {"--threads", "N", "this process's cores, less those other processes hold",
     "the FE's threads"},
};

static const csxOptTable kCalTable = {
    "calibrate", "",
    "Run the full FE model on every calibration case (chamber modes, unequal pressures, "
    "held-out combinations, stiffness probes, the leg under its weight), one file per case in "
    "DIR, merge them into FILE.h5 and read the table back as the legs will; with every mode "
    "finished, print the calibration model's report.",
    kCalOpts, CSX_NOPT(kCalOpts), NULL};

enum { MAX_SETS = 32, MAX_PICK = CSF_CAL_MAX_CASES };

/* the definition of a calibration: the parsed options (the strings point into argv) */
typedef struct {
  const char* out;       /* the merged table */
  const char* dir;       /* the case files */
  const char* actname;   /* the actuator preset */
  const char* model_out; /* NULL, or the model's predictions */
  const char* report;    /* NULL, or a merged table to report on alone */
  csrCalOptions copt;    /* the model rule of the report */
  const char* sets[MAX_SETS];
  const char* pick[MAX_PICK];
  int nset, npick, list, merge_only, threads;
  csfCalSettings cs;     /* the FE settings of every case */
  FILE* table;           /* where the results go (the command: stdout; a study's step: its log) */
  FILE* notes;           /* where the cases' progress goes (stderr; the log) */
} CalDef;

/* what a calibration gives back besides its files */
typedef struct {
  int ran, skipped, finished, ncase; /* cases run now, already done, finished of all */
  char table_line[256];  /* "crawlsim calibrate: table FILE (N cases)" ("": nothing merged) */
} CalResult;


/* a case's progress lines: its name and where they go */
typedef struct {
  const char* name;
  FILE* notes;
} CaseProgress;


static void progress(void* user, const csfBendStep* s) {
  const CaseProgress* cp = user;
  const char* name = cp->name;
  const char* indef = s->neg_pivots > 0 ? ", tangent indefinite" : "";
  if (s->volume_control) {
    fprintf(cp->notes, "  %s: volume control: p = %.5f MPa (dp %+.5f), %d Newton iterations, "
            "%.1f s%s\n", name, s->p, s->dp, s->newton_iters, s->wall, indef);
    return;
  }
  fprintf(cp->notes, "  %s: p = %.4f MPa, %d Newton iterations, %d cut-backs, %.1f s, total %.1f "
          "deg%s\n", name, s->p, s->newton_iters, s->cutbacks, s->wall, s->angle_total, indef);
}


static int parseNumber(const char* flag, const char* v, double lo, double hi, double* out,
                       csError* err) {
  char* end;
  errno = 0;
  double x = strtod(v, &end);
  if (end == v || *end || errno || !isfinite(x) || x < lo || x > hi) {
    cs_errorSet(err, CS_ERR_ARG, "%s '%s' must be a number in [%g, %g]", flag, v, lo,
                hi);
    return 1;
  }
  *out = x;
  return 0;
}


/* Print the table's map and its calibration model's report on `table` (and write the
 * predictions to model_out); closes cal. A pair-mode table has no model: an error only when
 * `need_model`. 0, or 1 with err filled. */
static int reportModel(FILE* table, csrCalibration* cal, const char* path,
                       const char* model_out, int need_model, csError* err) {
  csrBendMap map = csr_calibrationMap(cal);
  fprintf(table, "crawlsim calibrate: %s (pressures up to %g MPa)\n", map.name, map.p_max);
  /* the model's errors against the table (robot_calibration_model.h) */
  const csrCalModel* model = csr_calibrationModel(cal);
  int rc = 0;
  if (!model) {
    if (need_model) {
      cs_errorSet(err, CS_ERR_ARG, "%s: a pair-mode table, no mode model to report",
                  path);
      rc = 1;
    }
  } else if (csr_calReportPrint(model, csr_calibrationTable(cal), table, err) != CS_OK ||
             (model_out &&
              csr_calReportWrite(model, csr_calibrationTable(cal), model_out, err) != CS_OK)) {
    rc = 1;
  } else if (model_out) {
    fprintf(table, "crawlsim calibrate: model predictions %s\n", model_out);
  }
  csr_calibrationClose(cal);
  return rc;
}


/* argv into d: 0; 1 with err filled; 2 when `it` holds --help or an option error (*kind) */
static int parseCal(int argc, char** argv, CalDef* d, csxOptIter* it, csxOptKind* kind,
                    csError* err) {
  memset(d, 0, sizeof *d);
  d->out = "calibration_fe.h5";
  d->dir = "calibration_cases";
  d->actname = "leg";
  d->copt = csr_calModelDefaultOptions();
  d->cs = csf_calibrationDefault();
  csfCalSettings* cs = &d->cs;
  csx_optBegin(it);
  while ((*kind = csx_optNext(&kCalTable, argc, argv, it)) != CSX_OPT_END) {
    if (*kind == CSX_OPT_HELP || *kind == CSX_OPT_ERROR) {
      return 2;
    }
    if (*kind == CSX_OPT_OPERAND) {
      cs_errorSet(err, CS_ERR_ARG, "unexpected argument '%s'", it->value);
      return 1;
    }
    const char* a = it->opt->name;
    const char* v = it->value;
    if (!strcmp(a, "--list")) {
      d->list = 1;
      continue;
    }
    if (!strcmp(a, "--merge-only")) {
      d->merge_only = 1;
      continue;
    }
    int bad = 0;
    if (!strcmp(a, "--threads")) {
      bad = csx_feParseThreads(v, &d->threads, err);
    } else if (!strcmp(a, "--mesh-size")) {
      bad = parseNumber(a, v, 0.5, 20, &cs->mesh_size, err);
    } else if (!strcmp(a, "--fibre-size")) {
      bad = parseNumber(a, v, 0.05, 20, &cs->fibre_size, err);
    } else if (!strcmp(a, "--fibre-split")) {
      bad = strcmp(v, "0") != 0 && strcmp(v, "1") != 0;
      if (bad) {
        cs_errorSet(err, CS_ERR_ARG, "--fibre-split '%s' must be 0 or 1", v);
      }
      cs->fibre_split = !strcmp(v, "1");
    } else if (!strcmp(a, "--mesh-symmetric")) {
      bad = strcmp(v, "0") != 0 && strcmp(v, "1") != 0;
      if (bad) {
        cs_errorSet(err, CS_ERR_ARG, "--mesh-symmetric '%s' must be 0 or 1", v);
      }
      cs->mesh_symmetric = !strcmp(v, "1");
    } else if (!strcmp(a, "--fibre-turn")) {
      double deg = 0;
      bad = parseNumber(a, v, -270, 270, &deg, err);
      if (!bad && fmod(deg, 90.0) != 0) {
        cs_errorSet(err, CS_ERR_ARG, "--fibre-turn '%s' must be a multiple of 90", v);
        bad = 1;
      }
      cs->fibre_turn = (int)(deg / 90.0);
    } else if (!strcmp(a, "--fibre-law")) {
      cs->fibre_tension_only = csr_fibreLawParse(v);
      bad = cs->fibre_tension_only < 0;
      if (bad) {
        cs_errorSet(err, CS_ERR_ARG, "--fibre-law '%s' must be linear or tension-only",
                    v);
      }
    } else if (!strcmp(a, "--p-step")) {
      bad = parseNumber(a, v, 1e-4, 0.5, &cs->p_step, err);
    } else if (!strcmp(a, "--newton-rtol")) {
      bad = parseNumber(a, v, 1e-12, 1e-3, &cs->newton_rtol, err);
    } else if (!strcmp(a, "--p-max")) {
      bad = parseNumber(a, v, 1e-4, 1.0, &cs->p_cap, err);
    } else if (!strcmp(a, "--out")) {
      d->out = v;
    } else if (!strcmp(a, "--dir")) {
      d->dir = v;
    } else if (!strcmp(a, "--model-out")) {
      d->model_out = v;
    } else if (!strcmp(a, "--report")) {
      d->report = v;
    } else if (!strcmp(a, "--cal-rule")) {
      if (!csr_calRuleParse(v, &d->copt.rule)) {
        cs_errorSet(err, CS_ERR_ARG, "unknown --cal-rule '%.60s' (expected prism, rbf or "
                    "rbf-pair)", v);
        return 1;
      }
    } else if (!strcmp(a, "--actuator")) {
      d->actname = v;
    } else if (!strcmp(a, "--case")) {
      if (!csf_calibrationCaseFind(v)) {
        cs_errorSet(err, CS_ERR_ARG, "--case '%s': no such case (see --list)", v);
        return 1;
      }
      if (d->npick == MAX_PICK) {
        cs_errorSet(err, CS_ERR_ARG, "more than %d --case options", MAX_PICK);
        return 1;
      }
      d->pick[d->npick++] = v;
    } else if (!strcmp(a, "--set")) {
      if (d->nset == MAX_SETS) {
        cs_errorSet(err, CS_ERR_ARG, "more than %d --set options", MAX_SETS);
        return 1;
      }
      d->sets[d->nset++] = v;
    }
    if (bad) {
      return 1;
    }
  }
  return 0;
}


/* run the calibration d defines, its lines on d->table and d->notes: the exit status (0; 1
 * or 128 + a signal with err filled) and *res */
static int executeCal(const CalDef* d, CalResult* res, csError* err) {
  csfCalSettings cs = d->cs;
  const char* const out = d->out;
  const char* const dir = d->dir;
  int ncase = 0;
  const csfCalCase* cases = csf_calibrationCases(&ncase);
  if (d->list) {
    for (int k = 0; k < ncase; k++) {
      fprintf(d->table, "%-10s %-8s p <= %.3g MPa  ratio %g:%g:%g:%g%s  %s\n", cases[k].name,
              cases[k].kind == CSF_CAL_MODE      ? "mode"
              : cases[k].kind == CSF_CAL_HOLDOUT ? "held-out"
              : cases[k].kind == CSF_CAL_GRAVITY ? "gravity"
                                                 : "symmetry",
              cases[k].p_max, cases[k].ratio[0], cases[k].ratio[1], cases[k].ratio[2],
              cases[k].ratio[3], cases[k].probes ? ", probes" : "", cases[k].about);
    }
    return 0;
  }
  /* the actuator: preset, then every --set, then a consistency check */
  csrActuator act;
  if (csr_actuatorPreset(&act, d->actname, err) != CS_OK) {
    return 1;
  }
  for (int k = 0; k < d->nset; k++) {
    if (csr_actuatorSetString(&act, d->sets[k], err) != CS_OK) {
      return 1;
    }
  }
  if (csr_actuatorValidate(&act, err) != CS_OK) {
    return 1;
  }
  if (d->report) {
    /* the report of a merged table alone (no case files needed) */
    csrCalibration* cal = csr_calibrationOpenWith(d->report, &act, &d->copt, err);
    if (!cal) {
      return 1;
    }
    return reportModel(d->table, cal, d->report, d->model_out, 1, err);
  }
  if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
    cs_errorSet(err, CS_ERR_ARG, "%s: cannot create the case directory: %s", dir,
                strerror(errno));
    return 1;
  }
  /* run what is not done yet, on the thread plan's count (fem_threads.h) */
  csfThreadPlan plan;
  if (!d->merge_only) {
    csx_fePlanThreads(d->notes, "calibrate", d->threads, &plan);
    cs.threads = plan.threads;
    cs.threads_why = plan.why;
    cs.mpi_ranks = csx_feRanks(&cs.mpi_ranks_local); /* crawlsim-mpi under mpirun */
  }
  char stem[600];
  const double t_all = csu_wallSeconds();
  int ran = 0, skipped = 0;
  for (int k = 0; k < ncase && !d->merge_only; k++) {
    int chosen = d->npick == 0;
    for (int q = 0; q < d->npick; q++) {
      chosen |= !strcmp(d->pick[q], cases[k].name);
    }
    if (!chosen) {
      continue;
    }
    char path[600], part[620];
    snprintf(path, sizeof path, "%s/%s.h5", dir, cases[k].name);
    snprintf(part, sizeof part, "%s.part", path);
    if (csf_calibrationCaseDone(path, &act, cases + k, &cs)) {
      skipped++;
      continue;
    }
    fprintf(d->notes, "crawlsim calibrate: case %s (%s): 0..%g MPa\n", cases[k].name,
            cases[k].about, cs.p_cap > 0 ? fmin(cases[k].p_max, cs.p_cap) : cases[k].p_max);
    snprintf(stem, sizeof stem, "%s/%s.mesh", dir, cases[k].name); /* per case: runs of
                                                                    * other cases may share dir */
    cs.work_stem = stem;
    char vtu[620];
    snprintf(vtu, sizeof vtu, "%s/%s.vtu", dir, cases[k].name); /* the deformed leg (ParaView) */
    cs.vtu_path = vtu;
    CaseProgress cp = {cases[k].name, d->notes};
    cs.progress = progress;
    cs.progress_user = &cp;
    cs.cancel = csx_signalFlag(); /* SIGINT/SIGTERM: this case ends, no case file; resumable */
    const double t0 = csu_wallSeconds();
    if (csf_calibrationRunCase(&act, cases + k, &cs, part, err) != CS_OK) {
      char cause[sizeof err->msg];
      memcpy(cause, err->msg, sizeof cause);
      cs_errorSet(err, err->status, "case %s: %.400s%s", cases[k].name, cause,
                  err->status == CS_ERR_INTERRUPTED ? " (run again to continue: finished cases "
                  "are kept)" : "");
      remove(part);
      return err->status != CS_ERR_INTERRUPTED ? 1
             : csx_signalExitCode() ? csx_signalExitCode() : 130;
    }
    if (rename(part, path) != 0) {
      cs_errorSet(err, CS_ERR_ARG, "%s: cannot rename to %s: %s", part, path,
                  strerror(errno));
      return 1;
    }
    fprintf(d->notes, "crawlsim calibrate: case %s done in %.0f s -> %s\n", cases[k].name,
            csu_wallSeconds() - t0, path);
    ran++;
  }
  /* merge every finished case file of this actuator and these settings */
  const char* paths[CSF_CAL_MAX_CASES];
  char store[CSF_CAL_MAX_CASES][600];
  int np = 0;
  for (int k = 0; k < ncase; k++) {
    snprintf(store[np], sizeof store[np], "%s/%s.h5", dir, cases[k].name);
    if (csf_calibrationCaseDone(store[np], &act, cases + k, &cs)) {
      paths[np] = store[np];
      np++;
    }
  }
  res->ran = ran;
  res->skipped = skipped;
  res->finished = np;
  res->ncase = ncase;
  fprintf(d->table, "crawlsim calibrate: %d cases run, %d already done, %d of %d finished (%.0f "
          "s)\n", ran, skipped, np, ncase, csu_wallSeconds() - t_all);
  if (np == 0) {
    cs_errorSet(err, CS_ERR_ARG, "%s: no finished case to merge", dir);
    return 1;
  }
  if (csf_calibrationMerge(paths, np, out, err) != CS_OK) {
    return 1;
  }
  snprintf(res->table_line, sizeof res->table_line, "crawlsim calibrate: table %s (%d cases)",
           out, np);
  fprintf(d->table, "%s\n", res->table_line);
  /* read it back as the legs will */
  csrCalibration* cal = csr_calibrationOpenWith(out, &act, &d->copt, err);
  if (!cal && np < ncase) {
    /* cases still to run (the calibration goes case by case): not an error yet */
    fprintf(d->table, "crawlsim calibrate: not usable by the legs until every mode is finished: "
            "%s\n", err->msg);
    cs_errorClear(err);
    return 0;
  }
  if (!cal) {
    return 1;
  }
  return reportModel(d->table, cal, out, d->model_out, 0, err);
}


/* `crawlsim calibrate` with its results on `table`, the cases' progress on `notes` and its
 * results in *sres (NULL: the command line; else a study's step, both streams its log) */
static int calibrateCommand(int argc, char** argv, FILE* table, FILE* notes,
                            csxStepResult* sres) {
  /* SIGINT/SIGTERM end the work after the step in progress (cs_signal.h); this command
   * polls the flag */
  csx_signalInstall();
  CalDef d;
  csxOptIter it;
  csxOptKind kind;
  csError err;
  cs_errorClear(&err);
  int rc = parseCal(argc, argv, &d, &it, &kind, &err);
  rc = csx_parseEnd(&kCalTable, rc, kind, &it, &err, notes, sres);
  if (rc >= 0) {
    return rc;
  }
  d.table = table;
  d.notes = notes;
  CalResult res;
  memset(&res, 0, sizeof res);
  rc = executeCal(&d, &res, &err);
  if (sres) {
    snprintf(sres->summary, sizeof sres->summary, "%s", res.table_line);
  }
  if (rc != 0) {
    csx_stepFailed(sres, notes, "calibrate", err.msg);
  }
  return rc;
}


int csx_cmdCalibrate(int argc, char** argv) {
  return calibrateCommand(argc, argv, stdout, stderr, NULL);
}


int csx_stepCalibrate(int argc, char** argv, FILE* log, csxStepResult* res) {
  return calibrateCommand(argc, argv, log, log, res);
}

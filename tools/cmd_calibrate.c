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


static void progress(void* user, const csfBendStep* s) {
  const char* name = user;
  const char* indef = s->neg_pivots > 0 ? ", tangent indefinite" : "";
  if (s->volume_control) {
    fprintf(stderr, "  %s: volume control: p = %.5f MPa (dp %+.5f), %d Newton iterations, "
            "%.1f s%s\n", name, s->p, s->dp, s->newton_iters, s->wall, indef);
    return;
  }
  fprintf(stderr, "  %s: p = %.4f MPa, %d Newton iterations, %d cut-backs, %.1f s, total %.1f "
          "deg%s\n", name, s->p, s->newton_iters, s->cutbacks, s->wall, s->angle_total, indef);
}


static int parseNumber(const char* flag, const char* v, double lo, double hi, double* out) {
  char* end;
  errno = 0;
  double x = strtod(v, &end);
  if (end == v || *end || errno || !isfinite(x) || x < lo || x > hi) {
    fprintf(stderr, "crawlsim calibrate: %s '%s' must be a number in [%g, %g]\n", flag, v, lo,
            hi);
    return 1;
  }
  *out = x;
  return 0;
}


/* Print the table's map and its calibration model's report (and write the predictions to
 * model_out); closes cal. A pair-mode table has no model: an error only when `need_model`. */
static int reportModel(csrCalibration* cal, const char* path, const char* model_out,
                       int need_model) {
  csError err;
  cs_errorClear(&err);
  csrBendMap map = csr_calibrationMap(cal);
  printf("crawlsim calibrate: %s (pressures up to %g MPa)\n", map.name, map.p_max);
  /* the model's errors against the table (robot_calibration_model.h) */
  const csrCalModel* model = csr_calibrationModel(cal);
  int rc = 0;
  if (!model) {
    if (need_model) {
      fprintf(stderr, "crawlsim calibrate: %s: a pair-mode table, no mode model to report\n",
              path);
      rc = 1;
    }
  } else if (csr_calReportPrint(model, csr_calibrationTable(cal), stdout, &err) != CS_OK ||
             (model_out &&
              csr_calReportWrite(model, csr_calibrationTable(cal), model_out, &err) != CS_OK)) {
    fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
    rc = 1;
  } else if (model_out) {
    printf("crawlsim calibrate: model predictions %s\n", model_out);
  }
  csr_calibrationClose(cal);
  return rc;
}


int csx_cmdCalibrate(int argc, char** argv) {
  /* SIGINT/SIGTERM end the work after the step in progress (cs_signal.h); this command
   * polls the flag */
  csx_signalInstall();
  const char* out = "calibration_fe.h5";
  const char* dir = "calibration_cases";
  const char* actname = "leg";
  const char* model_out = NULL;
  const char* report = NULL;
  csrCalOptions copt = csr_calModelDefaultOptions();
  const char* sets[MAX_SETS];
  const char* pick[MAX_PICK];
  int nset = 0, npick = 0, list = 0, merge_only = 0, threads = 0;
  csfCalSettings cs = csf_calibrationDefault();
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kCalTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kCalTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      fprintf(stderr, "crawlsim calibrate: unexpected argument '%s'\n", it.value);
      return 1;
    }
    const char* a = it.opt->name;
    const char* v = it.value;
    if (!strcmp(a, "--list")) {
      list = 1;
      continue;
    }
    if (!strcmp(a, "--merge-only")) {
      merge_only = 1;
      continue;
    }
    int bad = 0;
    if (!strcmp(a, "--threads")) {
      bad = csx_feParseThreads("calibrate", v, &threads);
    } else if (!strcmp(a, "--mesh-size")) {
      bad = parseNumber(a, v, 0.5, 20, &cs.mesh_size);
    } else if (!strcmp(a, "--fibre-size")) {
      bad = parseNumber(a, v, 0.05, 20, &cs.fibre_size);
    } else if (!strcmp(a, "--fibre-split")) {
      bad = strcmp(v, "0") != 0 && strcmp(v, "1") != 0;
      if (bad) {
        fprintf(stderr, "crawlsim calibrate: --fibre-split '%s' must be 0 or 1\n", v);
      }
      cs.fibre_split = !strcmp(v, "1");
    } else if (!strcmp(a, "--mesh-symmetric")) {
      bad = strcmp(v, "0") != 0 && strcmp(v, "1") != 0;
      if (bad) {
        fprintf(stderr, "crawlsim calibrate: --mesh-symmetric '%s' must be 0 or 1\n", v);
      }
      cs.mesh_symmetric = !strcmp(v, "1");
    } else if (!strcmp(a, "--fibre-turn")) {
      double deg = 0;
      bad = parseNumber(a, v, -270, 270, &deg);
      if (!bad && fmod(deg, 90.0) != 0) {
        fprintf(stderr, "crawlsim calibrate: --fibre-turn '%s' must be a multiple of 90\n", v);
        bad = 1;
      }
      cs.fibre_turn = (int)(deg / 90.0);
    } else if (!strcmp(a, "--fibre-law")) {
      cs.fibre_tension_only = csr_fibreLawParse(v);
      bad = cs.fibre_tension_only < 0;
      if (bad) {
        fprintf(stderr, "crawlsim calibrate: --fibre-law '%s' must be linear or tension-only\n",
                v);
      }
    } else if (!strcmp(a, "--p-step")) {
      bad = parseNumber(a, v, 1e-4, 0.5, &cs.p_step);
    } else if (!strcmp(a, "--newton-rtol")) {
      bad = parseNumber(a, v, 1e-12, 1e-3, &cs.newton_rtol);
    } else if (!strcmp(a, "--p-max")) {
      bad = parseNumber(a, v, 1e-4, 1.0, &cs.p_cap);
    } else if (!strcmp(a, "--out")) {
      out = v;
    } else if (!strcmp(a, "--dir")) {
      dir = v;
    } else if (!strcmp(a, "--model-out")) {
      model_out = v;
    } else if (!strcmp(a, "--report")) {
      report = v;
    } else if (!strcmp(a, "--cal-rule")) {
      if (!csr_calRuleParse(v, &copt.rule)) {
        fprintf(stderr, "crawlsim calibrate: unknown --cal-rule '%.60s' (expected prism, rbf or "
                "rbf-pair)\n", v);
        return 1;
      }
    } else if (!strcmp(a, "--actuator")) {
      actname = v;
    } else if (!strcmp(a, "--case")) {
      if (!csf_calibrationCaseFind(v)) {
        fprintf(stderr, "crawlsim calibrate: --case '%s': no such case (see --list)\n", v);
        return 1;
      }
      if (npick == MAX_PICK) {
        fprintf(stderr, "crawlsim calibrate: more than %d --case options\n", MAX_PICK);
        return 1;
      }
      pick[npick++] = v;
    } else if (!strcmp(a, "--set")) {
      if (nset == MAX_SETS) {
        fprintf(stderr, "crawlsim calibrate: more than %d --set options\n", MAX_SETS);
        return 1;
      }
      sets[nset++] = v;
    }
    if (bad) {
      return 1;
    }
  }
  int ncase = 0;
  const csfCalCase* cases = csf_calibrationCases(&ncase);
  if (list) {
    for (int k = 0; k < ncase; k++) {
      printf("%-10s %-8s p <= %.3g MPa  ratio %g:%g:%g:%g%s  %s\n", cases[k].name,
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
  csError err;
  cs_errorClear(&err);
  csrActuator act;
  if (csr_actuatorPreset(&act, actname, &err) != CS_OK) {
    fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
    return 1;
  }
  for (int k = 0; k < nset; k++) {
    if (csr_actuatorSetString(&act, sets[k], &err) != CS_OK) {
      fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
      return 1;
    }
  }
  if (csr_actuatorValidate(&act, &err) != CS_OK) {
    fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
    return 1;
  }
  if (report) {
    /* the report of a merged table alone (no case files needed) */
    csrCalibration* cal = csr_calibrationOpenWith(report, &act, &copt, &err);
    if (!cal) {
      fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
      return 1;
    }
    return reportModel(cal, report, model_out, 1);
  }
  if (mkdir(dir, 0777) != 0 && errno != EEXIST) {
    fprintf(stderr, "crawlsim calibrate: %s: cannot create the case directory: %s\n", dir,
            strerror(errno));
    return 1;
  }
  /* run what is not done yet, on the thread plan's count (fem_threads.h) */
  csfThreadPlan plan;
  if (!merge_only) {
    csx_fePlanThreads("calibrate", threads, &plan);
    cs.threads = plan.threads;
    cs.threads_why = plan.why;
    cs.mpi_ranks = csx_feRanks(&cs.mpi_ranks_local); /* crawlsim-mpi under mpirun */
  }
  char stem[600];
  const double t_all = csu_wallSeconds();
  int ran = 0, skipped = 0;
  for (int k = 0; k < ncase && !merge_only; k++) {
    int chosen = npick == 0;
    for (int q = 0; q < npick; q++) {
      chosen |= !strcmp(pick[q], cases[k].name);
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
    fprintf(stderr, "crawlsim calibrate: case %s (%s): 0..%g MPa\n", cases[k].name,
            cases[k].about, cs.p_cap > 0 ? fmin(cases[k].p_max, cs.p_cap) : cases[k].p_max);
    snprintf(stem, sizeof stem, "%s/%s.mesh", dir, cases[k].name); /* per case: runs of
                                                                    * other cases may share dir */
    cs.work_stem = stem;
    char vtu[620];
    snprintf(vtu, sizeof vtu, "%s/%s.vtu", dir, cases[k].name); /* the deformed leg (ParaView) */
    cs.vtu_path = vtu;
    cs.progress = progress;
    cs.progress_user = (void*)cases[k].name;
    cs.cancel = csx_signalFlag(); /* SIGINT/SIGTERM: this case ends, no case file; resumable */
    const double t0 = csu_wallSeconds();
    if (csf_calibrationRunCase(&act, cases + k, &cs, part, &err) != CS_OK) {
      fprintf(stderr, "crawlsim calibrate: case %s: %s%s\n", cases[k].name, err.msg,
              err.status == CS_ERR_INTERRUPTED ? " (run again to continue: finished cases are "
              "kept)" : "");
      remove(part);
      return err.status != CS_ERR_INTERRUPTED ? 1
             : csx_signalExitCode() ? csx_signalExitCode() : 130;
    }
    if (rename(part, path) != 0) {
      fprintf(stderr, "crawlsim calibrate: %s: cannot rename to %s: %s\n", part, path,
              strerror(errno));
      return 1;
    }
    fprintf(stderr, "crawlsim calibrate: case %s done in %.0f s -> %s\n", cases[k].name,
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
  printf("crawlsim calibrate: %d cases run, %d already done, %d of %d finished (%.0f s)\n", ran,
         skipped, np, ncase, csu_wallSeconds() - t_all);
  if (np == 0) {
    fprintf(stderr, "crawlsim calibrate: %s: no finished case to merge\n", dir);
    return 1;
  }
  if (csf_calibrationMerge(paths, np, out, &err) != CS_OK) {
    fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
    return 1;
  }
  printf("crawlsim calibrate: table %s (%d cases)\n", out, np);
  /* read it back as the legs will */
  csrCalibration* cal = csr_calibrationOpenWith(out, &act, &copt, &err);
  if (!cal && np < ncase) {
    /* cases still to run (the calibration goes case by case): not an error yet */
    printf("crawlsim calibrate: not usable by the legs until every mode is finished: %s\n",
           err.msg);
    return 0;
  }
  if (!cal) {
    fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
    return 1;
  }
  return reportModel(cal, out, model_out, 0);
}

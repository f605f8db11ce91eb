/* bench_strain_driver.c: the real-time factor of the flat road on its scene defaults (the
 * 23-mode symmetric-mesh table under rbf-pair, gaits/flat_road_rod.csv, `paper`), one level
 * after the other in ONE process, so their ratio is measured under the same load (not a test:
 * prints numbers; docs/notes/strain_leg.md "In the driver").
 *
 *   bench_strain_driver [t_end_s] [LEVEL[:LINKS[:DT_S[:ORDER[:TREE_TOL_MM[:ACTIVE]]]]]]...
 *
 * (ORDER 0, TREE_TOL 0: the defaults; ACTIVE the strain level's setting active_set, 1 the
 * contact ghosts in the Newton passes, 0 the law alone, absent: the default)
 *
 * Default: 9 s of `strain` (its defaults: 3 bending modes per segment, tree coupling at its
 * 0.5 ms), `strain:3:0.001` and `rod:8` (the scene's default: 8 elements per segment,
 * Gauss-Seidel at 1 ms). Each run
 * goes through cs_run into a scratch HDF5 file, as `crawlsim run` does. Printed per run: CPU
 * seconds of the process (clock(): the time this process got, less sensitive to the machine's
 * load than wall time) and the real-time factor from it, the wall time, and the split of the
 * step by stage from the driver's wall timers (sim_model.h): legs (actuation, the legs'
 * condensation and back-substitution, or their advance), contact (the support's collision),
 * tree (cs_couplingApplyTree: the support's 6 x 6 solves AND every Newton pass after the
 * first, i.e. the legs' update and iterate, which is most of the leg work at 5 ms; the first
 * pass is in legs), support (its ODE step, less contact and tree), pneumatics,
 * output, the rest (schedule, check, state saves); then the support's x at the end. The
 * stages' shares are wall-time fractions: on a loaded machine a preempted stage looks dearer,
 * so compare the shares of runs made together. The data files come from $CS_SOURCE_DIR
 * (default ../../..); with CS_BENCH_KEEP=DIR each run's file stays in DIR. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "sim_model.h"

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }


static void quiet(int num, const char* msg, va_list ap) {
  (void)num;
  (void)msg;
  (void)ap;
}


static int bench(const char* src, const char* arg, double t_end) {
  char level[32] = "", terr[600], gait[600], cal[600];
  int links = 0, order = 0, active = -1;
  double dt = 0, tol = 0;
  /* LEVEL[:LINKS[:DT[:ORDER]]] (ORDER: the tree step's formula, 1 backward Euler, 2 BDF2; 0 or
   * absent: the level's default; TREE_TOL: the tree step's Newton tolerance, mm) */
  const char* c1 = strchr(arg, ':');
  snprintf(level, sizeof level, "%.*s", c1 ? (int)(c1 - arg) : (int)strlen(arg), arg);
  if (c1) {
    links = atoi(c1 + 1);
    const char* c2 = strchr(c1 + 1, ':');
    dt = c2 ? atof(c2 + 1) : 0;
    const char* c3 = c2 ? strchr(c2 + 1, ':') : NULL;
    order = c3 ? atoi(c3 + 1) : 0;
    const char* c4 = c3 ? strchr(c3 + 1, ':') : NULL;
    tol = c4 ? atof(c4 + 1) : 0;
    const char* c5 = c4 ? strchr(c4 + 1, ':') : NULL;
    active = c5 ? atoi(c5 + 1) : -1;
  }
  const csrLegType* type = csr_legTypeFind(level, NULL);
  if (!type) {
    fprintf(stderr, "bench_strain_driver: unknown level '%s'\n", level);
    return 1;
  }
  snprintf(terr, sizeof terr, "%s/terrains/flat_road.terrain", src);
  snprintf(gait, sizeof gait, "%s/gaits/flat_road_rod.csv", src);
  snprintf(cal, sizeof cal, "%s/robot/calibration_fe_leg_modes_sym.h5", src);
  csModel m;
  cs_modelInit(&m);
  cs_modelSetConditions(&m, CS_CONDITIONS_PAPER);
  cs_modelSetLegLevel(&m, type);
  if (csr_legSettingSet(type, &m.robot.leg_settings, "links",
                        links > 0 ? links : type->prepare ? 3 : 8, NULL) != CS_OK) {
    fprintf(stderr, "bench_strain_driver: --links %d is not a value of legs %s\n", links,
            type->name);
    cs_modelDestroy(&m);
    return 1;
  }
  if (dt > 0) {
    m.opt.h = dt;
  }
  if (order > 0 && csr_legSettingSet(type, &m.robot.leg_settings, "step_order", order, NULL) != CS_OK) {
    fprintf(stderr, "bench_strain_driver: order %d is not a value of legs %s\n", order, type->name);
    cs_modelDestroy(&m);
    return 1;
  }
  if (active >= 0 &&
      csr_legSettingSet(type, &m.robot.leg_settings, "active_set", active, NULL) != CS_OK) {
    fprintf(stderr, "bench_strain_driver: active_set %d is not a value of legs %s\n", active,
            type->name);
    cs_modelDestroy(&m);
    return 1;
  }
  if (tol > 0) {
    m.opt.tree_tol = tol;
  }
  m.opt.t_end = t_end;
  csrCalRule rule;
  if (csr_calRuleParse("rbf-pair", &rule)) {
    m.cal_rule = (int)rule;
  }
  csError err;
  cs_errorClear(&err);
  if (cs_modelLoad(&m, "flat-road", terr, gait, cal, &err) != CS_OK) {
    fprintf(stderr, "bench_strain_driver: %s\n", err.msg);
    cs_modelDestroy(&m);
    return 1;
  }
  csData* d = cs_dataCreate(&m, &err);
  if (!d || cs_settle(&m, d, &err) != CS_OK) {
    fprintf(stderr, "bench_strain_driver: %s\n", err.msg);
    cs_dataDestroy(d);
    cs_modelDestroy(&m);
    return 1;
  }
  /* CS_BENCH_KEEP=DIR keeps each run's file as DIR/LEVEL_LINKS_DT_ORDER[_noactive].h5 (its track, for the
   * errors against a reference: docs/bench/levels_one_process_2026-12-05) */
  const char* keep = getenv("CS_BENCH_KEEP");
  char out[700];
  if (keep) {
    snprintf(out, sizeof out, "%s/%s_%d_%g_%d%s.h5", keep, level,
             (int)csr_legSettingGet(type, &m.robot.leg_settings, "links", 0), m.opt.h, order,
             active == 0 ? "_noactive" : "");
  } else {
    snprintf(out, sizeof out, "bench_strain_driver_%s.h5", level);
  }
  const double c0 = cpu();
  double wall = 0;
  csStatus st = cs_runWrite(&m, d, out, &wall, &err);
  const double c = cpu() - c0;
  if (!keep) {
    remove(out);
  }
  /* steps and rejections of the run (the data's counts include the settling) */
  const long nstep = cs_stepCount(d) - lround(m.opt.settle / cs_modelMacroStep(&m));
  double x[3];
  cs_supportDisplacement(d, x);
  const csuTimer* tm = cs_timers(d);
  const double step = tm[CS_TIMER_STEP].wall, total = step + tm[CS_TIMER_OUTPUT].wall;
  const double support = tm[CS_TIMER_SUPPORT].wall - tm[CS_TIMER_CONTACT].wall -
                         tm[CS_TIMER_TREE].wall;
  const double rest = step - tm[CS_TIMER_LEGS].wall - tm[CS_TIMER_SUPPORT].wall -
                      tm[CS_TIMER_PNEUMATICS].wall;
  const double t_run = cs_time(d);
  printf("%s, %d per segment, h %g ms (order %d, tol %g mm), coupling %s: %.2f s simulated%s, CPU %.2f s -> real-time "
         "factor %.3f (wall %.2f s: %.3f), %ld steps, %ld rejected (with the settling); x(end) %.2f mm\n", level,
         (int)csr_legSettingGet(type, &m.robot.leg_settings, "links", 0), m.opt.h * 1e3,
         (int)csr_legSettingGet(type, &m.robot.leg_settings, "step_order", 1), m.opt.tree_tol,
         m.opt.coupling == CS_COUPLING_TREE           ? "tree"
         : m.opt.coupling == CS_COUPLING_GAUSS_SEIDEL ? "gs"
         : m.opt.coupling == CS_COUPLING_STABILISED   ? "stabilised"
                                                      : "staggered",
         t_run, st == CS_OK ? "" : " (stopped)", c, t_run / c, wall, t_run / wall, nstep,
         cs_rejectCount(d), x[0]);
  if (m.opt.coupling == CS_COUPLING_TREE) {
    printf("  tree: %ld Newton passes (%.2f per step, with the settling and the rejected tries), "
           "%ld contact ghosts released (active_set %d)\n",
           cs_treePassCount(d), (double)cs_treePassCount(d) / (double)cs_stepCount(d),
           cs_treeReleaseCount(d),
           (int)csr_legSettingGet(type, &m.robot.leg_settings, "active_set", 0));
  }
  printf("  split of the wall time (%%): legs %.1f, contact %.2f, tree %.2f, support %.2f, "
         "pneumatics %.2f, output %.2f, rest %.2f\n", 100 * tm[CS_TIMER_LEGS].wall / total,
         100 * tm[CS_TIMER_CONTACT].wall / total, 100 * tm[CS_TIMER_TREE].wall / total,
         100 * support / total, 100 * tm[CS_TIMER_PNEUMATICS].wall / total,
         100 * tm[CS_TIMER_OUTPUT].wall / total, 100 * rest / total);
  printf("  legs: %.1f us of CPU per leg and step (the CPU time shared by the wall fractions)\n",
         1e6 * c * tm[CS_TIMER_LEGS].wall / total / (CSR_NLEG * (double)nstep));
  if (st != CS_OK) {
    printf("  stopped: %s\n", err.msg);
  }
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  return 0;
}


int main(int argc, char** argv) {
  const char* src = getenv("CS_SOURCE_DIR");
  if (!src) {
    src = "../../..";
  }
  const double t_end = argc > 1 ? atof(argv[1]) : 9.0;
  dInitODE2(0);
  dSetMessageHandler(quiet);
  int rc = 0;
  if (argc > 2) {
    for (int i = 2; i < argc && rc == 0; i++) {
      rc = bench(src, argv[i], t_end);
    }
  } else {
    rc = bench(src, "strain", t_end);
    if (rc == 0) {
      rc = bench(src, "strain:3:0.001", t_end);
    }
    if (rc == 0) {
      rc = bench(src, "rod:8", t_end);
    }
  }
  dCloseODE();
  return rc;
}

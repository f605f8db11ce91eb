/* bench_strain_driver.c: the real-time factor of the flat road on its scene defaults (the
 * 23-mode symmetric-mesh table under rbf-pair, gaits/flat_road_rod.csv, `paper`), one level
 * after the other in ONE process, so their ratio is measured under the same load (not a test:
 * prints numbers; docs/notes/strain_leg.md "In the driver").
 *
 *   bench_strain_driver [t_end_s] [LEVEL[:LINKS[:DT_S[:ORDER[:TREE_TOL_MM[:ACTIVE[:FRIC[:TRUST[:KEEP[:JOINTS[:SHEAR[:SUB[:CALQ]]]]]]]]]]]]]...
 *
 * (ORDER 0, TREE_TOL 0: the defaults; ACTIVE the strain level's setting active_set, 1 the
 * contact ghosts in the Newton passes, 0 the law alone; FRIC its setting friction_tangent, 0
 * the anchors' secant in the iterates, 1 the law's tangent; TRUST its setting slot_trust, 1 the
 * passes' slot trust region, 0 the full move; KEEP its setting keep_matrix, 0 a new iteration
 * matrix every step, > 0 the legs' factors kept across steps until a mode moves that far; -1
 * or absent: the default; with keep_matrix the legs' factorisations per step are printed;
 * JOINTS, SHEAR, SUB the strain level's basis settings joints (-1 rigid, 0 constant
 * curvature; -2 or absent: the default), shear (1 or 0 Kirchhoff) and sub (Magnus
 * sub-intervals per flexible piece), -1 or absent: the defaults; for rod legs JOINTS >= 1 is
 * their setting joint_links, the elements per solid joint, default 1; CALQ the strain level's
 * cal_quantum, the calibration's pressure resolution in MPa, -1 or absent: the default)
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
 * output, the rest (schedule, check, state saves); then the support's x at the end; then the
 * same split with the legs' own calls timed apart (legTimerWrap below: the calibration, the
 * first pass, the later Newton passes and the finish; the tree solve alone). The scene is the
 * flat road, or CS_BENCH_SCENE (a built-in scene's name, e.g. obstacle: its terrain, gait,
 * table and rule, under `paper`). The
 * stages' shares are wall-time fractions: on a loaded machine a preempted stage looks dearer,
 * so compare the shares of runs made together. CS_BENCH_PTOL=K scales the pneumatic
 * tolerances by K, CS_BENCH_PASSES=N sets the tree step's passes before a rejection,
 * CS_BENCH_ADA=TOL runs the adaptive tree step at TOL mm (DT its longest step). The data files come from $CS_SOURCE_DIR
 * (default ../../..); with CS_BENCH_KEEP=DIR each run's file stays in DIR. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "robot_strain.h"
#include "sim_model.h"

/* under valgrind --tool=callgrind --instr-atstart=no the instrumentation starts at the
 * measured window (CS_BENCH_FROM): the settling and the steps before it run uninstrumented */
#if defined(__has_include)
#if __has_include(<valgrind/callgrind.h>)
#include <valgrind/callgrind.h>
#endif
#endif
#ifndef CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_START_INSTRUMENTATION
#define CALLGRIND_DUMP_STATS_AT(label) ((void)(label))
#endif

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }


static void quiet(int num, const char* msg, va_list ap) {
  (void)num;
  (void)msg;
  (void)ap;
}


/* ---- the legs' own stages, timed from outside the library (issue 32's stage split) --------
 * The driver's timers (sim_model.h) put the legs' first pass (prepare) and end (finish) in
 * "legs" and every later Newton pass (update + iterate) in "tree" with the support's 6 x 6
 * solves. To print the tree solve apart, the bench runs the level through a copy of its
 * csrLegType whose calls are wrapped by the monotonic clock (core_clock.h csu_wallSeconds,
 * ~25 ns a reading against the legs' ~50-100 us a pass): the wrappers only read the clock and
 * add to the sums below, never touch what the leg computes, so the run's results are the
 * unwrapped level's bit for bit (the x(end) it prints is the check). The sums are this
 * program's (a bench, one run at a time): the library keeps no global state. */
enum { LT_ACTUATE, LT_PREPARE, LT_FINISH, LT_UPDATE, LT_ITERATE, LT_ADVANCE, LT_N };
static struct {
  const csrLegType* inner; /* the level the wrappers call */
  csuTimer t[LT_N];
  csrLeg* legs[CSR_NLEG];  /* the legs seen by prepare (the strain level's counts) */
  int nlegs;
} gLegTime;


static int timedActuate(csrLeg* leg, double t0, const double p0[12], double t1,
                        const double p1[12]) {
  const double w = csu_wallSeconds();
  const int rc = gLegTime.inner->actuate(leg, t0, p0, t1, p1);
  csu_timerAdd(&gLegTime.t[LT_ACTUATE], w);
  return rc;
}


static int timedAdvance(csrLeg* leg, double t, double H, const csrBaseState* b0,
                        const csrBaseState* b1, csrWrench* wr, csError* err) {
  const double w = csu_wallSeconds();
  const int rc = gLegTime.inner->advance(leg, t, H, b0, b1, wr, err);
  csu_timerAdd(&gLegTime.t[LT_ADVANCE], w);
  return rc;
}


static int timedPrepare(csrLeg* leg, double h, const csrBaseState* b0, double Z[36],
                        double rho[6]) {
  int seen = 0;
  for (int k = 0; k < gLegTime.nlegs; k++) {
    seen |= gLegTime.legs[k] == leg;
  }
  if (!seen && gLegTime.nlegs < CSR_NLEG) {
    gLegTime.legs[gLegTime.nlegs++] = leg;
  }
  const double w = csu_wallSeconds();
  const int rc = gLegTime.inner->prepare(leg, h, b0, Z, rho);
  csu_timerAdd(&gLegTime.t[LT_PREPARE], w);
  return rc;
}


static int timedFinish(csrLeg* leg, const csrBaseState* b1, csrWrench* wr) {
  const double w = csu_wallSeconds();
  const int rc = gLegTime.inner->finish(leg, b1, wr);
  csu_timerAdd(&gLegTime.t[LT_FINISH], w);
  return rc;
}


static int timedUpdate(csrLeg* leg, const csrBaseState* b1, double alpha,
                       const csrBaseState* b1_alpha, double* change) {
  const double w = csu_wallSeconds();
  const int rc = gLegTime.inner->update(leg, b1, alpha, b1_alpha, change);
  csu_timerAdd(&gLegTime.t[LT_UPDATE], w);
  return rc;
}


static int timedIterate(csrLeg* leg, double Z[36], double rho[6]) {
  const double w = csu_wallSeconds();
  const int rc = gLegTime.inner->iterate(leg, Z, rho);
  csu_timerAdd(&gLegTime.t[LT_ITERATE], w);
  return rc;
}


/* *timed = *type with its stepping calls wrapped (those it has) */
static void legTimerWrap(const csrLegType* type, csrLegType* timed) {
  memset(&gLegTime, 0, sizeof gLegTime);
  gLegTime.inner = type;
  *timed = *type;
  timed->actuate = type->actuate ? timedActuate : NULL;
  timed->advance = type->advance ? timedAdvance : NULL;
  timed->prepare = type->prepare ? timedPrepare : NULL;
  timed->finish = type->finish ? timedFinish : NULL;
  timed->update = type->update ? timedUpdate : NULL;
  timed->iterate = type->iterate ? timedIterate : NULL;
}


/* the stage split of one run (after it): the driver's timers with "legs" and "tree" opened up
 * by the wrappers' sums (settling excluded: the sums restart with the run, as the driver's) */
static void printStages(const csuTimer* tm, double cpu_s, long nstep) {
  const double step = tm[CS_TIMER_STEP].wall, out = tm[CS_TIMER_OUTPUT].wall;
  const double total = step + out;
  const csuTimer* lt = gLegTime.t;
  const double act = lt[LT_ACTUATE].wall;
  const double first = lt[LT_PREPARE].wall + lt[LT_ADVANCE].wall;
  const double passes = lt[LT_UPDATE].wall + lt[LT_ITERATE].wall;
  const double fin = lt[LT_FINISH].wall;
  const double legs = act + first + passes + fin;
  /* the tree stage less the legs' passes inside it: the support's 6 x 6 solves and sums */
  const double tree = tm[CS_TIMER_TREE].wall - passes;
  const double support = tm[CS_TIMER_SUPPORT].wall - tm[CS_TIMER_CONTACT].wall -
                         tm[CS_TIMER_TREE].wall;
  /* the driver's "legs" stage less the wrapped calls: its loops, hip states, wrench sums */
  const double glue = tm[CS_TIMER_LEGS].wall - act - first - fin;
  const double rest = step - tm[CS_TIMER_LEGS].wall - tm[CS_TIMER_SUPPORT].wall -
                      tm[CS_TIMER_PNEUMATICS].wall;
  printf("  stages (%% of the wall time, the legs opened up by wrapping the level's calls): "
         "legs %.1f [calibration %.1f, first pass %.1f, later passes %.1f, finish %.1f], "
         "tree solve %.2f, contact %.2f, support/ODE %.2f, pneumatics/CVODE %.2f, output "
         "%.2f, driver glue %.2f, rest %.2f\n",
         100 * legs / total, 100 * act / total, 100 * first / total, 100 * passes / total,
         100 * fin / total, 100 * tree / total, 100 * tm[CS_TIMER_CONTACT].wall / total,
         100 * support / total, 100 * tm[CS_TIMER_PNEUMATICS].wall / total, 100 * out / total,
         100 * glue / total, 100 * rest / total);
  /* the same as CPU per simulated second's share: what each stage costs at the run's rate */
  printf("  per leg and step (CPU by the wall shares): calibration %.2f us, first pass %.2f "
         "us, later passes %.2f us, finish %.2f us; output %.1f us per step (%ld passes: "
         "%.2f us per later pass and leg)\n",
         1e6 * cpu_s * act / total / (CSR_NLEG * (double)nstep),
         1e6 * cpu_s * first / total / (CSR_NLEG * (double)nstep),
         1e6 * cpu_s * passes / total / (CSR_NLEG * (double)nstep),
         1e6 * cpu_s * fin / total / (CSR_NLEG * (double)nstep),
         1e6 * cpu_s * out / total / (double)nstep, lt[LT_ITERATE].count,
         lt[LT_ITERATE].count > 0 ? 1e6 * cpu_s * passes / total / (double)lt[LT_ITERATE].count
                                  : 0.0);
}


/* the counts at a measured window's start (CS_BENCH_FROM, CS_BENCH_WINDOWS) */
typedef struct Window_ {
  double t0;
  long pass, step, rej, lsteps;
  csAdaptiveStats ada;
} Window;


static long legSteps(void) {
  long n = 0;
  for (int k = 0; k < gLegTime.nlegs && gLegTime.inner == &csr_leg_strain; k++) {
    long a, b, c;
    csr_legStrainCounts(gLegTime.legs[k], &a, &b, &c);
    n += a;
  }
  return n;
}


static void windowStart(const csModel* m, const csData* d, Window* w) {
  (void)m;
  w->t0 = cs_time(d);
  w->pass = cs_treePassCount(d);
  w->step = cs_stepCount(d);
  w->rej = cs_rejectCount(d);
  w->lsteps = legSteps();
  cs_adaptiveStats(d, &w->ada);
}


/* the window's counts: the leg steps prepared (tries, rejected ones included), the tree's
 * Newton passes per leg step, the legs' calls (gLegTime, reset at the window's start) */
static void windowPrint(const csModel* m, const csData* d, const Window* w) {
  csAdaptiveStats ada;
  cs_adaptiveStats(d, &ada);
  const long ls = legSteps() - w->lsteps, npass = cs_treePassCount(d) - w->pass;
  const double tries = (double)ls / CSR_NLEG;
  printf("  window [%g, %g] s: %ld macro steps (%ld rejected), %ld leg steps prepared (%.0f tries "
         "of the tree step), %ld tree passes (%.3f per try), leg calls: prepare %ld, iterate %ld, "
         "finish %ld, actuate %ld; adaptive %d: %ld accepted, %ld rejected by the error\n",
         w->t0, cs_time(d), cs_stepCount(d) - w->step, cs_rejectCount(d) - w->rej, ls, tries,
         npass, tries > 0 ? (double)npass / tries : 0.0, gLegTime.t[LT_PREPARE].count,
         gLegTime.t[LT_ITERATE].count, gLegTime.t[LT_FINISH].count,
         gLegTime.t[LT_ACTUATE].count, m->opt.step_adaptive, ada.accepted - w->ada.accepted,
         ada.rejected - w->ada.rejected);
}


static int bench(const char* src, const char* arg, double t_end) {
  char level[32] = "", terr[600], gait[600], cal[600];
  int links = 0, order = 0, active = -1, fric = -1, trust = -1, joints = -2, shear = -1, sub = -1;
  double dt = 0, tol = 0, kmat = -1, calq = -1;
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
    const char* c6 = c5 ? strchr(c5 + 1, ':') : NULL;
    fric = c6 ? atoi(c6 + 1) : -1;
    const char* c7 = c6 ? strchr(c6 + 1, ':') : NULL;
    trust = c7 ? atoi(c7 + 1) : -1;
    const char* c8 = c7 ? strchr(c7 + 1, ':') : NULL;
    kmat = c8 ? atof(c8 + 1) : -1;
    const char* c9 = c8 ? strchr(c8 + 1, ':') : NULL;
    joints = c9 ? atoi(c9 + 1) : -2;
    const char* c10 = c9 ? strchr(c9 + 1, ':') : NULL;
    shear = c10 ? atoi(c10 + 1) : -1;
    const char* c11 = c10 ? strchr(c10 + 1, ':') : NULL;
    sub = c11 ? atoi(c11 + 1) : -1;
    const char* c12 = c11 ? strchr(c11 + 1, ':') : NULL;
    calq = c12 ? atof(c12 + 1) : -1;
  }
  const csrLegType* type = csr_legTypeFind(level, NULL);
  if (!type) {
    fprintf(stderr, "bench_strain_driver: unknown level '%s'\n", level);
    return 1;
  }
  const char* scene_name = getenv("CS_BENCH_SCENE") ? getenv("CS_BENCH_SCENE") : "flat-road";
  const csScene* scene = cs_sceneFind(scene_name);
  if (!scene) {
    fprintf(stderr, "bench_strain_driver: unknown scene '%s'\n", scene_name);
    return 1;
  }
  snprintf(terr, sizeof terr, "%s/%s", src, scene->terrain);
  snprintf(gait, sizeof gait, "%s/%s", src, scene->gait);
  snprintf(cal, sizeof cal, "%s/%s", src, scene->calibration);
  csrLegType timed;
  legTimerWrap(type, &timed);
  type = &timed;
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
  /* CS_BENCH_ADA=TOL: the adaptive tree step (sim_adaptive.c) at the local error TOL mm, DT
   * its longest step (`crawlsim run --strain-step adaptive --step-tol TOL --dt DT`) */
  if (getenv("CS_BENCH_ADA") && atof(getenv("CS_BENCH_ADA")) > 0) {
    m.opt.step_adaptive = 1;
    m.opt.step_tol = atof(getenv("CS_BENCH_ADA"));
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
  if (fric >= 0 &&
      csr_legSettingSet(type, &m.robot.leg_settings, "friction_tangent", fric, NULL) != CS_OK) {
    fprintf(stderr, "bench_strain_driver: friction_tangent %d is not a value of legs %s\n", fric,
            type->name);
    cs_modelDestroy(&m);
    return 1;
  }
  if (trust >= 0 &&
      csr_legSettingSet(type, &m.robot.leg_settings, "slot_trust", trust, NULL) != CS_OK) {
    fprintf(stderr, "bench_strain_driver: slot_trust %d is not a value of legs %s\n", trust,
            type->name);
    cs_modelDestroy(&m);
    return 1;
  }
  if (kmat >= 0 &&
      csr_legSettingSet(type, &m.robot.leg_settings, "keep_matrix", kmat, NULL) != CS_OK) {
    fprintf(stderr, "bench_strain_driver: keep_matrix %g is not a value of legs %s\n", kmat,
            type->name);
    cs_modelDestroy(&m);
    return 1;
  }
  /* the strain level's basis beyond links (JOINTS -2, SHEAR and SUB -1 or absent: the defaults) */
  /* (rod legs: JOINTS >= 1 is their setting joint_links, the elements per solid joint) */
  const int rodj = csr_legSettingFind(type, "joint_links") != NULL;
  const char* bname[3] = {rodj ? "joint_links" : "joints", "shear", "sub"};
  const int bval[3] = {joints, shear, sub}, bunset[3] = {-2, -1, -1};
  for (int i = 0; i < 3; i++) {
    if (bval[i] != bunset[i] &&
        csr_legSettingSet(type, &m.robot.leg_settings, bname[i], bval[i], NULL) != CS_OK) {
      fprintf(stderr, "bench_strain_driver: %s %d is not a value of legs %s\n", bname[i],
              bval[i], type->name);
      cs_modelDestroy(&m);
      return 1;
    }
  }
  if (calq >= 0 &&
      csr_legSettingSet(type, &m.robot.leg_settings, "cal_quantum", calq, NULL) != CS_OK) {
    fprintf(stderr, "bench_strain_driver: cal_quantum %g is not a value of legs %s\n", calq,
            type->name);
    cs_modelDestroy(&m);
    return 1;
  }
  if (tol > 0) {
    m.opt.tree_tol = tol;
  }
  /* CS_BENCH_ADAPTIVE=TOL: the adaptive tree step at step_tol TOL mm (`--strain-step adaptive
   * --step-tol TOL`), its longest step DT or 5 ms (as cs_rundef.c's default) */
  if (getenv("CS_BENCH_ADAPTIVE") && atof(getenv("CS_BENCH_ADAPTIVE")) > 0) {
    m.opt.step_adaptive = 1;
    m.opt.step_tol = atof(getenv("CS_BENCH_ADAPTIVE"));
    if (!(dt > 0)) {
      m.opt.h = 0.005;
    }
  }
  /* CS_BENCH_PASSES=N: the tree step's Newton passes before a step is rejected (tree_iterations) */
  if (getenv("CS_BENCH_PASSES") && atoi(getenv("CS_BENCH_PASSES")) > 0) {
    m.opt.tree_iterations = atoi(getenv("CS_BENCH_PASSES"));
  }
  /* CS_BENCH_CARRY=1: with CS_BENCH_PASSES=1 the legs' momentum residual is carried
   * (tree_carry, the event17 prototype) */
  if (getenv("CS_BENCH_CARRY")) {
    m.opt.tree_carry = atoi(getenv("CS_BENCH_CARRY"));
  }
  /* CS_BENCH_PTOL=K multiplies the pneumatics' CVODE tolerances (the run-to-run noise floor's
   * "10x tighter pneumatic tolerance": K = 0.1) */
  if (getenv("CS_BENCH_PTOL") && atof(getenv("CS_BENCH_PTOL")) > 0) {
    m.opt.pneumatic_rtol *= atof(getenv("CS_BENCH_PTOL"));
    m.opt.pneumatic_atol *= atof(getenv("CS_BENCH_PTOL"));
  }
  m.opt.t_end = t_end;
  csrCalRule rule;
  if (csr_calRuleParse(scene->cal_rule, &rule)) {
    m.cal_rule = (int)rule;
  }
  csError err;
  cs_errorClear(&err);
  if (cs_modelLoad(&m, scene->name, terr, gait, cal, &err) != CS_OK) {
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
  /* CS_BENCH_KEEP=DIR keeps each run's file as DIR/SCENE_LEVEL_LINKS_DT_ORDER[_noactive][_tangent][_trust][_keepK].h5 (its track, for the
   * errors against a reference: docs/bench/levels_one_process_2026-12-05) */
  const char* keep = getenv("CS_BENCH_KEEP");
  char out[700];
  if (keep) {
    char ks[32] = "";
    if (kmat > 0) {
      snprintf(ks, sizeof ks, "_keep%g", kmat);
    }
    char bs[48] = "";
    if (rodj && joints != -2) {
      snprintf(bs, sizeof bs, "_jl%d", (int)csr_legSettingGet(type, &m.robot.leg_settings,
                                                             "joint_links", 1));
    } else if (joints != -2 || shear >= 0 || sub >= 0) {
      snprintf(bs, sizeof bs, "_j%d_s%d_n%d",
               (int)csr_legSettingGet(type, &m.robot.leg_settings, "joints", 0),
               (int)csr_legSettingGet(type, &m.robot.leg_settings, "shear", 1),
               csr_strainSubIntervals((int)csr_legSettingGet(type, &m.robot.leg_settings, "links", 2),
                                      (int)csr_legSettingGet(type, &m.robot.leg_settings, "sub", 0)));
    }
    char qs[32] = "";
    if (calq >= 0) {
      snprintf(qs, sizeof qs, "_calq%g", calq);
    }
    snprintf(out, sizeof out, "%s/%s_%s_%d_%g_%d%s%s%s%s%s%s.h5", keep, scene->name, level,
             (int)csr_legSettingGet(type, &m.robot.leg_settings, "links", 0), m.opt.h, order,
             active == 0 ? "_noactive" : "",
             fric == 1 ? "_tangent" : "", trust == 1 ? "_trust" : "", ks, bs, qs);
  } else {
    snprintf(out, sizeof out, "bench_strain_driver_%s.h5", level);
  }
  /* CS_BENCH_FROM=T0: the steps to T0 (s) first, outside the measured run: the run is then
   * [T0, T0 + t_end] (its file's times start at 0), the counts below are the window's */
  const double t_from = getenv("CS_BENCH_FROM") ? atof(getenv("CS_BENCH_FROM")) : 0;
  for (long i = 0, n0 = lround(t_from / cs_modelMacroStep(&m)); i < n0; i++) {
    if (cs_step(&m, d, &err) != CS_OK) {
      fprintf(stderr, "bench_strain_driver: before the window: %s\n", err.msg);
      cs_dataDestroy(d);
      cs_modelDestroy(&m);
      return 1;
    }
  }
  /* CS_BENCH_WINDOWS=N: N consecutive runs of t_end each (a file each), every one's counts
   * printed and, under callgrind, its profile dumped apart (CALLGRIND_DUMP_STATS_AT): the
   * instructions of [0, T], [T, 2T], ... in one process; the lines after the last are the last
   * window's (the stage split and the per-step figures, the whole run's timers) */
  const int nwin = getenv("CS_BENCH_WINDOWS") && atoi(getenv("CS_BENCH_WINDOWS")) > 1
                       ? atoi(getenv("CS_BENCH_WINDOWS"))
                       : 1;
  for (int w = 0; w + 1 < nwin; w++) {
    Window win;
    windowStart(&m, d, &win);
    CALLGRIND_START_INSTRUMENTATION;
    memset(gLegTime.t, 0, sizeof gLegTime.t);
    double wall_w = 0;
    const csStatus sw = cs_runWrite(&m, d, out, &wall_w, &err);
    windowPrint(&m, d, &win);
    char label[64];
    snprintf(label, sizeof label, "window %g-%g s", win.t0, cs_time(d));
    CALLGRIND_DUMP_STATS_AT(label);
    if (!keep) {
      remove(out);
    }
    if (sw != CS_OK) {
      fprintf(stderr, "bench_strain_driver: window %d: %s\n", w, err.msg);
      cs_dataDestroy(d);
      cs_modelDestroy(&m);
      return 1;
    }
  }
  const double t_win = cs_time(d); /* the last window's start */
  Window win;
  windowStart(&m, d, &win);
  CALLGRIND_START_INSTRUMENTATION;
  memset(gLegTime.t, 0, sizeof gLegTime.t); /* the run's, not the settling's */
  const double c0 = cpu();
  double wall = 0;
  const double w_all = csu_wallSeconds();
  csStatus st = cs_runWrite(&m, d, out, &wall, &err);
  /* cs_runWrite's wall time after the run's loop: the file's last image and its XDMF */
  const double w_end = csu_wallSeconds() - w_all - wall;
  const double c = cpu() - c0;
  if (!keep) {
    remove(out);
  }
  /* steps and rejections of the run (the data's counts include the settling) */
  const long nstep = cs_stepCount(d) - lround((m.opt.settle + t_win) / cs_modelMacroStep(&m));
  double x[3];
  cs_supportDisplacement(d, x);
  const csuTimer* tm = cs_timers(d);
  const double step = tm[CS_TIMER_STEP].wall, total = step + tm[CS_TIMER_OUTPUT].wall;
  const double support = tm[CS_TIMER_SUPPORT].wall - tm[CS_TIMER_CONTACT].wall -
                         tm[CS_TIMER_TREE].wall;
  const double rest = step - tm[CS_TIMER_LEGS].wall - tm[CS_TIMER_SUPPORT].wall -
                      tm[CS_TIMER_PNEUMATICS].wall;
  const double t_run = cs_time(d) - t_win; /* the run's simulated time */
  printf("%s: %s, %d per segment, h %g ms (order %d, tol %g mm), coupling %s: %.2f s simulated%s, CPU %.2f s -> real-time "
         "factor %.3f (wall %.2f s: %.3f), %ld steps, %ld rejected (with the settling); x(end) %.2f mm\n", scene->name, level,
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
           "%ld contact ghosts released, %ld passes limited (active_set %d, friction_tangent "
           "%d, slot_trust %d)\n",
           cs_treePassCount(d), (double)cs_treePassCount(d) / (double)cs_stepCount(d),
           cs_treeReleaseCount(d), cs_treeLimitCount(d),
           (int)csr_legSettingGet(type, &m.robot.leg_settings, "active_set", 0),
           (int)csr_legSettingGet(type, &m.robot.leg_settings, "friction_tangent", 0),
           (int)csr_legSettingGet(type, &m.robot.leg_settings, "slot_trust", 0));
    if (gLegTime.inner == &csr_leg_strain) {
      printf("  basis: links %d, joints %d, shear %d, sub %d; cal_quantum %g MPa\n",
             (int)csr_legSettingGet(type, &m.robot.leg_settings, "links", 0),
             (int)csr_legSettingGet(type, &m.robot.leg_settings, "joints", 0),
             (int)csr_legSettingGet(type, &m.robot.leg_settings, "shear", 1),
             csr_strainSubIntervals((int)csr_legSettingGet(type, &m.robot.leg_settings, "links", 2),
                                    (int)csr_legSettingGet(type, &m.robot.leg_settings, "sub", 0)),
             csr_legSettingGet(type, &m.robot.leg_settings, "cal_quantum", 0));
      long lsteps = 0, lfac = 0, lkept = 0;
      for (int k = 0; k < gLegTime.nlegs; k++) {
        long a, b, c;
        csr_legStrainCounts(gLegTime.legs[k], &a, &b, &c);
        lsteps += a;
        lfac += b;
        lkept += c;
      }
      printf("  legs: %ld prepared steps (%ld on an earlier step's factor), %ld factorisations "
             "of W_ll (%.3f per leg step; keep_matrix %g; the settling's included)\n", lsteps,
             lkept, lfac, lsteps > 0 ? (double)lfac / (double)lsteps : 0.0,
             csr_legSettingGet(type, &m.robot.leg_settings, "keep_matrix", 0));
    }
  }
  printf("  split of the wall time (%%): legs %.1f, contact %.2f, tree %.2f, support %.2f, "
         "pneumatics %.2f, output %.2f, rest %.2f\n", 100 * tm[CS_TIMER_LEGS].wall / total,
         100 * tm[CS_TIMER_CONTACT].wall / total, 100 * tm[CS_TIMER_TREE].wall / total,
         100 * support / total, 100 * tm[CS_TIMER_PNEUMATICS].wall / total,
         100 * tm[CS_TIMER_OUTPUT].wall / total, 100 * rest / total);
  printf("  legs: %.1f us of CPU per leg and step (the CPU time shared by the wall fractions)\n",
         1e6 * c * tm[CS_TIMER_LEGS].wall / total / (CSR_NLEG * (double)nstep));
  printStages(tm, c, nstep);
  printf("  after the run: the file's last image and the XDMF beside it %.3f s wall (%.1f %% of "
         "the run's wall time; at 100x real time the run would take %.3f s)\n", w_end,
         100 * w_end / (wall > 0 ? wall : 1), t_run / 100);
  windowPrint(&m, d, &win);
  long pn[2];
  cs_pneumaticCounts(d, pn);
  const long nstep_all = cs_stepCount(d) + cs_rejectCount(d);
  printf("  pneumatics: %ld CVODE steps and %ld right-hand sides on the 96 pressures (%.2f and "
         "%.2f per macro step tried, with the settling)\n", pn[0], pn[1],
         (double)pn[0] / (double)(nstep_all > 0 ? nstep_all : 1),
         (double)pn[1] / (double)(nstep_all > 0 ? nstep_all : 1));
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

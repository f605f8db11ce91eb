/* test_state.c: the whole simulation state (cs_stateGet/Set) and step rollback on the shipped
 * flat road with the library's default legs (rod, 4 elements per segment, Gauss-Seidel) on the
 * mission's table (sim_scene.h CS_MISSION_*):
 *  - a step that fails in any stage (the calibration map failing at the legs' next table
 *    node, fatally, as out of range or recoverably; the check stage) leaves every byte of the
 *    state as it was, and a run continued after the failures is bit-identical to one that
 *    restored its own state at the same steps;
 *  - get, set, step twice from the same state gives bit-identical states;
 *  - states that are not states (NaN, a seed out of range, a non-unit quaternion) are refused
 *    and change nothing;
 *  - on rod legs (the scene's defaults, 2 elements per segment), two restores of one state
 *    followed by the same 1, 5 or 25 steps are bit-identical (~1 s more).
 * Runs of 0.1-0.3 s at 1 m/s^2 gravity during the first pressure ramp (the legs ask the map
 * for new table nodes then): a few seconds, so it also runs under the sanitizers. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "sim_model.h"
#include "sim_scene.h"

static char g_src[512];

/* a calibration map that passes through to the real one and, when armed, fails every call at a
 * pressure above the highest it has answered so far. The rod legs ask the map for the nodes of
 * their lazily filled tables (robot_rod_act.c), not every step: during a pressure ramp the next
 * node up is asked for within a few steps, and every ask for it fails while armed, whatever
 * data (and table) asks, so a failure is a property of the state, not of a call count. */
typedef struct {
  csrBendMap inner;
  long calls;
  double p_seen; /* MPa: the highest pressure answered */
  int armed;     /* fail calls above p_seen */
  int code;      /* what a failing call returns */
} FailMap;


static int failEval(const void* ctx, int seg, const double p[4], double bend[2],
                    double* stretch) {
  FailMap* f = (FailMap*)ctx; /* the test owns it: counting calls is its purpose */
  f->calls++;
  double pm = fmax(fmax(p[0], p[1]), fmax(p[2], p[3]));
  if (f->armed && pm > f->p_seen) {
    return f->code;
  }
  if (!f->armed) {
    f->p_seen = fmax(f->p_seen, pm);
  }
  return f->inner.eval(f->inner.ctx, seg, p, bend, stretch);
}


/* the flat-road model at 1 m/s^2 with the failing map in front of the mission's calibration */
static int loadModel(csModel* m, FailMap* fm, double tau) {
  char terr[600], gait[600], cal[600];
  snprintf(terr, sizeof terr, "%s/terrains/flat_road.terrain", g_src);
  snprintf(gait, sizeof gait, "%s/gaits/flat_road_paper.csv", g_src);
  snprintf(cal, sizeof cal, "%s/%s", g_src, CS_MISSION_CALIBRATION);
  cs_modelInit(m);
  csrCalRule rule;
  if (csr_calRuleParse(CS_MISSION_CAL_RULE, &rule)) {
    m->cal_rule = (int)rule;
  }
  m->opt.gravity = 1e3;
  m->opt.settle = 0.02;
  m->opt.pneumatic_tau = tau;
  csError err;
  cs_errorClear(&err);
  if (cs_modelLoad(m, "flat-road", terr, gait, cal, &err) != CS_OK) {
    fprintf(stderr, "load: %s\n", err.msg);
    return 0;
  }
  fm->inner = m->robot.map;
  fm->calls = 0;
  fm->p_seen = 0;
  fm->armed = 0;
  fm->code = -1;
  m->robot.map.eval = failEval;
  m->robot.map.ctx = fm;
  return 1;
}


static csData* makeData(const csModel* m) {
  csError err;
  cs_errorClear(&err);
  csData* d = cs_dataCreate(m, &err);
  CS_EXPECT(d != NULL);
  if (d) {
    CS_EXPECT(cs_settle(m, d, &err) == CS_OK);
  }
  return d;
}


static int stepN(const csModel* m, csData* d, int n) {
  csError err;
  for (int i = 0; i < n; i++) {
    if (cs_step(m, d, &err) != CS_OK) {
      fprintf(stderr, "step: %s\n", err.msg);
      return 0;
    }
  }
  return 1;
}


/* step until a step fails (at most `max_steps`): that step's status `want`, every byte of the
 * state as before it, the reject counted */
static void expectFailedStepChangesNothing(const csModel* m, csData* d, csStatus want,
                                           int max_steps, const char* what) {
  int n = cs_stateSize(m, d);
  double* before = malloc(n * sizeof(double));
  double* after = malloc(n * sizeof(double));
  csError err;
  cs_errorClear(&err);
  csStatus st = CS_OK;
  long steps = 0, rejects = 0;
  int k = 0;
  for (; k < max_steps && st == CS_OK; k++) {
    cs_stateGet(m, d, before);
    steps = cs_stepCount(d);
    rejects = cs_rejectCount(d);
    st = cs_step(m, d, &err);
  }
  CS_EXPECT(st == want);
  CS_EXPECT(strstr(err.msg, "t = ") == err.msg); /* the message names the time */
  cs_stateGet(m, d, after);
  CS_EXPECT(memcmp(before, after, n * sizeof(double)) == 0);
  CS_EXPECT(cs_stepCount(d) == steps && cs_rejectCount(d) == rejects + 1);
  printf("  %s (step %d after arming): %s -> state unchanged: %s\n", what, k,
         cs_statusString(st), memcmp(before, after, n * sizeof(double)) ? "NO" : "yes");
  free(before);
  free(after);
}


/* failures in the legs stage (after the pneumatics advanced CVODE) and in the check stage */
static void test_failed_step_changes_nothing(void) {
  csModel m;
  FailMap fm;
  CS_EXPECT(loadModel(&m, &fm, 0.02));
  csData* d = makeData(&m);
  /* into the first ramp, where every step re-evaluates the map */
  CS_EXPECT(d && stepN(&m, d, 100));
  /* the next table node the legs ask for fails: fatally, recoverably (the step is retried in
   * halves, which ask again), above the calibrated range */
  const int codes[3] = {-1, 1, CSR_MAP_OUT_OF_RANGE};
  const csStatus want[3] = {CS_ERR_SOLVER, CS_ERR_REJECTED, CS_ERR_RANGE};
  const char* what[3] = {"map fails (fatal)", "map fails (recoverable)", "map out of range"};
  for (int i = 0; i < 3; i++) {
    fm.armed = 1;
    fm.code = codes[i];
    expectFailedStepChangesNothing(&m, d, want[i], 50, what[i]);
  }
  fm.armed = 0;
  /* the last stage: a speed limit no state meets */
  double vmax = m.opt.max_speed;
  m.opt.max_speed = 1e-12;
  expectFailedStepChangesNothing(&m, d, CS_ERR_DIVERGED, 1, "check stage");
  m.opt.max_speed = vmax;
  /* and the run goes on */
  CS_EXPECT(stepN(&m, d, 10));
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
}


/* with the pressures following the schedule exactly (tau = 0, no pneumatic CVODE), a run
 * continued after failed steps is bit-identical to one that never failed but restored its own
 * state at the same steps: a failed step is exactly a restore of the state before it (the
 * ODE bodies, the data's random seed, the legs' own state). The restore is in the comparison
 * because each rod leg's CVODE restarts from a restored state (its step history is not state,
 * sim_model.h), so a run that never restores differs at the integrators' tolerances. The two
 * datas step interleaved in one process: each keeps its own place in ODE's process-wide random
 * sequence. */
static void test_run_after_failures_is_bit_identical(void) {
  csModel m;
  FailMap fm;
  CS_EXPECT(loadModel(&m, &fm, 0.0));
  csData* ref = makeData(&m);
  csData* d = makeData(&m);
  CS_EXPECT(ref && d && stepN(&m, ref, 50));
  CS_EXPECT(d && stepN(&m, d, 50));
  int n = d ? cs_stateSize(&m, d) : 0;
  double* a = malloc(n * sizeof(double));
  double* b = malloc(n * sizeof(double));
  int failed = 0;
  for (int k = 0; ref && d && k < 5; k++) {
    fm.armed = 1;
    fm.code = k % 2 ? 1 : -1; /* recoverable (retried in halves) and fatal */
    csError err;
    int steps = 0;
    /* both step while the legs' next table node is not yet asked for; d meets it first (the
     * two datas' tables fill alike: the same states ask for the same nodes) */
    while (steps < 50 && cs_step(&m, d, &err) == CS_OK) {
      CS_EXPECT(cs_step(&m, ref, &err) == CS_OK);
      steps++;
    }
    failed += steps < 50;
    fm.armed = 0;
    cs_stateGet(&m, ref, a); /* what d's failed step did: restore the state before it */
    CS_EXPECT(cs_stateSet(&m, ref, a, &err) == CS_OK);
    CS_EXPECT(stepN(&m, d, 20) && stepN(&m, ref, 20));
  }
  CS_EXPECT(failed == 5);
  if (ref && d) {
    cs_stateGet(&m, ref, a);
    cs_stateGet(&m, d, b);
    CS_EXPECT(cs_time(d) == cs_time(ref) && cs_rejectCount(d) == 5 && cs_rejectCount(ref) == 0);
    CS_EXPECT(memcmp(a, b, n * sizeof(double)) == 0);
    double worst = 0;
    for (int i = 0; i < n; i++) {
      worst = fmax(worst, fabs(a[i] - b[i]));
    }
    printf("  after 5 failed steps: largest state difference %g (t = %.3f s)\n", worst,
           cs_time(d));
  }
  free(a);
  free(b);
  cs_dataDestroy(ref);
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
}


/* get/set/step twice from the same state: bit-identical states (pneumatic CVODE included: both
 * runs restart it from the same pressures) */
static void test_set_step_twice_is_bit_identical(void) {
  csModel m;
  FailMap fm;
  CS_EXPECT(loadModel(&m, &fm, 0.02));
  csData* d = makeData(&m);
  CS_EXPECT(d && stepN(&m, d, 120));
  int n = cs_stateSize(&m, d);
  double* s0 = malloc(n * sizeof(double));
  double* r1 = malloc(n * sizeof(double));
  double* r2 = malloc(n * sizeof(double));
  cs_stateGet(&m, d, s0);
  csError err;
  CS_EXPECT(cs_stateSet(&m, d, s0, &err) == CS_OK);
  CS_EXPECT(stepN(&m, d, 60));
  cs_stateGet(&m, d, r1);
  CS_EXPECT(cs_stateSet(&m, d, s0, &err) == CS_OK);
  /* set, then get: the same bytes (bit-exact restore) */
  cs_stateGet(&m, d, r2);
  CS_EXPECT(memcmp(s0, r2, n * sizeof(double)) == 0);
  CS_EXPECT(stepN(&m, d, 60));
  cs_stateGet(&m, d, r2);
  CS_EXPECT(memcmp(r1, r2, n * sizeof(double)) == 0);
  CS_EXPECT(r1[0] > s0[0]); /* time moved on: the steps did something */
  CS_EXPECT(memcmp(r1 + 2, s0 + 2, (n - 2) * sizeof(double)) != 0);
  free(s0);
  free(r1);
  free(r2);
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
}


/* what is not a state is refused and changes nothing */
static void test_bad_states_are_refused(void) {
  csModel m;
  FailMap fm;
  CS_EXPECT(loadModel(&m, &fm, 0.02));
  csData* d = makeData(&m);
  CS_EXPECT(d && stepN(&m, d, 20));
  int n = cs_stateSize(&m, d);
  double* s = malloc(n * sizeof(double));
  double* x = malloc(n * sizeof(double));
  double* after = malloc(n * sizeof(double));
  cs_stateGet(&m, d, s);
  /* layout: t, seed, 96 pressures, the support body (13), legs A..H (one level: eight slices
   * of one size), then the coupling's carried data (co-simulated legs): found from the end by
   * which part refuses a NaN, so the robot's part must end where eight equal legs do */
  int robot_end = n;
  for (int i = n - 1; i >= 2 + 96; i--) {
    memcpy(x, s, n * sizeof(double));
    x[i] = NAN;
    csError e;
    cs_errorClear(&e);
    CS_EXPECT(cs_stateSet(&m, d, x, &e) == CS_ERR_ARG);
    if (strstr(e.msg, "robot's part")) {
      robot_end = i + 1;
      break;
    }
    CS_EXPECT(strstr(e.msg, "coupling's part") != NULL);
  }
  const int nlegs = robot_end - (2 + 96 + 13);
  CS_EXPECT(nlegs > 0 && nlegs % 8 == 0 && robot_end < n);
  printf("  state: %d doubles, legs %d each, the coupling's %d\n", n, nlegs / 8, n - robot_end);
  CS_EXPECT(s[0] == cs_time(d));
  struct {
    int index;
    double value;
    const char* what;
  } bad[5] = {{0, NAN, "time NaN"},
              {1, 4294967296.0, "seed beyond 32 bits"},
              {1, 0.5, "fractional seed"},
              {2 + 96 + 3, 2.0, "support quaternion not unit"},
              {robot_end - 1, INFINITY, "leg H value infinite"}};
  for (int k = 0; k < 5; k++) {
    memcpy(x, s, n * sizeof(double));
    x[bad[k].index] = bad[k].value;
    csError err;
    cs_errorClear(&err);
    CS_EXPECT(cs_stateSet(&m, d, x, &err) == CS_ERR_ARG);
    cs_stateGet(&m, d, after);
    CS_EXPECT(memcmp(s, after, n * sizeof(double)) == 0);
    printf("  %s: %s\n", bad[k].what, err.msg);
  }
  /* a value of leg E not finite, after the support's and legs A-D's slices were accepted:
   * they must come back too */
  memcpy(x, s, n * sizeof(double));
  x[2 + 96 + 13 + nlegs / 2] = NAN;
  csError err;
  CS_EXPECT(cs_stateSet(&m, d, x, &err) == CS_ERR_ARG);
  cs_stateGet(&m, d, after);
  CS_EXPECT(memcmp(s, after, n * sizeof(double)) == 0);
  free(s);
  free(x);
  free(after);
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
}


/* the flat road on its scene's defaults (rod legs on the 23-mode symmetric-mesh table under
 * rbf-pair, the designed gait, `paper`, Gauss-Seidel coupling, tau 0.02 s) with `links`
 * elements per segment (the test takes 2: the missing state was the same at the scene's 8,
 * measured before the fix); 0 if the rod level is not built */
static int loadRodScene(csModel* m, int links) {
  const csScene* sc = cs_sceneFind("flat-road");
  const csrLegType* rod = csr_legTypeFind("rod", NULL);
  if (!sc || !rod) {
    return 0;
  }
  char terr[600], gait[600], cal[600];
  snprintf(terr, sizeof terr, "%s/%s", g_src, sc->terrain);
  snprintf(gait, sizeof gait, "%s/%s", g_src, sc->gait);
  snprintf(cal, sizeof cal, "%s/%s", g_src, sc->calibration);
  cs_modelInit(m);
  cs_modelSetConditions(m, sc->conditions);
  csrCalRule rule;
  if (sc->cal_rule && csr_calRuleParse(sc->cal_rule, &rule)) {
    m->cal_rule = (int)rule;
  }
  csError err;
  cs_errorClear(&err);
  if (cs_modelLoad(m, "flat-road", terr, gait, cal, &err) != CS_OK) {
    fprintf(stderr, "load: %s\n", err.msg);
    return 0;
  }
  cs_modelSetLegLevel(m, rod);
  if (csr_legSettingSet(rod, &m->robot.leg_settings, "links", links, &err) != CS_OK) {
    fprintf(stderr, "links: %s\n", err.msg);
    return 0;
  }
  return 1;
}


/* On rod legs (co-simulated, Gauss-Seidel, each leg's own CVODE, the pneumatics' CVODE): two
 * restores of one saved state, each followed by the same steps, give bit-identical states. The
 * integrators restart from the state (robot_leg.h, sim_model.h), so anything a step reads that
 * is not in the state (a lagged Jacobian, a reused actuation, a step-size history, the legs'
 * base impulse accumulated since their last restart: the one that was missing, robot_rod_dyn.c)
 * shows here. (A run continued without a restore keeps its integrators' history and differs
 * at their tolerances: not required.) The state is saved in the
 * walk (1.2 s, a stance phase with pressures relaxing under the lag) and a few steps after. */
static void test_rod_restore_is_bit_identical(void) {
  csModel m;
  if (!loadRodScene(&m, 2)) {
    printf("  rod level or scene not available: skipped\n");
    return;
  }
  CS_EXPECT(m.opt.coupling == CS_COUPLING_GAUSS_SEIDEL && m.opt.pneumatic_tau > 0);
  csData* d = makeData(&m);
  const int n0 = (int)lround(1.2 / cs_modelMacroStep(&m));
  CS_EXPECT(d && stepN(&m, d, n0));
  const int n = d ? cs_stateSize(&m, d) : 0;
  double* s0 = malloc(n * sizeof(double));
  double* r1 = malloc(n * sizeof(double));
  double* r2 = malloc(n * sizeof(double));
  csError err;
  cs_errorClear(&err);
  int worst_k = -1;
  double worst = 0;
  for (int steps = 1; d && steps <= 25; steps *= 5) {
    cs_stateGet(&m, d, s0);
    CS_EXPECT(stepN(&m, d, steps + 7)); /* elsewhere: the restores start from a history */
    CS_EXPECT(cs_stateSet(&m, d, s0, &err) == CS_OK);
    CS_EXPECT(stepN(&m, d, steps));
    cs_stateGet(&m, d, r1);
    CS_EXPECT(stepN(&m, d, 3));
    CS_EXPECT(cs_stateSet(&m, d, s0, &err) == CS_OK);
    CS_EXPECT(stepN(&m, d, steps));
    cs_stateGet(&m, d, r2);
    int ndiff = 0;
    for (int i = 0; i < n; i++) {
      ndiff += r1[i] != r2[i];
      if (fabs(r1[i] - r2[i]) > worst) {
        worst = fabs(r1[i] - r2[i]);
        worst_k = i;
      }
    }
    printf("  %d step(s) after the restore: %d of %d entries differ between the two restores\n",
           steps, ndiff, n);
    CS_EXPECT(ndiff == 0);
    CS_EXPECT(memcmp(r1, r2, n * sizeof(double)) == 0);
    CS_EXPECT(memcmp(r1 + 2, s0 + 2, (n - 2) * sizeof(double)) != 0); /* the steps moved */
  }
  printf("  largest difference %g (entry %d)\n", worst, worst_k);
  free(s0);
  free(r1);
  free(r2);
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(g_src, sizeof g_src, "%s", src ? src : ".");
  dInitODE2(0);
  CS_RUN(test_failed_step_changes_nothing);
  CS_RUN(test_run_after_failures_is_bit_identical);
  CS_RUN(test_set_step_twice_is_bit_identical);
  CS_RUN(test_bad_states_are_refused);
  CS_RUN(test_rod_restore_is_bit_identical);
  dCloseODE();
  return cs_testSummary();
}

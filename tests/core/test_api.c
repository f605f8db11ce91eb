/* test_api.c: the public API (core/crawlsim.h) on the shipped flat road with the scene's rod legs
 * at their cheapest measured configuration (2 elements per segment, `--rod-tol 20`):
 *  - the run definition: defaults valid; every field out of range refused with a message
 *    naming the field (its `crawlsim run` option); NULL everywhere an error, never a crash;
 *  - pressures from a controller: one that replays the gait table gives the table's run bit
 *    for bit (every state value, each step), with and without the pneumatic lag; a held zero
 *    command leaves the support where it settled;
 *  - failures: a controller that fails, or commands out of range, fail the step and change
 *    nothing; a step after a failure is refused until reset; reset returns to t = 0;
 *  - cs_run without an output file and its result;
 *  - cs_bend: its grid, the straight actuator at p = 0, bad input refused.
 * Short runs (0.05-0.2 s at the shipped step), so it runs under the sanitizers too. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crawlsim.h"
#include "cs_test.h"

/* the scene's own gait, terrain and calibration on the cheapest rod of the speed/accuracy
 * chart (docs/studies/speed_accuracy.md; the flat road's default legs are strain): the API is
 * what is tested here */
static csRunDef cheapDef(void) {
  csRunDef d = cs_defaultRunDef();
  d.legs = "rod";
  d.links = 2;
  d.rod_tol = 20;
  return d;
}


static void expectRefused(csRunDef d, const char* what) {
  csError err;
  cs_errorClear(&err);
  csStatus st = cs_runDefValidate(&d, &err);
  CS_EXPECT(st != CS_OK);
  CS_EXPECT(strstr(err.msg, what) != NULL);
  if (!strstr(err.msg, what)) {
    fprintf(stderr, "  expected '%s' in: %s\n", what, err.msg);
  }
}


static void test_rundef_validation(void) {
  csError err;
  csRunDef d = cs_defaultRunDef();
  CS_EXPECT(cs_runDefValidate(&d, &err) == CS_OK);
  CS_EXPECT(cs_runDefValidate(NULL, &err) == CS_ERR_ARG && strstr(err.msg, "NULL"));
  CS_EXPECT(cs_runDefValidate(NULL, NULL) == CS_ERR_ARG); /* no error record: still an error */
  d = cs_defaultRunDef(); d.friction = -0.5; expectRefused(d, "--friction -0.5 must be >= 0");
  d = cs_defaultRunDef(); d.friction = NAN; CS_EXPECT(cs_runDefValidate(&d, &err) == CS_OK);
  d = cs_defaultRunDef(); d.pressure_scale = NAN; expectRefused(d, "--pressure-scale");
  d = cs_defaultRunDef(); d.t_end = -1; expectRefused(d, "--t-end -1 s must be >= 0");
  d = cs_defaultRunDef(); d.t_end = INFINITY; expectRefused(d, "--t-end inf is not a finite number");
  d = cs_defaultRunDef(); d.dt = 0; expectRefused(d, "--dt 0 s must be > 0");
  d = cs_defaultRunDef(); d.dt = 0.002; d.output_dt = 0.001; expectRefused(d, "--output-dt");
  d = cs_defaultRunDef(); d.ramp = -1; expectRefused(d, "--ramp -1 s");
  d = cs_defaultRunDef(); d.tau = -1; expectRefused(d, "--tau -1 s");
  d = cs_defaultRunDef(); d.gravity = -9.81; expectRefused(d, "--gravity");
  d = cs_defaultRunDef(); d.support_mass_kg = 0; expectRefused(d, "--support-mass 0 kg");
  d = cs_defaultRunDef(); d.links = 2.5; expectRefused(d, "--links 2.5 must be an integer");
  d = cs_defaultRunDef(); d.iterations = 1e30; expectRefused(d, "--iterations");
  d = cs_defaultRunDef(); d.macro_steps = 0; expectRefused(d, "--macro-steps 0");
  d = cs_defaultRunDef(); d.contact_scale = 1e7; expectRefused(d, "--contact-scale");
  d = cs_defaultRunDef(); d.legs = "rod"; d.rod_tol = 0; expectRefused(d, "--rod-tol 0");
  d = cs_defaultRunDef(); d.slope_deg = 50; expectRefused(d, "--slope-deg 50");
  d = cs_defaultRunDef(); d.scene = "moon"; expectRefused(d, "unknown scene 'moon'");
  d = cs_defaultRunDef(); d.legs = "jelly"; expectRefused(d, "unknown leg model 'jelly'");
  d = cs_defaultRunDef(); d.legs = "auto"; expectRefused(d, "--legs auto needs --tol");
  d = cs_defaultRunDef(); d.legs_tol_mm = 1; expectRefused(d, "--tol and --levels go with");
  d = cs_defaultRunDef(); d.conditions = "mars"; expectRefused(d, "unknown conditions 'mars'");
  d = cs_defaultRunDef(); d.coupling = "glue"; expectRefused(d, "unknown coupling 'glue'");
  d = cs_defaultRunDef(); d.legs = "rod"; d.coupling = "tree";
  expectRefused(d, "--coupling tree needs");
  d = cs_defaultRunDef(); d.cal_rule = "hats"; expectRefused(d, "unknown --cal-rule 'hats'");
  d = cs_defaultRunDef(); d.cal_drop = "ei"; expectRefused(d, "bad --cal-drop 'ei'");
  d = cs_defaultRunDef(); d.legs = "strain"; d.cal_drop = "stretch";
  expectRefused(d, "--cal-drop is for rod legs, not strain");
  d = cs_defaultRunDef(); d.n_actuator_set = 2; expectRefused(d, "--set");
  d = cs_defaultRunDef(); d.no_gait = 7; expectRefused(d, "no_gait");
}


/* NULL and files that are not there: an error with a message, never a crash */
static void test_null_and_bad_files(void) {
  csError err;
  CS_EXPECT(cs_simCreate(NULL, &err) == NULL && strstr(err.msg, "NULL"));
  CS_EXPECT(cs_simCreate(NULL, NULL) == NULL);
  CS_EXPECT(cs_simStep(NULL, &err) == CS_ERR_ARG && strstr(err.msg, "NULL"));
  CS_EXPECT(cs_simRunUntil(NULL, 1, &err) == CS_ERR_ARG);
  CS_EXPECT(cs_simReset(NULL, &err) == CS_ERR_ARG);
  CS_EXPECT(cs_simSetPressureCommand(NULL, NULL, &err) == CS_ERR_ARG);
  CS_EXPECT(cs_simSetController(NULL, NULL, NULL, &err) == CS_ERR_ARG);
  CS_EXPECT(cs_simStateSet(NULL, NULL, &err) == CS_ERR_ARG);
  double x[3] = {7, 7, 7}, q[4], f[24], p[96];
  cs_simSupportPose(NULL, x, q);
  cs_simSupportTwist(NULL, x, q);
  cs_simFootForces(NULL, f);
  cs_simPressures(NULL, p);
  cs_simGaitCommand(NULL, 0, p);
  cs_simStateGet(NULL, p);
  CS_EXPECT(x[0] == 7); /* untouched */
  CS_EXPECT(cs_simLegCenterline(NULL, 0, 5, f) == -1);
  CS_EXPECT(isnan(cs_simTime(NULL)) && cs_simStateSize(NULL) == 0);
  cs_simDestroy(NULL);
  csRunResult r;
  CS_EXPECT(cs_run(NULL, &r, &err) == CS_ERR_ARG && r.status == CS_ERR_ARG);
  CS_EXPECT(cs_run(NULL, NULL, NULL) == CS_ERR_ARG);
  csRunDef d = cheapDef();
  d.gait = "no/such/gait.csv";
  CS_EXPECT(cs_simCreate(&d, &err) == NULL && strstr(err.msg, "no/such/gait.csv"));
  CS_EXPECT(cs_run(&d, &r, &err) != CS_OK && strstr(r.message, "no/such/gait.csv") &&
            r.verdict[0] == '\0');
  d = cheapDef();
  d.out = "no/such/dir/run.h5";
  CS_EXPECT(cs_run(&d, &r, &err) == CS_ERR_IO && strstr(err.msg, "--out no/such/dir/run.h5"));
  d = cheapDef();
  d.no_gait = 1; /* nothing to say how long */
  CS_EXPECT(cs_run(&d, &r, &err) == CS_ERR_ARG && strstr(err.msg, "--t-end > 0"));
}


/* the gait table, evaluated where the driver asks: the same schedule through the controller */
static int replayGait(csSim* s, double t, double* p_cmd, void* user) {
  long* calls = user;
  (*calls)++;
  cs_simGaitCommand(s, t, p_cmd);
  return 0;
}


/* n steps of a with the gait and b with the replaying controller: every state value equal */
static void replayCompare(double tau, int n) {
  csRunDef d = cheapDef();
  d.tau = tau;
  csError err;
  csSim* a = cs_simCreate(&d, &err);
  csSim* b = cs_simCreate(&d, &err);
  CS_EXPECT(a && b);
  if (!a || !b) {
    fprintf(stderr, "  %s\n", err.msg);
    cs_simDestroy(a);
    cs_simDestroy(b);
    return;
  }
  long calls = 0;
  CS_EXPECT(cs_simSetController(b, replayGait, &calls, &err) == CS_OK);
  int ns = cs_simStateSize(a);
  CS_EXPECT(ns == cs_simStateSize(b) && ns > 96);
  double* xa = malloc(sizeof(double) * (size_t)ns);
  double* xb = malloc(sizeof(double) * (size_t)ns);
  int same = 1;
  for (int i = 0; i < n && same; i++) {
    CS_EXPECT(cs_simStep(a, &err) == CS_OK);
    CS_EXPECT(cs_simStep(b, &err) == CS_OK);
    cs_simStateGet(a, xa);
    cs_simStateGet(b, xb);
    same = !memcmp(xa, xb, sizeof(double) * (size_t)ns);
  }
  CS_EXPECT(same);
  CS_EXPECT(calls >= n); /* asked at least once a step */
  /* not a trivial comparison: the chambers are pressurised by then */
  double p[96], pmax = 0;
  cs_simPressures(b, p);
  for (int i = 0; i < 96; i++) pmax = fmax(pmax, p[i]);
  printf("replay (tau %g s): %d steps identical, controller asked %ld times, max pressure "
         "%.4g MPa\n", tau, n, calls, pmax);
  CS_EXPECT(pmax > 0.01);
  free(xa);
  free(xb);
  cs_simDestroy(a);
  cs_simDestroy(b);
}


static void test_controller_replays_gait(void) {
  /* 250 steps: the shipped gait states a 0.3 s actuation time, so its chambers pass 0.01 MPa
     only after ~0.13 s */
  replayCompare(0.02, 250); /* the shipped lag: the command inside the integrator */
  replayCompare(0.0, 250);  /* no lag: the command at each step's end */
}


/* zero pressures held: the settled robot stays where it settled */
static void test_zero_command_stands(void) {
  csRunDef d = cheapDef();
  csError err;
  csSim* s = cs_simCreate(&d, &err);
  CS_EXPECT(s != NULL);
  if (!s) return;
  double zero[96] = {0}, x[3], q[4];
  CS_EXPECT(cs_simSetPressureCommand(s, zero, &err) == CS_OK);
  CS_EXPECT(cs_simRunUntil(s, 0.2, &err) == CS_OK);
  CS_EXPECT_NEAR(cs_simTime(s), 0.2, 1e-9, 0); /* 200 steps of 1 ms, summed */
  cs_simSupportPose(s, x, q);
  double p[96], pmax = 0;
  cs_simPressures(s, p);
  for (int i = 0; i < 96; i++) pmax = fmax(pmax, fabs(p[i]));
  printf("zero command: after 0.2 s the support moved (%.3g, %.3g, %.3g) mm, max |p| %.3g MPa\n",
         x[0], x[1], x[2], pmax);
  /* the integrator's absolute tolerance (1e-8 MPa) bounds what it leaves of a zero command */
  CS_EXPECT(pmax < 1e-8);
  /* 0.05 mm: a twentieth of the millimetre the gait's first stride moves in its first 0.2 s
   * ramp would be; the settled robot only creeps by contact compliance */
  CS_EXPECT(fabs(x[0]) < 0.05 && fabs(x[1]) < 0.05 && fabs(x[2]) < 0.05);
  cs_simDestroy(s);
}


static int failLate(csSim* s, double t, double* p_cmd, void* user) {
  (void)user;
  cs_simGaitCommand(s, t, p_cmd);
  return t > 0.0105 ? 3 : 0;
}


static int nanLate(csSim* s, double t, double* p_cmd, void* user) {
  (void)user;
  cs_simGaitCommand(s, t, p_cmd);
  if (t > 0.0105) p_cmd[5] = NAN;
  return 0;
}


/* a failing controller (with and without the lag): the step fails, nothing changes, the next
 * step is refused, reset returns to t = 0 */
static void failureCase(double tau, csController f, const char* what) {
  csRunDef d = cheapDef();
  d.tau = tau;
  csError err;
  csSim* s = cs_simCreate(&d, &err);
  CS_EXPECT(s != NULL);
  if (!s) return;
  int ns = cs_simStateSize(s);
  double* x0 = malloc(sizeof(double) * (size_t)ns);
  double* x1 = malloc(sizeof(double) * (size_t)ns);
  double* xs = malloc(sizeof(double) * (size_t)ns);
  cs_simStateGet(s, xs); /* settled */
  CS_EXPECT(cs_simSetController(s, f, NULL, &err) == CS_OK);
  CS_EXPECT(cs_simRunUntil(s, 0.01, &err) == CS_OK);
  cs_simStateGet(s, x0);
  csStatus st = cs_simStep(s, &err);
  CS_EXPECT(st == CS_ERR_EXTERNAL && strstr(err.msg, what));
  cs_simStateGet(s, x1);
  CS_EXPECT(!memcmp(x0, x1, sizeof(double) * (size_t)ns));
  CS_EXPECT(cs_simStep(s, &err) == CS_ERR_ARG && strstr(err.msg, "after a failed step"));
  CS_EXPECT(cs_simReset(s, &err) == CS_OK);
  CS_EXPECT(cs_simTime(s) == 0);
  cs_simStateGet(s, x1);
  CS_EXPECT(!memcmp(xs, x1, sizeof(double) * (size_t)ns));
  CS_EXPECT(cs_simStep(s, &err) == CS_OK); /* t = 0.001: the controller passes again */
  free(x0);
  free(x1);
  free(xs);
  cs_simDestroy(s);
}


static void test_controller_failure(void) {
  failureCase(0.02, failLate, "the controller returned 3");
  failureCase(0.0, failLate, "the controller returned 3");
  failureCase(0.02, nanLate, "must be finite");
  failureCase(0.0, nanLate, "must be finite");
}


static void test_command_and_readouts(void) {
  csRunDef d = cheapDef();
  d.no_gait = 1;
  csError err;
  csSim* s = cs_simCreate(&d, &err);
  CS_EXPECT(s != NULL);
  if (!s) return;
  CS_EXPECT(cs_simChamberCount(s) == 96 && cs_simLegCount(s) == 8);
  CS_EXPECT_NEAR(cs_simMacroStep(s), 1e-3, 0, 0); /* the rod's default exchange, exactly */
  double p[96] = {0};
  p[10] = 1.5;
  CS_EXPECT(cs_simSetPressureCommand(s, p, &err) == CS_ERR_RANGE && strstr(err.msg, "index 10"));
  p[10] = NAN;
  CS_EXPECT(cs_simSetPressureCommand(s, p, &err) == CS_ERR_RANGE);
  p[10] = 0.1;
  CS_EXPECT(cs_simSetPressureCommand(s, p, &err) == CS_OK);
  CS_EXPECT(cs_simRunUntil(s, 0.05, &err) == CS_OK);
  double pr[96];
  cs_simPressures(s, pr);
  /* the lag: p = 0.1 (1 - exp(-t / tau)) at t = 0.05 s, tau = 0.02 s; CVODE's tolerances
   * (rtol 1e-6, atol 1e-8 MPa) bound the error far below 1e-5 MPa */
  CS_EXPECT_NEAR(pr[10], 0.1 * (1 - exp(-0.05 / 0.02)), 1e-5, 0);
  CS_EXPECT(pr[11] == 0);
  double xyz[25 * 3];
  CS_EXPECT(cs_simLegCenterline(s, 8, 25, xyz) == -1);
  CS_EXPECT(cs_simLegCenterline(s, 0, 1, xyz) == -1);
  CS_EXPECT(cs_simLegCenterline(s, 0, 25, NULL) == -1);
  CS_EXPECT(cs_simLegCenterline(s, 0, 25, xyz) == 0);
  CS_EXPECT(xyz[1] > xyz[24 * 3 + 1]); /* the hip above the foot (world y up) */
  double f[8][3], load = 0;
  cs_simFootForces(s, &f[0][0]);
  for (int k = 0; k < 8; k++) load += f[k][1];
  CS_EXPECT(load > 0); /* the ground carries the robot through its feet */
  double v[3], w[3];
  cs_simSupportTwist(s, v, w);
  CS_EXPECT(isfinite(v[0] + v[1] + v[2] + w[0] + w[1] + w[2]));
  /* a state that is not one is refused and changes nothing */
  int ns = cs_simStateSize(s);
  double* x = malloc(sizeof(double) * (size_t)ns);
  cs_simStateGet(s, x);
  double t_before = cs_simTime(s);
  x[2] = NAN;
  CS_EXPECT(cs_simStateSet(s, x, &err) != CS_OK);
  CS_EXPECT(cs_simTime(s) == t_before);
  free(x);
  CS_EXPECT(cs_simRunUntil(s, NAN, &err) == CS_ERR_RANGE);
  cs_simDestroy(s);
}


static void test_run_without_file(void) {
  csRunDef d = cheapDef();
  d.t_end = 0.05;
  csRunResult r;
  csError err;
  CS_EXPECT(cs_run(&d, &r, &err) == CS_OK);
  CS_EXPECT(r.status == CS_OK && !strcmp(r.verdict, "stands") && !strcmp(r.legs, "rod"));
  CS_EXPECT(!strcmp(r.scene, "flat-road") && !strcmp(r.conditions, "paper"));
  CS_EXPECT_NEAR(r.t_end, 0.05, 1e-9, 0); /* 50 steps of 1 ms, summed */
  /* steps since creation, the settling's included (as the file's `steps` attribute) */
  CS_EXPECT(r.steps >= 50 && r.rejected_steps == 0 && r.ntimer > 5);
  CS_EXPECT(r.robot_mass_g > 0);
  printf("cs_run: %s, %s legs, verdict %s at t = %g s, %s\n", r.scene, r.legs, r.verdict,
         r.t_end, cs_version());
}


/* cs_bend (the analytic model, milliseconds): the sweep's grid, the unpressurised straight
 * actuator, a bend that grows with p, and bad input refused with a message, never a crash */
static void test_bend(void) {
  csError err;
  csBendDef d = cs_defaultBendDef();
  CS_EXPECT(cs_bendDefValidate(&d, &err) == CS_OK);
  CS_EXPECT(cs_bendDefValidate(NULL, &err) == CS_ERR_ARG && strstr(err.msg, "NULL"));
  CS_EXPECT(cs_bendRowCount(NULL, NULL) == -1);
  d.p_max = 0.33; /* off the 0.05 grid: 0, 0.05, ..., 0.3 and 0.33 */
  int rows = cs_bendRowCount(&d, &err);
  CS_EXPECT(rows == 8);
  double p[8], ang[8][3], tip[8][3];
  int n = -1;
  CS_EXPECT(cs_bend(&d, 7, p, &ang[0][0], &tip[0][0], &n, &err) == CS_ERR_RANGE && n == 0 &&
            strstr(err.msg, "capacity"));
  CS_EXPECT(cs_bend(&d, 8, NULL, &ang[0][0], &tip[0][0], &n, &err) == CS_ERR_ARG);
  CS_EXPECT(cs_bend(&d, 8, p, &ang[0][0], &tip[0][0], &n, &err) == CS_OK && n == 8);
  CS_EXPECT(p[0] == 0 && p[7] == 0.33 && fabs(p[6] - 0.3) < 1e-15);
  /* p = 0: no bend, the tip on the axis e3 */
  CS_EXPECT(ang[0][0] == 0 && ang[0][1] == 0 && ang[0][2] == 0);
  CS_EXPECT(fabs(tip[0][0]) < 1e-12 && fabs(tip[0][1]) < 1e-12 && tip[0][2] > 0);
  for (int i = 1; i < 8; i++) { /* Θ grows with p (chambers 1,2 of every segment) */
    CS_EXPECT(ang[i][0] + ang[i][1] + ang[i][2] > ang[i - 1][0] + ang[i - 1][1] + ang[i - 1][2]);
  }
  const char* sets[] = {"S1=-3"};
  d = cs_defaultBendDef(); d.model = "fe";
  CS_EXPECT(cs_bendDefValidate(&d, &err) != CS_OK && strstr(err.msg, "'fe'"));
  d = cs_defaultBendDef(); d.p_step = 0;
  CS_EXPECT(cs_bendDefValidate(&d, &err) == CS_ERR_RANGE && strstr(err.msg, "--p-step"));
  d = cs_defaultBendDef(); d.p_max = INFINITY;
  CS_EXPECT(cs_bendDefValidate(&d, &err) == CS_ERR_RANGE && strstr(err.msg, "--p-max"));
  d = cs_defaultBendDef(); d.chambers = "0";
  CS_EXPECT(cs_bendDefValidate(&d, &err) != CS_OK && strstr(err.msg, "--chambers"));
  d = cs_defaultBendDef(); d.actuator_set = sets; d.n_actuator_set = 1;
  CS_EXPECT(cs_bendDefValidate(&d, &err) != CS_OK && strstr(err.msg, "S1"));
  d = cs_defaultBendDef(); d.n_actuator_set = 1; /* no strings */
  CS_EXPECT(cs_bendDefValidate(&d, &err) == CS_ERR_ARG && strstr(err.msg, "--set"));
  d = cs_defaultBendDef(); d.calibration = "analytic";
  CS_EXPECT(cs_bendDefValidate(&d, &err) == CS_ERR_ARG && strstr(err.msg, "--calibration"));
  d = cs_defaultBendDef(); d.model = "strain"; d.links = 2.5;
  CS_EXPECT(cs_bendDefValidate(&d, &err) == CS_ERR_RANGE && strstr(err.msg, "--links"));
  d = cs_defaultBendDef(); d.model = "rod"; d.links = 2;
  CS_EXPECT(cs_bendDefValidate(&d, &err) == CS_ERR_ARG && strstr(err.msg, "--links"));
  d = cs_defaultBendDef(); d.model = "strain"; d.mesh_size = 2;
  CS_EXPECT(cs_bendDefValidate(&d, &err) == CS_ERR_ARG && strstr(err.msg, "--mesh-size"));
  d = cs_defaultBendDef(); d.model = "rod"; d.calibration = "/nonexistent/cal.h5"; d.p_max = 0.3;
  CS_EXPECT(cs_bend(&d, 8, p, &ang[0][0], &tip[0][0], &n, &err) != CS_OK && n == 0 &&
            strstr(err.msg, "nonexistent"));
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_rundef_validation);
  CS_RUN(test_null_and_bad_files);
  CS_RUN(test_bend);
  CS_RUN(test_command_and_readouts);
  CS_RUN(test_run_without_file);
  CS_RUN(test_zero_command_stands);
  CS_RUN(test_controller_failure);
  CS_RUN(test_controller_replays_gait);
  return cs_testSummary();
}

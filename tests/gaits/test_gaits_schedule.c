/* test_gaits_schedule.c: p(t) from a gait table (gaits_schedule.h): exact plateaus, zero
 * before the first row, monotone ramps, continuity of value and slope at the ramp ends, the
 * ramp clamped to a short row spacing, the pressure scale, the shapes, steps (ramp 0), the
 * rate against finite differences, and argument errors. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "gaits_schedule.h"

/* half-width of the central differences (s): small against the 0.1-0.2 s ramps, large enough
 * that rounding (1e-16 MPa / 1e-6 s = 1e-10 MPa/s) stays far below the tolerances below */
#define FD_STEP 1e-6
/* rate tolerance (MPa/s): the central-difference error h^2/6 |p'''| with |p'''| <= 60 * 0.3 *
 * 1.3 / 0.1^3 = 23400 MPa/s^3 (quintic, steepest ramp, scale 1.3) is 4e-9, rounding of t +- h
 * adds ~1e-9 (ulp(1.6) / 2h * 10 MPa/s); 1e-7 leaves a wide margin */
#define RATE_TOL 1e-7
/* jump across a ramp end over +-FD_STEP for a C1 shape: p' = 0 there, so |dp| <= p''/2 h^2 =
 * 0.5 * 6*0.3/0.1^2 * 1e-12 = 9e-11 MPa; 1e-9 MPa is well above, and a C0 kink (slope up to
 * 4.5 MPa/s) would give 4.5e-6 */
#define END_JUMP_TOL 1e-9

/* labels used by the test table */
enum { L1 = 1, L2 = 2, L96 = 96 };

/* rows (s):     t = 0.5    1.5   1.6 (0.1 after: the ramp is clamped)   3.0
 * chamber 1:      0.2      0     0                                      0
 * chamber 2:      0        0.3   0.1                                    0
 * chamber 96:     0.25     0.25  0.25                                   0.25 */
static csgGait* makeGait(void) {
  static const double kT[] = {0.5, 1.5, 1.6, 3.0};
  static const double kP1[] = {0.2, 0.0, 0.0, 0.0};
  static const double kP2[] = {0.0, 0.3, 0.1, 0.0};
  csError err;
  csgGait* g = csg_gaitCreate(4, &err);
  for (int i = 0; g && i < 4; i++) {
    csg_gaitSetTime(g, i, kT[i], &err);
    csg_gaitSetPressure(g, i, L1, kP1[i], &err);
    csg_gaitSetPressure(g, i, L2, kP2[i], &err);
    csg_gaitSetPressure(g, i, L96, 0.25, &err);
  }
  CS_EXPECT(g && csg_gaitValidate(g, NULL, &err) == CS_OK);
  return g;
}


/* p(t) of one chamber (NAN on failure) */
static double pAt(const csgGait* g, const csgScheduleOptions* o, double t, int label) {
  double p[CSG_NLABEL];
  if (csg_scheduleEval(g, o, t, p) != CS_OK) {
    return NAN;
  }
  return p[label - 1];
}


static double rateAt(const csgGait* g, const csgScheduleOptions* o, double t, int label) {
  double r[CSG_NLABEL];
  if (csg_scheduleEvalRate(g, o, t, r) != CS_OK) {
    return NAN;
  }
  return r[label - 1];
}


static void test_defaults(void) {
  csgScheduleOptions o = csg_defaultScheduleOptions();
  CS_EXPECT(o.ramp == 0.2 && o.shape == CSG_RAMP_SMOOTHSTEP && o.pressure_scale == 1.0);
  csError err;
  CS_EXPECT(csg_scheduleCheckOptions(&o, &err) == CS_OK);
}


/* zero before t_0, exact values on every plateau, the last row held forever */
static void test_plateaus(void) {
  csgGait* g = makeGait();
  if (!g) {
    return;
  }
  csgScheduleOptions o = csg_defaultScheduleOptions();
  double p[CSG_NLABEL];
  CS_EXPECT(csg_scheduleEval(g, &o, 0.0, p) == CS_OK);
  int all_zero = 1;
  for (int l = 0; l < CSG_NLABEL; l++) {
    all_zero &= p[l] == 0.0;
  }
  CS_EXPECT(all_zero);
  CS_EXPECT(pAt(g, &o, 0.4999999, L96) == 0.0);
  CS_EXPECT(pAt(g, &o, 0.5, L1) == 0.0); /* the ramp starts at the row's time */

  /* row 0 plateau [0.7, 1.5): exact, since the blend is (1-s) a + s b with s = 1 */
  CS_EXPECT(pAt(g, NULL, 0.7, L1) == 0.2);
  CS_EXPECT(pAt(g, &o, 1.0, L1) == 0.2);
  CS_EXPECT(pAt(g, &o, 1.4999999, L1) == 0.2);
  CS_EXPECT(pAt(g, &o, 1.0, L2) == 0.0);
  CS_EXPECT(pAt(g, &o, 1.0, L96) == 0.25);
  /* a chamber that never changes stays exact through later ramps */
  CS_EXPECT(pAt(g, &o, 1.55, L96) == 0.25 && pAt(g, &o, 3.1, L96) == 0.25);
  /* row 2 plateau [1.8, 3.0) and the last row, held for ever */
  CS_EXPECT(pAt(g, &o, 1.8, L2) == 0.1);
  CS_EXPECT(pAt(g, &o, 2.9, L2) == 0.1);
  CS_EXPECT(pAt(g, &o, 3.2, L2) == 0.0);
  CS_EXPECT(pAt(g, &o, 1e6, L96) == 0.25);
  /* ramp midpoints: smoothstep(1/2) = 1/2 */
  CS_EXPECT_NEAR(pAt(g, &o, 0.6, L1), 0.1, 1e-15, 0); /* 1e-15: a few ulps of the blend */
  CS_EXPECT_NEAR(pAt(g, &o, 1.6 + 0.1, L2), 0.2, 1e-15, 0);
  csg_gaitDestroy(g);
}


/* each ramp moves monotonically from the old plateau to the new one */
static void test_monotoneRamp(void) {
  csgGait* g = makeGait();
  if (!g) {
    return;
  }
  csgScheduleOptions o = csg_defaultScheduleOptions();
  for (int shape = CSG_RAMP_SMOOTHSTEP; shape <= CSG_RAMP_LINEAR; shape++) {
    o.shape = (csgRampShape)shape;
    int up_ok = 1, down_ok = 1;
    double prev_up = pAt(g, &o, 0.5, L1), prev_down = pAt(g, &o, 1.5, L1);
    for (int k = 1; k <= 1000; k++) {
      double up = pAt(g, &o, 0.5 + 0.2 * k / 1000.0, L1);   /* 0 -> 0.2 on [0.5, 0.7] */
      double down = pAt(g, &o, 1.5 + 0.2 * k / 1000.0, L1); /* 0.2 -> 0 on [1.5, 1.6] */
      up_ok &= up >= prev_up && up >= 0.0 && up <= 0.2;
      down_ok &= down <= prev_down && down >= 0.0 && down <= 0.2;
      prev_up = up;
      prev_down = down;
    }
    CS_EXPECT(up_ok && down_ok);
    CS_EXPECT(prev_up == 0.2 && prev_down == 0.0);
  }
  csg_gaitDestroy(g);
}


/* value and slope are continuous at both ends of every ramp (smooth shapes) */
static void test_continuityAtRampEnds(void) {
  csgGait* g = makeGait();
  if (!g) {
    return;
  }
  /* ramp ends: row starts, plateau starts (ramp 0.2 or clamped 0.1), and the clamped end at
   * 1.6 where the next ramp starts at once */
  static const double kEnds[] = {0.5, 0.7, 1.5, 1.6, 1.8, 3.0, 3.2};
  static const int kLabels[] = {L1, L2, L96};
  for (int shape = CSG_RAMP_SMOOTHSTEP; shape <= CSG_RAMP_QUINTIC; shape++) {
    csgScheduleOptions o = csg_defaultScheduleOptions();
    o.shape = (csgRampShape)shape;
    for (size_t e = 0; e < sizeof kEnds / sizeof kEnds[0]; e++) {
      for (size_t k = 0; k < sizeof kLabels / sizeof kLabels[0]; k++) {
        double t = kEnds[e];
        int l = kLabels[k];
        double below = pAt(g, &o, t - FD_STEP, l), at = pAt(g, &o, t, l);
        double above = pAt(g, &o, t + FD_STEP, l);
        CS_EXPECT_NEAR(below, at, END_JUMP_TOL, 0);
        CS_EXPECT_NEAR(above, at, END_JUMP_TOL, 0);
        /* slope: zero at every ramp end, from both sides */
        CS_EXPECT_NEAR(rateAt(g, &o, t - FD_STEP, l), 0.0, 1e-3, 0); /* 6 h/r^2 * dP <= 2e-4 */
        CS_EXPECT_NEAR(rateAt(g, &o, t + FD_STEP, l), 0.0, 1e-3, 0);
        CS_EXPECT_NEAR(rateAt(g, &o, t, l), 0.0, 1e-12, 0);
      }
    }
  }
  /* the linear shape, by contrast, kinks: its slope jumps at a ramp start */
  csgScheduleOptions lin = csg_defaultScheduleOptions();
  lin.shape = CSG_RAMP_LINEAR;
  CS_EXPECT_NEAR(rateAt(g, &lin, 0.5 + FD_STEP, L1), 1.0, 1e-12, 1e-12); /* 0.2 MPa / 0.2 s */
  CS_EXPECT(rateAt(g, &lin, 0.5 - FD_STEP, L1) == 0.0);
  csg_gaitDestroy(g);
}


/* the analytic rate matches central differences of p inside the ramps */
static void test_rateMatchesDifferences(void) {
  csgGait* g = makeGait();
  if (!g) {
    return;
  }
  static const double kT[] = {0.55, 0.6, 0.66, 1.52, 1.55, 1.59, 1.65, 1.75};
  for (int shape = CSG_RAMP_SMOOTHSTEP; shape <= CSG_RAMP_QUINTIC; shape++) {
    csgScheduleOptions o = csg_defaultScheduleOptions();
    o.shape = (csgRampShape)shape;
    o.pressure_scale = 1.3;
    for (size_t i = 0; i < sizeof kT / sizeof kT[0]; i++) {
      for (int l = L1; l <= L2; l++) {
        double fd =
            (pAt(g, &o, kT[i] + FD_STEP, l) - pAt(g, &o, kT[i] - FD_STEP, l)) / (2.0 * FD_STEP);
        CS_EXPECT_NEAR(rateAt(g, &o, kT[i], l), fd, RATE_TOL, 0);
      }
    }
  }
  csg_gaitDestroy(g);
}


/* a ramp longer than the row spacing is clamped to it and ends exactly at the next row */
static void test_clampedRamp(void) {
  csgGait* g = makeGait();
  if (!g) {
    return;
  }
  csgScheduleOptions o = csg_defaultScheduleOptions();
  /* row 1 at 1.5, row 2 at 1.6: chamber 2 goes 0 -> 0.3 over [1.5, 1.6], not [1.5, 1.7] */
  CS_EXPECT_NEAR(pAt(g, &o, 1.55, L2), 0.15, 1e-15, 0); /* midpoint of the clamped ramp */
  CS_EXPECT_NEAR(pAt(g, &o, 1.6 - 1e-9, L2), 0.3, 1e-12, 0);
  CS_EXPECT(pAt(g, &o, 1.6, L2) == 0.3); /* the next ramp starts from the full plateau */
  /* and chamber 1 reaches 0 by 1.6 */
  CS_EXPECT(pAt(g, &o, 1.6, L1) == 0.0);
  /* a ramp longer than every spacing: the last row still ramps over the full length */
  o.ramp = 10.0;
  CS_EXPECT_NEAR(pAt(g, &o, 1.0, L1), 0.1, 1e-15, 0);  /* clamped to 1 s, midpoint */
  CS_EXPECT_NEAR(pAt(g, &o, 8.0, L2), 0.05, 1e-15, 0); /* last row: 0.1 -> 0 over 10 s */
  csg_gaitDestroy(g);
}


static void test_scaleAndSteps(void) {
  csgGait* g = makeGait();
  if (!g) {
    return;
  }
  csgScheduleOptions o = csg_defaultScheduleOptions();
  o.pressure_scale = 1.5;
  CS_EXPECT(pAt(g, &o, 1.0, L1) == 1.5 * 0.2);
  CS_EXPECT(pAt(g, &o, 2.0, L2) == 1.5 * 0.1);
  CS_EXPECT_NEAR(pAt(g, &o, 0.6, L1), 1.5 * 0.1, 1e-15, 0);
  CS_EXPECT_NEAR(rateAt(g, &o, 0.6, L1), 1.5 * 0.2 * 1.5 / 0.2, 1e-12, 1e-12); /* S'(1/2)=1.5 */
  o.pressure_scale = 0.0;
  CS_EXPECT(pAt(g, &o, 1.0, L1) == 0.0);

  /* ramp 0: the bare step table, new value from the row's time on */
  o = csg_defaultScheduleOptions();
  o.ramp = 0.0;
  CS_EXPECT(pAt(g, &o, 0.5, L1) == 0.2);
  CS_EXPECT(pAt(g, &o, 0.4999999, L1) == 0.0);
  CS_EXPECT(pAt(g, &o, 1.5, L2) == 0.3 && pAt(g, &o, 1.5999999, L2) == 0.3);
  CS_EXPECT(pAt(g, &o, 1.6, L2) == 0.1);
  CS_EXPECT(rateAt(g, &o, 0.5, L1) == 0.0);

  /* quintic value at u = 1/4: 10/64 - 15/256 + 6/1024 */
  o = csg_defaultScheduleOptions();
  o.shape = CSG_RAMP_QUINTIC;
  CS_EXPECT_NEAR(pAt(g, &o, 0.55, L1), 0.2 * 0.103515625, 1e-15, 0);
  o.shape = CSG_RAMP_SMOOTHSTEP; /* smoothstep at u = 1/4: 3/16 - 2/64 = 0.15625 */
  CS_EXPECT_NEAR(pAt(g, &o, 0.55, L1), 0.2 * 0.15625, 1e-15, 0);
  csg_gaitDestroy(g);
}


static void test_badArguments(void) {
  csgGait* g = makeGait();
  if (!g) {
    return;
  }
  csError err;
  double p[CSG_NLABEL];
  p[0] = -7.0;
  csgScheduleOptions o = csg_defaultScheduleOptions();
  CS_EXPECT(csg_scheduleEval(NULL, &o, 1.0, p) == CS_ERR_ARG);
  CS_EXPECT(csg_scheduleEval(g, &o, NAN, p) == CS_ERR_ARG);
  CS_EXPECT(csg_scheduleEval(g, &o, 1.0, NULL) == CS_ERR_ARG);
  CS_EXPECT(csg_scheduleEvalRate(g, &o, INFINITY, p) == CS_ERR_ARG);
  o.ramp = -0.1;
  CS_EXPECT(csg_scheduleEval(g, &o, 1.0, p) == CS_ERR_ARG);
  CS_EXPECT(csg_scheduleCheckOptions(&o, &err) == CS_ERR_ARG && strstr(err.msg, "ramp"));
  o = csg_defaultScheduleOptions();
  o.pressure_scale = NAN;
  CS_EXPECT(csg_scheduleCheckOptions(&o, &err) == CS_ERR_ARG && strstr(err.msg, "scale"));
  CS_EXPECT(csg_scheduleEval(g, &o, 1.0, p) == CS_ERR_ARG);
  o = csg_defaultScheduleOptions();
  o.shape = (csgRampShape)7;
  CS_EXPECT(csg_scheduleCheckOptions(&o, &err) == CS_ERR_ARG && strstr(err.msg, "shape"));
  CS_EXPECT(csg_scheduleEval(g, &o, 1.0, p) == CS_ERR_ARG);
  CS_EXPECT(p[0] == -7.0); /* untouched on failure */
  csgGait* empty = csg_gaitCreate(0, &err);
  CS_EXPECT(csg_scheduleEval(empty, NULL, 1.0, p) == CS_ERR_ARG);
  csg_gaitDestroy(empty);
  csg_gaitDestroy(g);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_defaults);
  CS_RUN(test_plateaus);
  CS_RUN(test_monotoneRamp);
  CS_RUN(test_continuityAtRampEnds);
  CS_RUN(test_rateMatchesDifferences);
  CS_RUN(test_clampedRamp);
  CS_RUN(test_scaleAndSteps);
  CS_RUN(test_badArguments);
  return cs_testSummary();
}

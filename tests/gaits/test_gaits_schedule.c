/* test_gaits_schedule.c: p(t) from a gait table (gaits_schedule.h): exact plateaus, zero
 * before the first row, monotone ramps, continuity of value and slope at the ramp ends,
 * ramps longer than the row spacing (overlapping changes in closed form: a reversal mid-ramp,
 * a step under a ramp longer than dense repeated rows, the commands' range kept), spacings
 * equal to the ramp up to rounding, the pressure scale, the shapes, steps (ramp 0), the rate
 * against finite differences, and argument errors. */
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

/* rows (s):     t = 0.5    1.5   1.6 (0.1 after: the 0.2 s ramps overlap)   3.0
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
  /* ramp ends where no other ramp runs: row starts, plateau starts (1.8: the overlapping
   * changes of 1.5 and 1.6 both done) */
  static const double kEnds[] = {0.5, 0.7, 1.5, 1.8, 3.0, 3.2};
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
  /* inside the overlap (1.6: row 2 starts while row 1 runs; 1.7: row 1 ends while row 2
   * runs) value and slope stay continuous, the slope not zero */
  for (int shape = CSG_RAMP_SMOOTHSTEP; shape <= CSG_RAMP_QUINTIC; shape++) {
    csgScheduleOptions o = csg_defaultScheduleOptions();
    o.shape = (csgRampShape)shape;
    static const double kInner[] = {1.6, 1.7};
    for (int e = 0; e < 2; e++) {
      double t = kInner[e];
      CS_EXPECT_NEAR(pAt(g, &o, t - FD_STEP, L2), pAt(g, &o, t, L2), 1e-5, 0); /* |p'| h */
      CS_EXPECT_NEAR(pAt(g, &o, t + FD_STEP, L2), pAt(g, &o, t, L2), 1e-5, 0);
      CS_EXPECT_NEAR(rateAt(g, &o, t - FD_STEP, L2), rateAt(g, &o, t, L2), 1e-3, 0);
      CS_EXPECT_NEAR(rateAt(g, &o, t + FD_STEP, L2), rateAt(g, &o, t, L2), 1e-3, 0);
      CS_EXPECT(fabs(rateAt(g, &o, t, L2)) > 0.1);
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


/* smoothstep, for closed forms */
static double smooth(double u) { return u <= 0 ? 0 : u >= 1 ? 1 : u * u * (3 - 2 * u); }


/* a ramp longer than the row spacing: each row's change still takes the full ramp and the
 * changes add (a reversal mid-ramp), in closed form */
static void test_overlappingRamps(void) {
  csgGait* g = makeGait();
  if (!g) {
    return;
  }
  csgScheduleOptions o = csg_defaultScheduleOptions();
  /* chamber 2: 0 -> 0.3 from 1.5, reversed to 0.1 at 1.6 while still rising:
   * p = 0.3 S((t - 1.5)/0.2) - 0.2 S((t - 1.6)/0.2); it peaks inside the overlap, below 0.3 */
  static const double kT[] = {1.55, 1.6, 1.63, 1.65, 1.7, 1.75, 1.8, 2.0};
  double peak = 0.0;
  for (size_t i = 0; i < sizeof kT / sizeof kT[0]; i++) {
    double t = kT[i];
    double want = 0.3 * smooth((t - 1.5) / 0.2) - 0.2 * smooth((t - 1.6) / 0.2);
    CS_EXPECT_NEAR(pAt(g, &o, t, L2), want, 1e-15, 0);
    /* the rate is the derivative of the same sum: 6u(1-u)/r per change */
    double u1 = (t - 1.5) / 0.2, u2 = (t - 1.6) / 0.2;
    double rate = (u1 >= 0 && u1 < 1 ? 0.3 * 6 * u1 * (1 - u1) / 0.2 : 0) -
                  (u2 >= 0 && u2 < 1 ? 0.2 * 6 * u2 * (1 - u2) / 0.2 : 0);
    CS_EXPECT_NEAR(rateAt(g, &o, t, L2), rate, 1e-12, 0);
    peak = fmax(peak, pAt(g, &o, t, L2));
  }
  CS_EXPECT(peak > 0.16 && peak < 0.3); /* the reversal caught the rise mid-way */
  CS_EXPECT(pAt(g, &o, 1.8, L2) == 0.1); /* both done: the plateau exactly */
  /* chamber 1: 0.2 -> 0 from 1.5 takes the full 0.2 s though row 2 comes at 1.6 */
  CS_EXPECT_NEAR(pAt(g, &o, 1.6, L1), 0.1, 1e-15, 0);
  CS_EXPECT(pAt(g, &o, 1.7, L1) == 0.0);
  /* a ramp longer than every spacing: each change spreads over 10 s */
  o.ramp = 10.0;
  CS_EXPECT_NEAR(pAt(g, &o, 1.0, L1), 0.2 * smooth(0.05), 1e-15, 0);
  CS_EXPECT_NEAR(pAt(g, &o, 8.0, L2),
                 0.3 * smooth(0.65) - 0.2 * smooth(0.64) - 0.1 * smooth(0.5), 1e-15, 0);
  CS_EXPECT(pAt(g, &o, 13.0, L2) == 0.0 && pAt(g, &o, 13.0, L96) == 0.25);
  csg_gaitDestroy(g);
}


/* a step command in a table that repeats it every 0.05 s, played with a 0.5 s ramp: the
 * repeated rows add nothing, so the chamber follows one 0.5 s ramp, p = P S((t - 1)/0.5), and
 * arrives exactly; every value stays within the commands' range [0, P] */
static void test_stepUnderLongRamp(void) {
  csError err;
  const int n = 60; /* rows 0, 0.05, ..., 2.95 s; the step at row 20 (1 s) */
  csgGait* g = csg_gaitCreate(n, &err);
  CS_EXPECT(g != NULL);
  if (!g) {
    return;
  }
  for (int i = 0; i < n; i++) {
    csg_gaitSetTime(g, i, 0.05 * i, &err);
    csg_gaitSetPressure(g, i, L1, i >= 20 ? 0.25 : 0.0, &err);
    /* chamber 2: a fast square wave, 0.05 s up, 0.05 s down, from 0.5 s */
    csg_gaitSetPressure(g, i, L2, i >= 10 && i % 2 ? 0.3 : 0.0, &err);
  }
  CS_EXPECT(csg_gaitValidate(g, NULL, &err) == CS_OK);
  csgScheduleOptions o = csg_defaultScheduleOptions();
  o.ramp = 0.5;
  int in_range = 1;
  for (int k = 0; k <= 3000; k++) {
    double t = 0.001 * k;
    double want = 0.25 * smooth((t - 1.0) / 0.5);
    CS_EXPECT_NEAR(pAt(g, &o, t, L1), want, 1e-15, 0);
    double p2 = pAt(g, &o, t, L2);
    in_range &= p2 >= -1e-15 && p2 <= 0.3 + 1e-15;
  }
  CS_EXPECT(in_range);
  /* the square wave's mean (0.15 MPa) comes through and its ripple is smoothed: the kernel
   * 6u(1-u)/T (T = 0.5 s) passes a 10 Hz wave (fT = 5) by 12/(2 pi fT)^2 = 0.0122, so the
   * fundamental (4/pi) 0.15 MPa leaves 0.0023 MPa (harmonics 1e-4): 3e-3 bounds it */
  for (int k = 0; k < 10; k++) {
    CS_EXPECT_NEAR(pAt(g, &o, 2.0 + 0.01 * k, L2), 0.15, 3e-3, 0);
  }
  CS_EXPECT(pAt(g, &o, 1.5, L1) == 0.25 && pAt(g, &o, 2.2, L1) == 0.25);
  CS_EXPECT(pAt(g, &o, 1.0, L1) == 0.0);
  CS_EXPECT_NEAR(rateAt(g, &o, 1.25, L1), 0.25 * 1.5 / 0.5, 1e-12, 0); /* S'(1/2) = 1.5 */
  /* the old rule (each change cut to the 0.05 s rows) would have arrived by 1.05 s */
  CS_EXPECT(pAt(g, &o, 1.05, L1) < 0.01);
  csg_gaitDestroy(g);
}


/* a spacing equal to the ramp up to rounding counts as the spacing (either way), so the
 * change fills the interval and the next one starts from the exact plateau */
static void test_roundingSpacing(void) {
  csError err;
  csgGait* g = csg_gaitCreate(4, &err);
  CS_EXPECT(g != NULL);
  if (!g) {
    return;
  }
  /* spacings 0.3 - 0.2 = 0.09999999999999998 (below 0.1) and 0.7 - 0.6 = 0.09999999999999998,
   * 0.6 - 0.3 = 0.3 (fits) */
  static const double kT[] = {0.2, 0.3, 0.6, 0.7};
  static const double kP[] = {0.1, 0.3, 0.05, 0.2};
  for (int i = 0; i < 4; i++) {
    csg_gaitSetTime(g, i, kT[i], &err);
    csg_gaitSetPressure(g, i, L1, kP[i], &err);
  }
  csgScheduleOptions o = csg_defaultScheduleOptions();
  o.ramp = 0.1;
  CS_EXPECT(pAt(g, &o, 0.3, L1) == 0.1);   /* row 0's change done exactly at row 1 */
  CS_EXPECT(pAt(g, &o, 0.7, L1) == 0.05);  /* row 2's change: 0.1 s, done by row 3 */
  CS_EXPECT(pAt(g, &o, 0.45, L1) == 0.3);
  /* inside: the ramp is the spacing, 0.25 of the way at a quarter of it */
  double gap = 0.3 - 0.2;
  CS_EXPECT_NEAR(pAt(g, &o, 0.2 + 0.25 * gap, L1), smooth(0.25) * 0.1, 1e-16, 0);
  /* a ramp 1e-12 s longer than the spacing is the same ramp */
  o.ramp = 0.1 + 1e-12;
  CS_EXPECT(pAt(g, &o, 0.3, L1) == 0.1);
  CS_EXPECT_NEAR(pAt(g, &o, 0.25, L1), 0.05, 1e-16, 0);
  /* within rounding either way, the same pressures as the spacing itself, bit for bit */
  csgScheduleOptions lo = o, hi = o, eq = o;
  lo.ramp = gap - 1e-12;
  hi.ramp = gap + 1e-12;
  eq.ramp = gap;
  int same = 1;
  for (int k = 0; k <= 100; k++) {
    double t = 0.2 + gap * k / 100.0;
    double p = pAt(g, &eq, t, L1);
    same &= pAt(g, &lo, t, L1) == p && pAt(g, &hi, t, L1) == p;
    same &= rateAt(g, &lo, t, L1) == rateAt(g, &eq, t, L1);
  }
  CS_EXPECT(same);
  /* but 1e-6 s longer overlaps, as it should: at row 1's time row 0 is not quite done */
  o.ramp = 0.1 + 1e-6;
  CS_EXPECT(pAt(g, &o, 0.3, L1) < 0.1 && pAt(g, &o, 0.3, L1) > 0.1 - 1e-9);
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
  CS_RUN(test_overlappingRamps);
  CS_RUN(test_stepUnderLongRamp);
  CS_RUN(test_roundingSpacing);
  CS_RUN(test_scaleAndSteps);
  CS_RUN(test_badArguments);
  return cs_testSummary();
}

/* test_strain_adaptive.c: the error-controlled tree step (core/sim_adaptive.c,
 * `--strain-step adaptive`):
 *  - its estimate and controller on a closed form: backward Euler on a free harmonic
 *    oscillator (one leg mode's vibration, x'' = -ω² x) stepped by the controller's own parts
 *    (cs_adaptiveErrorNorm, cs_adaptiveFactor, the driver's accept/reject rule): the estimate
 *    of one step from the exact state is the true local error to within 10 % at small steps,
 *    and over 1 s the error against cos(ω t) falls with the tolerance at its order (local
 *    error ~ tol per step, steps ~ tol^-1/2, so the global error ~ tol^1/2: the measured
 *    slope within 0.35-0.65 per decade) while the steps grow as tol^-1/2;
 *  - the same for BDF2 (step_order 2; cs_adaptiveErrorNorm2, cs_adaptiveFactor2) with the
 *    variable-step formula the legs take (csr_strainBdf2Coeffs): the estimate of one step
 *    from exact history within 10 % of the true local error at small steps, at a constant step
 *    and at step ratios 1.5 and 0.6 (the error constant's ratio dependence), and the global
 *    error's slope ~ 2/3 per decade (local ~ tol, steps ~ tol^-1/3: within 0.5-0.85) with the
 *    steps' slope ~ 1/3 (within 0.2-0.45);
 *  - through the driver on the flat road (strain legs, tree coupling): every macro step ends
 *    on its own time exactly (the output's grid), the run takes fewer steps than its shortest
 *    step would, rejects some by the error and two datas stepped alike are bit-identical, and
 *    a run continued from a restored state (cs_stateGet / cs_stateSet, with the controller's
 *    memory) equals the uninterrupted one bit for bit;
 *  - a step the legs reject at every size fails with CS_ERR_REJECTED and leaves the state as
 *    it was at the macro step's start (the rollback), as with a fixed step, also when it
 *    fails after an accepted step within the macro step.
 * The checkpoint/resume of an adaptive run is test_checkpoint's. ~0.3 s settling and 0.3 s of
 * gait per data at 5 ms macro steps: a few seconds in release. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "strain_flat_fixture.h"
#include "robot_strain.h"  /* csr_strainBdf2Coeffs: the legs' variable-step BDF2 */
#include "sim_internal.h" /* the controller's parts and counts */
#include "sim_model.h"

static char g_src[512];


/* ---- the closed form -------------------------------------------------------------------- */

/* one backward-Euler step of x' = v, v' = -w² x (the same update as the tree step's: the
 * velocity implicit, x1 = x0 + h v1) */
static void beStep(double w, double h, const double y0[2], double y1[2]) {
  const double a = w * w * h * h;
  y1[1] = (y0[1] - h * w * w * y0[0]) / (1 + a);
  y1[0] = y0[0] + h * y1[1];
}


/* one variable-step BDF2 step of the same oscillator (the legs' formula, csr_strainBdf2Coeffs
 * with coefficients c: x1 = c0 x0 + c1 x_-1 + he v1, v1 = c0 v0 + c1 v_-1 - he w² x1, he =
 * c2 h) from y0 after ym (the state one step before) */
static void bdfStep(double w, const double c[3], double h, const double ym[2],
                    const double y0[2], double y1[2]) {
  const double he = c[2] * h;
  const double X = c[0] * y0[0] + c[1] * ym[0], V = c[0] * y0[1] + c[1] * ym[1];
  y1[1] = (V - he * w * w * X) / (1 + he * he * w * w);
  y1[0] = X + he * y1[1];
}


/* the controller's run over [0, T] on x(0) = 1 mm, v(0) = 0 (the driver's loop, sim_adaptive.c
 * cs_adaptiveStep, with h_max the macro step), backward Euler (order 1) or BDF2 (order 2; its
 * first step backward Euler, its second tested by backward Euler's estimate, as the driver's):
 * returns the error in the phase plane |(x - cos(w T), (v + w sin(w T)) / w)|
 * (mm); *steps the accepted steps */
static double oscillatorRun(int order, double w, double T, double H, double tol, long* steps) {
  const double tv = 0.01; /* velocities' tolerance: tol per 10 ms, as the driver's */
  const double tols[2] = {tol, tol / tv};
  double y[2] = {1, 0}, ym[2] = {1, 0}, dy_prev[2] = {0, 0}, dy_prev2[2] = {0, 0};
  double t = 0, h_prop = order == 2 ? H / 64 : H / 8, h_prev = 0, h_prev2 = 0;
  const double h_min = H / 64;
  *steps = 0;
  while (t < T * (1 - 1e-12)) {
    const double t1 = fmin(T, (floor(t / H + 1e-9) + 1) * H);
    const double rest = t1 - t, n = ceil(rest / h_prop * (1 - 1e-9));
    const double h = n <= 1 ? rest : rest / n;
    double y1[2], dy[2], c[3];
    csr_strainBdf2Coeffs(h, order == 2 ? h_prev : 0, c);
    bdfStep(w, c, h, ym, y, y1);
    dy[0] = y1[0] - y[0];
    dy[1] = y1[1] - y[1];
    const int second = c[1] != 0 && h_prev2 > 0;
    const double E = second ? cs_adaptiveErrorNorm2(2, dy, dy_prev, dy_prev2, tols, h, h_prev,
                                                    h_prev2, (1 - c[2]) / (2 * c[2] - 1))
                     : h_prev > 0 ? cs_adaptiveErrorNorm(2, dy, dy_prev, tols, h / h_prev)
                                  : 0;
    const double f = second ? cs_adaptiveFactor2(E) : cs_adaptiveFactor(E);
    if (h_prev > 0 && E > 1 && h > h_min * (1 + 1e-9)) {
      h_prop = fmax(h_min, h * f);
      continue;
    }
    ym[0] = y[0], ym[1] = y[1];
    y[0] = y1[0], y[1] = y1[1];
    dy_prev2[0] = dy_prev[0], dy_prev2[1] = dy_prev[1];
    dy_prev[0] = dy[0], dy_prev[1] = dy[1];
    t = n <= 1 ? t1 : t + h;
    h_prop = h_prev > 0 ? fmin(H, fmax(h_min, h * f)) : h;
    h_prev2 = h_prev;
    h_prev = h;
    (*steps)++;
  }
  /* the error in the phase plane (mm): |x(1 s) - cos| alone sees the amplitude's error only,
   * since w T is a whole number of half turns, and BDF2's amplitude error is a higher order
   * (its damping per step ~ (w h)⁴) than its phase error */
  return hypot(y[0] - cos(w * T), (y[1] + w * sin(w * T)) / w);
}


/* the global error and the steps against the tolerance over three decades: their slopes per
 * decade within [lo_e, hi_e] and [lo_n, hi_n] */
static void expectSlopes(int order, double w, const double tol[3], double lo_e, double hi_e,
                         double lo_n, double hi_n) {
  double e[3];
  long n[3];
  for (int k = 0; k < 3; k++) {
    e[k] = oscillatorRun(order, w, 1.0, 5e-3, tol[k], &n[k]);
    printf("  order %d, tol %g mm: error at 1 s %.4g mm in %ld steps\n", order, tol[k], e[k],
           n[k]);
  }
  for (int k = 0; k < 2; k++) {
    const double se = log10(e[k] / e[k + 1]), sn = log10((double)n[k + 1] / n[k]);
    printf("  per decade of tol: error slope %.3f, steps slope %.3f\n", se, sn);
    CS_EXPECT(se > lo_e && se < hi_e);
    CS_EXPECT(sn > lo_n && sn < hi_n);
  }
}


static void test_adaptive_estimate_and_order_on_an_oscillator(void) {
  const double w = 2 * 3.14159265358979 * 5; /* 5 Hz, 1 mm */
  /* the estimate of one step from the exact state at t against its true error, after an
   * exact previous step of the same h (the estimate's history) */
  for (double h = 1e-3; h >= 1.24e-4; h *= 0.5) {
    const double t0 = 0.0123;
    double yp[2] = {cos(w * (t0 - h)), -w * sin(w * (t0 - h))};
    double y0[2] = {cos(w * t0), -w * sin(w * t0)}, y1[2];
    beStep(w, h, y0, y1);
    /* the previous step's change as backward Euler made it from the exact state there */
    double yq[2];
    beStep(w, h, yp, yq);
    const double dy_prev[2] = {yq[0] - yp[0], yq[1] - yp[1]};
    const double dy[2] = {y1[0] - y0[0], y1[1] - y0[1]};
    const double ones[2] = {1, 1};
    const double est = cs_adaptiveErrorNorm(1, dy, dy_prev, ones, 1.0); /* x alone */
    const double truth = fabs(y1[0] - cos(w * (t0 + h)));
    printf("  h %.3g ms: estimate %.4g mm, true local error %.4g mm (ratio %.3f)\n", h * 1e3,
           est, truth, est / truth);
    if (h < 2.6e-4) {
      CS_EXPECT(fabs(est / truth - 1) < 0.1);
    }
  }
  /* the global error and the steps against the tolerance: three decades */
  const double tol[3] = {1e-3, 1e-4, 1e-5};
  expectSlopes(1, w, tol, 0.35, 0.65, 0.35, 0.65);
}


static void test_adaptive_bdf2_estimate_and_order_on_an_oscillator(void) {
  const double w = 2 * 3.14159265358979 * 5; /* 5 Hz, 1 mm */
  /* one BDF2 step from exact history (x at t0 - h1 - h2, t0 - h1, t0) against its true local
   * error, at three ratios h / h1 (h1 = h2) */
  const double ratio[3] = {1.0, 1.5, 0.6};
  for (int r = 0; r < 3; r++) {
    for (double h = 1e-3; h >= 1.24e-4; h *= 0.5) {
      const double t0 = 0.0123, h1 = h / ratio[r], h2 = h1;
      double ex[4][2]; /* exact at t0 - h1 - h2, t0 - h1, t0, t0 + h */
      const double ts[4] = {t0 - h1 - h2, t0 - h1, t0, t0 + h};
      for (int i = 0; i < 4; i++) {
        ex[i][0] = cos(w * ts[i]);
        ex[i][1] = -w * sin(w * ts[i]);
      }
      double c[3], y1[2];
      csr_strainBdf2Coeffs(h, h1, c);
      bdfStep(w, c, h, ex[1], ex[2], y1);
      const double dy[1] = {y1[0] - ex[2][0]}, dy1[1] = {ex[2][0] - ex[1][0]};
      const double dy2[1] = {ex[1][0] - ex[0][0]}, one[1] = {1};
      const double est = cs_adaptiveErrorNorm2(1, dy, dy1, dy2, one, h, h1, h2,
                                               (1 - c[2]) / (2 * c[2] - 1));
      const double truth = fabs(y1[0] - ex[3][0]);
      printf("  ratio %.1f, h %.3g ms: estimate %.4g mm, true local error %.4g mm (ratio %.3f)"
             "\n", ratio[r], h * 1e3, est, truth, est / truth);
      if (h < 2.6e-4) {
        CS_EXPECT(fabs(est / truth - 1) < 0.1);
      }
    }
  }
  /* the global error and the steps against the tolerance: three decades (2/3 and 1/3), a
   * decade tighter than backward Euler's (at 1e-3 mm BDF2's steps are the macro step's 5 ms) */
  const double tol[3] = {1e-4, 1e-5, 1e-6};
  expectSlopes(2, w, tol, 0.5, 0.85, 0.2, 0.45);
}


/* ---- through the driver ----------------------------------------------------------------- */

/* the rejecting double: with g_reject_all, prepare refuses every step after g_allow more calls
 * (each try prepares the eight legs once) */
static int g_reject_all;
static long g_allow;
static int prepareRejecting(csrLeg* leg, double h, const csrBaseState* b0, double Z[36],
                            double rho[6]) {
  if (g_reject_all && g_allow-- <= 0) {
    return 1;
  }
  return csr_leg_strain.prepare(leg, h, b0, Z, rho);
}


/* the flat road as the scene sets it up, on strain legs of `type`, adaptive at 5 ms, the tree
 * step's formula `order` (0: the level's) */
static int loadModel(csModel* m, const csrLegType* type, double tol, int order) {
  return csTestLoadFlatStrainOrder(m, g_src, type, 5e-3, 2, 1, tol, order);
}




/* n macro steps; each must end at t + H exactly (the output's grid) */
static int stepN(const csModel* m, csData* d, int n) {
  csError err;
  const double H = cs_modelMacroStep(m);
  for (int i = 0; i < n; i++) {
    const double t1 = cs_time(d) + H;
    if (cs_step(m, d, &err) != CS_OK) {
      printf("  step at t = %g s: %s\n", cs_time(d), err.msg);
      return 0;
    }
    if (cs_time(d) != t1) {
      printf("  macro step ended at %.17g s, not %.17g\n", cs_time(d), t1);
      return 0;
    }
  }
  return 1;
}


static int sameState(const csModel* m, const csData* a, const csData* b) {
  int n = cs_stateSize(m, a);
  double* x = malloc(2 * (size_t)n * sizeof(double));
  if (!x) {
    return 0;
  }
  cs_stateGet(m, a, x);
  cs_stateGet(m, b, x + n);
  int same = memcmp(x, x + n, (size_t)n * sizeof(double)) == 0;
  free(x);
  return same;
}


static void repeatsRestoresGrid(int order) {
  csModel m;
  CS_EXPECT(loadModel(&m, &csr_leg_strain, 0.01, order));
  csData* a = csTestSettledData(&m);
  csData* b = csTestSettledData(&m);
  const int n = a ? cs_stateSize(&m, a) : 0;
  double* x = n ? malloc(3 * (size_t)n * sizeof(double)) : NULL;
  if (!a || !b || !x) {
    CS_EXPECT(0);
    free(x);
    cs_dataDestroy(a);
    cs_dataDestroy(b);
    cs_modelDestroy(&m);
    return;
  }
  CS_EXPECT(stepN(&m, a, 40) && stepN(&m, b, 40)); /* 0.2 s: the gait's first ramp */
  const int same = sameState(&m, a, b);
  CS_EXPECT(same);
  /* restored: the reference is itself restored (CVODE restarted), then both step 20 */
  csError err;
  cs_stateGet(&m, a, x);
  CS_EXPECT(cs_stateSet(&m, a, x, &err) == CS_OK);
  CS_EXPECT(stepN(&m, a, 20));
  cs_stateGet(&m, a, x + n);
  CS_EXPECT(cs_stateSet(&m, a, x, &err) == CS_OK);
  CS_EXPECT(stepN(&m, a, 20));
  cs_stateGet(&m, a, x + 2 * n);
  const int restored = memcmp(x + n, x + 2 * n, (size_t)n * sizeof(double)) == 0;
  CS_EXPECT(restored);
  csAdaptiveStats s;
  cs_adaptiveStats(a, &s);
  /* the steps the run took against the 5 ms grid's and the shortest step's count */
  const long grid = cs_stepCount(a), at_min = lround(cs_stepCount(a) * 5e-3 / s.h_min);
  printf("  order %d: %ld macro steps of 5 ms: %ld accepted steps (%ld rejected by the error), "
         "h %.3g / %.3g / %.3g ms; two datas %s, restored %s\n", order, grid, s.accepted,
         s.rejected,
         s.h_min * 1e3, s.h_median * 1e3, s.h_max * 1e3, same ? "bit-identical" : "DIFFER",
         restored ? "bit-identical" : "DIFFERS");
  CS_EXPECT(s.accepted >= grid);
  CS_EXPECT(s.h_min < s.h_max);
  CS_EXPECT(s.accepted < at_min);
  CS_EXPECT(s.rejected > 0);
  free(x);
  cs_dataDestroy(a);
  cs_dataDestroy(b);
  cs_modelDestroy(&m);
}


static void test_adaptive_repeats_restores_and_keeps_the_grid(void) { repeatsRestoresGrid(1); }


/* the same under BDF2 (its controller memory holds two steps: CS_ADA_STATE2) */
static void test_adaptive_bdf2_repeats_restores_and_keeps_the_grid(void) {
  repeatsRestoresGrid(2);
}


static void test_adaptive_rejected_everywhere_changes_nothing(void) {
  csrLegType rej = csr_leg_strain;
  rej.prepare = prepareRejecting;
  csModel m;
  CS_EXPECT(loadModel(&m, &rej, 0.01, 0));
  g_reject_all = 0;
  csData* d = csTestSettledData(&m);
  const int n = d ? cs_stateSize(&m, d) : 0;
  double* x = n ? malloc(2 * (size_t)n * sizeof(double)) : NULL;
  if (!d || !x) {
    CS_EXPECT(0);
    free(x);
    cs_dataDestroy(d);
    cs_modelDestroy(&m);
    return;
  }
  CS_EXPECT(stepN(&m, d, 10));
  /* from the macro step's start (allow 0) and from its second step on (allow 8: the first of
   * four steps, the proposal set to H / 4, is accepted) */
  for (int k = 0; k < 2; k++) {
    d->ada.h_prop = 0.25 * cs_modelMacroStep(&m);
    cs_stateGet(&m, d, x);
    g_reject_all = 1;
    g_allow = 8 * k;
    csError err;
    cs_errorClear(&err);
    const long acc0 = d->ada.accepted;
    const csStatus st = cs_step(&m, d, &err);
    g_reject_all = 0;
    cs_stateGet(&m, d, x + n);
    const int unchanged = memcmp(x, x + n, (size_t)n * sizeof(double)) == 0;
    printf("  rejected everywhere after %ld accepted steps: status %d (%s), state %s\n",
           d->ada.accepted - acc0, (int)st, err.msg, unchanged ? "unchanged" : "CHANGED");
    CS_EXPECT(st == CS_ERR_REJECTED);
    CS_EXPECT(d->ada.accepted - acc0 == k);
    CS_EXPECT(unchanged);
  }
  free(x);
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
}


int main(int argc, char** argv) {
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(g_src, sizeof g_src, "%s", src ? src : ".");
  cs_testInit(argc, argv);
  dInitODE2(0);
  CS_RUN(test_adaptive_estimate_and_order_on_an_oscillator);
  CS_RUN(test_adaptive_bdf2_estimate_and_order_on_an_oscillator);
  CS_RUN(test_adaptive_repeats_restores_and_keeps_the_grid);
  CS_RUN(test_adaptive_bdf2_repeats_restores_and_keeps_the_grid);
  CS_RUN(test_adaptive_rejected_everywhere_changes_nothing);
  dCloseODE();
  return cs_testSummary();
}

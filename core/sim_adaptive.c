/* sim_adaptive.c: an error-controlled step for the tree coupling (issue 32; see sim_model.h
 * csOptions.step_adaptive).
 *
 * Rationale. The strain level's backward-Euler tree step makes its error where the motion
 * turns fast (landings, lift-offs, the crawl's start), not in the smooth strokes between; a
 * fixed step must be short enough for the worst moment. Here each macro step H (cs_step's
 * unit, the output's and the checkpoints' grid: nothing outside the driver changes) is crossed
 * in steps whose length a local error estimate chooses, as CVODE and Hairer-Wanner II.8 do:
 *
 * - The estimate is the difference of the trapezoidal rule and backward Euler over the same
 *   step, which needs no second solve: backward Euler's own slope at a step's end is
 *   f(y_n) = (y_n - y_{n-1}) / h_{n-1} (its defining equation), so
 *     e = (h / 2) (f(y_{n+1}) - f(y_n)) = (Δy_n - r Δy_{n-1}) / 2,  r = h_n / h_{n-1},
 *   backward Euler's local error -(h²/2) y'' to O(h³) (Hairer-Wanner I.4 / II.8, the
 *   difference of an embedded pair). It is taken on the watched state: the support's centre
 *   (mm), velocity (mm/s) and angular velocity times CS_ADA_LEVER (mm/s), and every foot's
 *   position (mm), in a weighted RMS norm E = sqrt(mean((e_i / tol_i)²)) with tol_i = step_tol
 *   for positions and step_tol / CS_ADA_TV for velocities.
 * - A step with E <= 1 is accepted; else the state is restored from the try's saved state (the
 *   driver's rollback, sim_step.c) and the step retried shorter. A try that a stage rejects
 *   (Newton, a sunk foot) is halved inside cs_stepTry as with a fixed step.
 * - The next step is h (0.9 / sqrt(E)) (the I controller of an order-1 estimate: E ~ h²),
 *   bounded to [1/5, 2] h and to [H / 2^CS_ADA_MIN_OCT, H]; the macro step's remainder is
 *   cut into equal steps no longer than the proposal, so every macro step ends on its own
 *   time exactly (the output is sampled at its times, as with a fixed step). A step the
 *   stages had to halve proposes at most half its length.
 * - Where no history exists (the run's first step, a restored state without one) the step is
 *   accepted untested at H / 2^CS_ADA_START_OCT.
 *
 * BDF2 (the level's step_order 2: the legs' and the support's variable-step formula,
 * csr_strainBdf2Coeffs, ratio w = h / h_legs <= 2) is second order: its local error is
 * L h³ y''' with L = -(1 + w)² / (6 w (1 + 2 w)) (-2/9 at w = 1; the formula's residual on a
 * cubic), and backward Euler's estimate above would be first order's. Its estimate is the
 * one of Hairer-Wanner III.5 / CVODE's BDF (Milne's device): the step's end y_{n+1} minus the
 * quadratic P through y_{n-2}, y_{n-1}, y_n extrapolated by h is
 *   y_{n+1} - P = y''' (h (h + h1) (h + h1 + h2) / 6 - L h³) + O(h⁴)
 * (the predictor's error minus the formula's), so the local error is
 *   e = L h³ / (h (h + h1) (h + h1 + h2) / 6 - L h³) (y_{n+1} - P),
 * at a constant step -(2/11) times the third difference Δy_n - 2 Δy_{n-1} + Δy_{n-2}. The
 * next step is then h (0.9 / E^(1/3)) (E ~ h³), within the same bounds. A BDF2 step without
 * the third point (the run's second step) is tested with backward Euler's estimate (an upper
 * bound of its error at small h, so only ever too short; the first step is H / 64 then, as its
 * error is backward Euler's), and a step the formula takes as
 * backward Euler (the first, or after the stages' halvings left a ratio w > 2: the legs'
 * coefficients say, csrLegType.stepCoeffs) with backward Euler's estimate and controller.
 * The three points need not be the legs' own steps (a halved try's pieces are not watched):
 * the predictor interpolates any three; only L takes the legs' last step.
 *
 * The controller's memory (h_prop, h_prev, Δy_{n-1}; BDF2 also h_prev2, Δy_{n-2}) is part of
 * the state (sim_state.c), so a rejected step, a restore and a resumed checkpoint continue
 * exactly as the uninterrupted run. The pneumatics (CVODE) are integrated across each step
 * with its end as the stop time, as across a fixed one. */
#include <math.h>
#include <string.h>

#include "sim_internal.h"

/* the lever (mm) that turns the support's angular velocity into a speed: ~ half the support's
 * length (30 x 60 mm body), where its rotation moves the hips */
#define CS_ADA_LEVER 30.0
/* the time (s) over which a velocity error counts as a position error of step_tol: 10 ms, the
 * output interval */
#define CS_ADA_TV 0.01
/* the shortest step: H / 2^6 (78 µs at 5 ms); a step there is accepted whatever its error
 * (the stages' own halvings go further, sim_step.c) */
#define CS_ADA_MIN_OCT 6
/* the first step: H / 2^3; under BDF2 H / 2^6 (CS_ADA_MIN_OCT): the first step is backward
 * Euler's and untested, and its error ~ h² y'' / 2 must not stand above a second-order run's
 * own (on test_strain_adaptive's oscillator at 1e-5 mm it was a fifth of the global error at
 * H / 8); the controller doubles it within six steps */
#define CS_ADA_START_OCT 3
/* the step-size histogram: CS_ADA_NBIN bins of 1/16 octave below H */
#define CS_ADA_BIN_PER_OCT 16.0


/* the tree step's formula: 1 backward Euler, 2 BDF2 (the level's setting step_order, as the
 * run file records it, sim_run.c) */
static int stepOrder(const csModel* m) {
  const csrLegType* lt = m->robot.leg_type;
  return (int)csr_legSettingGet(lt, &m->robot.leg_settings, "step_order",
                                lt->step_order ? lt->step_order : 1);
}


int cs_adaptiveStateSize(const csModel* m) {
  if (!m->opt.step_adaptive) {
    return 0;
  }
  return stepOrder(m) == 2 ? CS_ADA_STATE2 : CS_ADA_STATE;
}


void cs_adaptiveStateGet(const csData* d, double* x) {
  x[0] = d->ada.h_prop;
  x[1] = d->ada.h_prev;
  memcpy(x + 2, d->ada.dy_prev, sizeof d->ada.dy_prev);
  if (cs_adaptiveStateSize(d->m) == CS_ADA_STATE2) {
    x[CS_ADA_STATE] = d->ada.h_prev2;
    memcpy(x + CS_ADA_STATE + 1, d->ada.dy_prev2, sizeof d->ada.dy_prev2);
  }
}


/* a step's length h (at most the macro step H, t1 - t to round-off) and the watched state's
 * change dy that it made are valid */
static int historyValid(double H, double h, const double* dy) {
  if (!(h >= 0 && h <= 2 * H)) {
    return 0;
  }
  for (int i = 0; i < CS_ADA_NY; i++) {
    if (!isfinite(dy[i])) {
      return 0;
    }
  }
  return 1;
}


int cs_adaptiveStateCheck(const csModel* m, const double* x) {
  const double H = cs_modelMacroStep(m);
  if (!(x[0] >= 0 && x[0] <= 2 * H) || !historyValid(H, x[1], x + 2)) {
    return -1;
  }
  if (cs_adaptiveStateSize(m) == CS_ADA_STATE2 &&
      !historyValid(H, x[CS_ADA_STATE], x + CS_ADA_STATE + 1)) {
    return -1;
  }
  return 0;
}


void cs_adaptiveStateSet(csData* d, const double* x) {
  d->ada.h_prop = x[0];
  d->ada.h_prev = x[1];
  memcpy(d->ada.dy_prev, x + 2, sizeof d->ada.dy_prev);
  if (cs_adaptiveStateSize(d->m) == CS_ADA_STATE2) {
    d->ada.h_prev2 = x[CS_ADA_STATE];
    memcpy(d->ada.dy_prev2, x + CS_ADA_STATE + 1, sizeof d->ada.dy_prev2);
  } else {
    d->ada.h_prev2 = 0;
  }
}


/* the watched state y[CS_ADA_NY] now and each entry's tolerance (mm or mm/s) */
static void watched(const csModel* m, const csData* d, double* y, double* tol) {
  const double tx = m->opt.step_tol, tv = m->opt.step_tol / CS_ADA_TV;
  const dReal* x = dBodyGetPosition(d->robot->support);
  const dReal* v = dBodyGetLinearVel(d->robot->support);
  const dReal* w = dBodyGetAngularVel(d->robot->support);
  for (int i = 0; i < 3; i++) {
    y[i] = x[i];
    y[3 + i] = v[i];
    y[6 + i] = CS_ADA_LEVER * w[i];
    tol[i] = tx;
    tol[3 + i] = tol[6 + i] = tv;
  }
  for (int k = 0; k < CSR_NLEG; k++) {
    double c[6]; /* hip and foot */
    m->robot.leg_type->centerline(d->robot->legs[k], 2, c);
    for (int i = 0; i < 3; i++) {
      y[9 + 3 * k + i] = c[3 + i];
      tol[9 + 3 * k + i] = tx;
    }
  }
}


double cs_adaptiveErrorNorm(int n, const double* dy, const double* dy_prev, const double* tol,
                            double r) {
  double s = 0;
  for (int i = 0; i < n; i++) {
    const double e = 0.5 * (dy[i] - r * dy_prev[i]) / tol[i];
    s += e * e;
  }
  return sqrt(s / n);
}


/* the I controller of an estimate of order `order` (E ~ h^(order + 1)) */
static double factorOf(double E, int order) {
  if (!(E > 0)) {
    return 2.0;
  }
  return fmin(2.0, fmax(0.2, 0.9 / (order == 2 ? cbrt(E) : sqrt(E))));
}


double cs_adaptiveFactor(double E) { return factorOf(E, 1); }


double cs_adaptiveErrorNorm2(int n, const double* dy, const double* dy1, const double* dy2,
                             const double* tol, double h, double h1, double h2, double w) {
  /* |L| h³, BDF2's error constant at ratio w (the header's derivation), and the predictor's
   * error h (h + h1) (h + h1 + h2) / 6 per unit y''' */
  const double Lh3 = (1 + w) * (1 + w) / (6 * w * (1 + 2 * w)) * h * h * h;
  const double K = Lh3 / (h * (h + h1) * (h + h1 + h2) / 6 + Lh3);
  /* P - y_n in Newton's form: h [y_n, y_n-1] + h (h + h1) [y_n, y_n-1, y_n-2] */
  const double a = h / h1, b = h * (h + h1) / (h1 + h2);
  double s = 0;
  for (int i = 0; i < n; i++) {
    const double e = K * (dy[i] - a * dy1[i] - b * (dy1[i] / h1 - dy2[i] / h2)) / tol[i];
    s += e * e;
  }
  return sqrt(s / n);
}


double cs_adaptiveFactor2(double E) { return factorOf(E, 2); }


static void recordStep(csData* d, double h, double H) {
  csAdaptive* a = &d->ada;
  a->accepted++;
  a->h_min = a->accepted == 1 ? h : fmin(a->h_min, h);
  a->h_max = a->accepted == 1 ? h : fmax(a->h_max, h);
  int b = (int)floor(-log2(h / H) * CS_ADA_BIN_PER_OCT);
  b = b < 0 ? 0 : b >= CS_ADA_NBIN ? CS_ADA_NBIN - 1 : b;
  a->bins[b]++;
}


csStatus cs_adaptiveStep(const csModel* m, csData* d, double t1, csError* err) {
  csAdaptive* a = &d->ada;
  const double H = cs_modelMacroStep(m);
  const double h_min = H / (1 << CS_ADA_MIN_OCT);
  double y0[CS_ADA_NY], y1[CS_ADA_NY], dy[CS_ADA_NY], tol[CS_ADA_NY];
  /* the macro step's start (the slot after the halvings' slots, sim_driver.c): a step that
   * fails for good restores it, so a failed cs_step changes nothing (sim_model.h) */
  double* x0 = d->save + (size_t)(CS_MAX_SPLIT + 1) * (size_t)d->nstate;
  cs_stateGet(m, d, x0);
  while (d->t < t1) {
    if (!(a->h_prop > 0)) {
      a->h_prop = H / (1 << (stepOrder(m) == 2 ? CS_ADA_MIN_OCT : CS_ADA_START_OCT));
    }
    /* the rest of the macro step in equal steps no longer than the proposal (the 1e-9 keeps
     * a remainder that is the proposal to round-off one step) */
    const double rest = t1 - d->t;
    const double n = ceil(rest / a->h_prop * (1 - 1e-9));
    const double h = n <= 1 ? rest : rest / n;
    const double te = n <= 1 ? t1 : d->t + h;
    watched(m, d, y0, tol);
    /* the formula this step takes (BDF2 when the legs' last step is within a ratio of 2) */
    double c[3] = {1, 0, 1};
    if (m->robot.leg_type->stepCoeffs) {
      m->robot.leg_type->stepCoeffs(d->robot->legs[0], h, c);
    }
    const int bdf = c[1] != 0;
    const long nrej0 = d->nreject;
    csStatus st = cs_stepTry(m, d, te, h, 0, err);
    if (st != CS_OK) {
      dJointGroupEmpty(d->contacts);
      cs_stateSet(m, d, x0, NULL);
      return st;
    }
    watched(m, d, y1, tol);
    for (int i = 0; i < CS_ADA_NY; i++) {
      dy[i] = y1[i] - y0[i];
    }
    const int tested = a->h_prev > 0;
    /* second order's estimate where the formula was BDF2 and three points exist */
    const int second = bdf && tested && a->h_prev2 > 0;
    /* the formula's ratio from its coefficient c2 = (1 + w) / (1 + 2 w) */
    const double E =
        second ? cs_adaptiveErrorNorm2(CS_ADA_NY, dy, a->dy_prev, a->dy_prev2, tol, h,
                                       a->h_prev, a->h_prev2, (1 - c[2]) / (2 * c[2] - 1))
        : tested ? cs_adaptiveErrorNorm(CS_ADA_NY, dy, a->dy_prev, tol, h / a->h_prev)
                 : 0;
    const double f = second ? cs_adaptiveFactor2(E) : cs_adaptiveFactor(E);
    if (tested && E > 1 && h > h_min * (1 + 1e-9)) {
      /* rejected: back to the step's start (saved by cs_stepTry in slot 0), shorter */
      dJointGroupEmpty(d->contacts);
      cs_stateSet(m, d, d->save, NULL);
      a->rejected++;
      a->h_prop = fmax(h_min, h * f);
      continue;
    }
    d->t = te;
    memcpy(a->dy_prev2, a->dy_prev, sizeof a->dy_prev2);
    a->h_prev2 = a->h_prev;
    memcpy(a->dy_prev, dy, sizeof dy);
    a->h_prev = h;
    a->h_prop = tested ? fmin(H, fmax(h_min, h * f)) : h;
    if (d->nreject > nrej0) {
      /* the stages halved this step (Newton, a sunk foot): the next one no longer than a half,
       * as CVODE shrinks after a convergence failure (its pieces' passes cost more than the
       * error test saves) */
      a->h_prop = fmax(h_min, fmin(a->h_prop, 0.5 * h));
    }
    recordStep(d, h, H);
  }
  return CS_OK;
}


void cs_adaptiveStats(const csData* d, csAdaptiveStats* s) {
  const csAdaptive* a = &d->ada;
  memset(s, 0, sizeof *s);
  s->accepted = a->accepted;
  s->rejected = a->rejected;
  if (a->accepted == 0) {
    return;
  }
  s->h_min = a->h_min;
  s->h_max = a->h_max;
  /* the median bin's centre, within the extremes */
  const double H = cs_modelMacroStep(d->m);
  long half = (a->accepted + 1) / 2, c = 0;
  for (int b = 0; b < CS_ADA_NBIN; b++) {
    c += a->bins[b];
    if (c >= half) {
      s->h_median = fmin(s->h_max, fmax(s->h_min, H * exp2(-(b + 0.5) / CS_ADA_BIN_PER_OCT)));
      break;
    }
  }
}

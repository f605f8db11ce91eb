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
 * The controller's memory (h_prop, h_prev, Δy_{n-1}) is part of the state (sim_state.c), so a
 * rejected step, a restore and a resumed checkpoint continue exactly as the uninterrupted run.
 * The pneumatics (CVODE) are integrated across each step with its end as the stop time, as
 * across a fixed one. */
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
/* the first step: H / 2^3 */
#define CS_ADA_START_OCT 3
/* the step-size histogram: CS_ADA_NBIN bins of 1/16 octave below H */
#define CS_ADA_BIN_PER_OCT 16.0


int cs_adaptiveStateSize(const csModel* m) { return m->opt.step_adaptive ? CS_ADA_STATE : 0; }


void cs_adaptiveStateGet(const csData* d, double* x) {
  x[0] = d->ada.h_prop;
  x[1] = d->ada.h_prev;
  memcpy(x + 2, d->ada.dy_prev, sizeof d->ada.dy_prev);
}


int cs_adaptiveStateCheck(const csModel* m, const double* x) {
  const double H = cs_modelMacroStep(m);
  /* a step is at most the macro step, t1 - t to round-off */
  if (!(x[0] >= 0 && x[0] <= 2 * H && x[1] >= 0 && x[1] <= 2 * H)) {
    return -1;
  }
  for (int i = 0; i < CS_ADA_NY; i++) {
    if (!isfinite(x[2 + i])) {
      return -1;
    }
  }
  return 0;
}


void cs_adaptiveStateSet(csData* d, const double* x) {
  d->ada.h_prop = x[0];
  d->ada.h_prev = x[1];
  memcpy(d->ada.dy_prev, x + 2, sizeof d->ada.dy_prev);
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


double cs_adaptiveFactor(double E) {
  if (!(E > 0)) {
    return 2.0;
  }
  return fmin(2.0, fmax(0.2, 0.9 / sqrt(E)));
}


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
      a->h_prop = H / (1 << CS_ADA_START_OCT);
    }
    /* the rest of the macro step in equal steps no longer than the proposal (the 1e-9 keeps
     * a remainder that is the proposal to round-off one step) */
    const double rest = t1 - d->t;
    const double n = ceil(rest / a->h_prop * (1 - 1e-9));
    const double h = n <= 1 ? rest : rest / n;
    const double te = n <= 1 ? t1 : d->t + h;
    watched(m, d, y0, tol);
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
    const double E =
        tested ? cs_adaptiveErrorNorm(CS_ADA_NY, dy, a->dy_prev, tol, h / a->h_prev) : 0;
    if (tested && E > 1 && h > h_min * (1 + 1e-9)) {
      /* rejected: back to the step's start (saved by cs_stepTry in slot 0), shorter */
      dJointGroupEmpty(d->contacts);
      cs_stateSet(m, d, d->save, NULL);
      a->rejected++;
      a->h_prop = fmax(h_min, h * cs_adaptiveFactor(E));
      continue;
    }
    d->t = te;
    memcpy(a->dy_prev, dy, sizeof dy);
    a->h_prev = h;
    a->h_prop = tested ? fmin(H, fmax(h_min, h * cs_adaptiveFactor(E))) : h;
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

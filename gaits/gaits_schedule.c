/* gaits_schedule.c: p(t) from a gait table (see gaits_schedule.h for the definition). */
#include "gaits_schedule.h"

#include <math.h>

/* the row whose interval [t_i, t_{i+1}) holds t, or -1 before the first row */
static int findRow(const csgGait* g, double t);
/* ramp shape S(u) and its derivative dS/du, u clamped to [0, 1] */
static double shapeValue(csgRampShape shape, double u);
static double shapeSlope(csgRampShape shape, double u);
/* the options' validity, without a message */
static int optionsOk(const csgScheduleOptions* opt);


csgScheduleOptions csg_defaultScheduleOptions(void) {
  csgScheduleOptions o;
  o.ramp = CSG_DEFAULT_RAMP;
  o.shape = CSG_RAMP_SMOOTHSTEP;
  o.pressure_scale = 1.0;
  return o;
}


static int optionsOk(const csgScheduleOptions* opt) {
  return isfinite(opt->ramp) && opt->ramp >= 0.0 && isfinite(opt->pressure_scale) &&
         opt->pressure_scale >= 0.0 &&
         (opt->shape == CSG_RAMP_SMOOTHSTEP || opt->shape == CSG_RAMP_QUINTIC ||
          opt->shape == CSG_RAMP_LINEAR);
}


csStatus csg_scheduleCheckOptions(const csgScheduleOptions* opt, csError* err) {
  if (!opt) {
    return cs_errorSet(err, CS_ERR_ARG, "schedule options: NULL");
  }
  if (!isfinite(opt->ramp) || opt->ramp < 0.0) {
    return cs_errorSet(err, CS_ERR_ARG, "schedule options: ramp %g s must be >= 0 and finite",
                       opt->ramp);
  }
  if (!isfinite(opt->pressure_scale) || opt->pressure_scale < 0.0) {
    return cs_errorSet(err, CS_ERR_ARG, "schedule options: pressure scale %g must be >= 0",
                       opt->pressure_scale);
  }
  if (!optionsOk(opt)) {
    return cs_errorSet(err, CS_ERR_ARG, "schedule options: unknown ramp shape %d", (int)opt->shape);
  }
  return CS_OK;
}


static int findRow(const csgGait* g, double t) {
  /* binary search for the last i with t_i <= t */
  if (t < g->time[0]) {
    return -1;
  }
  int lo = 0, hi = g->nrow - 1;
  while (lo < hi) {
    int mid = lo + (hi - lo + 1) / 2;
    if (g->time[mid] <= t) {
      lo = mid;
    } else {
      hi = mid - 1;
    }
  }
  return lo;
}


static double shapeValue(csgRampShape shape, double u) {
  if (u <= 0.0) {
    return 0.0;
  }
  if (u >= 1.0) {
    return 1.0;
  }
  switch (shape) {
    case CSG_RAMP_QUINTIC:
      return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
    case CSG_RAMP_LINEAR:
      return u;
    case CSG_RAMP_SMOOTHSTEP:
      break;
  }
  return u * u * (3.0 - 2.0 * u);
}


static double shapeSlope(csgRampShape shape, double u) {
  /* one-sided from the right: a linear ramp has slope 1 at u = 0, 0 at u = 1 */
  if (u < 0.0 || u >= 1.0) {
    return 0.0;
  }
  switch (shape) {
    case CSG_RAMP_QUINTIC:
      return 30.0 * u * u * (1.0 - u) * (1.0 - u);
    case CSG_RAMP_LINEAR:
      return 1.0;
    case CSG_RAMP_SMOOTHSTEP:
      break;
  }
  return 6.0 * u * (1.0 - u);
}


/* Whether row k's ramp fits its row spacing: it ends by the next row's time, or overruns it
 * by less than CSG_RAMP_ROUNDING (the last row's ramp never fits: it has no next row). */
static int rampFits(const csgGait* g, double ramp, int k) {
  return k + 1 < g->nrow && g->time[k + 1] - g->time[k] >= ramp - CSG_RAMP_ROUNDING;
}


/* Row k's ramp length r_k (s): the ramp, or the row spacing where the two differ by rounding
 * only (either way), so that this change fills the interval to the next row exactly. (That
 * is what a ramp cut to the row spacing gave before, so such tables play as they did.) */
static double rowRamp(const csgGait* g, double ramp, int k) {
  if (k + 1 < g->nrow) {
    double gap = g->time[k + 1] - g->time[k];
    if (fabs(gap - ramp) <= CSG_RAMP_ROUNDING) {
      return gap;
    }
  }
  return ramp;
}


/* Whether row k's change (k <= row, the row of t) still runs at t. A fitting ramp has
 * finished by the next row's time (so the next change starts from the exact plateau); else
 * compare with the end time itself, so t = t_k + r_k is finished exactly even when
 * (t - t_k) / r_k rounds to just below 1. */
static int rowRunning(const csgGait* g, double ramp, int k, int row, double t) {
  if (k < row && rampFits(g, ramp, k)) {
    return 0;
  }
  return t < g->time[k] + rowRamp(g, ramp, k);
}


/* Where t sits: the rows whose ramps still run at t are among j..row (j = row + 1: none);
 * every row before j has finished its change, so the schedule is P_{j-1} (vented for j = 0)
 * plus the changes (P_k - P_{k-1}) S(u_k), k = j..row, with S = 1 for a finished one.
 * Returns 0 if the arguments are bad. */
typedef struct {
  int row; /* the last row with t_k <= t, -1 before the first */
  int j;   /* the first running row (row + 1 when none runs) */
} schedulePoint;

static int locate(const csgGait* g, const csgScheduleOptions* opt, double t, schedulePoint* sp) {
  if (!g || g->nrow < 1 || !opt || !optionsOk(opt) || !isfinite(t)) {
    return 0;
  }
  sp->row = findRow(g, t);
  sp->j = sp->row + 1;
  if (sp->row < 0 || !(opt->ramp > 0.0)) {
    return 1;
  }
  /* r_k <= ramp + CSG_RAMP_ROUNDING, so a row with t at or past t_k plus that has finished,
   * and so has every earlier one (the bound grows with k): the scan visits only the rows of
   * the last ramp length */
  const double reach = opt->ramp + CSG_RAMP_ROUNDING;
  for (int k = sp->row; k >= 0 && t < g->time[k] + reach; k--) {
    if (rowRunning(g, opt->ramp, k, sp->row, t)) {
      sp->j = k;
    }
  }
  return 1;
}


/* the ramp fraction u_k = (t - t_k) / r_k of row k at t (1 once finished) and 1 / r_k */
static double rowFraction(const csgGait* g, double ramp, int k, int row, double t,
                          double* inv_r) {
  double r = rowRamp(g, ramp, k);
  *inv_r = 1.0 / r;
  return rowRunning(g, ramp, k, row, t) ? (t - g->time[k]) / r : 1.0;
}


/* the options of opt NULL: the defaults, with the table's stated ramp if any */
static csgScheduleOptions defaultsFor(const csgGait* g) {
  csgScheduleOptions o = csg_defaultScheduleOptions();
  if (g && !isnan(g->ramp)) {
    o.ramp = g->ramp;
  }
  return o;
}


/* row k's pressures (96), NULL for k < 0 (vented) */
static const double* rowPressure(const csgGait* g, int k) {
  return k >= 0 ? &g->pressure[(size_t)CSG_NLABEL * k] : NULL;
}


/* u_k of row k (k <= row) at t: the ramp fraction, 1 once finished; ctx is the caller's view
 * of the rows' start times (the table's, or csg_scheduleEvalHeld's shifted ones) */
typedef double (*rowFractionFn)(const void* ctx, int k, int row, double t);

/* The schedule at t from the rows j..row whose changes run (j = row + 1: none): the plateau of
 * row j - 1 (vented for j = 0) plus (P_k - P_{k-1}) S(u_k), k = j..row, all scaled by the
 * options' pressure scale. One running change is written as a blend so both plateaus come out
 * exact (s = 0 -> P_{j-1}, s = 1 -> P_row); several (a ramp longer than the row spacing) are
 * superposed. Shared by csg_scheduleEval and csg_scheduleEvalHeld, which differ only in the
 * rows' start times. */
static void superpose(const csgGait* g, const csgScheduleOptions* o, int j, int row, double t,
                      rowFractionFn fraction, const void* ctx, double p_out[CSG_NLABEL]) {
  const double K = o->pressure_scale;
  const double* base = rowPressure(g, j - 1); /* the last finished row's plateau */
  if (j > row) {
    for (int l = 0; l < CSG_NLABEL; l++) {
      p_out[l] = base ? K * base[l] : 0.0;
    }
    return;
  }
  if (j == row) {
    const double s = shapeValue(o->shape, fraction(ctx, row, row, t));
    const double* cur = rowPressure(g, row);
    for (int l = 0; l < CSG_NLABEL; l++) {
      double a = base ? base[l] : 0.0;
      p_out[l] = K * ((1.0 - s) * a + s * cur[l]);
    }
    return;
  }
  for (int l = 0; l < CSG_NLABEL; l++) {
    p_out[l] = base ? base[l] : 0.0;
  }
  for (int k = j; k <= row; k++) {
    const double s = shapeValue(o->shape, fraction(ctx, k, row, t));
    const double* prev = rowPressure(g, k - 1);
    const double* cur = rowPressure(g, k);
    for (int l = 0; l < CSG_NLABEL; l++) {
      p_out[l] += (cur[l] - (prev ? prev[l] : 0.0)) * s;
    }
  }
  for (int l = 0; l < CSG_NLABEL; l++) {
    p_out[l] *= K;
  }
}


/* the table's own start times (csg_scheduleEval) */
typedef struct {
  const csgGait* g;
  double ramp;
} tableRows;

static double tableFraction(const void* ctx, int k, int row, double t) {
  const tableRows* v = ctx;
  double inv_r;
  return rowFraction(v->g, v->ramp, k, row, t, &inv_r);
}


csStatus csg_scheduleEval(const csgGait* g, const csgScheduleOptions* opt, double t,
                          double p_out[CSG_NLABEL]) {
  csgScheduleOptions def = defaultsFor(g);
  const csgScheduleOptions* o = opt ? opt : &def;
  schedulePoint sp;
  if (!p_out || !locate(g, o, t, &sp)) {
    return CS_ERR_ARG;
  }
  const tableRows v = {g, o->ramp};
  superpose(g, o, sp.j, sp.row, t, tableFraction, &v, p_out);
  return CS_OK;
}


/* held rows (csg_scheduleEvalHeld): row k's offset and shifted start */
typedef struct {
  const csgGait* g;
  int nbreak;
  const double* breaks;
  const double* off;
  double ramp; /* the options' ramp (s) */
} heldRows;

static double heldStart(const heldRows* h, int k) {
  const double tk = h->g->time[k];
  int lo = 0, hi = h->nbreak; /* s: the number of breaks below tk */
  while (lo < hi) {
    int mid = lo + (hi - lo) / 2;
    if (h->breaks[mid] < tk - CSG_RAMP_ROUNDING) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  return tk + h->off[lo];
}

/* rampFits, rowRamp and rowRunning on the shifted times */
static double heldRamp(const heldRows* h, double ramp, int k) {
  if (k + 1 < h->g->nrow) {
    double gap = heldStart(h, k + 1) - heldStart(h, k);
    if (fabs(gap - ramp) <= CSG_RAMP_ROUNDING) {
      return gap;
    }
  }
  return ramp;
}

static int heldRunning(const heldRows* h, double ramp, int k, int row, double t) {
  if (k < row && k + 1 < h->g->nrow &&
      heldStart(h, k + 1) - heldStart(h, k) >= ramp - CSG_RAMP_ROUNDING) {
    return 0;
  }
  return t < heldStart(h, k) + heldRamp(h, ramp, k);
}


static double heldFraction(const void* ctx, int k, int row, double t) {
  const heldRows* h = ctx;
  const double r = heldRamp(h, h->ramp, k);
  return heldRunning(h, h->ramp, k, row, t) ? (t - heldStart(h, k)) / r : 1.0;
}


csStatus csg_scheduleEvalHeld(const csgGait* g, const csgScheduleOptions* opt, double t,
                              int nbreak, const double* breaks, const double* off,
                              double t_issued, double p_out[CSG_NLABEL]) {
  csgScheduleOptions def = defaultsFor(g);
  const csgScheduleOptions* o = opt ? opt : &def;
  if (!p_out || !g || g->nrow < 1 || !optionsOk(o) || !isfinite(t) || nbreak < 0 || !off ||
      (nbreak > 0 && !breaks) || isnan(t_issued)) {
    return CS_ERR_ARG;
  }
  const heldRows h = {g, nbreak, breaks, off, o->ramp};
  /* the issued rows: t_i <= t_issued */
  int nis = findRow(g, t_issued) + 1;
  /* the last issued row that has started (shifted starts do not decrease) */
  int row = -1, lo = 0, hi = nis - 1;
  while (lo <= hi) {
    int mid = lo + (hi - lo) / 2;
    if (heldStart(&h, mid) <= t) {
      row = mid;
      lo = mid + 1;
    } else {
      hi = mid - 1;
    }
  }
  int j = row + 1;
  if (row >= 0 && o->ramp > 0.0) {
    const double reach = o->ramp + CSG_RAMP_ROUNDING;
    for (int k = row; k >= 0 && t < heldStart(&h, k) + reach; k--) {
      if (heldRunning(&h, o->ramp, k, row, t)) {
        j = k;
      }
    }
  }
  superpose(g, o, j, row, t, heldFraction, &h, p_out);
  return CS_OK;
}


csStatus csg_scheduleEvalRate(const csgGait* g, const csgScheduleOptions* opt, double t,
                              double dpdt_out[CSG_NLABEL]) {
  csgScheduleOptions def = defaultsFor(g);
  const csgScheduleOptions* o = opt ? opt : &def;
  schedulePoint sp;
  if (!dpdt_out || !locate(g, o, t, &sp)) {
    return CS_ERR_ARG;
  }
  for (int l = 0; l < CSG_NLABEL; l++) {
    dpdt_out[l] = 0.0;
  }
  /* the derivative of the sum above: sum_k (P_k - P_{k-1}) S'(u_k) / r_k (finished rows and
   * a step, ramp 0, add nothing) */
  for (int r = sp.j; r <= sp.row; r++) {
    double inv_r;
    double ds = shapeSlope(o->shape, rowFraction(g, o->ramp, r, sp.row, t, &inv_r)) * inv_r;
    const double* prev = rowPressure(g, r - 1);
    const double* cur = rowPressure(g, r);
    for (int l = 0; l < CSG_NLABEL; l++) {
      dpdt_out[l] += o->pressure_scale * (cur[l] - (prev ? prev[l] : 0.0)) * ds;
    }
  }
  return CS_OK;
}

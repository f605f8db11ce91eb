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


/* where t sits: row i (-1 before the first), the previous and current rows' pressures, the
 * ramp fraction u and 1/r_i (1/s; 0 for a step). Returns 0 if the arguments are bad. */
typedef struct {
  int row;
  const double* prev; /* (96) MPa, NULL = vented (before row 0) */
  const double* cur;  /* (96) MPa, NULL before the first row */
  double u;           /* ramp fraction, in [0, 1] */
  double inv_ramp;    /* 1/s */
} schedulePoint;

static int locate(const csgGait* g, const csgScheduleOptions* opt, double t, schedulePoint* sp) {
  if (!g || g->nrow < 1 || !opt || !optionsOk(opt) || !isfinite(t)) {
    return 0;
  }
  sp->row = findRow(g, t);
  sp->prev = NULL;
  sp->cur = NULL;
  sp->u = 1.0;
  sp->inv_ramp = 0.0;
  if (sp->row < 0) {
    return 1;
  }
  int i = sp->row;
  sp->cur = &g->pressure[(size_t)CSG_NLABEL * i];
  sp->prev = i > 0 ? &g->pressure[(size_t)CSG_NLABEL * (i - 1)] : NULL;
  /* ramp clamped to the row spacing so it ends by the next row's time */
  double r = opt->ramp;
  if (i + 1 < g->nrow && g->time[i + 1] - g->time[i] < r) {
    r = g->time[i + 1] - g->time[i];
  }
  if (r > 0.0) {
    /* compare with the end time itself, so t = t_i + r lands on the plateau exactly even when
     * (t - t_i) / r rounds to just below 1 */
    sp->u = t >= g->time[i] + r ? 1.0 : (t - g->time[i]) / r;
    sp->inv_ramp = 1.0 / r;
  }
  return 1;
}


csStatus csg_scheduleEval(const csgGait* g, const csgScheduleOptions* opt, double t,
                          double p_out[CSG_NLABEL]) {
  csgScheduleOptions def = csg_defaultScheduleOptions();
  const csgScheduleOptions* o = opt ? opt : &def;
  schedulePoint sp;
  if (!p_out || !locate(g, o, t, &sp)) {
    return CS_ERR_ARG;
  }
  double k = o->pressure_scale;
  if (!sp.cur) {
    for (int l = 0; l < CSG_NLABEL; l++) {
      p_out[l] = 0.0;
    }
    return CS_OK;
  }
  double s = shapeValue(o->shape, sp.u);
  for (int l = 0; l < CSG_NLABEL; l++) {
    double a = sp.prev ? sp.prev[l] : 0.0;
    /* written as a blend so both plateaus come out exact (s = 0 -> a, s = 1 -> cur) */
    p_out[l] = k * ((1.0 - s) * a + s * sp.cur[l]);
  }
  return CS_OK;
}


csStatus csg_scheduleEvalRate(const csgGait* g, const csgScheduleOptions* opt, double t,
                              double dpdt_out[CSG_NLABEL]) {
  csgScheduleOptions def = csg_defaultScheduleOptions();
  const csgScheduleOptions* o = opt ? opt : &def;
  schedulePoint sp;
  if (!dpdt_out || !locate(g, o, t, &sp)) {
    return CS_ERR_ARG;
  }
  double ds = sp.cur ? shapeSlope(o->shape, sp.u) * sp.inv_ramp : 0.0;
  for (int l = 0; l < CSG_NLABEL; l++) {
    double a = sp.prev ? sp.prev[l] : 0.0;
    double b = sp.cur ? sp.cur[l] : 0.0;
    dpdt_out[l] = o->pressure_scale * (b - a) * ds;
  }
  return CS_OK;
}

/* sim_gate.c: the landing gate's player (issue 33; the rule: gaits_gate.h; the design and its
 * runs: docs/studies/obstacle.md, "2026-12-06, fifth session" and "sixth session").
 *
 * A sensing controller inside the schedule: at each step's start (cs_gateDecide, from the
 * state alone) the gates whose table time has come are tested on the measured chamber
 * pressures; a gate that is not down holds the table's clock for the step (no row past it is
 * issued; the changes issued before it arrive as they would, the chambers filling on), and
 * the accepted step's length goes onto the hold and the gate's wait (cs_gateCommit). Every row
 * issued after a gate released starts later by the holds so far (gaits_schedule.h
 * csg_scheduleEvalHeld). While nothing has been held the schedule is csg_scheduleEval itself,
 * so a run whose gates never wait is the open-loop run bit for bit.
 *
 * The state's gate part (sim_state.c): the next gate, the hold, the current wait and each
 * released gate's wait; the decision fields in csData are recomputed from it at every step's
 * start and after a restore, so a retried or restored step decides again identically. The
 * design's pressures at the gates' times are integrated once here at load. Nothing is
 * allocated during a run. */
#include <math.h>
#include <string.h>

#include "sim_internal.h"

/* s: a table time within this of a gate's counts as reached (the run's time is a sum of
 * steps: 2.6 s may come out 1e-15 s short of it) */
#define GATE_TIME_TOL 1e-9
/* s: the design's integration step (the exact solution of dp/dt = (c - p) / lag for c linear
 * over each sub-step; the table's 0.05 s ramps are smooth on it) */
#define DESIGN_STEP 5e-4


/* the design's pressures at every gate's time: the table on time through the file's ramp and
 * lag, p' = (c - p) / lag, from vented at t = 0, sub-steps of DESIGN_STEP, each exact for a
 * command linear over it: p1 = c1 + (p0 - c0) a - (c1 - c0) / h lag (1 - a), a = exp(-h / lag) */
static void designPressures(const csModel* m, csgGateSet* s) {
  csgScheduleOptions o = m->sched;
  o.ramp = s->ramp;
  double p[CSG_NLABEL] = {0}, c0[CSG_NLABEL], c1[CSG_NLABEL];
  double t = 0;
  csg_scheduleEval(m->gait, &o, t, c0);
  for (int k = 0; k < s->n; k++) {
    while (t < s->gate[k].t) {
      const double h = fmin(DESIGN_STEP, s->gate[k].t - t);
      const double t1 = h < DESIGN_STEP ? s->gate[k].t : t + h;
      const double a = exp(-h / s->lag);
      csg_scheduleEval(m->gait, &o, t1, c1);
      for (int l = 0; l < CSG_NLABEL; l++) {
        p[l] = c1[l] + (p[l] - c0[l]) * a - (c1[l] - c0[l]) / h * s->lag * (1 - a);
      }
      memcpy(c0, c1, sizeof c0);
      t = t1;
    }
    memcpy(s->gate[k].p_design, p, sizeof p);
  }
}


csStatus cs_modelLoadGate(csModel* m, const char* path, csError* err) {
  if (!m->gait) {
    return cs_errorSet(err, CS_ERR_ARG, "--gate %s: a gate needs a gait table", path);
  }
  csgGateSet* s = csg_gateRead(path, err);
  if (!s) {
    return err ? err->status : CS_ERR_PARSE;
  }
  designPressures(m, s);
  csg_gateDestroy(m->gate);
  m->gate = s;
  return CS_OK;
}


/* the crawl's decision at the step's start (gaits_gate.h `crawl`), and the walk's (`walk`, the
 * same rule on x): every decision boundary the table's clock tau has passed reads the
 * support's measured position now (the state's); the first that says stop sets the skip, and
 * no boundary is read after it. i, v, skip the committed boundaries read, coordinate at the
 * last, skip; out the step's. Nothing here moves the support: the skip only changes which
 * table row the valves are given. */
static void endDecide(const csModel* m, const csData* d, int walk, double tau, double i, double v,
                      double skip, double* out) {
  const csgGateSet* s = m->gate;
  const int n = walk ? s->walk_n : s->crawl_n;
  const double t0 = walk ? s->walk_t0 : s->crawl_t0, tp = walk ? s->walk_tp : s->crawl_tpz;
  if (n > 0 && !m->pressure_source && skip == 0) {
    double pos[3];
    cs_supportDisplacement(d, pos);
    const double now = walk ? pos[0] : pos[2];
    for (;;) {
      const int j = (n - 1) % 2 + 2 * (int)i;
      if (j > n - 1 || tau < t0 + (j + 1) * tp - GATE_TIME_TOL) {
        break;
      }
      const int left = walk ? csg_gateWalkSkip(s, j, now, v) : csg_gateCrawlSkip(s, j, now, v);
      i += 1;
      v = now;
      if (left > 0) {
        skip = left * tp;
        break;
      }
    }
  }
  out[0] = i;
  out[1] = v;
  out[2] = skip;
}


void cs_gateDecide(const csModel* m, csData* d) {
  const csgGateSet* s = m->gate;
  if (!s) {
    return;
  }
  const int g0 = (int)d->gate_i;
  int gi = g0, holding = 0;
  double w = d->gate_wait;
  /* the table's clock: every gate comes before the walk and the crawl, the walk before the
   * crawl's first slot (gaits_gate.c), so a skip decided here never jumps over a gate, and the
   * crawl reads the clock the walk's decision leaves */
  double out[3];
  endDecide(m, d, 1, d->t - d->gate_hold + d->walk_skip + d->crawl_skip, d->walk_i, d->walk_x,
            d->walk_skip, out);
  d->walk_i_next = out[0];
  d->walk_x_next = out[1];
  d->walk_skip_next = out[2];
  endDecide(m, d, 0, d->t - d->gate_hold + d->walk_skip_next + d->crawl_skip, d->crawl_i,
            d->crawl_z, d->crawl_skip, out);
  d->crawl_i_next = out[0];
  d->crawl_z_next = out[1];
  d->crawl_skip_next = out[2];
  const double tau = d->t - d->gate_hold + d->walk_skip_next + d->crawl_skip_next;
  /* a caller's pressure source (cs_simSetController, a held command) drives the chambers
   * instead of the table: the gate neither tests nor holds meanwhile */
  if (!m->pressure_source && d->t >= 0 && gi < s->n && tau >= s->gate[gi].t - GATE_TIME_TOL) {
    /* the valves' command: the last row issued (the table's clock is at tau) */
    double v[CSG_NLABEL], pos[3];
    csgScheduleOptions o = m->sched;
    o.ramp = 0; /* the rows themselves */
    csg_scheduleEval(m->gait, &o, tau + 1e-12, v);
    cs_supportDisplacement(d, pos); /* mm: the measured support, for a gate's `x XMIN` */
    while (gi < s->n && tau >= s->gate[gi].t - GATE_TIME_TOL) {
      if (w >= s->maxwait - GATE_TIME_TOL ||
          csg_gateReady(&s->gate[gi], d->p, v, s->ptol, pos[0])) {
        gi++;
        w = 0;
      } else {
        holding = 1;
        break;
      }
    }
  }
  /* the rows' offsets: after gate k, the waits of gates 0..k (released, or this one's so far) */
  d->gate_off[0] = 0;
  for (int k = 0; k < s->n; k++) {
    const double rel = k < g0 ? d->gate_rel[k] : k < gi ? (k == g0 ? d->gate_wait : 0)
                       : k == gi ? w : 0;
    d->gate_off[k + 1] = d->gate_off[k] + rel;
  }
  d->gate_next = gi;
  d->gate_holding = holding;
  d->gate_issued = holding ? tau + 1e-12 : INFINITY;
}


void cs_gateCommit(const csModel* m, csData* d, double h) {
  if (!m->gate) {
    return;
  }
  const int g0 = (int)d->gate_i;
  for (int k = g0; k < d->gate_next; k++) {
    d->gate_rel[k] = k == g0 ? d->gate_wait : 0;
  }
  if (d->gate_next > g0) {
    d->gate_wait = 0;
  }
  d->gate_i = d->gate_next;
  d->crawl_i = d->crawl_i_next;
  d->crawl_z = d->crawl_z_next;
  d->crawl_skip = d->crawl_skip_next;
  d->walk_i = d->walk_i_next;
  d->walk_x = d->walk_x_next;
  d->walk_skip = d->walk_skip_next;
  if (d->gate_holding) {
    d->gate_hold += h;
    d->gate_wait += h;
  }
}


void cs_gateEval(const csModel* m, const csData* d, const csgGait* g, double t, double* p_cmd) {
  if (m->gate) {
    t += d->walk_skip_next + d->crawl_skip_next; /* the skips (the decisions this step plays) */
  }
  if (!m->gate || (d->gate_hold == 0 && !d->gate_holding)) {
    csg_scheduleEval(g, &m->sched, t, p_cmd);
    return;
  }
  csg_scheduleEvalHeld(g, &m->sched, t, m->gate->n, m->gate->time, d->gate_off, d->gate_issued,
                       p_cmd);
}


double cs_gateTableTime(const csModel* m, const csData* d, double t) {
  return m->gate ? t - d->gate_hold + d->walk_skip_next + d->crawl_skip_next : t;
}


int cs_runOverAt(const csModel* m, const csData* d, long i) {
  if (m->opt.t_end > 0 || !m->gate || !m->gait) {
    return 0; /* --t-end wins; without a gate the loop's step count is the end */
  }
  /* the committed skips (the _next ones are the coming step's, stale after a restore); half a
   * macro step: the loop's own lround(t_end / H) rounding of the same end */
  const double tau = d->t - d->gate_hold + d->walk_skip + d->crawl_skip;
  return i % cs_modelOutputEvery(m) == 0 && tau >= cs_modelTableEnd(m) - 0.5 * cs_modelMacroStep(m);
}


double cs_gateReleasedWait(const csData* d, int k) {
  return k >= 0 && k < (int)d->gate_i ? d->gate_rel[k] : 0;
}


void cs_gateHeld(const csModel* m, const csData* d, double* hold_s, int* released, int* waited) {
  *hold_s = 0;
  *released = 0;
  *waited = 0;
  if (!m->gate) {
    return;
  }
  *hold_s = d->gate_hold;
  *released = (int)d->gate_i;
  for (int k = 0; k < (int)d->gate_i; k++) {
    *waited += d->gate_rel[k] > 0;
  }
}

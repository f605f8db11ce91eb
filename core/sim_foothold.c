/* sim_foothold.c: the footholds' player (issue 33; the design: docs/studies/obstacle.md, "A
 * foothold that reads the support"): the gait table's command with, over each foothold's
 * window, its legs' columns from the candidate chosen at its lift from where the support
 * stands.
 *
 * The choice (gaits_foothold.h csg_footholdChoose) is made once per foothold, in the first
 * schedule evaluation at or past its lift time t; every evaluation within a step reads the
 * state at the step's start (the schedule stage and the pneumatic integrator run before the
 * legs and the support move), so the choice is a function of that state: a retried step
 * restores the state, the undecided latch with it, and decides again from the same state. The
 * latches are part of the state (sim_state.c), so cs_stateSet restores them bit for bit.
 * Footholds are applied in order, so where a chained one (the same legs' next step, gaits_
 * foothold.h) overlaps the earlier one's window, the later's columns hold.
 * Nothing is allocated here (the candidates' commands go through one stack array). */
#include <math.h>
#include <string.h>

#include "sim_internal.h"


csStatus cs_modelLoadFoothold(csModel* m, const char* path, csError* err) {
  if (!m->gait) {
    return cs_errorSet(err, CS_ERR_ARG, "--foothold %s: footholds need a gait table", path);
  }
  if (m->terrain.heading_deg != 0 || m->terrain.slope_deg != 0 || m->terrain.has_hf) {
    return cs_errorSet(err, CS_ERR_RANGE, "--foothold %s: footholds measure along the terrain's "
                       "x: the terrain %s must have heading 0, slope 0 and no heightfield", path,
                       m->terrain.source);
  }
  csgFootholdSet* s = csg_footholdRead(path, NULL, err);
  if (!s) {
    return err ? err->status : CS_ERR_PARSE;
  }
  /* a candidate holds only the rows around its change, and the row before them must stand
   * finished (gaits_schedule.h): so every change must end by the next row, the ramp fit the
   * rows (a longer --ramp reaches back before the slice) */
  for (int k = 0; k < s->n; k++) {
    for (int i = 0; i < s->fh[k].ncand; i++) {
      const csgGait* c = s->fh[k].cand[i].table;
      for (int r = 0; r + 1 < c->nrow; r++) {
        if (c->time[r + 1] - c->time[r] < m->sched.ramp - CSG_RAMP_ROUNDING) {
          double gap = c->time[r + 1] - c->time[r], t = c->time[r];
          csg_footholdDestroy(s); /* c is gone from here */
          return cs_errorSet(err, CS_ERR_RANGE, "--foothold %s: the ramp %g s is longer than "
                             "a candidate's rows (%.3g s at t = %g s): footholds need a ramp "
                             "that fits the rows", path, m->sched.ramp, gap, t);
        }
      }
    }
  }
  csg_footholdDestroy(m->foothold);
  m->foothold = s;
  /* the edges: x ends of every box standing above the lowest box top (the road) */
  double low = INFINITY;
  for (int b = 0; b < m->terrain.nbox; b++) {
    low = fmin(low, m->terrain.box[b].whi[1]);
  }
  m->fh_nedge = 0;
  for (int b = 0; b < m->terrain.nbox; b++) {
    const cstBox* x = &m->terrain.box[b];
    if (x->whi[1] > low) {
      m->fh_edge[m->fh_nedge++] = x->wlo[0];
      m->fh_edge[m->fh_nedge++] = x->whi[0];
    }
  }
  return CS_OK;
}


void cs_footholdApply(const csModel* m, csData* d, double t, double* p_cmd) {
  const csgFootholdSet* s = m->foothold;
  /* T, W0, W1 are table times: with a landing gate, the run's time less its hold (the
   * candidates' rows are held as the table's, sim_gate.c) */
  const double tt = cs_gateTableTime(m, d, t);
  for (int k = 0; k < s->n && tt >= s->fh[k].t; k++) {
    const csgFoothold* f = &s->fh[k];
    if (d->fh_choice[k] < 0) {
      double land[CSG_FOOTHOLD_MAX_CAND], lo[CSG_FOOTHOLD_MAX_CAND], hi[CSG_FOOTHOLD_MAX_CAND];
      double pos[3];
      for (int i = 0; i < f->ncand; i++) {
        land[i] = f->cand[i].land;
        lo[i] = f->cand[i].lo;
        hi[i] = f->cand[i].hi;
      }
      cs_supportDisplacement(d, pos);
      const int c = csg_footholdChoose(f->ncand, land, lo, hi, f->nominal, pos[0] - f->xplan,
                                       m->fh_edge, m->fh_nedge, f->margin);
      d->fh_choice[k] = c >= 0 ? c : f->nominal; /* -1 only for a non-finite support x */
    }
    if (tt < f->w0 || tt >= f->w1) {
      continue;
    }
    double pc[CSG_NLABEL];
    cs_gateEval(m, d, f->cand[(int)d->fh_choice[k]].table, t, pc);
    for (int leg = 0; leg < CSG_NLEG; leg++) {
      if (f->legs & (1u << leg)) {
        memcpy(p_cmd + 12 * leg, pc + 12 * leg, 12 * sizeof(double));
      }
    }
  }
}

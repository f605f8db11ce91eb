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
 * The chosen candidate's command is the table with its legs' rows replaced over the window
 * (gaits_foothold.h csg_footholdCompose), played through the same ramp and gate as the table:
 * the table's schedule plus, on the legs, the schedules of the candidate's composite less its
 * base. So any ramp works, a ramp longer than the rows included (the choice's changes arrive
 * as smeared as the table's and run up to one ramp past the window); a chained foothold's rows
 * hold from its W0 on (the composites are cut there), each foothold adding its own difference.
 * Nothing is allocated here (the commands go through stack arrays). */
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
  /* each candidate's command as the table with its rows (gaits_foothold.h): any ramp */
  csStatus st = csg_footholdCompose(s, m->gait, err);
  if (st != CS_OK) {
    csg_footholdDestroy(s);
    return st;
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
    /* the chosen rows' difference from the table's, S(comp) - S(base) on the legs: exactly 0
     * before W0 and from one ramp past the tail on (gaits_foothold.h), so skipped there; the
     * sum is the table with the chosen rows, a mean of commands >= 0 that rounding could put
     * a few 1e-17 MPa below 0 */
    if (tt < f->w0 || tt >= f->tail + m->sched.ramp) {
      continue;
    }
    const csgFootholdCand* c = &f->cand[(int)d->fh_choice[k]];
    double pc[CSG_NLABEL], pb[CSG_NLABEL];
    cs_gateEval(m, d, c->comp, t, pc);
    cs_gateEval(m, d, c->base, t, pb);
    for (int leg = 0; leg < CSG_NLEG; leg++) {
      if (f->legs & (1u << leg)) {
        for (int l = 12 * leg; l < 12 * leg + 12; l++) {
          p_cmd[l] = fmax(0.0, p_cmd[l] + (pc[l] - pb[l]));
        }
      }
    }
  }
}

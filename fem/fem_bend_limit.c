/* fem_bend_limit.c: the sweep's stage past a limit point or a bifurcation (fem_bend_run.h).
 *
 * Rationale. When a pressure step collapses, or a converged step shows a bifurcation (a
 * negative pivot more than the state before), the sweep hands the path to chamber-volume
 * control (csf_passLimit, fem_path.h), which also switches branches at a bifurcation. This file
 * watches that path state by state (angles for unwrapping, the inertia, the twin-chamber
 * asymmetry, the --until-angle target, the bifurcation's report) and decides how the sweep goes
 * on: resumed under pressure control, or ended with the reason. It was split from fem_bend.c
 * (850 lines) when branch switching was added. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem_bend_branch.h"
#include "fem_bend_run.h"
#include "fem_bend_wall.h"
#include "fem_path.h"

/* ---- stage: the path past a limit point ------------------------------------------------- */

/* The path's inertia in the run's summary: the most negative pivots, and the first converged
 * state (pressure p) whose tangent had any, with the last definite state before it. */
void csf_bendNoteInertia(csfBendInfo* info, int neg, double p, double p_last_definite) {
  info->neg_pivots_max = neg > info->neg_pivots_max ? neg : info->neg_pivots_max;
  if (neg > 0 && isnan(info->p_indefinite)) {
    info->p_indefinite = p;
    info->p_definite = p_last_definite;
  }
}


/* output rows one volume-controlled stretch can land; more are skipped (a stretch ends after
 * CSF_PATH_RISING rising states or past a limit; its volume steps grow to 8x the first: the
 * fibre-free short actuator of test_fem_bend at p_step 0.005 passed 8 output pressures; the leg
 * at 0.025, one). Scratch: (2 + this) states, ~1.3 MB each on the leg at l_soft 4 */
#define CSF_BEND_PASSED_ROWS 16

/* Per-state watcher of the volume-controlled path past a limit point (csf_passLimit callback):
 * tracks the angles (for unwrapping), the angles at the pressure maximum, reports progress, and
 * stops the path when the --until-angle target is reached. */
typedef struct {
  const csrActuator* act;
  const csfBendOptions* o;
  const csfGauges* gauges;
  const double* axis;
  double* ang_conv;                   /* [4] last angles: 3 segments, total (deg) */
  double a_limit, ang_limit[3], tip_limit[3]; /* at the pressure maximum */
  int until_hit; /* 1: target reached before the limit (stable state), 2: after it (in the snap) */
  double p_hit, a_hit, ang_hit[3], tip_hit[3];
  csfBendInfo* info;     /* the run's summary: the path's inertia (p_definite, p_indefinite) */
  double p_definite;     /* last state of the path so far with a positive definite tangent */
  const double (*ratio)[CSR_NCHAMBER]; /* (3 x 4) chamber pressure ratios: twin asymmetry */
  double amp;            /* branch perturbation, mm (for the report) */
  int on_branch;         /* the sweep was on a switched branch already */
  int neg_last;          /* negative pivots of the last state reported */
  double hist_p[8], hist_a[8]; /* the last states' pressures and total angles (ring) */
  int nhist;
  /* output pressures the path passes while rising (rowsOnRisingPath): each one's state
   * interpolated linearly in p between the two path states that bracket it */
  size_t ns;             /* state length */
  double* s_last;        /* (ns) the path's previous state, at pressure p_last */
  double* s_cur;         /* (ns) the state just reported (swapped with s_last) */
  double p_last;
  int k_next;            /* next output row index (Run.k_out's numbering) */
  int nrow;
  double p_row[CSF_BEND_PASSED_ROWS];
  double* s_row[CSF_BEND_PASSED_ROWS]; /* (ns each) */
} LimitWatch;

/* total angle of the recent path state at pressure p (the bifurcating state), NAN if not kept */
static double watchAngleAt(const LimitWatch* lw, double p) {
  for (int k = 0; k < lw->nhist && k < 8; k++) {
    if (lw->hist_p[k] == p) {
      return lw->hist_a[k];
    }
  }
  return NAN;
}


/* output row k exists: the one before it lies below p_max */
static int outputExists(const csfBendOptions* o, int k) {
  return (k - 1) * o->p_step < o->p_max - 1e-9 * o->p_step;
}


/* the output pressures between the path's previous state and the one in d (pressure p): their
 * interpolated states are kept while the path rises; a branch switch (no path in between)
 * passes them */
static void capturePassedRows(LimitWatch* lw, const csfModel* m, const csfData* d, double p,
                              int branch_state) {
  const csfBendOptions* o = lw->o;
  const double eps = 1e-9 * o->p_step;
  csf_stateGet(m, d, lw->s_cur);
  while (outputExists(o, lw->k_next) && csf_bendOutputPressure(o, lw->k_next) <= p + eps) {
    const double pg = csf_bendOutputPressure(o, lw->k_next);
    if (!branch_state && p > lw->p_last && pg >= lw->p_last - eps &&
        lw->nrow < CSF_BEND_PASSED_ROWS) {
      const double f = (pg - lw->p_last) / (p - lw->p_last);
      double* s = lw->s_row[lw->nrow];
      for (size_t i = 0; i < lw->ns; i++) {
        s[i] = lw->s_last[i] + f * (lw->s_cur[i] - lw->s_last[i]);
      }
      lw->p_row[lw->nrow++] = pg;
    }
    lw->k_next++;
  }
  double* t = lw->s_last; /* the state just reported is the next one's previous */
  lw->s_last = lw->s_cur;
  lw->s_cur = t;
  lw->p_last = p;
}


static int limitWatch(void* user, const csfModel* m, const csfData* d, const csfPathPoint* pt) {
  LimitWatch* lw = user;
  capturePassedRows(lw, m, d, pt->p, pt->branch == 2);
  double ang[3], tot, tip[3];
  csf_bendMeasure(lw->act, lw->gauges, m, d, lw->axis, lw->ang_conv, ang, &tot, tip);
  lw->ang_conv[0] = ang[0], lw->ang_conv[1] = ang[1], lw->ang_conv[2] = ang[2];
  lw->ang_conv[3] = tot;
  /* the inertia along the volume path too: a negative pivot while the pressure still rises is a
   * bifurcation of the path (pressure control would leave it), past a maximum a limit point */
  const int neg = csf_linSolverNegativePivots(d->ls);
  csf_bendNoteInertia(lw->info, neg, pt->p, lw->p_definite);
  if (neg == 0) {
    lw->p_definite = pt->p;
  }
  if (pt->is_max) {
    lw->a_limit = tot;
    memcpy(lw->ang_limit, ang, sizeof ang);
    memcpy(lw->tip_limit, tip, sizeof tip);
  }
  double asym[CSR_NSEG];
  csfBendStep rep = {pt->p, pt->dp, pt->newton_iters, 0, pt->wall, tot, {ang[0], ang[1], ang[2]},
                     1, pt->volume, neg, pt->branch ? pt->branch : lw->on_branch,
                     csf_bendChamberAsymmetry(m, d, lw->ratio, asym), NULL, NAN, NAN, NAN,
                     NAN};
  csf_bendNoteWall(m, d, lw->ratio, pt->p, tot, lw->info, &rep);
  if (pt->branch == 2 && pt->result) {
    /* the branch switch: what broke, and where the path went */
    csfBendInfo* info = lw->info;
    info->n_bifurcation++;
    info->branch_switched = 1;
    info->p_bifurcation = pt->result->p_bif;
    info->angle_bifurcation = watchAngleAt(lw, pt->result->p_bif);
    csf_bendBifurcationNote(lw->act, pt->result, info->angle_bifurcation, lw->amp, rep.asym,
                            info->bifurcation_note, sizeof info->bifurcation_note);
    rep.note = info->bifurcation_note;
  }
  lw->hist_p[lw->nhist % 8] = pt->p, lw->hist_a[lw->nhist % 8] = tot;
  lw->nhist++;
  lw->neg_last = neg;
  if (lw->o->progress) {
    lw->o->progress(lw->o->progress_user, &rep);
  }
  if (isfinite(lw->o->until_angle) && tot >= lw->o->until_angle) {
    lw->until_hit = pt->past_limit ? 2 : 1;
    lw->p_hit = pt->p, lw->a_hit = tot;
    memcpy(lw->ang_hit, ang, sizeof ang);
    memcpy(lw->tip_hit, tip, sizeof tip);
    return 1;
  }
  return 0;
}


/* Rows at the output pressures a rising volume-controlled stretch passed (stageLimit), up to
 * r->p: each is solved under pressure control from its state interpolated along the path
 * (capturePassedRows); one with no such state (past CSF_BEND_PASSED_ROWS, or across a branch
 * switch) or whose solve fails is counted in n_rows_skipped. d is left at s_conv. */
static csStatus rowsOnRisingPath(Run* r, const LimitWatch* lw, csError* err) {
  const csfBendOptions* o = r->o;
  csfModel* m = r->w.fe.model;
  csfData* d = r->w.data;
  const double eps = 1e-9 * o->p_step;
  csStatus st = CS_OK;
  while (st == CS_OK && outputExists(o, r->k_out) &&
         csf_bendOutputPressure(o, r->k_out) <= r->p + eps) {
    const double pg = csf_bendOutputPressure(o, r->k_out);
    int k = 0;
    while (k < lw->nrow && fabs(lw->p_row[k] - pg) > eps) {
      k++;
    }
    int it = 0;
    csError lerr = {0};
    if (k < lw->nrow) {
      csf_stateSet(m, d, lw->s_row[k]);
    }
    if (k < lw->nrow && csf_newtonSolve(m, d, pg, &r->nopt, &it, &lerr) == CS_OK) {
      double ang[3], tot, tip[3];
      csf_bendMeasure(r->act, r->w.fe.gauges, m, d, r->w.fe.axis, r->ang_conv, ang, &tot, tip);
      st = csf_bendStageRow(r, pg, ang, tot, tip, err);
      if (st == CS_OK && pg >= o->p_max - eps && r->p > o->p_max + eps) {
        /* the path ran past the sweep's end: the sweep ends on its last row (the final state
         * the VTU and the summary describe), not beyond p_max */
        csf_stateGet(m, d, r->w.s_conv);
        r->p = pg;
        r->ang_conv[0] = ang[0], r->ang_conv[1] = ang[1], r->ang_conv[2] = ang[2];
        r->ang_conv[3] = tot;
      }
    } else {
      r->info.n_rows_skipped++;
    }
    r->info.n_newton += it;
    r->k_out++;
  }
  csf_stateSet(m, d, r->w.s_conv);
  return st;
}


/* csf_bendStageLimit with `keep`, (2 + CSF_BEND_PASSED_ROWS) x ns doubles of scratch for the
 * rows the path passes (LimitWatch) */
static int followByVolume(Run* r, double* keep, csStatus* st, csError* err) {
  const csfBendOptions* o = r->o;
  csfModel* m = r->w.fe.model;
  csfData* d = r->w.data;
  csError lerr = {0};
  LimitWatch lw;
  memset(&lw, 0, sizeof lw);
  lw.act = r->act, lw.o = o, lw.gauges = r->w.fe.gauges, lw.axis = r->w.fe.axis;
  lw.ang_conv = r->ang_conv;
  lw.info = &r->info;
  lw.p_definite = r->p;
  lw.ratio = (const double(*)[CSR_NCHAMBER])o->spec.ratio;
  lw.on_branch = r->on_branch;
  lw.neg_last = r->neg_conv;
  lw.hist_p[0] = r->p, lw.hist_a[0] = r->ang_conv[3], lw.nhist = 1; /* the entry state */
  /* the rows the path may pass: the entry state first (its own row, if any, is written) */
  lw.ns = r->ns;
  lw.p_last = r->p;
  lw.k_next = r->k_out;
  lw.s_last = keep, lw.s_cur = keep + r->ns;
  for (int k = 0; k < CSF_BEND_PASSED_ROWS; k++) {
    lw.s_row[k] = keep + (2 + k) * r->ns;
  }
  memcpy(lw.s_last, r->w.s_conv, r->ns * sizeof(double));
  const int forced = r->volume_forced == 1;
  if (forced) {
    r->volume_forced = 2;
  }
  csf_stateSet(m, d, r->w.s_conv);
  csf_bendMeasure(r->act, r->w.fe.gauges, m, d, r->w.fe.axis, r->ang_conv, lw.ang_limit,
                  &lw.a_limit, lw.tip_limit);
  csfLimitOptions lopt = csf_limitDefault();
  /* the sweep ends after four halvings of a failing volume step (each failure is a stagnated
   * Newton solve, 13-20 iterations on the leg: a 1e-4 collapse took 13 halvings) */
  lopt.min_dv_rel = 1.0 / 16.0;
  lopt.callback = limitWatch;
  lopt.user = &lw;
  lopt.branch_switch = o->branch_switch && !r->on_branch; /* one switch per sweep */
  lopt.critical_mode = !r->info.bifurcation_note[0]; /* the first bifurcation's mode, always */
  if (o->branch_amp > 0) {
    lopt.branch_amp = o->branch_amp;
  }
  lw.amp = lopt.branch_amp;
  lopt.neg_prev = r->neg_prev, lopt.neg_conv = r->neg_conv;
  csfLimitResult lr;
  const csStatus lst = csf_passLimit(m, d, r->w.s_prev, r->w.s_conv, r->w.s_tmp, r->V_prev,
                                     r->V_conv, r->p, &r->nopt, &lopt, &lr, &lerr);
  r->info.n_newton += lr.n_newton;
  r->info.n_volume_steps += lr.n_steps;
  r->on_branch |= lr.switched;
  r->neg_prev = r->neg_conv = lw.neg_last;
  if (lr.n_bifurcation > 0 && !lr.switched && !r->info.bifurcation_note[0]) {
    /* a bifurcation without an accepted branch: reported all the same */
    r->info.n_bifurcation += lr.n_bifurcation;
    r->info.p_bifurcation = lr.p_bif;
    r->info.angle_bifurcation = watchAngleAt(&lw, lr.p_bif);
    csf_bendBifurcationNote(r->act, &lr, r->info.angle_bifurcation, lw.amp, NAN,
                            r->info.bifurcation_note, sizeof r->info.bifurcation_note);
  }
  if (!lr.no_limit) {
    /* this episode is the sweep's latest limit: an earlier resume no longer describes it */
    r->info.p_limit = lr.p_limit;
    r->info.angle_limit = lw.a_limit;
    r->info.p_resume = r->info.angle_resume = NAN;
    r->info.limit_shown = lr.fell;
  }
  r->p = d->load;
  const double V_end = d->vol_w; /* the last converged state's volume (d is reused below) */
  if (lst == CS_OK && lr.stopped) {
    /* the target angle: before the limit the state at p_hit is an equilibrium, not refined;
     * after it a pressure-controlled load reaches the angle by snapping at p_limit */
    const int snap = lw.until_hit == 2;
    if (snap || fabs(lw.a_hit - o->until_angle) <= o->angle_tol) {
      r->out->p_until_angle = snap ? lr.p_limit : lw.p_hit;
    }
    snprintf(r->info.until_note, sizeof r->info.until_note,
             snap ? "reached in the snap-through at the limit pressure %.6g MPa (%.2f deg "
                    "at the limit, %.2f deg on the volume-controlled path)"
                  : "passed under volume control below the limit (%.6g MPa so far; %.2f "
                    "deg there, %.2f deg): not refined",
             lr.p_limit, lw.a_limit, lw.a_hit);
    *st = csf_bendStageRow(r, snap ? lr.p_limit : lw.p_hit, snap ? lw.ang_limit : lw.ang_hit,
                   snap ? lw.a_limit : lw.a_hit, snap ? lw.tip_limit : lw.tip_hit, err);
    return 1;
  }
  if (lst != CS_OK) {
    snprintf(r->info.limit_note, sizeof r->info.limit_note, "%.190s", lerr.msg);
    return 1; /* no stable branch found: the sweep ends at the last volume-controlled state */
  }
  if (lr.no_limit) {
    /* a hard stretch, not a limit point (or one asked for, csfBendOptions.volume_from): every
     * state of the volume path is stable under pressure control, so each output pressure it
     * passed gets its row, solved under pressure control from the state interpolated along
     * the path (rowsOnRisingPath) */
    r->info.n_hard_passed += !forced;
    *st = rowsOnRisingPath(r, &lw, err);
    if (*st != CS_OK) {
      return 1;
    }
  } else {
    /* stable again above the limit: output pressures passed in the snap are skipped (no
     * stable state there) */
    r->info.p_resume = lr.p_resume;
    r->info.angle_resume = r->ang_conv[3];
  }
  /* resume pressure control from the volume path's last two states */
  r->V_prev = r->V_conv = V_end;
  r->p_prev = lr.p_before;
  r->have_prev = r->p > r->p_prev;
  r->have_pp = 0; /* the volume path's states are not on the pressure-controlled branch */
  memcpy(r->ang_prev, r->ang_conv, sizeof r->ang_prev);
  while (r->k_out * o->p_step <= r->p + 1e-9 * o->p_step) {
    r->k_out++;
    r->info.n_rows_skipped += !lr.no_limit;
  }
  r->dp = 0.25 * o->p_step;
  return 0;
}


/* Follow the path by chamber volume from the collapsed step. Returns 1 when the sweep ends
 * there (no stable branch, or the until-angle was met on the path; *st carries a row error),
 * 0 when it resumes under pressure control (r's state updated to the path's last two states). */
int csf_bendStageLimit(Run* r, csStatus* st, csError* err) {
  double* keep = malloc((2 + CSF_BEND_PASSED_ROWS) * r->ns * sizeof(double));
  if (!keep) {
    *st = cs_errorSet(err, CS_ERR_MEMORY, "fem: out of memory for the volume-controlled path");
    return 1;
  }
  const int end = followByVolume(r, keep, st, err);
  free(keep);
  return end;
}

/* fem_bend_run.h: the running state of one csf_bend sweep, shared by its stages (internal to
 * fem/: fem_bend.c has the sweep and its pressure-controlled stages, fem_bend_limit.c the stage
 * past a limit point or a bifurcation). Units: MPa, mm^3, degrees, seconds. */
#ifndef CS_FEM_BEND_RUN_H
#define CS_FEM_BEND_RUN_H

#include <math.h>
#include <stddef.h>

#include "fem_bend.h"

#ifdef __cplusplus
extern "C" {
#endif

/* everything a sweep owns, freed in one place */
typedef struct {
  csfActuatorFE fe;
  csfData* data;
  double* s_conv; /* (csf_stateSize) last converged state */
  double* s_prev; /* (csf_stateSize) the converged state before it */
  double* s_pp;   /* (csf_stateSize) the converged state before s_prev (quadratic predictor) */
  double* s_tmp;  /* (csf_stateSize) scratch */
  double* s_row;  /* (csf_stateSize) scratch: a row's state while its probes run */
} Sweep;

/* the running state of one sweep, passed to every stage */
typedef struct {
  const csrActuator* act;
  const csfBendOptions* o;
  csrBendCurve* out;
  csfBendInfo info;
  Sweep w;
  csfNewtonOptions nopt;
  size_t ns;                    /* state length (csf_stateSize) */
  double p, p_prev, dp;         /* converged pressure, the one before, next step (MPa) */
  double p_pp;                  /* pressure of s_pp */
  double a_pp;                  /* total angle of s_pp (deg) */
  double V_conv, V_prev;        /* weighted chamber volumes of s_conv and s_prev */
  double ang_conv[4], ang_prev[4]; /* angles (3 segments, total; deg) of s_conv, s_prev */
  int k_out;                    /* next output row index: pressure k_out p_step */
  int have_prev;                /* s_prev is a converged state below s_conv */
  int have_pp;                  /* s_pp is a converged state below s_prev (same branch) */
  int n_hard;                   /* accepted steps in a row that needed cut-backs */
  int neg_conv, neg_prev;       /* negative pivots of s_conv and s_prev (-1: unknown) */
  int on_branch;                /* 1: past a branch switch (csfBendStep.branch) */
  int volume_forced;            /* csfBendOptions.volume_from: 0 not yet, 1 the stretch asked
                                 * (stageStep), 2 done */
  double t_start;
} Run;

/* Output pressure k of a sweep (Run.k_out's numbering: k p_step, the last one p_max), MPa: the
 * one rule the stepping (fem_bend.c) and the volume path (fem_bend_limit.c) land rows on. */
static inline double csf_bendOutputPressure(const csfBendOptions* o, int k) {
  return fmin(k * o->p_step, o->p_max);
}

/* Append a row to the curve (and to the record, with probes where asked) at the converged
 * state in r's data (fem_bend.c). */
csStatus csf_bendStageRow(Run* r, double p, const double ang[3], double tot, const double tip[3],
                          csError* err);

/* The path's inertia in the run's summary (fem_bend_limit.c): the most negative pivots, and the
 * first converged state (pressure p) whose tangent had any, with the last definite state before
 * it. */
void csf_bendNoteInertia(csfBendInfo* info, int neg, double p, double p_last_definite);

/* Follow the path by chamber volume from s_conv (a collapsed pressure step, or a bifurcation;
 * fem_bend_limit.c). Returns 1 when the sweep ends there (no stable branch, or the until-angle
 * was met on the path; *st carries a row error), 0 when it resumes under pressure control (r's
 * state updated to the path's last two states). */
int csf_bendStageLimit(Run* r, csStatus* st, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_BEND_RUN_H */

/* fem_bend.c: pressure sweep of the FE actuator as named stages (see fem_bend.h).
 *
 * Rationale.
 * Stages: set-up (the actuator's FE model, fem_actuator.h; data; state buffers), dead-load ramp
 * (gravity, tip force),
 * then per step: a pressure step with cut-backs, the limit-point path when a step collapses or
 * a bifurcation shows (fem_bend_limit.c, with the branch switch),
 * the refinement of --until-angle, an output row (with optional stiffness probes), step control;
 * finally the outputs (VTU, deck) and the summary.
 * Load stepping: pressure control with a secant predictor (s_pred = s_n + dp/dp_prev (s_n -
 * s_n-1) on the whole Newton state), which follows the large rotations of a 360 deg bend with
 * few Newton iterations; the step halves on divergence and grows by 1.5 after easy steps
 * (CSF_BEND_GROW_ITERS), capped at p_step so that every output pressure is hit exactly. The
 * first step from the unloaded state is p_first: the linearised step from u = 0 rotates the
 * chamber walls without bending them, and larger first steps only fail. A step that collapses below
 * CSF_BEND_DP_MIN_REL p_step is taken as a limit point of the pressure-controlled path: the path
 * is then followed by chamber-volume control (csf_passLimit, fem_path.h) through the pressure
 * maximum, which is reported as p_limit; where the pressure rises above it again the sweep
 * resumes under pressure control (a pressure-controlled actuator snaps across), else it ends.
 * --until-angle: once a step crosses the target angle, the crossing is bracketed by two
 * converged states and refined by safeguarded regula falsi, each trial an equilibrium solve, to
 * |angle - target| <= angle_tol: the reported pressure is an equilibrium, not an extrapolation.
 * Stiffness probes: at the requested output rows, an extra dead tip force along each base axis
 * is solved from the row's converged state and the state restored afterwards; the changes of the
 * segments' bend and stretch are the leg's compliance there (fem_calibration.h reduces them). */
#include "fem_bend.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "core_text.h"
#include "fem_bend_branch.h"
#include "fem_bend_run.h"
#include "fem_bend_wall.h"
#include "fem_output.h"
#include "fem_path.h"

#define CSF_BEND_DP_MIN_REL 1e-3 /* smallest step, relative to p_step, before "limit point" */
/* a hard stretch of the pressure path: CSF_BEND_HARD_STEPS accepted steps in a row that each
 * needed cut-backs, with the step down to CSF_BEND_HARD_DP_REL p_step, is handed to the
 * volume-controlled path (which resumes pressure control where the path is easy again). Measured
 * on the leg, Omega1&Omega2 at 0.19 MPa (135 deg): Newton stagnates at |R| ~ 0.05 N of 36 N for
 * steps above ~1e-3 MPa while steps of 2-6e-4 MPa converge in 2-3 iterations, so halving down
 * to CSF_BEND_DP_MIN_REL crept 1e-4 MPa per 3-6 minutes (40-iteration failed attempts). */
#define CSF_BEND_HARD_STEPS 2
#define CSF_BEND_HARD_DP_REL 0.25
/* a step that would end within this fraction of itself below an output pressure is stretched to
 * it (measured: a 0.0002 MPa sliver step after a 0.0166 step cost 3 Newton iterations, 22 s) */
#define CSF_BEND_SNAP 0.25
#define CSF_BEND_FIRST_REL 0.25 /* default first step, relative to p_step */
/* Newton's convergence test in a sweep: |R| <= 1e-6 (|f_int| + |f_ext|). Newton converges
 * quadratically at the end (|R| 2e-7 -> 6e-11 N, 7e-7 -> 1e-10 on the short leg), so 1e-8
 * bought one more iteration per step (one factorisation in seven) for a displacement change
 * of order |K^-1 R|; measured: the short leg's angles and tip at 0.1 MPa agree to every
 * printed digit (1e-3 deg, 1e-3 mm) between 1e-8 and 1e-6, and the baseline's 360 deg
 * pressure to 0.01 % (fem/README.md "The 360 deg run").
 * The element and patch tests keep csf_newtonDefault's 1e-8. */
#define CSF_BEND_NEWTON_RTOL 1e-6
/* step control by Newton iterations: grow by 1.5 after <= CSF_BEND_GROW_ITERS, shrink by 0.7
 * after > CSF_BEND_SHRINK_ITERS. With the tension-only fibres the count hardly depends on the
 * step: most fibres sit in the law's smoothing zone (|E| < 5e-4, S'' = 1000), whose curvature,
 * not the load increment, sets Newton's pre-asymptotic phase. Measured on the baseline leg
 * (l_soft 4, Omega1&Omega2): 12 iterations at 0.0125 MPa steps, 13 at 0.019, 14-16 at
 * 0.022-0.031; on the short leg 6-8 at 0.006 and at 0.02 MPa alike. Growing only after <= 5
 * (the rule of the 20-node ties) kept the steps at 0.004-0.007 MPa: the 360 deg run took 66
 * steps, 565 iterations; with 12 / 16: fem/README.md "The 360 deg run". */
#define CSF_BEND_GROW_ITERS 12
#define CSF_BEND_SHRINK_ITERS 16

csfBendOptions csf_bendDefault(void) {
  csfBendOptions o;
  memset(&o, 0, sizeof o);
  o.spec = csf_actuatorSpecDefault();
  o.p_max = 0.4;
  o.p_step = 0.05;
  o.p_first = 0.0;
  o.until_angle = NAN;
  o.angle_tol = 0.1;
  o.continuation = 1;
  o.branch_switch = 0;
  o.krylov = 0;
  o.symmetric = -1;
  o.newton_rtol = CSF_BEND_NEWTON_RTOL;
  return o;
}


csStatus csf_bendSetChambers(csfBendOptions* opts, const char* list, csError* err) {
  unsigned mask = 0;
  csStatus st = csu_chamberListParse(list, CSR_NCHAMBER, "--chambers", &mask, err);
  if (st != CS_OK) {
    return st;
  }
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      opts->spec.ratio[s][j] = (mask >> j) & 1u ? 1.0 : 0.0;
    }
  }
  return CS_OK;
}


static void sweepFree(Sweep* w) {
  csf_dataDestroy(w->data);
  csf_actuatorFEDestroy(&w->fe);
  free(w->s_conv);
  free(w->s_prev);
  free(w->s_pp);
  free(w->s_tmp);
  free(w->s_row);
}




/* ---- stage: set-up --------------------------------------------------------------------- */

static csStatus stageSetup(Run* r, csError* err) {
  const csfBendOptions* o = r->o;
  const double t0 = csf_wallTime();
  csfActuatorSpec spec = o->spec;
  csStatus st = csf_actuatorFECreate(r->act, &spec, &r->w.fe, err);
  if (st != CS_OK) {
    return st;
  }
  r->info.t_mesh = csf_wallTime() - t0; /* meshing dominates; the model follows */
  const double* g = o->spec.gravity;
  const double* F = o->spec.tip_force;
  if (r->w.fe.ncham == 0 && g[0] == 0 && g[1] == 0 && g[2] == 0 && F[0] == 0 && F[1] == 0 &&
      F[2] == 0) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_bend: no chamber is pressurised and no load given");
  }
  r->w.fe.model->solver.symmetric = o->symmetric;
  r->w.fe.model->solver.max_threads = o->threads;
  r->w.fe.model->solver.ranks = o->spec.mpi_ranks > 1 ? o->spec.mpi_ranks : 1;
  const csfModel* m = r->w.fe.model;
  r->w.data = csf_dataCreate(m, err);
  r->ns = csf_stateSize(m);
  r->w.s_conv = calloc(r->ns, sizeof(double));
  r->w.s_prev = calloc(r->ns, sizeof(double));
  r->w.s_pp = calloc(r->ns, sizeof(double));
  r->w.s_tmp = calloc(r->ns, sizeof(double));
  r->w.s_row = calloc(r->ns, sizeof(double));
  if (!r->w.data) {
    return err && err->status ? err->status : CS_ERR_MEMORY;
  }
  if (!r->w.s_conv || !r->w.s_prev || !r->w.s_pp || !r->w.s_tmp || !r->w.s_row) {
    /* found by the fault suite: this failure came back with an empty message */
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_bend: out of memory for the state copies (5 x %zu "
                       "values)", (size_t)r->ns);
  }
  r->info.ntet = r->w.fe.mesh->ntet, r->info.nnode = r->w.fe.mesh->nnode;
  r->info.nfibre = m->nfib, r->info.ndof = m->ndof;
  r->info.nfibre_projected = m->fib_projected;
  r->info.t_setup = csf_wallTime() - t0 - r->info.t_mesh;
  r->nopt = csf_newtonDefault();
  r->nopt.threads = o->threads;
  r->nopt.krylov = o->krylov;
  r->nopt.line_search = o->line_search;
  r->nopt.monitor = o->newton_monitor;
  r->nopt.monitor_user = o->progress_user;
  if (o->newton_rtol > 0) {
    r->nopt.rtol = o->newton_rtol;
  }
  r->nopt.max_iter = 40; /* slender body: Newton crosses flat energy valleys (measured up to 12) */
  return CS_OK;
}


/* ---- stage: dead-load ramp ------------------------------------------------------------- */

/* the dead loads (gravity, a tip force) alone at p = 0, ramped in factor gamma (m->gravity =
 * gamma g, the tip force gamma F) with the load stepping's rules, so that the p = 0 row is the
 * equilibrium under them: a soft leg under its full weight in one step does not converge (the
 * leg at 9.81 m/s^2, fem/README.md), and without the ramp a tip force entered only with the
 * first pressure step, the p = 0 row being the unloaded reference state (measured on the leg,
 * 0.05 N along e1: its tip undeflected at p = 0, where the load bends it 25 mm) */
static csStatus stageDeadLoads(Run* r, csError* err) {
  const double* g = r->o->spec.gravity;
  const double* F = r->o->spec.tip_force;
  if (g[0] == 0 && g[1] == 0 && g[2] == 0 && F[0] == 0 && F[1] == 0 && F[2] == 0) {
    return CS_OK;
  }
  csfModel* m = r->w.fe.model;
  csfData* d = r->w.data;
  csError lerr = {0};
  double gam = 0.0, dgam = 1.0;
  while (gam < 1.0) {
    const double next = fmin(gam + dgam, 1.0);
    const double Fn[3] = {next * F[0], next * F[1], next * F[2]};
    for (int i = 0; i < 3; i++) {
      m->gravity[i] = next * g[i];
    }
    csf_actuatorSetTipForce(&r->w.fe, Fn);
    int it = 0;
    const csStatus gst = csf_newtonSolve(m, d, 0.0, &r->nopt, &it, &lerr);
    r->info.n_newton += it;
    if (gst == CS_OK) {
      gam = next;
      r->info.n_gravity_steps++;
      if (it <= 5) {
        dgam *= 1.5;
      }
    } else if ((dgam *= 0.5) < 1e-3) {
      csf_actuatorSetTipForce(&r->w.fe, F);
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem_bend: no equilibrium under the dead loads "
                         "(gravity, tip force) beyond %.4g of their value: %s", gam, lerr.msg);
    }
  }
  return CS_OK;
}


/* ---- stage: output row (and its stiffness probes) ---------------------------------------- */

static int wantsProbe(const csfBendOptions* o, double p) {
  for (int k = 0; k < o->nprobe_p; k++) {
    if (fabs(p - o->probe_p[k]) <= 1e-9 * o->p_step) {
      return 1;
    }
  }
  return 0;
}


/* the probes of a row at the converged state in d: each from that state, restored after. The
 * row and its probes are solved to csf_newtonDefault's 1e-8: a probe's response is the
 * difference of two equilibria under a force (5e-3 N) that the sweep's tolerance (1e-6 of a
 * 36 N force scale) would blur by up to 1 % */
static void runProbes(Run* r, csfBendRow* row) {
  csfActuatorFE* fe = &r->w.fe;
  csfModel* m = fe->model;
  csfData* d = r->w.data;
  csfNewtonOptions strict = r->nopt;
  strict.rtol = csf_newtonDefault().rtol;
  {
    int it = 0;
    csError lerr = {0};
    (void)csf_newtonSolve(m, d, row->p, &strict, &it, &lerr); /* restores d on failure */
    r->info.n_newton += it;
    r->info.n_probe_newton += it;
  }
  csf_stateGet(m, d, r->w.s_row);
  const double* F0 = r->o->spec.tip_force;
  row->nprobe = 3;
  for (int k = 0; k < 3; k++) {
    row->probe_ok[k] = 0;
    memset(row->probe_force[k], 0, sizeof row->probe_force[k]);
    if (!(r->o->probe_force[k] > 0)) {
      continue;
    }
    /* the probe force, or a quarter of it when Newton fails from the row's state (the
     * compliance is linear in these forces; the force actually used is recorded) */
    for (int attempt = 0; attempt < 2 && !row->probe_ok[k]; attempt++) {
      const double Fk = r->o->probe_force[k] * (attempt ? 0.25 : 1.0);
      double F[3] = {F0[0], F0[1], F0[2]};
      F[k] += Fk;
      csf_actuatorSetTipForce(fe, F);
      int it = 0;
      csError lerr = {0};
      if (csf_newtonSolve(m, d, row->p, &strict, &it, &lerr) == CS_OK) {
        double R[9];
        row->probe_ok[k] = csf_segmentMeasure(r->act, fe->gauges, m, d, row->probe_seg[k],
                                              row->probe_tip[k], R) == 0;
        row->probe_force[k][k] = Fk;
      }
      r->info.n_newton += it;
      r->info.n_probe_newton += it;
      csf_stateSet(m, d, r->w.s_row);
    }
  }
  csf_actuatorSetTipForce(fe, F0);
}


/* append a row to the curve (and to the record, with probes where asked) */
csStatus csf_bendStageRow(Run* r, double p, const double ang[3], double tot,
                          const double tip[3], csError* err) {
  csStatus st = csr_bendCurvePush(r->out, p, ang, tip, err);
  if (st != CS_OK) {
    return st;
  }
  r->out->angle_total[r->out->m - 1] = tot; /* base-to-tip rotation, joints included */
  csfBendRecord* rec = r->o->record;
  if (!rec || rec->m >= rec->cap) {
    return CS_OK;
  }
  csfBendRow* row = rec->row + rec->m;
  memset(row, 0, sizeof *row);
  row->p = p;
  row->angle_total = tot;
  if (csf_segmentMeasure(r->act, r->w.fe.gauges, r->w.fe.model, r->w.data, row->seg, row->tip,
                         row->Rtip) != 0) {
    return cs_errorSet(err, CS_ERR_DIVERGED, "fem_bend: degenerate face frame at %.5g MPa", p);
  }
  if (wantsProbe(r->o, p)) {
    runProbes(r, row);
  }
  rec->m++;
  return CS_OK;
}


/* ---- stage: one pressure step ------------------------------------------------------------ */

/* One converged step from r->p towards the next output pressure, cutting back on failure.
 * Returns 1 when converged (d at *target), 0 when the step collapsed below the minimum (a limit
 * point; d restored to s_conv only by the caller's choice). */
/* --until-angle: when the last three converged states predict the target angle inside the
 * coming step, the step ends at the predicted crossing instead (aimed CSF_BEND_UNTIL_AIM
 * angle_tol past the target), so it lands within angle_tol and no refinement trial follows.
 * The prediction is inverse quadratic interpolation, p as a quadratic in the total angle
 * through (a_pp, p_pp), (a_prev, p_prev), (a_conv, p): its error is third order in the step.
 * Why: stepping on to the next regular pressure overshoots, and the refinement then solves
 * the bracket again: on the baseline 360 deg run that last step cost a cut-back and another
 * equilibrium solve (docs/notes/code_measurements.md "FE bend: the step that lands on the
 * target angle"). Returns the step's (possibly shortened) target pressure. */
#define CSF_BEND_UNTIL_AIM 0.5
static double untilTarget(const Run* r, double target) {
  const csfBendOptions* o = r->o;
  if (!isfinite(o->until_angle) || !r->have_pp || !(r->p > r->p_prev && r->p_prev > r->p_pp)) {
    return target;
  }
  const double x0 = r->a_pp, x1 = r->ang_prev[3], x2 = r->ang_conv[3];
  if (!(x2 > x1 && x1 > x0) || !(x2 < o->until_angle)) {
    return target; /* the angle not rising steadily: no prediction */
  }
  const double a = o->until_angle + CSF_BEND_UNTIL_AIM * o->angle_tol;
  /* only where the secant through the last two states already reaches the target within the
   * step: far from it a quadratic in the angle extrapolates wildly (measured: at 94 of 360 deg
   * it cut a 0.028 MPa step to 0.009) */
  if (!(x2 + (x2 - x1) / (r->p - r->p_prev) * (target - r->p) >= a)) {
    return target;
  }
  const double l0 = (a - x1) * (a - x2) / ((x0 - x1) * (x0 - x2));
  const double l1 = (a - x0) * (a - x2) / ((x1 - x0) * (x1 - x2));
  const double l2 = (a - x0) * (a - x1) / ((x2 - x0) * (x2 - x1));
  const double pc = l0 * r->p_pp + l1 * r->p_prev + l2 * r->p;
  return pc > r->p && pc < target ? pc : target;
}


static int stageStep(Run* r, double* target_out, int* iters, int* cut) {
  const csfBendOptions* o = r->o;
  csfModel* m = r->w.fe.model;
  csfData* d = r->w.data;
  const double dp_min = CSF_BEND_DP_MIN_REL * o->p_step;
  csError lerr = {0};
  *cut = 0;
  if (r->n_hard >= CSF_BEND_HARD_STEPS && r->dp < CSF_BEND_HARD_DP_REL * o->p_step) {
    r->n_hard = 0;
    return 0; /* a hard stretch of the path: follow it by volume (CSF_BEND_HARD_STEPS) */
  }
  if (o->volume_from > 0 && o->continuation && r->volume_forced == 0 && r->have_prev &&
      r->p >= o->volume_from - 1e-9 * o->p_step) {
    r->volume_forced = 1;
    return 0; /* a volume-controlled stretch asked for (csfBendOptions.volume_from) */
  }
  int plain = 0; /* 1: this attempt starts from s_conv (the first Newton step is the tangent
                  * predictor) */
  for (;;) {
    const double next_out = csf_bendOutputPressure(o, r->k_out);
    double target = fmin(r->p + r->dp, next_out);
    if (next_out - target < CSF_BEND_SNAP * r->dp) {
      target = next_out; /* no sliver step just before an output pressure */
    }
    target = untilTarget(r, target);
    /* predictor on the whole state (u, element dilatations, fibre stresses): quadratic
     * (Lagrange) through the last three converged states, or secant through two; after a
     * failed extrapolated attempt the same step is tried once from s_conv, whose first Newton
     * step is the tangent predictor: near a bifurcation of the symmetric path a soft mode grows
     * fast with p, which the tangent sees and an extrapolation of past states does not.
     * Measured and not kept: a guard that starts from s_conv when its residual at the target
     * is smaller than the predictor's (or 10x smaller). Near 360 deg the quadratic predictor
     * did fail twice (|R| 1.4e4 and 3.5e4 N against 355 and 271 N from s_conv; 17 iterations
     * lost in the run), but |R| misjudges the start: its excess sits in the stiff fibre
     * directions, the shortfall of s_conv in the soft bending mode (at 0.031 MPa the secant's
     * 770 N converged in 13 iterations, s_conv's 200 N in 21), and the guard doubled the
     * iterations at 0.03-0.05 MPa. The residual at the target before any Newton step does not
     * separate the failures either: the predictors that converge start hundreds to thousands
     * of times above the converged state's (docs/notes/code_measurements.md "FE bend: no guard
     * on the predictor's residual") */
    if (plain) {
      csf_stateSet(m, d, r->w.s_conv);
    } else if (r->have_pp && r->p > r->p_prev && r->p_prev > r->p_pp) {
      const double x0 = r->p_pp, x1 = r->p_prev, x2 = r->p, x = target;
      const double l0 = (x - x1) * (x - x2) / ((x0 - x1) * (x0 - x2));
      const double l1 = (x - x0) * (x - x2) / ((x1 - x0) * (x1 - x2));
      const double l2 = (x - x0) * (x - x1) / ((x2 - x0) * (x2 - x1));
      for (size_t i = 0; i < r->ns; i++) {
        r->w.s_tmp[i] = l0 * r->w.s_pp[i] + l1 * r->w.s_prev[i] + l2 * r->w.s_conv[i];
      }
      csf_stateSet(m, d, r->w.s_tmp);
    } else if (r->have_prev && r->p > r->p_prev) {
      const double f = (target - r->p) / (r->p - r->p_prev);
      for (size_t i = 0; i < r->ns; i++) {
        r->w.s_tmp[i] = r->w.s_conv[i] + f * (r->w.s_conv[i] - r->w.s_prev[i]);
      }
      csf_stateSet(m, d, r->w.s_tmp);
    } else {
      csf_stateSet(m, d, r->w.s_conv);
    }
    if (csf_newtonSolve(m, d, target, &r->nopt, iters, &lerr) == CS_OK) {
      *target_out = target;
      return 1;
    }
    r->info.n_newton += *iters;
    (*cut)++;
    r->info.n_cutbacks++;
    if (!plain && r->have_prev && r->p > r->p_prev) {
      plain = 1; /* the same step once more from s_conv */
      r->dp = target - r->p;
      continue;
    }
    plain = 0;
    r->dp = 0.5 * (target - r->p);
    if (r->dp < dp_min) {
      return 0;
    }
  }
}


/* ---- stage: refine --until-angle --------------------------------------------------------- */

/* bracket [p_prev, p] by converged states (s_prev, s_conv); regula falsi with 10 % safeguard;
 * each trial starts from the nearer bracketing state, restored whole (u, element dilatations,
 * fibre stresses: csf_stateSet), and reaches its pressure by load stepping with cut-backs; an
 * interpolated start shortens the rotated fibres (chord of an arc) */
static csStatus stageRefine(Run* r, const double ang[3], double tot, const double tip[3],
                            csError* err) {
  const csfBendOptions* o = r->o;
  csfModel* m = r->w.fe.model;
  csfData* d = r->w.data;
  csError lerr = {0};
  double lo = r->p_prev, hi = r->p, alo = r->ang_prev[3];
  double ahi = tot;
  double* slo = r->w.s_prev;
  double* shi = r->w.s_conv;
  double a_found = tot, p_found = r->p;
  double ang_found[3] = {ang[0], ang[1], ang[2]}, tip_found[3] = {tip[0], tip[1], tip[2]};
  int fails = 0;
  for (int it = 0; it < 40 && fabs(a_found - o->until_angle) > o->angle_tol; it++) {
    double f = (o->until_angle - alo) / (ahi - alo);
    f = fails ? 0.5 : fmin(fmax(f, 0.1), 0.9); /* bisect after a failure */
    const double pm = lo + f * (hi - lo);
    const int from_lo = f <= 0.5;
    csf_stateSet(m, d, from_lo ? slo : shi);
    int itb = 0;
    r->info.n_until_trials++;
    if (csf_loadRamp(m, d, pm, 1, &r->nopt, &itb, &lerr) != CS_OK) {
      r->info.n_newton += itb;
      r->info.n_until_failed++;
      snprintf(r->info.until_note, sizeof r->info.until_note,
               "trial %.6g MPa from %.6g MPa: %.150s", pm, from_lo ? lo : hi, lerr.msg);
      if (++fails > 4) {
        break;
      }
      continue;
    }
    fails = 0;
    r->info.n_newton += itb;
    double am[3], tm, tpm[3], pr[4] = {r->ang_prev[0], r->ang_prev[1], r->ang_prev[2], alo};
    csf_bendMeasure(r->act, r->w.fe.gauges, m, d, r->w.fe.axis, pr, am, &tm, tpm);
    a_found = tm, p_found = pm;
    memcpy(ang_found, am, sizeof am);
    memcpy(tip_found, tpm, sizeof tpm);
    if (tm < o->until_angle) {
      lo = pm, alo = tm;
      csf_stateGet(m, d, slo);
    } else {
      hi = pm, ahi = tm;
      csf_stateGet(m, d, shi);
    }
  }
  if (fabs(a_found - o->until_angle) <= o->angle_tol) {
    r->out->p_until_angle = p_found;
  }
  return csf_bendStageRow(r, p_found, ang_found, a_found, tip_found, err);
}


/* ---- stage: finish ----------------------------------------------------------------------- */

static csStatus stageFinish(Run* r, csError* err) {
  const csfBendOptions* o = r->o;
  csfModel* m = r->w.fe.model;
  csfData* d = r->w.data;
  csStatus st = CS_OK;
  /* volume preservation at the final state */
  csf_assemble(m, d, r->p, 0);
  for (int e = 0; e < r->w.fe.mesh->ntet; e++) {
    r->info.max_j_dev = fmax(r->info.max_j_dev, fabs(d->vratio[e] - 1.0));
  }
  r->info.j_min = csf_worstElement(m, d, r->info.j_min_X);
  /* the free surfaces there: crease onset and closing chambers (fem_bend_wall.h) */
  st = csf_bendWallMeasure(m, d, (const double(*)[CSR_NCHAMBER])o->spec.ratio, 1, &r->info.wall,
                           err);
  if (st != CS_OK) {
    return st;
  }
  if (r->info.wall.vented.npoint > 0) {
    double dx[3];
    csu_sub3(dx, r->info.j_min_X, r->info.wall.vented.X);
    r->info.j_min_wall_dist = csu_norm3(dx);
  }
  if (o->vtu_path) {
    st = csf_writeVtu(m, d, o->vtu_path, err);
  }
  if (st == CS_OK && o->inp_path) {
    st = csf_writeInp(m, r->act, d->load, o->inp_path, err);
  }
  return st;
}


static void fillStats(Run* r) {
  const csfData* d = r->w.data;
  if (!d) {
    return;
  }
  r->info.t_assemble = d->stats.t_assemble;
  r->info.t_factor = d->stats.t_factor;
  r->info.t_solve = d->stats.t_solve;
  r->info.factor_nnz = csf_linSolverFactorNnz(d->ls);
  r->info.n_factor = d->stats.n_factor;
  r->info.n_repivot = csf_linSolverRepivots(d->ls);
  r->info.n_krylov = d->stats.n_krylov;
  r->info.n_krylov_iter = d->stats.n_krylov_iter;
  r->info.n_restore = d->stats.n_restore;
  r->info.n_repeat = d->stats.n_repeat;
  snprintf(r->info.solver, sizeof r->info.solver, "%s", csf_linSolverName(d->ls));
  r->info.factor_threads = csf_linSolverThreads(d->ls);
  r->info.factor_flops = csf_linSolverFlops(d->ls);
  r->info.mpi_ranks = csf_linSolverRanks(d->ls);
  csf_linSolverMemory(d->ls, &r->info.factor_mem_rank_mb, &r->info.factor_mem_total_mb);
}


/* ---- the sweep ---------------------------------------------------------------------------- */

csStatus csf_bend(const csrActuator* act, const csfBendOptions* o, csrBendCurve* out,
                  csError* err) {
  Run r;
  memset(&r, 0, sizeof r);
  r.t_start = csf_wallTime();
  r.act = act, r.o = o, r.out = out;
  r.info.p_limit = r.info.p_resume = r.info.angle_limit = r.info.angle_resume = NAN;
  r.info.p_definite = r.info.p_indefinite = NAN;
  r.info.neg_pivots_max = -1;
  r.info.p_bifurcation = r.info.angle_bifurcation = NAN;
  r.info.p_crease = r.info.angle_crease = r.info.p_crease_skin = NAN;
  r.info.j_min_wall_dist = NAN;
  out->p_until_angle = NAN;
  if (o->record) {
    o->record->m = 0;
  }
  if (!(o->p_step > 0) || !(o->p_max > 0) || !(o->p_first >= 0)) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_bend: need p_step, p_max > 0 and p_first >= 0");
  }
  csStatus st = stageSetup(&r, err);
  if (st == CS_OK) {
    st = stageDeadLoads(&r, err);
  }
  if (st != CS_OK) {
    sweepFree(&r.w);
    return st;
  }
  csfModel* m = r.w.fe.model;
  csfData* d = r.w.data;
  csf_stateGet(m, d, r.w.s_conv);
  memcpy(r.w.s_prev, r.w.s_conv, r.ns * sizeof(double));
  csf_assemble(m, d, 0.0, 0); /* the initial chamber volume */
  r.V_conv = r.V_prev = d->vol_w;
  r.dp = o->p_first > 0 ? fmin(o->p_first, o->p_step) : CSF_BEND_FIRST_REL * o->p_step;
  r.k_out = 1;
  const double eps = 1e-9 * o->p_step;
  const int want_until = isfinite(o->until_angle);
  {
    /* row at p = 0 */
    double ang[3], tot, tip[3];
    csf_bendMeasure(act, r.w.fe.gauges, m, d, r.w.fe.axis, r.ang_conv, ang, &tot, tip);
    st = csf_bendStageRow(&r, 0.0, ang, tot, tip, err);
  }
  while (st == CS_OK && r.p < o->p_max - eps) {
    if (o->cancel && *o->cancel) {
      /* between load steps: the rows so far are converged states */
      st = cs_errorSet(err, CS_ERR_INTERRUPTED, "fem_bend: interrupted at p = %.6g MPa after %d "
                       "load steps (%zu rows kept)", r.p, r.info.n_steps, out->m);
      break;
    }
    const double t_step = csf_wallTime();
    double target = r.p;
    int iters = 0, cut = 0;
    if (!stageStep(&r, &target, &iters, &cut)) {
      if (!o->continuation) {
        r.info.p_limit = r.p;
        r.info.limit_shown = 0;
        csf_stateSet(m, d, r.w.s_conv);
        break;
      }
      if (csf_bendStageLimit(&r, &st, err)) {
        break;
      }
      continue;
    }
    r.V_prev = r.V_conv;
    r.V_conv = d->vol_w; /* the converged state's weighted chamber volume (last assembly) */
    r.info.n_newton += iters;
    r.info.n_steps++;
    double ang[3], tot, tip[3];
    csf_bendMeasure(act, r.w.fe.gauges, m, d, r.w.fe.axis, r.ang_conv, ang, &tot, tip);
    const int neg = csf_linSolverNegativePivots(d->ls);
    double asym[CSR_NSEG];
    csfBendStep rep = {target, target - r.p, iters, cut, csf_wallTime() - t_step, tot,
                       {ang[0], ang[1], ang[2]}, 0, d->vol_w, neg, r.on_branch,
                       csf_bendChamberAsymmetry(m, d, (const double(*)[CSR_NCHAMBER])o->spec.ratio,
                                                asym), NULL, NAN, NAN, NAN, NAN};
    csf_bendNoteWall(m, d, (const double(*)[CSR_NCHAMBER])o->spec.ratio, target, tot, &r.info,
                     &rep);
    /* a bifurcation under pressure control: a negative pivot more than the state before */
    const int bif = o->branch_switch && o->continuation && !r.on_branch && r.neg_conv >= 0 &&
                    neg > r.neg_conv; /* (without the switch: reported on the volume path) */
    r.neg_prev = r.neg_conv;
    r.neg_conv = neg;
    /* stability of the pressure-controlled path: the inertia of its tangent (the state before
     * is definite while p_indefinite is unset) */
    csf_bendNoteInertia(&r.info, neg, target, r.p);
    /* accept: the buffers shift (s_pp <- s_prev <- s_conv <- d) */
    double* recycled = r.w.s_pp;
    r.w.s_pp = r.w.s_prev;
    r.w.s_prev = r.w.s_conv;
    r.w.s_conv = recycled;
    csf_stateGet(m, d, r.w.s_conv);
    r.p_pp = r.p_prev;
    r.a_pp = r.ang_prev[3];
    r.have_pp = r.have_prev;
    memcpy(r.ang_prev, r.ang_conv, sizeof r.ang_prev);
    r.ang_conv[0] = ang[0], r.ang_conv[1] = ang[1], r.ang_conv[2] = ang[2], r.ang_conv[3] = tot;
    r.p_prev = r.p;
    r.p = target;
    r.have_prev = 1;
    if (o->progress) {
      o->progress(o->progress_user, &rep);
    }
    /* within angle_tol below the target is a hit too (stageRefine then keeps it) */
    if (want_until && tot >= o->until_angle - o->angle_tol) {
      st = stageRefine(&r, ang, tot, tip, err);
      break;
    }
    if (fabs(r.p - csf_bendOutputPressure(o, r.k_out)) <= eps) {
      st = csf_bendStageRow(&r, r.p, ang, tot, tip, err);
      r.k_out++;
    }
    if (bif && st == CS_OK) {
      /* leave the path here (the volume-controlled path switches at its entry state) */
      if (csf_bendStageLimit(&r, &st, err)) {
        break;
      }
      continue;
    }
    /* step control: no growth right after a step that needed cut-backs */
    r.n_hard = cut > 0 ? r.n_hard + 1 : 0;
    if (cut > 0) {
      /* keep dp */
    } else if (iters <= CSF_BEND_GROW_ITERS) {
      r.dp = fmin(1.5 * r.dp, o->p_step);
    } else if (iters > CSF_BEND_SHRINK_ITERS) {
      r.dp *= 0.7;
    }
  }
  if (st == CS_OK) {
    st = stageFinish(&r, err);
  }
  fillStats(&r);
  r.info.t_total = csf_wallTime() - r.t_start;
  if (o->info) {
    *o->info = r.info;
  }
  sweepFree(&r.w);
  return st;
}

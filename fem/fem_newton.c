/* fem_newton.c: Newton's method, volume control and load stepping (fem_newton.h). */
#include "fem_newton.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "fem_krylov.h"
#include "fem_linsolve.h"

/* Line search with a watchdog (Chamberlain et al. 1982, "The watchdog technique"): a full
 * Newton step is accepted unless an element inverts or the residual grows by more than
 * CSF_LS_GROWTH_FIRST; only when CSF_LS_WATCH accepted steps in a row have not improved on the
 * best residual so far does Newton return to the best iterate and backtrack from it, halving
 * while the residual would grow by more than CSF_LS_GROWTH (i.e. not decrease). A decrease test
 * on every step is wrong here: with kappa = 2000 mu a full Newton step leaves a volumetric residual
 * O(kappa eps^2) that the next iteration removes (measured on the tube: residual x120 after the
 * full step, then quadratic convergence; an Armijo test cut every step to 1/16 and stalled), and
 * that happens near the solution too: on the baseline at 0.2334 MPa |R| reached 1.3e-2 N in 4
 * iterations, the next full step grew it, the strict growth limit 2 then cut 9 steps to 1/32..1/2
 * and the step took 17 iterations (run trace of the 360 deg sweep, fem/README.md).
 * After a return to the best iterate the first step must decrease the residual below the best's
 * (CSF_LS_GROWTH = 1; it was 2): the Newton step from that iterate is the one that already led to
 * CSF_LS_WATCH steps without improvement, and taking it again under a lenient test repeats them
 * exactly: with the limit 2 a trace cycled through the same three residuals until the
 * stagnation test ended the attempt (docs/notes/code_measurements.md "FE line search after a
 * return to the best iterate"). */
#define CSF_LS_GROWTH_FIRST 1e4
#define CSF_LS_GROWTH 1.0
#define CSF_LS_WATCH 3
#define CSF_NEWTON_HIST 128        /* iterations whose |R| is kept for the stagnation test */
#define CSF_NEWTON_STALL_WINDOW 6  /* iterations that must halve the best |R| before them */
#define CSF_NEWTON_STALL_MIN 12    /* no stagnation test before this iteration */

/* Stagnation test (csf_newtonSolve, csf_newtonSolveVolume): records |R| before iteration `it`
 * in hist (CSF_NEWTON_HIST entries); from iteration CSF_NEWTON_STALL_MIN on, 1 when the last
 * CSF_NEWTON_STALL_WINDOW iterations have not halved the best |R| before them (*recent, *before:
 * those two minima). Measured on the leg at 0.2 MPa: |R| bounced between 0.05 and 0.2 N of 36 N
 * from iteration 7 to 40, and each failed attempt cost 40 iterations, 2-5 minutes. */
static int newtonStalled(double* hist, int it, double rnorm, double* recent, double* before) {
  *recent = *before = INFINITY;
  if (it > CSF_NEWTON_HIST) {
    return 0;
  }
  hist[it - 1] = rnorm;
  if (it <= CSF_NEWTON_STALL_MIN) {
    return 0;
  }
  for (int k = 0; k < it; k++) {
    if (k < it - CSF_NEWTON_STALL_WINDOW) {
      *before = fmin(*before, hist[k]);
    } else {
      *recent = fmin(*recent, hist[k]);
    }
  }
  return *recent > 0.5 * *before;
}


/* where the monitor looks: the free node with the largest nodal residual |R_a| and the element
 * with the smallest pointwise J (diagnostics of a stall) */
static void monitorLocate(const csfModel* m, const csfData* d, csfNewtonIter* rep) {
  const int nn = m->ndof / 3;
  rep->rmax = 0.0;
  rep->rmax_node = -1;
  for (int a = 0; a < nn; a++) {
    double s = 0.0;
    for (int i = 0; i < 3; i++) {
      const double r = m->fixed[3 * a + i] ? 0.0 : d->r[3 * a + i];
      s += r * r;
    }
    if (s > rep->rmax * rep->rmax) {
      rep->rmax = sqrt(s);
      rep->rmax_node = a;
    }
  }
  if (rep->rmax_node >= 0) {
    for (int i = 0; i < 3; i++) {
      rep->rmax_X[i] = m->mesh->x[3 * rep->rmax_node + i];
    }
  }
  rep->jmin = csf_worstElement(m, d, rep->jmin_X);
}


csfNewtonOptions csf_newtonDefault(void) {
  csfNewtonOptions o;
  o.max_iter = 25;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.max_ls = 6;
  o.line_search = CSF_LS_RESIDUAL;
  o.ls_eta = 0.5;
  o.threads = 0;
  o.krylov = 0; /* measured: does not pay on the fibred actuator (fem/README.md) */
  o.krylov_maxit = 30;
  o.krylov_eta = 1e-6;
  o.monitor = NULL;
  o.monitor_user = NULL;
  o.shift = 0.0;
  return o;
}


/* theta_e = (v_e + alpha g_e . du_e) / V_e: the linearised volume constraint of the three-field
 * form (element pressure p_e = kappa (theta_e - 1) follows) */
static void updateTheta(const csfModel* m, csfData* d, double alpha) {
  /* fibres: E_lin = E0 + d0 . (alpha dd) / L0^2, S_state = S(E_lin) */
  for (int f = 0; f < m->nfib; f++) {
    const int* fv = m->fib_node + 20 * (size_t)f;
    const double* c = m->fib_coef + 20 * (size_t)f;
    double dd[3] = {0, 0, 0};
    for (int a = 0; a < 20; a++) {
      for (int i = 0; i < 3; i++) {
        dd[i] += c[a] * d->du[3 * fv[a] + i];
      }
    }
    const double* d0 = d->fib_d0 + 3 * (size_t)f;
    const double L0 = m->fib_L0[f];
    double El = d->fib_E0[f] + alpha * (d0[0] * dd[0] + d0[1] * dd[1] + d0[2] * dd[2]) / (L0 * L0);
    double dS;
    csf_fibreLaw(m->fib_tension_only, El, &d->fib_S[f], &dS);
  }
  if (m->mat.form != CSF_FORM_MIXED_P0) {
    return;
  }
  for (int e = 0; e < m->mesh->ntet; e++) {
    const int* tv = m->mesh->tet + 10 * e;
    const double* g = d->g0 + 30 * (size_t)e;
    double s = 0;
    for (int a = 0; a < 10; a++) {
      for (int i = 0; i < 3; i++) {
        s += g[3 * a + i] * d->du[3 * tv[a] + i];
      }
    }
    d->theta[e] = d->vr0[e] + alpha * s / m->vol[e];
    d->pel[e] = m->mat.kappa * (d->theta[e] - 1.0);
  }
}


/* energy slope g = R . du over the free dofs at the last assembly (N mm) */
static double slope(const csfModel* m, const csfData* d) {
  double g = 0;
  for (int i = 0; i < m->ndof; i++) {
    if (!m->fixed[i]) {
      g += d->r[i] * d->du[i];
    }
  }
  return g;
}


/* Line search on the energy slope g(s) = R(u + s du) . du (Crisfield 1991, Sec. 9.3; FEBio's
 * line search): with closed chambers the follower pressure is conservative, so g is the slope of
 * the total potential along du, and the best step is its root. s = 1 is accepted when
 * g(1) <= 0 (energy still falls: the step is not too long) or |g(1)| <= eta |g(0)|; otherwise the
 * root is bracketed in (0, 1) and found by Illinois regula falsi until |g(s)| <= eta |g(0)|
 * (eta = 0.5: a loose search, the Newton step does the rest). An inverted element halves s.
 * Trial residuals are assembled without K; the accepted point is assembled with K. On entry d->r
 * is the residual at u (s = 0) and d->du the Newton step; on success d->u = u + s du. Returns 1
 * on success, 0 when no acceptable s was found (d->u is then left at some trial point). */
static int energyLineSearch(const csfModel* m, csfData* d, double load,
                            const csfNewtonOptions* opt, double* alpha_out, double* g0_out,
                            double* g1_out, int* neval) {
  const size_t n = (size_t)m->ndof;
  const double g0 = slope(m, d);
  *g0_out = g0;
  double moved = 0.0, s = 1.0;
  double sa = 0.0, ga = g0, sb = NAN, gb = NAN; /* bracket: g(sa) < 0 < g(sb) */
  int side = 0, accepted = 0, last_ok = 0;
  double g = NAN;
  for (int k = 0; k <= opt->max_ls + 4; k++) {
    for (size_t i = 0; i < n; i++) {
      d->u[i] += (s - moved) * d->du[i];
    }
    moved = s;
    updateTheta(m, d, s);
    (*neval)++;
    if (csf_assemble(m, d, load, 0) != 0) {
      sb = s, gb = NAN; /* inverted: too long */
      s = 0.5 * (sa + s);
      last_ok = 0;
      continue;
    }
    g = slope(m, d);
    last_ok = 1;
    if (!(g0 < 0.0)) {
      /* not a descent direction of the potential (modified tangent): keep the Newton step */
      accepted = 1;
      break;
    }
    if ((s == 1.0 && g <= 0.0) || fabs(g) <= opt->ls_eta * fabs(g0)) {
      accepted = 1;
      break;
    }
    if (g < 0.0) {
      sa = s, ga = g;
      if (side == -1 && isfinite(gb)) {
        gb *= 0.5; /* Illinois: the same end moved twice */
      }
      side = -1;
    } else {
      sb = s, gb = g;
      if (side == 1) {
        ga *= 0.5;
      }
      side = 1;
    }
    s = isfinite(gb) ? sa - ga * (sb - sa) / (gb - ga) : 0.5 * (sa + sb);
    /* keep the trial inside the bracket, away from its ends */
    const double w = sb - sa;
    s = fmin(fmax(s, sa + 0.05 * w), sb - 0.05 * w);
  }
  if (!accepted && !last_ok) {
    return 0;
  }
  /* budget spent on a valid point: take it, Newton continues from there */
  *alpha_out = moved;
  *g1_out = g;
  return csf_assemble(m, d, load, 1) == 0;
}


/* GMRES callbacks: the assembled tangent, and the last factorisation as preconditioner */
typedef struct {
  const csfModel* m;
  csfData* d;
} KrylovCtx;

static int krylovApplyK(void* ctx, const double* x, double* y) {
  const KrylovCtx* c = ctx;
  csf_tangentApply(c->m, c->d, x, y);
  return 0;
}

static int krylovApplyM(void* ctx, const double* x, double* y) {
  const KrylovCtx* c = ctx;
  memcpy(y, x, (size_t)c->m->ndof * sizeof(double));
  return csf_linSolverSolve(c->d->ls, y);
}


/* Solve K du = b, b in d->du on entry, du in d->du on exit, with the tangent of the last
 * assembly. eta: the forcing term for GMRES. Returns 0, or non-zero when the tangent is
 * singular. A fresh factorisation when Krylov reuse is off, no factorisation exists yet, the
 * last GMRES solve was slow, or GMRES does not converge within krylov_maxit. */
static int tangentSolve(const csfModel* m, csfData* d, const csfNewtonOptions* opt, double eta) {
  const size_t n = (size_t)m->ndof;
  if (opt->krylov && d->have_factor && !d->refactor_next) {
    const double t0 = csf_wallTime();
    KrylovCtx ctx = {m, d};
    memcpy(d->kry_b, d->du, n * sizeof(double));
    memset(d->du, 0, n * sizeof(double));
    int its = 0;
    double rr = 0;
    const int rc = csf_gmres(m->ndof, CSF_KRYLOV_RESTART, opt->krylov_maxit, eta, krylovApplyK,
                             krylovApplyM, &ctx, d->kry_b, d->du, d->kry_work, &its, &rr);
    d->stats.t_solve += csf_wallTime() - t0;
    d->stats.n_krylov_iter += its;
    if (rc == 0) {
      d->stats.n_krylov++;
      d->refactor_next = 2 * its > opt->krylov_maxit;
      return 0;
    }
    memcpy(d->du, d->kry_b, n * sizeof(double)); /* not converged: solve directly */
  }
  double t0 = csf_wallTime();
  const int fst = csf_linSolverFactor(d->ls, d->kval);
  d->stats.t_factor += csf_wallTime() - t0;
  d->stats.n_factor++;
  if (fst != 0) {
    d->have_factor = 0;
    return fst;
  }
  d->have_factor = 1;
  d->refactor_next = 0;
  t0 = csf_wallTime();
  const int sst = csf_linSolverSolve(d->ls, d->du);
  d->stats.t_solve += csf_wallTime() - t0;
  return sst;
}


csStatus csf_newtonSolve(const csfModel* m, csfData* d, double load, const csfNewtonOptions* opt,
                         int* iters, csError* err) {
  const size_t n = (size_t)m->ndof;
#ifdef _OPENMP
  if (opt->threads > 0) {
    omp_set_num_threads(opt->threads);
  }
#endif
  memcpy(d->u_save, d->u, n * sizeof(double));
  const size_t nt = (size_t)m->mesh->ntet;
  memcpy(d->theta_save, d->theta, nt * sizeof(double));
  const size_t nfb = (size_t)m->nfib;
  memcpy(d->fib_S_save, d->fib_S, nfb * sizeof(double));
  int it = 0, strict = 0, since_best = 0;
  double r_prev = 0, r_best = INFINITY;
  if (csf_assemble(m, d, load, 1) != 0) {
    memcpy(d->u, d->u_save, n * sizeof(double));
    memcpy(d->theta, d->theta_save, nt * sizeof(double));
    memcpy(d->fib_S, d->fib_S_save, nfb * sizeof(double));
    if (iters) {
      *iters = 0;
    }
    return cs_errorSet(err, CS_ERR_DIVERGED, "fem: inverted element at the start of load %g",
                       load);
  }
  double hist[CSF_NEWTON_HIST]; /* |R| per iteration (newtonStalled) */
  for (it = 1; it <= opt->max_iter; it++) {
    if (d->rnorm <= fmax(opt->atol, opt->rtol * d->fnorm)) {
      break;
    }
    double recent, before;
    if (newtonStalled(hist, it, d->rnorm, &recent, &before)) {
      memcpy(d->u, d->u_save, n * sizeof(double));
      memcpy(d->theta, d->theta_save, nt * sizeof(double));
      memcpy(d->fib_S, d->fib_S_save, nfb * sizeof(double));
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: Newton stagnated at load %g (|R| %.3g "
                         "after %d iterations, best %.3g before the last %d)", load, recent,
                         it - 1, before, CSF_NEWTON_STALL_WINDOW);
    }
    if (!strict && it <= CSF_NEWTON_HIST) {
      /* an iterate that repeats an earlier one is a cycle (a restored best iterate, strict = 1,
       * repeats by construction and is not counted) */
      for (int k = 0; k < it - 1; k++) {
        if (fabs(hist[k] - d->rnorm) <= 1e-12 * d->rnorm) {
          d->stats.n_repeat++;
          break;
        }
      }
    }
    /* solve K du = -R; the forcing term (Eisenstat and Walker 1996, choice 2, capped at
     * krylov_eta) is loose while Newton is far from the solution and tight near it, but never
     * tighter than the convergence test needs */
    const double target = fmax(opt->atol, opt->rtol * d->fnorm);
    double eta = opt->krylov_eta;
    if (it > 1 && r_prev > 0) {
      const double q = d->rnorm / r_prev;
      eta = fmin(opt->krylov_eta, 0.9 * q * q);
    }
    eta = fmin(opt->krylov_eta, fmax(eta, 0.1 * target / d->rnorm));
    r_prev = d->rnorm;
    for (size_t i = 0; i < n; i++) {
      d->du[i] = m->fixed[i] ? load * m->u_fix[i] - d->u[i] : -d->r[i];
    }
    if (tangentSolve(m, d, opt, eta) != 0) {
      memcpy(d->u, d->u_save, n * sizeof(double));
      memcpy(d->theta, d->theta_save, nt * sizeof(double));
      memcpy(d->fib_S, d->fib_S_save, nfb * sizeof(double));
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: singular tangent at load %g (iter %d)",
                         load, it);
    }
    d->stats.n_newton++;
    /* base of the linearised dilatation update: v/V and g at the current iterate */
    memcpy(d->vr0, d->vratio, nt * sizeof(double));
    memcpy(d->g0, d->gel, nt * 30 * sizeof(double));
    memcpy(d->fib_E0, d->fib_E, nfb * sizeof(double));
    memcpy(d->fib_d0, d->fib_d, 3 * nfb * sizeof(double));
    /* line search */
    double alpha = 1.0, g0 = 0.0, g1 = 0.0;
    int ok = 0, neval = 0;
    int moves_fixed = 0;
    for (size_t i = 0; i < n; i++) {
      if (m->fixed[i] && d->du[i] != 0.0) {
        moves_fixed = 1;
        break;
      }
    }
    if (opt->line_search == CSF_LS_ENERGY && !moves_fixed) {
      ok = energyLineSearch(m, d, load, opt, &alpha, &g0, &g1, &neval);
    } else {
      /* full step (watchdog: lenient) or backtracking on ||R|| (strict) */
      const double r0 = d->rnorm;
      const double growth = strict ? CSF_LS_GROWTH : CSF_LS_GROWTH_FIRST;
      double moved = 0.0;
      for (int ls = 0; ls <= opt->max_ls; ls++) {
        for (size_t i = 0; i < n; i++) {
          d->u[i] += (alpha - moved) * d->du[i];
        }
        moved = alpha;
        updateTheta(m, d, alpha);
        int st = csf_assemble(m, d, load, 1);
        neval++;
        if (st == 0 && d->rnorm < growth * r0) {
          ok = 1;
          break;
        }
        alpha *= 0.5;
      }
      /* the watchdog: remember the best iterate; after CSF_LS_WATCH steps without improving on
       * it, go back to it and continue strictly */
      strict = 0;
      if (ok && d->rnorm < r_best) {
        r_best = d->rnorm;
        since_best = 0;
        memcpy(d->u_best, d->u, n * sizeof(double));
        memcpy(d->theta_best, d->theta, nt * sizeof(double));
        memcpy(d->fib_S_best, d->fib_S, nfb * sizeof(double));
      } else if (ok && ++since_best >= CSF_LS_WATCH) {
        memcpy(d->u, d->u_best, n * sizeof(double));
        memcpy(d->theta, d->theta_best, nt * sizeof(double));
        memcpy(d->fib_S, d->fib_S_best, nfb * sizeof(double));
        ok = csf_assemble(m, d, load, 1) == 0;
        since_best = 0;
        strict = 1;
        d->stats.n_restore++;
      }
    }
    if (!ok) {
      memcpy(d->u, d->u_save, n * sizeof(double));
      memcpy(d->theta, d->theta_save, nt * sizeof(double));
      memcpy(d->fib_S, d->fib_S_save, nfb * sizeof(double));
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: line search failed at load %g (iter %d)",
                         load, it);
    }
    /* fibre law zones: how many fibres changed zone in this step (diagnostics) */
    /* where the trouble sits (rmax..., jmin_X): monitorLocate */
    csfNewtonIter rep = {load, it, alpha, neval, g0, g1, d->rnorm, d->fnorm, 0, 0, 0,
                         csf_linSolverNegativePivots(d->ls), .jmin = d->jmin};
    if (opt->monitor) {
      monitorLocate(m, d, &rep);
    }
    for (int f = 0; f < m->nfib; f++) {
      const double E = d->fib_E[f];
      const unsigned char z = E <= -CSF_FIBRE_SLACK ? 0 : (E < CSF_FIBRE_SLACK ? 1 : 2);
      rep.fib_switch += z != d->fib_zone[f];
      rep.fib_smooth += z == 1;
      rep.fib_taut += z == 2;
      d->fib_zone[f] = z;
    }
    if (opt->monitor) {
      opt->monitor(opt->monitor_user, &rep);
    }
  }
  if (iters) {
    *iters = it - 1;
  }
  if (d->rnorm > fmax(opt->atol, opt->rtol * d->fnorm)) {
    memcpy(d->u, d->u_save, n * sizeof(double));
    memcpy(d->theta, d->theta_save, nt * sizeof(double));
    memcpy(d->fib_S, d->fib_S_save, nfb * sizeof(double));
    csf_assemble(m, d, d->load, 0);
    return cs_errorSet(err, CS_ERR_DIVERGED,
                       "fem: Newton did not converge at load %g in %d iterations (|R| %.3g N)",
                       load, opt->max_iter, d->rnorm);
  }
  return CS_OK;
}


/* restore the Newton entry state (u, dilatation and fibre states, load) */
static void restoreEntry(const csfModel* m, csfData* d, double load0) {
  memcpy(d->u, d->u_save, (size_t)m->ndof * sizeof(double));
  memcpy(d->theta, d->theta_save, (size_t)m->mesh->ntet * sizeof(double));
  memcpy(d->fib_S, d->fib_S_save, (size_t)m->nfib * sizeof(double));
  csf_assemble(m, d, load0, 0);
}


csStatus csf_newtonSolveVolume(const csfModel* m, csfData* d, double vol_target,
                               const csfNewtonOptions* opt, int* iters, csError* err) {
  const size_t n = (size_t)m->ndof, nt = (size_t)m->mesh->ntet, nfb = (size_t)m->nfib;
#ifdef _OPENMP
  if (opt->threads > 0) {
    omp_set_num_threads(opt->threads);
  }
#endif
  const double load0 = d->load;
  memcpy(d->u_save, d->u, n * sizeof(double));
  memcpy(d->theta_save, d->theta, nt * sizeof(double));
  memcpy(d->fib_S_save, d->fib_S, nfb * sizeof(double));
  double load = load0;
  int it = 0;
  if (iters) {
    *iters = 0;
  }
  if (csf_assemble(m, d, load, 1) != 0) {
    restoreEntry(m, d, load0);
    return cs_errorSet(err, CS_ERR_DIVERGED, "fem: inverted element at the start of volume %g",
                       vol_target);
  }
  const double vtol = opt->rtol * fabs(vol_target);
  double hist[CSF_NEWTON_HIST]; /* |R| per iteration (newtonStalled) */
  for (it = 1; it <= opt->max_iter; it++) {
    const double c = d->vol_w - vol_target;
    if (d->rnorm <= fmax(opt->atol, opt->rtol * d->fnorm) && fabs(c) <= vtol) {
      break;
    }
    double recent, before;
    if (newtonStalled(hist, it, d->rnorm, &recent, &before)) {
      restoreEntry(m, d, load0);
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: volume control stagnated at volume %g "
                         "(|R| %.3g N after %d iterations, best %.3g before the last %d)",
                         vol_target, recent, it - 1, before, CSF_NEWTON_STALL_WINDOW);
    }
    /* K x1 = -R (fixed dofs moved to their targets), K x2 = b = dVw/du */
    for (size_t i = 0; i < n; i++) {
      d->du[i] = m->fixed[i] ? load * m->u_fix[i] - d->u[i] : -d->r[i];
      d->du2[i] = d->fext1[i];
    }
    if (opt->shift != 0.0) {
      /* the iteration matrix K - shift I (csfNewtonOptions.shift); kval is reassembled at the
       * next iterate, so the shift is applied in place */
      for (int i = 0; i < m->ndof; i++) {
        for (int q = m->row_ptr[i]; q < m->row_ptr[i + 1] && !m->fixed[i]; q++) {
          d->kval[q] -= m->col[q] == i ? opt->shift : 0.0;
        }
      }
    }
    double t0 = csf_wallTime();
    int fst = csf_linSolverFactor(d->ls, d->kval);
    d->stats.t_factor += csf_wallTime() - t0;
    d->stats.n_factor++;
    d->have_factor = fst == 0 && opt->shift == 0.0;
    d->refactor_next = 0;
    if (fst != 0) {
      restoreEntry(m, d, load0);
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: singular tangent at volume %g (iter %d)",
                         vol_target, it);
    }
    t0 = csf_wallTime();
    csf_linSolverSolve(d->ls, d->du);
    csf_linSolverSolve(d->ls, d->du2);
    d->stats.t_solve += csf_wallTime() - t0;
    d->stats.n_newton++;
    /* constraint b . du = -c with du = x1 + dload x2 */
    double bx1 = 0, bx2 = 0;
    for (size_t i = 0; i < n; i++) {
      bx1 += d->fext1[i] * d->du[i];
      bx2 += d->fext1[i] * d->du2[i];
    }
    if (!(fabs(bx2) > 0)) {
      restoreEntry(m, d, load0);
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: volume control: b.K^-1.b = 0 (iter %d)", it);
    }
    const double dload = -(c + bx1) / bx2;
    for (size_t i = 0; i < n; i++) {
      d->du[i] += dload * d->du2[i];
    }
    memcpy(d->vr0, d->vratio, nt * sizeof(double));
    memcpy(d->g0, d->gel, nt * 30 * sizeof(double));
    memcpy(d->fib_E0, d->fib_E, nfb * sizeof(double));
    memcpy(d->fib_d0, d->fib_d, 3 * nfb * sizeof(double));
    /* step, halved while an element inverts */
    double alpha = 1.0, moved = 0.0;
    int ok = 0;
    for (int ls = 0; ls <= opt->max_ls; ls++) {
      for (size_t i = 0; i < n; i++) {
        d->u[i] += (alpha - moved) * d->du[i];
      }
      load += (alpha - moved) * dload;
      moved = alpha;
      updateTheta(m, d, alpha);
      if (csf_assemble(m, d, load, 1) == 0) {
        ok = 1;
        break;
      }
      alpha *= 0.5;
    }
    if (!ok) {
      restoreEntry(m, d, load0);
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: inverted elements at volume %g (iter %d)",
                         vol_target, it);
    }
    if (opt->monitor) {
      csfNewtonIter rep = {load, it, alpha, 1, 0, 0, d->rnorm, d->fnorm, 0, 0, 0,
                           csf_linSolverNegativePivots(d->ls), .jmin = d->jmin};
      monitorLocate(m, d, &rep);
      opt->monitor(opt->monitor_user, &rep);
    }
  }
  if (iters) {
    *iters = it - 1;
  }
  if (d->rnorm > fmax(opt->atol, opt->rtol * d->fnorm) ||
      fabs(d->vol_w - vol_target) > vtol) {
    restoreEntry(m, d, load0);
    return cs_errorSet(err, CS_ERR_DIVERGED,
                       "fem: volume control did not converge at volume %g in %d iterations "
                       "(|R| %.3g N)", vol_target, opt->max_iter, d->rnorm);
  }
  return CS_OK;
}


csStatus csf_loadRamp(const csfModel* m, csfData* d, double load_end, int nstep,
                      const csfNewtonOptions* opt, int* iters, csError* err) {
  double load = d->load, dl = (load_end - load) / nstep;
  const double dl_min = 1e-4 * fabs(load_end - load);
  int total = 0;
  while ((dl > 0 && load < load_end) || (dl < 0 && load > load_end)) {
    double target = (dl > 0) ? fmin(load + dl, load_end) : fmax(load + dl, load_end);
    int it = 0;
    csStatus st = csf_newtonSolve(m, d, target, opt, &it, err);
    total += it;
    if (st != CS_OK) {
      dl *= 0.5;
      if (fabs(dl) < dl_min) {
        if (iters) {
          *iters = total;
        }
        return st;
      }
      continue;
    }
    load = target;
    if (it <= 5) {
      dl *= 1.5;
    }
  }
  if (iters) {
    *iters = total;
  }
  return CS_OK;
}

/* fem_path.c: volume-controlled continuation past pressure limit points (see fem_path.h).
 *
 * Rationale. Under pressure control a limit point shows as a load step that collapses: past the
 * maximum there is no nearby equilibrium at a higher pressure. Prescribing the chamber volume
 * instead makes the path single-valued through the maximum (Crisfield 1991, Sec. 9.4, with the
 * chamber volume as the constraint; for a fluid-filled chamber this is also what a volume- or
 * mass-controlled supply does). The constraint is the weighted sum over all pressurised chambers;
 * where several chambers in parallel could balloon alone, the path follows the one the mesh
 * and geometry favour, as a real actuator does.
 *
 * Branch switching. A converged state whose tangent has one negative pivot more than the state
 * before, while the pressure still rises, lies just past a bifurcation of the path: the
 * pressure-volume path itself has no maximum there (a limit point would make the pressure fall),
 * but a mode phi orthogonal to it has lost its stiffness (K phi = lambda phi, lambda < 0; for a
 * path that keeps a mirror symmetry of the structure, phi breaks it and b . phi = 0, b = dVw/du).
 * Newton on the old path then meets a nearly singular K whose steps carry large phi components
 * (the sweeps end with inverted elements there). The other branch through the bifurcation leaves
 * along phi (Riks 1979; Wriggers 2008, Sec. 7.5, "branch switching by perturbation"): the state
 * is perturbed by a small multiple of phi and solved at the same volume (then the next one). The
 * solve is a descent: the volume-controlled iteration with K - 2 lambda I, definite, so the old
 * path's state, a saddle of the energy at fixed volume, repels and the iteration stops at a
 * stable state if one is near (plain Newton from the perturbed state diverged: switchBranch).
 * phi comes from inverse iteration (csf_linSolverInverseIteration), on K - sigma I with sigma
 * just below the negative eigenvalue nearest zero, placed by the inertia of shifted
 * factorisations (csf_pathCriticalMode: the eigenvalue of smallest modulus is often a slender
 * body's soft positive mode instead). Rejected: a bordered solve of the extended system
 * (K phi = 0, |phi| = 1) that locates the critical point exactly (Wriggers-Simo 1990): twice the
 * unknowns and a second derivative of K, for a point the inertia already brackets to one step;
 * an imperfect geometry (the path then has no bifurcation, but its answer depends on the
 * imperfection's size). */
#include "fem_path.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* "not a limit point": this many consecutive rising volume steps, ending this fraction above the
 * pressure where pressure control gave up */
#define CSF_PATH_RISING 5
#define CSF_PATH_RISE 0.01
/* critical mode: inverse iteration stops when 1 - |cos| between iterates is below this (an
 * angle of 1.4e-5 rad), or after CSF_PATH_EIG_MAXIT solves */
#define CSF_PATH_EIG_TOL 1e-10
#define CSF_PATH_EIG_MAXIT 30
/* the first shift tried below a negative eigenvalue, relative to the largest free diagonal
 * entry of K (csf_pathCriticalMode): decades from here down to -max diag */
#define CSF_PATH_SHIFT_MIN 1e-10
/* the branch switch's descent (switchBranch): iterate with K - 2 lambda I (lambda < 0, the
 * critical eigenvalue), definite with the critical mode at |lambda|, for at most this many
 * iterations (linear convergence) */
#define CSF_PATH_DESCENT_SHIFT 2.0
#define CSF_PATH_DESCENT_MAXIT 60
/* a perturbed state that converges with its component along phi at least this fraction of the
 * perturbation has left the old path (Newton back on the old path removes the component) */
#define CSF_PATH_DEPART 0.5
/* default perturbation: 0.05 mm at the largest nodal component, a twentieth of the 1 mm walls
 * of the thinnest Sec. 4 actuator (b = 3, r1 = 2.5) and 1/80 of its l_soft 4 elements */
#define CSF_PATH_BRANCH_AMP 0.05

csfLimitOptions csf_limitDefault(void) {
  csfLimitOptions o;
  memset(&o, 0, sizeof o);
  o.max_steps = 200;
  o.max_vol_ratio = 20.0;
  o.min_dv_rel = 1e-4;
  o.branch_amp = CSF_PATH_BRANCH_AMP;
  o.neg_prev = o.neg_conv = -1;
  return o;
}


/* factor K - sigma I (sigma on the free dofs' diagonal; Dirichlet rows keep their identity)
 * from d->kval into kshift (nnz); returns its negative pivots (the eigenvalues of K below
 * sigma, Sylvester), or -2 when the factorisation fails */
static int factorShifted(const csfModel* m, csfData* d, double sigma, double* kshift) {
  memcpy(kshift, d->kval, (size_t)m->nnz * sizeof(double));
  for (int i = 0; i < m->ndof; i++) {
    for (int q = m->row_ptr[i]; q < m->row_ptr[i + 1] && !m->fixed[i]; q++) {
      if (m->col[q] == i) {
        kshift[q] -= sigma;
      }
    }
  }
  const double t0 = csf_wallTime();
  const int fst = csf_linSolverFactor(d->ls, kshift);
  d->stats.t_factor += csf_wallTime() - t0;
  d->stats.n_factor++;
  return fst != 0 ? -2 : csf_linSolverNegativePivots(d->ls);
}


csStatus csf_pathCriticalMode(const csfModel* m, csfData* d, int maxit, double* phi,
                              double* work, csfCriticalMode* cm, csError* err) {
  const int n = m->ndof;
  memset(cm, 0, sizeof *cm);
  cm->lambda = cm->residual = cm->change = NAN;
  cm->node_max = -1;
  if (csf_assemble(m, d, d->load, 1) != 0) {
    return cs_errorSet(err, CS_ERR_DIVERGED, "fem: critical mode: inverted element at %.6g MPa",
                       d->load);
  }
  double* kshift = malloc((size_t)m->nnz * sizeof(double));
  if (!kshift) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem: critical mode: out of memory");
  }
  /* the inertia of K itself */
  const int neg0 = factorShifted(m, d, 0.0, kshift);
  cm->neg_pivots = neg0;
  d->have_factor = 0; /* d->ls will hold a shifted matrix: no preconditioner for Newton */
  d->refactor_next = 0;
  if (neg0 < -1) {
    free(kshift);
    return cs_errorSet(err, CS_ERR_DIVERGED, "fem: critical mode: singular tangent at %.6g MPa",
                       d->load);
  }
  /* the shift. With negative pivots the wanted mode is the negative eigenvalue nearest zero,
   * lambda_t, and the eigenvalue of smallest modulus need not be it: the l_soft 4 thin-walled
   * actuator at its bifurcation (0.19159 MPa, one negative pivot, lambda_t = -1.6e-3 N/mm) has a
   * positive eigenvalue of 4.1e-7 N/mm, largest at the tip (a slender body's soft global mode:
   * test_fem_branch's column sways at 2.2e-7), which plain inverse iteration found. Any sigma below
   * lambda_t (and above the next negative one) makes lambda_t the eigenvalue of K - sigma I of
   * smallest modulus; the rate is (lambda_t - sigma) / (lambda_next - sigma) <= 1 - lambda_t /
   * sigma against the positive ones. sigma is found by inertia (Sylvester): decades below zero,
   * from 1e-10 of the largest free diagonal entry, until K - sigma I has one negative pivot less
   * than K, then two geometric bisections of the last decade (the bracket then spans a factor
   * 10^0.25 = 1.78: rate <= 0.44). */
  double sigma = 0.0;
  if (neg0 > 0) {
    double dmax = 0;
    for (int i = 0; i < n; i++) {
      for (int q = m->row_ptr[i]; q < m->row_ptr[i + 1] && !m->fixed[i]; q++) {
        dmax = m->col[q] == i ? fmax(dmax, fabs(d->kval[q])) : dmax;
      }
    }
    double hi = 0.0, lo = NAN; /* count(lambda < hi) = neg0, count(lambda < lo) < neg0 */
    for (double sg = -CSF_PATH_SHIFT_MIN * dmax; sg >= -dmax; sg *= 10.0) {
      const int c = factorShifted(m, d, sg, kshift);
      cm->n_shift++;
      if (c >= 0 && c < neg0) {
        lo = sg;
        break;
      }
      hi = sg;
    }
    for (int k = 0; k < 2 && isfinite(lo) && hi < 0.0; k++) {
      const double mid = -sqrt(lo * hi);
      const int c = factorShifted(m, d, mid, kshift);
      cm->n_shift++;
      if (c >= 0 && c < neg0) {
        lo = mid;
      } else {
        hi = mid;
      }
    }
    sigma = isfinite(lo) ? lo : 0.0;
  }
  if (factorShifted(m, d, sigma, kshift) < -1) {
    free(kshift);
    return cs_errorSet(err, CS_ERR_DIVERGED, "fem: critical mode: singular shifted tangent at "
                       "%.6g MPa (shift %.3g)", d->load, sigma);
  }
  cm->sigma = sigma;
  /* deterministic start: a linear congruential sequence in [-1, 1) (Numerical Recipes' 32-bit
   * constants), not aligned with any mode of the structure */
  uint32_t z = 20261203u;
  for (int i = 0; i < n; i++) {
    z = 1664525u * z + 1013904223u;
    phi[i] = m->fixed[i] ? 0.0 : (double)(z >> 8) / (double)(1u << 23) - 1.0;
  }
  csfEigResult er;
  const double t1 = csf_wallTime();
  const int rc = csf_linSolverInverseIteration(d->ls, m->fixed, maxit, CSF_PATH_EIG_TOL, phi,
                                               work, &er);
  d->stats.t_solve += csf_wallTime() - t1;
  free(kshift);
  cm->lambda = er.lambda + sigma, cm->residual = er.residual, cm->change = er.change;
  cm->iters = er.iters;
  if (rc != 0) {
    return cs_errorSet(err, CS_ERR_DIVERGED, "fem: critical mode: inverse iteration failed at "
                       "%.6g MPa", d->load);
  }
  /* its angle to the volume direction b = dVw/du (d->fext1, 0 on fixed dofs) */
  double bb = 0, bp = 0;
  for (int i = 0; i < n; i++) {
    bb += d->fext1[i] * d->fext1[i];
    bp += d->fext1[i] * phi[i];
  }
  cm->b_cos = bb > 0 ? bp / sqrt(bb) : 0.0;
  /* where it is largest */
  for (int a = 0; a < n / 3; a++) {
    const double pa = sqrt(phi[3 * a] * phi[3 * a] + phi[3 * a + 1] * phi[3 * a + 1] +
                           phi[3 * a + 2] * phi[3 * a + 2]);
    if (pa > cm->phi_max) {
      cm->phi_max = pa;
      cm->node_max = a;
    }
  }
  for (int i = 0; i < 3 && cm->node_max >= 0; i++) {
    cm->X_max[i] = m->mesh->x[3 * cm->node_max + i];
  }
  return CS_OK;
}


/* negative pivots of the tangent at the state in d (assembled and factored afresh), -2 when
 * the state cannot be assembled or factored */
static int stateInertia(const csfModel* m, csfData* d) {
  if (csf_assemble(m, d, d->load, 1) != 0) {
    return -2;
  }
  const double t0 = csf_wallTime();
  const int fst = csf_linSolverFactor(d->ls, d->kval);
  d->stats.t_factor += csf_wallTime() - t0;
  d->stats.n_factor++;
  return fst != 0 ? -2 : csf_linSolverNegativePivots(d->ls);
}


/* Leave the path at its converged state s_c (volume V, negative pivots neg_c) along the critical
 * mode (file comment): perturbed by +-amp phi / max_a |phi_a| and solved at V, then at V + dV.
 * The solve is the volume-controlled iteration with K - sigma I, sigma = CSF_PATH_DESCENT_SHIFT
 * lambda (csfNewtonOptions.shift). Plain Newton from the perturbed state (an earlier build, on
 * the thin-walled actuator) reached |R| 1.6e3 N against a 56 N force scale and inverted
 * elements: its step along phi is the residual's phi component over lambda = -1.6e-3 N/mm. The
 * shifted matrix is definite, so the iteration descends the energy at fixed volume away from the
 * unstable path (along phi the old state repels: the component grows by -sigma / (lambda -
 * sigma) = 2 per iteration near it) and stops at a stable state if one is near. Measured on that
 * actuator: none is (the web collapses, fem/README.md "Branch switching"). Returns 1 with d and
 * s_out at the accepted branch state (*V_out its volume), 0 with d at s_c when no perturbed solve
 * left the path, or when opt->branch_switch is off (the mode is computed either way;
 * res->branch_note says how each solve ended). */
static int switchBranch(const csfModel* m, csfData* d, const double* s_c, double* s_out,
                        double V, double dV, int neg_c, const csfNewtonOptions* nopt,
                        const csfLimitOptions* opt, csfLimitResult* res, double* V_out) {
  const int n = m->ndof;
  double* phi = malloc((size_t)n * sizeof(double));
  double* work = malloc((size_t)n * sizeof(double));
  csError lerr = {0};
  int ok = 0;
  csf_stateSet(m, d, s_c);
  res->branch_note[0] = '\0';
  if (!phi || !work) {
    snprintf(res->branch_note, sizeof res->branch_note, "out of memory for the critical mode");
  } else if (csf_pathCriticalMode(m, d, CSF_PATH_EIG_MAXIT, phi, work, &res->mode, &lerr) !=
             CS_OK) {
    snprintf(res->branch_note, sizeof res->branch_note, "%.190s", lerr.msg);
  } else {
    /* phi scaled to a largest nodal component of 1: the perturbation's size is amp, mm */
    double pp = 0;
    for (int i = 0; i < n; i++) {
      phi[i] /= res->mode.phi_max;
      pp += phi[i] * phi[i];
    }
    const double amp = opt->branch_amp;
    if (!opt->branch_switch) {
      snprintf(res->branch_note, sizeof res->branch_note, "branch switching off");
    }
    csfNewtonOptions dopt = *nopt;
    dopt.shift = res->mode.lambda < 0 ? CSF_PATH_DESCENT_SHIFT * res->mode.lambda : 0.0;
    dopt.max_iter = CSF_PATH_DESCENT_MAXIT;
    for (int k = 0; k < 4 && !ok && opt->branch_switch; k++) {
      const int sign = k % 2 ? -1 : 1;
      const double Vt = k < 2 ? V : V + dV; /* the same volume first: past the critical point
                                             * the branch is there already, nearest */
      csf_stateSet(m, d, s_c);
      for (int i = 0; i < n; i++) {
        d->u[i] += sign * amp * phi[i];
      }
      /* element dilatations and fibre stresses of the perturbed displacement */
      csf_dataSyncVolume(m, d);
      /* the descent to the sweep's tolerance: a Newton finish from a loosely converged descent
       * (1e-3) went back to the old path (measured on the thin-walled actuator: the Newton step
       * along phi is the residual's phi component over lambda ~ -1.6e-3 N/mm) */
      int it = 0;
      csStatus st = csf_newtonSolveVolume(m, d, Vt, &dopt, &it, &lerr);
      res->n_newton += it;
      res->branch_tries++;
      const size_t k0 = strlen(res->branch_note);
      char* note = res->branch_note + k0;
      const size_t room = sizeof res->branch_note - k0;
      if (st != CS_OK) {
        snprintf(note, room, "%s%+d at %.6g mm^3: %.70s", k0 ? "; " : "", sign, Vt, lerr.msg);
        continue;
      }
      /* the component along phi relative to s_c (u is the state's first ndof entries) */
      double xi = 0;
      for (int i = 0; i < n; i++) {
        xi += phi[i] * (d->u[i] - s_c[i]);
      }
      xi /= pp;
      const int neg = stateInertia(m, d);
      if ((neg >= 0 && neg < neg_c) || fabs(xi) >= CSF_PATH_DEPART * amp) {
        ok = 1;
        res->branch_sign = sign;
        res->branch_xi = xi;
        res->branch_neg = neg;
        csf_stateGet(m, d, s_out);
        *V_out = Vt;
      } else {
        snprintf(note, room, "%s%+d at %.6g mm^3 returned to the path in %d iterations (%.3g mm "
                 "along phi, %d negative pivots)", k0 ? "; " : "", sign, Vt, it, xi, neg);
      }
    }
  }
  if (!ok) {
    csf_stateSet(m, d, s_c);
  }
  free(phi);
  free(work);
  return ok;
}


/* the state switchBranch left in s_tmp (and d) becomes the path's converged state: the step
 * is counted and reported (kind 2) to the callback, the limit raised if it is higher; p_last
 * and neg_last follow it. Returns 1 when the callback stopped the sweep (res->stopped). */
static int acceptBranch(const csfModel* m, csfData* d, double* s_prev, double* s_conv,
                        const double* s_tmp, size_t ns, double Vb, double t0,
                        const csfLimitOptions* opt, csfLimitResult* res, double* p_last,
                        int* neg_last) {
  res->switched = 1;
  memcpy(s_prev, s_conv, ns * sizeof(double));
  memcpy(s_conv, s_tmp, ns * sizeof(double));
  res->n_steps++;
  const double pb = d->load;
  *neg_last = csf_linSolverNegativePivots(d->ls);
  csfPathPoint pt = {pb, pb - *p_last, Vb, 0, csf_wallTime() - t0, 0, 0, *neg_last, 2, res};
  if (pb >= res->p_limit) {
    res->p_limit = pb, res->V_limit = Vb;
    pt.is_max = 1;
  }
  res->p_before = *p_last;
  *p_last = pb;
  if (opt->callback && opt->callback(opt->user, m, d, &pt)) {
    res->stopped = 1;
    return 1;
  }
  return 0;
}


csStatus csf_passLimit(const csfModel* m, csfData* d, double* s_prev, double* s_conv,
                       double* s_tmp, double V_prev, double V_conv, double p_conv,
                       const csfNewtonOptions* nopt, const csfLimitOptions* opt,
                       csfLimitResult* res, csError* err) {
  const size_t ns = csf_stateSize(m);
  memset(res, 0, sizeof *res);
  res->p_limit = p_conv;
  res->V_limit = V_conv;
  res->p_resume = NAN;
  res->p_before = p_conv;
  /* first volume step: the last pressure step's volume change (large near the limit, where
   * dV/dp grows without bound) */
  const double dV0 = V_conv > V_prev ? V_conv - V_prev : 1e-3 * fabs(V_conv);
  double dV = dV0, V = V_conv, Vp = V_prev, p_last = p_conv;
  int fell = 0, rising = 0;
  int neg_last = opt->neg_conv, on_branch = 0;
  csError lerr = {0};
  /* a bifurcation crossed between the entry states (pressure control, rising): switch first */
  const int watch = opt->branch_switch || opt->critical_mode;
  if (watch && opt->neg_prev >= 0 && opt->neg_conv > opt->neg_prev) {
    const double t0 = csf_wallTime();
    double Vb = V;
    res->n_bifurcation++;
    res->p_bif = p_conv, res->V_bif = V_conv;
    csf_stateSet(m, d, s_conv);
    if (switchBranch(m, d, s_conv, s_tmp, V, dV, opt->neg_conv, nopt, opt, res, &Vb)) {
      on_branch = 1;
      Vp = V = Vb; /* no secant across the switch: the next step starts from the branch state */
      if (acceptBranch(m, d, s_prev, s_conv, s_tmp, ns, Vb, t0, opt, res, &p_last, &neg_last)) {
        return CS_OK;
      }
    }
    csf_stateSet(m, d, s_conv);
  }
  for (;;) {
    if (res->n_steps >= opt->max_steps || V > opt->max_vol_ratio * fabs(V_conv)) {
      csf_stateSet(m, d, s_conv);
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: no stable branch above the limit %.6g MPa "
                         "within %d volume steps / %.3g x the volume (at %.6g MPa)",
                         res->p_limit, res->n_steps, V / V_conv, p_last);
    }
    const double t0 = csf_wallTime();
    const double Vt = V + dV;
    const double f = V > Vp ? (Vt - V) / (V - Vp) : 0.0; /* secant predictor in the volume */
    for (size_t i = 0; i < ns; i++) {
      s_tmp[i] = s_conv[i] + f * (s_conv[i] - s_prev[i]);
    }
    csf_stateSet(m, d, s_tmp);
    int it = 0;
    const csStatus st = csf_newtonSolveVolume(m, d, Vt, nopt, &it, &lerr);
    res->n_newton += it;
    if (st != CS_OK) {
      dV *= 0.5;
      if (dV < opt->min_dv_rel * dV0) {
        csf_stateSet(m, d, s_conv);
        return cs_errorSet(err, CS_ERR_DIVERGED, "fem: volume step collapsed at %.6g MPa past "
                           "the limit %.6g MPa: %.200s", p_last, res->p_limit, lerr.msg);
      }
      continue;
    }
    res->n_steps++;
    const double pl = d->load;
    memcpy(s_prev, s_conv, ns * sizeof(double));
    csf_stateGet(m, d, s_conv);
    Vp = V, V = Vt;
    const int neg = csf_linSolverNegativePivots(d->ls);
    csfPathPoint pt = {pl, pl - p_last, Vt, it, csf_wallTime() - t0, 0, 0, neg, on_branch, res};
    if (!fell && pl >= res->p_limit) {
      res->p_limit = pl, res->V_limit = Vt;
      pt.is_max = 1;
    } else if (pl < res->p_limit) {
      fell = 1;
    }
    pt.past_limit = fell;
    res->fell = fell;
    res->p_before = p_last;
    p_last = pl;
    if (opt->callback && opt->callback(opt->user, m, d, &pt)) {
      res->stopped = 1;
      return CS_OK;
    }
    /* a bifurcation: one more negative pivot with the pressure still rising */
    if (watch && !res->switched && res->n_bifurcation == 0 && !fell && pt.dp > 0 &&
        neg_last >= 0 && neg > neg_last) {
      const double t1 = csf_wallTime();
      double Vb = V;
      res->n_bifurcation++;
      res->p_bif = pl, res->V_bif = V;
      if (switchBranch(m, d, s_conv, s_tmp, V, dV, neg, nopt, opt, res, &Vb)) {
        on_branch = 1;
        Vp = V = Vb; /* no secant across the switch */
        rising = 0;
        if (acceptBranch(m, d, s_prev, s_conv, s_tmp, ns, Vb, t1, opt, res, &p_last,
                         &neg_last)) {
          return CS_OK;
        }
        continue;
      }
      csf_stateSet(m, d, s_conv);
    }
    neg_last = neg;
    if (fell && pl > res->p_limit) {
      res->p_resume = pl;
      return CS_OK;
    }
    /* still rising well above where pressure control gave up: that was no limit point (Newton
     * failed for another reason), the path is stable under pressure control */
    rising = pt.dp > 0 ? rising + 1 : 0;
    if (!fell && rising >= CSF_PATH_RISING && pl > (1.0 + CSF_PATH_RISE) * p_conv &&
        (!opt->branch_switch || neg <= 0)) {
      res->p_resume = pl;
      res->no_limit = 1;
      return CS_OK;
    }
    if (it <= 5) {
      dV = fmin(1.5 * dV, 8.0 * dV0);
    } else if (it > 10) {
      dV *= 0.7;
    }
  }
}

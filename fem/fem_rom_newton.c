/* fem_rom_newton.c: the reduced Newton on q (fem_rom.h csf_romNewton): the dense LU of the
 * reduced tangent, the line search, the element states' update along a step, and the
 * quasi-Newton (BFGS) pairs. The residual and tangent it solves with are fem_rom_eval.c's
 * csf_romEvaluate; the model and its data are fem_rom.c.
 *
 * Rationale.
 * The dense n x n system is solved by LU with partial pivoting (n is tens to a few hundred; the
 * tangent may be indefinite past a limit point). The element states (theta_e, the fibres' S)
 * follow the step as the FE's three-field Newton does (fem_rom_eval.c says why they are the
 * kernels' state variables). */
#include "fem_rom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_element.h"
#include "fem_material.h"
#include "fem_rom_fibre.h"
#include "fem_rom_internal.h"
#include "fem_rom_mixed.h"

#define ROM_LS_SHRINK 0.5 /* line-search step factor */
/* the FE's watchdog line search (fem_newton.c CSF_LS_GROWTH_FIRST, CSF_LS_WATCH) */
#define ROM_LS_GROWTH_FIRST 1e4
#define ROM_LS_WATCH 3

csfRomNewtonOptions csf_romNewtonDefault(void) {
  csfRomNewtonOptions o;
  o.max_iter = 40;
  o.rtol = 1e-8; /* the FE's element tests' default (csf_newtonDefault) */
  o.atol = 1e-12;
  o.max_ls = 8;
  o.k_lag = 0.0;
  o.bfgs = 0;
  o.bfgs_keep = 0;
  return o;
}

/* LU with partial pivoting of A (n x n row-major) in place, the row swaps in piv; -1 singular */
static int luFactor(int n, double* A, int* piv) {
  for (int k = 0; k < n; k++) {
    int p = k;
    for (int i = k + 1; i < n; i++) {
      p = fabs(A[(size_t)i * n + k]) > fabs(A[(size_t)p * n + k]) ? i : p;
    }
    piv[k] = p;
    if (A[(size_t)p * n + k] == 0.0) {
      return -1;
    }
    if (p != k) {
      for (int j = 0; j < n; j++) {
        const double t = A[(size_t)k * n + j];
        A[(size_t)k * n + j] = A[(size_t)p * n + j], A[(size_t)p * n + j] = t;
      }
    }
    for (int i = k + 1; i < n; i++) {
      const double l = A[(size_t)i * n + k] / A[(size_t)k * n + k];
      A[(size_t)i * n + k] = l;
      for (int j = k + 1; j < n; j++) {
        A[(size_t)i * n + j] -= l * A[(size_t)k * n + j];
      }
    }
  }
  return 0;
}

/* solve with luFactor's factor: b becomes x */
static void luSolveFactored(int n, const double* LU, const int* piv, double* b) {
  for (int k = 0; k < n; k++) {
    if (piv[k] != k) {
      const double t = b[k];
      b[k] = b[piv[k]], b[piv[k]] = t;
    }
  }
  for (int i = 1; i < n; i++) {
    double s = b[i];
    for (int j = 0; j < i; j++) {
      s -= LU[(size_t)i * n + j] * b[j];
    }
    b[i] = s;
  }
  for (int i = n - 1; i >= 0; i--) {
    double s = b[i];
    for (int j = i + 1; j < n; j++) {
      s -= LU[(size_t)i * n + j] * b[j];
    }
    b[i] = s / LU[(size_t)i * n + i];
  }
}

/* the three-field update along alpha dq (fem_newton.c updateTheta): theta_e = (v_e + alpha g_e .
 * du_e) / V_e, the fibres' S = S(E0 + alpha d0 . dd / L0^2), over the kept elements */
static void updateStates(const csfRom* r, csfRomData* d, double alpha) {
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  if (r->m > 0) {
    /* mixed: p^_state = A^-1 sum_e w_e P_e (v_e + alpha g_e . du_e - V_e), linearised at the
     * iterate, and theta_e = 1 + P_e . p^_state / kappa carries it into the kernel */
    const int mm = r->m;
    double* ps = d->mtmp;
    memset(ps, 0, (size_t)mm * sizeof(double));
    for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
      const int e = r->el[CSF_ROM_SET_TET][k];
      double due[30];
      csf_romGather(r, d->dq, 10, me->tet + 10 * (size_t)e, due);
      const double* g = d->g0 + 30 * (size_t)e;
      double sg = 0;
      for (int a = 0; a < 30; a++) {
        sg += g[a] * due[a];
      }
      const double c = r->w[CSF_ROM_SET_TET][k] * ((d->vr0[e] - 1.0) * m->vol[e] + alpha * sg);
      const double* Pe = r->P + (size_t)e * (size_t)mm;
      for (int i = 0; i < mm; i++) {
        ps[i] += c * Pe[i];
      }
    }
    csf_romMixedSolve(r, ps);
    for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
      const int e = r->el[CSF_ROM_SET_TET][k];
      const double* Pe = r->P + (size_t)e * (size_t)mm;
      double pe = 0;
      for (int i = 0; i < mm; i++) {
        pe += Pe[i] * ps[i];
      }
      d->theta[e] = 1.0 + pe / m->mat.kappa;
    }
  }
  for (int k = 0; r->m == 0 && k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    double due[30];
    csf_romGather(r, d->dq, 10, me->tet + 10 * (size_t)e, due);
    const double* g = d->g0 + 30 * (size_t)e;
    double s = 0;
    for (int a = 0; a < 30; a++) {
      s += g[a] * due[a];
    }
    d->theta[e] = d->vr0[e] + alpha * s / m->vol[e];
  }
  if (r->mf > 0) {
    csf_romFibreStates(r, d, alpha);
  }
  for (int k = 0; r->mf == 0 && k < r->nel[CSF_ROM_SET_FIBRE]; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    const double* D = r->fib_D + (size_t)k * 3 * (size_t)r->n;
    double dd[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < r->n; j++) {
        dd[i] += D[(size_t)i * r->n + j] * d->dq[j];
      }
    }
    const double* d0 = d->fib_d0 + 3 * (size_t)f;
    const double L0 = m->fib_L0[f];
    const double El = d->fib_E0[f] + alpha * (d0[0] * dd[0] + d0[1] * dd[1] + d0[2] * dd[2]) /
                                         (L0 * L0);
    double dS;
    csf_fibreLaw(m->fib_tension_only, El, &d->fib_S[f], &dS);
  }
}

/* copy the states of the kept elements between buffers (dst <- src) */
static void copyStates(const csfRom* r, double* th_dst, const double* th_src, double* S_dst,
                       const double* S_src) {
  for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    th_dst[e] = th_src[e];
  }
  for (int k = 0; k < r->nel[CSF_ROM_SET_FIBRE]; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    S_dst[f] = S_src[f];
  }
}

/* the update's base: v/V, g, E and d of the kept elements at the iterate */
static void keepBase(const csfRom* r, csfRomData* d) {
  for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    d->vr0[e] = d->vr[e];
    memcpy(d->g0 + 30 * (size_t)e, d->gel + 30 * (size_t)e, 30 * sizeof(double));
  }
  for (int k = 0; k < r->nel[CSF_ROM_SET_FIBRE]; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    d->fib_E0[f] = d->fib_E[f];
    memcpy(d->fib_d0 + 3 * (size_t)f, d->fib_d + 3 * (size_t)f, 3 * sizeof(double));
  }
}

static csStatus newtonFail(const csfRom* r, csfRomData* d, const csfRomLoad* load, int it,
                           csError* err, const char* why) {
  d->lu_valid = 0;
  memcpy(d->q, d->q_save, (size_t)r->n * sizeof(double));
  copyStates(r, d->theta, d->theta_save, d->fib_S, d->fib_S_save);
  csf_romEvaluate(r, d, load, 0);
  return cs_errorSet(err, CS_ERR_DIVERGED, "fem_rom: %s at iteration %d (|r| %.3g N of %.3g)",
                     why, it, d->rnorm, d->fnorm);
}

/* factor K at the current iterate into d->lu (d->lu_valid); -1 singular. A new factor drops
 * the BFGS pairs of the old one. */
static int factorTangent(const csfRom* r, csfRomData* d) {
  const int n = r->n;
  memcpy(d->lu, d->K, (size_t)n * (size_t)n * sizeof(double));
  d->lu_valid = luFactor(n, d->lu, d->piv) == 0;
  d->bf_k = 0;
  return d->lu_valid ? 0 : -1;
}

void csf_romQuasiNewtonApply(const csfRom* r, csfRomData* d, double* x) {
  /* the two-loop recursion (Nocedal and Wright 2006, alg. 7.4), H0 = K0^-1 (the kept LU) */
  const size_t n = (size_t)r->n;
  for (int k = d->bf_k - 1; k >= 0; k--) {
    const double* s = d->bf_s + (size_t)k * n, *y = d->bf_y + (size_t)k * n;
    double a = 0;
    for (size_t j = 0; j < n; j++) {
      a += s[j] * x[j];
    }
    a *= d->bf_rho[k];
    d->bf_a[k] = a;
    for (size_t j = 0; j < n; j++) {
      x[j] -= a * y[j];
    }
  }
  luSolveFactored(r->n, d->lu, d->piv, x);
  for (int k = 0; k < d->bf_k; k++) {
    const double* s = d->bf_s + (size_t)k * n, *y = d->bf_y + (size_t)k * n;
    double b = 0;
    for (size_t j = 0; j < n; j++) {
      b += y[j] * x[j];
    }
    b = d->bf_a[k] - d->bf_rho[k] * b;
    for (size_t j = 0; j < n; j++) {
      x[j] += b * s[j];
    }
  }
}

int csf_romQuasiNewtonPush(const csfRom* r, csfRomData* d, const double* s, const double* y,
                           int cap) {
  const size_t n = (size_t)r->n;
  cap = cap < CSF_ROM_BFGS_MAX ? cap : CSF_ROM_BFGS_MAX;
  double ys = 0, ss = 0, yy = 0;
  for (size_t j = 0; j < n; j++) {
    ys += y[j] * s[j], ss += s[j] * s[j], yy += y[j] * y[j];
  }
  /* curvature condition: BFGS keeps H positive definite only with y . s > 0; a pair this close
   * to it (round-off of the residual's difference) is not worth storing either */
  if (cap <= 0 || !(ys > 1e-12 * sqrt(ss * yy))) {
    return 0;
  }
  if (d->bf_k == cap) {
    /* the oldest pair leaves (L-BFGS's memory) */
    memmove(d->bf_s, d->bf_s + n, (size_t)(cap - 1) * n * sizeof(double));
    memmove(d->bf_y, d->bf_y + n, (size_t)(cap - 1) * n * sizeof(double));
    memmove(d->bf_rho, d->bf_rho + 1, (size_t)(cap - 1) * sizeof(double));
    d->bf_k--;
  }
  memcpy(d->bf_s + (size_t)d->bf_k * n, s, n * sizeof(double));
  memcpy(d->bf_y + (size_t)d->bf_k * n, y, n * sizeof(double));
  d->bf_rho[d->bf_k] = 1.0 / ys;
  d->bf_k++;
  return 1;
}

csStatus csf_romFactorTangent(const csfRom* r, csfRomData* d, csError* err) {
  if (factorTangent(r, d) != 0) {
    return cs_errorSet(err, CS_ERR_SOLVER, "fem_rom: singular reduced tangent");
  }
  return CS_OK;
}

/* after a step taken on the kept factor: its secant pair (s = q - q0, y = r - r0) */
static void pushStep(const csfRom* r, csfRomData* d, int cap) {
  const size_t n = (size_t)r->n;
  double* s = d->tmp;
  for (size_t j = 0; j < n; j++) {
    s[j] = d->q[j] - d->q0[j];
    d->bf_r0[j] = d->r[j] - d->bf_r0[j]; /* y, in the r0 buffer: it is refilled every step */
  }
  csf_romQuasiNewtonPush(r, d, s, d->bf_r0, cap);
}

csStatus csf_romNewton(const csfRom* r, csfRomData* d, const csfRomLoad* load,
                       const csfRomNewtonOptions* o, int* iters, csError* err) {
  const size_t n = (size_t)r->n;
  const int lag = o->k_lag > 0.0;
  memcpy(d->q_save, d->q, n * sizeof(double));
  copyStates(r, d->theta_save, d->theta, d->fib_S_save, d->fib_S);
  int it = 0, strict = 0, since_best = 0;
  if (iters) {
    *iters = 0;
  }
  if (!lag) {
    d->lu_valid = 0;
  }
  const int bfgs = lag ? o->bfgs : 0;
  if (!o->bfgs_keep || !d->lu_valid) {
    d->bf_k = 0; /* the pairs belong to the last call's load */
  }
  /* the tangent of this iterate is in d->K (fresh) or only the residual was evaluated */
  int fresh = !(lag && d->lu_valid);
  if (csf_romEvaluate(r, d, load, fresh) != 0) {
    return newtonFail(r, d, load, it, err, "the starting state is not physical (an inverted "
                      "element)");
  }
  double r_best = INFINITY; /* the first iterate is the first best one (fem_newton.c) */
  while (!(d->rnorm <= o->rtol * d->fnorm || d->rnorm <= o->atol)) {
    if (it >= o->max_iter) {
      return newtonFail(r, d, load, it, err, "Newton did not converge");
    }
    if (fresh && factorTangent(r, d) != 0) {
      return newtonFail(r, d, load, it, err, "singular reduced tangent");
    }
    for (size_t j = 0; j < n; j++) {
      d->dq[j] = -d->r[j];
    }
    memcpy(d->bf_r0, d->r, n * sizeof(double));
    if (bfgs > 0) {
      csf_romQuasiNewtonApply(r, d, d->dq); /* K0^-1 alone while no pair is stored */
    } else {
      luSolveFactored(r->n, d->lu, d->piv, d->dq);
    }
    keepBase(r, d);
    memcpy(d->q0, d->q, n * sizeof(double));
    const double r0 = d->rnorm;
    if (!fresh) {
      /* a step on the kept factor: taken if it reduces |r|, else taken back; the tangent is
       * formed at this iterate and the step redone as a Newton step */
      for (size_t j = 0; j < n; j++) {
        d->q[j] = d->q0[j] + d->dq[j];
      }
      /* the residual does not depend on the states: they follow only a step that is taken
       * (reset to v/V at q0 instead, the spurious pressure of an overshooting iterate would
       * enter the next tangent: the stall csfRomData describes) */
      const int ev = csf_romEvaluate(r, d, load, 0);
      if (ev == 0 && d->rnorm < r0) {
        updateStates(r, d, 1.0);
        it++;
        d->n_newton++;
        fresh = 0;
        if (bfgs > 0) {
          pushStep(r, d, bfgs);
        }
        if (d->rnorm > o->k_lag * r0) {
          /* slow contraction: a new tangent at the new iterate */
          if (csf_romEvaluate(r, d, load, 1) != 0) {
            return newtonFail(r, d, load, it, err, "the iterate is not physical");
          }
          fresh = 1;
        }
        if (d->rnorm < r_best) {
          r_best = d->rnorm;
          memcpy(d->q_best, d->q, n * sizeof(double));
          copyStates(r, d->theta_best, d->theta, d->fib_S_best, d->fib_S);
        }
        continue;
      }
      memcpy(d->q, d->q0, n * sizeof(double));
      if (csf_romEvaluate(r, d, load, 1) != 0) {
        return newtonFail(r, d, load, it, err, "the iterate is not physical");
      }
      fresh = 1;
      continue;
    }
    /* a full step unless |r| grows past ROM_LS_GROWTH_FIRST (lenient) or at all (strict, after
     * the watchdog's return), halving otherwise (fem_newton.c) */
    const double growth = strict ? 1.0 : ROM_LS_GROWTH_FIRST;
    double alpha = 1.0;
    int ok = 0;
    for (int ls = 0; ls <= o->max_ls; ls++) {
      for (size_t j = 0; j < n; j++) {
        d->q[j] = d->q0[j] + alpha * d->dq[j];
      }
      updateStates(r, d, alpha);
      /* with a lagged tangent the trial evaluates the residual alone first */
      if (csf_romEvaluate(r, d, load, !lag) == 0 && d->rnorm < growth * r0) {
        ok = 1;
        break;
      }
      alpha *= ROM_LS_SHRINK;
    }
    it++;
    d->n_newton++;
    if (!ok) {
      return newtonFail(r, d, load, it, err, "line search failed");
    }
    fresh = !lag;
    if (bfgs > 0 && d->rnorm <= o->k_lag * r0) {
      pushStep(r, d, bfgs); /* the factor is kept: this step's pair corrects it */
    }
    if (lag && d->rnorm > o->k_lag * r0) {
      if (csf_romEvaluate(r, d, load, 1) != 0) {
        return newtonFail(r, d, load, it, err, "the iterate is not physical");
      }
      fresh = 1;
    }
    strict = 0;
    if (d->rnorm < r_best) {
      r_best = d->rnorm;
      since_best = 0;
      memcpy(d->q_best, d->q, n * sizeof(double));
      copyStates(r, d->theta_best, d->theta, d->fib_S_best, d->fib_S);
    } else if (++since_best >= ROM_LS_WATCH) {
      memcpy(d->q, d->q_best, n * sizeof(double));
      copyStates(r, d->theta, d->theta_best, d->fib_S, d->fib_S_best);
      if (csf_romEvaluate(r, d, load, 1) != 0) {
        return newtonFail(r, d, load, it, err, "the best iterate is not physical");
      }
      fresh = 1;
      since_best = 0;
      strict = 1;
    }
  }
  if (iters) {
    *iters = it;
  }
  return CS_OK;
}

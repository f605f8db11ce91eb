/* robot_rod_static.c: the Cosserat-rod leg's static layer: the equilibrium under pressures, a
 * tip load and gravity (Newton with load stepping), and one point of `crawlsim bend --model
 * rod`.
 *
 * ---- Method (rationale) ---------------------------------------------------------------------
 * Unknowns: per element the node position x_e (3) and a rotation increment δψ_e (3, body
 * frame: Q_e <- Q_e exp([δψ_e])), 6N in all; the residual is the kernel's node forces and frame
 * torques at zero velocity (the same force laws the dynamics integrates), scaled by a
 * characteristic force F_c = max(EI/L², |tip force|, weight, |tip moment|/L) and F_c L, so one
 * tolerance serves every rod. The Jacobian is block tridiagonal (element blocks couple to their
 * neighbours; 6 x 6 blocks) and built by forward differences in three column groups of blocks
 * (18 residual evaluations, exact sparsity, relative error ~1e-8 with the steps below),
 * factored by the block LU of robot_rod_linsol.c. Newton takes the full step when the residual norm
 * drops by the Armijo factor, otherwise halves it (down to 1/64). Load stepping: the
 * intrinsic strains, tip load and gravity move linearly from the last solved load to the new
 * one; the increment doubles after a success and halves after a failure (down to 1/4096 of
 * the range). A closed-form energy line search was not needed: the problems here (dead
 * loads, gravity, intrinsic strains) are conservative and the residual merit function works
 * from the straight state up to full 2π bends in one or a few increments. KINSOL would do the
 * same with less control over the multiplicative rotation update, which is not a vector-space
 * increment. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "robot_rod_internal.h"

/* forward-difference steps: positions relative to the rod length (strain steps ~1e-7 per
 * element, ≈ √eps times the strain scale) and rotations in rad */
#define CSR_ROD_FD_X_REL 1e-8
#define CSR_ROD_FD_PHI 1e-7
/* Armijo factor and the smallest line-search step */
#define CSR_ROD_ARMIJO 1e-4
#define CSR_ROD_MIN_ALPHA (1.0 / 64)
/* smallest load increment (fraction of the load change) before giving up */
#define CSR_ROD_MIN_DLAM (1.0 / 4096)

/* static loads: strains interpolated from act0 to act1 by lam, tip load and gravity likewise */
typedef struct {
  csrRodSegmentActuation act0[CSR_NSEG], act1[CSR_NSEG];
  double tipF0[3], tipF1[3], tipM0[3], tipM1[3];
  double g0, g1; /* gravity factor 0 or 1 at both ends */
} StaticPath;

/* the loads at fraction lam of the path */
static void pathLoads(const csrRodModel* m, const StaticPath* P, double lam, csrRodLoads* ld);
/* scaled residual of state y under ld into r (6N); 0 ok, 1 not a configuration */
static int residual(const csrRodModel* m, csrRodData* d, const double* y, const csrRodLoads* ld,
                    double Fc, double* r);
/* y <- y ⊕ alpha δ (positions added, rotations composed on the right) into out */
static void applyStep(const csrRodModel* m, const double* y, const double* del, double alpha,
                      double* out);
/* Newton at fixed loads from d's state; 0 converged (state updated), 1 not */
static int newton(const csrRodModel* m, csrRodData* d, const csrRodLoads* ld, double Fc,
                  csrRodStaticInfo* info);
/* ∞-norm */
static double normInf(const double* a, int n);


static double normInf(const double* a, int n) {
  double r = 0;
  for (int i = 0; i < n; i++) {
    double v = fabs(a[i]);
    if (!(v <= r)) {
      r = v; /* also propagates NaN */
    }
  }
  return r;
}


static void pathLoads(const csrRodModel* m, const StaticPath* P, double lam, csrRodLoads* ld) {
  csrRodSegmentActuation act[CSR_NSEG];
  for (int s = 0; s < CSR_NSEG; s++) {
    const csrRodSegmentActuation *a = &P->act0[s], *b = &P->act1[s];
    csrRodSegmentActuation* o = &act[s];
    memset(o, 0, sizeof *o);
    for (int k = 0; k < 3; k++) {
      o->u0[k] = a->u0[k] + lam * (b->u0[k] - a->u0[k]);
      o->sigma0[k] = a->sigma0[k] + lam * (b->sigma0[k] - a->sigma0[k]);
    }
    /* calibrated stiffness: the target's (stiffness is a property, not a load to ramp) */
    o->has_section = b->has_section;
    o->section = b->section;
  }
  csr_rodLoadsFromActuation_(m, act, ld);
  double g = P->g0 + lam * (P->g1 - P->g0);
  for (int k = 0; k < 3; k++) {
    ld->gravity[k] = g * m->gravity[k];
    ld->tip_force[k] = P->tipF0[k] + lam * (P->tipF1[k] - P->tipF0[k]);
    ld->tip_moment[k] = P->tipM0[k] + lam * (P->tipM1[k] - P->tipM0[k]);
  }
  ld->damping = 0;
  ld->contact = 0;
}


static int residual(const csrRodModel* m, csrRodData* d, const double* y, const csrRodLoads* ld,
                    double Fc, double* r) {
  double q0[4];
  const double zero[3] = {0, 0, 0};
  csu_mat3ToQuat(q0, d->cur_base.R);
  if (csr_rodUnpack_(m, &d->wk, y, d->cur_base.x, q0, zero, zero) != 0) {
    return 1;
  }
  d->wk.hist = NULL;
  d->wk.dhist = NULL;
  csr_rodForces_(m, &d->wk, ld, 0, NULL, 0);
  const double sF = 1.0 / Fc, sT = 1.0 / (Fc * m->L);
  for (int e = 1; e <= m->N; e++) {
    double* re = r + 6 * (e - 1);
    for (int k = 0; k < 3; k++) {
      re[k] = d->wk.F[3 * e + k] * sF;
      re[3 + k] = d->wk.T[3 * e + k] * sT;
    }
  }
  return isfinite(normInf(r, 6 * m->N)) ? 0 : 1;
}


static void applyStep(const csrRodModel* m, const double* y, const double* del, double alpha,
                      double* out) {
  if (out != y) {
    memcpy(out, y, (size_t)m->nstate * sizeof(double));
  }
  for (int e = 1; e <= m->N; e++) {
    double* b = out + m->boff[e];
    const double* de = del + 6 * (e - 1);
    for (int k = 0; k < 3; k++) {
      b[CSR_ROD_BX + k] += alpha * de[k];
    }
    double phi[3] = {alpha * de[3], alpha * de[4], alpha * de[5]}, dq[4], q[4];
    csr_rodQexp(dq, phi);
    csr_rodQmul(q, b + CSR_ROD_BQ, dq);
    csr_rodQnormalize(q);
    memcpy(b + CSR_ROD_BQ, q, sizeof q);
  }
}


/* the block-tridiagonal Jacobian of the scaled residual at y (r = residual at y) into
 * d->bt_static */
static int jacobian(const csrRodModel* m, csrRodData* d, const double* y, const csrRodLoads* ld,
                    double Fc, const double* r) {
  const int N = m->N, n = 6 * N;
  const double hx = CSR_ROD_FD_X_REL * m->L;
  csrRodBt* bt = &d->bt_static;
  csr_rodBtZero_(bt);
  double* del = d->sdel;
  for (int g = 0; g < 3; g++) {
    for (int c = 0; c < 6; c++) {
      const double h = c < 3 ? hx : CSR_ROD_FD_PHI;
      memset(del, 0, (size_t)n * sizeof(double));
      for (int e = 1 + g; e <= N; e += 3) {
        del[6 * (e - 1) + c] = h;
      }
      applyStep(m, y, del, 1.0, d->sy);
      if (residual(m, d, d->sy, ld, Fc, d->sres2) != 0) {
        return 1;
      }
      /* column c of block column j = e - 1 (0-based) in block rows j-1, j, j+1 */
      for (int e = 1 + g; e <= N; e += 3) {
        const int j = e - 1;
        for (int i = j - 1; i <= j + 1; i++) {
          if (i < 0 || i >= N) {
            continue;
          }
          double* blk = i == j ? bt->D + 36 * i : (i > j ? bt->B + 36 * i : bt->C + 36 * i);
          for (int rr = 0; rr < 6; rr++) {
            blk[6 * rr + c] = (d->sres2[6 * i + rr] - r[6 * i + rr]) / h;
          }
        }
      }
    }
  }
  return 0;
}


static int newton(const csrRodModel* m, csrRodData* d, const csrRodLoads* ld, double Fc,
                  csrRodStaticInfo* info) {
  const int n = 6 * m->N;
  double* y = d->y + CSR_ROD_NIMP;
  double* r = d->sres;
  if (residual(m, d, y, ld, Fc, r) != 0) {
    return 1;
  }
  double rn = normInf(r, n);
  for (int it = 0; it < m->par.static_max_iter; it++) {
    if (rn <= m->par.static_tol) {
      info->residual = rn;
      return 0;
    }
    info->newton_iters++;
    if (jacobian(m, d, y, ld, Fc, r) != 0 || csr_rodBtFactor_(&d->bt_static) != 0) {
      return 1;
    }
    for (int i = 0; i < n; i++) {
      d->sdel[i] = -r[i];
    }
    csr_rodBtSolve_(&d->bt_static, d->sdel);
    /* backtracking on the residual's 2-norm */
    double r2 = 0;
    for (int i = 0; i < n; i++) {
      r2 += r[i] * r[i];
    }
    double alpha = 1.0;
    int accepted = 0;
    while (alpha >= CSR_ROD_MIN_ALPHA) {
      applyStep(m, y, d->sdel, alpha, d->sy);
      if (residual(m, d, d->sy, ld, Fc, d->sres2) == 0) {
        double t2 = 0;
        for (int i = 0; i < n; i++) {
          t2 += d->sres2[i] * d->sres2[i];
        }
        if (sqrt(t2) <= (1 - CSR_ROD_ARMIJO * alpha) * sqrt(r2)) {
          accepted = 1;
          break;
        }
      }
      alpha *= 0.5;
    }
    if (!accepted) {
      /* near round-off the merit cannot decrease any more: accept a tiny residual */
      info->residual = rn;
      return rn <= 1e3 * m->par.static_tol ? 0 : 1;
    }
    memcpy(y, d->sy, (size_t)m->nstate * sizeof(double));
    memcpy(r, d->sres2, (size_t)n * sizeof(double));
    rn = normInf(r, n);
  }
  info->residual = rn;
  return rn <= m->par.static_tol ? 0 : 1;
}


csStatus csr_rodStatic(const csrRodModel* m, csrRodData* d, const csrRodStaticLoad* load,
                       csrRodStaticInfo* info, csError* err) {
  csrRodStaticInfo tmp;
  if (!info) {
    info = &tmp;
  }
  memset(info, 0, sizeof *info);
  if (!m || !d || !load) {
    return cs_errorSet(err, CS_ERR_ARG, "rod static: NULL argument");
  }
  double chk = 0;
  for (int k = 0; k < 3; k++) {
    chk += load->tip_force[k] + load->tip_moment[k];
  }
  for (int k = 0; k < CSR_NSEG * CSR_NCHAMBER; k++) {
    chk += load->p[k];
  }
  if (!isfinite(chk)) {
    return cs_errorSet(err, CS_ERR_ARG, "rod static: pressures and tip load must be finite");
  }
  StaticPath P;
  memset(&P, 0, sizeof P);
  for (int s = 0; s < CSR_NSEG; s++) {
    int rc = csr_rodActuationEval_(m, s, load->p + CSR_NCHAMBER * s, &P.act1[s], d->cb_msg,
                                   sizeof d->cb_msg);
    if (rc != 0) {
      return cs_errorSet(err, rc == CSR_MAP_OUT_OF_RANGE ? CS_ERR_RANGE : CS_ERR_SOLVER,
                         "rod static: %s", d->cb_msg);
    }
  }
  memcpy(P.tipF1, load->tip_force, sizeof P.tipF1);
  memcpy(P.tipM1, load->tip_moment, sizeof P.tipM1);
  P.g1 = load->gravity ? 1 : 0;
  if (d->static_valid) {
    memcpy(P.act0, d->static_act, sizeof P.act0);
    memcpy(P.tipF0, d->static_load.tip_force, sizeof P.tipF0);
    memcpy(P.tipM0, d->static_load.tip_moment, sizeof P.tipM0);
    P.g0 = d->static_load.gravity ? 1 : 0;
  } else {
    /* the state is not a known equilibrium: Newton from it under the full new load */
    memcpy(P.act0, P.act1, sizeof P.act0);
    memcpy(P.tipF0, P.tipF1, sizeof P.tipF0);
    memcpy(P.tipM0, P.tipM1, sizeof P.tipM0);
    P.g0 = P.g1;
  }
  /* characteristic force: bending (EI/L²), the loads, the weight */
  double EI = 0;
  for (int k = 0; k < m->npiece; k++) {
    EI = fmax(EI, fmax(m->piece[k].section.EI[0], m->piece[k].section.EI[1]));
  }
  double Fc = EI / (m->L * m->L);
  Fc = fmax(Fc, fmax(csu_norm3(P.tipF1), csu_norm3(P.tipF0)));
  Fc = fmax(Fc, fmax(csu_norm3(P.tipM1), csu_norm3(P.tipM0)) / m->L);
  Fc = fmax(Fc, m->mass * csu_norm3(m->gravity) * fmax(P.g0, P.g1));

  const size_t ny = CSR_ROD_NIMP + (size_t)m->nstate;
  double* y = d->y + CSR_ROD_NIMP;
  memcpy(d->backup, d->y, ny * sizeof(double));
  /* at rest: velocities zero */
  for (int e = 0; e < m->N; e++) {
    double* b = y + m->boff[e + 1];
    memset(b + CSR_ROD_BV, 0, 6 * sizeof(double));
  }
  double lam = 0, dlam = 1;
  while (lam < 1) {
    double lt = fmin(1.0, lam + dlam);
    csrRodLoads ld;
    pathLoads(m, &P, lt, &ld);
    memcpy(d->sy0, y, (size_t)m->nstate * sizeof(double));
    if (newton(m, d, &ld, Fc, info) == 0) {
      lam = lt;
      info->load_steps++;
      dlam = fmin(2 * dlam, 1.0);
    } else {
      memcpy(y, d->sy0, (size_t)m->nstate * sizeof(double));
      dlam *= 0.5;
      info->cutbacks++;
      if (dlam < CSR_ROD_MIN_DLAM) {
        memcpy(d->y, d->backup, ny * sizeof(double));
        return cs_errorSet(err, CS_ERR_SOLVER,
                           "rod static: Newton failed at load fraction %.4f of the step "
                           "(increment below %g, residual %.3g after %d iterations)",
                           lam, CSR_ROD_MIN_DLAM, info->residual, info->newton_iters);
      }
    }
  }
  /* the rod now carries this load: actuation and tip load as the dynamics will see them */
  d->static_valid = 1;
  d->static_load = *load;
  memcpy(d->static_act, P.act1, sizeof d->static_act);
  memset(&d->act, 0, sizeof d->act);
  d->act.ta = d->act.tb = d->t;
  memcpy(d->act.a, P.act1, sizeof d->act.a);
  memcpy(d->act.b, P.act1, sizeof d->act.b);
  memcpy(d->act.pa, load->p, sizeof d->act.pa);
  memcpy(d->act.pb, load->p, sizeof d->act.pb);
  d->act.set = 1;
  memcpy(d->tip_force, load->tip_force, sizeof d->tip_force);
  memcpy(d->tip_moment, load->tip_moment, sizeof d->tip_moment);
  d->need_reinit = 1;
  return CS_OK;
}


csStatus csr_rodBendPoint(const csrRodModel* m, csrRodData* d, const double p[12],
                          const double tip_force_base[3], double angle_deg[CSR_NSEG],
                          double tip[3], csError* err) {
  csrRodStaticLoad ld;
  memset(&ld, 0, sizeof ld);
  memcpy(ld.p, p, sizeof ld.p);
  csu_mulMatVec3(ld.tip_force, d->cur_base.R, tip_force_base);
  csStatus st = csr_rodStatic(m, d, &ld, NULL, err);
  if (st != CS_OK) {
    return st;
  }
  double ang[CSR_NSEG];
  csr_rodSegmentAngles(m, d, ang, tip);
  for (int s = 0; s < CSR_NSEG; s++) {
    angle_deg[s] = ang[s] / CS_DEG;
  }
  return CS_OK;
}

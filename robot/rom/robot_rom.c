/* robot_rom.c: the reduced-order FE leg's dynamics in the hip's floating frame (robot_rom.h):
 * the right-hand side and its dense Jacobian for CVODE (BDF), the base motion across a macro
 * step, advance with the base wrench by momentum balance, momentum,
 * state get/set. The model (its mass operators) is robot_rom_model.c's.
 *
 * Integration: y = [q, q'] (2n), y' = [q', M_r⁻¹ F(t, q, q')]. The reduced leg is stiff (the
 * bulk and fibre modes of the FE survive in the span at kHz, the damping C = τ_d K_r(0) makes
 * them real eigenvalues near -τ_d ω²), so CVODE's BDF with a Newton iteration on the dense
 * 2n x 2n matrix I - γJ, J from the reduced tangent K_r(q) (csf_romEvaluate, exact derivative
 * with the states synchronised) and the inertia operators. n is a few tens: a dense LU is the
 * whole linear algebra. */
#include "robot_rom.h"

#include <cvode/cvode.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_config.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include "core_math.h"
#include "core_sun.h"

_Static_assert(sizeof(sunrealtype) == sizeof(double), "crawlsim needs double SUNDIALS");

/* the base motion of one macro step (robot_rom.h "Base motion") */
typedef struct RomBase_ {
  double ta, H;
  double x0[3], v0[3], x1[3], v1[3]; /* hip point, world */
  double R0[9];                      /* frame at ta */
  double dphi0[3], Phi[3], dphi1[3]; /* rotation vector's Hermite data, frame-0 coordinates */
} RomBase;

struct csrRomData_ {
  const csrRomModel* m;
  int n;
  double t;
  csrBaseState base;  /* the hip at t */
  double pt0, pt1, p0[12], p1[12];
  double* fdead;      /* (n) reduced dead load, or unused when have_dead = 0 */
  int have_dead;
  RomBase bm;
  csfRomData* fd;     /* the reduced FE's evaluation data */
  double* face_p;     /* (nface) */
  double* F;          /* (n) scratch: generalised force */
  double* G;          /* (n x n) scratch */
  double* backup;     /* (2n + nz) the state before a step, restored when it fails */
  /* contact (m->contact): y = [q, q', I_m (3), z (nz), I_f (3)], I_f the contact force's
   * impulse; scratch for the sole's load and its differences */
  int ny;             /* 2n + 3, + nz + 3 with contact */
  double* Fc;         /* (n) */
  double* zd;         /* (nz) */
  double* Gs;         /* ((6 + nz) x (2n + nz)) the sole's derivatives (csr_romSoleJacobian) */
  double* sw;         /* its work (csr_romSoleWorkSize) */
  double* As;         /* (n x 6) [Ūᵀ Rᵀ, Wᵀ Rᵀ] */
  double* y;          /* pointer into yv */
  SUNContext sun;
  N_Vector yv, atol;
  SUNMatrix A;
  SUNLinearSolver LS;
  void* cvode;
  /* the lagged tangent (csrRomParams.tangent_lag): K_r at q_lag and pressures p_lag */
  double* Klag;       /* (n x n) */
  double* qlag;       /* (n) */
  double* vmax;       /* (n) max_i |V_ik|, mm per unit q_k */
  double plag[12];
  int lag_valid;
  long tangents;      /* evaluations with the tangent (jacs less the lagged ones) */
  long steps, rhs, jacs, restarts, retries, sole;
  /* CVODE's counters of its earlier lives (a restart's CVodeReInit zeroes them) */
  long cv_setups, cv_niters, cv_nfails, cv_efails;
  int cb_status;
  int need_reinit;    /* 1: the next advance restarts CVODE (after create, reset, set, failure) */
};


/* ---- base motion ------------------------------------------------------------------------ */

static void setBase(RomBase* bm, double ta, double H, const csrBaseState* b0,
                    const csrBaseState* b1) {
  bm->ta = ta;
  bm->H = H;
  memcpy(bm->x0, b0->x, sizeof bm->x0);
  memcpy(bm->v0, b0->v, sizeof bm->v0);
  memcpy(bm->x1, b1->x, sizeof bm->x1);
  memcpy(bm->v1, b1->v, sizeof bm->v1);
  memcpy(bm->R0, b0->R, sizeof bm->R0);
  double R01[9], R0t[9];
  csu_transpose3(R0t, b0->R);
  csu_mulMat3(R01, R0t, b1->R);
  csu_mat3ToRotVec(bm->Phi, R01);
  double wb0[3], wb1[3];
  csu_mulMatTVec3(wb0, b0->R, b0->w);
  csu_mulMatTVec3(wb1, b1->R, b1->w);
  csu_scale3(bm->dphi0, wb0, H);
  csu_scale3(bm->dphi1, wb1, H);
}


/* the hip point at time t (world), the cubic Hermite of baseAt */
static void baseX(const RomBase* bm, double t, double xh[3]) {
  const double H = bm->H, u = (t - bm->ta) / H, u2 = u * u, u3 = u2 * u;
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2,
               h11 = u3 - u2;
  for (int k = 0; k < 3; k++) {
    xh[k] = h00 * bm->x0[k] + h10 * H * bm->v0[k] + h01 * bm->x1[k] + h11 * H * bm->v1[k];
  }
}


/* at time t: frame R, hip velocity vh and acceleration ah (world), ω and α (hip frame) */
static void baseAt(const RomBase* bm, double t, double R[9], double vh[3], double ah[3],
                   double w[3], double al[3]) {
  const double H = bm->H, u = (t - bm->ta) / H, u2 = u * u, u3 = u2 * u;
  const double h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2, h11 = u3 - u2;
  const double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = -d00, d11 = 3 * u2 - 2 * u;
  const double s00 = 12 * u - 6, s10 = 6 * u - 4, s01 = -s00, s11 = 6 * u - 2;
  double phi[3];
  for (int k = 0; k < 3; k++) {
    const double p0 = bm->x0[k], p1 = bm->x1[k], m0 = H * bm->v0[k], m1 = H * bm->v1[k];
    vh[k] = (d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1) / H;
    ah[k] = (s00 * p0 + s10 * m0 + s01 * p1 + s11 * m1) / (H * H);
    phi[k] = h10 * bm->dphi0[k] + h01 * bm->Phi[k] + h11 * bm->dphi1[k];
    w[k] = (d10 * bm->dphi0[k] + d01 * bm->Phi[k] + d11 * bm->dphi1[k]) / H;
    al[k] = (s10 * bm->dphi0[k] + s01 * bm->Phi[k] + s11 * bm->dphi1[k]) / (H * H);
  }
  double dR[9];
  csu_rotVecToMat3(dR, phi);
  csu_mulMat3(R, bm->R0, dR);
}


/* ---- right-hand side and Jacobian --------------------------------------------------------- */

/* the centrifugal coefficients c_ij of ω×(ω×r) = Σ c_ij D_ij r, order (00 11 22 01 02 12) */
static void centrifugal(const double w[3], double c[6]) {
  const double w2 = csu_dot3(w, w);
  c[0] = w[0] * w[0] - w2;
  c[1] = w[1] * w[1] - w2;
  c[2] = w[2] * w[2] - w2;
  c[3] = 2 * w[0] * w[1];
  c[4] = 2 * w[0] * w[2];
  c[5] = 2 * w[1] * w[2];
}


/* the 12 chamber pressures at t (MPa): linear between the macro step's ends, held outside */
static void pressuresAt(const csrRomData* d, double t, double p[12]) {
  double al = d->pt1 > d->pt0 ? (t - d->pt0) / (d->pt1 - d->pt0) : 1.0;
  al = al < 0 ? 0 : (al > 1 ? 1 : al);
  for (int i = 0; i < 12; i++) {
    p[i] = (1 - al) * d->p0[i] + al * d->p1[i];
  }
}


/* the loads of the reduced FE at t: chamber pressures on their faces, the dead load */
static void loadAt(const csrRomModel* m, csrRomData* d, double t, csfRomLoad* ld) {
  memset(ld, 0, sizeof *ld);
  double p[12];
  pressuresAt(d, t, p);
  int any = 0;
  for (int f = 0; f < m->nface; f++) {
    const int c = m->face_ch[f];
    d->face_p[f] = c < 0 ? 0.0 : p[c];
    any |= d->face_p[f] != 0;
  }
  ld->face_p = any ? d->face_p : NULL;
  ld->f_dead = d->have_dead ? d->fdead : NULL;
}


/* F(t, q, q') into d->F; want_k: also the reduced tangent in d->fd->K. 0, > 0 recoverable */
static int generalisedForce(const csrRomModel* m, csrRomData* d, double t, const double* q,
                            const double* qd, int want_k, double w_out[3], double al_out[3]) {
  const int n = m->n;
  const size_t nn = (size_t)n * n;
  double R[9], vh[3], ah[3], w[3], al[3], c[6];
  baseAt(&d->bm, t, R, vh, ah, w, al);
  centrifugal(w, c);
  csfRomLoad ld;
  loadAt(m, d, t, &ld);
  memcpy(d->fd->q, q, (size_t)n * sizeof(double));
  const int rc = csf_romEvaluate(m->rom, d->fd, &ld, want_k);
  if (rc != 0) {
    return rc > 0 ? 1 : -1;
  }
  /* the frame's acceleration minus gravity, in the hip frame */
  double ga[3], gb[3];
  csu_sub3(ga, m->par.gravity, ah);
  csu_mulMatTVec3(gb, R, ga);
  for (int k = 0; k < n; k++) {
    double f = -d->fd->r[k];
    const double* Tk = m->T + 3 * (size_t)k;
    f += Tk[0] * gb[0] + Tk[1] * gb[1] + Tk[2] * gb[2];
    for (int i = 0; i < 3; i++) {
      f -= al[i] * m->e[(size_t)i * n + k];
    }
    for (int i = 0; i < 6; i++) {
      f -= c[i] * m->d[(size_t)i * n + k];
    }
    const double* Ck = m->C + (size_t)k * n;
    const double* Q0 = m->Q + (size_t)k * n;
    const double* Q1 = Q0 + nn;
    const double* Q2 = Q1 + nn;
    const double* S0 = m->S + (size_t)k * n;
    for (int l = 0; l < n; l++) {
      const double Qal = al[0] * Q0[l] + al[1] * Q1[l] + al[2] * Q2[l];
      const double Qw = w[0] * Q0[l] + w[1] * Q1[l] + w[2] * Q2[l];
      double Sc = 0;
      for (int i = 0; i < 6; i++) {
        Sc += c[i] * S0[(size_t)i * nn + l];
      }
      f -= (Qal + Sc) * q[l] + (Ck[l] + 2 * Qw) * qd[l];
    }
    d->F[k] = f;
  }
  if (w_out) {
    memcpy(w_out, w, 3 * sizeof(double));
    memcpy(al_out, al, 3 * sizeof(double));
  }
  return 0;
}


static void momentIntegrand(const csrRomModel* m, const csrRomData* d, double t, const double* Y,
                            double* out);


static int rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  csrRomData* d = user;
  const csrRomModel* m = d->m;
  const int n = m->n;
  const double* Y = N_VGetArrayPointer(y);
  double* Yd = N_VGetArrayPointer(ydot);
  d->rhs++;
  const int rc = generalisedForce(m, d, (double)t, Y, Y + n, 0, NULL, NULL);
  if (rc != 0) {
    d->cb_status = rc;
    return rc;
  }
  memcpy(Yd, Y + n, (size_t)n * sizeof(double));
  for (int k = 0; k < n; k++) {
    const double* Mk = m->Minv + (size_t)k * n;
    double a = 0;
    for (int l = 0; l < n; l++) {
      a += Mk[l] * d->F[l];
    }
    Yd[n + k] = a;
  }
  momentIntegrand(m, d, (double)t, Y, Yd + 2 * n);
  if (m->contact) {
    /* the sole's load: into the accelerations, its history's rate, the force's impulse and
     * its moment about the hip into the moment's impulse */
    double R[9], xh[3], vh[3], ah[3], w[3], al[3], x0[3], r[3], rf[3];
    baseAt(&d->bm, (double)t, R, vh, ah, w, al);
    baseX(&d->bm, (double)t, xh);
    cscShapeLoad ld;
    d->sole++;
    const int rcc = csr_romSoleLoad(m, R, xh, vh, w, Y, Y + n, Y + 2 * n + 3, d->Fc,
                                    Yd + 2 * n + 3, &ld, x0, NULL);
    if (rcc != 0) {
      d->cb_status = rcc > 0 ? 1 : -1;
      return d->cb_status;
    }
    for (int k = 0; k < n; k++) {
      const double* Mk = m->Minv + (size_t)k * n;
      double a = 0;
      for (int l = 0; l < n; l++) {
        a += Mk[l] * d->Fc[l];
      }
      Yd[n + k] += a;
    }
    csu_sub3(r, x0, xh);
    csu_cross3(rf, r, ld.f0);
    for (int k = 0; k < 3; k++) {
      Yd[2 * n + k] += rf[k] + ld.m[k];
      Yd[2 * n + 3 + m->nz + k] = ld.f0[k];
    }
  }
  return 0;
}


/* the sole's part of the Jacobian (robot_rom.h csr_romSoleJacobian: the law's derivatives in
 * the foot's coordinates, chained analytically through its pose in q, q'): the rows of q''
 * get M_r⁻¹ [Ūᵀ Rᵀ, Wᵀ Rᵀ] G_(f0, m), a rank-6 product; the rows of z' get G_z' */
static int soleJacobian(const csrRomModel* m, csrRomData* d, double t, const double* Y,
                        SUNMatrix J) {
  const int n = m->n, nz = m->nz, oz = 2 * n + 3, nc = 2 * n + nz;
  double R[9], xh[3], vh[3], ah[3], w[3], al[3], L[6];
  baseAt(&d->bm, t, R, vh, ah, w, al);
  baseX(&d->bm, t, xh);
  d->sole += 1 + 2 * (12 + nz);
  const int rc = csr_romSoleJacobian(m, R, xh, vh, w, Y, Y + n, Y + oz, L, d->zd, d->Gs,
                                     d->sw);
  if (rc != 0) {
    return rc;
  }
  /* B = M_r⁻¹ A, A = [Ūᵀ Rᵀ, Wᵀ Rᵀ] (n x 6) */
  for (int l = 0; l < n; l++) {
    for (int r = 0; r < 3; r++) {
      double a = 0, b = 0;
      for (int i = 0; i < 3; i++) {
        a += m->Us[(size_t)i * n + l] * R[3 * r + i];
        b += m->Ws[(size_t)i * n + l] * R[3 * r + i];
      }
      d->As[6 * l + r] = a;
      d->As[6 * l + 3 + r] = b;
    }
  }
  for (int k = 0; k < n; k++) {
    const double* Mk = m->Minv + (size_t)k * n;
    double b[6] = {0, 0, 0, 0, 0, 0};
    for (int l = 0; l < n; l++) {
      for (int r = 0; r < 6; r++) {
        b[r] += Mk[l] * d->As[6 * l + r];
      }
    }
    for (int c = 0; c < nc; c++) {
      const int col = c < 2 * n ? c : oz + (c - 2 * n);
      double a = 0;
      for (int r = 0; r < 6; r++) {
        a += b[r] * d->Gs[(size_t)r * nc + c];
      }
      SM_ELEMENT_D(J, n + k, col) += a;
    }
  }
  for (int i = 0; i < nz; i++) {
    for (int c = 0; c < nc; c++) {
      const int col = c < 2 * n ? c : oz + (c - 2 * n);
      SM_ELEMENT_D(J, oz + i, col) = d->Gs[(size_t)(6 + i) * nc + c];
    }
  }
  return 0;
}


/* J = [[0, I], [M⁻¹ ∂F/∂q, M⁻¹ ∂F/∂q']] with ∂F/∂q = -K_r(q) - Σ α_k Q_k - Σ c_ij S_ij and
 * ∂F/∂q' = -C - 2 Σ ω_k Q_k (the pressures' load stiffness is in K_r: fem_rom.h) */
static int jac(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix J, void* user, N_Vector t1,
               N_Vector t2, N_Vector t3) {
  (void)fy, (void)t1, (void)t2, (void)t3;
  csrRomData* d = user;
  const csrRomModel* m = d->m;
  const int n = m->n;
  const size_t nn = (size_t)n * n;
  const double* Y = N_VGetArrayPointer(y);
  double w[3], al[3], c[6];
  d->jacs++;
  double pc[12];
  pressuresAt(d, (double)t, pc);
  int reuse = d->lag_valid && m->par.tangent_lag > 0;
  if (reuse) {
    double moved = 0, dp = 0;
    for (int k = 0; k < n; k++) {
      moved += fabs(Y[k] - d->qlag[k]) * d->vmax[k];
    }
    for (int i = 0; i < 12; i++) {
      dp = fmax(dp, fabs(pc[i] - d->plag[i]));
    }
    reuse = moved <= m->par.tangent_lag && dp <= 1e-3;
  }
  const double* K = d->fd->K;
  if (reuse) {
    double R[9], vh[3], ah[3];
    baseAt(&d->bm, (double)t, R, vh, ah, w, al);
    K = d->Klag;
  } else {
    const int rc = generalisedForce(m, d, (double)t, Y, Y + n, 1, w, al);
    if (rc != 0) {
      d->cb_status = rc;
      return rc;
    }
    d->tangents++;
    if (m->par.tangent_lag > 0) {
      memcpy(d->Klag, d->fd->K, nn * sizeof(double));
      memcpy(d->qlag, Y, (size_t)n * sizeof(double));
      memcpy(d->plag, pc, sizeof pc);
      d->lag_valid = 1;
    }
  }
  centrifugal(w, c);
  SUNMatZero(J);
  for (int k = 0; k < n; k++) {
    SM_ELEMENT_D(J, k, n + k) = 1.0;
  }
  for (int half = 0; half < 2; half++) {
    /* G = ∂F/∂q (half 0) or ∂F/∂q' (half 1) */
    for (size_t kl = 0; kl < nn; kl++) {
      double g;
      if (half == 0) {
        g = -K[kl] - al[0] * m->Q[kl] - al[1] * m->Q[nn + kl] - al[2] * m->Q[2 * nn + kl];
        for (int i = 0; i < 6; i++) {
          g -= c[i] * m->S[(size_t)i * nn + kl];
        }
      } else {
        g = -m->C[kl] - 2 * (w[0] * m->Q[kl] + w[1] * m->Q[nn + kl] + w[2] * m->Q[2 * nn + kl]);
      }
      d->G[kl] = g;
    }
    for (int k = 0; k < n; k++) {
      const double* Mk = m->Minv + (size_t)k * n;
      for (int l = 0; l < n; l++) {
        double a = 0;
        for (int j = 0; j < n; j++) {
          a += Mk[j] * d->G[(size_t)j * n + l];
        }
        SM_ELEMENT_D(J, n + k, half * n + l) = a;
      }
    }
  }
  if (m->contact) {
    const int rcs = soleJacobian(m, d, (double)t, Y, J);
    if (rcs != 0) {
      d->cb_status = rcs > 0 ? 1 : -1;
      return d->cb_status;
    }
  }
  return 0;
}


/* the first mass moment s(q) = s0 + Tᵀ q (hip frame, t mm) */
static void firstMoment(const csrRomModel* m, const double* q, double s[3]) {
  memcpy(s, m->s0, 3 * sizeof(double));
  for (int k = 0; k < m->n; k++) {
    for (int i = 0; i < 3; i++) {
      s[i] += m->T[3 * (size_t)k + i] * q[k];
    }
  }
}


/* P and L_h (world) at q, q' with the frame R, hip velocity vh (world), ω (hip frame) */
static void momentumOf(const csrRomModel* m, const double* q, const double* qd, const double R[9],
                       const double vh[3], const double w[3], double P[3], double L[3]) {
  const int n = m->n;
  const size_t nn = (size_t)n * n;
  double s[3], pb[3], ws[3];
  firstMoment(m, q, s);
  /* P = m v_h + R (ω × s + Tᵀ q') */
  csu_cross3(ws, w, s);
  for (int i = 0; i < 3; i++) {
    pb[i] = ws[i];
    for (int k = 0; k < n; k++) {
      pb[i] += m->T[3 * (size_t)k + i] * qd[k];
    }
  }
  double Rp[3];
  csu_mulMatVec3(Rp, R, pb);
  for (int i = 0; i < 3; i++) {
    P[i] = m->mass * vh[i] + Rp[i];
  }
  /* L_h = R [ s × Rᵀ v_h + I(q) ω + h ],  J(q)_ij = J0_ij + 2 d_ij.q + q.S_ij q,
   * I = tr(J) 1 - J,  h_k = q'.(e_k + Q_k q) */
  double Jq[6];
  for (int i = 0; i < 6; i++) {
    double a = m->J0[i];
    for (int k = 0; k < n; k++) {
      const double* Sk = m->S + (size_t)i * nn + (size_t)k * n;
      double sq = 0;
      for (int l = 0; l < n; l++) {
        sq += Sk[l] * q[l];
      }
      a += (2 * m->d[(size_t)i * n + k] + sq) * q[k];
    }
    Jq[i] = a;
  }
  const double tr = Jq[0] + Jq[1] + Jq[2];
  const double I[9] = {tr - Jq[0], -Jq[3], -Jq[4], -Jq[3], tr - Jq[1], -Jq[5],
                       -Jq[4], -Jq[5], tr - Jq[2]};
  double vb[3], lb[3], Iw[3];
  csu_mulMatTVec3(vb, R, vh);
  csu_cross3(lb, s, vb);
  csu_mulMatVec3(Iw, I, w);
  csu_add3(lb, lb, Iw);
  for (int i = 0; i < 3; i++) {
    const double* e = m->e + (size_t)i * n;
    const double* Qi = m->Q + (size_t)i * nn;
    double h = 0;
    for (int k = 0; k < n; k++) {
      double a = e[k];
      for (int l = 0; l < n; l++) {
        a += Qi[(size_t)k * n + l] * q[l];
      }
      h += qd[k] * a;
    }
    lb[i] += h;
  }
  csu_mulMatVec3(L, R, lb);
}


/* the integrand of the base moment's impulse: R s(q) × g - v_h × P (the last 3 components of
 * y: CVODE has no quadrature module (CVODES has), so they ride in y, restarted from zero at
 * every advance and under error control, as the rod's impulse; their Jacobian rows are left
 * out: nothing depends on them, and the modified Newton converges on them with y) */
static void momentIntegrand(const csrRomModel* m, const csrRomData* d, double t, const double* Y,
                            double* out) {
  double R[9], vh[3], ah[3], w[3], al[3], s[3], Rs[3], P[3], L[3], a[3], b[3];
  baseAt(&d->bm, t, R, vh, ah, w, al);
  firstMoment(m, Y, s);
  csu_mulMatVec3(Rs, R, s);
  csu_cross3(a, Rs, m->par.gravity);
  momentumOf(m, Y, Y + m->n, R, vh, w, P, L);
  csu_cross3(b, vh, P);
  csu_sub3(out, a, b);
}


void csr_romMomentum(const csrRomModel* m, const csrRomData* d, double P[3], double L[3]) {
  double wb[3];
  csu_mulMatTVec3(wb, d->base.R, d->base.w);
  momentumOf(m, d->y, d->y + m->n, d->base.R, d->base.v, wb, P, L);
}


/* ---- data ------------------------------------------------------------------------------- */

void csr_romDataDestroy(csrRomData* d) {
  if (!d) {
    return;
  }
  CVodeFree(&d->cvode);
  SUNLinSolFree(d->LS);
  SUNMatDestroy(d->A);
  N_VDestroy(d->yv);
  N_VDestroy(d->atol);
  if (d->sun) {
    SUNContext_Free(&d->sun);
  }
  csf_romDataDestroy(d->fd);
  free(d->fdead), free(d->face_p), free(d->F), free(d->G), free(d->backup);
  free(d->Fc), free(d->zd), free(d->Gs), free(d->sw), free(d->As);
  free(d->Klag), free(d->qlag), free(d->vmax);
  free(d);
}


csrRomData* csr_romDataCreate(const csrRomModel* m, csError* err) {
  if (!m) {
    cs_errorSet(err, CS_ERR_ARG, "rom leg: no model");
    return NULL;
  }
  const int n = m->n;
  csrRomData* d = calloc(1, sizeof *d);
  if (!d) {
    cs_errorSet(err, CS_ERR_MEMORY, "rom leg: out of memory");
    return NULL;
  }
  d->m = m;
  d->n = n;
  d->fd = csf_romDataCreate(m->rom, err);
  d->fdead = calloc((size_t)n, sizeof(double));
  d->face_p = calloc((size_t)(m->nface > 0 ? m->nface : 1), sizeof(double));
  d->F = calloc((size_t)n, sizeof(double));
  d->G = calloc((size_t)n * n, sizeof(double));
  const int nz = m->contact ? m->nz : 0;
  d->ny = 2 * n + 3 + (m->contact ? nz + 3 : 0);
  d->backup = calloc(2 * (size_t)n + nz, sizeof(double));
  d->Fc = calloc((size_t)n, sizeof(double));
  d->zd = calloc((size_t)nz + 1, sizeof(double));
  d->Gs = m->contact ? calloc((size_t)(6 + nz) * (2 * (size_t)n + nz), sizeof(double)) : NULL;
  d->sw = m->contact ? calloc((size_t)csr_romSoleWorkSize(m), sizeof(double)) : NULL;
  d->As = calloc(6 * (size_t)n, sizeof(double));
  d->Klag = m->par.tangent_lag > 0 ? calloc((size_t)n * n, sizeof(double)) : NULL;
  d->qlag = calloc((size_t)n, sizeof(double));
  d->vmax = calloc((size_t)n, sizeof(double));
  if (!d->fd || !d->fdead || !d->face_p || !d->F || !d->G || !d->backup || !d->Fc || !d->zd ||
      (m->contact && (!d->Gs || !d->sw)) || !d->As || (m->par.tangent_lag > 0 && !d->Klag) ||
      !d->qlag || !d->vmax) {
    csr_romDataDestroy(d);
    cs_errorSet(err, CS_ERR_MEMORY, "rom leg: out of memory (n = %d)", n);
    return NULL;
  }
  d->fd->sync = 1; /* the exact tangent (fem_rom.h): the Jacobian of CVODE's Newton */
  if (cs_sunContextCreate(&d->sun) != 0) { /* it never prints: the flags name the cause */
    d->sun = NULL;
    csr_romDataDestroy(d);
    cs_errorSet(err, CS_ERR_SOLVER, "rom leg: cannot create a SUNDIALS context");
    return NULL;
  }
  d->yv = N_VNew_Serial(d->ny, d->sun);
  d->atol = N_VNew_Serial(d->ny, d->sun);
  d->A = d->yv ? SUNDenseMatrix(d->ny, d->ny, d->sun) : NULL;
  d->LS = d->A ? SUNLinSol_Dense(d->yv, d->A, d->sun) : NULL;
  if (!d->yv || !d->atol || !d->A || !d->LS) {
    csr_romDataDestroy(d);
    cs_errorSet(err, CS_ERR_MEMORY, "rom leg: cannot allocate SUNDIALS objects");
    return NULL;
  }
  d->y = N_VGetArrayPointer(d->yv);
  double* at = N_VGetArrayPointer(d->atol);
  for (int k = 0; k < n; k++) {
    double vmax = 0; /* the largest nodal displacement of a unit q_k, mm */
    for (int i = 0; i < m->rom->ndof; i++) {
      vmax = fmax(vmax, fabs(m->rom->V[(size_t)i * n + k]));
    }
    d->vmax[k] = vmax;
    at[k] = m->par.atol_u / (vmax > 0 ? vmax : 1.0);
    at[n + k] = 1e3 * at[k]; /* q' over a millisecond */
  }
  for (int k = 2 * n; k < d->ny; k++) {
    at[k] = 1.0; /* the impulses: set per advance */
  }
  for (int i = 0; i < nz; i++) {
    /* the bristle (mm; the torsional one in rad over a 1 mm arm): as a displacement */
    at[2 * n + 3 + i] = m->par.atol_u;
  }
  d->cvode = CVodeCreate(CV_BDF, d->sun);
  if (!d->cvode || CVodeInit(d->cvode, rhs, 0.0, d->yv) != CV_SUCCESS ||
      CVodeSVtolerances(d->cvode, m->par.rtol, d->atol) != CV_SUCCESS ||
      CVodeSetUserData(d->cvode, d) != CV_SUCCESS ||
      CVodeSetLinearSolver(d->cvode, d->LS, d->A) != CV_SUCCESS ||
      CVodeSetJacFn(d->cvode, jac) != CV_SUCCESS ||
      CVodeSetMaxNumSteps(d->cvode, m->par.max_steps) != CV_SUCCESS) {
    csr_romDataDestroy(d);
    cs_errorSet(err, CS_ERR_SOLVER, "rom leg: cannot set up CVODE (BDF, dense)");
    return NULL;
  }
  cs_cvodeSilence(d->cvode);
  csrBaseState b;
  memset(&b, 0, sizeof b);
  csu_eye3(b.R);
  csr_romReset(m, d, 0.0, &b);
  return d;
}


void csr_romReset(const csrRomModel* m, csrRomData* d, double t, const csrBaseState* b) {
  memset(d->y, 0, (size_t)d->ny * sizeof(double));
  if (m->contact) {
    csc_softStateInit(m->contact, d->y + 2 * m->n + 3);
  }
  csf_romDataReset(m->rom, d->fd);
  d->t = t;
  d->base = *b;
  d->pt0 = d->pt1 = t;
  d->need_reinit = 1;
  memset(d->p0, 0, sizeof d->p0);
  memset(d->p1, 0, sizeof d->p1);
}


void csr_romActuate(csrRomData* d, double t0, const double p0[12], double t1,
                    const double p1[12]) {
  d->pt0 = t0;
  d->pt1 = t1;
  memcpy(d->p0, p0, sizeof d->p0);
  memcpy(d->p1, p1, sizeof d->p1);
}


void csr_romSetDeadLoad(const csrRomModel* m, csrRomData* d, const double* fr) {
  d->have_dead = fr != NULL;
  if (fr) {
    memcpy(d->fdead, fr, (size_t)m->n * sizeof(double));
  }
}


const double* csr_romQ(const csrRomData* d) { return d->y; }
const double* csr_romZ(const csrRomData* d) {
  return d->m->contact ? d->y + 2 * d->n + 3 : NULL;
}
const double* csr_romQdot(const csrRomData* d) { return d->y + d->n; }
double csr_romTime(const csrRomData* d) { return d->t; }


void csr_romStats(const csrRomData* d, long* steps, long* rhs_n, long* jacs, long* restarts) {
  long ns = 0;
  if (d->cvode) {
    CVodeGetNumSteps(d->cvode, &ns);
  }
  *steps = d->steps + ns;
  *rhs_n = d->rhs;
  *jacs = d->jacs;
  *restarts = d->restarts; /* retries included */
}


void csr_romGetStats(const csrRomData* d, csrRomStats* s) {
  long ns = 0, nsu = 0, nni = 0, nnf = 0, nef = 0;
  if (d->cvode) {
    CVodeGetNumSteps(d->cvode, &ns);
    CVodeGetNumLinSolvSetups(d->cvode, &nsu);
    CVodeGetNumNonlinSolvIters(d->cvode, &nni);
    CVodeGetNumNonlinSolvConvFails(d->cvode, &nnf);
    CVodeGetNumErrTestFails(d->cvode, &nef);
  }
  s->steps = d->steps + ns;
  s->rhs = d->rhs;
  s->jacs = d->jacs;
  s->tangents = d->tangents;
  s->lin_setups = d->cv_setups + nsu;
  s->nl_iters = d->cv_niters + nni;
  s->nl_fails = d->cv_nfails + nnf;
  s->err_fails = d->cv_efails + nef;
  s->restarts = d->restarts;
  s->retries = d->retries;
  s->sole = d->sole;
}


/* a hip that starts a step more than this away from where the last one ended (mm, rad) has
 * jumped (a teleport, a restored driver): CVODE restarts. Smaller differences are the
 * coupling's normal corrections of the predicted end state (as the rod's, robot_rod_dyn.c) */
#define CSR_ROM_BASE_JUMP_X 0.1
#define CSR_ROM_BASE_JUMP_PHI 1e-3

static int baseJumped(const csrBaseState* a, const csrBaseState* b) {
  double dx[3], Rt[9], Rab[9], phi[3];
  csu_sub3(dx, a->x, b->x);
  csu_transpose3(Rt, a->R);
  csu_mulMat3(Rab, Rt, b->R);
  csu_mat3ToRotVec(phi, Rab);
  return !(csu_norm3(dx) <= CSR_ROM_BASE_JUMP_X && csu_norm3(phi) <= CSR_ROM_BASE_JUMP_PHI);
}


/* restart CVODE from the state at t for steps of H (the moment impulse from zero) */
static int restartAt(const csrRomModel* m, csrRomData* d, double t, double H) {
  const int n = m->n;
  long ns = 0, nsu = 0, nni = 0, nnf = 0, nef = 0;
  CVodeGetNumSteps(d->cvode, &ns);
  CVodeGetNumLinSolvSetups(d->cvode, &nsu);
  CVodeGetNumNonlinSolvIters(d->cvode, &nni);
  CVodeGetNumNonlinSolvConvFails(d->cvode, &nnf);
  CVodeGetNumErrTestFails(d->cvode, &nef);
  d->lag_valid = 0; /* a restart takes a fresh tangent (two restores step alike) */
  d->steps += ns;
  d->cv_setups += nsu;
  d->cv_niters += nni;
  d->cv_nfails += nnf;
  d->cv_efails += nef;
  d->restarts++;
  /* the moment's impulse from zero: only its change over an advance is used, and its absolute
   * value sets the rounding of that change, so a restored state (which does not hold it)
   * steps bit for bit only from zero */
  const int oi = 2 * n + 3 + (m->contact ? m->nz : 0); /* the force impulse, with contact */
  for (int k = 0; k < 3; k++) {
    d->y[2 * n + k] = 0;
    if (m->contact) {
      d->y[oi + k] = 0;
    }
  }
  /* the moment impulse's tolerance: the averaged wrench's over a 10 mm arm, for steps of this
   * H (set at restarts only: CVODE binds its error weights' data before its first step) */
  double* at = N_VGetArrayPointer(d->atol);
  for (int k = 0; k < 3; k++) {
    at[2 * n + k] = m->par.atol_wrench * 10.0 * H;
    if (m->contact) {
      at[oi + k] = m->par.atol_wrench * H;
    }
  }
  if (CVodeReInit(d->cvode, t, d->yv) != CV_SUCCESS ||
      CVodeSVtolerances(d->cvode, m->par.rtol, d->atol) != CV_SUCCESS) {
    return -1;
  }
  d->need_reinit = 0;
  return 0;
}


int csr_romAdvance(const csrRomModel* m, csrRomData* d, double t, double H,
                   const csrBaseState* b0, const csrBaseState* b1, csrWrench* w, csError* err) {
  if (!m || !d || !b0 || !b1 || !(H > 0) || !isfinite(H) || !isfinite(t)) {
    cs_errorSet(err, CS_ERR_ARG, "rom advance: need a model, data, both base states and H > 0");
    return -1;
  }
  const int n = m->n;
  setBase(&d->bm, t, H, b0, b1);
  double P0[3], L0[3];
  {
    const csrBaseState last = d->base;
    d->base = *b0;
    csr_romMomentum(m, d, P0, L0);
    d->base = last; /* compared with b0 below */
  }
  const int nz = m->contact ? m->nz : 0, oi = 2 * n + 3 + nz;
  memcpy(d->backup, d->y, 2 * (size_t)n * sizeof(double));
  memcpy(d->backup + 2 * n, d->y + 2 * n + 3, (size_t)nz * sizeof(double));
  d->cb_status = 0;
  int restart = d->need_reinit || fabs(t - d->t) > 1e-12 * (1 + fabs(t)) ||
                baseJumped(&d->base, b0);
  d->base = *b0;
  double I0[3], F0[3] = {0, 0, 0};
  for (;;) {
    if (restart && restartAt(m, d, t, H) != 0) {
      cs_errorSet(err, CS_ERR_SOLVER, "rom advance: CVODE restart failed at t = %g s", t);
      return -1;
    }
    if (CVodeSetStopTime(d->cvode, t + H) != CV_SUCCESS) {
      cs_errorSet(err, CS_ERR_SOLVER, "rom advance: CVODE refused the stop time %g s", t + H);
      return -1;
    }
    memcpy(I0, d->y + 2 * n, sizeof I0);
    if (nz) {
      memcpy(F0, d->y + oi, sizeof F0);
    }
    sunrealtype tret = t;
    const int flag = CVode(d->cvode, t + H, d->yv, &tret, CV_NORMAL);
    if (flag >= 0) {
      break;
    }
    memcpy(d->y, d->backup, 2 * (size_t)n * sizeof(double));
    memcpy(d->y + 2 * n + 3, d->backup + 2 * n, (size_t)nz * sizeof(double));
    d->need_reinit = 1;
    const int fatal = d->cb_status < 0 || flag == CV_ILL_INPUT || flag == CV_MEM_FAIL ||
                      flag == CV_MEM_NULL;
    if (!fatal && !restart) {
      /* a continued step that failed (its history extrapolated across the kink of the hip's
       * acceleration or of the pressures' rate at the macro step's start, which a tight
       * tolerance cannot resolve by shrinking h): once more from the state, fresh */
      restart = 1;
      d->retries++;
      d->cb_status = 0;
      continue;
    }
    char* name = CVodeGetReturnFlagName(flag);
    cs_errorSet(err, fatal ? CS_ERR_SOLVER : CS_ERR_DIVERGED,
                "rom advance from t = %.6g s by H = %.3g s failed at t = %.6g s: CVODE %s", t,
                H, (double)tret, name ? name : "?");
    free(name);
    return fatal ? -1 : 1;
  }
  double Iq[3], If[3] = {0, 0, 0};
  for (int k = 0; k < 3; k++) {
    Iq[k] = d->y[2 * n + k] - I0[k];
    if (nz) {
      If[k] = d->y[oi + k] - F0[k];
    }
  }
  d->t = t + H;
  d->base = *b1;
  if (w) {
    double P1[3], L1[3];
    csr_romMomentum(m, d, P1, L1);
    for (int k = 0; k < 3; k++) {
      /* the contact's impulse reached the leg from outside the support: the support gets it */
      w->f[k] = m->mass * m->par.gravity[k] - (P1[k] - P0[k]) / H + If[k] / H;
      w->m[k] = (Iq[k] - (L1[k] - L0[k])) / H;
    }
  }
  return 0;
}


int csr_romStateSize(const csrRomModel* m) {
  return 1 + 2 * m->n + 18 + 2 + 24 + (m->contact ? m->nz : 0);
}


void csr_romGetState(const csrRomModel* m, const csrRomData* d, double* x) {
  const int n = m->n;
  x[0] = d->t;
  memcpy(x + 1, d->y, 2 * (size_t)n * sizeof(double));
  double* b = x + 1 + 2 * n;
  memcpy(b, d->base.x, 3 * sizeof(double));
  memcpy(b + 3, d->base.R, 9 * sizeof(double));
  memcpy(b + 12, d->base.v, 3 * sizeof(double));
  memcpy(b + 15, d->base.w, 3 * sizeof(double));
  b[18] = d->pt0;
  b[19] = d->pt1;
  memcpy(b + 20, d->p0, 12 * sizeof(double));
  memcpy(b + 32, d->p1, 12 * sizeof(double));
  if (m->contact) {
    memcpy(b + 44, d->y + 2 * n + 3, (size_t)m->nz * sizeof(double));
  }
}


int csr_romSetState(const csrRomModel* m, csrRomData* d, const double* x) {
  const int ns = csr_romStateSize(m);
  for (int i = 0; i < ns; i++) {
    if (!isfinite(x[i])) {
      return -1;
    }
  }
  const int n = m->n;
  d->t = x[0];
  memcpy(d->y, x + 1, 2 * (size_t)n * sizeof(double));
  const double* b = x + 1 + 2 * n;
  memcpy(d->base.x, b, 3 * sizeof(double));
  memcpy(d->base.R, b + 3, 9 * sizeof(double));
  memcpy(d->base.v, b + 12, 3 * sizeof(double));
  memcpy(d->base.w, b + 15, 3 * sizeof(double));
  d->pt0 = b[18];
  d->pt1 = b[19];
  memcpy(d->p0, b + 20, 12 * sizeof(double));
  memcpy(d->p1, b + 32, 12 * sizeof(double));
  if (m->contact) {
    memcpy(d->y + 2 * n + 3, b + 44, (size_t)m->nz * sizeof(double));
  }
  d->need_reinit = 1;
  /* the reduced FE's states (θ, fibre stress) are synchronised at every evaluation (sync = 1):
   * nothing else to restore */
  return 0;
}

/* robot_strain_dyn.c: the strain leg's dynamics (robot_strain.h): state, base, the linearly
 * implicit step condensed onto the base, energy and momentum.
 *
 * ---- Equations ----------------------------------------------------------------------------
 * Unknown velocities u = (V_b, η): the base's body twist (hip frame) and q̇. Each Simpson point
 * p (robot_strain.c) moves with the body twist V_p = G_p u, G_p = [Ad(g_p⁻¹), J_p], g_p its pose
 * relative to the hip. Per point the Newton-Euler equations in its body frame (angular first)
 *   M_p V̇_p - ad(V_p)ᵀ M_p V_p = F_p,   V̇_p = G_p u̇ + Ġ_p u,
 * with M_p the Simpson weight times the section's mass per length, projected by G_pᵀ and summed
 * (d'Alembert), plus the strains' elastic force b - K q and Kelvin-Voigt damping -τ_d K η (the
 * nodal rod's damping_time on every strain rate: the viscous stress τ_d C ξ̇ projects to τ_d K
 * exactly, K = ∫ΦᵀCΦ):
 *   M(q) u̇ = Σ G_pᵀ (F_p - M_p Ġ_p u + ad(V_p)ᵀ M_p V_p) + [0; b - K q - τ_d K η].
 * Ġ_p u (the velocity-product accelerations) is a central difference of G_p(q ± εη) u with ε
 * moving the largest mode by 1e-6 rad (relative error ~1e-12 from truncation, ~1e-10 from
 * round-off; SoRoSim derives it by a second recursion, which is the optimisation to make when
 * the step's cost is measured).
 *
 * ---- Step ---------------------------------------------------------------------------------
 * Backward Euler on velocities linearised at the step's start (the design's W Δu = h r): the
 * elastic and damping forces at the step's end, K q1 = K (q0 + h η0 + h Δη) and τ_d K η1, the
 * rest (inertial velocity products, weight, tip load, the mass matrix) at the start, so
 *   W = M(q0) + (h τ_d + h²) [0 0; 0 K],   r = the right-hand side above at (q0, u0) - h K η0.
 * Positions follow with the new velocities: q1 = q0 + h η1 (the base: the caller, e.g.
 * g_b exp(h V_b1), or ODE's x1 = x0 + h v1). The leg block W_ll is symmetric positive definite
 * (mass plus stiffness) without contact; the contact's friction makes it unsymmetric, so it is
 * factored by LU (partial pivoting) and the leg condensed onto the base. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "robot_strain_internal.h"

/* the velocity-product difference moves the fastest mode by this much (rad or strain) */
#define CSR_STRAIN_BIAS_STEP 1e-6


int csr_strainStateSize(const csrStrainModel* m) { return 2 * m->n + m->nhist; }


void csr_strainGetState(const csrStrainModel* m, const csrStrainData* d, double* y) {
  memcpy(y, d->q, (size_t)m->n * sizeof(double));
  memcpy(y + m->n, d->eta, (size_t)m->n * sizeof(double));
  memcpy(y + 2 * m->n, d->z, (size_t)m->nhist * sizeof(double));
}


int csr_strainSetState(const csrStrainModel* m, csrStrainData* d, const double* y) {
  for (int j = 0; j < 2 * m->n + m->nhist; j++) {
    if (!isfinite(y[j])) {
      return -1;
    }
  }
  memcpy(d->q, y, (size_t)m->n * sizeof(double));
  memcpy(d->eta, y + m->n, (size_t)m->n * sizeof(double));
  memcpy(d->z, y + 2 * m->n, (size_t)m->nhist * sizeof(double));
  d->kin_valid = 0;
  d->h = 0;
  return 0;
}


void csr_strainSetBase(const csrStrainModel* m, csrStrainData* d, const csrBaseState* b) {
  (void)m;
  memcpy(d->Rb, b->R, sizeof d->Rb);
  memcpy(d->xb, b->x, sizeof d->xb);
  csu_mulMatTVec3(d->Vb, b->R, b->w);
  csu_mulMatTVec3(d->Vb + 3, b->R, b->v);
  d->h = 0;
}


void csr_strainSetTipLoad(csrStrainData* d, const double force[3], const double moment[3]) {
  memcpy(d->tipd_f, force, sizeof d->tipd_f);
  memcpy(d->tipd_m, moment, sizeof d->tipd_m);
}


/* V = G_p u at point p (current kinematics) */
static void pointTwist(const csrStrainModel* m, const csrStrainData* d, int p, const double Vb[6],
                       const double* eta, double V[6]) {
  const int n = m->n;
  const double* R = d->R + 9 * p;
  const double* x = d->x + 3 * p;
  /* Ad(g⁻¹) V_b = (Rᵀ ω; Rᵀ (v + ω × x)) */
  double wx[3], t[3];
  csu_cross3(wx, Vb, x);
  csu_add3(t, Vb + 3, wx);
  csu_mulMatTVec3(V, R, Vb);
  csu_mulMatTVec3(V + 3, R, t);
  const double* J = d->J + (size_t)p * 6 * n;
  for (int r = 0; r < 6; r++) {
    double s = 0;
    for (int j = 0; j < n; j++) {
      s += J[r * n + j] * eta[j];
    }
    V[r] += s;
  }
}


/* the point twists at q + ε η into out (np x 6), by the twist recursion alone (no poses or
 * Jacobians: the kinematics stays valid) */
static void twistsAt(const csrStrainModel* m, csrStrainData* d, double eps, double* out) {
  for (int j = 0; j < m->n; j++) {
    d->q_save[j] = d->q[j] + eps * d->eta[j];
  }
  csr_strainTwists_(m, d->q_save, d->eta, d->Vb, out);
}


/* the 6 x 6 Ad(g_p⁻¹) = [Rᵀ 0; -Rᵀ x^ Rᵀ] of point p */
static void adInv(const csrStrainData* d, int p, double A[36]) {
  const double* R = d->R + 9 * p;
  const double* x = d->x + 3 * p;
  memset(A, 0, 36 * sizeof(double));
  for (int c = 0; c < 3; c++) {
    /* column c of the angular block: Rᵀ e_c; of the coupling: Rᵀ (e_c × x) */
    double e[3] = {0, 0, 0}, ex[3], col[3], rc[3];
    e[c] = 1;
    csu_mulMatTVec3(col, R, e);
    csu_cross3(ex, e, x);
    csu_mulMatTVec3(rc, R, ex);
    for (int r = 0; r < 3; r++) {
      A[6 * r + c] = col[r];
      A[6 * (r + 3) + c + 3] = col[r];
      A[6 * (r + 3) + c] = rc[r];
    }
  }
}


int csr_strainPrepare(const csrStrainModel* m, csrStrainData* d, double h, double Z[36],
                      double rho[6]) {
  if (!(h > 0) || !isfinite(h) || !Z || !rho) {
    return -1;
  }
  const int n = m->n;
  d->h = 0;
  /* the velocity-product accelerations Ġ_p u by central differences */
  double emax = 0;
  for (int j = 0; j < n; j++) {
    emax = fmax(emax, fabs(d->eta[j]) * m->dscale[j]);
  }
  if (emax > 0) {
    double eps = CSR_STRAIN_BIAS_STEP / emax;
    twistsAt(m, d, eps, d->Ab);
    twistsAt(m, d, -eps, d->Vs);
    for (int i = 0; i < 6 * m->np; i++) {
      d->Ab[i] = (d->Ab[i] - d->Vs[i]) / (2 * eps);
    }
  } else {
    memset(d->Ab, 0, (size_t)6 * m->np * sizeof(double));
  }
  /* the kinematics relative to the base: the last Finish left it valid at this q (the
   * return-mapping needed it) */
  if (d->kin_valid < 2) {
    csr_strainKinematics_(m, d, 1);
  }
  /* W_bb, W_lb, W_ll (its lower triangle) and r */
  double Wbb[36], rb[6];
  memset(Wbb, 0, sizeof Wbb);
  memset(rb, 0, sizeof rb);
  memset(d->Wll, 0, (size_t)n * n * sizeof(double));
  memset(d->Wlb, 0, (size_t)n * 6 * sizeof(double));
  memset(d->rl, 0, (size_t)n * sizeof(double));
  double gh[3];
  csu_mulMatTVec3(gh, d->Rb, m->gravity);
  for (int p = 0; p < m->np; p++) {
    const double* Ms = m->Ms + 6 * p;
    const double* J = d->J + (size_t)p * 6 * n;
    double* V = d->Vp + 6 * p;
    pointTwist(m, d, p, d->Vb, d->eta, V);
    double A[36];
    adInv(d, p, A);
    /* F_p - M_p Ġ_p u + ad(V)ᵀ M_p V, ad(V)ᵀ (μ; π) = (-ω × μ - v × π; -ω × π) */
    double mu[3] = {Ms[0] * V[0], Ms[1] * V[1], Ms[2] * V[2]};
    double pi[3] = {Ms[3] * V[3], Ms[4] * V[4], Ms[5] * V[5]};
    double F[6], t1[3], t2[3], gb[3];
    csu_cross3(t1, V, mu);
    csu_cross3(t2, V + 3, pi);
    csu_mulMatTVec3(gb, d->R + 9 * p, gh);
    for (int r = 0; r < 3; r++) {
      F[r] = -t1[r] - t2[r] - Ms[r] * d->Ab[6 * p + r];
    }
    csu_cross3(t1, V, pi);
    for (int r = 0; r < 3; r++) {
      F[3 + r] = -t1[r] - Ms[3 + r] * d->Ab[6 * p + 3 + r] + Ms[3 + r] * gb[r];
    }
    if (p == m->np - 1) {
      /* the tip load in the tip's body frame */
      double Rw[9], xw[3], fb[3], mb[3];
      csr_strainWorld_(d, d->R + 9 * p, d->x + 3 * p, Rw, xw);
      csu_mulMatTVec3(mb, Rw, d->tipd_m);
      csu_mulMatTVec3(fb, Rw, d->tipd_f);
      for (int r = 0; r < 3; r++) {
        F[r] += mb[r];
        F[3 + r] += fb[r];
      }
    }
    /* r_b += Aᵀ F, r_l += Jᵀ F; W_bb += Aᵀ M A, W_lb += Jᵀ M A, W_ll += Jᵀ M J (its lower
     * triangle; J's columns from pcol on are zero) */
    const int nc = m->pcol[p];
    for (int r = 0; r < 6; r++) {
      const double* Jr = J + r * n;
      for (int c = 0; c < 6; c++) {
        rb[c] += A[6 * r + c] * F[r];
      }
      for (int j = 0; j < nc; j++) {
        d->rl[j] += Jr[j] * F[r];
      }
      if (Ms[r] == 0) {
        continue;
      }
      double MA[6];
      for (int c = 0; c < 6; c++) {
        MA[c] = Ms[r] * A[6 * r + c];
      }
      for (int a = 0; a < 6; a++) {
        if (A[6 * r + a] != 0) {
          for (int c = 0; c < 6; c++) {
            Wbb[6 * a + c] += A[6 * r + a] * MA[c];
          }
        }
      }
      for (int j = 0; j < nc; j++) {
        double* wlb = d->Wlb + 6 * j;
        for (int c = 0; c < 6; c++) {
          wlb[c] += Jr[j] * MA[c];
        }
        double MJ = Ms[r] * Jr[j];
        double* wll = d->Wll + (size_t)j * n;
        for (int k = 0; k <= j; k++) {
          wll[k] += MJ * Jr[k];
        }
      }
    }
  }
  /* W_ll in full, W_bl = W_lbᵀ, then the contact (which need not be symmetric) */
  for (int j = 0; j < n; j++) {
    for (int k = 0; k < j; k++) {
      d->Wll[k * n + j] = d->Wll[j * n + k];
    }
    for (int c = 0; c < 6; c++) {
      d->Wbl[n * c + j] = d->Wlb[6 * j + c];
    }
  }
  if (m->soft) {
    /* u0 = (V_b, η) in the scratch after the linearisation's rows */
    double* uu = d->Gs + 21 * (6 + n);
    memcpy(uu, d->Vb, 6 * sizeof(double));
    memcpy(uu + 6, d->eta, (size_t)n * sizeof(double));
    int rc = csr_strainContactAssemble_(m, d, h, uu, Wbb, rb, d->Gs);
    if (rc != 0) {
      return rc > 0 ? rc : 1;
    }
  }
  /* the strains' elastic and damping forces, linearised at the step's end */
  const double tau = m->rpar.damping_time;
  for (int j = 0; j < n; j++) {
    d->rl[j] += d->b[j] - d->Kd[j] * (d->q[j] + (tau + h) * d->eta[j]);
    d->Wll[j * n + j] += (h * tau + h * h) * d->Kd[j];
  }
  for (int j = 0; j < n; j++) {
    if (!isfinite(d->rl[j])) {
      return 1;
    }
  }
  if (csr_strainLuFactor_(d->Wll, n, d->piv)) {
    return 1;
  }
  /* X = W_ll⁻¹ W_lb (its 6 columns at once), y = W_ll⁻¹ h r_l */
  memcpy(d->X, d->Wlb, (size_t)n * 6 * sizeof(double));
  csr_strainLuSolveMulti_(d->Wll, n, d->piv, d->X, 6);
  for (int j = 0; j < n; j++) {
    d->y[j] = h * d->rl[j];
  }
  csr_strainLuSolve_(d->Wll, n, d->piv, d->y);
  /* Z = W_bb - W_bl X, ρ = h r_b - W_bl y */
  double WbX[36];
  for (int a = 0; a < 6; a++) {
    for (int c = 0; c < 6; c++) {
      double t = 0;
      for (int j = 0; j < n; j++) {
        t += d->Wbl[n * a + j] * d->X[6 * j + c];
      }
      WbX[6 * a + c] = t;
    }
    double t = 0;
    for (int j = 0; j < n; j++) {
      t += d->Wbl[n * a + j] * d->y[j];
    }
    rho[a] = h * rb[a] - t;
  }
  for (int i = 0; i < 36; i++) {
    Z[i] = Wbb[i] - WbX[i];
  }
  memcpy(d->Zp, Z, sizeof d->Zp);
  memcpy(d->rhop, rho, sizeof d->rhop);
  memcpy(d->Rbp, d->Rb, sizeof d->Rbp);
  d->h = h;
  return 0;
}


int csr_strainFinish(const csrStrainModel* m, csrStrainData* d, const double dV[6],
                     const csrBaseState* b1) {
  const int n = m->n;
  /* the base's impulse on the leg is Z ΔV - ρ (hip body coordinates, (moment; force)): the leg
   * exerts its opposite, averaged over the step */
  double Jb[6];
  for (int a = 0; a < 6; a++) {
    double s = -d->rhop[a];
    for (int c = 0; c < 6; c++) {
      s += d->Zp[6 * a + c] * dV[c];
    }
    Jb[a] = -s / d->h;
  }
  csu_mulMatVec3(d->wbase.m, d->Rbp, Jb);
  csu_mulMatVec3(d->wbase.f, d->Rbp, Jb + 3);
  for (int j = 0; j < n; j++) {
    double s = d->y[j];
    for (int c = 0; c < 6; c++) {
      s -= d->X[6 * j + c] * dV[c];
    }
    d->eta[j] += s;
    d->q[j] += d->h * d->eta[j];
  }
  d->kin_valid = 0;
  d->h = 0;
  if (b1) {
    csr_strainSetBase(m, d, b1);
  } else {
    for (int c = 0; c < 6; c++) {
      d->Vb[c] += dV[c];
    }
  }
  if (!m->soft) {
    return 0;
  }
  /* return-map the friction anchors at the step's end */
  csr_strainKinematics_(m, d, 1);
  csr_strainPointTwists_(m, d);
  return csr_strainContactUpdate_(m, d);
}


void csr_strainBaseWrench(const csrStrainModel* m, const csrStrainData* d, csrWrench* w) {
  (void)m;
  *w = d->wbase;
}


void csr_strainPointTwists_(const csrStrainModel* m, csrStrainData* d) {
  for (int p = 0; p < m->np; p++) {
    pointTwist(m, d, p, d->Vb, d->eta, d->Vp + 6 * p);
  }
}


void csr_strainEnergy(const csrStrainModel* m, csrStrainData* d, double* kinetic,
                      double* elastic) {
  csr_strainKinematics_(m, d, 1);
  double T = 0;
  for (int p = 0; p < m->np; p++) {
    double V[6];
    pointTwist(m, d, p, d->Vb, d->eta, V);
    for (int r = 0; r < 6; r++) {
      T += 0.5 * m->Ms[6 * p + r] * V[r] * V[r];
    }
  }
  /* ½ (q - q0)ᵀ K (q - q0) with K q0 = b */
  double U = 0;
  for (int j = 0; j < m->n; j++) {
    double q0 = d->b[j] / d->Kd[j];
    U += 0.5 * d->Kd[j] * (d->q[j] - q0) * (d->q[j] - q0);
  }
  *kinetic = T;
  *elastic = U;
}


void csr_strainMassMoment(const csrStrainModel* m, csrStrainData* d, double mx[3]) {
  if (d->kin_valid < 1) {
    csr_strainKinematics_(m, d, 0);
  }
  memset(mx, 0, 3 * sizeof(double));
  for (int p = 0; p < m->np; p++) {
    double R[9], x[3];
    csr_strainWorld_(d, d->R + 9 * p, d->x + 3 * p, R, x);
    csu_addScl3(mx, mx, x, m->Ms[6 * p + 3]);
  }
}


void csr_strainMomentum(const csrStrainModel* m, csrStrainData* d, double P[3]) {
  csr_strainKinematics_(m, d, 1);
  memset(P, 0, 3 * sizeof(double));
  for (int p = 0; p < m->np; p++) {
    double V[6], R[9], x[3], vw[3];
    pointTwist(m, d, p, d->Vb, d->eta, V);
    csr_strainWorld_(d, d->R + 9 * p, d->x + 3 * p, R, x);
    csu_mulMatVec3(vw, R, V + 3);
    csu_addScl3(P, P, vw, m->Ms[6 * p + 3]);
  }
}

/* robot_strain_dyn.c: the strain leg's dynamics (robot_strain.h): state, base, the linearly
 * implicit step (its assembly, prepare, iterates, update and commit); its condensation onto the
 * base: robot_strain_condense.c; the inertia and the mass-weighted read-outs:
 * robot_strain_inertia.c.
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


/* the BDF2 history's doubles after [q, η, anchors, D]: q and η (2n), the base twist (6), Σ m x
 * (3), D (3) of the last step's start, and its length (1) */
static int historySize(const csrStrainModel* m) { return 2 * m->n + 13; }


void csr_strainStepCoeffs(const csrStrainModel* m, const csrStrainData* d, double h,
                          double c[3]) {
  csr_strainBdf2Coeffs(h, m->par.step_order == 2 ? d->hprev : 0, c);
}


int csr_strainStateSize(const csrStrainModel* m) {
  return 2 * m->n + m->nhist + 3 + historySize(m);
}


void csr_strainBdf2Coeffs(double h, double h_prev, double c[3]) {
  const double w = h_prev > 0 ? h / h_prev : 0;
  if (!(w > 0) || w > 2) {
    c[0] = 1, c[1] = 0, c[2] = 1;
    return;
  }
  c[0] = (1 + w) * (1 + w) / (1 + 2 * w);
  c[1] = -w * w / (1 + 2 * w);
  c[2] = (1 + w) / (1 + 2 * w);
}


void csr_strainGetState(const csrStrainModel* m, const csrStrainData* d, double* y) {
  memcpy(y, d->q, (size_t)m->n * sizeof(double));
  memcpy(y + m->n, d->eta, (size_t)m->n * sizeof(double));
  memcpy(y + 2 * m->n, d->z, (size_t)m->nhist * sizeof(double));
  memcpy(y + 2 * m->n + m->nhist, d->Dm, sizeof d->Dm);
  double* yh = y + 2 * m->n + m->nhist + 3;
  memcpy(yh, d->qm1, (size_t)m->n * sizeof(double));
  memcpy(yh + m->n, d->etam1, (size_t)m->n * sizeof(double));
  memcpy(yh + 2 * m->n, d->Vbm1, sizeof d->Vbm1);
  memcpy(yh + 2 * m->n + 6, d->Xm1, sizeof d->Xm1);
  memcpy(yh + 2 * m->n + 9, d->Dm1, sizeof d->Dm1);
  yh[2 * m->n + 12] = d->hprev;
}


int csr_strainSetState(const csrStrainModel* m, csrStrainData* d, const double* y) {
  for (int j = 0; j < csr_strainStateSize(m); j++) {
    if (!isfinite(y[j])) {
      return -1;
    }
  }
  memcpy(d->q, y, (size_t)m->n * sizeof(double));
  memcpy(d->eta, y + m->n, (size_t)m->n * sizeof(double));
  memcpy(d->z, y + 2 * m->n, (size_t)m->nhist * sizeof(double));
  memcpy(d->Dm, y + 2 * m->n + m->nhist, sizeof d->Dm);
  const double* yh = y + 2 * m->n + m->nhist + 3;
  memcpy(d->qm1, yh, (size_t)m->n * sizeof(double));
  memcpy(d->etam1, yh + m->n, (size_t)m->n * sizeof(double));
  memcpy(d->Vbm1, yh + 2 * m->n, sizeof d->Vbm1);
  memcpy(d->Xm1, yh + 2 * m->n + 6, sizeof d->Xm1);
  memcpy(d->Dm1, yh + 2 * m->n + 9, sizeof d->Dm1);
  d->hprev = yh[2 * m->n + 12];
  d->kin_valid = 0;
  d->h = 0;
  d->kf = 0; /* a restored state (a rejected step's retry) refactors */
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


/* the 6 x 6 Ad(g_p⁻¹) of point p */
static void adInv(const csrStrainData* d, int p, double A[36]) {
  csr_strainAdInv_(d->R + 9 * p, d->x + 3 * p, A);
}


/* the step's start: Σ m x (kinematics valid), q0, η0, the base's twist and frame, Δu = 0 */
static void saveStart(const csrStrainModel* m, csrStrainData* d) {
  const int n = m->n;
  csr_strainMassMomentAt_(m, d, d->X0m);
  memcpy(d->q0, d->q, (size_t)n * sizeof(double));
  memcpy(d->eta0, d->eta, (size_t)n * sizeof(double));
  memcpy(d->Vb0, d->Vb, sizeof d->Vb0);
  memcpy(d->Rbp, d->Rb, sizeof d->Rbp);
  memset(d->du, 0, (size_t)(6 + n) * sizeof(double));
  d->fcl_ok = 0; /* the one-pass carry's record: only this step's start assembly sets it */
}


/* The step's inertia and forces at the state now, into d->WM* and d->rM*.
 * at_iterate 0 (step_order 1, the step's start): the inertia M(q0), the velocity products,
 * weight and tip load at the start, the strains' elastic and damping forces linearised at the
 * end (exact: they are linear), W Δu = h r backward Euler linearised at the start.
 * at_iterate 1 (step_order 2, the state an iterate u_it = u0 + Δu_it, q_it = q̄ + h η_it with
 * h = c[2] h_step): everything at the iterate, so that h r = W Δu_it - R(u_it) with the BDF
 * residual R = M(q_it) (u_it - ū) - h (F(q_it, u_it) + b - K q_it - τ_d K η_it), ū = c[0] u0 +
 * c[1] u_-1; the contact (added by condense) and the momentum rows complete it:
 *   h r = M (ū - u0) + (h τ_d + h²) K Δη_it + h (F + b - K q_it - τ_d K η_it).
 * Converged (R = 0 with the contact's force at the iterate) the step is BDF2 exactly. */
static int assemble(const csrStrainModel* m, csrStrainData* d, double h, int at_iterate,
                    int inertia) {
  const int n = m->n;
  /* the kinematics relative to the base: the last Finish left it valid at this q (the
   * return-mapping needed it). Backward Euler's start by the recursion reads a midpoint's
   * Jacobian through its own piece's columns alone (the recursion's L_p; its step force's
   * J_pᵀ F_p on the earlier columns is J_cᵀ Ad(e^-Ω)ᵀ F_p through the chain point c before it,
   * J_p = Ad(e^-Ω) J_c there): the commit's want_J 4 left out the rest (~1/3 of the Jacobians'
   * columns). Whichever kinematics this q has (want_J 4, or 1 from a read-out: their columns
   * the same bits) the start takes this path, so a restored state steps as the kept one */
  const int mid_own = !at_iterate && !inertia && csr_strainArticStep_(m);
  if (mid_own) {
    if (!(d->kin_valid == 2 || (d->kin_valid == 1 && d->kin_midown)) ||
        !csr_strainStepsAt_(m, d)) {
      csr_strainKinematics_(m, d, 4);
    }
  } else if (d->kin_valid < 2) {
    csr_strainKinematics_(m, d, 1);
  }
  /* the velocity-product accelerations Ġ_p u: the twist recursion's derivative along q in
   * the direction η (csr_strainTwistRates_, one pass, exact to round-off, on the kinematics'
   * step exponentials where they are this q's); zero at η = 0. The twists it forms on the way
   * are the points' V_p = G_p u to round-off (the recursion V_to = Ad(e^-Ω) V_from + T(Ω) Ω̇
   * against the Jacobians' sum Ad(g_p⁻¹) V_b + J_p η): r below takes the midpoints' (the
   * chain points' again from their Jacobians: the contact's law is memoised on the shapes'
   * bits, and a twist of other bits misses the memo; docs/notes/strain_leg.md, legpass19) */
  int moving = 0;
  for (int j = 0; j < n && !moving; j++) {
    moving = d->eta[j] != 0;
  }
  if (moving) {
    csr_strainTwistRates_(m, d->q, d->eta, d->Vb, csr_strainStepsAt_(m, d), d->Vs, d->Ab);
  } else {
    memset(d->Ab, 0, (size_t)6 * m->np * sizeof(double));
  }
  /* the inertia W_bb, W_lb, W_ll (a step keeping its factor skips it: the residual forms
   * M(q0) Δu matrix-free), then r point by point */
  if (inertia) {
    csr_strainInertia_(m, d);
  }
  d->wm_step = inertia;
  d->art_pass = at_iterate && !inertia;
  double* rb = d->rMb;
  memset(rb, 0, sizeof d->rMb);
  memset(d->rMl, 0, (size_t)n * sizeof(double));
  double gh[3];
  csu_mulMatTVec3(gh, d->Rb, m->gravity);
  int pk = 0; /* the piece of point p (pt0[pk] < p <= pt0[pk + 1]) */
  for (int p = 0; p < m->np; p++) {
    const double* Ms = m->Ms + 6 * p;
    const double* J = d->J + (size_t)p * 6 * n;
    double* V = d->Vp + 6 * p;
    while (p > m->pt0[pk + 1]) {
      pk++;
    }
    if (moving && (p & 1)) {
      /* a midpoint's twist from the rate recursion; the chain points' from their Jacobians
       * below, the bits the contact's shapes were evaluated at (the law's memo, loadOf) */
      memcpy(V, d->Vs + 6 * p, 6 * sizeof(double));
    } else if (mid_own && (p & 1)) {
      /* at rest V_p = Ad(g_p⁻¹) V_b = (Rᵀ ω; Rᵀ (v + ω × x)), J_p η = 0 */
      double wx[3], t[3];
      csu_cross3(wx, d->Vb, d->x + 3 * p);
      csu_add3(t, d->Vb + 3, wx);
      csu_mulMatTVec3(V, d->R + 9 * p, d->Vb);
      csu_mulMatTVec3(V + 3, d->R + 9 * p, t);
    } else {
      csr_strainPointTwist_(m, d, p, d->Vb, d->eta, V);
    }
    d->vp_gen = -1; /* written here, not by csr_strainPointTwists_: its memo is off */
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
    /* r_b += Aᵀ F, r_l += Jᵀ F (J's columns from pcol on are zero): each entry's six terms
     * added in r's order, as six passes over r_l would (the same bits), r_l read and written
     * once */
    const int nc = m->pcol[p];
    for (int r = 0; r < 6; r++) {
      for (int c = 0; c < 6; c++) {
        rb[c] += A[6 * r + c] * F[r];
      }
    }
    if (mid_own && (p & 1)) {
      /* a midpoint: its own columns, then the earlier ones through the chain point p - 1 */
      const int c0 = m->dof0[pk];
      const double* ks = d->ks + 16 * p;
      double Fc[6];
      csr_strainRows6_(d->rMl + c0, J + c0, n, F, nc - c0, 1);
      csr_strainAdExpTApply_(ks, ks + 9, F, Fc);
      csr_strainRows6_(d->rMl, J - (size_t)6 * n, n, Fc, c0, 1);
    } else {
      csr_strainRows6_(d->rMl, J, n, F, nc, 1);
    }
  }
  const double tau = m->rpar.damping_time;
  if (at_iterate) {
    /* BDF's history, M (ū - u0) / h with ū - u0 = (c0 - 1) u0 + c1 u_-1 (zero for backward
     * Euler), by the inertia alone (before K joins W_ll's diagonal) */
    const double c0 = d->bc[0], c1 = d->bc[1];
    if ((c0 != 1 || c1 != 0) && !inertia) {
      /* the recursion's pass (csr_strainArticStep_) forms no inertia matrix: M w matrix-free at the
       * iterate's kinematics (J at every point: assembled above), the same sums to round-off */
      double* w = d->Gs; /* 6 + n scratch; M w into d->Mu */
      for (int c = 0; c < 6; c++) {
        w[c] = ((c0 - 1) * d->Vb0[c] + c1 * d->Vbm1[c]) / h;
      }
      for (int j = 0; j < n; j++) {
        w[6 + j] = ((c0 - 1) * d->eta0[j] + c1 * d->etam1[j]) / h;
      }
      csr_strainInertiaApply_(m, d->R, d->x, d->J, w, d->Mu);
      for (int a = 0; a < 6; a++) {
        rb[a] += d->Mu[a];
      }
      for (int j = 0; j < n; j++) {
        d->rMl[j] += d->Mu[6 + j];
      }
    } else if (c0 != 1 || c1 != 0) {
      double* w = d->Gs; /* 6 + n scratch */
      for (int c = 0; c < 6; c++) {
        w[c] = ((c0 - 1) * d->Vb0[c] + c1 * d->Vbm1[c]) / h;
      }
      for (int j = 0; j < n; j++) {
        w[6 + j] = ((c0 - 1) * d->eta0[j] + c1 * d->etam1[j]) / h;
      }
      for (int a = 0; a < 6; a++) {
        double t = 0;
        for (int c = 0; c < 6; c++) {
          t += d->WMbb[6 * a + c] * w[c];
        }
        for (int j = 0; j < n; j++) {
          t += d->WMlb[6 * j + a] * w[6 + j];
        }
        rb[a] += t;
      }
      for (int j = 0; j < n; j++) {
        double t = 0;
        for (int c = 0; c < 6; c++) {
          t += d->WMlb[6 * j + c] * w[c];
        }
        for (int k = 0; k < n; k++) {
          t += d->WMll[(size_t)j * n + k] * w[6 + k];
        }
        d->rMl[j] += t;
      }
    }
    /* the elastic and damping forces at the iterate and W's (h τ_d + h²) K Δη_it */
    for (int j = 0; j < n; j++) {
      d->rMl[j] += d->b[j] - d->Kd[j] * (d->q[j] + tau * d->eta[j]) +
                   (tau + h) * d->Kd[j] * d->du[6 + j];
      if (inertia) {
        d->WMll[j * n + j] += (h * tau + h * h) * d->Kd[j];
      }
      if (!isfinite(d->rMl[j])) {
        return 1;
      }
    }
    return 0;
  }
  /* the strains' elastic and damping forces at the step's end,
   * b - K (q0 + h η1) - τ_d K η1 with η1 = η0 + Δη */
  for (int j = 0; j < n; j++) {
    d->rMl[j] += d->b[j] - d->Kd[j] * (d->q[j] + (tau + h) * d->eta[j]);
    if (inertia) {
      d->WMll[j * n + j] += (h * tau + h * h) * d->Kd[j];
    }
    if (!isfinite(d->rMl[j])) {
      return 1;
    }
  }
  saveStart(m, d);
  return 0;
}


/* the base's pose at the step's end at its start twist, g_b exp(h V_b), into Rb, xb */
static void predictBase(const csrStrainData* d, double h, double* Rb, double* xb) {
  double Om[6], Re[9], pe[3], t[3];
  for (int c = 0; c < 6; c++) {
    Om[c] = h * d->Vb[c];
  }
  csr_strainExp_(Om, Re, pe);
  double R1[9], x1[3]; /* Rb, xb may be d->Rb, d->xb */
  csu_mulMat3(R1, d->Rb, Re);
  csu_mulMatVec3(t, d->Rb, pe);
  csu_add3(x1, d->xb, t);
  memcpy(Rb, R1, sizeof R1);
  memcpy(xb, x1, sizeof x1);
}


/* The shapes' poses at the predicted end of the step, q0 + h η0 with the hip moved on by its
 * start twist (g_b exp(h V_b)), into d->sst (x0, x1, R), from the poses' kinematics there; the
 * kinematics at q0 back after (its Jacobians untouched). The start's contact linearisation
 * carries the shapes over the step by y0 + h S u1 (robot_strain_contact.c), linear in the
 * strains: a stance leg that bends by δ = h |η| L over a step moves its foot by ~δ²/L more
 * than that, micrometres at 5 ms, against a foot resting 0.6 µm deep (docs/notes/
 * strain_leg.md, "Active set"); these poses give the linear model that offset. */
void csr_strainPredictShapes_(const csrStrainModel* m, csrStrainData* d, double h) {
  const int n = m->n;
  const int valid = d->kin_valid;
  for (int j = 0; j < n; j++) {
    d->q_save[j] = d->q[j];
    d->q[j] += h * d->eta[j];
  }
  memcpy(d->Rs_save, d->R, (size_t)9 * m->np * sizeof(double));
  memcpy(d->xs_save, d->x, (size_t)3 * m->np * sizeof(double));
  /* the shapes end at chain points: their poses alone (the midpoints' are restored below) */
  csr_strainKinematics_(m, d, 3);
  double Rb[9], xb[3];
  memcpy(Rb, d->Rb, sizeof Rb);
  memcpy(xb, d->xb, sizeof xb);
  predictBase(d, h, d->Rb, d->xb);
  for (int s = 0; s < m->nshape; s++) {
    const int a = m->shape_a[s], b = m->shape_b[s];
    double Rt[9];
    cscShapeState* st = d->sst + s;
    csr_strainWorld_(d, d->R + 9 * a, d->x + 3 * a, st->R, st->x0);
    csr_strainWorld_(d, d->R + 9 * b, d->x + 3 * b, Rt, st->x1);
  }
  memcpy(d->Rb, Rb, sizeof Rb);
  memcpy(d->xb, xb, sizeof xb);
  memcpy(d->q, d->q_save, (size_t)n * sizeof(double));
  /* the poses at q0 back from their copy (the same numbers the kinematics would recompute) */
  memcpy(d->R, d->Rs_save, (size_t)9 * m->np * sizeof(double));
  memcpy(d->x, d->xs_save, (size_t)3 * m->np * sizeof(double));
  d->kin_valid = valid;
  d->pred = 1;
}


/* ---- Kept matrix (keep_matrix) ------------------------------------------------------------
 * A step keeps the last factorisation of W (W_ll with the contact's linearisation factored,
 * X = W_ll⁻¹ W_lb, Z onto the base) when it has the same h, no mode moved more than
 * keep_strain since that factorisation, the state was not restored since, and at its first
 * iterate every contact slot is in the state the factor was linearised in. Its passes are
 * then chord steps W_f δ = -R with the exact residual (csr_strainCondenseKept_): the step converges to
 * the same backward Euler step as with a fresh W, only the path differs. Within the step a
 * kept factor is dropped as before: a slot changing state, a released ghost, an iterate whose
 * move shrank less than 4x over the last. What a kept step skips: the inertia's assembly, the
 * contact's linearisation (its law's derivatives and Sᵀ A S), the factorisation and its
 * six-column solve (docs/notes/strain_leg.md, "A kept iteration matrix"). */

/* 1: no mode moved more than keep_strain since the kept factorisation (rad or strain over its
 * piece) */
static int keptStrains(const csrStrainModel* m, const csrStrainData* d) {
  if (!(m->par.keep_strain >= 0)) {
    return 0;
  }
  for (int j = 0; j < m->n; j++) {
    if (fabs(d->q[j] - d->qf[j]) * m->dscale[j] > m->par.keep_strain) {
      return 0;
    }
  }
  return 1;
}


/* A kept step's first pass (after assemble without the inertia: r_M, the start saved, Δu = 0):
 * the chord step from the iterate Δu = 0, the strains at q0 + h η0 and the hip at
 * g_b exp(h V_b0), with the contact's load there (no linearisation) and the base's momentum
 * rows as an iterate's. Returns 1 when it is taken (Z, ρ, d->y set), 0 when the step must
 * refactor (a slot not in the factor's state, a pose past a shape's radius, not finite): the
 * state (q, base) is the start's either way, the kinematics not valid. */
static int prepareKept(const csrStrainModel* m, csrStrainData* d, double h, double Z[36],
                       double rho[6]) {
  const int n = m->n;
  double Rb[9], xb[3];
  memcpy(Rb, d->Rb, sizeof Rb);
  memcpy(xb, d->xb, sizeof xb);
  predictBase(d, h, d->Rb, d->xb);
  for (int j = 0; j < n; j++) {
    d->q[j] = d->q0[j] + h * d->eta0[j];
  }
  d->kin_valid = 0;
  double fb[6] = {0, 0, 0, 0, 0, 0};
  int same = 1, rc = 0;
  memset(d->fl, 0, (size_t)n * sizeof(double));
  /* the poses first: a leg that touches nowhere there needs no Jacobians or twists (its
   * factor's state holds if it had no contact either) */
  csr_strainKinematics_(m, d, 0);
  if (csr_strainContactNone_(m, d)) {
    memset(d->fcw, 0, sizeof d->fcw);
    d->ntouch = 0;
    same = d->lu_plain;
  } else {
    csr_strainKinematics_(m, d, 2);
    csr_strainPointTwistsChain_(m, d);
    rc = csr_strainContactLoads_(m, d, fb, d->fl, &same);
  }
  int kept = 0;
  if (rc == 0 && same) {
    d->w_lag = 1;
    kept = csr_strainCondenseKept_(m, d, h, d->du, fb, Z, rho) == 0;
  }
  memcpy(d->q, d->q0, (size_t)n * sizeof(double));
  memcpy(d->Rb, Rb, sizeof Rb);
  memcpy(d->xb, xb, sizeof xb);
  d->kin_valid = 0;
  if (!kept) {
    d->w_lag = 0;
  }
  return kept;
}


/* BDF2's prepare (step_order 2): the start saved, the first iterate u_it = u0 at the predicted
 * q̄ + c2 h η0, everything assembled there */
static int prepareBdf(const csrStrainModel* m, csrStrainData* d, double h, double Z[36],
                      double rho[6]) {
  const int n = m->n;
  csr_strainBdf2Coeffs(h, d->hprev, d->bc);
  d->he = d->bc[2] * h;
  if (d->kin_valid < 1) {
    csr_strainKinematics_(m, d, 0);
  }
  saveStart(m, d);
  if (m->soft && m->par.active_set) {
    /* the contact's linear model about the start until the first iterate (robot_strain_contact.c
     * csr_strainGhostStart_) */
    if (!csr_strainChainJ_(d)) {
      csr_strainKinematics_(m, d, 2);
    }
    csr_strainPointTwistsChain_(m, d);
    int rc = csr_strainGhostStart_(m, d);
    if (rc != 0) {
      return rc;
    }
  }
  if (!m->par.step_refresh && d->bc[1] != 0) {
    /* the linearly implicit step assembles its inertia, velocity products and weight once,
     * here: at the velocities extrapolated from the last two starts, u0 + ω (u0 - u_-1)
     * (ω = h / h_prev), O(h²) from the step's end, so that what the step freezes errs by
     * O(h³) per step as BDF2 itself (at u0 the velocity products' O(h) error made the step
     * first order: test_strain_dyn step_order_observed). The iterate is then Δu = u_p - u0,
     * and the assembled h r = W Δu_p - R(u_p) is the linear model about it. */
    const double w = h / d->hprev;
    for (int c = 0; c < 6; c++) {
      d->du[c] = w * (d->Vb0[c] - d->Vbm1[c]);
      d->Vb[c] = d->Vb0[c] + d->du[c];
    }
    for (int j = 0; j < n; j++) {
      d->du[6 + j] = w * (d->eta0[j] - d->etam1[j]);
      d->eta[j] = d->eta0[j] + d->du[6 + j];
    }
  }
  for (int j = 0; j < n; j++) {
    d->q[j] = d->bc[0] * d->q0[j] + d->bc[1] * d->qm1[j] + d->he * d->eta[j];
  }
  d->kin_valid = 0;
  csr_strainKinematics_(m, d, 1);
  d->lu_plain = 0;
  int rc = assemble(m, d, d->he, 1, !csr_strainArticStep_(m));
  return rc != 0 ? rc : csr_strainCondense_(m, d, d->he, d->du, Z, rho);
}


int csr_strainPrepare(const csrStrainModel* m, csrStrainData* d, double h, double Z[36],
                      double rho[6]) {
  if (!(h > 0) || !isfinite(h) || !Z || !rho) {
    return -1;
  }
  d->h = 0;
  d->w_step = 0;
  d->at_iterate = 0;
  /* the active set is the step's: none held before its first linearisation */
  csr_strainGhostReset_(m, d);
  int rc;
  if (m->par.step_order == 2) {
    rc = prepareBdf(m, d, h, Z, rho);
    if (rc != 0) {
      /* the start back: the state is not changed by a failed prepare */
      memcpy(d->q, d->q0, (size_t)m->n * sizeof(double));
      memcpy(d->eta, d->eta0, (size_t)m->n * sizeof(double));
      memcpy(d->Vb, d->Vb0, sizeof d->Vb);
      d->kin_valid = 0;
    }
  } else {
    d->bc[0] = 1, d->bc[1] = 0, d->bc[2] = 1;
    d->he = h;
    d->nstep++;
    int keep = m->par.keep_matrix && d->kf && d->kf_h == h && keptStrains(m, d);
    rc = assemble(m, d, h, 0, !keep && !csr_strainArticStep_(m));
    if (rc == 0 && m->par.keep_matrix) {
      /* the start's kinematics for the residual's M(q0) Δu at later passes (the iterates
       * overwrite d->R, d->x, d->J) and for a refactorisation at an iterate: a kept step
       * swaps the arrays (the start's into R0, x0, J0, d->R... scratch), a new factor copies */
      if (keep) {
        double* t = d->R;
        d->R = d->R0, d->R0 = t;
        t = d->x;
        d->x = d->x0, d->x0 = t;
        t = d->J;
        d->J = d->J0, d->J0 = t;
        d->kin_valid = 0;
        d->kin_gen++;
      } else {
        memcpy(d->R0, d->R, (size_t)9 * m->np * sizeof(double));
        memcpy(d->x0, d->x, (size_t)3 * m->np * sizeof(double));
        memcpy(d->J0, d->J, (size_t)6 * m->np * m->n * sizeof(double));
      }
    }
    if (rc == 0 && keep) {
      keep = prepareKept(m, d, h, Z, rho);
      d->nkept += keep;
      if (!keep) {
        /* refactor after all: the start's kinematics back, W_M as assemble forms it */
        const double tau = m->rpar.damping_time;
        memcpy(d->R, d->R0, (size_t)9 * m->np * sizeof(double));
        memcpy(d->x, d->x0, (size_t)3 * m->np * sizeof(double));
        memcpy(d->J, d->J0, (size_t)6 * m->np * m->n * sizeof(double));
        d->kin_valid = 2;
        d->kin_gen++;
        csr_strainPointTwists_(m, d); /* the chain points' twists were the predicted end's */
        if (!d->wm_step) {
          csr_strainInertia_(m, d);
          for (int j = 0; j < m->n; j++) {
            d->WMll[j * m->n + j] += (h * tau + h * h) * d->Kd[j];
          }
          d->wm_step = 1;
        }
      }
    }
    if (rc == 0 && !keep) {
      if (m->soft && m->par.active_set) {
        /* the predicted poses are read only by a shape that touches at the start: formed
         * there, at the first (csr_strainContactAssemble_); a swing leg's start skips the
         * kinematics at q0 + h η0 (docs/notes/strain_leg.md, branch speed11) */
        d->pred = 2;
      }
      rc = csr_strainCondense_(m, d, h, NULL, Z, rho);
      d->pred = 0;
    }
  }
  if (rc != 0) {
    return rc;
  }
  d->h = h;
  d->chg_last = d->chg_prev = INFINITY;
  d->nreuse = 0;
  return 0;
}


static int iterateAt(const csrStrainModel* m, csrStrainData* d, double Z[36], double rho[6]);


int csr_strainIterate(const csrStrainModel* m, csrStrainData* d, double Z[36], double rho[6]) {
  const int rc = iterateAt(m, d, Z, rho);
  d->ghost_hold = 0; /* BDF2's contact model about the start ends with the first iterate */
  return rc;
}


static int iterateAt(const csrStrainModel* m, csrStrainData* d, double Z[36], double rho[6]) {
  if (!(d->h > 0) || !Z || !rho) {
    return -1;
  }
  /* a leg without contact in its factor: if no shape touches at the iterate's poses, the
   * iterate needs those poses alone (no Jacobians, no point twists); BDF2 with step_refresh
   * assembles its whole residual at the iterate instead */
  /* the linearly implicit BDF2 refreshes its linear model at the iterate (as step_refresh
   * would every pass) when the leg's own move shrank less than 4x over its last iterate: the
   * frozen inertia and velocity products no longer carry the iteration there (a touch-down,
   * a foot's stick/slip) */
  d->at_iterate = 1;
  int full = csr_strainBdfFull_(m);
  if (m->par.step_order == 2 && !full && d->chg_prev < INFINITY &&
      !(d->chg_last <= 0.25 * d->chg_prev)) {
    full = 1;
    d->w_step = 0;
  }
  if (d->lu_plain && !full) {
    if (d->kin_valid < 1) {
      csr_strainKinematics_(m, d, 0);
    }
    if (csr_strainContactNone_(m, d)) {
      memset(d->fcw, 0, sizeof d->fcw);
      d->ntouch = 0;
      if (!d->w_lag) {
        return csr_strainCondensePlain_(m, d, d->he, d->du, Z, rho);
      }
      /* an earlier step's factor without contact: its chord step. Its contraction is not
       * tested: the factor lags by the inertia's change alone (keep_strain bounds it), while
       * the leg's move from pass to pass follows the support's, which the stance legs'
       * contact decides (tested, the 4x rule refreshed swing legs at most passes) */
      if (!d->fresh) {
        const double fb[6] = {0, 0, 0, 0, 0, 0};
        memset(d->fl, 0, (size_t)m->n * sizeof(double));
        d->nreuse++;
        return csr_strainCondenseKept_(m, d, d->he, d->du, fb, Z, rho);
      }
    }
  }
  /* the kinematics and point twists at the iterate's end of the step */
  if (full) {
    if (d->kin_valid < 2) {
      csr_strainKinematics_(m, d, 1);
    }
    int rc = assemble(m, d, d->he, 1, !csr_strainArticStep_(m));
    return rc != 0 ? rc : csr_strainCondense_(m, d, d->he, d->du, Z, rho);
  }
  /* backward Euler's iterate that may keep its matrix (csr_strainCondense_'s test, less the
   * slots' states the loads decide): the loads need the poses, the chain points' twists and
   * Sᵀ L, not the chain points' Jacobians (the twists by their recursion, Sᵀ L by the adjoint
   * sweep, on the kinematics' steps: want_J 5 keeps T(Ω), ∂Ω/∂q), which only a new
   * linearisation reads: formed when the condensation asks for them (5 329 of the flat
   * road's 6 302 touching iterates keep; docs/notes/strain_leg.md, kept20) */
  if (m->par.step_order == 1 && !d->fresh && (!d->lu_plain || d->w_lag) &&
      (d->nreuse == 0 || d->chg_last <= 0.25 * d->chg_prev || d->lu_plain) &&
      !csr_strainChainJ_(d)) {
    if (!d->kst_ok || !csr_strainStepsAt_(m, d)) {
      csr_strainKinematics_(m, d, 5);
    }
    csr_strainChainTwistsNoJ_(m, d);
    const int rc = csr_strainCondense_(m, d, d->he, d->du, Z, rho);
    if (rc != CSR_STRAIN_NEED_J) {
      return rc;
    }
  }
  /* the contact's loads and linearisation need the Jacobians and twists at the shapes' ends
   * alone, the chain points: the midpoints' Jacobians (half of the recursion's columns) are
   * skipped, the same numbers at the chain points */
  if (d->kin_valid < 2) {
    csr_strainKinematics_(m, d, 2);
  }
  csr_strainPointTwistsChain_(m, d);
  return csr_strainCondense_(m, d, d->he, d->du, Z, rho);
}


int csr_strainRelease(const csrStrainModel* m, csrStrainData* d) {
  if (!(d->h > 0)) {
    return 0;
  }
  const int n = csr_strainGhostRelease_(m, d);
  if (n > 0) {
    /* the kept matrix holds the released shapes' stiffness: the next iterate linearises
     * afresh (kept, the chord crawls through the gap: docs/notes/strain_leg.md, "Newton's
     * contraction", FAST2_LOSTKEEP) */
    d->fresh = 1;
  }
  return n;
}


double csr_strainStepLimit(const csrStrainModel* m, csrStrainData* d, const double dV[6]) {
  if (!m->par.slot_trust || m->par.step_order != 1 || !(d->h > 0) || !dV || !d->at_iterate ||
      d->lu_plain || d->kin_valid < 1) {
    return 1.0; /* an iterate's condense formed the Jacobians at the chain points at least
                   (want_J 2, kin_valid 1; the foot's point is one) or everywhere (kin_valid 2) */
  }
  if (!csr_strainChainJ_(d)) {
    /* a kept iterate's loads went without the chain points' Jacobians: the trust region's
     * foot rows read them (the poses at the same q: the same bits) */
    csr_strainKinematics_(m, d, 2);
  }
  /* the full move from the last iterate: the base's ΔV and the rates' y - X ΔV (as
   * csr_strainUpdateDamped) less the iterate's */
  const int n = m->n;
  double* dd = d->fl; /* scratch (n): the contact's force at the iterate is used up */
  double dd6[6];
  for (int c = 0; c < 6; c++) {
    dd6[c] = dV[c] - d->du[c];
  }
  for (int j = 0; j < n; j++) {
    double t = d->y[j];
    for (int c = 0; c < 6; c++) {
      t -= d->X[6 * j + c] * dV[c];
    }
    dd[j] = t - d->du[6 + j];
  }
  return csr_strainContactLimit_(m, d, d->h, dd6, dd);
}


int csr_strainUpdate(const csrStrainModel* m, csrStrainData* d, const double dV[6],
                     const csrBaseState* b1, double* change) {
  return csr_strainUpdateDamped(m, d, dV, 1.0, b1, change);
}


int csr_strainUpdateDamped(const csrStrainModel* m, csrStrainData* d, const double dV[6],
                           double alpha, const csrBaseState* b1, double* change) {
  if (!(d->h > 0) || !dV || !(alpha > 0 && alpha <= 1)) {
    return -1;
  }
  const int n = m->n;
  const double h = d->h, he = d->he;
  const int bdf = m->par.step_order == 2;
  /* the base's ΔV of this iterate: the last one moved by alpha toward the solve's */
  double dVa[6];
  for (int c = 0; c < 6; c++) {
    dVa[c] = d->du[c] + alpha * (dV[c] - d->du[c]);
  }
  /* the base's impulse on the leg is Z ΔV - ρ (hip body coordinates, (moment; force)): the leg
   * exerts its opposite, averaged over the step */
  double Jb[6];
  for (int a = 0; a < 6; a++) {
    double s = -d->rhop[a];
    for (int c = 0; c < 6; c++) {
      s += d->Zp[6 * a + c] * dVa[c];
    }
    Jb[a] = -s / he;
  }
  csu_mulMatVec3(d->wbase.m, d->Rbp, Jb);
  csu_mulMatVec3(d->wbase.f, d->Rbp, Jb + 3);
  /* Δη = y - X ΔV; the largest move of a mode against the last iterate, as rotation or
   * strain over its piece */
  double chg = 0;
  for (int j = 0; j < n; j++) {
    double s = d->y[j];
    for (int c = 0; c < 6; c++) {
      s -= d->X[6 * j + c] * dV[c];
    }
    chg = fmax(chg, h * fabs(s - d->du[6 + j]) * m->dscale[j]);
    s = d->du[6 + j] + alpha * (s - d->du[6 + j]);
    d->du[6 + j] = s;
    d->eta[j] = d->eta0[j] + s;
    d->q[j] = bdf ? d->bc[0] * d->q0[j] + d->bc[1] * d->qm1[j] + he * d->eta[j]
                  : d->q0[j] + h * d->eta[j];
  }
  memcpy(d->du, dVa, 6 * sizeof(double));
  d->chg_prev = d->chg_last;
  d->chg_last = chg;
  if (change) {
    *change = isfinite(chg) ? chg : INFINITY;
  }
  d->kin_valid = 0;
  if (b1) {
    memcpy(d->Rb, b1->R, sizeof d->Rb);
    memcpy(d->xb, b1->x, sizeof d->xb);
    csu_mulMatTVec3(d->Vb, b1->R, b1->w);
    csu_mulMatTVec3(d->Vb + 3, b1->R, b1->v);
  } else {
    for (int c = 0; c < 6; c++) {
      d->Vb[c] = d->Vb0[c] + dVa[c];
    }
  }
  return isfinite(chg) ? 0 : 1;
}


int csr_strainCommit(const csrStrainModel* m, csrStrainData* d) {
  if (!(d->h > 0)) {
    return -1;
  }
  const double h = d->h;
  d->h = 0;
  /* the kinematics at the step's end: the next step's start and the return-mapping need it.
   * BDF2's next prepare forms its own at the extrapolated iterate and reads at the start the
   * poses (Σ m x) and the chain points' Jacobians (the contact's records) alone, as do the
   * return-mapping and the output's contact read-out: the midpoints' Jacobians are left out
   * (want_J 2; docs/notes/strain_leg.md, bdf15) */
  if (d->kin_valid < 2) {
    /* backward Euler's next start by the recursion reads the midpoints' own columns alone
     * (assemble): want_J 4 */
    csr_strainKinematics_(m, d, m->par.step_order == 2 ? 2 : csr_strainArticStep_(m) ? 4 : 1);
  }
  double X1[3];
  csr_strainMassMomentAt_(m, d, X1);
  for (int i = 0; i < 3; i++) {
    const double Dnew = m->par.step_order == 2
                            ? (X1[i] - d->bc[0] * d->X0m[i] - d->bc[1] * d->Xm1[i]) / d->he
                            : (X1[i] - d->X0m[i]) / h;
    /* the history moves on (BDF2's; kept by backward Euler too, unused there) */
    d->Dm1[i] = d->Dm[i];
    d->Xm1[i] = d->X0m[i];
    d->Dm[i] = Dnew;
  }
  memcpy(d->qm1, d->q0, (size_t)m->n * sizeof(double));
  memcpy(d->etam1, d->eta0, (size_t)m->n * sizeof(double));
  memcpy(d->Vbm1, d->Vb0, sizeof d->Vbm1);
  d->hprev = h;
  if (!m->soft) {
    return 0;
  }
  /* return-map the friction anchors at the step's end (the shapes' twists, at the chain
   * points: the next prepare forms every point's twist anew) */
  csr_strainPointTwistsChain_(m, d);
  return csr_strainContactUpdate_(m, d);
}


int csr_strainFinish(const csrStrainModel* m, csrStrainData* d, const double dV[6],
                     const csrBaseState* b1) {
  int rc = csr_strainUpdate(m, d, dV, b1, NULL);
  if (rc != 0) {
    d->h = 0;
    return rc;
  }
  return csr_strainCommit(m, d);
}


void csr_strainBaseWrench(const csrStrainModel* m, const csrStrainData* d, csrWrench* w) {
  (void)m;
  *w = d->wbase;
}


void csr_strainCounts(const csrStrainData* d, long* steps, long* factors, long* kept) {
  *steps = d->nstep;
  *factors = d->nfactor;
  *kept = d->nkept;
}

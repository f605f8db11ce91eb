/* robot_strain_condense.c: the strain leg's step condensed onto its base, the paths by which a
 * pass turns W Δu = h r (robot_strain_dyn.c: the step, its assembly of W_M and r_M) into the
 * base's Z, ρ and the leg's X = W_ll⁻¹ W_lb, y = W_ll⁻¹ h r_l:
 *  - csr_strainCondense_: a pass that linearises the contact (robot_strain_contact.c) and
 *    chooses its factor: the articulated recursion at a step's start or a BDF2 pass assembled
 *    at its iterate (condenseStart; condenseStance with the contact's blocks, artic 2:
 *    robot_strain_artic.c), the Woodbury update of that factor at an iterate that refactors
 *    (condenseUpdate: robot_strain_woodbury.c), or the dense W_ll's Cholesky or LU
 *    (factorAndCondense, W_M formed where the recursion left it out: wmFrom, denseStart);
 *  - csr_strainCondensePlain_: an iterate without contact on a factor without it (ρ alone);
 *  - csr_strainCondenseKept_: a chord iterate on the step's (or an earlier step's) factor,
 *    through the dense factor or the recursion's pieces (condenseKeptArtic);
 *  - the base's rows of linear momentum in the discrete momentum form at an iterate
 *    (momentumRows), which every iterate's ρ takes.
 * The equations and the step's form: robot_strain_dyn.c's header; the paths' costs and checks:
 * docs/notes/strain_leg.md ("The articulated condensation", "An iterate's refactor by the
 * Woodbury update", "bdf14"). */
#include <math.h>
#include <string.h>

#include "core_math.h"
#include "robot_strain_internal.h"


/* An iterate's base rows of linear momentum in the discrete momentum form (robot_strain.h,
 * Momentum): their residual, exact at the iterate,
 *   R = R_b1ᵀ ((X(q1, g_b1) - X0) / h - D_prev - h (f_contact + m g + f_tip)),
 * X = Σ m x the leg's mass moment, D_prev the last step's (X1 - X0) / h, and h r of those rows
 * replaced by W Δu_it - R: the Newton pass solves W Δu = W Δu_it - R on them (W's rows are the
 * momentum's Jacobian, Σ m ∂x/∂u / h · h = the mass matrix's rows). */
static void momentumRows(const csrStrainModel* m, const csrStrainData* d, double h,
                         const double* du, const double Wbb[36], double rb[6]) {
  const int n = m->n;
  double X1[3], f[3], Rw[3], Rl[3];
  csr_strainMassMomentAt_(m, d, X1);
  /* the world forces: contact, weight (the model's gravity is zero when weightless), tip */
  csu_scale3(f, m->gravity, m->mass);
  csu_add3(f, f, d->fcw);
  csu_add3(f, f, d->tipd_f);
  for (int i = 0; i < 3; i++) {
    /* BDF2 (robot_strain.h): (X1 - X̄) / h - D̄ = h f, X̄ = c0 X0 + c1 X_-1, D̄ = c0 D0 + c1 D_-1
     * (h the implicit part's step); backward Euler: X̄ = X0, D̄ = D0 */
    const double Xb = m->par.step_order == 2 ? d->bc[0] * d->X0m[i] + d->bc[1] * d->Xm1[i]
                                             : d->X0m[i];
    const double Db = m->par.step_order == 2 ? d->bc[0] * d->Dm[i] + d->bc[1] * d->Dm1[i]
                                             : d->Dm[i];
    Rw[i] = (X1[i] - Xb) / h - Db - h * f[i];
  }
  csu_mulMatTVec3(Rl, d->Rb, Rw);
  for (int i = 0; i < 3; i++) {
    double Wdu = 0;
    for (int c = 0; c < 6; c++) {
      Wdu += Wbb[6 * (3 + i) + c] * du[c];
    }
    for (int j = 0; j < n; j++) {
      Wdu += d->Wbl[n * (3 + i) + j] * du[6 + j];
    }
    rb[3 + i] = (Wdu - Rl[i]) / h;
  }
}


/* An iterate without contact, whose last factor had none either: W_ll, W_lb, r_l and so X, y
 * and Z are the last pass's; only the base's momentum rows (ρ) change (they need the poses
 * alone: the leg's mass moment) */
int csr_strainCondensePlain_(const csrStrainModel* m, csrStrainData* d, double h,
                             const double* du, double Z[36], double rho[6]) {
  const int n = m->n;
  double Wbb[36], rb[6];
  memcpy(Wbb, d->WMbb, sizeof Wbb);
  memcpy(rb, d->rMb, sizeof rb);
  momentumRows(m, d, h, du, Wbb, rb);
  for (int a = 0; a < 6; a++) {
    double t = 0;
    for (int j = 0; j < n; j++) {
      t += d->Wbl[n * a + j] * d->y[j];
    }
    rho[a] = h * rb[a] - t;
  }
  memcpy(Z, d->Zp, sizeof d->Zp);
  memcpy(d->rhop, rho, sizeof d->rhop);
  for (int a = 0; a < 6; a++) {
    if (!isfinite(rho[a])) {
      return 1;
    }
  }
  return 0;
}


/* condenseKept on the recursion's factor (art_f: a touching leg's start with artic 2): W_f -
 * W_M is the contact's -h Sᵀ A S of the start's touching shapes (d->cS, cA), so the
 * right-hand side W_f Δu_it - R = h (r_M + f) - h Sᵀ A S Δu_it needs no n x n matrix; W_ll⁻¹
 * by the pieces' factors (csr_strainArticSolve_), whose W_bl W_ll⁻¹ gives ρ */
static int condenseKeptArtic(const csrStrainModel* m, csrStrainData* d, double h,
                             const double* du, const double fb[6], double Z[36], double rho[6]) {
  const int n = m->n, nu = 6 + n;
  /* on an iterate's Woodbury update of the start's factor (wb_f) W_f - W_M is the iterate's
   * shapes' part (wS, wA), and W_ll⁻¹ the update's */
  const int wb = d->wb_f;
  const int nsh = wb ? d->nwt : d->nct;
  double* wc = d->Mu; /* (6 + n) scratch: (W_f - W_M) Δu_it */
  memset(wc, 0, (size_t)nu * sizeof(double));
  for (int c = 0; c < nsh; c++) {
    const double* S = (wb ? d->wS : d->cS) + (size_t)c * 6 * nu;
    const double* A = (wb ? d->wA : d->cA) + 36 * c;
    double Sdu[6], g[6];
    for (int r = 0; r < 6; r++) {
      double t = 0;
      for (int k = 0; k < nu; k++) {
        t += S[r * nu + k] * du[k];
      }
      Sdu[r] = t;
    }
    for (int r = 0; r < 6; r++) {
      double t = 0;
      for (int k = 0; k < 6; k++) {
        t += A[6 * r + k] * Sdu[k];
      }
      g[r] = -h * t;
    }
    csr_strainRows6_(wc, S, nu, g, nu, 1);
  }
  double rb[6];
  for (int j = 0; j < n; j++) {
    d->y[j] = h * (d->rMl[j] + d->fl[j]) + wc[6 + j];
    if (!isfinite(d->y[j])) {
      return 1;
    }
  }
  for (int a = 0; a < 6; a++) {
    rb[a] = (h * (d->rMb[a] + fb[a]) + wc[a]) / h;
  }
  momentumRows(m, d, h, du, d->Wbbp, rb);
  double w[6];
  if (wb) {
    csr_strainWoodburySolve_(m, d, h, d->y);
    for (int a = 0; a < 6; a++) {
      double t = 0;
      for (int j = 0; j < n; j++) {
        t += d->Wbl[n * a + j] * d->y[j];
      }
      w[a] = t;
    }
  } else {
    csr_strainArticSolve_(m, d, d->y, w);
  }
  for (int a = 0; a < 6; a++) {
    rho[a] = h * rb[a] - w[a];
    if (!isfinite(rho[a])) {
      return 1;
    }
  }
  memcpy(Z, d->Zp, sizeof d->Zp);
  memcpy(d->rhop, rho, sizeof d->rhop);
  return 0;
}


/* A Newton iterate that keeps the step's last iteration matrix W_f (factored in d->Wll, its
 * blocks d->Wu, d->Wlb, d->Wbl, d->Wbbp; Z = d->Zp): the chord step W_f δ = -R(Δu_it), so in
 * the whole step's Δu the right-hand side is W_f Δu_it - R = h r + (W_f - W_M) Δu_it, with
 * h r = h (r_M + the contact's force at the iterate, fl, fb) and W_M Δu = h r_M the step's
 * part without contact (linear in Δu: its residual is W_M Δu_it - h r_M). Converged it is the
 * same step (R = 0); only the iterates' path differs. Then ρ as in the full pass, Z kept. */
int csr_strainCondenseKept_(const csrStrainModel* m, csrStrainData* d, double h,
                            const double* du, const double fb[6], double Z[36], double rho[6]) {
  const int n = m->n;
  if (d->art_f || d->wb_f) {
    return condenseKeptArtic(m, d, h, du, fb, Z, rho);
  }
  const double* dV = du;
  const double* de = du + 6;
  double rb[6];
  if (!d->wm_step) {
    /* the factor is an earlier step's and this step's W_M was not assembled (Kept matrix):
     * W_f Δu_it - R with the residual R = W_M Δu_it - h (r_M + f) formed from its parts,
     * W_M Δu = M(q0) Δu (matrix-free at the start's kinematics) + (h τ_d + h²) K Δη, whatever
     * W_f is (where W_M is assembled, below, the same sums from its matrix) */
    const double tau = m->rpar.damping_time;
    int zero = 1;
    for (int k = 0; k < 6 + n && zero; k++) {
      zero = du[k] == 0;
    }
    if (zero) {
      memset(d->Mu, 0, (size_t)(6 + n) * sizeof(double)); /* a kept step's first pass */
    } else {
      csr_strainInertiaApply_(m, d->R0, d->x0, d->J0, du, d->Mu);
    }
    for (int j = 0; j < n; j++) {
      const double* wu = d->Wu + (size_t)j * n;
      double t = h * (d->rMl[j] + d->fl[j]) - d->Mu[6 + j] - (h * tau + h * h) * d->Kd[j] * de[j];
      for (int k = 0; k < n; k++) {
        t += wu[k] * de[k];
      }
      for (int c = 0; c < 6; c++) {
        t += d->Wlb[6 * j + c] * dV[c];
      }
      d->y[j] = t;
    }
    for (int a = 0; a < 6; a++) {
      double t = h * (d->rMb[a] + fb[a]) - d->Mu[a];
      for (int c = 0; c < 6; c++) {
        t += d->Wbbp[6 * a + c] * dV[c];
      }
      for (int j = 0; j < n; j++) {
        t += d->Wbl[n * a + j] * de[j];
      }
      rb[a] = t / h;
    }
  } else {
    /* this step's W_M assembled: W_f - W_M from its matrix (W_f this step's or an earlier's) */
    for (int j = 0; j < n; j++) {
      const double* wu = d->Wu + (size_t)j * n;
      const double* wm = d->WMll + (size_t)j * n;
      double t = h * (d->rMl[j] + d->fl[j]);
      for (int k = 0; k < n; k++) {
        t += (wu[k] - wm[k]) * de[k];
      }
      for (int c = 0; c < 6; c++) {
        t += (d->Wlb[6 * j + c] - d->WMlb[6 * j + c]) * dV[c];
      }
      d->y[j] = t;
    }
    for (int a = 0; a < 6; a++) {
      double t = h * (d->rMb[a] + fb[a]);
      for (int c = 0; c < 6; c++) {
        t += (d->Wbbp[6 * a + c] - d->WMbb[6 * a + c]) * dV[c];
      }
      for (int j = 0; j < n; j++) {
        t += (d->Wbl[n * a + j] - d->WMlb[6 * j + a]) * de[j];
      }
      rb[a] = t / h;
    }
  }
  momentumRows(m, d, h, du, d->Wbbp, rb);
  for (int j = 0; j < n; j++) {
    if (!isfinite(d->y[j])) {
      return 1;
    }
  }
  if (d->chol) {
    csr_strainCholSolve_(d->Wll, n, d->y);
  } else {
    csr_strainLuSolve_(d->Wll, n, d->piv, d->y);
  }
  for (int a = 0; a < 6; a++) {
    double t = 0;
    for (int j = 0; j < n; j++) {
      t += d->Wbl[n * a + j] * d->y[j];
    }
    rho[a] = h * rb[a] - t;
    if (!isfinite(rho[a])) {
      return 1;
    }
  }
  memcpy(Z, d->Zp, sizeof d->Zp);
  memcpy(d->rhop, rho, sizeof d->rhop);
  return 0;
}


/* the step's start kinematics (at q0, with J at every point) into d->R0, x0, J0, the current
 * kinematics (d->R, x, J, kin_valid) kept */
static void startKinematics(const csrStrainModel* m, csrStrainData* d) {
  const int n = m->n, valid = d->kin_valid, chain = d->kin_chain, midown = d->kin_midown;
  double* t;
  t = d->R, d->R = d->R0, d->R0 = t;
  t = d->x, d->x = d->x0, d->x0 = t;
  t = d->J, d->J = d->J0, d->J0 = t;
  memcpy(d->q_save, d->q, (size_t)n * sizeof(double));
  memcpy(d->q, d->q0, (size_t)n * sizeof(double));
  csr_strainKinematics_(m, d, 1);
  memcpy(d->q, d->q_save, (size_t)n * sizeof(double));
  t = d->R, d->R = d->R0, d->R0 = t;
  t = d->x, d->x = d->x0, d->x0 = t;
  t = d->J, d->J = d->J0, d->J0 = t;
  d->kin_valid = valid;
  d->kin_chain = chain;
  d->kin_midown = midown;
}


/* W_M of the step (d->WM*, wm_step) at the kinematics R, x, J: the inertia and the strains'
 * (h τ_d + h²) K on W_ll's diagonal */
static void wmFrom(const csrStrainModel* m, csrStrainData* d, double h, const double* R,
                   const double* x, const double* J) {
  const int n = m->n;
  const double tau = m->rpar.damping_time;
  csr_strainInertiaFrom_(m, d, R, x, J);
  for (int j = 0; j < n; j++) {
    d->WMll[j * n + j] += (h * tau + h * h) * d->Kd[j];
  }
  d->wm_step = 1;
}


/* The dense W_ll, W_lb, W_bl, W_bb, r_l, r_b of the step's start: W_M (assembled here, at the
 * start's kinematics, if the prepare left it out) plus the contact's part, which
 * condenseStart linearised into zeroed blocks (cW*: d->Wll, d->Wlb, d->Wbl, Wbb, rb, d->rl
 * hold the contact's alone). Added entry by entry: the bits of adding the contact into W_M
 * directly while one shape touches (its terms enter each entry once). */
static void denseStart(const csrStrainModel* m, csrStrainData* d, double h, double Wbb[36],
                       double rb[6]) {
  const int n = m->n;
  if (!d->wm_step) {
    wmFrom(m, d, h, d->R, d->x, d->J);
  }
  for (size_t i = 0; i < (size_t)n * n; i++) {
    d->Wll[i] = d->WMll[i] + d->Wll[i];
  }
  for (int j = 0; j < n; j++) {
    for (int c = 0; c < 6; c++) {
      d->Wlb[6 * j + c] = d->WMlb[6 * j + c] + d->Wlb[6 * j + c];
      d->Wbl[n * c + j] = d->WMlb[6 * j + c] + d->Wbl[n * c + j];
    }
    d->rl[j] = d->rMl[j] + d->rl[j];
  }
  for (int i = 0; i < 36; i++) {
    Wbb[i] = d->WMbb[i] + Wbb[i];
  }
  for (int c = 0; c < 6; c++) {
    rb[c] = d->rMb[c] + rb[c];
  }
}


static int factorAndCondense(const csrStrainModel* m, csrStrainData* d, double h,
                             const double* du, double Wbb[36], double rb[6], double Z[36],
                             double rho[6]);


void csr_strainClearStart_(const csrStrainModel* m, csrStrainData* d) {
  if (!d->wl_pending) {
    return;
  }
  const int n = m->n;
  if (!d->wc_sparse) {
    memset(d->Wll, 0, (size_t)n * n * sizeof(double));
  }
  memset(d->Wlb, 0, (size_t)n * 6 * sizeof(double));
  memset(d->Wbl, 0, (size_t)n * 6 * sizeof(double));
  memset(d->rl, 0, (size_t)n * sizeof(double));
  d->wl_pending = 0;
}


/* the recursion's factor of a leg without contact (condenseStart: a step's start or BDF2's
 * iterate): W's blocks W_M's (W_lb and W_bl from the recursion's W_lb), h r's r_M's; 1 if r_l
 * is not finite */
static int plainFactored(const csrStrainModel* m, csrStrainData* d) {
  const int n = m->n;
  d->wl_pending = 0;
  d->lu_plain = 1;
  d->kf = 0;
  memcpy(d->Wlb, d->WMlb, (size_t)n * 6 * sizeof(double));
  for (int j = 0; j < n; j++) {
    for (int c = 0; c < 6; c++) {
      d->Wbl[n * c + j] = d->WMlb[6 * j + c];
    }
  }
  memcpy(d->rl, d->rMl, (size_t)n * sizeof(double));
  for (int j = 0; j < n; j++) {
    if (!isfinite(d->rl[j])) {
      return 1;
    }
  }
  return 0;
}


/* the current kinematics kept in d->R0, x0, J0 (k0) for a later pass that forms W_M there:
 * the arrays swapped, not copied; the iterates form their own (kin_valid 0). W_M's composite
 * inertias (csr_strainInertiaFrom_) read the chain points' Jacobians and the midpoints' own
 * columns alone, which backward Euler's start on want_J 4 has too */
static void keepKinematics(csrStrainData* d) {
  double* t;
  t = d->R, d->R = d->R0, d->R0 = t;
  t = d->x, d->x = d->x0, d->x0 = t;
  t = d->J, d->J = d->J0, d->J0 = t;
  d->kin_valid = 0;
  d->kin_gen++;
  d->k0 = 1;
}


/* the recursion's start done (no Cholesky factor of W_ll: its pieces' are the recursion's):
 * counted, Z and ρ kept for the step's iterates */
static int keepFactored(csrStrainData* d, const double Z[36], const double rho[6]) {
  d->chol = 0;
  d->nfactor++;
  memcpy(d->Zp, Z, sizeof d->Zp);
  memcpy(d->rhop, rho, sizeof d->rhop);
  d->w_step = 1;
  return 0;
}


/* A touching leg's start by the recursion (artic 2): the contact's blocks without W_ll's
 * (Wbb, d->Wlb, d->Wbl, rb, d->rl: the contact's alone) and its shapes' S, A (d->cS, cA);
 * W_M's and the contact's parts condensed piece by piece, W_f's base blocks (the momentum
 * rows and the kept iterates read them) as denseStart adds them. A recursion that fails
 * (a shape across pieces, a singular piece block) takes the dense path with W_ll's contact
 * block formed from the kept shapes (the same entries as the assembly's). */
static int condenseStance(const csrStrainModel* m, csrStrainData* d, double h, const double* du,
                          double Wbb[36], double rb[6], double Z[36], double rho[6]) {
  const int n = m->n, nu = 6 + n;
  double rbt[6];
  for (int c = 0; c < 6; c++) {
    rbt[c] = d->rMb[c] + rb[c];
  }
  for (int j = 0; j < n; j++) {
    d->fl[j] = d->rMl[j] + d->rl[j]; /* fl: scratch until the iterates' loads */
  }
  if (csr_strainCondenseArtic_(m, d, h, d->fl, rbt, Z, rho) != 0) {
    memset(d->Wll, 0, (size_t)n * n * sizeof(double));
    for (int c = 0; c < d->nct; c++) {
      csr_strainShapeW_(m, d, h, d->cS + (size_t)c * 6 * nu, d->cA + 36 * c, d->Gs,
                        d->Gs + 6 * nu, Wbb, 2);
    }
    denseStart(m, d, h, Wbb, rb);
    return factorAndCondense(m, d, h, du, Wbb, rb, Z, rho);
  }
  memcpy(d->rl, d->fl, (size_t)n * sizeof(double));
  for (int j = 0; j < n; j++) {
    for (int c = 0; c < 6; c++) {
      d->Wlb[6 * j + c] = d->WMlb[6 * j + c] + d->Wlb[6 * j + c];
      d->Wbl[n * c + j] = d->WMlb[6 * j + c] + d->Wbl[n * c + j];
    }
    if (!isfinite(d->rl[j])) {
      return 1;
    }
  }
  for (int i = 0; i < 36; i++) {
    d->Wbbp[i] = d->WMbb[i] + Wbb[i];
  }
  if (du) {
    /* BDF2's iterate: the momentum rows replace h r_b's rows 3-5 (factorAndCondense's); ρ is
     * linear in r_b, ρ = h r_b - W_bl W_ll⁻¹ h r_l: the change h (r_b' - r_b) added. Z, ρ in
     * the hip's coordinates at the iterate */
    double rbm[6];
    memcpy(rbm, rbt, sizeof rbm);
    momentumRows(m, d, h, du, d->Wbbp, rbm);
    for (int c = 3; c < 6; c++) {
      rho[c] += h * (rbm[c] - rbt[c]);
      if (!isfinite(rho[c])) {
        return 1;
      }
    }
    memcpy(d->Rbp, d->Rb, sizeof d->Rbp);
  }
  d->lu_plain = 0;
  d->kf = 0;
  d->art_f = 1;
  /* the start's kinematics kept for an iterate that refactors (it forms W_M from them): the
   * arrays swapped, not copied; the iterates form their own (kin_valid 0) */
  keepKinematics(d);
  return keepFactored(d, Z, rho);
}


/* A backward-Euler step's start (csr_strainArticStep_, du NULL): the contact linearised first (into
 * zeroed blocks); a leg that touches nothing is condensed by the recursion
 * (robot_strain_artic.c, no n x n matrix), one that touches by the dense factor of W_M plus the
 * contact's part, or with artic 2 by the recursion with the contact's blocks (condenseStance;
 * an iterate that must refactor forms W_M then: condense).
 * A BDF2 pass assembled at its iterate Δu_it = du without W_M (art_pass): W is M(q_it) +
 * (h τ_d + h²) [0 0; 0 K] at the iterate's kinematics with h = c2 h_step, the form backward
 * Euler's start has at q0, so the recursion condenses it the same way, r_M holding the
 * history's M (ū - u0) / h (assemble); the contact linearised at the iterate; a leg that
 * touches takes the dense path (W_M at the iterate's kinematics, the momentum rows). */
static int condenseStart(const csrStrainModel* m, csrStrainData* d, double h, const double* du,
                         double Z[36], double rho[6]) {
  double Wbb[36], rb[6];
  memset(Wbb, 0, sizeof Wbb);
  memset(rb, 0, sizeof rb);
  /* d->Wll, Wlb, Wbl, rl are zeroed where they are first written or read (wl_pending): at
   * the first shape that touches (csr_strainContactAssemble_), else before the dense path
   * here; the recursion reads none of them (a swing leg's start skips the n x n clear) */
  d->wl_pending = 1;
  d->ntouch = 0;
  d->nct = 0;
  d->art_f = 0;
  d->wb_f = 0;
  d->k0 = 0;
  const int stance = m->par.artic == 2 && !d->wm_step;
  d->wc_sparse = stance;
  if (m->soft) {
    int rc = csr_strainContactAssemble_(m, d, h, du, Wbb, rb, d->Gs);
    if (rc != 0) {
      d->wl_pending = 0; /* the blocks are not read: the next condense writes them whole */
      d->wc_sparse = 0;
      return rc > 0 ? rc : 1;
    }
  }
  d->wc_sparse = 0;
  if (d->ntouch > 0 && stance) {
    return condenseStance(m, d, h, du, Wbb, rb, Z, rho);
  }
  if (d->ntouch > 0 || d->wm_step || csr_strainCondenseArtic_(m, d, h, d->rMl, d->rMb, Z, rho)) {
    /* the dense path (a touching leg, W_M formed, or a piece's block not positive definite:
     * its LU decides): W_M added to the contact's blocks, zero if no shape touched */
    csr_strainClearStart_(m, d);
    denseStart(m, d, h, Wbb, rb);
    return factorAndCondense(m, d, h, du, Wbb, rb, Z, rho);
  }
  if (plainFactored(m, d) != 0) {
    return 1;
  }
  keepFactored(d, Z, rho);
  if (!du) {
    return 0;
  }
  /* BDF2's iterate: ρ with the iterate's momentum rows, ρ = h r_b - W_bl y as
   * factorAndCondense's (the recursion's y = W_ll⁻¹ h r_l), Z, ρ in the hip's coordinates at
   * the iterate; its kinematics kept for a later iterate that refactors (step_refresh 0) */
  memcpy(d->Rbp, d->Rb, sizeof d->Rbp);
  const int rc = csr_strainCondensePlain_(m, d, h, du, Z, rho);
  keepKinematics(d);
  return rc;
}


/* W_M's blocks but W_ll's and h r's into the iterate's (Wbb, rb, d->Wlb, d->Wbl, d->rl), for
 * the contact's assembly to add its part to; no shape touching yet */
static void wmBlocks(const csrStrainModel* m, csrStrainData* d, double Wbb[36], double rb[6]) {
  const int n = m->n;
  memcpy(Wbb, d->WMbb, 36 * sizeof(double));
  memcpy(rb, d->rMb, 6 * sizeof(double));
  memcpy(d->Wlb, d->WMlb, (size_t)n * 6 * sizeof(double));
  memcpy(d->rl, d->rMl, (size_t)n * sizeof(double));
  for (int j = 0; j < n; j++) {
    for (int c = 0; c < 6; c++) {
      d->Wbl[n * c + j] = d->Wlb[6 * j + c];
    }
  }
  d->ntouch = 0;
}


/* An iterate that refactors after a stance start by the recursion (art_f) or after such a
 * refactor (wb_f): W = W_M(q0) plus the iterate's contact by the Woodbury update of the
 * start's pieces' factors (robot_strain_woodbury.c): no W_M, no n x n block or LU. The
 * contact's assembly forms the iterate's S, A (wS, wA), W's base rows and columns and h r
 * (wc_sparse 2); a singular update takes the dense path (W_M at the start's kinematics, k0,
 * W_ll's contact block from the kept shapes, as condenseStance's fallback).
 * The linearly implicit BDF2 (step_refresh 0) the same way: its W_M is the last assembled
 * iterate's (the prepare's extrapolated one, or a refreshed iterate's), M(q_it) +
 * (h τ_d + h²) [0 0; 0 K] with h = c2 h_step (the he condense is given), whose kinematics the
 * recursion kept in d->R0, x0, J0 (keepKinematics) and whose pieces it factored with the
 * contact's -h Sᵀ A S linearised there at the same h: W_f and W differ by the contact's parts
 * alone, as backward Euler's (docs/notes/strain_leg.md, bdf15). Z, ρ then in the hip's
 * coordinates at this iterate (d->Rbp), as factorAndCondense's. */
static int condenseUpdate(const csrStrainModel* m, csrStrainData* d, double h, const double* du,
                          double Z[36], double rho[6]) {
  const int n = m->n, nu = 6 + n;
  double Wbb[36], rb[6], rbm[6];
  wmBlocks(m, d, Wbb, rb);
  d->nwt = 0;
  if (m->soft) {
    /* W_bl gains the contact's own rows (not W_lb's transpose with friction) */
    d->wc_sparse = 2;
    const int rc = csr_strainContactAssemble_(m, d, h, du, Wbb, rb, d->Gs);
    d->wc_sparse = 0;
    if (rc != 0) {
      return rc > 0 ? rc : 1;
    }
  }
  for (int j = 0; j < n; j++) {
    if (!isfinite(d->rl[j])) {
      return 1;
    }
  }
  memcpy(rbm, rb, sizeof rbm);
  momentumRows(m, d, h, du, Wbb, rbm);
  if (csr_strainCondenseWoodbury_(m, d, h, Wbb, rbm, Z, rho) == 0) {
    d->lu_plain = d->ntouch == 0;
    d->art_f = 0;
    d->wb_f = 1;
    d->kf = 0;
    d->chol = 0;
    d->nfactor++;
    memcpy(d->Wbbp, Wbb, sizeof d->Wbbp);
    memcpy(d->Zp, Z, sizeof d->Zp);
    memcpy(d->rhop, rho, sizeof d->rhop);
    if (m->par.step_order == 2) {
      memcpy(d->Rbp, d->Rb, sizeof d->Rbp);
    }
    d->w_step = 1;
    return 0;
  }
  /* the dense path: W_M at the start's kinematics, W_ll's contact block from the iterate's
   * shapes (the assembly's own entries) */
  if (!d->wm_step) {
    wmFrom(m, d, h, d->R0, d->x0, d->J0);
  }
  memcpy(d->Wll, d->WMll, (size_t)n * n * sizeof(double));
  for (int c = 0; c < d->nwt; c++) {
    csr_strainShapeW_(m, d, h, d->wS + (size_t)c * 6 * nu, d->wA + 36 * c, d->Gs,
                      d->Gs + 6 * nu, Wbb, 2);
  }
  return factorAndCondense(m, d, h, du, Wbb, rb, Z, rho);
}


/* W = W_M + the contact's linearisation at the current kinematics and point twists (du NULL:
 * the step's start, predicted; else the iterate Δu = du), factored and condensed: Z, ρ.
 * An iterate keeps the last iteration matrix (csr_strainCondenseKept_) while every contact
 * slot is in the state (touching, past the friction's saturation) it was linearised in and the
 * leg's moves shrink: a new linearisation costs the contact's 12 law evaluations per touching
 * shape, its assembly and an LU of W_ll; a kept one, the law once per shape and one solve
 * (docs/notes/strain_leg.md, Cost). */
int csr_strainCondense_(const csrStrainModel* m, csrStrainData* d, double h, const double* du,
                        double Z[36], double rho[6]) {
  const int n = m->n;
  double Wbb[36], rb[6];
  /* BDF2 with step_refresh assembles the whole residual at every iterate: nothing is kept.
   * Backward Euler and the linearly implicit BDF2 (step_refresh 0) keep W_M and r_M over the
   * step's iterates (the linear model of everything but the contact), the latter once its
   * prepare has condensed at the first iterate (w_step) */
  const int full = csr_strainBdfFull_(m);
  if (du && !full && (m->par.step_order == 1 || d->w_step)) {
    double fb[6] = {0, 0, 0, 0, 0, 0};
    int same = 1;
    memset(d->fl, 0, (size_t)n * sizeof(double));
    int rc = csr_strainContactLoads_(m, d, fb, d->fl, &same);
    if (rc != 0) {
      return rc > 0 ? rc : 1;
    }
    if (d->lu_plain && d->ntouch == 0 && !d->w_lag) {
      return csr_strainCondensePlain_(m, d, h, du, Z, rho);
    }
    /* keep W while the slots keep their state and the leg's move shrank at least 4x over the
     * last kept iterate (a chord iteration contracting slower than that costs more passes
     * than the new linearisation saves); a factor without contact is this step's exact W_M
     * (condensePlain above) unless it is an earlier step's */
    int shrinks = d->nreuse == 0 || d->chg_last <= 0.25 * d->chg_prev;
    if (d->lu_plain && d->w_lag && d->ntouch == 0) {
      shrinks = 1; /* as in iterateAt: a kept factor without contact at an iterate without */
    }
    if ((!d->lu_plain || d->w_lag) && same && shrinks && !d->fresh) {
      d->nreuse++;
      return csr_strainCondenseKept_(m, d, h, du, fb, Z, rho);
    }
    if (!csr_strainChainJ_(d)) {
      /* the loads were formed without the chain points' Jacobians (iterateAt's try at a
       * kept matrix); the new linearisation reads them */
      return CSR_STRAIN_NEED_J;
    }
  }
  d->nreuse = 0;
  d->fresh = 0;
  if ((!du && csr_strainArticStep_(m)) || (du && d->art_pass)) {
    d->art_pass = 0;
    return condenseStart(m, d, h, du, Z, rho);
  }
  if (du && (d->art_f || d->wb_f)) {
    return condenseUpdate(m, d, h, du, Z, rho);
  }
  if (!d->wm_step) {
    /* a step that kept an earlier factor (keep_matrix), or whose start was condensed by the
     * recursion (artic), refactors: W_M at the start's kinematics, as the dense prepare would
     * have assembled it. keep_matrix keeps them (d->R0, x0, J0), and so does a touching
     * leg's recursion (condenseStance swapped them there: k0); after a swing leg's they are
     * formed again at q0 into those arrays (a function of q alone: the same bits), the
     * iterate's kinematics left in place */
    if (!m->par.keep_matrix && !d->k0) {
      startKinematics(m, d);
    }
    wmFrom(m, d, h, d->R0, d->x0, d->J0);
  }
  memcpy(d->Wll, d->WMll, (size_t)n * n * sizeof(double));
  wmBlocks(m, d, Wbb, rb);
  if (m->soft) {
    int rc = csr_strainContactAssemble_(m, d, h, du, Wbb, rb, d->Gs);
    if (rc != 0) {
      return rc > 0 ? rc : 1;
    }
  }
  return factorAndCondense(m, d, h, du, Wbb, rb, Z, rho);
}


/* condense's dense part: W's blocks (d->Wll, d->Wlb, d->Wbl, Wbb) and h r (d->rl, rb) with the
 * contact's linearisation in them, factored and condensed onto the base: Z, ρ */
static int factorAndCondense(const csrStrainModel* m, csrStrainData* d, double h,
                             const double* du, double Wbb[36], double rb[6], double Z[36],
                             double rho[6]) {
  const int n = m->n;
  d->lu_plain = d->ntouch == 0;
  d->art_f = 0;
  d->wb_f = 0;
  if (du) {
    momentumRows(m, d, h, du, Wbb, rb);
  }
  for (int j = 0; j < n; j++) {
    if (!isfinite(d->rl[j])) {
      return 1;
    }
  }
  if (!d->lu_plain || m->par.keep_matrix) {
    memcpy(d->Wu, d->Wll, (size_t)n * n * sizeof(double));
    memcpy(d->Wbbp, Wbb, 36 * sizeof(double));
  }
  d->kf = 0;
  /* W_ll without contact is W_M's, symmetric positive definite (mass plus stiffness): its
   * Cholesky factor, half the LU's work (this factor is used here alone: a later iterate
   * without contact keeps X and y, one with contact linearises afresh); with the contact's
   * friction W_ll is unsymmetric: LU. A Cholesky that meets a pivot <= 0 falls back to the
   * LU. */
  int chol = 0;
  if (d->lu_plain) {
    chol = csr_strainCholFactor_(d->Wll, n) == 0;
    if (!chol) {
      /* W_ll was W_M's alone */
      memcpy(d->Wll, d->WMll, (size_t)n * n * sizeof(double));
    }
  }
  if (!chol && csr_strainLuFactor_(d->Wll, n, d->piv)) {
    return 1;
  }
  d->chol = chol;
  d->nfactor++;
  if (m->par.keep_matrix) {
    /* this factor may serve the next steps (csr_strainPrepare, Kept matrix) */
    d->kf = 1;
    d->kf_h = h;
    d->w_lag = 0;
    memcpy(d->qf, d->q, (size_t)n * sizeof(double));
  }
  /* X = W_ll⁻¹ W_lb (its 6 columns at once), y = W_ll⁻¹ h r_l */
  memcpy(d->X, d->Wlb, (size_t)n * 6 * sizeof(double));
  for (int j = 0; j < n; j++) {
    d->y[j] = h * d->rl[j];
  }
  if (chol) {
    csr_strainCholSolve6_(d->Wll, n, d->X);
    csr_strainCholSolve_(d->Wll, n, d->y);
  } else {
    csr_strainLuSolveMulti_(d->Wll, n, d->piv, d->X, 6);
    csr_strainLuSolve_(d->Wll, n, d->piv, d->y);
  }
  /* Z = W_bb - W_bl X, ρ = h r_b - W_bl y */
  for (int a = 0; a < 6; a++) {
    for (int c = 0; c < 6; c++) {
      double t = 0;
      for (int j = 0; j < n; j++) {
        t += d->Wbl[n * a + j] * d->X[6 * j + c];
      }
      Z[6 * a + c] = Wbb[6 * a + c] - t;
    }
    double t = 0;
    for (int j = 0; j < n; j++) {
      t += d->Wbl[n * a + j] * d->y[j];
    }
    rho[a] = h * rb[a] - t;
  }
  memcpy(d->Zp, Z, sizeof d->Zp);
  memcpy(d->rhop, rho, sizeof d->rhop);
  if (m->par.step_order == 2) {
    /* Z, ρ are in the hip's body coordinates at the iterate */
    memcpy(d->Rbp, d->Rb, sizeof d->Rbp);
  }
  d->w_step = 1;
  for (int a = 0; a < 6; a++) {
    if (!isfinite(rho[a])) {
      return 1;
    }
  }
  return 0;
}

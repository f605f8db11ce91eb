/* robot_rod_linsol.c: CVODE's linear system for the rod's BDF step, reduced to the velocity
 * unknowns and solved with the block-tridiagonal kernel of robot_rod_bt.c.
 *
 * ---- Why not CVODE's band solver (measured) -------------------------------------------------
 * With SUNBandMatrix + SUNLinSol_Band over the whole state (13 per element, half bandwidth 25)
 * the band LU and its solves took 82 % of a leg's run time (bench_rod gait, 4 elements per
 * segment: 80 ms per simulated second, SUNDlsMat_bandGBTRF 52 %, GBTRS 20 %, the force kernel
 * 2 %); CVODE refactors at every larger change of γ (170 times per simulated second against 12
 * Jacobians). This file keeps CVODE's Newton iteration, error control and Jacobian-reuse logic
 * (a user linear-system function, CVodeSetLinSysFn) and solves its systems (I - γJ) δ = b by
 * eliminating the position-level unknowns, which the implicit step ties to the velocities:
 *   δx_j = b_x + γ δv_j,   δq_j = (I - γΩ_j)⁻¹ (b_q + γ G_j δω_j)   (q̇ = Ω q = G ω, Ω the
 *   skew 4 x 4 right multiplication by ½(0, ω), Ω² = -|ω|²/4 I, so (I - γΩ)⁻¹ =
 *   (I + γΩ)/(1 + γ²|ω|²/4)); the forces see δq through the body rotation increment
 *   δψ_j = Π_j δq_j = Π_j (I - γΩ_j)⁻¹ b_q + γ W_j δω_j, W = (I - γ/2 [ω]×)/(1 + γ²|ω|²/4)
 *   (an earlier Ω ≈ 0 cost 8e-4 relative at γ|ω| = 1e-3: test_rod_linsol),
 *   δh_m = (I - γ ∂ḣ_m/∂h_m)⁻¹ (b_h + γ (∂ḣ_m/∂x δx + ∂ḣ_m/∂ψ δψ + ∂ḣ_m/∂u δu))  (contact
 *   history, exact),
 * leaving the Schur complement on u = (v, ω): block tridiagonal with 6 x 6 blocks (element i
 * couples to i±1), S = I - γ ∂u̇/∂u - γ² ∂u̇/∂(x, ψ) - γ ∂u̇/∂h Z. It is factored by block LU
 * (Thomas algorithm, pivoted inverses of the diagonal blocks; S ≈ M⁻¹(M + γC + γ²K) is
 * block-diagonally dominated like a mass-damping-stiffness matrix, which block LU factors
 * stably). The base impulse rows take δI = b_I (they feed nothing back; their error weight is
 * zero). Result on the same gait leg: 80 -> 9 ms per simulated second (the force kernel is now
 * the largest single item with CVODE's own vector norms).
 *
 * ---- Jacobian ------------------------------------------------------------------------------
 * The blocks ∂(u̇, ḣ)/∂(x, ψ, v, ω, h) are kept until CVODE asks for a new Jacobian, in two
 * parts: the internal forces and gravity by column-grouped forward differences of the
 * right-hand side without the contact hook (3 groups x 12 evaluations), the contact by
 * differences of each element's hook alone (a few calls per touching element, its history
 * columns otherwise). Contact is what changes abruptly (touch-down, lift-off, stick-slip) and
 * makes CVODE ask; the internal part is refreshed only every CSR_ROD_JAC_INT_STEPS steps or
 * when a contact-only refresh did not let the step converge. An element's history that does
 * not couple to the motion (out of contact) is solved on its own, which with most capsules in
 * the air halved the solve (road bench, 8 legs: 8.4 -> 9.8 x real time). Each new γ only
 * re-assembles and re-factors S (O(N)). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "robot_rod_internal.h"

/* relative forward-difference step (≈ √eps) and the per-kind scales it multiplies:
 * positions by max(|x|, L), rotations by 1 rad, velocities by max(|v|, L / 0.02 s), angular
 * velocities by max(|ω|, 1 / 0.02 s), history by max(|h|, 1e4 atol_hist) */
#define CSR_ROD_JAC_REL 1.5e-8
#define CSR_ROD_JAC_TIME 0.02
/* steps between refreshes of the Jacobian's internal part: measured neutral between 0 and 20
 * on the road bench (8.0-8.2 x real time) while cutting the right-hand sides by 25 % */
#define CSR_ROD_JAC_INT_STEPS 5

/* ---- the CVODE linear system --------------------------------------------------------------- */

/* Jacobian block of row element i (1..N), column element i - 1 + k (k = 0..2): (6 + nhmax)
 * rows (v̇ 3, ω̇ 3, ḣ nh_i) x (12 + nhmax) columns (x 3, ψ 3, v 3, ω 3, h nh_j), row-major;
 * rows and columns past an element's own history count stay zero */
static double* jblockIn(const csrRodModel* m, double* base, int i, int k) {
  const int nr = 6 + m->nhmax, nc = 12 + m->nhmax;
  return base + ((size_t)(i - 1) * 3 + (size_t)k) * (size_t)(nr * nc);
}


static double* jblock(const csrRodModel* m, const csrRodData* d, int i, int k) {
  return jblockIn(m, d->jac, i, k);
}


/* doubles in one set of Jacobian blocks */
static size_t jacSize(const csrRodModel* m) {
  return 3 * (size_t)m->N * (size_t)(6 + m->nhmax) * (size_t)(12 + m->nhmax);
}


/* perturb column c (0..11 + nh) of element block b by h */
static void perturb(double* b, int c, double h) {
  if (c < 3) {
    b[CSR_ROD_BX + c] += h;
  } else if (c < 6) {
    double phi[3] = {0, 0, 0}, dq[4], q[4];
    phi[c - 3] = h;
    csr_rodQexp(dq, phi);
    csr_rodQmul(q, b + CSR_ROD_BQ, dq);
    memcpy(b + CSR_ROD_BQ, q, sizeof q);
  } else if (c < 12) {
    b[CSR_ROD_BV + c - 6] += h;
  } else {
    b[CSR_ROD_BH + c - 12] += h;
  }
}


/* the difference step of column c of element block b */
static double stepOf(const csrRodModel* m, const double* b, int c) {
  double v, scale;
  if (c < 3) {
    v = b[CSR_ROD_BX + c];
    scale = m->L;
  } else if (c < 6) {
    v = 0;
    scale = 1;
  } else if (c < 9) {
    v = b[CSR_ROD_BV + c - 6];
    scale = m->L / CSR_ROD_JAC_TIME;
  } else if (c < 12) {
    v = b[CSR_ROD_BW + c - 9];
    scale = 1 / CSR_ROD_JAC_TIME;
  } else {
    v = b[CSR_ROD_BH + c - 12];
    scale = 1e4 * m->par.atol_hist;
  }
  return CSR_ROD_JAC_REL * fmax(fabs(v), scale);
}


/* accelerations (v̇, ω̇, ḣ) of element i from a right-hand-side vector */
static const double* accelOf(const csrRodModel* m, const double* f, int i) {
  return f + CSR_ROD_NIMP + m->boff[i] + CSR_ROD_BV;
}


/* The internal part of the Jacobian blocks at (t, y): column-grouped forward differences of the
 * right-hand side without the contact hook (3 x 12 evaluations; internal forces do not depend
 * on the contact history, and without the hook nothing moves it) into d->jac_int. ftmp0 and
 * ftmp are scratch. 0 ok, else the right-hand side's code. */
static int internalJacobian(const csrRodModel* m, csrRodData* d, double t, N_Vector y,
                            N_Vector ytmp, N_Vector ftmp0, N_Vector ftmp) {
  const int N = m->N, nc = 12 + m->nhmax;
  const double* Y = N_VGetArrayPointer(y);
  const double* F0 = N_VGetArrayPointer(ftmp0);
  double* Yp = N_VGetArrayPointer(ytmp);
  const double* F1 = N_VGetArrayPointer(ftmp);
  const size_t ny = CSR_ROD_NIMP + (size_t)m->nstate;
  memset(d->jac_int, 0, jacSize(m) * sizeof(double));
  d->no_contact = 1;
  int rc = csr_rodRhs_(t, y, ftmp0, d);
  d->stats.rhs_evals++;
  for (int g = 0; g < 3 && rc == 0; g++) {
    for (int c = 0; c < 12 && rc == 0; c++) {
      memcpy(Yp, Y, ny * sizeof(double));
      for (int j = 1 + g; j <= N; j += 3) {
        double* b = Yp + CSR_ROD_NIMP + m->boff[j];
        perturb(b, c, stepOf(m, b, c));
      }
      rc = csr_rodRhs_(t, ytmp, ftmp, d);
      d->stats.rhs_evals++;
      for (int j = 1 + g; j <= N && rc == 0; j += 3) {
        const size_t o = CSR_ROD_NIMP + (size_t)m->boff[j];
        /* the step actually taken: the round-off of y + h for the additive columns; the
         * rotation columns are exact (multiplicative) */
        const int slot = c < 3 ? CSR_ROD_BX + c : CSR_ROD_BV + c - 6;
        double h = (c >= 3 && c < 6) ? stepOf(m, Y + o, c) : Yp[o + slot] - Y[o + slot];
        for (int i = j - 1; i <= j + 1; i++) {
          if (i < 1 || i > N) {
            continue;
          }
          double* J = jblockIn(m, d->jac_int, i, j - i + 1);
          const double* a0 = accelOf(m, F0, i);
          const double* a1 = accelOf(m, F1, i);
          for (int r = 0; r < 6; r++) {
            J[nc * r + c] = (a1[r] - a0[r]) / h;
          }
        }
      }
    }
  }
  d->no_contact = 0;
  return rc;
}


/* The contact part at (t, y): each element's hook differenced in the columns it depends on (node
 * e-1's position and velocity, element e's whole block) when it touches, in its history
 * columns only when it does not (the history still relaxes there), into d->jac_con. A few
 * hook calls per element instead of whole right-hand sides. */
static int contactJacobian(const csrRodModel* m, csrRodData* d, double t, N_Vector y) {
  const int N = m->N, nc = 12 + m->nhmax;
  memset(d->jac_con, 0, jacSize(m) * sizeof(double));
  if (!m->contact.eval) {
    return 0;
  }
  const double* Ys = N_VGetArrayPointer(y) + CSR_ROD_NIMP;
  double* Yc = d->con_y;
  memcpy(Yc, Ys, (size_t)m->nstate * sizeof(double));
  double x0[3], v0[3];
  csr_rodBaseAt_(d, t, x0, v0);
  double a0[9 + CSR_ROD_MAX_HIST], a1[9 + CSR_ROD_MAX_HIST];
  for (int e = 1; e <= N; e++) {
    int active = 0, dummy = 0;
    int rc = csr_rodContactAccel_(m, Ys, e, x0, v0, a0, &active);
    if (rc != 0) {
      return rc;
    }
    const int nh = m->nh[e], nout = 9 + nh;
    for (int side = 0; side < 2; side++) {
      const int j = e - 1 + side; /* column element: e-1 (its node), then e */
      if (j < 1 || (!active && side == 0)) {
        continue;
      }
      for (int c = 0; c < 12 + m->nh[j]; c++) {
        /* node e-1 enters through its position and velocity only; inactive: history only */
        if (side == 0 && !((c < 3) || (c >= 6 && c < 9))) {
          continue;
        }
        if (side == 1 && !active && c < 12) {
          continue;
        }
        if (side == 0 && c >= 12) {
          continue;
        }
        double* b = Yc + m->boff[j];
        const double* b0 = Ys + m->boff[j];
        double h = stepOf(m, b0, c);
        perturb(b, c, h);
        if (c < 3 || c >= 6) {
          const int slot =
              c < 3 ? CSR_ROD_BX + c : (c < 12 ? CSR_ROD_BV + c - 6 : CSR_ROD_BH + c - 12);
          h = b[slot] - b0[slot];
        }
        rc = csr_rodContactAccel_(m, Yc, e, x0, v0, a1, &dummy);
        memcpy(b, b0, (size_t)(CSR_ROD_BH + m->nh[j]) * sizeof(double));
        if (rc != 0) {
          return rc;
        }
        /* rows: node e-1's v̇ (element e-1's block), node e's v̇, frame e's ω̇, ḣ_e */
        if (e > 1) {
          double* Jp = jblockIn(m, d->jac_con, e - 1, j - (e - 1) + 1);
          for (int r = 0; r < 3; r++) {
            Jp[nc * r + c] += (a1[r] - a0[r]) / h;
          }
        }
        double* Je = jblockIn(m, d->jac_con, e, j - e + 1);
        for (int r = 0; r < nout - 3; r++) {
          Je[nc * r + c] += (a1[3 + r] - a0[3 + r]) / h;
        }
      }
    }
  }
  return 0;
}


int csr_rodLinSys_(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix A, sunbooleantype jok,
                   sunbooleantype* jcur, sunrealtype gamma, void* user, N_Vector tmp1,
                   N_Vector tmp2, N_Vector tmp3) {
  (void)A;
  (void)fy;
  csrRodData* d = user;
  const csrRodModel* m = d->m;
  d->ls_gamma = gamma;
  const double* Y = N_VGetArrayPointer(y);
  for (int e = 1; e <= m->N; e++) {
    const double* q = Y + CSR_ROD_NIMP + m->boff[e] + CSR_ROD_BQ;
    double* qh = d->ls_q + 4 * (e - 1);
    memcpy(qh, q, 4 * sizeof(double));
    memcpy(d->ls_w + 3 * (e - 1), Y + CSR_ROD_NIMP + m->boff[e] + CSR_ROD_BW, 3 * sizeof(double));
    d->ls_qn[e - 1] = csr_rodQnormalize(qh);
    if (!(d->ls_qn[e - 1] > 0)) {
      return 1;
    }
  }
  if (!jok || !d->ls_have_jac) {
    /* the internal part changes with the configuration, slowly; the contact part changes
     * abruptly when a shape touches, lifts or slips, which is what makes CVODE ask for most
     * new Jacobians: refresh the internal part only on the first request, every
     * CSR_ROD_JAC_INT_STEPS steps, or when a contact-only refresh did not let the same step
     * converge */
    long nst = 0;
    CVodeGetNumSteps(d->cvode, &nst);
    nst += d->stats.steps;
    int full = !d->ls_have_jac || d->jac_int_step < 0 || nst - d->jac_int_step >=
               CSR_ROD_JAC_INT_STEPS || nst == d->jac_last_step || !m->contact.eval;
    d->jac_last_step = nst;
    int rc = 0;
    if (full) {
      rc = internalJacobian(m, d, t, y, tmp1, tmp3, tmp2);
      d->jac_int_step = nst;
    }
    if (rc == 0) {
      rc = contactJacobian(m, d, t, y);
    }
    if (rc != 0) {
      return rc;
    }
    const size_t n = jacSize(m);
    for (size_t k = 0; k < n; k++) {
      d->jac[k] = d->jac_int[k] + d->jac_con[k];
    }
    /* an element's history couples to the motion only in contact (∂u̇/∂h or ∂ḣ/∂(x, ψ, u)
     * non-zero); out of it the history just relaxes on its own, which the solver then treats
     * alone (most elements most of the time) */
    const int nc = 12 + m->nhmax;
    for (int e = 1; e <= m->N; e++) {
      int act = 0;
      for (int k = 0; k < 3 && !act; k++) {
        const int i = e + 1 - k; /* rows of elements e-1, e, e+1 in column e's history */
        if (i >= 1 && i <= m->N) {
          const double* J = jblock(m, d, i, k);
          for (int r = 0; r < 6 && !act; r++) {
            for (int c = 0; c < m->nh[e]; c++) {
              act |= J[nc * r + 12 + c] != 0;
            }
          }
        }
        const int j = e - 1 + k; /* ḣ_e by the motion of elements e-1, e, e+1 */
        if (j >= 1 && j <= m->N) {
          const double* J = jblock(m, d, e, k);
          for (int r = 6; r < 6 + m->nh[e] && !act; r++) {
            for (int c = 0; c < 12; c++) {
              act |= J[nc * r + c] != 0;
            }
          }
        }
      }
      d->ls_hact[e - 1] = act;
    }
    d->ls_have_jac = 1;
    d->jac_version++;
    *jcur = SUNTRUE;
  } else {
    *jcur = SUNFALSE;
  }
  return 0;
}


/* kinW at an explicit step size g (the condensed interface gains use ODE's step, not CVODE's) */
static void kinWAt(const csrRodData* d, double g, int j, double W[9]);
/* W = (I - γ/2 [ω]×) / (1 + γ²|ω|²/4) of element j (row-major 3 x 3): δψ per γ δω, at the
 * step size γ of CVODE's current system */
static void kinW(const csrRodData* d, int j, double W[9]) { kinWAt(d, d->ls_gamma, j, W); }


static void kinWAt(const csrRodData* d, double g, int j, double W[9]) {
  const double* w = d->ls_w + 3 * (j - 1);
  const double h = 0.5 * g;
  const double den = 1.0 / (1.0 + h * h * csu_dot3(w, w));
  W[0] = den;
  W[1] = h * w[2] * den;
  W[2] = -h * w[1] * den;
  W[3] = -h * w[2] * den;
  W[4] = den;
  W[5] = h * w[0] * den;
  W[6] = h * w[1] * den;
  W[7] = -h * w[0] * den;
  W[8] = den;
}


/* 1 / (1 + γ²|ω_j|²/4) of every element at CVODE's current γ (lsSetup: the solves that follow
 * use it twice per element) */
static void storeMqDen(csrRodData* d) {
  const double h = 0.5 * d->ls_gamma;
  for (int j = 1; j <= d->m->N; j++) {
    const double* w = d->ls_w + 3 * (j - 1);
    d->ls_den[j - 1] = 1.0 / (1.0 + h * h * csu_dot3(w, w));
  }
}


/* v <- (I - γΩ_j)⁻¹ v for a quaternion-space vector v of element j (at the γ of the last
 * setup, storeMqDen) */
static void applyMqInv(const csrRodData* d, int j, double v[4]) {
  const double* w = d->ls_w + 3 * (j - 1);
  const double h = 0.5 * d->ls_gamma;
  const double wq[4] = {0, w[0], w[1], w[2]};
  double t[4];
  csr_rodQmul(t, v, wq); /* 2 Ω v */
  const double den = d->ls_den[j - 1];
  for (int k = 0; k < 4; k++) {
    v[k] = (v[k] + h * t[k]) * den;
  }
}


/* the position coupling of a Jacobian row with column element j: (∂/∂x)_c for c < 3 (pairs
 * with δv), (∂/∂ψ W_j)_c for c >= 3 (pairs with δω) */
static void positionRow(const double* row, const double W[9], double out[6]) {
  for (int c = 0; c < 3; c++) {
    out[c] = row[c];
    out[3 + c] = row[3] * W[c] + row[4] * W[3 + c] + row[5] * W[6 + c];
  }
}


/* Z_m (nh x 6) for history element m and column element j: Mh_m⁻¹ (γ ∂ḣ/∂u + γ² ∂ḣ/∂x P_v +
 * γ² ∂ḣ/∂ψ W_j P_ω); Mhinv (nh x nh) given */
static void historyCoupling(const csrRodModel* m, const csrRodData* d, double g, int mm, int j,
                            const double* Mhinv, double* Z) {
  const int nh = m->nh[mm], nc = 12 + m->nhmax;
  const double* J = jblock(m, d, mm, j - mm + 1);
  double T[CSR_ROD_MAX_HIST * 6], W[9], pr[6];
  kinWAt(d, g, j, W);
  for (int r = 0; r < nh; r++) {
    const double* row = J + nc * (6 + r);
    positionRow(row, W, pr);
    for (int c = 0; c < 6; c++) {
      T[6 * r + c] = g * row[6 + c] + g * g * pr[c];
    }
  }
  for (int r = 0; r < nh; r++) {
    for (int c = 0; c < 6; c++) {
      double s = 0;
      for (int k = 0; k < nh; k++) {
        s += Mhinv[nh * r + k] * T[6 * k + c];
      }
      Z[6 * r + c] = s;
    }
  }
}


/* invert a small matrix (n <= CSR_ROD_MAX_HIST) by Gauss-Jordan with partial pivoting */
static int invertSmall(int n, const double* A, double* Ainv) {
  double W[CSR_ROD_MAX_HIST * 2 * CSR_ROD_MAX_HIST];
  const int w = 2 * n;
  for (int r = 0; r < n; r++) {
    for (int c = 0; c < n; c++) {
      W[w * r + c] = A[n * r + c];
      W[w * r + n + c] = (r == c) ? 1 : 0;
    }
  }
  for (int k = 0; k < n; k++) {
    int p = k;
    for (int r = k + 1; r < n; r++) {
      if (fabs(W[w * r + k]) > fabs(W[w * p + k])) {
        p = r;
      }
    }
    if (!(fabs(W[w * p + k]) > 0)) {
      return 1;
    }
    for (int c = 0; c < w; c++) {
      double t = W[w * k + c];
      W[w * k + c] = W[w * p + c];
      W[w * p + c] = t;
    }
    double inv = 1.0 / W[w * k + k];
    for (int c = 0; c < w; c++) {
      W[w * k + c] *= inv;
    }
    for (int r = 0; r < n; r++) {
      if (r != k && W[w * r + k] != 0) {
        double f = W[w * r + k];
        for (int c = 0; c < w; c++) {
          W[w * r + c] -= f * W[w * k + c];
        }
      }
    }
  }
  for (int r = 0; r < n; r++) {
    for (int c = 0; c < n; c++) {
      Ainv[n * r + c] = W[w * r + n + c];
    }
  }
  return 0;
}


/* assemble the reduced matrix S of the implicit step g from the stored Jacobian blocks into bt
 * (the history's (I - g ∂ḣ/∂h)⁻¹ into Mhinv, N blocks at stride nhmax²) and factor it;
 * 0, or 1 when a block is singular */
static int assembleReduced(csrRodData* d, double g, csrRodBt* bt, double* Mhinv) {
  const csrRodModel* m = d->m;
  const int N = m->N, nhm = m->nhmax, nc = 12 + nhm;
  /* every block the factorisation reads is written below (B_0 and C_{N-1} are never read): no
   * zeroing first */
  /* history: Mh_m⁻¹ = (I - γ ∂ḣ_m/∂h_m)⁻¹ per element (nh_m x nh_m, stored at stride nhmax²) */
  for (int e = 1; e <= N; e++) {
    const int nh = m->nh[e];
    if (nh == 0) {
      continue;
    }
    double Mh[CSR_ROD_MAX_HIST * CSR_ROD_MAX_HIST];
    const double* J = jblock(m, d, e, 1);
    for (int r = 0; r < nh; r++) {
      for (int c = 0; c < nh; c++) {
        Mh[nh * r + c] = (r == c ? 1.0 : 0.0) - g * J[nc * (6 + r) + 12 + c];
      }
    }
    if (invertSmall(nh, Mh, Mhinv + (size_t)(e - 1) * nhm * nhm) != 0) {
      return 1;
    }
  }
  for (int i = 1; i <= N; i++) {
    for (int k = 0; k < 3; k++) {
      int j = i - 1 + k;
      if (j < 1 || j > N) {
        continue;
      }
      double* S = (k == 0 ? bt->B : (k == 1 ? bt->D : bt->C)) + 36 * (i - 1);
      const double* J = jblock(m, d, i, k);
      double W[9], pr[6];
      kinWAt(d, g, j, W);
      for (int r = 0; r < 6; r++) {
        const double* row = J + nc * r;
        positionRow(row, W, pr);
        for (int c = 0; c < 6; c++) {
          /* ∂u̇/∂u, and the position coupling: x with v (c < 3), ψ W with ω (c >= 3) */
          S[6 * r + c] = (k == 1 && r == c ? 1.0 : 0.0) - g * row[6 + c] - g * g * pr[c];
        }
      }
      /* history of elements mm coupling row i and column j: - γ ∂u̇_i/∂h_mm Z_mm,j */
      for (int mm = j - 1; mm <= j + 1 && nhm > 0; mm++) {
        if (mm < 1 || mm > N || mm < i - 1 || mm > i + 1 || m->nh[mm] == 0 ||
            !d->ls_hact[mm - 1]) {
          continue;
        }
        const int nh = m->nh[mm];
        double Z[CSR_ROD_MAX_HIST * 6];
        historyCoupling(m, d, g, mm, j, Mhinv + (size_t)(mm - 1) * nhm * nhm, Z);
        const double* Ji = jblock(m, d, i, mm - i + 1);
        for (int r = 0; r < 6; r++) {
          for (int c = 0; c < 6; c++) {
            double s = 0;
            for (int q = 0; q < nh; q++) {
              s += Ji[nc * r + 12 + q] * Z[6 * q + c];
            }
            S[6 * r + c] -= g * s;
          }
        }
      }
    }
  }
  return csr_rodBtFactor_(bt);
}


/* SUNLinSolSetup: assemble and factor S for the stored γ and Jacobian blocks */
static int lsSetup(SUNLinearSolver LS, SUNMatrix A) {
  (void)A;
  csrRodData* d = LS->content;
  storeMqDen(d);
  int rc = assembleReduced(d, d->ls_gamma, &d->bt_dyn, d->ls_Mhinv);
  d->ls_last = rc ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
  return rc ? SUNLS_LUFACT_FAIL : SUNLS_SUCCESS;
}


int csr_rodCondensedHip_(csrRodData* d, double g, const double* rhs, int ncol, double* out) {
  const csrRodModel* m = d->m;
  if (!d->ls_have_jac || !(g > 0) || ncol < 1 || ncol > CSR_ROD_GAIN_COLS) {
    return 1;
  }
  /* the step's own matrix in the gains' storage: CVODE's factorisation (bt_dyn, at its γ) stays
   * as it is for the next Newton iteration */
  if (assembleReduced(d, g, &d->bt_gain, d->gain_Mhinv) != 0) {
    return 1;
  }
  double* r = d->gain_r;
  for (int c = 0; c < ncol; c++) {
    memset(r, 0, 6 * (size_t)m->N * sizeof(double));
    for (int k = 0; k < 6; k++) {
      r[k] = rhs[6 * c + k];
    }
    csr_rodBtSolve_(&d->bt_gain, r);
    memcpy(out + 6 * c, r, 6 * sizeof(double));
  }
  return 0;
}


void csr_rodKinW_(const csrRodData* d, double g, int j, double W[9]) { kinWAt(d, g, j, W); }


/* SUNLinSolSolve: x = (I - γJ)⁻¹ b through the reduced system */
static int lsSolve(SUNLinearSolver LS, SUNMatrix A, N_Vector x, N_Vector b, sunrealtype tol) {
  (void)A;
  (void)tol;
  csrRodData* d = LS->content;
  const csrRodModel* m = d->m;
  const int N = m->N, nhm = m->nhmax, nc = 12 + nhm;
  const double g = d->ls_gamma;
  const double* B = N_VGetArrayPointer(b);
  double* X = N_VGetArrayPointer(x);
  double* bpsi = d->ls_bpsi; /* (N x 3) Π (I - γΩ)⁻¹ b_q */
  double* r = d->ls_r;       /* (N x 6) reduced right-hand side, then δu */
  double* hb = d->ls_hb;     /* (N x nhmax) Mh⁻¹ (b_h + γ ∂ḣ/∂x b_x + γ ∂ḣ/∂ψ bψ) */
  /* Π_j (I - γΩ_j)⁻¹ b_q, Π v = 2 vec(conj(q̂) ⊗ v) / |q| */
  for (int j = 1; j <= N; j++) {
    const double* bq = B + CSR_ROD_NIMP + m->boff[j] + CSR_ROD_BQ;
    double t[4], v[4] = {bq[0], bq[1], bq[2], bq[3]};
    applyMqInv(d, j, v);
    csr_rodQmulConj(t, d->ls_q + 4 * (j - 1), v);
    double s = 2.0 / d->ls_qn[j - 1];
    for (int k = 0; k < 3; k++) {
      bpsi[3 * (j - 1) + k] = s * t[1 + k];
    }
  }
  /* position-level part of the right-hand side of element j: (b_x, bψ) */
#define BX(j) (B + CSR_ROD_NIMP + m->boff[j] + CSR_ROD_BX)
#define BPSI(j) (bpsi + 3 * ((j) - 1))
  for (int mm = 1; mm <= N; mm++) {
    const int nh = m->nh[mm];
    if (nh == 0) {
      continue;
    }
    double t[CSR_ROD_MAX_HIST];
    const double* bh = B + CSR_ROD_NIMP + m->boff[mm] + CSR_ROD_BH;
    for (int q = 0; q < nh; q++) {
      t[q] = bh[q];
    }
    for (int k = 0; k < 3 && d->ls_hact[mm - 1]; k++) {
      int j = mm - 1 + k;
      if (j < 1 || j > N) {
        continue;
      }
      const double* J = jblock(m, d, mm, k);
      for (int q = 0; q < nh; q++) {
        const double* row = J + nc * (6 + q);
        for (int c = 0; c < 3; c++) {
          t[q] += g * (row[c] * BX(j)[c] + row[3 + c] * BPSI(j)[c]);
        }
      }
    }
    const double* Mi = d->ls_Mhinv + (size_t)(mm - 1) * nhm * nhm;
    for (int q = 0; q < nh; q++) {
      double s = 0;
      for (int k = 0; k < nh; k++) {
        s += Mi[nh * q + k] * t[k];
      }
      hb[(size_t)(mm - 1) * nhm + q] = s;
    }
  }
  for (int i = 1; i <= N; i++) {
    const double* bu = B + CSR_ROD_NIMP + m->boff[i] + CSR_ROD_BV;
    double* ri = r + 6 * (i - 1);
    for (int k = 0; k < 6; k++) {
      ri[k] = bu[k];
    }
    for (int k = 0; k < 3; k++) {
      int j = i - 1 + k;
      if (j < 1 || j > N) {
        continue;
      }
      const double* J = jblock(m, d, i, k);
      for (int rr = 0; rr < 6; rr++) {
        const double* row = J + nc * rr;
        double s = 0;
        for (int c = 0; c < 3; c++) {
          s += row[c] * BX(j)[c] + row[3 + c] * BPSI(j)[c];
        }
        for (int q = 0; d->ls_hact[j - 1] && q < m->nh[j]; q++) {
          s += row[12 + q] * hb[(size_t)(j - 1) * nhm + q];
        }
        ri[rr] += g * s;
      }
    }
  }
  csr_rodBtSolve_(&d->bt_dyn, r);
  /* back-substitution: positions, quaternions, history; impulse rows unchanged */
  memcpy(X, B, CSR_ROD_NIMP * sizeof(double));
  for (int j = 1; j <= N; j++) {
    const double* bj = B + CSR_ROD_NIMP + m->boff[j];
    double* xj = X + CSR_ROD_NIMP + m->boff[j];
    const double* du = r + 6 * (j - 1);
    for (int k = 0; k < 3; k++) {
      xj[CSR_ROD_BX + k] = bj[CSR_ROD_BX + k] + g * du[k];
      xj[CSR_ROD_BV + k] = du[k];
      xj[CSR_ROD_BW + k] = du[3 + k];
    }
    /* δq = (I - γΩ)⁻¹ (b_q + γ G δω), G δω = ½ q ⊗ (0, δω) (the state's quaternion) */
    const double* q = d->ls_q + 4 * (j - 1);
    const double wq[4] = {0, du[3], du[4], du[5]};
    double gq[4], v[4];
    csr_rodQmul(gq, q, wq);
    for (int k = 0; k < 4; k++) {
      v[k] = bj[CSR_ROD_BQ + k] + 0.5 * g * d->ls_qn[j - 1] * gq[k];
    }
    applyMqInv(d, j, v);
    memcpy(xj + CSR_ROD_BQ, v, sizeof v);
  }
  for (int mm = 1; mm <= N; mm++) {
    const int nh = m->nh[mm];
    if (nh == 0) {
      continue;
    }
    double t[CSR_ROD_MAX_HIST];
    for (int q = 0; q < nh; q++) {
      t[q] = 0;
    }
    for (int k = 0; k < 3 && d->ls_hact[mm - 1]; k++) {
      int j = mm - 1 + k;
      if (j < 1 || j > N) {
        continue;
      }
      const double* J = jblock(m, d, mm, k);
      const double* du = r + 6 * (j - 1);
      double W[9], pr[6];
      kinW(d, j, W);
      for (int q = 0; q < nh; q++) {
        const double* row = J + nc * (6 + q);
        positionRow(row, W, pr);
        for (int c = 0; c < 6; c++) {
          /* the u-dependent part of δx, δψ (γ δv, γ W δω) and u itself */
          t[q] += g * (g * pr[c] + row[6 + c]) * du[c];
        }
      }
    }
    const double* Mi = d->ls_Mhinv + (size_t)(mm - 1) * nhm * nhm;
    double* xh = X + CSR_ROD_NIMP + m->boff[mm] + CSR_ROD_BH;
    for (int q = 0; q < nh; q++) {
      double s = 0;
      for (int k = 0; k < nh; k++) {
        s += Mi[nh * q + k] * t[k];
      }
      xh[q] = hb[(size_t)(mm - 1) * nhm + q] + s;
    }
  }
#undef BX
#undef BPSI
  d->ls_last = SUNLS_SUCCESS;
  return SUNLS_SUCCESS;
}


static SUNLinearSolver_Type lsGetType(SUNLinearSolver LS) {
  (void)LS;
  return SUNLINEARSOLVER_DIRECT;
}


static SUNLinearSolver_ID lsGetId(SUNLinearSolver LS) {
  (void)LS;
  return SUNLINEARSOLVER_CUSTOM;
}


static sunindextype lsLastFlag(SUNLinearSolver LS) {
  const csrRodData* d = LS->content;
  return d->ls_last;
}


static int lsFree(SUNLinearSolver LS) {
  if (LS) {
    LS->content = NULL;
    SUNLinSolFreeEmpty(LS);
  }
  return 0;
}


static SUNMatrix_ID matGetId(SUNMatrix A) {
  (void)A;
  return SUNMATRIX_CUSTOM;
}


static void matDestroy(SUNMatrix A) {
  if (A) {
    A->content = NULL;
    SUNMatFreeEmpty(A);
  }
}


int csr_rodLinsolAttach_(csrRodData* d) {
  const csrRodModel* m = d->m;
  const int N = m->N, nh = m->nhmax;
  const size_t nblk = (size_t)(6 + nh) * (size_t)(12 + nh);
  d->jac = calloc(3 * (size_t)N * nblk, sizeof(double));
  d->jac_int = calloc(3 * (size_t)N * nblk, sizeof(double));
  d->jac_con = calloc(3 * (size_t)N * nblk, sizeof(double));
  d->con_y = calloc((size_t)m->nstate, sizeof(double));
  d->jac_int_step = -1;
  d->jac_last_step = -1;
  d->ls_q = calloc(4 * (size_t)N, sizeof(double));
  d->ls_qn = calloc((size_t)N, sizeof(double));
  d->ls_den = calloc((size_t)N, sizeof(double));
  d->ls_w = calloc(3 * (size_t)N, sizeof(double));
  d->ls_hact = calloc((size_t)N, sizeof(int));
  d->ls_bpsi = calloc(3 * (size_t)N, sizeof(double));
  d->ls_r = calloc(6 * (size_t)N, sizeof(double));
  d->ls_hb = calloc((size_t)N * (size_t)(nh > 0 ? nh : 1), sizeof(double));
  d->ls_Mhinv = calloc((size_t)N * (size_t)(nh > 0 ? nh * nh : 1), sizeof(double));
  if (!d->jac || !d->jac_int || !d->jac_con || !d->con_y || !d->ls_q || !d->ls_qn || !d->ls_w ||
      !d->ls_den || !d->ls_hact || !d->ls_bpsi || !d->ls_r || !d->ls_hb ||
      !d->ls_Mhinv || !csr_rodBtAlloc_(&d->bt_dyn, N) || !csr_rodBtAlloc_(&d->bt_gain, N)) {
    return 1;
  }
  d->gain_Mhinv = calloc((size_t)N * (size_t)(nh > 0 ? nh * nh : 1), sizeof(double));
  d->gain_r = calloc(6 * (size_t)N, sizeof(double));
  if (!d->gain_Mhinv || !d->gain_r) {
    return 1;
  }
  d->LS = SUNLinSolNewEmpty(d->sun);
  d->A = SUNMatNewEmpty(d->sun);
  if (!d->LS || !d->A) {
    return 1;
  }
  d->LS->content = d;
  d->LS->ops->gettype = lsGetType;
  d->LS->ops->getid = lsGetId;
  d->LS->ops->setup = lsSetup;
  d->LS->ops->solve = lsSolve;
  d->LS->ops->lastflag = lsLastFlag;
  d->LS->ops->free = lsFree;
  d->A->content = d;
  d->A->ops->getid = matGetId;
  d->A->ops->destroy = matDestroy;
  if (CVodeSetLinearSolver(d->cvode, d->LS, d->A) != CV_SUCCESS ||
      CVodeSetLinSysFn(d->cvode, csr_rodLinSys_) != CV_SUCCESS) {
    return 1;
  }
  return 0;
}


void csr_rodLinsolFree_(csrRodData* d) {
  free(d->jac);
  free(d->jac_int);
  free(d->jac_con);
  free(d->con_y);
  free(d->ls_q);
  free(d->ls_qn);
  free(d->ls_den);
  free(d->ls_w);
  free(d->ls_hact);
  free(d->ls_bpsi);
  free(d->ls_r);
  free(d->ls_hb);
  free(d->ls_Mhinv);
  free(d->gain_Mhinv);
  free(d->gain_r);
  csr_rodBtFree_(&d->bt_dyn);
  csr_rodBtFree_(&d->bt_gain);
}

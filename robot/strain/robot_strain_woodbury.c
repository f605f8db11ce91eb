/* robot_strain_woodbury.c: a Newton iterate's new iteration matrix on a stance leg whose step
 * started by the articulated recursion with the contact's blocks (robot_strain_artic.c,
 * artic 2), without W_M's dense assembly or an n x n factor (robot_strain_internal.h
 * csr_strainCondenseWoodbury_).
 *
 * An iterate refactors when a contact slot changed its state: its matrix is
 *   W = W_M(q0) - h Σ_{iterate's shapes} S_jᵀ A_j S_j
 * (W_M at the step's start, the contact linearised at the iterate: robot_strain_condense.c),
 * while the start's recursion factored, piece by piece,
 *   W_f = W_M(q0) - h Σ_{start's shapes} S_cᵀ A_c S_c
 * (the linearly implicit BDF2's: W_M at its last assembled iterate and h = c2 h_step in both,
 * robot_strain_condense.c condenseUpdate).
 * So W = W_f + Uᵀ C U with U the stacked S rows of both sets (m = 6 (n_start + n_iterate) rows
 * of 6 + n) and C block diagonal: +h A_c for a start's shape (its part leaves), -h A_j for an
 * iterate's (its part enters). On the leg's block, with R = W_f,ll⁻¹ (the pieces' factors,
 * csr_strainArticSolve_) and U_l, U_b U's leg and base columns, the Woodbury identity
 *   (W_f,ll + U_lᵀ C U_l)⁻¹ = R - Q K⁻¹ C U_l R,   Q = R U_lᵀ (n x m),   K = I + C U_l Q (m x m)
 * (the form without C⁻¹: A_j may be singular; K is singular exactly when W_ll is, by the
 * determinant lemma det W_ll = det W_f,ll det K). The step's blocks then follow as the dense
 * path's (factorAndCondense) from W_ll⁻¹ on W_lb and h r_l:
 *   R W_lb = X_f + Q C U_b   (W_lb = W_f,lb + U_lᵀ C U_b; X_f = R W_f,lb, the start's X),
 *   X = T - Q K⁻¹ C U_l T on T = [R W_lb, R h r_l], y its last column,
 *   Z = W_bb - W_bl X,   ρ = h r_b - W_bl y.
 * Cost: m + 1 solves through the pieces (~10 k instructions each at n 36) and O(m² n + m³)
 * for K, against W_M's assembly (~0.1 M), the contact's n x n block and the n x n LU with its
 * seven solves (~0.14 M). The kept iterates after it solve the same way (one sweep and the
 * m x m correction: csr_strainWoodburySolve_). The same Z, ρ, X, y as the dense LU to
 * round-off (test_strain_refactor stance_refactor_is_the_dense_one). */
#include <math.h>
#include <string.h>

#include "robot_strain_internal.h"


/* row i of the stacked U (6 + n): the start's shapes' S rows first, then the iterate's */
static const double* urow(const csrStrainModel* m, const csrStrainData* d, int i) {
  const size_t nu = (size_t)(6 + m->n);
  const int c = i / 6, r = i % 6;
  return c < d->nct ? d->cS + ((size_t)c * 6 + r) * nu
                    : d->wS + ((size_t)(c - d->nct) * 6 + r) * nu;
}


/* G (m x nc, row-major, leading dimension ld) := C G in place, C's block of shape c being
 * +h A_c (a start's shape) or -h A_j (an iterate's) */
static void applyC(const csrStrainData* d, double h, double* G, int m, int nc, int ld) {
  for (int c = 0; 6 * c < m; c++) {
    const double* A = c < d->nct ? d->cA + 36 * c : d->wA + 36 * (c - d->nct);
    const double s = c < d->nct ? h : -h;
    for (int j = 0; j < nc; j++) {
      double g[6], v[6];
      for (int k = 0; k < 6; k++) {
        g[k] = G[(size_t)(6 * c + k) * ld + j];
      }
      for (int r = 0; r < 6; r++) {
        double t = 0;
        for (int k = 0; k < 6; k++) {
          t += A[6 * r + k] * g[k];
        }
        v[r] = s * t;
      }
      for (int r = 0; r < 6; r++) {
        G[(size_t)(6 * c + r) * ld + j] = v[r];
      }
    }
  }
}


static double dot(const double* a, const double* b, int n) {
  double t = 0;
  for (int j = 0; j < n; j++) {
    t += a[j] * b[j];
  }
  return t;
}


/* the scratch after K's storage (12 x the rank bound) */
static double* scratch(const csrStrainModel* m, csrStrainData* d) {
  const size_t mw = (size_t)12 * m->nshape + 1;
  return d->wbK + mw * mw;
}


int csr_strainCondenseWoodbury_(const csrStrainModel* m, csrStrainData* d, double h,
                                const double Wbb[36], const double rb[6], double Z[36],
                                double rho[6]) {
  const int n = m->n, mt = 6 * (d->nct + d->nwt);
  if (!(d->art_f || d->wb_f) || mt == 0 || d->nct + d->nwt > 2 * m->nshape) {
    return 1;
  }
  if (d->art_f) {
    memcpy(d->wbX, d->X, (size_t)n * 6 * sizeof(double)); /* the start's X_f */
  }
  /* Q = R U_lᵀ (n x m, row-major): the m columns solved side by side */
  double* Q = d->wbQ;
  double* G = scratch(m, d);
  for (int i = 0; i < mt; i++) {
    const double* u = urow(m, d, i) + 6;
    for (int j = 0; j < n; j++) {
      Q[(size_t)j * mt + i] = u[j];
    }
  }
  csr_strainArticSolveMulti_(m, d, Q, mt, G);
  /* K = I + C U_l Q */
  double* K = d->wbK;
  for (int i = 0; i < mt; i++) {
    const double* u = urow(m, d, i) + 6;
    double* k = K + (size_t)i * mt;
    memset(k, 0, (size_t)mt * sizeof(double));
    for (int j = 0; j < n; j++) {
      const double uj = u[j];
      const double* q = Q + (size_t)j * mt;
      for (int c = 0; c < mt; c++) {
        k[c] += uj * q[c];
      }
    }
  }
  applyC(d, h, K, mt, mt, mt);
  for (int i = 0; i < mt; i++) {
    K[(size_t)i * mt + i] += 1;
  }
  if (csr_strainLuFactor_(K, mt, d->wbPiv)) {
    return 1;
  }
  /* T = [R W_lb, R h r_l] into d->X, d->y: R W_lb = X_f + Q (C U_b) */
  for (int i = 0; i < mt; i++) {
    memcpy(G + 7 * i, urow(m, d, i), 6 * sizeof(double));
  }
  applyC(d, h, G, mt, 6, 7);
  for (int j = 0; j < n; j++) {
    const double* q = Q + (size_t)j * mt;
    double t[6];
    memcpy(t, d->wbX + 6 * j, sizeof t);
    for (int i = 0; i < mt; i++) {
      for (int c = 0; c < 6; c++) {
        t[c] += q[i] * G[7 * i + c];
      }
    }
    memcpy(d->X + 6 * j, t, sizeof t);
    d->y[j] = h * d->rl[j];
  }
  double w[6];
  csr_strainArticSolve_(m, d, d->y, w);
  /* the correction Q K⁻¹ C U_l T */
  for (int i = 0; i < mt; i++) {
    const double* u = urow(m, d, i) + 6;
    double t[6] = {0, 0, 0, 0, 0, 0};
    for (int j = 0; j < n; j++) {
      for (int c = 0; c < 6; c++) {
        t[c] += u[j] * d->X[6 * j + c];
      }
    }
    memcpy(G + 7 * i, t, sizeof t);
    G[7 * i + 6] = dot(u, d->y, n);
  }
  applyC(d, h, G, mt, 7, 7);
  csr_strainLuSolveMulti_(K, mt, d->wbPiv, G, 7);
  for (int j = 0; j < n; j++) {
    const double* q = Q + (size_t)j * mt;
    double t[7] = {0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < mt; i++) {
      for (int c = 0; c < 7; c++) {
        t[c] += q[i] * G[7 * i + c];
      }
    }
    for (int c = 0; c < 6; c++) {
      d->X[6 * j + c] -= t[c];
    }
    d->y[j] -= t[6];
  }
  /* Z = W_bb - W_bl X, ρ = h r_b - W_bl y (as factorAndCondense) */
  for (int a = 0; a < 6; a++) {
    const double* wbl = d->Wbl + (size_t)n * a;
    double t[6] = {0, 0, 0, 0, 0, 0};
    for (int j = 0; j < n; j++) {
      for (int c = 0; c < 6; c++) {
        t[c] += wbl[j] * d->X[6 * j + c];
      }
    }
    for (int c = 0; c < 6; c++) {
      Z[6 * a + c] = Wbb[6 * a + c] - t[c];
    }
    rho[a] = h * rb[a] - dot(wbl, d->y, n);
    if (!isfinite(rho[a])) {
      return 1;
    }
  }
  return 0;
}


void csr_strainWoodburySolve_(const csrStrainModel* m, csrStrainData* d, double h, double* y) {
  const int n = m->n, mt = 6 * (d->nct + d->nwt);
  double w[6];
  csr_strainArticSolve_(m, d, y, w);
  double* g = scratch(m, d);
  for (int i = 0; i < mt; i++) {
    g[i] = dot(urow(m, d, i) + 6, y, n);
  }
  applyC(d, h, g, mt, 1, 1);
  csr_strainLuSolve_(d->wbK, mt, d->wbPiv, g);
  for (int j = 0; j < n; j++) {
    y[j] -= dot(d->wbQ + (size_t)j * mt, g, mt);
  }
}

/* robot_strain_lie.c: the strain leg's kinematics (robot_strain.h): SE(3) exponential, adjoint
 * and tangent operator, the Legendre strain basis, the Zanna (4th-order Magnus) step and the
 * recursion of poses and body Jacobians along the rod.
 *
 * Rationale. The product of exponentials over sub-intervals with a 4th-order Magnus expansion
 * is SoRoSim's choice (Mathew et al., "SoRoSim", IEEE RAM 2022; Renda et al., IEEE TRO 2020):
 * exact for a constant strain (one exponential; the calibrated arcs of unloaded segments are
 * reproduced to round-off at any sub-division), 4th order otherwise; the Jacobian recursion is
 * the exact derivative of that discrete map (so the generalised forces Jᵀ F are the exact
 * gradients of the discrete work), not an approximation of the continuous one.
 * T(Ω) = dexp(-Ω) in closed form is Selig's degree-4 polynomial in ad(Ω) (the minimal
 * polynomial of ad on se(3) is x (x² + θ²)²); near θ = |ω| = 0 its coefficients cancel
 * (relative error ~ ε/θ⁴), so below θ = 0.05 the series is summed instead (its terms fall as
 * θ^(j-1)/(j+1)!, 10 terms reach round-off). test_strain_model checks both against a 60-term
 * series. */
#include <math.h>
#include <string.h>

#include "core_math.h"
#include "robot_strain_internal.h"

/* below this |ω| (rad) T(Ω) is summed as a series (header) */
#define CSR_STRAIN_SERIES_THETA 0.05
/* terms of that series: the 10th is ~θ⁹/11! |v| < 1e-19 |v| */
#define CSR_STRAIN_SERIES_TERMS 12

static void hat3(const double a[3], double H[9]) {
  H[0] = 0;
  H[1] = -a[2];
  H[2] = a[1];
  H[3] = a[2];
  H[4] = 0;
  H[5] = -a[0];
  H[6] = -a[1];
  H[7] = a[0];
  H[8] = 0;
}


void csr_strainAd_(const double xi[6], double ad[36]) {
  double W[9], V[9];
  hat3(xi, W);
  hat3(xi + 3, V);
  memset(ad, 0, 36 * sizeof(double));
  for (int r = 0; r < 3; r++) {
    for (int c = 0; c < 3; c++) {
      ad[6 * r + c] = W[3 * r + c];
      ad[6 * (r + 3) + c + 3] = W[3 * r + c];
      ad[6 * (r + 3) + c] = V[3 * r + c];
    }
  }
}


void csr_strainExp_(const double Om[6], double R[9], double x[3]) {
  const double* w = Om;
  const double* v = Om + 3;
  double th2 = csu_dot3(w, w), th = sqrt(th2);
  /* R = I + a ω^ + b ω^², x = (I + b ω^ + c ω^²) v (Rodrigues; left Jacobian of SO(3)) */
  double a, b, c;
  if (th < 1e-4) {
    a = 1 - th2 / 6;
    b = 0.5 - th2 / 24;
    c = 1.0 / 6 - th2 / 120;
  } else {
    a = sin(th) / th;
    b = (1 - cos(th)) / th2;
    c = (th - sin(th)) / (th2 * th);
  }
  double W[9], W2[9];
  hat3(w, W);
  csu_mulMat3(W2, W, W);
  for (int i = 0; i < 9; i++) {
    R[i] = a * W[i] + b * W2[i] + (i % 4 == 0 ? 1.0 : 0.0);
  }
  double Wv[3], W2v[3];
  csu_mulMatVec3(Wv, W, v);
  csu_mulMatVec3(W2v, W2, v);
  for (int i = 0; i < 3; i++) {
    x[i] = v[i] + b * Wv[i] + c * W2v[i];
  }
}


static void mul6(double C[36], const double A[36], const double B[36]) {
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int k = 0; k < 6; k++) {
        s += A[6 * i + k] * B[6 * k + j];
      }
      C[6 * i + j] = s;
    }
  }
}


void csr_strainTangent_(const double Om[6], double T[36]) {
  double ad[36], P[36], tmp[36];
  csr_strainAd_(Om, ad);
  double th = csu_norm3(Om);
  memset(T, 0, 36 * sizeof(double));
  for (int i = 0; i < 6; i++) {
    T[7 * i] = 1;
  }
  memcpy(P, ad, sizeof P);
  if (th < CSR_STRAIN_SERIES_THETA) {
    /* Σ_j (-ad)^j / (j + 1)! */
    double f = -0.5;
    for (int j = 1; j <= CSR_STRAIN_SERIES_TERMS; j++) {
      for (int i = 0; i < 36; i++) {
        T[i] += f * P[i];
      }
      f *= -1.0 / (j + 2);
      mul6(tmp, P, ad);
      memcpy(P, tmp, sizeof P);
    }
    return;
  }
  /* dexp(-Ω) = I + c1 ad + c2 ad² + c3 ad³ + c4 ad⁴ (Selig; the odd coefficients of dexp(Ω)
   * change sign with ad) */
  double s = sin(th), c = cos(th), t2 = th * th, t3 = t2 * th, t4 = t3 * th, t5 = t4 * th;
  double k[4] = {-(4 - 4 * c - th * s) / (2 * t2), (4 * th - 5 * s + th * c) / (2 * t3),
                 -(2 - 2 * c - th * s) / (2 * t4), (2 * th - 3 * s + th * c) / (2 * t5)};
  for (int j = 0; j < 4; j++) {
    for (int i = 0; i < 36; i++) {
      T[i] += k[j] * P[i];
    }
    if (j < 3) {
      mul6(tmp, P, ad);
      memcpy(P, tmp, sizeof P);
    }
  }
}


void csr_strainLegendre_(int n, double s, double* P) {
  P[0] = 1;
  if (n >= 1) {
    P[1] = s;
  }
  for (int k = 1; k < n; k++) {
    P[k + 1] = ((2 * k + 1) * s * P[k] - k * P[k - 1]) / (k + 1);
  }
}


/* shape function of unknown j at local arc length s of its piece (length S) */
static double shape(const csrStrainModel* m, int j, const double* P) {
  return P[m->dorder[j]];
}


void csr_strainAt_(const csrStrainModel* m, const double* q, int k, double s, double xi[6]) {
  double P[CSR_STRAIN_MAX_ORDER + 1];
  double S = m->piece[k].length;
  csr_strainLegendre_(m->pmax, 2 * s / S - 1, P);
  memset(xi, 0, 6 * sizeof(double));
  xi[5] = 1;
  for (int j = m->dof0[k]; j < m->dof0[k] + m->ndof[k]; j++) {
    xi[m->dcomp[j]] += shape(m, j, P) * q[j];
  }
}


void csr_strainMagnus_(const csrStrainModel* m, const double* q, int k, double s, double h,
                       double Om[6], double* dOm) {
  /* Gauss points of [s, s + h] */
  const double g = sqrt(3.0) / 6;
  double sa = s + (0.5 - g) * h, sb = s + (0.5 + g) * h;
  double xa[6], xb[6], ada[36], adb[36];
  csr_strainAt_(m, q, k, sa, xa);
  csr_strainAt_(m, q, k, sb, xb);
  csr_strainAd_(xa, ada);
  csr_strainAd_(xb, adb);
  /* Ω = h/2 (ξa + ξb) + √3 h²/12 ad(ξa) ξb (robot_strain.h) */
  const double c2 = sqrt(3.0) * h * h / 12;
  for (int r = 0; r < 6; r++) {
    double comm = 0;
    for (int c = 0; c < 6; c++) {
      comm += ada[6 * r + c] * xb[c];
    }
    Om[r] = 0.5 * h * (xa[r] + xb[r]) + c2 * comm;
  }
  if (!dOm) {
    return;
  }
  /* ∂Ω/∂q_j = h/2 (φa + φb) e_c + √3 h²/12 (φb ad(ξa) e_c - φa ad(ξb) e_c) */
  double Pa[CSR_STRAIN_MAX_ORDER + 1], Pb[CSR_STRAIN_MAX_ORDER + 1];
  double S = m->piece[k].length;
  csr_strainLegendre_(m->pmax, 2 * sa / S - 1, Pa);
  csr_strainLegendre_(m->pmax, 2 * sb / S - 1, Pb);
  int nd = m->ndof[k];
  for (int jj = 0; jj < nd; jj++) {
    int j = m->dof0[k] + jj, c = m->dcomp[j];
    double fa = shape(m, j, Pa), fb = shape(m, j, Pb);
    for (int r = 0; r < 6; r++) {
      dOm[nd * r + jj] = c2 * (fb * ada[6 * r + c] - fa * adb[6 * r + c]);
    }
    dOm[nd * c + jj] += 0.5 * h * (fa + fb);
  }
}


/* pose and Jacobian at point `to` from point `from` through the step Ω (dOm over piece k's
 * unknowns, NULL for a rigid step) */
static void stepPoint(const csrStrainModel* m, csrStrainData* d, int from, int to, int k,
                      const double Om[6], const double* dOm, int want_J) {
  double Re[9], pe[3], tmp[3];
  csr_strainExp_(Om, Re, pe);
  csu_mulMat3(d->R + 9 * to, d->R + 9 * from, Re);
  csu_mulMatVec3(tmp, d->R + 9 * from, pe);
  csu_add3(d->x + 3 * to, d->x + 3 * from, tmp);
  if (!want_J) {
    return;
  }
  const int n = m->n, ncol = m->dof0[k] + m->ndof[k];
  const double* Jf = d->J + (size_t)from * 6 * n;
  double* Jt = d->J + (size_t)to * 6 * n;
  /* Ad(exp(-Ω)) (a; b) = (Reᵀ a; Reᵀ (b - pe × a)) on each column */
  for (int c = 0; c < ncol; c++) {
    double a[3] = {Jf[c], Jf[n + c], Jf[2 * n + c]};
    double bb[3] = {Jf[3 * n + c], Jf[4 * n + c], Jf[5 * n + c]};
    double pxa[3], u[3], w[3];
    csu_cross3(pxa, pe, a);
    csu_sub3(u, bb, pxa);
    csu_mulMatTVec3(w, Re, a);
    csu_mulMatTVec3(tmp, Re, u);
    for (int r = 0; r < 3; r++) {
      Jt[r * n + c] = w[r];
      Jt[(r + 3) * n + c] = tmp[r];
    }
  }
  for (int r = 0; r < 6; r++) {
    for (int c = ncol; c < n; c++) {
      Jt[r * n + c] = 0;
    }
  }
  if (dOm) {
    double T[36];
    csr_strainTangent_(Om, T);
    int nd = m->ndof[k], c0 = m->dof0[k];
    for (int r = 0; r < 6; r++) {
      for (int jj = 0; jj < nd; jj++) {
        double s = 0;
        for (int i = 0; i < 6; i++) {
          s += T[6 * r + i] * dOm[nd * i + jj];
        }
        Jt[r * n + c0 + jj] += s;
      }
    }
  }
}


void csr_strainKinematics_(const csrStrainModel* m, csrStrainData* d, int want_J) {
  /* the clamp: poses are relative to the base (hip) frame */
  csu_eye3(d->R);
  memset(d->x, 0, 3 * sizeof(double));
  if (want_J) {
    memset(d->J, 0, (size_t)6 * m->n * sizeof(double));
  }
  /* ∂Ω/∂q of one step: 6 x (largest ndof) */
  double dOm[6 * CSR_STRAIN_MAX_PIECE_DOF];
  for (int k = 0; k < m->npiece; k++) {
    double h = m->piece[k].length / m->nsub[k];
    for (int i = 0; i < m->nsub[k]; i++) {
      int p = m->pt0[k] + 2 * i;
      if (m->rigid[k]) {
        const double Oh[6] = {0, 0, 0, 0, 0, 0.5 * h}, Of[6] = {0, 0, 0, 0, 0, h};
        stepPoint(m, d, p, p + 1, k, Oh, NULL, want_J);
        stepPoint(m, d, p, p + 2, k, Of, NULL, want_J);
        continue;
      }
      double Om[6];
      csr_strainMagnus_(m, d->q, k, i * h, 0.5 * h, Om, want_J ? dOm : NULL);
      stepPoint(m, d, p, p + 1, k, Om, want_J ? dOm : NULL, want_J);
      csr_strainMagnus_(m, d->q, k, i * h, h, Om, want_J ? dOm : NULL);
      stepPoint(m, d, p, p + 2, k, Om, want_J ? dOm : NULL, want_J);
    }
  }
  d->kin_valid = want_J ? 2 : 1;
}

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
 * (relative error ~ ε/θ⁴), so below θ = 0.05 its coefficients come from the series folded
 * down by the minimal polynomial (its terms fall as θ^(j-1)/(j+1)!, 10 terms reach round-off).
 * T is formed on its 3 x 3 blocks and, where only T v is needed (the twist recursion of the
 * velocity products), applied to the vector.
 * Where only Σ_p G_pᵀ F_p of point wrenches is needed, the adjoint (backward) recursion of
 * the same map gives it without the 6 x n Jacobians (csr_strainProject_): from the tip back,
 * W_p = F_p + Σ_children Ad(exp(-Ω))ᵀ W_child and the piece's forces (∂Ω/∂q)ᵀ T(Ω)ᵀ W_child,
 * O(6 nd + 36) per step instead of O(6 n) per point twice (the Jacobians, then Jᵀ F). test_strain_model checks both branches against a
 * 60-term series. */
#include <math.h>
#include <stdlib.h>
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


void csr_strainAdInv_(const double R[9], const double x[3], double A[36]) {
  /* [Rᵀ 0; -Rᵀ x^ Rᵀ]: column c of the coupling block is Rᵀ (e_c × x) */
  memset(A, 0, 36 * sizeof(double));
  for (int c = 0; c < 3; c++) {
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


/* θ = |ω| of a step Ω and sin θ, cos θ where the exponential's or the tangent's closed form
 * uses them: one step's exponential and tangent share the one libm call (the same values as
 * each calling sin and cos itself) */
typedef struct {
  double th2, th, sn, cs;
} csrTrig;

/* the exponential's closed form from this θ on (its series below) */
#define CSR_STRAIN_EXP_THETA 1e-4

static void trigOf(const double Om[6], csrTrig* t) {
  t->th2 = csu_dot3(Om, Om);
  t->th = sqrt(t->th2);
  t->sn = t->cs = 0;
  if (t->th >= CSR_STRAIN_EXP_THETA || t->th >= CSR_STRAIN_SERIES_THETA) {
    t->sn = sin(t->th);
    t->cs = cos(t->th);
  }
}


static void expWith(const double Om[6], const csrTrig* tg, double R[9], double x[3]) {
  const double* w = Om;
  const double* v = Om + 3;
  const double th2 = tg->th2, th = tg->th;
  /* R = I + a ω^ + b ω^², x = (I + b ω^ + c ω^²) v (Rodrigues; left Jacobian of SO(3)) */
  double a, b, c;
  if (th < CSR_STRAIN_EXP_THETA) {
    a = 1 - th2 / 6;
    b = 0.5 - th2 / 24;
    c = 1.0 / 6 - th2 / 120;
  } else {
    a = tg->sn / th;
    b = (1 - tg->cs) / th2;
    c = (th - tg->sn) / (th2 * th);
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


void csr_strainExp_(const double Om[6], double R[9], double x[3]) {
  csrTrig tg;
  trigOf(Om, &tg);
  expWith(Om, &tg, R, x);
}


/* C = A B (3 x 3) */
static void mul3(double C[9], const double A[9], const double B[9]) {
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
    }
  }
}


/* the coefficients c_0..c_4 of T(Ω) = Σ_j c_j ad(Ω)^j (its minimal polynomial x (x² + θ²)²
 * reduces every higher power). θ >= SERIES_THETA: Selig's closed form; below, the series
 * Σ_j (-1)^j ad^j / (j + 1)! folded down by ad^j = -2 θ² ad^(j-2) - θ⁴ ad^(j-4) (j >= 5), its
 * terms falling as θ^(j-1) / (j + 1)! (header: 12 terms reach round-off) */
static void tangentCoefficients(const csrTrig* tg, double c[5]) {
  const double th = tg->th;
  if (th < CSR_STRAIN_SERIES_THETA) {
    double s[CSR_STRAIN_SERIES_TERMS + 1], f = 1, t2 = th * th, t4 = t2 * t2;
    for (int j = 0; j <= CSR_STRAIN_SERIES_TERMS; j++) {
      s[j] = f;
      f *= -1.0 / (j + 2);
    }
    for (int j = CSR_STRAIN_SERIES_TERMS; j >= 5; j--) {
      s[j - 2] -= 2 * t2 * s[j];
      s[j - 4] -= t4 * s[j];
    }
    memcpy(c, s, 5 * sizeof(double));
    return;
  }
  /* dexp(-Ω) = I + c1 ad + c2 ad² + c3 ad³ + c4 ad⁴ (Selig; the odd coefficients of dexp(Ω)
   * change sign with ad) */
  double sn = tg->sn, cs = tg->cs, t2 = th * th, t3 = t2 * th, t4 = t3 * th, t5 = t4 * th;
  c[0] = 1;
  c[1] = -(4 - 4 * cs - th * sn) / (2 * t2);
  c[2] = (4 * th - 5 * sn + th * cs) / (2 * t3);
  c[3] = -(2 - 2 * cs - th * sn) / (2 * t4);
  c[4] = (2 * th - 3 * sn + th * cs) / (2 * t5);
}


static void tangentWith(const double Om[6], const csrTrig* tg, double T[36]);

void csr_strainTangent_(const double Om[6], double T[36]) {
  csrTrig tg;
  trigOf(Om, &tg);
  tangentWith(Om, &tg, T);
}


static void tangentWith(const double Om[6], const csrTrig* tg, double T[36]) {
  /* ad^j = [A_j 0; B_j A_j] with A_1 = ω^, B_1 = v^: A_{j+1} = A_j ω^, B_{j+1} = B_j ω^ + A_j v^
   * (3 x 3 blocks: the 6 x 6 products' zero block skipped) */
  double c[5], W[9], Vh[9], A[9], B[9], An[9], Bn[9], t[9];
  tangentCoefficients(tg, c);
  hat3(Om, W);
  hat3(Om + 3, Vh);
  double TA[9] = {c[0], 0, 0, 0, c[0], 0, 0, 0, c[0]}, TB[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  memcpy(A, W, sizeof A);
  memcpy(B, Vh, sizeof B);
  for (int j = 1; j <= 4; j++) {
    for (int i = 0; i < 9; i++) {
      TA[i] += c[j] * A[i];
      TB[i] += c[j] * B[i];
    }
    if (j < 4) {
      mul3(An, A, W);
      mul3(Bn, B, W);
      mul3(t, A, Vh);
      for (int i = 0; i < 9; i++) {
        Bn[i] += t[i];
      }
      memcpy(A, An, sizeof A);
      memcpy(B, Bn, sizeof B);
    }
  }
  for (int r = 0; r < 3; r++) {
    for (int cc = 0; cc < 3; cc++) {
      T[6 * r + cc] = TA[3 * r + cc];
      T[6 * r + cc + 3] = 0;
      T[6 * (r + 3) + cc] = TB[3 * r + cc];
      T[6 * (r + 3) + cc + 3] = TA[3 * r + cc];
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


/* ξ of piece k where the Legendre values are P */
static void strainAtP(const csrStrainModel* m, const double* q, int k, const double* P,
                      double xi[6]) {
  memset(xi, 0, 6 * sizeof(double));
  xi[5] = 1;
  for (int j = m->dof0[k]; j < m->dof0[k] + m->ndof[k]; j++) {
    xi[m->dcomp[j]] += shape(m, j, P) * q[j];
  }
}


void csr_strainAt_(const csrStrainModel* m, const double* q, int k, double s, double xi[6]) {
  double P[CSR_STRAIN_MAX_ORDER + 1];
  double S = m->piece[k].length;
  csr_strainLegendre_(m->pmax, 2 * s / S - 1, P);
  strainAtP(m, q, k, P, xi);
}


/* the Gauss points of the Zanna step [s, s + h] (csr_strainMagnus_, magnusRate) */
static void gaussPoints(double s, double h, double* sa, double* sb) {
  const double g = sqrt(3.0) / 6;
  *sa = s + (0.5 - g) * h;
  *sb = s + (0.5 + g) * h;
}


int csr_strainLegendreTable_(csrStrainModel* m) {
  const int w = m->pmax + 1;
  int nsub = 0;
  for (int k = 0; k < m->npiece; k++) {
    m->gleg0[k] = nsub;
    nsub += m->nsub[k];
  }
  m->gleg = calloc((size_t)nsub * 4 * w, sizeof(double));
  if (!m->gleg) {
    return 1;
  }
  for (int k = 0; k < m->npiece; k++) {
    /* the kinematics' own expressions (csr_strainKinematics_, csr_strainTwists_) */
    const double h = m->piece[k].length / m->nsub[k], S = m->piece[k].length;
    for (int i = 0; i < m->nsub[k]; i++) {
      for (int whole = 0; whole < 2; whole++) {
        double sa, sb;
        gaussPoints(i * h, whole ? h : 0.5 * h, &sa, &sb);
        double* P = m->gleg + ((size_t)(m->gleg0[k] + i) * 4 + 2 * whole) * w;
        csr_strainLegendre_(m->pmax, 2 * sa / S - 1, P);
        csr_strainLegendre_(m->pmax, 2 * sb / S - 1, P + w);
      }
    }
  }
  return 0;
}


const double* csr_strainLegendreAt_(const csrStrainModel* m, int k, int i, int whole, int ab) {
  const int w = m->pmax + 1;
  return m->gleg + ((size_t)(m->gleg0[k] + i) * 4 + 2 * whole + ab) * w;
}


/* csr_strainMagnus_ with the Legendre values at the step's Gauss points given */
static void magnusP(const csrStrainModel* m, const double* q, int k, double h, const double* Pa,
                    const double* Pb, double Om[6], double* dOm);

void csr_strainMagnus_(const csrStrainModel* m, const double* q, int k, double s, double h,
                       double Om[6], double* dOm) {
  double sa, sb, Pa[CSR_STRAIN_MAX_ORDER + 1], Pb[CSR_STRAIN_MAX_ORDER + 1];
  const double S = m->piece[k].length;
  gaussPoints(s, h, &sa, &sb);
  csr_strainLegendre_(m->pmax, 2 * sa / S - 1, Pa);
  csr_strainLegendre_(m->pmax, 2 * sb / S - 1, Pb);
  magnusP(m, q, k, h, Pa, Pb, Om, dOm);
}


static void magnusP(const csrStrainModel* m, const double* q, int k, double h, const double* Pa,
                    const double* Pb, double Om[6], double* dOm) {
  double xa[6], xb[6], Wa[9], Va[9];
  strainAtP(m, q, k, Pa, xa);
  strainAtP(m, q, k, Pb, xb);
  hat3(xa, Wa);
  hat3(xa + 3, Va);
  /* Ω = h/2 (ξa + ξb) + √3 h²/12 ad(ξa) ξb (robot_strain.h), ad(ξa) = [ω^ 0; v^ ω^] row by
   * row over its nonzero entries in column order from a +0 sum: the bits of the full six-term
   * row (a term with a zero entry adds ±0 to a sum that is never -0) */
  const double c2 = sqrt(3.0) * h * h / 12;
  for (int r = 0; r < 3; r++) {
    const double* w = Wa + 3 * r;
    const double* v = Va + 3 * r;
    double ca = 0, cb = 0;
    for (int c = 0; c < 3; c++) {
      if (c != r) {
        ca += w[c] * xb[c];
      }
    }
    for (int c = 0; c < 3; c++) {
      if (c != r) {
        cb += v[c] * xb[c];
      }
    }
    for (int c = 0; c < 3; c++) {
      if (c != r) {
        cb += w[c] * xb[3 + c];
      }
    }
    Om[r] = 0.5 * h * (xa[r] + xb[r]) + c2 * ca;
    Om[3 + r] = 0.5 * h * (xa[3 + r] + xb[3 + r]) + c2 * cb;
  }
  if (!dOm) {
    return;
  }
  double ada[36], adb[36];
  csr_strainAd_(xa, ada);
  csr_strainAd_(xb, adb);
  /* ∂Ω/∂q_j = h/2 (φa + φb) e_c + √3 h²/12 (φb ad(ξa) e_c - φa ad(ξb) e_c) */
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


/* Jt[:, c] = Ad(exp(-Ω)) Jf[:, c] = (Reᵀ a; Reᵀ (b - pe × a)) for the columns c < ncol of
 * the 6 x n Jacobians Jf (a its rows 0-2, b 3-5) and Jt (distinct points). Row by row with
 * every column's arithmetic in the order of the cross product and csu_mulMatTVec3 (so the
 * same bits as a column at a time), which the compiler vectorises over the columns. */
static void adExpColumns(const double Re[9], const double pe[3], const double* restrict Jf,
                         double* restrict Jt, int n, int ncol) {
  const double R0 = Re[0], R1 = Re[1], R2 = Re[2], R3 = Re[3], R4 = Re[4], R5 = Re[5],
               R6 = Re[6], R7 = Re[7], R8 = Re[8], p0 = pe[0], p1 = pe[1], p2 = pe[2];
  const double *a0 = Jf, *a1 = Jf + n, *a2 = Jf + 2 * n;
  const double *b0 = Jf + 3 * n, *b1 = Jf + 4 * n, *b2 = Jf + 5 * n;
  double *w0 = Jt, *w1 = Jt + n, *w2 = Jt + 2 * n, *t0 = Jt + 3 * n, *t1 = Jt + 4 * n,
         *t2 = Jt + 5 * n;
  for (int c = 0; c < ncol; c++) {
    const double x0 = a0[c], x1 = a1[c], x2 = a2[c];
    const double u0 = b0[c] - (p1 * x2 - p2 * x1);
    const double u1 = b1[c] - (p2 * x0 - p0 * x2);
    const double u2 = b2[c] - (p0 * x1 - p1 * x0);
    w0[c] = R0 * x0 + R3 * x1 + R6 * x2;
    w1[c] = R1 * x0 + R4 * x1 + R7 * x2;
    w2[c] = R2 * x0 + R5 * x1 + R8 * x2;
    t0[c] = R0 * u0 + R3 * u1 + R6 * u2;
    t1[c] = R1 * u0 + R4 * u1 + R7 * u2;
    t2[c] = R2 * u0 + R5 * u1 + R8 * u2;
  }
}


/* J[r][jj] += Σ_i T[r][i] dOm[i][jj] (J the piece's first column in a 6 x n Jacobian, dOm
 * 6 x nd): each entry summed over i in order from 0, as a column at a time did, the terms of
 * T's zero block (rows 0-2, columns 3-5) left out (adding ±0 to the sum changes no bit), the
 * columns vectorised */
static void tangentColumns(const double T[36], const double* restrict dOm, int nd,
                           double* restrict J, int n) {
  for (int r = 0; r < 6; r++) {
    const double* Tr = T + 6 * r;
    const double T0 = Tr[0], T1 = Tr[1], T2 = Tr[2], T3 = Tr[3], T4 = Tr[4], T5 = Tr[5];
    double* Jr = J + (size_t)r * n;
    if (r < 3) {
      for (int jj = 0; jj < nd; jj++) {
        double s = 0;
        s += T0 * dOm[jj];
        s += T1 * dOm[nd + jj];
        s += T2 * dOm[2 * nd + jj];
        Jr[jj] += s;
      }
    } else {
      for (int jj = 0; jj < nd; jj++) {
        double s = 0;
        s += T0 * dOm[jj];
        s += T1 * dOm[nd + jj];
        s += T2 * dOm[2 * nd + jj];
        s += T3 * dOm[3 * nd + jj];
        s += T4 * dOm[4 * nd + jj];
        s += T5 * dOm[5 * nd + jj];
        Jr[jj] += s;
      }
    }
  }
}


/* the trig of a kinematics step kept in d->ks (stepPoint's layout) */
static void trigFromSteps(const double* ks, csrTrig* tg) {
  tg->th2 = ks[12];
  tg->th = ks[13];
  tg->sn = ks[14];
  tg->cs = ks[15];
}


/* pose and Jacobian at point `to` from point `from` through the step Ω (dOm over piece k's
 * unknowns, NULL for a rigid step) */
static void stepPoint(const csrStrainModel* m, csrStrainData* d, int from, int to, int k,
                      const double Om[6], const double* dOm, int want_J, int col0) {
  double Re[9], pe[3], tmp[3];
  csrTrig tg;
  trigOf(Om, &tg);
  expWith(Om, &tg, Re, pe);
  double* ks = d->ks + 16 * to; /* the velocity products' (csr_strainTwistRates_) */
  memcpy(ks, Re, sizeof Re);
  memcpy(ks + 9, pe, sizeof pe);
  ks[12] = tg.th2;
  ks[13] = tg.th;
  ks[14] = tg.sn;
  ks[15] = tg.cs;
  csu_mulMat3(d->R + 9 * to, d->R + 9 * from, Re);
  csu_mulMatVec3(tmp, d->R + 9 * from, pe);
  csu_add3(d->x + 3 * to, d->x + 3 * from, tmp);
  if (!want_J) {
    return;
  }
  /* the columns from col0 on (0: all; a midpoint of want_J 4: its own piece's): each
   * column's arithmetic is its own, so the same bits as a whole pass gives them */
  const int n = m->n, ncol = m->dof0[k] + m->ndof[k];
  adExpColumns(Re, pe, d->J + (size_t)from * 6 * n + col0, d->J + (size_t)to * 6 * n + col0, n,
               ncol - col0);
  double* Jt = d->J + (size_t)to * 6 * n;
  /* Jt's columns from ncol on are zero: d->J and d->J0 (which swaps or copies with it) are
   * allocated zeroed (csr_strainDataCreate) and only this step and tangentColumns write a
   * point's Jacobian, both below its ncol, the same ncol at every call (the point's piece) */
  if (dOm) {
    double T[36];
    tangentWith(Om, &tg, T);
    tangentColumns(T, dOm, m->ndof[k], Jt + m->dof0[k], n);
  }
}


void csr_strainKinematics_(const csrStrainModel* m, csrStrainData* d, int want_J) {
  /* want_J 2: the Jacobians at the chain points alone (the midpoints are leaves: nothing
   * downstream of them needs theirs), poses everywhere; 3: the poses at the chain points
   * alone (the contact's shapes end there), no Jacobians, the midpoints' left as they were */
  const int chain_only = want_J == 3;
  if (chain_only) {
    want_J = 0;
  }
  /* want_J 4: the midpoints' own columns alone (mid_col0 their piece's first) */
  const int mid_own = want_J == 4;
  if (mid_own) {
    want_J = 2;
  }
  const int mid_J = want_J == 1 || mid_own;
  /* want_J 5: the poses (as 0) and, at each flexible chain step, T(Ω) and ∂Ω/∂q into d->kst
   * (a kept iterate's twists and Sᵀ L: csr_strainChainTwistsNoJ_, csr_strainChainProjectNoJ_) */
  const int steps_T = want_J == 5;
  if (steps_T) {
    want_J = 0;
  }
  d->kin_gen++; /* csr_strainPointTwists_'s memo */
  d->ks_ok = 0;
  d->kst_ok = 0;
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
        if (!chain_only) {
          stepPoint(m, d, p, p + 1, k, Oh, NULL, mid_J, mid_own ? m->dof0[k] : 0);
        }
        stepPoint(m, d, p, p + 2, k, Of, NULL, want_J, 0);
        continue;
      }
      double Om[6];
      if (!chain_only) {
        magnusP(m, d->q, k, 0.5 * h, csr_strainLegendreAt_(m, k, i, 0, 0),
                csr_strainLegendreAt_(m, k, i, 0, 1), Om, mid_J ? dOm : NULL);
        stepPoint(m, d, p, p + 1, k, Om, mid_J ? dOm : NULL, mid_J, mid_own ? m->dof0[k] : 0);
      }
      double* kst = d->kst + (size_t)(p + 2) * CSR_STRAIN_KST;
      magnusP(m, d->q, k, h, csr_strainLegendreAt_(m, k, i, 1, 0),
              csr_strainLegendreAt_(m, k, i, 1, 1), Om,
              want_J ? dOm : (steps_T ? kst + 36 : NULL));
      stepPoint(m, d, p, p + 2, k, Om, want_J ? dOm : NULL, want_J, 0);
      if (steps_T) {
        csrTrig tg;
        trigFromSteps(d->ks + 16 * (p + 2), &tg);
        tangentWith(Om, &tg, kst);
      }
    }
  }
  d->kst_ok = steps_T;
  d->kin_valid = chain_only ? 0 : (want_J == 1 ? 2 : 1);
  if (!chain_only) {
    memcpy(d->ks_q, d->q, (size_t)m->n * sizeof(double));
    d->ks_ok = 1;
  }
  if (!chain_only) {
    d->kin_chain = want_J != 0; /* want_J 3 leaves J as it was */
    d->kin_midown = mid_own;
  }
}


/* Ad(exp(-Ω))ᵀ of one Zanna step applied to a wrench W (μ; φ) at its end point: the wrench
 * at its start, (Re μ + pe × Re φ; Re φ) for exp(Ω) = (Re, pe) (the transpose of stepPoint's
 * column map (a; b) -> (Reᵀ a; Reᵀ (b - pe × a))) */
static void adExpTApply(const double Re[9], const double pe[3], const double W[6],
                        double out[6]) {
  double rf[3], t[3];
  csu_mulMatVec3(rf, Re, W + 3);
  csu_mulMatVec3(out, Re, W);
  csu_cross3(t, pe, rf);
  csu_add3(out, out, t);
  memcpy(out + 3, rf, sizeof rf);
}


void csr_strainAdExpTApply_(const double Re[9], const double pe[3], const double W[6],
                            double out[6]) {
  adExpTApply(Re, pe, W, out);
}


/* a flexible step's share on its piece's nd unknowns of a wrench W at its end point:
 * Qk += (∂Ω/∂q)ᵀ T(Ω)ᵀ W (the own columns T ∂Ω/∂q of the step's Jacobian, transposed) */
static void ownShare(const double T[36], const double* dOm, int nd, const double W[6],
                     double* Qk) {
  double u[6];
  for (int i = 0; i < 6; i++) {
    double t = 0;
    for (int r = 0; r < 6; r++) {
      t += T[6 * r + i] * W[r];
    }
    u[i] = t;
  }
  for (int jj = 0; jj < nd; jj++) {
    double t = 0;
    for (int i = 0; i < 6; i++) {
      t += dOm[nd * i + jj] * u[i];
    }
    Qk[jj] += t;
  }
}


/* one step's share of the adjoint recursion (csr_strainProject_): the wrench W_to at the step's
 * end point adds Ad(exp(-Ω))ᵀ W_to to its start's (acc) and (∂Ω/∂q)ᵀ T(Ω)ᵀ W_to to piece k's
 * generalised forces (a flexible piece) */
static void projectStep(const csrStrainModel* m, const double* q, int k, double s, double h,
                        const double W_to[6], double acc[6], double* Q) {
  double Om[6] = {0, 0, 0, 0, 0, h}, dOm[6 * CSR_STRAIN_MAX_PIECE_DOF];
  if (!m->rigid[k]) {
    csr_strainMagnus_(m, q, k, s, h, Om, dOm);
  }
  double Re[9], pe[3], back[6];
  csr_strainExp_(Om, Re, pe);
  adExpTApply(Re, pe, W_to, back);
  for (int i = 0; i < 6; i++) {
    acc[i] += back[i];
  }
  if (m->rigid[k]) {
    return;
  }
  double T[36];
  csr_strainTangent_(Om, T);
  ownShare(T, dOm, m->ndof[k], W_to, Q + m->dof0[k]);
}


void csr_strainProject_(const csrStrainModel* m, const double* q, const double* F, double Fb[6],
                        double* Q) {
  memset(Q, 0, (size_t)m->n * sizeof(double));
  /* W: the wrench of everything from the current chain point to the tip, at that point */
  double W[6];
  memcpy(W, F + 6 * (m->np - 1), sizeof W);
  for (int k = m->npiece - 1; k >= 0; k--) {
    const double h = m->piece[k].length / m->nsub[k];
    for (int i = m->nsub[k] - 1; i >= 0; i--) {
      const int p = m->pt0[k] + 2 * i;
      double acc[6];
      memcpy(acc, F + 6 * p, sizeof acc);
      projectStep(m, q, k, i * h, h, W, acc, Q);                 /* p -> p + 2 (the chain) */
      projectStep(m, q, k, i * h, 0.5 * h, F + 6 * (p + 1), acc, Q); /* p -> p + 1 (a leaf) */
      memcpy(W, acc, sizeof W);
    }
  }
  /* the hip point moves with the base: Ad = I */
  memcpy(Fb, W, sizeof W);
}


/* ad(Ω) (a; b) = (ω × a; v × a + ω × b) */
static void adApply(const double Om[6], const double in[6], double out[6]) {
  double t[3];
  csu_cross3(out, Om, in);
  csu_cross3(out + 3, Om + 3, in);
  csu_cross3(t, Om, in + 3);
  csu_add3(out + 3, out + 3, t);
}


static void tangentApplyWith(const double Om[6], const csrTrig* tg, const double v[6],
                             double out[6]) {
  double c[5], P[6], Q[6];
  tangentCoefficients(tg, c);
  memcpy(out, v, 6 * sizeof(double));
  memcpy(P, v, sizeof P);
  for (int j = 1; j <= 4; j++) {
    adApply(Om, P, Q);
    memcpy(P, Q, sizeof P);
    for (int i = 0; i < 6; i++) {
      out[i] += c[j] * P[i];
    }
  }
}


void csr_strainTangentApply_(const double Om[6], const double v[6], double out[6]) {
  csrTrig tg;
  trigOf(Om, &tg);
  tangentApplyWith(Om, &tg, v, out);
}


/* ξ at the Gauss points a, b (Legendre values Pa, Pb) of piece k at q, and ξ̇ there at η:
 * ξ = Σ_j Φ_j q_j (the constant stretch added by the caller) and ξ̇ = Σ_j Φ_j η_j, the four sums
 * in one pass over the piece's unknowns */
static void strainRates4(const csrStrainModel* m, const double* q, const double* eta, int k,
                         const double* Pa, const double* Pb, double xa[6], double xb[6],
                         double xad[6], double xbd[6]) {
  memset(xa, 0, 6 * sizeof(double));
  memset(xb, 0, 6 * sizeof(double));
  memset(xad, 0, 6 * sizeof(double));
  memset(xbd, 0, 6 * sizeof(double));
  for (int j = m->dof0[k]; j < m->dof0[k] + m->ndof[k]; j++) {
    const int c = m->dcomp[j], o = m->dorder[j];
    xa[c] += Pa[o] * q[j];
    xb[c] += Pb[o] * q[j];
    xad[c] += Pa[o] * eta[j];
    xbd[c] += Pb[o] * eta[j];
  }
}


/* Ω of one Zanna step (as csr_strainMagnus_) and its rate Ω̇ = (∂Ω/∂q) η; if Omdd is not
 * NULL, Ω̈ = (∂Ω̇/∂q) η = 2 c ad(ξ̇_a) ξ̇_b (ξ_a, ξ_b are affine in q, ξ̇ = ∂ξ/∂q η) */
static void magnusRate(const csrStrainModel* m, const double* q, const double* eta, int k,
                       int i, int whole, double h, double Om[6], double Omd[6],
                       double* Omdd) {
  const double* Pa = csr_strainLegendreAt_(m, k, i, whole, 0);
  const double* Pb = csr_strainLegendreAt_(m, k, i, whole, 1);
  double xa[6], xb[6], xad[6], xbd[6], t1[6], t2[6], t3[6];
  strainRates4(m, q, eta, k, Pa, Pb, xa, xb, xad, xbd);
  xa[5] += 1;
  xb[5] += 1;
  const double c2 = sqrt(3.0) * h * h / 12;
  adApply(xa, xb, t1);
  adApply(xad, xb, t2);
  adApply(xa, xbd, t3);
  for (int r = 0; r < 6; r++) {
    Om[r] = 0.5 * h * (xa[r] + xb[r]) + c2 * t1[r];
    Omd[r] = 0.5 * h * (xad[r] + xbd[r]) + c2 * (t2[r] + t3[r]);
  }
  if (Omdd) {
    adApply(xad, xbd, t1);
    for (int r = 0; r < 6; r++) {
      Omdd[r] = 2 * c2 * t1[r];
    }
  }
}


/* V_to = Ad(exp(-Ω)) V_from + T(Ω) Ω̇ */
static void twistStep(const double Om[6], const double Omd[6], const double Vf[6],
                      double Vt[6]) {
  double Re[9], pe[3], pxa[3], u[3], tw[6];
  csrTrig tg;
  trigOf(Om, &tg);
  expWith(Om, &tg, Re, pe);
  csu_cross3(pxa, pe, Vf);
  csu_sub3(u, Vf + 3, pxa);
  csu_mulMatTVec3(Vt, Re, Vf);
  csu_mulMatTVec3(Vt + 3, Re, u);
  tangentApplyWith(Om, &tg, Omd, tw);
  for (int r = 0; r < 6; r++) {
    Vt[r] += tw[r];
  }
}


void csr_strainTwists_(const csrStrainModel* m, const double* q, const double* eta,
                       const double Vb[6], double* V) {
  memcpy(V, Vb, 6 * sizeof(double));
  for (int k = 0; k < m->npiece; k++) {
    double h = m->piece[k].length / m->nsub[k];
    for (int i = 0; i < m->nsub[k]; i++) {
      int p = m->pt0[k] + 2 * i;
      double Om[6], Omd[6] = {0, 0, 0, 0, 0, 0};
      if (m->rigid[k]) {
        const double Oh[6] = {0, 0, 0, 0, 0, 0.5 * h}, Of[6] = {0, 0, 0, 0, 0, h};
        twistStep(Oh, Omd, V + 6 * p, V + 6 * (p + 1));
        twistStep(Of, Omd, V + 6 * p, V + 6 * (p + 2));
        continue;
      }
      magnusRate(m, q, eta, k, i, 0, 0.5 * h, Om, Omd, NULL);
      twistStep(Om, Omd, V + 6 * p, V + 6 * (p + 1));
      magnusRate(m, q, eta, k, i, 1, h, Om, Omd, NULL);
      twistStep(Om, Omd, V + 6 * p, V + 6 * (p + 2));
    }
  }
}


/* tangentCoefficients' c_j (the same bits) and dc_j = ∂c_j/∂(θ²) (c_0 = 1: dc_0 = 0), the
 * same two branches: the folded series differentiated term by term in t2 = θ² (t4 = t2²),
 * Selig's closed forms c_j = ±N_j / (2 θ^(j+1)) by c_j' / (2 θ) with
 * c_j' = ±(θ N_j' - (j + 1) N_j) / (2 θ^(j+2)) */
static void tangentCoefficientRates(const csrTrig* tg, double c[5], double dc[5]) {
  const double th = tg->th;
  if (th < CSR_STRAIN_SERIES_THETA) {
    double s[CSR_STRAIN_SERIES_TERMS + 1], ds[CSR_STRAIN_SERIES_TERMS + 1], f = 1;
    const double t2 = th * th, t4 = t2 * t2;
    for (int j = 0; j <= CSR_STRAIN_SERIES_TERMS; j++) {
      s[j] = f;
      ds[j] = 0;
      f *= -1.0 / (j + 2);
    }
    for (int j = CSR_STRAIN_SERIES_TERMS; j >= 5; j--) {
      ds[j - 2] -= 2 * s[j] + 2 * t2 * ds[j];
      ds[j - 4] -= 2 * t2 * s[j] + t4 * ds[j];
      s[j - 2] -= 2 * t2 * s[j];
      s[j - 4] -= t4 * s[j];
    }
    memcpy(c, s, 5 * sizeof(double));
    memcpy(dc, ds, 5 * sizeof(double));
    return;
  }
  tangentCoefficients(tg, c);
  const double sn = tg->sn, cs = tg->cs, t2 = th * th, t3 = t2 * th, t4 = t3 * th;
  const double n1 = 4 - 4 * cs - th * sn, n1d = 3 * sn - th * cs;
  const double n2 = 4 * th - 5 * sn + th * cs, n2d = 4 - 4 * cs - th * sn;
  const double n3 = 2 - 2 * cs - th * sn, n3d = sn - th * cs;
  const double n4 = 2 * th - 3 * sn + th * cs, n4d = 2 - 2 * cs - th * sn;
  dc[0] = 0;
  dc[1] = -(th * n1d - 2 * n1) / (4 * t4);
  dc[2] = (th * n2d - 3 * n2) / (4 * t4 * th);
  dc[3] = -(th * n3d - 4 * n3) / (4 * t4 * t2);
  dc[4] = (th * n4d - 5 * n4) / (4 * t4 * t3);
}


/* out = Ad(exp(-Ω)) in, exp(Ω) = (Re, pe): (Reᵀ ω; Reᵀ (v - pe × ω)) (twistStep's own) */
static void adExpInvApply(const double Re[9], const double pe[3], const double in[6],
                          double out[6]) {
  double pxa[3], u[3];
  csu_cross3(pxa, pe, in);
  csu_sub3(u, in + 3, pxa);
  csu_mulMatTVec3(out, Re, in);
  csu_mulMatTVec3(out + 3, Re, u);
}


/* One step of the twist recursion and of its rate along q (η and V_b fixed): V_to = Ad(e⁻Ω)
 * V_from + ψ with ψ = T(Ω) Ω̇ (twistStep), and its directional derivative in q along η
 *   A_to = Ad(e⁻Ω) A_from + ad(V_to) ψ + ψ̇,   ψ̇ = T(Ω) Ω̈ + DT(Ω)[Ω̇] Ω̇,
 * (d/dε Ad(e^-Ω) = -ad(T(Ω) Ω̇) Ad(e^-Ω), and -ad(ψ) (V_to - ψ) = ad(V_to) ψ). With T(Ω) =
 * Σ_j c_j(θ) ad(Ω)^j and P_j = ad(Ω)^j Ω̇: DT[Ω̇] Ω̇ = Σ_j dc_j δ(θ²) P_j + Σ_j c_j Σ_{i<j}
 * ad(Ω)^i ad(Ω̇) P_{j-1-i}, δ(θ²) = 2 ω·ω̇, the i = j-1 terms zero (ad(Ω̇) Ω̇ = 0). Grouped by
 * the power of ad(Ω) and summed by Horner with T(Ω) Ω̈ (4 products by ad(Ω), 3 by ad(Ω̇)):
 *   T Ω̈ + Σ_j c_j D(ad^j)[Ω̇] Ω̇ = Σ_i ad(Ω)^i (c_i Ω̈ + ad(Ω̇) G_i),
 *   G_0 = c2 P1 + c3 P2 + c4 P3, G_1 = c3 P1 + c4 P2, G_2 = c4 P1, G_3 = G_4 = 0.
 * Omd NULL: a rigid step (Ω̇ = Ω̈ = 0, ψ = ψ̇ = 0). ks not NULL: the kinematics' exp(Ω) and θ,
 * sin θ, cos θ of this step (d->ks, the same Ω to round-off: csr_strainMagnus_'s expressions),
 * else formed here. */
static void twistRateStep(const double Om[6], const double* Omd, const double* Omdd,
                          const double* ks, const double Vf[6], const double Af[6], double Vt[6],
                          double At[6]) {
  double Rs[9], ps[3];
  const double *Re = Rs, *pe = ps;
  csrTrig tg;
  if (ks) {
    Re = ks;
    pe = ks + 9;
    tg.th2 = ks[12];
    tg.th = ks[13];
    tg.sn = ks[14];
    tg.cs = ks[15];
  } else {
    trigOf(Om, &tg);
    expWith(Om, &tg, Rs, ps);
  }
  adExpInvApply(Re, pe, Vf, Vt);
  adExpInvApply(Re, pe, Af, At);
  if (!Omd) {
    return;
  }
  double c[5], dc[5], P[5][6], psi[6], z[6], g[6], t[6];
  tangentCoefficientRates(&tg, c, dc);
  /* ψ exactly as tangentApplyWith forms it (twistStep's bits) */
  memcpy(P[0], Omd, sizeof P[0]);
  memcpy(psi, Omd, sizeof psi);
  for (int j = 1; j <= 4; j++) {
    adApply(Om, P[j - 1], P[j]);
    for (int i = 0; i < 6; i++) {
      psi[i] += c[j] * P[j][i];
    }
  }
  for (int i = 0; i < 6; i++) {
    z[i] = c[4] * Omdd[i];
  }
  for (int p = 3; p >= 0; p--) {
    adApply(Om, z, t);
    for (int i = 0; i < 6; i++) {
      z[i] = t[i] + c[p] * Omdd[i];
    }
    if (p <= 2) {
      for (int i = 0; i < 6; i++) {
        g[i] = c[p + 2] * P[1][i] + (p <= 1 ? c[p + 3] * P[2][i] : 0) +
               (p == 0 ? c[4] * P[3][i] : 0);
      }
      adApply(Omd, g, t);
      for (int i = 0; i < 6; i++) {
        z[i] += t[i];
      }
    }
  }
  const double dth2 = 2 * csu_dot3(Om, Omd);
  for (int i = 0; i < 6; i++) {
    Vt[i] += psi[i];
    z[i] += dth2 * (dc[1] * P[1][i] + dc[2] * P[2][i] + dc[3] * P[3][i] + dc[4] * P[4][i]);
  }
  adApply(Vt, psi, t);
  for (int i = 0; i < 6; i++) {
    At[i] += t[i] + z[i];
  }
}


const double* csr_strainStepsAt_(const csrStrainModel* m, const csrStrainData* d) {
  if (!d->ks_ok || memcmp(d->ks_q, d->q, (size_t)m->n * sizeof(double)) != 0) {
    return NULL;
  }
  return d->ks;
}


void csr_strainTwistRates_(const csrStrainModel* m, const double* q, const double* eta,
                           const double Vb[6], const double* ks, double* V, double* A) {
  memcpy(V, Vb, 6 * sizeof(double));
  memset(A, 0, 6 * sizeof(double));
  for (int k = 0; k < m->npiece; k++) {
    const double h = m->piece[k].length / m->nsub[k];
    for (int i = 0; i < m->nsub[k]; i++) {
      const int p = m->pt0[k] + 2 * i;
      double* V0 = V + 6 * p;
      double* A0 = A + 6 * p;
      if (m->rigid[k]) {
        const double Oh[6] = {0, 0, 0, 0, 0, 0.5 * h}, Of[6] = {0, 0, 0, 0, 0, h};
        twistRateStep(Oh, NULL, NULL, ks ? ks + 16 * (p + 1) : NULL, V0, A0, V0 + 6, A0 + 6);
        twistRateStep(Of, NULL, NULL, ks ? ks + 16 * (p + 2) : NULL, V0, A0, V0 + 12, A0 + 12);
        continue;
      }
      for (int whole = 0; whole < 2; whole++) {
        double Om[6], Omd[6], Omdd[6];
        magnusRate(m, q, eta, k, i, whole, whole ? h : 0.5 * h, Om, Omd, Omdd);
        const int to = p + 1 + whole;
        twistRateStep(Om, Omd, Omdd, ks ? ks + 16 * to : NULL, V0, A0, V + 6 * to, A + 6 * to);
      }
    }
  }
}


void csr_strainChainTwistsNoJ_(const csrStrainModel* m, csrStrainData* d) {
  double* V = d->Vp;
  d->vp_gen = -1; /* not csr_strainPointTwists_'s memo */
  memcpy(V, d->Vb, 6 * sizeof(double));
  for (int k = 0; k < m->npiece; k++) {
    for (int i = 0; i < m->nsub[k]; i++) {
      const int p = m->pt0[k] + 2 * i, to = p + 2;
      const double* ks = d->ks + 16 * to;
      /* V_to = Ad(exp(-Ω)) V_p + T(Ω) Ω̇ (twistStep), exp(Ω) and θ the kinematics' own */
      adExpInvApply(ks, ks + 9, V + 6 * p, V + 6 * to);
      if (m->rigid[k]) {
        continue; /* Ω̇ = 0 */
      }
      /* Ω̇ = (∂Ω/∂q) η on the piece's unknowns, T(Ω) Ω̇: the kinematics' own (want_J 5) */
      const double* T = d->kst + (size_t)to * CSR_STRAIN_KST;
      const double* dOm = T + 36;
      const double* et = d->eta + m->dof0[k];
      const int nd = m->ndof[k];
      double Omd[6];
      for (int c = 0; c < 6; c++) {
        double t = 0;
        for (int jj = 0; jj < nd; jj++) {
          t += dOm[nd * c + jj] * et[jj];
        }
        Omd[c] = t;
      }
      for (int r = 0; r < 6; r++) {
        double t = 0;
        for (int c = 0; c < 6; c++) {
          t += T[6 * r + c] * Omd[c];
        }
        V[6 * to + r] += t;
      }
    }
  }
}


void csr_strainChainProjectNoJ_(const csrStrainModel* m, const csrStrainData* d, const double* F,
                                int plast, double* Q) {
  /* W: the wrenches at the chain points from the current one to plast, at the current one */
  double W[6] = {0, 0, 0, 0, 0, 0};
  for (int k = m->npiece - 1; k >= 0; k--) {
    for (int i = m->nsub[k] - 1; i >= 0; i--) {
      const int p = m->pt0[k] + 2 * i, to = p + 2;
      if (to > plast) {
        continue;
      }
      for (int r = 0; r < 6; r++) {
        W[r] += F[6 * to + r];
      }
      const double* ks = d->ks + 16 * to;
      if (!m->rigid[k]) {
        /* J_to's own columns are T(Ω) ∂Ω/∂q (stepPoint): their share (∂Ω/∂q)ᵀ T(Ω)ᵀ W, T
         * and ∂Ω/∂q the kinematics' (want_J 5) */
        const double* T = d->kst + (size_t)to * CSR_STRAIN_KST;
        ownShare(T, T + 36, m->ndof[k], W, Q + m->dof0[k]);
      }
      /* the earlier columns J_to = Ad(exp(-Ω)) J_p: W moves to p */
      double back[6];
      adExpTApply(ks, ks + 9, W, back);
      memcpy(W, back, sizeof W);
    }
  }
}

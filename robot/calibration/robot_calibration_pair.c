/* robot_calibration_pair.c: the bend base of CSR_CAL_RULE_RBF_PAIR (robot_calibration_model.h):
 * the single-chamber superposition with one factor per opposite chamber pair, fitted to the
 * bending modes; the modes' residuals over it are interpolated as in CSR_CAL_RULE_RBF.
 *
 * Why. The superposition -Σ_j θ1(p_j) ĉ_j groups the chambers in the two opposite pairs
 * (Ω1, Ω3) along the diagonal d1 and (Ω2, Ω4) along d2: each pair bends along its diagonal by
 * θ1(p_hi) - θ1(p_lo). The FE bends the fitted modes differently from that in two ways with a
 * clear physical
 * reading (shipped table, 0.4 MPa, FE / superposition along -m̂): a pair bends LESS when the
 * other pair, which lies on its neutral axis, is pressurised (O12 0.88, O124 0.73: those chambers'
 * fibres tighten and stiffen the section, the probed EI rises 1.3x by 0.3 MPa), and MORE when its
 * own low chamber is pressurised (O1O234r05 1.05, and held-out H7, Ω3 at 0.7 p, 1.17; the run but
 * unshipped O1O3r05 1.10: the opposite chamber stretches the segment by up to 25 %, so the same
 * curvature turns the end tangent further). H7 misses under CSR_CAL_RULE_RBF by that bend
 * magnitude alone (5.1 deg per segment at 0.4 MPa, -10 %; its stretch is within 0.001 and its
 * bend direction within 0.2 deg: README "Calibration").
 * How. Along each diagonal the pair's superposed bend is multiplied by
 *   K = exp(k0 n + k1 l + k2 n^2 + k3 l^2),
 * n the sum of the other pair's pressures (on the neutral axis), l the pair's lower pressure
 * (MPa), per segment; K = 1 for a single chamber, so Ω1 alone stays the single-chamber curve.
 * k is the least-squares fit of the bend vectors (rad) of every row of the bending modes used
 * (all but O1, O13, O1234; a mode left out for cross-validation is left out of the fit too) by
 * Levenberg-Marquardt. Shipped table: k ~ (0.10-0.11, 0.03-0.06, -0.61--0.63, 1.96-2.21) per
 * MPa, MPa^2 for the three segments; with the refining modes merged in the fit moves little
 * (docs/notes/code_measurements.md "Calibration: the pair factor with the refining modes").
 * Alternatives measured (tools/calib_rules.py, docs/bench/calib_rules_2026-12-03): the same
 * factor linear in n and l only (H2 misses from 0.15 MPa: the linear term acts already at low
 * pressure where the superposition is right), quadratic only (H4 8.0 mm), and the curvature
 * superposition times the pattern's stretch (θ1 / λ1 x λ: a purely kinematic correction, H7
 * still 20.9 mm; with the pair factor on top no better than the factor alone). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "robot_calibration_internal.h"

/* Levenberg-Marquardt: iterations, forward-difference step in k (1e-7: the factor is smooth,
 * k is O(1)), initial damping; the fit stops when a step changes the cost by less than
 * PAIR_COST_RTOL relative */
#define PAIR_MAX_IT 100
#define PAIR_FD_STEP 1e-7
#define PAIR_LAMBDA0 1e-3
#define PAIR_COST_RTOL 1e-14
/* a fit is kept when K stays within these bounds at every pressure up to the range; otherwise
 * the rule falls back to K = 1 (the plain superposition + RBF) */
#define PAIR_K_MIN 0.2
#define PAIR_K_MAX 5.0

/* one fitted row: canonical pressures (MPa) and the FE bend vector of the segment (rad) */
typedef struct {
  double pc[4];
  double b[2];
} PairRow;

static double pairFactor(const double k[CSR_CAL_NPAIR], double n, double l);
static void pairBendK(const csrCalCurve* base, const double k[CSR_CAL_NPAIR], int s,
                      const double pc[4], double bend[2]);
static double pairCost(const csrCalCurve* base, const double k[CSR_CAL_NPAIR], int s,
                       const PairRow* rows, int n, double* r);
static int solve4(double A[CSR_CAL_NPAIR][CSR_CAL_NPAIR], double b[CSR_CAL_NPAIR]);


/* the factor of one diagonal: n the other pair's sum, l this pair's lower pressure (MPa) */
static double pairFactor(const double k[CSR_CAL_NPAIR], double n, double l) {
  return exp(k[0] * n + k[1] * l + k[2] * n * n + k[3] * l * l);
}


/* -Σ over the two diagonals of (θ1(p_hi) - θ1(p_lo)) K ĉ, grouped as csr_calSuperposeBend_ */
static void pairBendK(const csrCalCurve* base, const double k[CSR_CAL_NPAIR], int s,
                      const double pc[4], double bend[2]) {
  double t[4];
  for (int j = 0; j < 4; j++) {
    double q[NB];
    t[j] = 0;
    if (pc[j] > 0) {
      csr_calCurveEval_(base, pc[j], s, q);
      t[j] = q[B_THETA];
    }
  }
  const double K1 = pairFactor(k, pc[1] + pc[3], fmin(pc[0], pc[2]));
  const double K2 = pairFactor(k, pc[0] + pc[2], fmin(pc[1], pc[3]));
  const double g1 = (t[0] - t[2]) * K1, g2 = (t[1] - t[3]) * K2;
  bend[0] = -RSQ2 * (g1 + g2);
  bend[1] = -RSQ2 * (g1 - g2);
}


void csr_calPairBend_(const csrCalModel* m, int s, const double pc[4], double bend[2]) {
  pairBendK(&m->base, m->kpair[s], s, pc, bend);
}


/* the residuals r (2 n: model - FE, rad) and the cost Σ r^2 */
static double pairCost(const csrCalCurve* base, const double k[CSR_CAL_NPAIR], int s,
                       const PairRow* rows, int n, double* r) {
  double cost = 0;
  for (int i = 0; i < n; i++) {
    double b[2];
    pairBendK(base, k, s, rows[i].pc, b);
    r[2 * i] = b[0] - rows[i].b[0];
    r[2 * i + 1] = b[1] - rows[i].b[1];
    cost += r[2 * i] * r[2 * i] + r[2 * i + 1] * r[2 * i + 1];
  }
  return cost;
}


/* solve A x = b (4 x 4, symmetric positive definite after damping) in place by Gaussian
 * elimination with partial pivoting; 0 if singular */
static int solve4(double A[CSR_CAL_NPAIR][CSR_CAL_NPAIR], double b[CSR_CAL_NPAIR]) {
  enum { N = CSR_CAL_NPAIR };
  for (int c = 0; c < N; c++) {
    int piv = c;
    for (int i = c + 1; i < N; i++) {
      if (fabs(A[i][c]) > fabs(A[piv][c])) {
        piv = i;
      }
    }
    if (!(fabs(A[piv][c]) > 0)) {
      return 0;
    }
    for (int j = 0; j < N; j++) {
      const double t = A[c][j];
      A[c][j] = A[piv][j], A[piv][j] = t;
    }
    const double tb = b[c];
    b[c] = b[piv], b[piv] = tb;
    for (int i = c + 1; i < N; i++) {
      const double f = A[i][c] / A[c][c];
      for (int j = c; j < N; j++) A[i][j] -= f * A[c][j];
      b[i] -= f * b[c];
    }
  }
  for (int i = N - 1; i >= 0; i--) {
    double v = b[i];
    for (int j = i + 1; j < N; j++) v -= A[i][j] * b[j];
    b[i] = v / A[i][i];
  }
  return 1;
}


int csr_calPairFit_(csrCalModel* m, const csrCalCase* const mode[CSR_CAL_NROLE], int s) {
  enum { N = CSR_CAL_NPAIR };
  memset(m->kpair[s], 0, sizeof m->kpair[s]);
  int cap = 0;
  for (int r = 0; r < CSR_CAL_NROLE; r++) cap += mode[r] ? mode[r]->m : 0;
  PairRow* rows = malloc((size_t)cap * sizeof *rows);
  double* r = malloc((size_t)(2 * cap) * (N + 1) * sizeof(double));
  if (!rows || !r) {
    free(rows), free(r);
    return 0;
  }
  /* every row above rest of the bending modes (the elongation modes bend by 0 by symmetry and
   * O1 is the base itself) */
  int n = 0;
  for (int q = 0; q < CSR_CAL_NROLE; q++) {
    const csrCalCase* c = mode[q];
    if (!c || q == CSR_CAL_O1 || q == CSR_CAL_O13 || q == CSR_CAL_O1234) {
      continue;
    }
    for (int i = 1; i < c->m && c->pressure[i] <= m->p_max + P_RANGE_TOL; i++) {
      for (int j = 0; j < 4; j++) rows[n].pc[j] = c->ratio[j] * c->pressure[i];
      rows[n].b[0] = c->bend[6 * i + 2 * s] - c->bend[2 * s];
      rows[n].b[1] = c->bend[6 * i + 2 * s + 1] - c->bend[2 * s + 1];
      n++;
    }
  }
  /* Levenberg-Marquardt from K = 1, Jacobian by forward differences */
  double k[N] = {0, 0, 0, 0}, lambda = PAIR_LAMBDA0;
  double* r0 = r;
  double* J = r + 2 * cap; /* (N x 2n) */
  double cost = n >= N ? pairCost(&m->base, k, s, rows, n, r0) : NAN;
  for (int it = 0; n >= N && it < PAIR_MAX_IT; it++) {
    for (int a = 0; a < N; a++) {
      double kh[N];
      memcpy(kh, k, sizeof k);
      kh[a] += PAIR_FD_STEP;
      pairCost(&m->base, kh, s, rows, n, J + a * 2 * cap);
      for (int i = 0; i < 2 * n; i++) {
        J[a * 2 * cap + i] = (J[a * 2 * cap + i] - r0[i]) / PAIR_FD_STEP;
      }
    }
    double JtJ[N][N], g[N];
    for (int a = 0; a < N; a++) {
      g[a] = 0;
      for (int i = 0; i < 2 * n; i++) g[a] += J[a * 2 * cap + i] * r0[i];
      for (int b = 0; b < N; b++) {
        JtJ[a][b] = 0;
        for (int i = 0; i < 2 * n; i++) JtJ[a][b] += J[a * 2 * cap + i] * J[b * 2 * cap + i];
      }
    }
    /* damped steps until one lowers the cost */
    int accepted = 0;
    double change = 0;
    for (int tries = 0; tries < 20 && !accepted; tries++) {
      double A[N][N], d[N], kt[N];
      for (int a = 0; a < N; a++) {
        for (int b = 0; b < N; b++) A[a][b] = JtJ[a][b];
        A[a][a] *= 1 + lambda;
        d[a] = -g[a];
      }
      if (!solve4(A, d)) {
        lambda *= 10;
        continue;
      }
      for (int a = 0; a < N; a++) kt[a] = k[a] + d[a];
      double ct = 0;
      for (int i = 0; i < n; i++) {
        double b[2];
        pairBendK(&m->base, kt, s, rows[i].pc, b);
        ct += (b[0] - rows[i].b[0]) * (b[0] - rows[i].b[0]) +
              (b[1] - rows[i].b[1]) * (b[1] - rows[i].b[1]);
      }
      if (ct < cost) {
        change = cost - ct;
        memcpy(k, kt, sizeof k);
        cost = pairCost(&m->base, k, s, rows, n, r0);
        lambda = fmax(lambda / 10, 1e-12);
        accepted = 1;
      } else {
        lambda *= 10;
      }
    }
    if (!accepted || change <= PAIR_COST_RTOL * cost) {
      break;
    }
  }
  /* keep a finite fit whose factor stays moderate over the range; else K = 1 */
  int ok = n >= N;
  for (int a = 0; a < N && ok; a++) ok = isfinite(k[a]);
  for (int q = 0; q <= 10 && ok; q++) {
    for (int w = 0; w <= 10 && ok; w++) {
      const double K = pairFactor(k, 0.2 * q * m->p_max, 0.1 * w * m->p_max);
      ok = K >= PAIR_K_MIN && K <= PAIR_K_MAX;
    }
  }
  if (ok) {
    memcpy(m->kpair[s], k, sizeof k);
  }
  free(rows), free(r);
  return 1;
}

/* robot_calibration_rbf.c: the interactions of CSR_CAL_RULE_RBF (robot_calibration_model.h):
 * each mode's difference from the single-chamber superposition, interpolated over the
 * symmetric images of the modes' shapes by a Gaussian radial basis function.
 *
 * Why. The default rule interpolates the same differences over the canonical shape prism with
 * hierarchical hats; at 0.3-0.4 MPa those differences are large and curved (O124 at 0.4 MPa:
 * superposition 98.0 deg per segment, FE 71.7) and the piecewise-linear hats between few modes
 * miss the held-out cases by up to 35 mm at the tip (README "Calibration"). A smooth
 * interpolant of the same data does better (tools/calib_rules.py, docs/bench/
 * calib_rules_2026-12-03): on the shipped table H4-H6 meet the target over their whole sweeps
 * and the refining modes left out one at a time miss by 11.7 mm at most instead of 27.5.
 * How. Shapes x = p / P (P the highest pressure) live in 4-D; every fitted mode contributes its
 * images under the section's eight symmetries (quarter turns, the mirror Ω2 <-> Ω4), duplicates
 * dropped, each carrying the mode's residual curves with its bend vector turned and mirrored
 * accordingly. The kernel depends on Euclidean distance, which the symmetries (permutations of
 * the chambers) keep, so the interpolant is equivariant by construction: no canonical form is
 * needed for continuity, a pattern with zero pressure moment (invariant under the half turn)
 * gets zero residual bend to round-off, and every image, hence every fitted row, is returned
 * (cardinal weights: w = A^-1 phi(x) is the unit vector at a node; the residual along P is each
 * mode's monotone cubic, exact at its rows). Gaussian without a polynomial part: away from the
 * modes the residual decays to 0 and the model to the superposition, never an extrapolation of
 * a trend. The width is chosen by the left-out errors of the refining modes (RBF_WIDTH).
 * Tabulated. Evaluated as written, the field costs the cardinal weights w = A^-1 phi (rbf_n^2
 * products) and one curve evaluation per mode at every call, once per leg, segment and step in
 * a run. The residual curves are cubic on every interval between the union of their rows, so
 * on such an interval the field is sum_i phi_i(x) sum_k tau^k G_ik (tau = P - B_i, k = 0..3),
 * with G_ik = sum_j (A^-1)_ij L_j a_rj,k (L_j the image's turn and mirror, a_rj,k the power
 * coefficients of its mode's cubic there): the same function, summed in another order, for
 * rbf_n kernels and 4 rbf_n NF products (tabulate; the difference to the definition
 * is round-off, test_calibration_rbf field_tabulated_matches_definition).
 * Alternatives measured and rejected (same script): the cubic r^3 and thin-plate kernels with a
 * linear part (held out 4.6-5.0 deg / 20.5-22.4 mm but left out 6.1-6.7 deg / 17.9-18.1 mm),
 * the RBF without the superposition base (H7 23.6 mm, H2 misses), and a base from the pressure
 * moment's size and the mean pressure alone (O12O34r3 and O124 sit at nearly equal moment and
 * mean pressure but bend 101.5 and 71.7 deg at 0.4 MPa). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "robot_calibration_internal.h"

/* Gaussian width in the shape space x = p / P (-): the left-out refining modes' worst tip error
 * on the shipped table was 25.0 / 20.8 / 11.7 / 11.6 / 12.6 / 15.6 mm at widths 0.25 / 0.35 /
 * 0.5 / 0.7 / 1.0 / 1.5, and 4.0 deg of bend at 0.5 against 5.9 at 0.7: 0.5 (the distance from
 * a corner of the prism to its edge midpoint) */
#define RBF_WIDTH 0.5
/* the most doubles of the tabulated field (32 MB; the shipped tables need ~0.1-1 MB) */
#define RBF_TABLE_MAX ((size_t)4 << 20)
/* images closer than this in shape space are the same pattern (exact ratios in the tables) */
#define RBF_SAME_TOL 1e-12

/* Gaussian of the squared distance */
static double kernel(double r2) { return exp(-r2 / (RBF_WIDTH * RBF_WIDTH)); }


/* the image of pattern r under k quarter turns and the mirror: q = D^mir r, p[(i + k) % 4] = q[i]
 * (the inverse of the canonical form's map, so its bend is csr_calFromCanonical_(bend, k, mir)) */
static void imagePattern(const double r[4], int k, int mir, double p[4]) {
  const double q[4] = {r[0], mir ? r[3] : r[1], r[2], mir ? r[1] : r[3]};
  for (int i = 0; i < 4; i++) p[(i + k) % 4] = q[i];
}


/* one mode's residual curves in its own frame (F_A, F_B hold the bend vector's two components
 * here): the FE's symmetric part minus the superposition, the scalars minus their base */
static int buildResidual(csrCalModel* m, const csrCalCase* c, csrCalCurve* f) {
  const int n = csr_calRowsTo_(c, m->p_max);
  if (!csr_calCurveAlloc_(f, n, NF)) {
    return 0;
  }
  const double* r = c->ratio;
  double mv[2];
  csr_calMoment_(r, mv);
  const double mn = hypot(mv[0], mv[1]);
  const int sym = csr_calMirrorSymmetric_(r);
  for (int i = 0; i < n; i++) {
    const double p = c->pressure[i];
    f->p[i] = p;
    for (int s = 0; s < CSR_NSEG; s++) {
      double* y = f->y + (i * CSR_NSEG + s) * NF;
      double b0 = c->bend[6 * i + 2 * s] - c->bend[2 * s];
      double b1 = c->bend[6 * i + 2 * s + 1] - c->bend[2 * s + 1];
      if (mn == 0) {
        b0 = b1 = 0; /* zero pressure moment: no bend by symmetry */
      } else if (sym) {
        /* a mirror-symmetric pattern bends along its mirror line, m̂: the rest is mesh
         * asymmetry */
        const double along = (b0 * mv[0] + b1 * mv[1]) / mn;
        b0 = along * mv[0] / mn, b1 = along * mv[1] / mn;
      }
      y[F_A] = b0, y[F_B] = b1;
      y[F_STRETCH] = c->stretch[3 * i + s] - c->stretch[s];
      y[F_RADIAL] = c->radial[3 * i + s] - c->radial[s];
      y[F_RADMAX] = c->radial_max[3 * i + s] - c->radial_max[s];
      if (p > 0) {
        const double pc[4] = {r[0] * p, r[1] * p, r[2] * p, r[3] * p};
        double bb[2], bs[3];
        csr_calBaseBend_(m, s, pc, bb);
        csr_calBaseScalars_(m, s, pc, bs);
        y[F_A] -= bb[0], y[F_B] -= bb[1];
        for (int q = 0; q < 3; q++) y[F_STRETCH + q] -= bs[q];
      }
    }
  }
  csr_calCurveSlopes_(f);
  return 1;
}


/* the inverse of the symmetric positive definite A (n x n, overwritten) into inv by Cholesky;
 * 0 if A is not numerically positive definite */
static int invertSpd(double* A, int n, double* inv) {
  for (int j = 0; j < n; j++) {
    double d = A[j * n + j];
    for (int k = 0; k < j; k++) d -= A[j * n + k] * A[j * n + k];
    if (!(d > 0)) {
      return 0;
    }
    A[j * n + j] = sqrt(d);
    for (int i = j + 1; i < n; i++) {
      double v = A[i * n + j];
      for (int k = 0; k < j; k++) v -= A[i * n + k] * A[j * n + k];
      A[i * n + j] = v / A[j * n + j];
    }
  }
  /* columns of the inverse: L L^T x = e_c */
  for (int c = 0; c < n; c++) {
    double* x = inv + c * n; /* A^-1 is symmetric: column c = row c */
    for (int i = 0; i < n; i++) {
      double v = i == c ? 1 : 0;
      for (int k = 0; k < i; k++) v -= A[i * n + k] * x[k];
      x[i] = v / A[i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) {
      double v = x[i];
      for (int k = i + 1; k < n; k++) v -= A[k * n + i] * x[k];
      x[i] = v / A[i * n + i];
    }
  }
  return 1;
}


static int compareDouble(const void* a, const void* b) {
  const double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}


/* the power coefficients a[k] (k = 0..3) in tau = P - lo of curve c's component q of segment s
 * on [lo, hi], an interval inside one of its Hermite intervals or outside its rows (constant:
 * csr_calCurveEval_ clamps) */
static void curveCubic(const csrCalCurve* c, int s, int q, double lo, double hi, double a[4]) {
  const int n = CSR_NSEG * c->nc, off = s * c->nc + q, last = c->m - 1;
  const double mid = 0.5 * (lo + hi);
  a[1] = a[2] = a[3] = 0;
  if (mid <= c->p[0] || mid >= c->p[last]) {
    a[0] = c->y[(mid <= c->p[0] ? 0 : last) * n + off];
    return;
  }
  int i = 0;
  while (i < last - 1 && c->p[i + 1] <= mid) i++;
  const double h = c->p[i + 1] - c->p[i];
  const double y0 = c->y[i * n + off], y1 = c->y[(i + 1) * n + off];
  const double m0 = h * c->d[i * n + off], m1 = h * c->d[(i + 1) * n + off];
  /* the Hermite cubic in t = (P - p_i) / h: c0 + c1 t + c2 t^2 + c3 t^3 */
  const double c0 = y0, c1 = m0, c2 = -3 * y0 - 2 * m0 + 3 * y1 - m1,
               c3 = 2 * y0 + m0 - 2 * y1 + m1;
  /* its Taylor coefficients at t0 (P = lo), then in tau = h (t - t0) */
  const double t0 = (lo - c->p[i]) / h;
  a[0] = c0 + t0 * (c1 + t0 * (c2 + t0 * c3));
  a[1] = (c1 + t0 * (2 * c2 + 3 * t0 * c3)) / h;
  a[2] = (c2 + 3 * t0 * c3) / (h * h);
  a[3] = c3 / (h * h * h);
}


/* the tabulated field (header): 1 ok (or nothing to tabulate: rbf_nb stays 0 and the
 * definition is used), 0 out of memory */
static int tabulate(csrCalModel* m) {
  const int n = m->rbf_n;
  int ntot = 0;
  for (int r = 0; r < CSR_CAL_NROLE; r++) ntot += m->rbf_res[r].m;
  if (n == 0 || ntot < 2) {
    return 1;
  }
  double* B = malloc((size_t)ntot * sizeof(double));
  if (!B) {
    return 0;
  }
  int nb = 0;
  for (int r = 0; r < CSR_CAL_NROLE; r++) {
    for (int i = 0; i < m->rbf_res[r].m; i++) B[nb++] = m->rbf_res[r].p[i];
  }
  qsort(B, (size_t)nb, sizeof(double), compareDouble);
  int u = 0;
  for (int i = 0; i < nb; i++) {
    if (u == 0 || B[i] != B[u - 1]) B[u++] = B[i];
  }
  nb = u;
  if (nb < 2) {
    free(B);
    return 1;
  }
  const size_t per_int = (size_t)CSR_NSEG * 4 * n * NF;
  if ((size_t)(nb - 1) * per_int > RBF_TABLE_MAX) {
    free(B);
    return 1; /* a table of very many distinct rows: the definition, not a huge table */
  }
  double* G = calloc((size_t)(nb - 1) * per_int, sizeof(double));
  if (!G) {
    free(B);
    return 0;
  }
  /* the images' residual cubics on one interval, turned into the image's frame:
   * L[j][k][NF] (k the power) */
  double* L = malloc((size_t)n * 4 * NF * sizeof(double));
  if (!L) {
    free(B), free(G);
    return 0;
  }
  for (int iv = 0; iv < nb - 1; iv++) {
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 0; j < n; j++) {
        const csrCalCurve* c = &m->rbf_res[m->rbf_role[j]];
        double a[NF][4];
        for (int q = 0; q < NF; q++) curveCubic(c, s, q, B[iv], B[iv + 1], a[q]);
        for (int k = 0; k < 4; k++) {
          double* Ljk = L + ((size_t)j * 4 + k) * NF;
          const double bc[2] = {a[F_A][k], a[F_B][k]};
          csr_calFromCanonical_(bc, m->rbf_k[j], m->rbf_mir[j], Ljk + F_A);
          for (int q = F_STRETCH; q < NF; q++) Ljk[q] = a[q][k];
        }
      }
      /* G_ik = sum_j (A^-1)_ij L_jk (A^-1 symmetric) */
      double* Gs = G + (size_t)iv * per_int + (size_t)s * 4 * n * NF;
      for (int i = 0; i < n; i++) {
        const double* row = m->rbf_inv + (size_t)i * n;
        for (int k = 0; k < 4; k++) {
          double* g = Gs + ((size_t)k * n + i) * NF;
          for (int j = 0; j < n; j++) {
            const double* Ljk = L + ((size_t)j * 4 + k) * NF;
            for (int q = 0; q < NF; q++) g[q] += row[j] * Ljk[q];
          }
        }
      }
    }
  }
  free(L);
  m->rbf_nb = nb;
  m->rbf_B = B;
  m->rbf_G = G;
  return 1;
}


int csr_calRbfBuild_(csrCalModel* m, const csrCalCase* const mode[CSR_CAL_NROLE]) {
  int n = 0;
  for (int r = 0; r < CSR_CAL_NROLE; r++) {
    if (!mode[r]) {
      continue;
    }
    if (!buildResidual(m, mode[r], &m->rbf_res[r])) {
      return 0;
    }
    /* the mode's distinct images under the eight symmetries */
    for (int k = 0; k < 4; k++) {
      for (int mir = 0; mir < 2; mir++) {
        double x[4];
        imagePattern(mode[r]->ratio, k, mir, x);
        int dup = 0;
        for (int j = 0; j < n && !dup; j++) {
          dup = fabs(x[0] - m->rbf_x[j][0]) + fabs(x[1] - m->rbf_x[j][1]) +
                    fabs(x[2] - m->rbf_x[j][2]) + fabs(x[3] - m->rbf_x[j][3]) <=
                RBF_SAME_TOL;
        }
        if (!dup) {
          memcpy(m->rbf_x[n], x, sizeof x);
          m->rbf_role[n] = r, m->rbf_k[n] = k, m->rbf_mir[n] = mir;
          n++;
        }
      }
    }
  }
  m->rbf_n = n;
  double* A = malloc((size_t)n * n * sizeof(double));
  m->rbf_inv = malloc((size_t)n * n * sizeof(double));
  if (!A || !m->rbf_inv) {
    free(A);
    return 0;
  }
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      double r2 = 0;
      for (int q = 0; q < 4; q++) r2 += (m->rbf_x[i][q] - m->rbf_x[j][q]) *
                                        (m->rbf_x[i][q] - m->rbf_x[j][q]);
      A[i * n + j] = kernel(r2);
    }
  }
  /* distinct nodes make the Gaussian matrix positive definite (condition 16 on the shipped
   * table's 35 images) */
  const int ok = invertSpd(A, n, m->rbf_inv);
  free(A);
  if (!ok) {
    return -1;
  }
  return tabulate(m);
}


void csr_calRbfField_(const csrCalModel* m, int s, const double pc[4], double bend[2],
                      double sc[3]) {
  const int nb = m->rbf_nb;
  if (nb < 2) {
    csr_calRbfFieldDirect_(m, s, pc, bend, sc);
    return;
  }
  const int n = m->rbf_n;
  const double P = pc[0];
  const double x[4] = {pc[0] / P, pc[1] / P, pc[2] / P, pc[3] / P};
  /* the interval of P (clamped to the rows, as the curves clamp) */
  const double* B = m->rbf_B;
  const double Pc = P <= B[0] ? B[0] : (P >= B[nb - 1] ? B[nb - 1] : P);
  int lo = 0, hi = nb - 1;
  while (hi - lo > 1) {
    const int mid = (lo + hi) / 2;
    (B[mid] <= Pc ? (lo = mid) : (hi = mid));
  }
  const double tau = Pc - B[lo];
  const double tk[4] = {1, tau, tau * tau, tau * tau * tau};
  const double* G = m->rbf_G + ((size_t)lo * CSR_NSEG + s) * 4 * n * NF;
  double f[NF] = {0, 0, 0, 0, 0};
  for (int i = 0; i < n; i++) {
    double r2 = 0;
    for (int q = 0; q < 4; q++) r2 += (x[q] - m->rbf_x[i][q]) * (x[q] - m->rbf_x[i][q]);
    const double phi = kernel(r2);
    double g[NF] = {0, 0, 0, 0, 0};
    for (int k = 3; k >= 0; k--) {
      const double* Gk = G + ((size_t)k * n + i) * NF;
      for (int q = 0; q < NF; q++) g[q] += tk[k] * Gk[q];
    }
    for (int q = 0; q < NF; q++) f[q] += phi * g[q];
  }
  bend[0] = f[F_A], bend[1] = f[F_B];
  for (int q = 0; q < 3; q++) sc[q] = f[F_STRETCH + q];
}


void csr_calRbfFieldDirect_(const csrCalModel* m, int s, const double pc[4], double bend[2],
                      double sc[3]) {
  const int n = m->rbf_n;
  const double P = pc[0];
  const double x[4] = {pc[0] / P, pc[1] / P, pc[2] / P, pc[3] / P};
  /* the residual curves of every mode at P, once */
  double y[CSR_CAL_NROLE][NF];
  for (int r = 0; r < CSR_CAL_NROLE; r++) {
    if (m->rbf_res[r].m > 0) {
      csr_calCurveEval_(&m->rbf_res[r], P, s, y[r]);
    }
  }
  double phi[RBF_MAXN];
  for (int j = 0; j < n; j++) {
    double r2 = 0;
    for (int q = 0; q < 4; q++) r2 += (x[q] - m->rbf_x[j][q]) * (x[q] - m->rbf_x[j][q]);
    phi[j] = kernel(r2);
  }
  bend[0] = bend[1] = 0;
  sc[0] = sc[1] = sc[2] = 0;
  for (int j = 0; j < n; j++) {
    /* cardinal weight of image j: row j of A^-1 times phi */
    const double* row = m->rbf_inv + j * n;
    double w = 0;
    for (int i = 0; i < n; i++) w += row[i] * phi[i];
    const double* yj = y[m->rbf_role[j]];
    double b[2];
    csr_calFromCanonical_(yj + F_A, m->rbf_k[j], m->rbf_mir[j], b);
    bend[0] += w * b[0], bend[1] += w * b[1];
    for (int q = 0; q < 3; q++) sc[q] += w * yj[F_STRETCH + q];
  }
}

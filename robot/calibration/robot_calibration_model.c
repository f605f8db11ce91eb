/* robot_calibration_model.c: evaluating the calibration model (robot_calibration_model.h has
 * the rule; robot_calibration_build.c builds it): the canonical form of a pressure pattern, the
 * prism weights, the superposition bases, the stiffness, and the queries. No allocation. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "robot_calibration_internal.h"
#include "robot_leg.h"

/* chamber ratios of each role (fem_calibration.c's case list) */
static const struct {
  const char* name;
  double ratio[CSR_NCHAMBER];
} kRoles[CSR_CAL_NROLE] = {
    {"O1", {1, 0, 0, 0}},         {"O13", {1, 0, 1, 0}},  {"O12", {1, 1, 0, 0}},
    {"O124", {1, 1, 0, 1}},       {"O1234", {1, 1, 1, 1}}, {"O12r05", {1, 0.5, 0, 0}},
    {"O12O34r3", {1, 1, 1.0 / 3.0, 1.0 / 3.0}}, {"O1O234r05", {1, 0.5, 0.5, 0.5}},
    {"O1O234r075", {1, 0.75, 0.75, 0.75}}, {"O124O3r05", {1, 1, 0.5, 1}},
    {"O1O23r05O4r025", {1, 0.5, 0.5, 0.25}}, {"O1O3r05", {1, 0, 0.5, 0}},
    {"O12O4r05", {1, 1, 0, 0.5}}, {"O1O24r05", {1, 0.5, 0, 0.5}}, {"O13O2r05", {1, 0.5, 1, 0}},
    {"O1O2r067O4r033", {1, 2.0 / 3.0, 0, 1.0 / 3.0}},
    {"O13O2r067O4r033", {1, 2.0 / 3.0, 1, 1.0 / 3.0}}, {"O1O23r05", {1, 0.5, 0.5, 0}},
    {"O12O34r05", {1, 1, 0.5, 0.5}},
    {"O1O24r075O3r025", {1, 0.75, 0.25, 0.75}}, {"O1O234r025", {1, 0.25, 0.25, 0.25}},
    {"O1O24r025O3r075", {1, 0.25, 0.75, 0.25}}, {"O13O24r05", {1, 0.5, 1, 0.5}},
};

csrCalOptions csr_calModelDefaultOptions(void) {
  csrCalOptions o;
  memset(&o, 0, sizeof o);
  o.rule = CSR_CAL_RULE_SUPERPOSITION;
  o.scalar_rule = CSR_CAL_RULE_SUPERPOSITION;
  return o;
}


void csr_calModelModePattern(csrCalRole role, double ratio[CSR_NCHAMBER], const char** name) {
  if (role < 0 || role >= CSR_CAL_NROLE) {
    role = CSR_CAL_O1;
  }
  memcpy(ratio, kRoles[role].ratio, sizeof kRoles[role].ratio);
  if (name) {
    *name = kRoles[role].name;
  }
}


/* the nc components of segment s at pressure p (clamped to the rows: callers check the range):
 * exact at a row (t = 0 or 1 make the other Hermite weights exactly 0) */
void csr_calCurveEval_(const csrCalCurve* c, double p, int s, double* out) {
  int lo = 0, hi = c->m - 1;
  if (p <= c->p[0]) {
    p = c->p[0];
  } else if (p >= c->p[hi]) {
    p = c->p[hi];
  }
  while (hi - lo > 1) {
    int mid = (lo + hi) / 2;
    (c->p[mid] <= p ? (lo = mid) : (hi = mid));
  }
  const double h = c->p[hi] - c->p[lo], t = (p - c->p[lo]) / h;
  const double t2 = t * t, t3 = t2 * t;
  const double h00 = 2 * t3 - 3 * t2 + 1, h10 = t3 - 2 * t2 + t, h01 = -2 * t3 + 3 * t2,
               h11 = t3 - t2;
  const int n = CSR_NSEG * c->nc, off = s * c->nc;
  for (int q = 0; q < c->nc; q++) {
    const int a = lo * n + off + q, b = hi * n + off + q;
    out[q] = h00 * c->y[a] + h * h10 * c->d[a] + h01 * c->y[b] + h * h11 * c->d[b];
  }
}


/* ---- canonical form and prism weights ---------------------------------------------------- */

/* pressure moment (p1 + p2 - p3 - p4, p1 - p2 - p3 + p4) of a pattern */
void csr_calMoment_(const double p[4], double mvec[2]) {
  mvec[0] = (p[0] + p[1]) - (p[2] + p[3]);
  mvec[1] = (p[0] + p[3]) - (p[1] + p[2]);
}


/* 1 when some mirror of the section maps the pattern onto itself (exact comparison: the
 * patterns are the table's ratios) */
int csr_calMirrorSymmetric_(const double r[4]) {
  return (r[0] == r[1] && r[2] == r[3]) || (r[0] == r[3] && r[1] == r[2]) || r[1] == r[3] ||
         r[0] == r[2];
}


/* canonical form: pc = D^mir R^k p with (R p)_i = p_(i+1) (the pattern turned by +90 deg) and
 * D swapping Ω2, Ω4; the highest chamber first (the first of equal ones), pc[1] >= pc[3] */
void csr_calCanonical_(const double p[4], double pc[4], int* k, int* mir) {
  int j = 0;
  for (int i = 1; i < 4; i++) {
    if (p[i] > p[j]) {
      j = i;
    }
  }
  for (int i = 0; i < 4; i++) {
    pc[i] = p[(i + j) % 4];
  }
  *k = j;
  *mir = pc[1] < pc[3];
  if (*mir) {
    double t = pc[1];
    pc[1] = pc[3], pc[3] = t;
  }
}


/* bend vector of the canonical pattern back in the segment's frame: bend(p) = Rot(-90 k) D^mir
 * bend(pc), Rot(90) (x, y) = (-y, x), D (x, y) = (y, x) */
void csr_calFromCanonical_(const double bc[2], int k, int mir, double b[2]) {
  double x = mir ? bc[1] : bc[0], y = mir ? bc[0] : bc[1];
  for (int i = 0; i < k; i++) {
    double t = x; /* Rot(-90): (x, y) -> (y, -x) */
    x = y, y = -t;
  }
  b[0] = x, b[1] = y;
}


/* the inverse: a bend vector in the pattern's frame into the canonical frame,
 * bc = D^mir Rot(+90 k) b */
void csr_calToCanonical_(const double b[2], int k, int mir, double bc[2]) {
  double x = b[0], y = b[1];
  for (int i = 0; i < k; i++) {
    double t = x; /* Rot(+90): (x, y) -> (-y, x) */
    x = -y, y = t;
  }
  bc[0] = mir ? y : x, bc[1] = mir ? x : y;
}


/* hat function on [0, 1] peaking at c (0 < c < 1), 0 at both ends */
static double hat(double x, double c) {
  return x <= c ? x / c : (1 - x) / (1 - c);
}


/* hat function on [lo, 1] peaking at c (lo < c < 1), 0 outside */
static double hatOn(double x, double lo, double c) {
  return x <= lo ? 0 : x <= c ? (x - lo) / (c - lo) : (1 - x) / (1 - c);
}


/* weights of the vertices at prism point (x2, w, x3): trilinear between the corners, the
 * refining modes as bumps (their surpluses carry the rest). Hierarchical order (the enum's):
 * every bump vanishes at every vertex before it, so each vertex's surplus is its FE value
 * minus the interpolation of the vertices before it and the model returns every vertex. The
 * edge midpoints' bumps are the corner weights of their edge's ends with a hat along it; the
 * pair V_E124 / V_E124M is one case and its mirror image, so the weights stay symmetric under
 * w <-> x3 on the face x2 = 1, where the canonical form is ambiguous (p1 = p2). */
void csr_calWeights_(const csrCalModel* m, double x2, double w, double x3, double W[NV]) {
  W[V_O1] = (1 - x2) * (1 - x3);
  W[V_O13] = (1 - x2) * x3;
  W[V_O12] = x2 * (1 - w) * (1 - x3);
  W[V_O124] = x2 * w * (1 - x3);
  W[V_O124M] = x2 * (1 - w) * x3;
  W[V_O1234] = x2 * w * x3;
  W[V_R05] = m->use[V_R05] ? hat(x2, m->coord[V_R05][0]) * (1 - w) * (1 - x3) : 0;
  W[V_E13] = m->use[V_E13] ? (1 - x2) * hat(x3, m->coord[V_E13][2]) : 0;
  W[V_E124] = m->use[V_E124] ? x2 * w * hat(x3, m->coord[V_E124][2]) : 0;
  W[V_E124M] = m->use[V_E124M] ? x2 * hat(w, m->coord[V_E124M][1]) * x3 : 0;
  W[V_R3] = m->use[V_R3] ? x2 * hat(w, m->coord[V_R3][1]) * hat(x3, m->coord[V_R3][2]) : 0;
  W[V_F05] = m->use[V_F05] ? hat(x2, m->coord[V_F05][0]) * w * hat(x3, m->coord[V_F05][2]) : 0;
  const double lo = m->use[V_F05] ? m->coord[V_F05][0] : 0; /* the coarser level's node */
  W[V_F075] = m->use[V_F075]
                  ? hatOn(x2, lo, m->coord[V_F075][0]) * w * hatOn(x3, lo, m->coord[V_F075][2])
                  : 0;
  W[V_C] = m->use[V_C] ? hat(x2, m->coord[V_C][0]) * hat(w, m->coord[V_C][1]) *
                             hat(x3, m->coord[V_C][2])
                       : 0;
}


/* -Σ_j e(p_j) ĉ_j K(p̄) with e(p) = θ1(p) / K(p / 4) (the single-chamber response without its
 * own mean-pressure factor), grouped by diagonals: exactly 0 when p1 = p3 and p2 = p4 */
void csr_calSuperposeBend_(const csrCalCurve* base, const double k[2], int s, const double pc[4],
                          double bend[2]) {
  double t[4];
  for (int j = 0; j < 4; j++) {
    double q[NB];
    t[j] = 0;
    if (pc[j] > 0) {
      csr_calCurveEval_(base, pc[j], s, q);
      t[j] = q[B_THETA] / csr_calMeanFactor_(k, 0.25 * pc[j]);
    }
  }
  const double f = csr_calMeanFactor_(k, 0.25 * ((pc[0] + pc[1]) + (pc[2] + pc[3])));
  const double g1 = t[0] - t[2], g2 = t[1] - t[3];
  bend[0] = -RSQ2 * (g1 + g2) * f;
  bend[1] = -RSQ2 * (g1 - g2) * f;
}


/* the bend base at canonical pressures pc (P = pc[0] <= range), canonical frame: the
 * superposition of the single-chamber response (also under CSR_CAL_RULE_RBF; scaled by the
 * fitted mean-pressure factor for CSR_CAL_RULE_SCALED, by the pair factor for
 * CSR_CAL_RULE_RBF_PAIR), or 0 */
void csr_calBaseBend_(const csrCalModel* m, int s, const double pc[4], double bend[2]) {
  bend[0] = bend[1] = 0;
  if (m->opt.rule == CSR_CAL_RULE_SUPERPOSITION || m->opt.rule == CSR_CAL_RULE_SCALED ||
      m->opt.rule == CSR_CAL_RULE_RBF) {
    csr_calSuperposeBend_(&m->base, m->kfac[s], s, pc, bend);
  } else if (m->opt.rule == CSR_CAL_RULE_RBF_PAIR) {
    csr_calPairBend_(m, s, pc, bend);
  }
}


/* the scalar base (changes of stretch, radial, largest radial growth) at canonical pc: the
 * superposition of the single-chamber response, the all-four response at the mean pressure,
 * or 0 */
void csr_calBaseScalars_(const csrCalModel* m, int s, const double pc[4], double sc[3]) {
  sc[0] = sc[1] = sc[2] = 0;
  if (m->opt.scalar_rule == CSR_CAL_RULE_SUPERPOSITION) {
    for (int j = 0; j < 4; j++) {
      if (pc[j] > 0) {
        double q[NB];
        csr_calCurveEval_(&m->base, pc[j], s, q);
        for (int c = 0; c < 3; c++) sc[c] += q[B_STRETCH + c];
      }
    }
  } else if (m->opt.scalar_rule == CSR_CAL_RULE_MEAN) {
    const double pbar = 0.25 * ((pc[0] + pc[1]) + (pc[2] + pc[3]));
    if (pbar > 0) {
      double q[NF];
      csr_calCurveEval_(&m->mean, pbar, s, q);
      for (int c = 0; c < 3; c++) sc[c] = q[F_STRETCH + c];
    }
  }
}


/* the model in the canonical frame: bend and scalars of segment s at canonical pc */
static void evalCanonical(const csrCalModel* m, int s, const double pc[4], double bend[2],
                          double sc[3]) {
  if (m->opt.rule == CSR_CAL_RULE_RBF || m->opt.rule == CSR_CAL_RULE_RBF_PAIR) {
    /* bases + the residual interpolated over the modes' symmetric images */
    double rb[2], rs[3], bs[3], mv[2];
    csr_calRbfField_(m, s, pc, rb, rs);
    csr_calMoment_(pc, mv);
    if (mv[0] == 0 && mv[1] == 0) {
      rb[0] = rb[1] = 0; /* the interpolant gives 0 to round-off (equivariance); exactly 0 */
    }
    csr_calBaseBend_(m, s, pc, bend);
    csr_calBaseScalars_(m, s, pc, bs);
    bend[0] += rb[0], bend[1] += rb[1];
    for (int c = 0; c < 3; c++) sc[c] = bs[c] + rs[c];
    return;
  }
  const double P = pc[0];
  const double x2 = pc[1] / P, x3 = pc[2] / P, x4 = pc[3] / P;
  const double w = x2 > 0 ? x4 / x2 : 0;
  double W[NV];
  csr_calWeights_(m, x2, w, x3, W);
  double f[NF] = {0, 0, 0, 0, 0};
  for (int v = 0; v < NV; v++) {
    if (W[v] != 0) {
      double fv[NF];
      csr_calCurveEval_(&m->field[v], P, s, fv);
      for (int q = 0; q < NF; q++) {
        f[q] += W[v] * fv[q];
      }
    }
  }
  double bs[3];
  csr_calBaseBend_(m, s, pc, bend);
  csr_calBaseScalars_(m, s, pc, bs);
  for (int c = 0; c < 3; c++) {
    sc[c] = f[F_STRETCH + c] + bs[c];
  }
  /* a along -m̂, b along m̂ turned by +90 deg; m = 0 (only the elongation modes weigh) has
   * a = b = 0 */
  double mv[2];
  csr_calMoment_(pc, mv);
  const double mn = hypot(mv[0], mv[1]);
  if (mn > 0) {
    const double u0 = mv[0] / mn, u1 = mv[1] / mn;
    bend[0] += -f[F_A] * u0 - f[F_B] * u1;
    bend[1] += -f[F_A] * u1 + f[F_B] * u0;
  }
}


int csr_calModelEval(const csrCalModel* m, int seg, const double p[CSR_NCHAMBER],
                     csrCalSegment* out) {
  if (seg < 0 || seg >= CSR_NSEG) {
    return -1;
  }
  double q[4], pmax = 0;
  for (int j = 0; j < 4; j++) {
    if (!(p[j] >= -P_NEG_TOL)) {
      return 1; /* NaN or clearly negative: non-physical, the integrator may cut its step */
    }
    q[j] = p[j] > 0 ? p[j] : 0;
    pmax = fmax(pmax, q[j]);
  }
  if (pmax > m->p_max + P_RANGE_TOL) {
    return CSR_MAP_OUT_OF_RANGE;
  }
  out->bend[0] = out->bend[1] = 0;
  out->stretch = 1;
  out->radial = 0;
  out->radius = m->leg.a;
  if (pmax == 0) {
    return 0; /* vented: the rest state */
  }
  double pc[4], bc[2], sc[3];
  int k, mir;
  csr_calCanonical_(q, pc, &k, &mir);
  if (pc[0] > m->p_max) {
    pc[0] = m->p_max; /* round-off above the last row */
  }
  evalCanonical(m, seg, pc, bc, sc);
  csr_calFromCanonical_(bc, k, mir, out->bend);
  out->stretch = 1 + sc[0];
  out->radial = sc[1];
  out->radius = m->leg.a + sc[2];
  if (!(out->stretch > 0)) {
    /* the superposed changes of a table's modes can sum past -1 (a table of shrinking modes:
     * found by fuzz_calib_h5) although every row the reader accepted is > 0: non-physical */
    return 1;
  }
  return 0;
}


/* ---- stiffness, queries -------------------------------------------------------------------- */

/* piecewise-linear interpolation in sorted points (x within [X[0], X[n-1]]) */
static double linear(const double* X, const double* Y, int n, double x) {
  if (n == 1) {
    return Y[0];
  }
  int i = 0;
  while (i < n - 2 && X[i + 1] < x) i++;
  const double t = fmin(fmax((x - X[i]) / (X[i + 1] - X[i]), 0), 1);
  return (1 - t) * Y[i] + t * Y[i + 1];
}


int csr_calModelStiffness(const csrCalModel* m, int seg, const double p[CSR_NCHAMBER],
                          double* EI, double* EA) {
  if (seg < 0 || seg >= CSR_NSEG) {
    return -1;
  }
  if (isnan(m->k_pmax)) {
    return 2;
  }
  double pbar = 0, pmax = 0;
  for (int j = 0; j < 4; j++) {
    if (!(p[j] >= -P_NEG_TOL)) {
      return 1;
    }
    pbar += 0.25 * fmax(p[j], 0);
    pmax = fmax(pmax, p[j]);
  }
  if (pmax > m->p_max + P_RANGE_TOL || pbar > m->k_pmax + P_RANGE_TOL) {
    return CSR_MAP_OUT_OF_RANGE;
  }
  *EI = linear(m->kp[0][seg], m->kv[0][seg], m->nk[0][seg], pbar);
  *EA = linear(m->kp[1][seg], m->kv[1][seg], m->nk[1][seg], pbar);
  return 0;
}


double csr_calModelPMax(const csrCalModel* m) { return m->p_max; }
const char* csr_calModelLimitCase(const csrCalModel* m) { return m->limit_case; }
double csr_calModelStiffnessPMax(const csrCalModel* m) { return m->k_pmax; }
const char* csr_calModelName(const csrCalModel* m) { return m->name; }
const csrActuator* csr_calModelLeg(const csrCalModel* m) { return &m->leg; }


const csrCalOptions* csr_calModelOptions(const csrCalModel* m) { return &m->opt; }


void csr_calModelMeanFactor(const csrCalModel* m, int seg, double k[2], double* rms) {
  const int ok = seg >= 0 && seg < CSR_NSEG;
  k[0] = ok ? m->kfac[seg][0] : 0;
  k[1] = ok ? m->kfac[seg][1] : 0;
  *rms = ok && m->opt.rule == CSR_CAL_RULE_SCALED ? m->kfit_rms[seg] : NAN;
}


int csr_calModelUses(const csrCalModel* m, csrCalRole role) {
  return role >= 0 && role < CSR_CAL_NROLE && m->role_use[role];
}


void csr_calModelStiffnessPoints(const csrCalModel* m, int seg, int which, int* n,
                                 const double** pbar, const double** value) {
  const int ok = seg >= 0 && seg < CSR_NSEG && (which == 0 || which == 1);
  *n = ok ? m->nk[which][seg] : 0;
  *pbar = *n ? m->kp[which][seg] : NULL;
  *value = *n ? m->kv[which][seg] : NULL;
}



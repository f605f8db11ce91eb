/* robot_calibration_model.c: the calibration model from an FE mode table
 * (robot_calibration_model.h has the rule and its rationale).
 *
 * Layers: monotone cubic curves of the modes' rows (Fritsch-Carlson); the modes as fields in
 * the canonical frame (symmetric part, rest subtracted, residual from the superposition base,
 * hierarchical surpluses of the refining modes); the evaluation (canonical form, prism weights,
 * back to the segment's frame); the stiffness points; the comparison with a case. */
#include "robot_calibration_model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "robot_analytic.h"
#include "robot_leg.h"

/* pressures down to -1e-9 MPa are the pneumatics integrator's round-off around a vented
 * chamber (its lag decays towards 0 from above), so they count as 0; below that the state is
 * non-physical */
#define P_NEG_TOL 1e-9
/* a pressure may exceed the range by round-off of the caller's ratio x p products */
#define P_RANGE_TOL 1e-12
/* probes at equal mean pressure (both probed modes at p = 0) are merged */
#define PBAR_TOL 1e-12
/* the held-out target of issue 8: 5 % of the bend angle or 1 deg, 2 % of the leg length */
#define TARGET_BEND_REL 0.05
#define TARGET_BEND_ABS (1.0 * CS_DEG)
#define TARGET_TIP_REL 0.02

/* components of a mode's field per segment and row */
enum { F_A = 0, F_B, F_STRETCH, F_RADIAL, F_RADMAX, NF };
/* components of the single-chamber base per segment and row */
enum { B_THETA = 0, B_STRETCH, B_RADIAL, B_RADMAX, NB };

/* the vertices of the interpolation: the six corners of the prism and the two refining modes */
enum { V_O1 = 0, V_O13, V_O12, V_O124, V_O124M, V_O1234, V_R05, V_R3, NV };

/* chamber ratios of each role (fem_calibration.c's case list) */
static const struct {
  const char* name;
  double ratio[CSR_NCHAMBER];
} kRoles[CSR_CAL_NROLE] = {
    {"O1", {1, 0, 0, 0}},         {"O13", {1, 0, 1, 0}},  {"O12", {1, 1, 0, 0}},
    {"O124", {1, 1, 0, 1}},       {"O1234", {1, 1, 1, 1}}, {"O12r05", {1, 0.5, 0, 0}},
    {"O12O34r3", {1, 1, 1.0 / 3.0, 1.0 / 3.0}},
};

/* rows of one mode: p (m), y and slopes (m x 3 x nc) */
typedef struct {
  int m, nc;
  double* p;
  double* y;
  double* d;
} Curve;

struct csrCalModel_ {
  csrActuator leg;
  csrCalOptions opt;
  double p_max;            /* MPa: bend model range */
  char limit_case[64];     /* the mode that ends it */
  int use[NV];             /* vertex in use */
  double coord[NV][3];     /* (x2, w = x4/x2, x3) of each vertex */
  Curve base;              /* Ω1 alone: θ1 along -ĉ1, δstretch, δradial, δradial_max */
  Curve mean;              /* all four: the scalar changes at p = the mean pressure (F_ layout) */
  double kfac[CSR_NSEG][2]; /* mean-pressure factor of the scaled superposition (0: none) */
  double kfit_rms[CSR_NSEG]; /* rms of log(a_model / a_FE) of that fit over the bending modes */
  Curve field[NV];         /* a, b, δstretch, δradial, δradial_max (residual or value) */
  int nk[2][CSR_NSEG];     /* stiffness points of EI (0) and EA (1) per segment */
  double* kp[2][CSR_NSEG]; /* (nk) mean pressure, MPa */
  double* kv[2][CSR_NSEG]; /* (nk) EI (N mm^2) or EA (N) */
  double k_pmax;           /* MPa: highest mean pressure of the stiffness (NAN: none) */
  char name[1280];
};

/* unit diagonal directions of the chambers: ĉ1 = d1, ĉ2 = d2, ĉ3 = -d1, ĉ4 = -d2 */
#define RSQ2 0.70710678118654752440


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


/* ---- curves: monotone piecewise cubic Hermite (Fritsch-Carlson, as scipy's PCHIP) -------- */

static int curveAlloc(Curve* c, int m, int nc) {
  c->m = m, c->nc = nc;
  c->p = malloc((size_t)m * sizeof(double));
  c->y = malloc((size_t)m * CSR_NSEG * nc * sizeof(double));
  c->d = malloc((size_t)m * CSR_NSEG * nc * sizeof(double));
  return c->p && c->y && c->d;
}


static void curveFree(Curve* c) {
  free(c->p), free(c->y), free(c->d);
  memset(c, 0, sizeof *c);
}


/* the slope at an end from the two end intervals, kept shape-preserving (scipy _edge_case) */
static double edgeSlope(double h0, double h1, double s0, double s1) {
  double d = ((2 * h0 + h1) * s0 - h0 * s1) / (h0 + h1);
  if ((d > 0) != (s0 > 0) || s0 == 0) {
    return 0;
  }
  if ((s0 > 0) != (s1 > 0) && fabs(d) > 3 * fabs(s0)) {
    return 3 * s0;
  }
  return d;
}


/* slopes of every component series: weighted harmonic mean of the secants inside (0 at a
 * local extremum), so the interpolant neither overshoots nor wiggles between rows */
static void curveSlopes(Curve* c) {
  const int m = c->m, n = CSR_NSEG * c->nc;
  for (int q = 0; q < n; q++) {
    if (m == 2) {
      double s = (c->y[n + q] - c->y[q]) / (c->p[1] - c->p[0]);
      c->d[q] = c->d[n + q] = s;
      continue;
    }
    for (int i = 1; i < m - 1; i++) {
      double h0 = c->p[i] - c->p[i - 1], h1 = c->p[i + 1] - c->p[i];
      double s0 = (c->y[i * n + q] - c->y[(i - 1) * n + q]) / h0;
      double s1 = (c->y[(i + 1) * n + q] - c->y[i * n + q]) / h1;
      if (s0 * s1 <= 0) {
        c->d[i * n + q] = 0;
      } else {
        double w1 = 2 * h1 + h0, w2 = h1 + 2 * h0;
        c->d[i * n + q] = (w1 + w2) / (w1 / s0 + w2 / s1);
      }
    }
    double h0 = c->p[1] - c->p[0], h1 = c->p[2] - c->p[1];
    double s0 = (c->y[n + q] - c->y[q]) / h0, s1 = (c->y[2 * n + q] - c->y[n + q]) / h1;
    c->d[q] = edgeSlope(h0, h1, s0, s1);
    h0 = c->p[m - 1] - c->p[m - 2], h1 = c->p[m - 2] - c->p[m - 3];
    s0 = (c->y[(m - 1) * n + q] - c->y[(m - 2) * n + q]) / h0;
    s1 = (c->y[(m - 2) * n + q] - c->y[(m - 3) * n + q]) / h1;
    c->d[(m - 1) * n + q] = edgeSlope(h0, h1, s0, s1);
  }
}


/* the nc components of segment s at pressure p (clamped to the rows: callers check the range):
 * exact at a row (t = 0 or 1 make the other Hermite weights exactly 0) */
static void curveEval(const Curve* c, double p, int s, double* out) {
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
static void moment(const double p[4], double mvec[2]) {
  mvec[0] = (p[0] + p[1]) - (p[2] + p[3]);
  mvec[1] = (p[0] + p[3]) - (p[1] + p[2]);
}


/* 1 when some mirror of the section maps the pattern onto itself (exact comparison: the
 * patterns are the table's ratios) */
static int mirrorSymmetric(const double r[4]) {
  return (r[0] == r[1] && r[2] == r[3]) || (r[0] == r[3] && r[1] == r[2]) || r[1] == r[3] ||
         r[0] == r[2];
}


/* canonical form: pc = D^mir R^k p with (R p)_i = p_(i+1) (the pattern turned by +90 deg) and
 * D swapping Ω2, Ω4; the highest chamber first (the first of equal ones), pc[1] >= pc[3] */
static void canonical(const double p[4], double pc[4], int* k, int* mir) {
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
static void fromCanonical(const double bc[2], int k, int mir, double b[2]) {
  double x = mir ? bc[1] : bc[0], y = mir ? bc[0] : bc[1];
  for (int i = 0; i < k; i++) {
    double t = x; /* Rot(-90): (x, y) -> (y, -x) */
    x = y, y = -t;
  }
  b[0] = x, b[1] = y;
}


/* hat function on [0, 1] peaking at c (0 < c < 1), 0 at both ends */
static double hat(double x, double c) {
  return x <= c ? x / c : (1 - x) / (1 - c);
}


/* weights of the vertices at prism point (x2, w, x3): trilinear between the corners, the
 * refining modes as bumps (their surpluses carry the rest) */
static void weights(const csrCalModel* m, double x2, double w, double x3, double W[NV]) {
  W[V_O1] = (1 - x2) * (1 - x3);
  W[V_O13] = (1 - x2) * x3;
  W[V_O12] = x2 * (1 - w) * (1 - x3);
  W[V_O124] = x2 * w * (1 - x3);
  W[V_O124M] = x2 * (1 - w) * x3;
  W[V_O1234] = x2 * w * x3;
  W[V_R05] = m->use[V_R05] ? hat(x2, m->coord[V_R05][0]) * (1 - w) * (1 - x3) : 0;
  W[V_R3] = m->use[V_R3] ? x2 * hat(w, m->coord[V_R3][1]) * hat(x3, m->coord[V_R3][2]) : 0;
}


/* the mean-pressure factor of the scaled superposition: K(x) = exp(k1 x + k2 x^2), K(0) = 1 */
static double meanFactor(const double k[2], double x) { return exp(x * (k[0] + k[1] * x)); }


/* -Σ_j e(p_j) ĉ_j K(p̄) with e(p) = θ1(p) / K(p / 4) (the single-chamber response without its
 * own mean-pressure factor), grouped by diagonals: exactly 0 when p1 = p3 and p2 = p4 */
static void superposeBend(const Curve* base, const double k[2], int s, const double pc[4],
                          double bend[2]) {
  double t[4];
  for (int j = 0; j < 4; j++) {
    double q[NB];
    t[j] = 0;
    if (pc[j] > 0) {
      curveEval(base, pc[j], s, q);
      t[j] = q[B_THETA] / meanFactor(k, 0.25 * pc[j]);
    }
  }
  const double f = meanFactor(k, 0.25 * ((pc[0] + pc[1]) + (pc[2] + pc[3])));
  const double g1 = t[0] - t[2], g2 = t[1] - t[3];
  bend[0] = -RSQ2 * (g1 + g2) * f;
  bend[1] = -RSQ2 * (g1 - g2) * f;
}


/* the bend base at canonical pressures pc (P = pc[0] <= range), canonical frame: the
 * superposition of the single-chamber response (scaled by the fitted mean-pressure factor for
 * CSR_CAL_RULE_SCALED), or 0 */
static void baseBend(const csrCalModel* m, int s, const double pc[4], double bend[2]) {
  bend[0] = bend[1] = 0;
  if (m->opt.rule == CSR_CAL_RULE_SUPERPOSITION || m->opt.rule == CSR_CAL_RULE_SCALED) {
    superposeBend(&m->base, m->kfac[s], s, pc, bend);
  }
}


/* the scalar base (changes of stretch, radial, largest radial growth) at canonical pc: the
 * superposition of the single-chamber response, the all-four response at the mean pressure,
 * or 0 */
static void baseScalars(const csrCalModel* m, int s, const double pc[4], double sc[3]) {
  sc[0] = sc[1] = sc[2] = 0;
  if (m->opt.scalar_rule == CSR_CAL_RULE_SUPERPOSITION) {
    for (int j = 0; j < 4; j++) {
      if (pc[j] > 0) {
        double q[NB];
        curveEval(&m->base, pc[j], s, q);
        for (int c = 0; c < 3; c++) sc[c] += q[B_STRETCH + c];
      }
    }
  } else if (m->opt.scalar_rule == CSR_CAL_RULE_MEAN) {
    const double pbar = 0.25 * ((pc[0] + pc[1]) + (pc[2] + pc[3]));
    if (pbar > 0) {
      double q[NF];
      curveEval(&m->mean, pbar, s, q);
      for (int c = 0; c < 3; c++) sc[c] = q[F_STRETCH + c];
    }
  }
}


/* the model in the canonical frame: bend and scalars of segment s at canonical pc */
static void evalCanonical(const csrCalModel* m, int s, const double pc[4], double bend[2],
                          double sc[3]) {
  const double P = pc[0];
  const double x2 = pc[1] / P, x3 = pc[2] / P, x4 = pc[3] / P;
  const double w = x2 > 0 ? x4 / x2 : 0;
  double W[NV];
  weights(m, x2, w, x3, W);
  double f[NF] = {0, 0, 0, 0, 0};
  for (int v = 0; v < NV; v++) {
    if (W[v] != 0) {
      double fv[NF];
      curveEval(&m->field[v], P, s, fv);
      for (int q = 0; q < NF; q++) {
        f[q] += W[v] * fv[q];
      }
    }
  }
  double bs[3];
  baseBend(m, s, pc, bend);
  baseScalars(m, s, pc, bs);
  for (int c = 0; c < 3; c++) {
    sc[c] = f[F_STRETCH + c] + bs[c];
  }
  /* a along -m̂, b along m̂ turned by +90 deg; m = 0 (only the elongation modes weigh) has
   * a = b = 0 */
  double mv[2];
  moment(pc, mv);
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
  canonical(q, pc, &k, &mir);
  if (pc[0] > m->p_max) {
    pc[0] = m->p_max; /* round-off above the last row */
  }
  evalCanonical(m, seg, pc, bc, sc);
  fromCanonical(bc, k, mir, out->bend);
  out->stretch = 1 + sc[0];
  out->radial = sc[1];
  out->radius = m->leg.a + sc[2];
  return 0;
}


/* ---- building ----------------------------------------------------------------------------- */

/* rows of a case up to its limit point (a pressure-controlled actuator snaps past it) */
static int usableRows(const csrCalCase* c) {
  int n = c->m;
  if (isfinite(c->p_limit)) {
    n = 0;
    while (n < c->m && c->pressure[n] <= c->p_limit + P_RANGE_TOL) n++;
  }
  return n;
}


/* the number of rows of c needed to reach P: up to the first row >= P */
static int rowsTo(const csrCalCase* c, double P) {
  int n = 1;
  while (n < c->m && c->pressure[n - 1] < P - P_RANGE_TOL) n++;
  return n;
}


/* the base: Ω1 alone, its symmetric part (along the diagonal d1), rest row subtracted */
static int buildBase(csrCalModel* m, const csrCalCase* c) {
  const int n = rowsTo(c, m->p_max);
  if (!curveAlloc(&m->base, n, NB)) {
    return 0;
  }
  for (int i = 0; i < n; i++) {
    m->base.p[i] = c->pressure[i];
    for (int s = 0; s < CSR_NSEG; s++) {
      double* y = m->base.y + (i * CSR_NSEG + s) * NB;
      const double b0 = c->bend[6 * i + 2 * s] - c->bend[2 * s];
      const double b1 = c->bend[6 * i + 2 * s + 1] - c->bend[2 * s + 1];
      y[B_THETA] = -RSQ2 * (b0 + b1);
      y[B_STRETCH] = c->stretch[3 * i + s] - c->stretch[s];
      y[B_RADIAL] = c->radial[3 * i + s] - c->radial[s];
      y[B_RADMAX] = c->radial_max[3 * i + s] - c->radial_max[s];
    }
  }
  curveSlopes(&m->base);
  return 1;
}


/* one bending mode's row for the mean-pressure factor fit: canonical pressures and the FE's
 * bend magnitude along -m̂ (rad) */
typedef struct {
  double pc[4];
  double a;
} FitRow;


/* log(a_model / a_FE) of every row for factor k (a model magnitude <= 0 counts as a miss of
 * 10, far outside any fit) */
static void fitResiduals(const Curve* base, int s, const FitRow* rows, int n, const double k[2],
                         double* r) {
  for (int i = 0; i < n; i++) {
    double b[2], mv[2];
    superposeBend(base, k, s, rows[i].pc, b);
    moment(rows[i].pc, mv);
    const double mn = hypot(mv[0], mv[1]);
    const double a = -(b[0] * mv[0] + b[1] * mv[1]) / mn;
    r[i] = a > 0 ? log(a / rows[i].a) : 10;
  }
}


/* Fit K(x) = exp(k1 x + k2 x^2) of segment s to the bending modes (Gauss-Newton on log
 * magnitudes, rows bent by more than FIT_MIN_BEND). Falls back to K = 1 when there are fewer
 * than 3 rows or the fit leaves K outside [FIT_K_MIN, FIT_K_MAX] on the range. */
#define FIT_MIN_BEND (1.0 * CS_DEG) /* smaller bends are dominated by the FE's asymmetry */
#define FIT_K_MIN 0.2
#define FIT_K_MAX 5.0
static int fitMeanFactor(csrCalModel* m, const csrCalCase* const* mode, int s) {
  static const int kRolesFit[4] = {CSR_CAL_O12, CSR_CAL_O124, CSR_CAL_O12R05, CSR_CAL_O12O34R3};
  int cap = 0;
  for (int q = 0; q < 4; q++) cap += mode[kRolesFit[q]] ? mode[kRolesFit[q]]->m : 0;
  FitRow* rows = malloc((size_t)(cap > 0 ? cap : 1) * sizeof *rows);
  double* r = malloc((size_t)(3 * (cap > 0 ? cap : 1)) * sizeof(double));
  if (!rows || !r) {
    free(rows), free(r);
    return 0;
  }
  int n = 0;
  for (int q = 0; q < 4; q++) {
    const csrCalCase* c = mode[kRolesFit[q]];
    for (int i = 1; c && i < c->m && c->pressure[i] <= m->p_max + P_RANGE_TOL; i++) {
      double mv[2];
      moment(c->ratio, mv);
      const double mn = hypot(mv[0], mv[1]);
      const double b0 = c->bend[6 * i + 2 * s] - c->bend[2 * s];
      const double b1 = c->bend[6 * i + 2 * s + 1] - c->bend[2 * s + 1];
      const double a = -(b0 * mv[0] + b1 * mv[1]) / mn;
      if (a > FIT_MIN_BEND) {
        for (int j = 0; j < 4; j++) rows[n].pc[j] = c->ratio[j] * c->pressure[i];
        rows[n].a = a;
        n++;
      }
    }
  }
  double k[2] = {0, 0};
  double* r0 = r + cap;
  double* r1 = r + 2 * cap;
  double cost = INFINITY;
  for (int it = 0; n >= 3 && it < 50; it++) {
    fitResiduals(&m->base, s, rows, n, k, r);
    double c0 = 0;
    for (int i = 0; i < n; i++) c0 += r[i] * r[i];
    if (!(c0 < cost * (1 + 1e-12))) {
      break; /* no progress */
    }
    cost = c0;
    /* Jacobian by differences (the factor is smooth; 1e-6 in k moves log a by ~1e-7) */
    const double h = 1e-6;
    const double k0[2] = {k[0] + h, k[1]}, k1[2] = {k[0], k[1] + h};
    fitResiduals(&m->base, s, rows, n, k0, r0);
    fitResiduals(&m->base, s, rows, n, k1, r1);
    double A[3] = {0, 0, 0}, g[2] = {0, 0};
    for (int i = 0; i < n; i++) {
      const double j0 = (r0[i] - r[i]) / h, j1 = (r1[i] - r[i]) / h;
      A[0] += j0 * j0, A[1] += j0 * j1, A[2] += j1 * j1;
      g[0] += j0 * r[i], g[1] += j1 * r[i];
    }
    const double det = A[0] * A[2] - A[1] * A[1];
    if (!(fabs(det) > 0)) {
      break;
    }
    const double d0 = -(A[2] * g[0] - A[1] * g[1]) / det, d1 = -(A[0] * g[1] - A[1] * g[0]) / det;
    k[0] += d0, k[1] += d1;
    if (fabs(d0) + fabs(d1) < 1e-12) {
      break;
    }
  }
  /* keep a fit that is finite and moderate over the range; else no factor */
  int ok = n >= 3 && isfinite(k[0]) && isfinite(k[1]);
  for (int q = 0; q <= 10 && ok; q++) {
    const double K = meanFactor(k, 0.1 * q * m->p_max);
    ok = K >= FIT_K_MIN && K <= FIT_K_MAX;
  }
  if (!ok) {
    k[0] = k[1] = 0;
  }
  m->kfac[s][0] = k[0], m->kfac[s][1] = k[1];
  fitResiduals(&m->base, s, rows, n, k, r);
  double rms = 0;
  for (int i = 0; i < n; i++) rms += r[i] * r[i];
  m->kfit_rms[s] = n > 0 ? sqrt(rms / n) : NAN;
  free(rows), free(r);
  return 1;
}


/* the all-four mode's scalar changes from rest, for the mean-pressure scalar base */
static int buildMean(csrCalModel* m, const csrCalCase* c) {
  const int n = rowsTo(c, m->p_max);
  if (!curveAlloc(&m->mean, n, NF)) {
    return 0;
  }
  for (int i = 0; i < n; i++) {
    m->mean.p[i] = c->pressure[i];
    for (int s = 0; s < CSR_NSEG; s++) {
      double* y = m->mean.y + (i * CSR_NSEG + s) * NF;
      y[F_A] = y[F_B] = 0;
      y[F_STRETCH] = c->stretch[3 * i + s] - c->stretch[s];
      y[F_RADIAL] = c->radial[3 * i + s] - c->radial[s];
      y[F_RADMAX] = c->radial_max[3 * i + s] - c->radial_max[s];
    }
  }
  curveSlopes(&m->mean);
  return 1;
}


/* vertex v from case c (mirror: the image of c under the mirror Ω1 <-> Ω2, Ω3 <-> Ω4) with
 * canonical pattern r: symmetric part, rest subtracted, minus the base under the superposition
 * rule, minus the lower vertices' interpolation for the refining modes (surplus) */
static int buildField(csrCalModel* m, int v, const csrCalCase* c, int mirror,
                      const double r[4]) {
  const int n = rowsTo(c, m->p_max);
  Curve* f = &m->field[v];
  if (!curveAlloc(f, n, NF)) {
    return 0;
  }
  double mv[2];
  moment(r, mv);
  const double mn = hypot(mv[0], mv[1]);
  const double u0 = mn > 0 ? mv[0] / mn : 0, u1 = mn > 0 ? mv[1] / mn : 0;
  const int sym = mirrorSymmetric(r);
  double W[NV];
  weights(m, m->coord[v][0], m->coord[v][1], m->coord[v][2], W);
  for (int i = 0; i < n; i++) {
    const double p = c->pressure[i];
    f->p[i] = p;
    for (int s = 0; s < CSR_NSEG; s++) {
      double* y = f->y + (i * CSR_NSEG + s) * NF;
      double b0 = c->bend[6 * i + 2 * s] - c->bend[2 * s];
      double b1 = c->bend[6 * i + 2 * s + 1] - c->bend[2 * s + 1];
      if (mirror) {
        b1 = -b1;
      }
      y[F_A] = -(b0 * u0 + b1 * u1);
      y[F_B] = sym ? 0 : -b0 * u1 + b1 * u0;
      if (mn == 0) {
        y[F_A] = y[F_B] = 0; /* zero pressure moment: no bend by symmetry */
      }
      y[F_STRETCH] = c->stretch[3 * i + s] - c->stretch[s];
      y[F_RADIAL] = c->radial[3 * i + s] - c->radial[s];
      y[F_RADMAX] = c->radial_max[3 * i + s] - c->radial_max[s];
      if (p > 0) {
        double pc[4] = {r[0] * p, r[1] * p, r[2] * p, r[3] * p}, bb[2], bs[3];
        baseBend(m, s, pc, bb);
        baseScalars(m, s, pc, bs);
        y[F_A] -= mn > 0 ? -(bb[0] * u0 + bb[1] * u1) : 0;
        y[F_B] -= mn > 0 && !sym ? -bb[0] * u1 + bb[1] * u0 : 0;
        for (int q = 0; q < 3; q++) {
          y[F_STRETCH + q] -= bs[q];
        }
      }
      /* refining modes: subtract what the vertices below them already give here */
      for (int u = 0; u < v && v >= V_R05; u++) {
        if (W[u] != 0 && m->use[u]) {
          double fu[NF];
          curveEval(&m->field[u], p, s, fu);
          for (int q = 0; q < NF; q++) {
            y[q] -= W[u] * fu[q];
          }
        }
      }
    }
  }
  curveSlopes(f);
  return 1;
}


/* Sorted, merged points (x, y) from n candidates: NaN values of y dropped, equal x (within
 * PBAR_TOL) averaged. Writes X, Y (capacity n); returns the count. */
static int mergePoints(const double* x, const double* y, int n, double* X, double* Y) {
  int k = 0;
  for (int i = 0; i < n; i++) {
    if (isnan(y[i])) {
      continue;
    }
    int cnt = 0;
    double sum = 0;
    int seen = 0;
    for (int j = 0; j < k; j++) {
      seen |= fabs(X[j] - x[i]) <= PBAR_TOL;
    }
    if (seen) {
      continue; /* already merged with an earlier equal x */
    }
    for (int j = i; j < n; j++) {
      if (!isnan(y[j]) && fabs(x[j] - x[i]) <= PBAR_TOL) {
        sum += y[j];
        cnt++;
      }
    }
    X[k] = x[i];
    Y[k] = sum / cnt;
    k++;
  }
  /* a handful of points: insertion sort by x */
  for (int a = 1; a < k; a++) {
    for (int b = a; b > 0 && X[b] < X[b - 1]; b--) {
      double tx = X[b], ty = Y[b];
      X[b] = X[b - 1], Y[b] = Y[b - 1];
      X[b - 1] = tx, Y[b - 1] = ty;
    }
  }
  return k;
}


/* mean-pressure stiffness points of every segment from the probes of every mode */
static int buildStiffness(csrCalModel* m, const csrCalTable* t) {
  int cap = 0;
  for (int i = 0; i < t->ncase; i++) {
    cap += t->cases[i].kind == CSR_CAL_MODE ? t->cases[i].k : 0;
  }
  m->k_pmax = NAN;
  if (cap == 0) {
    return 1;
  }
  double* x = malloc((size_t)cap * sizeof(double));
  double* ei = malloc((size_t)cap * sizeof(double));
  double* ea = malloc((size_t)cap * sizeof(double));
  int ok = x && ei && ea;
  double pmax = INFINITY;
  for (int s = 0; s < CSR_NSEG && ok; s++) {
    int n = 0;
    for (int i = 0; i < t->ncase; i++) {
      const csrCalCase* c = t->cases + i;
      if (c->kind != CSR_CAL_MODE) {
        continue;
      }
      const double rbar = 0.25 * (c->ratio[0] + c->ratio[1] + c->ratio[2] + c->ratio[3]);
      for (int k = 0; k < c->k; k++) {
        const double e1 = c->EI[6 * k + 2 * s], e2 = c->EI[6 * k + 2 * s + 1];
        /* isotropic section: the mean of the two probes (one if the other failed) */
        x[n] = rbar * c->probe_pressure[k];
        ei[n] = isnan(e1) ? e2 : isnan(e2) ? e1 : 0.5 * (e1 + e2);
        ea[n] = c->EA[3 * k + s];
        n++;
      }
    }
    for (int q = 0; q < 2 && ok; q++) {
      m->kp[q][s] = malloc((size_t)n * sizeof(double));
      m->kv[q][s] = malloc((size_t)n * sizeof(double));
      ok = m->kp[q][s] && m->kv[q][s];
      if (ok) {
        m->nk[q][s] = mergePoints(x, q == 0 ? ei : ea, n, m->kp[q][s], m->kv[q][s]);
        /* the rest state must be probed: the range starts at p̄ = 0 */
        const int nk = m->nk[q][s];
        pmax = nk > 0 && m->kp[q][s][0] == 0 ? fmin(pmax, m->kp[q][s][nk - 1]) : -1;
      }
    }
  }
  free(x), free(ei), free(ea);
  if (ok && pmax >= 0) {
    m->k_pmax = pmax;
  } else {
    memset(m->nk, 0, sizeof m->nk);
  }
  return ok;
}


csrCalModel* csr_calModelCreate(const csrCalTable* t, const csrActuator* leg,
                                const csrCalOptions* opt, csError* err) {
  csrCalModel* m = calloc(1, sizeof *m);
  if (!m) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", t->path);
    return NULL;
  }
  m->leg = *leg;
  m->opt = opt ? *opt : csr_calModelDefaultOptions();
  /* the modes by their chamber patterns (names are for messages only) */
  const csrCalCase* mode[CSR_CAL_NROLE];
  for (int r = 0; r < CSR_CAL_NROLE; r++) {
    mode[r] = csr_calTableFind(t, CSR_CAL_MODE, kRoles[r].ratio);
    if (!mode[r] && r <= CSR_CAL_O1234) {
      cs_errorSet(err, CS_ERR_PARSE, "%s: the table has no finished mode case %s (chambers at "
                  "%g:%g:%g:%g): the calibration model needs it", t->path, kRoles[r].name,
                  kRoles[r].ratio[0], kRoles[r].ratio[1], kRoles[r].ratio[2], kRoles[r].ratio[3]);
      csr_calModelDestroy(m);
      return NULL;
    }
    if (r > CSR_CAL_O1234 && (m->opt.exclude & (1u << r))) {
      mode[r] = NULL;
    }
  }
  /* the range: the smallest end of the modes used */
  m->p_max = INFINITY;
  for (int r = 0; r < CSR_CAL_NROLE; r++) {
    if (mode[r]) {
      const int n = usableRows(mode[r]);
      const double end = n >= 2 ? mode[r]->pressure[n - 1] : 0;
      if (end < m->p_max) {
        m->p_max = end;
        snprintf(m->limit_case, sizeof m->limit_case, "%s", mode[r]->name);
      }
    }
  }
  if (!(m->p_max > 0)) {
    cs_errorSet(err, CS_ERR_RANGE, "%s: mode case %s has no pressure range before its limit "
                "point", t->path, m->limit_case);
    csr_calModelDestroy(m);
    return NULL;
  }
  /* vertices: role, mirror image, prism coordinates */
  static const struct {
    int role, mirror;
  } kV[NV] = {{CSR_CAL_O1, 0},   {CSR_CAL_O13, 0},   {CSR_CAL_O12, 0},    {CSR_CAL_O124, 0},
              {CSR_CAL_O124, 1}, {CSR_CAL_O1234, 0}, {CSR_CAL_O12R05, 0}, {CSR_CAL_O12O34R3, 0}};
  int ok = buildBase(m, mode[CSR_CAL_O1]) && buildMean(m, mode[CSR_CAL_O1234]);
  for (int s = 0; s < CSR_NSEG && ok && m->opt.rule == CSR_CAL_RULE_SCALED; s++) {
    ok = fitMeanFactor(m, mode, s);
  }
  for (int v = 0; v < NV && ok; v++) {
    const csrCalCase* c = mode[kV[v].role];
    m->use[v] = c != NULL;
    if (!c) {
      continue;
    }
    double r[4];
    memcpy(r, c->ratio, sizeof r);
    if (kV[v].mirror) {
      const double t0 = r[0], t2 = r[2];
      r[0] = r[1], r[1] = t0, r[2] = r[3], r[3] = t2;
    }
    m->coord[v][0] = r[1];
    m->coord[v][1] = r[1] > 0 ? r[3] / r[1] : 0;
    m->coord[v][2] = r[2];
    ok = buildField(m, v, c, kV[v].mirror, r);
  }
  ok = ok && buildStiffness(m, t);
  if (!ok) {
    cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", t->path);
    csr_calModelDestroy(m);
    return NULL;
  }
  int nmode = 0;
  for (int r = 0; r < CSR_CAL_NROLE; r++) nmode += mode[r] != NULL;
  char stiff[96];
  if (isnan(m->k_pmax)) {
    snprintf(stiff, sizeof stiff, "no stiffness probes");
  } else {
    snprintf(stiff, sizeof stiff, "EI, EA at mean pressures 0..%g MPa", m->k_pmax);
  }
  snprintf(m->name, sizeof m->name, "FE mode table (%s; %d modes; 0..%g MPa, range ended by %s; "
           "%s; l_soft %g mm, %.64s, version %.32s): %.512s",
           m->opt.rule == CSR_CAL_RULE_SUPERPOSITION ? "superposition + interpolated interactions"
                                                     : "interpolation between modes",
           nmode, m->p_max, m->limit_case, stiff, t->fe_mesh_size, t->fe_solver, t->version,
           t->path);
  return m;
}


void csr_calModelDestroy(csrCalModel* m) {
  if (!m) {
    return;
  }
  curveFree(&m->base);
  curveFree(&m->mean);
  for (int v = 0; v < NV; v++) {
    curveFree(&m->field[v]);
  }
  for (int q = 0; q < 2; q++) {
    for (int s = 0; s < CSR_NSEG; s++) {
      free(m->kp[q][s]), free(m->kv[q][s]);
    }
  }
  free(m);
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


void csr_calModelMeanFactor(const csrCalModel* m, int seg, double k[2], double* rms) {
  const int ok = seg >= 0 && seg < CSR_NSEG;
  k[0] = ok ? m->kfac[seg][0] : 0;
  k[1] = ok ? m->kfac[seg][1] : 0;
  *rms = ok && m->opt.rule == CSR_CAL_RULE_SCALED ? m->kfit_rms[seg] : NAN;
}


int csr_calModelUses(const csrCalModel* m, csrCalRole role) {
  static const int kFirst[CSR_CAL_NROLE] = {V_O1, V_O13, V_O12, V_O124, V_O1234, V_R05, V_R3};
  return role >= 0 && role < CSR_CAL_NROLE && m->use[kFirst[role]];
}


void csr_calModelStiffnessPoints(const csrCalModel* m, int seg, int which, int* n,
                                 const double** pbar, const double** value) {
  const int ok = seg >= 0 && seg < CSR_NSEG && (which == 0 || which == 1);
  *n = ok ? m->nk[which][seg] : 0;
  *pbar = *n ? m->kp[which][seg] : NULL;
  *value = *n ? m->kv[which][seg] : NULL;
}


/* ---- comparison with a case ---------------------------------------------------------------- */

csStatus csr_calModelCompare(const csrCalModel* m, const csrCalCase* c, csrCalCompare* out,
                             csError* err) {
  memset(out, 0, sizeof *out);
  if (c->kind == CSR_CAL_GRAVITY) {
    return cs_errorSet(err, CS_ERR_ARG, "case %s: a gravity case has no chamber pattern",
                       c->name);
  }
  out->bend_deg = -1;
  const double L = csr_actuatorLength(&m->leg);
  for (int i = 0; i < c->m && c->pressure[i] <= m->p_max + P_RANGE_TOL; i++) {
    const double p = c->pressure[i];
    csrSegmentStrain sm[CSR_NSEG], sf[CSR_NSEG];
    memset(sm, 0, sizeof sm);
    memset(sf, 0, sizeof sf);
    for (int s = 0; s < CSR_NSEG; s++) {
      const double P[4] = {c->ratio[0] * p, c->ratio[1] * p, c->ratio[2] * p, c->ratio[3] * p};
      csrCalSegment q;
      if (csr_calModelEval(m, s, P, &q) != 0) {
        return cs_errorSet(err, CS_ERR_SOLVER, "case %s: the model fails at %g MPa", c->name, p);
      }
      const double* bf = c->bend + 6 * i + 2 * s;
      const double d = hypot(q.bend[0] - bf[0], q.bend[1] - bf[1]), mag = hypot(bf[0], bf[1]);
      const double score = d / fmax(TARGET_BEND_REL * mag, TARGET_BEND_ABS);
      if (d / CS_DEG > out->bend_deg) {
        out->bend_deg = d / CS_DEG, out->bend_at_p = p, out->bend_at_seg = s;
        out->bend_fe_deg = mag / CS_DEG;
      }
      out->bend_score = fmax(out->bend_score, score);
      out->stretch = fmax(out->stretch, fabs(q.stretch - c->stretch[3 * i + s]));
      const double S = m->leg.S[s];
      sm[s].lambda0 = q.stretch, sm[s].kappa[0] = -q.bend[0] / S, sm[s].kappa[1] = -q.bend[1] / S;
      sf[s].lambda0 = c->stretch[3 * i + s];
      sf[s].kappa[0] = -bf[0] / S, sf[s].kappa[1] = -bf[1] / S;
    }
    double tm[3], tf[3];
    if (csr_ccForwardKinematics(&m->leg, sm, 1, NULL, tm, NULL, err) != CS_OK ||
        csr_ccForwardKinematics(&m->leg, sf, 1, NULL, tf, NULL, err) != CS_OK) {
      return cs_errorSet(err, CS_ERR_SOLVER, "case %s: kinematics fail at %g MPa", c->name, p);
    }
    const double* tip = c->tip + 3 * i;
    const double dt[3] = {tm[0] - tip[0], tm[1] - tip[1], tm[2] - tip[2]};
    const double dc[3] = {tf[0] - tip[0], tf[1] - tip[1], tf[2] - tip[2]};
    out->tip_mm = fmax(out->tip_mm, csu_norm3(dt));
    out->tip_cc_mm = fmax(out->tip_cc_mm, csu_norm3(dc));
    out->tip_score = fmax(out->tip_score, csu_norm3(dt) / (TARGET_TIP_REL * L));
    out->rows++;
    out->p_last = p;
  }
  if (out->rows == 0) {
    out->bend_deg = 0;
    return cs_errorSet(err, CS_ERR_RANGE, "case %s: no row within the model's range", c->name);
  }
  return CS_OK;
}

/* robot_calibration_build.c: building the calibration model from a checked table
 * (robot_calibration_model.h has the rule): the modes' rows as monotone cubic curves (their
 * symmetric part, rest row subtracted, residual from the base, surplus over the lower vertices),
 * the fit of the mean-pressure factor, the stiffness points. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robot_calibration_internal.h"

/* ---- curves: monotone piecewise cubic Hermite (Fritsch-Carlson, as scipy's PCHIP) -------- */

int csr_calCurveAlloc_(csrCalCurve* c, int m, int nc) {
  c->m = m, c->nc = nc;
  c->p = malloc((size_t)m * sizeof(double));
  c->y = malloc((size_t)m * CSR_NSEG * nc * sizeof(double));
  c->d = malloc((size_t)m * CSR_NSEG * nc * sizeof(double));
  return c->p && c->y && c->d;
}


void csr_calCurveFree_(csrCalCurve* c) {
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
void csr_calCurveSlopes_(csrCalCurve* c) {
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
int csr_calRowsTo_(const csrCalCase* c, double P) {
  int n = 1;
  while (n < c->m && c->pressure[n - 1] < P - P_RANGE_TOL) n++;
  return n;
}


/* the base: Ω1 alone, its symmetric part (along the diagonal d1), rest row subtracted */
static int buildBase(csrCalModel* m, const csrCalCase* c) {
  const int n = csr_calRowsTo_(c, m->p_max);
  if (!csr_calCurveAlloc_(&m->base, n, NB)) {
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
  csr_calCurveSlopes_(&m->base);
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
static void fitResiduals(const csrCalCurve* base, int s, const FitRow* rows, int n, const double k[2],
                         double* r) {
  for (int i = 0; i < n; i++) {
    double b[2], mv[2];
    csr_calSuperposeBend_(base, k, s, rows[i].pc, b);
    csr_calMoment_(rows[i].pc, mv);
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
  enum { NFIT = 9 };
  static const int kRolesFit[NFIT] = {CSR_CAL_O12,       CSR_CAL_O124,       CSR_CAL_O12R05,
                                      CSR_CAL_O12O34R3,  CSR_CAL_O1O234R05,  CSR_CAL_O1O234R075,
                                      CSR_CAL_O124O3R05, CSR_CAL_O1O23R05O4R025, CSR_CAL_O1O3R05};
  int cap = 0;
  for (int q = 0; q < NFIT; q++) cap += mode[kRolesFit[q]] ? mode[kRolesFit[q]]->m : 0;
  FitRow* rows = malloc((size_t)(cap > 0 ? cap : 1) * sizeof *rows);
  double* r = malloc((size_t)(3 * (cap > 0 ? cap : 1)) * sizeof(double));
  if (!rows || !r) {
    free(rows), free(r);
    return 0;
  }
  int n = 0;
  for (int q = 0; q < NFIT; q++) {
    const csrCalCase* c = mode[kRolesFit[q]];
    for (int i = 1; c && i < c->m && c->pressure[i] <= m->p_max + P_RANGE_TOL; i++) {
      double mv[2];
      csr_calMoment_(c->ratio, mv);
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
    const double K = csr_calMeanFactor_(k, 0.1 * q * m->p_max);
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
  const int n = csr_calRowsTo_(c, m->p_max);
  if (!csr_calCurveAlloc_(&m->mean, n, NF)) {
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
  csr_calCurveSlopes_(&m->mean);
  return 1;
}


/* vertex v from case c (mirror: the image of c under the mirror Ω1 <-> Ω2, Ω3 <-> Ω4) with
 * canonical pattern r: symmetric part, rest subtracted, minus the base under the superposition
 * rule, minus the lower vertices' interpolation for the refining modes (surplus) */
static int buildField(csrCalModel* m, int v, const csrCalCase* c, int mirror,
                      const double r[4]) {
  const int n = csr_calRowsTo_(c, m->p_max);
  csrCalCurve* f = &m->field[v];
  if (!csr_calCurveAlloc_(f, n, NF)) {
    return 0;
  }
  double mv[2];
  csr_calMoment_(r, mv);
  const double mn = hypot(mv[0], mv[1]);
  const double u0 = mn > 0 ? mv[0] / mn : 0, u1 = mn > 0 ? mv[1] / mn : 0;
  const int sym = csr_calMirrorSymmetric_(r);
  double W[NV];
  csr_calWeights_(m, m->coord[v][0], m->coord[v][1], m->coord[v][2], W);
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
        csr_calBaseBend_(m, s, pc, bb);
        csr_calBaseScalars_(m, s, pc, bs);
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
          csr_calCurveEval_(&m->field[u], p, s, fu);
          for (int q = 0; q < NF; q++) {
            y[q] -= W[u] * fu[q];
          }
        }
      }
    }
  }
  csr_calCurveSlopes_(f);
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


double csr_calProbeEI_(const csrCalCase* c, int k, int s) {
  const double e1 = c->EI[6 * k + 2 * s], e2 = c->EI[6 * k + 2 * s + 1];
  return isnan(e1) ? e2 : isnan(e2) ? e1 : 0.5 * (e1 + e2);
}


/* The probes' reduction to EI and EA (fem_calibration.c) is exact for a straight segment; a bent
 * one mixes modes: the tip force also bends it, which moves its chord-and-angle stretch, and the
 * moment varies along the arc. Measured on Omega1&Omega2 of the leg (tension-only fibres): at
 * 0.1 MPa (segments bent 0.30 rad) EI is within 5 % of the straight all-four leg's but EA is 6-57 %
 * above it; at 0.2-0.3 MPa (0.9-1.6 rad) EI scatters 552-8614 N mm^2 and EA 48-96 N. So a probe
 * counts for a segment only where that segment's bend at the probe's row is at most: */
#define PROBE_BEND_EI 0.5 /* rad, for EI */
#define PROBE_BEND_EA 0.1 /* rad, for EA */

/* the bend angle (rad) of segment s at the row of probe k (the reader checked it is a row) */
static double probeBend(const csrCalCase* c, int k, int s) {
  for (int i = 0; i < c->m; i++) {
    if (fabs(c->pressure[i] - c->probe_pressure[k]) <= PBAR_TOL) {
      return hypot(c->bend[6 * i + 2 * s], c->bend[6 * i + 2 * s + 1]);
    }
  }
  return INFINITY;
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
        const double beta = probeBend(c, k, s);
        x[n] = rbar * c->probe_pressure[k];
        ei[n] = beta > PROBE_BEND_EI ? NAN : csr_calProbeEI_(c, k, s);
        ea[n] = beta > PROBE_BEND_EA ? NAN : c->EA[3 * k + s];
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
    double ratio[CSR_NCHAMBER];
    const char* name;
    csr_calModelModePattern((csrCalRole)r, ratio, &name);
    mode[r] = csr_calTableFind(t, CSR_CAL_MODE, ratio);
    if (!mode[r] && r <= CSR_CAL_O1234) {
      cs_errorSet(err, CS_ERR_PARSE, "%s: the table has no finished mode case %s (chambers at "
                  "%g:%g:%g:%g): the calibration model needs it", t->path, name, ratio[0],
                  ratio[1], ratio[2], ratio[3]);
      csr_calModelDestroy(m);
      return NULL;
    }
    if (r > CSR_CAL_O1234 && (m->opt.exclude & (1u << r))) {
      mode[r] = NULL;
    }
    /* the modes past the prism's hierarchy are nodes of the RBF rules only */
    if (r > CSR_CAL_O1O3R05 && m->opt.rule != CSR_CAL_RULE_RBF &&
        m->opt.rule != CSR_CAL_RULE_RBF_PAIR) {
      mode[r] = NULL;
    }
    m->role_use[r] = mode[r] != NULL;
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
              {CSR_CAL_O124, 1}, {CSR_CAL_O1234, 0}, {CSR_CAL_O12R05, 0},
              {CSR_CAL_O1O3R05, 0}, {CSR_CAL_O124O3R05, 0}, {CSR_CAL_O124O3R05, 1},
              {CSR_CAL_O12O34R3, 0}, {CSR_CAL_O1O234R05, 0}, {CSR_CAL_O1O234R075, 0},
              {CSR_CAL_O1O23R05O4R025, 0}};
  int ok = buildBase(m, mode[CSR_CAL_O1]) && buildMean(m, mode[CSR_CAL_O1234]);
  for (int s = 0; s < CSR_NSEG && ok && m->opt.rule == CSR_CAL_RULE_SCALED; s++) {
    ok = fitMeanFactor(m, mode, s);
  }
  for (int s = 0; s < CSR_NSEG && ok && m->opt.rule == CSR_CAL_RULE_RBF_PAIR; s++) {
    ok = csr_calPairFit_(m, mode, s);
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
  int rbf_ok = 1;
  if (ok && (m->opt.rule == CSR_CAL_RULE_RBF || m->opt.rule == CSR_CAL_RULE_RBF_PAIR)) {
    rbf_ok = csr_calRbfBuild_(m, mode);
    ok = rbf_ok == 1;
  }
  if (rbf_ok < 0) {
    cs_errorSet(err, CS_ERR_SOLVER, "%s: the RBF rule's kernel matrix is singular", t->path);
    csr_calModelDestroy(m);
    return NULL;
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
           : m->opt.rule == CSR_CAL_RULE_RBF ? "superposition + RBF-interpolated interactions"
           : m->opt.rule == CSR_CAL_RULE_RBF_PAIR
               ? "pair-factor superposition + RBF-interpolated interactions"
                                             : "interpolation between modes",
           nmode, m->p_max, m->limit_case, stiff, t->fe_mesh_size, t->fe_solver, t->version,
           t->path);
  return m;
}


void csr_calModelDestroy(csrCalModel* m) {
  if (!m) {
    return;
  }
  csr_calCurveFree_(&m->base);
  csr_calCurveFree_(&m->mean);
  for (int v = 0; v < NV; v++) {
    csr_calCurveFree_(&m->field[v]);
  }
  for (int r = 0; r < CSR_CAL_NROLE; r++) {
    csr_calCurveFree_(&m->rbf_res[r]);
  }
  free(m->rbf_inv);
  free(m->rbf_B);
  free(m->rbf_G);
  for (int q = 0; q < 2; q++) {
    for (int s = 0; s < CSR_NSEG; s++) {
      free(m->kp[q][s]), free(m->kv[q][s]);
    }
  }
  free(m);
}



/* robot_analytic.c: analytic constant-curvature actuator model and forward kinematics (see
 * robot_analytic.h for the derivation, D1-D7, and the sign conventions).
 *
 * Rationale of the numerics. The equilibrium (A5) is the minimum of a strictly convex,
 * coercive potential in q = (λ0, κ1, κ2), so we minimise it by Newton's method with the exact
 * Hessian and a backtracking (Armijo) line search that also keeps λ > 0 on the whole section;
 * from the linear (small-strain) solution it converges in 3-8 iterations up to 5 MPa.
 * The paper's single-DOF variant is the same minimisation restricted to the line
 * q = (1, 0, 0) + t (h, κ̂), so both share one solver (`minimise`, m = 3 or 1 unknowns).
 * Alternatives rejected: a closed-form small-strain beam (wrong at the large stretches of a
 * 360° bend) and a fixed-point iteration on the moment balance (slow, no convergence proof).
 * The section quadrature is generated on the fly (no storage, no allocation); a segment solve
 * costs 4-9 section passes of 2560 integrand evaluations, ~0.2 ms (see the header). */
#include "robot_analytic.h"

#include <math.h>
#include <string.h>

enum { NPATCH = 5 };                      /* boundary pieces of a quadrant cell seen from (b,b) */
static const double kArmijo = 1e-4;       /* sufficient-decrease factor of the line search */
static const double kEnergyNoise = 1e-12; /* relative round-off allowed in the potential */
static const int kMaxHalvings = 60;       /* line-search step halvings before giving up */
static const double kSmallAngle = 1e-4;   /* below this angle (rad) the arc uses series */
static const double kGaussTol = 1e-16;    /* Newton step on a Legendre root: at round-off */
static const int kGaussIter = 100;        /* Newton iterations per root (3-6 are used) */

/* Gauss-Legendre nodes and weights on [-1, 1] */
typedef struct {
  int n;
  double x[CSR_ANALYTIC_MAX_NQUAD], w[CSR_ANALYTIC_MAX_NQUAD];
} GaussRule;

/* polar quadrature of the quadrant cell [0,a]² (fillet at (a,a)) about the chamber centre */
typedef struct {
  double a, b, r1, r2;
  double phi[NPATCH + 1]; /* kink directions (rad), increasing, phi[5] = phi[0] + 2π */
  GaussRule gphi, gr;     /* angular and radial rules */
} SectionRule;

/* what sectionIntegrate accumulates: area moments, or W with its derivatives at q */
typedef enum { INT_GEOMETRY, INT_DERIVATIVES } IntMode;

/* accumulated section integrals */
typedef struct {
  double area, m11, m22; /* INT_GEOMETRY: ∫dA, ∫x1² dA, ∫x2² dA (mm^2, mm^4) */
  double e;              /* ∫ W dA (N) */
  double g[3];           /* ∫ W' (1, x1, x2) dA (N, N mm) */
  double h[3][3];        /* ∫ W'' (1, x)(1, x)^T dA */
} SectionSums;

/* the minimisation problem: Φ(y) = Σ coef ∫W(λ(q)) dA - F·q with q = q0 + B y */
typedef struct {
  SectionRule rule;
  double C10, C20;            /* MPa */
  double len_holed, len_full; /* lengths (mm) weighting the holed / full section integrals */
  double F[3];                /* generalised chamber forces Σ p_j A Lc (1, c_j) (N, N mm) */
  double q0[3];               /* q at y = 0 */
  double B[3][3];             /* columns 0..m-1 span the unknowns */
  int m;                      /* number of unknowns, 1 or 3 */
} Problem;

/* Gauss-Legendre rule of order n (Newton on P_n from Tricomi's initial guess) */
static void gaussLegendre(int n, GaussRule* g);
/* check the chamber fits inside the filleted square and build the cell's patches */
static csStatus sectionRuleInit(const csrActuator* act, const csrAnalyticOptions* opt,
                                SectionRule* sr, csError* err);
/* distance from the chamber centre to the cell boundary along (c, s) within patch k */
static double cellBoundary(const SectionRule* sr, int k, double c, double s);
/* integrate over the 4 mirrored cells with inner radius r_in (r1 holed, 0 full section) */
static void sectionIntegrate(const SectionRule* sr, double C10, double C20, double r_in,
                             const double q[3], IntMode mode, SectionSums* out);
/* smallest stretch over the filleted square for q (λ is affine: attained on the boundary) */
static double minStretch(const SectionRule* sr, const double q[3]);
/* Φ and its gradient/Hessian in the m unknowns */
static double potential(const Problem* pb, const double q[3], double gy[3], double Hy[3][3]);
/* minimise Φ over y from y = 0 (damped Newton); q receives the minimiser */
static csStatus minimise(const Problem* pb, const csrAnalyticOptions* opt, int seg, double q[3],
                         int* iterations, csError* err);
/* argument checks shared by the segment solvers: resolves the options (NULL = defaults) into
 * *o, builds the section rule, Lc and the chamber force vector */
static csStatus setupProblem(const csrActuator* act, int seg, const double p[4],
                             const csrAnalyticOptions* opt, const csrSegmentStrain* out,
                             csrAnalyticOptions* o, Problem* pb, csError* err);
/* Yeoh energy with λ2 = 1, λ3 = 1/λ (D2): W, dW/dλ, d²W/dλ² */
static void yeohStretch(double C10, double C20, double lam, double* W, double* dW, double* d2W);
/* tip direction angle of a curvature vector (centreline turns towards -κ) */
static double bendDirection(const double kappa[2], double theta, double tol);


csrAnalyticOptions csr_analyticDefaultOptions(void) {
  csrAnalyticOptions o;
  o.nquad = 16;       /* area and I to ~1e-13 relative (order 12: 5e-10), see header */
  o.nquad_r = 8;      /* θ, λ0 to round-off up to 5 MPa (order 4: 4e-9), see header */
  o.tol_step = 1e-12; /* Newton is quadratic: the error after this step is far below it */
  o.max_iter = 100;   /* typical use is 3-8 iterations */
  return o;
}


static void gaussLegendre(int n, GaussRule* g) {
  g->n = n;
  for (int i = 0; i < n; i++) {
    double x = cos(CS_PI * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < kGaussIter; it++) {
      /* P_n(x) and P_n'(x) by the three-term recurrence */
      double p0 = 1.0, p1 = x;
      for (int k = 2; k <= n; k++) {
        double pk = ((2.0 * k - 1.0) * x * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = pk;
      }
      dp = n * (x * p1 - p0) / (x * x - 1.0);
      double dx = p1 / dp;
      x -= dx;
      if (fabs(dx) < kGaussTol) {
        break;
      }
    }
    g->x[i] = x;
    g->w[i] = 2.0 / ((1.0 - x * x) * dp * dp);
  }
}


static csStatus sectionRuleInit(const csrActuator* act, const csrAnalyticOptions* opt,
                                SectionRule* sr, csError* err) {
  csStatus st = csr_actuatorValidate(act, err);
  if (st != CS_OK) {
    return st;
  }
  if (opt->nquad < 4 || opt->nquad > CSR_ANALYTIC_MAX_NQUAD || opt->nquad_r < 2 ||
      opt->nquad_r > CSR_ANALYTIC_MAX_NQUAD) {
    return cs_errorSet(err, CS_ERR_ARG,
                       "analytic model: need nquad in 4..%d and nquad_r in 2..%d (got %d, %d)",
                       CSR_ANALYTIC_MAX_NQUAD, CSR_ANALYTIC_MAX_NQUAD, opt->nquad, opt->nquad_r);
  }
  double a = act->a, b = act->b, r1 = act->r1, r2 = act->r2;
  /* validation guarantees a - b > r1 (straight walls); the fillet may still cut the chamber
   * when the chamber centre lies in the corner zone (b > a - r2) */
  double qc = b - (a - r2);
  if (qc > 0 && !(r2 - sqrt(2.0) * qc > r1)) {
    return cs_errorSet(err, CS_ERR_RANGE,
                       "analytic model: chamber (b = %g, r1 = %g mm) breaks through the corner "
                       "fillet (a = %g, r2 = %g mm)",
                       b, r1, a, r2);
  }
  sr->a = a;
  sr->b = b;
  sr->r1 = r1;
  sr->r2 = r2;
  /* kinks seen from (b,b), counter-clockwise: (0,0), (a,0), (a,a-r2), (a-r2,a), (0,a) */
  sr->phi[0] = atan2(-b, -b);
  sr->phi[1] = atan2(-b, a - b);
  sr->phi[2] = atan2(a - r2 - b, a - b);
  sr->phi[3] = atan2(a - b, a - r2 - b);
  sr->phi[4] = atan2(a - b, -b);
  sr->phi[5] = sr->phi[0] + 2.0 * CS_PI;
  gaussLegendre(opt->nquad, &sr->gphi);
  gaussLegendre(opt->nquad_r, &sr->gr);
  return CS_OK;
}


static double cellBoundary(const SectionRule* sr, int k, double c, double s) {
  double a = sr->a, b = sr->b;
  switch (k) {
    case 0: /* edge y = 0 */
      return -b / s;
    case 1: /* edge x = a */
      return (a - b) / c;
    case 2: { /* fillet arc, centre (a - r2, a - r2): far root of |(b,b) + ρ d - o| = r2 */
      double o = a - sr->r2 - b;
      double dd = o * (c + s);
      return dd + sqrt(fmax(dd * dd - 2.0 * o * o + sr->r2 * sr->r2, 0.0));
    }
    case 3: /* edge y = a */
      return (a - b) / s;
    default: /* edge x = 0 */
      return -b / c;
  }
}


static void sectionIntegrate(const SectionRule* sr, double C10, double C20, double r_in,
                             const double q[3], IntMode mode, SectionSums* out) {
  const GaussRule *gp = &sr->gphi, *gr = &sr->gr;
  const double q0 = q[0], q1 = q[1], q2 = q[2], b = sr->b;
  /* local accumulators (no aliasing with q): geometry moments; energy; gradient ∫W'(1, x);
   * Hessian ∫W''(1, x)(1, x)^T as h0, h1, h2, h11, h12, h22 */
  double area = 0, m11 = 0, m22 = 0, e = 0, g0 = 0, g1 = 0, g2 = 0;
  double h0 = 0, h1 = 0, h2 = 0, h11 = 0, h12 = 0, h22 = 0;
  for (int k = 0; k < NPATCH; k++) {
    double hphi = 0.5 * (sr->phi[k + 1] - sr->phi[k]);
    if (!(hphi > 0)) {
      continue; /* zero-width arc patch when r2 = 0 */
    }
    double mphi = 0.5 * (sr->phi[k + 1] + sr->phi[k]);
    for (int i = 0; i < gp->n; i++) {
      double phi = mphi + hphi * gp->x[i];
      double c = cos(phi), s = sin(phi);
      double rho = cellBoundary(sr, k, c, s);
      double hr = 0.5 * (rho - r_in), mr = 0.5 * (rho + r_in);
      for (int j = 0; j < gr->n; j++) {
        double r = mr + hr * gr->x[j];
        double w = gp->w[i] * gr->w[j] * hphi * hr * r; /* polar Jacobian r dr dφ */
        double X = b + r * c, Y = b + r * s;
        if (mode == INT_GEOMETRY) {
          /* the four mirrored cells contribute equally to these even moments */
          area += 4 * w;
          m11 += 4 * w * X * X;
          m22 += 4 * w * Y * Y;
          continue;
        }
        /* the same point in the four quadrant cells: x = (±X, ±Y) */
        for (int mi = 0; mi < 4; mi++) {
          double x1 = (mi < 2) ? X : -X, x2 = (mi == 0 || mi == 3) ? Y : -Y;
          double W, dW, d2W;
          yeohStretch(C10, C20, q0 + q1 * x1 + q2 * x2, &W, &dW, &d2W);
          double wd = w * dW, wh = w * d2W;
          e += w * W;
          g0 += wd;
          g1 += wd * x1;
          g2 += wd * x2;
          h0 += wh;
          h1 += wh * x1;
          h2 += wh * x2;
          h11 += wh * x1 * x1;
          h12 += wh * x1 * x2;
          h22 += wh * x2 * x2;
        }
      }
    }
  }
  SectionSums r = {area, m11, m22, e, {g0, g1, g2}, {{h0, h1, h2}, {h1, h11, h12}, {h2, h12, h22}}};
  *out = r;
}


static void yeohStretch(double C10, double C20, double lam, double* W, double* dW, double* d2W) {
  double il = 1.0 / lam;
  double gs = lam - il; /* λ - 1/λ */
  double f = gs * gs;   /* I1 - 3 */
  double fp = 2.0 * gs * (1.0 + il * il);
  double fpp = 2.0 * (1.0 + 3.0 * il * il * il * il);
  double k = C10 + 2.0 * C20 * f; /* dW/df */
  *W = (C10 + C20 * f) * f;
  *dW = k * fp;
  *d2W = k * fpp + 2.0 * C20 * fp * fp;
}


static double minStretch(const SectionRule* sr, const double q[3]) {
  /* support function of the filleted square in direction -κ */
  double kn = hypot(q[1], q[2]);
  return q[0] - (sr->a - sr->r2) * (fabs(q[1]) + fabs(q[2])) - sr->r2 * kn;
}


static double potential(const Problem* pb, const double q[3], double gy[3], double Hy[3][3]) {
  SectionSums sh, sf;
  sectionIntegrate(&pb->rule, pb->C10, pb->C20, pb->rule.r1, q, INT_DERIVATIVES, &sh);
  if (pb->len_full > 0) {
    sectionIntegrate(&pb->rule, pb->C10, pb->C20, 0.0, q, INT_DERIVATIVES, &sf);
  } else {
    memset(&sf, 0, sizeof sf);
  }
  double phi = pb->len_holed * sh.e + pb->len_full * sf.e;
  for (int i = 0; i < 3; i++) {
    phi -= pb->F[i] * q[i];
  }
  /* gradient/Hessian in q, then projected on the unknowns: g_y = B^T g_q, H_y = B^T H_q B */
  double gq[3], Hq[3][3];
  for (int i = 0; i < 3; i++) {
    gq[i] = pb->len_holed * sh.g[i] + pb->len_full * sf.g[i] - pb->F[i];
    for (int j = 0; j < 3; j++) {
      Hq[i][j] = pb->len_holed * sh.h[i][j] + pb->len_full * sf.h[i][j];
    }
  }
  for (int a = 0; a < pb->m; a++) {
    gy[a] = 0;
    for (int i = 0; i < 3; i++) {
      gy[a] += pb->B[i][a] * gq[i];
    }
    for (int b = 0; b < pb->m; b++) {
      double s = 0;
      for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
          s += pb->B[i][a] * Hq[i][j] * pb->B[j][b];
        }
      }
      Hy[a][b] = s;
    }
  }
  return phi;
}


/* solve H d = -g for SPD H (m x m, m <= 3) by Cholesky; returns 0, or -1 if not SPD */
static int solveSpd(int m, double H[3][3], const double g[3], double d[3]) {
  double L[3][3] = {{0}};
  for (int i = 0; i < m; i++) {
    for (int j = 0; j <= i; j++) {
      double s = H[i][j];
      for (int k = 0; k < j; k++) {
        s -= L[i][k] * L[j][k];
      }
      if (i == j) {
        if (!(s > 0)) {
          return -1;
        }
        L[i][i] = sqrt(s);
      } else {
        L[i][j] = s / L[j][j];
      }
    }
  }
  double z[3];
  for (int i = 0; i < m; i++) {
    double s = -g[i];
    for (int k = 0; k < i; k++) {
      s -= L[i][k] * z[k];
    }
    z[i] = s / L[i][i];
  }
  for (int i = m - 1; i >= 0; i--) {
    double s = z[i];
    for (int k = i + 1; k < m; k++) {
      s -= L[k][i] * d[k];
    }
    d[i] = s / L[i][i];
  }
  return 0;
}


static csStatus minimise(const Problem* pb, const csrAnalyticOptions* opt, int seg, double q[3],
                         int* iterations, csError* err) {
  memcpy(q, pb->q0, 3 * sizeof(double));
  /* energy scale for the round-off allowance of the sufficient-decrease test (N mm) */
  double escale = (pb->len_holed + pb->len_full) * pb->C10 * pb->rule.a * pb->rule.a;
  /* one pass gives Φ, gradient and Hessian; a trial point's pass is reused when accepted */
  double gy[3], Hy[3][3];
  double phi = potential(pb, q, gy, Hy);
  double step = INFINITY;
  for (int it = 1; it <= opt->max_iter; it++) {
    double d[3] = {0, 0, 0};
    if (!isfinite(phi) || solveSpd(pb->m, Hy, gy, d) != 0) {
      return cs_errorSet(err, CS_ERR_SOLVER,
                         "analytic model II%d: singular or non-finite Newton system at "
                         "iteration %d",
                         seg + 1, it);
    }
    /* the step in q and its size |dλ0| + a |dκ| */
    double dq[3] = {0, 0, 0}, slope = 0;
    for (int a = 0; a < pb->m; a++) {
      slope += gy[a] * d[a];
      for (int i = 0; i < 3; i++) {
        dq[i] += pb->B[i][a] * d[a];
      }
    }
    step = fabs(dq[0]) + pb->rule.a * hypot(dq[1], dq[2]);
    if (step <= opt->tol_step) {
      /* quadratic convergence: q + dq is within ~step² of the minimiser */
      for (int i = 0; i < 3; i++) {
        q[i] += dq[i];
      }
      *iterations = it;
      return CS_OK;
    }
    /* backtracking: stay where λ > 0 everywhere, then require sufficient decrease */
    double t = 1.0, qt[3], gt[3], Ht[3][3], phit = NAN;
    int accepted = 0;
    for (int h = 0; h <= kMaxHalvings; h++, t *= 0.5) {
      for (int i = 0; i < 3; i++) {
        qt[i] = q[i] + t * dq[i];
      }
      if (!(minStretch(&pb->rule, qt) > 0)) {
        continue;
      }
      phit = potential(pb, qt, gt, Ht);
      if (phit <= phi + kArmijo * t * slope + kEnergyNoise * (fabs(phi) + escale)) {
        accepted = 1;
        break;
      }
    }
    if (!accepted) {
      return cs_errorSet(err, CS_ERR_SOLVER,
                         "analytic model II%d: line search failed at iteration %d", seg + 1, it);
    }
    memcpy(q, qt, sizeof qt);
    memcpy(gy, gt, sizeof gt);
    memcpy(Hy, Ht, sizeof Ht);
    phi = phit;
  }
  return cs_errorSet(err, CS_ERR_SOLVER,
                     "analytic model II%d: Newton did not converge in %d iterations (last step "
                     "%g)",
                     seg + 1, opt->max_iter, step);
}


static csStatus setupProblem(const csrActuator* act, int seg, const double p[4],
                             const csrAnalyticOptions* opt, const csrSegmentStrain* out,
                             csrAnalyticOptions* o, Problem* pb, csError* err) {
  *o = opt ? *opt : csr_analyticDefaultOptions();
  if (!act || !p || !out || seg < 0 || seg >= CSR_NSEG) {
    return cs_errorSet(err, CS_ERR_ARG, "analytic model: bad arguments (segment %d)", seg);
  }
  if (!(o->tol_step > 0) || o->max_iter < 1) {
    return cs_errorSet(err, CS_ERR_ARG, "analytic model: need tol_step > 0 and max_iter >= 1");
  }
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    if (!(isfinite(p[j]) && p[j] >= 0)) {
      return cs_errorSet(err, CS_ERR_RANGE,
                         "analytic model II%d: pressure of chamber %d is %g MPa (need a finite "
                         "value >= 0)",
                         seg + 1, j + 1, p[j]);
    }
  }
  memset(pb, 0, sizeof *pb);
  csStatus st = sectionRuleInit(act, o, &pb->rule, err);
  if (st != CS_OK) {
    return st;
  }
  pb->C10 = act->C10;
  pb->C20 = act->C20;
  double Lc = act->S[seg] - 2.0 * act->c;
  pb->len_holed = Lc;
  /* chamber end forces p_j A acting at c_j, times Lc (D4): Σ p_j dV_j/dq */
  static const double cx[4] = {1, 1, -1, -1}, cy[4] = {1, -1, -1, 1};
  double A = CS_PI * act->r1 * act->r1;
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    pb->F[0] += p[j] * A * Lc;
    pb->F[1] += p[j] * A * Lc * cx[j] * act->b;
    pb->F[2] += p[j] * A * Lc * cy[j] * act->b;
  }
  return CS_OK;
}


static double bendDirection(const double kappa[2], double theta, double tol) {
  if (!(theta > tol)) {
    return 0.0;
  }
  return atan2(-kappa[1], -kappa[0]);
}


csStatus csr_analyticSectionCompute(const csrActuator* act, const csrAnalyticOptions* opt,
                                    csrSectionProps* out, csError* err) {
  csrAnalyticOptions o = opt ? *opt : csr_analyticDefaultOptions();
  if (!act || !out) {
    return cs_errorSet(err, CS_ERR_ARG, "analytic section: NULL argument");
  }
  SectionRule sr;
  csStatus st = sectionRuleInit(act, &o, &sr, err);
  if (st != CS_OK) {
    return st;
  }
  const double q[3] = {1, 0, 0};
  SectionSums sh, sf;
  sectionIntegrate(&sr, 0, 0, sr.r1, q, INT_GEOMETRY, &sh);
  sectionIntegrate(&sr, 0, 0, 0.0, q, INT_GEOMETRY, &sf);
  out->area_holed = sh.area;
  out->I_holed = sh.m11;
  out->area_full = sf.area;
  out->I_full = sf.m11;
  return CS_OK;
}


csStatus csr_analyticSegmentWith(const csrActuator* act, int seg, const double p[4],
                                 const csrAnalyticOptions* opt, csrSegmentStrain* out,
                                 csError* err) {
  csrAnalyticOptions o;
  Problem pb;
  csStatus st = setupProblem(act, seg, p, opt, out, &o, &pb, err);
  if (st != CS_OK) {
    return st;
  }
  /* unknowns q = (λ0, κ1, κ2) of the chambered part; start from the linear solution (D7),
   * or from the straight state if that is infeasible (any feasible start converges) */
  pb.m = 3;
  for (int i = 0; i < 3; i++) {
    pb.B[i][i] = 1.0;
  }
  SectionSums geo;
  const double q1[3] = {1, 0, 0};
  sectionIntegrate(&pb.rule, 0, 0, pb.rule.r1, q1, INT_GEOMETRY, &geo);
  double Ek = 8.0 * act->C10 * pb.len_holed; /* E' Lc (N/mm) */
  pb.q0[0] = 1.0 + pb.F[0] / (Ek * geo.area);
  pb.q0[1] = pb.F[1] / (Ek * geo.m11);
  pb.q0[2] = pb.F[2] / (Ek * geo.m22);
  if (!(minStretch(&pb.rule, pb.q0) > 0)) {
    memcpy(pb.q0, q1, sizeof q1);
  }
  double q[3];
  int iters = 0;
  st = minimise(&pb, &o, seg, q, &iters, err);
  if (st != CS_OK) {
    return st;
  }
  /* spread the chambered part's angle over the whole segment (D6) */
  double S = act->S[seg], Lc = pb.len_holed;
  csrSegmentStrain r;
  r.lambda_c = q[0];
  r.kappa_c[0] = q[1];
  r.kappa_c[1] = q[2];
  r.theta = hypot(q[1], q[2]) * Lc;
  r.lambda0 = (q[0] * Lc + 2.0 * act->c) / S;
  r.kappa[0] = q[1] * Lc / S;
  r.kappa[1] = q[2] * Lc / S;
  r.phi = bendDirection(r.kappa, r.theta, o.tol_step);
  r.iterations = iters;
  *out = r;
  return CS_OK;
}


csStatus csr_analyticSegment(const csrActuator* act, int seg, const double p[4],
                             csrSegmentStrain* out, csError* err) {
  return csr_analyticSegmentWith(act, seg, p, NULL, out, err);
}


csStatus csr_analyticActuator(const csrActuator* act, const double p[CSR_NSEG * CSR_NCHAMBER],
                              csrSegmentStrain out[CSR_NSEG], csError* err) {
  if (!p || !out) {
    return cs_errorSet(err, CS_ERR_ARG, "analytic model: NULL argument");
  }
  csrSegmentStrain tmp[CSR_NSEG];
  for (int s = 0; s < CSR_NSEG; s++) {
    csStatus st = csr_analyticSegment(act, s, &p[CSR_NCHAMBER * s], &tmp[s], err);
    if (st != CS_OK) {
      return st;
    }
  }
  memcpy(out, tmp, sizeof tmp);
  return CS_OK;
}


csStatus csr_analyticSegmentPaper(const csrActuator* act, int seg, const double p[4],
                                  const csrAnalyticOptions* opt, csrSegmentStrain* out,
                                  csError* err) {
  csrAnalyticOptions o;
  Problem pb;
  csStatus st = setupProblem(act, seg, p, opt, out, &o, &pb, err);
  if (st != CS_OK) {
    return st;
  }
  csrSegmentStrain r;
  memset(&r, 0, sizeof r);
  r.lambda0 = r.lambda_c = 1.0;
  double mn = hypot(pb.F[1], pb.F[2]);
  if (mn > 0) {
    /* one unknown t = θ/S along q = (1,0,0) + t (h, κ̂); κ̂ along the pressure moment, h the
     * distance to the passive extreme fibre (support of the filleted square in -κ̂) */
    double k1 = pb.F[1] / mn, k2 = pb.F[2] / mn;
    double h = (act->a - act->r2) * (fabs(k1) + fabs(k2)) + act->r2;
    pb.m = 1;
    pb.q0[0] = 1.0;
    pb.B[0][0] = h;
    pb.B[1][0] = k1;
    pb.B[2][0] = k2;
    /* uniform curvature over S: the full-section caps bend along (paper's V1, Eq. 3) */
    pb.len_full = 2.0 * act->c;
    double q[3];
    st = minimise(&pb, &o, seg, q, &r.iterations, err);
    if (st != CS_OK) {
      return st;
    }
    r.lambda0 = r.lambda_c = q[0];
    r.kappa[0] = r.kappa_c[0] = q[1];
    r.kappa[1] = r.kappa_c[1] = q[2];
    r.theta = hypot(q[1], q[2]) * act->S[seg];
    r.phi = bendDirection(r.kappa, r.theta, o.tol_step);
  }
  *out = r;
  return CS_OK;
}


void csr_ccArcPose(double s, double lambda0, const double kappa[2], double pos[3], double R[9]) {
  /* rotation vector ω = s u, u = (κ2, -κ1, 0) (header sign convention); angle α = |κ| s */
  double w1 = s * kappa[1], w2 = -s * kappa[0];
  double al = hypot(w1, w2);
  double A, B; /* sin α / α and (1 - cos α) / α², cancellation-free */
  if (al < kSmallAngle) {
    double a2 = al * al;
    A = 1.0 - a2 / 6.0 + a2 * a2 / 120.0;
    B = 0.5 - a2 / 24.0 + a2 * a2 / 720.0;
  } else {
    double sh = sin(0.5 * al) / al;
    A = sin(al) / al;
    B = 2.0 * sh * sh;
  }
  /* position: deformed arc length L = λ0 s; L (1 - cos α)/α along -κ̂, L sin α / α along e3 */
  double L = lambda0 * s;
  pos[0] = -L * s * B * kappa[0];
  pos[1] = -L * s * B * kappa[1];
  pos[2] = L * A;
  /* Rodrigues: R = I + A [ω]x + B [ω]x², ω = (w1, w2, 0) */
  R[0] = 1.0 - B * w2 * w2;
  R[1] = B * w1 * w2;
  R[2] = A * w2;
  R[3] = B * w1 * w2;
  R[4] = 1.0 - B * w1 * w1;
  R[5] = -A * w1;
  R[6] = -A * w2;
  R[7] = A * w1;
  R[8] = 1.0 - B * (w1 * w1 + w2 * w2);
}


csStatus csr_ccForwardKinematics(const csrActuator* act, const csrSegmentStrain strains[CSR_NSEG],
                                 int nsample_per_segment, double* centerline, double tip[3],
                                 double R_tip[9], csError* err) {
  if (!act || !strains || !tip || (centerline && nsample_per_segment < 1)) {
    return cs_errorSet(err, CS_ERR_ARG,
                       "forward kinematics: bad arguments (nsample_per_segment = %d)",
                       nsample_per_segment);
  }
  for (int i = 0; i < CSR_NSEG; i++) {
    const csrSegmentStrain* st = &strains[i];
    if (!(st->lambda0 > 0 && isfinite(st->lambda0) && isfinite(st->kappa[0]) &&
          isfinite(st->kappa[1]))) {
      return cs_errorSet(err, CS_ERR_RANGE,
                         "forward kinematics: segment II%d has stretch %g, curvature (%g, %g)",
                         i + 1, st->lambda0, st->kappa[0], st->kappa[1]);
    }
  }
  /* running frame: position pos, orientation R (columns = section axes e1, e2, e3) */
  double pos[3] = {0, 0, 0}, R[9];
  csu_eye3(R);
  int row = 0;
  for (int i = 0; i < CSR_NSEG; i++) {
    const csrSegmentStrain* st = &strains[i];
    double pl[3], Rl[9], dp[3];
    if (centerline) {
      csu_copy3(&centerline[3 * row++], pos);
      for (int k = 1; k <= nsample_per_segment; k++) {
        csr_ccArcPose(act->S[i] * k / nsample_per_segment, st->lambda0, st->kappa, pl, Rl);
        csu_mulMatVec3(dp, R, pl);
        csu_add3(&centerline[3 * row++], pos, dp);
      }
    }
    /* compose the segment's transform (Eq. 10) */
    csr_ccArcPose(act->S[i], st->lambda0, st->kappa, pl, Rl);
    csu_mulMatVec3(dp, R, pl);
    csu_add3(pos, pos, dp);
    double Rn[9];
    csu_mulMat3(Rn, R, Rl);
    memcpy(R, Rn, sizeof R);
    /* straight, unstretched joint along the current axis */
    if (i < CSR_NSEG - 1) {
      const double e3[3] = {R[2], R[5], R[8]};
      csu_addScl3(pos, pos, e3, act->LS[i]);
    }
  }
  csu_copy3(tip, pos);
  if (R_tip) {
    memcpy(R_tip, R, sizeof R);
  }
  return CS_OK;
}

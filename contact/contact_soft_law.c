/* contact_soft_law.c: the kernels of the soft contact law (contact_soft.h for the model,
 * contact_soft_internal.h for the shared types): normal loads of capsules and sole points,
 * a slot's contact frame, and the friction laws of both history modes.
 *
 * Rationale of what the header does not say:
 * - Every switch is C1 (smoothPos, step01, the plastic factor alpha and step mode's
 *   saturation), so the right-hand side a BDF integrator sees has a continuous derivative: its
 *   Newton iteration converges and its error estimate is not fooled by kinks. The price is a few
 *   transition widths (d_onset, v_plastic, 1 - u_elastic) far below the scales of interest.
 * - A slot's normal is the direction of its summed elastic normal forces and its load point their
 *   centroid, both weighted by the elastic force (not the damped one), so they are defined and
 *   smooth whenever the slot touches, even while Hunt-Crossley's factor is 0.
 * - The bristle z is a world vector; only its part in the current tangent plane acts, and its
 *   normal part relaxes with tau_reset, so z follows a normal that turns (a capsule rolling over
 *   an edge) without a jump.
 * - The foot patch's torsion: a rotation phi of the sole about its normal deflects every sole
 *   point by r phi, so with the translational law's stiffness per unit load (1/delta_t) the
 *   torsional stiffness is J / delta_t, J = sum N_i r_i^2 about the pressure centre; all points
 *   slipping give the Coulomb couple mu sum N_i r_i. The single torsional bristle reproduces both
 *   (its stick range is phi_s = mu delta_t R1 / J); it ignores the interaction of twisting and
 *   sliding at once (Contensou), which the per-point foot keeps. r is regularised as
 *   sqrt(r^2 + rho^2) in R1 so the centre point of the grid does not make R1 kink. */
#include <math.h>
#include <string.h>

#include "contact_soft_internal.h"
#include "core_math.h"

enum { GL_NEWTON = 60 }; /* Newton iterations for a Gauss-Legendre node (converges in ~5) */

/* Hunt-Crossley's factor 1 + c d' is used as is above this value and smoothly taken to 0 below
 * it (smoothPos): the damping never makes the force negative (pull) */
#define HC_CLIP 0.5
/* a Gauss-Legendre node is converged when Newton's step is below this (round-off of cos) */
#define GL_TOL 1e-15

/* Gauss-Lobatto nodes and weights on [-1, 1] for 2..5 points (Abramowitz & Stegun 25.4.32) */
static const double kLobX[4][CSC_SOFT_MAX_SIDE] = {
    {-1, 1},
    {-1, 0, 1},
    {-1, -0.44721359549995794, 0.44721359549995794, 1},
    {-1, -0.65465367070797714, 0, 0.65465367070797714, 1}};
static const double kLobW[4][CSC_SOFT_MAX_SIDE] = {
    {1, 1},
    {1.0 / 3, 4.0 / 3, 1.0 / 3},
    {1.0 / 6, 5.0 / 6, 5.0 / 6, 1.0 / 6},
    {0.1, 49.0 / 90, 32.0 / 45, 49.0 / 90, 0.1}};

/* 0 for x <= 0, x for x >= X, x^2 (2X - x) / X^2 between: C1, monotone, never above x; its
 * slope peaks at 4/3 (x = 2X/3) */
static double smoothPos(double x, double X);
/* 0, 3t^2 - 2t^3, 1 for t <= 0, in [0, 1], >= 1 (C1) */
static double step01(double t);
/* plastic factor of the integrated law at friction ratio u: 0 below ue, ((u - ue)/(1 - ue))^2
 * up to u = 1, then linear with the same slope (C1; u = 1 attracts a sliding bristle) */
static double plasticAlpha(double u, double ue);
/* saturation of step mode: m(u) = u up to ue, 1 from 2 - ue, a parabola between; *dm = m' */
static double stepSaturation(double u, double ue, double* dm);
/* the Dupont flow of a bristle of ratio u along unit direction uh at slip rate w (outward
 * component wr = uh . w): returns the factor alpha <wr>+ to subtract along uh */
static double plasticFlow(const cscSoftParams* p, double u, double wr, double w_smooth);


static double smoothPos(double x, double X) {
  if (x <= 0) {
    return 0;
  }
  if (x >= X) {
    return x;
  }
  return x * x * (2 * X - x) / (X * X);
}


static double step01(double t) {
  if (t <= 0) {
    return 0;
  }
  if (t >= 1) {
    return 1;
  }
  return t * t * (3 - 2 * t);
}


static double plasticAlpha(double u, double ue) {
  double b = (u - ue) / (1 - ue);
  if (b <= 0) {
    return 0;
  }
  return b <= 1 ? b * b : 2 * b - 1;
}


static double stepSaturation(double u, double ue, double* dm) {
  double e = 1 - ue;
  if (u <= ue) {
    *dm = 1;
    return u;
  }
  if (u >= 1 + e) {
    *dm = 0;
    return 1;
  }
  double t = u - ue;
  *dm = 1 - t / (2 * e);
  return u - t * t / (4 * e);
}


static double plasticFlow(const cscSoftParams* p, double u, double wr, double w_smooth) {
  return plasticAlpha(u, p->u_elastic) * smoothPos(wr, w_smooth);
}


void csc_softGaussLegendre(int n, double* x, double* w) {
  for (int i = 0; i < n; i++) {
    /* Newton on P_n from the classical first guess (Numerical Recipes' gauleg) */
    double t = cos(CS_PI * (i + 0.75) / (n + 0.5)), dp = 1;
    for (int it = 0; it < GL_NEWTON; it++) {
      double p0 = 1, p1 = t;
      for (int k = 2; k <= n; k++) {
        double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n == 1 ? 1 : n * (t * p1 - p0) / (t * t - 1);
      double dt = p1 / dp;
      t -= dt;
      if (fabs(dt) < GL_TOL) {
        break;
      }
    }
    x[i] = -t; /* the guesses run from +1 down: store ascending */
    w[i] = 2 / ((1 - t * t) * dp * dp);
  }
}


void csc_softAxisPoint(const cscShapeState* st, double s, double x[3], double v[3]) {
  for (int k = 0; k < 3; k++) {
    x[k] = (1 - s) * st->x0[k] + s * st->x1[k];
    v[k] = (1 - s) * st->v0[k] + s * st->v1[k];
  }
}


void csc_softFootVelocity(const cscShapeState* st, const double x[3], double v[3]) {
  double r[3], wr[3];
  csu_sub3(r, x, st->x0);
  csu_cross3(wr, st->w, r);
  csu_add3(v, st->v0, wr);
}


void csc_softAddForce(const cscShape* sh, const cscShapeState* st, double s, const double x[3],
                      const double f[3], cscShapeLoad* load) {
  double base[3], r[3], mr[3];
  if (sh->kind == CSC_SHAPE_CAPSULE) {
    double v[3];
    csc_softAxisPoint(st, s, base, v);
    csu_addScl3(load->f0, load->f0, f, 1 - s);
    csu_addScl3(load->f1, load->f1, f, s);
  } else {
    csu_copy3(base, st->x0);
    csu_add3(load->f0, load->f0, f);
  }
  csu_sub3(r, x, base);
  csu_cross3(mr, r, f);
  csu_add3(load->m, load->m, mr);
}


/* add the line load el (N) of the axis point x at parameter s (moving at v) against a surface
 * with normal n and friction mu to the slot acc and the load (split by the lever rule: through
 * the axis, no couple) */
static void axisAccumulate(const cscSoftParams* p, double el, const double n[3], double mu,
                           const double x[3], const double v[3], double s, cscSoftAcc* acc,
                           cscShapeLoad* load) {
  double F = el * smoothPos(1 - p->c_hc * csu_dot3(n, v), HC_CLIP);
  double f[3];
  csu_scale3(f, n, F);
  csu_addScl3(load->f0, load->f0, f, 1 - s);
  csu_addScl3(load->f1, load->f1, f, s);
  csu_add3(acc->Fn, acc->Fn, f);
  csu_addScl3(acc->Fel_n, acc->Fel_n, n, el);
  acc->W += el;
  acc->muW += el * mu;
  csu_addScl3(acc->xw, acc->xw, x, el);
  acc->sw += el * s;
}


/* signed distance (mm) of the capsule's axis point at s to the heightfield, +INFINITY beyond
 * reach */
static double axisHfDistance(const cstHeightfield* hf, const cscShapeState* st, double s,
                             double reach) {
  double x[3], v[3];
  csc_softAxisPoint(st, s, x, v);
  return cst_hfSignedDistance(hf, x, reach, NULL, NULL);
}


/* The line load of a capsule (axis length L, radius r, line modulus kline; bounds lo, hi)
 * against the heightfield: Gauss-Legendre over the stretch of the axis within r of the
 * surface, each point's depth exact (cst_hfSignedDistance). The stretch is found by sampling
 * the axis at CSC_HF_SAMPLES + 1 points and bisecting its two ends to 2^-40 of the axis: exact
 * to round-off where the axis meets the surface once (a plane, a gentle heightfield), but a
 * contact shorter than 1/CSC_HF_SAMPLES of the axis between two samples is missed, and two
 * separate contacts are integrated as one stretch (the gap between them adds nothing but
 * costs quadrature points). */
static void capsuleHeightfield(const cscSoftModel* m, const cscShapeState* st, double r,
                               double L, double kline, const double lo[3], const double hi[3],
                               cscSoftAcc* acc, cscShapeLoad* load) {
  const cscSoftParams* p = &m->p;
  const cstHeightfield* hf = &m->terrain.hf;
  if (lo[1] > hf->hmax + p->d_onset || hi[0] < hf->x0 || hi[2] < hf->z0 ||
      lo[0] > hf->x0 + hf->dx * (hf->nx - 1) || lo[2] > hf->z0 + hf->dz * (hf->nz - 1)) {
    return;
  }
  double reach = r + p->d_onset, sd[CSC_HF_SAMPLES + 1];
  int first = -1, last = -1;
  for (int k = 0; k <= CSC_HF_SAMPLES; k++) {
    sd[k] = axisHfDistance(hf, st, (double)k / CSC_HF_SAMPLES, reach);
    if (sd[k] <= 0) {
      acc->deep++; /* the axis under the surface: r deep */
      acc->dmax = fmax(acc->dmax, r);
      return;
    }
    if (sd[k] <= r) {
      if (first < 0) first = k;
      last = k;
    }
    if (isfinite(sd[k])) acc->dmax = fmax(acc->dmax, r - sd[k]);
  }
  if (first < 0) {
    return;
  }
  /* bisect the ends: [a, b] with a outside (or the axis end), b inside */
  double sa = (double)first / CSC_HF_SAMPLES, sb = (double)last / CSC_HF_SAMPLES;
  if (first > 0) {
    double a = (double)(first - 1) / CSC_HF_SAMPLES, b = sa;
    for (int it = 0; it < 40; it++) {
      double c = 0.5 * (a + b);
      if (axisHfDistance(hf, st, c, reach) <= r) b = c; else a = c;
    }
    sa = b;
  }
  if (last < CSC_HF_SAMPLES) {
    double a = sb, b = (double)(last + 1) / CSC_HF_SAMPLES;
    for (int it = 0; it < 40; it++) {
      double c = 0.5 * (a + b);
      if (axisHfDistance(hf, st, c, reach) <= r) a = c; else b = c;
    }
    sb = a;
  }
  if (!(sb > sa)) {
    return;
  }
  double mid = 0.5 * (sa + sb), half = 0.5 * (sb - sa);
  double mu = hf->own_mu ? hf->mu : p->mu;
  for (int i = 0; i < p->nquad; i++) {
    double s = mid + half * m->gl_x[i], x[3], v[3], cp[3], n[3];
    csc_softAxisPoint(st, s, x, v);
    double depth = r - cst_hfSignedDistance(hf, x, reach, cp, n);
    if (!(depth > 0)) {
      continue;
    }
    double g = smoothPos(depth, p->d_onset);
    axisAccumulate(p, kline * g * sqrt(g) * L * half * m->gl_w[i], n, mu, x, v, s, acc, load);
  }
}


void csc_softCapsuleNormal(const cscSoftModel* m, const cscShape* sh, const cscShapeState* st,
                           cscSoftAcc* acc, cscShapeLoad* load) {
  const cscSoftParams* p = &m->p;
  double r = sh->radius, d[3], lo[3], hi[3];
  csu_sub3(d, st->x1, st->x0);
  double L = csu_norm3(d);
  for (int k = 0; k < 3; k++) {
    lo[k] = fmin(st->x0[k], st->x1[k]) - r;
    hi[k] = fmax(st->x0[k], st->x1[k]) + r;
  }
  int idx[CST_MAX_BOXES];
  int nb = cst_terrainBoxesNear(&m->terrain, lo, hi, p->d_onset, idx, CST_MAX_BOXES);
  /* foundation line load per mm of axis at depth d: k (4/3) sqrt(2 r) g(d)^(3/2) */
  double kline = p->k_area * (4.0 / 3.0) * sqrt(2 * r);
  for (int ib = 0; ib < nb; ib++) {
    const cstBox* b = &m->terrain.box[idx[ib]];
    cscSegBox q;
    csc_segBoxInit(&q, st->x0, st->x1, b);
    if (q.q_min <= 0) {
      acc->deep++; /* the axis touches the box: r deep, not a contact this law describes */
      acc->dmax = fmax(acc->dmax, r);
      continue;
    }
    acc->dmax = fmax(acc->dmax, r - sqrt(q.q_min));
    double sa, sb;
    if (L == 0 || !csc_segBoxInterval(&q, r * r, &sa, &sb) || sb <= sa) {
      continue;
    }
    /* Gauss-Legendre over the stretch [sa, sb] where the axis is within r of the box */
    double mid = 0.5 * (sa + sb), half = 0.5 * (sb - sa);
    for (int i = 0; i < p->nquad; i++) {
      double s = mid + half * m->gl_x[i], x[3], v[3], cp[3], n[3];
      csc_softAxisPoint(st, s, x, v);
      double depth = r - cst_boxSignedDistance(b, x, cp, n);
      if (depth <= 0) {
        continue;
      }
      double g = smoothPos(depth, p->d_onset);
      axisAccumulate(p, kline * g * sqrt(g) * L * half * m->gl_w[i], n,
                     cst_terrainBoxMu(&m->terrain, idx[ib], p->mu), x, v, s, acc, load);
    }
  }
  if (m->terrain.has_hf && L > 0) {
    capsuleHeightfield(m, st, r, L, kline, lo, hi, acc, load);
  }
}


void csc_softSolePoint(const cscShape* sh, const cscShapeState* st, int i, int j, double c[3],
                       double* A) {
  const double* X = kLobX[sh->nside - CSC_SOFT_MIN_SIDE];
  const double* W = kLobW[sh->nside - CSC_SOFT_MIN_SIDE];
  double a = sh->half_side, rho = sh->radius;
  /* on the Lobatto nodes of [-a, a]: the sole's force and moments of a linear pressure are
   * exact (degree 2 nside - 3 >= 1); the rim spheres reach rho beyond the sides, which the
   * leg's last capsule (radius a) covers anyway */
  double xi = a * X[i], eta = a * X[j];
  /* columns of R: e1 = (R0, R3, R6), e2 = (R1, R4, R7), e3 = (R2, R5, R8); the sphere sits rho
   * inside the sole (e3 points out of it) */
  for (int k = 0; k < 3; k++) {
    c[k] = st->x0[k] + xi * st->R[3 * k] + eta * st->R[3 * k + 1] - rho * st->R[3 * k + 2];
  }
  /* the sphere's pressure element: its Lobatto weight of the whole 2a x 2a sole */
  *A = a * a * W[i] * W[j];
}


/* elastic force (N) of one sole sphere (centre c, element A) on box b, its normal n and
 * signed distance *sd of the centre */
static double solePointElastic(const cscSoftParams* p, double rho, double A, const double c[3],
                               const cstBox* b, double n[3], double* sd) {
  double cp[3];
  *sd = cst_boxSignedDistance(b, c, cp, n);
  double depth = rho - *sd;
  return depth > 0 ? p->k_area * A * smoothPos(depth, p->d_onset) : 0;
}


/* add one sole sphere's normal force (elastic el against a surface with normal n, friction mu,
 * centre c moving at v) to acc and load */
static void soleAccumulate(const cscSoftParams* p, double el, const double n[3], double mu,
                           const double c[3], const double v[3], const cscShapeState* st,
                           cscSoftAcc* acc, cscShapeLoad* load) {
  double F = el * smoothPos(1 - p->c_hc * csu_dot3(n, v), HC_CLIP);
  double f[3], r[3], mr[3];
  csu_scale3(f, n, F);
  csu_add3(load->f0, load->f0, f);
  csu_sub3(r, c, st->x0); /* the force passes through the sphere's centre */
  csu_cross3(mr, r, f);
  csu_add3(load->m, load->m, mr);
  csu_add3(acc->Fn, acc->Fn, f);
  csu_addScl3(acc->Fel_n, acc->Fel_n, n, el);
  acc->W += el;
  acc->muW += el * mu;
  csu_addScl3(acc->xw, acc->xw, c, el);
}


int csc_softSolePointNormal(const cscSoftModel* m, double rho, double A, const double c[3],
                            const cscShapeState* st, cscSoftAcc* acc, cscShapeLoad* load,
                            double* elout) {
  const cscSoftParams* p = &m->p;
  double lo[3], hi[3], v[3];
  for (int k = 0; k < 3; k++) {
    lo[k] = c[k] - rho;
    hi[k] = c[k] + rho;
  }
  csc_softFootVelocity(st, c, v);
  int idx[CST_MAX_BOXES];
  int nb = cst_terrainBoxesNear(&m->terrain, lo, hi, p->d_onset, idx, CST_MAX_BOXES);
  nb = nb < CST_MAX_BOXES ? nb : CST_MAX_BOXES;
  for (int ib = 0; ib < nb; ib++) {
    double n[3], sd;
    double el = solePointElastic(p, rho, A, c, &m->terrain.box[idx[ib]], n, &sd);
    if (elout) {
      elout[ib] = el;
    }
    if (sd <= 0) {
      acc->deep++; /* the sphere's centre is in the box: rho deep */
    }
    acc->dmax = fmax(acc->dmax, rho - sd);
    if (el > 0) {
      soleAccumulate(p, el, n, cst_terrainBoxMu(&m->terrain, idx[ib], p->mu), c, v, st, acc,
                     load);
    }
  }
  if (m->terrain.has_hf) {
    /* the heightfield, exact: the sphere's centre against the nearest triangle in reach */
    const cstHeightfield* hf = &m->terrain.hf;
    double n[3], cp[3];
    double sd = cst_hfSignedDistance(hf, c, rho + p->d_onset, cp, n);
    if (isfinite(sd)) {
      double depth = rho - sd;
      double el = depth > 0 ? p->k_area * A * smoothPos(depth, p->d_onset) : 0;
      if (elout) {
        elout[nb] = el;
      }
      nb++;
      if (sd <= 0) {
        acc->deep++;
      }
      acc->dmax = fmax(acc->dmax, depth);
      if (el > 0) {
        soleAccumulate(p, el, n, hf->own_mu ? hf->mu : p->mu, c, v, st, acc, load);
      }
    }
  }
  return nb;
}


void csc_softFootTorsionMoments(const cscSoleLoads* sl, double rho, const double xc[3],
                                const double n[3], double* Jel, double* R1el) {
  *Jel = 0;
  *R1el = 0;
  for (int k = 0; k < sl->npt; k++) {
    double r[3];
    csu_sub3(r, sl->c[k], xc);
    csu_addScl3(r, r, n, -csu_dot3(r, n));
    double r2 = csu_dot3(r, r);
    for (int ib = 0; ib < sl->nel[k]; ib++) {
      double el = sl->el[k][ib];
      *Jel += el * r2;
      *R1el += el * sqrt(r2 + rho * rho);
    }
  }
}


const cscSoftParams* csc_softSlotParams(const cscSoftModel* m, const cscSoftAcc* acc,
                                        cscSoftParams* buf) {
  if (!m->terrain.has_mu || !(acc->W > 0)) {
    return &m->p; /* one friction everywhere: the same bits as before surfaces had their own */
  }
  *buf = m->p;
  buf->mu = acc->muW / acc->W;
  return buf;
}


int csc_softSlotFinish(const cscSoftAcc* acc, cscSoftGeom* g) {
  memset(g, 0, sizeof *g);
  if (!(acc->W > 0)) {
    return 0;
  }
  csu_copy3(g->n, acc->Fel_n);
  if (csu_normalize3(g->n) == 0) {
    /* opposite faces pressing equally (a slot squeezed in a gap): no net normal */
    return 0;
  }
  g->N = fmax(0.0, csu_dot3(acc->Fn, g->n));
  csu_scale3(g->xc, acc->xw, 1.0 / acc->W);
  g->sc = acc->sw / acc->W;
  return 1;
}


void csc_softFrictionIntegrated(const cscSoftParams* p, const cscSoftAcc* acc,
                                const cscSoftGeom* g, int touching, const double vc[3],
                                const double z[3], double zd[3], cscSoftFriction* f) {
  /* out of contact (or in the first d_onset of the gap) z relaxes towards 0 */
  double leak = acc->dmax < 0 ? step01(-acc->dmax / p->d_onset) / p->tau_reset : 0;
  csu_scale3(zd, z, -leak);
  csu_set3(f->ft, 0, 0, 0);
  f->ratio = 0;
  f->sliding = 0;
  if (!touching) {
    return;
  }
  if (p->mu == 0) {
    csu_addScl3(zd, zd, z, -1.0 / p->tau_reset); /* frictionless: nothing to remember */
    return;
  }
  const double* n = g->n;
  double zn = csu_dot3(z, n), zt[3], wt[3];
  csu_addScl3(zt, z, n, -zn);
  csu_addScl3(wt, vc, n, -csu_dot3(vc, n));
  /* the bristle's normal part (left by a turning normal) relaxes: it exerts no force */
  csu_addScl3(zd, zd, n, -zn / p->tau_reset);
  /* Dupont et al. (2002) in vector form: z' = w - alpha(u) <u_hat . w>+ u_hat */
  double zs = p->mu * p->delta_t, nz = csu_norm3(zt), u = nz / zs, flow[3];
  csu_copy3(flow, wt);
  if (nz > 0) {
    double uh[3];
    csu_scale3(uh, zt, 1.0 / nz);
    double wr = csu_dot3(uh, wt);
    csu_addScl3(flow, flow, uh, -plasticFlow(p, u, wr, p->v_plastic));
    f->sliding = u > p->u_elastic && wr > p->v_plastic;
  }
  /* the bristle starts to follow the slip over the onset of the contact */
  csu_addScl3(zd, zd, flow, step01(acc->dmax / p->d_onset));
  /* F_t = -(N / delta_t) (z_t + tau_t z_t'), z_t' the tangential part of z' */
  double et[3];
  csu_addScl3(et, zd, n, -csu_dot3(zd, n));
  for (int k = 0; k < 3; k++) f->ft[k] = -(g->N / p->delta_t) * (zt[k] + p->tau_t * et[k]);
  f->ratio = u;
}


void csc_softFrictionTorsion(const cscSoftParams* p, const cscSoftAcc* acc,
                             const cscSoftGeom* g, int touching, double wn, double Jel,
                             double R1el, double phi, double* phid, cscSoftFriction* f) {
  double leak = acc->dmax < 0 ? step01(-acc->dmax / p->d_onset) / p->tau_reset : 0;
  *phid = -leak * phi;
  f->T = 0;
  /* a single touching point (J = 0) or no friction: no couple, nothing to remember */
  if (!touching || p->mu == 0 || !(Jel > 0) || !(acc->W > 0)) {
    if (touching) {
      *phid -= phi / p->tau_reset;
    }
    return;
  }
  /* stick range phi_s = mu delta_t R1 / J; the rotational smoothing rate v_plastic / r_gyr */
  double phis = p->mu * p->delta_t * R1el / Jel, u = fabs(phi) / phis;
  double sgn = phi >= 0 ? 1.0 : -1.0, w_smooth = p->v_plastic / sqrt(Jel / acc->W);
  double flow = wn - sgn * plasticFlow(p, u, sgn * wn, w_smooth);
  *phid += step01(acc->dmax / p->d_onset) * flow;
  /* T = -(J / delta_t) (phi + tau_t phi'), J scaled from elastic to the damped load N */
  double J = Jel * g->N / acc->W;
  f->T = -(J / p->delta_t) * (phi + p->tau_t * *phid);
}


void csc_softFrictionStep(const cscSoftParams* p, const cscSoftGeom* g, const double xm[3],
                          const double vm[3], const double a[3], cscSoftFriction* f) {
  const double* n = g->n;
  double zr[3], wt[3], gd[3];
  csu_sub3(zr, xm, a);
  csu_addScl3(zr, zr, n, -csu_dot3(zr, n));
  csu_addScl3(wt, vm, n, -csu_dot3(vm, n));
  /* the damped deflection gd = z_r + tau_t w: the stuck bristle's force is -(N / delta_t) gd;
   * its return map onto |F_t| <= mu N is the radial one with the C1 saturation m
   * (contact_soft_internal.h: F_t = -mu N m(s) gd / |gd|, s = |gd| / (mu delta_t)) */
  csu_addScl3(gd, zr, wt, p->tau_t);
  const double zs = p->mu * p->delta_t, ng = csu_norm3(gd), s = ng / zs;
  const double k = g->N / p->delta_t;
  if (s <= p->u_elastic) {
    /* elastic stick: m(s) = s, the Kelvin-Voigt bristle itself */
    for (int j = 0; j < 3; j++) f->ft[j] = -k * gd[j];
  } else {
    double dm, mval = stepSaturation(s, p->u_elastic, &dm);
    (void)dm;
    csu_scale3(f->ft, gd, -k * zs * mval / ng);
  }
  f->T = 0;
  f->ratio = s;
  f->sliding = s > 1;
}

/* contact_soft_jac.c: the derivatives of a shape's load under the soft law in step mode
 * (contact_soft.h csc_softShapeJacobian), by forward differentiation of the law's own steps.
 *
 * Every quantity of the foot's law (contact_soft_law.c: sole point, signed distance and normal
 * of the box, elastic force, Hunt-Crossley factor, slot's normal and load, the anchor's
 * step-mode friction) is carried as a value and its 12 partial derivatives with respect to
 * the shape's coordinates y = (x0, φ, v0, ω) (a dual number with 12 directions). The law is C1
 * (contact_soft_law.c), so these are its exact derivatives wherever it is evaluated (at its C1
 * seams, the one-sided derivatives agree). The values follow the law's own operations and
 * order where it matters for the branches (which box, touching or not, which piece of a
 * smoothing): the branch taken is the law's.
 *
 * Covered: a foot (sole points as slots) in step mode against terrain boxes (aligned or
 * oriented) with one friction everywhere. Not covered (returns CSC_SOFT_NO_JACOBIAN, the
 * caller differences the law): capsules (their Gauss-Legendre stretch ends move with the pose
 * and would need the segment-box interval's derivative), a heightfield, friction per surface,
 * integrated history. */
#include <math.h>
#include <string.h>

#include "contact_soft_internal.h"
#include "core_math.h"

/* Hunt-Crossley's clip of contact_soft_law.c (HC_CLIP): the same smoothing */
#define JAC_HC_CLIP 0.5

enum { ND = 12 }; /* directions: x0 (0..2), φ (3..5), v0 (6..8), ω (9..11) */
/* a pose-only quantity (sole point, distance, normal, elastic force, the slot's normal, the
 * anchor's deflection) has no derivative along v0, ω: its directions 0..NP-1 alone */
enum { NP = 6 };

typedef struct {
  double v;
  double d[ND];
} dual;

typedef struct {
  dual c[3];
} dvec;



static inline dual jConst(double v) {
  dual r;
  r.v = v;
  memset(r.d, 0, sizeof r.d);
  return r;
}


static inline dual jAdd(dual a, dual b) {
  a.v += b.v;
  for (int k = 0; k < ND; k++) a.d[k] += b.d[k];
  return a;
}


static inline dual jSub(dual a, dual b) {
  a.v -= b.v;
  for (int k = 0; k < ND; k++) a.d[k] -= b.d[k];
  return a;
}


static inline dual jMul(dual a, dual b) {
  dual r;
  r.v = a.v * b.v;
  for (int k = 0; k < ND; k++) r.d[k] = a.d[k] * b.v + a.v * b.d[k];
  return r;
}


static inline dual jScl(dual a, double s) {
  a.v *= s;
  for (int k = 0; k < ND; k++) a.d[k] *= s;
  return a;
}


/* f(a) from its value f and slope df at a.v */
static inline dual jChain(dual a, double f, double df) {
  dual r;
  r.v = f;
  for (int k = 0; k < ND; k++) r.d[k] = df * a.d[k];
  return r;
}


static inline dual jDiv(dual a, dual b) {
  dual r;
  r.v = a.v / b.v;
  const double ib = 1.0 / b.v;
  for (int k = 0; k < ND; k++) r.d[k] = (a.d[k] - r.v * b.d[k]) * ib;
  return r;
}


static inline dual jSqrt(dual a) {
  double s = sqrt(a.v);
  return jChain(a, s, s > 0 ? 0.5 / s : 0);
}


/* The vector operations below write their result through pointers, element by element, with
 * the very expressions (and order) of the scalar operations above (jMul's a' b + a b', the
 * sums' grouping): the same bits as composing jMul/jAdd, without the 104-byte temporaries
 * that composing them by value copied. Those taking n form directions 0..n-1 and set the
 * rest to 0: n = NP where every operand is a pose-only quantity (their directions NP.. are 0,
 * so are the result's), ND otherwise (sole20 in docs/notes/strain_leg.md). */

/* *r = a·b, grouped as (a0 b0 + a1 b1) + a2 b2 */
static inline void vDot(dual* r, const dvec* a, const dvec* b, int n) {
  const dual *a0 = &a->c[0], *a1 = &a->c[1], *a2 = &a->c[2];
  const dual *b0 = &b->c[0], *b1 = &b->c[1], *b2 = &b->c[2];
  double d[ND] = {0};
  for (int k = 0; k < n; k++) {
    d[k] = ((a0->d[k] * b0->v + a0->v * b0->d[k]) + (a1->d[k] * b1->v + a1->v * b1->d[k])) +
           (a2->d[k] * b2->v + a2->v * b2->d[k]);
  }
  r->v = (a0->v * b0->v + a1->v * b1->v) + a2->v * b2->v;
  memcpy(r->d, d, sizeof d);
}


static inline void vAdd(dvec* r, const dvec* a, const dvec* b) {
  for (int j = 0; j < 3; j++) {
    r->c[j].v = a->c[j].v + b->c[j].v;
    for (int k = 0; k < ND; k++) r->c[j].d[k] = a->c[j].d[k] + b->c[j].d[k];
  }
}


static inline void vSub(dvec* r, const dvec* a, const dvec* b, int n) {
  for (int j = 0; j < 3; j++) {
    r->c[j].v = a->c[j].v - b->c[j].v;
    for (int k = 0; k < n; k++) r->c[j].d[k] = a->c[j].d[k] - b->c[j].d[k];
    for (int k = n; k < ND; k++) r->c[j].d[k] = 0;
  }
}


/* r = a + b s (s a dual scalar; r may be a, not b) */
static inline void vAxpy(dvec* r, const dvec* a, const dvec* b, const dual* s, int n) {
  for (int j = 0; j < 3; j++) {
    const dual* bj = &b->c[j];
    for (int k = 0; k < n; k++) {
      r->c[j].d[k] = a->c[j].d[k] + (bj->d[k] * s->v + bj->v * s->d[k]);
    }
    for (int k = n; k < ND; k++) r->c[j].d[k] = 0;
    r->c[j].v = a->c[j].v + bj->v * s->v;
  }
}


/* r = a s (r may be a) */
static inline void vScale(dvec* r, const dvec* a, const dual* s, int n) {
  for (int j = 0; j < 3; j++) {
    const double av = a->c[j].v;
    for (int k = 0; k < n; k++) r->c[j].d[k] = a->c[j].d[k] * s->v + av * s->d[k];
    for (int k = n; k < ND; k++) r->c[j].d[k] = 0;
    r->c[j].v = av * s->v;
  }
}


/* one component of acc + a × b: r = acc + (p q - u w) (jMul's expressions, jSub's, then
 * jAdd's: the same bits as forming the cross product and adding it) */
static inline void crossAddComp(dual* r, const dual* acc, const dual* p, const dual* q,
                                const dual* u, const dual* w) {
  for (int k = 0; k < ND; k++) {
    r->d[k] = acc->d[k] + ((p->d[k] * q->v + p->v * q->d[k]) - (u->d[k] * w->v + u->v * w->d[k]));
  }
  r->v = acc->v + (p->v * q->v - u->v * w->v);
}


/* r = acc + a × b, in place (r may be acc, neither a nor b) */
static void vCrossAdd(dvec* r, const dvec* acc, const dvec* a, const dvec* b) {
  crossAddComp(&r->c[0], &acc->c[0], &a->c[1], &b->c[2], &a->c[2], &b->c[1]);
  crossAddComp(&r->c[1], &acc->c[1], &a->c[2], &b->c[0], &a->c[0], &b->c[2]);
  crossAddComp(&r->c[2], &acc->c[2], &a->c[0], &b->c[1], &a->c[1], &b->c[0]);
}


static inline void vZero(dvec* r) {
  for (int j = 0; j < 3; j++) r->c[j] = jConst(0);
}


/* contact_soft_law.c smoothPos with its slope */
static dual jSmoothPos(dual x, double X) {
  if (x.v <= 0) {
    return jConst(0);
  }
  if (x.v >= X) {
    return x;
  }
  const double t = x.v;
  return jChain(x, t * t * (2 * X - t) / (X * X), (4 * X * t - 3 * t * t) / (X * X));
}


/* contact_soft_law.c stepSaturation: m(u) and m'(u), both as duals (m'' = -1 / (2 e) on the
 * parabola) */
static void jStepSaturation(dual u, double ue, dual* mv, dual* dm) {
  const double e = 1 - ue;
  if (u.v <= ue) {
    *mv = u;
    *dm = jConst(1);
    return;
  }
  if (u.v >= 1 + e) {
    *mv = jConst(1);
    *dm = jConst(0);
    return;
  }
  const double t = u.v - ue;
  *mv = jChain(u, u.v - t * t / (4 * e), 1 - t / (2 * e));
  *dm = jChain(u, 1 - t / (2 * e), -1 / (2 * e));
}


/* a world point p of the rigid foot (offset r = p - x0 from the sole centre) as a dual: ∂p/∂x0
 * = I, ∂p/∂φ = -r^ (R -> exp(φ^) R turns r to r + φ × r) */
static void footPoint(const double p[3], const double x0[3], dvec* out) {
  double r[3];
  csu_sub3(r, p, x0);
  for (int j = 0; j < 3; j++) {
    out->c[j] = jConst(p[j]);
    out->c[j].d[j] = 1;
  }
  /* (φ × r)_j = ε_jkl φ_k r_l */
  out->c[0].d[3 + 1] = r[2];
  out->c[0].d[3 + 2] = -r[1];
  out->c[1].d[3 + 0] = -r[2];
  out->c[1].d[3 + 2] = r[0];
  out->c[2].d[3 + 0] = r[1];
  out->c[2].d[3 + 1] = -r[0];
}


/* velocity of a foot point p (dual, its offset from x0 r = p - x0): v0 + ω × r */
static void footVelocity(const dvec* p, const dvec* x0, const dvec* v0, const dvec* w,
                         dvec* v) {
  dvec r;
  vSub(&r, p, x0, NP);
  vCrossAdd(v, v0, w, &r);
}


/* signed distance of point c (dual) to box b and the box's normal there, as duals: the
 * distance's gradient is the normal; the normal turns only where the closest point is an edge
 * or a corner of the box, ∂n/∂c = (I - n nᵀ) P / dist with P the projector on the box axes
 * along which c is clamped (box frame) */
static dual boxDistance(const cstBox* b, const dvec* c, dvec* n) {
  double x[3] = {c->c[0].v, c->c[1].v, c->c[2].v}, cp[3], nv[3];
  const double sd = cst_boxSignedDistance(b, x, cp, nv);
  dual s = jConst(sd);
  for (int k = 0; k < NP; k++) { /* c is pose-only */
    s.d[k] = nv[0] * c->c[0].d[k] + nv[1] * c->c[1].d[k] + nv[2] * c->c[2].d[k];
  }
  double Jn[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  if (sd > 0) {
    /* the clamped axes of the box frame (contact of an edge or a corner: two or three) */
    double y[3];
    if (b->oriented) {
      cst_boxToLocal(b, x, y);
    } else {
      csu_copy3(y, x);
    }
    int ncl = 0, cl[3];
    for (int k = 0; k < 3; k++) {
      cl[k] = y[k] < b->lo[k] || y[k] > b->hi[k];
      ncl += cl[k];
    }
    if (ncl > 1) {
      /* P = Σ a_k a_kᵀ over the clamped axes a_k (world columns of the box's R), then
       * (I - n nᵀ) P / sd */
      double P[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
      for (int k = 0; k < 3; k++) {
        if (!cl[k]) {
          continue;
        }
        double a[3] = {0, 0, 0};
        if (b->oriented) {
          for (int j = 0; j < 3; j++) a[j] = b->R[3 * j + k];
        } else {
          a[k] = 1;
        }
        for (int i = 0; i < 3; i++) {
          for (int j = 0; j < 3; j++) P[3 * i + j] += a[i] * a[j];
        }
      }
      for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
          double t = P[3 * i + j];
          for (int l = 0; l < 3; l++) t -= nv[i] * nv[l] * P[3 * l + j];
          Jn[3 * i + j] = t / sd;
        }
      }
    }
  }
  for (int i = 0; i < 3; i++) {
    n->c[i] = jConst(nv[i]);
    for (int k = 0; k < NP; k++) {
      n->c[i].d[k] = Jn[3 * i] * c->c[0].d[k] + Jn[3 * i + 1] * c->c[1].d[k] +
                     Jn[3 * i + 2] * c->c[2].d[k];
    }
  }
  return s;
}


/* one sole point k of foot i in step mode (the law: csc_softSolePointNormal,
 * csc_softSlotFinish, slotStep's friction), its load added to f0 and mo (about x0);
 * returns the number of its samples inside a box */
static int solePoint(const cscSoftModel* m, const cscShape* sh, const cscShapeState* st, int k,
                     const double* zk, const dvec* x0, const dvec* v0, const dvec* w, dvec* f0,
                     dvec* mo) {
  const cscSoftParams* p = &m->p;
  const double rho = sh->radius;
  double cv[3], A;
  csc_softSolePoint(sh, st, k / sh->nside, k % sh->nside, cv, &A);
  dvec c, vc, r;
  footPoint(cv, st->x0, &c);
  vSub(&r, &c, x0, NP);
  int have_vc = 0; /* the sphere's velocity, formed where a box presses it */
  double lo[3], hi[3];
  for (int j = 0; j < 3; j++) {
    lo[j] = cv[j] - rho;
    hi[j] = cv[j] + rho;
  }
  int idx[CST_MAX_BOXES];
  int nb = cst_terrainBoxesNear(&m->terrain, lo, hi, p->d_onset, idx, CST_MAX_BOXES);
  nb = nb < CST_MAX_BOXES ? nb : CST_MAX_BOXES;
  /* the slot's sums (cscSoftAcc): Fn, Fel_n, W */
  dvec Fn, Fel;
  vZero(&Fn);
  vZero(&Fel);
  dual W = jConst(0);
  int deep = 0;
  for (int ib = 0; ib < nb; ib++) {
    dvec n;
    dual sd = boxDistance(&m->terrain.box[idx[ib]], &c, &n);
    if (sd.v <= 0) {
      deep++;
    }
    dual depth = jSub(jConst(rho), sd);
    if (!(depth.v > 0)) {
      continue;
    }
    dual el = jScl(jSmoothPos(depth, p->d_onset), p->k_area * A);
    if (!(el.v > 0)) {
      continue;
    }
    if (!have_vc) {
      footVelocity(&c, x0, v0, w, &vc);
      have_vc = 1;
    }
    /* F = el <1 - c_hc n·v>, f = n F through the sphere's centre */
    dual nv;
    vDot(&nv, &n, &vc, ND);
    dual hc = jSmoothPos(jSub(jConst(1), jScl(nv, p->c_hc)), JAC_HC_CLIP);
    dual F = jMul(el, hc);
    dvec f;
    vScale(&f, &n, &F, ND);
    vAdd(f0, f0, &f);
    vCrossAdd(mo, mo, &r, &f);
    vAdd(&Fn, &Fn, &f);
    vAxpy(&Fel, &Fel, &n, &el, NP);
    W = jAdd(W, el);
  }
  /* csc_softSlotFinish: the slot's normal and load */
  if (!(W.v > 0)) {
    return deep;
  }
  dual nn;
  vDot(&nn, &Fel, &Fel, NP);
  nn = jSqrt(nn);
  if (!(nn.v > 0)) {
    return deep;
  }
  dvec gn;
  dual inv = jDiv(jConst(1), nn);
  vScale(&gn, &Fel, &inv, NP);
  dual N;
  vDot(&N, &Fn, &gn, ND);
  if (!(N.v > 0)) {
    N = jConst(0);
  }
  /* slotStep: friction at the sole point above the sphere, anchored (tag >= 0) */
  if (!(zk[3] >= 0) || !(p->mu > 0)) {
    return deep;
  }
  double xmv[3];
  for (int j = 0; j < 3; j++) xmv[j] = cv[j] + rho * st->R[3 * j + 2];
  dvec xm, vm, zr, wt;
  footPoint(xmv, st->x0, &xm);
  footVelocity(&xm, x0, v0, w, &vm);
  /* csc_softFrictionStep: the damped deflection g = z_r + tau_t w, s = |g| / (mu delta_t);
   * ft = -(N / delta_t) g in elastic stick, -(N / delta_t) mu delta_t m(s) g / |g| past it */
  for (int j = 0; j < 3; j++) zr.c[j] = jSub(xm.c[j], jConst(zk[j]));
  dual pr;
  vDot(&pr, &zr, &gn, NP);
  pr = jScl(pr, -1);
  vAxpy(&zr, &zr, &gn, &pr, NP);
  vDot(&pr, &vm, &gn, ND);
  pr = jScl(pr, -1);
  vAxpy(&wt, &vm, &gn, &pr, ND);
  dvec gd;
  const dual tau = jConst(p->tau_t);
  vAxpy(&gd, &zr, &wt, &tau, ND);
  const double zs = p->mu * p->delta_t;
  dual ng;
  vDot(&ng, &gd, &gd, ND);
  ng = jSqrt(ng);
  dual sr = ng; /* s by the law's division (its branch test), the slopes alike */
  sr.v = ng.v / zs;
  for (int k = 0; k < ND; k++) sr.d[k] = ng.d[k] / zs;
  dual fac = jScl(N, -1 / p->delta_t);
  if (sr.v > p->u_elastic) {
    dual mv, dm;
    jStepSaturation(sr, p->u_elastic, &mv, &dm);
    fac = jMul(fac, jDiv(jScl(mv, zs), ng));
  }
  dvec ft, rm;
  vScale(&ft, &gd, &fac, ND);
  vAdd(f0, f0, &ft);
  vSub(&rm, &xm, x0, NP);
  vCrossAdd(mo, mo, &rm, &ft);
  return deep;
}


int csc_softShapeJacobian(const cscSoftModel* m, int i, const cscShapeState* s, const double* z,
                          double L[6], double K[36], double C[36]) {
  if (!m || i < 0 || i >= m->nshape || !s || !L || !K || !C ||
      (!z && m->zoff[i + 1] > m->zoff[i])) {
    return -1;
  }
  const cscShape* sh = &m->shape[i];
  if (sh->kind != CSC_SHAPE_FOOT || m->p.history != CSC_HISTORY_STEP || m->patch[i] ||
      m->terrain.has_hf || m->terrain.has_mu) {
    return CSC_SOFT_NO_JACOBIAN;
  }
  const double* v = (const double*)s;
  for (size_t k = 0; k < sizeof *s / sizeof(double); k++) {
    if (!isfinite(v[k])) {
      return 1;
    }
  }
  const int nz = m->zoff[i + 1] - m->zoff[i];
  for (int k = 0; k < nz; k++) {
    if (!isfinite(z[k])) {
      return 1;
    }
  }
  /* the seeds: x0, v0, ω their own directions (R's turn enters through footPoint) */
  dvec x0, v0, w, f0, mo;
  for (int j = 0; j < 3; j++) {
    x0.c[j] = jConst(s->x0[j]);
    x0.c[j].d[j] = 1;
    v0.c[j] = jConst(s->v0[j]);
    v0.c[j].d[6 + j] = 1;
    w.c[j] = jConst(s->w[j]);
    w.c[j].d[9 + j] = 1;
  }
  vZero(&f0);
  vZero(&mo);
  const int nsl = m->first[i + 1] - m->first[i];
  int deep = 0;
  for (int k = 0; k < nsl; k++) {
    deep += solePoint(m, sh, s, k, z + (size_t)4 * k, &x0, &v0, &w, &f0, &mo);
  }
  for (int r = 0; r < 3; r++) {
    L[r] = f0.c[r].v;
    L[3 + r] = mo.c[r].v;
    for (int c = 0; c < 6; c++) {
      K[6 * r + c] = f0.c[r].d[c];
      K[6 * (3 + r) + c] = mo.c[r].d[c];
      C[6 * r + c] = f0.c[r].d[6 + c];
      C[6 * (3 + r) + c] = mo.c[r].d[6 + c];
    }
  }
  return deep > 0 ? 1 : 0;
}

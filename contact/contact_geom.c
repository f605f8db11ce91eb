/* contact_geom.c: closed-form and libccd penetration queries (see contact_geom.h).
 *
 * The segment-box distance: per axis k the excess e_k(s) of x_k(s) = p0_k + s d_k beyond the
 * box's slab [lo_k, hi_k] is 0 inside the slab and linear outside it, so q(s) = sum e_k(s)^2 is
 * a convex piecewise quadratic whose breakpoints are the slab crossings. On each piece the
 * active axes are fixed (found at the piece's midpoint) and q = A s^2 + B s + C exactly. Its
 * minimum and level sets then come from quadratics, with no iteration, which is what makes the
 * capsule's line load (contact_soft.c) a smooth function of the capsule's pose. */
#include "contact_geom.h"

#include <math.h>
#include <string.h>

#include "core_math.h"

enum { MAX_BRK = 8 }; /* 2 ends + 2 slab planes x 3 axes */

/* MPR tolerance (mm) and iteration cap: see csc_ccdInit in the header */
#define CCD_MPR_TOL_MM 1e-9
#define CCD_MAX_ITER 200

/* smaller-s root of A s^2 + B s + C = 0 (first == 1) or the larger one (first == 0), computed
 * without cancellation (Numerical Recipes' form); requires A > 0 and a real root */
static double quadRoot(double A, double B, double C, int first);

/* separating-axis penetration of segment p0 -> p1 into box b (axis inside the box): depth of
 * the segment (mm), the normal out of the box, and the axis parameter of the deepest point */
static double segmentBoxSat(const double p0[3], const double p1[3], const cstBox* b,
                            double n[3], double* s_deep);


double csc_sphereBoxPenetration(const double c[3], double r, const cstBox* b,
                                cscPenetration* out) {
  double cp[3], n[3];
  double depth = r - cst_boxSignedDistance(b, c, cp, n);
  if (out) {
    out->depth = depth;
    csu_copy3(out->normal, n);
    /* midway between the sphere's deepest point c - r n and the box surface point cp */
    for (int k = 0; k < 3; k++) out->pos[k] = 0.5 * (c[k] - r * n[k] + cp[k]);
  }
  return depth;
}


/* an oriented box's own frame: the segment's ends in it and the box as an axis-aligned one
 * there (distances are invariant under the rigid motion, so q(s) is the same function) */
static cstBox alignedFrame(const cstBox* b, const double p0[3], const double p1[3], double l0[3],
                           double l1[3]) {
  cstBox a;
  memset(&a, 0, sizeof a);
  csu_copy3(a.lo, b->lo);
  csu_copy3(a.hi, b->hi);
  cst_boxToLocal(b, p0, l0);
  cst_boxToLocal(b, p1, l1);
  return a;
}


void csc_segBoxInit(cscSegBox* q, const double p0[3], const double p1[3], const cstBox* b) {
  if (b->oriented) {
    double l0[3], l1[3];
    cstBox a = alignedFrame(b, p0, p1, l0, l1);
    csc_segBoxInit(q, l0, l1, &a);
    return;
  }
  double d[3];
  csu_sub3(d, p1, p0);
  /* breakpoints: the slab crossings strictly inside (0, 1), sorted, duplicates removed */
  double s[MAX_BRK];
  int ns = 0;
  s[ns++] = 0.0;
  for (int k = 0; k < 3; k++) {
    if (d[k] == 0) {
      continue;
    }
    double plane[2] = {b->lo[k], b->hi[k]};
    for (int i = 0; i < 2; i++) {
      double t = (plane[i] - p0[k]) / d[k];
      if (t > 0 && t < 1) {
        s[ns++] = t;
      }
    }
  }
  s[ns++] = 1.0;
  for (int i = 1; i < ns; i++) { /* insertion sort of <= 8 values */
    double v = s[i];
    int j = i - 1;
    while (j >= 0 && s[j] > v) {
      s[j + 1] = s[j];
      j--;
    }
    s[j + 1] = v;
  }
  int nb = 0;
  for (int i = 0; i < ns; i++) {
    if (nb == 0 || s[i] > q->brk[nb - 1]) {
      q->brk[nb++] = s[i];
    }
  }
  q->npiece = nb - 1;
  /* each piece's quadratic from its active axes: e = alpha + beta s */
  for (int j = 0; j < q->npiece; j++) {
    double mid = 0.5 * (q->brk[j] + q->brk[j + 1]);
    double A = 0, B = 0, C = 0;
    for (int k = 0; k < 3; k++) {
      double x = p0[k] + mid * d[k], alpha, beta;
      if (x < b->lo[k]) {
        alpha = b->lo[k] - p0[k];
        beta = -d[k];
      } else if (x > b->hi[k]) {
        alpha = p0[k] - b->hi[k];
        beta = d[k];
      } else {
        continue;
      }
      A += beta * beta;
      B += 2 * alpha * beta;
      C += alpha * alpha;
    }
    q->A[j] = A;
    q->B[j] = B;
    q->C[j] = C;
  }
  /* the minimum: per piece at the vertex of its parabola, clamped to the piece */
  int jmin = 0;
  q->q_min = INFINITY;
  q->s_min = 0;
  for (int j = 0; j < q->npiece; j++) {
    double sj = q->A[j] > 0 ? -q->B[j] / (2 * q->A[j]) : 0.5 * (q->brk[j] + q->brk[j + 1]);
    sj = fmin(fmax(sj, q->brk[j]), q->brk[j + 1]);
    double v = fmax(0.0, (q->A[j] * sj + q->B[j]) * sj + q->C[j]);
    if (v < q->q_min) {
      q->q_min = v;
      q->s_min = sj;
      jmin = j;
    }
  }
  /* a flat minimum (the segment parallel to a face: A = 0 exactly, no active axis moves) spans
   * whole pieces: report the middle of the flat stretch */
  if (q->A[jmin] == 0) {
    int jl = jmin, jr = jmin;
    while (jl > 0 && q->A[jl - 1] == 0) jl--;
    while (jr < q->npiece - 1 && q->A[jr + 1] == 0) jr++;
    q->s_min = 0.5 * (q->brk[jl] + q->brk[jr + 1]);
  }
}


double csc_segBoxEval(const cscSegBox* q, double s) {
  int j = 0;
  while (j < q->npiece - 1 && s > q->brk[j + 1]) j++;
  return fmax(0.0, (q->A[j] * s + q->B[j]) * s + q->C[j]);
}


static double quadRoot(double A, double B, double C, int first) {
  double disc = fmax(0.0, B * B - 4 * A * C);
  double t = -0.5 * (B + copysign(sqrt(disc), B));
  double r1 = t / A, r2 = (t != 0) ? C / t : r1;
  double lo = fmin(r1, r2), hi = fmax(r1, r2);
  return first ? lo : hi;
}


int csc_segBoxInterval(const cscSegBox* q, double level, double* sa, double* sb) {
  if (!(level >= q->q_min)) {
    return 0;
  }
  /* left end: q decreases from s = 0 to s_min, so the crossing lies in the first piece whose
   * right end is inside the level set or reaches s_min (the level set may lie inside one
   * piece); on that piece it is the smaller root of its quadratic */
  *sa = 0.0;
  if (csc_segBoxEval(q, 0.0) > level) {
    for (int j = 0; j < q->npiece; j++) {
      double s1 = q->brk[j + 1];
      if ((q->A[j] * s1 + q->B[j]) * s1 + q->C[j] <= level || s1 >= q->s_min) {
        double r = q->A[j] > 0 ? quadRoot(q->A[j], q->B[j], q->C[j] - level, 1) : q->s_min;
        *sa = fmin(fmax(r, q->brk[j]), fmin(s1, q->s_min));
        break;
      }
    }
  }
  /* right end: the mirror image */
  *sb = 1.0;
  if (csc_segBoxEval(q, 1.0) > level) {
    for (int j = q->npiece - 1; j >= 0; j--) {
      double s0 = q->brk[j];
      if ((q->A[j] * s0 + q->B[j]) * s0 + q->C[j] <= level || s0 <= q->s_min) {
        double r = q->A[j] > 0 ? quadRoot(q->A[j], q->B[j], q->C[j] - level, 0) : q->s_min;
        *sb = fmax(fmin(r, q->brk[j + 1]), fmax(s0, q->s_min));
        break;
      }
    }
  }
  return 1;
}


static double segmentBoxSat(const double p0[3], const double p1[3], const cstBox* b,
                            double n[3], double* s_deep) {
  double d[3], c[3], h[3];
  csu_sub3(d, p1, p0);
  for (int k = 0; k < 3; k++) {
    c[k] = 0.5 * (b->lo[k] + b->hi[k]);
    h[k] = 0.5 * (b->hi[k] - b->lo[k]);
  }
  /* candidate axes: the box's face normals and axis x edge directions (a segment has no faces) */
  double axes[6][3];
  int na = 0;
  for (int k = 0; k < 3; k++) {
    csu_set3(axes[na], k == 0, k == 1, k == 2);
    na++;
  }
  double dn = csu_norm3(d);
  for (int k = 0; k < 3 && dn > 0; k++) {
    double e[3] = {k == 0, k == 1, k == 2}, a[3];
    csu_cross3(a, d, e);
    /* skip directions that are nearly a face normal already or degenerate */
    if (csu_normalize3(a) > 1e-9 * dn) {
      csu_copy3(axes[na++], a);
    }
  }
  double best = INFINITY;
  for (int i = 0; i < na; i++) {
    const double* a = axes[i];
    double s0 = csu_dot3(p0, a), s1 = csu_dot3(p1, a);
    double smin = fmin(s0, s1), smax = fmax(s0, s1);
    double rb = h[0] * fabs(a[0]) + h[1] * fabs(a[1]) + h[2] * fabs(a[2]);
    double bmin = csu_dot3(c, a) - rb, bmax = csu_dot3(c, a) + rb;
    double up = bmax - smin, down = smax - bmin; /* push the segment along +a or -a */
    if (up < best) {
      best = up;
      csu_copy3(n, a);
      *s_deep = s0 == s1 ? 0.5 : (s0 < s1 ? 0.0 : 1.0);
    }
    if (down < best) {
      best = down;
      csu_scale3(n, a, -1.0);
      *s_deep = s0 == s1 ? 0.5 : (s0 > s1 ? 0.0 : 1.0);
    }
  }
  return best;
}


double csc_capsuleBoxPenetration(const double p0[3], const double p1[3], double r,
                                 const cstBox* b, cscPenetration* out, double* s) {
  if (b->oriented) {
    double l0[3], l1[3];
    cstBox a = alignedFrame(b, p0, p1, l0, l1);
    cscPenetration pl;
    double depth = csc_capsuleBoxPenetration(l0, l1, r, &a, &pl, s);
    if (out) {
      out->depth = pl.depth;
      cst_boxDirToWorld(b, pl.normal, out->normal);
      cst_boxPointToWorld(b, pl.pos, out->pos);
    }
    return depth;
  }
  cscSegBox q;
  csc_segBoxInit(&q, p0, p1, b);
  double x[3], d[3], n[3] = {0, 1, 0}, depth, s_deep = 0.5;
  csu_sub3(d, p1, p0);
  if (q.q_min > 0) {
    /* axis outside: closest axis point to its clamp on the box */
    s_deep = q.s_min;
    csu_addScl3(x, p0, d, s_deep);
    double cp[3];
    double dist = cst_boxSignedDistance(b, x, cp, n);
    depth = r - dist;
  } else {
    depth = r + segmentBoxSat(p0, p1, b, n, &s_deep);
    csu_addScl3(x, p0, d, s_deep);
  }
  if (out) {
    out->depth = depth;
    csu_copy3(out->normal, n);
    /* deepest capsule point x - r n and the box surface depth further along +n */
    for (int k = 0; k < 3; k++) out->pos[k] = x[k] - r * n[k] + 0.5 * depth * n[k];
  }
  if (s) {
    *s = s_deep;
  }
  return depth;
}


void csc_ccdShapeSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out) {
  const cscCcdShape* s = obj;
  double u[3] = {dir->v[0], dir->v[1], dir->v[2]};
  if (csu_normalize3(u) == 0) {
    csu_set3(u, 1, 0, 0);
  }
  double p[3];
  switch (s->kind) {
    case CSC_CCD_SPHERE:
      csu_addScl3(p, s->c, u, s->r);
      break;
    case CSC_CCD_CAPSULE:
      csu_addScl3(p, csu_dot3(s->p0, u) >= csu_dot3(s->p1, u) ? s->p0 : s->p1, u, s->r);
      break;
    case CSC_CCD_BOX:
    default:
      csu_copy3(p, s->c);
      for (int k = 0; k < 3; k++) {
        double e[3] = {s->R[k], s->R[3 + k], s->R[6 + k]}; /* column k */
        csu_addScl3(p, p, e, csu_dot3(e, u) >= 0 ? s->h[k] : -s->h[k]);
      }
      break;
  }
  ccdVec3Set(out, p[0], p[1], p[2]);
}


void csc_ccdShapeCenter(const void* obj, ccd_vec3_t* out) {
  const cscCcdShape* s = obj;
  if (s->kind == CSC_CCD_CAPSULE) {
    ccdVec3Set(out, 0.5 * (s->p0[0] + s->p1[0]), 0.5 * (s->p0[1] + s->p1[1]),
               0.5 * (s->p0[2] + s->p1[2]));
  } else {
    ccdVec3Set(out, s->c[0], s->c[1], s->c[2]);
  }
}


void csc_ccdInit(ccd_t* ccd) {
  CCD_INIT(ccd);
  ccd->mpr_tolerance = CCD_MPR_TOL_MM;
  ccd->max_iterations = CCD_MAX_ITER;
}


int csc_ccdPenetration(const cscCcdShape* s, const cstBox* b, const ccd_t* ccd,
                       cscPenetration* out) {
  ccd_t c;
  if (ccd) {
    c = *ccd;
  } else {
    csc_ccdInit(&c);
  }
  /* obj1 = the box, obj2 = the shape: libccd's dir then moves the shape out of the box */
  c.support1 = cst_ccdBoxSupport;
  c.center1 = cst_ccdBoxCenter;
  c.support2 = csc_ccdShapeSupport;
  c.center2 = csc_ccdShapeCenter;
  ccd_real_t depth;
  ccd_vec3_t dir, pos;
  if (ccdMPRPenetration(b, s, &c, &depth, &dir, &pos) != 0) {
    return 0;
  }
  out->depth = depth;
  for (int k = 0; k < 3; k++) {
    out->normal[k] = dir.v[k];
    out->pos[k] = pos.v[k];
  }
  return 1;
}

/* fem_wall.c: in-surface stretches and wall gaps of the actuator's free surfaces (fem_wall.h).
 *
 * Rationale. The stretch is read off the surface itself, not off the owning element's F: the
 * Tri6 face map x(s, t) of the deformed surface over the reference one gives the two tangent
 * bases A = dX/d(s,t) and a = dx/d(s,t) (3 x 2), and the squared principal stretches are the
 * generalised eigenvalues of (a^T a, A^T A). That is the surface's own stretch, the quantity a
 * crease criterion is stated in, it needs no element, and it is exact for any deformation the
 * quadratic face interpolates (a homogeneous one in particular). The owning element's F at the
 * face would add the normal stretch, which the mixed P2/P0 element does not constrain pointwise
 * (its pointwise J is ~0.4 where elements fold while the element dilatation stays within 0.5 %
 * of 1): the normal stretch is taken from incompressibility instead (fem_wall.h).
 * The gap is a node-to-triangle distance over the straight sub-triangles of each Tri6, brute
 * force per cavity (a 2 mm chamber has ~10^2-10^3 face nodes: ~10^6 distance evaluations, an
 * estimate of well under a second, against a load step of 10 s or more; not timed separately). */
#include "fem_wall.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"

/* the six points of the degree-4 triangle rule (Dunavant 1985), (s, t): interior points cover
 * the face's stretch field well enough to find its extremes (the weights are not needed) */
static const double kTriA = 0.445948490915965, kTriB = 0.091576213509771;

/* the straight sub-triangles of a Tri6 (VTK order: vertices 0 1 2, edge nodes 3 = (0,1),
 * 4 = (1,2), 5 = (2,0)) */
static const int kSub[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};

/* 1 when `tag` is in tags[0..ntag) */
static int hasTag(int ntag, const int* tags, int tag);
/* squared distance from point p to triangle (a, b, c); Ericson 2005, Sec. 5.1.5 */
static double pointTriangleDist2(const double p[3], const double a[3], const double b[3],
                                 const double c[3]);


static int hasTag(int ntag, const int* tags, int tag) {
  for (int k = 0; k < ntag; k++) {
    if (tags[k] == tag) {
      return 1;
    }
  }
  return 0;
}


void csf_wallStretch(const csfMesh* me, const double* u, int ntag, const int* tags,
                     csfWallStretch* w) {
  memset(w, 0, sizeof *w);
  w->lam_eq = INFINITY, w->lam_min = INFINITY;
  w->lam_c = w->lam_t = NAN;
  w->face = w->tag = w->tet = -1;
  const double pts[6][2] = {{kTriA, kTriA}, {1 - 2 * kTriA, kTriA}, {kTriA, 1 - 2 * kTriA},
                            {kTriB, kTriB}, {1 - 2 * kTriB, kTriB}, {kTriB, 1 - 2 * kTriB}};
  for (int f = 0; f < me->nface; f++) {
    if (!hasTag(ntag, tags, me->face_tag[f])) {
      continue;
    }
    const int* fn = me->face + 6 * f;
    for (int q = 0; q < 6; q++) {
      double dN[12], N[6];
      csf_tri6Shape(pts[q][0], pts[q][1], NULL, dN);
      /* reference and deformed tangents A_k = dX/dxi_k, a_k = dx/dxi_k (k = s, t) */
      double A[2][3] = {{0}}, a[2][3] = {{0}};
      for (int n = 0; n < 6; n++) {
        const double* X = me->x + 3 * fn[n];
        const double* un = u + 3 * fn[n];
        for (int i = 0; i < 3; i++) {
          for (int k = 0; k < 2; k++) {
            A[k][i] += dN[2 * n + k] * X[i];
            a[k][i] += dN[2 * n + k] * (X[i] + un[i]);
          }
        }
      }
      double G[3] = {0}, g[3] = {0}; /* metrics (11, 22, 12) */
      for (int i = 0; i < 3; i++) {
        G[0] += A[0][i] * A[0][i], G[1] += A[1][i] * A[1][i], G[2] += A[0][i] * A[1][i];
        g[0] += a[0][i] * a[0][i], g[1] += a[1][i] * a[1][i], g[2] += a[0][i] * a[1][i];
      }
      /* det(g - mu G) = 0: mu^2 det G - mu (g11 G22 + g22 G11 - 2 g12 G12) + det g = 0 */
      const double dG = G[0] * G[1] - G[2] * G[2];
      const double dg = g[0] * g[1] - g[2] * g[2];
      const double bq = g[0] * G[1] + g[1] * G[0] - 2 * g[2] * G[2];
      if (!(dG > 0)) {
        continue; /* a degenerate reference face: no tangent plane */
      }
      const double disc = sqrt(fmax(bq * bq - 4 * dG * dg, 0.0));
      const double mu_t = (bq + disc) / (2 * dG);
      const double mu_c = fmax(dg / (dG * mu_t), 0.0); /* the product of the roots is dg/dG */
      const double lc = sqrt(mu_c), lt = sqrt(mu_t);
      const double leq = lc * sqrt(lt);
      w->npoint++;
      w->lam_min = fmin(w->lam_min, lc);
      if (leq < w->lam_eq) {
        w->lam_eq = leq, w->lam_c = lc, w->lam_t = lt;
        w->face = f, w->tag = me->face_tag[f], w->tet = me->face_tet ? me->face_tet[f] : -1;
        csf_tri6Shape(pts[q][0], pts[q][1], N, NULL);
        for (int i = 0; i < 3; i++) {
          w->X[i] = 0;
          for (int n = 0; n < 6; n++) {
            w->X[i] += N[n] * me->x[3 * fn[n] + i];
          }
        }
        /* eigenvector v (s, t) of mu_c: a row of (g - mu_c G) v = 0, the larger one */
        const double r0[2] = {g[0] - mu_c * G[0], g[2] - mu_c * G[2]};
        const double r1[2] = {g[2] - mu_c * G[2], g[1] - mu_c * G[1]};
        const double* r = hypot(r0[0], r0[1]) >= hypot(r1[0], r1[1]) ? r0 : r1;
        double v[2] = {-r[1], r[0]};
        if (hypot(v[0], v[1]) == 0) {
          v[0] = 1, v[1] = 0; /* equal stretches: any direction */
        }
        double nd = 0;
        for (int i = 0; i < 3; i++) {
          w->dir[i] = A[0][i] * v[0] + A[1][i] * v[1];
          nd += w->dir[i] * w->dir[i];
        }
        nd = sqrt(nd);
        for (int i = 0; i < 3; i++) {
          w->dir[i] = nd > 0 ? w->dir[i] / nd : 0;
        }
      }
    }
  }
}


static double pointTriangleDist2(const double p[3], const double a[3], const double b[3],
                                 const double c[3]) {
  double ab[3], ac[3], ap[3], q[3];
  csu_sub3(ab, b, a), csu_sub3(ac, c, a), csu_sub3(ap, p, a);
  const double d1 = csu_dot3(ab, ap), d2 = csu_dot3(ac, ap);
  if (d1 <= 0 && d2 <= 0) {
    memcpy(q, a, sizeof q); /* vertex region a */
  } else {
    double bp[3], cp[3];
    csu_sub3(bp, p, b), csu_sub3(cp, p, c);
    const double d3 = csu_dot3(ab, bp), d4 = csu_dot3(ac, bp);
    const double d5 = csu_dot3(ab, cp), d6 = csu_dot3(ac, cp);
    const double vc = d1 * d4 - d3 * d2, vb = d5 * d2 - d1 * d6, va = d3 * d6 - d5 * d4;
    if (d3 >= 0 && d4 <= d3) {
      memcpy(q, b, sizeof q); /* vertex region b */
    } else if (d6 >= 0 && d5 <= d6) {
      memcpy(q, c, sizeof q); /* vertex region c */
    } else if (vc <= 0 && d1 >= 0 && d3 <= 0) {
      const double v = d1 / (d1 - d3); /* edge ab */
      for (int i = 0; i < 3; i++) {
        q[i] = a[i] + v * ab[i];
      }
    } else if (vb <= 0 && d2 >= 0 && d6 <= 0) {
      const double v = d2 / (d2 - d6); /* edge ac */
      for (int i = 0; i < 3; i++) {
        q[i] = a[i] + v * ac[i];
      }
    } else if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
      const double v = (d4 - d3) / ((d4 - d3) + (d5 - d6)); /* edge bc */
      for (int i = 0; i < 3; i++) {
        q[i] = b[i] + v * (c[i] - b[i]);
      }
    } else {
      const double den = 1.0 / (va + vb + vc); /* interior */
      const double v = vb * den, wgt = vc * den;
      for (int i = 0; i < 3; i++) {
        q[i] = a[i] + ab[i] * v + ac[i] * wgt;
      }
    }
  }
  double pq[3];
  csu_sub3(pq, p, q);
  return csu_dot3(pq, pq);
}


csStatus csf_wallGap(const csfMesh* me, const double* u, int ntag, const int* tags,
                     double cos_opp, csfWallGap* g, csError* err) {
  g->gap = INFINITY, g->gap_ref = NAN, g->node = -1;
  g->X[0] = g->X[1] = g->X[2] = NAN;
  int nf = 0;
  for (int f = 0; f < me->nface; f++) {
    nf += hasTag(ntag, tags, me->face_tag[f]);
  }
  if (nf == 0) {
    return CS_OK;
  }
  /* the cavity's faces as sub-triangles (reference and deformed corners, reference unit
   * normal), its nodes listed once (loc: mesh node -> list index) with area-weighted normals */
  int* loc = malloc((size_t)me->nnode * sizeof *loc);
  int* nl = malloc((size_t)6 * nf * sizeof *nl);
  double* nn_ = calloc((size_t)18 * nf, sizeof *nn_);   /* node normals (list order) */
  double* xs = malloc((size_t)nf * 36 * sizeof *xs);    /* deformed corners */
  double* Xs = malloc((size_t)nf * 36 * sizeof *Xs);    /* reference corners */
  double* ns = malloc((size_t)nf * 12 * sizeof *ns);    /* reference unit normals */
  if (!loc || !nl || !nn_ || !xs || !Xs || !ns) {
    free(loc), free(nl), free(nn_), free(xs), free(Xs), free(ns);
    return cs_errorSet(err, CS_ERR_MEMORY, "csf_wallGap: out of memory for %d faces", nf);
  }
  for (int i = 0; i < me->nnode; i++) {
    loc[i] = -1;
  }
  int nn = 0, k4 = 0;
  for (int f = 0; f < me->nface; f++) {
    if (!hasTag(ntag, tags, me->face_tag[f])) {
      continue;
    }
    const int* fn = me->face + 6 * f;
    for (int n = 0; n < 6; n++) {
      if (loc[fn[n]] < 0) {
        loc[fn[n]] = nn;
        nl[nn++] = fn[n];
      }
    }
    for (int k = 0; k < 4; k++, k4++) {
      for (int c = 0; c < 3; c++) {
        const int node = fn[kSub[k][c]];
        for (int i = 0; i < 3; i++) {
          Xs[9 * k4 + 3 * c + i] = me->x[3 * node + i];
          xs[9 * k4 + 3 * c + i] = me->x[3 * node + i] + u[3 * node + i];
        }
      }
      const double* T = Xs + 9 * k4;
      double e1[3], e2[3], nv[3];
      csu_sub3(e1, T + 3, T), csu_sub3(e2, T + 6, T);
      csu_cross3(nv, e1, e2);
      const double an = csu_norm3(nv);
      for (int c = 0; c < 3; c++) {
        for (int i = 0; i < 3; i++) {
          nn_[3 * loc[fn[kSub[k][c]]] + i] += nv[i]; /* area-weighted */
        }
      }
      for (int i = 0; i < 3; i++) {
        ns[3 * k4 + i] = an > 0 ? nv[i] / an : 0;
      }
    }
  }
  for (int a = 0; a < nn; a++) {
    csu_normalize3(nn_ + 3 * a);
  }
  /* every node against every sub-triangle that faces it in the reference state */
  for (int a = 0; a < nn; a++) {
    const int node = nl[a];
    const double* Xp = me->x + 3 * node;
    const double* na = nn_ + 3 * a;
    double xp[3];
    for (int i = 0; i < 3; i++) {
      xp[i] = Xp[i] + u[3 * node + i];
    }
    for (int s = 0; s < k4; s++) {
      const double* nt = ns + 3 * s;
      if (csu_dot3(na, nt) > cos_opp) {
        continue; /* not opposite: the same side of the wall, or a neighbour */
      }
      const double* t = xs + 9 * s;
      const double d2 = pointTriangleDist2(xp, t, t + 3, t + 6);
      if (d2 < g->gap * g->gap) {
        const double* T = Xs + 9 * s;
        g->gap = sqrt(d2), g->gap_ref = sqrt(pointTriangleDist2(Xp, T, T + 3, T + 6));
        g->node = node;
        memcpy(g->X, Xp, sizeof g->X);
      }
    }
  }
  free(loc), free(nl), free(nn_), free(xs), free(Xs), free(ns);
  return CS_OK;
}

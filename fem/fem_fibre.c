/* fem_fibre.c: embedded fibres: locating fibre points in host tetrahedra (csf_modelAddFibre).
 *
 * A fibre is a polyline in the reference configuration; each of its points is located in the
 * tetrahedron that contains it (uniform bucket grid over element bounding boxes, then the
 * tetrahedron with the largest smallest barycentric coordinate, refined by Newton's method on the
 * Tet10 isoparametric map). The point then moves with the body: x = sum_a N_a(xi) x_a, which is
 * the "tie" of the paper's fibre model (ABAQUS embedded/tie constraint) without extra unknowns. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem_material.h"
#include "fem_model.h"

/* tolerance on the smallest barycentric coordinate for "inside" (dimensionless): points on a
 * face shared by two elements are inside both; 1e-6 absorbs round-off of the helix coordinates */
#define CSF_LOCATE_TOL 1e-6

typedef struct {
  double lo[3], h;   /* grid origin (mm) and cell size (mm) */
  int n[3];          /* cells per direction */
  int* start;        /* (ncell + 1) */
  int* item;         /* tetrahedra per cell */
} Grid;


static void gridFree(Grid* g) {
  free(g->start);
  free(g->item);
}


static int gridCell(const Grid* g, const double x[3], int c[3]) {
  for (int d = 0; d < 3; d++) {
    c[d] = (int)floor((x[d] - g->lo[d]) / g->h);
    if (c[d] < 0 || c[d] >= g->n[d]) {
      return 0;
    }
  }
  return 1;
}


static csStatus gridBuild(const csfMesh* me, Grid* g, csError* err) {
  double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
  for (int i = 0; i < me->nnode; i++) {
    for (int d = 0; d < 3; d++) {
      lo[d] = fmin(lo[d], me->x[3 * i + d]);
      hi[d] = fmax(hi[d], me->x[3 * i + d]);
    }
  }
  double vol = (hi[0] - lo[0]) * (hi[1] - lo[1]) * (hi[2] - lo[2]);
  g->h = 2.0 * cbrt(vol / me->ntet) + 1e-12;
  size_t ncell = 1;
  for (int d = 0; d < 3; d++) {
    g->lo[d] = lo[d] - 1e-6 * g->h;
    g->n[d] = (int)((hi[d] - g->lo[d]) / g->h) + 1;
    ncell *= (size_t)g->n[d];
  }
  g->start = calloc(ncell + 1, sizeof(int));
  if (!g->start) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_fibre: out of memory (grid)");
  }
  for (int pass = 0; pass < 2; pass++) {
    for (int e = 0; e < me->ntet; e++) {
      double blo[3] = {INFINITY, INFINITY, INFINITY}, bhi[3] = {-INFINITY, -INFINITY, -INFINITY};
      for (int a = 0; a < 10; a++) {
        const double* x = me->x + 3 * me->tet[10 * e + a];
        for (int d = 0; d < 3; d++) {
          blo[d] = fmin(blo[d], x[d]);
          bhi[d] = fmax(bhi[d], x[d]);
        }
      }
      int c0[3], c1[3];
      for (int d = 0; d < 3; d++) {
        c0[d] = (int)floor((blo[d] - g->lo[d]) / g->h);
        c1[d] = (int)floor((bhi[d] - g->lo[d]) / g->h);
        c0[d] = c0[d] < 0 ? 0 : c0[d];
        c1[d] = c1[d] >= g->n[d] ? g->n[d] - 1 : c1[d];
      }
      for (int k = c0[2]; k <= c1[2]; k++) {
        for (int j = c0[1]; j <= c1[1]; j++) {
          for (int i = c0[0]; i <= c1[0]; i++) {
            size_t c = ((size_t)k * g->n[1] + j) * g->n[0] + i;
            if (pass == 0) {
              g->start[c + 1]++;
            } else {
              g->item[g->start[c]++] = e;
            }
          }
        }
      }
    }
    if (pass == 0) {
      for (size_t c = 0; c < ncell; c++) {
        g->start[c + 1] += g->start[c];
      }
      g->item = malloc((size_t)(g->start[ncell] > 0 ? g->start[ncell] : 1) * sizeof(int));
      if (!g->item) {
        return cs_errorSet(err, CS_ERR_MEMORY, "fem_fibre: out of memory (grid)");
      }
    }
  }
  /* pass 2 advanced start[c] to the end of cell c: shift back */
  for (size_t c = ncell; c > 0; c--) {
    g->start[c] = g->start[c - 1];
  }
  g->start[0] = 0;
  return CS_OK;
}


/* natural coordinates of x in tetrahedron e: linear guess, then Newton on the Tet10 map */
static double locateIn(const csfMesh* me, int e, const double x[3], double xi[3]) {
  const int* tv = me->tet + 10 * e;
  const double* x0 = me->x + 3 * tv[0];
  double A[9], r[3];
  for (int d = 0; d < 3; d++) {
    for (int k = 0; k < 3; k++) {
      A[3 * d + k] = me->x[3 * tv[k + 1] + d] - x0[d];
    }
    r[d] = x[d] - x0[d];
  }
  for (int it = 0; it < 4; it++) {
    double det = A[0] * (A[4] * A[8] - A[5] * A[7]) - A[1] * (A[3] * A[8] - A[5] * A[6]) +
                 A[2] * (A[3] * A[7] - A[4] * A[6]);
    if (det == 0) {
      return -INFINITY;
    }
    double s[3];
    /* Cramer's rule: s = A^-1 r */
    for (int k = 0; k < 3; k++) {
      double B[9];
      memcpy(B, A, sizeof B);
      for (int d = 0; d < 3; d++) {
        B[3 * d + k] = r[d];
      }
      s[k] = (B[0] * (B[4] * B[8] - B[5] * B[7]) - B[1] * (B[3] * B[8] - B[5] * B[6]) +
              B[2] * (B[3] * B[7] - B[4] * B[6])) /
             det;
    }
    if (it == 0) {
      memcpy(xi, s, sizeof s);
    } else {
      for (int k = 0; k < 3; k++) {
        xi[k] += s[k];
      }
    }
    /* residual of the quadratic map and its Jacobian at xi */
    double N[10], dN[30];
    csf_tet10Shape(xi, N, dN);
    double xm[3] = {0, 0, 0};
    memset(A, 0, sizeof A);
    for (int a = 0; a < 10; a++) {
      const double* xa = me->x + 3 * tv[a];
      for (int d = 0; d < 3; d++) {
        xm[d] += N[a] * xa[d];
        for (int k = 0; k < 3; k++) {
          A[3 * d + k] += xa[d] * dN[3 * a + k];
        }
      }
    }
    for (int d = 0; d < 3; d++) {
      r[d] = x[d] - xm[d];
    }
  }
  return fmin(fmin(xi[0], xi[1]), fmin(xi[2], 1.0 - xi[0] - xi[1] - xi[2]));
}


/* find host of x: returns tetrahedron or -1; xi filled */
static int locate(const csfMesh* me, const Grid* g, const double x[3], double xi[3]) {
  int c[3];
  if (!gridCell(g, x, c)) {
    return -1;
  }
  size_t cell = ((size_t)c[2] * g->n[1] + c[1]) * g->n[0] + c[0];
  int best = -1;
  double bscore = -INFINITY, bxi[3] = {0, 0, 0};
  for (int q = g->start[cell]; q < g->start[cell + 1]; q++) {
    double t[3];
    double s = locateIn(me, g->item[q], x, t);
    if (s > bscore) {
      bscore = s, best = g->item[q];
      memcpy(bxi, t, sizeof bxi);
    }
  }
  if (best < 0 || bscore < -CSF_LOCATE_TOL) {
    return -1;
  }
  memcpy(xi, bxi, sizeof bxi);
  return best;
}


/* Points within this fraction of the local element size outside the meshed body are projected
 * onto it: the mesh's faceted surface lies inside the true one by the sagitta of its chords, h^2 /
 * (8 r) on a fillet of radius r (0.15 mm for 1.6 mm chords on r2 = 2 mm), more where folded
 * elements were straightened (csf_meshFixInverted), while the helices run CSF_FIBRE_INSET =
 * 0.2 mm below the true surface: a point up to ~0.2 of an element outside belongs on the surface
 * (issue 13: b = 3, r1 = 1.5 failed with a point 0.05 mm outside). Beyond it the fibre is truly
 * outside and refused. */
#define CSF_FIBRE_PROJECT_REL 0.2

/* longest edge of tetrahedron e (its corner nodes), mm */
static double tetSize(const csfMesh* me, int e) {
  const int* tv = me->tet + 10 * e;
  double hmax = 0;
  for (int a = 0; a < 4; a++) {
    for (int b = a + 1; b < 4; b++) {
      const double* x = me->x + 3 * tv[a];
      const double* y = me->x + 3 * tv[b];
      hmax = fmax(hmax, sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                             (x[2] - y[2]) * (x[2] - y[2])));
    }
  }
  return hmax;
}


/* Closest point of tetrahedron e's straight-sided hull (its 4 corners) to x, as natural
 * coordinates xi (3) and the point p: x itself when inside; else its orthogonal projection onto
 * the plane of the face it lies beyond (then clamped into the face). The element's curvature is
 * left out: the points handled here lie a fraction of an element off the surface. */
static void closestInTet(const csfMesh* me, int e, const double x[3], double xi[3], double p[3]) {
  const int* tv = me->tet + 10 * e;
  const double* V[4] = {me->x + 3 * tv[0], me->x + 3 * tv[1], me->x + 3 * tv[2], me->x + 3 * tv[3]};
  double y[3] = {x[0], x[1], x[2]};
  for (int pass = 0; pass < 2; pass++) {
    /* barycentric coordinates of y in the straight tetrahedron: solve [V1-V0 V2-V0 V3-V0] t = y - V0 */
    double A[9], r[3], t[4];
    for (int d = 0; d < 3; d++) {
      for (int k = 0; k < 3; k++) {
        A[3 * d + k] = V[k + 1][d] - V[0][d];
      }
      r[d] = y[d] - V[0][d];
    }
    double Ai[9];
    const double det = csf_inv3(A, Ai);
    if (det == 0) {
      break;
    }
    for (int k = 0; k < 3; k++) {
      t[k + 1] = Ai[3 * k] * r[0] + Ai[3 * k + 1] * r[1] + Ai[3 * k + 2] * r[2];
    }
    t[0] = 1.0 - t[1] - t[2] - t[3];
    int v = 0;
    for (int a = 1; a < 4; a++) {
      v = t[a] < t[v] ? a : v;
    }
    if (t[v] >= 0 || pass == 1) {
      /* inside, or already on the face plane: clamp the round-off and finish */
      double sum = 0;
      for (int a = 0; a < 4; a++) {
        t[a] = fmax(t[a], 0.0);
        sum += t[a];
      }
      for (int a = 0; a < 3; a++) {
        xi[a] = t[a + 1] / sum;
      }
      break;
    }
    /* beyond the face opposite corner v: project onto that face's plane */
    const double* F0 = V[(v + 1) % 4];
    const double* F1 = V[(v + 2) % 4];
    const double* F2 = V[(v + 3) % 4];
    double a1[3], a2[3], nrm[3];
    for (int d = 0; d < 3; d++) {
      a1[d] = F1[d] - F0[d];
      a2[d] = F2[d] - F0[d];
    }
    nrm[0] = a1[1] * a2[2] - a1[2] * a2[1];
    nrm[1] = a1[2] * a2[0] - a1[0] * a2[2];
    nrm[2] = a1[0] * a2[1] - a1[1] * a2[0];
    const double nn = nrm[0] * nrm[0] + nrm[1] * nrm[1] + nrm[2] * nrm[2];
    if (!(nn > 0)) {
      break;
    }
    const double h = ((y[0] - F0[0]) * nrm[0] + (y[1] - F0[1]) * nrm[1] + (y[2] - F0[2]) * nrm[2]) / nn;
    for (int d = 0; d < 3; d++) {
      y[d] -= h * nrm[d];
    }
  }
  double N[10];
  csf_tet10Shape(xi, N, NULL);
  p[0] = p[1] = p[2] = 0;
  for (int a = 0; a < 10; a++) {
    for (int d = 0; d < 3; d++) {
      p[d] += N[a] * me->x[3 * tv[a] + d];
    }
  }
}


/* Project x onto the nearest element of the grid cells around it (closestInTet). Returns the
 * element, or -1 if none lies within CSF_FIBRE_PROJECT_REL of its size; *dist gets the distance
 * to the nearest candidate (mm). */
static int projectOntoBody(const csfMesh* me, const Grid* g, const double x[3], double xi[3],
                           double p[3], double* dist) {
  int c[3];
  *dist = INFINITY;
  for (int d = 0; d < 3; d++) {
    c[d] = (int)floor((x[d] - g->lo[d]) / g->h);
  }
  int best = -1;
  double bxi[3] = {0, 0, 0}, bp[3] = {0, 0, 0}, bsize = 0;
  for (int dk = -1; dk <= 1; dk++) {
    for (int dj = -1; dj <= 1; dj++) {
      for (int di = -1; di <= 1; di++) {
        const int i = c[0] + di, j = c[1] + dj, k = c[2] + dk;
        if (i < 0 || j < 0 || k < 0 || i >= g->n[0] || j >= g->n[1] || k >= g->n[2]) {
          continue;
        }
        const size_t cell = ((size_t)k * g->n[1] + j) * g->n[0] + i;
        for (int q = g->start[cell]; q < g->start[cell + 1]; q++) {
          const int e = g->item[q];
          double t[3], y[3];
          closestInTet(me, e, x, t, y);
          const double dd = sqrt((y[0] - x[0]) * (y[0] - x[0]) + (y[1] - x[1]) * (y[1] - x[1]) +
                                 (y[2] - x[2]) * (y[2] - x[2]));
          if (dd < *dist) {
            *dist = dd, best = e, bsize = tetSize(me, e);
            memcpy(bxi, t, sizeof bxi);
            memcpy(bp, y, sizeof bp);
          }
        }
      }
    }
  }
  if (best < 0 || *dist > CSF_FIBRE_PROJECT_REL * bsize) {
    return -1;
  }
  memcpy(xi, bxi, sizeof bxi);
  memcpy(p, bp, sizeof bp);
  return best;
}


/* host of x, tetrahedron `prefer` when x lies in it (points on a shared face belong to both:
 * staying in the current host keeps the split points on its boundary); -1 outside the body */
static int locateInOrNear(const csfMesh* me, const Grid* g, int prefer, const double x[3],
                          double xi[3]) {
  if (locateIn(me, prefer, x, xi) >= -CSF_LOCATE_TOL) {
    return prefer;
  }
  return locate(me, g, x, xi);
}


/* Fibre elements of the polyline segment P0 -> P1 (hosts h0, h1 with natural coordinates xi0,
 * xi1), appended to m's arrays at index *nf (capacity cap): one element per host tetrahedron the
 * chord crosses, its end points on the faces where the host changes (found by bisection along
 * the chord), so that each element couples the 10 nodes of a single tetrahedron and adds no fill
 * to the tangent's pattern. Where an intermediate chord point lies in no element (the chord
 * leaves the faceted body between two interior points), the segment is kept as one element tied
 * to both hosts. Returns the number of elements written, or -1 when cap is exceeded. */
#define CSF_FIBRE_MAX_PIECES 64
#define CSF_FIBRE_BISECT 40      /* bisection steps: 2^-40 of the chord, far below round-off */
/* mm: pieces shorter than this are dropped (a chord clipping a corner, or ending a hair past a
 * face): their strain is a difference of interpolated positions, so its round-off is
 * ~1e-14 mm / L0 (measured: pieces of 1e-15 mm had strains of order 1 and stalled Newton);
 * at 1e-5 mm it is 1e-9, and the dropped fibre length is below 1e-5 mm per face crossing */
#define CSF_FIBRE_MIN_PIECE 1e-5

static int addPiece(csfModel* m, int f, int ha, const double xa[3], int hb, const double xb[3],
                    double EA) {
  const csfMesh* me = m->mesh;
  double xi[3], Na[10], Nb[10];
  locateIn(me, ha, xa, xi);
  csf_tet10Shape(xi, Na, NULL);
  locateIn(me, hb, xb, xi);
  csf_tet10Shape(xi, Nb, NULL);
  for (int a = 0; a < 10; a++) {
    m->fib_node[20 * f + a] = me->tet[10 * ha + a];
    m->fib_coef[20 * f + a] = -Na[a];
    m->fib_node[20 * f + 10 + a] = me->tet[10 * hb + a];
    m->fib_coef[20 * f + 10 + a] = Nb[a];
  }
  /* reference length from the interpolated end points (what the element actually sees), so the
   * fibre starts stress free even where the host map is only approximately inverted */
  double dX[3] = {0, 0, 0};
  for (int a = 0; a < 20; a++) {
    for (int d = 0; d < 3; d++) {
      dX[d] += m->fib_coef[20 * f + a] * me->x[3 * m->fib_node[20 * f + a] + d];
    }
  }
  m->fib_L0[f] = sqrt(dX[0] * dX[0] + dX[1] * dX[1] + dX[2] * dX[2]);
  m->fib_EA[f] = EA;
  return m->fib_L0[f] > CSF_FIBRE_MIN_PIECE ? 0 : -1;
}


static int splitSegment(csfModel* m, const Grid* g, const double* P0, int h0, const double* P1,
                        int h1, double EA, int split, int* nf, int cap) {
  const csfMesh* me = m->mesh;
  int written = 0;
  double a[3] = {P0[0], P0[1], P0[2]};
  int ha = h0;
  for (int piece = 0; piece < CSF_FIBRE_MAX_PIECES; piece++) {
    if (*nf >= cap) {
      return -1;
    }
    if (ha == h1 || !split) {
      if (addPiece(m, *nf, ha, a, h1, P1, EA) == 0) {
        (*nf)++, written++;
      }
      return written;
    }
    /* bisection on the chord a -> P1 for the point where the host stops being ha */
    double lo = 0, hi = 1, xi[3];
    int h_hi = h1;
    for (int it = 0; it < CSF_FIBRE_BISECT; it++) {
      const double t = 0.5 * (lo + hi);
      double x[3];
      for (int d = 0; d < 3; d++) {
        x[d] = a[d] + t * (P1[d] - a[d]);
      }
      const int h = locateInOrNear(me, g, ha, x, xi);
      if (h < 0) {
        /* the chord leaves the body: one element tied to both hosts (the old rule) */
        if (addPiece(m, *nf, ha, a, h1, P1, EA) == 0) {
          (*nf)++, written++;
        }
        return written;
      }
      if (h == ha) {
        lo = t;
      } else {
        hi = t, h_hi = h;
      }
    }
    double c[3];
    for (int d = 0; d < 3; d++) {
      c[d] = a[d] + hi * (P1[d] - a[d]);
    }
    /* the piece a -> c lies in ha; c is on ha's face (natural coordinates within round-off) */
    if (addPiece(m, *nf, ha, a, ha, c, EA) == 0) {
      (*nf)++, written++;
    }
    memcpy(a, c, sizeof a);
    ha = h_hi;
  }
  /* too many pieces (a degenerate chord along faces): close with one two-host element */
  if (*nf < cap && addPiece(m, *nf, ha, a, h1, P1, EA) == 0) {
    (*nf)++, written++;
  }
  return written;
}


csStatus csf_modelAddFibre(csfModel* m, int npts, const double* pts, double E, double radius,
                           csError* err) {
  if (m->finalized) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_fibre: add fibres before csf_modelFinalize");
  }
  if (npts < 2 || !(E > 0) || !(radius > 0)) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_fibre: need >= 2 points, E > 0, radius > 0");
  }
  const csfMesh* me = m->mesh;
  Grid g = {0};
  csStatus st = gridBuild(me, &g, err);
  if (st != CS_OK) {
    gridFree(&g);
    return st;
  }
  int* host = malloc((size_t)npts * sizeof(int));
  double* N = malloc((size_t)npts * 10 * sizeof(double));
  /* capacity: every segment may be split at each face its chord crosses */
  const int nf = m->nfib + (npts - 1) * (m->fib_split ? CSF_FIBRE_MAX_PIECES + 1 : 1);
  int* fnode = realloc(m->fib_node, (size_t)nf * 20 * sizeof(int));
  if (fnode) {
    m->fib_node = fnode;
  }
  double* fcoef = realloc(m->fib_coef, (size_t)nf * 20 * sizeof(double));
  if (fcoef) {
    m->fib_coef = fcoef;
  }
  double* fL0 = realloc(m->fib_L0, (size_t)nf * sizeof(double));
  if (fL0) {
    m->fib_L0 = fL0;
  }
  double* fEA = realloc(m->fib_EA, (size_t)nf * sizeof(double));
  if (fEA) {
    m->fib_EA = fEA;
  }
  if (!host || !N || !fnode || !fcoef || !fL0 || !fEA) {
    free(host), free(N), gridFree(&g);
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_fibre: out of memory (%d points)", npts);
  }
  double* at = malloc((size_t)npts * 3 * sizeof(double)); /* the points, projected if need be */
  if (!at) {
    free(host), free(N), gridFree(&g);
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_fibre: out of memory (%d points)", npts);
  }
  memcpy(at, pts, (size_t)npts * 3 * sizeof(double));
  for (int p = 0; p < npts; p++) {
    double xi[3];
    host[p] = locate(me, &g, at + 3 * p, xi);
    if (host[p] < 0) {
      double proj[3], dist;
      host[p] = projectOntoBody(me, &g, at + 3 * p, xi, proj, &dist);
      if (host[p] < 0) {
        free(host), free(N), free(at), gridFree(&g);
        return cs_errorSet(err, CS_ERR_RANGE,
                           "fem_fibre: fibre point %d (%g, %g, %g) mm lies %.3g mm outside the "
                           "meshed body (more than %g of the nearest element's size)", p,
                           pts[3 * p], pts[3 * p + 1], pts[3 * p + 2], dist,
                           CSF_FIBRE_PROJECT_REL);
      }
      memcpy(at + 3 * p, proj, sizeof proj);
      m->fib_projected++;
    }
    csf_tet10Shape(xi, N + 10 * p, NULL);
  }
  const double area = CS_PI * radius * radius;
  int nf_done = m->nfib;
  for (int s = 0; s + 1 < npts; s++) {
    if (splitSegment(m, &g, at + 3 * s, host[s], at + 3 * (s + 1), host[s + 1], E * area,
                     m->fib_split, &nf_done, nf) < 0) {
      free(host), free(N), free(at), gridFree(&g);
      return cs_errorSet(err, CS_ERR_MEMORY, "fem_fibre: fibre segment %d crosses too many "
                         "elements", s);
    }
  }
  m->nfib = nf_done;
  /* give back the split capacity that was not used */
  const size_t keep = (size_t)(nf_done > 0 ? nf_done : 1);
  int* fn2 = realloc(m->fib_node, keep * 20 * sizeof(int));
  double* fc2 = realloc(m->fib_coef, keep * 20 * sizeof(double));
  double* fl2 = realloc(m->fib_L0, keep * sizeof(double));
  double* fe2 = realloc(m->fib_EA, keep * sizeof(double));
  m->fib_node = fn2 ? fn2 : m->fib_node;
  m->fib_coef = fc2 ? fc2 : m->fib_coef;
  m->fib_L0 = fl2 ? fl2 : m->fib_L0;
  m->fib_EA = fe2 ? fe2 : m->fib_EA;
  free(host), free(N), free(at), gridFree(&g);
  return CS_OK;
}

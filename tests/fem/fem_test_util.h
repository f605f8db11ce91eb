/* fem_test_util.h: helpers shared by the fem tests (header-only, static functions). */
#ifndef CS_FEM_TEST_UTIL_H
#define CS_FEM_TEST_UTIL_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fem_newton.h"

/* scale map: unit cube -> [0,sx] x [0,sy] x [0,sz] */
static inline void ftScaleMap(void* user, const double xi[3], double x[3]) {
  const double* s = user;
  x[0] = s[0] * xi[0];
  x[1] = s[1] * xi[1];
  x[2] = s[2] * xi[2];
}

/* fix dof `dir` of every node with |x[coord] - val| < tol, prescribing u = value * load */
static inline int ftFix(csfModel* m, int coord, double val, int dir, double value) {
  int n = 0;
  for (int i = 0; i < m->mesh->nnode; i++) {
    if (fabs(m->mesh->x[3 * i + coord] - val) < 1e-9) {
      m->fixed[3 * i + dir] = 1;
      m->u_fix[3 * i + dir] = value;
      n++;
    }
  }
  return n;
}

/* ramp the load factor 0 -> 1 in nstep equal steps; returns CS_OK or the failing status */
static inline csStatus ftRamp(const csfModel* m, csfData* d, int nstep, csError* err) {
  csfNewtonOptions o = csf_newtonDefault();
  for (int s = 1; s <= nstep; s++) {
    csStatus st = csf_newtonSolve(m, d, (double)s / nstep, &o, NULL, err);
    if (st != CS_OK) {
      fprintf(stderr, "ramp step %d: %s\n", s, err->msg);
      return st;
    }
  }
  return CS_OK;
}

/* volume-weighted mean Cauchy stress component c (0..5) over the mesh */
static inline double ftMeanStress(const csfModel* m, const csfData* d, int c) {
  double s = 0, v = 0;
  for (int e = 0; e < m->mesh->ntet; e++) {
    double sig[6];
    csf_tetCauchyAt(m, d, e, sig);
    s += sig[c] * m->vol[e];
    v += m->vol[e];
  }
  return s / v;
}

/* the reduced models' full basis: every free dof of m (ndof x n, the identity on the free
 * dofs, zero rows on clamped ones); *n_out gets n; the caller frees */
static inline double* ftFreeDofBasis(const csfModel* m, int* n_out) {
  int n = 0;
  *n_out = 0;
  if (m->ndof <= 0) {
    return NULL;
  }
  for (int i = 0; i < m->ndof; i++) {
    n += !m->fixed[i];
  }
  /* both factors positive ints, so the product fits a size_t (GCC's alloc-size check cannot see
   * the sign of ndof through the loop otherwise) */
  const size_t rows = (size_t)(unsigned)m->ndof, cols = (size_t)(unsigned)(n > 0 ? n : 1);
  double* V = calloc(rows * cols, sizeof(double));
  for (int i = 0, j = 0; V && i < m->ndof; i++) {
    if (!m->fixed[i]) {
      V[(size_t)i * n + j++] = 1.0;
    }
  }
  *n_out = n;
  return V;
}

/* the k x k identity (row-major; the caller frees) */
static inline double* ftIdentity(int k) {
  double* I = calloc((size_t)k * (size_t)k + 1, sizeof(double));
  for (int i = 0; I && i < k; i++) {
    I[(size_t)i * k + i] = 1.0;
  }
  return I;
}

#endif /* CS_FEM_TEST_UTIL_H */

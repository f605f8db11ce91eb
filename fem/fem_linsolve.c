/* fem_linsolve.c: KLU backend of csfLinSolver (see fem_linsolve.h).
 *
 * KLU factors a matrix given in compressed-column form. Our tangent is stored in CSR, which is
 * the CSC form of K^T; we factor K^T and solve with klu_tsolve, i.e. (K^T)^T x = K x = b, so no
 * transposed copy is needed. The ordering is AMD (KLU's default) after a BTF permutation;
 * partial pivoting with KLU's default tolerance 0.001. */
#include "fem_linsolve.h"

#include <klu.h>
#include <stdlib.h>

struct csfLinSolver_ {
  int n;
  int* ap; /* KLU wants non-const int arrays */
  int* ai;
  klu_common common;
  klu_symbolic* sym;
  klu_numeric* num;
};


csfLinSolver* csf_linSolverCreate(int n, const int* row_ptr, const int* col, csError* err) {
  csfLinSolver* s = calloc(1, sizeof *s);
  if (!s) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_linsolve: out of memory");
    return NULL;
  }
  s->n = n;
  s->ap = (int*)row_ptr;
  s->ai = (int*)col;
  klu_defaults(&s->common);
  s->sym = klu_analyze(n, s->ap, s->ai, &s->common);
  if (!s->sym) {
    cs_errorSet(err, CS_ERR_SOLVER, "fem_linsolve: KLU analysis failed (status %d, n %d)",
                s->common.status, n);
    free(s);
    return NULL;
  }
  return s;
}


int csf_linSolverFactor(csfLinSolver* s, const double* val) {
  if (s->num) {
    klu_free_numeric(&s->num, &s->common);
  }
  s->num = klu_factor(s->ap, s->ai, (double*)val, s->sym, &s->common);
  return s->num ? 0 : 1;
}


int csf_linSolverSolve(csfLinSolver* s, double* b) {
  return klu_tsolve(s->sym, s->num, s->n, 1, b, &s->common) ? 0 : 1;
}


double csf_linSolverFactorNnz(const csfLinSolver* s) {
  return s->num ? (double)s->num->lnz + (double)s->num->unz : 0.0;
}


void csf_linSolverDestroy(csfLinSolver* s) {
  if (!s) {
    return;
  }
  if (s->num) {
    klu_free_numeric(&s->num, &s->common);
  }
  if (s->sym) {
    klu_free_symbolic(&s->sym, &s->common);
  }
  free(s);
}

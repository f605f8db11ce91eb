/* fem_linsolve.c: MUMPS and KLU backends of csfLinSolver (see fem_linsolve.h).
 *
 * KLU factors a matrix given in compressed-column form. Our tangent is stored in CSR, which is
 * the CSC form of K^T; we factor K^T and solve with klu_tsolve, i.e. (K^T)^T x = K x = b, so no
 * transposed copy is needed.
 * MUMPS takes coordinate triplets (1-based): they are built once from the CSR pattern; values
 * are passed by pointer at every factorisation. The sequential library (no MPI) is used, so no
 * process-wide MPI initialisation is needed. Unsymmetric mode (SYM = 0): the follower-pressure
 * stiffness is not symmetric face by face. Output of MUMPS is silenced (ICNTL 1-4). */
#include "fem_linsolve.h"

#include <dmumps_c.h>
#include <klu.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif

/* Run MUMPS single-threaded. Measured (bench_fem_solver, 51207 dofs): factor 3.1 s with one
 * thread, 20 s with two OpenMP threads under libgomp's default active waiting (spinning threads
 * of our assembly loop and MUMPS' own OpenMP regions compete), 3.2 s with two threads and
 * OMP_WAIT_POLICY=passive. Threads are used for assembly instead. */
static int enterSerial(void) {
#ifdef _OPENMP
  int prev = omp_get_max_threads();
  omp_set_num_threads(1);
  return prev;
#else
  return 1;
#endif
}


static void leaveSerial(int prev) {
#ifdef _OPENMP
  omp_set_num_threads(prev);
#else
  (void)prev;
#endif
}

#define MUMPS_JOB_INIT -1
#define MUMPS_JOB_END -2
#define MUMPS_USE_COMM_WORLD -987654
/* MUMPS ICNTL(14): extra workspace in percent for delayed pivots (default 20); 60 avoids the
 * -9 "workspace too small" error measured on indefinite tangents near limit points */
#define MUMPS_MEM_RELAX 60

struct csfLinSolver_ {
  csfSolverKind kind;
  int n;
  /* KLU */
  int* ap;
  int* ai;
  klu_common common;
  klu_symbolic* sym;
  klu_numeric* num;
  /* MUMPS */
  DMUMPS_STRUC_C id;
  int* irn;
  int* jcn;
  int mumps_on;
  int factored;
};


csfLinSolver* csf_linSolverCreate(csfSolverKind kind, int n, const int* row_ptr, const int* col,
                                  csError* err) {
  csfLinSolver* s = calloc(1, sizeof *s);
  if (!s) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_linsolve: out of memory");
    return NULL;
  }
  s->kind = kind;
  s->n = n;
  s->ap = (int*)row_ptr;
  s->ai = (int*)col;
  if (kind == CSF_SOLVER_KLU) {
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
  const int nnz = row_ptr[n];
  s->irn = malloc((size_t)nnz * sizeof(int));
  s->jcn = malloc((size_t)nnz * sizeof(int));
  if (!s->irn || !s->jcn) {
    csf_linSolverDestroy(s);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_linsolve: out of memory (%d nonzeros)", nnz);
    return NULL;
  }
  for (int i = 0; i < n; i++) {
    for (int q = row_ptr[i]; q < row_ptr[i + 1]; q++) {
      s->irn[q] = i + 1;
      s->jcn[q] = col[q] + 1;
    }
  }
  s->id.job = MUMPS_JOB_INIT;
  s->id.par = 1;
  s->id.sym = 0;
  s->id.comm_fortran = MUMPS_USE_COMM_WORLD;
  int prev0 = enterSerial();
  dmumps_c(&s->id);
  leaveSerial(prev0);
  s->mumps_on = 1;
  if (s->id.infog[0] < 0) {
    cs_errorSet(err, CS_ERR_SOLVER, "fem_linsolve: MUMPS init failed (INFOG(1) %d)",
                s->id.infog[0]);
    csf_linSolverDestroy(s);
    return NULL;
  }
  s->id.icntl[0] = -1; /* no error, diagnostic, global output */
  s->id.icntl[1] = -1;
  s->id.icntl[2] = -1;
  s->id.icntl[3] = 0;
  s->id.icntl[6] = 7; /* ordering: automatic choice (METIS when available) */
  s->id.icntl[13] = MUMPS_MEM_RELAX;
  s->id.n = n;
  s->id.nnz = nnz;
  s->id.irn = s->irn;
  s->id.jcn = s->jcn;
  s->id.job = 1; /* analysis */
  int prev = enterSerial();
  dmumps_c(&s->id);
  leaveSerial(prev);
  if (s->id.infog[0] < 0) {
    cs_errorSet(err, CS_ERR_SOLVER, "fem_linsolve: MUMPS analysis failed (INFOG(1) %d, (2) %d)",
                s->id.infog[0], s->id.infog[1]);
    csf_linSolverDestroy(s);
    return NULL;
  }
  return s;
}


int csf_linSolverFactor(csfLinSolver* s, const double* val) {
  if (s->kind == CSF_SOLVER_KLU) {
    if (s->num) {
      klu_free_numeric(&s->num, &s->common);
    }
    s->num = klu_factor(s->ap, s->ai, (double*)val, s->sym, &s->common);
    return s->num ? 0 : 1;
  }
  s->id.a = (double*)val;
  s->id.job = 2;
  int prev = enterSerial();
  dmumps_c(&s->id);
  if (s->id.infog[0] == -9 || s->id.infog[0] == -8) {
    /* workspace too small (delayed pivots): double the relaxation and retry once */
    s->id.icntl[13] *= 2;
    dmumps_c(&s->id);
  }
  leaveSerial(prev);
  s->factored = s->id.infog[0] >= 0;
  return s->factored ? 0 : 1;
}


int csf_linSolverSolve(csfLinSolver* s, double* b) {
  if (s->kind == CSF_SOLVER_KLU) {
    return klu_tsolve(s->sym, s->num, s->n, 1, b, &s->common) ? 0 : 1;
  }
  s->id.rhs = b;
  s->id.nrhs = 1;
  s->id.lrhs = s->n;
  s->id.job = 3;
  int prev = enterSerial();
  dmumps_c(&s->id);
  leaveSerial(prev);
  return s->id.infog[0] >= 0 ? 0 : 1;
}


double csf_linSolverFactorNnz(const csfLinSolver* s) {
  if (s->kind == CSF_SOLVER_KLU) {
    return s->num ? (double)s->num->lnz + (double)s->num->unz : 0.0;
  }
  /* INFOG(29): effective number of entries in the factors (negative: millions) */
  long v = s->id.infog[28];
  return v < 0 ? -1e6 * (double)v : (double)v;
}


const char* csf_linSolverName(const csfLinSolver* s) {
  return s->kind == CSF_SOLVER_KLU ? "klu" : "mumps";
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
  if (s->mumps_on) {
    s->id.job = MUMPS_JOB_END;
    dmumps_c(&s->id);
  }
  free(s->irn);
  free(s->jcn);
  free(s);
}

/* fem_linsolve.c: MUMPS and KLU backends of csfLinSolver (see fem_linsolve.h).
 *
 * KLU factors a matrix given in compressed-column form. Our tangent is stored in CSR, which is
 * the CSC form of K^T; we factor K^T and solve with klu_tsolve, i.e. (K^T)^T x = K x = b, so no
 * transposed copy is needed.
 * MUMPS takes coordinate triplets (1-based): they are built once from the CSR pattern. In
 * unsymmetric mode (SYM = 0) the values are passed by pointer at every factorisation; in
 * symmetric mode (SYM = 2, general symmetric: LDL^T with 1x1 and 2x2 pivots, for tangents that
 * turn indefinite past limit points) only the upper triangle is given (MUMPS sums entries given
 * twice), so its values are gathered into a buffer (`sel` maps them) before each factorisation.
 * The sequential library (no MPI) is used by default, so no process-wide MPI initialisation is
 * needed. The MPI build (CS_FEM_MPI: Debian's libmumps on OpenMPI, the cs_fem_mpi library of
 * crawlsim-mpi; the two MUMPS builds define the same symbols, so a program links one of them)
 * runs MUMPS on MPI_COMM_SELF, or, with opt.ranks > 1, on every rank of MPI_COMM_WORLD: this
 * process is MUMPS's host (PAR = 1: it works too) and holds the matrix and the right-hand side
 * (centralised input, ICNTL(18) = ICNTL(20) = 0); before each MUMPS call it sends the call's
 * job to the other ranks, which sit in csf_linSolverServe and make the same call on their own
 * instance (mumpsCall). Only the host runs the FE; the others take part in the factorisations
 * and solves and nothing else.
 * Output of MUMPS is silenced (ICNTL 1-4).
 * Threads: Debian's sequential MUMPS is built with OpenMP and calls OpenBLAS (OpenMP build); both
 * take their thread count from omp_set_num_threads, which is set for the duration of each MUMPS
 * call and restored afterwards (the assembly loop has its own count). */
#include "fem_linsolve.h"

#ifdef CS_FEM_MPI
#define _POSIX_C_SOURCE 200809L /* nanosleep */
#endif
#include <dmumps_c.h>
#include <math.h>
#include <klu.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#ifdef _OPENMP
#include <omp.h>
#endif
#ifdef CS_FEM_MPI
#include <mpi.h>
#include <time.h>
#endif

/* Relative residual an unpivoted LDL^T of an indefinite matrix must meet at a solve before it
 * is redone with pivoting: MUMPS's pivoted LDL^T reaches 1e-14..1e-10 on the FE tangents
 * (κ up to ~1e9), and a Newton direction 1e-8 off costs nothing; an unstable unpivoted
 * factorisation (a pivot near zero) is off by many orders more */
#define CSF_SOLVE_RTOL 1e-8

/* Set the OpenMP thread count for a MUMPS call; returns the previous one. */
static int enterThreads(int threads) {
#ifdef _OPENMP
  int prev = omp_get_max_threads();
  if (threads > 0) {
    omp_set_num_threads(threads);
  }
  return prev;
#else
  (void)threads;
  return 1;
#endif
}


static void leaveThreads(int prev) {
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

/* largest LWK_USER MUMPS' 32-bit integer interface takes */
#define MUMPS_LWK_MAX 2147483647.0

struct csfLinSolver_ {
  csfLinSolverOptions opt;
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
  int* sel;     /* symmetric mode: (nz) CSR index of each upper-triangle entry given to MUMPS */
  double* aval; /* symmetric mode: (nz) gathered values */
  double* wk;   /* MUMPS main workspace S, owned here (WK_USER, LWK_USER entries) */
  int nthreads; /* threads of factorisations and solves (opt.threads, or chosen by size) */
  long lwk;
  int mumps_on;
  int factored;
  double piv_default; /* MUMPS's CNTL(1) after initialisation (0.01) */
  int pivot_next;     /* 1: the next factorisation pivots (the last one had to be redone) */
  int check_solve;    /* 1: unpivoted and indefinite: solves check their residual */
  int n_repivot;      /* no-pivoting factorisations redone with threshold pivoting */
  double* bcopy;      /* (n) symmetric mode: the right-hand side of a checked solve */
  double* rcheck;     /* (n) symmetric mode: its residual */
  int nranks;         /* MPI ranks taking part in the factorisations (1: this process alone) */
};


/* ---- the host's orders to the other ranks (MPI build, opt.ranks > 1) ---------------------- */

/* one MUMPS call as the other ranks must repeat it */
typedef struct {
  long long key; /* the host's solver (its address): the other ranks' instance of it */
  int job;       /* MUMPS JOB, or ORDER_QUIT */
  int sym;       /* SYM (JOB = -1) */
  int icntl14;   /* workspace relaxation, % (grows on a retry: the ranks grow theirs) */
  int threads;   /* OpenMP threads of the call (0: unchanged) */
  double cntl1;  /* pivoting threshold */
} Order;

#define ORDER_QUIT 1000
#define ORDER_TAG 3801
/* a rank waiting for its next order sleeps this long between looks (s): short against a
 * factorisation (~1 s), long enough to leave the cores to the host's assembly */
#define ORDER_POLL_S 0.001
/* instances a serving rank holds at once (a sweep holds one; room for tools that hold more) */
#define SERVE_MAX 16


/* dmumps_c, first ordered on the other ranks when they take part */
static void mumpsCall(csfLinSolver* s) {
#ifdef CS_FEM_MPI
  if (s->nranks > 1) {
    const Order o = {(long long)(intptr_t)s, s->id.job, s->id.sym, s->id.icntl[13], s->nthreads,
                     s->id.cntl[0]};
    for (int r = 1; r < s->nranks; r++) {
      MPI_Send(&o, (int)sizeof o, MPI_BYTE, r, ORDER_TAG, MPI_COMM_WORLD);
    }
  }
#endif
  dmumps_c(&s->id);
}


/* Main workspace S for the numeric factorisation, from the analysis: INFO(8) entries (negative:
 * millions) plus the ICNTL(14) relaxation for delayed pivots. MUMPS allocates S itself at every
 * factorisation otherwise; measured (bench_fem_linsolve, baseline l_soft 4): the ~0.9 GB were
 * mapped and zeroed anew each time, 0.2 M page faults and 10-25 % of the factorisation time. A
 * workspace owned here (WK_USER) is touched once. */
static double workspaceEstimate(const csfLinSolver* s) {
  const double info8 = (double)s->id.info[7];
  const double need = info8 < 0 ? -1e6 * info8 : info8;
  return need * (1.0 + 0.01 * s->id.icntl[13]);
}


/* (re)allocate WK_USER to at least `entries` doubles; 0 on success */
static int growWorkspace(csfLinSolver* s, double entries) {
  if (!(entries > 0)) {
    return 0;
  }
  if (entries > MUMPS_LWK_MAX) {
    entries = MUMPS_LWK_MAX;
  }
  if ((double)s->lwk >= entries) {
    return 0;
  }
  double* wk = malloc((size_t)entries * sizeof(double));
  if (!wk) {
    return 1;
  }
  free(s->wk);
  s->wk = wk;
  s->lwk = (long)entries;
  s->id.wk_user = wk;
  s->id.lwk_user = (int)s->lwk;
  return 0;
}




csfLinSolver* csf_linSolverCreate(const csfLinSolverOptions* opt, int n, const int* row_ptr,
                                  const int* col, csError* err) {
  csfLinSolver* s = calloc(1, sizeof *s);
  if (!s) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_linsolve: out of memory");
    return NULL;
  }
  s->opt = opt ? *opt : csf_linSolverDefault();
  const csfSolverKind kind = s->opt.kind;
  if (kind == CSF_SOLVER_KLU) {
    s->opt.symmetric = 0;
  }
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
  int nnz = row_ptr[n];
  if (s->opt.symmetric) {
    int nz = 0;
    for (int i = 0; i < n; i++) {
      for (int q = row_ptr[i]; q < row_ptr[i + 1]; q++) {
        nz += col[q] >= i;
      }
    }
    nnz = nz;
  }
  s->irn = malloc((size_t)nnz * sizeof(int));
  s->jcn = malloc((size_t)nnz * sizeof(int));
  if (s->opt.symmetric) {
    s->sel = malloc((size_t)nnz * sizeof(int));
    s->aval = malloc((size_t)nnz * sizeof(double));
    s->bcopy = malloc((size_t)n * sizeof(double));
    s->rcheck = malloc((size_t)n * sizeof(double));
  }
  if (!s->irn || !s->jcn ||
      (s->opt.symmetric && (!s->sel || !s->aval || !s->bcopy || !s->rcheck))) {
    csf_linSolverDestroy(s);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_linsolve: out of memory (%d nonzeros)", nnz);
    return NULL;
  }
  int k = 0;
  for (int i = 0; i < n; i++) {
    for (int q = row_ptr[i]; q < row_ptr[i + 1]; q++) {
      if (s->opt.symmetric && col[q] < i) {
        continue;
      }
      s->irn[k] = i + 1;
      s->jcn[k] = col[q] + 1;
      if (s->sel) {
        s->sel[k] = q;
      }
      k++;
    }
  }
  /* the initialisation and analysis run on the cap too (0: OpenMP's current count) */
  s->nthreads = s->opt.threads > 0 ? s->opt.threads : s->opt.max_threads;
  s->id.job = MUMPS_JOB_INIT;
  s->id.par = 1;
  s->id.sym = s->opt.symmetric ? 2 : 0;
  s->id.comm_fortran = MUMPS_USE_COMM_WORLD;
  s->nranks = 1;
#ifdef CS_FEM_MPI
  int mpi_on = 0;
  MPI_Initialized(&mpi_on);
  if (!mpi_on) {
    cs_errorSet(err, CS_ERR_SOLVER, "fem_linsolve: MPI is not initialised (the MPI build's MUMPS "
                "needs MPI_Init before its first solver)");
    csf_linSolverDestroy(s);
    return NULL;
  }
  if (s->opt.ranks > 1) {
    int size = 1, rank = 0;
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    if (rank != 0 || size != s->opt.ranks) {
      cs_errorSet(err, CS_ERR_ARG, "fem_linsolve: %d ranks requested, but this is rank %d of %d "
                  "(the host must be rank 0 of MPI_COMM_WORLD)", s->opt.ranks, rank, size);
      csf_linSolverDestroy(s);
      return NULL;
    }
    s->nranks = size;
  } else {
    s->id.comm_fortran = (MUMPS_INT)MPI_Comm_c2f(MPI_COMM_SELF);
  }
#else
  if (s->opt.ranks > 1) {
    cs_errorSet(err, CS_ERR_ARG, "fem_linsolve: %d MPI ranks requested from the sequential "
                "MUMPS build (crawlsim-mpi links the MPI one)", s->opt.ranks);
    csf_linSolverDestroy(s);
    return NULL;
  }
#endif
  int prev0 = enterThreads(s->nthreads);
  mumpsCall(s);
  leaveThreads(prev0);
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
  s->id.icntl[6] = s->opt.ordering; /* ICNTL(7): ordering (7 = automatic choice) */
  s->id.icntl[13] = MUMPS_MEM_RELAX;
  s->piv_default = s->id.cntl[0];
  if (s->opt.pivot_threshold >= 0) {
    s->id.cntl[0] = s->opt.pivot_threshold;
  }
  s->id.n = n;
  s->id.nnz = nnz;
  s->id.irn = s->irn;
  s->id.jcn = s->jcn;
  s->id.job = 1; /* analysis */
  int prev = enterThreads(s->nthreads);
  mumpsCall(s);
  leaveThreads(prev);
  if (s->id.infog[0] < 0) {
    cs_errorSet(err, CS_ERR_SOLVER, "fem_linsolve: MUMPS analysis failed (INFOG(1) %d, (2) %d)",
                s->id.infog[0], s->id.infog[1]);
    csf_linSolverDestroy(s);
    return NULL;
  }
  s->nthreads = s->opt.threads;
  if (s->nthreads <= 0) {
#ifdef _OPENMP
    const int most = s->opt.max_threads > 0 ? s->opt.max_threads : omp_get_max_threads();
    s->nthreads = s->id.rinfog[0] < CSF_MT_MIN_FLOPS ? 1 : most;
#else
    s->nthreads = 1;
#endif
  }
  if (growWorkspace(s, workspaceEstimate(s)) != 0) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_linsolve: out of memory for the MUMPS workspace "
                "(%.3g entries)", workspaceEstimate(s));
    csf_linSolverDestroy(s);
    return NULL;
  }
  return s;
}


/* MUMPS's numeric factorisation of s->id.a (threads set by the caller), retrying with a doubled
 * workspace when delayed pivots of an indefinite tangent overflow it (INFOG(1) -8, -9). */
static void mumpsFactor(csfLinSolver* s) {
  s->id.job = 2;
  mumpsCall(s);
  for (int retry = 0; retry < 2 && (s->id.infog[0] == -9 || s->id.infog[0] == -8); retry++) {
    s->id.icntl[13] *= 2;
    if (growWorkspace(s, 2.0 * (double)s->lwk) != 0) {
      break;
    }
    mumpsCall(s);
  }
}


/* An unpivoted LDL^T that failed (a zero pivot) or missed its solve's residual check, factored
 * again with MUMPS's threshold pivoting, whose 2x2 pivots keep it stable; the next
 * factorisation pivots too. */
static void repivot(csfLinSolver* s) {
  s->id.cntl[0] = s->piv_default;
  s->n_repivot++;
  s->pivot_next = 1;
  mumpsFactor(s);
}


int csf_linSolverFactor(csfLinSolver* s, const double* val) {
  if (s->opt.kind == CSF_SOLVER_KLU) {
    if (s->num) {
      klu_free_numeric(&s->num, &s->common);
    }
    s->num = klu_factor(s->ap, s->ai, (double*)val, s->sym, &s->common);
    return s->num ? 0 : 1;
  }
  if (s->opt.symmetric) {
    const int nz = s->id.nnz;
    for (int k = 0; k < nz; k++) {
      s->aval[k] = val[s->sel[k]];
    }
    s->id.a = s->aval;
  } else {
    s->id.a = (double*)val;
  }
  /* checked unpivoted LDL^T (fem_linsolve.h): a definite tangent factors stably on its
   * diagonal pivots, and MUMPS's threshold test then only costs time (baseline leg, l_soft 4:
   * 1.93-2.02 s against 2.52-2.64 s per factorisation, the same fill, solutions 5e-9 apart:
   * fem/README.md "Speed"). An indefinite matrix factored without pivoting is checked by the
   * residual of its solves (csf_linSolverSolve) and redone with pivoting only if that fails:
   * the extrapolated predictor's state has 1-3 negative pivots at nearly every load step of
   * the baseline's 360 deg run, and its next iterate none */
  const int checked = s->opt.symmetric && s->opt.pivot_threshold < 0;
  if (checked) {
    s->id.cntl[0] = s->pivot_next ? s->piv_default : 0.0;
    s->pivot_next = 0;
  }
  int prev = enterThreads(s->nthreads);
  mumpsFactor(s);
  if (checked && s->id.cntl[0] == 0.0 && s->id.infog[0] < 0) {
    /* singular on the diagonal (a zero pivot without pivoting) */
    repivot(s);
  }
  leaveThreads(prev);
  s->factored = s->id.infog[0] >= 0;
  /* an unpivoted factorisation of an indefinite matrix is checked at its solves */
  s->check_solve = s->factored && checked && s->id.cntl[0] == 0.0 && s->id.infog[11] > 0;
  return s->factored ? 0 : 1;
}


/* Relative residual |A x - b| / |b| of a solve (A from the upper-triangle triplets given to
 * MUMPS, b in s->bcopy) within CSF_SOLVE_RTOL, and finite. */
static int solveAccurate(const csfLinSolver* s, const double* x) {
  double* r = s->rcheck;
  memcpy(r, s->bcopy, (size_t)s->n * sizeof(double));
  const int nz = s->id.nnz;
  for (int k = 0; k < nz; k++) {
    const int i = s->irn[k] - 1, j = s->jcn[k] - 1;
    const double a = s->aval[k];
    r[i] -= a * x[j];
    if (i != j) {
      r[j] -= a * x[i];
    }
  }
  double rr = 0, bb = 0;
  for (int i = 0; i < s->n; i++) {
    rr += r[i] * r[i];
    bb += s->bcopy[i] * s->bcopy[i];
  }
  return isfinite(rr) && rr <= CSF_SOLVE_RTOL * CSF_SOLVE_RTOL * bb;
}


int csf_linSolverSolve(csfLinSolver* s, double* b) {
  if (s->opt.kind == CSF_SOLVER_KLU) {
    return klu_tsolve(s->sym, s->num, s->n, 1, b, &s->common) ? 0 : 1;
  }
  if (s->check_solve) {
    memcpy(s->bcopy, b, (size_t)s->n * sizeof(double));
  }
  s->id.rhs = b;
  s->id.nrhs = 1;
  s->id.lrhs = s->n;
  s->id.job = 3;
  int prev = enterThreads(s->nthreads);
  mumpsCall(s);
  if (s->check_solve && s->id.infog[0] >= 0 && !solveAccurate(s, b)) {
    /* the unpivoted LDL^T of an indefinite matrix lost accuracy (a small pivot): factor again
     * with threshold pivoting and solve once more */
    repivot(s);
    s->check_solve = 0;
    s->factored = s->id.infog[0] >= 0;
    if (s->factored) {
      memcpy(b, s->bcopy, (size_t)s->n * sizeof(double));
      s->id.job = 3;
      mumpsCall(s);
    }
  }
  leaveThreads(prev);
  return s->id.infog[0] >= 0 ? 0 : 1;
}


double csf_linSolverFactorNnz(const csfLinSolver* s) {
  if (s->opt.kind == CSF_SOLVER_KLU) {
    return s->num ? (double)s->num->lnz + (double)s->num->unz : 0.0;
  }
  /* INFOG(29): effective number of entries in the factors (negative: millions) */
  long v = s->id.infog[28];
  return v < 0 ? -1e6 * (double)v : (double)v;
}


double csf_linSolverFlops(const csfLinSolver* s) {
  return s->opt.kind == CSF_SOLVER_KLU ? 0.0 : s->id.rinfog[0];
}


const char* csf_linSolverName(const csfLinSolver* s) {
  if (s->opt.kind == CSF_SOLVER_KLU) {
    return "klu";
  }
  return s->opt.symmetric ? "mumps-ldlt" : "mumps-lu";
}


int csf_linSolverThreads(const csfLinSolver* s) {
  return s->opt.kind == CSF_SOLVER_KLU ? 1 : s->nthreads;
}


int csf_linSolverNegativePivots(const csfLinSolver* s) {
  if (s->opt.kind == CSF_SOLVER_KLU || !s->opt.symmetric || !s->factored) {
    return -1;
  }
  return s->id.infog[11];
}


int csf_linSolverRepivots(const csfLinSolver* s) { return s->n_repivot; }


int csf_linSolverOrdering(const csfLinSolver* s) {
  return s->opt.kind == CSF_SOLVER_KLU ? -1 : s->id.infog[6];
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
    mumpsCall(s);
  }
  free(s->irn);
  free(s->jcn);
  free(s->sel);
  free(s->aval);
  free(s->bcopy);
  free(s->rcheck);
  free(s->wk);
  free(s);
}


/* unit 2-norm over the kept entries (skipped ones set to 0); returns the norm before scaling */
static double normalise(int n, const unsigned char* skip, double* v) {
  double s2 = 0;
  for (int i = 0; i < n; i++) {
    if (skip && skip[i]) {
      v[i] = 0.0;
    }
    s2 += v[i] * v[i];
  }
  const double nv = sqrt(s2);
  if (nv > 0) {
    for (int i = 0; i < n; i++) {
      v[i] /= nv;
    }
  }
  return nv;
}


int csf_linSolverInverseIteration(csfLinSolver* s, const unsigned char* skip, int maxit,
                                  double tol, double* x, double* work, csfEigResult* res) {
  const int n = s->n;
  memset(res, 0, sizeof *res);
  res->lambda = res->residual = res->change = NAN;
  if (!(normalise(n, skip, x) > 0)) {
    return 1;
  }
  for (int k = 0; k < maxit; k++) {
    /* y = K^-1 v_k; v_k+1 = y / |y|; K v_k+1 = v_k / |y| */
    memcpy(work, x, (size_t)n * sizeof(double));
    if (csf_linSolverSolve(s, work) != 0) {
      return 1;
    }
    res->iters++;
    const double ny = normalise(n, skip, work);
    if (!(ny > 0) || !isfinite(ny)) {
      return 1;
    }
    double c = 0;
    for (int i = 0; i < n; i++) {
      c += work[i] * x[i];
    }
    /* Rayleigh quotient and residual |v_k / |y| - lambda v_k+1| (|v_k+1| = 1) */
    res->lambda = c / ny;
    double r2 = 0;
    for (int i = 0; i < n; i++) {
      const double r = x[i] / ny - res->lambda * work[i];
      r2 += r * r;
    }
    res->residual = sqrt(r2);
    res->change = 1.0 - fabs(c);
    memcpy(x, work, (size_t)n * sizeof(double));
    if (res->change <= tol) {
      break;
    }
  }
  /* deterministic sign: the largest entry positive */
  int imax = 0;
  for (int i = 1; i < n; i++) {
    imax = fabs(x[i]) > fabs(x[imax]) ? i : imax;
  }
  if (x[imax] < 0) {
    for (int i = 0; i < n; i++) {
      x[i] = -x[i];
    }
  }
  return 0;
}


int csf_linSolverRanks(const csfLinSolver* s) { return s->nranks; }


void csf_linSolverMemory(const csfLinSolver* s, double* max_rank_mb, double* total_mb) {
  /* INFOG(21), INFOG(22): memory effectively used by the factorisation, MB, the largest on one
   * rank and the sum over the ranks (the workspace given by WK_USER included) */
  const int on = s->opt.kind != CSF_SOLVER_KLU && s->factored;
  *max_rank_mb = on ? (double)s->id.infog[20] : 0.0;
  *total_mb = on ? (double)s->id.infog[21] : 0.0;
}


#ifdef CS_FEM_MPI
/* receive the next order from rank 0 without spinning in MPI_Recv */
static void lazyOrder(Order* o) {
  for (;;) {
    int flag = 0;
    MPI_Iprobe(0, ORDER_TAG, MPI_COMM_WORLD, &flag, MPI_STATUS_IGNORE);
    if (flag) {
      MPI_Recv(o, (int)sizeof *o, MPI_BYTE, 0, ORDER_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return;
    }
    const struct timespec ts = {0, (long)(ORDER_POLL_S * 1e9)};
    nanosleep(&ts, NULL);
  }
}
#endif


csStatus csf_linSolverServe(csError* err) {
#ifdef CS_FEM_MPI
  /* this rank's instances, each a csfLinSolver of its own (MUMPS structure and workspace),
   * keyed by the host's solver */
  long long key[SERVE_MAX];
  csfLinSolver* inst[SERVE_MAX];
  memset(inst, 0, sizeof inst);
  csStatus st = CS_OK;
  for (;;) {
    Order o;
    lazyOrder(&o);
    if (o.job == ORDER_QUIT) {
      break;
    }
    int k = 0;
    const int want_free = o.job == MUMPS_JOB_INIT;
    while (k < SERVE_MAX && !(want_free ? inst[k] == NULL : inst[k] && key[k] == o.key)) {
      k++;
    }
    if (k == SERVE_MAX) {
      /* the host's call cannot be matched: the collective MUMPS call would hang; report it
       * and stop serving (the host then fails in MPI, and mpirun ends the job) */
      st = cs_errorSet(err, CS_ERR_SOLVER, "fem_linsolve: rank cannot serve MUMPS job %d (%s)",
                       o.job, want_free ? "too many solvers" : "unknown solver");
      break;
    }
    if (want_free) {
      inst[k] = calloc(1, sizeof *inst[k]);
      if (!inst[k]) {
        st = cs_errorSet(err, CS_ERR_MEMORY, "fem_linsolve: out of memory");
        break;
      }
      key[k] = o.key;
      inst[k]->id.par = 1;
      inst[k]->id.sym = o.sym;
      inst[k]->id.comm_fortran = MUMPS_USE_COMM_WORLD;
      inst[k]->nranks = 1; /* it orders nobody */
    }
    csfLinSolver* w = inst[k];
#ifdef _OPENMP
    if (o.threads > 0) {
      omp_set_num_threads(o.threads);
    }
#endif
    w->id.job = o.job;
    if (o.job != MUMPS_JOB_INIT) {
      w->id.icntl[13] = o.icntl14;
      w->id.cntl[0] = o.cntl1;
    }
    if (o.job == 2 && growWorkspace(w, workspaceEstimate(w)) != 0) {
      /* without its workspace MUMPS allocates its own: slower, not wrong */
      w->id.wk_user = NULL;
      w->id.lwk_user = 0;
    }
    dmumps_c(&w->id);
    if (o.job == MUMPS_JOB_INIT) {
      w->mumps_on = 1;
      w->id.icntl[0] = -1;
      w->id.icntl[1] = -1;
      w->id.icntl[2] = -1;
      w->id.icntl[3] = 0;
    } else if (o.job == 1 && w->id.infog[0] >= 0) {
      (void)growWorkspace(w, workspaceEstimate(w));
    } else if (o.job == MUMPS_JOB_END) {
      w->mumps_on = 0;
      free(w->wk);
      free(w);
      inst[k] = NULL;
    }
  }
  for (int k = 0; k < SERVE_MAX; k++) {
    if (inst[k]) {
      /* the host never ended it: no collective call left to make */
      free(inst[k]->wk);
      free(inst[k]);
    }
  }
  return st;
#else
  return cs_errorSet(err, CS_ERR_ARG, "fem_linsolve: csf_linSolverServe needs the MPI build");
#endif
}


void csf_linSolverServeStop(void) {
#ifdef CS_FEM_MPI
  int on = 0, size = 1;
  MPI_Initialized(&on);
  if (!on) {
    return;
  }
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const Order o = {0, ORDER_QUIT, 0, 0, 0, 0.0};
  for (int r = 1; r < size; r++) {
    MPI_Send(&o, (int)sizeof o, MPI_BYTE, r, ORDER_TAG, MPI_COMM_WORLD);
  }
#endif
}


int csf_linSolverHaveMpi(void) {
#ifdef CS_FEM_MPI
  return 1;
#else
  return 0;
#endif
}

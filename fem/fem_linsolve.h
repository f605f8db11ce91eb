/* fem_linsolve.h: sparse direct solvers behind the FE Newton iteration (internal to fem/).
 *
 * Owns: csfLinSolver, a factorisation of the tangent K given in scalar CSR (row_ptr, col, val),
 * with the symbolic analysis (fill-reducing ordering, elimination tree) done once per pattern at
 * creation and only a numeric factorisation per Newton iteration. K may be indefinite (past
 * limit points, under volume control); it is symmetric where the model's loads are conservative
 * (csfModel.symmetric, fem_assembly.h) and non-symmetric otherwise (follower pressure on open
 * surfaces).
 * Backends (chosen by measurement, fem/README.md "Sparse solver"):
 *   MUMPS, sequential build (libmumps-seq, CeCILL-C), multifrontal with BLAS-3 fronts
 *     (OpenBLAS), unsymmetric LU (SYM = 0) or symmetric indefinite LDL^T with 2x2 pivots
 *     (SYM = 2: half the entries, half the flops): the default; in the cs_fem_mpi build
 *     (CS_FEM_MPI) the MPI one (libmumps on OpenMPI), on this process or over every rank
 *     (opt.ranks; the other ranks in csf_linSolverServe);
 *   KLU (SuiteSparse, LGPL-2.1+): left-looking, no supernodes; 30-100x slower on 3D Tet10
 *     meshes, kept as a fallback and for the measurement (always unsymmetric). */
#ifndef CS_FEM_LINSOLVE_H
#define CS_FEM_LINSOLVE_H

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum csfSolverKind_ {
  CSF_SOLVER_MUMPS = 0, /* default */
  CSF_SOLVER_KLU = 1,
} csfSolverKind;

/* Options of a solver (docs/style.md 17). */
typedef struct csfLinSolverOptions_ {
  csfSolverKind kind;
  int symmetric; /* 1: K is symmetric, factor LDL^T from its upper triangle (MUMPS only) */
  int ordering;  /* MUMPS ICNTL(7): 7 automatic (default), 5 METIS, 3 SCOTCH, 4 PORD, 2 AMF,
                  * 6 QAMD, 0 AMD; orderings the library was built without fall back to auto */
  int threads;   /* threads of the factorisation and solves (MUMPS OpenMP and threaded BLAS);
                  * 0 = by size: one below CSF_MT_MIN_FLOPS, else max_threads */
  int max_threads; /* the size rule's count above CSF_MT_MIN_FLOPS (0 = the OpenMP default:
                    * every core of the affinity mask); the thread plan (fem_threads.h) */
  int ranks;     /* MPI ranks of the factorisation (MPI build only, csf_linSolverHaveMpi): 1
                  * (default) = this process alone (MPI_COMM_SELF); N > 1 = every rank of
                  * MPI_COMM_WORLD (N its size), this process being rank 0, the host, and the
                  * others serving (csf_linSolverServe) */
  double pivot_threshold; /* MUMPS CNTL(1), the relative threshold of partial pivoting. For
                           * LDL^T, < 0 (default) = checked: no pivoting (0); a factorisation
                           * that meets a zero pivot, or an indefinite one whose solve misses a
                           * relative residual of 1e-8, is redone with MUMPS's 0.01, and so is
                           * the next one (fem_linsolve.c). >= 0: fixed. LU: < 0 keeps MUMPS's
                           * default, >= 0 sets it. */
} csfLinSolverOptions;

/* Factorisations below this many flops (MUMPS' estimate from the analysis) run on one thread
 * by default. Measured on the 2-core machine: the baseline actuator at l_soft 4 (2.2e10 flops,
 * LDL^T) factors 1.3x faster on two threads, while the small meshes of the tests
 * (test_fem_locking, < 1e9 flops) ran 1.3x slower on two threads (thread start-up and waiting
 * dominate small fronts). */
#define CSF_MT_MIN_FLOPS 5e9

/* MUMPS, unsymmetric, automatic ordering, threads by size. */
csfLinSolverOptions csf_linSolverDefault(void);

typedef struct csfLinSolver_ csfLinSolver;

/* Analyse the pattern (n x n, CSR; arrays are referenced, not copied, and must outlive the
 * solver): ordering and symbolic factorisation, once. With opt->symmetric the pattern must be
 * structurally symmetric (it is for FE patterns). Returns NULL and fills err on failure. */
csfLinSolver* csf_linSolverCreate(const csfLinSolverOptions* opt, int n, const int* row_ptr,
                                  const int* col, csError* err);

/* Numeric factorisation of the CSR values `val` (nnz; with a symmetric solver only the upper
 * triangle is read). Returns 0, or non-zero if singular or out of workspace. */
int csf_linSolverFactor(csfLinSolver* s, const double* val);

/* Solve K x = b in place (b on entry, x on exit), with the last factorisation. */
int csf_linSolverSolve(csfLinSolver* s, double* b);

/* Number of nonzeros in the factors of the last factorisation (fill measure; for LDL^T the
 * entries of L and D). */
double csf_linSolverFactorNnz(const csfLinSolver* s);

/* Floating-point operations of one factorisation estimated by the analysis (MUMPS RINFOG(1);
 * 0 for KLU). */
double csf_linSolverFlops(const csfLinSolver* s);

/* Threads of the factorisations and solves (opt.threads, or chosen by size at the analysis). */
int csf_linSolverThreads(const csfLinSolver* s);

/* Backend and mode ("mumps-ldlt", "mumps-lu", "klu"). */
const char* csf_linSolverName(const csfLinSolver* s);

/* Negative pivots of the last LDL^T factorisation (MUMPS INFOG(12) with SYM = 2): by
 * Sylvester's law of inertia the number of negative eigenvalues of K. A stable equilibrium has
 * a positive definite tangent (0); a count that grows along a path marks a critical point
 * (limit or bifurcation) crossed. -1 for LU and KLU (no inertia). */
int csf_linSolverNegativePivots(const csfLinSolver* s);

/* How many unpivoted LDL^T factorisations (pivot_threshold < 0) were redone with threshold
 * pivoting: a zero pivot, or an indefinite matrix whose solve missed its residual check. 0 for
 * LU and KLU. */
int csf_linSolverRepivots(const csfLinSolver* s);

/* Result of csf_linSolverInverseIteration. */
typedef struct csfEigResult_ {
  double lambda;   /* Rayleigh quotient v . K v of the last iterate (|v| = 1), units of K */
  double residual; /* |K v - lambda v| of the last iterate, units of K (0 for an eigenpair) */
  double change;   /* 1 - |v_k . v_k-1| of the last step (0 when the direction stopped moving) */
  int iters;       /* solves done */
} csfEigResult;

/* Inverse iteration with the last factorisation: the eigenvector of K whose eigenvalue has the
 * smallest modulus (near a critical point of a path, the mode that turns K singular). Iterates
 * v_k+1 = K^-1 v_k / |K^-1 v_k| until 1 - |v_k+1 . v_k| <= tol or maxit solves; converges at
 * the rate |lambda_1 / lambda_2| per solve. No product with K is needed: K v_k+1 = v_k / |y|
 * (y = K^-1 v_k), so lambda = v_k+1 . v_k / |y| and the residual follow from the last two
 * iterates. skip (n, may be NULL): entries held at 0, for Dirichlet dofs whose identity rows
 * and columns decouple them from the rest (their eigenvalue 1 is excluded). x (n): the start
 * vector on entry (not zero on the kept entries), the unit eigenvector on exit, signed so that
 * its largest entry is positive; work (n) scratch. Returns 0, or non-zero when a solve fails
 * or an iterate vanishes. */
int csf_linSolverInverseIteration(csfLinSolver* s, const unsigned char* skip, int maxit,
                                  double tol, double* x, double* work, csfEigResult* res);

/* Ordering actually used (MUMPS INFOG(7); -1 for KLU). */
int csf_linSolverOrdering(const csfLinSolver* s);

void csf_linSolverDestroy(csfLinSolver* s);

/* MPI ranks taking part in the factorisations (1: this process alone). */
int csf_linSolverRanks(const csfLinSolver* s);

/* Memory the last factorisation used, MB (MUMPS INFOG(21), INFOG(22)): the most on one rank and
 * the sum over the ranks; 0 for KLU or before a factorisation. */
void csf_linSolverMemory(const csfLinSolver* s, double* max_rank_mb, double* total_mb);

/* 1 in the MPI build (cs_fem_mpi: MUMPS on OpenMPI), 0 in the sequential one. */
int csf_linSolverHaveMpi(void);

/* The other ranks' side of a distributed FE (MPI build): called on every rank but 0 of
 * MPI_COMM_WORLD, it makes the MUMPS calls rank 0's solvers order (creation, analysis,
 * factorisations, solves, destruction; the host's matrix and right-hand side stay on the host)
 * until rank 0 calls csf_linSolverServeStop. Waits between calls sleep (no spinning core).
 * Returns CS_OK, or an error for an order it cannot match (or the sequential build). */
csStatus csf_linSolverServe(csError* err);

/* Rank 0: end every other rank's csf_linSolverServe (MPI build; nothing otherwise). Call it
 * once, after the last solver of rank 0 was destroyed. */
void csf_linSolverServeStop(void);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_LINSOLVE_H */

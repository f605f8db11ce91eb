/* fem_linsolve.h: sparse direct solvers behind the FE Newton iteration (internal to fem/).
 *
 * Owns: csfLinSolver, a factorisation of the tangent K given in scalar CSR (row_ptr, col, val),
 * with the symbolic analysis (fill-reducing ordering) done once per pattern and a numeric
 * factorisation per Newton iteration. K may be non-symmetric (follower pressure) and indefinite.
 * Backends (chosen by measurement, fem/README.md "Sparse solver"):
 *   MUMPS, sequential build (libmumps-seq, CeCILL-C), multifrontal with METIS/AMD ordering and
 *     BLAS-3 fronts (OpenBLAS, both cores): the default;
 *   KLU (SuiteSparse, LGPL-2.1+): left-looking, no supernodes; 30-100x slower on 3D Tet10
 *     meshes, kept as a fallback and for the measurement. */
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

typedef struct csfLinSolver_ csfLinSolver;

/* Analyse the pattern (n x n, CSR; arrays are referenced, not copied, and must outlive the
 * solver). Returns NULL and fills err on failure. */
csfLinSolver* csf_linSolverCreate(csfSolverKind kind, int n, const int* row_ptr, const int* col,
                                  csError* err);

/* Numeric factorisation of the CSR values `val` (nnz). Returns 0, or non-zero if singular. */
int csf_linSolverFactor(csfLinSolver* s, const double* val);

/* Solve K x = b in place (b on entry, x on exit), with the last factorisation. */
int csf_linSolverSolve(csfLinSolver* s, double* b);

/* Number of nonzeros in the factors of the last factorisation (fill measure). */
double csf_linSolverFactorNnz(const csfLinSolver* s);

/* Backend name ("mumps", "klu"). */
const char* csf_linSolverName(const csfLinSolver* s);

void csf_linSolverDestroy(csfLinSolver* s);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_LINSOLVE_H */

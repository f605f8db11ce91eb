/* fem_krylov.h: restarted GMRES with right preconditioning (internal to fem/).
 *
 * Owns: csf_gmres, a matrix-free GMRES(m) (Saad and Schultz 1986; Saad, "Iterative Methods for
 * Sparse Linear Systems", 2nd ed., Alg. 9.5) whose operator and preconditioner are callbacks,
 * and its caller-owned workspace. Right preconditioning (solve A M^-1 y = b, x = M^-1 y) keeps
 * the monitored residual the true residual b - A x, which is what Newton's forcing term
 * bounds. Used by fem_newton.c with the last sparse factorisation of the tangent as M.
 * Arrays are length n unless stated; nothing is allocated. */
#ifndef CS_FEM_KRYLOV_H
#define CS_FEM_KRYLOV_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* y = op(x); x and y do not alias. Returns 0, non-zero on failure (GMRES stops). */
typedef int (*csfLinOp)(void* ctx, const double* x, double* y);

/* largest restart length (the Hessenberg solve keeps its coefficients on the stack) */
#define CSF_GMRES_MAX_RESTART 200

/* Workspace of GMRES(restart) for n unknowns: doubles needed (csf_gmresWorkSize). */
size_t csf_gmresWorkSize(int n, int restart);

/* Solve A x = b to ||b - A x|| <= rtol ||b||, starting from x (in: initial guess, out: solution),
 * with at most `maxit` iterations in cycles of `restart`. `work` holds csf_gmresWorkSize doubles.
 * Returns 0 when converged, 1 when not converged within maxit (x is the best iterate), -1 when an
 * operator failed. *its: iterations done; *relres: final ||b - A x|| / ||b||. */
int csf_gmres(int n, int restart, int maxit, double rtol, csfLinOp A, csfLinOp Minv, void* ctx,
              const double* b, double* x, double* work, int* its, double* relres);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_KRYLOV_H */

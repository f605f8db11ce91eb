/* fem_newton.h: Newton's method, load stepping and volume control for the FE model (solver
 * layer).
 *
 * Owns: csfNewtonOptions, csf_newtonSolve (pressure / load control with line search),
 * csf_newtonSolveVolume (chamber-volume control, the bordered system that passes pressure limit
 * points), csf_loadRamp (adaptive load stepping), and the linearised updates of the mixed
 * element dilatations and fibre stress states between iterations. Each solve either converges or
 * restores the state it started from (a failed solve changes nothing).
 * Linear solves: a sparse direct factorisation of the tangent (fem_linsolve.h) per iteration,
 * or, with csfNewtonOptions.krylov, GMRES preconditioned by the last factorisation, refactoring
 * only when GMRES stalls (fem_newton.c, "Rationale"). Units: mm, MPa, N. */
#ifndef CS_FEM_NEWTON_H
#define CS_FEM_NEWTON_H

#include "core_status.h"
#include "fem_assembly.h"
#include "fem_model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Line search of csf_newtonSolve. */
typedef enum csfLineSearch_ {
  CSF_LS_RESIDUAL = 0, /* backtracking on ||R|| (halving while ||R|| grows, see fem_newton.c) */
  CSF_LS_ENERGY = 1,   /* root of the energy slope g(s) = R(u + s du) . du on the free dofs
                        * (conservative loads: closed chambers), Illinois regula falsi */
} csfLineSearch;

/* One Newton iteration, reported to csfNewtonOptions.monitor. */
typedef struct csfNewtonIter_ {
  double load;      /* load factor */
  int iter;         /* 1-based iteration */
  double alpha;     /* accepted step length */
  int n_eval;       /* residual evaluations in the line search */
  double g0, g1;    /* energy slope R.du at s = 0 and at the accepted s, N mm */
  double rnorm;     /* ||R|| after the step, N */
  double fnorm;     /* force scale, N */
  int fib_switch;   /* fibres whose law zone (slack / smoothing / taut) changed in this step */
  int fib_smooth;   /* fibres inside the smoothing zone |E| < delta after the step */
  int fib_taut;     /* fibres with E >= delta after the step */
  int neg_pivots;   /* negative pivots of the last factorisation (LDL^T; with krylov it may be
                     * an earlier iterate's tangent); -1 with LU */
  double jmin;      /* smallest pointwise J = det F at the quadrature points after the step */
  double rmax;      /* largest nodal residual |R_a| (3-vector) on a free node after the step, N */
  int rmax_node;    /* that node (0-based) */
  double rmax_X[3]; /* its reference position, mm (where a stall sits in the actuator) */
  double jmin_X[3]; /* reference centroid of the element with the smallest J, mm */
} csfNewtonIter;

/* Newton options (docs/style.md 17). */
typedef struct csfNewtonOptions_ {
  int max_iter;   /* Newton iterations per load level */
  double rtol;    /* ||R|| <= rtol * fnorm (dimensionless) */
  double atol;    /* ... or ||R|| <= atol, N */
  int max_ls;     /* line-search halvings / regula falsi evaluations */
  csfLineSearch line_search; /* default CSF_LS_RESIDUAL */
  double ls_eta;  /* energy line search: accept s when |g(s)| <= ls_eta |g(0)| (dimensionless) */
  int threads;    /* OpenMP threads for assembly, 0 = library default */
  int krylov;     /* 1: a Newton step's linear system K du = -R is solved by GMRES preconditioned
                   * with the last factorisation (of an earlier iterate's or load step's tangent);
                   * the tangent is factored afresh only when GMRES needs more than krylov_maxit
                   * iterations (then at once) or more than half of them (then at the next
                   * step). 0: factor every iteration (a plain Newton method) */
  int krylov_maxit;   /* GMRES iterations before a solve falls back to a new factorisation */
  double krylov_eta;  /* largest forcing term: ||K du + R|| <= eta ||R|| (dimensionless) */
  void (*monitor)(void* user, const csfNewtonIter* it); /* optional, per iteration */
  void* monitor_user;
  double shift;   /* N/mm, csf_newtonSolveVolume only: iterate with K - shift I (free dofs) in
                   * place of K; the residual, hence the converged state, is unchanged. 0
                   * (default): Newton. Below the most negative eigenvalue of an indefinite K
                   * the iteration matrix is definite, and the iteration descends the energy
                   * (under the volume constraint) to a stable state instead of converging to the
                   * nearest, unstable one; convergence is then linear (fem_path.c uses it to
                   * leave a bifurcation) */
} csfNewtonOptions;

csfNewtonOptions csf_newtonDefault(void);

/* Solve R(u, load) = 0 by Newton's method with backtracking line search, starting from d->u
 * (Dirichlet dofs move to load * u_fix within the first Newton step, through the linearised lift). On failure d->u is restored and
 * CS_ERR_DIVERGED is returned (recoverable: the caller cuts the load step); `iters` (may be
 * NULL) receives the number of iterations. */
csStatus csf_newtonSolve(const csfModel* m, csfData* d, double load, const csfNewtonOptions* opt,
                         int* iters, csError* err);

/* Volume control (passes pressure limit points): solve R(u, load) = 0 together with
 * d->vol_w(u) = vol_target, the load factor being an unknown (bordered Newton: two solves with
 * one factorisation per iteration, Crisfield 1991 Sec. 9.4 with the chamber volume as the
 * constraint). Starts from d->u and d->load; on success d->load holds the load factor. Converged
 * when ||R|| <= rtol fnorm (or atol) and |vol_w - vol_target| <= rtol |vol_target|. On failure the
 * state is restored and CS_ERR_DIVERGED returned. */
csStatus csf_newtonSolveVolume(const csfModel* m, csfData* d, double vol_target,
                               const csfNewtonOptions* opt, int* iters, csError* err);

/* Adaptive ramp of the load factor from d->load to load_end, starting with nstep equal steps;
 * a step that fails is halved (down to 1e-4 of the range), easy steps (<= 5 iterations) grow
 * by 1.5. `iters` (may be NULL) receives the total Newton iterations. */
csStatus csf_loadRamp(const csfModel* m, csfData* d, double load_end, int nstep,
                      const csfNewtonOptions* opt, int* iters, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_NEWTON_H */

/* fem_path.h: following an equilibrium path past a pressure limit point or a bifurcation.
 *
 * Owns: csf_passLimit, the volume-controlled continuation used by the pressure sweeps (csf_bend)
 * when pressure control meets a limit point, and its options and result; csf_pathCriticalMode,
 * the critical mode of a converged state (inverse iteration on its tangent), and the branch
 * switching at a bifurcation that csf_passLimit does with it. The states it moves
 * between are csf_stateGet/csf_stateSet vectors (fem_model.h); the caller owns them.
 * Units: MPa (the load factor is the chamber pressure), mm^3, seconds. */
#ifndef CS_FEM_PATH_H
#define CS_FEM_PATH_H

#include "core_status.h"
#include "fem_newton.h"

#ifdef __cplusplus
extern "C" {
#endif

struct csfLimitResult_;

/* One converged state of the volume-controlled path, reported to csfLimitOptions.callback. */
typedef struct csfPathPoint_ {
  double p;         /* pressure (load factor) of the state, MPa */
  double dp;        /* change from the previous state, MPa (negative past the limit) */
  double volume;    /* prescribed weighted chamber volume (csfData.vol_w), mm^3 */
  int newton_iters; /* iterations of this step */
  double wall;      /* wall time of the step including failed attempts, s */
  int is_max;       /* 1: the largest pressure so far (the limit point, until the path falls) */
  int past_limit;   /* 1: the pressure has fallen below the maximum */
  int neg_pivots;   /* negative pivots of the state's last tangent factorisation (-1: LU) */
  int branch;       /* 0: the path as it came; 1: on a branch switched to at a bifurcation;
                     * 2: the first state of that branch (csfLimitResult.mode describes it) */
  const struct csfLimitResult_* result; /* the path's result so far (bifurcation, mode) */
} csfPathPoint;

/* The critical mode of a converged state: the eigenvector of its tangent K (free dofs) whose
 * eigenvalue has the smallest modulus (csf_pathCriticalMode). */
typedef struct csfCriticalMode_ {
  double lambda;   /* its eigenvalue (Rayleigh quotient), N/mm: < 0 past a critical point */
  double residual; /* |K phi - lambda phi| (|phi| = 1), N/mm: convergence of the iteration */
  double change;   /* 1 - |cos| between the last two iterates */
  int iters;       /* solves of the inverse iteration */
  int neg_pivots;  /* negative pivots of the tangent factored at the state */
  double sigma;    /* shift of the inverse iteration (on K - sigma I), N/mm: 0 on a definite
                    * tangent, else just below the negative eigenvalue nearest zero */
  int n_shift;     /* factorisations of shifted tangents spent finding sigma */
  double b_cos;    /* cos of the angle between phi and b = dVw/du, the volume (pressure load)
                    * direction: 0 for a mode that breaks a symmetry the path keeps */
  int node_max;    /* node of the largest nodal component |phi_a| */
  double X_max[3]; /* its reference position, mm */
  double phi_max;  /* that largest nodal component of the unit vector phi */
} csfCriticalMode;

/* Called at each converged state (d holds it); return nonzero to stop following the path there. */
typedef int (*csfPathCallback)(void* user, const csfModel* m, const csfData* d,
                               const csfPathPoint* pt);

typedef struct csfLimitOptions_ {
  int max_steps;        /* converged volume steps before giving up (default 200) */
  double max_vol_ratio; /* give up when the volume exceeds this multiple of the start (20) */
  double min_dv_rel;    /* the step has collapsed below this fraction of the first (1e-4) */
  csfPathCallback callback; /* optional */
  void* user;
  /* branch switching: at the first converged state whose tangent has more negative pivots than
   * the state before while the pressure still rises (a bifurcation: past a limit point the
   * pressure falls), the path leaves the branch it followed along the critical mode phi
   * (csf_pathCriticalMode): the state is perturbed by branch_amp phi / max_a |phi_a| and solved
   * at the next volume (then at the same volume), both signs; the new branch is accepted when
   * Newton converges to a state with fewer negative pivots or whose component along phi stays
   * at least half the perturbation (it departed from the old path) */
  int critical_mode;    /* 1: at a bifurcation compute its critical mode (csfLimitResult.mode)
                         * even when no switch is tried (default 0) */
  int branch_switch;    /* 1: switch branches at a bifurcation (default 0; implies the mode).
                         * Measured on the thin-walled actuator (b = 3, r1 = 2.5, l_soft 4):
                         * no branch found, fem/README.md "Branch switching" */
  double branch_amp;    /* mm, largest nodal displacement of the perturbation (default 0.05) */
  int neg_prev, neg_conv; /* negative pivots of the entry states s_prev, s_conv (-1: unknown):
                           * a bifurcation crossed between them is switched at the entry */
} csfLimitOptions;

csfLimitOptions csf_limitDefault(void);

typedef struct csfLimitResult_ {
  double p_limit;   /* largest pressure on the path (the limit point), MPa */
  double V_limit;   /* volume there, mm^3 */
  double p_resume;  /* first pressure above p_limit after the path fell and rose again, MPa;
                     * NAN when not reached (balloons without bound, or stopped) */
  double p_before;  /* pressure of the state before the end state (left in s_prev), MPa */
  int n_steps;      /* converged volume steps */
  long n_newton;    /* Newton iterations, failed attempts included */
  int stopped;      /* 1: the callback stopped the path */
  int no_limit;     /* 1: the pressure kept rising under volume control (the pressure-controlled
                     * step had failed for another reason); p_resume set, p_limit meaningless */
  int fell;         /* 1: the pressure fell below p_limit on the path: a limit point shown
                     * (0 with an error: the path ended before the pressure fell) */
  int n_bifurcation; /* bifurcations met (more negative pivots with the pressure rising) */
  int switched;      /* 1: a branch was switched at the bifurcation (mode, below) */
  double p_bif, V_bif; /* pressure (MPa) and volume (mm^3) of the first state past it */
  csfCriticalMode mode; /* the critical mode there */
  int branch_sign;   /* sign of the accepted perturbation (+1 / -1), 0: none accepted */
  double branch_xi;  /* component along phi / max_a |phi_a| of the first branch state
                      * relative to the bifurcating one, mm */
  int branch_neg;    /* negative pivots of the first branch state */
  int branch_tries;  /* perturbed solves tried (failed and accepted) */
  char branch_note[480]; /* why no branch was accepted ("" when none was tried or one was) */
} csfLimitResult;

/* Follow the path past a limit point of pressure control by prescribing the weighted chamber
 * volume (csf_newtonSolveVolume; the pressure is an unknown), starting from two converged states
 * of the pressure-controlled path: s_prev (volume V_prev) and s_conv (volume V_conv, pressure
 * p_conv; csf_stateSize doubles each; s_tmp is scratch). Volume steps start at V_conv - V_prev
 * and adapt like load steps (halved on failure, x1.5 after <= 5 iterations, at most 8x the first;
 * secant predictor on the whole state). The path passes the pressure maximum p_limit, falls and,
 * where the material stiffens (Yeoh C20 > 0), rises again: at the first state above p_limit it
 * is stable under pressure control again (a pressure-controlled load snaps to it from the limit
 * state) and the function returns CS_OK with p_resume set. CS_OK with stopped = 1 when the
 * callback stopped it; CS_ERR_DIVERGED (and a message) when no stable branch was found within
 * max_steps / max_vol_ratio or the step collapsed. On return d and s_conv hold the last
 * converged state, s_prev the one before it (pressure p_before). */
csStatus csf_passLimit(const csfModel* m, csfData* d, double* s_prev, double* s_conv,
                       double* s_tmp, double V_prev, double V_conv, double p_conv,
                       const csfNewtonOptions* nopt, const csfLimitOptions* opt,
                       csfLimitResult* res, csError* err);

/* The critical mode of the state in d (its load factor d->load): assembles and factors the
 * tangent there (LDL^T: its negative pivots), then inverse iteration (csf_linSolverInverse-
 * Iteration) on the free dofs from a deterministic start vector, up to maxit solves: on a
 * definite tangent for the eigenvalue of smallest modulus; with negative pivots for the
 * negative eigenvalue nearest zero (the one that crossed last), on K - sigma I with sigma
 * placed just below it by the inertia of shifted factorisations (fem_path.c). d->ls is left
 * with a shifted factorisation (d->have_factor = 0). phi (ndof)
 * receives the unit eigenvector (0 on Dirichlet dofs), work (ndof) is scratch. d's state is
 * unchanged (its residual and tangent are those of the state). CS_ERR_DIVERGED when the state
 * is not assemblable or the tangent singular. */
csStatus csf_pathCriticalMode(const csfModel* m, csfData* d, int maxit, double* phi,
                              double* work, csfCriticalMode* cm, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_PATH_H */

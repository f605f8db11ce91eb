/* fem_path.h: following an equilibrium path past a pressure limit point.
 *
 * Owns: csf_passLimit, the volume-controlled continuation used by the pressure sweeps (csf_bend)
 * when pressure control meets a limit point, and its options and result. The states it moves
 * between are csf_stateGet/csf_stateSet vectors (fem_model.h); the caller owns them.
 * Units: MPa (the load factor is the chamber pressure), mm^3, seconds. */
#ifndef CS_FEM_PATH_H
#define CS_FEM_PATH_H

#include "core_status.h"
#include "fem_newton.h"

#ifdef __cplusplus
extern "C" {
#endif

/* One converged state of the volume-controlled path, reported to csfLimitOptions.callback. */
typedef struct csfPathPoint_ {
  double p;         /* pressure (load factor) of the state, MPa */
  double dp;        /* change from the previous state, MPa (negative past the limit) */
  double volume;    /* prescribed weighted chamber volume (csfData.vol_w), mm^3 */
  int newton_iters; /* iterations of this step */
  double wall;      /* wall time of the step including failed attempts, s */
  int is_max;       /* 1: the largest pressure so far (the limit point, until the path falls) */
  int past_limit;   /* 1: the pressure has fallen below the maximum */
} csfPathPoint;

/* Called at each converged state (d holds it); return nonzero to stop following the path there. */
typedef int (*csfPathCallback)(void* user, const csfModel* m, const csfData* d,
                               const csfPathPoint* pt);

typedef struct csfLimitOptions_ {
  int max_steps;        /* converged volume steps before giving up (default 200) */
  double max_vol_ratio; /* give up when the volume exceeds this multiple of the start (20) */
  double min_dv_rel;    /* the step has collapsed below this fraction of the first (1e-4) */
  csfPathCallback callback; /* optional */
  void* user;
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

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_PATH_H */

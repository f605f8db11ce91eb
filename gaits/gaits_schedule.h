/* gaits_schedule.h: the pressure schedule p(t) of the 96 chambers, from a gait table.
 *
 * Owns: csgScheduleOptions (ramp length and shape, pressure scale) and the evaluation of
 * p(t) and dp/dt, without allocation (safe inside the step loop).
 *
 * The schedule, for rows i = 0..n-1 with times t_i and pressures P_i (MPa, gaits_csv.h), and
 * P_{-1} = 0 (the robot starts vented):
 *   p(t) = 0                                                for t < t_0
 *   p(t) = K [P_{i-1} + (P_i - P_{i-1}) S((t - t_i) / r_i)]  for t_i <= t < t_{i+1}
 * with t_n = +inf (the last row holds forever: a gait that should end vented ends with a row
 * of zeros), K = pressure_scale, S the ramp shape (S(u) = 0 for u <= 0, 1 for u >= 1), and
 * ramp length r_i = min(ramp, t_{i+1} - t_i) (r_{n-1} = ramp). So row i's values hold on
 * [t_i + r_i, t_{i+1}) and the change from the previous row happens on [t_i, t_i + r_i], i.e.
 * it starts at the row's time (the valves switch at t_i) rather than being centred on it.
 * Clamping r_i to the row spacing makes every ramp end no later than the next row's time, so
 * each ramp starts from the exact previous plateau and p(t) stays continuous (and, with a
 * smooth shape, C1) however dense the rows are. At t_0 the first row is ramped up from 0.
 * ramp = 0 gives the bare piecewise-constant table (p jumps at t_i; p(t_i) = K P_i).
 *
 * Why ramps: a step in pressure is an impulsive load that the stiff leg models would have to
 * resolve with tiny steps, and real valves and tubing need time to fill a chamber. Default
 * 0.2 s: short against the paper's 1 s gait phases (the plateau keeps 80 % of each phase),
 * long enough for the step control of the implicit leg integrators to pass smoothly.
 * Default shape: smoothstep 3u^2 - 2u^3 (C1: zero slope at both ends, no kink in the load);
 * quintic 10u^3 - 15u^4 + 6u^5 (C2) when a continuous pressure rate of change matters. */
#ifndef CS_GAITS_SCHEDULE_H
#define CS_GAITS_SCHEDULE_H

#include "core_status.h"
#include "gaits_csv.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Default ramp length (s); see the rationale above. */
#define CSG_DEFAULT_RAMP 0.2

/* Ramp shape S(u) on u in [0, 1]. */
typedef enum csgRampShape_ {
  CSG_RAMP_SMOOTHSTEP = 0, /* 3u^2 - 2u^3: C1 (default) */
  CSG_RAMP_QUINTIC = 1,    /* 10u^3 - 15u^4 + 6u^5: C2 */
  CSG_RAMP_LINEAR = 2      /* u: C0, kinks at both ends (for comparison and tests) */
} csgRampShape;

/* How a gait table becomes p(t). */
typedef struct csgScheduleOptions_ {
  double ramp;           /* s: length of the change at each row time (>= 0; 0 = steps) */
  csgRampShape shape;    /* shape of the change */
  double pressure_scale; /* dimensionless factor on every pressure (>= 0; --pressure-scale) */
} csgScheduleOptions;

/* ramp = CSG_DEFAULT_RAMP, smoothstep, pressure_scale = 1. */
csgScheduleOptions csg_defaultScheduleOptions(void);

/* Check options once, with a message (CS_ERR_ARG: ramp or scale negative or not finite,
 * unknown shape). The evaluators return CS_ERR_ARG for the same cases, without a message. */
csStatus csg_scheduleCheckOptions(const csgScheduleOptions* opt, csError* err);

/* p(t) (MPa) of all chambers at time t (s): p_out[label - 1], shape (96). opt NULL = defaults.
 * g must be a valid table (csg_gaitValidate). No allocation; O(log nrow). Returns CS_OK, or
 * CS_ERR_ARG (p_out untouched) for NULL or empty g, bad options or a non-finite t. */
csStatus csg_scheduleEval(const csgGait* g, const csgScheduleOptions* opt, double t,
                          double p_out[CSG_NLABEL]);

/* dp/dt (MPa/s) of all chambers at time t (s), shape (96), same conventions as
 * csg_scheduleEval. At a jump (ramp = 0, or a linear ramp's ends) it returns the one-sided
 * rate from the right. */
csStatus csg_scheduleEvalRate(const csgGait* g, const csgScheduleOptions* opt, double t,
                              double dpdt_out[CSG_NLABEL]);

#ifdef __cplusplus
}
#endif
#endif /* CS_GAITS_SCHEDULE_H */

/* gaits_schedule.h: the pressure schedule p(t) of the 96 chambers, from a gait table.
 *
 * Owns: csgScheduleOptions (ramp length and shape, pressure scale) and the evaluation of
 * p(t) and dp/dt, without allocation (safe inside the step loop).
 *
 * The schedule, for rows i = 0..n-1 with times t_i and pressures P_i (MPa, gaits_csv.h), and
 * P_{-1} = 0 (the robot starts vented), is the table's step command passed through the ramp:
 *   p(t) = K sum_{i: t_i <= t} (P_i - P_{i-1}) S((t - t_i) / r_i)
 * with K = pressure_scale and S the ramp shape (S(u) = 0 for u <= 0, 1 for u >= 1). Each
 * row's change starts at the row's time (the valves switch at t_i) and takes the ramp length
 * r_i = ramp to arrive, whatever the rows after it do: a chamber takes `ramp` to reach a new
 * command. So p(t) = 0 before t_0, the last row holds for ever (a gait that should end vented
 * ends with a row of zeros), and ramp = 0 gives the bare piecewise-constant table (p jumps at
 * t_i; p(t_i) = K P_i).
 * - Where a ramp fits its row spacing (t_{i+1} - t_i >= ramp) the change has finished by the
 *   next row: p(t) = K [P_{i-1} + (P_i - P_{i-1}) S((t - t_i) / r_i)] on [t_i, t_{i+1}), row
 *   i's values hold on [t_i + r_i, t_{i+1}), and the next change starts from that exact
 *   plateau. (Computed as a blend, so the plateaus are exact.)
 * - Where rows come faster than the ramp, the changes overlap and add: p is a weighted mean
 *   of the last `ramp` seconds of commands (weights S'(u)/r >= 0, summing to 1), so it never
 *   leaves the range of the commands it follows, it is as smooth as S (C1 for smoothstep),
 *   and a row that repeats its predecessor adds nothing (the schedule depends on the command,
 *   not on how densely it is tabulated). A gait sampled every 0.05 s (the designer's tables)
 *   played with ramp 0.5 is its motion smeared and delayed by about 0.25 s.
 *   (Until 2026-12-06 a ramp longer than the row spacing was cut to the spacing, so such a
 *   table ignored --ramp; the two agree wherever the ramp fits.)
 * - A ramp within CSG_RAMP_ROUNDING of its row spacing (either way) is taken as the spacing:
 *   the difference is rounding of the row times (0.05 s rows differ by 0.04999999999999716 or
 *   0.05000000000000071 after subtraction), and the change fills the interval to the next row
 *   exactly, as a ramp cut to the spacing did. A table sampled every S s played with ramp S
 *   (its `# @ramp S`, gaits_csv.h) is therefore its samples joined by the shape S(u).
 * Cost: O(log nrow) to find the row plus the rows within one ramp length before t.
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

/* Default ramp length (s); see the rationale above. A gait table may state its own
 * (gaits_csv.h: `# @ramp S`); the run uses it where --ramp is not given. */
#define CSG_DEFAULT_RAMP 0.2

/* Overrun (s) of a ramp past the next row's time that counts as rounding of the row times
 * (see above): far below any step or row spacing in use (>= 1e-4 s), far above the 1e-15 s
 * that subtracting two row times near 30 s can lose. */
#define CSG_RAMP_ROUNDING 1e-9

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

/* p(t) (MPa) of all chambers at time t (s): p_out[label - 1], shape (96). opt NULL = defaults
 * with the table's stated ramp (`# @ramp`, gaits_csv.h) where it states one.
 * g must be a valid table (csg_gaitValidate). No allocation; O(log nrow + the rows within one
 * ramp before t). Returns CS_OK, or
 * CS_ERR_ARG (p_out untouched) for NULL or empty g, bad options or a non-finite t. */
csStatus csg_scheduleEval(const csgGait* g, const csgScheduleOptions* opt, double t,
                          double p_out[CSG_NLABEL]);

/* p(t) with held rows (the landing gate, gaits_gate.h, core/sim_gate.c): the sum above with
 * row i's change starting at t_i + off_i instead of t_i,
 *   p(t) = K sum_{i: t_i <= t_issued, t_i + off_i <= t} (P_i - P_{i-1}) S((t - t_i - off_i) / r_i)
 * so a gate that held the table's clock for a while delays every row issued after it by that
 * while, and the changes already issued arrive as they would have (the chambers fill on).
 * off_i = off[s], s the number of breaks[] (table times, ascending) below t_i (a row at a
 * break's time belongs before it); off has nbreak + 1 values, not decreasing. Rows with
 * t_i > t_issued are not issued yet (a gate holds them; +inf: every row). Ramp lengths and
 * fits as above, on the shifted times. With every off 0 and t_issued +inf this is
 * csg_scheduleEval's value up to rounding (a caller that needs that run bit for bit calls
 * csg_scheduleEval). No allocation. Returns CS_OK, or CS_ERR_ARG as csg_scheduleEval (also
 * for nbreak < 0 or NULL off). */
csStatus csg_scheduleEvalHeld(const csgGait* g, const csgScheduleOptions* opt, double t,
                              int nbreak, const double* breaks, const double* off,
                              double t_issued, double p_out[CSG_NLABEL]);

/* dp/dt (MPa/s) of all chambers at time t (s), shape (96), same conventions as
 * csg_scheduleEval. At a jump (ramp = 0, or a linear ramp's ends) it returns the one-sided
 * rate from the right. */
csStatus csg_scheduleEvalRate(const csgGait* g, const csgScheduleOptions* opt, double t,
                              double dpdt_out[CSG_NLABEL]);

#ifdef __cplusplus
}
#endif
#endif /* CS_GAITS_SCHEDULE_H */

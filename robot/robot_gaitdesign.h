/* robot_gaitdesign.h: derive gait pressures from the calibrated leg model.
 *
 * Owns: the inverse problems a gait designer needs ("which pressure gives this foot stroke?"),
 * solved on the calibration map and the constant-curvature forward kinematics, so that a gait's
 * pressures follow from our model rather than from the paper's printed values (REFERENCE.md,
 * "Gait tables": the leg motion is the target, not the pressure).
 *
 * Flat-road leg motions (leg frame: e1 = crawl direction, e3 down the leg):
 *  - stroke ("S-shape"): II1 chambers Ω3&Ω4 and II2 chambers Ω1&Ω2 at one pressure p_S; II1
 *    bends towards +e1 and II2 back, so the foot stays vertical and moves +e1 by the stroke,
 *    and the leg gets shorter (it lifts);
 *  - crouch ("Z-shape"): II1 Ω3&Ω4 and II3 Ω3&Ω4 at p_S, II2 Ω1&Ω2 at the pressure p_Z that
 *    bends II2 twice as far; the foot returns under the hip (zero e1 offset) while the leg
 *    is shorter than in the S-shape. */
#ifndef CS_ROBOT_GAITDESIGN_H
#define CS_ROBOT_GAITDESIGN_H

#include "core_status.h"
#include "robot_actuator.h"
#include "robot_leg.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct csrFlatRoadDesign_ {
  double p_stroke;      /* MPa: S-shape pressure giving the requested stroke */
  double p_crouch_II2;  /* MPa: II2 pressure of the crouch (twice the S-shape bend) */
  double stroke;        /* mm: foot offset along e1 reached in the S-shape */
  double lift_stroke;   /* mm: how much shorter (along e3) the S-shaped leg is than straight */
  double lift_crouch;   /* mm: same for the crouch */
  double crouch_offset; /* mm: residual foot offset along e1 in the crouch */
  double theta_stroke_deg; /* per-segment bend of the S-shape (deg) */
} csrFlatRoadDesign;

/* Foot position (leg frame, mm) for the segment bends produced by pressures p[12] (segment-major: p[4 s + j]). */
csStatus csr_footFromPressures(const csrActuator* act, const csrBendMap* map,
                               const double p[CSR_NSEG * CSR_NCHAMBER], double foot[3],
                               csError* err);

/* Solve for the flat-road pressures giving `stroke` mm of foot travel, searching p in
 * (0, p_max]. CS_ERR_RANGE if the stroke is not reachable below p_max. */
csStatus csr_designFlatRoad(const csrActuator* act, const csrBendMap* map, double stroke,
                            double p_max, csrFlatRoadDesign* out, csError* err);

#ifdef __cplusplus
}
#endif
#endif

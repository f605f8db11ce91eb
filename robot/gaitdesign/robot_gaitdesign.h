/* robot_gaitdesign.h: derive gait pressures from the calibrated leg model.
 *
 * Owns: the inverse problems a gait designer needs ("which pressure gives this foot stroke?"),
 * solved on the calibration map and the constant-curvature forward kinematics, so that a gait's
 * pressures follow from our model rather than from the paper's printed values (docs/reference.md,
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
#include "gaits_csv.h"
#include "gaits_design.h"
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

/* ---- gait design descriptions (gaits_design.h) -> gait tables ------------------------------
 * Each pose's chamber sets are solved in file order: a set's common pressure is found by
 * bisection on [0, p_max] so that its target (stroke, side, lift, rise, bend) holds on the
 * calibrated map's constant-curvature forward kinematics, given the pose's earlier sets; the
 * targets are monotone in the pressure of the set that drives them (checked: the target must
 * lie between its values at 0 and p_max, else CS_ERR_RANGE names the line).
 * A move between two foot poses (or `straight`) takes the foot along the straight line between
 * their (stroke, lift) with a level sole, each sample a foot pose of its own (a swing from
 * behind the hip to in front of it stays lifted). Any other move from pose P to Q takes each
 * segment's bend linearly from P's to Q's (pressures from
 * the inverse map of the segment's chamber set, robot_gaitdesign.c movePath), so a foot that
 * is vertical at both ends stays vertical; the path parameter is timed so that the leg's shape
 * (the RMS displacement of its centreline points, leg frame) moves along its path with the
 * smoothstep profile (or at constant speed, `linear`): s(u) = 3u^2 - 2u^3, u = (t - T0)/DURATION. Why: the swinging legs' mass and the
 * support's shift must be accelerated by the stance feet's friction alone (under `paper`
 * conditions the four stance feet hold mu x the support's weight, 0.39 N at mu 0.8, while the
 * four swinging legs weigh 139 g), so a move's peak acceleration 6 D / T^2 is what the design
 * controls, not the pressure's ramp. The table holds a row every `sample` s (one grid for all
 * legs); row k carries the pressures of time (k + 1) sample, and a table with timed moves
 * states `# @ramp sample` (gaits_csv.h), so each row's change fills the interval to the next row and the
 * table follows the designed motion one sample behind. A longer --ramp (an actuation time,
 * gaits_schedule.h) smears and delays that motion. */
typedef struct csrGaitDesignOptions_ {
  double p_max;   /* MPa: highest pressure a solve may use (capped by the map's range) */
  int stretch;    /* 1: the forward kinematics include the map's axial stretch (a leg level
                     that stretches); 0: bends only (rise targets refused) */
} csrGaitDesignOptions;

/* p_max 0.3 MPa, no stretch. */
csrGaitDesignOptions csr_defaultGaitDesignOptions(void);

/* The solved poses of a description. */
typedef struct csrDesignedPoses_ {
  int npose;
  double p[CSG_DESIGN_MAX_POSES][CSR_NSEG * CSR_NCHAMBER];   /* MPa, segment-major */
  double set_p[CSG_DESIGN_MAX_POSES][CSG_DESIGN_MAX_SETS];   /* MPa of each set */
  double foot[CSG_DESIGN_MAX_POSES][3];                      /* mm, leg frame, from straight */
} csrDesignedPoses;

/* Solve every pose of d. Errors name the description's file and line. */
csStatus csr_designPoses(const csrActuator* act, const csrBendMap* map, const csgDesign* d,
                         const csrGaitDesignOptions* opt, csrDesignedPoses* out, csError* err);

/* Build the gait table of d from its solved poses (caller destroys it). */
csgGait* csr_designGait(const csrActuator* act, const csrBendMap* map, const csgDesign* d,
                        const csrGaitDesignOptions* opt, const csrDesignedPoses* poses,
                        csError* err);

/* One line per pose for a gait file's header: name, each set's chambers and pressure, foot
 * offset (stroke, side, lift) (mm). Writes at most size bytes. */
void csr_designPosesFormat(const csgDesign* d, const csrDesignedPoses* poses, char* buf,
                           size_t size);

#ifdef __cplusplus
}
#endif
#endif

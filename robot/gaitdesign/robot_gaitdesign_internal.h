/* robot_gaitdesign_internal.h: what the gait designer's two files share (not public).
 *
 * robot_gaitdesign_pose.c owns the leg model on the calibration map (forward kinematics with or
 * without the map's stretch, bends, the inverse of one set's bend) and the pose solvers;
 * robot_gaitdesign.c builds the moves' pressure paths and the table from them. Pressures P[12]
 * are segment-major (II1 Ω1..Ω4, II2, II3), MPa; positions in the leg frame, mm. */
#ifndef CS_ROBOT_GAITDESIGN_INTERNAL_H
#define CS_ROBOT_GAITDESIGN_INTERNAL_H

#include "core_status.h"
#include "gaits_design.h"
#include "robot_actuator.h"
#include "robot_leg.h"

/* samples per segment of the centreline that times a move (robot_gaitdesign.h); rows of it */
enum { CSR_GD_SHAPE_SAMPLES = 4, CSR_GD_SHAPE_ROWS = CSR_NSEG * (CSR_GD_SHAPE_SAMPLES + 1) };

/* foot (leg frame, mm) for pressures P, with (stretch = 1) or without the map's stretch */
csStatus csr_gdFootAt_(const csrActuator* act, const csrBendMap* map, const double P[12],
                       int stretch, double foot[3], csError* err);

/* the leg's centreline (CSR_GD_SHAPE_ROWS x 3, leg frame, mm) for pressures P */
csStatus csr_gdShapeAt_(const csrActuator* act, const csrBendMap* map, const double P[12],
                        int stretch, double* cl, csError* err);

/* bend magnitude *b (rad) of segment s with pressure p on the chambers of `set` (bit j =
 * Ω(j+1)); 0, or -1 when the map fails */
int csr_gdBendOf_(const csrBendMap* map, int s, unsigned set, double p, double* b);

/* the pressure *p in [0, pmax] at which `set` of segment s bends by `want` (rad), by bisection
 * (the bend grows with the pressure); 0, or -1 when the map fails */
int csr_gdPressureOfBend_(const csrBendMap* map, int s, unsigned set, double pmax, double want,
                          double* p);

/* a foot pose (set->kind CSG_TARGET_FOOT: stroke set->value, lift set->value2, branch
 * set->branch): its pressures into P; errors name src:set->line and the pose `name` */
csStatus csr_gdSolveFootPose_(const csrActuator* act, const csrBendMap* map,
                              const csgDesignSet* set, double pmax, int stretch,
                              const double foot0[3], double P[12], const char* src,
                              const char* name, csError* err);

#endif

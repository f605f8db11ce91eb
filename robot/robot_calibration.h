/* robot_calibration.h: the pressure -> segment-bend maps (calibrations) the dynamic legs use.
 *
 * Owns: the PROVISIONAL calibration used until the FE calibration of issue 3 exists: the
 * analytic model (robot_analytic.h) with its bend angles multiplied by one factor chosen so
 * that a reference actuator reaches a reference total angle at a reference pressure. The
 * reference comes from a small data file (robot/calibration_provisional.txt), not from code:
 *   # comment
 *   actuator baseline          preset of the reference actuator
 *   chambers 1,2               chambers inflated in all three segments
 *   pressure_MPa 0.403         reference pressure
 *   total_angle_deg 360        total bending angle reached at that pressure
 * Why scale the angle and not the stiffness: the analytic model under-predicts the bend of
 * the real (FE) actuator because it ignores the ballooning of the thin chamber walls, which
 * adds actuation, not compliance; scaling the actuation keeps the leg's bending stiffness
 * under external loads (its weight, ground reactions) at the section's E'I. */
#ifndef CS_ROBOT_CALIBRATION_H
#define CS_ROBOT_CALIBRATION_H

#include "core_status.h"
#include "robot_actuator.h"
#include "robot_leg.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct csrProvisionalMap_ csrProvisionalMap;

/* Read the reference from `path`, compute the factor with the analytic model, and bind the map
 * to the leg actuator `leg`. NULL with err ("<file>:<line>: cause") on failure. */
csrProvisionalMap* csr_provisionalMapCreate(const char* path, const csrActuator* leg,
                                            csError* err);
void csr_provisionalMapDestroy(csrProvisionalMap* pm);

/* The map to put in csrRobotModel.map; valid while pm lives. */
csrBendMap csr_provisionalMapGet(const csrProvisionalMap* pm);

/* The factor on the analytic bend angle (-). */
double csr_provisionalMapScale(const csrProvisionalMap* pm);

/* Evaluate the map directly: bend[2] (rad) and stretch for segment seg of the bound leg. */
int csr_provisionalMapEval(const csrProvisionalMap* pm, int seg, const double p[4],
                           double bend[2], double* stretch);

#ifdef __cplusplus
}
#endif
#endif

/* robot_odebody.h: exact save and restore of an ODE body's state (in-world leg levels and the
 * support).
 *
 * Owns: the flat layout of one body's state, CSR_BODY_STATE = 13 doubles:
 *   [0..2] position (mm), [3..6] quaternion (w, x, y, z), [7..9] linear velocity (mm/s),
 *   [10..12] angular velocity (rad/s), world frame,
 * and csr_bodyStateGet/Set, which round-trip it bit for bit.
 *
 * Why not just dBodySetQuaternion. ODE renormalises the quaternion it is given and rebuilds
 * the rotation matrix from it; renormalising a quaternion that ODE's own step has already
 * normalised changes its last bits in 40 % of the cases (measured on 1e5 post-step
 * quaternions), so a state restored that way is not the state saved and the run after it
 * drifts at round-off (2e-14 mm after 500 steps, measured). csr_bodyStateSet therefore sets
 * the body through the API (geoms are notified, accumulated forces cleared) and then writes
 * the saved quaternion bits back into the body's storage, with the rotation matrix rebuilt by
 * dQtoR exactly as ODE's step does after it normalises (ODE 0.16: dxStepBody). The storage is
 * the one dBodyGetQuaternion/dBodyGetRotation return pointers to. Checked by test_state:
 * get/set/step from the same state is bit-identical to stepping without the restore. */
#ifndef CS_ROBOT_ODEBODY_H
#define CS_ROBOT_ODEBODY_H

#include <ode/ode.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CSR_BODY_STATE 13 /* doubles per body (layout above) */

/* Copy body b's state into x[13]. */
void csr_bodyStateGet(dBodyID b, double x[CSR_BODY_STATE]);

/* Restore body b to x[13] bit-exactly and clear its accumulated force and torque. Returns 0,
 * or -1 (body unchanged) if x holds a non-finite value or a quaternion far from unit length
 * (| |q|^2 - 1 | > 1e-6: not a state ODE wrote). */
int csr_bodyStateSet(dBodyID b, const double x[CSR_BODY_STATE]);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_ODEBODY_H */

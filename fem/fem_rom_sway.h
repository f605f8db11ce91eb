/* fem_rom_sway.h: the foot's compliance of the FE leg and of its reduced model under an axial
 * load (issue 34, the FE-informed verdict on the Earth stance; the procedure is
 * actuator/robot_sway.h's: condensed to the guided stiffness, its zero is the
 * sway-buckling load).
 *
 * The foot is the tip face. Its lateral displacement delta and its rotation theta are linear
 * functionals of the nodal displacement, delta = c_lat . u and theta = c_rot . u:
 *   c_lat: the tip face's consistent weights of a unit uniform traction along e1
 *          (csfActuatorFE.tip_unit), so delta is the face's mean displacement along e1;
 *   c_rot: on the axial (e3) components, -s w_a (X_a - Xbar) / sum_b w_b (X_b - Xbar)^2 with
 *          w the same weights, X the nodes' e1 coordinate, Xbar = sum w X and s = +-1 the sign
 *          of the tip's side of the clamp along e3, so theta is the least-squares turn of the
 *          face's axial displacement, the leg's axis tilted towards +e1 (rad; the rod's
 *          csr_rodSwayCompliance measures the same).
 * The loads H and M are those same vectors (H c_lat, M c_rot as nodal forces): each is the
 * work-conjugate of its measure, so the compliance C_ij = c_i . K^-1 c_j is symmetric with a
 * symmetric tangent. M is the linear axial traction over the face (a pure moment in N mm); the
 * face may warp, so theta = 0 holds the face's mean plane, not every node: a sole free to
 * warp, softer than a rigid foot (by how much is not measured). The axial load is the dead
 * force -P s e3 (N) on the face (uniform traction).
 * Units: mm, N, N mm. */
#ifndef CS_FEM_ROM_SWAY_H
#define CS_FEM_ROM_SWAY_H

#include "core_status.h"
#include "fem_actuator.h"
#include "fem_newton.h"
#include "fem_rom_act.h"

#ifdef __cplusplus
extern "C" {
#endif

/* c_lat and c_rot (ndof each, caller's) of the FE model's tip face, and the axial unit vector
 * s e3 (axis, towards the tip). CS_ERR_ARG when the tip face has no extent along e1. */
csStatus csf_swayFunctionals(const csfActuatorFE* fe, double* c_lat, double* c_rot,
                             double axis[3], csError* err);

/* The reduced model at the axial load P (N; csf_romActuatorSolve from its last solved load,
 * no pressure, no gravity) and its compliance C = {c11, c12, c22} (mm/N, 1/N, 1/(N mm)) from
 * the exact reduced tangent there (sync: the converged dilatations and fibre states):
 * C_ij = (V^T c_i) . K_r^-1 (V^T c_j). Errors: the statics' (CS_ERR_DIVERGED), a state that
 * is not physical, a singular tangent (CS_ERR_SOLVER), out of memory. */
csStatus csf_romSwayCompliance(csfRomActuator* ra, const double* c_lat, const double* c_rot,
                               const double axis[3], double P, double C[3], csError* err);

/* The full FE at the axial load P from the state in d, in equilibrium with the axial load
 * P_from on the face (0 at the reference state): the dead load ramped in adaptive steps (Newton
 * at load factor 0: no pressure), then its tangent at the converged state (theta = v/V, the
 * exact derivative) factored once and solved for c_lat and c_rot: C as above; *neg the
 * factorisation's negative pivots (-1 without LDL^T), *newton the Newton iterations spent.
 * Errors: no equilibrium (CS_ERR_DIVERGED), a singular tangent (CS_ERR_SOLVER), memory. */
csStatus csf_feSwayCompliance(csfActuatorFE* fe, csfData* d, const csfNewtonOptions* nopt,
                              const double* c_lat, const double* c_rot, const double axis[3],
                              double P_from, double P, double C[3], int* neg, int* newton,
                              csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ROM_SWAY_H */

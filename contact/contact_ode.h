/* contact_ode.h: rigid contacts between the robot and the terrain in ODE.
 *
 * Owns: cscContactParams (friction coefficient and contact compliance, the model side) and
 * csc_collide(), which runs ODE's collision detection between the terrain space and the robot
 * space and creates one contact joint per contact point in a caller-owned joint group.
 *
 * Friction is Coulomb, per surface: a terrain box's own mu (terrains_terrain.h, the geom's data)
 * or else the run's cscContactParams.mu. ODE's default "mu" is a constant force limit in
 * newtons; we set
 * dContactApprox1 so the limit is mu times the normal force (debian-deps.md), with the friction
 * pyramid aligned to the contact's tangent directions. The contact is a stiff spring-damper
 * (kp, kd) mapped to ODE's soft ERP/CFM at the step h: ERP = h kp / (h kp + kd),
 * CFM = 1 / (h kp + kd) (ODE manual). Collision between geoms of the robot itself is never
 * tested: the legs are far apart and the support is rigid.
 *
 * Pairs ODE resolves with libccd (cylinder/convex pairs) return one point; the robot's
 * geoms here are capsules and boxes against boxes, which ODE handles natively. */
#ifndef CS_CONTACT_ODE_H
#define CS_CONTACT_ODE_H

#include <ode/ode.h>

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cscContactParams_ {
  double mu;           /* Coulomb friction coefficient (-) */
  double kp;           /* contact normal stiffness (N/mm) */
  double kd;           /* contact normal damping (N s/mm) */
  int max_points;      /* contact points per geom pair */
  double stiffness_scale; /* -: multiplies the soft law's foundation modulus (k_area) of
                             co-simulated legs (rod); 1 (`crawlsim run --contact-scale`) */
} cscContactParams;

/* Defaults with their reasons (see contact_ode.c). */
cscContactParams csc_defaultContactParams(void);

/* Validate (mu >= 0 finite, kp > 0, kd >= 0, 1 <= max_points <= 16, stiffness_scale > 0). */
csStatus csc_contactParamsValidate(const cscContactParams* p, csError* err);

/* Per-step contact result, filled by csc_collide. */
typedef struct cscContactStats_ {
  int npoints;      /* contact points created this step */
  double max_depth; /* deepest penetration (mm) */
} cscContactStats;

/* Collide every geom of `robot` against every geom of `terrain`, adding contact joints to
 * `group` for the step h (s). Allocation-free apart from ODE's own joint group storage. */
void csc_collide(const cscContactParams* p, dWorldID world, dSpaceID terrain, dSpaceID robot,
                 dJointGroupID group, double h, cscContactStats* stats);

#ifdef __cplusplus
}
#endif
#endif

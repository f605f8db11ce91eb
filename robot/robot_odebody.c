/* robot_odebody.c: exact ODE body state get/set (see robot_odebody.h). */
#include "robot_odebody.h"

#include <math.h>
#include <string.h>

/* | |q|^2 - 1 | above this is not a quaternion ODE normalised (ODE keeps it to ~1e-16) */
#define QUAT_NORM_TOL 1e-6


void csr_bodyStateGet(dBodyID b, double x[CSR_BODY_STATE]) {
  memcpy(x, dBodyGetPosition(b), 3 * sizeof(double));
  memcpy(x + 3, dBodyGetQuaternion(b), 4 * sizeof(double));
  memcpy(x + 7, dBodyGetLinearVel(b), 3 * sizeof(double));
  memcpy(x + 10, dBodyGetAngularVel(b), 3 * sizeof(double));
}


int csr_bodyStateSet(dBodyID b, const double x[CSR_BODY_STATE]) {
  for (int i = 0; i < CSR_BODY_STATE; i++) {
    if (!isfinite(x[i])) {
      return -1;
    }
  }
  double n2 = x[3] * x[3] + x[4] * x[4] + x[5] * x[5] + x[6] * x[6];
  if (!(fabs(n2 - 1) <= QUAT_NORM_TOL)) {
    return -1;
  }
  dBodySetPosition(b, x[0], x[1], x[2]);
  dBodySetQuaternion(b, x + 3); /* moves the geoms; renormalises (see the header) */
  /* the saved bits back into the body's own quaternion and rotation (robot_odebody.h) */
  dReal* q = (dReal*)dBodyGetQuaternion(b);
  memcpy(q, x + 3, 4 * sizeof(double));
  dReal* R = (dReal*)dBodyGetRotation(b);
  dQtoR(q, R);
  dBodySetLinearVel(b, x[7], x[8], x[9]);
  dBodySetAngularVel(b, x[10], x[11], x[12]);
  dBodySetForce(b, 0, 0, 0);
  dBodySetTorque(b, 0, 0, 0);
  return 0;
}

/* robot_rod_sway.c: the rod's tip compliance under an axial load (robot_rod.h
 * csr_rodSwayCompliance; the sway-buckling procedure of actuator/robot_sway.h). */
#include <math.h>
#include <string.h>

#include "robot_rod.h"

/* node N's position and element N's frame (columns d1 d2 d3) from the state */
static void tipFrame(const csrRodModel* m, const csrRodData* d, double* y, double x[3],
                     double R[3][3]) {
  csr_rodGetState(m, d, y);
  const double* b = y + csr_rodStateOffset(m, csr_rodElements(m));
  const double w = b[3], qx = b[4], qy = b[5], qz = b[6];
  x[0] = b[0], x[1] = b[1], x[2] = b[2];
  const double c[3][3] = {{1 - 2 * (qy * qy + qz * qz), 2 * (qx * qy + w * qz), 2 * (qx * qz - w * qy)},
                          {2 * (qx * qy - w * qz), 1 - 2 * (qx * qx + qz * qz), 2 * (qy * qz + w * qx)},
                          {2 * (qx * qz + w * qy), 2 * (qy * qz - w * qx), 1 - 2 * (qx * qx + qy * qy)}};
  for (int k = 0; k < 3; k++) {
    for (int i = 0; i < 3; i++) {
      R[k][i] = c[k][i]; /* R[k] is column d_{k+1} */
    }
  }
}

csStatus csr_rodSwayCompliance(const csrRodModel* m, csrRodData* d, double P, double dH,
                               double dM, double* y, double C[3], csError* err) {
  if (!(dH > 0) || !(dM > 0) || !isfinite(P)) {
    return cs_errorSet(err, CS_ERR_ARG, "rod sway: the perturbations (%g N, %g N mm) must be "
                       "positive and the load %g finite", dH, dM, P);
  }
  double x0[3], R0[3][3];
  tipFrame(m, d, y, x0, R0);
  /* the straight leg's axis d3 and the bending plane (d1, d3) from the foot's frame before
   * the load: a dead load -P d3 compresses it, H d1 pushes the foot sideways, M d2 turns it */
  const double* d1 = R0[0], *d2 = R0[1], *d3 = R0[2];
  csrRodStaticLoad ld;
  memset(&ld, 0, sizeof ld);
  for (int i = 0; i < 3; i++) {
    ld.tip_force[i] = -P * d3[i];
  }
  csStatus st = csr_rodStatic(m, d, &ld, NULL, err);
  if (st != CS_OK) {
    return st;
  }
  /* central differences about the loaded state: the even orders of the response cancel */
  double r[4][2];
  for (int k = 0; k < 4 && st == CS_OK; k++) {
    csrRodStaticLoad lp = ld;
    const double s = k % 2 ? -1.0 : 1.0;
    for (int i = 0; i < 3; i++) {
      lp.tip_force[i] += k < 2 ? s * dH * d1[i] : 0.0;
      lp.tip_moment[i] = k < 2 ? 0.0 : s * dM * d2[i];
    }
    st = csr_rodStatic(m, d, &lp, NULL, err);
    if (st == CS_OK) {
      double x[3], R[3][3];
      tipFrame(m, d, y, x, R);
      r[k][0] = (x[0] - x0[0]) * d1[0] + (x[1] - x0[1]) * d1[1] + (x[2] - x0[2]) * d1[2];
      r[k][1] = R[2][0] * d1[0] + R[2][1] * d1[1] + R[2][2] * d1[2]; /* d3 tilted to d1 */
      st = csr_rodStatic(m, d, &ld, NULL, err); /* back to the straight state */
    }
  }
  if (st != CS_OK) {
    return st;
  }
  C[0] = (r[0][0] - r[1][0]) / (2 * dH);
  const double c21 = (r[0][1] - r[1][1]) / (2 * dH), c12 = (r[2][0] - r[3][0]) / (2 * dM);
  C[1] = 0.5 * (c12 + c21); /* equal by reciprocity (a conservative rod), to the differences */
  C[2] = (r[2][1] - r[3][1]) / (2 * dM);
  return CS_OK;
}

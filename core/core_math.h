/* core_math.h: small fixed-size math used everywhere (vec3, quat, mat3), header-only.
 *
 * Owns: csReal (the one scalar type, equal to ODE's dReal and SUNDIALS' sunrealtype, asserted
 * where those headers are included), vec3 as csReal[3], quaternions as csReal[4] = (w, x, y, z),
 * row-major mat3 as csReal[9]. Functions allow aliasing of output and input unless noted. */
#ifndef CS_CORE_MATH_H
#define CS_CORE_MATH_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef double csReal;

#define CS_PI 3.14159265358979323846
#define CS_DEG (CS_PI / 180.0) /* radians per degree */

static inline void csu_set3(csReal r[3], csReal x, csReal y, csReal z) {
  r[0] = x;
  r[1] = y;
  r[2] = z;
}
static inline void csu_copy3(csReal r[3], const csReal a[3]) {
  r[0] = a[0];
  r[1] = a[1];
  r[2] = a[2];
}
static inline void csu_add3(csReal r[3], const csReal a[3], const csReal b[3]) {
  r[0] = a[0] + b[0];
  r[1] = a[1] + b[1];
  r[2] = a[2] + b[2];
}
static inline void csu_sub3(csReal r[3], const csReal a[3], const csReal b[3]) {
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}
static inline void csu_scale3(csReal r[3], const csReal a[3], csReal s) {
  r[0] = a[0] * s;
  r[1] = a[1] * s;
  r[2] = a[2] * s;
}
/* r = a + s*b */
static inline void csu_addScl3(csReal r[3], const csReal a[3], const csReal b[3], csReal s) {
  r[0] = a[0] + s * b[0];
  r[1] = a[1] + s * b[1];
  r[2] = a[2] + s * b[2];
}
static inline csReal csu_dot3(const csReal a[3], const csReal b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline csReal csu_norm3(const csReal a[3]) { return sqrt(csu_dot3(a, a)); }
/* r = a x b (r must not alias a or b) */
static inline void csu_cross3(csReal r[3], const csReal a[3], const csReal b[3]) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
/* normalise in place; returns the old norm (0 leaves a unchanged) */
static inline csReal csu_normalize3(csReal a[3]) {
  csReal n = csu_norm3(a);
  if (n > 0) {
    csu_scale3(a, a, 1.0 / n);
  }
  return n;
}

/* r = M a for row-major 3x3 M (r must not alias a) */
static inline void csu_mulMatVec3(csReal r[3], const csReal M[9], const csReal a[3]) {
  r[0] = M[0] * a[0] + M[1] * a[1] + M[2] * a[2];
  r[1] = M[3] * a[0] + M[4] * a[1] + M[5] * a[2];
  r[2] = M[6] * a[0] + M[7] * a[1] + M[8] * a[2];
}
/* R = A B for row-major 3x3 (R must not alias A or B) */
static inline void csu_mulMat3(csReal R[9], const csReal A[9], const csReal B[9]) {
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      R[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
    }
  }
}
static inline void csu_eye3(csReal R[9]) {
  for (int i = 0; i < 9; i++) {
    R[i] = (i % 4 == 0) ? 1.0 : 0.0;
  }
}
/* rotation matrix of angle th (rad) about unit axis u (Rodrigues) */
static inline void csu_axisAngleToMat3(csReal R[9], const csReal u[3], csReal th) {
  csReal c = cos(th), s = sin(th), t = 1 - c;
  R[0] = t * u[0] * u[0] + c;
  R[1] = t * u[0] * u[1] - s * u[2];
  R[2] = t * u[0] * u[2] + s * u[1];
  R[3] = t * u[0] * u[1] + s * u[2];
  R[4] = t * u[1] * u[1] + c;
  R[5] = t * u[1] * u[2] - s * u[0];
  R[6] = t * u[0] * u[2] - s * u[1];
  R[7] = t * u[1] * u[2] + s * u[0];
  R[8] = t * u[2] * u[2] + c;
}
/* rotation matrix of a unit quaternion q = (w, x, y, z) */
static inline void csu_quatToMat3(csReal R[9], const csReal q[4]) {
  csReal w = q[0], x = q[1], y = q[2], z = q[3];
  R[0] = 1 - 2 * (y * y + z * z);
  R[1] = 2 * (x * y - w * z);
  R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z);
  R[4] = 1 - 2 * (x * x + z * z);
  R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y);
  R[7] = 2 * (y * z + w * x);
  R[8] = 1 - 2 * (x * x + y * y);
}

#ifdef __cplusplus
}
#endif
#endif /* CS_CORE_MATH_H */

/* test_fem_angle.c: the bend-angle measurement (csf_bendAxisAngle) against closed-form
 * rotations: a rotation about the bending axis by any angle (past 180 and 360 deg) is measured
 * exactly; with a small out-of-plane tilt added, the measured angle stays smooth and monotone
 * through a full turn (the signed full rotation angle used before jumped there from 360 - eps to
 * 360 + eps, which made a 360 deg --until-angle target unreachable within 0.1 deg). */
#include <math.h>
#include <stdio.h>

#include "cs_test.h"
#include "fem_bend.h"

/* row-major rotation about unit axis n by angle t (Rodrigues) */
static void rotAxis(const double n[3], double t, double R[9]) {
  const double c = cos(t), s = sin(t), v = 1.0 - c;
  R[0] = c + n[0] * n[0] * v, R[1] = n[0] * n[1] * v - n[2] * s, R[2] = n[0] * n[2] * v + n[1] * s;
  R[3] = n[1] * n[0] * v + n[2] * s, R[4] = c + n[1] * n[1] * v, R[5] = n[1] * n[2] * v - n[0] * s;
  R[6] = n[2] * n[0] * v - n[1] * s, R[7] = n[2] * n[1] * v + n[0] * s, R[8] = c + n[2] * n[2] * v;
}

static void mul(const double A[9], const double B[9], double C[9]) {
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      C[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
    }
  }
}

static void test_pure_bend_any_angle(void) {
  const double axis[3] = {0, 1, 0};
  const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  double worst = 0, prev = 0;
  /* 0 .. 720 deg in 0.7 deg steps, each measured against the previous (unwrapping) */
  for (int k = 0; k <= 1030; k++) {
    const double t = k * 0.7 * CS_DEG;
    double R[9];
    rotAxis(axis, t, R);
    const double a = csf_bendAxisAngle(I, R, axis, prev);
    worst = fmax(worst, fabs(a - t));
    prev = a;
  }
  printf("  pure bend 0..721 deg: max error %.2e rad\n", worst);
  /* round-off of the quaternion extraction: a few ulps of pi */
  CS_EXPECT(worst < 1e-12);
  /* a negative bend is negative, and the frame Ra need not be the identity (Ra^T Rb) */
  double Ra[9], Rb[9], Rt[9];
  rotAxis(axis, 0.3, Ra);
  rotAxis(axis, -0.5, Rt);
  mul(Ra, Rt, Rb);
  CS_EXPECT_NEAR(csf_bendAxisAngle(Ra, Rb, axis, 0.0), -0.5, 1e-12, 0);
}

static void test_full_turn_with_tilt(void) {
  /* bend t about y composed with a fixed 0.3 deg tilt about x (out of plane): the measured
   * angle must be monotone in t through 360 deg and within tilt^2 of t (second order: the twist
   * of R_y(t) R_x(e) about y differs from t by O(e^2)) */
  const double axis[3] = {0, 1, 0}, ex[3] = {1, 0, 0};
  const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  const double e = 0.3 * CS_DEG;
  double Rx[9];
  rotAxis(ex, e, Rx);
  double prev = 355.0 * CS_DEG, worst = 0;
  int monotone = 1;
  for (int k = 0; k <= 1000; k++) {
    const double t = (355.0 + 0.01 * k) * CS_DEG;
    double Ry[9], R[9];
    rotAxis(axis, t, Ry);
    mul(Ry, Rx, R);
    const double a = csf_bendAxisAngle(I, R, axis, prev);
    if (k > 0 && !(a > prev)) {
      monotone = 0;
    }
    worst = fmax(worst, fabs(a - t));
    prev = a;
  }
  printf("  bend 355..365 deg with a 0.3 deg tilt: max deviation %.2e deg, monotone %d\n",
         worst / CS_DEG, monotone);
  CS_EXPECT(monotone);
  CS_EXPECT(worst < e * e);
}

int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_pure_bend_any_angle);
  CS_RUN(test_full_turn_with_tilt);
  return cs_testSummary();
}

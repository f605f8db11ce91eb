/* robot_sway.c: the sway-buckling load from a leg's tip compliance (robot_sway.h). */
#include "robot_sway.h"

#include <math.h>

#include "core_math.h"

double csr_swayGuided(double c11, double c12, double c22) {
  if (!(c22 != 0.0) || !isfinite(c11) || !isfinite(c12) || !isfinite(c22)) {
    return NAN;
  }
  const double c = c11 - c12 * c12 / c22; /* the lateral compliance with theta held at 0 */
  return c != 0.0 ? 1.0 / c : NAN;
}

double csr_swayZero(int n, const double* P, const double* k, int* extrapolated) {
  *extrapolated = 0;
  for (int i = 1; i < n; i++) {
    if (k[i - 1] > 0 && k[i] <= 0) {
      return P[i - 1] + (P[i] - P[i - 1]) * k[i - 1] / (k[i - 1] - k[i]);
    }
  }
  if (n < 2 || !(k[n - 1] < k[n - 2]) || !(k[n - 1] > 0)) {
    return NAN;
  }
  *extrapolated = 1;
  return P[n - 1] + (P[n - 1] - P[n - 2]) * k[n - 1] / (k[n - 2] - k[n - 1]);
}

double csr_swayEuler(double EI, double L) {
  return CS_PI * CS_PI * EI / (L * L);
}

double csr_cantileverEuler(double EI, double L) {
  return 0.25 * csr_swayEuler(EI, L);
}

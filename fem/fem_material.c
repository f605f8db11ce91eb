/* fem_material.c: Yeoh law and fibre law (fem_material.h).
 *
 * Rationale. The paper's Elastosil is second-order Yeoh (docs/reference.md), written in the
 * isochoric invariant I1b = J^(-2/3) tr C so that the deviatoric energy is exactly
 * incompressible-consistent; the volumetric part U(J) lives in the element layer (mixed P2/P0 or
 * pointwise), because its treatment is a discretisation choice, not a material one. */
#include "fem_material.h"

#include <math.h>

csfMaterial csf_materialDefault(double C10, double C20, double rho) {
  csfMaterial m;
  m.C10 = C10;
  m.C20 = C20;
  m.kappa = CSF_KAPPA_RATIO * 2.0 * C10;
  m.kappa_pt = 0.0;
  m.rho = rho;
  m.form = CSF_FORM_MIXED_P0;
  return m;
}


double csf_inv3(const double F[9], double Fi[9]) {
  double c0 = F[4] * F[8] - F[5] * F[7];
  double c1 = F[5] * F[6] - F[3] * F[8];
  double c2 = F[3] * F[7] - F[4] * F[6];
  double det = F[0] * c0 + F[1] * c1 + F[2] * c2;
  if (det == 0.0) {
    return 0.0;
  }
  double id = 1.0 / det;
  Fi[0] = c0 * id;
  Fi[1] = (F[2] * F[7] - F[1] * F[8]) * id;
  Fi[2] = (F[1] * F[5] - F[2] * F[4]) * id;
  Fi[3] = c1 * id;
  Fi[4] = (F[0] * F[8] - F[2] * F[6]) * id;
  Fi[5] = (F[2] * F[3] - F[0] * F[5]) * id;
  Fi[6] = c2 * id;
  Fi[7] = (F[1] * F[6] - F[0] * F[7]) * id;
  Fi[8] = (F[0] * F[4] - F[1] * F[3]) * id;
  return det;
}


double csf_yeohDev(double C10, double C20, const double F[9], double* W, double P[9],
                   double A[81]) {
  double Fi[9];
  double J = csf_inv3(F, Fi);
  if (!(J > 0)) {
    return J;
  }
  double I1 = 0;
  for (int i = 0; i < 9; i++) {
    I1 += F[i] * F[i];
  }
  const double g = pow(J, -2.0 / 3.0);
  const double e = g * I1 - 3.0;              /* I1b - 3 */
  const double d1 = C10 + 2.0 * C20 * e;      /* dW/dI1b, MPa */
  const double d2 = 2.0 * C20;                /* d2W/dI1b2, MPa */
  if (W) {
    *W = C10 * e + C20 * e * e;
  }
  /* D = dI1b/dF = g (2 F - 2/3 I1 F^-T); Fi is row-major F^-1, so (F^-T)_iJ = Fi[3J+i] */
  double D[9];
  for (int i = 0; i < 3; i++) {
    for (int J2 = 0; J2 < 3; J2++) {
      D[3 * i + J2] = g * (2.0 * F[3 * i + J2] - (2.0 / 3.0) * I1 * Fi[3 * J2 + i]);
    }
  }
  if (P) {
    for (int i = 0; i < 9; i++) {
      P[i] = d1 * D[i];
    }
  }
  if (A) {
    /* A = d2 D x D + d1 H, H_iJkL = -2/3 Fi_Lk D_iJ - 4/3 g F_kL Fi_Ji + 2 g d_ik d_JL
     *                                 + 2/3 g I1 Fi_Jk Fi_Li */
    for (int i = 0; i < 3; i++) {
      for (int J2 = 0; J2 < 3; J2++) {
        const int iJ = 3 * i + J2;
        for (int k = 0; k < 3; k++) {
          for (int L = 0; L < 3; L++) {
            const int kL = 3 * k + L;
            double H = -(2.0 / 3.0) * Fi[3 * L + k] * D[iJ] -
                       (4.0 / 3.0) * g * F[kL] * Fi[3 * J2 + i] +
                       (2.0 / 3.0) * g * I1 * Fi[3 * J2 + k] * Fi[3 * L + i];
            if (i == k && J2 == L) {
              H += 2.0 * g;
            }
            A[9 * iJ + kL] = d2 * D[iJ] * D[kL] + d1 * H;
          }
        }
      }
    }
  }
  return J;
}


void csf_fibreLaw(int tension_only, double E, double* S, double* dS) {
  *S = E, *dS = 1.0;
  if (tension_only) {
    const double dl = CSF_FIBRE_SLACK;
    if (E <= -dl) {
      *S = 0, *dS = 0;
    } else if (E < dl) {
      *S = (E + dl) * (E + dl) / (4.0 * dl);
      *dS = (E + dl) / (2.0 * dl);
    }
  }
}

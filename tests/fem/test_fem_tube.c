/* test_fem_tube.c: thick-walled Yeoh tube under internal follower pressure (plane strain) against
 * the semi-analytic incompressible solution, and a fibre-wrapped tube whose radial growth the
 * hoop fibres restrict. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cs_test.h"
#include "fem_test_util.h"

#define TUBE_A 2.0  /* inner radius, mm */
#define TUBE_B 5.0  /* outer radius, mm */
#define TUBE_H 1.0  /* slice height, mm */

/* quarter tube: xi0 -> radius, xi1 -> angle 0..pi/2, xi2 -> height */
static void tubeMap(void* user, const double xi[3], double x[3]) {
  (void)user;
  double r = TUBE_A + (TUBE_B - TUBE_A) * xi[0], th = 0.5 * CS_PI * xi[1];
  x[0] = r * cos(th);
  x[1] = r * sin(th);
  x[2] = TUBE_H * xi[2];
}

/* incompressible plane strain: pressure needed for deformed inner radius a,
 * p = int_A^B 2 W'(I1) (lt^2 - lr^2) R / r^2 dR, r^2 = R^2 + a^2 - A^2 (Simpson, 2000 panels) */
static double tubePressure(double a, double C10, double C20) {
  const int n = 2000;
  double s = 0;
  for (int k = 0; k <= n; k++) {
    double R = TUBE_A + (TUBE_B - TUBE_A) * k / n;
    double r2 = R * R + a * a - TUBE_A * TUBE_A;
    double lt2 = r2 / (R * R), lr2 = 1.0 / lt2, I1 = lt2 + lr2 + 1.0;
    double f = 2.0 * (C10 + 2.0 * C20 * (I1 - 3.0)) * (lt2 - lr2) * R / r2;
    s += f * ((k == 0 || k == n) ? 1 : (k % 2 ? 4 : 2));
  }
  return s * (TUBE_B - TUBE_A) / n / 3.0;
}

/* FE inner radius of the quarter tube at pressure p (MPa); optional hoop fibres */
static double feInnerRadius(double p, int nr, int nth, int fibres, double kratio, int* iters_out) {
  csError err = {0};
  int n[3] = {nr, nth, 1};
  csfMesh* me = csf_meshCreateBox(n, tubeMap, NULL, 0.0, &err);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
  mat.kappa = kratio * 2.0 * mat.C10;
  csfModel* m = csf_modelCreate(me, &mat, &err);
  for (int i = 0; i < me->nnode; i++) {
    const double* X = me->x + 3 * i;
    m->fixed[3 * i + 2] = 1; /* plane strain */
    if (fabs(X[0]) < 1e-9) {
      m->fixed[3 * i] = 1;     /* symmetry x = 0 */
    }
    if (fabs(X[1]) < 1e-9) {
      m->fixed[3 * i + 1] = 1; /* symmetry y = 0 */
    }
  }
  csf_modelAddPressure(m, 1, 1.0);
  if (fibres) {
    /* hoop fibres at mid-height, 0.2 mm inside the outer surface, every 0.25 mm in height */
    for (int k = 0; k < 3; k++) {
      double pts[3 * 33];
      for (int q = 0; q < 33; q++) {
        double th = 0.5 * CS_PI * q / 32.0, r = TUBE_B - 0.2;
        pts[3 * q] = r * cos(th), pts[3 * q + 1] = r * sin(th), pts[3 * q + 2] = 0.25 + 0.25 * k;
      }
      CS_EXPECT(csf_modelAddFibre(m, 33, pts, 31067.0, 0.0889, &err) == CS_OK);
    }
  }
  csf_modelFinalize(m, &err);
  csfData* d = csf_dataCreate(m, &err);
  csfNewtonOptions o = csf_newtonDefault();
  CS_EXPECT(csf_loadRamp(m, d, p, 4, &o, iters_out, &err) == CS_OK);
  /* inner node on the x axis: X = (A, 0, 0) */
  double a = NAN;
  for (int i = 0; i < me->nnode; i++) {
    const double* X = me->x + 3 * i;
    if (fabs(X[0] - TUBE_A) < 1e-9 && fabs(X[1]) < 1e-9 && fabs(X[2]) < 1e-9) {
      a = X[0] + d->u[3 * i];
    }
  }
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
  return a;
}

static void test_tube_pressure(void) {
  const double p = 0.15; /* MPa: inflates the bore by about 50 % */
  /* semi-analytic inner radius by bisection on p(a) */
  double lo = TUBE_A, hi = 3 * TUBE_A;
  for (int it = 0; it < 100; it++) {
    double mid = 0.5 * (lo + hi);
    if (tubePressure(mid, 0.11, 0.02) < p) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  const double a_ref = 0.5 * (lo + hi);
  int it1, it2, it3;
  double a1 = feInnerRadius(p, 2, 4, 0, CSF_KAPPA_RATIO, &it1);
  double a2 = feInnerRadius(p, 4, 8, 0, CSF_KAPPA_RATIO, &it2);
  double a3 = feInnerRadius(p, 4, 8, 0, 10 * CSF_KAPPA_RATIO, &it3);
  printf("  tube p %.3f MPa: a/A semi-analytic %.6f, FE (2x4) %.6f, FE (4x8) %.6f; Newton "
         "iterations %d, %d\n", p, a_ref / TUBE_A, a1 / TUBE_A, a2 / TUBE_A, it1, it2);
  printf("  errors: %.3e, %.3e, kappa x10: %.3e (relative to the bore growth a - A)\n",
         (a1 - a_ref) / (a_ref - TUBE_A), (a2 - a_ref) / (a_ref - TUBE_A),
         (a3 - a_ref) / (a_ref - TUBE_A));
  /* measured -2.9e-3 (2x4), -3.2e-3 (4x8), -3.5e-3 (4x8, kappa x10): a systematic 0.3 % in the
   * bore growth (50 % inflation) that neither refinement nor kappa removes; see fem/README.md
   * ("Known deviations"). 5e-3 bounds it; a wrong pressure load or tangent gives > 5 %. */
  CS_EXPECT_NEAR(a1 - TUBE_A, a_ref - TUBE_A, 0, 5e-3);
  CS_EXPECT_NEAR(a2 - TUBE_A, a_ref - TUBE_A, 0, 5e-3);
  CS_EXPECT_NEAR(a3 - TUBE_A, a_ref - TUBE_A, 0, 5e-3);
  /* adaptive ramp from 4 steps: measured 18 (2x4) and 82 (4x8, with cutbacks) iterations */
  CS_EXPECT(it2 <= 150);
}

static void test_tube_fibres(void) {
  const double p = 0.15;
  int it0, it1;
  double a0 = feInnerRadius(p, 3, 6, 0, CSF_KAPPA_RATIO, &it0);
  double a1 = feInnerRadius(p, 3, 6, 1, CSF_KAPPA_RATIO, &it1);
  printf("  fibre-wrapped tube: bore growth %.4f mm without fibres, %.4f mm with hoop fibres\n",
         a0 - TUBE_A, a1 - TUBE_A);
  /* three Kevlar hoops (EA = 771 N each) on a 1 mm slice make the outer radius nearly
   * inextensible: growth must drop by more than half */
  CS_EXPECT(a1 - TUBE_A < 0.5 * (a0 - TUBE_A));
  CS_EXPECT(a1 > TUBE_A);
}

int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_tube_pressure);
  CS_RUN(test_tube_fibres);
  return cs_testSummary();
}

/* test_fem_tube.c: thick-walled Yeoh tube under internal follower pressure (plane strain) against
 * the semi-analytic solution of the FE's compressible material (checked against the incompressible
 * one as kappa -> inf), with second-order convergence of the bore growth; and a fibre-wrapped tube
 * whose radial growth the hoop fibres restrict. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cs_test.h"
#include "fem_test_util.h"

#define TUBE_A 2.0  /* inner radius, mm */
#define TUBE_B 5.0  /* outer radius, mm */
#define TUBE_H 1.0  /* slice height of the fibre test, mm */
#define TUBE_C10 0.11 /* Yeoh constants, MPa */
#define TUBE_C20 0.02

/* quarter tube: xi0 -> radius, xi1 -> angle 0..pi/2, xi2 -> height (user: slice height, mm) */
static void tubeMap(void* user, const double xi[3], double x[3]) {
  const double h = *(const double*)user;
  double r = TUBE_A + (TUBE_B - TUBE_A) * xi[0], th = 0.5 * CS_PI * xi[1];
  x[0] = r * cos(th);
  x[1] = r * sin(th);
  x[2] = h * xi[2];
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

/* incompressible inner radius at pressure p: bisection on tubePressure */
static double tubeRadiusIncompressible(double p) {
  double lo = TUBE_A, hi = 3 * TUBE_A;
  for (int it = 0; it < 100; it++) {
    double mid = 0.5 * (lo + hi);
    if (tubePressure(mid, TUBE_C10, TUBE_C20) < p) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

/* The FE material is compressible: W = C10 (I1b - 3) + C20 (I1b - 3)^2 + kappa/2 (J - 1)^2.
 * Principal first Piola-Kirchhoff stresses (radial, hoop) of plane strain, lz = 1, MPa. */
static void tubePK(double lr, double lt, double kappa, double* Pr, double* Pt) {
  double J = lr * lt, Jm = pow(J, -2.0 / 3.0), I1b = Jm * (lr * lr + lt * lt + 1.0);
  double W1 = TUBE_C10 + 2.0 * TUBE_C20 * (I1b - 3.0), pv = kappa * (J - 1.0);
  *Pr = 2.0 * W1 * (Jm * lr * lr - I1b / 3.0) / lr + pv * lt; /* J sigma_rr / lr */
  *Pt = 2.0 * W1 * (Jm * lt * lt - I1b / 3.0) / lt + pv * lr;
}

/* radial stretch lr with radial PK stress Pr at hoop stretch lt (Pr increases with lr) */
static double tubeStretch(double Pr, double lt, double kappa) {
  double lo = 0.05, hi = 5.0, P, Q;
  for (int it = 0; it < 80; it++) {
    double mid = 0.5 * (lo + hi);
    tubePK(mid, lt, kappa, &P, &Q);
    if (P < Pr) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return 0.5 * (lo + hi);
}

/* radial PK stress at R = B for deformed inner radius a: RK4 on (r, Pr) from R = A, where
 * Pr = -p a / A (Cauchy traction p on the deformed bore), r' = lr(Pr, r/R),
 * Pr' = (Pt - Pr) / R (equilibrium in the reference frame), 200 steps */
static double tubeShoot(double a, double p, double kappa) {
  const int n = 200;
  const double h = (TUBE_B - TUBE_A) / n;
  double R = TUBE_A, y[2] = {a, -p * a / TUBE_A}, k[4][2];
  for (int s = 0; s < n; s++) {
    for (int q = 0; q < 4; q++) {
      double c = q == 0 ? 0 : (q == 3 ? 1.0 : 0.5), Rq = R + c * h, yq[2], Pr, Pt;
      for (int j = 0; j < 2; j++) {
        yq[j] = y[j] + (q == 0 ? 0 : c * h * k[q - 1][j]);
      }
      double lt = yq[0] / Rq, lr = tubeStretch(yq[1], lt, kappa);
      tubePK(lr, lt, kappa, &Pr, &Pt);
      k[q][0] = lr;
      k[q][1] = (Pt - yq[1]) / Rq;
    }
    for (int j = 0; j < 2; j++) {
      y[j] += h / 6.0 * (k[0][j] + 2 * k[1][j] + 2 * k[2][j] + k[3][j]);
    }
    R += h;
  }
  return y[1];
}

/* compressible inner radius at pressure p: secant on tubeShoot(a) = 0 (traction-free outside) */
static double tubeRadiusCompressible(double p, double kappa) {
  double x0 = 1.3 * TUBE_A, x1 = 1.9 * TUBE_A;
  double f0 = tubeShoot(x0, p, kappa), f1 = tubeShoot(x1, p, kappa);
  for (int it = 0; it < 40 && fabs(x1 - x0) > 1e-13 && f1 != f0; it++) {
    double x2 = x1 - f1 * (x1 - x0) / (f1 - f0);
    x0 = x1, f0 = f1;
    x1 = x2, f1 = tubeShoot(x1, p, kappa);
  }
  return x1;
}

/* Volume enclosed by the bore (faces tagged 1) between the symmetry planes, deformed by u (NULL:
 * reference), mm^3: V = -1/2 int (x, y, 0) . n da over the curved Tri6 faces (n out of the body;
 * the symmetry, top and bottom planes add no flux), 6-point degree-4 rule (Dunavant), exact for
 * the quartic integrand of a quadratic face. */
static double boreVolume(const csfMesh* me, const double* u) {
  static const double qa[2] = {0.445948490915965, 0.091576213509771};
  static const double qw[2] = {0.223381589678011, 0.109951743655322};
  double V = 0;
  for (int f = 0; f < me->nface; f++) {
    if (me->face_tag[f] != 1) {
      continue;
    }
    double x[6][3];
    for (int a = 0; a < 6; a++) {
      int nd = me->face[6 * f + a];
      for (int c = 0; c < 3; c++) {
        x[a][c] = me->x[3 * nd + c] + (u ? u[3 * nd + c] : 0.0);
      }
    }
    for (int g = 0; g < 6; g++) {
      double L[3] = {qa[g / 3], qa[g / 3], qa[g / 3]};
      L[g % 3] = 1.0 - 2.0 * qa[g / 3];
      /* Tri6 shape functions of (xi, eta) = (L1, L2) and their derivatives */
      double N[6] = {L[0] * (2 * L[0] - 1), L[1] * (2 * L[1] - 1), L[2] * (2 * L[2] - 1),
                     4 * L[0] * L[1],       4 * L[1] * L[2],       4 * L[2] * L[0]};
      double dxi[6] = {1 - 4 * L[0], 4 * L[1] - 1, 0, 4 * (L[0] - L[1]), 4 * L[2], -4 * L[2]};
      double deta[6] = {1 - 4 * L[0], 0, 4 * L[2] - 1, -4 * L[1], 4 * L[1], 4 * (L[0] - L[2])};
      double X[3] = {0}, t1[3] = {0}, t2[3] = {0};
      for (int a = 0; a < 6; a++) {
        for (int c = 0; c < 3; c++) {
          X[c] += N[a] * x[a][c];
          t1[c] += dxi[a] * x[a][c];
          t2[c] += deta[a] * x[a][c];
        }
      }
      double nx = t1[1] * t2[2] - t1[2] * t2[1], ny = t1[2] * t2[0] - t1[0] * t2[2];
      V -= 0.5 * qw[g / 3] * 0.5 * (X[0] * nx + X[1] * ny); /* reference triangle area 1/2 */
    }
  }
  return V;
}

/* FE bore measures of one run (mm) */
typedef struct TubeBore_ {
  double a_vol;  /* radius of the circle with the bore's enclosed area: sqrt(4 V / (pi h)) */
  double a_vol0; /* the same on the reference mesh (quadratic arcs instead of the circle) */
  double a_pt;   /* radius of the node X = (A, 0, 0) (bottom face) */
  double a_top;  /* radius of the node X = (A, 0, h) (top face) */
} TubeBore;

/* FE quarter tube (nr x nth x 1 cells, slice height h) at pressure p (MPa), optional hoop
 * fibres. */
static TubeBore feTube(double p, int nr, int nth, double h, int fibres, double kratio,
                       int* iters_out) {
  csError err = {0};
  int n[3] = {nr, nth, 1};
  csfMesh* me = csf_meshCreateBox(n, tubeMap, &h, 0.0, &err);
  csfMaterial mat = csf_materialDefault(TUBE_C10, TUBE_C20, 1130e-12);
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
  TubeBore b = {NAN, NAN, NAN, NAN};
  for (int i = 0; i < me->nnode; i++) {
    const double* X = me->x + 3 * i;
    if (fabs(X[0] - TUBE_A) < 1e-9 && fabs(X[1]) < 1e-9) {
      if (fabs(X[2]) < 1e-9) {
        b.a_pt = X[0] + d->u[3 * i];
      } else if (fabs(X[2] - h) < 1e-9) {
        b.a_top = X[0] + d->u[3 * i];
      }
    }
  }
  b.a_vol = sqrt(4.0 * boreVolume(me, d->u) / (CS_PI * h));
  b.a_vol0 = sqrt(4.0 * boreVolume(me, NULL) / (CS_PI * h));
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
  return b;
}

static void test_tube_pressure(void) {
  const double p = 0.15; /* MPa: inflates the bore by about 65 % */
  const double kappa = CSF_KAPPA_RATIO * 2.0 * TUBE_C10;
  const double a_inc = tubeRadiusIncompressible(p);
  const double a_ref = tubeRadiusCompressible(p, kappa);
  const double a_ref10 = tubeRadiusCompressible(p, 10 * kappa);
  const double g_ref = a_ref - TUBE_A, g_ref10 = a_ref10 - TUBE_A;
  /* the two references agree as kappa -> inf: the shooting (RK4, 200 steps; 400 steps changes
   * a by < 1e-9) against the incompressible integral (Simpson, 2000 panels); measured 3.7e-7 at
   * kappa x1000, the 1/kappa trend of the compressibility shift (3.7e-4 at kappa, 3.7e-5 at
   * 10 kappa), so 2e-6 leaves room for that shift only */
  const double a_inf = tubeRadiusCompressible(p, 1000 * kappa);
  printf("  tube p %.3f MPa: a/A incompressible %.9f, compressible kappa x1000 %.9f, x10 %.9f, "
         "x1 %.9f\n", p, a_inc / TUBE_A, a_inf / TUBE_A, a_ref10 / TUBE_A, a_ref / TUBE_A);
  CS_EXPECT_NEAR(a_inf - TUBE_A, a_inc - TUBE_A, 0, 2e-6);
  printf("  compressibility (kappa = %g C10) adds %.3e to the bore growth a - A\n",
         2 * CSF_KAPPA_RATIO, (a_ref - a_inc) / (a_inc - TUBE_A));
  /* FE on a shape-regular family: the slice height is scaled with the cells (0.75 mm radial,
   * 0.4..1 mm hoop, 0.75 mm high, then half that) */
  int it1, it2, it3;
  TubeBore b1 = feTube(p, 4, 8, 0.75, 0, CSF_KAPPA_RATIO, &it1);
  TubeBore b2 = feTube(p, 8, 16, 0.375, 0, CSF_KAPPA_RATIO, &it2);
  TubeBore b3 = feTube(p, 4, 8, 0.75, 0, 10 * CSF_KAPPA_RATIO, &it3);
  /* errors relative to the bore growth of the compressible reference */
  double v1 = (b1.a_vol - a_ref) / g_ref, v2 = (b2.a_vol - a_ref) / g_ref;
  double v3 = (b3.a_vol - a_ref10) / g_ref10;
  double p1 = (b1.a_pt - a_ref) / g_ref, p2 = (b2.a_pt - a_ref) / g_ref;
  printf("  FE (4x8, 8x16, 4x8 kappa x10): Newton iterations %d, %d, %d\n", it1, it2, it3);
  printf("  bore growth error, enclosed area: %.3e, %.3e, %.3e (reference mesh: %.1e, %.1e)\n",
         v1, v2, v3, (b1.a_vol0 - TUBE_A) / g_ref, (b2.a_vol0 - TUBE_A) / g_ref);
  printf("  bore growth error at (A,0,0): %.3e, %.3e; at (A,0,h): %.3e, %.3e\n", p1, p2,
         (b1.a_top - a_ref) / g_ref, (b2.a_top - a_ref) / g_ref);
  /* The FE error is discretisation error of a 65 % hoop stretch at the bore (12 % at the outer
   * radius). Measured, enclosed-area radius vs the compressible reference, on this family:
   * 2x4 +9.9e-3, 4x8 +2.92e-3, 8x16 +7.5e-4, 16x32 +1.8e-4 (ratios 3.4, 3.9, 4.1: second
   * order). Bounds: 4e-3 and 1e-3 (1.35 x measured) and the error must fall by more than 3
   * from 4x8 to 8x16. The reference mesh's quadratic arcs put its enclosed-area radius 2.4e-6
   * of the growth below A (4x8): the mesh geometry is not the error. */
  CS_EXPECT_NEAR(b1.a_vol - TUBE_A, g_ref, 0, 4e-3);
  CS_EXPECT_NEAR(b2.a_vol - TUBE_A, g_ref, 0, 1e-3);
  CS_EXPECT(fabs(v1) > 3.0 * fabs(v2));
  /* kappa x10 against its own reference: the same error (measured +2.92e-3 both: no locking) */
  CS_EXPECT_NEAR(v3, v1, 1e-4, 0);
  /* Single nodes see more: the one-layer Kuhn split is not symmetric in z, so the discrete bore
   * radius varies through the slice (4x8: -3.2e-3 at z = 0, +3.5e-3 at z = h on the x axis;
   * 8x16: -1.5e-3, +1.1e-3; 16x32: -5.3e-4, +3.2e-4). The old test read only (A,0,0) on a
   * fixed 1 mm slice against the incompressible solution and found -2.9e-3 (2x4) and -3.2e-3
   * (4x8): the bottom of this spread plus the 3.7e-4 compressibility shift, not a bias. Bound
   * at (A,0,0), 8x16: 2e-3 (1.35 x measured). */
  CS_EXPECT_NEAR(b2.a_pt - TUBE_A, g_ref, 0, 2e-3);
  /* adaptive ramp from 4 steps: measured 13, 13, 14 iterations */
  CS_EXPECT(it1 <= 30 && it2 <= 30 && it3 <= 30);
}

static void test_tube_fibres(void) {
  const double p = 0.15;
  int it0, it1;
  double a0 = feTube(p, 3, 6, TUBE_H, 0, CSF_KAPPA_RATIO, &it0).a_pt;
  double a1 = feTube(p, 3, 6, TUBE_H, 1, CSF_KAPPA_RATIO, &it1).a_pt;
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

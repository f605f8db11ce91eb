/* test_fem_element.c: Yeoh Tet10 kernel verification: consistent tangent by finite differences
 * (body, follower pressure, fibres), homogeneous uniaxial and equibiaxial stretch against the
 * closed-form incompressible Yeoh Cauchy stress, and a nonlinear patch test. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "fem_test_util.h"

/* Yeoh dW/dI1 for the incompressible closed forms (MPa) */
static double yeohD1(double I1) { return 0.11 + 2.0 * 0.02 * (I1 - 3.0); }


/* Cauchy stress diagonal of the (slightly compressible) model at F = diag(f): the model's own
 * closed form, sigma = P F^T / J + kappa (J - 1) I */
static void modelStress(const double f[3], double kappa, double sig[3]) {
  double F[9] = {f[0], 0, 0, 0, f[1], 0, 0, 0, f[2]}, P[9];
  double J = csf_yeohDev(0.11, 0.02, F, NULL, P, NULL);
  for (int i = 0; i < 3; i++) {
    sig[i] = P[4 * i] * f[i] / J + kappa * (J - 1.0);
  }
}


/* free stretch l (bisection) such that sigma[free] = 0 with the other stretches fixed */
static double freeStretch(double f[3], int nfree, const int* freeidx, double kappa) {
  double lo = 0.2, hi = 2.0;
  for (int it = 0; it < 200; it++) {
    double mid = 0.5 * (lo + hi), sig[3];
    for (int k = 0; k < nfree; k++) {
      f[freeidx[k]] = mid;
    }
    modelStress(f, kappa, sig);
    if (sig[freeidx[0]] > 0) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  return 0.5 * (lo + hi);
}


/* K vs central differences of R for a random state, both formulations, with pressure + fibre */
static void tangentFd(csfFormulation form) {
  csError err = {0};
  int n[3] = {1, 1, 2};
  double sc[3] = {2.0, 1.5, 3.0};
  csfMesh* me = csf_meshCreateBox(n, ftScaleMap, sc, 0.0, &err);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
  mat.kappa = 50.0; /* moderate kappa keeps the FD check well conditioned (MPa) */
  mat.form = form;
  csfModel* m = csf_modelCreate(me, &mat, &err);
  CS_EXPECT(csf_modelAddPressure(m, 2, 1.0) > 0);
  double fib[3 * 3] = {0.3, 0.2, 0.5, 1.7, 1.2, 1.5, 0.5, 0.7, 2.8};
  CS_EXPECT(csf_modelAddFibre(m, 3, fib, 31067.0, 0.0889, &err) == CS_OK);
  m->gravity[1] = -9810.0;
  CS_EXPECT(csf_modelFinalize(m, &err) == CS_OK);
  csfData* d = csf_dataCreate(m, &err);
  /* random moderate displacement that stretches the fibre (tension) */
  srand(7);
  for (int i = 0; i < m->ndof; i++) {
    d->u[i] = 0.08 * ((double)rand() / RAND_MAX - 0.5) + 0.1 * me->x[i] * (i % 3 == 0);
  }
  const double load = 0.05; /* MPa */
  d->load = load;
  csf_dataSyncVolume(m, d);
  CS_EXPECT(csf_assemble(m, d, load, 1) == 0);
  const int nd = m->ndof;
  double* K = calloc((size_t)nd * nd, sizeof(double));
  for (int i = 0; i < nd; i++) {
    for (int q = m->row_ptr[i]; q < m->row_ptr[i + 1]; q++) {
      K[(size_t)i * nd + m->col[q]] = d->kval[q];
    }
  }
  double* rp = malloc((size_t)nd * sizeof(double));
  double maxerr = 0, maxk = 0;
  const double h = 1e-6; /* mm: central differences, truncation ~h^2, round-off ~1e-16/h */
  for (int j = 0; j < nd; j++) {
    double u0 = d->u[j];
    d->u[j] = u0 + h;
    csf_assemble(m, d, load, 0);
    memcpy(rp, d->r, (size_t)nd * sizeof(double));
    d->u[j] = u0 - h;
    csf_assemble(m, d, load, 0);
    d->u[j] = u0;
    for (int i = 0; i < nd; i++) {
      double fd = (rp[i] - d->r[i]) / (2 * h);
      maxerr = fmax(maxerr, fabs(fd - K[(size_t)i * nd + j]));
      maxk = fmax(maxk, fabs(K[(size_t)i * nd + j]));
    }
  }
  printf("  tangent FD (%s): max |K - K_fd| = %.3e, max |K| = %.3e\n",
         form == CSF_FORM_MIXED_P0 ? "mixed P2/P0" : "displacement P2", maxerr, maxk);
  /* measured ~1e-8 relative; 1e-6 leaves margin for FD round-off yet catches any wrong term
   * (a missing term is O(1e-2) relative or larger) */
  CS_EXPECT_NEAR(maxerr / maxk, 0.0, 1e-6, 0);
  free(K), free(rp);
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
}

static void test_tangent_mixed(void) { tangentFd(CSF_FORM_MIXED_P0); }
static void test_tangent_displacement(void) { tangentFd(CSF_FORM_DISPLACEMENT); }


static void test_uniaxial(void) {
  csError err = {0};
  int n[3] = {2, 2, 2};
  csfMesh* me = csf_meshCreateBox(n, NULL, NULL, 0.0, &err);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
  csfModel* m = csf_modelCreate(me, &mat, &err);
  const double lam = 2.0; /* stretch 100 %: large deformation */
  ftFix(m, 0, 0.0, 0, 0.0);
  ftFix(m, 1, 0.0, 1, 0.0);
  ftFix(m, 2, 0.0, 2, 0.0);
  ftFix(m, 2, 1.0, 2, lam - 1.0);
  csf_modelFinalize(m, &err);
  csfData* d = csf_dataCreate(m, &err);
  CS_EXPECT(ftRamp(m, d, 4, &err) == CS_OK);
  double I1 = lam * lam + 2.0 / lam;
  double sz = 2.0 * (lam * lam - 1.0 / lam) * yeohD1(I1);
  double szz = ftMeanStress(m, d, 2), sxx = ftMeanStress(m, d, 0);
  printf("  uniaxial lambda %.1f: sigma_zz %.6f vs %.6f MPa, sigma_xx %.2e, J-1 %.2e\n", lam,
         szz, sz, sxx, d->vratio[0] - 1.0);
  /* exact homogeneous solution of the model itself (kappa finite): lateral stretch by bisection */
  double f[3] = {1, 1, lam}, sig[3];
  const int fr[2] = {0, 1};
  freeStretch(f, 2, fr, mat.kappa);
  modelStress(f, mat.kappa, sig);
  printf("  model closed form: sigma_zz %.9f MPa, lateral stretch %.9f (FE %.9f)\n", sig[2], f[0],
         1.0 + d->u[3 * (me->nnode - 1)] / me->x[3 * (me->nnode - 1)]);
  /* FE vs the model's closed form: the homogeneous field is exactly representable, so only the
   * Newton tolerance remains (measured ~1e-12 relative) */
  CS_EXPECT_NEAR(szz, sig[2], 0, 1e-8);
  /* vs the incompressible closed form: kappa = 2000 mu gives J - 1 = 1.0e-3 here and a stress
   * difference of 2.3e-3 relative (measured); 5e-3 bounds the compressibility effect */
  CS_EXPECT_NEAR(szz, sz, 0, 5e-3);
  CS_EXPECT_NEAR(sxx, 0.0, 1e-8 * sz, 0);
  CS_EXPECT_NEAR(d->vratio[0], 1.0, 2e-3, 0);
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
}


static void test_equibiaxial(void) {
  csError err = {0};
  int n[3] = {2, 2, 1};
  csfMesh* me = csf_meshCreateBox(n, NULL, NULL, 0.0, &err);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
  csfModel* m = csf_modelCreate(me, &mat, &err);
  const double lam = 1.6;
  ftFix(m, 0, 0.0, 0, 0.0);
  ftFix(m, 1, 0.0, 1, 0.0);
  ftFix(m, 2, 0.0, 2, 0.0);
  ftFix(m, 0, 1.0, 0, lam - 1.0);
  ftFix(m, 1, 1.0, 1, lam - 1.0);
  csf_modelFinalize(m, &err);
  csfData* d = csf_dataCreate(m, &err);
  CS_EXPECT(ftRamp(m, d, 4, &err) == CS_OK);
  double I1 = 2 * lam * lam + 1.0 / pow(lam, 4);
  double s = 2.0 * (lam * lam - 1.0 / pow(lam, 4)) * yeohD1(I1);
  double sxx = ftMeanStress(m, d, 0), syy = ftMeanStress(m, d, 1), szz = ftMeanStress(m, d, 2);
  printf("  equibiaxial lambda %.1f: sigma_xx %.6f sigma_yy %.6f vs %.6f MPa, sigma_zz %.2e\n",
         lam, sxx, syy, s, szz);
  double f[3] = {lam, lam, 1}, sig[3];
  const int fr[1] = {2};
  freeStretch(f, 1, fr, mat.kappa);
  modelStress(f, mat.kappa, sig);
  printf("  model closed form: sigma_xx %.9f MPa\n", sig[0]);
  /* exactly representable homogeneous field: Newton tolerance only */
  CS_EXPECT_NEAR(sxx, sig[0], 0, 1e-8);
  CS_EXPECT_NEAR(syy, sig[0], 0, 1e-8);
  /* incompressible closed form: measured 3.5e-3 relative from kappa = 2000 mu; bound 5e-3 */
  CS_EXPECT_NEAR(sxx, s, 0, 5e-3);
  CS_EXPECT_NEAR(syy, s, 0, 5e-3);
  CS_EXPECT_NEAR(szz, 0.0, 1e-8 * s, 0);
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
}


/* csf_worstElement: under u = (0, 0, -a z^2) on the unit cube (exact in Tet10) the pointwise J is
 * 1 - 2 a z, so the smallest J sits in the top layer (z in [0.5, 1]) and lies between 1 - 2a
 * (the top face) and 1 - a (the layer's bottom); a homogeneous J = 0.5 is returned exactly */
static void test_worst_element(void) {
  csError err = {0};
  int n[3] = {2, 2, 2};
  csfMesh* me = csf_meshCreateBox(n, NULL, NULL, 0.0, &err);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
  csfModel* m = csf_modelCreate(me, &mat, &err);
  CS_EXPECT(csf_modelFinalize(m, &err) == CS_OK);
  csfData* d = csf_dataCreate(m, &err);
  const double a = 0.2;
  for (int i = 0; i < me->nnode; i++) {
    const double z = me->x[3 * i + 2];
    d->u[3 * i] = d->u[3 * i + 1] = 0.0;
    d->u[3 * i + 2] = -a * z * z;
  }
  csf_assemble(m, d, 0.0, 0);
  double X[3];
  double j = csf_worstElement(m, d, X);
  printf("  u = -a z^2: smallest J %.6f at (%.3f, %.3f, %.3f); bounds [%.3f, %.3f]\n", j, X[0],
         X[1], X[2], 1 - 2 * a, 1 - a);
  CS_EXPECT(j >= 1 - 2 * a - 1e-12 && j <= 1 - a + 1e-12);
  CS_EXPECT(X[2] > 0.5 && X[2] < 1.0);
  CS_EXPECT_NEAR(j, d->jmin, 0, 0); /* the element holding the assembly's minimum */
  for (int i = 0; i < me->nnode; i++) {
    d->u[3 * i + 2] = -0.5 * me->x[3 * i + 2];
  }
  csf_assemble(m, d, 0.0, 0);
  CS_EXPECT_NEAR(csf_worstElement(m, d, X), 0.5, 1e-12, 0);
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
}


/* nonlinear patch test: affine boundary displacement on a distorted mesh -> affine field */
static void test_patch(void) {
  csError err = {0};
  int n[3] = {3, 3, 3};
  csfMesh* me = csf_meshCreateBox(n, NULL, NULL, 0.3, &err);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
  csfModel* m = csf_modelCreate(me, &mat, &err);
  const double G[9] = {0.25, 0.1, -0.05, 0.0, -0.12, 0.08, 0.04, -0.02, -0.1}; /* F - I */
  for (int i = 0; i < me->nnode; i++) {
    const double* X = me->x + 3 * i;
    int bnd = 0;
    for (int k = 0; k < 3; k++) {
      bnd = bnd || fabs(X[k]) < 1e-12 || fabs(X[k] - 1) < 1e-12;
    }
    if (bnd) {
      for (int c = 0; c < 3; c++) {
        m->fixed[3 * i + c] = 1;
        m->u_fix[3 * i + c] = G[3 * c] * X[0] + G[3 * c + 1] * X[1] + G[3 * c + 2] * X[2];
      }
    }
  }
  csf_modelFinalize(m, &err);
  csfData* d = csf_dataCreate(m, &err);
  CS_EXPECT(ftRamp(m, d, 2, &err) == CS_OK);
  double maxe = 0;
  for (int i = 0; i < me->nnode; i++) {
    const double* X = me->x + 3 * i;
    for (int c = 0; c < 3; c++) {
      double ue = G[3 * c] * X[0] + G[3 * c + 1] * X[1] + G[3 * c + 2] * X[2];
      maxe = fmax(maxe, fabs(d->u[3 * i + c] - ue));
    }
  }
  printf("  patch test: max |u - u_affine| = %.3e mm (%d nodes)\n", maxe, me->nnode);
  /* the affine field is in the P2 space, so only the Newton tolerance (rtol 1e-8 on forces of
   * order 1 N, stiffness ~ kappa) remains: measured ~1e-12 mm */
  CS_EXPECT_NEAR(maxe, 0.0, 1e-8, 0);
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_tangent_mixed);
  CS_RUN(test_tangent_displacement);
  CS_RUN(test_uniaxial);
  CS_RUN(test_equibiaxial);
  CS_RUN(test_patch);
  CS_RUN(test_worst_element);
  return cs_testSummary();
}

/* test_fem_branch.c: the critical mode of a converged state and branch switching (fem_path.h).
 *
 * test_critical_mode_of_a_compressed_column: a silicone column 40 x 4 x 2 mm, clamped at x = 0,
 * its end face x = L pushed in axially (u_x = -delta on every node: no end rotation, sway free;
 * the clamped-guided Euler column, effective length L). Its straight state loses stability at the
 * axial strain eps_cr = pi^2 I / (A L^2) per bending axis: h^2 pi^2 / (12 L^2) = 2.06e-3 about
 * the weak axis (h = 2 mm, sway along z), 8.22e-3 about the strong one. At eps = 1e-3 the
 * tangent is definite; at 4e-3 it has exactly one negative pivot and csf_pathCriticalMode must
 * return that negative eigenvalue's mode (not the smallest |lambda|), an eigenpair of K to its
 * residual, zero on the clamp, swaying along z. Measured (20 x 4 x 2 Tet10 boxes, 1.9 s): 0 and 1
 * negative pivots; lambda 2.2e-7 and -5.4e-7 N/mm, the sway carrying 99.9 % of |phi|^2, largest
 * at the free end. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "fem_path.h"
#include "fem_test_util.h"

#define COL_L 40.0  /* mm */
#define COL_B 4.0   /* mm, along y */
#define COL_H 2.0   /* mm, along z: the weak axis */
#define COL_C10 0.11 /* MPa */
#define COL_C20 0.02 /* MPa */

/* the column at axial strain eps (straight state by a 4-step ramp), its critical mode */
static void columnMode(double eps, csfCriticalMode* cm, double* kres, double* sway_z,
                       double* sway_y, double* phi_fixed) {
  csError err = {0};
  int n[3] = {20, 4, 2};
  double sc[3] = {COL_L, COL_B, COL_H};
  csfMesh* me = csf_meshCreateBox(n, ftScaleMap, sc, 0.0, &err);
  csfMaterial mat = csf_materialDefault(COL_C10, COL_C20, 0.0);
  csfModel* m = csf_modelCreate(me, &mat, &err);
  for (int c = 0; c < 3; c++) {
    ftFix(m, 0, 0.0, c, 0.0);
  }
  ftFix(m, 0, COL_L, 0, -eps * COL_L);
  m->solver.symmetric = 1;
  CS_EXPECT(csf_modelFinalize(m, &err) == CS_OK);
  csfData* d = csf_dataCreate(m, &err);
  CS_EXPECT(ftRamp(m, d, 4, &err) == CS_OK);
  const int nd = m->ndof;
  double* phi = calloc((size_t)nd, sizeof(double));
  double* w = calloc((size_t)nd, sizeof(double));
  double* kp = calloc((size_t)nd, sizeof(double));
  CS_EXPECT(csf_pathCriticalMode(m, d, 60, phi, w, cm, &err) == CS_OK);
  /* |K phi - lambda phi| with the state's own tangent (d->kval: K, not the shifted copy) */
  csf_tangentApply(m, d, phi, kp);
  double r2 = 0, z2 = 0, y2 = 0, f2 = 0;
  for (int i = 0; i < nd; i++) {
    if (m->fixed[i]) {
      f2 += phi[i] * phi[i];
      continue;
    }
    r2 += (kp[i] - cm->lambda * phi[i]) * (kp[i] - cm->lambda * phi[i]);
    z2 += i % 3 == 2 ? phi[i] * phi[i] : 0.0;
    y2 += i % 3 == 1 ? phi[i] * phi[i] : 0.0;
  }
  *kres = sqrt(r2), *sway_z = z2, *sway_y = y2, *phi_fixed = sqrt(f2);
  free(phi), free(w), free(kp);
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
}


static void test_critical_mode_of_a_compressed_column(void) {
  const double eps_cr = CS_PI * CS_PI * COL_H * COL_H / (12.0 * COL_L * COL_L);
  const double eps[2] = {0.5 * eps_cr, 2.0 * eps_cr};
  for (int k = 0; k < 2; k++) {
    csfCriticalMode cm;
    double kres, z2, y2, f;
    columnMode(eps[k], &cm, &kres, &z2, &y2, &f);
    printf("  eps %.3e (Euler, weak axis: %.3e): %d negative pivots, lambda %.4g N/mm, sigma "
           "%.3g (%d shifted factorisations), %d solves, |K phi - lambda phi| %.2e, sway z %.3f "
           "y %.3f of |phi|^2, largest at (%.1f, %.1f, %.1f)\n", eps[k], eps_cr, cm.neg_pivots,
           cm.lambda, cm.sigma, cm.n_shift, cm.iters, kres, z2, y2, cm.X_max[0], cm.X_max[1],
           cm.X_max[2]);
    CS_EXPECT(cm.neg_pivots == k);
    CS_EXPECT(f == 0.0);
    if (k == 0) {
      CS_EXPECT(cm.lambda > 0 && cm.sigma == 0.0);
      continue;
    }
    CS_EXPECT(cm.lambda < 0 && cm.sigma <= cm.lambda);
    /* an eigenpair of K: measured |K phi - lambda phi| 2.3e-13 against lambda -5.4e-7 N/mm
     * (4e-7 relative, 5 solves at rate ~0.1 from the shift -5.9e-7); 1e-5 leaves margin */
    CS_EXPECT(kres <= 1e-5 * fabs(cm.lambda));
    /* weak-axis sway: the z components carry most of the mode, largest away from the clamp */
    CS_EXPECT(z2 > 0.8 && y2 < 0.05);
    CS_EXPECT(cm.X_max[0] > 0.5 * COL_L);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_critical_mode_of_a_compressed_column);
  return cs_testSummary();
}

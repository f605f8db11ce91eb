/* test_fem_gravity.c: the gravity body load. A silicone cantilever block (Elastosil density and
 * Yeoh constants) clamped at x = 0 sags under its own weight:
 *  - the clamp reaction equals the weight rho g V exactly (the load vector integrates N_a rho g
 *    with the 4-point rule, exact for the P2 shape functions on straight tetrahedra);
 *  - at small load the tip deflection approaches the beam value (Euler-Bernoulli plus the
 *    Timoshenko shear term, E = 6 C10, G = 2 C10 for the incompressible limit) as the mesh is
 *    refined;
 *  - the sag is linear in g at small load and reverses with g. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cs_test.h"
#include "fem_test_util.h"

#define BEAM_L 40.0   /* mm */
#define BEAM_H 4.0    /* mm, square section */
#define RHO 1130e-12  /* t/mm^3, Elastosil M4601 (docs/reference.md) */
#define C10 0.11      /* MPa */
#define C20 0.02      /* MPa */
/* 0.1 of Earth's gravity, mm/s^2: tip deflection ~ 1 % of L, so geometric nonlinearity and the
 * C20 stiffening stay below the mesh error measured below (the load is a test input, not the
 * real gravity: the point is the body-load implementation) */
#define GRAV 981.0

/* tip deflection (-u_y of the node at x = L, y = 0 on the mid-plane z = H/2), reaction sum */
static double sag(int nl, int nh, double g, double* reaction, double* weight) {
  csError err = {0};
  int n[3] = {nl, nh, nh};
  double sc[3] = {BEAM_L, BEAM_H, BEAM_H};
  csfMesh* me = csf_meshCreateBox(n, ftScaleMap, sc, 0.0, &err);
  csfMaterial mat = csf_materialDefault(C10, C20, RHO);
  csfModel* m = csf_modelCreate(me, &mat, &err);
  for (int c = 0; c < 3; c++) {
    ftFix(m, 0, 0.0, c, 0.0); /* clamped at x = 0 */
  }
  m->gravity[1] = -g;
  csf_modelFinalize(m, &err);
  csfData* d = csf_dataCreate(m, &err);
  csfNewtonOptions o = csf_newtonDefault();
  int it = 0;
  CS_EXPECT(csf_newtonSolve(m, d, 0.0, &o, &it, &err) == CS_OK);
  double w = NAN;
  for (int i = 0; i < me->nnode; i++) {
    const double* X = me->x + 3 * i;
    if (fabs(X[0] - BEAM_L) < 1e-9 && fabs(X[1]) < 1e-9 && fabs(X[2] - 0.5 * BEAM_H) < 1e-9) {
      w = -d->u[3 * i + 1];
    }
  }
  double vol = 0;
  for (int e = 0; e < me->ntet; e++) {
    vol += m->vol[e];
  }
  *weight = RHO * g * vol;
  *reaction = csf_reactionSum(m, d, 1); /* internal force on the clamp, +y holds the weight */
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
  return w;
}


static void test_cantilever_self_weight(void) {
  /* beam reference: q = rho g A (N/mm), I = H^4/12, E = 6 C10, G = E/3, shear factor 5/6 */
  const double A = BEAM_H * BEAM_H, I = BEAM_H * BEAM_H * BEAM_H * BEAM_H / 12.0;
  const double E = 6.0 * C10, G = E / 3.0, q = RHO * GRAV * A;
  const double w_eb = q * pow(BEAM_L, 4) / (8.0 * E * I);
  const double w_ref = w_eb + q * BEAM_L * BEAM_L / (2.0 * (5.0 / 6.0) * G * A);
  const int nl[3] = {10, 20, 40}, nh[3] = {1, 2, 4};
  double w[3], rx[3], wt[3];
  for (int k = 0; k < 3; k++) {
    w[k] = sag(nl[k], nh[k], GRAV, &rx[k], &wt[k]);
    printf("  mesh %2dx%dx%d: tip sag %.6f mm (beam %.6f, EB only %.6f: %+.2f %%), reaction "
           "%.6e N, weight %.6e N\n",
           nl[k], nh[k], nh[k], w[k], w_ref, w_eb, 100.0 * (w[k] / w_ref - 1.0), rx[k], wt[k]);
    /* the body load integrates to the weight: round-off and Newton's rtol 1e-8 of the force */
    CS_EXPECT_NEAR(rx[k], wt[k], 0, 1e-6);
  }
  /* measured against the beam value (Timoshenko 0.40794 mm): 10x1x1 +42.3 % (one mixed element
   * through the thickness is far too flexible, as in test_fem_locking), 20x2x2 +1.27 %, 40x4x4
   * -1.88 %. The last refinement still moves the sag by 3.1 %, converging from above, and the
   * beam model leaves out the 3D clamp (the incompressible section cannot contract at x = 0) and
   * is itself only O((H/L)^2) = 1 % accurate; 3 % covers both and still fails a body load that
   * is wrong by a constant factor (density, sign, quadrature weight) */
  CS_EXPECT_NEAR(w[2], w_ref, 0, 3e-2);
  /* the error must shrink under refinement */
  CS_EXPECT(fabs(w[2] - w_ref) < fabs(w[0] - w_ref));
  /* linear at small load: doubling g doubles the sag, reversing g reverses it */
  double r2, wt2, rm, wtm;
  const double w2 = sag(nl[1], nh[1], 2.0 * GRAV, &r2, &wt2);
  const double wm = sag(nl[1], nh[1], -GRAV, &rm, &wtm);
  printf("  2g: %.6f mm (ratio %.5f); -g: %.6f mm\n", w2, w2 / w[1], wm);
  /* measured: ratio 1.99860, -g gives -0.413481 vs 0.413108 mm (0.09 %): the second-order
   * (geometric) part at 1 % deflection; 5e-3 is five times that */
  CS_EXPECT_NEAR(w2 / w[1], 2.0, 0, 5e-3);
  CS_EXPECT_NEAR(wm, -w[1], 0, 5e-3);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_cantilever_self_weight);
  return cs_testSummary();
}

/* test_fem_wall.c: the free-surface measures of fem_wall.h against closed forms.
 * - homogeneous deformation: a jittered box under F = R diag(l, 1, 1/l) has in-surface
 *   stretches (l, 1) on the faces normal to e3, (l, 1/l) normal to e2, (1/l, 1) normal to e1;
 *   the gap between its faces x = 0 and x = L is l L.
 * - a ring squashed to an ellipse: the bore's gap between walls 120 deg apart is 2 k a sin 60,
 *   within the sagitta of the straight sub-triangles.
 * - a solved plane-strain compression of a Yeoh block (rollers, free top face): the top face's
 *   plane-strain-equivalent stretch equals the prescribed l at every load step and passes the
 *   crease onset exactly at the step where l does; the side face's second stretch is 1/l to
 *   within the element dilatation. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "cs_test.h"
#include "fem_test_util.h"
#include "fem_wall.h"

#define BOX 4.0     /* mm, edge of the block */
#define RING_A 2.0  /* mm, bore radius of the ring */
#define RING_B 3.0  /* mm, outer radius */
#define RING_H 4.0  /* mm, length */
#define RING_N 12   /* elements around: Tri6 corners every 15 deg on the bore */

/* rounding of the measure: the metrics and a quadratic's roots in double from O(1) data */
static const double kTolRound = 1e-10;

/* full ring: xi0 radial (a..b), xi1 around (0..2 pi; the seam's nodes are duplicated, which the
 * measures do not mind), xi2 along z */
static void ringMap(void* user, const double xi[3], double x[3]) {
  (void)user;
  const double r = RING_A + (RING_B - RING_A) * xi[0], th = 2.0 * CS_PI * xi[1];
  x[0] = r * cos(th);
  x[1] = r * sin(th);
  x[2] = RING_H * xi[2];
}


/* u = (F - I) X on every node */
static void applyF(const csfMesh* me, const double F[9], double* u) {
  for (int n = 0; n < me->nnode; n++) {
    const double* X = me->x + 3 * n;
    for (int i = 0; i < 3; i++) {
      u[3 * n + i] = F[3 * i] * X[0] + F[3 * i + 1] * X[1] + F[3 * i + 2] * X[2] - X[i];
    }
  }
}


static void test_homogeneous(void) {
  csError err = {0};
  const int n[3] = {3, 3, 3};
  const double sc[3] = {BOX, BOX, BOX};
  csfMesh* me = csf_meshCreateBox(n, ftScaleMap, (void*)sc, 0.1, &err);
  CS_EXPECT(me != NULL);
  if (!me) {
    return;
  }
  double* u = calloc((size_t)3 * me->nnode, sizeof *u);
  const double l = 0.6, c = cos(0.3), s = sin(0.3);
  /* F = R diag(l, 1, 1/l), R about e3 by 0.3 rad (stretches are frame-indifferent) */
  const double F[9] = {c * l, -s, 0, s * l, c, 0, 0, 0, 1.0 / l};
  applyF(me, F, u);
  const int tz[2] = {5, 6}, ty[2] = {3, 4}, tx[2] = {1, 2};
  csfWallStretch w;
  csf_wallStretch(me, u, 2, tz, &w);
  printf("  faces normal to e3: lam_c %.15f lam_t %.15f lam_eq %.15f (%d points)\n", w.lam_c,
         w.lam_t, w.lam_eq, w.npoint);
  CS_EXPECT(w.npoint == 6 * 2 * 2 * n[0] * n[1]);
  CS_EXPECT_NEAR(w.lam_c, l, kTolRound, 0);
  CS_EXPECT_NEAR(w.lam_t, 1.0, kTolRound, 0);
  CS_EXPECT_NEAR(w.lam_eq, l, kTolRound, 0);
  CS_EXPECT_NEAR(fabs(w.dir[0]), 1.0, kTolRound, 0); /* compressed along e1 */
  csf_wallStretch(me, u, 2, ty, &w);
  CS_EXPECT_NEAR(w.lam_c, l, kTolRound, 0);
  CS_EXPECT_NEAR(w.lam_t, 1.0 / l, kTolRound, 0);
  CS_EXPECT_NEAR(w.lam_eq, l * sqrt(1.0 / l), kTolRound, 0);
  csf_wallStretch(me, u, 2, tx, &w);
  CS_EXPECT_NEAR(w.lam_c, 1.0, kTolRound, 0);
  CS_EXPECT_NEAR(w.lam_t, 1.0 / l, kTolRound, 0);
  /* the gap between the faces x = 0 and x = L: l L */
  csfWallGap g;
  CS_EXPECT(csf_wallGap(me, u, 2, tx, -0.5, &g, &err) == CS_OK);
  printf("  gap between x = 0 and x = L: %.15f mm (reference %.15f)\n", g.gap, g.gap_ref);
  CS_EXPECT_NEAR(g.gap, l * BOX, kTolRound, 0);
  CS_EXPECT_NEAR(g.gap_ref, BOX, kTolRound, 0);
  /* one flat face has no pair facing each other: infinite gap */
  CS_EXPECT(csf_wallGap(me, u, 1, tx, -0.5, &g, &err) == CS_OK);
  CS_EXPECT(isinf(g.gap) && g.node == -1);
  free(u);
  csf_meshDestroy(me);
}


static void test_ring_gap(void) {
  csError err = {0};
  const int n[3] = {1, RING_N, 2};
  csfMesh* me = csf_meshCreateBox(n, ringMap, NULL, 0.0, &err);
  CS_EXPECT(me != NULL);
  if (!me) {
    return;
  }
  double* u = calloc((size_t)3 * me->nnode, sizeof *u);
  const int bore = 1; /* xi0 = 0 */
  const double k = 0.3;
  const double F[9] = {1, 0, 0, 0, k, 0, 0, 0, 1};
  applyF(me, F, u);
  csfWallGap g;
  CS_EXPECT(csf_wallGap(me, u, 1, &bore, -0.5, &g, &err) == CS_OK);
  /* points at least 120 deg apart on the ellipse (a cos t, k a sin t): the closest pair is
   * t = +-60 deg, 2 k a sin 60 deg apart (nodes sit every 30 deg); the straight sub-triangles
   * lie inside the ellipse by at most the sagitta of a 15 deg chord of the circle,
   * a (1 - cos 7.5 deg) (the squash only shortens chords) */
  const double sag = RING_A * (1.0 - cos(CS_PI / (4.0 * RING_N)));
  const double gap = 2.0 * k * RING_A * sin(CS_PI / 3.0);
  printf("  squashed ring: gap %.6f mm, closed form %.6f mm, sagitta %.4f mm; at (%.3f, %.3f, "
         "%.3f)\n", g.gap, gap, sag, g.X[0], g.X[1], g.X[2]);
  CS_EXPECT(g.gap <= gap + kTolRound);
  CS_EXPECT(g.gap >= gap - sag);
  CS_EXPECT(fabs(fabs(g.X[0]) - RING_A * 0.5) < 1e-9); /* at +-60 deg or +-120 deg */
  free(u);
  csf_meshDestroy(me);
}


static void test_plane_strain_compression(void) {
  csError err = {0};
  const int n[3] = {3, 3, 3};
  const double sc[3] = {BOX, BOX, BOX};
  csfMesh* me = csf_meshCreateBox(n, ftScaleMap, (void*)sc, 0.1, &err);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12); /* Elastosil, the actuator's */
  csfModel* m = csf_modelCreate(me, &mat, &err);
  CS_EXPECT(m != NULL);
  if (!m) {
    csf_meshDestroy(me);
    return;
  }
  /* rollers: x = 0 and x = L along e1 (compression), y = 0 and y = L in e2 (plane strain),
   * z = 0 in e3; the face z = L is free */
  const double l_end = 0.56, nstep = 11; /* l = 0.96, 0.92, ..., 0.56: crosses 0.65 once */
  ftFix(m, 0, 0.0, 0, 0.0);
  ftFix(m, 0, BOX, 0, (l_end - 1.0) * BOX);
  ftFix(m, 1, 0.0, 1, 0.0);
  ftFix(m, 1, BOX, 1, 0.0);
  ftFix(m, 2, 0.0, 2, 0.0);
  CS_EXPECT(csf_modelFinalize(m, &err) == CS_OK);
  csfData* d = csf_dataCreate(m, &err);
  csfNewtonOptions o = csf_newtonDefault();
  const int top = 6, side = 3;
  int first_past = -1;
  for (int s = 1; s <= nstep; s++) {
    const double load = s / nstep, l = 1.0 + load * (l_end - 1.0);
    if (csf_newtonSolve(m, d, load, &o, NULL, &err) != CS_OK) {
      fprintf(stderr, "step %d: %s\n", s, err.msg);
      CS_EXPECT(0);
      break;
    }
    double dev = 0;
    for (int e = 0; e < me->ntet; e++) {
      dev = fmax(dev, fabs(d->vratio[e] - 1.0));
    }
    csfWallStretch wt, ws;
    csf_wallStretch(me, d->u, 1, &top, &wt);
    csf_wallStretch(me, d->u, 1, &side, &ws);
    printf("  l %.2f: top lam_eq %.9f (lam_c %.9f, lam_t %.9f); side lam_c %.9f lam_t %.9f "
           "(1/l %.9f), max |v/V - 1| %.2e\n", l, wt.lam_eq, wt.lam_c, wt.lam_t, ws.lam_c,
           ws.lam_t, 1.0 / l, dev);
    /* the homogeneous state is the discrete solution (the mixed Tet10 passes the patch test):
     * the top face's free nodes sit there to Newton's tolerance, rtol 1e-8 of the force scale
     * on a ~0.1 MPa x 16 mm^2 block: 1e-7 in stretch is 10^2 above it */
    const double tol_newton = 1e-7;
    CS_EXPECT_NEAR(wt.lam_eq, l, tol_newton, 0);
    CS_EXPECT_NEAR(wt.lam_c, l, tol_newton, 0);
    CS_EXPECT_NEAR(wt.lam_t, 1.0, tol_newton, 0);
    /* the side: (l, l_z), l_z = v/V / l for the element dilatation, 1/l incompressible */
    CS_EXPECT_NEAR(ws.lam_c, l, tol_newton, 0);
    CS_EXPECT_NEAR(ws.lam_t, 1.0 / l, dev / l + tol_newton, 0);
    if (first_past < 0 && wt.lam_eq < CSF_CREASE_STRETCH) {
      first_past = s;
      CS_EXPECT(l < CSF_CREASE_STRETCH && l + (1.0 - l_end) / nstep > CSF_CREASE_STRETCH);
    }
  }
  CS_EXPECT(first_past > 0);
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_homogeneous);
  CS_RUN(test_ring_gap);
  CS_RUN(test_plane_strain_compression);
  return cs_testSummary();
}

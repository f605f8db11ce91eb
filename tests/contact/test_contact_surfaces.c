/* test_contact_surfaces.c: terrains beyond axis-aligned boxes, against closed forms.
 *
 * - A block on an incline (ODE's contacts, contact_ode.h) holds while tan(theta) < mu and
 *   slides with a = g (sin theta - mu cos theta) above it: on an oriented box with its own
 *   friction (the run's is different, so the box's must be the one used), and on a flat box
 *   with the terrain's `slope` (gravity turned instead of the ground), which must agree.
 * - The soft law's geometry is exact on an oriented box: a sphere, a capsule and the segment
 *   distance against a turned box equal those against the axis-aligned box in its frame,
 *   turned (distances are invariant under rigid motions), and libccd's MPR on the oriented box
 *   agrees to its tolerance.
 * - Friction per surface in the soft law: a box with its own mu gives the same forces and
 *   bristle rates, to the last bit, as the run's mu set to that value. */
#include <math.h>
#include <ode/ode.h>
#include <stdio.h>
#include <string.h>

#include "contact_ode.h"
#include "contact_soft.h"
#include "cs_test.h"
#include "terrains_ccd.h"
#include "terrains_hfield.h"

static const double kH = 1e-3;     /* s */
static const double kG = 9810.0;   /* mm/s^2 */
static const double kMass = 40e-6; /* t (40 g) */
static const double kDeg = 3.14159265358979323846 / 180.0;


/* A 30 x 10 x 30 mm block resting on an incline of theta (rad) for `seconds` after 0.1 s of
 * settling; returns its displacement (mm) along the downhill direction. turned = 1: the ground
 * is an oriented box turned by theta about +z with friction mu, the run's friction 0.8;
 * turned = 0: the ground is a flat box, gravity is turned (a terrain `slope`), the run's
 * friction mu. */
static double blockOnIncline(double theta, double mu, int turned, double seconds) {
  static cstTerrain t; /* ~33 KB with its heightfield: not on the stack */
  memset(&t, 0, sizeof t);
  cscContactParams p = csc_defaultContactParams();
  double up[3] = {0, 1, 0}; /* the ground's outward normal */
  if (turned == 2) {
    /* a heightfield built as the same inclined plane through the origin: 21 x 5 samples,
     * 2000 mm long as the box */
    cstHeightfield* hf = &t.hf;
    hf->nx = 21;
    hf->nz = 5;
    hf->x0 = -1000;
    hf->z0 = -150;
    hf->dx = 100;
    hf->dz = 75;
    for (int j = 0; j < hf->nz; j++) {
      for (int i = 0; i < hf->nx; i++) hf->h[j * hf->nx + i] = tan(theta) * (hf->x0 + i * hf->dx);
    }
    hf->hmin = hf->h[0];
    hf->hmax = hf->h[hf->nx - 1];
    hf->thickness = 20;
    hf->own_mu = 1;
    hf->mu = mu;
    t.has_hf = 1;
    t.has_mu = 1;
    p.mu = 0.8;
    up[0] = -sin(theta);
    up[1] = cos(theta);
  } else if (turned) {
    /* its top face through the origin: the centre 10 mm below along the turned normal */
    up[0] = -sin(theta);
    up[1] = cos(theta);
    double c[3] = {-10 * up[0], -10 * up[1], 0}, len[3] = {2000, 20, 300}, axis[3] = {0, 0, 1};
    cst_boxOriented(&t.box[0], c, len, axis, theta / kDeg, mu);
    t.has_mu = 1;
    p.mu = 0.8;
  } else {
    cstBox b = {.lo = {-1000, -20, -150}, .hi = {1000, 0, 150}};
    t.box[0] = b;
    t.slope_deg = theta / kDeg;
    p.mu = mu;
  }
  t.nbox = turned == 2 ? 0 : 1;
  double gdir[3];
  cst_terrainGravityDir(&t, gdir);
  if (turned) { /* gravity straight down; the ground turned (box or heightfield) */
    gdir[0] = 0;
    gdir[1] = -1;
  }
  dWorldID w = dWorldCreate();
  dWorldSetGravity(w, kG * gdir[0], kG * gdir[1], kG * gdir[2]);
  dSpaceID ground = dSimpleSpaceCreate(0), robot = dSimpleSpaceCreate(0);
  cst_terrainBuildOde(&t, ground);
  dBodyID b = dBodyCreate(w);
  dMass m;
  dMassSetBoxTotal(&m, kMass, 30, 10, 30);
  dBodySetMass(b, &m);
  /* resting on the surface: centre 5 mm along its normal, turned with it */
  dBodySetPosition(b, 5 * up[0], 5 * up[1], 0);
  dMatrix3 R;
  dRFromAxisAndAngle(R, 0, 0, 1, turned ? theta : 0);
  dBodySetRotation(b, R);
  dGeomID f = dCreateBox(robot, 30, 10, 30);
  dGeomSetBody(f, b);
  dJointGroupID group = dJointGroupCreate(0);
  cscContactStats st;
  double x0[3] = {0, 0, 0};
  int n = (int)((seconds + 0.1) / kH + 0.5);
  for (int i = 0; i < n; i++) {
    if (i == (int)(0.1 / kH + 0.5)) {
      memcpy(x0, dBodyGetPosition(b), sizeof x0);
    }
    csc_collide(&p, w, ground, robot, group, kH, &st);
    dWorldStep(w, kH); /* the exact LCP: the closed form is about friction, not PGS */
    dJointGroupEmpty(group);
  }
  const dReal* x = dBodyGetPosition(b);
  /* downhill: the turned ground falls towards -x; with turned gravity -x as well */
  double down[3] = {turned ? -cos(theta) : -1, turned ? -sin(theta) : 0, 0};
  double s = (x[0] - x0[0]) * down[0] + (x[1] - x0[1]) * down[1] + (x[2] - x0[2]) * down[2];
  dJointGroupDestroy(group);
  dSpaceDestroy(robot);
  cst_hfReleaseOde(ground);
  dSpaceDestroy(ground);
  dWorldDestroy(w);
  return s;
}


static void test_block_holds_below_and_slides_above_tan_mu(void) {
  const double mu = 0.5, T = 1.0;
  static const char* const kind[3] = {"slope", "oriented box", "heightfield"};
  for (int turned = 0; turned < 3; turned++) {
    /* 90 % of the limit: held. The contact spring's settling along the slope (m g sin / kp
     * ~ 2e-3 mm) is over before t0 = 0.1 s; 1e-4 mm over 1 s bounds the exact LCP's drift
     * (measured ~1e-9 mm) with room */
    double th = atan(0.9 * mu);
    double s = blockOnIncline(th, mu, turned, T);
    printf("  %s, tan = 0.9 mu: moved %.2e mm\n", kind[turned], s);
    CS_EXPECT_NEAR(s, 0.0, 1e-4, 0);
    /* 110 %: slides with a = g (sin - mu cos), the net 10 % of the friction force. 1 % of
     * the net (0.1 % of mu N) for the first-order time steps (measured 0.08 %) */
    th = atan(1.1 * mu);
    s = blockOnIncline(th, mu, turned, T);
    /* it slides from t = 0 (placed touching): s = a ((t0 + T)^2 - t0^2) / 2 after t0 */
    double a = kG * (sin(th) - mu * cos(th)), t0 = 0.1;
    double expect = 0.5 * a * ((t0 + T) * (t0 + T) - t0 * t0);
    printf("  %s, tan = 1.1 mu: slid %.2f mm, closed form %.2f mm\n", kind[turned], s, expect);
    CS_EXPECT_NEAR(s, expect, 0, 0.01);
  }
  /* the three ways of making a slope are the same physics: the slides agree to 1e-6 (the
   * solves differ by round-off only; measured 5e-15 for the oriented box) */
  double th = atan(1.3 * mu);
  double s0 = blockOnIncline(th, mu, 0, T), s1 = blockOnIncline(th, mu, 1, T);
  double s2 = blockOnIncline(th, mu, 2, T);
  printf("  tan = 1.3 mu: slope %.3f mm, oriented box %.3f mm, heightfield %.3f mm\n", s0, s1, s2);
  CS_EXPECT_NEAR(s1, s0, 0, 1e-6);
  CS_EXPECT_NEAR(s2, s0, 0, 1e-6);
}


/* a turned box and the same box axis-aligned in its own frame */
static void turnedBox(cstBox* ob, cstBox* ab) {
  double c[3] = {12, -7, 3}, len[3] = {40, 20, 30}, axis[3] = {0.3, 0.2, 1};
  CS_EXPECT(cst_boxOriented(ob, c, len, axis, 23, -1) == 1);
  memset(ab, 0, sizeof *ab);
  for (int k = 0; k < 3; k++) {
    ab->lo[k] = ob->lo[k];
    ab->hi[k] = ob->hi[k];
  }
}


static void test_oriented_box_geometry_equals_turned_aligned(void) {
  cstBox ob, ab;
  turnedBox(&ob, &ab);
  /* points and segments chosen in the box frame: outside a face, an edge, a corner, inside */
  const double pts[5][3] = {{0, 13, 0}, {22, 12, 0}, {21, 11, 16}, {5, 4, 2}, {-19, 0, -13.5}};
  for (int i = 0; i < 5; i++) {
    double xw[3], cpa[3], na[3], cpo[3], no[3], cpw[3], nw[3];
    cst_boxPointToWorld(&ob, pts[i], xw);
    double da = cst_boxSignedDistance(&ab, pts[i], cpa, na);
    double dd = cst_boxSignedDistance(&ob, xw, cpo, no);
    cst_boxPointToWorld(&ob, cpa, cpw);
    cst_boxDirToWorld(&ob, na, nw);
    /* round-off of one rotation and back: 1e-12 mm on 50 mm */
    CS_EXPECT_NEAR(dd, da, 1e-12, 0);
    for (int k = 0; k < 3; k++) {
      CS_EXPECT_NEAR(cpo[k], cpw[k], 1e-12, 0);
      CS_EXPECT_NEAR(no[k], nw[k], 1e-12, 0);
    }
    /* a sphere of radius 3 at the point: the same depth */
    cscPenetration pa, po;
    CS_EXPECT_NEAR(csc_sphereBoxPenetration(xw, 3, &ob, &po),
                   csc_sphereBoxPenetration(pts[i], 3, &ab, &pa), 1e-12, 0);
    /* a capsule from this point to the next one */
    const double* q = pts[(i + 1) % 5];
    double qw[3];
    cst_boxPointToWorld(&ob, q, qw);
    double sa, so;
    double ca = csc_capsuleBoxPenetration(pts[i], q, 2.5, &ab, &pa, &sa);
    double co = csc_capsuleBoxPenetration(xw, qw, 2.5, &ob, &po, &so);
    CS_EXPECT_NEAR(co, ca, 1e-12, 0);
    /* the segment's squared distance: the same piecewise quadratic */
    cscSegBox qa, qo;
    csc_segBoxInit(&qa, pts[i], q, &ab);
    csc_segBoxInit(&qo, xw, qw, &ob);
    if (qa.q_min > 1e-6) {
      /* axis outside the box: a unique deepest point and normal (with the axis inside, the
       * separating-axis test's ties between equally deep stretches go either way on
       * round-off, and the depth above is what the law uses) */
      CS_EXPECT_NEAR(so, sa, 1e-12, 0);
      double nt[3];
      cst_boxDirToWorld(&ob, pa.normal, nt);
      for (int k = 0; k < 3; k++) CS_EXPECT_NEAR(po.normal[k], nt[k], 1e-12, 0);
    }
    CS_EXPECT_NEAR(qo.q_min, qa.q_min, 1e-9, 0); /* mm^2 */
    CS_EXPECT_NEAR(csc_segBoxEval(&qo, 0.37), csc_segBoxEval(&qa, 0.37), 1e-9, 0);
  }
  /* libccd's MPR with the oriented box's support function: a 6 mm cube sunk 1 mm into the
   * top face (box frame y = 10), turned with the box; MPR's tolerance is 1e-9 mm, 1e-6 for
   * its iterations' round-off on a face contact */
  cscCcdShape s;
  memset(&s, 0, sizeof s);
  s.kind = CSC_CCD_BOX;
  double cl[3] = {3, 12, -4};
  cst_boxPointToWorld(&ob, cl, s.c);
  for (int k = 0; k < 9; k++) s.R[k] = ob.R[k];
  s.h[0] = s.h[1] = s.h[2] = 3;
  cscPenetration pc;
  CS_EXPECT(csc_ccdPenetration(&s, &ob, NULL, &pc) == 1);
  CS_EXPECT_NEAR(pc.depth, 1.0, 1e-6, 0);
  double ny[3], yl[3] = {0, 1, 0};
  cst_boxDirToWorld(&ob, yl, ny);
  for (int k = 0; k < 3; k++) CS_EXPECT_NEAR(pc.normal[k], ny[k], 1e-6, 0);
}


/* one foot pressed into a box and sliding: loads and bristle rates */
static void footLoads(const cstTerrain* t, double mu_run, cscShapeLoad* ld, double zd[4]) {
  cscSoftParams p = csc_softDefaultParams();
  p.mu = mu_run;
  cscShape sh = csc_softFoot(7.5);
  csError err;
  cscSoftModel* m = csc_softCreate(&p, t, 1, &sh, &err);
  CS_EXPECT(m != NULL);
  if (!m) return;
  cscShapeState st;
  memset(&st, 0, sizeof st);
  /* sole 2 um into the top face (y = 0), e3 = -y points out of the sole */
  double R[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(st.R, R, sizeof R);
  st.x0[1] = -0.002; /* the sole's face (its spheres' lowest points) 2 um deep */
  st.v0[0] = 3;           /* slipping 3 mm/s */
  double z[4] = {0.004, 0, 0.001, 0};
  CS_EXPECT(csc_softNState(m) == 4);
  CS_EXPECT(csc_softCompute(m, &st, z, ld, zd, NULL, NULL) == 0);
  csc_softDestroy(m);
}


static void test_own_friction_equals_run_friction(void) {
  cstTerrain t;
  memset(&t, 0, sizeof t);
  cstBox b = {.lo = {-100, -20, -100}, .hi = {100, 0, 100}};
  t.box[0] = b;
  t.nbox = 1;
  cscShapeLoad l0, l1, l2;
  double z0[4], z1[4], z2[4];
  footLoads(&t, 0.3, &l0, z0); /* the run's mu */
  t.box[0].own_mu = 1;
  t.box[0].mu = 0.3;
  t.has_mu = 1;
  footLoads(&t, 0.9, &l1, z1); /* the box's own, the run's ignored */
  CS_EXPECT(memcmp(&l0, &l1, sizeof l0) == 0);
  CS_EXPECT(memcmp(z0, z1, sizeof z0) == 0);
  /* and it matters: the run's 0.9 gives another friction force */
  t.box[0].own_mu = 0;
  t.has_mu = 0;
  footLoads(&t, 0.9, &l2, z2);
  CS_EXPECT(fabs(l2.f0[0] - l0.f0[0]) > 1e-6 * fabs(l0.f0[1]));
  printf("  friction force x: own mu 0.3 %.6g N, run mu 0.3 %.6g N, run mu 0.9 %.6g N\n",
         l1.f0[0], l0.f0[0], l2.f0[0]);
}


/* loads of a foot and a capsule on terrain t (shapes pressed into the plane y = tan(th) x) */
static void shapesOnPlane(const cstTerrain* t, double th, cscShapeLoad ld[2], double zd[7],
                          cscSoftReport* rep) {
  cscSoftParams p = csc_softDefaultParams();
  cscShape sh[2] = {csc_softFoot(7.5), csc_softCapsule(7.5)};
  csError err;
  cscSoftModel* m = csc_softCreate(&p, t, 2, sh, &err);
  CS_EXPECT(m != NULL);
  if (!m) return;
  cscShapeState st[2];
  memset(st, 0, sizeof st);
  /* the foot: its sole in the plane, 3 um deep, e3 = -(plane normal) */
  double nrm[3] = {-sin(th), cos(th), 0}, tng[3] = {cos(th), sin(th), 0};
  double R[9] = {tng[0], 0, -nrm[0], tng[1], 0, -nrm[1], tng[2], 1, -nrm[2]};
  memcpy(st[0].R, R, sizeof R);
  for (int k = 0; k < 3; k++) st[0].x0[k] = 40 * tng[k] - 0.003 * nrm[k];
  st[0].v0[0] = 2;
  /* the capsule: an axis 60 mm long, tilted against the plane so that one end dips 5 um in */
  for (int k = 0; k < 3; k++) {
    st[1].x0[k] = -60 * tng[k] + (7.5 - 0.005) * nrm[k];
    st[1].x1[k] = st[1].x0[k] + 60 * tng[k] + 3 * nrm[k];
  }
  st[1].x0[2] = st[1].x1[2] = 20;
  double z[7] = {0.002, 0, 0, 0, 0.001, 0, 0};
  CS_EXPECT(csc_softNState(m) == 7);
  memset(rep, 0, sizeof *rep);
  CS_EXPECT(csc_softCompute(m, st, z, ld, zd, NULL, rep) == 0);
  csc_softDestroy(m);
}


static void test_heightfield_plane_equals_plane(void) {
  const double th = 10 * kDeg;
  static cstTerrain hfT, boxT;
  memset(&hfT, 0, sizeof hfT);
  memset(&boxT, 0, sizeof boxT);
  cstHeightfield* hf = &hfT.hf;
  hf->nx = 7;
  hf->nz = 4;
  hf->x0 = -150;
  hf->z0 = -60;
  hf->dx = 50;
  hf->dz = 40;
  for (int j = 0; j < hf->nz; j++) {
    for (int i = 0; i < hf->nx; i++) hf->h[j * hf->nx + i] = tan(th) * (hf->x0 + i * hf->dx);
  }
  hf->hmin = hf->h[0];
  hf->hmax = hf->h[hf->nx - 1];
  hf->thickness = 20;
  hfT.has_hf = 1;
  /* the same plane as an oriented box's top face: centre 10 mm under the origin */
  double c[3] = {10 * sin(th), -10 * cos(th), 0}, len[3] = {400, 20, 300}, axis[3] = {0, 0, 1};
  cst_boxOriented(&boxT.box[0], c, len, axis, 10, -1);
  boxT.nbox = 1;
  /* the surface height: the plane's, 1e-12 mm */
  for (double x = -140; x < 150; x += 37) {
    CS_EXPECT_NEAR(cst_hfHeightAt(hf, x, 11), tan(th) * x, 1e-12, 0);
  }
  cscShapeLoad lh[2], lb[2];
  double zh[7], zb[7];
  cscSoftReport rh, rb;
  shapesOnPlane(&hfT, th, lh, zh, &rh);
  shapesOnPlane(&boxT, th, lb, zb, &rb);
  printf("  foot: heightfield F = (%.9g, %.9g) N, box (%.9g, %.9g) N; capsule Fy %.9g / %.9g N\n",
         lh[0].f0[0], lh[0].f0[1], lb[0].f0[0], lb[0].f0[1], lh[1].f0[1] + lh[1].f1[1],
         lb[1].f0[1] + lb[1].f1[1]);
  CS_EXPECT(rh.ncontact == 2 && rb.ncontact == 2);
  /* the foot: the same sphere distances to round-off (1e-9 relative); the capsule's stretch is
   * bisected to 2^-40 of the axis on the heightfield, exact roots on the box: 1e-7 relative */
  for (int k = 0; k < 3; k++) {
    CS_EXPECT_NEAR(lh[0].f0[k], lb[0].f0[k], 1e-12, 1e-9);
    CS_EXPECT_NEAR(lh[0].m[k], lb[0].m[k], 1e-9, 1e-9);
    CS_EXPECT_NEAR(lh[1].f0[k], lb[1].f0[k], 1e-12, 1e-7);
    CS_EXPECT_NEAR(lh[1].f1[k], lb[1].f1[k], 1e-12, 1e-7);
  }
  for (int k = 0; k < 7; k++) CS_EXPECT_NEAR(zh[k], zb[k], 1e-12, 1e-7);
  CS_EXPECT(fabs(lh[1].f0[1] + lh[1].f1[1]) > 0); /* the capsule does touch */
  /* ODE: a box resting into both surfaces gets the same contact depth and normal */
  dSpaceID s1 = dSimpleSpaceCreate(0), s2 = dSimpleSpaceCreate(0);
  dGeomID gh = cst_hfBuildOde(hf, s1);
  cst_terrainBuildOde(&boxT, s2);
  dGeomID gb = dSpaceGetGeom(s2, 0);
  dGeomID probe = dCreateBox(0, 30, 10, 30);
  dMatrix3 Rp;
  dRFromAxisAndAngle(Rp, 0, 0, 1, th);
  dGeomSetRotation(probe, Rp);
  dGeomSetPosition(probe, 20 * cos(th) - (5 - 0.01) * sin(th),
                   20 * sin(th) + (5 - 0.01) * cos(th), 0);
  dContactGeom ch[8], cb[8];
  int nh = dCollide(gh, probe, 8, ch, sizeof ch[0]), nbx = dCollide(gb, probe, 8, cb, sizeof cb[0]);
  CS_EXPECT(nh > 0 && nbx > 0);
  double dh = 0, db = 0;
  for (int i = 0; i < nh; i++) dh = fmax(dh, ch[i].depth);
  for (int i = 0; i < nbx; i++) db = fmax(db, cb[i].depth);
  printf("  ODE: heightfield %d points, depth %.6g mm; box %d points, depth %.6g mm\n", nh, dh, nbx, db);
  CS_EXPECT_NEAR(dh, 0.01, 1e-9, 0); /* 10 um, as placed */
  CS_EXPECT_NEAR(db, 0.01, 1e-9, 0);
  dGeomDestroy(probe);
  cst_hfReleaseOde(s1);
  dSpaceDestroy(s1);
  dSpaceDestroy(s2);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  dInitODE2(0);
  CS_RUN(test_block_holds_below_and_slides_above_tan_mu);
  CS_RUN(test_oriented_box_geometry_equals_turned_aligned);
  CS_RUN(test_own_friction_equals_run_friction);
  CS_RUN(test_heightfield_plane_equals_plane);
  dCloseODE();
  return cs_testSummary();
}

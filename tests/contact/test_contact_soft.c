/* test_contact_soft.c: the soft contact law (contact_soft.h): normal force against the closed
 * forms of the elastic foundation, never pulling and continuous; a foot resting flat; and the
 * elasto-plastic friction on a rigid foot block integrated by CVODE BDF with the contact in its
 * right-hand side, in both history modes.
 *
 * The block: 40 g, a 15 x 15 x 15 mm cube whose bottom face is the foot (the leg's 2a x 2a
 * sole), moving in the x-y plane (x, y, rotation about z) under gravity plus a downward load so
 * that the normal load is 0.8 N (a stance leg's share of the 0.33 kg robot); mu = 0.8. After
 * 0.1 s at rest it is pushed at the sole's centre (no tipping moment) by F, ramped over 20 ms
 * (smoothstep) and then held.
 *
 * Measured (printed by the cases), mu N = 0.64 N, push held 2 s at 0.9 mu N and 0.5 s when
 * sliding; "rhs" counts CVODE's right-hand sides including its dense Jacobian's:
 *   history, foot          0.9 mu N creep      1.1 mu N friction   2 mu N friction    rhs
 *   integrated, patch      2.7e-9 um/s         1.00000 mu N        1.00000 mu N       770-1754
 *   integrated, points     1.2e-5 um/s         1.00000             1.00000            1164-1822
 *   step, H = 1 ms         2.1e-7 um/s         1.00000             1.00000            31k-110k
 *   step, H = 10 ms        4.0e-7 um/s         1.00000             1.00000            5.0k-45k
 * (kinematic friction F - m a; the contact's own force at the end agrees to 0.25 %.) Both
 * histories meet the requirement; integrated costs 6-60x fewer right-hand sides because step
 * mode restarts BDF (order 1, new Jacobian) at every update: hence the default. Under the
 * same 2 mu N push ODE's contacts resist 0.483 mu N (the block of tests/contact/test_contact.c).
 * Shaken at 0.6 +- 0.15 mu N (40 Hz) the default foot drifts 8e-8 um/s, a fully plastic
 * bristle (u_elastic = 0) 62 um/s. */
#include <cvode/cvode.h>
#include <math.h>
#include <nvector/nvector_serial.h>
#include <stdio.h>
#include <string.h>
#include <sundials/sundials_types.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <time.h>

#include "contact_soft.h"
#include "contact_soft_internal.h"
#include "core_math.h"
#include "cs_test.h"

_Static_assert(sizeof(sunrealtype) == sizeof(double), "crawlsim needs double SUNDIALS");

static const double kMass = 40e-6;   /* t: 40 g */
static const double kLoad = 0.8;     /* N: normal load on the foot: its weight 0.39 N + 0.41 N */
static const double kHalf = 7.5;     /* mm: half side of the block and its sole */
static const double kTPush = 0.1;    /* s: start of the push */
static const double kRamp = 0.02;    /* s: push ramp */

/* the ground: a 200 m long slab whose top is y = 0 (a 2 mu N push slides 8 m in 1 s) */
static cstTerrain groundTerrain(void) {
  cstTerrain t;
  memset(&t, 0, sizeof t);
  t.nbox = 1;
  t.box[0] = (cstBox){.lo = {-1e5, -20, -150}, .hi = {1e5, 0, 150}};
  return t;
}


/* ---------------------------------------------------------------------------------------- */
/* static checks of the law                                                                  */

/* a foot of half side a at the origin's ground, sole at height y (mm), level, at rest */
static cscShapeState footAt(double y) {
  cscShapeState s;
  memset(&s, 0, sizeof s);
  csu_set3(s.x0, 0, y, 0);
  /* columns e1 = +x, e2 = +z, e3 = -y (outward sole normal, down) */
  double R[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(s.R, R, sizeof R);
  return s;
}


static void test_soft_normal_foot_flat_closed_form(void) {
  cscSoftParams p = csc_softDefaultParams();
  p.foot = CSC_FOOT_POINTS; /* a slot per sole point: each one's load is visible */
  cstTerrain t = groundTerrain();
  for (int nside = 2; nside <= 5; nside++) {
    cscShape sh = csc_softFoot(kHalf);
    sh.nside = nside;
    csError err;
    cscSoftModel* m = csc_softCreate(&p, &t, 1, &sh, &err);
    CS_EXPECT(m != NULL);
    double z[5 * 5 * 4];
    csc_softStateInit(m, z);
    cscShapeState st = footAt(-0.01);
    cscShapeLoad ld;
    cscSlotInfo info[25];
    cscSoftReport rep;
    CS_EXPECT(csc_softCompute(m, &st, z, &ld, NULL, info, &rep) == 0);
    /* the foundation under a flat sole: N = k (2a)^2 d, exact because d >= d_onset and the
     * Lobatto weights sum to the sole's area; round-off of ~25 products: 1e-13 relative */
    double N = p.k_area * 4 * kHalf * kHalf * 0.01;
    CS_EXPECT_NEAR(ld.f0[1], N, 0, 1e-13);
    CS_EXPECT_NEAR(ld.f0[0], 0, 1e-15, 0);
    /* a flat sole: no moment about its centre (symmetric to round-off, 1e-13 N mm) */
    CS_EXPECT_NEAR(csu_norm3(ld.m), 0, 1e-13, 0);
    CS_EXPECT(rep.ncontact == nside * nside && rep.nsliding == 0);
    CS_EXPECT_NEAR(rep.max_depth, 0.01, 1e-15, 1e-12);
    /* equal pressure under every sole point: N_i = k d A_i with A_i the point's Gauss-Lobatto
     * weight of the sole (Abramowitz & Stegun 25.4.32, tabulated here independently) */
    static const double lw[4][5] = {{1, 1},
                                    {1.0 / 3, 4.0 / 3, 1.0 / 3},
                                    {1.0 / 6, 5.0 / 6, 5.0 / 6, 1.0 / 6},
                                    {0.1, 49.0 / 90, 32.0 / 45, 49.0 / 90, 0.1}};
    for (int k = 0; k < nside * nside; k++) {
      double A = kHalf * kHalf * lw[nside - 2][k / nside] * lw[nside - 2][k % nside];
      CS_EXPECT_NEAR(info[k].N, p.k_area * 0.01 * A, 0, 1e-13);
    }
    if (nside == 2) {
      /* 2 x 2: the corners carry a quarter each */
      for (int k = 0; k < 4; k++) CS_EXPECT_NEAR(info[k].N, N / 4, 0, 1e-13);
    }
    csc_softDestroy(m);
  }
}


/* one capsule (axis p0 -> p1, radius r) at rest against terrain t: the total force f (N) */
static void capsuleForce(const cscSoftParams* p, double r, const double p0[3],
                         const double p1[3], const cstTerrain* t, double f[3]) {
  cscShape sh = csc_softCapsule(r);
  csError err;
  cscSoftModel* m = csc_softCreate(p, t, 1, &sh, &err);
  double z[4];
  csc_softStateInit(m, z);
  cscShapeState st;
  memset(&st, 0, sizeof st);
  csu_copy3(st.x0, p0);
  csu_copy3(st.x1, p1);
  cscShapeLoad ld;
  CS_EXPECT(csc_softCompute(m, &st, z, &ld, NULL, NULL, NULL) == 0);
  csu_add3(f, ld.f0, ld.f1);
  /* normal line loads act through the axis: no couple */
  CS_EXPECT(csu_norm3(ld.m) == 0);
  csc_softDestroy(m);
}


static void test_soft_normal_capsule_closed_forms(void) {
  cscSoftParams p = csc_softDefaultParams();
  p.d_onset = 1e-9; /* isolate the quadrature: the onset changes these integrals by (1e-9/d)^2.5 */
  cstTerrain t = groundTerrain();
  double r = 7.5, L = 10, d = 0.02, f[3];
  double kline = p.k_area * (4.0 / 3.0) * sqrt(2 * r);
  /* lying flat: constant depth, so Gauss is exact: F = k_line d^1.5 L (round-off 1e-14) */
  capsuleForce(&p, r, (double[3]){0, r - d, 0}, (double[3]){L, r - d, 0}, &t, f);
  CS_EXPECT_NEAR(f[1], kline * pow(d, 1.5) * L, 0, 1e-13);
  /* tilted by th with its low end d deep: the depth falls linearly along the axis, d - xi sin
   * th, to 0 at xi = d / sin th, so F = k_line d^1.5 (d / sin th) / 2.5. Measured quadrature
   * error with 4 points: see the print (the integrand ends as (s - s_a)^1.5); 8 points must do
   * better */
  double th = atan(d / 6.0);
  double p0[3] = {0, r - d, 0}, p1[3] = {L * cos(th), r - d + L * sin(th), 0};
  capsuleForce(&p, r, p0, p1, &t, f);
  double expect = kline * pow(d, 1.5) * (d / sin(th)) / 2.5;
  cscSoftParams p8 = p;
  p8.nquad = 8;
  double f8[3];
  capsuleForce(&p8, r, p0, p1, &t, f8);
  printf("  tilted capsule: F = %.9g N, closed form %.9g N: %.2e (4 points), %.2e (8 points)\n",
         f[1], expect, f[1] / expect - 1, f8[1] / expect - 1);
  /* measured -1.2e-4 with 4 points, -4.8e-6 with 8 */
  CS_EXPECT_NEAR(f[1], expect, 0, 5e-4);
  CS_EXPECT(fabs(f8[1] / expect - 1) < fabs(f[1] / expect - 1));
  /* against a step's edge, the axis at distance e = r - d from the edge line, the normal at
   * 45 deg: (1) parallel to the edge, a line load k_line d^1.5 over 20 mm along (-1, 1)/sqrt 2 */
  cstTerrain step = t;
  step.box[0] = (cstBox){.lo = {50, 0, -150}, .hi = {300, 40, 150}};
  double e = r - d, cx = 50 - e / sqrt(2), cy = 40 + e / sqrt(2);
  capsuleForce(&p, r, (double[3]){cx, cy, -10}, (double[3]){cx, cy, 10}, &step, f);
  CS_EXPECT_NEAR(f[1], kline * pow(d, 1.5) * 20 / sqrt(2), 0, 1e-12);
  CS_EXPECT_NEAR(f[0], -f[1], 0, 1e-12);
  /* (2) crossing the edge at right angles (axis along (1, 1, 0), tangent to the rounded edge):
   * the depth r - sqrt(e^2 + xi^2) falls off like a parabola, so the force is point-like,
   * pi k sqrt(r e) d^2 to O(d / r) = 3e-3 (the sphere's pi r k d^2 of the foundation); the
   * quadrature against a 20000-point midpoint rule of the same integrand */
  capsuleForce(&p, r, (double[3]){cx - 10, cy - 10, 0}, (double[3]){cx + 10, cy + 10, 0},
               &step, f);
  double Fc = csu_norm3(f), ref = 0, xmax = sqrt(r * r - e * e);
  for (int i = 0; i < 20000; i++) {
    double xi = -xmax + (i + 0.5) * 2 * xmax / 20000, rho = sqrt(e * e + xi * xi);
    ref += kline * pow(r - rho, 1.5) * (e / rho) * 2 * xmax / 20000;
  }
  double Fs = CS_PI * p.k_area * sqrt(r * e) * d * d;
  printf("  capsule across an edge: %.9g N, fine quadrature %.9g (%.2e), closed form %.9g"
         " (%.2e)\n", Fc, ref, Fc / ref - 1, Fs, Fc / Fs - 1);
  /* 4-point Gauss on a (1 - u^2)^1.5 profile: measured -1.6e-3 relative; 4e-3. The midpoint
   * reference itself is accurate to ~1e-6 */
  CS_EXPECT_NEAR(Fc, ref, 0, 4e-3);
  CS_EXPECT_NEAR(ref, Fs, 0, 3e-3);
}


static void test_soft_capsule_slides_onto_an_edge_smoothly(void) {
  /* a 10 mm capsule lying along x at 0.02 mm below the step's top level slides from the gap
   * side onto the step's top edge (x = 50) in 1 um steps: the contact stretch grows, so the
   * force grows by the line load k_line d^1.5 per mm, continuously and monotonically (the
   * rounded edge only spreads the onset). A chain of spheres at spacing h would instead bump by
   * up to (h/2)^2 / (2 r) in depth between them. */
  cscSoftParams p = csc_softDefaultParams();
  cstTerrain step = groundTerrain();
  step.box[0] = (cstBox){.lo = {50, 0, -150}, .hi = {300, 40, 150}};
  double r = 7.5, d = 0.02, L = 10, y = 40 + r - d, f[3], h = 1e-3;
  double lambda = p.k_area * (4.0 / 3.0) * sqrt(2 * r) * pow(d, 1.5);
  double prev = 0, slope_prev = 0, worst = 0, tv = 0;
  int falls = 0, n = 0;
  for (double x0 = 48; x0 <= 62; x0 += h, n++) {
    capsuleForce(&p, r, (double[3]){x0, y, 0}, (double[3]){x0 - L, y, 0}, &step, f);
    double F = csu_norm3(f);
    if (n > 0) {
      double slope = (F - prev) / h;
      worst = fmax(worst, fabs(slope));
      falls += slope < 0;
      if (n > 1) {
        tv += fabs(slope - slope_prev);
      }
      slope_prev = slope;
    }
    prev = F;
  }
  printf("  sliding onto an edge: max dF/dx %.5f N/mm (line load %.5f), total variation of the"
         " slope %.5f N/mm, %d falls\n", worst, lambda, tv, falls);
  CS_EXPECT(falls == 0);
  /* the slope is the line load once the stretch's end is on the face; the 4-point quadrature
   * of the rounded edge's tail (0.55 mm wide) shifts it by up to 8 % (measured 1.08); 10 % */
  CS_EXPECT(worst <= 1.1 * lambda);
  /* no bumps: the slope rises from 0 to ~lambda, wobbling smoothly with the quadrature, and
   * falls back to 0 when the whole capsule is on the top: its total variation stays a few
   * lambda (measured 2.5); a bumpy law would pile up variation at every bump */
  CS_EXPECT(tv <= 4 * lambda);
}


static void test_soft_normal_never_pulls_and_is_continuous(void) {
  cscSoftParams p = csc_softDefaultParams();
  cstTerrain t = groundTerrain();
  cscShape sh = csc_softFoot(kHalf);
  csError err;
  cscSoftModel* m = csc_softCreate(&p, &t, 1, &sh, &err);
  double z[36];
  csc_softStateInit(m, z);
  /* sweep the depth through 0 and d_onset at approach speeds from fast separation (the
   * Hunt-Crossley factor clipped) to fast approach: the force is >= 0, and its largest
   * difference quotient is the law's largest slope (no jump) */
  double vel[5] = {-200, -10, -5, 0, 50}; /* mm/s, + = approaching */
  double h = 1e-6, kmax = p.k_area * 4 * kHalf * kHalf;
  for (int iv = 0; iv < 5; iv++) {
    double prev = 0, worst = 0;
    int pulls = 0;
    for (int i = 0; i <= 6000; i++) {
      double dep = -1e-3 + i * h;
      cscShapeState st = footAt(-dep);
      st.v0[1] = -vel[iv];
      cscShapeLoad ld;
      csc_softCompute(m, &st, z, &ld, NULL, NULL, NULL);
      pulls += ld.f0[1] < 0;
      if (i > 0) {
        worst = fmax(worst, fabs(ld.f0[1] - prev) / h);
      }
      prev = ld.f0[1];
    }
    /* slope bound: k A (1 + c v) times 4/3, the largest slope of the C1 onset x^2 (2X - x) /
     * X^2 (at x = 2X/3); measured exactly that (300 N/mm at rest, 1800 at 50 mm/s), so a jump
     * anywhere would show; 1 % margin for the difference quotient's O(h) term */
    double bound = kmax * fmax(1.0, 1 + p.c_hc * vel[iv]) * (4.0 / 3.0) * 1.01;
    CS_EXPECT(pulls == 0);
    CS_EXPECT(worst <= bound);
    printf("  v = %6.1f mm/s: max dF/dd %.4g N/mm (bound %.4g), pulls %d\n", vel[iv], worst,
           bound, pulls);
  }
  /* the damping factor is continuous in the velocity through its clip: sweep at 5 um depth */
  double prev = 0, worst = 0;
  for (int i = 0; i <= 4000; i++) {
    double v = -20 + 0.005 * i;
    cscShapeState st = footAt(-5e-3);
    st.v0[1] = -v;
    cscShapeLoad ld;
    csc_softCompute(m, &st, z, &ld, NULL, NULL, NULL);
    CS_EXPECT(ld.f0[1] >= 0);
    if (i > 0) {
      worst = fmax(worst, fabs(ld.f0[1] - prev) / 0.005);
    }
    prev = ld.f0[1];
  }
  /* the largest slope in v is k A d c times the clip's 4/3, 1 % margin as above */
  printf("  at 5 um: max dF/dv %.4g N s/mm (bound %.4g)\n", worst,
         kmax * 5e-3 * p.c_hc * (4.0 / 3.0));
  CS_EXPECT(worst <= kmax * 5e-3 * p.c_hc * (4.0 / 3.0) * 1.01);
  csc_softDestroy(m);
}


static void test_soft_friction_law_states(void) {
  /* the bristle's rate and force in the three regimes, on the sole points of a level foot */
  cscSoftParams p = csc_softDefaultParams();
  p.foot = CSC_FOOT_POINTS;
  cstTerrain t = groundTerrain();
  cscShape sh = csc_softFoot(kHalf);
  sh.nside = 2;
  csError err;
  cscSoftModel* m = csc_softCreate(&p, &t, 1, &sh, &err);
  CS_EXPECT(csc_softNState(m) == 12);
  double z[12], zd[12], zs = p.mu * p.delta_t;
  cscShapeState st = footAt(-0.01);
  cscShapeLoad ld;
  cscSlotInfo info[4];
  /* stick at half the limit, at rest: z' = 0 exactly and F = -mu N / 2 */
  csc_softStateInit(m, z);
  for (int k = 0; k < 4; k++) z[3 * k] = 0.5 * zs;
  csc_softCompute(m, &st, z, &ld, zd, info, NULL);
  for (int k = 0; k < 12; k++) CS_EXPECT(zd[k] == 0);
  CS_EXPECT_NEAR(ld.f0[0], -0.5 * p.mu * ld.f0[1], 0, 1e-13);
  /* at the limit, sliding along z: the bristle stays (z' = w (1 - alpha) - ... = 0 once
   * alpha(1) = 1 and the positive part is exact, w > v_plastic) and F_t = -mu N */
  for (int k = 0; k < 4; k++) z[3 * k] = zs;
  st.v0[0] = 10.0;
  csc_softCompute(m, &st, z, &ld, zd, info, NULL);
  for (int k = 0; k < 12; k++) CS_EXPECT_NEAR(zd[k], 0, 1e-12, 0);
  CS_EXPECT_NEAR(ld.f0[0], -p.mu * ld.f0[1], 0, 1e-13);
  CS_EXPECT(info[0].sliding && fabs(info[0].ratio - 1) < 1e-13);
  /* unloading from the limit (moving back): purely elastic, z' = w */
  st.v0[0] = -10.0;
  csc_softCompute(m, &st, z, &ld, zd, info, NULL);
  CS_EXPECT_NEAR(zd[0], -10.0, 1e-12, 0);
  CS_EXPECT(!info[0].sliding);
  /* lifted 0.1 mm clear: no force, the bristle relaxes with tau_reset */
  st = footAt(0.1);
  csc_softCompute(m, &st, z, &ld, zd, info, NULL);
  CS_EXPECT(ld.f0[0] == 0 && ld.f0[1] == 0);
  CS_EXPECT_NEAR(zd[0], -zs / p.tau_reset, 0, 1e-14);
  csc_softDestroy(m);
}


static void test_soft_foot_patch_translation_and_torsion(void) {
  /* the patch foot (default): one bristle and one torsional bristle for the 3 x 3 sole */
  cscSoftParams p = csc_softDefaultParams();
  cstTerrain t = groundTerrain();
  cscShape sh = csc_softFoot(kHalf);
  csError err;
  cscSoftModel* m = csc_softCreate(&p, &t, 1, &sh, &err);
  CS_EXPECT(csc_softNState(m) == 4 && csc_softNSlot(m) == 1);
  double z[4] = {0, 0, 0, 0}, zd[4], d = 0.01, N = p.k_area * 4 * kHalf * kHalf * d;
  cscShapeState st = footAt(-d);
  cscShapeLoad ld;
  cscSlotInfo info;
  /* the sole's couple moments by the same quadrature, independently: Lobatto 3 x 3 on
   * [-a, a]^2 with the pressure k d, R1 = sum N_i sqrt(r_i^2 + rho^2), J = sum N_i r_i^2 */
  const double X[3] = {-1, 0, 1}, Wl[3] = {1.0 / 3, 4.0 / 3, 1.0 / 3};
  double R1 = 0, J = 0;
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      double Ni = p.k_area * d * kHalf * kHalf * Wl[i] * Wl[j];
      double r2 = kHalf * kHalf * (X[i] * X[i] + X[j] * X[j]);
      R1 += Ni * sqrt(r2 + sh.radius * sh.radius);
      J += Ni * r2;
    }
  }
  double phis = p.mu * p.delta_t * R1 / J;
  /* translation at the limit, sliding: Coulomb at the pressure centre (the sole's centre) */
  z[0] = p.mu * p.delta_t;
  st.v0[0] = 10;
  CS_EXPECT(csc_softCompute(m, &st, z, &ld, zd, &info, NULL) == 0);
  CS_EXPECT_NEAR(ld.f0[1], N, 0, 1e-13);
  CS_EXPECT_NEAR(ld.f0[0], -p.mu * N, 0, 1e-13);
  CS_EXPECT_NEAR(csu_norm3(ld.m), 0, 1e-13, 0); /* at the sole's plane: no moment about x0 */
  CS_EXPECT_NEAR(zd[0], 0, 1e-12, 0);
  /* twisted at half the torsional stick range, at rest: an elastic couple (J / delta_t) phi
   * about the normal (+y), and no drift */
  z[0] = 0;
  st.v0[0] = 0;
  z[3] = 0.5 * phis;
  CS_EXPECT(csc_softCompute(m, &st, z, &ld, zd, &info, NULL) == 0);
  CS_EXPECT_NEAR(ld.m[1], -(J / p.delta_t) * 0.5 * phis, 0, 1e-12);
  CS_EXPECT_NEAR(info.torsion, ld.m[1], 0, 1e-14);
  CS_EXPECT(zd[3] == 0);
  /* spinning at 1 rad/s with the bristle at its limit: the Coulomb couple mu R1, steady */
  z[3] = phis;
  csu_set3(st.w, 0, -1, 0); /* the sole spins about -y... */
  z[3] = -phis;             /* ...so its bristle is wound the other way */
  CS_EXPECT(csc_softCompute(m, &st, z, &ld, zd, &info, NULL) == 0);
  CS_EXPECT_NEAR(ld.m[1], p.mu * R1, 0, 1e-12);
  CS_EXPECT_NEAR(zd[3], 0, 1e-12, 0);
  /* the 3 x 3 sole's Coulomb couple against a uniformly pressed square's, mu N a (sqrt 2 +
   * asinh 1) / 3 = 0.7652 mu N a: the quadrature of |r| (printed) */
  double exact = p.mu * N * kHalf * (sqrt(2) + asinh(1.0)) / 3;
  printf("  torsional Coulomb couple %.5f N mm, uniform square %.5f N mm (%.3f)\n", ld.m[1],
         exact, ld.m[1] / exact);
  CS_EXPECT(ld.m[1] > 0.8 * exact && ld.m[1] < 1.05 * exact);
  csc_softDestroy(m);
}


/* the foot's broad phase (contact_soft.c footNearTerrain) skips the sole points only when none
 * of them would see a box: for tilted feet whose lowest sole sphere is from 2 um inside to 3
 * d_onset above the ground, every foot out of touch gets the same bits (no load, the history's
 * leak rates) as the sole points evaluated one by one. A broad phase that culls a foot in the
 * onset band (where the leak is partial) fails this. */
static void test_soft_foot_broad_phase_is_exact(void) {
  cscSoftParams p = csc_softDefaultParams();
  cstTerrain t = groundTerrain();
  cscShape sh = csc_softFoot(kHalf);
  csError err;
  cscSoftModel* m = csc_softCreate(&p, &t, 1, &sh, &err);
  CS_EXPECT(m != NULL);
  if (!m) {
    return;
  }
  unsigned seed = 12345;
  int n_out = 0, n_partial = 0, bad = 0;
  for (int trial = 0; trial < 4000; trial++) {
    /* a random rotation (unit quaternion from four uniform numbers) */
    double q[4], nq = 0;
    for (int k = 0; k < 4; k++) {
      seed = seed * 1103515245u + 12345u;
      q[k] = (double)(seed >> 8) / (double)(1u << 24) - 0.5;
      nq += q[k] * q[k];
    }
    nq = sqrt(nq);
    for (int k = 0; k < 4; k++) q[k] /= nq;
    cscShapeState st;
    memset(&st, 0, sizeof st);
    csu_quatToMat3(st.R, q);
    /* the lowest sole sphere's gap: -2 um .. 3 d_onset */
    double cmin = INFINITY, c[3], A;
    for (int k = 0; k < sh.nside * sh.nside; k++) {
      csc_softSolePoint(&sh, &st, k / sh.nside, k % sh.nside, c, &A);
      cmin = fmin(cmin, c[1]);
    }
    double gap = -2e-3 + (3 * p.d_onset + 2e-3) * (trial % 400) / 399.0;
    st.x0[1] = gap + sh.radius - cmin;
    st.v0[0] = 1;
    /* the points one by one, as before the broad phase */
    cscSoftAcc acc = {.dmax = -INFINITY};
    cscShapeLoad ref;
    memset(&ref, 0, sizeof ref);
    for (int k = 0; k < sh.nside * sh.nside; k++) {
      csc_softSolePoint(&sh, &st, k / sh.nside, k % sh.nside, c, &A);
      csc_softSolePointNormal(m, sh.radius, A, c, &st, &acc, &ref, NULL);
    }
    cscSoftGeom g;
    if (csc_softSlotFinish(&acc, &g)) {
      continue; /* touching: no broad phase question */
    }
    const double z[4] = {1e-3, -2e-3, 3e-3, 1e-2}, vs[3] = {0, 0, 0};
    double zr[4];
    cscSoftFriction f;
    csc_softFrictionIntegrated(&p, &acc, &g, 0, vs, z, zr, &f);
    csc_softFrictionTorsion(&p, &acc, &g, 0, 0, 0, 0, z[3], &zr[3], &f);
    cscShapeLoad ld;
    double zd[4];
    CS_EXPECT(csc_softCompute(m, &st, z, &ld, zd, NULL, NULL) == 0);
    n_out++;
    n_partial += acc.dmax > -INFINITY;
    bad += memcmp(zd, zr, sizeof zd) != 0 || memcmp(&ld, &ref, sizeof ld) != 0;
  }
  printf("  %d feet out of touch (%d of them within reach of the ground): %d differ\n", n_out,
         n_partial, bad);
  CS_EXPECT(bad == 0 && n_partial > 100 && n_out > n_partial + 100);
  csc_softDestroy(m);
}


static void test_soft_capsule_friction_slides_rolls_and_splits(void) {
  /* a capsule lying on the ground, 0.02 mm deep, its bristle at the limit along +x */
  cscSoftParams p = csc_softDefaultParams();
  cstTerrain t = groundTerrain();
  double r = 7.5, d = 0.02, L = 10;
  cscShape sh = csc_softCapsule(r);
  csError err;
  cscSoftModel* m = csc_softCreate(&p, &t, 1, &sh, &err);
  double z[3] = {p.mu * p.delta_t, 0, 0}, zd[3], z0[3] = {0, 0, 0};
  cscShapeState st;
  memset(&st, 0, sizeof st);
  csu_set3(st.x0, 0, r - d, 0);
  csu_set3(st.x1, L, r - d, 0);
  csu_set3(st.v0, 10, 0, 0);
  csu_set3(st.v1, 10, 0, 0);
  cscShapeLoad ld, ld2;
  cscSlotInfo info;
  CS_EXPECT(csc_softCompute(m, &st, z, &ld, zd, &info, NULL) == 0);
  double N = ld.f0[1] + ld.f1[1];
  /* sliding at the limit: Coulomb, split equally between the ends (load centroid at s = 1/2),
   * and the friction acts at the contact line r below the axis: couple r mu N about -z */
  CS_EXPECT_NEAR(ld.f0[0] + ld.f1[0], -p.mu * N, 0, 1e-13);
  CS_EXPECT_NEAR(ld.f0[0], ld.f1[0], 0, 1e-13);
  CS_EXPECT_NEAR(ld.m[2], -r * p.mu * N, 0, 1e-12);
  CS_EXPECT_NEAR(csu_norm3(zd), 0, 1e-12, 0);
  CS_EXPECT(info.sliding);
  /* rolling without slip: the axis moves at +10 mm/s and the section turns at -10 / r rad/s
   * about z, so the contact line is at rest: a fresh bristle does not grow (z' = 0) */
  csu_set3(st.w, 0, 0, -10 / r);
  CS_EXPECT(csc_softCompute(m, &st, z0, &ld2, zd, &info, NULL) == 0);
  CS_EXPECT_NEAR(csu_norm3(zd), 0, 1e-12, 0);
  CS_EXPECT_NEAR(ld2.f0[0] + ld2.f1[0], 0, 1e-15, 0);
  /* the same without the spin: the line slips at 10 mm/s and the bristle follows, z' = w */
  csu_set3(st.w, 0, 0, 0);
  CS_EXPECT(csc_softCompute(m, &st, z0, &ld2, zd, &info, NULL) == 0);
  CS_EXPECT_NEAR(zd[0], 10, 1e-12, 0);
  /* the same inputs give the same outputs, bit for bit (no hidden state) */
  cscShapeLoad ld3;
  double zd3[3];
  csc_softCompute(m, &st, z0, &ld3, zd3, NULL, NULL);
  CS_EXPECT(memcmp(&ld2, &ld3, sizeof ld2) == 0 && memcmp(zd, zd3, sizeof zd) == 0);
  csc_softDestroy(m);
}


static void test_soft_step_update_keeps_force_continuous(void) {
  /* step mode on a level foot: anchors appear at touch-down, are pulled to the stick range
   * when the foot slid further, and disappear at lift-off; the force is the same just before
   * and just after every update */
  cscSoftParams p = csc_softDefaultParams();
  p.history = CSC_HISTORY_STEP;
  cstTerrain t = groundTerrain();
  cscShape sh = csc_softFoot(kHalf);
  csError err;
  cscSoftModel* m = csc_softCreate(&p, &t, 1, &sh, &err);
  CS_EXPECT(csc_softNState(m) == 9 * 4);
  double z[36];
  csc_softStateInit(m, z);
  cscShapeState st = footAt(-0.01);
  cscShapeLoad before, after;
  /* touch-down: no anchor yet, so no friction; the update anchors at the current point */
  csc_softCompute(m, &st, z, &before, NULL, NULL, NULL);
  CS_EXPECT(before.f0[0] == 0);
  csc_softUpdate(m, &st, z);
  for (int k = 0; k < 9; k++) CS_EXPECT(z[4 * k + 3] == 0);
  csc_softCompute(m, &st, z, &after, NULL, NULL, NULL);
  CS_EXPECT_NEAR(after.f0[0], 0, 1e-15, 0);
  /* slid by 0.5 mm within the step (60 stick ranges): the force saturates at mu N, the update
   * clips the deflection to u = 2 - u_elastic where the saturation is already 1 */
  double zs = p.mu * p.delta_t;
  const double shifts[2] = {0.5, 0.3 * zs}; /* far beyond the range, then within it */
  for (int i = 0; i < 2; i++) {
    st.x0[0] += shifts[i];
    cscSlotInfo info[9];
    csc_softCompute(m, &st, z, &before, NULL, info, NULL);
    csc_softUpdate(m, &st, z);
    csc_softCompute(m, &st, z, &after, NULL, NULL, NULL);
    /* continuity to round-off of the anchor arithmetic (mm-sized numbers: 1e-15 N) */
    CS_EXPECT_NEAR(after.f0[0], before.f0[0], 1e-13, 0);
    if (i == 0) {
      CS_EXPECT_NEAR(before.f0[0], -p.mu * before.f0[1], 0, 1e-13);
      CS_EXPECT(info[4].sliding);
    }
  }
  /* lifted: free again */
  st = footAt(1.0);
  csc_softUpdate(m, &st, z);
  for (int k = 0; k < 9; k++) CS_EXPECT(z[4 * k + 3] < 0);
  /* integrated mode: the update changes nothing */
  cscSoftParams pi = csc_softDefaultParams();
  cscSoftModel* mi = csc_softCreate(&pi, &t, 1, &sh, &err);
  double zi[27], zc[27];
  for (int k = 0; k < 27; k++) zi[k] = zc[k] = 1e-3 * k;
  st = footAt(-0.01);
  CS_EXPECT(csc_softUpdate(mi, &st, zi) == 0 && memcmp(zi, zc, sizeof zi) == 0);
  csc_softDestroy(mi);
  csc_softDestroy(m);
}


static void test_soft_leg_per_shape_equals_whole_and_cost(void) {
  /* a leg of 20 capsules (a = 7.5 mm, 8 mm each) bent down onto the ground and a foot: the
   * per-shape API (a rod's per-element hook) gives the same numbers as the whole-leg call, bit
   * for bit; the cost per evaluation is printed (not asserted: no timing in tests) */
  enum { NC = 20 };
  cscSoftParams p = csc_softDefaultParams();
  cstTerrain t = groundTerrain();
  cscShape sh[NC + 1];
  for (int i = 0; i < NC; i++) sh[i] = csc_softCapsule(kHalf);
  sh[NC] = csc_softFoot(kHalf);
  csError err;
  cscSoftModel* m = csc_softCreate(&p, &t, NC + 1, sh, &err);
  int nz = csc_softNState(m);
  CS_EXPECT(nz == 3 * NC + 4);
  double z[3 * NC + 4], zd[3 * NC + 4], zd2[3 * NC + 4];
  cscShapeState st[NC + 1];
  memset(st, 0, sizeof st);
  /* the chord from (0, 80) descending at 30 deg for 10 capsules, then lying on the ground
   * (axis at r - 0.01) for 10, sliding at 5 mm/s; the foot flat at the end, 4 um deep */
  double x = 0, y = 80, h = 8;
  for (int i = 0; i < NC; i++) {
    csu_set3(st[i].x0, x, y, 0);
    if (i < 10) {
      x += h * cos(CS_PI / 6);
      y = fmax(kHalf - 0.01, y - h * sin(CS_PI / 6));
    } else {
      x += h;
      y = kHalf - 0.01;
    }
    csu_set3(st[i].x1, x, y, 0);
    csu_set3(st[i].v0, 5, 0, 0);
    csu_set3(st[i].v1, 5, 0, 0);
  }
  st[NC] = footAt(-0.004);
  st[NC].x0[0] = x + 20;
  csu_set3(st[NC].v0, 5, 0, 0);
  for (int k = 0; k < nz; k++) z[k] = 1e-3 * sin(k); /* some bristle state */
  cscShapeLoad ld[NC + 1], ld2;
  cscSoftReport rep, rep2;
  CS_EXPECT(csc_softCompute(m, st, z, ld, zd, NULL, &rep) == 0);
  memset(&rep2, 0, sizeof rep2);
  int same = 1;
  for (int i = 0; i < NC + 1; i++) {
    int off, cnt;
    csc_softShapeState(m, i, &off, &cnt);
    CS_EXPECT(csc_softComputeShape(m, i, &st[i], z + off, &ld2, zd2 + off, NULL, &rep2) == 0);
    same = same && memcmp(&ld2, &ld[i], sizeof ld2) == 0;
  }
  CS_EXPECT(same && memcmp(zd, zd2, sizeof zd) == 0);
  /* the one-force-at-a-point form is statically equivalent: resultant and moment about the
   * origin (round-off of ~100 mm lever arms on ~1 N: 1e-13 N mm) */
  double worst_f = 0, worst_m = 0;
  for (int i = 0; i < NC + 1; i++) {
    double f[3], P[3], M[3], mo[3], mp[3], t[3];
    csc_softLoadAsPointForce(m, i, &st[i], &ld[i], f, P, M);
    csu_cross3(mo, st[i].x0, ld[i].f0);
    csu_add3(mo, mo, ld[i].m);
    if (i < NC) {
      csu_cross3(t, st[i].x1, ld[i].f1);
      csu_add3(mo, mo, t);
    }
    csu_cross3(mp, P, f);
    csu_add3(mp, mp, M);
    double fr[3];
    csu_add3(fr, ld[i].f0, ld[i].f1);
    csu_sub3(fr, fr, f);
    csu_sub3(mp, mp, mo);
    worst_f = fmax(worst_f, csu_norm3(fr));
    worst_m = fmax(worst_m, csu_norm3(mp));
  }
  CS_EXPECT_NEAR(worst_f, 0, 1e-15, 0);
  CS_EXPECT_NEAR(worst_m, 0, 1e-12, 0);
  CS_EXPECT(rep.ncontact == rep2.ncontact && rep.ncontact >= 10);
  printf("  leg: %d of %d slots touching, max depth %.4f mm\n", rep.ncontact, NC + 1,
         rep.max_depth);
  int n = 2000;
  clock_t t0 = clock();
  for (int it = 0; it < n; it++) {
    st[NC].x0[1] = -0.004 - 1e-9 * it; /* defeat any caching by the compiler */
    csc_softCompute(m, st, z, ld, zd, NULL, NULL);
  }
  double us = 1e6 * (double)(clock() - t0) / CLOCKS_PER_SEC / n;
  printf("  one evaluation of 20 capsules + a foot: %.2f us\n", us);
  csc_softDestroy(m);
}


static void test_soft_bad_input_is_refused(void) {
  cscSoftParams p = csc_softDefaultParams();
  cstTerrain t = groundTerrain();
  csError err;
  p.mu = -1;
  CS_EXPECT(csc_softParamsValidate(&p, &err) == CS_ERR_RANGE && strstr(err.msg, "mu"));
  p = csc_softDefaultParams();
  p.u_elastic = 1.0;
  CS_EXPECT(csc_softParamsValidate(&p, &err) == CS_ERR_RANGE && strstr(err.msg, "u_elastic"));
  p = csc_softDefaultParams();
  p.k_area = NAN;
  CS_EXPECT(csc_softCreate(&p, &t, 0, NULL, &err) == NULL && strstr(err.msg, "k_area"));
  p = csc_softDefaultParams();
  p.nquad = 9;
  CS_EXPECT(csc_softParamsValidate(&p, &err) == CS_ERR_RANGE);
  p = csc_softDefaultParams();
  cscShape bad = csc_softFoot(kHalf);
  bad.radius = 8;
  CS_EXPECT(csc_softCreate(&p, &t, 1, &bad, &err) == NULL && strstr(err.msg, "shape 0"));
  bad = csc_softCapsule(0);
  CS_EXPECT(csc_softCreate(&p, &t, 1, &bad, &err) == NULL && strstr(err.msg, "radius"));
  /* a non-finite pose and a capsule whose axis is in the ground: recoverable (> 0) */
  cscShape sh = csc_softCapsule(7.5);
  cscSoftModel* m = csc_softCreate(&p, &t, 1, &sh, &err);
  double z[3] = {0, 0, 0};
  cscShapeState st;
  memset(&st, 0, sizeof st);
  st.x1[0] = 10;
  st.x0[1] = NAN;
  cscShapeLoad ld;
  CS_EXPECT(csc_softCompute(m, &st, z, &ld, NULL, NULL, NULL) > 0);
  st.x0[1] = -1;
  cscSoftReport rep;
  CS_EXPECT(csc_softCompute(m, &st, z, &ld, NULL, NULL, &rep) > 0 && rep.ndeep == 1);
  CS_EXPECT(csc_softCompute(NULL, &st, z, &ld, NULL, NULL, NULL) < 0);
  csc_softDestroy(m);
  csc_softDestroy(NULL);
}


/* ---------------------------------------------------------------------------------------- */
/* the foot block under CVODE BDF                                                            */

typedef struct {
  cscSoftModel* m;
  double push; /* N: held push at the sole's centre, along +x */
  double osc;  /* N: amplitude of a 40 Hz oscillation added to it (vibration test) */
} Block;

static const double kOscHz = 40.0; /* vibration test: a gait's actuation shakes at ~10-100 Hz */

enum { NB = 6 }; /* rigid state: x, y, th, vx, vy, om */

static double blockInertia(void) { return kMass * (2 * kHalf) * (2 * kHalf) * 2 / 12; }


/* pose of the foot (the block's bottom face) from the block's state */
static void blockPose(const double* y, cscShapeState* st) {
  double c = cos(y[2]), s = sin(y[2]);
  memset(st, 0, sizeof *st);
  /* columns: e1 = (c, s, 0), e2 = z, e3 = (s, -c, 0) = the sole's outward normal */
  double R[9] = {c, 0, s, s, 0, -c, 0, 1, 0};
  memcpy(st->R, R, sizeof R);
  double r[3] = {kHalf * s, -kHalf * c, 0}; /* centre -> sole centre */
  csu_set3(st->x0, y[0] + r[0], y[1] + r[1], 0);
  csu_set3(st->v0, y[3] - y[5] * r[1], y[4] + y[5] * r[0], 0);
  csu_set3(st->w, 0, 0, y[5]);
}


static double pushAt(const Block* b, double t) {
  double u = (t - kTPush) / kRamp;
  u = u <= 0 ? 0 : (u >= 1 ? 1 : u * u * (3 - 2 * u));
  return u * (b->push + b->osc * sin(2 * CS_PI * kOscHz * (t - kTPush)));
}


static int blockRhs(sunrealtype t, N_Vector yv, N_Vector ydv, void* user) {
  Block* b = user;
  const double* y = N_VGetArrayPointer(yv);
  double* yd = N_VGetArrayPointer(ydv);
  cscShapeState st;
  blockPose(y, &st);
  cscShapeLoad ld;
  int rc = csc_softCompute(b->m, &st, y + NB, &ld, yd + NB, NULL, NULL);
  if (rc != 0) {
    return rc > 0 ? 1 : -1;
  }
  double F = pushAt(b, t);
  double fx = ld.f0[0] + F, fy = ld.f0[1] - kLoad; /* weight + load = kLoad */
  double r[2] = {st.x0[0] - y[0], st.x0[1] - y[1]};
  double Mz = ld.m[2] + r[0] * ld.f0[1] - r[1] * (ld.f0[0] + F);
  yd[0] = y[3];
  yd[1] = y[4];
  yd[2] = y[5];
  yd[3] = fx / kMass;
  yd[4] = fy / kMass;
  yd[5] = Mz / blockInertia();
  return 0;
}


/* What a run measured. */
typedef struct {
  double t[8];       /* s: sample times */
  double y[8][NB];   /* rigid state at the samples */
  double ft;         /* N: friction force on the block at the end (x) */
  double N;          /* N: normal force at the end */
  double p_min, p_max; /* N/mm^2: smallest and largest sole-point pressure at the end */
  long nsteps, nrhs, nreinit; /* CVODE steps, right-hand sides (Jacobian's included) */
  int ok;
} Run;


/* Integrate the block from rest on the ground (optionally tilted by th0 and lifted by y0) to
 * t_end, sampling at the ns times ts; H = 0: one CVODE run (integrated history); H > 0: macro
 * steps of H with csc_softUpdate and CVodeReInit between them (step history). */
static Run runBlock(const cscSoftParams* p, double push, double osc, double th0, double y0,
                    const double* ts, int ns, double H) {
  Run out;
  memset(&out, 0, sizeof out);
  cstTerrain t = groundTerrain();
  cscShape sh = csc_softFoot(kHalf);
  csError err;
  Block b = {csc_softCreate(p, &t, 1, &sh, &err), push, osc};
  int nz = csc_softNState(b.m), n = NB + nz;
  SUNContext ctx;
  SUNContext_Create(NULL, &ctx);
  N_Vector y = N_VNew_Serial(n, ctx), atol = N_VNew_Serial(n, ctx);
  double* yp = N_VGetArrayPointer(y);
  double* ap = N_VGetArrayPointer(atol);
  memset(yp, 0, (size_t)n * sizeof *yp);
  /* start at the static sink-in kLoad / (k (2a)^2) */
  double d0 = kLoad / (p->k_area * 4 * kHalf * kHalf);
  yp[1] = kHalf - d0 + y0;
  yp[2] = th0;
  csc_softStateInit(b.m, yp + NB);
  /* absolute tolerances: 1e-9 mm on positions and bristles (the creep bound is 1.5e-6 mm over
   * 1.5 s), 1e-10 rad, 1e-6 mm/s and 1e-7 rad/s on rates; tags of step mode are constants */
  double atols[NB] = {1e-9, 1e-9, 1e-10, 1e-6, 1e-6, 1e-7};
  for (int k = 0; k < n; k++) ap[k] = k < NB ? atols[k] : 1e-9;
  void* cv = CVodeCreate(CV_BDF, ctx);
  SUNMatrix A = SUNDenseMatrix(n, n, ctx);
  SUNLinearSolver LS = SUNLinSol_Dense(y, A, ctx);
  CVodeInit(cv, blockRhs, 0.0, y);
  CVodeSVtolerances(cv, 1e-6, atol);
  CVodeSetUserData(cv, &b);
  CVodeSetLinearSolver(cv, LS, A);
  CVodeSetMaxNumSteps(cv, 2000000);
  double tcur = 0;
  out.ok = 1;
  for (int i = 0; i < ns && out.ok; i++) {
    if (H <= 0) {
      CVodeSetStopTime(cv, ts[i]);
      out.ok = CVode(cv, ts[i], y, &tcur, CV_NORMAL) >= 0;
    } else {
      while (tcur < ts[i] - 0.5 * H && out.ok) {
        double tn = tcur + H;
        CVodeSetStopTime(cv, tn);
        out.ok = CVode(cv, tn, y, &tcur, CV_NORMAL) >= 0;
        long ns_, nf_, nl_;
        CVodeGetNumSteps(cv, &ns_);
        CVodeGetNumRhsEvals(cv, &nf_);
        CVodeGetNumLinRhsEvals(cv, &nl_);
        out.nsteps += ns_;
        out.nrhs += nf_ + nl_;
        cscShapeState st;
        blockPose(yp, &st);
        csc_softUpdate(b.m, &st, yp + NB);
        CVodeReInit(cv, tcur, y);
        out.nreinit++;
      }
    }
    out.t[i] = tcur;
    memcpy(out.y[i], yp, sizeof out.y[i]);
  }
  if (H <= 0) { /* (step mode summed them per macro step: CVodeReInit restarts the counters) */
    long nl;
    CVodeGetNumSteps(cv, &out.nsteps);
    CVodeGetNumRhsEvals(cv, &out.nrhs);
    CVodeGetNumLinRhsEvals(cv, &nl); /* the dense Jacobian's difference quotients */
    out.nrhs += nl;
  }
  /* the contact at the end */
  cscShapeState st;
  blockPose(yp, &st);
  cscShapeLoad ld;
  cscSlotInfo info[9];
  csc_softCompute(b.m, &st, yp + NB, &ld, NULL, info, NULL);
  out.ft = ld.f0[0];
  out.N = ld.f0[1];
  out.p_min = INFINITY;
  out.p_max = 0;
  const double lw[3] = {1.0 / 3, 4.0 / 3, 1.0 / 3}; /* Lobatto weights of the 3 x 3 sole */
  for (int k = 0; k < csc_softNSlot(b.m) && csc_softNSlot(b.m) == 9; k++) {
    double pr = info[k].N / (kHalf * kHalf * lw[k / 3] * lw[k % 3]);
    out.p_min = fmin(out.p_min, pr);
    out.p_max = fmax(out.p_max, pr);
  }
  CVodeFree(&cv);
  SUNLinSolFree(LS);
  SUNMatDestroy(A);
  N_VDestroy(y);
  N_VDestroy(atol);
  SUNContext_Free(&ctx);
  csc_softDestroy(b.m);
  return out;
}


static void test_soft_foot_rests_flat_without_rocking(void) {
  /* dropped from 0.05 mm, tilted by 0.5 deg: after 0.5 s it lies level, the pressure under the
   * sole is uniform and carries the load; both foot frictions */
  for (int mode = 0; mode < 2; mode++) {
    cscSoftParams p = csc_softDefaultParams();
    p.foot = mode ? CSC_FOOT_POINTS : CSC_FOOT_PATCH;
    double ts[2] = {0.05, 0.5};
    Run r = runBlock(&p, 0, 0, 0.5 * CS_DEG, 0.05, ts, 2, 0);
    CS_EXPECT(r.ok);
    double x0_start = kHalf * sin(0.5 * CS_DEG), x0_end = r.y[1][0] + kHalf * sin(r.y[1][2]);
    printf("  at rest (%s foot): tilt %.3g rad, normal %.9f N, sole centre moved %.3g um, "
           "%ld steps\n", mode ? "point" : "patch", r.y[1][2], r.N, 1e3 * (x0_end - x0_start),
           r.nsteps);
    /* level: the tilt decays with the rocking mode's damping (~1 ms); what remains is the
     * integrator's tolerance (1e-10 rad) */
    CS_EXPECT_NEAR(r.y[1][2], 0, 1e-9, 0);
    CS_EXPECT_NEAR(r.y[1][5], 0, 1e-5, 0);
    /* the load is carried (static: to the integrator's rtol 1e-6) */
    CS_EXPECT_NEAR(r.N, kLoad, 0, 1e-6);
    /* it rolls onto its sole about the edge that lands first: the block's centre moves by
     * a sin(0.5 deg) = 65 um, the sole's centre stays where it touched down, to within the
     * bristles' elastic range (8 um) */
    CS_EXPECT(fabs(x0_end - x0_start) < 0.8 * 0.01);
    if (mode) {
      /* and spread evenly: a tilt th changes the pressure by k th x across the sole, so the
       * 1e-9 rad above allow p_max / p_min - 1 <= 2 th a / d0 = 4.2e-6 (measured 2e-6); 1e-5 */
      printf("  sole pressures %.9g..%.9g N/mm^2\n", r.p_min, r.p_max);
      CS_EXPECT_NEAR(r.p_max / r.p_min, 1, 0, 1e-5);
    }
  }
}


/* push at `ratio` x mu N: returns the run with samples at push + 0.1, 0.5, 1.0, 1.5, 2.0 s */
static Run pushRun(const cscSoftParams* p, double ratio, double H, double hold) {
  double ts[5] = {kTPush + 0.1, kTPush + 0.5, kTPush + 1.0, kTPush + 1.5, kTPush + 2.0};
  int ns = 1;
  while (ns < 5 && ts[ns] <= kTPush + hold + 1e-9) ns++;
  return runBlock(p, ratio * p->mu * kLoad, 0, 0, 0, ts, ns, H);
}


/* check a stick run (0.9 mu N for 2 s): creep after the initial deflection */
static void checkStick(const Run* r, const char* what) {
  CS_EXPECT(r->ok);
  double creep = (r->y[4][0] - r->y[1][0]) / (r->t[4] - r->t[1]); /* mm/s */
  printf("  %s, 0.9 mu N: deflection %.4f um, creep %.3g um/s, %ld steps, %ld rhs\n", what,
         1e3 * r->y[1][0], 1e3 * creep, r->nsteps, r->nrhs);
  /* the requirement: < 1 um/s; measured |creep| <= 1.2e-5 um/s integrated, 4e-7 um/s in step
   * mode (integrator noise: a static bristle has no drift term at all) */
  CS_EXPECT(fabs(creep) < 1e-3);
  /* the initial deflection is elastic plus the plastic part above u_elastic: within the
   * stick range (0.9 mu delta_t = 7.2 um) to 1.2 of it */
  CS_EXPECT(r->y[1][0] > 0 && r->y[1][0] < 1.2 * 0.8 * 0.01);
}


/* check a slide (ratio x mu N): the friction force from the kinematics and from the contact */
static void checkSlide(const Run* r, double ratio, const char* what, double* f_kin) {
  CS_EXPECT(r->ok);
  double mu_N = 0.8 * kLoad, F = ratio * mu_N;
  /* a = dv/dt between push + 0.1 s (after the ramp) and push + 0.5 s */
  double a = (r->y[1][3] - r->y[0][3]) / (r->t[1] - r->t[0]);
  double f = F - kMass * a;
  *f_kin = f;
  printf("  %s, %.1f mu N: friction %.5f mu N (kinematic), %.5f mu N (contact), slid %.1f mm, "
         "%ld steps, %ld rhs\n", what, ratio, f / mu_N, -r->ft / mu_N, r->y[1][0], r->nsteps,
         r->nrhs);
  /* the requirement: the Coulomb force within 5 % */
  CS_EXPECT_NEAR(f, mu_N, 0, 0.05);
  CS_EXPECT_NEAR(-r->ft, mu_N, 0, 0.05);
}


static void test_soft_friction_integrated_holds_and_slides(void) {
  for (int mode = 0; mode < 2; mode++) {
    cscSoftParams p = csc_softDefaultParams();
    p.foot = mode ? CSC_FOOT_POINTS : CSC_FOOT_PATCH;
    const char* what = mode ? "integrated, point foot" : "integrated, patch foot";
    Run r = pushRun(&p, 0.9, 0, 2.0);
    checkStick(&r, what);
    double f;
    r = pushRun(&p, 1.1, 0, 0.5);
    checkSlide(&r, 1.1, what, &f);
    r = pushRun(&p, 2.0, 0, 0.5);
    checkSlide(&r, 2.0, what, &f);
  }
}


static void test_soft_friction_vibration_does_not_ratchet(void) {
  /* a stance foot under 0.6 mu N shaken by +-0.15 mu N at 40 Hz for 2 s: below u_elastic the
   * bristle is purely elastic, so the foot oscillates in place; the same with u_elastic = 0
   * (plastic flow at any load, as in LuGre-type laws) walks away: the test can tell them apart.
   * Positions are compared at the same phase (whole periods after the push) */
  double ts[3] = {kTPush + 0.5, kTPush + 1.0, kTPush + 2.0};
  double drift[2];
  for (int i = 0; i < 2; i++) {
    cscSoftParams p = csc_softDefaultParams();
    if (i == 1) {
      p.u_elastic = 0;
    }
    double muN = p.mu * kLoad;
    Run r = runBlock(&p, 0.6 * muN, 0.15 * muN, 0, 0, ts, 3, 0);
    CS_EXPECT(r.ok);
    drift[i] = (r.y[2][0] - r.y[0][0]) / (r.t[2] - r.t[0]);
    printf("  shaken at 0.6 +- 0.15 mu N, u_elastic %.1f: drift %.3g um/s, %ld steps\n",
           p.u_elastic, 1e3 * drift[i], r.nsteps);
  }
  /* default: no ratcheting beyond integrator noise (measured 8e-8 um/s); bound 0.01 um/s */
  CS_EXPECT(fabs(drift[0]) < 1e-5);
  /* fully plastic: a steady walk (measured 62 um/s); bound 1 um/s, the creep requirement */
  CS_EXPECT(drift[1] > 1e-3);
}


static void test_soft_friction_step_mode_1ms_10ms(void) {
  cscSoftParams p = csc_softDefaultParams();
  p.history = CSC_HISTORY_STEP;
  double Hs[2] = {1e-3, 1e-2};
  for (int i = 0; i < 2; i++) {
    char what[64];
    snprintf(what, sizeof what, "step H = %g ms", 1e3 * Hs[i]);
    Run r = pushRun(&p, 0.9, Hs[i], 2.0);
    checkStick(&r, what);
    double f;
    r = pushRun(&p, 1.1, Hs[i], 0.5);
    checkSlide(&r, 1.1, what, &f);
    r = pushRun(&p, 2.0, Hs[i], 0.5);
    checkSlide(&r, 2.0, what, &f);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_soft_normal_foot_flat_closed_form);
  CS_RUN(test_soft_normal_capsule_closed_forms);
  CS_RUN(test_soft_capsule_slides_onto_an_edge_smoothly);
  CS_RUN(test_soft_normal_never_pulls_and_is_continuous);
  CS_RUN(test_soft_friction_law_states);
  CS_RUN(test_soft_foot_patch_translation_and_torsion);
  CS_RUN(test_soft_foot_broad_phase_is_exact);
  CS_RUN(test_soft_capsule_friction_slides_rolls_and_splits);
  CS_RUN(test_soft_step_update_keeps_force_continuous);
  CS_RUN(test_soft_leg_per_shape_equals_whole_and_cost);
  CS_RUN(test_soft_bad_input_is_refused);
  CS_RUN(test_soft_foot_rests_flat_without_rocking);
  CS_RUN(test_soft_friction_integrated_holds_and_slides);
  CS_RUN(test_soft_friction_vibration_does_not_ratchet);
  CS_RUN(test_soft_friction_step_mode_1ms_10ms);
  return cs_testSummary();
}

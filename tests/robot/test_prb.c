/* test_prb.c: the pseudo-rigid-body leg reproduces the constant-curvature shapes its
 * calibration map asks for, bends the right way, sags under its weight as a cantilever and
 * vibrates at the cantilever's first natural frequency; behind the leg interface
 * (robot_leg.h) its state round-trips bit for bit, reset returns it to its creation, its
 * contact shapes are its ODE geoms, it is an in-world level (no wrench, no gains), and a
 * weightless leg (conditions `paper`) keeps its mass but feels no gravity.
 *
 * Set-up: one leg hanging from a support welded to the world, gravity off unless stated,
 * pressures held until the leg is at rest: the slowest (swing) mode, ~15 rad/s, decays with
 * a loss factor of ~0.3 (robot_prb.c), e^{-0.15 * 15 t}: 3 s leave 1e-3 of the motion. */
#include <math.h>
#include <ode/ode.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "robot_analytic.h"
#include "robot_calibration.h"
#include "robot_gaitdesign.h"
#include "robot_leg.h"
#include "robot_odebody.h"

typedef struct {
  dWorldID world;
  dSpaceID space;
  dBodyID support;
  csrLeg* leg;
  csrActuator act;
  csrLegParams par;
  csrProvisionalMap* pm;
  csrBendMap map;
} Rig;

static const double kH = 1e-3;
/* spec.weightless of the next rig (conditions `paper`), reset to 0 by every rigInitWith */
static int g_weightless = 0;


/* build the rig for `act` (NULL: the `leg` preset) with `par` (NULL: its default leg params) */
/* links: the prb level's setting links (0: its default) */
static void rigInitWith(Rig* r, double gravity, const csrActuator* act, const csrLegParams* par,
                        int links) {
  memset(r, 0, sizeof *r);
  csError err;
  if (act) {
    r->act = *act;
  } else {
    CS_EXPECT(csr_actuatorPreset(&r->act, "leg", &err) == CS_OK);
  }
  char path[512];
  snprintf(path, sizeof path, "%s/robot/calibration_provisional.txt", getenv("CS_SOURCE_DIR"));
  r->pm = csr_provisionalMapCreate(path, &r->act, &err);
  CS_EXPECT(r->pm != NULL);
  r->map = csr_provisionalMapGet(r->pm);
  r->par = par ? *par : csr_defaultLegParams(&r->act);
  r->world = dWorldCreate();
  dWorldSetGravity(r->world, 0, -gravity, 0);
  dWorldSetQuickStepNumIterations(r->world, 200);
  r->space = dSimpleSpaceCreate(0);
  r->support = dBodyCreate(r->world);
  dBodySetPosition(r->support, 0, 0, 0);
  dJointID weld = dJointCreateFixed(r->world, 0);
  dJointAttach(weld, r->support, 0);
  dJointSetFixed(weld);
  csrLegSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.act = &r->act;
  spec.params = &r->par;
  csrLegSettings set;
  csr_legSettingsDefault(&csr_leg_prb, &set);
  if (links > 0) {
    CS_EXPECT(csr_legSettingSet(&csr_leg_prb, &set, "links", links, NULL) == CS_OK);
  }
  spec.settings = &set;
  spec.map = &r->map;
  spec.world = r->world;
  spec.space = r->space;
  spec.support = r->support;
  spec.h = kH;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0}; /* e1 = +x, e2 = +z, e3 = -y */
  memcpy(spec.frame, F, sizeof F);
  spec.weightless = g_weightless;
  g_weightless = 0;
  r->leg = csr_leg_prb.create(&spec, &err);
  CS_EXPECT(r->leg != NULL);
}


static void rigInit(Rig* r, double gravity) { rigInitWith(r, gravity, NULL, NULL, 0); }


static void rigFree(Rig* r) {
  csr_leg_prb.destroy(r->leg);
  dSpaceDestroy(r->space);
  dWorldDestroy(r->world);
  csr_provisionalMapDestroy(r->pm);
}


/* hold pressures for `seconds` and return the foot in the leg frame (e1, e2, e3) */
static void settle(Rig* r, const double p[12], double seconds, double foot[3]) {
  for (int i = 0; i < (int)(seconds / kH); i++) {
    CS_EXPECT(csr_leg_prb.actuate(r->leg, 0, p, 0, p) == 0);
    dWorldStep(r->world, kH);
  }
  double cl[2 * 3];
  csr_leg_prb.centerline(r->leg, 2, cl);
  /* world (x, y, z) -> leg frame (e1 = x, e2 = z, e3 = -y) */
  foot[0] = cl[3];
  foot[1] = cl[5];
  foot[2] = -cl[4];
}


/* S-shape and crouch: the chain's foot matches the constant-curvature FK of the same map */
static void test_prb_matches_cc_shapes(void) {
  Rig r;
  rigInit(&r, 0);
  csError err;
  csrFlatRoadDesign des;
  CS_EXPECT(csr_designFlatRoad(&r.act, &r.map, 39.0, 0.5, &des, &err) == CS_OK);
  double pS[12] = {0}, pZ[12] = {0}, ref[3], foot[3];
  pS[2] = pS[3] = des.p_stroke;
  pS[4] = pS[5] = des.p_stroke;
  memcpy(pZ, pS, sizeof pS);
  pZ[4] = pZ[5] = des.p_crouch_II2;
  pZ[10] = pZ[11] = des.p_stroke;
  for (int shape = 0; shape < 2; shape++) {
    const double* p = shape ? pZ : pS;
    CS_EXPECT(csr_footFromPressures(&r.act, &r.map, p, ref, &err) == CS_OK);
    settle(&r, p, 3.0, foot);
    /* tolerance 1.5 mm: the tangent polygon of 4 links per segment misplaces the end of a
     * 40-80 deg arc by ~L θ^2/(24 n^2) < 0.6 mm per segment, and the soft joints settle to
     * ~1e-3 of their target under the joint constraint's ERP */
    CS_EXPECT_NEAR(foot[0], ref[0], 1.5, 0);
    CS_EXPECT_NEAR(foot[1], ref[1], 1.5, 0);
    CS_EXPECT_NEAR(foot[2], ref[2], 1.5, 0);
  }
  /* the S-shape puts the foot forward (+e1), by the designed stroke */
  CS_EXPECT(des.stroke > 38.9 && des.stroke < 39.1);
  rigFree(&r);
}


/* Ω1&Ω2 of II1 (at +e1) bend the leg towards -e1 (towards Ω3&Ω4), Ω1&Ω4 (at +e2) towards -e2 */
static void test_prb_bend_direction(void) {
  Rig r;
  rigInit(&r, 0);
  double p[12] = {0}, foot[3];
  p[0] = p[1] = 0.1;
  settle(&r, p, 3.0, foot);
  CS_EXPECT(foot[0] < -5 && fabs(foot[1]) < 0.5);
  memset(p, 0, sizeof p);
  p[0] = p[3] = 0.1;
  settle(&r, p, 3.0, foot);
  CS_EXPECT(foot[1] < -5 && fabs(foot[0]) < 0.5);
  rigFree(&r);
}


/* vented leg under gravity, held horizontal? No: hanging straight, gravity along the leg
 * leaves it straight (no bending load) and it stays at full length */
static void test_prb_hanging_straight_under_gravity(void) {
  Rig r;
  rigInit(&r, 9810);
  double p[12] = {0}, foot[3];
  settle(&r, p, 0.5, foot);
  double L = csr_actuatorLength(&r.act);
  /* the joints are soft only in bending: the axial chain is rigid up to ODE's constraint
   * error, ~1e-6 mm here */
  CS_EXPECT_NEAR(foot[2], L, 1e-3, 0);
  CS_EXPECT_NEAR(foot[0], 0, 1e-6, 0);
  rigFree(&r);
}


/* a horizontal leg sags under its own weight like a cantilever. Small load (g/10) so that
 * linear beam theory holds: w_tip = ∫ M(s) (L - s) / EI(s) ds with M(s) = q (L - s)^2 / 2,
 * EI = E_bend I over the segments and rigid over the solid joints LS12, LS23 (as the chain
 * models them), q the mean weight per length. */
static void test_prb_cantilever_sag(void) {
  Rig r;
  rigInit(&r, 0);
  const double g = 981.0;
  dWorldSetGravity(r.world, -g, 0, 0); /* across the hanging leg, along -e1 */
  double p[12] = {0}, foot[3];
  settle(&r, p, 3.0, foot);
  double L = csr_actuatorLength(&r.act);
  double q = csr_leg_prb.mass(r.leg) * g / L;
  csrSectionProps sp;
  csError err;
  CS_EXPECT(csr_analyticSectionCompute(&r.act, NULL, &sp, &err) == CS_OK);
  double EI = r.par.E_bend * sp.I_holed, w = 0;
  const int n = 20000;
  for (int i = 0; i < n; i++) {
    double s = (i + 0.5) * L / n;
    int in_joint = 0;
    for (int k = 0; k < 2; k++) {
      double j0 = csr_actuatorSegmentStart(&r.act, k) + r.act.S[k];
      in_joint |= (s > j0 && s < j0 + r.act.LS[k]);
    }
    if (!in_joint) {
      w += q * (L - s) * (L - s) / 2 * (L - s) / EI * (L / n);
    }
  }
  /* 8 %: the chain's mass is not uniform (hollow chambered parts, solid caps and joints)
   * while the formula uses the mean, and the chain's hinge stiffness uses the holed section
   * over the caps too; both shift the tip by a few per cent */
  CS_EXPECT_NEAR(-foot[0], w, 0, 0.08);
  rigFree(&r);
}


/* Free vibration of a uniform cantilever (Euler-Bernoulli): ω1 = β1² sqrt(EI / (μ L⁴)),
 * β1 = 1.8751 (1 + cos β cosh β = 0). The actuator is made uniform for this (no solid joints,
 * chambers over the whole segment: LS12 = LS23 = 0, c -> 0) and undamped (damping_time 0).
 * The leg starts from its static sag under a small lateral load (close to mode 1) and swings
 * freely; ω is taken from the mean period over the zero crossings of the tip's deflection.
 * The chain is a Hencky bar-chain (hinges at the link mid-points), whose frequencies converge
 * as O(1/N²), here to the Rayleigh beam (the links' rotary inertia lowers ω by 0.19 %).
 * Measured errors against E-B: +2.39 % (3 links), +0.41 % (6), +0.00 % (12), -0.14 % (24),
 * -0.18 % (48); the step's numerical dispersion (ω h = 0.019) is ~1e-4. Returns ω/ω_EB - 1. */
static void uniformLeg(csrActuator* act) {
  csError err;
  CS_EXPECT(csr_actuatorPreset(act, "leg", &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(act, "LS12", 0, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(act, "LS23", 0, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(act, "c", 1e-6, &err) == CS_OK);
}


static double prbFirstFrequencyError(int links_per_segment) {
  csrActuator act;
  uniformLeg(&act);
  csrLegParams par = csr_defaultLegParams(&act);
  par.damping_time = 0;
  Rig r;
  rigInitWith(&r, 0, &act, &par, links_per_segment);
  const double p[12] = {0};
  /* static sag under g/100 across the leg, with damping from a temporary world damping */
  dWorldSetGravity(r.world, -98.1, 0, 0);
  dWorldSetLinearDamping(r.world, 0.05);
  dWorldSetAngularDamping(r.world, 0.05);
  double foot[3];
  settle(&r, p, 2.0, foot);
  dWorldSetLinearDamping(r.world, 0);
  dWorldSetAngularDamping(r.world, 0);
  dWorldSetGravity(r.world, 0, 0, 0);
  /* release: record the zero crossings of the tip's e1 deflection */
  double prev = foot[0], t = 0, first = NAN, last = NAN;
  int ncross = 0;
  for (int i = 0; i < (int)(3.0 / kH); i++) {
    CS_EXPECT(csr_leg_prb.actuate(r.leg, 0, p, 0, p) == 0);
    dWorldStep(r.world, kH);
    t += kH;
    double cl[6];
    csr_leg_prb.centerline(r.leg, 2, cl);
    double x = cl[3];
    if ((prev < 0) != (x < 0)) {
      double tc = t - kH * x / (x - prev); /* linear interpolation inside the step */
      if (ncross == 0) {
        first = tc;
      }
      last = tc;
      ncross++;
    }
    prev = x;
  }
  CS_EXPECT(ncross >= 6);
  double omega = 2 * CS_PI / (2 * (last - first) / (ncross - 1)); /* two crossings per period */
  double L = csr_actuatorLength(&r.act);
  double mu = csr_leg_prb.mass(r.leg) / L;
  double EI = par.E_bend * csr_legSectionI(&r.act);
  /* β1 from 1 + cos β cosh β = 0 by bisection on [1.8, 1.9] */
  double lo = 1.8, hi = 1.9;
  for (int it = 0; it < 60; it++) {
    double mid = 0.5 * (lo + hi);
    double f = 1 + cos(mid) * cosh(mid);
    (f > 0 ? (lo = mid) : (hi = mid));
  }
  double beta = 0.5 * (lo + hi);
  double omega_eb = beta * beta * sqrt(EI / (mu * L * L * L * L));
  printf("  prb %2d links: omega %.4f rad/s, Euler-Bernoulli %.4f rad/s, error %+.3f %%\n",
         CSR_NSEG * links_per_segment, omega, omega_eb, 100 * (omega / omega_eb - 1));
  rigFree(&r);
  return omega / omega_eb - 1;
}


static void test_prb_cantilever_vibration(void) {
  double e12 = prbFirstFrequencyError(4), e24 = prbFirstFrequencyError(8);
  double e48 = prbFirstFrequencyError(16);
  /* the default chain (4 links per segment): 1 % covers the O(1/N²) error of 3..12 links */
  CS_EXPECT(fabs(e12) < 0.01);
  /* O(1/N²): each halving of the link length shrinks the change by ~4 (measured 2.9, 3.6) */
  CS_EXPECT(fabs(e48 - e24) < fabs(e24 - e12) / 2.5);
  /* the limit (Richardson) is the Rayleigh beam: the links carry rotary inertia
   * m (2a)² / 12 per unit length (dMassSetBoxTotal), which E-B neglects; by Rayleigh's
   * quotient with the E-B mode φ, ω/ω_EB = 1 - r² ∫φ'² / (2 ∫φ²) to first order in
   * r² = (2a)² / 12. Quadrature of the closed-form mode on 2000 points (error ~1e-7). */
  csrActuator act;
  uniformLeg(&act);
  double beta = 1.8751040687119611, L = csr_actuatorLength(&act), a = act.a;
  double sig = (cosh(beta) + cos(beta)) / (sinh(beta) + sin(beta));
  double i0 = 0, i1 = 0;
  const int n = 2000;
  for (int k = 0; k < n; k++) {
    double x = (k + 0.5) / n * beta; /* βx/L */
    double phi = cosh(x) - cos(x) - sig * (sinh(x) - sin(x));
    double dphi = (sinh(x) + sin(x) - sig * (cosh(x) - cos(x))) * beta / L;
    i0 += phi * phi, i1 += dphi * dphi;
  }
  double r2 = (2 * a) * (2 * a) / 12;
  double e_rayleigh = -r2 * i1 / (2 * i0);
  double e_limit = e48 + (e48 - e24) / 3;
  printf("  Richardson limit %+.4f %%, Rayleigh beam %+.4f %%\n", 100 * e_limit,
         100 * e_rayleigh);
  /* 5e-4: the extrapolation's remainder (third difference ~1e-4) and the first-order
   * expansion in r² (~(r/L)^4 ~ 1e-6) */
  CS_EXPECT_NEAR(e_limit, e_rayleigh, 5e-4, 0);
}


/* step the rig n times at pressures p (ODE's dWorldStep: no random row order) */
static void stepRig(Rig* r, const double p[12], int n) {
  for (int i = 0; i < n; i++) {
    CS_EXPECT(csr_leg_prb.actuate(r->leg, 0, p, kH, p) == 0);
    dWorldStep(r->world, kH);
  }
}


/* get/set/reset: bit-exact, including the joint targets behind the map cache. The rig's
 * support is welded to the world by a soft constraint and moves by ~1e-10 mm under the leg's
 * reactions: it is part of the rig's state (in the driver: of the robot's) */
static void test_prb_state_round_trip_and_reset(void) {
  Rig r;
  rigInit(&r, 981);
  int n = csr_leg_prb.stateSize(r.leg);
  /* 13 bodies of 13 doubles and 3 segments' caches of 7 */
  CS_EXPECT(n == 13 * 13 + 3 * 7);
  double* s_init = malloc(n * sizeof(double));
  double* s0 = malloc(n * sizeof(double));
  double* r1 = malloc(n * sizeof(double));
  double* r2 = malloc(n * sizeof(double));
  csr_leg_prb.getState(r.leg, s_init);
  /* mid-motion: the S-shape pressures applied 0.2 s ago, the leg still swinging */
  double p[12] = {0}, q[12] = {0};
  p[2] = p[3] = p[4] = p[5] = 0.12;
  stepRig(&r, p, 200);
  csr_leg_prb.getState(r.leg, s0);
  double sup0[CSR_BODY_STATE];
  csr_bodyStateGet(r.support, sup0);
  /* the next pressures differ, so the cache is re-evaluated after the restore as well */
  q[2] = q[3] = q[4] = q[5] = 0.15;
  stepRig(&r, q, 150);
  csr_leg_prb.getState(r.leg, r1);
  CS_EXPECT(csr_leg_prb.setState(r.leg, s0) == 0);
  CS_EXPECT(csr_bodyStateSet(r.support, sup0) == 0);
  csr_leg_prb.getState(r.leg, r2);
  CS_EXPECT(memcmp(r2, s0, n * sizeof(double)) == 0);
  stepRig(&r, q, 150);
  csr_leg_prb.getState(r.leg, r2);
  CS_EXPECT(memcmp(r1, r2, n * sizeof(double)) == 0);
  csr_leg_prb.reset(r.leg);
  csr_leg_prb.getState(r.leg, r1);
  CS_EXPECT(memcmp(r1, s_init, n * sizeof(double)) == 0);
  /* invalid states are refused and change nothing */
  memcpy(r1, s0, n * sizeof(double));
  r1[13 * 4 + 3] = 5; /* body 4's quaternion w: not unit */
  CS_EXPECT(csr_leg_prb.setState(r.leg, r1) < 0);
  r1[13 * 4 + 3] = s0[13 * 4 + 3];
  r1[n - 1] = 0.5; /* a cache flag that is neither 0 nor 1 */
  CS_EXPECT(csr_leg_prb.setState(r.leg, r1) < 0);
  r1[n - 1] = s0[n - 1];
  r1[7] = NAN;
  CS_EXPECT(csr_leg_prb.setState(r.leg, r1) < 0);
  csr_leg_prb.getState(r.leg, r2);
  CS_EXPECT(memcmp(r2, s_init, n * sizeof(double)) == 0);
  free(s_init);
  free(s0);
  free(r1);
  free(r2);
  rigFree(&r);
}


/* in-world: advance is a no-op with a zero wrench, the gains are zero; the contact shapes are
 * the ODE geoms (capsules of radius a along the links, a box foot) covering the leg */
static void test_prb_interface_in_world(void) {
  Rig r;
  rigInit(&r, 0);
  CS_EXPECT(csr_leg_prb.in_world == 1 && !strcmp(csr_leg_prb.name, "prb"));
  csrBaseState b = {{0, 0, 0}, {1, 0, 0, 0, 0, -1, 0, 1, 0}, {0, 0, 0}, {0, 0, 0}};
  csrWrench w = {{1, 1, 1}, {1, 1, 1}};
  CS_EXPECT(csr_leg_prb.advance(r.leg, 0, 1e-3, &b, &b, &w, NULL) == 0);
  CS_EXPECT(w.f[0] == 0 && w.f[1] == 0 && w.f[2] == 0 && w.m[0] == 0 && w.m[2] == 0);
  double K[36], C[36];
  csr_leg_prb.interfaceGains(r.leg, K, C);
  for (int i = 0; i < 36; i++) {
    CS_EXPECT(K[i] == 0 && C[i] == 0);
  }
  int n = csr_leg_prb.contactShapes(r.leg, NULL, 0);
  CS_EXPECT(n == 13);
  csrContactShape sh[13];
  CS_EXPECT(csr_leg_prb.contactShapes(r.leg, sh, 13) == 13);
  double L = csr_actuatorLength(&r.act);
  for (int i = 0; i < n; i++) {
    CS_EXPECT(sh[i].kind == (i == n - 1 ? CSR_SHAPE_BOX : CSR_SHAPE_CAPSULE));
    CS_EXPECT(i == 0 || sh[i].s > sh[i - 1].s);
    if (sh[i].kind == CSR_SHAPE_CAPSULE) {
      /* the straight leg hangs along -y from the hip at the origin: the axis lies on it, the
       * capsule's caps end inside its link (within one radius of the link's ends) */
      CS_EXPECT_NEAR(sh[i].radius, r.act.a, 1e-12, 0);
      CS_EXPECT_NEAR(sh[i].a[0], 0, 1e-9, 0);
      CS_EXPECT_NEAR(sh[i].b[2], 0, 1e-9, 0);
      CS_EXPECT(sh[i].a[1] > sh[i].b[1]); /* from the hip side down */
      CS_EXPECT_NEAR(-0.5 * (sh[i].a[1] + sh[i].b[1]), sh[i].s, 1e-9, 0);
    } else {
      /* the foot: a box of half side a ending at the foot, L below the hip */
      CS_EXPECT_NEAR(sh[i].half[0], r.act.a, 1e-12, 0);
      CS_EXPECT_NEAR(-sh[i].a[1] + sh[i].half[2], L, 1e-9, 0);
    }
  }
  rigFree(&r);
}


/* conditions `paper`: gravity across the leg moves neither a weightless leg nor its mass */
static void test_prb_weightless_leg_does_not_sag(void) {
  Rig r;
  g_weightless = 1;
  rigInit(&r, 0);
  dWorldSetGravity(r.world, -9810, 0, 0);
  double p[12] = {0}, foot[3];
  settle(&r, p, 0.5, foot);
  /* no load: the foot stays under the hip up to the joints' round-off drift (measured 4e-9
   * mm; with its weight the same leg sags tens of mm) */
  CS_EXPECT_NEAR(foot[0], 0, 1e-6, 0);
  CS_EXPECT(csr_leg_prb.mass(r.leg) > 0);
  rigFree(&r);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  dInitODE2(0);
  CS_RUN(test_prb_bend_direction);
  CS_RUN(test_prb_matches_cc_shapes);
  CS_RUN(test_prb_hanging_straight_under_gravity);
  CS_RUN(test_prb_cantilever_sag);
  CS_RUN(test_prb_cantilever_vibration);
  CS_RUN(test_prb_state_round_trip_and_reset);
  CS_RUN(test_prb_interface_in_world);
  CS_RUN(test_prb_weightless_leg_does_not_sag);
  dCloseODE();
  return cs_testSummary();
}

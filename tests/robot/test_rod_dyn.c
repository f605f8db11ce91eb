/* test_rod_dyn.c: the Cosserat rod's dynamics (robot_rod_dyn.c, robot_rod_linsol.c): CVODE BDF
 * with the reduced Newton solver, the base drive, the wrench, the interface gains, contact hook
 * and failure handling.
 *
 * Cases:
 *  - first_bending_frequency: a slender uniform clamped-free rod (shear and rotary inertia made
 *    negligible) released from its first Euler-Bernoulli mode shape vibrates at
 *    ω1 = 1.8751² √(EI/(ρA L⁴)), converging as O(1/N²).
 *  - energy_does_not_grow: the leg under gravity released from a bent state: without damping
 *    the total energy stays at its initial value (BDF only loses a little), with Kelvin-Voigt
 *    damping it never increases between macro steps and decays.
 *  - pressure_step_steady_curvature: after a pressure step, gravity off, the leg settles with
 *    each segment at the calibrated bend and the tip at the constant-curvature kinematics.
 *  - hanging_wrench_is_weight: a bent leg hanging under gravity settles; the step-averaged base
 *    wrench is its weight and the weight's moment about the hip, as the static solution.
 *  - accelerating_base_is_gravity: a hip accelerating uniformly (gravity off) deflects the leg
 *    as gravity -a would, and the leg pulls the support back with -M a.
 *  - interface_gains_closed_form: at rest the axial, shear and rotational gains are the hip
 *    element's EA/l, kGA/l and the hip node's EI/(l/2), damping τ_d times them.
 *  - contact_hook_carries_weight: a floor under the foot (a penalty spring through the hook)
 *    takes the weight off the hip; the hook's history (contact time) is integrated.
 *  - failed_advance_changes_nothing: a hook that fails (NaN force) makes advance return > 0
 *    with the state bit-identical; the next advance succeeds; get/set state round-trips.
 *  - base_jumps_and_restarts: the hip starting a step 1 µm from where the last one ended (a
 *    coupling predictor's correction) is integrated across; 1 mm restarts CVODE. */
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "robot_analytic.h"
#include "robot_rod.h"

enum { MAXN = 64 };

/* 10 x 10 mm square uniform piece, E = 1 MPa, density 1e-9 t/mm³ (tests' uniform rod) */
static csrRodPiece uniformPiece(double L, int n, double Gfac, double rot_fac) {
  csrRodPiece p;
  memset(&p, 0, sizeof p);
  const double A = 100, I = 1e4 / 12, E = 1.0, G = Gfac * E, k = 10.0 * 1.5 / 17.5;
  p.length = L;
  p.nelem = n;
  p.segment = -1;
  p.section.EA = E * A;
  p.section.GA[0] = p.section.GA[1] = k * G * A;
  p.section.EI[0] = p.section.EI[1] = E * I;
  p.section.GJ = G * 0.1406 * 1e4;
  p.rhoA = 1e-9 * A;
  p.rhoI[0] = p.rhoI[1] = 1e-9 * I * rot_fac;
  p.rhoI[2] = 2e-9 * I * rot_fac;
  return p;
}


/* a linear calibration: Ω1&Ω2 bend II_s towards -e1 by 3 (1 + s/10) rad/MPa, no stretch */
static int linearMap(const void* ctx, int seg, const double p[4], double bend[2],
                     double* stretch) {
  (void)ctx;
  double f = 3.0 * (1.0 + 0.1 * seg);
  bend[0] = -f * (p[0] + p[1] - p[2] - p[3]) * 0.5;
  bend[1] = -f * (p[0] - p[1] - p[2] + p[3]) * 0.5;
  *stretch = 1.0;
  return 0;
}


/* the `leg` rod hanging (e3 = -y) from hip (0, 0, 0) with gravity g_y (mm/s², 0 = off) */
static int hangingLeg(csrActuator* act, const csrBendMap* map, csrRodParams* par, double g_y,
                      const csrRodContact* contact, csrRodModel** m, csrRodData** d) {
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(act, "leg", &err);
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.act = act;
  sp.params = par;
  sp.map = map;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(sp.frame, F, sizeof F);
  sp.gravity[1] = g_y;
  if (contact) {
    sp.contact = *contact;
  }
  *m = csr_rodModelCreate(&sp, &err);
  *d = *m ? csr_rodDataCreate(*m, &err) : NULL;
  if (!*d) {
    fprintf(stderr, "  %s\n", err.msg);
    csr_rodModelDestroy(*m);
  }
  CS_EXPECT(*d != NULL);
  return *d != NULL;
}


/* advance n macro steps of H with the base at rest and constant pressures p (NULL: vented);
 * wavg: the wrench of the last step; returns 0 or the first failure */
static int runSteps(const csrRodModel* m, csrRodData* d, double* t, double H, int n,
                    const double* p, csrWrench* wavg) {
  const double zero[12] = {0};
  const double* pp = p ? p : zero;
  csrBaseState b = csr_rodRestBase(m);
  csError err;
  for (int k = 0; k < n; k++) {
    int rc = csr_rodActuate(m, d, *t, pp, *t + H, pp);
    if (rc == 0) {
      rc = csr_rodAdvance(m, d, *t, H, &b, &b, wavg, &err);
    }
    if (rc != 0) {
      fprintf(stderr, "  advance failed at t = %g: %s\n", *t, err.msg);
      return rc;
    }
    *t += H;
  }
  return 0;
}


/* first cantilever mode of Euler-Bernoulli: φ(s) and φ'(s), βL = 1.87510407 */
static void modeShape(double s, double L, double* phi, double* dphi) {
  const double bl = 1.87510407, b = bl / L;
  const double sg = (cosh(bl) + cos(bl)) / (sinh(bl) + sin(bl));
  double x = b * s;
  *phi = cosh(x) - cos(x) - sg * (sinh(x) - sin(x));
  *dphi = b * (sinh(x) + sin(x) - sg * (cosh(x) - cos(x)));
}


/* measured first frequency (rad/s) of the uniform rod with n elements */
static double measureFrequency(int n) {
  const double L = 200, EI = 1e4 / 12, rhoA = 1e-7;
  const double w_eb = 1.87510407 * 1.87510407 * sqrt(EI / (rhoA * L * L * L * L));
  const double T = 2 * CS_PI / w_eb;
  csrRodParams par = csr_rodDefaultParams(NULL);
  /* a trace of Kelvin-Voigt damping overdamps the stiff axial/shear/rotation modes (which BDF
   * cannot step across undamped) and shifts ω1 by ζ²/2 = (ω1 τ/2)²/2 = 1e-7 */
  par.damping_time = 1e-4;
  /* time error far below the O(h²) discretisation error being measured */
  par.rtol = 1e-9;
  par.atol_pos = par.atol_rot = 1e-10;
  par.atol_vel = par.atol_omega = 1e-8;
  /* shear 100 x stiffer and rotary inertia 1e-3 x smaller: the rod is an Euler-Bernoulli beam
   * (the Timoshenko and Rayleigh corrections ~ (r/L)² (1 + E/kG) ~ 1e-3 would otherwise mix in;
   * left: ~1e-6) */
  csrRodPiece p = uniformPiece(L, n, 100.0, 1e-3);
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.params = &par;
  csu_eye3(sp.frame);
  csError err;
  csrRodModel* m = csr_rodModelCreatePieces(&p, 1, &sp, &err);
  csrRodData* d = m ? csr_rodDataCreate(m, &err) : NULL;
  if (!d) {
    csr_rodModelDestroy(m);
    return NAN;
  }
  /* the first mode shape, tip 1e-3 L: nodes displaced along e1, frames turned about e2 */
  const int N = csr_rodElements(m), ns = csr_rodStateSize(m);
  const double* s = csr_rodNodeArc(m);
  double* y = calloc((size_t)ns, sizeof(double));
  csr_rodGetState(m, d, y);
  double phiL, dum;
  modeShape(L, L, &phiL, &dum);
  const double A = 1e-3 * L / phiL;
  for (int e = 1; e <= N; e++) {
    double* b = y + csr_rodStateOffset(m, e);
    double ph, dph, ph0, dph0;
    modeShape(s[e], L, &ph, &dph);
    modeShape(0.5 * (s[e - 1] + s[e]), L, &ph0, &dph0);
    b[0] = A * ph;
    double ang = A * dph0; /* tangent angle: rotation about +e2 turns d3 towards +e1 */
    b[3] = cos(0.5 * ang);
    b[4] = 0;
    b[5] = sin(0.5 * ang);
    b[6] = 0;
  }
  csr_rodSetState(m, d, y);
  /* tip x after each macro step (T/400), upward zero crossings by linear interpolation */
  const double H = T / 400;
  double t = 0, prev = A * phiL, first = NAN, last = NAN;
  int ncross = 0;
  double x[3 * (MAXN + 1)];
  csrBaseState b = csr_rodRestBase(m);
  for (int k = 0; k < 400 * 4 + 100; k++) {
    if (csr_rodAdvance(m, d, t, H, &b, &b, NULL, &err) != 0) {
      fprintf(stderr, "  %s\n", err.msg);
      break;
    }
    t += H;
    csr_rodNodes(m, d, x);
    double cur = x[3 * N];
    if (prev < 0 && cur >= 0) {
      double tc = t - H * cur / (cur - prev);
      if (ncross == 0) {
        first = tc;
      }
      last = tc;
      ncross++;
    }
    prev = cur;
  }
  free(y);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
  return ncross >= 2 ? 2 * CS_PI * (ncross - 1) / (last - first) : NAN;
}


static void first_bending_frequency(void) {
  const double L = 200, EI = 1e4 / 12, rhoA = 1e-7;
  const double w_eb = 1.87510407 * 1.87510407 * sqrt(EI / (rhoA * L * L * L * L));
  double e[2];
  const int ns[2] = {10, 20};
  for (int j = 0; j < 2; j++) {
    double w = measureFrequency(ns[j]);
    e[j] = (w - w_eb) / w_eb;
    printf("  N = %d: ω1 = %.8g rad/s (Euler-Bernoulli %.8g), error %+.3e\n", ns[j], w, w_eb,
           e[j]);
  }
  /* lumped masses and midpoint curvature: O(h²); measured -8.31e-3 and -2.11e-3 (ratio 3.94);
   * the residual Timoshenko/Rayleigh correction (shear x100, rotary inertia x1e-3) is ~1e-6 */
  CS_EXPECT_NEAR(e[0] / e[1], 4.0, 0.2, 0);
  CS_EXPECT_NEAR(e[1], 0, 3e-3, 0);
}


static void energy_does_not_grow(void) {
  csrBendMap map = {linearMap, NULL, "linear", INFINITY};
  for (int damped = 0; damped < 2; damped++) {
    csrActuator act;
    csrRodParams par = csr_rodDefaultParams(NULL);
    par.damping_time = damped ? 0.02 : 0;
    /* undamped, the stiff modes are on the imaginary axis: BDF of order <= 2 (A-stable) */
    par.max_order = damped ? 5 : 2;
    par.rtol = damped ? 1e-4 : 1e-7;
    csrRodModel* m;
    csrRodData* d;
    if (!hangingLeg(&act, &map, &par, -9810, NULL, &m, &d)) {
      return;
    }
    /* bent by a lateral tip force, then released */
    csrRodStaticLoad ld;
    memset(&ld, 0, sizeof ld);
    ld.gravity = 1;
    ld.tip_force[0] = 0.3;
    csError err;
    CS_EXPECT(csr_rodStatic(m, d, &ld, NULL, &err) == CS_OK);
    const double z3[3] = {0, 0, 0};
    csr_rodSetTipLoad(d, z3, z3);
    csrRodEnergy e0;
    csr_rodEnergy(m, d, &e0);
    double E0 = e0.kinetic + e0.elastic + e0.gravity, Emax = E0, Eprev = E0, worst_rise = 0;
    double t = 0;
    for (int k = 0; k < 200; k++) {
      if (runSteps(m, d, &t, 5e-3, 1, NULL, NULL) != 0) {
        CS_EXPECT(0);
        break;
      }
      csrRodEnergy e;
      csr_rodEnergy(m, d, &e);
      double E = e.kinetic + e.elastic + e.gravity;
      Emax = fmax(Emax, E);
      worst_rise = fmax(worst_rise, E - Eprev);
      Eprev = E;
    }
    /* energies relative to the swing's energy scale: the work of the released tip force
     * (the elastic energy at t = 0 above the hanging state is ~0.3 N x 35 mm / 2) */
    double scale = fabs(e0.elastic) + 1e-3;
    printf("  damping %s: E(0) = %.9g, E(1 s) = %.9g, max E - E(0) = %.3g, worst rise per step "
           "%.3g N mm (swing energy %.4g N mm)\n", damped ? "on " : "off", E0, Eprev, Emax - E0,
           worst_rise, scale);
    if (!damped) {
      /* conservative semi-discretisation and A-stable BDF2: never above E(0) (measured: never;
       * the step-to-step wiggle is 4e-4 of the swing energy, below it); BDF2's numerical
       * dissipation of the higher modes loses 0.6 % in 1 s at rtol 1e-7: bound 2 % */
      CS_EXPECT_NEAR(fmax(Emax - E0, 0), 0, 1e-6 * scale, 0);
      CS_EXPECT(E0 - Eprev < 0.02 * scale);
    } else {
      /* dissipative: never up from one macro step to the next (beyond the integrator's local
       * error, rtol 1e-4 of a ~5 N mm energy: 5e-4), and most of the swing's energy gone */
      CS_EXPECT(worst_rise <= 5e-4 * scale);
      CS_EXPECT(E0 - Eprev > 0.5 * scale);
    }
    csr_rodDataDestroy(d);
    csr_rodModelDestroy(m);
  }
}


static void pressure_step_steady_curvature(void) {
  csrBendMap map = {linearMap, NULL, "linear", INFINITY};
  csrActuator act;
  csrRodParams par = csr_rodDefaultParams(NULL);
  par.damping_time = 0.1; /* well damped (ζ ≈ 0.75 at the first mode): settles in < 1 s */
  par.rtol = 1e-6;
  csrRodModel* m;
  csrRodData* d;
  if (!hangingLeg(&act, &map, &par, 0, NULL, &m, &d)) {
    return;
  }
  const double p[12] = {0.1, 0.1, 0, 0, 0.05, 0, 0, 0.05, 0, 0, 0.08, 0.08};
  double t = 0;
  CS_EXPECT(runSteps(m, d, &t, 5e-3, 300, p, NULL) == 0);
  double ang[3], tip[3];
  csr_rodSegmentAngles(m, d, ang, tip);
  csrSegmentStrain st[CSR_NSEG];
  memset(st, 0, sizeof st);
  for (int s = 0; s < CSR_NSEG; s++) {
    double bnd[2], str;
    linearMap(NULL, s, p + 4 * s, bnd, &str);
    st[s].lambda0 = str;
    st[s].kappa[0] = -bnd[0] / act.S[s];
    st[s].kappa[1] = -bnd[1] / act.S[s];
    st[s].theta = hypot(bnd[0], bnd[1]);
    printf("  II%d: %.6f deg (calibrated %.6f)\n", s + 1, ang[s] / CS_DEG, st[s].theta / CS_DEG);
    /* 1.5 s at ζ ≈ 0.75: the transient is e^-17 of the step; the integrator's tolerances
     * (rtol 1e-6) bound the rest: 1e-5 rad */
    CS_EXPECT_NEAR(ang[s], st[s].theta, 1e-5, 0);
  }
  double tipcc[3];
  csError err;
  csr_ccForwardKinematics(&act, st, 1, NULL, tipcc, NULL, &err);
  for (int k = 0; k < 3; k++) {
    /* 1e-5 rad over a 166 mm lever: 2e-3 mm */
    CS_EXPECT_NEAR(tip[k], tipcc[k], 5e-3, 0);
  }
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


static void hanging_wrench_is_weight(void) {
  csrBendMap map = {linearMap, NULL, "linear", INFINITY};
  csrActuator act;
  csrRodParams par = csr_rodDefaultParams(NULL);
  par.damping_time = 0.1;
  par.rtol = 1e-6;
  csrRodModel* m;
  csrRodData* d;
  if (!hangingLeg(&act, &map, &par, -9810, NULL, &m, &d)) {
    return;
  }
  const double p[12] = {0.1, 0.1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  double t = 0;
  csrWrench w;
  CS_EXPECT(runSteps(m, d, &t, 5e-3, 400, p, &w) == 0);
  const double M = csr_rodMass(m), g[3] = {0, -9810, 0};
  double mx[3], mom[3];
  csr_rodMassMoment(m, d, mx); /* hip at the origin: Σ m_i x_i */
  csu_cross3(mom, mx, g);
  printf("  dynamic: force (%.9g, %.9g, %.9g) N (weight %.9g), moment z %.9g (weight's %.9g) "
         "N mm\n", w.f[0], w.f[1], w.f[2], M * g[1], w.m[2], mom[2]);
  /* settled (2 s at ζ ≈ 0.75): residual motion e^-20; the step average then equals the
   * instantaneous wrench; measured 1e-9 relative */
  for (int k = 0; k < 3; k++) {
    CS_EXPECT_NEAR(w.f[k], M * g[k], 1e-6 * M * 9810, 0);
    CS_EXPECT_NEAR(w.m[k], mom[k], 1e-6 * M * 9810 * 166, 0);
  }
  CS_EXPECT(fabs(mom[2]) > 1.0);
  /* the same as the static equilibrium: foot positions within the tolerances (~1e-3 mm) */
  double x[3 * (MAXN + 1)], xs[3 * (MAXN + 1)];
  const int N = csr_rodElements(m);
  csr_rodNodes(m, d, x);
  csrRodStaticLoad ld;
  memset(&ld, 0, sizeof ld);
  memcpy(ld.p, p, sizeof ld.p);
  ld.gravity = 1;
  csError err;
  CS_EXPECT(csr_rodStatic(m, d, &ld, NULL, &err) == CS_OK);
  csr_rodNodes(m, d, xs);
  for (int k = 0; k < 3; k++) {
    CS_EXPECT_NEAR(x[3 * N + k], xs[3 * N + k], 1e-2, 0);
  }
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


/* The support receives exactly the momentum the leg's states lose: over any run of advances
 * Σ W H = M g T - (P(T) - P(0)) to round-off, whatever the integration error (the base force
 * is the leg's momentum balance, robot_rod_dyn.c). A shaken, bent, damped leg under gravity at
 * the shipped tolerances, 1 ms advances; the hip moves on a Lissajous path. Integrating the
 * clamp force instead missed this identity by the integration error: frictionless, the
 * robot's centre of mass drifted 24 mm in 9 s under Gauss-Seidel coupling. */
static void base_impulse_is_the_momentum_balance(void) {
  csrBendMap map = {linearMap, NULL, "linear", INFINITY};
  csrActuator act;
  csrRodParams par = csr_rodDefaultParams(NULL);
  csrRodModel* m;
  csrRodData* d;
  if (!hangingLeg(&act, &map, &par, -9810, NULL, &m, &d)) {
    return;
  }
  const double p[12] = {0.15, 0.15, 0, 0, 0, 0, 0, 0.1, 0.1, 0, 0, 0};
  const double H = 1e-3, A = 5.0, om = 2 * 3.14159265358979323846 * 3;
  csrBaseState rest = csr_rodRestBase(m), b0 = rest;
  double t = 0, J[3] = {0, 0, 0}, P0[3], P1[3], Jmax = 0;
  csr_rodMomentum(m, d, P0);
  csError err;
  int ok = 1;
  for (int k = 0; k < 600 && ok; k++) {
    csrBaseState b1 = rest;
    const double s = t + H;
    b1.x[0] += A * sin(om * s);
    b1.v[0] = A * om * cos(om * s);
    b1.x[1] += 0.5 * A * sin(2 * om * s);
    b1.v[1] = A * om * cos(2 * om * s);
    csrWrench w;
    ok = csr_rodActuate(m, d, t, p, s, p) == 0 &&
         csr_rodAdvance(m, d, t, H, &b0, &b1, &w, &err) == 0;
    for (int i = 0; i < 3; i++) {
      J[i] += w.f[i] * H;
      Jmax = fmax(Jmax, fabs(w.f[i]) * H);
    }
    b0 = b1;
    t = s;
  }
  CS_EXPECT(ok);
  csr_rodMomentum(m, d, P1);
  const double M = csr_rodMass(m), g[3] = {0, -9810, 0};
  double worst = 0, dP = 0;
  for (int i = 0; i < 3; i++) {
    const double r = J[i] - (M * g[i] * t - (P1[i] - P0[i]));
    worst = fmax(worst, fabs(r));
    dP = fmax(dP, fabs(P1[i] - P0[i]));
  }
  printf("  impulse to the support (%.9g, %.9g, %.9g) N s, momentum balance off by %.3g N s "
         "(largest step impulse %.3g, momentum change %.3g t mm/s)\n", J[0], J[1], J[2], worst,
         Jmax, dP);
  /* 600 sums of step impulses of up to Jmax: round-off ~600 x 1e-16 x Jmax; 1e-10 Jmax leaves
   * room, and an integration error of the rod's tolerances (rtol 1e-4) would be ~1e-4 */
  CS_EXPECT(worst < 1e-10 * Jmax * 600);
  CS_EXPECT(dP > 1e-3 * Jmax); /* the leg's momentum really changed: the test can fail */
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


static void accelerating_base_is_gravity(void) {
  csrActuator act;
  csrRodParams par = csr_rodDefaultParams(NULL);
  par.damping_time = 0.1;
  par.rtol = 1e-6;
  csrRodModel* m;
  csrRodData* d;
  if (!hangingLeg(&act, NULL, &par, 0, NULL, &m, &d)) {
    return;
  }
  const double a = 2000; /* mm/s², along +x */
  const double H = 5e-3;
  double t = 0;
  csrBaseState rest = csr_rodRestBase(m), b0 = rest, b1 = rest;
  csrWrench w;
  csError err;
  int ok = 1;
  for (int k = 0; k < 400 && ok; k++) {
    b0.x[0] = rest.x[0] + 0.5 * a * t * t;
    b0.v[0] = a * t;
    b1.x[0] = rest.x[0] + 0.5 * a * (t + H) * (t + H);
    b1.v[0] = a * (t + H);
    ok = csr_rodAdvance(m, d, t, H, &b0, &b1, &w, &err) == 0;
    t += H;
  }
  CS_EXPECT(ok);
  const double M = csr_rodMass(m);
  printf("  wrench force (%.9g, %.3g, %.3g) N vs -M a = %.9g N\n", w.f[0], w.f[1],
         w.f[2], -M * a);
  /* settled in the accelerating frame: the support must accelerate the whole leg */
  CS_EXPECT_NEAR(w.f[0], -M * a, 1e-6 * M * a, 0);
  /* the leg's shape relative to the hip = the static shape under gravity -a */
  const int N = csr_rodElements(m);
  double x[3 * (MAXN + 1)];
  csr_rodNodes(m, d, x);
  double rel[3];
  for (int k = 0; k < 3; k++) {
    rel[k] = x[3 * N + k] - x[k];
  }
  csrRodModel* m2;
  csrRodData* d2;
  csrActuator act2;
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  cs_errorClear(&err);
  csr_actuatorPreset(&act2, "leg", &err);
  sp.act = &act2;
  sp.params = &par;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(sp.frame, F, sizeof F);
  sp.gravity[0] = -a;
  m2 = csr_rodModelCreate(&sp, &err);
  d2 = m2 ? csr_rodDataCreate(m2, &err) : NULL;
  CS_EXPECT(d2 != NULL);
  if (d2) {
    csrRodStaticLoad ld;
    memset(&ld, 0, sizeof ld);
    ld.gravity = 1;
    CS_EXPECT(csr_rodStatic(m2, d2, &ld, NULL, &err) == CS_OK);
    double xs[3 * (MAXN + 1)];
    csr_rodNodes(m2, d2, xs);
    printf("  foot relative to the hip (%.6f, %.6f, %.6f), static under -a (%.6f, %.6f, %.6f)\n",
           rel[0], rel[1], rel[2], xs[3 * N], xs[3 * N + 1], xs[3 * N + 2]);
    for (int k = 0; k < 3; k++) {
      /* settled to e^-20; integrator tolerances ~1e-3 mm */
      CS_EXPECT_NEAR(rel[k], xs[3 * N + k], 1e-2, 0);
    }
    CS_EXPECT(fabs(xs[3 * N]) > 1.0); /* a visible deflection: the test can fail */
  }
  csr_rodDataDestroy(d2);
  csr_rodModelDestroy(m2);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


static void interface_gains_closed_form(void) {
  csrRodParams par = csr_rodDefaultParams(NULL);
  par.damping_time = 0.02;
  csrRodPiece p = uniformPiece(100, 10, 1.0 / 3, 1.0);
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.params = &par;
  csu_eye3(sp.frame); /* rod along +z */
  csError err;
  csrRodModel* m = csr_rodModelCreatePieces(&p, 1, &sp, &err);
  csrRodData* d = m ? csr_rodDataCreate(m, &err) : NULL;
  CS_EXPECT(d != NULL);
  if (!d) {
    csr_rodModelDestroy(m);
    return;
  }
  double K[36], C[36];
  csr_rodInterfaceGains(m, d, K, C);
  const double l = 10, EA = 100, kGA = 10.0 * 1.5 / 17.5 / 3 * 100, EI = 1e4 / 12;
  /* central differences of smooth laws: ~1e-9 relative */
  CS_EXPECT_NEAR(K[6 * 2 + 2], EA / l, 0, 1e-6);
  CS_EXPECT_NEAR(K[6 * 0 + 0], kGA / l, 0, 1e-6);
  CS_EXPECT_NEAR(K[6 * 1 + 1], kGA / l, 0, 1e-6);
  CS_EXPECT_NEAR(K[6 * 3 + 3], EI / (l / 2), 0, 1e-6);
  CS_EXPECT_NEAR(C[6 * 2 + 2], 0.02 * EA / l, 0, 1e-6);
  CS_EXPECT_NEAR(C[6 * 4 + 4], 0.02 * EI / (l / 2), 0, 1e-6);
  printf("  K_zz %.6g N/mm (EA/l %.6g), K_xx %.6g (kGA/l %.6g), K_φxφx %.6g N mm/rad (EI/(l/2) "
         "%.6g)\n", K[14], EA / l, K[0], kGA / l, K[21], EI / (l / 2));
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


/* a floor at y = floor_y under the foot: a penalty spring on the lowest sole point (the box
 * element's +d3 face centre), history[0] = time spent in contact */
typedef struct {
  double floor_y, k;
  int fail; /* 1: return a NaN force (for the failure test) */
} Floor;

static int floorHook(void* ctx, const csrRodShape* sh, const double* hist, double* dhist,
                     double f0[3], double f1[3], double moment[3]) {
  (void)hist;
  (void)moment;
  (void)f0;
  Floor* fl = ctx;
  if (sh->kind != CSR_ROD_SHAPE_BOX) {
    return 0;
  }
  if (fl->fail) {
    f1[1] = NAN;
    return 0;
  }
  double pen = fl->floor_y - sh->p1[1];
  if (pen > 0) {
    f1[1] = fl->k * pen; /* on the foot node */
    dhist[0] = 1;
  }
  return 0;
}


static void contact_hook_carries_weight(void) {
  csrActuator act;
  csrRodParams par = csr_rodDefaultParams(NULL);
  par.damping_time = 0.1;
  par.rtol = 1e-6;
  Floor fl = {-166.0 - 0.5, 10.0, 0}; /* 0.5 mm below the unloaded foot */
  csrRodContact c = {floorHook, &fl, 1, 2}; /* the foot element carries one more (unused) */
  csrRodModel* m;
  csrRodData* d;
  if (!hangingLeg(&act, NULL, &par, -9810 * 20, &c, &m, &d)) {
    return;
  }
  double t = 0;
  csrWrench w;
  CS_EXPECT(runSteps(m, d, &t, 5e-3, 300, NULL, &w) == 0);
  const double M = csr_rodMass(m), W = M * 9810 * 20;
  const int N = csr_rodElements(m), ns = csr_rodStateSize(m);
  double x[3 * (MAXN + 1)];
  csr_rodNodes(m, d, x);
  double floor_force = fl.k * (fl.floor_y - x[3 * N + 1]);
  double* y = calloc((size_t)ns, sizeof(double));
  csr_rodGetState(m, d, y);
  /* the foot element's history: time in contact, then the unused one (rate 0) */
  double tc = y[ns - 2];
  CS_EXPECT(y[ns - 1] == 0);
  CS_EXPECT(csr_rodStateHist(m, N) == 2 && csr_rodStateHist(m, 1) == 1);
  CS_EXPECT(ns == 13 * N + (N - 1) + 2);
  printf("  hip carries %.6g N of the %.6g N weight, the floor %.6g N; in contact %.4f s of "
         "%.2f\n", -w.f[1], W, floor_force, tc, t);
  /* 20 g makes the foot touch (the leg stretches 0.5 mm under 20 x its weight) */
  CS_EXPECT(floor_force > 0.05 * W);
  /* statics of the settled leg: hip + floor = weight (tolerance as hanging_wrench_is_weight) */
  CS_EXPECT_NEAR(-w.f[1] + floor_force, W, 1e-5 * W, 0);
  /* the history integrates dhist = 1 while in contact: between 0 and the run time */
  CS_EXPECT(tc > 0.5 && tc <= t + 1e-9);
  free(y);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


static void failed_advance_changes_nothing(void) {
  csrActuator act;
  Floor fl = {-1e9, 10.0, 0};
  csrRodContact c = {floorHook, &fl, 1, 1};
  csrRodModel* m;
  csrRodData* d;
  if (!hangingLeg(&act, NULL, NULL, -9810, &c, &m, &d)) {
    return;
  }
  double t = 0;
  CS_EXPECT(runSteps(m, d, &t, 5e-3, 20, NULL, NULL) == 0);
  const int ns = csr_rodStateSize(m);
  double* y0 = calloc((size_t)ns, sizeof(double));
  double* y1 = calloc((size_t)ns, sizeof(double));
  csr_rodGetState(m, d, y0);
  fl.fail = 1;
  csrBaseState b = csr_rodRestBase(m);
  csError err;
  cs_errorClear(&err);
  int rc = csr_rodAdvance(m, d, t, 5e-3, &b, &b, NULL, &err);
  printf("  failed advance: %d, %s\n", rc, err.msg);
  CS_EXPECT(rc > 0);
  csr_rodGetState(m, d, y1);
  CS_EXPECT(memcmp(y0, y1, (size_t)ns * sizeof(double)) == 0);
  fl.fail = 0;
  CS_EXPECT(csr_rodAdvance(m, d, t, 5e-3, &b, &b, NULL, &err) == 0);
  /* set/get round trip is bit-exact */
  csr_rodSetState(m, d, y0);
  csr_rodGetState(m, d, y1);
  CS_EXPECT(memcmp(y0, y1, (size_t)ns * sizeof(double)) == 0);
  /* bad arguments are refused without touching the state */
  CS_EXPECT(csr_rodAdvance(m, d, t, -1.0, &b, &b, NULL, &err) < 0);
  csr_rodGetState(m, d, y1);
  CS_EXPECT(memcmp(y0, y1, (size_t)ns * sizeof(double)) == 0);
  free(y0);
  free(y1);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


static void base_jumps_and_restarts(void) {
  csrActuator act;
  csrRodModel* m;
  csrRodData* d;
  if (!hangingLeg(&act, NULL, NULL, -9810, NULL, &m, &d)) {
    return;
  }
  double t = 0;
  CS_EXPECT(runSteps(m, d, &t, 5e-3, 10, NULL, NULL) == 0);
  csrRodStats s0, s1, s2;
  csr_rodGetStats(d, &s0);
  csrBaseState b = csr_rodRestBase(m), b1 = b;
  csError err;
  /* a predictor's correction: 1 µm */
  b.x[0] += 1e-3;
  b1.x[0] += 1e-3;
  CS_EXPECT(csr_rodAdvance(m, d, t, 5e-3, &b, &b1, NULL, &err) == 0);
  t += 5e-3;
  csr_rodGetStats(d, &s1);
  CS_EXPECT(s1.reinits == s0.reinits);
  /* a teleport: 1 mm */
  b.x[0] += 1.0;
  b1.x[0] += 1.0;
  CS_EXPECT(csr_rodAdvance(m, d, t, 5e-3, &b, &b1, NULL, &err) == 0);
  csr_rodGetStats(d, &s2);
  CS_EXPECT(s2.reinits == s1.reinits + 1);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(base_jumps_and_restarts);
  CS_RUN(first_bending_frequency);
  CS_RUN(energy_does_not_grow);
  CS_RUN(pressure_step_steady_curvature);
  CS_RUN(hanging_wrench_is_weight);
  CS_RUN(base_impulse_is_the_momentum_balance);
  CS_RUN(accelerating_base_is_gravity);
  CS_RUN(interface_gains_closed_form);
  CS_RUN(contact_hook_carries_weight);
  CS_RUN(failed_advance_changes_nothing);
  return cs_testSummary();
}

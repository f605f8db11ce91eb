/* test_strain_static.c: the strain leg's statics (robot_strain.c) against closed forms and the
 * nodal rod.
 *
 * Uniform rods (one flexible piece, 10 x 10 mm square, E = 1 MPa: EA = 100 N, EI = 833.3 N mm²)
 * and the `leg` actuator. Cases:
 *  - end_moment_exact_arc: M = 2π EI/L bends the rod into one full circle: a constant strain is
 *    one exponential, so at bending order 0 and one sub-interval the tip is back at the hip with
 *    the clamp's frame and the midpoint on the circle's far side, to the solver's tolerance.
 *  - axial_stretch_exact: P/EA = 10 %: tip at L (1 + P/EA).
 *  - tip_load_linear: a small tip force: δ = PL³/(3EI) + PL/(kGA) with shear, PL³/(3EI) without
 *    (Kirchhoff), exact in the linear theory at bending order >= 1 (the moment is linear and the
 *    shear force constant along the rod).
 *  - tip_load_large_vs_nodal: a tip force that turns the tip by ~50°: the strain rod at bending
 *    orders 1..5 (axial orders one lower) against the nodal rod converged (32 and 64 elements,
 *    Richardson).
 *  - leg_unloaded_on_calibrated_arcs: the leg under the flat-road gait's pressures on the
 *    shipped calibration, no load: the strain rod's tip and the nodal rod's (whose nodes lie on
 *    the calibrated arcs at any element count) agree to round-off.
 *  - leg_tip_load_vs_nodal: chambers 1, 2 of every segment at 0..0.4 MPa with a 0.05 N tip force
 *    along e1 (the FE's loaded case, docs/bench/rod_vs_fe_sym_2026-12-04) on the 23-mode
 *    symmetric-mesh table under rbf-pair and on the shipped table: within 1 mm of the nodal rod
 *    at 16 elements per segment; prints the error by bending order and sub-intervals.
 *  - calibration_is_a_function_of_the_pressures: the actuation after a sequence of pressures
 *    equals the one made at the last pressures directly (bit for bit), exactly and on a
 *    pressure lattice (cal_quantum); a segment whose pressures held is not evaluated again, a
 *    move within a lattice simplex evaluates nothing, and the lattice's interpolation is closer
 *    to the exact calibration than its nearest node.
 *  - leg_tip_load_against_sub_intervals: the same load at the level's links 2 for 1 to 16 Magnus
 *    sub-intervals per piece: within 1 mm of the nodal rod at each, converging as they double.
 *  - hanging_leg_weight: the bent leg under its weight (conditions `earth`) against the nodal
 *    rod at 16 elements per segment.
 *  - failed_static_changes_nothing: a calibration refusing the pressure leaves q as it was. */
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "robot_calibration.h"
#include "robot_calibration_model.h"
#include "robot_rod.h"
#include "robot_strain.h"
#include "robot_strain_internal.h"
#include "strain_test_rods.h"

/* tip pose of a uniform rod along +z (clamp at the origin) under ld; 1 on success */
static int uniformTip(double L, double G, const csrStrainParams* sp, const csrRodStaticLoad* ld,
                      double x[3], double R[9], double xmid[3]) {
  csrRodPiece pc = uniformPieceG(L, G);
  csrRodParams rp = csr_rodDefaultParams(NULL);
  csrStrainSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.rod_params = &rp;
  spec.params = sp;
  csu_eye3(spec.frame);
  csError err;
  cs_errorClear(&err);
  csrStrainModel* m = csr_strainModelCreatePieces(&pc, NULL, 1, &spec, &err);
  csrStrainData* d = m ? csr_strainDataCreate(m, &err) : NULL;
  csrRodStaticInfo info;
  csStatus st = d ? csr_strainStatic(m, d, ld, &info, &err) : CS_ERR_ARG;
  if (st != CS_OK) {
    fprintf(stderr, "  static solve failed: %s\n", err.msg);
  } else {
    double Rm[9];
    csr_strainPose(m, d, L, x, R);
    if (xmid) {
      csr_strainPose(m, d, 0.5 * L, xmid, Rm);
    }
  }
  csr_strainDataDestroy(d);
  csr_strainModelDestroy(m);
  return st == CS_OK;
}


static void end_moment_exact_arc(void) {
  const double L = 100, EI = 1e4 / 12;
  csrRodStaticLoad ld;
  memset(&ld, 0, sizeof ld);
  ld.tip_moment[1] = 2 * CS_PI * EI / L; /* about +e2: d3 turns towards +e1 */
  csrStrainParams sp = csr_strainDefaultParams();
  sp.bend_order = 0;
  sp.nsub = 1;
  double x[3], R[9], xm[3];
  CS_EXPECT(uniformTip(L, 1.0 / 3, &sp, &ld, x, R, xm));
  double r = L / (2 * CS_PI);
  printf("  tip (%.3g, %.3g, %.3g), frame R11 %.15g, midpoint (%.12g, %.3g, %.3g) vs (%.12g, 0, "
         "0)\n", x[0], x[1], x[2], R[0], xm[0], xm[1], xm[2], 2 * r);
  /* the static tolerance (1e-11 rad over the piece) moves the tip by ~1e-9 mm */
  for (int k = 0; k < 3; k++) {
    CS_EXPECT_NEAR(x[k], 0, 1e-8, 0);
  }
  CS_EXPECT_NEAR(R[0], 1, 1e-10, 0);
  CS_EXPECT_NEAR(R[8], 1, 1e-10, 0);
  CS_EXPECT_NEAR(xm[0], 2 * r, 1e-8, 0);
  CS_EXPECT_NEAR(xm[2], 0, 1e-8, 0);
}


static void axial_stretch_exact(void) {
  const double L = 100, EA = 100, P = 10;
  csrRodStaticLoad ld;
  memset(&ld, 0, sizeof ld);
  ld.tip_force[2] = P;
  csrStrainParams sp = csr_strainDefaultParams();
  double x[3], R[9];
  CS_EXPECT(uniformTip(L, 1.0 / 3, &sp, &ld, x, R, NULL));
  printf("  tip z %.15g (exact %.15g)\n", x[2], L * (1 + P / EA));
  CS_EXPECT_NEAR(x[2], L * (1 + P / EA), 1e-9, 0); /* solver tolerance 1e-11 x 100 mm */
  CS_EXPECT_NEAR(x[0], 0, 1e-12, 0);
  CS_EXPECT_NEAR(x[1], 0, 1e-12, 0);
}


static void tip_load_linear(void) {
  const double L = 100, E = 1.0, I = 1e4 / 12, A = 100, G = E / 100;
  const double k = 10.0 * 1.5 / (12 + 5.5), P = 1e-5;
  csrRodStaticLoad ld;
  memset(&ld, 0, sizeof ld);
  ld.tip_force[0] = P;
  for (int shear = 1; shear >= 0; shear--) {
    csrStrainParams sp = csr_strainDefaultParams();
    sp.bend_order = 1;
    sp.shear = shear;
    double exact = P * L * L * L / (3 * E * I) + (shear ? P * L / (k * G * A) : 0);
    double x[3], R[9];
    CS_EXPECT(uniformTip(L, G, &sp, &ld, x, R, NULL));
    printf("  shear %d: tip deflection %.12g mm (exact %.12g), relative error %+.3e\n", shear,
           x[0], exact, (x[0] - exact) / exact);
    /* the linear theory is exact in this basis; what remains is the geometric nonlinearity
     * ~(δ/L)² = 2.5e-9 and the solver's 1e-11 rad: 1e-7 relative */
    CS_EXPECT_NEAR(x[0], exact, 0, 1e-7);
  }
}


/* tip of a uniform rod (shear G = E/3) under a tip force P along +x, nodal rod of n elements */
static int nodalUniformTip(double L, int n, const csrRodStaticLoad* ld, double tip[3]) {
  csrRodParams par = csr_rodDefaultParams(NULL);
  csrRodPiece p = uniformPieceG(L, 1.0 / 3);
  p.nelem = n;
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.params = &par;
  csu_eye3(sp.frame);
  csError err;
  cs_errorClear(&err);
  csrRodModel* m = csr_rodModelCreatePieces(&p, 1, &sp, &err);
  csrRodData* d = m ? csr_rodDataCreate(m, &err) : NULL;
  csStatus st = d ? csr_rodStatic(m, d, ld, NULL, &err) : CS_ERR_ARG;
  if (st == CS_OK) {
    double* x = calloc(3 * ((size_t)n + 1), sizeof(double));
    csr_rodNodes(m, d, x);
    memcpy(tip, x + 3 * n, 3 * sizeof(double));
    free(x);
  } else {
    fprintf(stderr, "  nodal static failed: %s\n", err.msg);
  }
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
  return st == CS_OK;
}


static void tip_load_large_vs_nodal(void) {
  const double L = 100, EI = 1e4 / 12;
  csrRodStaticLoad ld;
  memset(&ld, 0, sizeof ld);
  ld.tip_force[0] = 2.0 * EI / (L * L); /* PL²/EI = 2: the tip turns by ~50° */
  double t32[3], t64[3], ref[3];
  CS_EXPECT(nodalUniformTip(L, 32, &ld, t32));
  CS_EXPECT(nodalUniformTip(L, 64, &ld, t64));
  for (int k = 0; k < 3; k++) {
    ref[k] = (4 * t64[k] - t32[k]) / 3; /* the nodal rod is second order (test_rod_static) */
  }
  printf("  nodal 64: (%.8f, %.8f), Richardson (%.8f, %.8f), |64 - Richardson| %.2e mm\n",
         t64[0], t64[2], ref[0], ref[2], hypot(t64[0] - ref[0], t64[2] - ref[2]));
  double e_prev = INFINITY;
  for (int order = 1; order <= 5; order++) {
    csrStrainParams sp = csr_strainDefaultParams();
    sp.bend_order = order;
    sp.axial_order = order - 1;
    sp.nsub = 8;
    double x[3], R[9];
    CS_EXPECT(uniformTip(L, 1.0 / 3, &sp, &ld, x, R, NULL));
    double e = hypot(x[0] - ref[0], x[2] - ref[2]);
    sp.axial_order = 0;
    double x0[3];
    CS_EXPECT(uniformTip(L, 1.0 / 3, &sp, &ld, x0, R, NULL));
    printf("  bend order %d, axial order %d: tip (%.8f, %.8f), off the nodal reference by %.3e "
           "mm (%.3e with constant twist, shear and stretch)\n", order, order - 1, x[0], x[2], e,
           hypot(x0[0] - ref[0], x0[2] - ref[2]));
    /* measured 0.115, 2.1e-3, 3.5e-4, 2.0e-4, 4.2e-4 mm at orders 1..5: the strain rod
     * converges until it meets the reference's own error (the Richardson extrapolation moved
     * the 64-element tip by 5.5e-3 mm, so its remainder is ~1e-4 mm); with twist, shear and
     * stretch constant it stops at 0.023 mm (the axial and shear forces of a tip force turn
     * along a 50° bend) */
    if (order == 2 || order == 3) {
      CS_EXPECT(e < 0.5 * e_prev);
    }
    if (order >= 3) {
      CS_EXPECT(e < 1e-3);
    }
    e_prev = e;
  }
}


/* ---- the leg ----------------------------------------------------------------------------- */

/* a calibration of the `leg` actuator: the shipped table, or a mode table with a rule */
typedef struct {
  csrActuator act;
  csrCalibration* cal;
  csrBendMap map;
  csrRodCalibration rodcal;
  int has_rodcal;
} LegCal;

static int openCal(LegCal* c, const char* file, const char* rule) {
  csError err;
  cs_errorClear(&err);
  memset(c, 0, sizeof *c);
  csr_actuatorPreset(&c->act, "leg", &err);
  char path[1024];
  snprintf(path, sizeof path, "%s/robot/%s", getenv("CS_SOURCE_DIR"), file);
  if (rule) {
    csrCalOptions opt = csr_calModelDefaultOptions();
    CS_EXPECT(csr_calRuleParse(rule, &opt.rule));
    c->cal = csr_calibrationOpenWith(path, &c->act, &opt, &err);
  } else {
    c->cal = csr_calibrationOpen(path, &c->act, &err);
  }
  if (!c->cal) {
    fprintf(stderr, "  %s\n", err.msg);
  }
  CS_EXPECT(c->cal != NULL);
  if (!c->cal) {
    return 0;
  }
  c->map = csr_calibrationMap(c->cal);
  c->has_rodcal = csr_calibrationRod(c->cal, &c->rodcal);
  return 1;
}


/* the leg hanging along -y (e1 = +x, e2 = +z, e3 = -y) at the origin, gravity g or none */
static void legFrame(double F[9]) {
  const double f[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(F, f, sizeof f);
}


static csrStrainModel* strainLeg(const LegCal* c, const csrStrainParams* sp, const double g[3]) {
  csrStrainSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.act = &c->act;
  spec.params = sp;
  spec.map = &c->map;
  spec.calib = c->has_rodcal ? &c->rodcal : NULL;
  legFrame(spec.frame);
  if (g) {
    memcpy(spec.gravity, g, sizeof spec.gravity);
  }
  csError err;
  cs_errorClear(&err);
  csrStrainModel* m = csr_strainModelCreate(&spec, &err);
  if (!m) {
    fprintf(stderr, "  %s\n", err.msg);
  }
  CS_EXPECT(m != NULL);
  return m;
}


static csrRodModel* nodalLeg(const LegCal* c, int eps, const double g[3]) {
  csrRodParams par = csr_rodDefaultParams(&c->act);
  par.elements_per_segment = eps;
  csrRodSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.act = &c->act;
  spec.params = &par;
  spec.map = &c->map;
  spec.calib = c->has_rodcal ? &c->rodcal : NULL;
  legFrame(spec.frame);
  if (g) {
    memcpy(spec.gravity, g, sizeof spec.gravity);
  }
  csError err;
  cs_errorClear(&err);
  csrRodModel* m = csr_rodModelCreate(&spec, &err);
  if (!m) {
    fprintf(stderr, "  %s\n", err.msg);
  }
  CS_EXPECT(m != NULL);
  return m;
}


/* the foot's tip (node N; the strain rod's X = L) under ld */
static int nodalTip(csrRodModel* m, csrRodData* d, const csrRodStaticLoad* ld, double tip[3]) {
  csError err;
  cs_errorClear(&err);
  if (csr_rodStatic(m, d, ld, NULL, &err) != CS_OK) {
    fprintf(stderr, "  nodal: %s\n", err.msg);
    return 0;
  }
  int N = csr_rodElements(m);
  double* x = calloc(3 * ((size_t)N + 1), sizeof(double));
  csr_rodNodes(m, d, x);
  memcpy(tip, x + 3 * N, 3 * sizeof(double));
  free(x);
  return 1;
}


static int strainTip(csrStrainModel* m, csrStrainData* d, const csrRodStaticLoad* ld,
                     double tip[3]) {
  csError err;
  cs_errorClear(&err);
  if (csr_strainStatic(m, d, ld, NULL, &err) != CS_OK) {
    fprintf(stderr, "  strain: %s\n", err.msg);
    return 0;
  }
  double R[9];
  csr_strainPose(m, d, csr_strainLength(m), tip, R);
  return 1;
}


static double dist3(const double a[3], const double b[3]) {
  double d[3];
  csu_sub3(d, a, b);
  return csu_norm3(d);
}


static void leg_unloaded_on_calibrated_arcs(void) {
  LegCal c;
  if (!openCal(&c, "calibration_fe_leg.h5", NULL)) {
    return;
  }
  csrStrainParams sp = csr_strainDefaultParams();
  csrStrainModel* sm = strainLeg(&c, &sp, NULL);
  csrRodModel* rm = nodalLeg(&c, 4, NULL);
  csError err;
  csrStrainData* sd = sm ? csr_strainDataCreate(sm, &err) : NULL;
  csrRodData* rd = rm ? csr_rodDataCreate(rm, &err) : NULL;
  if (sd && rd) {
    /* the flat-road gait's swing: II1-Ω3&Ω4 and II2-Ω1&Ω2 at 0.18 MPa; and an unequal set */
    const double sets[2][12] = {{0, 0, 0.18, 0.18, 0.18, 0.18, 0, 0, 0, 0, 0, 0},
                                {0.2, 0.05, 0, 0, 0, 0.1, 0.15, 0, 0.1, 0.1, 0.1, 0.1}};
    for (int s = 0; s < 2; s++) {
      csrRodStaticLoad ld;
      memset(&ld, 0, sizeof ld);
      memcpy(ld.p, sets[s], sizeof ld.p);
      double ts[3], tn[3];
      CS_EXPECT(strainTip(sm, sd, &ld, ts));
      CS_EXPECT(nodalTip(rm, rd, &ld, tn));
      double e = dist3(ts, tn);
      printf("  set %d: strain tip (%.9f, %.9f, %.9f), nodal (%.9f, %.9f, %.9f): %.2e mm\n", s,
             ts[0], ts[1], ts[2], tn[0], tn[1], tn[2], e);
      /* both integrate the same constant strains exactly; the solvers' tolerances (1e-11 rad,
       * scaled residual 1e-10) leave ~1e-8 mm */
      CS_EXPECT_NEAR(e, 0, 1e-6, 0);
      CS_EXPECT(dist3(ts, (double[3]){0, -csr_strainLength(sm), 0}) > 10); /* it bent */
    }
  }
  csr_strainDataDestroy(sd);
  csr_rodDataDestroy(rd);
  csr_strainModelDestroy(sm);
  csr_rodModelDestroy(rm);
  csr_calibrationClose(c.cal);
}


/* largest tip distance (mm) between the strain leg (sp) and the nodal leg at eps elements per
 * segment over chambers 1, 2 at 0..pmax under a 0.05 N tip force along e1 */
static double loadedSweep(const LegCal* c, const csrStrainParams* sp, csrRodModel* rm,
                          double pmax, double* at_p) {
  csError err;
  csrStrainModel* sm = strainLeg(c, sp, NULL);
  csrStrainData* sd = sm ? csr_strainDataCreate(sm, &err) : NULL;
  csrRodData* rd = rm ? csr_rodDataCreate(rm, &err) : NULL;
  double worst = sd && rd ? 0 : INFINITY;
  for (int i = 0; sd && rd && i <= 8; i++) {
    double p = pmax * i / 8;
    csrRodStaticLoad ld;
    memset(&ld, 0, sizeof ld);
    for (int s = 0; s < 3; s++) {
      ld.p[4 * s] = ld.p[4 * s + 1] = p;
    }
    ld.tip_force[0] = 0.05; /* e1 = +x */
    double ts[3], tn[3];
    if (!strainTip(sm, sd, &ld, ts) || !nodalTip(rm, rd, &ld, tn)) {
      worst = INFINITY;
      break;
    }
    double e = dist3(ts, tn);
    if (e > worst) {
      worst = e;
      *at_p = p;
    }
  }
  csr_strainDataDestroy(sd);
  csr_rodDataDestroy(rd);
  csr_strainModelDestroy(sm);
  return worst;
}


static void leg_tip_load_vs_nodal(void) {
  const char* files[2] = {"calibration_fe_leg_modes_sym.h5", "calibration_fe_leg.h5"};
  const char* rules[2] = {"rbf-pair", NULL};
  for (int f = 0; f < 2; f++) {
    LegCal c;
    if (!openCal(&c, files[f], rules[f])) {
      return;
    }
    double pmax = fmin(0.4, c.map.p_max);
    csrRodModel* rm = nodalLeg(&c, 16, NULL);
    printf("  %s%s%s, chambers 1,2 at 0..%.2f MPa, 0.05 N along e1, against the nodal rod at 16 "
           "elements per segment:\n", files[f], rules[f] ? " " : "", rules[f] ? rules[f] : "",
           pmax);
    const int orders[4] = {0, 1, 2, 3};
    for (int o = 0; o < 4; o++) {
      csrStrainParams sp = csr_strainDefaultParams();
      sp.bend_order = orders[o];
      double at = 0;
      double e = loadedSweep(&c, &sp, rm, pmax, &at);
      printf("    bend order %d, %d sub-intervals: worst %.4f mm (at %.3f MPa)\n", sp.bend_order,
             sp.nsub, e, at);
      if (sp.bend_order == csr_strainDefaultParams().bend_order) {
        CS_EXPECT(e < 1.0); /* the target */
      }
    }
    csrRodModel* rm8 = nodalLeg(&c, 8, NULL);
    csrStrainParams sp = csr_strainDefaultParams();
    double at = 0;
    double e8 = loadedSweep(&c, &sp, rm8, pmax, &at);
    printf("    (the default strain leg against the nodal rod at 8 elements: %.4f mm)\n", e8);
    csr_rodModelDestroy(rm8);
    csr_rodModelDestroy(rm);
    csr_calibrationClose(c.cal);
  }
}


/* The quadrature's resolution (nsub: Magnus sub-intervals per flexible piece) at the level's
 * basis (links 2, bend order 1), on the flat road's table: the loaded leg's tip against the nodal
 * rod at 16 elements per segment within the 1 mm at every nsub from 1, and the tip's
 * distance from the same leg at 16 sub-intervals (the kinematics' own error) shrinking as nsub
 * doubles */
static void leg_tip_load_against_sub_intervals(void) {
  LegCal c;
  if (!openCal(&c, "calibration_fe_leg_modes_sym.h5", "rbf-pair")) {
    return;
  }
  const double pmax = fmin(0.4, c.map.p_max);
  csrRodModel* rm = nodalLeg(&c, 16, NULL);
  csError err;
  csrRodData* rd = rm ? csr_rodDataCreate(rm, &err) : NULL;
  CS_EXPECT(rd != NULL);
  const int subs[5] = {16, 1, 2, 4, 8};
  double tips[5][9][3], prev = INFINITY;
  for (int i = 0; rd && i < 5; i++) {
    csrStrainParams sp = csr_strainDefaultParams();
    sp.bend_order = 1;
    sp.nsub = subs[i];
    csrStrainModel* sm = strainLeg(&c, &sp, NULL);
    csrStrainData* sd = sm ? csr_strainDataCreate(sm, &err) : NULL;
    CS_EXPECT(sd != NULL);
    double worst = 0, self = 0;
    for (int j = 0; sd && j <= 8; j++) {
      csrRodStaticLoad ld;
      memset(&ld, 0, sizeof ld);
      for (int s = 0; s < 3; s++) {
        ld.p[4 * s] = ld.p[4 * s + 1] = pmax * j / 8;
      }
      ld.tip_force[0] = 0.05;
      double tn[3];
      CS_EXPECT(strainTip(sm, sd, &ld, tips[i][j]) && nodalTip(rm, rd, &ld, tn));
      worst = fmax(worst, dist3(tips[i][j], tn));
      self = fmax(self, dist3(tips[i][j], tips[0][j]));
    }
    printf("  links 2, %2d sub-intervals: worst %.4f mm from the nodal rod at 16 elements, "
           "%.3e mm from 16 sub-intervals\n", subs[i], worst, self);
    CS_EXPECT(worst < 1.0); /* the 1 mm */
    if (i > 0) {
      CS_EXPECT(self < prev); /* converging in nsub */
      prev = self;
    }
    csr_strainDataDestroy(sd);
    csr_strainModelDestroy(sm);
  }
  csr_rodDataDestroy(rd);
  csr_rodModelDestroy(rm);
  csr_calibrationClose(c.cal);
}


/* d's stiffness and rest-strain terms (Kd, b) bit for bit equal to e's */
static int sameActuation(const csrStrainModel* m, const csrStrainData* d, const csrStrainData* e) {
  const size_t sz = (size_t)csr_strainDofs(m) * sizeof(double);
  return memcmp(d->Kd, e->Kd, sz) == 0 && memcmp(d->b, e->b, sz) == 0;
}


/* largest |Δb| between d and e over the largest |b| of e */
static double restTermsGap(const csrStrainModel* m, const csrStrainData* d, const csrStrainData* e) {
  double db = 0, bmax = 0;
  for (int j = 0; j < csr_strainDofs(m); j++) {
    db = fmax(db, fabs(d->b[j] - e->b[j]));
    bmax = fmax(bmax, fabs(e->b[j]));
  }
  return db / bmax;
}


/* The calibration's memo and its pressure lattice (cal_quantum): the actuation is a function of
 * the pressures alone (a leg actuated through a sequence of pressures and one actuated at the
 * last of them directly agree bit for bit, so a restored state needs nothing more); exactly, a
 * segment whose pressures held is not evaluated again; on the lattice, pressures inside the same
 * simplex evaluate nothing new, and the interpolation is closer to the exact calibration than
 * the nearest lattice node is */
static void calibration_is_a_function_of_the_pressures(void) {
  LegCal c;
  if (!openCal(&c, "calibration_fe_leg_modes_sym.h5", "rbf-pair")) {
    return;
  }
  const double quanta[2] = {0, 0.01};
  csError err;
  csrStrainModel* me = NULL;
  csrStrainData* e = NULL; /* the exact calibration */
  for (int qi = 0; qi < 2; qi++) {
    csrStrainParams sp = csr_strainDefaultParams();
    sp.bend_order = 1;
    sp.cal_quantum = quanta[qi];
    csrStrainModel* m = strainLeg(&c, &sp, NULL);
    csrStrainData* a = m ? csr_strainDataCreate(m, &err) : NULL;
    csrStrainData* b = m ? csr_strainDataCreate(m, &err) : NULL;
    CS_EXPECT(a && b);
    if (!a || !b) {
      csr_strainDataDestroy(a);
      csr_strainDataDestroy(b);
      csr_strainModelDestroy(m);
      break;
    }
    double p1[12] = {0}, p2[12] = {0};
    for (int s = 0; s < 3; s++) {
      p1[4 * s] = p1[4 * s + 1] = 0.1 + 0.1 * s;
    }
    memcpy(p2, p1, sizeof p2);
    p2[0] = 0.2516; /* segment 0 alone moves */
    p2[1] = 0.2531;
    CS_EXPECT(csr_strainActuate(m, a, p1, &err) == 0);
    const long n1 = a->ncal;
    CS_EXPECT(csr_strainActuate(m, a, p2, &err) == 0);
    const long evals = a->ncal - n1;
    CS_EXPECT(csr_strainActuate(m, b, p2, &err) == 0);
    printf("  cal_quantum %g MPa: segment 0 moved, %ld evaluation(s); through the sequence and "
           "direct: %s\n", quanta[qi], evals, sameActuation(m, a, b) ? "bit-identical" : "DIFFER");
    CS_EXPECT(sameActuation(m, a, b));
    if (quanta[qi] == 0) {
      CS_EXPECT(evals == 1);
      me = m;
      e = a;
      m = NULL;
      a = NULL;
    } else {
      /* at most the simplex's five vertices, all of segment 0 */
      CS_EXPECT(evals >= 1 && evals <= 5);
      /* a move inside the same simplex (the fractions' order kept): nothing evaluated */
      double p3[12];
      memcpy(p3, p2, sizeof p3);
      p3[0] = 0.2512;
      p3[1] = 0.2537;
      const long n2 = a->ncal;
      CS_EXPECT(csr_strainActuate(m, a, p3, &err) == 0);
      CS_EXPECT(a->ncal == n2);
      /* against the exact calibration at p3 and at the nearest node (0.25, 0.25) */
      double node[12];
      memcpy(node, p3, sizeof node);
      node[0] = node[1] = 0.25;
      csrStrainData* en = me ? csr_strainDataCreate(me, &err) : NULL;
      CS_EXPECT(e && en && csr_strainActuate(me, e, p3, &err) == 0 &&
                csr_strainActuate(me, en, node, &err) == 0);
      if (e && en) {
        const double gi = restTermsGap(m, a, e), gn = restTermsGap(m, en, e);
        printf("  at (%.4f, %.4f) MPa the rest terms b differ from the exact calibration's by "
               "%.3e of the largest (interpolated), %.3e (the nearest node)\n", p3[0], p3[1],
               gi, gn);
        CS_EXPECT(gi > 0);
        CS_EXPECT(gi < gn);
      }
      csr_strainDataDestroy(en);
    }
    csr_strainDataDestroy(a);
    csr_strainDataDestroy(b);
    csr_strainModelDestroy(m);
  }
  csr_strainDataDestroy(e);
  csr_strainModelDestroy(me);
  csr_calibrationClose(c.cal);
}


static void hanging_leg_weight(void) {
  LegCal c;
  if (!openCal(&c, "calibration_fe_leg.h5", NULL)) {
    return;
  }
  const double g[3] = {0, -9810, 0};
  csrStrainParams sp = csr_strainDefaultParams();
  csrStrainModel* sm = strainLeg(&c, &sp, g);
  csrRodModel* rm = nodalLeg(&c, 16, g);
  csError err;
  csrStrainData* sd = sm ? csr_strainDataCreate(sm, &err) : NULL;
  csrRodData* rd = rm ? csr_rodDataCreate(rm, &err) : NULL;
  if (sd && rd) {
    csrRodStaticLoad ld;
    memset(&ld, 0, sizeof ld);
    ld.gravity = 1;
    ld.p[2] = ld.p[3] = 0.18; /* II1 bent: the weight bends it further */
    double ts[3], tn[3];
    CS_EXPECT(strainTip(sm, sd, &ld, ts));
    CS_EXPECT(nodalTip(rm, rd, &ld, tn));
    double e = dist3(ts, tn);
    printf("  strain tip (%.6f, %.6f, %.6f), nodal (%.6f, %.6f, %.6f): %.4f mm; masses %.6g, "
           "%.6g t\n", ts[0], ts[1], ts[2], tn[0], tn[1], tn[2], e, csr_strainMass(sm),
           csr_rodMass(rm));
    CS_EXPECT(e < 1.0);
    CS_EXPECT_NEAR(csr_strainMass(sm), csr_rodMass(rm), 0, 1e-12); /* the same pieces */
  }
  csr_strainDataDestroy(sd);
  csr_rodDataDestroy(rd);
  csr_strainModelDestroy(sm);
  csr_rodModelDestroy(rm);
  csr_calibrationClose(c.cal);
}


static int failingMap(const void* ctx, int seg, const double p[4], double bend[2],
                      double* stretch) {
  (void)ctx;
  (void)seg;
  bend[0] = -p[0];
  bend[1] = 0;
  *stretch = 1;
  return p[0] > 0.5 ? CSR_MAP_OUT_OF_RANGE : 0;
}


static void failed_static_changes_nothing(void) {
  csrActuator act;
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(&act, "leg", &err);
  csrBendMap map = {failingMap, NULL, "failing", 0.5};
  csrStrainSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.act = &act;
  spec.map = &map;
  legFrame(spec.frame);
  csrStrainModel* m = csr_strainModelCreate(&spec, &err);
  csrStrainData* d = m ? csr_strainDataCreate(m, &err) : NULL;
  CS_EXPECT(d != NULL);
  if (!d) {
    csr_strainModelDestroy(m);
    return;
  }
  csrRodStaticLoad ld;
  memset(&ld, 0, sizeof ld);
  ld.p[0] = 0.3;
  ld.tip_force[0] = 0.01;
  CS_EXPECT(csr_strainStatic(m, d, &ld, NULL, &err) == CS_OK);
  int n = csr_strainDofs(m);
  double* q0 = calloc((size_t)n, sizeof(double));
  double* q1 = calloc((size_t)n, sizeof(double));
  double x0[3], x1[3], R[9];
  csr_strainGetQ(m, d, q0);
  csr_strainPose(m, d, csr_strainLength(m), x0, R);
  ld.p[0] = 0.6;
  CS_EXPECT(csr_strainStatic(m, d, &ld, NULL, &err) == CS_ERR_RANGE);
  printf("  error: %s\n", err.msg);
  csr_strainGetQ(m, d, q1);
  csr_strainPose(m, d, csr_strainLength(m), x1, R);
  CS_EXPECT(memcmp(q0, q1, (size_t)n * sizeof(double)) == 0);
  CS_EXPECT(memcmp(x0, x1, sizeof x0) == 0);
  /* and the next load continues from the kept state */
  ld.p[0] = 0.4;
  CS_EXPECT(csr_strainStatic(m, d, &ld, NULL, &err) == CS_OK);
  free(q0);
  free(q1);
  csr_strainDataDestroy(d);
  csr_strainModelDestroy(m);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(end_moment_exact_arc);
  CS_RUN(axial_stretch_exact);
  CS_RUN(tip_load_linear);
  CS_RUN(tip_load_large_vs_nodal);
  CS_RUN(leg_unloaded_on_calibrated_arcs);
  CS_RUN(leg_tip_load_vs_nodal);
  CS_RUN(leg_tip_load_against_sub_intervals);
  CS_RUN(calibration_is_a_function_of_the_pressures);
  CS_RUN(hanging_leg_weight);
  CS_RUN(failed_static_changes_nothing);
  return cs_testSummary();
}

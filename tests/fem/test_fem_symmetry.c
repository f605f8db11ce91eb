/* test_fem_symmetry.c: the FE model on the mesh with the square section's symmetries
 * (csfActuatorSpec.mesh_symmetric) answers a chamber pattern turned by a quarter turn, its
 * fibres turned with it (fibre_turn), with its answer turned: Omega2 alone against Omega1
 * alone turned by -90 deg, tip and segment bends, to the Newton tolerance; and a pattern
 * mirrored in the plane y = 0 (the fibres' own mirror: the two helices start on +e1 and wind
 * both ways) with its answer mirrored: Omega1 at 1, Omega2 at 0.5 against Omega2 at 1, Omega1 at
 * 0.5. On gmsh's mesh of the whole body the turned pair differs by the mesh (its own case:
 * the scatter the symmetric mesh removes). Without fibres the elongation modes (all four, the
 * diagonal pair) do not bend, to the Newton tolerance. Short leg (15 mm segments, 3 fibre
 * turns), l_soft 5, 0.05 MPa: two sweeps per case, ~30-40 s each; slow. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "fem_bend.h"

/* tip (mm) and bends of the short leg under the chamber ratios r (every segment) at p_max,
 * with its fibres or without */
static int tipOfFibres(int symmetric, int fibres, const double r[4], int fibre_turn,
                       const char* stem, double tip[3], double bend[3][2]) {
  csError err = {0};
  csrActuator act;
  csr_actuatorPreset(&act, "leg", &err);
  const char* set[] = {"S1=15", "S2=15", "S3=15", "n1=3", "n2=3", "n3=3"};
  for (int i = 0; i < 6; i++) {
    CS_EXPECT(csr_actuatorSetString(&act, set[i], &err) == CS_OK);
  }
  csfBendOptions o = csf_bendDefault();
  o.spec.mesh_size = 5.0;
  o.spec.fibre_size = 1.0;
  o.spec.mesh_symmetric = symmetric;
  o.spec.fibres = fibres;
  o.spec.fibre_turn = fibre_turn;
  o.spec.work_stem = stem; /* each case its own: ctest runs the cases in parallel */
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      o.spec.ratio[s][j] = r[j];
    }
  }
  o.p_max = 0.05;
  o.p_step = 0.05;
  o.newton_rtol = 1e-10;
  csrBendCurve bc;
  csr_bendCurveInit(&bc, 4, &err);
  csfBendRecord rec = {0, 4, (csfBendRow[4]){{0}}};
  o.record = &rec;
  csStatus st = csf_bend(&act, &o, &bc, &err);
  if (st != CS_OK) {
    fprintf(stderr, "%s\n", err.msg);
  }
  CS_EXPECT(st == CS_OK && rec.m >= 2);
  int ok = st == CS_OK && rec.m >= 2;
  if (ok) {
    const csfBendRow* r = rec.row + rec.m - 1;
    memcpy(tip, r->tip, 3 * sizeof(double));
    for (int s = 0; s < CSR_NSEG; s++) {
      bend[s][0] = r->seg[s].bend[0];
      bend[s][1] = r->seg[s].bend[1];
    }
  }
  csr_bendCurveFree(&bc);
  return ok;
}


/* the same with the fibres */
static int tipOf(int symmetric, const double r[4], int fibre_turn, const char* stem,
                 double tip[3], double bend[3][2]) {
  return tipOfFibres(symmetric, 1, r, fibre_turn, stem, tip, bend);
}


/* |a turned by -90 deg about e3 - b|: (x, y, z) -> (y, -x, z) */
static double turnedDistance(const double a[3], const double b[3]) {
  return sqrt(pow(a[1] - b[0], 2) + pow(-a[0] - b[1], 2) + pow(a[2] - b[2], 2));
}


static const double kO1[4] = {1, 0, 0, 0}, kO2[4] = {0, 1, 0, 0};


static void test_turned_pattern_gives_the_turned_answer(void) {
  double t1[3], t2[3], b1[3][2], b2[3][2];
  if (!tipOf(1, kO1, 0, "sym_turn_a", t1, b1) || !tipOf(1, kO2, -1, "sym_turn_b", t2, b2)) {
    return;
  }
  const double d = turnedDistance(t1, t2);
  double db = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    /* a segment's bend vector (rotation about e1, e2 of its base frame) turns with the body */
    db = fmax(db, fabs(b1[s][1] - b2[s][0]) + fabs(-b1[s][0] - b2[s][1]));
  }
  printf("  symmetric mesh: Omega1 tip (%.4f, %.4f, %.4f) mm, Omega2 (fibres turned) against it "
         "turned %.2e mm, bends %.2e\n", t1[0], t1[1], t1[2], d, db);
  /* Newton's |R| <= 1e-10 of the force scale: a tip of ~1 mm deflection to ~1e-8 mm */
  CS_EXPECT(d < 1e-6);
  CS_EXPECT(db < 1e-6);
  CS_EXPECT(hypot(t1[0], t1[1]) > 0.1); /* it did bend */
}


/* the same pair on gmsh's mesh of the whole body: apart by the mesh (measured 0.09 mm at 1 mm of
 * deflection; 1e-3 mm is far above the Newton tolerance and far below that, so a whole-body
 * mesh that happened to be symmetric would show here) */
static void test_whole_body_mesh_is_not_symmetric(void) {
  double w1[3], w2[3], c1[3][2], c2[3][2];
  if (!tipOf(0, kO1, 0, "whole_turn_a", w1, c1) || !tipOf(0, kO2, -1, "whole_turn_b", w2, c2)) {
    return;
  }
  const double d = turnedDistance(w1, w2);
  printf("  whole-body mesh: the same pair %.2e mm apart\n", d);
  CS_EXPECT(d > 1e-3);
}


static void test_mirrored_pattern_gives_the_mirrored_answer(void) {
  const double r1[4] = {1, 0.5, 0, 0}, r2[4] = {0.5, 1, 0, 0};
  double t1[3], t2[3], b1[3][2], b2[3][2];
  if (!tipOf(1, r1, 0, "sym_mirror_a", t1, b1) || !tipOf(1, r2, 0, "sym_mirror_b", t2, b2)) {
    return;
  }
  /* the mirror y -> -y takes Omega1 to Omega2 (centres (+b, +b), (+b, -b)) and a bend vector
   * (b0, b1) to (b0, -b1) */
  const double d = sqrt(pow(t1[0] - t2[0], 2) + pow(t1[1] + t2[1], 2) + pow(t1[2] - t2[2], 2));
  double db = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    db = fmax(db, fabs(b1[s][0] - b2[s][0]) + fabs(b1[s][1] + b2[s][1]));
  }
  printf("  symmetric mesh: 1 : 0.5 tip (%.4f, %.4f, %.4f) mm, 0.5 : 1 against it mirrored "
         "%.2e mm, bends %.2e\n", t1[0], t1[1], t1[2], d, db);
  CS_EXPECT(d < 1e-6);
  CS_EXPECT(db < 1e-6);
  CS_EXPECT(fabs(t1[1]) > 0.01); /* it bends off the mirror plane */
}


/* all four chambers (and Omega1 & Omega3, the diagonal pair) on the symmetric mesh without the
 * fibres: the pattern is invariant under the half turn, which reverses any bend, so no segment
 * bends and the tip stays on the axis, to the Newton tolerance (the whole-body mesh bends the
 * leg's elongation modes by 1.1-1.6 deg at 0.4 MPa, README "Calibration") */
static void test_elongation_modes_do_not_bend(void) {
  const double all[4] = {1, 1, 1, 1}, diag[4] = {1, 0, 1, 0};
  const double* r[2] = {all, diag};
  const char* stem[2] = {"sym_elong_a", "sym_elong_b"};
  for (int k = 0; k < 2; k++) {
    double t[3], b[3][2];
    if (!tipOfFibres(1, 0, r[k], 0, stem[k], t, b)) {
      return;
    }
    double worst = 0;
    for (int s = 0; s < CSR_NSEG; s++) {
      worst = fmax(worst, hypot(b[s][0], b[s][1]));
    }
    printf("  %s, no fibres: tip (%.2e, %.2e, %.4f) mm, largest bend %.2e rad\n",
           k ? "Omega1&Omega3" : "all four", t[0], t[1], t[2], worst);
    CS_EXPECT(hypot(t[0], t[1]) < 1e-8);
    CS_EXPECT(worst < 1e-9);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_turned_pattern_gives_the_turned_answer);
  CS_RUN(test_mirrored_pattern_gives_the_mirrored_answer);
  CS_RUN(test_whole_body_mesh_is_not_symmetric);
  CS_RUN(test_elongation_modes_do_not_bend);
  return cs_testSummary();
}

/* test_fem_symmetry.c: the FE model on the mesh with the section's fourfold symmetry
 * (csfActuatorSpec.mesh_symmetric) answers a chamber pattern turned by a quarter turn, its
 * fibres turned with it (fibre_turn), with its answer turned: Omega2 alone against Omega1
 * alone turned by -90 deg, tip and segment bends, to the Newton tolerance. On gmsh's mesh of the
 * whole body the same pair differs by the mesh (printed beside it: the scatter the symmetric
 * mesh removes). Short leg (15 mm segments, 3 fibre turns), l_soft 5, 0.05 MPa: ~1 min, slow. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "fem_bend.h"

/* tip (mm) of the short leg under one chamber j (1..4) of every segment at p_max */
static int tipOf(int symmetric, int chamber, int fibre_turn, double tip[3], double bend[3][2]) {
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
  o.spec.fibre_turn = fibre_turn;
  o.spec.work_stem = symmetric ? "sym_mesh" : "whole_mesh";
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      o.spec.ratio[s][j] = j + 1 == chamber ? 1.0 : 0.0;
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


/* |a turned by -90 deg about e3 - b|: (x, y, z) -> (y, -x, z) */
static double turnedDistance(const double a[3], const double b[3]) {
  return sqrt(pow(a[1] - b[0], 2) + pow(-a[0] - b[1], 2) + pow(a[2] - b[2], 2));
}


static void test_turned_pattern_gives_the_turned_answer(void) {
  double t1[3], t2[3], b1[3][2], b2[3][2], w1[3], w2[3], c1[3][2], c2[3][2];
  if (!tipOf(1, 1, 0, t1, b1) || !tipOf(1, 2, -1, t2, b2)) {
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
  if (tipOf(0, 1, 0, w1, c1) && tipOf(0, 2, -1, w2, c2)) {
    printf("  whole-body mesh: the same pair %.2e mm apart\n", turnedDistance(w1, w2));
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_turned_pattern_gives_the_turned_answer);
  return cs_testSummary();
}

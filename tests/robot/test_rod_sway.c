/* test_rod_sway.c: the sway-buckling procedure (actuator/robot_sway.h, the rod's
 * compliance robot_rod.h csr_rodSwayCompliance; `crawlsim rom sway` applies the same to the
 * reduced model and the FE) against the closed forms of a straight uniform column.
 *
 * A uniform rod (one piece, E = 1 MPa, 10 x 10 mm square: EI = 833.3 N mm^2, kGA from G = E/3),
 * L = 200 mm, 32 elements, hip clamped along +z. Cases:
 *  - guided_compliance_algebra: the Euler-Bernoulli cantilever's exact compliance condenses to
 *    k_sway = 12 EI / L^3 (the formula, on numbers it did not make).
 * The rod's foot is its last element's frame (robot_rod.h): its moment acts there and holding
 * it flat holds the whole last element, whose bending energy sits at the nodes before it
 * (Voronoi lengths), so the guided column flexes over L' = L - l_N / 2 (l_N = L / 32 here:
 * P_cr 3.2 % above the column of length L; measured 3.3 %); the clamped-free column, loaded at
 * the tip node, over L.
 *  - unloaded_stiffness_timoshenko: at P = 0 the rod's condensed stiffness is the guided
 *    Timoshenko beam's 1 / (L'^3 / (12 EI) + L' / kGA) and 1 / c11 the cantilever's
 *    1 / (L^3 / (3 EI) + L / kGA), within 0.3 % (discretisation, O(1/N^2)).
 *  - sway_buckling_euler: the zero of k_sway(P) on a grid of loads (0.047 P_e steps, no row
 *    at a buckling load, where the tangent is singular) is the sway-buckling load pi^2 EI / L'^2 with Engesser's shear
 *    correction P / (1 + P / kGA), within 0.5 % (the grid's interpolation and the
 *    discretisation), with L' as above; the zero of 1 / c11 the cantilever's pi^2 EI / (4 L^2), corrected
 *    alike, within 0.5 %.
 *  - zero_crossing_and_extrapolation: csr_swayZero interpolates inside the table, extrapolates
 *    a falling table (flagged), and gives NAN for a rising one. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "robot_rod.h"
#include "robot_sway.h"

static const double kL = 200.0, kE = 1.0, kA = 100.0, kI = 1e4 / 12.0;
static const double kShear = 10.0 * 1.5 / (12.0 + 5.5); /* the rod's square-section k */
#define NEL 32

/* the guided column's flexible length: the foot element's frame is held (see above) */
static double guidedLength(void) {
  return kL - 0.5 * kL / NEL;
}

static double kGA(void) {
  return kShear * (kE / 3.0) * kA;
}

/* the uniform rod and its data; 0 on failure */
static int makeRod(csrRodModel** m, csrRodData** d, double** y) {
  csrRodParams par = csr_rodDefaultParams(NULL);
  csrRodPiece p;
  memset(&p, 0, sizeof p);
  p.length = kL;
  p.nelem = NEL;
  p.segment = -1;
  p.section.EA = kE * kA;
  p.section.GA[0] = p.section.GA[1] = kGA();
  p.section.EI[0] = p.section.EI[1] = kE * kI;
  p.section.GJ = (kE / 3.0) * 0.1406 * 1e4;
  p.rhoA = 1e-9 * kA;
  p.rhoI[0] = p.rhoI[1] = 1e-9 * kI;
  p.rhoI[2] = 2e-9 * kI;
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.params = &par;
  sp.frame[0] = sp.frame[4] = sp.frame[8] = 1.0;
  csError err;
  cs_errorClear(&err);
  *m = csr_rodModelCreatePieces(&p, 1, &sp, &err);
  *d = *m ? csr_rodDataCreate(*m, &err) : NULL;
  *y = *m ? malloc((size_t)csr_rodStateSize(*m) * sizeof(double)) : NULL;
  if (!*m || !*d || !*y) {
    fprintf(stderr, "  rod set-up failed: %s\n", err.msg);
    return 0;
  }
  return 1;
}

static void freeRod(csrRodModel* m, csrRodData* d, double* y) {
  free(y);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}

static void guided_compliance_algebra(void) {
  const double EI = 2.5e3, L = 150.0;
  const double c11 = L * L * L / (3 * EI), c12 = L * L / (2 * EI), c22 = L / EI;
  CS_EXPECT_NEAR(csr_swayGuided(c11, c12, c22), 12 * EI / (L * L * L), 0, 1e-12);
  CS_EXPECT(isnan(csr_swayGuided(c11, c12, 0.0)));
  CS_EXPECT_NEAR(csr_swayEuler(EI, L), 4 * csr_cantileverEuler(EI, L), 0, 1e-15);
}

static void unloaded_stiffness_timoshenko(void) {
  csrRodModel* m;
  csrRodData* d;
  double* y;
  if (!makeRod(&m, &d, &y)) {
    CS_EXPECT(0);
    return;
  }
  csError err;
  cs_errorClear(&err);
  double C[3];
  const csStatus st = csr_rodSwayCompliance(m, d, 0.0, 1e-5, 1e-5 * kL, y, C, &err);
  CS_EXPECT(st == CS_OK);
  const double EI = kE * kI, L3 = kL * kL * kL;
  const double Lg = guidedLength();
  CS_EXPECT_NEAR(csr_swayGuided(C[0], C[1], C[2]), 1.0 / (Lg * Lg * Lg / (12 * EI) + Lg / kGA()),
                 0, 3e-3);
  CS_EXPECT_NEAR(1.0 / C[0], 1.0 / (L3 / (3 * EI) + kL / kGA()), 0, 3e-3);
  freeRod(m, d, y);
}

static void sway_buckling_euler(void) {
  csrRodModel* m;
  csrRodData* d;
  double* y;
  if (!makeRod(&m, &d, &y)) {
    CS_EXPECT(0);
    return;
  }
  const double EI = kE * kI;
  const double Pe = csr_swayEuler(EI, guidedLength()), Pc = csr_cantileverEuler(EI, kL);
  enum { NP = 28 }; /* to 1.27 P_e: the rod stays straight past its higher modes too, but a row near one is singular */
  double P[NP], ks[NP], kc[NP];
  csError err;
  cs_errorClear(&err);
  int ok = 1;
  for (int k = 0; k < NP && ok; k++) {
    P[k] = 0.047 * Pe * k; /* no row at a buckling load: the tangent is singular there */
    double C[3];
    ok = csr_rodSwayCompliance(m, d, P[k], 1e-5, 1e-5 * kL, y, C, &err) == CS_OK;
    if (!ok) {
      fprintf(stderr, "  at P = %g N: %s\n", P[k], err.msg);
    }
    ks[k] = csr_swayGuided(C[0], C[1], C[2]);
    kc[k] = 1.0 / C[0];
  }
  CS_EXPECT(ok);
  int ext = 0;
  const double ps = csr_swayZero(NP, P, ks, &ext);
  CS_EXPECT(!ext);
  CS_EXPECT_NEAR(ps, Pe / (1 + Pe / kGA()), 0, 5e-3);
  const double pc = csr_swayZero(NP, P, kc, &ext);
  CS_EXPECT(!ext);
  CS_EXPECT_NEAR(pc, Pc / (1 + Pc / kGA()), 0, 5e-3);
  printf("  sway-buckling %.6g N (Euler-Engesser %.6g), cantilever %.6g N (%.6g)\n", ps,
         Pe / (1 + Pe / kGA()), pc, Pc / (1 + Pc / kGA()));
  freeRod(m, d, y);
}

static void zero_crossing_and_extrapolation(void) {
  const double P[3] = {0.0, 1.0, 2.0};
  const double k1[3] = {3.0, 1.0, -1.0}, k2[3] = {4.0, 3.0, 2.0}, k3[3] = {1.0, 2.0, 3.0};
  int ext = -1;
  CS_EXPECT_NEAR(csr_swayZero(3, P, k1, &ext), 1.5, 0, 1e-14);
  CS_EXPECT(ext == 0);
  CS_EXPECT_NEAR(csr_swayZero(3, P, k2, &ext), 4.0, 0, 1e-14);
  CS_EXPECT(ext == 1);
  CS_EXPECT(isnan(csr_swayZero(3, P, k3, &ext)));
  CS_EXPECT(isnan(csr_swayZero(1, P, k1, &ext)));
}

int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(guided_compliance_algebra);
  CS_RUN(unloaded_stiffness_timoshenko);
  CS_RUN(sway_buckling_euler);
  CS_RUN(zero_crossing_and_extrapolation);
  return cs_testSummary();
}

/* test_rod_model.c: the Cosserat rod's force kernel (robot_rod_model.c) is the exact gradient of
 * its discrete energy, balances globally, and its rest/actuated states are what the model says.
 *
 * Cases:
 *  - forces_are_energy_gradient: at a random strained configuration of the leg (five pieces,
 *    intrinsic curvature, stretch and twist), every node force and frame torque equals minus
 *    the central difference of the elastic energy (positions and right-multiplied rotations).
 *  - internal_forces_balance: with no external load the node forces sum to zero and the total
 *    moment Σ x_i × F_i + Q_i T_i about the origin vanishes (the energy is invariant under rigid
 *    motions of base and rod together), and the energy is invariant under such a motion.
 *  - rest_state_is_stress_free: the reset state has zero forces and zero elastic energy.
 *  - leg_pieces_and_mass: the leg's five pieces have the actuator's lengths, the total mass is
 *    the silicone density times the solid volume (chambers hollow over S - 2c).
 *  - hip_terms_from_first_element: the kernel over element 1 alone gives the hip node's force
 *    and the base frame's torque bit for bit as over the whole rod (the wrench and gains use
 *    it). */
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "robot_analytic.h"
#include "robot_rod_internal.h"

/* deterministic pseudo-random numbers in [-1, 1] (LCG; no global state) */
static double rnd(unsigned* s) {
  *s = *s * 1664525u + 1013904223u;
  return (double)(*s >> 8) / (double)(1u << 24) * 2.0 - 1.0;
}


/* a leg model with nseg elements per segment, gravity off, base frame = identity (leg along
 * +z), and its data; 1 on success */
static int makeLeg(csrActuator* act, int nseg, csrRodModel** m, csrRodData** d) {
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(act, "leg", &err);
  csrRodParams par = csr_rodDefaultParams(act);
  par.elements_per_segment = nseg;
  csrRodSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.act = act;
  spec.params = &par;
  csu_eye3(spec.frame);
  *m = csr_rodModelCreate(&spec, &err);
  *d = *m ? csr_rodDataCreate(*m, &err) : NULL;
  if (!*d) {
    fprintf(stderr, "%s\n", err.msg);
    csr_rodModelDestroy(*m);
    *m = NULL;
  }
  CS_EXPECT(*d != NULL);
  return *d != NULL;
}


/* loads with intrinsic strains on the actuated pieces, no damping, no external load */
static void strainedLoads(const csrRodModel* m, csrRodLoads* ld) {
  csrRodSegmentActuation act[CSR_NSEG];
  memset(act, 0, sizeof act);
  for (int s = 0; s < CSR_NSEG; s++) {
    act[s].u0[0] = 0.004 * (s + 1);
    act[s].u0[1] = -0.006 + 0.003 * s;
    act[s].u0[2] = 0.001;
    act[s].sigma0[2] = 0.02;
  }
  memset(ld, 0, sizeof *ld);
  csr_rodLoadsFromActuation_(m, act, ld);
}


/* elastic energy of state y with the base at x0, q0 */
static double energyOf(const csrRodModel* m, csrRodData* d, const csrRodLoads* ld,
                       const double* y, const double x0[3], const double q0[4]) {
  const double z[3] = {0, 0, 0};
  if (csr_rodUnpack_(m, &d->wk, y, x0, q0, z, z) != 0) {
    return NAN;
  }
  d->wk.hist = d->wk.dhist = NULL;
  csr_rodForces_(m, &d->wk, ld, 1, NULL, 0);
  return d->wk.elastic;
}


/* a random configuration near rest: ~1 mm displacements, ~0.2 rad rotations */
static void randomState(const csrRodModel* m, double* y, unsigned seed) {
  csr_rodRestState_(m, y);
  unsigned s = seed;
  for (int e = 0; e < m->N; e++) {
    double* b = y + m->boff[e + 1];
    double phi[3], dq[4], q[4];
    for (int k = 0; k < 3; k++) {
      b[CSR_ROD_BX + k] += rnd(&s);
      phi[k] = 0.2 * rnd(&s);
    }
    csr_rodQexp(dq, phi);
    csr_rodQmul(q, b + CSR_ROD_BQ, dq);
    memcpy(b + CSR_ROD_BQ, q, sizeof q);
  }
}


static void forces_are_energy_gradient(void) {
  csrActuator act;
  csrRodModel* m;
  csrRodData* d;
  if (!makeLeg(&act, 3, &m, &d)) {
    return;
  }
  csrRodLoads ld;
  strainedLoads(m, &ld);
  const int n = m->nstate;
  double* y = calloc((size_t)n, sizeof(double));
  double* yp = calloc((size_t)n, sizeof(double));
  double* F = calloc(3 * ((size_t)m->N + 1), sizeof(double));
  double* T = calloc(3 * ((size_t)m->N + 1), sizeof(double));
  randomState(m, y, 7u);
  const double x0[3] = {0.3, -0.2, 0.1};
  double q0[4], phi0[3] = {0.05, -0.1, 0.02};
  csr_rodQexp(q0, phi0);
  energyOf(m, d, &ld, y, x0, q0);
  memcpy(F, d->wk.F, 3 * ((size_t)m->N + 1) * sizeof(double));
  memcpy(T, d->wk.T, 3 * ((size_t)m->N + 1) * sizeof(double));
  /* central differences with h = 1e-5 (mm, rad): truncation h² E''' / 6 and round-off
   * eps E / h are both ~1e-10 of the force scale (265 N: the stiff axial springs of strained
   * elements): measured worst 3e-8 N = 1.1e-10 of it; tolerance 1e-7 of it */
  const double h = 1e-5;
  double fmaxabs = 0;
  for (int i = 0; i < 3 * (m->N + 1); i++) {
    fmaxabs = fmax(fmaxabs, fmax(fabs(F[i]), fabs(T[i])));
  }
  double worst = 0;
  for (int e = 1; e <= m->N; e++) {
    for (int k = 0; k < 6; k++) {
      double Ep = 0, Em = 0; /* both sides are always set; the initialisers quiet GCC 12 under LTO */
      for (int side = 0; side < 2; side++) {
        double sg = side ? -1 : 1;
        memcpy(yp, y, (size_t)n * sizeof(double));
        double* b = yp + m->boff[e];
        if (k < 3) {
          b[CSR_ROD_BX + k] += sg * h;
        } else {
          double ph[3] = {0, 0, 0}, dq[4], q[4];
          ph[k - 3] = sg * h;
          csr_rodQexp(dq, ph);
          csr_rodQnormalize(b + CSR_ROD_BQ);
          csr_rodQmul(q, b + CSR_ROD_BQ, dq);
          memcpy(b + CSR_ROD_BQ, q, sizeof q);
        }
        double E = energyOf(m, d, &ld, yp, x0, q0);
        if (side == 0) {
          Ep = E;
        } else {
          Em = E;
        }
      }
      double grad = (Ep - Em) / (2 * h);
      double kern = k < 3 ? F[3 * e + k] : T[3 * e + k - 3];
      worst = fmax(worst, fabs(grad + kern));
      CS_EXPECT_NEAR(-grad, kern, 1e-7 * fmaxabs, 0);
    }
  }
  printf("  max |F + dE/dq| = %.3g (force scale %.3g)\n", worst, fmaxabs);
  free(y);
  free(yp);
  free(F);
  free(T);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


/* Σ F and Σ (x × F + Q T) over nodes/frames 0..N of the unpacked configuration in d->wk */
static void totals(const csrRodModel* m, const csrRodData* d, double f[3], double mo[3]) {
  f[0] = f[1] = f[2] = mo[0] = mo[1] = mo[2] = 0;
  for (int i = 0; i <= m->N; i++) {
    double c[3], tw[3];
    csu_add3(f, f, d->wk.F + 3 * i);
    csu_cross3(c, d->wk.x + 3 * i, d->wk.F + 3 * i);
    csu_mulMatVec3(tw, d->wk.R + 9 * i, d->wk.T + 3 * i);
    csu_add3(mo, mo, c);
    csu_add3(mo, mo, tw);
  }
}


static void internal_forces_balance(void) {
  csrActuator act;
  csrRodModel* m;
  csrRodData* d;
  if (!makeLeg(&act, 4, &m, &d)) {
    return;
  }
  csrRodLoads ld;
  strainedLoads(m, &ld);
  double* y = calloc((size_t)m->nstate, sizeof(double));
  randomState(m, y, 11u);
  const double x0[3] = {1, 2, 3};
  const double q0[4] = {1, 0, 0, 0};
  double E0 = energyOf(m, d, &ld, y, x0, q0);
  double f[3], mo[3];
  totals(m, d, f, mo);
  double fs = 0;
  for (int i = 0; i < 3 * (m->N + 1); i++) {
    fs = fmax(fs, fabs(d->wk.F[i]));
  }
  /* sums of O(N) terms of size fs: round-off ~ N eps fs ~ 1e-14 fs; tolerance 1e-11 fs (and
   * fs L for moments, L = 166 mm) */
  for (int k = 0; k < 3; k++) {
    CS_EXPECT_NEAR(f[k], 0, 1e-11 * fs, 0);
    CS_EXPECT_NEAR(mo[k], 0, 1e-11 * fs * m->L, 0);
  }
  /* a rigid motion of base and rod together leaves the energy unchanged (to round-off) */
  double phi[3] = {0.7, -0.4, 1.1}, g[4], R[9], shift[3] = {10, -20, 5};
  csr_rodQexp(g, phi);
  csu_quatToMat3(R, g);
  for (int e = 0; e < m->N; e++) {
    double* b = y + m->boff[e + 1];
    double x[3], q[4];
    csu_mulMatVec3(x, R, b + CSR_ROD_BX);
    csu_add3(b + CSR_ROD_BX, x, shift);
    csr_rodQmul(q, g, b + CSR_ROD_BQ);
    memcpy(b + CSR_ROD_BQ, q, sizeof q);
  }
  double x0r[3], q0r[4];
  csu_mulMatVec3(x0r, R, x0);
  csu_add3(x0r, x0r, shift);
  csr_rodQmul(q0r, g, q0);
  double E1 = energyOf(m, d, &ld, y, x0r, q0r);
  /* energy ~ 1 N mm from strains ~1e-2; round-off of the rotated strains ~1e-14 relative */
  CS_EXPECT_NEAR(E1, E0, 0, 1e-10);
  free(y);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


static void rest_state_is_stress_free(void) {
  csrActuator act;
  csrRodModel* m;
  csrRodData* d;
  if (!makeLeg(&act, 4, &m, &d)) {
    return;
  }
  csrRodEnergy en;
  csr_rodEnergy(m, d, &en);
  /* exactly straight, unit quaternions: strains are round-off (~1e-16) */
  CS_EXPECT_NEAR(en.elastic, 0, 1e-20, 0);
  CS_EXPECT_NEAR(en.kinetic, 0, 0, 0);
  csrWrench w;
  csr_rodBaseWrench(m, d, &w);
  for (int k = 0; k < 3; k++) {
    CS_EXPECT_NEAR(w.f[k], 0, 1e-12, 0);
    CS_EXPECT_NEAR(w.m[k], 0, 1e-12, 0);
  }
  CS_EXPECT(csr_rodStateSize(m) == m->N * 13);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


static void leg_pieces_and_mass(void) {
  csrActuator act;
  csrRodModel* m;
  csrRodData* d;
  if (!makeLeg(&act, 4, &m, &d)) {
    return;
  }
  CS_EXPECT(m->npiece == 5);
  CS_EXPECT(m->N == 3 * 4 + 2);
  CS_EXPECT_NEAR(csr_rodLength(m), csr_actuatorLength(&act), 1e-12, 0);
  csrSectionProps sp;
  csr_analyticSectionCompute(&act, NULL, &sp, NULL);
  double vol = sp.area_full * csr_actuatorLength(&act);
  for (int s = 0; s < CSR_NSEG; s++) {
    vol -= 4 * CS_PI * act.r1 * act.r1 * (act.S[s] - 2 * act.c);
  }
  /* the quadrature's area is exact to ~2e-13 (robot_analytic.h) */
  CS_EXPECT_NEAR(csr_rodMass(m), act.rho * vol, 0, 1e-10);
  printf("  leg mass %.4f g, %d elements, %d states\n", csr_rodMass(m) * 1e6, m->N, m->nstate);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


static void hip_terms_from_first_element(void) {
  csrActuator act;
  csrRodModel* m;
  csrRodData* d;
  if (!makeLeg(&act, 4, &m, &d)) {
    return;
  }
  csrRodLoads ld;
  strainedLoads(m, &ld);
  ld.gravity[1] = -9810;
  ld.damping = 0.02;
  double* y = calloc((size_t)m->nstate, sizeof(double));
  randomState(m, y, 5u);
  for (int e = 1; e <= m->N; e++) {
    double* b = y + m->boff[e];
    for (int k = 0; k < 3; k++) {
      b[CSR_ROD_BV + k] = 10.0 * (k + 1) * e;
      b[CSR_ROD_BW + k] = 0.3 * k - 0.1 * e;
    }
  }
  const double x0[3] = {1, 2, 3}, v0[3] = {5, -3, 1}, w0[3] = {0.2, -0.1, 0.4};
  double q0[4], ph[3] = {0.1, 0.2, -0.3};
  csr_rodQexp(q0, ph);
  double F0[3], T0[3];
  CS_EXPECT(csr_rodUnpack_(m, &d->wk, y, x0, q0, v0, w0) == 0);
  d->wk.hist = d->wk.dhist = NULL;
  csr_rodForces_(m, &d->wk, &ld, 0, NULL, 0);
  memcpy(F0, d->wk.F, sizeof F0);
  memcpy(T0, d->wk.T, sizeof T0);
  CS_EXPECT(csr_rodUnpackPart_(m, &d->wk, y, 1, x0, q0, v0, w0) == 0);
  csr_rodForces_(m, &d->wk, &ld, 0, NULL, 0);
  CS_EXPECT(memcmp(F0, d->wk.F, sizeof F0) == 0);
  CS_EXPECT(memcmp(T0, d->wk.T, sizeof T0) == 0);
  CS_EXPECT(csu_norm3(F0) > 1e-3 && csu_norm3(T0) > 1e-3); /* non-trivial terms */
  free(y);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(hip_terms_from_first_element);
  CS_RUN(forces_are_energy_gradient);
  CS_RUN(internal_forces_balance);
  CS_RUN(rest_state_is_stress_free);
  CS_RUN(leg_pieces_and_mass);
  return cs_testSummary();
}

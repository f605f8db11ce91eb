/* scratch: one step with one linearised pass against the converged Newton step from the same
 * state (the Newton run's states), fixed step h, order ORD: the largest difference of the
 * support's position and of each foot's per step, mean over N steps from t = 1 s. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "cs_test.h"
#include "strain_flat_fixture.h"
#include "sim_internal.h"
#include "sim_model.h"
static void rec(const csModel* m, const csData* d, double* y) {
  const dReal* x = dBodyGetPosition(d->robot->support);
  for (int i = 0; i < 3; i++) y[i] = x[i];
  for (int k = 0; k < CSR_NLEG; k++) {
    double c[6];
    m->robot.leg_type->centerline(d->robot->legs[k], 2, c);
    for (int i = 0; i < 3; i++) y[3 + 3 * k + i] = c[3 + i];
  }
}
int main(int argc, char** argv) {
  double h = atof(argv[1]); int ord = atoi(argv[2]); int N = atoi(argv[3]);
  int carry = argc > 4 ? atoi(argv[4]) : 0;
  dInitODE2(0);
  csModel m;
  if (!csTestLoadFlatStrainOrder(&m, getenv("CS_SOURCE_DIR"), &csr_leg_strain, h, 2, 0, 0, ord)) return 1;
  m.opt.tree_iterations = 24;
  if (getenv("LP_MU")) m.contact.mu = atof(getenv("LP_MU"));
  csData* d = csTestSettledData(&m);
  csError err;
  long n0 = lround(1.0 / h);
  for (long i = 0; i < n0; i++) if (cs_step(&m, d, &err) != CS_OK) { printf("%s\n", err.msg); return 1; }
  int ns = cs_stateSize(&m, d);
  double* x = malloc(ns * sizeof(double));
  double yn[27], yo[27], es = 0, ef[8] = {0}, esum = 0, efsum = 0;
  for (int s = 0; s < N; s++) {
    cs_stateGet(&m, d, x);
    m.opt.tree_iterations = 1; m.opt.tree_carry = carry;
    if (cs_step(&m, d, &err) != CS_OK) { printf("one: %s\n", err.msg); return 1; }
    rec(&m, d, yo);
    cs_stateSet(&m, d, x, &err);
    m.opt.tree_iterations = 24; m.opt.tree_carry = 0;
    if (cs_step(&m, d, &err) != CS_OK) { printf("newton: %s\n", err.msg); return 1; }
    rec(&m, d, yn);
    double e = 0;
    for (int i = 0; i < 3; i++) e = fmax(e, fabs(yo[i] - yn[i]));
    es = fmax(es, e); esum += e;
    double fm = 0;
    for (int k = 0; k < 8; k++) { double f = 0; for (int i = 0; i < 3; i++) f = fmax(f, fabs(yo[3+3*k+i] - yn[3+3*k+i])); ef[k] = fmax(ef[k], f); fm = fmax(fm, f);}
    efsum += fm;
    if (getenv("LP_V")) { printf("t %.4f sup %.2e feet", cs_time(d), e); for (int k = 0; k < 8; k++) { double f = 0; for (int i = 0; i < 3; i++) f = fmax(f, fabs(yo[3+3*k+i] - yn[3+3*k+i])); printf(" %c%.1e%s", 'A'+k, f, m.robot.leg_type->contactDepth(d->robot->legs[k]) > 0 ? "*" : " "); } printf("\n"); if (getenv("LP_LEG")) { int k = atoi(getenv("LP_LEG")); printf("   leg %c one (%.5f %.5f %.5f) newton (%.5f %.5f %.5f) start-state\n", 'A'+k, yo[3+3*k], yo[4+3*k], yo[5+3*k], yn[3+3*k], yn[4+3*k], yn[5+3*k]); } }
  }
  printf("h %g order %d carry %d, %d steps from 1 s: support max %.3e mean %.3e mm; feet max", h, ord, carry, N, es, esum / N);
  for (int k = 0; k < 8; k++) printf(" %.2e", ef[k]);
  printf(" mean(max foot) %.3e mm\n", efsum / N);
  return 0;
}

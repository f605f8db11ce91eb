/* scratch: test_strain_driver's frictionless centre of mass (1 s of the gait) on the adaptive
 * step TOL, order ORD, PASSES tree passes, CARRY */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include "cs_test.h"
#include "strain_flat_fixture.h"
#include "sim_internal.h"
#include "sim_model.h"
int main(int argc, char** argv) {
  double tol = atof(argv[1]); int ord = atoi(argv[2]); int passes = atoi(argv[3]); int carry = atoi(argv[4]);
  dInitODE2(0);
  csModel m;
  if (!csTestLoadFlatStrain(&m, getenv("CS_SOURCE_DIR"), &csr_leg_strain, 1e-3, 3, 0, 0.0)) return 1;
  m.contact.mu = 0; m.opt.h = 5e-3; m.opt.tree_iterations = passes;
  if (ord) csr_legSettingSet(m.robot.leg_type, &m.robot.leg_settings, "step_order", ord, NULL);
  if (tol > 0) { m.opt.step_adaptive = 1; m.opt.step_tol = tol; } else { m.opt.h = -tol; }
  m.opt.tree_carry = carry;
  csData* d = csTestSettledData(&m);
  if (!d) return 1;
  double big = 0;
  double c0[3], c1[3], x0[3], x1[3], moved = 0;
  cs_robotCenterOfMass(&m, d, c0);
  cs_supportDisplacement(d, x0);
  csError err;
  for (int i = 0; i < lround(1.0 / m.opt.h); i++) {
    if (cs_step(&m, d, &err) != CS_OK) { printf("%s\n", err.msg); return 1; }
    cs_supportDisplacement(d, x1);
    moved = fmax(moved, hypot(x1[0] - x0[0], x1[2] - x0[2]));
    big = fmax(big, sqrt(d->cosim.carry[0]*d->cosim.carry[0]+d->cosim.carry[1]*d->cosim.carry[1]+d->cosim.carry[2]*d->cosim.carry[2]));
  }
  cs_robotCenterOfMass(&m, d, c1);
  csAdaptiveStats s; cs_adaptiveStats(d, &s);
  printf("tol %g order %d passes %d carry %d: moved %.2f mm, centre of mass %.3e mm in 1 s; %ld accepted %ld rejected; largest carry %.3e\n", tol, ord, passes, carry, moved, hypot(c1[0] - c0[0], c1[2] - c0[2]), (long)s.accepted, (long)s.rejected, big);
  return 0;
}

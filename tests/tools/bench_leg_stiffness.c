/* bench_leg_stiffness.c: does the prb leg bend under its own weight as the full FE leg does?
 * (a cross-level check, not a ctest: the FE solve takes minutes)
 *
 *   bench_leg_stiffness [g_m_per_s2 (default 1)] [l_soft mm (4)] [--no-fibres]
 *
 * The `leg` actuator, base clamped, axis horizontal, gravity g across it (along e1), chambers
 * vented. Prints the tip's sag from three levels: Euler-Bernoulli with the prb's E'I = E_bend I
 * (solid joints rigid, as the chain has them), the prb chain in ODE (settled with damping), and
 * the full FE model (fem/, Tet10 mixed Yeoh with the Kevlar double helix). The ratio FE / prb is
 * the factor by which the prb's bending stiffness differs from the FE's. Small g keeps the sag
 * in the linear range (at g = 1 m/s^2 ~5 mm on 166 mm); at 9.81 both levels are nonlinear. */
#include <math.h>
#include <stdarg.h>
#include <ode/ode.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "fem_bend.h"
#include "robot_analytic.h"
#include "robot_calibration.h"
#include "robot_leg.h"

/* ODE's "zero length vector in dRFrom2Axes" on attaching universal joints is expected (see
 * tools/crawlsim.c): not printed here either */
static void quietOde(int num, const char* msg, va_list ap) { (void)num, (void)msg, (void)ap; }


static double prbSag(const csrActuator* act, const char* calib, double g_mm) {
  csError err;
  csrCalibration* cal = csr_calibrationOpen(calib, act, &err);
  if (!cal) {
    fprintf(stderr, "bench_leg_stiffness: %s\n", err.msg);
    return NAN;
  }
  csrBendMap map = csr_calibrationMap(cal);
  csrLegParams par = csr_defaultLegParams(act);
  dWorldID world = dWorldCreate();
  dWorldSetQuickStepNumIterations(world, 200);
  dWorldSetGravity(world, -g_mm, 0, 0); /* leg hangs along -y: gravity along -x is across it */
  dWorldSetLinearDamping(world, 0.02);
  dWorldSetAngularDamping(world, 0.02);
  dSpaceID space = dSimpleSpaceCreate(0);
  dBodyID support = dBodyCreate(world);
  dJointID weld = dJointCreateFixed(world, 0);
  dJointAttach(weld, support, 0);
  dJointSetFixed(weld);
  csrLegSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.act = act;
  spec.params = &par;
  spec.map = &map;
  spec.world = world;
  spec.space = space;
  spec.support = support;
  spec.h = 1e-3;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0}; /* e1 = +x, e2 = +z, e3 = -y */
  memcpy(spec.frame, F, sizeof F);
  csrLeg* leg = csr_leg_prb.create(&spec, &err);
  double sag = NAN;
  if (leg) {
    const double p[12] = {0};
    for (int i = 0; i < 5000; i++) {
      csr_leg_prb.actuate(leg, 0, p, 0, p);
      dWorldQuickStep(world, spec.h);
    }
    double cl[6];
    csr_leg_prb.centerline(leg, 2, cl);
    sag = -cl[3];
    csr_leg_prb.destroy(leg);
  }
  dSpaceDestroy(space);
  dWorldDestroy(world);
  csr_calibrationClose(cal);
  return sag;
}


int main(int argc, char** argv) {
  double g = argc > 1 ? atof(argv[1]) : 1.0, lsoft = argc > 2 ? atof(argv[2]) : 4.0;
  int fibres = !(argc > 3 && !strcmp(argv[3], "--no-fibres"));
  if (!(g > 0) || !(lsoft > 0)) {
    fprintf(stderr, "usage: bench_leg_stiffness [g m/s^2 > 0] [l_soft mm > 0] [--no-fibres]\n");
    return 2;
  }
  csError err;
  csrActuator act;
  if (csr_actuatorPreset(&act, "leg", &err) != CS_OK) return 1;
  const double g_mm = 1000 * g;

  /* Euler-Bernoulli: w = ∫ M(s) (L - s) / EI ds over the chambered parts, M = q (L - s)^2 / 2,
   * q from the leg's mass per length (the prb's own mass) */
  csrLegParams par = csr_defaultLegParams(&act);
  double L = csr_actuatorLength(&act), EI = par.E_bend * csr_legSectionI(&act);
  char calib[1024];
  snprintf(calib, sizeof calib, "%s/robot/calibration_provisional.txt", CS_SOURCE_DIR);
  dInitODE2(0);
  dSetMessageHandler(quietOde);
  double sag_prb = prbSag(&act, calib, g_mm);
  dCloseODE();
  csrSectionProps sp;
  csr_analyticSectionCompute(&act, NULL, &sp, &err);
  /* mean mass per length from the silicone volume (chambers hollow over S - 2c) */
  double V = 0;
  for (int s = 0; s < CSR_NSEG; s++) V += sp.area_holed * (act.S[s] - 2 * act.c);
  V += csr_actuatorOuterArea(&act) * (L - (act.S[0] + act.S[1] + act.S[2] - 6 * act.c));
  double q = act.rho * V * g_mm / L, w = 0;
  const int n = 20000;
  for (int i = 0; i < n; i++) {
    double s = (i + 0.5) * L / n;
    int in_joint = 0;
    for (int k = 0; k < 2; k++) {
      double j0 = csr_actuatorSegmentStart(&act, k) + act.S[k];
      in_joint |= (s > j0 && s < j0 + act.LS[k]);
    }
    if (!in_joint) w += q * (L - s) * (L - s) / 2 * (L - s) / EI * (L / n);
  }
  printf("leg actuator, L = %.1f mm, g = %g m/s^2 across the axis, chambers vented\n", L, g);
  printf("  Euler-Bernoulli (E'I = %.0f N mm^2, joints rigid): tip sag %.3f mm\n", EI, w);
  printf("  prb chain (%d links/segment):                   tip sag %.3f mm\n",
         (int)csr_legSettingGet(&csr_leg_prb, NULL, "links", 0), sag_prb);
  fflush(stdout);

  csfBendOptions o = csf_bendDefault();
  o.p_max = 1e-4;
  o.p_step = 1e-4;
  o.spec.mesh_size = lsoft;
  o.spec.fibres = fibres;
  o.spec.gravity[0] = -g_mm;
  o.spec.work_stem = "bench_leg_stiffness";
  csfBendInfo info;
  memset(&info, 0, sizeof info);
  o.info = &info;
  csrBendCurve bc;
  if (csr_bendCurveInit(&bc, 8, &err) != CS_OK) return 1;
  if (csf_bend(&act, &o, &bc, &err) != CS_OK) {
    fprintf(stderr, "bench_leg_stiffness: FE: %s\n", err.msg);
    csr_bendCurveFree(&bc);
    return 1;
  }
  double sag_fe = -bc.tip[0];
  printf("  full FE (l_soft %g mm, %s, %d Tet10):          tip sag %.3f mm (%.0f s)\n", lsoft,
         fibres ? "fibres" : "no fibres", info.ntet, sag_fe, info.t_total);
  printf("  FE / prb sag %.3f  (the prb's bending is %.3f x as stiff as the FE's)\n",
         sag_fe / sag_prb, sag_fe / sag_prb);
  csr_bendCurveFree(&bc);
  return 0;
}

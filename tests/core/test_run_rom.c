/* test_run_rom.c: the robot standing on rom legs (robot/rom/robot_rom_leg.c) on the flat road:
 * the support is held by the legs through their soles' contact, not prescribed.
 *
 * The leg file comes from outside the repository (115 MB for the short leg's basis of 96
 * modes, made by `crawlsim rom leg-file` from a basis of tools/rom_basis.py; docs/notes/rom.md
 * "--legs rom from a leg file"): its path in the environment variable CRAWLSIM_ROM_LEG_FILE,
 * the legs' segments in CRAWLSIM_ROM_LEG_S (mm, default 15: the short leg). Without the file
 * the test reports itself skipped (ctest's SKIP_RETURN_CODE 77), never passed.
 *
 * Criterion (a closed form: statics). No gait (zero pressures), earth conditions (the legs
 * weigh), the provisional calibration (the rom does not use the map; the run needs one of the
 * legs' actuator), the level's default coupling (stabilised: Gauss-Seidel diverges while settling,
 * docs/notes/rom.md "Settling on rom legs"). After cs_simCreate's settling (0.3 s), over a window of WINDOW s:
 *  - the terrain's force on the eight legs, averaged over the window, carries the robot's
 *    weight: |Σ f_y - m g| <= 5 % of m g. The support does not touch the ground (its force
 *    would be missing from the feet's), and its momentum change over the window, M Δv / T,
 *    is what the balance leaves: the tolerance covers a settling oscillation of
 *    Δv <= 0.05 g T (0.5 mm/s over 10 ms);
 *  - the support stays where it settled: |Δx| < 0.2 mm and its tilt < 1 deg. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "crawlsim.h"
#include "cs_test.h"

#define WINDOW 0.01 /* s */

static double g_mass_g = NAN;

static void logLine(void* user, const char* line) {
  (void)user;
  printf("  | %s\n", line);
  const char* p = strstr(line, "robot mass ");
  if (p) {
    g_mass_g = atof(p + strlen("robot mass "));
  }
}

static const char* g_file;
static double g_S = 15.0;

static void robot_stands_on_rom_legs(void) {
  const char* file = g_file;
  const double S = g_S;
  char s1[32], s2[32], s3[32], cal[600];
  snprintf(s1, sizeof s1, "S1=%g", S);
  snprintf(s2, sizeof s2, "S2=%g", S);
  snprintf(s3, sizeof s3, "S3=%g", S);
  const char* sets[3] = {s1, s2, s3};
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(cal, sizeof cal, "%s/robot/calibration_provisional.txt", src ? src : ".");
  csRunDef def = cs_defaultRunDef();
  def.legs = "rom";
  def.rom_file = file;
  def.actuator_set = sets;
  def.n_actuator_set = 3;
  def.calibration = cal;
  def.no_gait = 1;
  def.conditions = "earth";
  def.log = logLine;
  csError err;
  cs_errorClear(&err);
  const clock_t c0 = clock();
  csSim* s = cs_simCreate(&def, &err);
  if (!s) {
    printf("  cs_simCreate: %s\n", err.msg);
  }
  CS_EXPECT(s != NULL);
  if (!s) {
    return;
  }
  const double c_create = (double)(clock() - c0) / CLOCKS_PER_SEC;
  double x0[3], q0[4], x[3], q[4], f[24];
  cs_simSupportPose(s, x0, q0);
  double fy = 0;
  int nstep = 0;
  const clock_t c1 = clock();
  csStatus st = CS_OK;
  while (st == CS_OK && cs_simTime(s) < WINDOW - 1e-9) {
    st = cs_simStep(s, &err);
    cs_simFootForces(s, f);
    for (int k = 0; k < 8; k++) {
      fy += f[3 * k + 1];
    }
    nstep++;
  }
  const double c_step = (double)(clock() - c1) / CLOCKS_PER_SEC;
  if (st != CS_OK) {
    printf("  step: %s\n", err.msg);
  }
  CS_EXPECT(st == CS_OK);
  fy /= nstep > 0 ? nstep : 1;
  cs_simSupportPose(s, x, q);
  const double W = g_mass_g * 1e-3 * 1e-3 * 9810.0; /* g -> t, times mm/s^2: N */
  const double tilt = 2 * acos(fmin(1.0, fabs(q[0]))) * 180 / acos(-1.0);
  const double dx = sqrt((x[0] - x0[0]) * (x[0] - x0[0]) + (x[1] - x0[1]) * (x[1] - x0[1]) +
                         (x[2] - x0[2]) * (x[2] - x0[2]));
  printf("  standing on rom legs: sum of the feet's f_y %.5g N against the weight %.5g N "
         "(%.2f %%), support moved %.4f mm, tilt %.3f deg over %g s (%d steps)\n", fy, W,
         100 * (fy - W) / W, dx, tilt, WINDOW, nstep);
  printf("  CPU: set-up and settling (0.3 s) %.1f s, %.1f s per simulated second while "
         "standing (8 legs, one core)\n", c_create, c_step / WINDOW);
  CS_EXPECT(isfinite(W) && fabs(fy - W) <= 0.05 * W);
  CS_EXPECT(dx < 0.2);
  CS_EXPECT(tilt < 1.0);
  cs_simDestroy(s);
}

int main(void) {
  const char* file = getenv("CRAWLSIM_ROM_LEG_FILE");
  if (!file || !file[0]) {
    printf("test_run_rom: skipped: no leg file (set CRAWLSIM_ROM_LEG_FILE to a file of crawlsim "
           "rom leg-file; docs/notes/rom.md)\n");
    return 77;
  }
  const char* es = getenv("CRAWLSIM_ROM_LEG_S");
  g_file = file;
  g_S = es ? atof(es) : 15.0;
  /* a case, so that the summary counts it (without one it reports 0 cases: a failure) */
  CS_RUN(robot_stands_on_rom_legs);
  return cs_testSummary();
}

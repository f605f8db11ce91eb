/* test_strain_obstacle_stop.c: the obstacle scene on strain legs (its defaults) restored at
 * 26.8 s from tests/core/data/strain_obstacle_26.8.state and stepped to 26.9 s. At 26.846 s a
 * foot's nonsmooth contact held the tree step's damped Newton passes in a cycle of period four
 * (moves 2.0, 2.4, 0.94, 0.54, 2.0 ... e-4 mm) at every halving of the step down to 1/16, and
 * the whole climb stopped there (docs/notes/strain_leg.md "The obstacle's stop"); the retried
 * step's damping now stays once half the passes are spent (core/sim_coupling.c). Checked: every
 * step succeeds, the time reaches 26.9 s, the support moves on (the crossing is the run's, not
 * a stand-still: > 1 mm in x over the 0.1 s, the robot crawls at ~60 mm/s here) and the feet's
 * forces stay finite. With the damping's old rule this test fails at 26.846 s with the
 * run's own message (last move 9.43e-05 mm): the file is the state the stopping run had at
 * 26.8 s (main at d77e82c). The fixed code reaches 26.8 s in a slightly different state (earlier
 * retried steps take the new rule) from which the old rule happens to pass, so when the
 * state's layout changes, regenerate the file with strain_obstacle_state built with the old
 * rule (the `else` of the damping restored) and check that this test fails there; a size
 * mismatch fails with that instruction. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "crawlsim.h"
#include "cs_test.h"

static double* readState(const char* path, int* n) {
  FILE* f = fopen(path, "r");
  if (!f) {
    return NULL;
  }
  double* x = NULL;
  if (fscanf(f, "%d", n) == 1 && *n > 0 && *n < 1000000) {
    x = malloc((size_t)*n * sizeof(double));
    for (int i = 0; x && i < *n; i++) {
      if (fscanf(f, "%la", x + i) != 1) {
        free(x);
        x = NULL;
      }
    }
  }
  fclose(f);
  return x;
}


static void test_obstacle_strain_steps_across_26_846(void) {
  const char* src = getenv("CS_SOURCE_DIR");
  char path[4096];
  snprintf(path, sizeof path, "%s/tests/core/data/strain_obstacle_26.8.state", src ? src : ".");
  int n = 0;
  double* x = readState(path, &n);
  CS_EXPECT(x != NULL);
  if (!x) {
    fprintf(stderr, "  cannot read %s\n", path);
    return;
  }
  csRunDef def = cs_defaultRunDef();
  def.scene = "obstacle";
  def.legs = "strain";
  def.data_dir = src;
  csError err;
  csSim* s = cs_simCreate(&def, &err);
  CS_EXPECT(s != NULL);
  if (!s) {
    fprintf(stderr, "  %s\n", err.msg);
    free(x);
    return;
  }
  CS_EXPECT(cs_simStateSize(s) == n);
  if (cs_simStateSize(s) != n) {
    fprintf(stderr, "  the state has %d values, the file %d: regenerate it with "
            "strain_obstacle_state 26.8 %s built with the damping's old rule (this file's "
            "header)\n", cs_simStateSize(s), n, path);
  } else {
    CS_EXPECT(cs_simStateSet(s, x, &err) == CS_OK);
    /* the file's time, to the step's round-off */
    CS_EXPECT_NEAR(cs_simTime(s), 26.8, 1e-9, 0);
    double p0[3], q[4], p1[3], f[24];
    cs_simSupportPose(s, p0, q);
    int failed = 0;
    while (cs_simTime(s) < 26.9 - 1e-9 && !failed) {
      if (cs_simStep(s, &err) != CS_OK) {
        fprintf(stderr, "  %s\n", err.msg);
        failed = 1;
      }
    }
    CS_EXPECT(!failed);
    CS_EXPECT_NEAR(cs_simTime(s), 26.9, 1e-9, 0); /* reached, to the step's round-off */
    cs_simSupportPose(s, p1, q);
    CS_EXPECT(fabs(p1[0] - p0[0]) > 1.0); /* mm: crawling at ~60 mm/s, not standing */
    cs_simFootForces(s, f);
    int finite = 1;
    for (int i = 0; i < 24; i++) {
      finite &= isfinite(f[i]);
    }
    CS_EXPECT(finite);
  }
  cs_simDestroy(s);
  free(x);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_obstacle_strain_steps_across_26_846);
  return cs_testSummary();
}

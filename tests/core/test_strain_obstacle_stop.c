/* test_strain_obstacle_stop.c: the obstacle scene on strain legs restored at 26.8 s from
 * tests/core/data/strain_obstacle_26.8.state and stepped to 26.9 s on the gait table that made
 * the state, tests/core/data/strain_obstacle_26.8_gait.csv (the scene's default until
 * 2026-12-06, gaits/obstacle.csv of 9e90162; the default since differs from 7.4 s on, and the
 * stop is that table's event, so the test names it, `paper` as the scene's). At 26.846 s a
 * foot's nonsmooth contact held the tree step's damped Newton passes in a cycle of period four
 * (moves 2.0, 2.4, 0.94, 0.54, 2.0 ... e-4 mm) at every halving of the step down to 1/16, and
 * the whole climb stopped there (docs/notes/strain_leg.md "The obstacle's stop"); the retried
 * step's damping now stays once half the passes are spent (core/sim_tree.c). Checked: every
 * step succeeds, the time reaches 26.9 s, the support moves on (the crossing is the run's, not
 * a stand-still: > 1 mm in x over the 0.1 s, the robot crawls at ~60 mm/s here) and the feet's
 * forces stay finite. With the damping's old rule this test fails at 26.846 s with the
 * run's own message (last move 9.43e-05 mm): the file is the state the stopping run had at
 * 26.8 s (main at d77e82c). The fixed code reaches 26.8 s in a slightly different state (earlier
 * retried steps take the new rule) from which the old rule happens to pass, so when the
 * state's layout changes, regenerate the file with strain_obstacle_state built with the old
 * rule (the `else` of the damping restored), run as `strain_obstacle_state 26.8 FILE obstacle
 * tests/core/data/strain_obstacle_26.8_gait.csv paper`, and check that this test fails there; a
 * size mismatch fails with that instruction. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "crawlsim.h"
#include "cs_test.h"
#include "restored_run.h"

static void test_obstacle_strain_steps_across_26_846(void) {
  const char* src = getenv("CS_SOURCE_DIR");
  char path[4096], gait[4096];
  snprintf(path, sizeof path, "%s/tests/core/data/strain_obstacle_26.8.state", src ? src : ".");
  snprintf(gait, sizeof gait, "%s/tests/core/data/strain_obstacle_26.8_gait.csv",
           src ? src : ".");
  csRunDef def = cs_defaultRunDef();
  def.scene = "obstacle";
  def.gait = gait;
  def.conditions = "paper"; /* a gait of one's own defaults to earth */
  def.legs = "strain";
  def.links = 3; /* the basis the state files were made with (3 bending modes per segment,
                   the level's default then) */
  def.dt = 1e-3; /* the step the state files were made with (the level's default then) */
  def.strain_sub = 4; /* the sub-intervals the state files were made with (4 capsules per
                        segment in their contact history; the level's default then) */
  def.data_dir = src;
  RestoredRun r = restoredRun(&def, path, 26.8, 26.9,
                              "strain_obstacle_state 26.8 FILE obstacle GAIT paper built with "
                              "the damping's old rule, this file's header");
  CS_EXPECT(r.ran);
  if (r.ran) {
    CS_EXPECT(!r.failed);
    CS_EXPECT_NEAR(r.t, 26.9, 1e-9, 0);          /* reached, to the step's round-off */
    CS_EXPECT(fabs(r.p1[0] - r.p0[0]) > 1.0);    /* mm: crawling at ~60 mm/s, not standing */
    CS_EXPECT(r.forces_finite);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_obstacle_strain_steps_across_26_846);
  return cs_testSummary();
}

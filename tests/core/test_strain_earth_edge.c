/* test_strain_earth_edge.c: the flat road under `earth` with the paper's table
 * (gaits/flat_road_paper.csv) on strain legs, restored at 0.904 s from
 * tests/core/data/strain_earth_0.904.state and stepped to 0.906 s. The robot slides backwards
 * off the road's start edge and falls; at 0.90425 s leg H lies across the edge (x = 0) and is
 * struck onto it at ~0.4 m/s: Hunt-Crossley's factor ~40 on its normal force (8-16 N where the
 * elastic load is ~0.3 N) and the friction's bristle damping with it. The contact's normal
 * stays within 1e-3 over the passes (the geometry is smooth over the edge), but over 62.5 us,
 * 1/16 of the 1 ms step, the leg's velocity changes by more than Newton's linear model of the
 * law holds over: the passes cycle, then crawl at 1/8 damping, and the run stopped there ("did
 * not converge in 48 Newton passes"). A rejected tree step now halves down to 1/256
 * (sim_internal.h CS_MAX_SPLIT 8): the same steps converge at 1/64 and the run falls off the
 * road at 1.021 s as the rod does at 1.023 s (docs/notes/strain_leg.md "The road's edge").
 * Checked: every step succeeds, the time reaches 0.906 s, the support goes on falling (its
 * height drops > 1 mm over the 2 ms: it falls at ~0.9 m/s here) and the feet's forces stay
 * finite. With CS_MAX_SPLIT 4 this test fails at 0.9043 s with the run's own message. The
 * file is the state of the run at 0.904 s, the same bits with either value (no step before
 * it was halved more than 4 times); regenerate it when the state's layout changes:
 *   strain_obstacle_state 0.904 FILE flat-road $CS_SOURCE_DIR/gaits/flat_road_paper.csv earth
 * (a size mismatch fails with that instruction). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "crawlsim.h"
#include "cs_test.h"
#include "restored_run.h"

static void test_earth_strain_steps_across_the_road_edge(void) {
  const char* src = getenv("CS_SOURCE_DIR");
  char path[4096], gait[4096];
  snprintf(path, sizeof path, "%s/tests/core/data/strain_earth_0.904.state", src ? src : ".");
  snprintf(gait, sizeof gait, "%s/gaits/flat_road_paper.csv", src ? src : ".");
  csRunDef def = cs_defaultRunDef();
  def.scene = "flat-road";
  def.legs = "strain";
  def.links = 3; /* the basis the state files were made with (3 bending modes per segment,
                   the level's default then) */
  def.dt = 1e-3; /* the step the state files were made with (the level's default then) */
  def.strain_sub = 4; /* the sub-intervals the state files were made with (4 capsules per
                        segment in their contact history; the level's default then) */
  def.gait = gait;
  def.conditions = "earth";
  def.data_dir = src;
  RestoredRun r = restoredRun(&def, path, 0.904, 0.906,
                              "strain_obstacle_state 0.904 FILE flat-road GAIT earth, this "
                              "file's header");
  CS_EXPECT(r.ran);
  if (r.ran) {
    CS_EXPECT(!r.failed);
    CS_EXPECT_NEAR(r.t, 0.906, 1e-9, 0);
    printf("  support height %.3f -> %.3f mm over 0.904 -> %.3f s\n", r.p0[1], r.p1[1], r.t);
    CS_EXPECT(r.p0[1] - r.p1[1] > 1.0); /* mm: falling at ~0.9 m/s, not held */
    CS_EXPECT(r.forces_finite);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_earth_strain_steps_across_the_road_edge);
  return cs_testSummary();
}

/* test_obstacle.c: the obstacle scene, shortened for CI (the whole run is the README's).
 *
 * Proves: (1) the shipped terrains/obstacle.terrain is the L-shaped road of the README (three
 * boxes; the step's top 40 mm above the road; the start on the road, 90 mm before the step);
 * (2) every scene defaults to strain legs (the flat road and the slope since 2026-12-07, the
 * obstacle since branch obst10), on the mission's calibration (the 23-mode symmetric-mesh
 * FE table under rbf-pair, which both gaits were designed on and the checks below name
 * explicitly); (3) the shipped gait's stances keep the support
 * level: a road leg's stance foot is the step's height below a step leg's (the design's own
 * forward kinematics with stretch), and no pose asks the rod level for a mean segment
 * pressure above the 0.3 MPa its stiffness probes reach (the poses a move uses); (4) the
 * scene's first cycle as `crawlsim run --scene obstacle` runs it (strain legs, `paper`, the
 * landing gate), through contact and friction alone: every leg stretches and the support rises
 * by what the model predicts for pose R, then the front pair steps onto the step and the wave's
 * first cycle (the pairs step in turn while the standing feet push) carries the support
 * forward, level, the front two pairs on the step, the rear two on the road, tilt below 10 deg,
 * no foot 1 mm inside the terrain. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crawlsim.h"
#include "cs_test.h"
#include "robot_gaitdesign.h"
#include "sim_model.h"
#include "sim_scene.h"

static char g_src[512];


/* the scene's shipped files (each buffer 600 bytes): terrain, gait, its default calibration
 * (the mode table), description */
static void scenePaths(char* terr, char* gait, char* cal, char* des) {
  snprintf(terr, 600, "%s/terrains/obstacle.terrain", g_src);
  snprintf(gait, 600, "%s/gaits/obstacle.csv", g_src);
  snprintf(cal, 600, "%s/robot/calibration_fe_leg_modes_sym.h5", g_src);
  snprintf(des, 600, "%s/gaits/obstacle.gait", g_src);
}


/* the scene's calibration rule (rbf-pair), as `crawlsim run --scene obstacle` sets it */
static void sceneRule(csModel* m) {
  const csScene* sc = cs_sceneFind("obstacle");
  csrCalRule rule;
  if (sc && sc->cal_rule && csr_calRuleParse(sc->cal_rule, &rule)) {
    m->cal_rule = (int)rule;
  }
}


static void test_obstacleTerrainIsTheLShapedStepRoad(void) {
  char p[600];
  snprintf(p, sizeof p, "%s/terrains/obstacle.terrain", g_src);
  cstTerrain t;
  csError err;
  CS_EXPECT(cst_terrainLoad(&t, p, &err) == CS_OK);
  CS_EXPECT(t.nbox == 3 && !strcmp(t.name, "obstacle"));
  /* road top 0, the step 40 mm above it (paper Sec. 5.2), the start 90 mm before the step */
  CS_EXPECT(cst_terrainHeightAt(&t, t.start[0], t.start[1]) == 0);
  CS_EXPECT(cst_terrainHeightAt(&t, 300, 117.5) == 40);
  CS_EXPECT(cst_terrainHeightAt(&t, 239, 117.5) == 0 && cst_terrainHeightAt(&t, 461, 117.5) == 0);
  /* the turn: the second arm carries the support 270 mm along +z at x = 150 + 646 */
  CS_EXPECT(cst_terrainHeightAt(&t, 796, 117.5 + 270 + 72.5) == 0);
}


/* every scene defaults to strain legs (the flat gait was searched on them, docs/notes/
 * gait_search.md; the obstacle's rule 17 was measured on them, docs/notes/obstacle.md), all on
 * the mission's calibration: the 23-mode symmetric-mesh table under rbf-pair (both gaits were
 * designed there) */
static void test_scenesRunTheirLevelsOnAnFeModeTable(void) {
  const csScene* fr = cs_sceneFind("flat-road");
  const csScene* ob = cs_sceneFind("obstacle");
  const csScene* sl = cs_sceneFind("slope");
  CS_EXPECT(fr && ob);
  if (fr && ob) {
    CS_EXPECT(!strcmp(fr->calibration, "robot/calibration_fe_leg_modes_sym.h5"));
    CS_EXPECT(fr->cal_rule && !strcmp(fr->cal_rule, "rbf-pair"));
    CS_EXPECT(!strcmp(ob->calibration, "robot/calibration_fe_leg_modes_sym.h5"));
    CS_EXPECT(ob->cal_rule && !strcmp(ob->cal_rule, "rbf-pair"));
    CS_EXPECT(fr->legs && !strcmp(fr->legs, "strain") && ob->legs && !strcmp(ob->legs, "strain"));
    CS_EXPECT(sl && sl->legs && !strcmp(sl->legs, fr->legs));
    CS_EXPECT(fr->rod_links >= 1 && ob->rod_links >= 1);
  }
  CS_EXPECT(cs_sceneCount() == 3 && cs_sceneFind("obstacle") && cs_sceneFind("flat-road"));
}


/* the designed poses of the shipped description (NULL on error; caller frees both) */
static csrDesignedPoses* designedPoses(csModel* m, csgDesign** dout) {
  char terr[600], gait[600], cal[600], des[600];
  scenePaths(terr, gait, cal, des);
  csError err;
  cs_errorClear(&err);
  csgDesign* d = malloc(sizeof *d);
  csrDesignedPoses* poses = malloc(sizeof *poses);
  csrGaitDesignOptions o = csr_defaultGaitDesignOptions();
  o.stretch = 1;
  o.p_max = 0.4; /* the mode table's range (the shipped table's command) */
  sceneRule(m);
  int ok = d && poses && cs_modelLoad(m, "obstacle", terr, gait, cal, &err) == CS_OK &&
           csg_designRead(d, des, &err) == CS_OK &&
           csr_designPoses(&m->robot.leg, &m->robot.map, d, &o, poses, &err) == CS_OK;
  if (!ok) {
    fprintf(stderr, "  %s\n", err.msg);
    free(d);
    free(poses);
    *dout = NULL;
    return NULL;
  }
  *dout = d;
  return poses;
}


static void test_obstacleStancesKeepTheSupportLevel(void) {
  csModel m;
  cs_modelInit(&m);
  csgDesign* d = NULL;
  csrDesignedPoses* poses = designedPoses(&m, &d);
  CS_EXPECT(poses != NULL);
  int pairs = 0, lowered = 0, unused = 0;
  double worst = 0, worst_low = 0, mean_max = 0;
  for (int q = 1; poses && q < d->npose; q++) {
    const char* n = d->pose[q].name;
    /* only what the gait commands can move the support: the description also writes the
     * road twin of every step stance and back (obstacle_gait.py "every x offset a stance uses
     * gets both stance lengths"), some of which no move uses (rule 17's GP50: a road stance
     * 50 mm ahead, 2.0 mm off the step's height, 0.303 MPa) */
    int used = 0;
    for (int k = 0; k < d->nmove && !used; k++) {
      used = d->move[k].pose == q;
    }
    if (!used) {
      unused++;
      continue;
    }
    /* rule 10's lowered road stances G<h>P<r> / GH<h>P<r> against their straight leg R<h> /
     * RH<h> of the same stretch: the stance bend must not change the support's height */
    if (n[0] == 'G' && (isdigit((unsigned char)n[1]) || n[1] == 'H')) {
      char base[CSG_DESIGN_NAME];
      size_t k = strcspn(n + 1, "PM");
      snprintf(base, sizeof base, "R%.*s", (int)k, n + 1);
      int b = csg_designPoseFind(d, base);
      CS_EXPECT(b > 0);
      if (b > 0) {
        worst_low = fmax(worst_low, fabs(poses->foot[q][2] - poses->foot[b][2]));
        lowered++;
      }
    }
    /* road stance GP<r> / GM<r> against the step stance SP<r> / SM<r> of the same stroke */
    if (n[0] == 'G' && (n[1] == 'P' || n[1] == 'M')) {
      char twin[CSG_DESIGN_NAME];
      snprintf(twin, sizeof twin, "S%s", n + 1);
      int s = csg_designPoseFind(d, twin);
      CS_EXPECT(s > 0);
      if (s > 0) {
        /* foot[2]: along e3 (down the leg), from the straight vented leg's foot */
        double dz = poses->foot[q][2] - poses->foot[s][2];
        worst = fmax(worst, fabs(dz - 40.0));
        CS_EXPECT_NEAR(poses->foot[q][0], poses->foot[s][0], 1e-6, 0);
        pairs++;
      }
    }
    for (int seg = 0; seg < 3; seg++) {
      double mean = 0;
      for (int j = 0; j < 4; j++) {
        mean += 0.25 * poses->p[q][4 * seg + j];
      }
      mean_max = fmax(mean_max, mean);
    }
  }
  /* every stance offset ahead and behind (at least four strokes each way); the step is 40 mm
   * (terrains/obstacle.terrain) and the S-shapes' own stretch differs by up to 1.1 mm between
   * the stretched and the vented leg */
  CS_EXPECT(pairs >= 8);
  CS_EXPECT(worst < 1.5);
  /* the walk comes down through three stretches to 15 mm (rule 10), several offsets each; the
   * same 1.5 mm as the S-shapes' own stretch above */
  CS_EXPECT(lowered >= 8);
  CS_EXPECT(worst_low < 1.5);
  CS_EXPECT(mean_max <= 0.3);
  printf("  %d stance pairs: road feet 40 mm +- %.2f mm below the step's; %d lowered stances "
         "within %.2f mm of their straight leg's stretch; highest mean segment pressure %.4f "
         "MPa (%d poses no move uses left out)\n", pairs, worst, lowered, worst_low, mean_max,
         unused);
  free(d);
  free(poses);
  cs_modelDestroy(&m);
}


/* the scene's first cycle as `crawlsim run --scene obstacle` runs it (no flag: strain legs at
 * the adaptive step, gaits/obstacle.csv under gaits/obstacle.gate), through the public API */
static void test_obstacleFirstCycleStepsOntoTheStep(void) {
  char terr[600], gait[600], cal[600], des[600];
  scenePaths(terr, gait, cal, des);
  csModel m;
  cs_modelInit(&m);
  csgDesign* d = NULL;
  csrDesignedPoses* poses = designedPoses(&m, &d);
  CS_EXPECT(poses != NULL);
  int r = poses ? csg_designPoseFind(d, "R") : -1;
  const double rise = r > 0 ? poses->foot[r][2] : NAN;
  free(d);
  free(poses);
  cs_modelDestroy(&m);
  CS_EXPECT(rise > 30);
  csRunDef def = cs_defaultRunDef();
  def.scene = "obstacle";
  def.data_dir = g_src;
  csError err;
  cs_errorClear(&err);
  csSim* s = cs_simCreate(&def, &err);
  CS_EXPECT(s != NULL);
  if (!s) {
    fprintf(stderr, "  %s\n", err.msg);
    return;
  }
  /* the raise, the front pair's step, the wave's first cycle (to 5.8 s): B, F set down on the
   * step at 5.4 s */
  const double t_end = 5.85;
  double x1[3] = {NAN, NAN, NAN}, x[3] = {NAN, NAN, NAN}, q[4], tilt = 0, sink = 0;
  double cl[8][2][3];
  csStatus st = CS_OK;
  for (int i = 1; st == CS_OK && i <= (int)lround(t_end / 0.01); i++) {
    st = cs_simRunUntil(s, 0.01 * i, &err);
    cs_simSupportPose(s, x, q);
    tilt = fmax(tilt, 2 * acos(fmin(1, fabs(q[0]))) * 180 / 3.14159265358979323846);
    if (i == 100) memcpy(x1, x, sizeof x1);
    /* how far a foot (the centreline's end) is inside the road (y < 0 before the step's
     * riser at x = 240) or the step (y < 40 past it), over the first cycle */
    for (int k = 0; k < 8; k++) {
      cs_simLegCenterline(s, k, 2, &cl[k][0][0]);
      sink = fmax(sink, (cl[k][1][0] < 240 ? 0 : 40) - cl[k][1][1]);
    }
  }
  CS_EXPECT(st == CS_OK);
  if (st != CS_OK) fprintf(stderr, "  %s\n", err.msg);
  /* the raise: the support stands on eight stretched legs (measured 39.6 mm against the
   * model's 40.0: the legs sag under the support), straight up */
  CS_EXPECT_NEAR(x1[1], rise, 0, 0.05);
  CS_EXPECT(fabs(x1[0]) < 1.0 && fabs(x1[2]) < 1.0);
  /* after the first cycle: A, E and B, F are on the step (past its edge at x = 240, at its
   * top y = 40 or a few mm above it: none slid down the riser; below a swing's 52 mm), the rear
   * four on the road; the support moved forward, level, 40 mm up. (On this table B, F carry
   * little once A, E have landed: at 5.8-5.9 s their feet stand unloaded 6-7 mm above the
   * step's top, docs/bench/obst10_2026-12-07c feet.py on the nominal) */
  int on_step = 0, on_road = 0;
  for (int k = 0; k < 8; k++) {
    const double fx = cl[k][1][0], fy = cl[k][1][1];
    int front = k == 0 || k == 1 || k == 4 || k == 5;
    on_step += front && fy > 37 && fy < 50 && fx > 240;
    on_road += !front && fy < 3 && fx < 240;
  }
  CS_EXPECT(on_step == 4 && on_road == 4);
  CS_EXPECT(x[0] > 20 && x[0] < 60);
  CS_EXPECT(fabs(x[1] - rise) < 5 && fabs(x[2]) < 3);
  /* issue 33's bound on the obstacle (the support pitches at B, F's landing on the step) */
  CS_EXPECT(tilt < 10.0);
  /* the legs' soft contact: a foot less than 1 mm inside the terrain (issue 33) */
  CS_EXPECT(sink < 1.0);
  printf("  rise %.2f mm at 1 s (model %.2f); at %.2f s: x %.1f h %.1f z %.2f mm, feet on the "
         "step %d (B at x %.1f h %.1f), on the road %d, tilt <= %.2f deg, a foot at most %.3f mm inside "
         "the terrain\n", x1[1], rise, t_end, x[0], x[1], x[2], on_step, cl[1][1][0], cl[1][1][1], on_road,
         tilt, sink);
  cs_simDestroy(s);
}


static void quiet(int num, const char* msg, va_list ap) {
  (void)num;
  (void)msg;
  (void)ap;
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  dInitODE2(0);
  dSetMessageHandler(quiet);
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(g_src, sizeof g_src, "%s", src ? src : ".");
  CS_RUN(test_obstacleTerrainIsTheLShapedStepRoad);
  CS_RUN(test_scenesRunTheirLevelsOnAnFeModeTable);
  CS_RUN(test_obstacleStancesKeepTheSupportLevel);
  CS_RUN(test_obstacleFirstCycleStepsOntoTheStep);
  dCloseODE();
  return cs_testSummary();
}

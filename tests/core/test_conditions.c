/* test_conditions.c: the scene conditions (core/sim_scene.h) and what they do to the physics.
 *
 * Proves: (1) `paper` makes the legs weightless and `earth` does not: standing at rest on the
 * flat road, the terrain carries the whole robot's weight under `earth` and only the
 * support's under `paper`, so the two loads differ by the legs' weight (the contact normal
 * force summed over ODE's contact joints and the legs' own contact laws, averaged over 0.1 s of
 * rest, rod legs on the mission's table); (2) the scene table:
 * the paper's scenes default to `paper`, a user's terrain or gait to `earth`, --conditions
 * wins, and a bad name is refused naming it; (3) a terrain's heading turns the robot, its
 * co-simulated legs included. */
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "sim_model.h"

static char g_src[512];


/* the mission's calibration (sim_scene.h CS_MISSION_*): its path into cal, its rule into m */
static void missionCalibration(csModel* m, char* cal, size_t n) {
  snprintf(cal, n, "%s/%s", g_src, CS_MISSION_CALIBRATION);
  csrCalRule rule;
  if (csr_calRuleParse(CS_MISSION_CAL_RULE, &rule)) {
    m->cal_rule = (int)rule;
  }
}


/* the robot settled at rest on the flat road under `c`, gravity 9.81 m/s^2, vented; the mean
 * contact force (N, world) over `n` further steps and the robot's and support's masses (t) */
static int restLoad(csConditions c, int n, double f[3], double* m_robot, double* m_support) {
  char terr[600], gait[600], cal[600];
  snprintf(terr, sizeof terr, "%s/terrains/flat_road.terrain", g_src);
  snprintf(gait, sizeof gait, "%s/gaits/flat_road_paper.csv", g_src);
  csModel m;
  cs_modelInit(&m); /* rod legs: their contacts are the legs' own law, not ODE's */
  missionCalibration(&m, cal, sizeof cal);
  cs_modelSetConditions(&m, c);
  /* rest: long enough for the landing's 0.5 mm drop and the legs' modes to die out (on rod
   * legs 1 s leaves the light `paper` load 1.3e-3 off its weight, 2 s 8e-5) */
  m.opt.settle = 2.0;
  csError err;
  cs_errorClear(&err);
  int ok = cs_modelLoad(&m, "flat-road", terr, gait, cal, &err) == CS_OK;
  csData* d = ok ? cs_dataCreate(&m, &err) : NULL;
  ok = d && cs_settle(&m, d, &err) == CS_OK;
  f[0] = f[1] = f[2] = 0;
  /* the gait's first row starts at t = 0: the schedule is vented before it; the steps are
   * taken as the settle's (pressures zero): step the data with a vented model instead */
  csg_gaitDestroy(m.gait);
  m.gait = NULL;
  for (int i = 0; ok && i < n; i++) {
    double fi[3], fk[3];
    ok = cs_step(&m, d, &err) == CS_OK;
    cs_contactForce(d, fi); /* ODE's contact joints (the support's, if it touches) */
    for (int leg = 0; leg < CSR_NLEG; leg++) {
      cs_footForce(&m, d, leg, fk); /* a co-simulated leg's own contact law */
      csu_add3(fi, fi, fk);
    }
    for (int k = 0; k < 3; k++) {
      f[k] += fi[k] / n;
    }
  }
  if (!ok) {
    fprintf(stderr, "restLoad: %s\n", err.msg);
  }
  *m_robot = d ? cs_robotMass(d) : 0;
  *m_support = m.robot.support_mass;
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  return ok;
}


static void test_legWeightChangesTheSupportLoadByTheLegsWeight(void) {
  double fe[3], fp[3], me, mp, se, sp;
  CS_EXPECT(restLoad(CS_CONDITIONS_EARTH, 100, fe, &me, &se));
  CS_EXPECT(restLoad(CS_CONDITIONS_PAPER, 100, fp, &mp, &sp));
  double g = 9810.0; /* mm/s^2: t mm/s^2 = N */
  /* at rest the terrain carries what gravity pulls: the whole robot under `earth`, the
   * support alone under `paper` (legs keep their mass: same robot mass in both). Tolerance:
   * the mean over 0.1 s of rest is within 4e-4 relative of the weight (measured on rod legs
   * 8e-5 under `paper`, 3.2e-4 under `earth`: the residual sway of the settled legs); 1e-3
   * leaves room and still tells a leg's 0.34 N apart from nothing */
  CS_EXPECT_NEAR(me, mp, 0, 1e-12);
  CS_EXPECT_NEAR(fe[1], me * g, 0, 1e-3);
  CS_EXPECT_NEAR(fp[1], sp * g, 0, 1e-3);
  /* the difference is the legs' weight: eight legs of 34.7 g, 2.73 N */
  CS_EXPECT_NEAR(fe[1] - fp[1], (me - sp) * g, 0, 2e-3);
  CS_EXPECT((me - sp) * g > 2.5);
  /* no horizontal load at rest (< 1 mN: the measured mean is ~1e-5 N) */
  CS_EXPECT(fabs(fe[0]) < 1e-3 && fabs(fp[0]) < 1e-3 && fabs(fe[2]) < 1e-3 &&
            fabs(fp[2]) < 1e-3);
  printf("  load at rest: earth %.5f N (robot %.5f N), paper %.5f N (support %.5f N)\n", fe[1],
         me * g, fp[1], sp * g);
}


static void test_sceneDefaultsAndOverrides(void) {
  const csScene* fr = cs_sceneFind("flat-road");
  const csScene* ob = cs_sceneFind("obstacle");
  CS_EXPECT(fr && ob && !cs_sceneFind("moon"));
  CS_EXPECT(cs_sceneCount() == 3 && cs_sceneAt(0) == fr && cs_sceneAt(3) == NULL);
  CS_EXPECT(cs_sceneFind("slope") && cs_sceneAt(2) == cs_sceneFind("slope"));
  csConditionsSource src;
  CS_EXPECT(cs_sceneConditions(fr, -1, 0, &src) == CS_CONDITIONS_PAPER &&
            src == CS_CONDITIONS_FROM_SCENE);
  CS_EXPECT(cs_sceneConditions(ob, -1, 0, &src) == CS_CONDITIONS_PAPER);
  CS_EXPECT(cs_sceneConditions(fr, -1, 1, &src) == CS_CONDITIONS_EARTH &&
            src == CS_CONDITIONS_FROM_USER);
  CS_EXPECT(cs_sceneConditions(fr, CS_CONDITIONS_EARTH, 0, &src) == CS_CONDITIONS_EARTH &&
            src == CS_CONDITIONS_FROM_OPTION);
  CS_EXPECT(cs_sceneConditions(fr, CS_CONDITIONS_PAPER, 1, &src) == CS_CONDITIONS_PAPER);
  csConditions c;
  csError err;
  CS_EXPECT(cs_conditionsParse("paper", &c, &err) == CS_OK && c == CS_CONDITIONS_PAPER);
  CS_EXPECT(cs_conditionsParse("earth", &c, &err) == CS_OK && c == CS_CONDITIONS_EARTH);
  CS_EXPECT(cs_conditionsParse("mars", &c, &err) == CS_ERR_ARG);
  CS_EXPECT(strstr(err.msg, "unknown conditions 'mars' (expected earth or paper)") != NULL);
  CS_EXPECT(!strcmp(cs_conditionsName(CS_CONDITIONS_PAPER), "paper") &&
            !strcmp(cs_conditionsName(CS_CONDITIONS_EARTH), "earth"));
  csModel m;
  cs_modelInit(&m);
  CS_EXPECT(m.conditions == CS_CONDITIONS_EARTH && m.opt.legs_weightless == 0);
  cs_modelSetConditions(&m, CS_CONDITIONS_PAPER);
  CS_EXPECT(m.opt.legs_weightless == 1);
  cs_modelSetConditions(&m, CS_CONDITIONS_EARTH);
  CS_EXPECT(m.opt.legs_weightless == 0);
}


/* the terrain's heading turns the robot: the support's +x axis and every hip turn about +y
 * (right-handed, 90 deg: +x -> -z), each leg hangs from its turned hip and the robot settles
 * standing, level */
static void test_headingTurnsTheRobot(void) {
  const char* text = "name turned\nbox -300 -20 -300 300 0 300\nstart 0 0\nheading 90\n";
  FILE* f = fopen("cond_heading.terrain", "wb");
  CS_EXPECT(f != NULL);
  if (!f) return;
  fputs(text, f);
  fclose(f);
  char gait[600], cal[600];
  snprintf(gait, sizeof gait, "%s/gaits/flat_road_paper.csv", g_src);
  csModel m;
  cs_modelInit(&m); /* rod legs: co-simulated, created at the heading (robot_robot.h) */
  missionCalibration(&m, cal, sizeof cal);
  cs_modelSetConditions(&m, CS_CONDITIONS_PAPER);
  csError err;
  cs_errorClear(&err);
  CS_EXPECT(cs_modelLoad(&m, "user", "cond_heading.terrain", gait, cal, &err) == CS_OK);
  csData* d = cs_dataCreate(&m, &err);
  CS_EXPECT(d != NULL);
  if (d) {
    double q[4], R[9], x = 0;
    cs_supportOrientation(d, q);
    csu_quatToMat3(R, q);
    /* the support's x axis (first column) points along -z; exact to round-off (1e-12) */
    CS_EXPECT_NEAR(R[0], 0, 1e-12, 0);
    CS_EXPECT_NEAR(R[6], -1, 1e-12, 0);
    double cl[2 * 3];
    cs_legCenterline(&m, d, 0, 2, cl); /* leg A: hip at (+75, -65) of the centre, turned */
    double c[3];
    double corners[24];
    cs_supportCorners(&m, d, corners);
    for (int k = 0; k < 3; k++) {
      c[k] = 0;
      for (int j = 0; j < 8; j++) c[k] += corners[3 * j + k] / 8;
    }
    CS_EXPECT_NEAR(cl[0] - c[0], -65, 1e-9, 0);
    CS_EXPECT_NEAR(cl[2] - c[2], -75, 1e-9, 0);
    /* the turned robot settles as the straight one does: standing, level (0.3 s) */
    CS_EXPECT(cs_settle(&m, d, &err) == CS_OK);
    cs_supportOrientation(d, q);
    csu_quatToMat3(R, q);
    x = R[4]; /* the support's up axis stays up: cos(tilt) */
    CS_EXPECT(x > 0.9999);
  }
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  remove("cond_heading.terrain");
}


/* ODE's informational messages (universal joints attached before their axes) are not errors */
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
  CS_RUN(test_sceneDefaultsAndOverrides);
  CS_RUN(test_headingTurnsTheRobot);
  CS_RUN(test_legWeightChangesTheSupportLoadByTheLegsWeight);
  dCloseODE();
  return cs_testSummary();
}

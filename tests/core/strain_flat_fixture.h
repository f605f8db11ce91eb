/* strain_flat_fixture.h: the flat road on strain legs as the scene sets it up (tools/cmd_run.c),
 * shared by test_strain_driver and test_strain_adaptive: the model from the source tree's
 * terrain, gait and calibration files under `paper` and rbf-pair, and a settled data. Test-only
 * (static functions in a header, as cs_test.h). */
#ifndef CS_TEST_STRAIN_FLAT_FIXTURE_H
#define CS_TEST_STRAIN_FLAT_FIXTURE_H

#include <stdio.h>
#include <stdlib.h>

#include "cs_test.h"
#include "sim_model.h"

/* The flat road on legs of `type` with `links` bending modes at macro step h (s); adaptive > 0
 * turns the adaptive step on at tolerance step_tol (mm); step_order 1 or 2 the tree step's
 * formula (0: the level's). src is the source tree. 1 on success. */
static int csTestLoadFlatStrainOrder(csModel* m, const char* src, const csrLegType* type,
                                     double h, int links, int adaptive, double step_tol,
                                     int step_order) {
  char terr[600], gait[600], cal[600];
  snprintf(terr, sizeof terr, "%s/terrains/flat_road.terrain", src);
  snprintf(gait, sizeof gait, "%s/gaits/flat_road_rod.csv", src);
  snprintf(cal, sizeof cal, "%s/robot/calibration_fe_leg_modes_sym.h5", src);
  cs_modelInit(m);
  cs_modelSetConditions(m, CS_CONDITIONS_PAPER);
  cs_modelSetLegLevel(m, type);
  m->opt.h = h;
  if (adaptive) {
    m->opt.step_adaptive = 1;
    m->opt.step_tol = step_tol;
  }
  CS_EXPECT(csr_legSettingSet(type, &m->robot.leg_settings, "links", links, NULL) == CS_OK);
  if (step_order) {
    CS_EXPECT(csr_legSettingSet(type, &m->robot.leg_settings, "step_order", step_order, NULL) ==
              CS_OK);
  }
  csrCalRule rule;
  if (csr_calRuleParse("rbf-pair", &rule)) {
    m->cal_rule = (int)rule;
  }
  csError err;
  cs_errorClear(&err);
  if (cs_modelLoad(m, "flat-road", terr, gait, cal, &err) != CS_OK) {
    fprintf(stderr, "load: %s\n", err.msg);
    return 0;
  }
  return 1;
}

static inline int csTestLoadFlatStrain(csModel* m, const char* src, const csrLegType* type,
                                       double h, int links, int adaptive, double step_tol) {
  return csTestLoadFlatStrainOrder(m, src, type, h, links, adaptive, step_tol, 0);
}

/* a data of m, settled (cs_settle); NULL if it cannot be made */
static csData* csTestSettledData(const csModel* m) {
  csError err;
  cs_errorClear(&err);
  csData* d = cs_dataCreate(m, &err);
  CS_EXPECT(d != NULL);
  if (!d) {
    printf("  create: %s\n", err.msg);
    return NULL;
  }
  if (cs_settle(m, d, &err) != CS_OK) {
    printf("  settle: %s\n", err.msg);
    CS_EXPECT(0);
  }
  return d;
}

/* n macro steps of m on d; 1 when every one succeeded (the failing one's error printed) */
static inline int csTestStepN(const csModel* m, csData* d, int n) {
  csError err;
  for (int i = 0; i < n; i++) {
    if (cs_step(m, d, &err) != CS_OK) {
      printf("  step at t = %g s: %s\n", cs_time(d), err.msg);
      return 0;
    }
  }
  return 1;
}

/* a test program's start: the source tree from CS_SOURCE_DIR (default ".") into src[n], the
 * harness's arguments, ODE */
static inline void csTestStrainInit(int argc, char** argv, char* src, size_t n) {
  const char* s = getenv("CS_SOURCE_DIR");
  snprintf(src, n, "%s", s ? s : ".");
  cs_testInit(argc, argv);
  dInitODE2(0);
}

#endif

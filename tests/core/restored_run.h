/* restored_run.h: a run restored from a state file (strain_obstacle_state's text: the count,
 * then one value a line in C's exact hexadecimal form) and stepped on, for the tests that pin a
 * stop of a long run to its last tenths of a second (test_strain_obstacle_stop,
 * test_strain_earth_edge). Header-only: each test includes it once. */
#ifndef CS_TEST_RESTORED_RUN_H
#define CS_TEST_RESTORED_RUN_H

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "crawlsim.h"
#include "cs_test.h"

/* what the restored run did */
typedef struct RestoredRun_ {
  int ran;          /* 1: the file was read, its size matched and the state was set */
  int failed;       /* 1: a step failed (its message printed) */
  double t;         /* s: the time reached */
  double p0[3], p1[3]; /* mm: the support's position at the file's time and at t */
  int forces_finite;   /* the feet's forces at t are finite */
} RestoredRun;

static double* restoredReadState(const char* path, int* n) {
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


/* The run of def restored from the state file at path (its time t0) and stepped to t1; regen
 * is printed when the file's size does not match the model's (how to regenerate it). */
static RestoredRun restoredRun(const csRunDef* def, const char* path, double t0, double t1,
                               const char* regen) {
  RestoredRun r = {0};
  int n = 0;
  double* x = restoredReadState(path, &n);
  CS_EXPECT(x != NULL);
  if (!x) {
    fprintf(stderr, "  cannot read %s\n", path);
    return r;
  }
  csError err;
  csSim* s = cs_simCreate(def, &err);
  CS_EXPECT(s != NULL);
  if (!s) {
    fprintf(stderr, "  %s\n", err.msg);
    free(x);
    return r;
  }
  CS_EXPECT(cs_simStateSize(s) == n);
  if (cs_simStateSize(s) != n) {
    fprintf(stderr, "  the state has %d values, the file %d: regenerate it (%s)\n",
            cs_simStateSize(s), n, regen);
  } else {
    CS_EXPECT(cs_simStateSet(s, x, &err) == CS_OK);
    CS_EXPECT_NEAR(cs_simTime(s), t0, 1e-9, 0); /* the file's time, to the step's round-off */
    double q[4], f[24];
    cs_simSupportPose(s, r.p0, q);
    while (cs_simTime(s) < t1 - 1e-9 && !r.failed) {
      if (cs_simStep(s, &err) != CS_OK) {
        fprintf(stderr, "  %s\n", err.msg);
        r.failed = 1;
      }
    }
    r.t = cs_simTime(s);
    cs_simSupportPose(s, r.p1, q);
    cs_simFootForces(s, f);
    r.forces_finite = 1;
    for (int i = 0; i < 24; i++) {
      r.forces_finite &= isfinite(f[i]);
    }
    r.ran = 1;
  }
  cs_simDestroy(s);
  free(x);
  return r;
}

#endif

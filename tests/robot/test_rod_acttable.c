/* test_rod_acttable.c: the rod's actuation tables (robot_rod_dyn.c actuationAt) against the
 * calibration evaluated directly, on the shipped FE calibration (robot/calibration_fe_leg.h5).
 *
 * Cases:
 *  - two_level_table: pressures with two chamber groups at two levels (one pair venting while
 *    the opposite pair fills, as the pneumatic lag makes them between the gait's rows; and
 *    unequal groups of one and two chambers), 0..0.3 MPa: the two-level table's bend (|Δu0| S,
 *    deg) and stretch against the calibration's own value, at random points, along the
 *    diagonal x = y (where the FE row interpolation by the larger pressure has its kink) and at
 *    grid nodes (exact). Measured 2026-12-02 (1076 points): max 0.0051 deg of bend (a leg
 *    tip 0.013 mm at 150 mm, the rod's position tolerance 0.01 mm), 8.4e-7 of stretch.
 *  - one_level_table: the same for one level (the older one-level table, whose error the
 *    two-level one matches): max 0.0053 deg, 3.9e-7.
 *  - other_pressures_exact: three levels go to the calibration directly (bit-identical).
 *  - dropped_parts_are_left_out: csrRodParams.cal_drop (`crawlsim run --cal-drop`) on the
 *    shipped FE mode table and the pair-mode table: the dropped stretch is exactly 0 and the
 *    dropped stiffness leaves the default section, directly and through the tables, while the
 *    intrinsic curvature stays the same bits; a flag outside CSR_CAL_DROP_* is refused. */
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "robot_calibration.h"
#include "robot_rod_internal.h"

static double rnd01(unsigned* s) {
  *s = *s * 1664525u + 1013904223u;
  return (double)(*s >> 8) / (double)(1u << 24);
}


/* a rod leg model on a shipped calibration table */
typedef struct {
  csrCalibration* cal;
  csrBendMap map;
  csrRodCalibration rodcal; /* a mode table's actuation with its stiffness (else unused) */
  csrActuator act;
  csrRodModel* m;
  csrRodData* d;
} Fixture;


/* the `leg` actuator's rod on robot/<name> with cal_drop `drop`: 0, or 1 when something
 * failed; *refused = 1 when the model refused its parameters */
static int buildRod(Fixture* f, const char* name, unsigned drop, int* refused) {
  memset(f, 0, sizeof *f);
  *refused = 0;
  csError err;
  cs_errorClear(&err);
  char path[1024];
  snprintf(path, sizeof path, "%s/robot/%s", getenv("CS_SOURCE_DIR"), name);
  csr_actuatorPreset(&f->act, "leg", &err);
  f->cal = csr_calibrationOpen(path, &f->act, &err);
  if (!f->cal) {
    printf("  %s\n", err.msg);
    return 1;
  }
  f->map = csr_calibrationMap(f->cal);
  csrRodParams par = csr_rodDefaultParams(&f->act);
  par.cal_drop = drop;
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.act = &f->act;
  sp.params = &par;
  sp.map = &f->map;
  if (csr_calibrationRod(f->cal, &f->rodcal)) {
    sp.calib = &f->rodcal; /* a mode table: as the rod leg level does (robot_rod_leg.c) */
  }
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(sp.frame, F, sizeof F);
  f->m = csr_rodModelCreate(&sp, &err);
  *refused = f->m == NULL;
  f->d = f->m ? csr_rodDataCreate(f->m, &err) : NULL;
  if (f->m && !f->d) {
    printf("  %s\n", err.msg);
    return 1;
  }
  return 0;
}


/* the pair-mode table's rod */
static int setup(Fixture* f) {
  int refused;
  return buildRod(f, "calibration_fe_leg.h5", 0, &refused) != 0 || refused;
}


static void teardown(Fixture* f) {
  csr_rodDataDestroy(f->d);
  csr_rodModelDestroy(f->m);
  csr_calibrationClose(f->cal);
}


/* the table's actuation of segment s at p4 (through csr_rodActuate) against the direct one:
 * bend error (deg) and stretch error; *bits: 1 when both agree bit for bit */
static void compare(Fixture* f, int s, const double p4[4], double* dbend, double* dstretch,
                    int* bits) {
  double p[12] = {0};
  memcpy(p + 4 * s, p4, 4 * sizeof(double));
  CS_EXPECT(csr_rodActuate(f->m, f->d, 0, p, 1, p) == 0);
  const csrRodSegmentActuation* a = &f->d->act.a[s];
  csrRodSegmentActuation ref;
  CS_EXPECT(csr_rodActuationEval_(f->m, s, p4, &ref, NULL, 0) == 0);
  double du[3];
  for (int k = 0; k < 3; k++) {
    du[k] = a->u0[k] - ref.u0[k];
  }
  *dbend = csu_norm3(du) * f->m->seg_len[s] * 180 / CS_PI;
  *dstretch = fabs(a->sigma0[2] - ref.sigma0[2]);
  *bits = memcmp(a->u0, ref.u0, sizeof ref.u0) == 0 &&
          memcmp(a->sigma0, ref.sigma0, sizeof ref.sigma0) == 0;
}


static void two_level_table(void) {
  Fixture f;
  if (setup(&f) != 0) {
    CS_EXPECT(0);
    return;
  }
  /* group A, group B (bit j: chamber j + 1) */
  const int groups[3][2] = {{0x3, 0xC}, {0x1, 0x6}, {0x5, 0xA}};
  unsigned seed = 7u;
  double worst_b = 0, worst_s = 0;
  int n = 0, grid_exact = 1;
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int g = 0; g < 3; g++) {
      for (int k = 0; k < 120; k++) {
        double x = 0.29 * rnd01(&seed), y = 0.29 * rnd01(&seed);
        if (k % 4 == 0) {
          y = x + 1e-3 * (rnd01(&seed) - 0.5); /* near the diagonal */
        }
        if (k % 10 == 1) {
          /* a grid node: exact */
          x = 5e-3 * (int)(x / 5e-3 + 0.5);
          y = 5e-3 * (int)(y / 5e-3 + 0.5) + 5e-3;
        }
        if (fabs(x - y) < 2e-7 || x < 1e-6 || y < 1e-6) {
          continue; /* one level, not this table */
        }
        double p4[4];
        for (int c = 0; c < 4; c++) {
          p4[c] = (groups[g][0] >> c & 1) ? x : ((groups[g][1] >> c & 1) ? y : 0);
        }
        double db, ds;
        int bits;
        compare(&f, s, p4, &db, &ds, &bits);
        worst_b = fmax(worst_b, db);
        worst_s = fmax(worst_s, ds);
        if (k % 10 == 1) {
          grid_exact &= db < 1e-12 && ds < 1e-14;
        }
        n++;
      }
    }
  }
  printf("  %d two-level points: max bend error %.2g deg, stretch %.2g; grid nodes exact: %d\n",
         n, worst_b, worst_s, grid_exact);
  CS_EXPECT(n > 800);
  CS_EXPECT(grid_exact);
  /* the one-level table's class of approximation (below); the bound has 2x margin */
  CS_EXPECT(worst_b < 1e-2);
  CS_EXPECT(worst_s < 2e-6);
  teardown(&f);
}


static void one_level_table(void) {
  Fixture f;
  if (setup(&f) != 0) {
    CS_EXPECT(0);
    return;
  }
  unsigned seed = 11u;
  double worst_b = 0, worst_s = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int k = 0; k < 100; k++) {
      double x = 0.29 * rnd01(&seed);
      const double p4[4] = {x, x, 0, 0};
      double db, ds;
      int bits;
      compare(&f, s, p4, &db, &ds, &bits);
      worst_b = fmax(worst_b, db);
      worst_s = fmax(worst_s, ds);
    }
  }
  printf("  one level: max bend error %.2g deg, stretch %.2g\n", worst_b, worst_s);
  CS_EXPECT(worst_b < 1e-2);
  CS_EXPECT(worst_s < 2e-6);
  teardown(&f);
}


static void other_pressures_exact(void) {
  Fixture f;
  if (setup(&f) != 0) {
    CS_EXPECT(0);
    return;
  }
  const double p4[4] = {0.11, 0.07, 0.23, 0};
  double db, ds;
  int bits;
  compare(&f, 1, p4, &db, &ds, &bits);
  CS_EXPECT(bits);
  teardown(&f);
}


static void dropped_parts_are_left_out(void) {
  const char* tables[2] = {"calibration_fe_leg_modes.h5", "calibration_fe_leg.h5"};
  const unsigned drops[3] = {CSR_CAL_DROP_STRETCH, CSR_CAL_DROP_STIFFNESS,
                             CSR_CAL_DROP_STRETCH | CSR_CAL_DROP_STIFFNESS};
  /* Ω1&Ω2 above Ω3 (an unequal pattern: stretch and bend both non-zero) */
  const double p4[4] = {0.2, 0.2, 0.05, 0};
  for (int t = 0; t < 2; t++) {
    Fixture full;
    int refused = 0;
    if (buildRod(&full, tables[t], 0, &refused) != 0 || refused) {
      CS_EXPECT(0);
      teardown(&full);
      continue;
    }
    for (int k = 0; k < 3; k++) {
      Fixture r;
      if (buildRod(&r, tables[t], drops[k], &refused) != 0 || refused) {
        CS_EXPECT(0);
        teardown(&r);
        continue;
      }
      for (int s = 0; s < CSR_NSEG; s++) {
        csrRodSegmentActuation a0, a1;
        CS_EXPECT(csr_rodActuationEval_(full.m, s, p4, &a0, NULL, 0) == 0);
        CS_EXPECT(csr_rodActuationEval_(r.m, s, p4, &a1, NULL, 0) == 0);
        CS_EXPECT(memcmp(a0.u0, a1.u0, sizeof a0.u0) == 0);
        /* the calibration has a stretch here, and a mode table a section */
        CS_EXPECT(fabs(a0.sigma0[2]) > 1e-3);
        CS_EXPECT(a0.has_section == (t == 0));
        if (drops[k] & CSR_CAL_DROP_STRETCH) {
          CS_EXPECT(a1.sigma0[2] == 0);
        } else {
          CS_EXPECT(a1.sigma0[2] == a0.sigma0[2]);
        }
        CS_EXPECT(a1.has_section == ((drops[k] & CSR_CAL_DROP_STIFFNESS) ? 0 : a0.has_section));
        /* through the rod's tables (what a run uses) */
        double p[12] = {0};
        memcpy(p + 4 * s, p4, sizeof p4);
        CS_EXPECT(csr_rodActuate(r.m, r.d, 0, p, 1, p) == 0);
        const csrRodSegmentActuation* at = &r.d->act.a[s];
        CS_EXPECT(((drops[k] & CSR_CAL_DROP_STRETCH) ? at->sigma0[2] == 0
                                                      : fabs(at->sigma0[2]) > 1e-3));
        CS_EXPECT(at->has_section == a1.has_section);
      }
      teardown(&r);
    }
    teardown(&full);
  }
  /* a flag the rod does not know is refused when the model is built */
  Fixture bad;
  int refused = 0;
  (void)buildRod(&bad, tables[0], 4u, &refused);
  CS_EXPECT(refused);
  teardown(&bad);
  /* the user's words (crawlsim run --cal-drop) and back */
  unsigned d = 99;
  char buf[32];
  CS_EXPECT(csr_calDropParse("stretch", &d) && d == CSR_CAL_DROP_STRETCH);
  CS_EXPECT(csr_calDropParse("stiffness,stretch", &d) &&
            d == (CSR_CAL_DROP_STRETCH | CSR_CAL_DROP_STIFFNESS));
  csr_calDropFormat(d, buf, sizeof buf);
  CS_EXPECT(!strcmp(buf, "stretch,stiffness"));
  CS_EXPECT(csr_calDropParse("none", &d) && d == 0);
  csr_calDropFormat(0, buf, sizeof buf);
  CS_EXPECT(!strcmp(buf, "none"));
  d = 7;
  const char* bad_words[6] = {"", "stretch,", ",stretch", "stretch,stretch", "Stretch", "ei"};
  for (int k = 0; k < 6; k++) {
    CS_EXPECT(!csr_calDropParse(bad_words[k], &d) && d == 7);
  }
  CS_EXPECT(!csr_calDropParse(NULL, &d));
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(two_level_table);
  CS_RUN(one_level_table);
  CS_RUN(other_pressures_exact);
  CS_RUN(dropped_parts_are_left_out);
  return cs_testSummary();
}

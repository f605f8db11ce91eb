/* test_calibration_rbf.c: the opt-in rules CSR_CAL_RULE_RBF (superposition + the modes'
 * differences interpolated by a Gaussian RBF over their symmetric images,
 * robot_calibration_rbf.c) and CSR_CAL_RULE_RBF_PAIR (the same over the superposition with a
 * fitted factor per opposite chamber pair, robot_calibration_pair.c) on the shipped FE mode
 * table (robot/calibration_fe_leg_modes.h5; the synthetic tables' checks of every rule are in
 * test_calibration_model.c), each test for both rules:
 *  - rbf_returns_fitted_rows: every fitted row (its symmetric part) to round-off;
 *  - rbf_symmetry: zero-moment patterns bend by exactly 0, turned or mirrored patterns turn or
 *    mirror the bend (random patterns);
 *  - rbf_holdout_and_left_out: the held-out cases' errors and the refining modes left out one
 *    at a time stay within the values measured on 2026-12-03 (docs/bench/
 *    calib_rules_2026-12-03), which beat the default rule's on the same table;
 * and on the full table (robot/calibration_fe_leg_modes_full.h5, 19 modes) under RBF_PAIR:
 *  - full_pair_returns_fitted_rows, full_pair_symmetry: as above, every mode a node;
 *  - full_pair_holdout_and_left_out: every held-out case meets the target up to the pressures
 *    measured on 2026-12-03 (H4 to 0.35 MPa, the others throughout; README "Calibration");
 *  - full_images_found: each symmetry case (O2, H4t, H6t, H7t) finds the case it is the image
 *    of and prints the FE's difference from it;
 * and on the symmetric-mesh table (robot/calibration_fe_leg_modes_sym.h5, 23 modes) under
 * RBF_PAIR the same three, and every held-out case (H1-H12) within the target over
 * 0-0.4 MPa;
 *  - field_tabulated_matches_definition: the field tabulated per pressure interval (what the
 *    model evaluates, robot_calibration_rbf.c "Tabulated") against its definition by the
 *    cardinal weights, on random patterns of all three tables and both rules, at the rows and
 *    between them: round-off (the largest difference is printed). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "robot_calibration.h"
#include "robot_calibration_internal.h"

/* the shipped table and the RBF model of it (NULL when it is not a mode table) */
typedef struct {
  csrCalTable table;
  csrCalModel* model;
  csrActuator leg;
} Shipped;

/* the shipped mode tables: the scenes' (9 modes) and the full one (every mode of the prism's
 * levels, 19) */
static const char* const kShipped = "calibration_fe_leg_modes.h5";
static const char* const kFull = "calibration_fe_leg_modes_full.h5";
/* the table on the mesh with the section's eight symmetries, 23 modes (2026-12-03) */
static const char* const kSym = "calibration_fe_leg_modes_sym.h5";

static int openTable(Shipped* s, const char* file, csrCalRule rule, unsigned exclude) {
  char path[1024];
  csError err;
  memset(s, 0, sizeof *s);
  snprintf(path, sizeof path, "%s/robot/%s", getenv("CS_SOURCE_DIR"), file);
  if (!csr_calTableIsModeTable(path)) {
    printf("  %s is not a mode table: nothing to check\n", path);
    return 0;
  }
  CS_EXPECT(csr_actuatorPreset(&s->leg, "leg", &err) == CS_OK);
  CS_EXPECT(csr_calTableRead(path, &s->leg, &s->table, &err) == CS_OK);
  csrCalOptions o = csr_calModelDefaultOptions();
  o.rule = rule;
  o.exclude = exclude;
  s->model = csr_calModelCreate(&s->table, &s->leg, &o, &err);
  CS_EXPECT(s->model != NULL);
  if (!s->model) {
    fprintf(stderr, "  %s\n", err.msg);
    csr_calTableFree(&s->table);
  }
  return s->model != NULL;
}

static void closeShipped(Shipped* s) {
  csr_calModelDestroy(s->model);
  csr_calTableFree(&s->table);
}


static void returnsFittedRows(const char* file, csrCalRule rule) {
  Shipped sh;
  if (!openTable(&sh, file, rule, 0)) {
    return;
  }
  int nmode = 0;
  for (int i = 0; i < sh.table.ncase; i++) {
    const csrCalCase* c = sh.table.cases + i;
    if (c->kind != CSR_CAL_MODE) {
      continue;
    }
    nmode++;
    const double* r = c->ratio;
    const double mv[2] = {r[0] + r[1] - r[2] - r[3], r[0] - r[1] - r[2] + r[3]};
    const double mn = hypot(mv[0], mv[1]);
    const int sym = (r[0] == r[1] && r[2] == r[3]) || r[1] == r[3] || r[0] == r[2];
    for (int row = 0; row < c->m; row++) {
      const double p = c->pressure[row];
      const double P[4] = {r[0] * p, r[1] * p, r[2] * p, r[3] * p};
      for (int s = 0; s < 3; s++) {
        csrCalSegment q;
        CS_EXPECT(csr_calModelEval(sh.model, s, P, &q) == 0);
        double want[2] = {c->bend[6 * row + 2 * s] - c->bend[2 * s],
                          c->bend[6 * row + 2 * s + 1] - c->bend[2 * s + 1]};
        if (mn == 0) {
          want[0] = want[1] = 0;
        } else if (sym) {
          const double along = (want[0] * mv[0] + want[1] * mv[1]) / mn;
          want[0] = along * mv[0] / mn, want[1] = along * mv[1] / mn;
        }
        /* round-off: the cardinal weights are unit vectors at the nodes to ~cond * eps
         * (condition 16) times residuals of up to 0.5 rad, and base + residual */
        CS_EXPECT_NEAR(q.bend[0], want[0], 1e-12, 0);
        CS_EXPECT_NEAR(q.bend[1], want[1], 1e-12, 0);
        CS_EXPECT_NEAR(q.stretch - 1, c->stretch[3 * row + s] - c->stretch[s], 1e-13, 0);
      }
    }
  }
  CS_EXPECT(nmode >= 9);
  closeShipped(&sh);
}


static void symmetry(const char* file, csrCalRule rule) {
  Shipped sh;
  if (!openTable(&sh, file, rule, 0)) {
    return;
  }
  unsigned seed = 7;
  for (int k = 0; k < 300; k++) {
    double p[4], t[4], d[4];
    for (int j = 0; j < 4; j++) {
      seed = seed * 1664525u + 1013904223u;
      p[j] = 0.4 * (double)(seed >> 8) / 16777216.0;
    }
    for (int j = 0; j < 4; j++) t[j] = p[(j + 1) % 4];
    d[0] = p[0], d[1] = p[3], d[2] = p[2], d[3] = p[1];
    const int s = k % 3;
    csrCalSegment q0, qt, qd, qz;
    CS_EXPECT(csr_calModelEval(sh.model, s, p, &q0) == 0);
    CS_EXPECT(csr_calModelEval(sh.model, s, t, &qt) == 0);
    CS_EXPECT(csr_calModelEval(sh.model, s, d, &qd) == 0);
    /* bend(R p) = Rot(+90) bend(p), bend(D p) = D bend(p): the same interpolant evaluated at
     * another canonical point, round-off of sums of ~35 terms of up to 0.5 rad */
    CS_EXPECT_NEAR(qt.bend[0], -q0.bend[1], 1e-13, 0);
    CS_EXPECT_NEAR(qt.bend[1], q0.bend[0], 1e-13, 0);
    CS_EXPECT_NEAR(qd.bend[0], q0.bend[1], 1e-13, 0);
    CS_EXPECT_NEAR(qd.bend[1], q0.bend[0], 1e-13, 0);
    CS_EXPECT_NEAR(qt.stretch, q0.stretch, 1e-14, 0);
    /* zero pressure moment (p1 = p3, p2 = p4): exactly no bend */
    const double z[4] = {p[0], p[1], p[0], p[1]};
    CS_EXPECT(csr_calModelEval(sh.model, s, z, &qz) == 0);
    CS_EXPECT(qz.bend[0] == 0 && qz.bend[1] == 0);
  }
  closeShipped(&sh);
}


/* measured on the shipped table (18 cases) on 2026-12-03, `crawlsim calibrate --report` and
 * tools/calib_rules.py (the default rule: held out 7.87 deg / 35.3 mm, H4-H6 meet to 0.25 MPa;
 * left out 7.63 deg / 27.5 mm) */
typedef struct {
  double held_tip_mm;  /* worst held-out tip error */
  double meets[8];     /* MPa: H1..H8 meet the target up to here (their last row: throughout) */
  double loo_tip_mm;   /* worst left-out refining mode's tip error */
  double loo_bend_deg; /* and bend error */
  int nloo;            /* refining modes in the table */
} Measured;
/* RBF: H7 at 0.4 MPa 22.78 mm, meets to 0.225 MPa, H1-H6 throughout; left out O1O234r05
 * 11.67 mm, O12r05 4.03 deg */
static const Measured kRbf = {22.78, {0.3, 0.2, 0.35, 0.4, 0.4, 0.4, 0.225, 0.4}, 11.67, 4.04, 4};
/* RBF_PAIR: H6 at 0.4 MPa 4.86 mm (H7 4.36, H4 4.54); H4 meets to 0.3, H6 to 0.375, H7 to
 * 0.25 MPa, the others throughout; left out O12r05 6.57 mm, 3.27 deg */
static const Measured kPair = {4.862, {0.3, 0.2, 0.35, 0.3, 0.4, 0.375, 0.25, 0.4}, 6.566, 3.273,
                               4};
/* RBF_PAIR on the full table (robot/calibration_fe_leg_modes_full.h5, 19 modes, 2026-12-03):
 * H4 at 0.4 MPa 3.63 mm, meets to 0.35 MPa, the others throughout; left out
 * O13O2r067O4r033 8.11 mm, O124O3r05 1.84 deg */
static const Measured kPairFull = {3.632, {0.3, 0.2, 0.35, 0.35, 0.4, 0.4, 0.4, 0.4}, 8.106,
                                   1.835, 14};
/* RBF_PAIR on the symmetric-mesh table (robot/calibration_fe_leg_modes_sym.h5, 23 modes,
 * 2026-12-03): every held-out case throughout (worst H11 2.126 mm); left out O13O2r067O4r033
 * 7.370 mm, O1O3r05 1.770 deg */
static const Measured kPairSym = {2.126, {0.3, 0.2, 0.35, 0.4, 0.4, 0.4, 0.4, 0.4}, 7.370,
                                  1.770, 18};
/* the bounds: the measured values + 0.5 % (the model is deterministic; the margin takes
 * libm's last bits and the pair factor's fit, converged to 1e-14 of its cost) */
#define RBF_MARGIN 1.005

static void holdoutAndLeftOut(const char* file, csrCalRule rule, const Measured* want) {
  Shipped sh;
  if (!openTable(&sh, file, rule, 0)) {
    return;
  }
  csError err;
  double worst_tip = 0;
  for (int i = 0; i < sh.table.ncase; i++) {
    const csrCalCase* c = sh.table.cases + i;
    csrCalCompare e;
    if (c->kind != CSR_CAL_HOLDOUT) {
      continue;
    }
    CS_EXPECT(csr_calModelCompare(sh.model, c, &e, &err) == CS_OK);
    printf("  %s: bend %.3f deg (score %.2f), tip %.3f mm (score %.2f), meets to %.3g of %.3g "
           "MPa\n", c->name, e.bend_deg, e.bend_score, e.tip_mm, e.tip_score, e.p_meets,
           e.p_last);
    worst_tip = fmax(worst_tip, e.tip_mm);
    const int h = c->name[0] == 'H' ? atoi(c->name + 1) : 0;
    if (h >= 1 && h <= 8) {
      CS_EXPECT(e.p_meets >= want->meets[h - 1] - 1e-12);
    }
  }
  CS_EXPECT(worst_tip <= want->held_tip_mm * RBF_MARGIN);
  /* the refining modes of the table, each predicted by the model built without it */
  int nloo = 0;
  for (int role = CSR_CAL_O12R05; role < CSR_CAL_NROLE; role++) {
    double ratio[4];
    const char* name;
    csr_calModelModePattern((csrCalRole)role, ratio, &name);
    if (!csr_calTableFind(&sh.table, CSR_CAL_MODE, ratio)) {
      continue;
    }
    nloo++;
    Shipped lo;
    if (!openTable(&lo, file, rule, 1u << role)) {
      return;
    }
    const csrCalCase* c = csr_calTableFind(&lo.table, CSR_CAL_MODE, ratio);
    csrCalCompare e;
    CS_EXPECT(c != NULL && !csr_calModelUses(lo.model, (csrCalRole)role));
    if (c && csr_calModelCompare(lo.model, c, &e, &err) == CS_OK) {
      printf("  left out %s: bend %.3f deg, tip %.3f mm\n", name, e.bend_deg, e.tip_mm);
      CS_EXPECT(e.bend_deg <= want->loo_bend_deg * RBF_MARGIN);
      CS_EXPECT(e.tip_mm <= want->loo_tip_mm * RBF_MARGIN);
    }
    closeShipped(&lo);
  }
  CS_EXPECT(nloo >= want->nloo);
  closeShipped(&sh);
}


static void test_rbf_returns_fitted_rows(void) { returnsFittedRows(kShipped, CSR_CAL_RULE_RBF); }
static void test_rbf_symmetry(void) { symmetry(kShipped, CSR_CAL_RULE_RBF); }
static void test_rbf_holdout_and_left_out(void) {
  holdoutAndLeftOut(kShipped, CSR_CAL_RULE_RBF, &kRbf);
}
static void test_pair_returns_fitted_rows(void) {
  returnsFittedRows(kShipped, CSR_CAL_RULE_RBF_PAIR);
}
static void test_pair_symmetry(void) { symmetry(kShipped, CSR_CAL_RULE_RBF_PAIR); }
static void test_pair_holdout_and_left_out(void) {
  holdoutAndLeftOut(kShipped, CSR_CAL_RULE_RBF_PAIR, &kPair);
}
/* the full table: all 19 modes are nodes, returned; equivariant; its held-out cases */
static void test_full_pair_returns_fitted_rows(void) {
  returnsFittedRows(kFull, CSR_CAL_RULE_RBF_PAIR);
}
static void test_full_pair_symmetry(void) { symmetry(kFull, CSR_CAL_RULE_RBF_PAIR); }
static void test_full_pair_holdout_and_left_out(void) {
  holdoutAndLeftOut(kFull, CSR_CAL_RULE_RBF_PAIR, &kPairFull);
}

/* the symmetric-mesh table: every mode returned, equivariant, and every held-out case (H1-H12)
 * within the target over its whole sweep (README "Calibration") */
static void test_sym_pair_returns_fitted_rows(void) {
  returnsFittedRows(kSym, CSR_CAL_RULE_RBF_PAIR);
}
static void test_sym_pair_symmetry(void) { symmetry(kSym, CSR_CAL_RULE_RBF_PAIR); }
static void test_sym_pair_holdout_and_left_out(void) {
  holdoutAndLeftOut(kSym, CSR_CAL_RULE_RBF_PAIR, &kPairSym);
}
static void test_sym_pair_every_holdout_meets_the_target(void) {
  Shipped sh;
  if (!openTable(&sh, kSym, CSR_CAL_RULE_RBF_PAIR, 0)) {
    return;
  }
  int n = 0;
  for (int i = 0; i < sh.table.ncase; i++) {
    const csrCalCase* c = sh.table.cases + i;
    csrCalCompare e;
    csError err;
    if (c->kind != CSR_CAL_HOLDOUT) {
      continue;
    }
    CS_EXPECT(csr_calModelCompare(sh.model, c, &e, &err) == CS_OK);
    /* bend within 5 % or 1 deg and tip within 2 % of the leg at every row to the last */
    CS_EXPECT(e.bend_score <= 1 && e.tip_score <= 1 && e.p_meets >= e.p_last);
    n++;
  }
  CS_EXPECT(n == 12); /* H1-H12 */
  closeShipped(&sh);
}


/* every symmetry case of the full table finds the case it is the image of, and the FE's
 * difference from it (its mesh asymmetry) is printed: the resolution of the reference */
static void test_full_images_found(void) {
  Shipped sh;
  if (!openTable(&sh, kFull, CSR_CAL_RULE_RBF_PAIR, 0)) {
    return;
  }
  const char* pairs[4][2] = {{"O2", "O1"}, {"H4t", "H4"}, {"H6t", "H6"}, {"H7t", "H7"}};
  for (int k = 0; k < 4; k++) {
    const csrCalCase* c = NULL;
    for (int i = 0; i < sh.table.ncase; i++) {
      if (!strcmp(sh.table.cases[i].name, pairs[k][0])) {
        c = sh.table.cases + i;
      }
    }
    CS_EXPECT(c != NULL);
    csrCalSymPair pr;
    csError err;
    if (!c || csr_calSymmetryPair(&sh.table, c, &pr, &err) != CS_OK) {
      CS_EXPECT(0);
      continue;
    }
    CS_EXPECT(pr.partner != NULL && !strcmp(pr.partner->name, pairs[k][1]));
    CS_EXPECT(pr.rows == c->m);
    printf("  %s against its image %s: bend %.3f deg, tip %.3f mm\n", c->name,
           pr.partner ? pr.partner->name : "?", pr.bend_deg, pr.tip_mm);
  }
  closeShipped(&sh);
}


/* the tabulated field against the definition: the largest difference over random canonical
 * patterns (P from 0 to past the range, the rows themselves included) */
static double tabulatedError(const char* file, csrCalRule rule) {
  Shipped sh;
  if (!openTable(&sh, file, rule, 0)) {
    return 0;
  }
  const csrCalModel* m = sh.model;
  CS_EXPECT(m->rbf_nb >= 2); /* the shipped tables are tabulated */
  double err = 0, size = 0;
  unsigned seed = 11;
  for (int k = 0; k < 600; k++) {
    double p[4];
    for (int j = 0; j < 4; j++) {
      seed = seed * 1664525u + 1013904223u;
      p[j] = (double)(seed >> 8) / 16777216.0;
    }
    /* canonical: the highest first, p[1] >= p[3]; P on a row every third pattern */
    double P = 1.05 * m->p_max * p[0];
    if (k % 3 == 0) {
      P = m->rbf_B[k % m->rbf_nb];
    }
    if (!(P > 0)) {
      continue;
    }
    const double pc[4] = {P, P * fmax(p[1], p[3]), P * p[2], P * fmin(p[1], p[3])};
    const int s = k % 3;
    double b0[2], s0[3], b1[2], s1[3];
    csr_calRbfFieldDirect_(m, s, pc, b0, s0);
    csr_calRbfField_(m, s, pc, b1, s1);
    for (int c = 0; c < 2; c++) {
      err = fmax(err, fabs(b1[c] - b0[c]));
      size = fmax(size, fabs(b0[c]));
    }
    for (int c = 0; c < 3; c++) {
      err = fmax(err, fabs(s1[c] - s0[c]));
      size = fmax(size, fabs(s0[c]));
    }
  }
  printf("  %s, rule %d (%d images, %d pressure breakpoints): largest |tabulated - "
         "definition| %.3g (largest value %.3g)\n", file, (int)rule, m->rbf_n, m->rbf_nb, err,
         size);
  /* the same sums in another order (~200 terms of up to ~0.5 rad) and cubics re-expanded in
   * powers of the interval's local pressure: round-off, far below the calibration's own
   * error (degrees) */
  CS_EXPECT(err <= 1e-12 * fmax(size, 1.0));
  CS_EXPECT(size > 0); /* the comparison saw the field */
  closeShipped(&sh);
  return err;
}


static void test_field_tabulated_matches_definition(void) {
  tabulatedError(kShipped, CSR_CAL_RULE_RBF);
  tabulatedError(kShipped, CSR_CAL_RULE_RBF_PAIR);
  tabulatedError(kFull, CSR_CAL_RULE_RBF_PAIR);
  tabulatedError(kSym, CSR_CAL_RULE_RBF_PAIR);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_rbf_returns_fitted_rows);
  CS_RUN(test_rbf_symmetry);
  CS_RUN(test_rbf_holdout_and_left_out);
  CS_RUN(test_pair_returns_fitted_rows);
  CS_RUN(test_pair_symmetry);
  CS_RUN(test_pair_holdout_and_left_out);
  CS_RUN(test_full_pair_returns_fitted_rows);
  CS_RUN(test_full_pair_symmetry);
  CS_RUN(test_full_pair_holdout_and_left_out);
  CS_RUN(test_full_images_found);
  CS_RUN(test_sym_pair_returns_fitted_rows);
  CS_RUN(test_sym_pair_symmetry);
  CS_RUN(test_sym_pair_holdout_and_left_out);
  CS_RUN(test_sym_pair_every_holdout_meets_the_target);
  CS_RUN(test_field_tabulated_matches_definition);
  return cs_testSummary();
}

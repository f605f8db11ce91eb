/* test_calibration_model.c: the calibration model of an FE mode table
 * (robot_calibration_model.h), on synthetic tables whose truth is known
 * (test_calibration_synth.h) and, when it is a mode table, on the shipped table:
 *  - superposition_truth_reproduced_everywhere: a truth that IS the superposition of a
 *    single-chamber response linear in p is returned to round-off at any pressures, any
 *    rotation or mirror of the chamber pattern (checks the canonical form and its inverse);
 *  - bends_past_half_turn: bends beyond 180 deg, which the FE writes as the rotation the other
 *    way, are continued by the reader and returned (up to 6.8 rad per segment);
 *  - fitted_rows_returned: the three rules (superposition, interpolation, the opt-in
 *    superposition + RBF; also in the next four tests) return every fitted mode's rows (nonlinear truth with
 *    interactions) to round-off; with a spurious FE bend the mirror-symmetric modes return
 *    their symmetric part (the component across the symmetry line removed, exactly);
 *  - elongation_gives_no_bend: equal pressures and Ω1&Ω3-type patterns bend by exactly 0 although
 *    the table's O1234 and O13 rows bend (mesh asymmetry);
 *  - symmetry_equivariance: turning or mirroring the pattern turns or mirrors the bend and keeps
 *    the scalars (random patterns, 1e-12); the O2 symmetry case is Ω1 turned;
 *  - continuity_across_ties: where the canonical form switches (two chambers highest, Ω2 = Ω4)
 *    the model is continuous;
 *  - holdout_on_nonlinear_truths: the held-out cases H1-H3 of two nonlinear truths (closed form
 *    with interactions; the analytic Yeoh model at 2.5x pressure) are predicted within the
 *    measured bounds below, and within the target;
 *    (the RBF rule on the shipped table: test_calibration_rbf.c)
 *  - range_and_bad_pressures: above the range CSR_MAP_OUT_OF_RANGE, round-off negatives are 0,
 *    real negatives and NaN recoverable;
 *  - stiffness_mean_pressure_rule: EI, EA linear in the mean pressure are returned exactly,
 *    failed (NaN) probes are skipped, above the probes refused, no probes -> none;
 *  - rod_adapter: the rod's csrRodCalibration of a mode table (also found from its bend map)
 *    gives the map's curvature and stretch and the probed section;
 *  - shipped_table_holdout: the shipped mode table (robot/calibration_fe_leg_modes.h5): its
 *    own FE rows returned, no bend for elongation, and its held-out cases
 *    meet the target (5 % of the bend or 1 deg; 2 % of the leg length in tip position, against
 *    the FE's symmetric part for a mirror-symmetric pattern) up to P_VALIDATED, and its
 *    symmetry case is predicted by the turned Ω1 mode.
 *  - compare_symmetric_part: the FE's bend across a pattern's mirror line (mesh asymmetry) is
 *    removed exactly from the symmetric-part tip; the range a case validates ends at its first
 *    row that misses.
 *  - symmetry_pair_carries_the_image: each symmetry case finds its image (O2 -> O1, H4t -> H4,
 *    H6t -> H6, H7t -> H7) and on an equivariant truth matches it to round-off (the turn and
 *    mirror carry bends and tip right); a spurious bend of fixed direction a p (not
 *    equivariant) shows as |a - R a| p = sqrt 2 |a| p between 90-deg images; a tip offset on
 *    one image is halved against the symmetrised FE. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "robot_analytic.h"
#include "robot_calibration.h"
#include "test_calibration_synth.h"

#define RSQ2 0.70710678118654752440

/* ---- truths ---------------------------------------------------------------------------------- */

/* -Σ_j θ(p_j) ĉ_j with θ = k p + q p^2 (ĉ_j the unit diagonal of chamber j) */
static void superpose(const double p[4], double k, double q, double bend[2]) {
  double t[4];
  for (int j = 0; j < 4; j++) t[j] = k * p[j] + q * p[j] * p[j];
  const double g1 = t[0] - t[2], g2 = t[1] - t[3];
  bend[0] = -RSQ2 * (g1 + g2);
  bend[1] = -RSQ2 * (g1 - g2);
}


/* linear single-chamber response, exact superposition: what the superposition rule reproduces
 * everywhere (a monotone cubic reproduces a linear function exactly) */
static void truthLinear(const void* ctx, int seg, const double p[4], double bend[2],
                        double* stretch, double* radial, double* radmax) {
  (void)ctx;
  superpose(p, 1.2 + 0.1 * seg, 0, bend);
  const double sum = p[0] + p[1] + p[2] + p[3];
  *stretch = 1 + 0.02 * sum;
  *radial = 0.004 * sum;
  *radmax = 0.3 * sum;
}


/* truthLinear at 8x the bend: Ω1 alone reaches 4.8 rad at 0.5 MPa, Ω1&Ω2 6.8 rad (past a full
 * turn) */
static void truthBig(const void* ctx, int seg, const double p[4], double bend[2],
                     double* stretch, double* radial, double* radmax) {
  truthLinear(ctx, seg, p, bend, stretch, radial, radmax);
  bend[0] *= 8, bend[1] *= 8;
}


/* nonlinear with interactions, symmetric under the section's group: the single-chamber bend
 * quadratic in p, modulated by the mean pressure and the moment's size; stretch and growth
 * with products of adjacent and of diagonal chambers */
static void truthInteract(const void* ctx, int seg, const double p[4], double bend[2],
                          double* stretch, double* radial, double* radmax) {
  (void)ctx;
  superpose(p, 1.0 + 0.1 * seg, 3.0, bend);
  const double pbar = 0.25 * (p[0] + p[1] + p[2] + p[3]);
  const double m1 = p[0] + p[1] - p[2] - p[3], m2 = p[0] - p[1] - p[2] + p[3];
  const double f = 1 - 0.8 * pbar + 0.3 * hypot(m1, m2);
  bend[0] *= f, bend[1] *= f;
  const double sum = p[0] + p[1] + p[2] + p[3];
  const double sq = p[0] * p[0] + p[1] * p[1] + p[2] * p[2] + p[3] * p[3];
  const double adj = p[0] * p[1] + p[1] * p[2] + p[2] * p[3] + p[3] * p[0];
  const double dia = p[0] * p[2] + p[1] * p[3];
  *stretch = 1 + 0.02 * sum + 0.05 * sq - 0.03 * adj + 0.02 * dia;
  *radial = 0.004 * sum + 0.01 * sq + 0.002 * adj;
  *radmax = 0.3 * sum + 0.4 * sq - 0.1 * dia;
}


/* the analytic constant-curvature Yeoh model (robot_analytic.h) of the leg at 2.5x the
 * pressure: large (up to ~2 rad per segment) and nonlinear bends, a physical interaction */
static void truthAnalytic(const void* ctx, int seg, const double p[4], double bend[2],
                          double* stretch, double* radial, double* radmax) {
  const csrActuator* act = ctx;
  const double q[4] = {2.5 * p[0], 2.5 * p[1], 2.5 * p[2], 2.5 * p[3]};
  csrSegmentStrain s;
  CS_EXPECT(csr_analyticSegment(act, seg, q, &s, NULL) == CS_OK);
  bend[0] = -s.kappa[0] * act->S[seg];
  bend[1] = -s.kappa[1] * act->S[seg];
  *stretch = s.lambda0;
  *radial = 0;
  *radmax = 0.2 * (p[0] + p[1] + p[2] + p[3]);
}


static void stiffLinear(const void* ctx, int seg, double pbar, double* EI, double* EA) {
  (void)ctx;
  *EI = (3000 + 100 * seg) * (1 + pbar);
  *EA = 200 * (1 + 2 * pbar);
}


/* deterministic pseudo-random numbers in [0, 1) */
static double rnd(unsigned* s) {
  *s = *s * 1664525u + 1013904223u;
  return (double)(*s >> 8) / 16777216.0;
}


static void legActuator(csrActuator* act) {
  csError err;
  CS_EXPECT(csr_actuatorPreset(act, "leg", &err) == CS_OK);
}


/* table + model of a truth; the caller frees both */
typedef struct {
  csrCalTable table;
  csrCalModel* model;
} Built;

static int build(Built* b, const char* path, const csrActuator* leg, SynthStateFn fn,
                 const void* ctx, double asym, csrCalRule rule) {
  SynthSpec sp = {fn, stiffLinear, ctx, 0.025, 0, asym, 0};
  synthWrite(path, leg, &sp);
  csError err;
  memset(b, 0, sizeof *b);
  if (csr_calTableRead(path, leg, &b->table, &err) != CS_OK) {
    fprintf(stderr, "  %s\n", err.msg);
    CS_EXPECT(0);
    return 0;
  }
  csrCalOptions o = csr_calModelDefaultOptions();
  o.rule = rule;
  b->model = csr_calModelCreate(&b->table, leg, &o, &err);
  CS_EXPECT(b->model != NULL);
  if (!b->model) {
    fprintf(stderr, "  %s\n", err.msg);
  }
  remove(path);
  return b->model != NULL;
}

static void unbuild(Built* b) {
  csr_calModelDestroy(b->model);
  csr_calTableFree(&b->table);
}


/* ---- tests ----------------------------------------------------------------------------------- */

static void test_superposition_truth_reproduced_everywhere(void) {
  csrActuator leg;
  legActuator(&leg);
  Built b;
  if (!build(&b, "calmod_lin.h5", &leg, truthLinear, NULL, 0, CSR_CAL_RULE_SUPERPOSITION)) {
    return;
  }
  unsigned seed = 7;
  for (int k = 0; k < 400; k++) {
    double p[4];
    for (int j = 0; j < 4; j++) {
      /* a quarter of the draws vent a chamber: patterns on the prism's faces too */
      p[j] = rnd(&seed) < 0.25 ? 0 : 0.5 * rnd(&seed);
    }
    const int s = k % 3;
    csrCalSegment q;
    CS_EXPECT(csr_calModelEval(b.model, s, p, &q) == 0);
    double bend[2], l, r, x;
    truthLinear(NULL, s, p, bend, &l, &r, &x);
    /* round-off of sums of terms ~1 rad: 1e-14 */
    CS_EXPECT_NEAR(q.bend[0], bend[0], 1e-14, 0);
    CS_EXPECT_NEAR(q.bend[1], bend[1], 1e-14, 0);
    CS_EXPECT_NEAR(q.stretch, l, 1e-14, 0);
    CS_EXPECT_NEAR(q.radial, r, 1e-15, 0);
    CS_EXPECT_NEAR(q.radius, leg.a + x, 1e-13, 0);
  }
  unbuild(&b);
}


/* the FE writes bends past 180 deg as the equivalent rotation the other way; the reader
 * continues them, so a truth bending up to 6.8 rad per segment is returned (superposition rule:
 * exactly, at any pattern) */
static void test_bends_past_half_turn(void) {
  csrActuator leg;
  legActuator(&leg);
  SynthSpec sp = {truthBig, stiffLinear, NULL, 0.025, 0, 0, 1};
  synthWrite("calmod_big.h5", &leg, &sp);
  csError err;
  csrCalTable t;
  CS_EXPECT(csr_calTableRead("calmod_big.h5", &leg, &t, &err) == CS_OK);
  /* the table holds wrapped vectors: O12's last row is 6.79 rad written as 0.51 rad the other
   * way; the reader has continued it */
  const double o12[4] = {1, 1, 0, 0};
  const csrCalCase* c = csr_calTableFind(&t, CSR_CAL_MODE, o12);
  CS_EXPECT(c != NULL && c->m == 21);
  if (c) {
    CS_EXPECT_NEAR(c->bend[6 * 20], -8 * 1.2 * 0.5 * 2 / sqrt(2.0), 1e-12, 0);
  }
  csrCalModel* m = csr_calModelCreate(&t, &leg, NULL, &err);
  CS_EXPECT(m != NULL);
  unsigned seed = 13;
  for (int k = 0; m && k < 200; k++) {
    double p[4], bend[2], l, r, x;
    for (int j = 0; j < 4; j++) p[j] = rnd(&seed) < 0.3 ? 0 : 0.5 * rnd(&seed);
    csrCalSegment q;
    CS_EXPECT(csr_calModelEval(m, k % 3, p, &q) == 0);
    truthBig(NULL, k % 3, p, bend, &l, &r, &x);
    CS_EXPECT_NEAR(q.bend[0], bend[0], 1e-13, 0);
    CS_EXPECT_NEAR(q.bend[1], bend[1], 1e-13, 0);
  }
  csr_calModelDestroy(m);
  csr_calTableFree(&t);
  remove("calmod_big.h5");
}


/* every row of every fitted mode of `b` within the model's range is returned: bend equal to
 * the row's (minus the part across a symmetry line when the pattern is mirror-symmetric),
 * scalars equal; rows above the range are refused */
/* the role of a mode case (by its chamber ratios), -1 if none */
static int roleOf(const csrCalCase* c) {
  for (int r = 0; r < CSR_CAL_NROLE; r++) {
    double ratio[CSR_NCHAMBER];
    csr_calModelModePattern((csrCalRole)r, ratio, NULL);
    if (!memcmp(ratio, c->ratio, sizeof ratio)) {
      return r;
    }
  }
  return -1;
}

static void expectRowsReturned(const Built* b, double asym) {
  int nmode = 0;
  for (int i = 0; i < b->table.ncase; i++) {
    const csrCalCase* c = b->table.cases + i;
    const int role = c->kind == CSR_CAL_MODE ? roleOf(c) : -1;
    /* the modes past the prism's hierarchy are the RBF rules' only */
    CS_EXPECT(c->kind != CSR_CAL_MODE || role >= 0);
    if (role < 0 || !csr_calModelUses(b->model, (csrCalRole)role)) {
      CS_EXPECT(role <= CSR_CAL_O1O3R05 || (csr_calModelOptions(b->model)->rule != CSR_CAL_RULE_RBF &&
                                            csr_calModelOptions(b->model)->rule != CSR_CAL_RULE_RBF_PAIR));
      continue;
    }
    nmode++;
    const double* r = c->ratio;
    const double mv[2] = {r[0] + r[1] - r[2] - r[3], r[0] - r[1] - r[2] + r[3]};
    const double mn = hypot(mv[0], mv[1]);
    const int sym = (r[0] == r[1] && r[2] == r[3]) || r[1] == r[3] || r[0] == r[2];
    for (int row = 0; row < c->m; row++) {
      for (int s = 0; s < 3; s++) {
        const double P[4] = {r[0] * c->pressure[row], r[1] * c->pressure[row],
                             r[2] * c->pressure[row], r[3] * c->pressure[row]};
        csrCalSegment q;
        if (c->pressure[row] > csr_calModelPMax(b->model) * (1 + 1e-12)) {
          /* above the model's range (a mode that ended lower, e.g. at a limit): refused */
          CS_EXPECT(csr_calModelEval(b->model, s, P, &q) != 0);
          continue;
        }
        CS_EXPECT(csr_calModelEval(b->model, s, P, &q) == 0);
        double want[2] = {c->bend[6 * row + 2 * s], c->bend[6 * row + 2 * s + 1]};
        if (mn == 0) {
          want[0] = want[1] = 0;
        } else if (sym) {
          const double u[2] = {mv[0] / mn, mv[1] / mn};
          const double along = want[0] * u[0] + want[1] * u[1];
          want[0] = along * u[0], want[1] = along * u[1];
        }
        /* round-off: base + (value - base) and weights 1 - 1e-16 at the 1/3 ratios */
        CS_EXPECT_NEAR(q.bend[0], want[0], 1e-13, 0);
        CS_EXPECT_NEAR(q.bend[1], want[1], 1e-13, 0);
        CS_EXPECT_NEAR(q.stretch - 1, c->stretch[3 * row + s] - c->stretch[s], 1e-14, 0);
        CS_EXPECT_NEAR(q.radial, c->radial[3 * row + s] - c->radial[s], 1e-14, 0);
        CS_EXPECT_NEAR(q.radius - csr_calModelLeg(b->model)->a,
                       c->radial_max[3 * row + s] - c->radial_max[s], 1e-13, 0);
      }
    }
  }
  /* every mode case the rule takes is one the model uses (the synthetic tables have every
   * role, the shipped one the nine of its time) */
  int used = 0;
  for (int r = 0; r < CSR_CAL_NROLE; r++) used += csr_calModelUses(b->model, (csrCalRole)r);
  CS_EXPECT(nmode == used && used >= CSR_CAL_O1234 + 1);
  (void)asym;
}


/* the rules the synthetic tests cover: superposition, interpolation, superposition + RBF */
static const csrCalRule kRules[3] = {CSR_CAL_RULE_SUPERPOSITION, CSR_CAL_RULE_INTERPOLATION,
                                     CSR_CAL_RULE_RBF};

static void test_fitted_rows_returned(void) {
  csrActuator leg;
  legActuator(&leg);
  for (int rule = 0; rule < 3; rule++) {
    for (int a = 0; a < 2; a++) {
      Built b;
      const double asym = a ? 0.05 : 0;
      if (build(&b, "calmod_rows.h5", &leg, truthInteract, NULL, asym, kRules[rule])) {
        expectRowsReturned(&b, asym);
        unbuild(&b);
      }
    }
  }
}


static void test_elongation_gives_no_bend(void) {
  csrActuator leg;
  legActuator(&leg);
  for (int rule = 0; rule < 3; rule++) {
    Built b;
    /* the spurious bend reaches 0.025 rad at 0.5 MPa in every row of O1234 and O13 */
    if (!build(&b, "calmod_elong.h5", &leg, truthInteract, NULL, 0.05, kRules[rule])) {
      continue;
    }
    unsigned seed = 11;
    for (int k = 0; k < 200; k++) {
      const double a = 0.5 * rnd(&seed), c = 0.5 * rnd(&seed);
      const double pats[3][4] = {{a, a, a, a}, {a, c, a, c}, {c, a, c, a}};
      for (int q = 0; q < 3; q++) {
        csrCalSegment out;
        CS_EXPECT(csr_calModelEval(b.model, k % 3, pats[q], &out) == 0);
        CS_EXPECT(out.bend[0] == 0 && out.bend[1] == 0);
        CS_EXPECT(out.stretch > 1);
      }
    }
    unbuild(&b);
  }
}


/* turn a pattern by +90 deg ((R p)_i = p_(i+1)) and mirror it (Ω2 <-> Ω4) */
static void turn(const double p[4], double r[4]) {
  for (int i = 0; i < 4; i++) r[i] = p[(i + 1) % 4];
}


static void test_symmetry_equivariance(void) {
  csrActuator leg;
  legActuator(&leg);
  for (int rule = 0; rule < 3; rule++) {
    Built b;
    if (!build(&b, "calmod_sym.h5", &leg, truthInteract, NULL, 0.02, kRules[rule])) {
      continue;
    }
    unsigned seed = 3;
    for (int k = 0; k < 300; k++) {
      double p[4], r[4], d[4];
      for (int j = 0; j < 4; j++) p[j] = 0.5 * rnd(&seed);
      turn(p, r);
      d[0] = p[0], d[1] = p[3], d[2] = p[2], d[3] = p[1];
      csrCalSegment q0, qr, qd;
      const int s = k % 3;
      CS_EXPECT(csr_calModelEval(b.model, s, p, &q0) == 0);
      CS_EXPECT(csr_calModelEval(b.model, s, r, &qr) == 0);
      CS_EXPECT(csr_calModelEval(b.model, s, d, &qd) == 0);
      /* bend(R p) = Rot(+90) bend(p); bend(D p) = D bend(p), D (x, y) = (y, x) */
      CS_EXPECT_NEAR(qr.bend[0], -q0.bend[1], 1e-13, 0);
      CS_EXPECT_NEAR(qr.bend[1], q0.bend[0], 1e-13, 0);
      CS_EXPECT_NEAR(qd.bend[0], q0.bend[1], 1e-13, 0);
      CS_EXPECT_NEAR(qd.bend[1], q0.bend[0], 1e-13, 0);
      CS_EXPECT_NEAR(qr.stretch, q0.stretch, 1e-14, 0);
      CS_EXPECT_NEAR(qd.radius, q0.radius, 1e-13, 0);
    }
    /* Ω2 alone is Ω1 alone turned by -90 deg. The truth is symmetric; the table's spurious
     * bend s = 0.02 p (0.8, 0.6) rad is in the O1 rows the model turns (its part along the
     * diagonal d1 = (1, 1)/√2 survives the symmetric projection) and in the O2 rows as it is, so
     * the model misses O2 by |Rot(-90) (s.d1) d1 - s| at 0.5 MPa, exactly */
    const double o2[4] = {0, 1, 0, 0};
    const csrCalCase* c = csr_calTableFind(&b.table, CSR_CAL_SYMMETRY, o2);
    CS_EXPECT(c != NULL);
    csrCalCompare e;
    csError err;
    if (c && csr_calModelCompare(b.model, c, &e, &err) == CS_OK) {
      const double sp[2] = {0.02 * 0.5 * 0.8, 0.02 * 0.5 * 0.6};
      const double along = (sp[0] + sp[1]) * RSQ2;
      const double turned[2] = {along * RSQ2, -along * RSQ2}; /* Rot(-90) d1 = (1, -1)/√2 */
      CS_EXPECT(e.rows == 21);
      CS_EXPECT_NEAR(e.bend_deg, hypot(turned[0] - sp[0], turned[1] - sp[1]) / CS_DEG, 1e-9, 0);
    }
    unbuild(&b);
  }
}


static void test_continuity_across_ties(void) {
  csrActuator leg;
  legActuator(&leg);
  for (int rule = 0; rule < 3; rule++) {
    Built b;
    if (!build(&b, "calmod_tie.h5", &leg, truthInteract, NULL, 0, kRules[rule])) {
      continue;
    }
    /* patterns on the faces where the canonical form changes: p1 = p2 highest, p1 = p4
     * highest, p1 = p3 highest, p2 = p4 below p1, all four equal, two vented */
    const double faces[6][4] = {{0.4, 0.4, 0.1, 0.25}, {0.4, 0.15, 0.3, 0.4},
                                {0.35, 0.2, 0.35, 0.05}, {0.45, 0.2, 0.1, 0.2},
                                {0.3, 0.3, 0.3, 0.3},    {0.3, 0.3, 0, 0}};
    const double eps = 1e-7;
    for (int f = 0; f < 6; f++) {
      for (int j = 0; j < 4; j++) {
        for (int sg = -1; sg <= 1; sg += 2) {
          double p[4];
          memcpy(p, faces[f], sizeof p);
          if (p[j] == 0 && sg < 0) {
            continue; /* a vented chamber cannot go below 0 */
          }
          p[j] += sg * eps;
          csrCalSegment a, q;
          CS_EXPECT(csr_calModelEval(b.model, 1, faces[f], &a) == 0);
          CS_EXPECT(csr_calModelEval(b.model, 1, p, &q) == 0);
          /* Lipschitz: the bend changes by at most ~10 rad/MPa here (measured slopes < 5):
           * 1e-6 for eps = 1e-7; a jump between the two canonical forms would be ~1e-2 */
          CS_EXPECT_NEAR(q.bend[0], a.bend[0], 1e-6, 0);
          CS_EXPECT_NEAR(q.bend[1], a.bend[1], 1e-6, 0);
          CS_EXPECT_NEAR(q.stretch, a.stretch, 1e-6, 0);
        }
      }
    }
    unbuild(&b);
  }
}


/* the held-out cases of a truth: worst bend error (deg) and tip error (mm) over H1-H5 */
static void holdoutErrors(const Built* b, int rule, double* bend_deg, double* tip_mm,
                          double* score) {
  *bend_deg = *tip_mm = *score = 0;
  int n = 0;
  for (int i = 0; i < b->table.ncase; i++) {
    const csrCalCase* c = b->table.cases + i;
    if (c->kind != CSR_CAL_HOLDOUT) {
      continue;
    }
    csrCalCompare e;
    csError err;
    CS_EXPECT(csr_calModelCompare(b->model, c, &e, &err) == CS_OK);
    CS_EXPECT(e.rows == c->m);
    /* the bounds were measured over H1-H8; H9-H12 (2026-12-03) are printed only */
    const int bounded = atoi(c->name + 1) <= 8;
    if (bounded) {
      *bend_deg = fmax(*bend_deg, e.bend_deg);
      *tip_mm = fmax(*tip_mm, e.tip_mm);
      *score = fmax(*score, fmax(e.bend_score, e.tip_score));
      n++;
    }
    printf("  %-6s %-13s bend %.4f deg (at %.3g MPa, II%d, of %.2f deg), tip %.4f mm\n", c->name,
           rule == CSR_CAL_RULE_SUPERPOSITION ? "superposition"
           : rule == CSR_CAL_RULE_RBF         ? "RBF"
                                              : "interpolation",
           e.bend_deg, e.bend_at_p, e.bend_at_seg + 1, e.bend_fe_deg, e.tip_mm);
  }
  CS_EXPECT(n == 8); /* H1-H8 */
}


static void test_holdout_on_nonlinear_truths(void) {
  csrActuator leg;
  legActuator(&leg);
  /* bounds: the worst errors measured on 2026-12-02 (deg, mm) per truth and rule, +30 %, with
   * the refining modes of 2026-12-02 (the edge midpoints O1O3r05 and O124O3r05, the prism's
   * centre O1O23r05O4r025) and the held-out H1-H7 (H8, added later, lies within them):
   * closed-form interactions: superposition 1.54 deg / 5.88 mm (H6; H4 0.86 deg / 3.28 mm, was
   * 3.23 deg / 12.4 mm before those modes), interpolation 5.03 deg / 19.5 mm (H6);
   * analytic x2.5: superposition 0.97 deg / 4.14 mm (H4), interpolation 4.69 deg / 20.7 mm (H6).
   * Superposition + RBF (2026-12-03, H1-H8): closed form 1.93 deg / 7.03 mm (H6), analytic
   * 1.16 deg / 4.57 mm (H6): on these smooth truths slightly above the hats (on the FE table
   * below them: docs/bench/calib_rules_2026-12-03).
   * Not the target: these truths only check that the interpolation between the modes
   * behaves as measured (a broken weight or surplus moves them by degrees) */
  const struct {
    SynthStateFn fn;
    const void* ctx;
    double bound_deg[3], bound_mm[3];
  } kTruth[2] = {{truthInteract, NULL, {2.00, 6.54, 2.50}, {7.64, 25.3, 9.14}},
                 {truthAnalytic, &leg, {1.27, 6.10, 1.51}, {5.38, 27.0, 5.94}}};
  for (int t = 0; t < 2; t++) {
    for (int rule = 0; rule < 3; rule++) {
      Built b;
      if (!build(&b, "calmod_ho.h5", &leg, kTruth[t].fn, kTruth[t].ctx, 0, kRules[rule])) {
        continue;
      }
      double bd, tm, sc;
      holdoutErrors(&b, kRules[rule], &bd, &tm, &sc);
      CS_EXPECT(bd <= kTruth[t].bound_deg[rule]);
      CS_EXPECT(tm <= kTruth[t].bound_mm[rule]);
      unbuild(&b);
    }
  }
}


static void test_range_and_bad_pressures(void) {
  csrActuator leg;
  legActuator(&leg);
  Built b;
  if (!build(&b, "calmod_range.h5", &leg, truthInteract, NULL, 0, CSR_CAL_RULE_SUPERPOSITION)) {
    return;
  }
  CS_EXPECT_NEAR(csr_calModelPMax(b.model), 0.5, 1e-15, 0);
  csrCalSegment q;
  const double over[4] = {0.1, 0.5000001, 0, 0}, edge[4] = {0.5, 0.5, 0.5, 0.5};
  CS_EXPECT(csr_calModelEval(b.model, 0, over, &q) == CSR_MAP_OUT_OF_RANGE);
  CS_EXPECT(csr_calModelEval(b.model, 0, edge, &q) == 0);
  const double tiny[4] = {0.2, -1e-10, 0, 0}, zero[4] = {0.2, 0, 0, 0};
  csrCalSegment qt;
  CS_EXPECT(csr_calModelEval(b.model, 2, tiny, &qt) == 0);
  CS_EXPECT(csr_calModelEval(b.model, 2, zero, &q) == 0);
  CS_EXPECT(qt.bend[0] == q.bend[0] && qt.bend[1] == q.bend[1]);
  const double neg[4] = {0.2, -1e-6, 0, 0}, nan4[4] = {0.2, NAN, 0, 0};
  CS_EXPECT(csr_calModelEval(b.model, 2, neg, &q) == 1);
  CS_EXPECT(csr_calModelEval(b.model, 2, nan4, &q) == 1);
  CS_EXPECT(csr_calModelEval(b.model, 3, zero, &q) < 0);
  /* vented: exactly the rest state */
  const double vent[4] = {0, 0, 0, 0};
  CS_EXPECT(csr_calModelEval(b.model, 1, vent, &q) == 0);
  CS_EXPECT(q.bend[0] == 0 && q.bend[1] == 0 && q.stretch == 1 && q.radius == leg.a);
  unbuild(&b);
}


static void test_stiffness_mean_pressure_rule(void) {
  csrActuator leg;
  legActuator(&leg);
  Built b;
  if (!build(&b, "calmod_k.h5", &leg, truthInteract, NULL, 0, CSR_CAL_RULE_SUPERPOSITION)) {
    return;
  }
  /* probes of O12 (p̄ = p/2) and O1234 (p̄ = p) at 0..0.3 MPa: p̄ up to 0.3 */
  CS_EXPECT_NEAR(csr_calModelStiffnessPMax(b.model), 0.3, 1e-15, 0);
  unsigned seed = 5;
  for (int k = 0; k < 50; k++) {
    double p[4];
    for (int j = 0; j < 4; j++) p[j] = 0.3 * rnd(&seed);
    const double pbar = 0.25 * (p[0] + p[1] + p[2] + p[3]);
    double EI, EA, wEI, wEA;
    CS_EXPECT(csr_calModelStiffness(b.model, k % 3, p, &EI, &EA) == 0);
    stiffLinear(NULL, k % 3, pbar, &wEI, &wEA);
    /* linear in p̄: piecewise-linear interpolation is exact to round-off */
    CS_EXPECT_NEAR(EI, wEI, 0, 1e-14);
    CS_EXPECT_NEAR(EA, wEA, 0, 1e-14);
  }
  double EI, EA;
  const double high[4] = {0.35, 0.35, 0.35, 0.35};
  CS_EXPECT(csr_calModelStiffness(b.model, 0, high, &EI, &EA) == CSR_MAP_OUT_OF_RANGE);
  int n;
  const double *pb, *v;
  csr_calModelStiffnessPoints(b.model, 0, 0, &n, &pb, &v);
  /* EI: p̄ = 0 (both modes), 0.05, 0.1 (both), 0.2, 0.3; O12's probe at 0.3 MPa (p̄ 0.15) is
   * left out: segment II1 is bent there by more than the 0.5 rad a probe may have */
  const csrCalCase* o12 = NULL;
  const double r12[4] = {1, 1, 0, 0};
  o12 = csr_calTableFind(&b.table, CSR_CAL_MODE, r12);
  CS_EXPECT(o12 != NULL && o12->m == 21); /* 0..0.5 MPa by 0.025 */
  if (o12) {
    /* row 12 (0.3 MPa) and row 4 (0.1 MPa) of II1 */
    CS_EXPECT(hypot(o12->bend[6 * 12], o12->bend[6 * 12 + 1]) > 0.5);
    CS_EXPECT(hypot(o12->bend[6 * 4], o12->bend[6 * 4 + 1]) <= 0.5);
  }
  CS_EXPECT(n == 5 && pb[0] == 0 && fabs(pb[1] - 0.05) < 1e-15 && fabs(pb[4] - 0.3) < 1e-15);
  /* EA: only probes of segments bent by 0.1 rad at most: O1234's (straight) and O12's at rest */
  csr_calModelStiffnessPoints(b.model, 0, 1, &n, &pb, &v);
  CS_EXPECT(n == 4 && pb[0] == 0 && fabs(pb[1] - 0.1) < 1e-15 && fabs(pb[3] - 0.3) < 1e-15);
  unbuild(&b);

  /* a failed probe (NaN) is skipped: O1234's EA at 0.3 MPa lost, EA ends at p̄ = 0.2 */
  SynthSpec sp = {truthInteract, stiffLinear, NULL, 0.025, 0, 0, 0};
  synthWrite("calmod_k2.h5", &leg, &sp);
  for (int s = 0; s < 3; s++) synthPoke("calmod_k2.h5", "/cases/O1234/EA", 3 * 3 + s, NAN);
  csError err;
  csrCalibration* c = csr_calibrationOpen("calmod_k2.h5", &leg, &err);
  CS_EXPECT(c != NULL);
  if (c) {
    const csrCalModel* m = csr_calibrationModel(c);
    CS_EXPECT_NEAR(csr_calModelStiffnessPMax(m), 0.2, 1e-15, 0);
    const double mid[4] = {0.2, 0.2, 0.2, 0.2};
    double wEI, wEA;
    CS_EXPECT(csr_calModelStiffness(m, 1, mid, &EI, &EA) == 0);
    stiffLinear(NULL, 1, 0.2, &wEI, &wEA);
    CS_EXPECT_NEAR(EA, wEA, 0, 1e-14);
  }
  csr_calibrationClose(c);
  /* no probes at all: no stiffness (2), the bend model unaffected */
  synthDelete("calmod_k2.h5", "/cases/O12/probe_pressure");
  synthDelete("calmod_k2.h5", "/cases/O1234/probe_pressure");
  c = csr_calibrationOpen("calmod_k2.h5", &leg, &err);
  CS_EXPECT(c != NULL);
  if (c) {
    const double mid[4] = {0.2, 0.1, 0, 0};
    CS_EXPECT(csr_calModelStiffness(csr_calibrationModel(c), 0, mid, &EI, &EA) == 2);
    CS_EXPECT(isnan(csr_calModelStiffnessPMax(csr_calibrationModel(c))));
  }
  csr_calibrationClose(c);
  remove("calmod_k2.h5");
}


static void test_rod_adapter(void) {
  csrActuator leg;
  legActuator(&leg);
  SynthSpec sp = {truthInteract, stiffLinear, NULL, 0.025, 0, 0, 0};
  synthWrite("calmod_rod.h5", &leg, &sp);
  csError err;
  csrCalibration* c = csr_calibrationOpen("calmod_rod.h5", &leg, &err);
  CS_EXPECT(c != NULL);
  if (!c) {
    return;
  }
  csrRodCalibration rc, rm;
  memset(&rm, 0, sizeof rm);
  CS_EXPECT(csr_calibrationRod(c, &rc) == 1);
  csrBendMap map = csr_calibrationMap(c);
  CS_EXPECT(csr_calibrationRodFromMap(&map, &rm) == 1 && rm.ctx == rc.ctx);
  const double p[4] = {0.25, 0.1, 0.05, 0};
  for (int s = 0; s < 3; s++) {
    csrRodSegmentActuation a;
    memset(&a, 0, sizeof a);
    CS_EXPECT(rc.eval(rc.ctx, s, p, &a) == 0);
    double bend[2], stretch, EI, EA;
    CS_EXPECT(map.eval(map.ctx, s, p, bend, &stretch) == 0);
    CS_EXPECT(csr_calModelStiffness(csr_calibrationModel(c), s, p, &EI, &EA) == 0);
    /* the rod's convention (robot_rod.h): u0 = (-bend[1], bend[0], 0) / S */
    CS_EXPECT_NEAR(a.u0[0], -bend[1] / leg.S[s], 1e-15, 0);
    CS_EXPECT_NEAR(a.u0[1], bend[0] / leg.S[s], 1e-15, 0);
    CS_EXPECT(a.u0[2] == 0 && a.sigma0[0] == 0 && a.sigma0[1] == 0);
    CS_EXPECT_NEAR(a.sigma0[2], stretch - 1, 1e-15, 0);
    CS_EXPECT(a.has_section == 1 && a.section.EI[0] == EI && a.section.EI[1] == EI);
    CS_EXPECT(a.section.EA == EA && a.section.GA[0] > 0 && a.section.GJ > 0);
  }
  /* above the probes' mean pressure the stiffness, and so the rod's actuation, is refused */
  const double high[4] = {0.4, 0.4, 0.4, 0.4};
  csrRodSegmentActuation a;
  memset(&a, 0, sizeof a);
  CS_EXPECT(rc.eval(rc.ctx, 0, high, &a) == CSR_MAP_OUT_OF_RANGE);
  csr_calibrationClose(c);
  remove("calmod_rod.h5");
  /* the provisional map is not a mode table */
  char path[1024];
  snprintf(path, sizeof path, "%s/robot/calibration_provisional.txt", getenv("CS_SOURCE_DIR"));
  c = csr_calibrationOpen(path, &leg, &err);
  CS_EXPECT(c != NULL);
  if (c) {
    map = csr_calibrationMap(c);
    CS_EXPECT(csr_calibrationRod(c, &rc) == 0 && csr_calibrationRodFromMap(&map, &rc) == 0);
    CS_EXPECT(csr_calibrationModel(c) == NULL);
  }
  csr_calibrationClose(c);
}


/* a mirror-symmetric held-out case whose FE bends across the mirror line (mesh asymmetry): the
 * tip against the FE's symmetric part ignores exactly that, the raw tip does not */
static void test_compare_symmetric_part(void) {
  csrActuator leg;
  legActuator(&leg);
  Built b;
  if (!build(&b, "calmod_sym.h5", &leg, truthLinear, NULL, 0, CSR_CAL_RULE_SUPERPOSITION)) {
    return;
  }
  csrCalCase* c = NULL;
  for (int i = 0; i < b.table.ncase; i++) {
    if (!strcmp(b.table.cases[i].name, "H3")) {
      c = b.table.cases + i;
    }
  }
  CS_EXPECT(c != NULL);
  if (!c) {
    unbuild(&b);
    return;
  }
  csrCalCompare e0, e1;
  csError err;
  CS_EXPECT(csr_calModelCompare(b.model, c, &e0, &err) == CS_OK);
  CS_EXPECT(e0.mirror == 1);
  /* the truth is the rule's own form: model = FE to round-off (1e-12 mm on a 166 mm leg) */
  CS_EXPECT(e0.tip_mm < 1e-9 && e0.tip_sym_mm < 1e-9);
  /* H3 = (1, a, a, a): its mirror line is the moment's direction (1, 1)/sqrt 2; add 1 deg per
   * segment and 0.1 MPa across it, with the FE tip from the same kinematics */
  const double across[2] = {-RSQ2, RSQ2};
  for (int i = 0; i < c->m; i++) {
    csrSegmentStrain ss[CSR_NSEG];
    memset(ss, 0, sizeof ss);
    for (int s = 0; s < CSR_NSEG; s++) {
      double* bf = c->bend + 6 * i + 2 * s;
      bf[0] += across[0] * CS_DEG * 10 * c->pressure[i];
      bf[1] += across[1] * CS_DEG * 10 * c->pressure[i];
      ss[s].lambda0 = c->stretch[3 * i + s];
      ss[s].kappa[0] = -bf[0] / leg.S[s], ss[s].kappa[1] = -bf[1] / leg.S[s];
    }
    CS_EXPECT(csr_ccForwardKinematics(&leg, ss, 1, NULL, c->tip + 3 * i, NULL, &err) == CS_OK);
  }
  CS_EXPECT(csr_calModelCompare(b.model, c, &e1, &err) == CS_OK);
  printf("  H3 with 1 deg / 0.1 MPa across its mirror line: tip %.3f mm, symmetric part %.2e mm\n",
         e1.tip_mm, e1.tip_sym_mm);
  CS_EXPECT(e1.tip_mm > 1.0);       /* 3.5 deg across at 0.35 MPa moves the tip by mm */
  CS_EXPECT(e1.tip_sym_mm < 1e-9);  /* removed exactly: round-off of the kinematics */
  /* it validates the model over its whole sweep on the symmetric part */
  CS_EXPECT(e0.p_meets == e0.p_last && e1.p_meets == e1.p_last);
  /* an FE tip 10 mm off from 0.2 MPa on (3 x the 3.32 mm target): meets it up to 0.175 */
  for (int i = 0; i < c->m; i++) {
    c->tip[3 * i] += c->pressure[i] > 0.19 ? 10.0 : 0.0;
  }
  csrCalCompare e2;
  CS_EXPECT(csr_calModelCompare(b.model, c, &e2, &err) == CS_OK);
  CS_EXPECT_NEAR(e2.p_meets, 0.175, 1e-12, 0);
  remove("calmod_sym.h5");
  unbuild(&b);
}


/* csr_calSymmetryPair and csr_calModelCompareSymmetrised on synthetic tables */
static void test_symmetry_pair_carries_the_image(void) {
  csrActuator leg;
  legActuator(&leg);
  const char* pairs[4][2] = {{"O2", "O1"}, {"H4t", "H4"}, {"H6t", "H6"}, {"H7t", "H7"}};
  for (int asym = 0; asym < 2; asym++) {
    Built b;
    const double a = asym ? 0.02 : 0; /* rad/MPa: 0.46 deg at 0.4 MPa */
    if (!build(&b, "calmod_pair.h5", &leg, truthInteract, NULL, a, CSR_CAL_RULE_SUPERPOSITION)) {
      return;
    }
    for (int k = 0; k < 4; k++) {
      const csrCalCase* c = NULL;
      for (int i = 0; i < b.table.ncase; i++) {
        if (!strcmp(b.table.cases[i].name, pairs[k][0])) {
          c = b.table.cases + i;
        }
      }
      CS_EXPECT(c != NULL);
      if (!c) {
        continue;
      }
      csrCalSymPair pr;
      csError err;
      CS_EXPECT(csr_calSymmetryPair(&b.table, c, &pr, &err) == CS_OK);
      CS_EXPECT(pr.partner != NULL && !strcmp(pr.partner->name, pairs[k][1]));
      CS_EXPECT(pr.rows == c->m);
      if (!asym) {
        CS_EXPECT(pr.bend_deg < 1e-10 && pr.tip_mm < 1e-9);
      } else {
        /* the spurious a p (0.8, 0.6) against its image turned by 90 deg */
        CS_EXPECT_NEAR(pr.bend_deg, sqrt(2.0) * a * pr.p_last / CS_DEG, 1e-9, 0);
        CS_EXPECT(pr.tip_mm > 0.1);
      }
      printf("  %s against %s (asym %g rad/MPa): bend %.3g deg, tip %.3g mm\n", c->name,
             pr.partner->name, a, pr.bend_deg, pr.tip_mm);
    }
    unbuild(&b);
  }
  /* on the rule's own form (the model exact to round-off), H4's FE tip 2 mm off along e1 from
   * 0.2 MPa: the model sees all of it raw, half of it against the mean with H4t */
  {
    Built b;
    if (build(&b, "calmod_pair.h5", &leg, truthLinear, NULL, 0, CSR_CAL_RULE_SUPERPOSITION)) {
      csrCalCase* h4 = NULL;
      for (int i = 0; i < b.table.ncase; i++) {
        if (!strcmp(b.table.cases[i].name, "H4")) {
          h4 = b.table.cases + i;
        }
      }
      csrCalSymPair pr;
      csrCalCompare e0, e1, es;
      csError err;
      CS_EXPECT(h4 != NULL && csr_calSymmetryPair(&b.table, h4, &pr, &err) == CS_OK);
      CS_EXPECT(pr.partner != NULL && !strcmp(pr.partner->name, "H4t"));
      CS_EXPECT(csr_calModelCompare(b.model, h4, &e0, &err) == CS_OK);
      for (int i = 0; i < h4->m; i++) {
        h4->tip[3 * i] += h4->pressure[i] > 0.19 ? 2.0 : 0.0;
      }
      CS_EXPECT(csr_calModelCompare(b.model, h4, &e1, &err) == CS_OK);
      CS_EXPECT(csr_calModelCompareSymmetrised(b.model, h4, &pr, &es, &err) == CS_OK);
      printf("  H4 with its tip 2 mm off: model %.4f -> %.4f mm raw, %.4f mm symmetrised\n",
             e0.tip_mm, e1.tip_mm, es.tip_mm);
      CS_EXPECT(e0.tip_mm < 1e-9);
      CS_EXPECT_NEAR(e1.tip_mm, 2.0, 1e-9, 0);
      CS_EXPECT_NEAR(es.tip_mm, 1.0, 1e-9, 0);
      CS_EXPECT(es.rows == e1.rows);
      unbuild(&b);
    }
  }
  /* a gravity case has no image; no argument, no comparison */
  csrCalSymPair none;
  csrCalCompare e;
  csError err;
  csrCalCase g;
  memset(&g, 0, sizeof g);
  g.kind = CSR_CAL_GRAVITY;
  csrCalTable t;
  memset(&t, 0, sizeof t);
  CS_EXPECT(csr_calSymmetryPair(&t, &g, &none, &err) == CS_OK && none.partner == NULL);
  CS_EXPECT(csr_calModelCompareSymmetrised(NULL, &g, &none, &e, &err) == CS_ERR_ARG);
}


/* MPa: the pressure up to which every held-out case of the shipped mode table meets the target
 * (5 % of the bend or 1 deg; tip 2 % of the leg) */
#define P_VALIDATED 0.225

static void test_shipped_table_holdout(void) {
  csrActuator leg;
  legActuator(&leg);
  char path[1024];
  /* the shipped mode table (robot/calibration_fe_leg_modes.h5, `crawlsim calibrate`), or the
   * default table once it is one */
  snprintf(path, sizeof path, "%s/robot/calibration_fe_leg_modes.h5", getenv("CS_SOURCE_DIR"));
  if (!csr_calTableIsModeTable(path)) {
    snprintf(path, sizeof path, "%s/robot/calibration_fe_leg.h5", getenv("CS_SOURCE_DIR"));
  }
  if (!csr_calTableIsModeTable(path)) {
    printf("  %s is not a mode table yet (pair-mode kind): nothing to check\n", path);
    return;
  }
  Built b;
  csError err;
  memset(&b, 0, sizeof b);
  CS_EXPECT(csr_calTableRead(path, &leg, &b.table, &err) == CS_OK);
  b.model = csr_calModelCreate(&b.table, &leg, NULL, &err);
  CS_EXPECT(b.model != NULL);
  if (!b.model) {
    fprintf(stderr, "  %s\n", err.msg);
    csr_calTableFree(&b.table);
    return;
  }
  /* its own FE points: every fitted row, symmetric part */
  expectRowsReturned(&b, 0);
  /* elongation: no bend at equal pressures */
  for (int k = 1; k <= 10; k++) {
    const double q = 0.1 * k * csr_calModelPMax(b.model);
    const double all[4] = {q, q, q, q}, diag[4] = {q, 0.3 * q, q, 0.3 * q};
    csrCalSegment a, d;
    CS_EXPECT(csr_calModelEval(b.model, k % 3, all, &a) == 0 && a.bend[0] == 0 && a.bend[1] == 0);
    CS_EXPECT(csr_calModelEval(b.model, k % 3, diag, &d) == 0 && d.bend[0] == 0 && d.bend[1] == 0);
  }
  /* the held-out cases meet the target; the symmetry case is reported */
  int nheld = 0;
  for (int i = 0; i < b.table.ncase; i++) {
    const csrCalCase* cs = b.table.cases + i;
    if (cs->kind != CSR_CAL_HOLDOUT && cs->kind != CSR_CAL_SYMMETRY) {
      continue;
    }
    csrCalCompare e;
    CS_EXPECT(csr_calModelCompare(b.model, cs, &e, &err) == CS_OK);
    printf("  %s: bend %.3f deg (of %.2f at %.3g MPa, II%d), score %.2f; tip %.3f mm (score "
           "%.2f; constant curvature alone %.3f mm)\n",
           cs->name, e.bend_deg, e.bend_fe_deg, e.bend_at_p, e.bend_at_seg + 1, e.bend_score,
           e.tip_mm, e.tip_score, e.tip_cc_mm);
    if (cs->kind == CSR_CAL_HOLDOUT) {
      /* the tip against the FE's symmetric part where the pattern has a mirror line: the FE's
       * bend across it is its mesh asymmetry, which the fitted modes are cleared of too */
      if (e.mirror) {
        printf("    against the FE's symmetric part: tip %.3f mm (score %.2f)\n", e.tip_sym_mm,
               e.tip_sym_score);
      }
      /* over the rows up to P_VALIDATED: above it the shipped table's H4-H7 miss (measured
       * 2026-12-02 on robot/calibration_fe_leg_modes.h5, 18 cases: H4, H5, H6 meet to 0.25 MPa,
       * H7 (added that day, after the modes were chosen) to 0.225; tip 7.3 / 10.5 / 19.9 / 35.3
       * mm at 0.4; README "Calibration"); a case that ends lower must meet it throughout */
      CS_EXPECT(e.p_meets >= fmin(e.p_last, P_VALIDATED) - 1e-12);
      if (e.p_meets >= e.p_last) {
        CS_EXPECT(e.bend_score <= 1);
        CS_EXPECT(e.tip_score <= 1 || (e.mirror && e.tip_sym_score <= 1));
      }
      printf("    meets the target up to %.3g MPa (of %.3g)\n", e.p_meets, e.p_last);
      nheld++;
    }
  }
  CS_EXPECT(nheld >= 3);
  unbuild(&b);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_superposition_truth_reproduced_everywhere);
  CS_RUN(test_bends_past_half_turn);
  CS_RUN(test_fitted_rows_returned);
  CS_RUN(test_elongation_gives_no_bend);
  CS_RUN(test_symmetry_equivariance);
  CS_RUN(test_continuity_across_ties);
  CS_RUN(test_holdout_on_nonlinear_truths);
  CS_RUN(test_range_and_bad_pressures);
  CS_RUN(test_stiffness_mean_pressure_rule);
  CS_RUN(test_rod_adapter);
  CS_RUN(test_compare_symmetric_part);
  CS_RUN(test_symmetry_pair_carries_the_image);
  CS_RUN(test_shipped_table_holdout);
  return cs_testSummary();
}

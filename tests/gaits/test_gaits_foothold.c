/* test_gaits_foothold.c: footholds (gaits_foothold.h): the choice on the two closed cases of
 * the design (docs/studies/obstacle.md, "A foothold that reads the support") and the rules
 * around them, then the .foothold reader on a good file and on every bad-input case, each a
 * one-line message naming the file, the line and the cause. Files go to the working directory
 * (the build tree). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "gaits_foothold.h"
#include "gaits_labels.h"
#include "gaits_schedule.h"


/* a hip 30 mm ahead of the plan takes the landing the plan's hip would, with the offset 30 mm
 * shorter, where that offset is a candidate: offsets 0..40 by 10 from a planned hip at 300
 * (landings 300 + r + 10), the plan's pick 30 (landing 340), on a plateau 240..460 */
static void test_hipAheadKeepsThePlannedLanding(void) {
  const double offset[5] = {0, 10, 20, 30, 40};
  double land[5];
  for (int i = 0; i < 5; i++) {
    land[i] = 300 + offset[i] + 10;
  }
  const double edges[2] = {240, 460};
  /* on plan: the plan's 30; 30 ahead: 30 - 30; 10 behind: 40; 20 ahead: 10 */
  CS_EXPECT(csg_footholdChoose(5, land, NULL, NULL, 3, 0.0, edges, 2, 25) == 3);
  CS_EXPECT(csg_footholdChoose(5, land, NULL, NULL, 3, 30.0, edges, 2, 25) == 0);
  CS_EXPECT(csg_footholdChoose(5, land, NULL, NULL, 3, -10.0, edges, 2, 25) == 4);
  CS_EXPECT(csg_footholdChoose(5, land, NULL, NULL, 3, 20.0, edges, 2, 25) == 1);
}


/* an edge between two candidates' landings: the one further from it */
static void test_edgeBetweenTakesTheFurther(void) {
  const double land[2] = {228, 255}; /* 12 before the riser at 240, 15 past it */
  const double edges[2] = {240, 460};
  CS_EXPECT(csg_footholdChoose(2, land, NULL, NULL, 0, 0.0, edges, 2, 25) == 1);
  const double land2[2] = {222, 250}; /* 18 before, 10 past */
  CS_EXPECT(csg_footholdChoose(2, land2, NULL, NULL, 1, 0.0, edges, 2, 25) == 0);
}


/* a landing its stance length does not suit is refused (the span it fits), and without edges
 * the plan's landing is kept */
static void test_fitsAndNoEdges(void) {
  const double land[3] = {200, 215, 270}; /* road, road, plateau */
  const double lo[3] = {-1e6, -1e6, 240}, hi[3] = {240, 240, 460};
  const double edges[2] = {240, 460};
  /* 30 ahead: 215 -> 245 is past the riser with a road length (does not fit), 200 -> 230
   * keeps 10, 270 -> 300 keeps 60: the nearest to the plan's 215 keeping 10 mm is 200's (230) */
  CS_EXPECT(csg_footholdChoose(3, land, lo, hi, 1, 30.0, edges, 2, 10) == 0);
  /* a margin none keeps: the fitting one of largest clearance (270 -> 300, 60 mm) */
  CS_EXPECT(csg_footholdChoose(3, land, lo, hi, 1, 30.0, edges, 2, 100) == 2);
  /* none fits (all shifted 300 mm): the largest clearance */
  CS_EXPECT(csg_footholdChoose(3, land, lo, hi, 1, 300.0, edges, 2, 10) == 2);
  CS_EXPECT(csg_footholdChoose(3, land, lo, hi, 1, 30.0, NULL, 0, 25) == 0);
  CS_EXPECT(csg_footholdChoose(3, land, lo, hi, 1, 0.0, NULL, 0, 25) == 1);
  /* bad arguments */
  CS_EXPECT(csg_footholdChoose(0, land, lo, hi, 0, 0.0, edges, 2, 25) == -1);
  CS_EXPECT(csg_footholdChoose(3, land, lo, hi, 3, 0.0, edges, 2, 25) == -1);
  CS_EXPECT(csg_footholdChoose(3, land, lo, hi, 1, NAN, edges, 2, 25) == -1);
  CS_EXPECT(csg_footholdChoose(3, NULL, lo, hi, 1, 0.0, edges, 2, 25) == -1);
}


static void writeTables(void) {
  cs_testWriteText("fh_c0.csv", "time,D_II1_O1,H_II1_O1\n0.9,0.1,0.1\n1,0.1,0.1\n2,0.2,0.2\n3,0,0\n");
  cs_testWriteText("fh_c1.csv", "time,D_II1_O1,H_II1_O1\n0.9,0.1,0.1\n1,0.1,0.1\n2,0.3,0.3\n3,0,0\n");
}


static void test_readGood(void) {
  writeTables();
  cs_testWriteText("fh_good.foothold", "# two candidates\n\n"
            "foothold 1 DH xplan 90 margin 25 window 1 3\n"
            "candidate 0 land 200 fits -1000 240 fh_c0.csv\n"
            "candidate 10 land 210 fits -1000 240 fh_c1.csv nominal  # the plan's\n");
  csError err;
  cs_errorClear(&err);
  csgFootholdSet* s = csg_footholdRead("fh_good.foothold", NULL, &err);
  CS_EXPECT(s != NULL);
  if (s) {
    CS_EXPECT(s->n == 1);
    const csgFoothold* f = &s->fh[0];
    CS_EXPECT(f->legs == ((1u << 3) | (1u << 7)));
    CS_EXPECT(f->ncand == 2 && f->nominal == 1);
    CS_EXPECT(f->t == 1 && f->xplan == 90 && f->margin == 25 && f->w0 == 1 && f->w1 == 3);
    CS_EXPECT(f->cand[1].offset == 10 && f->cand[1].land == 210 && f->cand[1].lo == -1000 &&
              f->cand[1].hi == 240);
    CS_EXPECT(f->cand[1].table && f->cand[1].table->nrow == 4);
  } else {
    fprintf(stderr, "  %s\n", err.msg);
  }
  csg_footholdDestroy(s);
}


/* a chain: the same legs' next step a foothold whose window starts within the earlier's and
 * ends after it (accepted) */
static void test_readChain(void) {
  writeTables();
  cs_testWriteText("fh_chain.foothold",
            "foothold 1 DH xplan 90 margin 25 window 1 2.5\n"
            "candidate 0 land 200 fits -1000 240 fh_c0.csv nominal\n"
            "foothold 1.5 H xplan 95 margin 25 window 2 3\n"
            "candidate 0 land 205 fits -1000 240 fh_c1.csv nominal\n");
  csError err;
  cs_errorClear(&err);
  csgFootholdSet* s = csg_footholdRead("fh_chain.foothold", NULL, &err);
  CS_EXPECT(s != NULL && s->n == 2);
  if (!s) fprintf(stderr, "  %s\n", err.msg);
  csg_footholdDestroy(s);
}


static void expectBad(const char* name, const char* text, csStatus status, int line,
                      const char* cause) {
  cs_testWriteText(name, text);
  csError err;
  cs_errorClear(&err);
  csgFootholdSet* s = csg_footholdRead(name, NULL, &err);
  CS_EXPECT(s == NULL);
  csg_footholdDestroy(s);
  char want[128];
  snprintf(want, sizeof want, "%s:%d:", name, line);
  int ok = err.status == status && strchr(err.msg, '\n') == NULL &&
           strstr(err.msg, want) == err.msg && strstr(err.msg, cause) != NULL;
  CS_EXPECT(ok);
  if (!ok) {
    fprintf(stderr, "  %s: status %d, message: %s\n", name, (int)err.status, err.msg);
  }
}


static void test_readBad(void) {
  writeTables();
  const char* f1 = "foothold 1 DH xplan 90 margin 25 window 1 3\n";
  char text[512];
  expectBad("fh_b1.foothold", "step 1 DH\n", CS_ERR_PARSE, 1, "unknown statement");
  expectBad("fh_b2.foothold", "foothold 1 DH xplan 90 margin 25\n", CS_ERR_PARSE, 1,
            "needs T LEGS");
  expectBad("fh_b3.foothold", "foothold 1 DX xplan 90 margin 25 window 1 3\n", CS_ERR_PARSE, 1,
            "not a leg");
  expectBad("fh_b4.foothold", "foothold 1 DH xplan nan margin 25 window 1 3\n", CS_ERR_PARSE, 1,
            "not a finite number");
  expectBad("fh_b5.foothold", "foothold 2 DH xplan 9 margin 25 window 1 3\n", CS_ERR_RANGE, 1,
            "T <= W0 < W1");
  expectBad("fh_b6.foothold", "candidate 0 land 200 fits -1000 1000 fh_c0.csv\n", CS_ERR_PARSE, 1,
            "before any 'foothold'");
  snprintf(text, sizeof text, "%scandidate 0 land 200 fits -1000 1000 fh_c0.csv\n", f1);
  expectBad("fh_b7.foothold", text, CS_ERR_PARSE, 2, "no nominal candidate");
  snprintf(text, sizeof text, "%scandidate 0 land 200 fits -1000 1000 fh_none.csv nominal\n", f1);
  expectBad("fh_b8.foothold", text, CS_ERR_IO, 2, "candidate table");
  snprintf(text, sizeof text, "%scandidate 0 land 200 fits -1000 1000 fh_c0.csv nominal\n"
           "candidate 1 land 201 fits -1000 1000 fh_c1.csv nominal\n", f1);
  expectBad("fh_b9.foothold", text, CS_ERR_PARSE, 3, "second nominal");
  expectBad("fh_b10.foothold", "foothold 0.5 DH xplan 9 margin 25 window 0.5 5\n"
            "candidate 0 land 200 fits -1000 1000 fh_c0.csv nominal\n", CS_ERR_RANGE, 2,
            "not the window");
  /* a window overlapping an earlier one on a shared leg without following it (ending first:
   * the earlier's rows would come back after it) */
  snprintf(text, sizeof text, "%scandidate 0 land 200 fits -1000 1000 fh_c0.csv nominal\n"
           "foothold 1.5 H xplan 9 margin 25 window 2 2.5\n", f1);
  expectBad("fh_b11.foothold", text, CS_ERR_RANGE, 3, "overlaps");
  snprintf(text, sizeof text, "%scandidate 0 land x fits -1000 1000 fh_c0.csv nominal\n", f1);
  expectBad("fh_b12.foothold", text, CS_ERR_PARSE, 2, "finite numbers");
  snprintf(text, sizeof text, "%scandidate 0 land 300 fits 0 240 fh_c0.csv nominal\n", f1);
  expectBad("fh_b14.foothold", text, CS_ERR_RANGE, 2, "outside the span");
  expectBad("fh_b13.foothold", "# nothing\n", CS_ERR_PARSE, 1, "no foothold");
}


/* ---- the command a candidate stands for, at any ramp (csg_footholdCompose) ---- */

#define NL CSG_NLABEL
/* a nominal table of rows every 0.05 s over 0..2 s whose pressures change at every row (leg
 * k's chamber c: a triangle wave of its own phase, 0..0.3 MPa) */
static csgGait* nominalTable(void) {
  csgGait* g = csg_gaitCreate(41, NULL);
  for (int i = 0; g && i < g->nrow; i++) {
    g->time[i] = 0.05 * i;
    for (int l = 0; l < NL; l++) {
      const double u = fmod(0.37 * i + 0.11 * l, 2.0);
      g->pressure[NL * i + l] = 0.15 * (u < 1 ? u : 2 - u) * 2;
    }
  }
  return g;
}

/* a candidate of legs `legs` over rows t0..t1 (s, 0.05 s apart): the nominal's rows with the
 * legs' columns scaled by `scale` and every other column 0.4 MPa (which the player must not
 * use) */
static csgGait* candidateTable(const csgGait* nom, unsigned legs, double t0, double t1,
                               double scale) {
  const int i0 = (int)lround(t0 / 0.05), n = (int)lround((t1 - t0) / 0.05) + 1;
  csgGait* g = csg_gaitCreate(n, NULL);
  for (int i = 0; g && i < n; i++) {
    g->time[i] = nom->time[i0 + i];
    for (int l = 0; l < NL; l++) {
      g->pressure[NL * i + l] = (legs >> (l / 12)) & 1u ? scale * nom->pressure[NL * (i0 + i) + l]
                                                       : 0.4;
    }
  }
  return g;
}

/* a set of footholds on nom: foothold k of legs legs[k], window w[k][0..1], its one candidate
 * (nominal: the index stands for itself here) scale[k] of the nominal over rows
 * w0 - 0.05 .. w1 + 0.1 (as tools/obstacle_gait.py cuts them) */
static csgFootholdSet* footholds(const csgGait* nom, int n, const unsigned* legs,
                                 const double (*w)[2], const double* scale) {
  csgFootholdSet* s = calloc(1, sizeof *s);
  s->n = n;
  for (int k = 0; k < n; k++) {
    csgFoothold* f = &s->fh[k];
    f->t = w[k][0];
    f->legs = legs[k];
    f->w0 = w[k][0];
    f->w1 = w[k][1];
    f->ncand = 1;
    f->nominal = 0;
    f->cand[0].table = candidateTable(nom, legs[k], w[k][0] - 0.05, w[k][1] + 0.1, scale[k]);
  }
  return s;
}

/* the command by hand: nom's rows with foothold k's legs' columns from its candidate over the
 * rows of its window, a later foothold's from its W0 on (the chain's rule) */
static csgGait* handComposite(const csgGait* nom, const csgFootholdSet* s) {
  csgGait* g = csg_gaitCreate(nom->nrow, NULL);
  memcpy(g->time, nom->time, sizeof(double) * (size_t)nom->nrow);
  memcpy(g->pressure, nom->pressure, sizeof(double) * NL * (size_t)nom->nrow);
  for (int k = 0; k < s->n; k++) {
    const csgFoothold* f = &s->fh[k];
    const csgGait* c = f->cand[0].table;
    for (int i = 0; i < nom->nrow; i++) {
      if (nom->time[i] < f->w0 - 1e-12 || nom->time[i] >= f->w1 - 1e-12) continue;
      const int j = (int)lround((nom->time[i] - c->time[0]) / 0.05);
      for (int l = 0; l < NL; l++) {
        if ((f->legs >> (l / 12)) & 1u) g->pressure[NL * i + l] = c->pressure[NL * j + l];
      }
    }
  }
  return g;
}

/* the player's arithmetic (core/sim_foothold.c) on the plain schedule: the nominal's p plus,
 * on each foothold's legs, its composite's less its base's */
static void played(const csgGait* nom, const csgFootholdSet* s, const csgScheduleOptions* o,
                   double t, double p[NL]) {
  csg_scheduleEval(nom, o, t, p);
  for (int k = 0; k < s->n; k++) {
    const csgFoothold* f = &s->fh[k];
    if (t < f->w0 || t >= f->tail + o->ramp) continue;
    double pc[NL], pb[NL];
    csg_scheduleEval(f->cand[0].comp, o, t, pc);
    csg_scheduleEval(f->cand[0].base, o, t, pb);
    for (int l = 0; l < NL; l++) {
      if ((f->legs >> (l / 12)) & 1u) p[l] = fmax(0.0, p[l] + (pc[l] - pb[l]));
    }
  }
}

/* the largest difference (MPa) of the played schedule's legs' columns from the hand
 * composite's over 0..3 s every 1 ms */
static double compareOver(const csgGait* nom, const csgFootholdSet* s, const csgGait* hand,
                          double ramp, unsigned legs) {
  csgScheduleOptions o = csg_defaultScheduleOptions();
  o.ramp = ramp;
  double worst = 0;
  for (int i = 0; i <= 3000; i++) {
    const double t = 1e-3 * i;
    double p[NL], q[NL];
    played(nom, s, &o, t, p);
    csg_scheduleEval(hand, &o, t, q);
    for (int l = 0; l < NL; l++) {
      if ((legs >> (l / 12)) & 1u) {
        worst = fmax(worst, fabs(p[l] - q[l]));
      }
    }
  }
  return worst;
}

/* One foothold (legs D, H; window 1.0..1.5 s; the candidate half the nominal's pressures) and
 * a chain (H's next step 1.3..1.8 s, a quarter): at ramps 0 (steps), 0.05 (the rows' spacing),
 * 0.2 and 0.5 s (ten rows: the case the player refused until margin18) the played command is
 * the hand-made table's schedule. Tolerance: the schedule sums at most 11 changes of <= 0.3
 * MPa, so rounding stays below 11 x 0.3 x 2.2e-16 ~ 1e-15 MPa; 1e-13 leaves room, while a
 * slice started from vented (the player's error before) is off by up to 0.3 MPa. */
static void test_composeAnyRamp(void) {
  csgGait* nom = nominalTable();
  const unsigned dh = (1u << 3) | (1u << 7), h = 1u << 7;
  const unsigned legs2[2] = {dh, h};
  const double w2[2][2] = {{1.0, 1.5}, {1.3, 1.8}};
  const double scale2[2] = {0.5, 0.25};
  const double ramps[4] = {0, 0.05, 0.2, 0.5};
  for (int n = 1; n <= 2; n++) {
    csgFootholdSet* s = footholds(nom, n, legs2, w2, scale2);
    csError err;
    cs_errorClear(&err);
    CS_EXPECT(csg_footholdCompose(s, nom, &err) == CS_OK);
    csgGait* hand = handComposite(nom, s);
    for (int r = 0; r < 4; r++) {
      const double worst = compareOver(nom, s, hand, ramps[r], dh);
      printf("%d foothold(s), ramp %.2f s: largest difference from the hand-made table %.2g "
             "MPa\n", n, ramps[r], worst);
      CS_EXPECT(worst < 1e-13);
    }
    /* the composite's difference is 0 before W0 and one ramp after its last row, so the player
     * may skip it there */
    CS_EXPECT(s->fh[0].tail >= s->fh[0].w1 && s->fh[0].tail < s->fh[0].w1 + 0.1 + 1e-12);
    csg_gaitDestroy(hand);
    csg_footholdDestroy(s);
  }
  csg_gaitDestroy(nom);
}


/* a candidate whose rows are not the nominal's (0.025 s later): with ramp 0 the played
 * command is the candidate's step value inside the window, the nominal's outside (the
 * definition, independent of how the composite is built) */
static void test_composeOffsetRows(void) {
  csgGait* nom = nominalTable();
  const unsigned dh = (1u << 3) | (1u << 7);
  const double w[1][2] = {{1.0, 1.5}};
  const double scale[1] = {0.5};
  csgFootholdSet* s = footholds(nom, 1, &dh, w, scale);
  csgGait* c = s->fh[0].cand[0].table;
  for (int i = 0; i < c->nrow; i++) c->time[i] += 0.025; /* 0.975 .. 1.625 */
  CS_EXPECT(csg_footholdCompose(s, nom, NULL) == CS_OK);
  csgScheduleOptions o = csg_defaultScheduleOptions();
  o.ramp = 0;
  int ok = 1;
  for (int i = 0; i <= 300; i++) {
    const double t = 0.01 * i + 0.0005;
    double p[NL];
    played(nom, s, &o, t, p);
    const int inside = t >= 1.0 && t < 1.5;
    const csgGait* g = inside ? c : nom;
    int row = -1;
    while (row + 1 < g->nrow && g->time[row + 1] <= t) row++;
    for (int l = 3 * 12; l < 4 * 12; l++) {
      const double want = row < 0 ? 0 : g->pressure[NL * row + l];
      if (fabs(p[l] - want) > 1e-15) ok = 0;
    }
  }
  CS_EXPECT(ok);
  csg_footholdDestroy(s);
  csg_gaitDestroy(nom);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_hipAheadKeepsThePlannedLanding);
  CS_RUN(test_edgeBetweenTakesTheFurther);
  CS_RUN(test_fitsAndNoEdges);
  CS_RUN(test_readGood);
  CS_RUN(test_readChain);
  CS_RUN(test_readBad);
  CS_RUN(test_composeAnyRamp);
  CS_RUN(test_composeOffsetRows);
  return cs_testSummary();
}

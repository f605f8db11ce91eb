/* test_gaits_foothold.c: footholds (gaits_foothold.h): the choice on the two closed cases of
 * the design (docs/studies/obstacle.md, "A foothold that reads the support") and the rules
 * around them, then the .foothold reader on a good file and on every bad-input case, each a
 * one-line message naming the file, the line and the cause. Files go to the working directory
 * (the build tree). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "gaits_foothold.h"


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


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_hipAheadKeepsThePlannedLanding);
  CS_RUN(test_edgeBetweenTakesTheFurther);
  CS_RUN(test_fitsAndNoEdges);
  CS_RUN(test_readGood);
  CS_RUN(test_readChain);
  CS_RUN(test_readBad);
  return cs_testSummary();
}

/* test_gaits_gate.c: the landing gate's file and rule (gaits_gate.h) and the schedule with
 * held rows (gaits_schedule.h csg_scheduleEvalHeld):
 *  - the shipped gaits/obstacle.gate reads: its design line and 75 gates, the first at 2.6 s
 *    waiting for A, E;
 *  - csg_gateDown: a pair as near its command as the design (within PTOL) is down, one
 *    chamber further behind is not, other legs do not count;
 *  - held rows: with no offset the held schedule is csg_scheduleEval's (to rounding); an
 *    offset o after a break delays every later row by o (p_held(t + o) = p(t) once the rows
 *    before the break have arrived), and rows past t_issued are not played;
 *  - the `crawl` statement reads its five numbers; bad ones (count, range, a gate after it or
 *    before it in time, a second one) fail naming file:line; the shipped gate has one (12
 *    slots, ship11);
 *  - csg_gateCrawlSkip, the crawl's rule on synthetic support positions: it ends the crawl
 *    (skips N - 1 - j slots) exactly when z + CARRY >= ZEND - (z - zprev) / 2, at boundaries of
 *    the release's phase with j >= 2 only;
 *  - the `walk` statement (issue 33, obst13) reads its five numbers beside a crawl; bad ones
 *    (count, range, before the last gate, a crawl starting inside the walk, a walk after the
 *    crawl, a gate after it, a second one) fail naming file:line; the shipped gate has one
 *    (5 slots before the turn, obst13);
 *  - csg_gateWalkSkip, the same rule on x with the walk's numbers: it ends the walk exactly
 *    when x + CARRY >= XEND - (x - xprev) / 2, at boundaries of its end's phase with j >= 2
 *    only, and never without the statement (the crawl's numbers do not count);
 *  - a gate's `x XMIN` (issue 33, ramp11): it reads, a gate without it has none (-inf), bad
 *    ones fail naming file:line; csg_gateReady on synthetic pressures and support positions:
 *    ready only when the pair is down and the support stands at XMIN or past it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "gaits_csv.h"
#include "gaits_gate.h"
#include "gaits_schedule.h"


static const char* src(const char* rel, char* buf, size_t n) {
  const char* s = getenv("CS_SOURCE_DIR");
  snprintf(buf, n, "%s/%s", s ? s : "../../..", rel);
  return buf;
}


static void test_shippedGateReads(void) {
  char path[1024];
  csError err;
  csgGateSet* s = csg_gateRead(src("gaits/obstacle.gate", path, sizeof path), &err);
  CS_EXPECT(s != NULL);
  if (!s) {
    fprintf(stderr, "  %s\n", err.msg);
    return;
  }
  char legs[9];
  csg_gateLegs(s->gate[0].legs, legs);
  CS_EXPECT(s->n == 75 && s->ramp == 0.05 && s->lag == 0.02 && s->ptol == 0.005 &&
            s->maxwait == 0.6);
  CS_EXPECT(s->gate[0].t == 2.6 && !strcmp(legs, "AE") && s->time[0] == 2.6);
  for (int k = 1; k < s->n; k++) CS_EXPECT(s->time[k] >= s->time[k - 1]);
  printf("gaits/obstacle.gate: %d gates, the first at %g s waiting for %s\n", s->n, s->gate[0].t,
         legs);
  csg_gateDestroy(s);
}


static void test_downRule(void) {
  csgGate g;
  memset(&g, 0, sizeof g);
  g.legs = 1u << 3; /* D */
  double p[CSG_NLABEL] = {0}, v[CSG_NLABEL] = {0};
  for (int c = 36; c < 48; c++) {
    v[c] = 0.2;            /* the command */
    g.p_design[c] = 0.19;  /* the design is 0.01 behind */
    p[c] = 0.186;          /* 0.014 behind: within 0.005 of the design's 0.01 */
  }
  CS_EXPECT(csg_gateDown(&g, p, v, 0.005) == 1);
  p[40] = 0.184; /* 0.016 behind: 0.006 more than the design */
  CS_EXPECT(csg_gateDown(&g, p, v, 0.005) == 0);
  CS_EXPECT(csg_gateDown(&g, p, v, 0.007) == 1);
  p[40] = 0.186;
  p[0] = 0; v[0] = 0.3; /* leg A far behind: not waited for */
  CS_EXPECT(csg_gateDown(&g, p, v, 0.005) == 1);
}


static void test_heldRowsDelay(void) {
  char path[1024];
  csError err;
  csgGait* g = csg_gaitRead(src("gaits/obstacle.csv", path, sizeof path), NULL, &err);
  CS_EXPECT(g != NULL);
  if (!g) return;
  csgScheduleOptions o = csg_defaultScheduleOptions();
  o.ramp = 0.05;
  const double brk[1] = {2.6};
  const double zero[2] = {0, 0}, off[2] = {0, 0.037};
  double a[CSG_NLABEL], b[CSG_NLABEL];
  double worst = 0, worst_shift = 0;
  int moved = 0;
  for (double t = 0; t < 6; t += 0.00731) {
    csg_scheduleEval(g, &o, t, a);
    CS_EXPECT(csg_scheduleEvalHeld(g, &o, t, 1, brk, zero, INFINITY, b) == CS_OK);
    for (int l = 0; l < CSG_NLABEL; l++) worst = fmax(worst, fabs(a[l] - b[l]));
    if (t > 2.6 + 0.05) { /* the rows before the break have arrived */
      csg_scheduleEvalHeld(g, &o, t + off[1], 1, brk, off, INFINITY, b);
      for (int l = 0; l < CSG_NLABEL; l++) worst_shift = fmax(worst_shift, fabs(a[l] - b[l]));
      csg_scheduleEval(g, &o, t + off[1], b);
      for (int l = 0; l < CSG_NLABEL; l++) moved |= fabs(a[l] - b[l]) > 1e-3;
    }
  }
  printf("held rows: no offset %.3g MPa from the schedule; offset 0.037 s: %.3g MPa from the "
         "schedule 0.037 s earlier\n", worst, worst_shift);
  CS_EXPECT(worst < 1e-12 && worst_shift < 1e-12 && moved);
  /* rows past t_issued are not played: held at 2.6 s, the row at 2.65 never starts */
  csg_scheduleEval(g, &o, 2.6 + 0.05, a);
  csg_scheduleEvalHeld(g, &o, 3.0, 1, brk, off, 2.6 + 1e-12, b);
  double d = 0;
  for (int l = 0; l < CSG_NLABEL; l++) d = fmax(d, fabs(a[l] - b[l]));
  CS_EXPECT(d < 1e-12);
  CS_EXPECT(csg_scheduleEvalHeld(g, &o, 1.0, 1, NULL, off, INFINITY, b) == CS_ERR_ARG);
  csg_gaitDestroy(g);
}


#define DESIGN "design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\n"

/* a bad gate file: its text and where the error must point (":LINE:") */
typedef struct {
  const char* text;
  const char* where;
} badGate;

/* each bad file fails to read, its message naming PREFIX_badK.gate:LINE */
static void expectBad(const char* prefix, const badGate* bad, size_t n) {
  for (size_t k = 0; k < n; k++) {
    char path[64], want[96];
    csError err;
    snprintf(path, sizeof path, "%s_bad%zu.gate", prefix, k);
    cs_testWriteText(path, bad[k].text);
    cs_errorClear(&err);
    csgGateSet* s = csg_gateRead(path, &err);
    snprintf(want, sizeof want, "%s%s", path, bad[k].where);
    CS_EXPECT(s == NULL && strstr(err.msg, want) != NULL);
    printf("%s\n", err.msg);
    csg_gateDestroy(s);
  }
}

static void test_crawlStatement(void) {
  csError err;
  cs_testWriteText("crawl_ok.gate", DESIGN "gate 2.6 AE\ncrawl 27.39 0.55 12 270 23 # z12\n");
  csgGateSet* s = csg_gateRead("crawl_ok.gate", &err);
  CS_EXPECT(s != NULL);
  if (s) {
    CS_EXPECT(s->n == 1 && s->crawl_n == 12 && s->crawl_t0 == 27.39 && s->crawl_tpz == 0.55 &&
              s->crawl_zend == 270 && s->crawl_carry == 23);
  }
  csg_gateDestroy(s);
  static const badGate kBad[] = {
      {DESIGN "gate 2.6 AE\ncrawl 27.39 0.55 12 270\n", ":3:"},          /* four numbers */
      {DESIGN "gate 2.6 AE\ncrawl 27.39 0.55 12.5 270 23\n", ":3:"},     /* N not whole */
      {DESIGN "gate 2.6 AE\ncrawl 27.39 0.55 2 270 23\n", ":3:"},        /* N < 3 */
      {DESIGN "gate 2.6 AE\ncrawl 27.39 0 12 270 23\n", ":3:"},          /* TPZ 0 */
      {DESIGN "gate 2.6 AE\ncrawl 27.39 0.55 12 270 -1\n", ":3:"},       /* CARRY < 0 */
      {DESIGN "gate 2.6 AE\ncrawl 2.0 0.55 12 270 23\n", ":3:"},         /* before the gate */
      {DESIGN "gate 2.6 AE\ncrawl 27.39 0.55 12 inf 23\n", ":3:"},       /* not finite */
      {DESIGN "crawl 27.39 0.55 12 270 23\ngate 2.6 AE\n", ":3:"},       /* a gate after it */
      {DESIGN "gate 2.6 AE\ncrawl 27 0.5 8 270 23\ncrawl 27 0.5 8 270 23\n", ":4:"},
  };
  expectBad("crawl", kBad, sizeof kBad / sizeof kBad[0]);
  char path[1024];
  s = csg_gateRead(src("gaits/obstacle.gate", path, sizeof path), &err);
  /* the shipped gate asks for it since ship11 (tools/obstacle_gait.py's default --crawl-max 12,
   * the statement's line in the file: 12 slots of 0.55 s from 28.49 s since obst13, whose walk
   * statement comes before it, to z 270 mm, carry 23) */
  CS_EXPECT(s != NULL && s->crawl_n == 12 && fabs(s->crawl_t0 - 28.49) < 1e-12 &&
            fabs(s->crawl_tpz - 0.55) < 1e-12 && s->crawl_zend == 270 && s->crawl_carry == 23);
  csg_gateDestroy(s);
}


static void test_crawlRule(void) {
  csgGateSet s;
  memset(&s, 0, sizeof s);
  s.crawl_n = 12;
  s.crawl_tpz = 0.55;
  s.crawl_zend = 270;
  s.crawl_carry = 23;
  /* slot j = 9 (2 left): a = 50, stop when z + 23 >= 270 - (z - zprev) / 2 = 245 + ..., i.e.
   * at z = 220 + 50: 270 - 25 = 245 <= 293: stop; at z = 196 (zprev 146): 219 < 245: go on */
  CS_EXPECT(csg_gateCrawlSkip(&s, 9, 270, 220) == 2);
  CS_EXPECT(csg_gateCrawlSkip(&s, 9, 196, 146) == 0);
  /* the edge: z + carry == zend - a / 2 stops (222 + 23 = 245 = 270 - 50 / 2, all exact in
   * binary), 0.5 mm less does not (244.5 < 270 - 49.5 / 2 = 245.25) */
  CS_EXPECT(csg_gateCrawlSkip(&s, 7, 222, 172) == 4);
  CS_EXPECT(csg_gateCrawlSkip(&s, 7, 221.5, 172) == 0);
  /* not a decision boundary: the other phase (an odd number of slots left), j < 2, the last */
  CS_EXPECT(csg_gateCrawlSkip(&s, 8, 1000, 0) == 0);
  CS_EXPECT(csg_gateCrawlSkip(&s, 1, 1000, 0) == 0);
  CS_EXPECT(csg_gateCrawlSkip(&s, 11, 1000, 0) == 0);
  s.crawl_n = 0; /* no statement: never */
  CS_EXPECT(csg_gateCrawlSkip(&s, 9, 1000, 0) == 0);
}


static void test_walkStatement(void) {
  csError err;
  cs_testWriteText("walk_ok.gate", DESIGN "gate 2.6 AE\nwalk 25.19 0.55 5 646 65 # wx1\n"
                   "crawl 28.49 0.55 12 270 23\n");
  csgGateSet* s = csg_gateRead("walk_ok.gate", &err);
  CS_EXPECT(s != NULL);
  if (s) {
    CS_EXPECT(s->n == 1 && s->walk_n == 5 && s->walk_t0 == 25.19 && s->walk_tp == 0.55 &&
              s->walk_xend == 646 && s->walk_carry == 65 && s->crawl_n == 12 &&
              s->crawl_t0 == 28.49);
  }
  csg_gateDestroy(s);
  static const badGate kBad[] = {
      {DESIGN "gate 2.6 AE\nwalk 25.19 0.55 5 646\n", ":3:"},       /* four numbers */
      {DESIGN "gate 2.6 AE\nwalk 25.19 0.55 5.5 646 65\n", ":3:"},  /* N not whole */
      {DESIGN "gate 2.6 AE\nwalk 25.19 0.55 2 646 65\n", ":3:"},    /* N < 3 */
      {DESIGN "gate 2.6 AE\nwalk 25.19 0 5 646 65\n", ":3:"},       /* TP 0 */
      {DESIGN "gate 2.6 AE\nwalk 25.19 0.55 5 646 -1\n", ":3:"},    /* CARRY < 0 */
      {DESIGN "gate 2.6 AE\nwalk 2.0 0.55 5 646 65\n", ":3:"},      /* before the gate */
      {DESIGN "gate 2.6 AE\nwalk 25.19 0.55 5 nan 65\n", ":3:"},    /* not finite */
      {DESIGN "walk 25.19 0.55 5 646 65\ngate 2.6 AE\n", ":3:"},    /* a gate after it */
      /* the crawl's first slot inside the walk (25.19 + 5 x 0.55 = 27.94 s) */
      {DESIGN "gate 2.6 AE\nwalk 25.19 0.55 5 646 65\ncrawl 27.39 0.55 12 270 23\n", ":4:"},
      {DESIGN "gate 2.6 AE\ncrawl 28.49 0.55 12 270 23\nwalk 25.19 0.55 5 646 65\n", ":4:"},
      {DESIGN "gate 2.6 AE\nwalk 25 0.5 5 646 65\nwalk 25 0.5 5 646 65\n", ":4:"},
  };
  expectBad("walk", kBad, sizeof kBad / sizeof kBad[0]);
  /* the shipped gate asks for it since obst13 (tools/obstacle_gait.py's default --walk-extra
   * 1: 5 slots of 0.55 s from 25.19 s before the turn, to x 646 mm, carry 65) */
  char path[1024];
  s = csg_gateRead(src("gaits/obstacle.gate", path, sizeof path), &err);
  CS_EXPECT(s != NULL && s->walk_n == 5 && fabs(s->walk_t0 - 25.19) < 1e-12 &&
            fabs(s->walk_tp - 0.55) < 1e-12 && s->walk_xend == 646 && s->walk_carry == 65);
  csg_gateDestroy(s);
}


static void test_walkRule(void) {
  csgGateSet s;
  memset(&s, 0, sizeof s);
  s.walk_n = 5;
  s.walk_tp = 0.55;
  s.walk_xend = 646;
  s.walk_carry = 65;
  /* slot j = 2 (2 left): the shipped nominal's 586.2 mm after 516.8 (a = 69.4): 651.2 >=
   * 646 - 34.7: end; the 0.5 s ramp's 547.4 after 494.4 (a = 53): 612.4 < 619.5: walk on
   * (docs/notes/obstacle.md "obst13") */
  CS_EXPECT(csg_gateWalkSkip(&s, 2, 586.2, 516.8) == 2);
  CS_EXPECT(csg_gateWalkSkip(&s, 2, 547.4, 494.4) == 0);
  /* the edge, exact in binary: 531 + 65 = 596 = 646 - 100 / 2 ends, 0.5 mm less does not
   * (595.5 < 646 - 99.5 / 2 = 596.25) */
  CS_EXPECT(csg_gateWalkSkip(&s, 2, 531, 431) == 2);
  CS_EXPECT(csg_gateWalkSkip(&s, 2, 530.5, 431) == 0);
  /* not a decision boundary: the other phase, j < 2, the last slot */
  CS_EXPECT(csg_gateWalkSkip(&s, 3, 1000, 0) == 0);
  CS_EXPECT(csg_gateWalkSkip(&s, 0, 1000, 0) == 0);
  CS_EXPECT(csg_gateWalkSkip(&s, 4, 1000, 0) == 0);
  /* a crawl's numbers are not the walk's: without the statement, never */
  s.walk_n = 0;
  s.crawl_n = 5;
  s.crawl_zend = 646;
  s.crawl_carry = 65;
  CS_EXPECT(csg_gateWalkSkip(&s, 2, 1000, 0) == 0);
  CS_EXPECT(csg_gateCrawlSkip(&s, 2, 1000, 0) == 2);
}


static void test_supportX(void) {
  csError err;
  cs_testWriteText("x_ok.gate", DESIGN "gate 2.6 AE\ngate 3.4 DH x 12.5  # a set-down\n");
  csgGateSet* s = csg_gateRead("x_ok.gate", &err);
  CS_EXPECT(s != NULL);
  if (s) {
    CS_EXPECT(s->n == 2 && isinf(s->gate[0].xmin) && s->gate[0].xmin < 0 &&
              s->gate[1].xmin == 12.5 && s->gate[1].t == 3.4);
  }
  csg_gateDestroy(s);
  static const char* kBad[] = {
      DESIGN "gate 2.6 AE x\n",        /* no number */
      DESIGN "gate 2.6 AE x twelve\n", /* not a number */
      DESIGN "gate 2.6 AE x nan\n",    /* not finite */
      DESIGN "gate 2.6 AE y 12\n",     /* not `x` */
      DESIGN "gate 2.6 AE x 12 13\n",  /* one word too many */
  };
  for (size_t k = 0; k < sizeof kBad / sizeof kBad[0]; k++) {
    char path[64], want[96];
    snprintf(path, sizeof path, "x_bad%zu.gate", k);
    cs_testWriteText(path, kBad[k]);
    cs_errorClear(&err);
    s = csg_gateRead(path, &err);
    snprintf(want, sizeof want, "%s:2:", path);
    CS_EXPECT(s == NULL && strstr(err.msg, want) != NULL);
    printf("%s\n", err.msg);
    csg_gateDestroy(s);
  }
  /* the rule: leg A (chambers 0..11) commanded 0.2 MPa, designed at 0.19 */
  csgGate g;
  memset(&g, 0, sizeof g);
  g.legs = 1u;
  g.xmin = 100;
  double p[CSG_NLABEL] = {0}, v[CSG_NLABEL] = {0};
  for (int c = 0; c < 12; c++) {
    v[c] = 0.2;
    g.p_design[c] = 0.19;
    p[c] = 0.195;
  }
  CS_EXPECT(csg_gateReady(&g, p, v, 0.005, 100) == 1);  /* down, at XMIN */
  CS_EXPECT(csg_gateReady(&g, p, v, 0.005, 99.5) == 0); /* down, 0.5 mm short */
  p[3] = 0.18;                                          /* one chamber behind the design */
  CS_EXPECT(csg_gateReady(&g, p, v, 0.005, 150) == 0);
  g.xmin = -INFINITY; /* no `x`: the pressures alone */
  CS_EXPECT(csg_gateReady(&g, p, v, 0.005, -1e9) == 0);
  p[3] = 0.195;
  CS_EXPECT(csg_gateReady(&g, p, v, 0.005, -1e9) == 1);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_shippedGateReads);
  CS_RUN(test_downRule);
  CS_RUN(test_crawlStatement);
  CS_RUN(test_crawlRule);
  CS_RUN(test_walkStatement);
  CS_RUN(test_walkRule);
  CS_RUN(test_supportX);
  CS_RUN(test_heldRowsDelay);
  return cs_testSummary();
}

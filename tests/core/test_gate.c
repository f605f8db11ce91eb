/* test_gate.c: the landing gate's player (core/sim_gate.c, `--gate`, the obstacle scene's
 * default gaits/obstacle.gate) on the obstacle scene with cheap rod legs (2 elements per
 * segment: the gate reads the chamber pressures only, which follow their command whatever the
 * legs do, so the waits do not depend on the legs' discretisation):
 *  - the nominal (valves as designed) never waits: its first 2.8 s, past the first gate at
 *    2.6 s, are the `--gate none` run bit for bit (every state value but the gate's appended
 *    part, each step), the gate released with no hold;
 *  - the pneumatic lag x2 (0.04 s) waits, and its first waits equal the prototype's model
 *    (docs/bench/obst_2026-12-06e/pneu.py, the pneumatics alone, in Python) as committed in
 *    tests/core/data/gate_tau2x_waits.txt (2.60 s A, E; 3.40 s D, H; 4.20 s C, G), within one
 *    1 ms step;
 *  - a restore repeats a wait: from a state before the first wait and from one inside it, two
 *    restores run to the same state bit for bit, with the same wait as the run that saved them;
 *    a gate part that is not a gate state is refused;
 *  - the crawl statement (a synthetic crawl of 5 slots of 0.1 s from 1.5 s, decided at 1.8 s
 *    after slot 2): with an end point no support reaches it goes on through every boundary
 *    and never skips; with one every support has passed it ends at the first decision and
 *    skips 2 slots, and the two runs are the same up to the decision and differ after it (the
 *    valves play the table 0.2 s on); two restores from before the decision run to the same
 *    state bit for bit and make the uncut run's decision; a crawl part that is not a state is refused;
 *  - the walk statement (obst13; a synthetic walk of 5 slots of 0.1 s from 1.0 s, decided at
 *    1.3 s after slot 2, before a crawl of 5 slots from 1.6 s): with an end no support
 *    reaches it reads all three boundaries and never skips, and the crawl decides on the
 *    table's clock (run 1.9 s); with one every support has passed it skips 2 slots at 1.3 s and
 *    the crawl decides 0.2 s earlier on the run's clock (1.7 s); the runs are the same up to
 *    the walk's decision and differ after it; two restores from before it run to the same
 *    state bit for bit with the uncut run's decisions; a walk part that is not a state is
 *    refused;
 *  - a gate's `x XMIN` (ramp11): with an XMIN every support has passed the run is the same
 *    gate's without it bit for bit; with one no support reaches it holds the file's maxwait;
 *    with XMIN 0.5 mm past where the support stands when the gate is reached it holds, and
 *    at every step's start it holds exactly while the measured support x is short of XMIN
 *    (until maxwait); two restores from inside that wait run to the same state bit for bit;
 *  - a malformed .gate file fails cs_simCreate with a message naming the file and line; a
 *    user's gait gets no gate by default. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crawlsim.h"
#include "cs_test.h"

#define NGATE 75 /* gates in gaits/obstacle.gate */
#define NCRAWL 6 /* its crawl and walk statements' parts of the state (boundaries read, z or x,
                  * skip: ship11, obst13) */
#define STEP 1e-3


static csRunDef cheapDef(void) {
  csRunDef d = cs_defaultRunDef();
  d.scene = "obstacle";
  d.legs = "rod"; /* the scene's default is strain; the cheap rod does for the pressures */
  d.links = 2;
  return d;
}


static csSim* make(const char* gate, double tau) {
  csRunDef d = cheapDef();
  d.gate = gate;
  if (tau > 0) d.tau = tau;
  csError err;
  cs_errorClear(&err);
  csSim* s = cs_simCreate(&d, &err);
  if (!s) fprintf(stderr, "  cs_simCreate: %s\n", err.msg);
  return s;
}


static void runTo(csSim* s, double t) {
  csError err;
  csStatus st = cs_simRunUntil(s, t, &err);
  CS_EXPECT(st == CS_OK);
  if (st != CS_OK) fprintf(stderr, "  %s\n", err.msg);
}


/* the nominal never waits: the open-loop run bit for bit through the first gate */
static void test_nominalNoWaitBitForBit(void) {
  csSim* a = make("none", 0);
  csSim* b = make(NULL, 0); /* the scene's default: gaits/obstacle.gate */
  CS_EXPECT(a && b);
  if (!a || !b) {
    cs_simDestroy(a);
    cs_simDestroy(b);
    return;
  }
  const int na = cs_simStateSize(a), nb = cs_simStateSize(b);
  CS_EXPECT(nb == na + 3 + NGATE + NCRAWL); /* next gate, hold, wait, the released waits, the
                                               crawl's decision */
  double* xa = malloc(sizeof(double) * (size_t)nb);
  double* xb = malloc(sizeof(double) * (size_t)nb);
  csError err;
  int same = 1, n = 0;
  while (same && cs_simTime(b) < 2.8 - 1e-9) {
    CS_EXPECT(cs_simStep(a, &err) == CS_OK);
    CS_EXPECT(cs_simStep(b, &err) == CS_OK);
    cs_simStateGet(a, xa);
    cs_simStateGet(b, xb);
    same = !memcmp(xa, xb, sizeof(double) * (size_t)na);
    n++;
  }
  CS_EXPECT(same);
  /* the gate at 2.6 s was reached and released, nothing held */
  CS_EXPECT(xb[na] == 1 && xb[na + 1] == 0 && xb[na + 2] == 0 && xb[na + 3] == 0);
  printf("nominal: %d steps identical to --gate none; gates released %g, hold %g s\n", n,
         xb[na], xb[na + 1]);
  free(xa);
  free(xb);
  cs_simDestroy(a);
  cs_simDestroy(b);
}


/* the committed waits of the prototype's model: T, legs, wait; returns how many */
static int readWaits(double* t, char legs[][9], double* w, int max) {
  const char* src = getenv("CS_SOURCE_DIR");
  char path[1024], line[256];
  snprintf(path, sizeof path, "%s/tests/core/data/gate_tau2x_waits.txt", src ? src : "../../..");
  FILE* f = fopen(path, "r");
  CS_EXPECT(f != NULL);
  int n = 0;
  while (f && n < max && fgets(line, sizeof line, f)) {
    if (line[0] == '#') continue;
    if (sscanf(line, "%lf %8s %lf", &t[n], legs[n], &w[n]) == 3) n++;
  }
  if (f) fclose(f);
  return n;
}


/* the gate's part of a state of size n */
static const double* gatePart(const double* x, int n) { return x + n - 3 - NGATE - NCRAWL; }


/* lag x2: the waits equal the model's; restores repeat a wait */
static void test_lagWaitsAsModelAndRestores(void) {
  double tm[8], wm[8];
  char lm[8][9];
  const int nm = readWaits(tm, lm, wm, 8);
  CS_EXPECT(nm == 3);
  csSim* s = make(NULL, 0.04);
  CS_EXPECT(s != NULL);
  if (!s || nm < 1) {
    cs_simDestroy(s);
    return;
  }
  const int n = cs_simStateSize(s);
  double* x0 = malloc(sizeof(double) * (size_t)n);
  double* x1 = malloc(sizeof(double) * (size_t)n);
  double* x2 = malloc(sizeof(double) * (size_t)n);
  double* y1 = malloc(sizeof(double) * (size_t)n);
  double* y2 = malloc(sizeof(double) * (size_t)n);
  csError err;
  runTo(s, 2.59);
  cs_simStateGet(s, x0); /* before the first gate */
  runTo(s, tm[0] + 0.5 * wm[0]);
  cs_simStateGet(s, x1); /* inside its wait */
  CS_EXPECT(gatePart(x1, n)[0] == 0 && gatePart(x1, n)[2] > 0);
  runTo(s, 2.7);
  cs_simStateGet(s, x2); /* released */
  const double w0 = gatePart(x2, n)[3];
  CS_EXPECT(gatePart(x2, n)[0] == 1 && w0 > 0);
  /* two restores of each state: the same run to 2.7 s bit for bit, the same wait */
  const double* from[2] = {x0, x1};
  for (int k = 0; k < 2; k++) {
    CS_EXPECT(cs_simStateSet(s, from[k], &err) == CS_OK);
    runTo(s, 2.7);
    cs_simStateGet(s, y1);
    CS_EXPECT(cs_simStateSet(s, from[k], &err) == CS_OK);
    runTo(s, 2.7);
    cs_simStateGet(s, y2);
    CS_EXPECT(!memcmp(y1, y2, sizeof(double) * (size_t)n));
    CS_EXPECT(gatePart(y1, n)[0] == 1 && gatePart(y1, n)[3] == w0);
    printf("restore from %s: wait %.4f s again (the run that saved it: %.4f s)\n",
           k ? "inside the wait" : "before the gate", gatePart(y1, n)[3], w0);
  }
  /* a gate part that is not a gate state */
  memcpy(y1, x2, sizeof(double) * (size_t)n);
  y1[n - 3 - NGATE - NCRAWL] = 0.5;
  CS_EXPECT(cs_simStateSet(s, y1, &err) == CS_ERR_ARG && strstr(err.msg, "gate"));
  y1[n - 3 - NGATE - NCRAWL] = 1;
  y1[n - 2 - NGATE - NCRAWL] = -1;
  CS_EXPECT(cs_simStateSet(s, y1, &err) == CS_ERR_ARG);
  /* on to the third gate: each wait as the model's, within one step */
  CS_EXPECT(cs_simStateSet(s, x2, &err) == CS_OK);
  runTo(s, 4.3);
  cs_simStateGet(s, y1);
  const double* g = gatePart(y1, n);
  CS_EXPECT(g[0] == nm);
  double sum = 0;
  for (int k = 0; k < nm; k++) {
    printf("gate %d at %.2f s waiting for %s: %.4f s; the model %.4f s\n", k + 1, tm[k], lm[k],
           g[3 + k], wm[k]);
    CS_EXPECT(wm[k] > 0.01); /* the model waits: the comparison is not trivial */
    CS_EXPECT_NEAR(g[3 + k], wm[k], 1.01 * STEP, 0);
    sum += g[3 + k];
  }
  CS_EXPECT_NEAR(g[1], sum, 1e-12, 0);
  free(x0);
  free(x1);
  free(x2);
  free(y1);
  free(y2);
  cs_simDestroy(s);
}


/* the crawl's decision in a run, and across a restore */
#define CRAWL_GATE(zend) \
  "design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\ngate 0.2 AE\ncrawl 1.5 0.1 5 " zend " 0\n"

static void test_crawlDecidesAndRestores(void) {
  cs_testWriteText("crawl_never.gate", CRAWL_GATE("1e6"));
  cs_testWriteText("crawl_stop.gate", CRAWL_GATE("-1e6"));
  csSim* go = make("crawl_never.gate", 0);
  csSim* st = make("crawl_stop.gate", 0);
  CS_EXPECT(go && st);
  if (!go || !st) {
    cs_simDestroy(go);
    cs_simDestroy(st);
    return;
  }
  const int n = cs_simStateSize(st);
  CS_EXPECT(n == cs_simStateSize(go));
  double* buf = malloc(sizeof(double) * 6 * (size_t)n); /* six states */
  CS_EXPECT(buf != NULL);
  if (!buf) return;
  double *a = buf, *b = buf + n, *x = buf + 2 * n, *u = buf + 3 * n, *y = buf + 4 * n;
  double* y0 = buf + 5 * n;
  csError err;
  /* before the decision (1.8 s) the two runs are one */
  runTo(go, 1.75);
  runTo(st, 1.75);
  cs_simStateGet(go, a);
  cs_simStateGet(st, x);
  CS_EXPECT(!memcmp(a, x, sizeof(double) * (size_t)n));
  CS_EXPECT(x[n - 3] == 1 && x[n - 1] == 0); /* the boundary after slot 0 read, no skip */
  runTo(go, 2.1);
  runTo(st, 1.9);
  cs_simStateGet(go, a);
  cs_simStateGet(st, u);
  /* never: all three boundaries (slots 0, 2, 4) read, no skip; stop: two read, 2 slots on */
  CS_EXPECT(a[n - 3] == 3 && a[n - 1] == 0);
  CS_EXPECT(u[n - 3] == 2 && u[n - 1] == 2 * 0.1 && isfinite(u[n - 2]));
  printf("crawl never ends: %g boundaries, skip %g s; ends at once: %g boundaries, skip %g s "
         "(support z %.4f mm at the decision)\n", a[n - 3], a[n - 1], u[n - 3], u[n - 1],
         u[n - 2]);
  /* the skip plays: at 1.9 s the chambers differ from the run that did not skip */
  runTo(go, 1.9);
  cs_simStateGet(go, b);
  double dp = 0;
  for (int i = 2; i < 2 + 96; i++) dp = fmax(dp, fabs(b[i] - u[i]));
  printf("chamber pressures 0.1 s after the skip: %.4g MPa from the unskipped run\n", dp);
  CS_EXPECT(dp > 1e-3);
  /* a restore from before the decision, twice: the same state at 1.9 s bit for bit, and the
   * uncut run's decision (a restore restarts the pneumatics' integrator, core/sim_state.c, so
   * the bodies match the uncut run's to its tolerance, not bit for bit; the checkpoint's
   * resume, which the uncut run matches, is test_checkpoint's) */
  for (int k = 0; k < 2; k++) {
    CS_EXPECT(cs_simStateSet(st, x, &err) == CS_OK);
    runTo(st, 1.9);
    cs_simStateGet(st, k ? y : y0);
  }
  CS_EXPECT(!memcmp(y, y0, sizeof(double) * (size_t)n));
  CS_EXPECT(y[n - 3] == u[n - 3] && y[n - 1] == u[n - 1]);
  printf("restored twice: bit for bit; decision z %.6f mm (the uncut run's %.6f mm)\n", y[n - 2],
         u[n - 2]);
  /* a crawl part that is not a state */
  memcpy(y, u, sizeof(double) * (size_t)n);
  y[n - 3] = 0.5;
  CS_EXPECT(cs_simStateSet(st, y, &err) == CS_ERR_ARG && strstr(err.msg, "gate"));
  y[n - 3] = 2;
  y[n - 1] = -0.1;
  CS_EXPECT(cs_simStateSet(st, y, &err) == CS_ERR_ARG);
  free(buf);
  cs_simDestroy(go);
  cs_simDestroy(st);
}


/* the walk's decision, then the crawl's on the clock it leaves, in a run and across a restore;
 * the state's last three values are the walk's (boundaries read, x, skip), the three before
 * them the crawl's */
#define WALK_GATE(xend) \
  "design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\ngate 0.2 AE\nwalk 1.0 0.1 5 " xend \
  " 0\ncrawl 1.6 0.1 5 -1e6 0\n"

static void test_walkDecidesThenCrawl(void) {
  cs_testWriteText("walk_never.gate", WALK_GATE("1e6"));
  cs_testWriteText("walk_stop.gate", WALK_GATE("-1e6"));
  csSim* go = make("walk_never.gate", 0);
  csSim* st = make("walk_stop.gate", 0);
  CS_EXPECT(go && st);
  const int n = go && st ? cs_simStateSize(st) : 0;
  double* buf = n ? malloc(sizeof(double) * 5 * (size_t)n) : NULL;
  CS_EXPECT(buf != NULL);
  if (!buf) {
    cs_simDestroy(go);
    cs_simDestroy(st);
    return;
  }
  double *a = buf, *x = buf + n, *u = buf + 2 * n, *y = buf + 3 * n, *y0 = buf + 4 * n;
  csError err;
  /* before the walk's decision (1.3 s) the two runs are one */
  runTo(go, 1.25);
  runTo(st, 1.25);
  cs_simStateGet(go, a);
  cs_simStateGet(st, x);
  CS_EXPECT(cs_simStateSize(go) == n && !memcmp(a, x, sizeof(double) * (size_t)n));
  CS_EXPECT(x[n - 3] == 1 && x[n - 1] == 0); /* the boundary after slot 0 read, no skip */
  /* 1.68 s: the stopped walk plays the table 0.2 s on (A, E lift from 1.8 s: 1.88 s), the
   * other not yet and has read all three boundaries (slots 0, 2, 4); the crawl's first
   * boundary (table 1.7 s) is behind the stopped run's clock only... */
  runTo(go, 1.68);
  runTo(st, 1.68);
  cs_simStateGet(go, a);
  cs_simStateGet(st, u);
  CS_EXPECT(a[n - 3] == 3 && a[n - 1] == 0 && u[n - 3] == 2 && u[n - 1] == 2 * 0.1);
  CS_EXPECT(u[n - 6] == 1 && u[n - 4] == 0 && a[n - 6] == 0);
  double dp = 0;
  for (int i = 2; i < 2 + 96; i++) dp = fmax(dp, fabs(a[i] - u[i]));
  printf("walk: never ends %g boundaries, skip %g s; ends at once %g boundaries, skip %g s "
         "(x %.4f mm); chambers %.4g MPa apart at 1.68 s\n", a[n - 3], a[n - 1], u[n - 3],
         u[n - 1], u[n - 2], dp);
  CS_EXPECT(dp > 1e-3);
  /* ...and it decides on the table's clock: at run 1.7 s after the walk's skip (table 1.9 s),
   * at run 1.9 s without it; each skips its 2 slots */
  runTo(st, 1.72);
  cs_simStateGet(st, u);
  CS_EXPECT(u[n - 6] == 2 && u[n - 4] == 2 * 0.1);
  runTo(go, 1.88);
  cs_simStateGet(go, a);
  CS_EXPECT(a[n - 6] == 1 && a[n - 4] == 0);
  runTo(go, 1.92);
  cs_simStateGet(go, a);
  CS_EXPECT(a[n - 6] == 2 && a[n - 4] == 2 * 0.1);
  /* two restores from before the walk's decision: bit for bit, the uncut run's decisions */
  for (int k = 0; k < 2; k++) {
    CS_EXPECT(cs_simStateSet(st, x, &err) == CS_OK);
    runTo(st, 1.72);
    cs_simStateGet(st, k ? y : y0);
  }
  CS_EXPECT(!memcmp(y, y0, sizeof(double) * (size_t)n));
  CS_EXPECT(y[n - 3] == u[n - 3] && y[n - 1] == u[n - 1] && y[n - 6] == u[n - 6] &&
            y[n - 4] == u[n - 4]);
  /* a walk part that is not a state */
  y[n - 3] = 6; /* more boundaries than slots */
  CS_EXPECT(cs_simStateSet(st, y, &err) == CS_ERR_ARG && strstr(err.msg, "gate"));
  free(buf);
  cs_simDestroy(go);
  cs_simDestroy(st);
}


/* a gate's `x XMIN`: one gate at 4.2 s (C, G's lift in the walk), maxwait 0.3 s */
#define XGATE(x) "design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.3\ngate 4.2 CG" x "\n"
#define XT 4.2
#define XWAIT 0.3

static void test_supportXHolds(void) {
  char text[256];
  cs_testWriteText("x_plain.gate", XGATE(""));
  cs_testWriteText("x_free.gate", XGATE(" x -1e6"));
  cs_testWriteText("x_never.gate", XGATE(" x 1e6"));
  csSim* plain = make("x_plain.gate", 0);
  csSim* fr = make("x_free.gate", 0);
  csSim* nv = make("x_never.gate", 0);
  CS_EXPECT(plain && fr && nv);
  if (!plain || !fr || !nv) {
    cs_simDestroy(plain);
    cs_simDestroy(fr);
    cs_simDestroy(nv);
    return;
  }
  const int n = cs_simStateSize(fr);
  double* buf = malloc(sizeof(double) * 5 * (size_t)n);
  CS_EXPECT(buf != NULL);
  if (!buf) return;
  double *a = buf, *b = buf + n, *w = buf + 2 * n, *y0 = buf + 3 * n, *y1 = buf + 4 * n;
  csError err;
  /* where the support stands when the gate is reached (the plain run's, read now) */
  runTo(plain, XT);
  double pos[3], q[4];
  cs_simSupportPose(plain, pos, q);
  const double xmin = pos[0] + 0.5;
  snprintf(text, sizeof text, XGATE(" x %.17g"), xmin);
  cs_testWriteText("x_mid.gate", text);
  csSim* mid = make("x_mid.gate", 0);
  CS_EXPECT(mid != NULL);
  /* an XMIN every support has passed: the plain gate's run bit for bit */
  runTo(plain, XT + 0.4);
  runTo(fr, XT + 0.4);
  cs_simStateGet(plain, a);
  cs_simStateGet(fr, b);
  CS_EXPECT(!memcmp(a, b, sizeof(double) * (size_t)n));
  CS_EXPECT(b[n - 4] == 1 && b[n - 3] == 0); /* released, no hold (valves as designed) */
  /* one no support reaches: the file's maxwait, within one step */
  runTo(nv, XT + 0.4);
  cs_simStateGet(nv, w);
  CS_EXPECT(w[n - 4] == 1);
  CS_EXPECT_NEAR(w[n - 1], XWAIT, 1.01 * STEP, 0);
  printf("x -1e6: the plain gate's run bit for bit; x 1e6: held %.4f s (maxwait %g s)\n",
         w[n - 1], XWAIT);
  /* XMIN just past the support: held while x < XMIN at a step's start, released at the first
   * step that starts with x >= XMIN or at maxwait */
  int held = 0, bad = 0, saved = 0;
  double x_rel = 0;
  runTo(mid, XT - 0.01);
  while (mid && cs_simTime(mid) < XT + 0.4) {
    cs_simStateGet(mid, a);
    cs_simSupportPose(mid, pos, q);
    CS_EXPECT(cs_simStep(mid, &err) == CS_OK);
    cs_simStateGet(mid, b);
    if (a[n - 4] == 0 && b[n - 4] == 0 && b[n - 2] > 0) { /* held this step */
      held++;
      bad += pos[0] >= xmin;
      if (!saved && held == 3) {
        memcpy(y0, a, sizeof(double) * (size_t)n); /* a state inside the wait */
        saved = 1;
      }
    } else if (a[n - 4] == 0 && b[n - 4] == 1) { /* released this step */
      bad += pos[0] < xmin && a[n - 2] < XWAIT - 1e-9;
      x_rel = pos[0];
    }
  }
  CS_EXPECT(held > 0 && bad == 0 && saved);
  printf("x %.4f mm (0.5 past the support at the gate): held %d steps, %s at x %.4f mm\n", xmin,
         held, b[n - 1] < XWAIT - 1e-9 ? "released by x" : "released by maxwait", x_rel);
  /* two restores from inside the wait: the same state bit for bit, the same wait */
  if (saved) {
    for (int k = 0; k < 2; k++) {
      CS_EXPECT(cs_simStateSet(mid, y0, &err) == CS_OK);
      runTo(mid, XT + 0.4);
      cs_simStateGet(mid, k ? y1 : w);
    }
    CS_EXPECT(!memcmp(w, y1, sizeof(double) * (size_t)n) && w[n - 1] == b[n - 1]);
  }
  free(buf);
  cs_simDestroy(plain);
  cs_simDestroy(fr);
  cs_simDestroy(nv);
  cs_simDestroy(mid);
}


/* malformed files: file and line; --gate none and a user's gait: no gate */
static void test_badGateFileNamesLine(void) {
  static const struct {
    const char* text;
    const char* where;
  } kBad[] = {
      {"# a gate\ndesign ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\nfence 2.6 AE\n", ":3:"},
      {"gate 2.6 AE\n", ":1:"},
      {"design ramp 0.05 lag 0 ptol 0.005 maxwait 0.6\ngate 2.6 AE\n", ":1:"},
      {"design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\ngate 2.6 AX\n", ":2:"},
      {"design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\ngate 2.6 AE\n\ngate 2.0 DH\n", ":4:"},
      {"design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\ngate nan AE\n", ":2:"},
      {"design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\n# none\n", ":2:"},
      {"design ramp 0.05 lag 0.02 ptol 0.005\ngate 2.6 AE\n", ":1:"},
      {"design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\ngate 2.6 AE x inf\n", ":2:"},
  };
  for (size_t k = 0; k < sizeof kBad / sizeof kBad[0]; k++) {
    char path[64];
    snprintf(path, sizeof path, "bad%zu.gate", k);
    cs_testWriteText(path, kBad[k].text);
    csRunDef d = cheapDef();
    d.gate = path;
    csError err;
    cs_errorClear(&err);
    csSim* s = cs_simCreate(&d, &err);
    char want[96];
    snprintf(want, sizeof want, "%s%s", path, kBad[k].where);
    CS_EXPECT(s == NULL && strstr(err.msg, want) != NULL);
    printf("%s: %s\n", path, err.msg);
    cs_simDestroy(s);
  }
  /* none, and a user's gait (the scene's own table named as a file): no gate part */
  csSim* a = make("none", 0);
  csSim* b = make(NULL, 0);
  const char* src = getenv("CS_SOURCE_DIR");
  char gait[1024];
  snprintf(gait, sizeof gait, "%s/gaits/obstacle.csv", src ? src : "../../..");
  csRunDef d = cheapDef();
  d.gait = gait;
  d.conditions = "paper";
  csError err;
  csSim* c = cs_simCreate(&d, &err);
  CS_EXPECT(a && b && c);
  if (a && b && c) {
    CS_EXPECT(cs_simStateSize(b) == cs_simStateSize(a) + 3 + NGATE + NCRAWL);
    CS_EXPECT(cs_simStateSize(c) == cs_simStateSize(a));
  }
  cs_simDestroy(a);
  cs_simDestroy(b);
  cs_simDestroy(c);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_badGateFileNamesLine);
  CS_RUN(test_crawlDecidesAndRestores);
  CS_RUN(test_walkDecidesThenCrawl);
  CS_RUN(test_supportXHolds);
  CS_RUN(test_nominalNoWaitBitForBit);
  CS_RUN(test_lagWaitsAsModelAndRestores);
  return cs_testSummary();
}

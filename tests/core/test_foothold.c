/* test_foothold.c: the footholds' player (core/sim_foothold.c, `--foothold`) on the shipped
 * flat road with the cheapest rod legs (as test_api.c), short runs:
 *  - candidates equal to the table: the run is the table's run bit for bit (every state value
 *    but the appended latch, each step), and the state has one more value, the latch, -1
 *    before the lift and a candidate after it;
 *  - a candidate that differs, chosen from the measured support (the plan expected the
 *    support 30 mm behind: the candidate landing 30 mm shorter is taken): the pressures of
 *    its leg (B) differ from the table's while the other legs' do not;
 *  - save and restore: from a state before the lift, two restores run to the same state bit
 *    for bit (the choice made again from the same state); a latch put in the state is the one
 *    that acts; a latch that is not a candidate is refused;
 *  - a chain (leg B's next step a foothold too, its window starting inside the first's): the
 *    later's columns hold over the overlap and after it;
 *  - a bad .foothold file fails cs_simCreate with a message naming the file and line;
 *  - a ramp ten rows long: equal candidates give the table's run bit for bit, a chosen one the
 *    run of the table with its rows over the window.
 * The flat road has no raised box (no edges): the choice is the candidate nearest the plan's
 * landing (gaits_foothold.h), which these cases steer through xplan. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crawlsim.h"
#include "cs_test.h"
#include "gaits_csv.h"

#define T_LIFT 0.05 /* s: the foothold's lift */
#define W0 0.05     /* s: its window */
#define W1 0.4
#define LEG 1       /* B: pressurised from the start of the flat road's gait */
#define OTHER 3     /* D: B's group, pressurised with it */


static csRunDef cheapDef(void) {
  csRunDef d = cs_defaultRunDef();
  d.legs = "rod"; /* the cheapest rod (the flat road's default legs are strain) */
  d.links = 2;
  d.rod_tol = 20;
  /* the rows' spacing (test_longRampPlaysTheComposite takes 0.5 s) */
  d.ramp = 0.05;
  return d;
}


/* the shipped flat road gait (the scene's default) with leg B's columns times `scale` (a
 * candidate table: the player uses leg B's columns over the window) */
static int writeCandidate(const char* path, double scale) {
  const char* src = getenv("CS_SOURCE_DIR");
  char gait[1024];
  snprintf(gait, sizeof gait, "%s/gaits/flat_road_rod.csv", src ? src : "../../..");
  csError err;
  csgGait* g = csg_gaitRead(gait, NULL, &err);
  if (!g) {
    fprintf(stderr, "  %s\n", err.msg);
    return -1;
  }
  for (int i = 0; i < g->nrow; i++) {
    for (int c = 0; c < 12; c++) {
      g->pressure[CSG_NLABEL * i + 12 * LEG + c] *= scale;
    }
  }
  csStatus st = csg_gaitWrite(g, path, "test_foothold candidate", &err);
  csg_gaitDestroy(g);
  return st == CS_OK ? 0 : -1;
}


/* a .foothold of one foothold of leg B: the nominal candidate (scale 1, landing 100) and one
 * of leg B's pressures times `scale` landing 70 mm; the plan expected the support at xplan */
static int writeFoothold(const char* path, double scale, double xplan) {
  if (writeCandidate("fh_nominal.csv", 1.0) || writeCandidate("fh_other.csv", scale)) {
    return -1;
  }
  FILE* f = fopen(path, "w");
  if (!f) return -1;
  fprintf(f, "foothold %g B xplan %g margin 0 window %g %g\n", T_LIFT, xplan, W0, W1);
  fprintf(f, "candidate 10 land 100 fits -1e3 1e3 fh_nominal.csv nominal\n"
             "candidate -20 land 70 fits -1e3 1e3 fh_other.csv\n");
  fclose(f);
  return 0;
}


static csSim* make(const char* foothold) {
  csRunDef d = cheapDef();
  d.foothold = foothold;
  csError err;
  cs_errorClear(&err);
  csSim* s = cs_simCreate(&d, &err);
  if (!s) fprintf(stderr, "  cs_simCreate: %s\n", err.msg);
  return s;
}


/* candidates equal to the table: the table's run, bit for bit */
static void test_sameCandidatesSameRun(void) {
  CS_EXPECT(writeFoothold("fh_same.foothold", 1.0, -30) == 0);
  csSim* a = make(NULL);
  csSim* b = make("fh_same.foothold");
  CS_EXPECT(a && b);
  if (a && b) {
    const int na = cs_simStateSize(a), nb = cs_simStateSize(b);
    CS_EXPECT(nb == na + 1);
    double* xa = malloc(sizeof(double) * (size_t)nb);
    double* xb = malloc(sizeof(double) * (size_t)nb);
    csError err;
    int same = 1;
    cs_simStateGet(b, xb);
    CS_EXPECT(xb[nb - 1] == -1);
    for (int i = 0; i < 120 && same; i++) {
      CS_EXPECT(cs_simStep(a, &err) == CS_OK);
      CS_EXPECT(cs_simStep(b, &err) == CS_OK);
      cs_simStateGet(a, xa);
      cs_simStateGet(b, xb);
      same = !memcmp(xa, xb, sizeof(double) * (size_t)na);
    }
    CS_EXPECT(same);
    CS_EXPECT(xb[nb - 1] == 1); /* decided: the candidate 30 mm shorter */
    printf("equal candidates: 120 steps identical to the table's run; latch %g\n", xb[nb - 1]);
    free(xa);
    free(xb);
  }
  cs_simDestroy(a);
  cs_simDestroy(b);
}


/* run s to time t */
static void runTo(csSim* s, double t) {
  csError err;
  csStatus st = cs_simRunUntil(s, t, &err);
  CS_EXPECT(st == CS_OK);
  if (st != CS_OK) fprintf(stderr, "  %s\n", err.msg);
}


static double legPressure(const csSim* s, int leg) {
  double p[96], sum = 0;
  cs_simPressures(s, p);
  for (int c = 0; c < 12; c++) sum += p[12 * leg + c];
  return sum;
}


/* a differing candidate is chosen from the measured support and acts on its leg only; the
 * latch is state */
static void test_choiceActsAndRestores(void) {
  CS_EXPECT(writeFoothold("fh_diff.foothold", 0.5, -30) == 0);
  csSim* a = make(NULL);
  csSim* b = make("fh_diff.foothold");
  CS_EXPECT(a && b);
  if (!a || !b) {
    cs_simDestroy(a);
    cs_simDestroy(b);
    return;
  }
  const int n = cs_simStateSize(b);
  double* x0 = malloc(sizeof(double) * (size_t)n);
  double* x1 = malloc(sizeof(double) * (size_t)n);
  double* x2 = malloc(sizeof(double) * (size_t)n);
  csError err;
  runTo(a, 0.02);
  runTo(b, 0.02);
  cs_simStateGet(b, x0);
  CS_EXPECT(x0[n - 1] == -1);
  runTo(a, 0.2);
  runTo(b, 0.2);
  cs_simStateGet(b, x1);
  CS_EXPECT(x1[n - 1] == 1);
  const double pa = legPressure(a, LEG), pb = legPressure(b, LEG);
  const double qa = legPressure(a, OTHER), qb = legPressure(b, OTHER);
  printf("leg B's pressures at 0.2 s (sum of 12): table %.6g, chosen candidate %.6g; leg D %.6g "
         "and %.6g\n", pa, pb, qa, qb);
  CS_EXPECT(pa > 0.1 && fabs(pb - 0.5 * pa) < 0.1 * pa); /* the lag's lead is well inside 10 % */
  /* the other legs' commands are the table's; their pressures share the integrator's steps
   * with leg B's, so they agree to its tolerances (rtol 1e-6 of 12 chambers' sum), not bits */
  CS_EXPECT(qa > 0.1 && fabs(qa - qb) < 1e-5 * qa);
  /* two restores of a state before the lift: the same run, bit for bit */
  CS_EXPECT(cs_simStateSet(b, x0, &err) == CS_OK);
  runTo(b, 0.2);
  cs_simStateGet(b, x1);
  CS_EXPECT(cs_simStateSet(b, x0, &err) == CS_OK);
  runTo(b, 0.2);
  cs_simStateGet(b, x2);
  CS_EXPECT(!memcmp(x1, x2, sizeof(double) * (size_t)n));
  /* the latch in the state is the one that acts: 0 (the nominal) gives the table's pressures */
  memcpy(x2, x1, sizeof(double) * (size_t)n);
  x2[n - 1] = 0;
  CS_EXPECT(cs_simStateSet(b, x2, &err) == CS_OK);
  runTo(b, 0.3);
  const double pn = legPressure(b, LEG);
  CS_EXPECT(cs_simStateSet(b, x1, &err) == CS_OK);
  runTo(b, 0.3);
  const double pc = legPressure(b, LEG);
  printf("at 0.3 s from the state at 0.2 s: latch 0 gives leg B %.6g, latch 1 %.6g\n", pn, pc);
  CS_EXPECT(pn > 1.5 * pc);
  /* a latch that is not a candidate */
  x2[n - 1] = 2;
  CS_EXPECT(cs_simStateSet(b, x2, &err) == CS_ERR_ARG && strstr(err.msg, "foothold 1"));
  x2[n - 1] = 0.5;
  CS_EXPECT(cs_simStateSet(b, x2, &err) == CS_ERR_ARG);
  free(x0);
  free(x1);
  free(x2);
  cs_simDestroy(a);
  cs_simDestroy(b);
}


/* a chain: leg B's next step a foothold too, its window starting inside the first's; each
 * picks its shorter candidate (the plan expected the support 30 mm behind): over the overlap
 * and after it the later's columns hold (B at 0.25 of the table's pressures, not the first's
 * 0.5) */
static void test_chainLaterHolds(void) {
  CS_EXPECT(writeCandidate("fh_nominal.csv", 1.0) == 0 && writeCandidate("fh_half.csv", 0.5) == 0 &&
            writeCandidate("fh_quarter.csv", 0.25) == 0);
  FILE* f = fopen("fh_chain.foothold", "w");
  CS_EXPECT(f != NULL);
  if (!f) return;
  fprintf(f, "foothold %g B xplan -30 margin 0 window %g 0.3\n"
             "candidate 10 land 100 fits -1e3 1e3 fh_nominal.csv nominal\n"
             "candidate -20 land 70 fits -1e3 1e3 fh_half.csv\n"
             "foothold 0.15 B xplan -30 margin 0 window 0.15 %g\n"
             "candidate 10 land 100 fits -1e3 1e3 fh_nominal.csv nominal\n"
             "candidate -20 land 70 fits -1e3 1e3 fh_quarter.csv\n", T_LIFT, W0, W1);
  fclose(f);
  csSim* a = make(NULL);
  csSim* b = make("fh_chain.foothold");
  CS_EXPECT(a && b);
  if (a && b) {
    runTo(a, 0.12);
    runTo(b, 0.12);
    const double pa1 = legPressure(a, LEG), pb1 = legPressure(b, LEG);
    runTo(a, 0.27);
    runTo(b, 0.27);
    const double pa2 = legPressure(a, LEG), pb2 = legPressure(b, LEG);
    runTo(a, 0.38);
    runTo(b, 0.38);
    const double pa3 = legPressure(a, LEG), pb3 = legPressure(b, LEG);
    printf("chain: leg B / table at 0.12 s %.4f (first: 0.5), 0.27 s %.4f and 0.38 s %.4f "
           "(second: 0.25)\n", pb1 / pa1, pb2 / pa2, pb3 / pa3);
    CS_EXPECT(pa1 > 0.1 && fabs(pb1 / pa1 - 0.5) < 0.05);
    CS_EXPECT(pa2 > 0.1 && fabs(pb2 / pa2 - 0.25) < 0.025);
    CS_EXPECT(pa3 > 0.1 && fabs(pb3 / pa3 - 0.25) < 0.025);
  }
  cs_simDestroy(a);
  cs_simDestroy(b);
}


static void test_badFile(void) {
  FILE* f = fopen("fh_bad.foothold", "w");
  CS_EXPECT(f != NULL);
  if (!f) return;
  fprintf(f, "# bad\nfoothold 1 AZ xplan 0 margin 0 window 1 2\n");
  fclose(f);
  csRunDef d = cheapDef();
  d.foothold = "fh_bad.foothold";
  csError err;
  cs_errorClear(&err);
  csSim* s = cs_simCreate(&d, &err);
  CS_EXPECT(s == NULL);
  CS_EXPECT(strstr(err.msg, "fh_bad.foothold:2:") != NULL && strchr(err.msg, '\n') == NULL);
  printf("bad file: %s\n", err.msg);
  cs_simDestroy(s);
  d.foothold = "fh_missing.foothold";
  s = cs_simCreate(&d, &err);
  CS_EXPECT(s == NULL && strstr(err.msg, "fh_missing.foothold") != NULL);
  cs_simDestroy(s);
}


/* the source's flat road table for rod legs (the scene's; the candidates are made from it) */
static const char* sourceGait(void) {
  static char path[1024];
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(path, sizeof path, "%s/gaits/flat_road_rod.csv", src ? src : "../../..");
  return path;
}


/* the table by hand that a chosen candidate stands for (gaits_foothold.h): the table's rows
 * with leg B's columns from `cand` for W0 <= t < W1 */
static int writeComposite(const char* path, const char* cand) {
  csError err;
  csgGait* g = csg_gaitRead(sourceGait(), NULL, &err);
  csgGait* c = csg_gaitRead(cand, NULL, &err);
  int ok = g && c && g->nrow == c->nrow;
  for (int i = 0; ok && i < g->nrow; i++) {
    if (g->time[i] >= W0 && g->time[i] < W1) {
      memcpy(&g->pressure[CSG_NLABEL * i + 12 * LEG], &c->pressure[CSG_NLABEL * i + 12 * LEG],
             12 * sizeof(double));
    }
  }
  ok = ok && csg_gaitWrite(g, path, "test_foothold composite", &err) == CS_OK;
  csg_gaitDestroy(g);
  csg_gaitDestroy(c);
  return ok ? 0 : -1;
}


static csSim* makeRamp(const char* gait, const char* foothold, double ramp) {
  csRunDef d = cheapDef();
  d.gait = gait;
  d.conditions = "paper"; /* the same for the table, its copy and the composite */
  d.foothold = foothold;
  d.ramp = ramp;
  csError err;
  cs_errorClear(&err);
  csSim* s = cs_simCreate(&d, &err);
  if (!s) fprintf(stderr, "  cs_simCreate: %s\n", err.msg);
  return s;
}


/* a ramp ten rows long (0.5 s against the rows' 0.05 s; refused until margin18): equal
 * candidates still give the table's run bit for bit; a chosen candidate (leg B at half the
 * table's pressures over 0.05..0.4 s) gives the run of the table with those rows, its ramps
 * reaching past the window: leg B's pressures at 0.3, 0.55 and 0.7 s (the last 0.3 s past
 * W1, within the ramp) agree with that table's run to the pneumatic integrator's tolerance
 * (relative 1e-5 of 12 chambers' sum, as above: the commands agree to rounding, not bits) and
 * differ from the table's by more than 10 %. */
static void test_longRampPlaysTheComposite(void) {
  CS_EXPECT(writeFoothold("fh_lr_same.foothold", 1.0, -30) == 0);
  csSim* a = makeRamp(sourceGait(), NULL, 0.5);
  csSim* b = makeRamp(sourceGait(), "fh_lr_same.foothold", 0.5);
  CS_EXPECT(a && b);
  if (a && b) {
    const int na = cs_simStateSize(a), nb = cs_simStateSize(b);
    double* xa = malloc(sizeof(double) * (size_t)nb);
    double* xb = malloc(sizeof(double) * (size_t)nb);
    csError err;
    int same = 1;
    for (int i = 0; i < 120 && same; i++) {
      CS_EXPECT(cs_simStep(a, &err) == CS_OK && cs_simStep(b, &err) == CS_OK);
      cs_simStateGet(a, xa);
      cs_simStateGet(b, xb);
      same = !memcmp(xa, xb, sizeof(double) * (size_t)na);
    }
    CS_EXPECT(same);
    printf("ramp 0.5 s, equal candidates: 120 steps identical to the table's run: %s\n",
           same ? "yes" : "no");
    free(xa);
    free(xb);
  }
  cs_simDestroy(b);
  CS_EXPECT(writeFoothold("fh_lr_diff.foothold", 0.5, -30) == 0 &&
            writeComposite("fh_lr_composite.csv", "fh_other.csv") == 0);
  b = makeRamp(sourceGait(), "fh_lr_diff.foothold", 0.5);
  csSim* c = makeRamp("fh_lr_composite.csv", NULL, 0.5);
  CS_EXPECT(b && c);
  if (a && b && c) {
    const double at[3] = {0.3, 0.55, 0.7};
    for (int i = 0; i < 3; i++) {
      runTo(a, at[i]);
      runTo(b, at[i]);
      runTo(c, at[i]);
      const double pa = legPressure(a, LEG), pb = legPressure(b, LEG), pc = legPressure(c, LEG);
      printf("ramp 0.5 s, leg B at %.2f s (sum of 12): table %.6g, foothold %.6g, the table "
             "with the candidate's rows %.6g\n", at[i], pa, pb, pc);
      CS_EXPECT(pc > 0.1 && fabs(pb - pc) < 1e-5 * pc);
      CS_EXPECT(fabs(pb - pa) > 0.1 * pa);
    }
  }
  cs_simDestroy(a);
  cs_simDestroy(b);
  cs_simDestroy(c);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_sameCandidatesSameRun);
  CS_RUN(test_choiceActsAndRestores);
  CS_RUN(test_chainLaterHolds);
  CS_RUN(test_badFile);
  CS_RUN(test_longRampPlaysTheComposite);
  return cs_testSummary();
}

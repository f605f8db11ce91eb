/* test_checkpoint.c: resumable runs (csRunDef.checkpoint / resume, `crawlsim run --checkpoint
 * FILE --resume FILE`; core/sim_checkpoint.c, sim_run.c):
 *  - a run cut at a checkpoint (its --t-end) and resumed to the end writes an output whose
 *    every dataset equals the uncut run's bit for bit, on rod legs (Gauss-Seidel, CVODE per
 *    leg) and on strain legs (the tree coupling, its fixed and its adaptive step, the latter
 *    with backward Euler and BDF2), and the same
 *    step count; the comparison is
 *    not trivial (the rows after the cut differ from the cut's); with a gate file whose crawl
 *    ends at the cut (its decision after the resume) too; one stopped before settling
 *    (a checkpoint at t < 0) settles when resumed and equals the uncut run too;
 *  - with a crawl statement and no --t-end the run ends when the table's clock reaches the
 *    table's end (the crawl's skip sooner), with or without an output file, and a run cut and
 *    resumed ends there too, bit for bit; an explicit --t-end wins;
 *  - a resume with another definition (friction, the checkpoint interval, links, the gate) is
 *    refused naming the file and the field, and leaves the output as it was;
 *  - a truncated checkpoint, one with a changed byte in its state and a file that is no
 *    checkpoint are refused naming the file and the cause;
 *  - the restart a checkpoint makes (the state got and set) and the steps after it allocate
 *    nothing (the project's own code's malloc, calloc, realloc counted through the linker).
 * Runs of 0.3 s after the 0.3 s settling, at the cheapest rod (2 elements per segment,
 * --rod-tol 20) and strain legs' defaults: a few seconds. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_h5read.h"
#include "crawlsim.h"
#include "cs_test.h"

/* every malloc, calloc and realloc of the project's own code linked into this test (the
 * static libraries; the linker's --wrap, tests/core/CMakeLists.txt) is counted: what a
 * checkpoint adds to the step loop must allocate nothing */
static long g_allocs;
void* __real_malloc(size_t n);
void* __real_calloc(size_t k, size_t n);
void* __real_realloc(void* p, size_t n);
void* __wrap_malloc(size_t n);
void* __wrap_calloc(size_t k, size_t n);
void* __wrap_realloc(void* p, size_t n);
void* __wrap_malloc(size_t n) {
  g_allocs++;
  return __real_malloc(n);
}
void* __wrap_calloc(size_t k, size_t n) {
  g_allocs++;
  return __real_calloc(k, n);
}
void* __wrap_realloc(void* p, size_t n) {
  g_allocs++;
  return __real_realloc(p, n);
}


static csRunDef baseDef(const char* legs) {
  csRunDef d = cs_defaultRunDef();
  d.legs = legs;
  if (!strcmp(legs, "rod")) {
    d.links = 2;
    d.rod_tol = 20;
  }
  d.checkpoint_every = 0.1;
  return d;
}


static csStatus runDef(const csRunDef* d, csRunResult* r, csError* err) {
  cs_errorClear(err);
  csStatus st = cs_run(d, r, err);
  if (st != CS_OK) {
    fprintf(stderr, "  run: %s\n", err->msg);
  }
  return st;
}


/* the run file's datasets (the output contract), compared bit for bit; rows of /time in *rows */
static int sameDatasets(const char* a, const char* b, long* rows) {
  static const char* const kPaths[] = {
      "/time", "/support/position", "/support/orientation", "/pressure", "/support/corners",
      "/contact/force", "/contact/max_depth", "/contact/leg_max_depth", "/contact/foot_force",
      "/contact/stance", "/terrain/corners", "/legs/A/centerline", "/legs/B/centerline",
      "/legs/C/centerline", "/legs/D/centerline", "/legs/E/centerline", "/legs/F/centerline",
      "/legs/G/centerline", "/legs/H/centerline"};
  csError err;
  csH5Reader* ra = cs_h5ReaderOpen(a, &err);
  csH5Reader* rb = cs_h5ReaderOpen(b, &err);
  int same = ra && rb;
  for (size_t k = 0; same && k < sizeof kPaths / sizeof kPaths[0]; k++) {
    size_t da[4] = {0}, db[4] = {0};
    int na = 0, nb = 0;
    double* va = cs_h5ReaderDoubles(ra, kPaths[k], 0, NULL, da, &na, &err);
    double* vb = cs_h5ReaderDoubles(rb, kPaths[k], 0, NULL, db, &nb, &err);
    size_t n = 1;
    for (int i = 0; i < na; i++) {
      n *= da[i];
    }
    const int ok = va && vb && na == nb && !memcmp(da, db, sizeof da) &&
                   !memcmp(va, vb, n * sizeof(double));
    if (!ok) {
      fprintf(stderr, "  %s differs between %s and %s\n", kPaths[k], a, b);
    }
    if (k == 0 && rows) {
      *rows = (long)da[0];
    }
    same = ok;
    free(va);
    free(vb);
  }
  cs_h5ReaderClose(ra);
  cs_h5ReaderClose(rb);
  return same;
}


/* the last w doubles of a dataset's row into v (a centreline's: its foot) */
static int readRow(const char* path, const char* name, long row, int w, double* v) {
  csError err;
  csH5Reader* r = cs_h5ReaderOpen(path, &err);
  size_t dims[4] = {0, 1, 1, 1};
  int rank = 0;
  double* all = r ? cs_h5ReaderDoubles(r, name, 0, NULL, dims, &rank, &err) : NULL;
  const size_t width = dims[1] * (rank > 2 ? dims[2] : 1) * (rank > 3 ? dims[3] : 1);
  const int ok = all && (size_t)row < dims[0] && width >= (size_t)w;
  if (ok) {
    memcpy(v, all + (size_t)(row + 1) * width - w, sizeof(double) * (size_t)w);
  }
  free(all);
  cs_h5ReaderClose(r);
  return ok;
}


/* a numeric root attribute (NaN when absent) */
static double readAttr(const char* path, const char* name) {
  csError err;
  csH5Reader* r = cs_h5ReaderOpen(path, &err);
  double v = NAN;
  if (!r || cs_h5ReaderAttrDouble(r, name, &v, &err) != CS_OK) v = NAN;
  cs_h5ReaderClose(r);
  return v;
}


/* the uncut run of 0.3 s against the same run cut at 0.2 s and resumed to 0.3 s */
/* step: NULL, or the strain level's --strain-step */
/* ... with the tree step's formula `order` (1 or 2; NaN the level's) */
static void resumedEqualsUncutOrder(const char* legs, const char* step, const char* gate,
                                    double order) {
  char a_out[64], a_ck[64], b_out[64], b_ck[64];
  const char* tag = step ? (order == 2 ? "adaptive_bdf2" : step) : gate ? "gate" : "";
  snprintf(a_out, sizeof a_out, "ckpt_%s%s_uncut.h5", legs, tag);
  snprintf(a_ck, sizeof a_ck, "ckpt_%s%s_uncut.ck", legs, tag);
  snprintf(b_out, sizeof b_out, "ckpt_%s%s_cut.h5", legs, tag);
  snprintf(b_ck, sizeof b_ck, "ckpt_%s%s_cut.ck", legs, tag);
  csError err;
  csRunResult ra, rb, rc;
  csRunDef a = baseDef(legs);
  a.strain_step = step;
  a.step_order = order;
  a.gate = gate;
  a.t_end = 0.3;
  a.out = a_out;
  a.checkpoint = a_ck;
  CS_EXPECT(runDef(&a, &ra, &err) == CS_OK);
  csRunDef b = baseDef(legs);
  b.strain_step = step;
  b.step_order = order;
  b.gate = gate;
  b.t_end = 0.2;
  b.out = b_out;
  b.checkpoint = b_ck;
  CS_EXPECT(runDef(&b, &rb, &err) == CS_OK);
  CS_EXPECT(rb.t_end < ra.t_end - 0.05);
  csRunDef c = baseDef(legs);
  c.strain_step = step;
  c.step_order = order;
  c.gate = gate;
  c.t_end = 0.3;
  c.out = b_out;
  c.resume = b_ck; /* the checkpoints go on into it */
  CS_EXPECT(runDef(&c, &rc, &err) == CS_OK);
  long rows = 0;
  const int same = sameDatasets(a_out, b_out, &rows);
  CS_EXPECT(same);
  CS_EXPECT(rows == 31); /* t = 0, 0.01, ..., 0.3 */
  CS_EXPECT(rc.steps == ra.steps && rc.t_end == ra.t_end);
  CS_EXPECT(memcmp(rc.position, ra.position, sizeof ra.position) == 0);
  /* not trivial: the legs and the pressures moved after the cut */
  double p20[96], p30[96], c20[3], c30[3];
  CS_EXPECT(readRow(b_out, "/pressure", 20, 96, p20) && readRow(b_out, "/pressure", 30, 96, p30));
  CS_EXPECT(memcmp(p20, p30, sizeof p20) != 0);
  CS_EXPECT(readRow(b_out, "/legs/A/centerline", 20, 3, c20) &&
            readRow(b_out, "/legs/A/centerline", 30, 3, c30));
  double dp = 0;
  for (int i = 0; i < 96; i++) {
    dp = fmax(dp, fabs(p30[i] - p20[i]));
  }
  const double dfoot =
      sqrt(pow(c30[0] - c20[0], 2) + pow(c30[1] - c20[1], 2) + pow(c30[2] - c20[2], 2));
  CS_EXPECT(dp > 0.01 && dfoot > 0.1); /* MPa, mm: the gait's first ramp is under way */
  printf("  %s legs%s%s: %ld rows %s; steps %ld; support x %.6f mm at 0.3 s; the pressures moved "
         "by up to %.4f MPa and the foot of leg A by %.3f mm after the cut\n", legs,
         step ? ", step " : gate ? ", " : "", tag, rows,
         same ? "equal bit for bit" : "DIFFER", rc.steps, rc.position[0], dp, dfoot);
  if (gate) { /* the crawl decided at the cut, after the resume: 2 slots on (the file's) */
    CS_EXPECT(readAttr(b_out, "crawl_skip_s") == 0.1 && readAttr(a_out, "crawl_skip_s") == 0.1);
  }
  /* the checkpoint file got the end's state: a later resume refuses to run past nothing */
  c.t_end = 0.3;
  CS_EXPECT(cs_run(&c, &rc, &err) == CS_ERR_ARG && strstr(err.msg, b_ck) &&
            strstr(err.msg, "nothing to continue"));
}


static void resumedEqualsUncutGate(const char* legs, const char* step, const char* gate) {
  resumedEqualsUncutOrder(legs, step, gate, NAN);
}
static void resumedEqualsUncutStep(const char* legs, const char* step) {
  resumedEqualsUncutGate(legs, step, NULL);
}
static void resumedEqualsUncut(const char* legs) { resumedEqualsUncutStep(legs, NULL); }


static void test_rod_resumed_equals_uncut(void) { resumedEqualsUncut("rod"); }


/* a run stopped (its cancel flag) before its first settling step leaves a checkpoint of the
 * settling (t < 0, no output rows); resumed, it settles and runs as the uncut run, bit for bit
 * (the uncut run of resumedEqualsUncut("rod"), run again here) */
static void test_settling_resumed_equals_uncut(void) {
  csError err;
  csRunResult ra, rb, rc;
  csRunDef a = baseDef("rod");
  a.t_end = 0.15;
  a.out = "ckpt_settle_uncut.h5";
  a.checkpoint = "ckpt_settle_uncut.ck";
  CS_EXPECT(runDef(&a, &ra, &err) == CS_OK);
  csRunDef b = baseDef("rod");
  b.t_end = 0.15;
  b.out = "ckpt_settle_cut.h5";
  b.checkpoint = "ckpt_settle_cut.ck";
  static volatile sig_atomic_t stop = 1;
  b.cancel = &stop;
  CS_EXPECT(cs_run(&b, &rb, &err) == CS_ERR_INTERRUPTED && strstr(err.msg, "settling"));
  printf("  stopped: %s\n", err.msg);
  csRunDef c = baseDef("rod");
  c.t_end = 0.15;
  c.out = "ckpt_settle_cut.h5";
  c.resume = "ckpt_settle_cut.ck";
  CS_EXPECT(runDef(&c, &rc, &err) == CS_OK);
  long rows = 0;
  CS_EXPECT(sameDatasets(a.out, c.out, &rows));
  CS_EXPECT(rows == 16 && rc.steps == ra.steps);
  printf("  settling resumed: %ld rows, %ld steps, support y %.9f mm as the uncut run's %.9f\n",
         rows, rc.steps, rc.position[1], ra.position[1]);
}
/* a landing gate with a lateral crawl (gaits_gate.h `crawl`) that ends at its first decision,
 * at 0.2 s, the cut: the resumed run decides as the uncut one and equals it bit for bit (the
 * crawl's part of the state in the checkpoint) */
static void test_gate_crawl_resumed_equals_uncut(void) {
  cs_testWriteText("ckpt_crawl.gate", "design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\n"
                   "gate 0.05 AE\ncrawl 0.05 0.05 5 -1e6 0\n");
  resumedEqualsUncutGate("rod", NULL, "ckpt_crawl.gate");
}


/* a root string attribute ("" when absent) */
static void readAttrString(const char* path, const char* name, char* buf, size_t size) {
  csError err;
  csH5Reader* r = cs_h5ReaderOpen(path, &err);
  if (!r || cs_h5ReaderAttrString(r, name, buf, size, &err) != CS_OK) buf[0] = '\0';
  cs_h5ReaderClose(r);
}


/* the run's end with a crawl statement and no --t-end (cs_runOverAt): the gait is over when the
 * table's clock t - hold + skip reaches the table's end, so the run ends the crawl's skip sooner
 * than the same table with a crawl that never ends (its end on the run's clock), at an output
 * row, and says why; the run without an output file (cs_run's other loop: the Python API's
 * `crawlsim.run` without out) ends at the same step; a run cut at 0.2 s (its --t-end) and
 * resumed without one ends there too, bit for bit */
static void test_gate_ends_the_run_when_the_table_is_over(void) {
  /* a table of one chamber's slow rise to 0.5 s (cheap: the rods barely move) */
  cs_testWriteText("ckpt_end.csv", "time,A_II1_O1\n0,0\n0.5,0.05\n");
  cs_testWriteText("ckpt_end_skip.gate", "design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\n"
                   "gate 0.05 AE\ncrawl 0.05 0.05 5 -1e6 0\n");
  cs_testWriteText("ckpt_end_full.gate", "design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\n"
                   "gate 0.05 AE\ncrawl 0.05 0.05 5 1e6 0\n");
  csError err;
  csRunResult rf, ra, rn, rb, rc;
  csRunDef f = baseDef("rod");
  f.gait = "ckpt_end.csv";
  f.gate = "ckpt_end_full.gate";
  f.out = "ckpt_end_full.h5";
  f.checkpoint_every = NAN; /* none (a checkpoint needs a file) */
  CS_EXPECT(runDef(&f, &rf, &err) == CS_OK);
  csRunDef a = f;
  a.gate = "ckpt_end_skip.gate";
  a.out = "ckpt_end_uncut.h5";
  a.checkpoint = "ckpt_end_uncut.ck";
  a.checkpoint_every = 0.1;
  CS_EXPECT(runDef(&a, &ra, &err) == CS_OK);
  const double skip = readAttr(a.out, "crawl_skip_s"), held = readAttr(a.out, "gate_held_s");
  const double held_f = readAttr(f.out, "gate_held_s");
  CS_EXPECT(readAttr(f.out, "crawl_skip_s") == 0 && skip > 0);
  /* the full table ends on its own clock (t - hold; it never holds here); the
   * skipped one when its table's clock, t - hold + skip, reaches the same end (to the output
   * row, 0.01 s) */
  const double tab_end = rf.t_end; /* cs_modelTableEnd: the table's last row plus one ramp */
  CS_EXPECT(fabs(ra.t_end - held + skip - tab_end) < 0.01 + 1e-9 && ra.t_end < rf.t_end - 0.05);
  char why[256];
  readAttrString(a.out, "end_reason", why, sizeof why);
  CS_EXPECT(strstr(why, "the gait is over") != NULL);
  printf("  the table ends at %g s (held %g s); with the crawl's skip of %g s (held %g s) the "
         "run ends at %g s: %s\n", tab_end, held_f, skip, held, ra.t_end, why);
  readAttrString(f.out, "end_reason", why, sizeof why);
  CS_EXPECT(strstr(why, "the table's end") != NULL);
  long rows = 0, rows_f = 0;
  CS_EXPECT(sameDatasets(a.out, a.out, &rows) && sameDatasets(f.out, f.out, &rows_f));
  CS_EXPECT(rows == lround(ra.t_end / 0.01) + 1 && rows < rows_f);
  /* no output file: the same end */
  csRunDef n = a;
  n.out = NULL;
  n.checkpoint = NULL;
  n.checkpoint_every = NAN; /* none (a checkpoint needs a file) */
  CS_EXPECT(runDef(&n, &rn, &err) == CS_OK);
  CS_EXPECT(rn.t_end == ra.t_end && rn.steps == ra.steps);
  /* cut at 0.2 s, resumed with no --t-end: the uncut run's end, bit for bit */
  csRunDef b = a;
  b.out = "ckpt_end_cut.h5";
  b.checkpoint = "ckpt_end_cut.ck";
  b.t_end = 0.2;
  CS_EXPECT(runDef(&b, &rb, &err) == CS_OK);
  csRunDef c = b;
  c.t_end = 0;
  c.resume = b.checkpoint;
  CS_EXPECT(runDef(&c, &rc, &err) == CS_OK);
  CS_EXPECT(sameDatasets(a.out, b.out, &rows));
  CS_EXPECT(rc.t_end == ra.t_end && rc.steps == ra.steps &&
            memcmp(rc.position, ra.position, sizeof ra.position) == 0);
  /* an explicit --t-end still wins over the gait's end */
  csRunDef e = a;
  e.out = "ckpt_end_tend.h5";
  e.checkpoint = NULL;
  e.checkpoint_every = NAN; /* none (a checkpoint needs a file) */
  e.t_end = rf.t_end;
  CS_EXPECT(runDef(&e, &rb, &err) == CS_OK);
  CS_EXPECT(fabs(rb.t_end - rf.t_end) < 1e-9);
  readAttrString(e.out, "end_reason", why, sizeof why);
  CS_EXPECT(strstr(why, "--t-end") != NULL);
  /* a gate that holds the table's clock (its x condition never met: it waits its maxwait)
   * without a crawl: the run goes on past the table's end on the run's clock, to where the
   * table's clock, t - hold, reaches it (to the output row) */
  cs_testWriteText("ckpt_end_hold.gate", "design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.3\n"
                   "gate 0.05 AE x 1e6\n");
  csRunDef g = f;
  g.gate = "ckpt_end_hold.gate";
  g.out = "ckpt_end_hold.h5";
  csRunResult rg;
  CS_EXPECT(runDef(&g, &rg, &err) == CS_OK);
  const double held_g = readAttr(g.out, "gate_held_s");
  readAttrString(g.out, "end_reason", why, sizeof why);
  printf("  a gate held %g s: the run ends at %g s (the table's end %g s): %s\n", held_g,
         rg.t_end, tab_end, why);
  CS_EXPECT(held_g > 0.2 && rg.t_end > tab_end + 0.2);
  CS_EXPECT(fabs(rg.t_end - held_g - tab_end) < 0.01 + 1e-9);
  CS_EXPECT(strstr(why, "the gait is over") != NULL);
}
static void test_strain_resumed_equals_uncut(void) { resumedEqualsUncut("strain"); }
/* the adaptive step (its controller's memory is state: sim_adaptive.c) */
static void test_strain_adaptive_resumed_equals_uncut(void) {
  resumedEqualsUncutStep("strain", "adaptive");
}
/* ... under BDF2 (the controller's memory holds two steps, the legs' and the support's BDF2
 * history is theirs: sim_adaptive.c CS_ADA_STATE2) */
static void test_strain_adaptive_bdf2_resumed_equals_uncut(void) {
  resumedEqualsUncutOrder("strain", "adaptive", NULL, 2);
}


/* a cut run of rod legs to resume wrongly: its output and checkpoint */
static int cutRun(const char* out, const char* ck) {
  csRunDef b = baseDef("rod");
  b.t_end = 0.1;
  b.out = out;
  b.checkpoint = ck;
  csError err;
  csRunResult r;
  return runDef(&b, &r, &err) == CS_OK;
}


static long timeRows(const char* out) {
  csError err;
  csH5Reader* r = cs_h5ReaderOpen(out, &err);
  size_t dims[4] = {0};
  double* t = r ? cs_h5ReaderDoubles(r, "/time", 1, NULL, dims, NULL, &err) : NULL;
  free(t);
  cs_h5ReaderClose(r);
  return t ? (long)dims[0] : -1;
}


static void expectResumeRefused(csRunDef c, const char* ck, const char* what) {
  csError err;
  csRunResult r;
  cs_errorClear(&err);
  c.resume = ck;
  c.t_end = 0.2;
  csStatus st = cs_run(&c, &r, &err);
  CS_EXPECT(st != CS_OK && strstr(err.msg, ck) && strstr(err.msg, what));
  if (st == CS_OK || !strstr(err.msg, what) || !strstr(err.msg, ck)) {
    fprintf(stderr, "  expected '%s' naming %s in: %s\n", what, ck, err.msg);
  } else {
    printf("  refused: %s\n", err.msg);
  }
}


static void test_other_definition_is_refused(void) {
  const char* out = "ckpt_other.h5";
  const char* ck = "ckpt_other.ck";
  CS_EXPECT(cutRun(out, ck));
  const long rows = timeRows(out);
  CS_EXPECT(rows == 11);
  csRunDef c = baseDef("rod");
  c.out = out;
  c.friction = 0.5;
  expectResumeRefused(c, ck, "friction");
  c = baseDef("rod");
  c.out = out;
  c.checkpoint_every = 0.05;
  expectResumeRefused(c, ck, "checkpoint-every");
  c = baseDef("rod");
  c.out = out;
  c.links = 3;
  expectResumeRefused(c, ck, "links");
  c = baseDef("rod");
  c.out = out;
  c.gate = "none"; /* the definition's gate word, as the foothold's (cs_runDefIdentity) */
  expectResumeRefused(c, ck, "gate");
  CS_EXPECT(timeRows(out) == rows); /* the output as it was */
  /* and the same definition resumes (the refusals were the differences'), also after a
   * resume that died before its first flush (the rows in OUT.prev, OUT an empty file) */
  CS_EXPECT(rename(out, "ckpt_other.h5.prev") == 0);
  cs_testWriteText(out, "");
  c = baseDef("rod");
  c.out = out;
  c.resume = ck;
  c.t_end = 0.15;
  csError err;
  csRunResult r;
  CS_EXPECT(runDef(&c, &r, &err) == CS_OK);
  CS_EXPECT(timeRows(out) == 16);
  FILE* prev = fopen("ckpt_other.h5.prev", "rb");
  CS_EXPECT(prev == NULL); /* removed once the new file was on disk */
  if (prev) {
    fclose(prev);
  }
}


static long fileSize(const char* path, unsigned char** bytes) {
  FILE* f = fopen(path, "rb");
  if (!f) {
    return -1;
  }
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  *bytes = malloc((size_t)n);
  if (!*bytes || fread(*bytes, 1, (size_t)n, f) != (size_t)n) {
    n = -1;
  }
  fclose(f);
  return n;
}


static void writeBytes(const char* path, const unsigned char* b, long n) {
  FILE* f = fopen(path, "wb");
  CS_EXPECT(f != NULL);
  if (f) {
    CS_EXPECT(fwrite(b, 1, (size_t)n, f) == (size_t)n);
    fclose(f);
  }
}


static void test_corrupt_checkpoint_is_refused(void) {
  const char* out = "ckpt_corrupt.h5";
  const char* ck = "ckpt_corrupt.ck";
  CS_EXPECT(cutRun(out, ck));
  unsigned char* b = NULL;
  long n = fileSize(ck, &b);
  CS_EXPECT(n > 1000);
  csRunDef c = baseDef("rod");
  c.out = out;
  /* truncated: half of it */
  writeBytes("ckpt_truncated.ck", b, n / 2);
  expectResumeRefused(c, "ckpt_truncated.ck", "not a readable checkpoint");
  /* a changed byte in the state: find the state's values in the file by the support's
   * orientation quaternion's bytes (4 doubles, unique in the file) */
  csError err;
  csH5Reader* r = cs_h5ReaderOpen(ck, &err);
  size_t dims[4] = {0};
  double* x = r ? cs_h5ReaderDoubles(r, "/state", 1, NULL, dims, NULL, &err) : NULL;
  cs_h5ReaderClose(r);
  CS_EXPECT(x && dims[0] > 120);
  long at = -1;
  for (long i = 0; x && i + 32 <= n && at < 0; i++) {
    /* the robot's part starts after t, seed and the 96 pressures: the support's position,
     * then its quaternion */
    if (!memcmp(b + i, x + 98 + 3, 32)) {
      at = i;
    }
  }
  CS_EXPECT(at > 0);
  if (at > 0) {
    b[at] ^= 1; /* the last bit of the quaternion's w */
    writeBytes("ckpt_flipped.ck", b, n);
    expectResumeRefused(c, "ckpt_flipped.ck", "checksum");
  }
  /* no checkpoint at all */
  cs_testWriteText("ckpt_text.ck", "not a checkpoint\n");
  expectResumeRefused(c, "ckpt_text.ck", "not a readable checkpoint");
  expectResumeRefused(c, "ckpt_missing.ck", "not a readable checkpoint");
  free(x);
  free(b);
}


/* the state saved and set again (what a periodic checkpoint does to the run besides writing
 * its file) and the steps after it allocate nothing, on rod and strain legs; the count is
 * alive (creating a simulation allocates) */
static void test_restart_and_steps_allocate_nothing(void) {
  const char* levels[] = {"rod", "strain"};
  for (int k = 0; k < 2; k++) {
    csRunDef d = baseDef(levels[k]);
    d.checkpoint_every = NAN;
    csError err;
    const long a0 = g_allocs;
    csSim* s = cs_simCreate(&d, &err);
    CS_EXPECT(s != NULL);
    if (!s) {
      continue;
    }
    const long created = g_allocs - a0;
    const int n = cs_simStateSize(s);
    double* x = malloc(sizeof(double) * (size_t)n);
    CS_EXPECT(x && cs_simRunUntil(s, 0.05, &err) == CS_OK);
    const long a1 = g_allocs;
    for (int i = 0; x && i < 5; i++) {
      cs_simStateGet(s, x);
      CS_EXPECT(cs_simStateSet(s, x, &err) == CS_OK);
      for (int j = 0; j < 20; j++) {
        CS_EXPECT(cs_simStep(s, &err) == CS_OK);
      }
    }
    const long in_loop = g_allocs - a1;
    printf("  %s legs: %ld allocations creating the simulation, %ld in 5 restarts and 100 steps "
           "(t = %.3f s)\n", levels[k], created, in_loop, cs_simTime(s));
    CS_EXPECT(created > 0 && in_loop == 0);
    free(x);
    cs_simDestroy(s);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_rod_resumed_equals_uncut);
  CS_RUN(test_strain_resumed_equals_uncut);
  CS_RUN(test_gate_crawl_resumed_equals_uncut);
  CS_RUN(test_gate_ends_the_run_when_the_table_is_over);
  CS_RUN(test_strain_adaptive_resumed_equals_uncut);
  CS_RUN(test_strain_adaptive_bdf2_resumed_equals_uncut);
  CS_RUN(test_settling_resumed_equals_uncut);
  CS_RUN(test_other_definition_is_refused);
  CS_RUN(test_corrupt_checkpoint_is_refused);
  CS_RUN(test_restart_and_steps_allocate_nothing);
  return cs_testSummary();
}

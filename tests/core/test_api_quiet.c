/* test_api_quiet.c: the library writes nothing to stdout or stderr (core/crawlsim.h: what a run
 * has to say goes to the caller's callbacks, csRunDef.log and csRunDef.progress).
 *
 * The test points file descriptors 1 and 2 at two temporary files (POSIX dup/dup2, in the test
 * only: the library must need no such thing) around calls that used to print or could print
 * through a dependency (HDF5's error stack, ODE's messages, SUNDIALS' error handler):
 *  - a whole run of 1 s (rod legs on the shipped flat road) with its HDF5 file, the log and the
 *    progress callbacks set: the progress callback is called once per simulated second (here
 *    once, at t = 1 s, with the support's displacement) and the log gets the banner lines;
 *  - the same with both callbacks NULL (the default);
 *  - failures: a range error, a calibration file that does not exist, an output file in a
 *    directory that does not exist, a stepped simulation whose controller fails;
 * then checks that both files are empty. A few seconds (1 s of rod legs). */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "crawlsim.h"
#include "cs_test.h"

/* what the callbacks saw */
typedef struct {
  int nlog, nprogress;
  double t_last, x_last[3], wall_last;
} Seen;

static void onLog(void* user, const char* line) {
  Seen* s = user;
  s->nlog += line && line[0] && !strchr(line, '\n'); /* one line, no newline (crawlsim.h) */
}

static void onProgress(void* user, double t, const double x[3], double wall_s) {
  Seen* s = user;
  s->nprogress++;
  s->t_last = t;
  memcpy(s->x_last, x, sizeof s->x_last);
  s->wall_last = wall_s;
}

static int failingController(csSim* s, double t, double* p_cmd, void* user) {
  (void)s;
  (void)p_cmd;
  (void)user;
  return t > 0.005 ? 3 : 0;
}

/* fds 1 and 2 into two files; returns 0, the saved fds in saved[2] */
static int captureBegin(const char* out_path, const char* err_path, int saved[2]) {
  fflush(NULL);
  FILE* o = fopen(out_path, "w");
  FILE* e = fopen(err_path, "w");
  if (!o || !e) {
    return -1;
  }
  saved[0] = dup(1);
  saved[1] = dup(2);
  int ok = saved[0] >= 0 && saved[1] >= 0 && dup2(fileno(o), 1) >= 0 && dup2(fileno(e), 2) >= 0;
  fclose(o);
  fclose(e);
  return ok ? 0 : -1;
}

static void captureEnd(const int saved[2]) {
  fflush(NULL);
  for (int k = 0; k < 2; k++) {
    if (saved[k] >= 0) {
      dup2(saved[k], k + 1);
      close(saved[k]);
    }
  }
}

static long fileSize(const char* path) {
  FILE* f = fopen(path, "rb");
  if (!f) {
    return -1;
  }
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fclose(f);
  return n;
}

static void printFile(const char* path) {
  FILE* f = fopen(path, "rb");
  char buf[512];
  size_t n;
  while (f && (n = fread(buf, 1, sizeof buf, f)) > 0) {
    fwrite(buf, 1, n, stderr);
  }
  if (f) {
    fclose(f);
  }
}


static void test_library_writes_nothing_to_stdout_or_stderr(void) {
  const char* out_path = "test_api_quiet.stdout";
  const char* err_path = "test_api_quiet.stderr";
  int saved[2] = {-1, -1};
  CS_EXPECT(captureBegin(out_path, err_path, saved) == 0);
  /* a whole run with its file and both callbacks */
  Seen seen;
  memset(&seen, 0, sizeof seen);
  csRunDef d = cs_defaultRunDef();
  d.legs = "rod";
  d.t_end = 1.0;
  d.out = "test_api_quiet.h5";
  d.log = onLog;
  d.log_user = &seen;
  d.progress = onProgress;
  d.progress_user = &seen;
  csRunResult r;
  csError err;
  const csStatus st_run = cs_run(&d, &r, &err);
  /* the same without callbacks (the default: nothing said at all) */
  csRunDef q = cs_defaultRunDef();
  q.legs = "rod";
  q.t_end = 0.05;
  csRunResult rq;
  const csStatus st_quiet = cs_run(&q, &rq, &err);
  /* failures */
  csRunDef b = cs_defaultRunDef();
  b.friction = -1;
  const csStatus st_range = cs_run(&b, NULL, &err);
  b = cs_defaultRunDef();
  b.legs = "rod";
  b.calibration = "no_such_calibration.h5";
  const csStatus st_cal = cs_run(&b, NULL, &err);
  b = cs_defaultRunDef();
  b.legs = "rod";
  b.t_end = 0.05;
  b.out = "no_such_directory/run.h5";
  const csStatus st_out = cs_run(&b, NULL, &err);
  csRunDef c = cs_defaultRunDef();
  c.legs = "rod";
  csSim* s = cs_simCreate(&c, &err);
  csStatus st_ctrl = CS_OK;
  if (s) {
    cs_simSetController(s, failingController, NULL, &err);
    st_ctrl = cs_simRunUntil(s, 0.02, &err);
    cs_simStep(s, &err); /* a step after the failure: refused */
    cs_simDestroy(s);
  }
  captureEnd(saved);

  CS_EXPECT(st_run == CS_OK && st_quiet == CS_OK);
  CS_EXPECT(st_range != CS_OK && st_cal != CS_OK && st_out != CS_OK);
  CS_EXPECT(s != NULL && st_ctrl == CS_ERR_EXTERNAL);
  /* the callbacks got what the command prints: the banner lines, a progress line at t = 1 s
   * (the driver's step count reaches one simulated second exactly: 1000 steps of 1 ms) */
  CS_EXPECT(seen.nlog >= 4);
  CS_EXPECT(seen.nprogress == 1);
  CS_EXPECT_NEAR(seen.t_last, 1.0, 1e-9, 0); /* 1000 steps of 1 ms, summed */
  CS_EXPECT(isfinite(seen.x_last[0]) && isfinite(seen.wall_last) && seen.wall_last > 0);
  /* where the run ended: the result's end state is where the progress saw it (t_end = 1 s) */
  CS_EXPECT_NEAR(seen.x_last[0], r.position[0], 1e-12, 0); /* the same state, read twice */
  const long n_out = fileSize(out_path), n_err = fileSize(err_path);
  CS_EXPECT(n_out == 0);
  CS_EXPECT(n_err == 0);
  if (n_out != 0 || n_err != 0) {
    fprintf(stderr, "--- written to stdout during the calls:\n");
    printFile(out_path);
    fprintf(stderr, "--- written to stderr during the calls:\n");
    printFile(err_path);
  }
  printf("1 s run: %d log lines, %d progress call(s) at t = %g s (x = %.3f mm); stdout %ld "
         "bytes, stderr %ld bytes during the calls\n", seen.nlog, seen.nprogress, seen.t_last,
         seen.x_last[0], n_out, n_err);
  remove(out_path);
  remove(err_path);
  remove("test_api_quiet.h5");
  remove("test_api_quiet.xdmf");
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_library_writes_nothing_to_stdout_or_stderr);
  return cs_testSummary();
}

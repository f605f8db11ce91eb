/* test_study_cli.c: `crawlsim study` end to end (tools/study_*.h, tools/cmd_study.c).
 *   argv[1] = the crawlsim executable, argv[2] = mpiexec (or "none" in a build without MPI).
 * What it proves:
 *  - bad study files are refused before anything runs: one line naming the file, the line and
 *    the cause, exit 1 (each kind of error once);
 *  - a small study (analytic bends, a short FE bend of a tiny actuator, a failing case, a short
 *    crawl run) runs sequentially into one HDF5 file with one progress line per case;
 *  - a second run without --resume is refused; with --resume it computes nothing; a missing or
 *    stale case file (killed case, edited case) is computed again, and only that one;
 *  - a study stopped by SIGINT (to its process group, as Ctrl-C), SIGTERM or kill -9 in the
 *    middle and then resumed gives the same results as the uninterrupted run (an interrupted
 *    case writes no case file, so it runs again; SIGINT/SIGTERM exit 128 + signal);
 *  - under `mpirun -n 2` the same study gives the same results, with the cases spread over
 *    ranks 0 and 1 (the MUMPS stub library also defines MPI_Comm_rank: both ranks would say 0
 *    if it were the one linked), for the dynamic and the static schedule.
 * The FE case meshes a 12 mm-segment actuator without fibres at l_soft 5 mm to 0.02 MPa (~10 s
 * for the bend, as much for its calibration step); OMP_NUM_THREADS=1 everywhere so that the
 * runs do the same arithmetic (no parallel reductions; see sameFe for what is left). */
#define _POSIX_C_SOURCE 200809L
#include <hdf5.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "cs_cli.h"
#include "cs_test.h"

static const char* g_exe;
static const char* g_mpiexec;

/* the small study: every kind of case a test can afford */
static const char kStudy[] =
    "# test_study_cli: a small study\n"
    "study small\n"
    "defaults bend --model analytic --actuator baseline --chambers 1,2 --p-max 0.4 --p-step 0.1\n"
    "case base bend --until-angle 100\n"
    "case r25 bend --set b=3 --set r1=2.5 --until-angle 100   # wider chambers bend more\n"
    "case two bend --pressures 1,0.5,0,0\n"
    "then run --t-end 0.2 --quiet\n"
    "defaults calibrate --actuator baseline --set S1=12 --set S2=12 --set S3=12 --set c=3"
    " --set LS12=4 --set LS23=4 --set n1=0 --set n2=0 --set n3=0 --mesh-size 5\n"
    "case fe_tiny bend --model fe --set S1=12 --set S2=12 --set S3=12 --set c=3 --set LS12=4"
    " --set LS23=4 --set n1=0 --set n2=0 --set n3=0 --mesh-size 5 --p-max 0.02 --p-step 0.02\n"
    "then calibrate --case O12 --p-max 0.02 --p-step 0.02\n"
    "case bad bend --model rom   # not available: the step fails, the case is recorded\n";

/* read a whole 1-D double dataset (n values at most); returns the count read, -1 on error */
static int readDoubles(hid_t f, const char* path, double* v, int n) {
  hid_t d = H5Dopen2(f, path, H5P_DEFAULT);
  if (d < 0) {
    return -1;
  }
  hid_t sp = H5Dget_space(d);
  hssize_t m = H5Sget_simple_extent_npoints(sp);
  int ok = m >= 0 && m <= n && H5Dread(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) >= 0;
  H5Sclose(sp);
  H5Dclose(d);
  return ok ? (int)m : -1;
}


/* a fixed-length string attribute of `obj` into out */
static int readAttr(hid_t f, const char* obj, const char* name, char* out, size_t size) {
  out[0] = '\0';
  hid_t a = H5Aopen_by_name(f, obj, name, H5P_DEFAULT, H5P_DEFAULT);
  if (a < 0) {
    return 0;
  }
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, size);
  hid_t ft = H5Aget_type(a);
  H5Tset_cset(t, H5Tget_cset(ft)); /* run and bend files write UTF-8 */
  H5Tclose(ft);
  int ok = H5Aread(a, t, out) >= 0;
  out[size - 1] = '\0';
  H5Tclose(t);
  H5Aclose(a);
  return ok;
}


/* count lines of text that contain `what` */
static int countLines(const char* text, const char* what) {
  int n = 0;
  for (const char* p = text; (p = strstr(p, what)) != NULL; p++) {
    n++;
  }
  return n;
}


/* ---- bad files --------------------------------------------------------------------------- */

typedef struct {
  const char* text; /* the file */
  int line;         /* the line the error must name */
  const char* cause; /* a piece of the message */
} BadFile;

static void refuses_bad_study_files(void) {
  static const BadFile kBad[] = {
      {"case a bend\nfrobnicate x\n", 2, "unknown statement 'frobnicate'"},
      {"case a\n", 1, "needs a name and a command"},
      {"case a simulate\n", 1, "unknown command 'simulate'"},
      {"case a bend\ncase a bend\n", 2, "already defined at line 1"},
      {"case a/b bend\n", 1, "case name 'a/b'"},
      {"then bend\n", 1, "'then' before the first case"},
      {"case a bend --p-maximum 1\n", 1, "unknown option '--p-maximum'"},
      {"case a bend --p-max\n", 1, "option --p-max needs a value"},
      {"case a bend --p-max nan\n", 1, "'nan' is not a finite number"},
      {"case a bend --p-max 1e999\n", 1, "'1e999' is not a finite number"},
      {"case a bend --out x.h5\n", 1, "--out is set by the study runner"},
      {"case a bend --p-max=0.3\n", 1, "write '--p-max VALUE'"},
      {"case a bend --set q=1\n", 1, "--set q=1"},
      {"# r1 too large for the wall\ncase a bend --set r1=5\n", 2, "is not valid"},
      {"case a run --gait nosuch.csv\n", 1, "no such file"},
      /* the strain level's step options are run options a study may give (a value is checked
       * as a number, so the option is known: tools/gait_search.py --legs strain passes them) */
      {"case a run --legs strain --strain-step adaptive --step-tol nan\n", 1,
       "'nan' is not a finite number"},
      {"case a run --legs strain --step-order x\n", 1, "'x' is not a finite number"},
      {"case a bend stray\n", 1, "unexpected word 'stray'"},
      {"case a bend\nthen bend\n", 2, "one step per command"},
      {"defaults fly --x\n", 1, "unknown command 'fly'"},
      {"case a bend\nstudy late\n", 2, "must come before the first case"},
      {"# nothing\n", 1, "no case"},
      {"case a gait-design\n", 1, "missing FILE.gait"},
      {"case a bend --model\tanalytic\r\nstudy x\n", 2, "must come before"},
  };
  for (size_t k = 0; k < sizeof kBad / sizeof kBad[0]; k++) {
    CS_EXPECT(cs_cliWriteText("bad.study", kBad[k].text));
    csCliResult r;
    cs_cliRun(g_exe, "study bad.study --check", "bad", &r);
    char where[32];
    snprintf(where, sizeof where, "bad.study:%d:", kBad[k].line);
    int ok = r.status == 1 && cs_cliOneLine(r.err) && strstr(r.err, where) &&
             strstr(r.err, kBad[k].cause);
    if (!ok) {
      fprintf(stderr, "bad file %zu: exit %d, stderr: %s", k, r.status, r.err);
    }
    CS_EXPECT(ok);
  }
  /* a NUL byte and an overlong line come from the line reader, with their line */
  FILE* f = fopen("bad.study", "wb");
  if (f) {
    fwrite("case a bend\ncase b be\0nd\n", 1, 26, f);
    fclose(f);
  }
  csCliResult r;
  cs_cliRun(g_exe, "study bad.study --check", "bad", &r);
  CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err) && strstr(r.err, "bad.study:2:") &&
            strstr(r.err, "NUL"));
  char* big = malloc(6000);
  if (big) {
    memcpy(big, "case a bend ", 12);
    memset(big + 12, 'x', 5000);
    strcpy(big + 5012, "\n");
    cs_cliWriteText("bad.study", big);
    free(big);
  }
  cs_cliRun(g_exe, "study bad.study --check", "bad", &r);
  CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err) && strstr(r.err, "bad.study:1:") &&
            strstr(r.err, "longer than"));
  cs_cliRun(g_exe, "study nosuch.study", "bad", &r);
  CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err) && strstr(r.err, "nosuch.study"));
  cs_cliRun(g_exe, "study", "bad", &r);
  CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err));
  cs_cliRun(g_exe, "study bad.study --schedule sometimes", "bad", &r);
  CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err) && strstr(r.err, "unknown schedule"));
  remove("bad.study");
}


/* ---- the small study: sequential, resume, MPI -------------------------------------------- */

enum { NCASE = 5 };
static const char* const kCases[NCASE] = {"base", "r25", "two", "fe_tiny", "bad"};

/* what the comparison of two runs looks at, per case */
typedef struct {
  char status[NCASE][32];
  double p_until[NCASE], angle[NCASE], x[NCASE][3];
  double fe_curve[64], cal_curve[64];
  int nfe, ncal;
  double run_pos[4096];
  int nrun;
  double rank[NCASE];
} Results;

static int readResults(const char* path, Results* r) {
  memset(r, 0, sizeof *r);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    return 0;
  }
  double xf[3 * NCASE];
  int ok = readDoubles(f, "/summary/p_until_angle_MPa", r->p_until, NCASE) == NCASE &&
           readDoubles(f, "/summary/angle_total_deg", r->angle, NCASE) == NCASE &&
           readDoubles(f, "/summary/x_final_mm", xf, 3 * NCASE) == 3 * NCASE &&
           readDoubles(f, "/summary/rank", r->rank, NCASE) == NCASE;
  for (int i = 0; i < NCASE; i++) {
    char obj[64];
    snprintf(obj, sizeof obj, "/cases/%s", kCases[i]);
    readAttr(f, obj, "status", r->status[i], sizeof r->status[i]);
    memcpy(r->x[i], xf + 3 * i, sizeof r->x[i]);
  }
  r->nfe = readDoubles(f, "/cases/fe_tiny/bend/angle_total_deg", r->fe_curve, 64);
  r->ncal = readDoubles(f, "/cases/fe_tiny/calibrate/cases/O12/angle_total_deg", r->cal_curve,
                        64);
  r->nrun = readDoubles(f, "/cases/two/run/support/position", r->run_pos, 4096);
  H5Fclose(f);
  return ok;
}


/* NaN-aware exact equality: analytic bends and crawl runs are bit-identical wherever they run */
static int same(double a, double b) { return (isnan(a) && isnan(b)) || a == b; }

/* FE values: equal to the last bits only when the case runs in the same place of a process.
 * Measured: the tiny FE bend run after a crawl run in the same process differs from the same
 * bend run first by 1.1e-14 deg of 0.472 (2.4e-14 relative; one thread everywhere, so not a
 * parallel reduction: the heap layout changes the blocking of the dense kernels). 1e-11
 * relative is a thousand times that and far below any physical difference. */
static int sameFe(double a, double b) {
  return (isnan(a) && isnan(b)) || fabs(a - b) <= 1e-11 * fmax(fabs(a), fabs(b));
}

static void expectSameResults(const Results* a, const Results* b) {
  for (int i = 0; i < NCASE; i++) {
    CS_EXPECT(!strcmp(a->status[i], b->status[i]));
    CS_EXPECT(same(a->p_until[i], b->p_until[i]));
    CS_EXPECT(sameFe(a->angle[i], b->angle[i]));
    for (int k = 0; k < 3; k++) {
      CS_EXPECT(same(a->x[i][k], b->x[i][k]));
    }
  }
  CS_EXPECT(a->nfe == b->nfe && a->nfe > 1);
  for (int k = 0; k < a->nfe && k < b->nfe; k++) {
    CS_EXPECT(sameFe(a->fe_curve[k], b->fe_curve[k]));
  }
  CS_EXPECT(a->ncal == b->ncal && a->ncal > 1);
  for (int k = 0; k < a->ncal && k < b->ncal; k++) {
    CS_EXPECT(sameFe(a->cal_curve[k], b->cal_curve[k]));
  }
  CS_EXPECT(a->nrun == b->nrun && a->nrun > 3);
  for (int k = 0; k < a->nrun && k < b->nrun; k++) {
    CS_EXPECT(same(a->run_pos[k], b->run_pos[k]));
  }
}

static Results g_seq;

static void runs_sequentially_then_resumes(void) {
  CS_EXPECT(cs_cliWriteText("small.study", kStudy));
  csCliResult r;
  cs_cliRun(g_exe, "study small.study --check", "seq", &r);
  CS_EXPECT(r.status == 0 && strstr(r.out, "5 cases, 7 steps: ok"));
  system("rm -rf seq_cases seq.h5");
  cs_cliRun(g_exe, "study small.study --out seq.h5", "seq", &r);
  /* `bad` fails (rom is not available): a result without a value, exit status 1 */
  CS_EXPECT(r.status == 1);
  CS_EXPECT(countLines(r.err, "crawlsim study: [") == NCASE);
  CS_EXPECT(strstr(r.err, "] bad failed") != NULL);
  CS_EXPECT(strstr(r.out, "4 complete, 0 stopped, 1 failed, 0 missing") != NULL);
  if (r.status != 1) {
    fprintf(stderr, "%s%s", r.out, r.err);
  }
  CS_EXPECT(readResults("seq.h5", &g_seq));
  for (int i = 0; i < NCASE - 1; i++) {
    CS_EXPECT(!strcmp(g_seq.status[i], "complete"));
  }
  CS_EXPECT(!strcmp(g_seq.status[4], "failed"));
  /* the analytic values, each case in its own process-free context: wider chambers bend more */
  CS_EXPECT(g_seq.p_until[1] < g_seq.p_until[0]);
  CS_EXPECT(isnan(g_seq.p_until[2]) && !isnan(g_seq.x[2][0]));

  /* again without --resume: refused (one line), nothing recomputed */
  cs_cliRun(g_exe, "study small.study --out seq.h5", "seq", &r);
  CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err) && strstr(r.err, "--resume"));
  /* --resume: nothing to run (the failed case counts as finished); --retry-failed reruns it */
  cs_cliRun(g_exe, "study small.study --out seq.h5 --resume", "seq", &r);
  CS_EXPECT(strstr(r.out, "0 to run") && countLines(r.err, "crawlsim study: [") == 0);
  cs_cliRun(g_exe, "study small.study --out seq.h5 --retry-failed --case bad", "seq", &r);
  CS_EXPECT(strstr(r.out, "1 to run") && countLines(r.err, "crawlsim study: [") == 1 &&
            strstr(r.err, "] bad failed"));
  /* a killed case: no case file (its .part and work files are left behind) -> run again */
  remove("seq_cases/r25.h5");
  cs_cliWriteText("seq_cases/r25.h5.part", "half a file");
  cs_cliRun(g_exe, "study small.study --out seq.h5 --resume", "seq", &r);
  CS_EXPECT(strstr(r.out, "1 to run") && countLines(r.err, "crawlsim study: [") == 1 &&
            strstr(r.err, "] r25 complete"));
  /* an edited case is stale: rerun, the others kept */
  char* edited = malloc(sizeof kStudy + 64);
  if (edited) {
    snprintf(edited, sizeof kStudy + 64, "%s", kStudy);
    char* p = strstr(edited, "--until-angle 100   #");
    if (p) {
      memcpy(p, "--until-angle 110   #", 21);
    }
    cs_cliWriteText("edited.study", edited);
    free(edited);
  }
  cs_cliRun(g_exe, "study edited.study --out seq.h5 --resume --list", "seq", &r);
  CS_EXPECT(strstr(r.out, "r25                      stale") != NULL);
  cs_cliRun(g_exe, "study edited.study --out seq.h5 --resume", "seq", &r);
  CS_EXPECT(strstr(r.out, "1 to run") && strstr(r.err, "] r25 complete") &&
            strstr(r.err, "total angle 110 deg"));
  /* back to the original: r25 runs once more and the results are the first run's */
  cs_cliRun(g_exe, "study small.study --out seq.h5 --resume", "seq", &r);
  CS_EXPECT(strstr(r.out, "1 to run"));
  Results again;
  CS_EXPECT(readResults("seq.h5", &again));
  expectSameResults(&g_seq, &again);
  remove("edited.study");
}


/* start `crawlsim study small.study --out kill.h5` in its own process group, send `sig` after
 * `delay_s` (to the group for SIGINT, as a terminal's Ctrl-C does), wait; returns the exit
 * status as a shell reports it (128 + signal for a death by signal), or -1 if the study had
 * finished before the signal */
static int runAndSignal(int sig, double delay_s) {
  pid_t pid = fork();
  if (pid == 0) {
    setpgid(0, 0);
    /* as from a terminal: ctest itself may run with SIGINT ignored (a background job), which
     * crawlsim would keep */
    signal(SIGINT, SIG_DFL);
    signal(SIGTERM, SIG_DFL);
    if (!freopen("kill.out", "w", stdout) || !freopen("kill.err", "w", stderr)) {
      _exit(127);
    }
    execl(g_exe, g_exe, "study", "small.study", "--out", "kill.h5", (char*)NULL);
    _exit(127);
  }
  if (pid < 0) {
    return -2;
  }
  setpgid(pid, pid);
  struct timespec ts = {(time_t)delay_s, (long)((delay_s - (time_t)delay_s) * 1e9)};
  nanosleep(&ts, NULL);
  int status = 0;
  if (waitpid(pid, &status, WNOHANG) == pid) {
    return -1;
  }
  if (sig == SIGINT) {
    kill(-pid, sig);
  } else {
    kill(pid, sig);
  }
  waitpid(pid, &status, 0);
  if (sig == SIGKILL) {
    kill(-pid, SIGKILL); /* gmsh may outlive its parent */
  }
  return WIFSIGNALED(status) ? 128 + WTERMSIG(status) : WEXITSTATUS(status);
}


static void interrupted_or_killed_then_resumed_gives_the_same_results(void) {
  /* the signals are crawlsim's promise; crawlsim-mpi (MPI initialised in its main, OpenMPI's
   * singleton daemon beside it) is not held to it yet: under it this case fails (the exit status
   * is not 128 + the signal and the resumed table differs: docs/notes/faults.md, "Not covered") */
  const char* base = strrchr(g_exe, '/');
  if (!strcmp(base ? base + 1 : g_exe, "crawlsim-mpi")) {
    fprintf(stderr, "test_study_cli: signals are not tested through crawlsim-mpi\n");
    return;
  }
  /* the study runs ~25 s (the FE case is most of it): the signals land in the analytic bends
   * and the crawl run, in the FE bend, and in the FE calibration step */
  static const int kSig[3] = {SIGINT, SIGTERM, SIGKILL};
  static const double kDelay[3] = {1.0, 6.0, 14.0};
  for (int k = 0; k < 3; k++) {
    system("rm -rf kill_cases kill.h5");
    int rc = runAndSignal(kSig[k], kDelay[k]);
    if (rc == -1) {
      fprintf(stderr, "test_study_cli: the study finished within %.0f s: signal %d not tested\n",
              kDelay[k], kSig[k]);
    } else {
      CS_EXPECT(rc == 128 + kSig[k]);
    }
    csCliResult r;
    cs_cliRun(g_exe, "study small.study --out kill.h5 --resume", "kill", &r);
    CS_EXPECT(r.status == 1); /* the failing case, as in the uninterrupted run */
    CS_EXPECT(strstr(r.out, "4 complete, 0 stopped, 1 failed, 0 missing") != NULL);
    Results m;
    CS_EXPECT(readResults("kill.h5", &m));
    expectSameResults(&g_seq, &m);
  }
  system("rm -rf kill_cases kill.h5 kill.out kill.err");
}


static void mpirun_two_ranks_gives_the_same_results(void) {
  if (!strcmp(g_mpiexec, "none")) {
    fprintf(stderr, "test_study_cli: no MPI in this build: the mpirun case is skipped\n");
    return;
  }
  static const char* const kSchedules[2] = {"dynamic", "static"};
  for (int k = 0; k < 2; k++) {
    char cmd[2048];
    system("rm -rf mpi_cases mpi.h5");
    /* --oversubscribe: the CI machine may have one core; --bind-to none: ctest may run other
     * tests beside this one */
    snprintf(cmd, sizeof cmd, "\"%s\" -n 2 --oversubscribe --bind-to none \"%s\" study "
             "small.study --out mpi.h5 --schedule %s", g_mpiexec, g_exe, kSchedules[k]);
    csCliResult r;
    cs_cliRun("env", cmd, "mpi", &r);
    CS_EXPECT(r.status == 1); /* the failing case, as sequentially */
    CS_EXPECT(strstr(r.out, "2 ranks") != NULL);
    CS_EXPECT(strstr(r.out, "4 complete, 0 stopped, 1 failed, 0 missing") != NULL);
    CS_EXPECT(countLines(r.err, "crawlsim study: [") == NCASE);
    Results m;
    CS_EXPECT(readResults("mpi.h5", &m));
    expectSameResults(&g_seq, &m);
    int on0 = 0, on1 = 0;
    for (int i = 0; i < NCASE; i++) {
      on0 += m.rank[i] == 0;
      on1 += m.rank[i] == 1;
    }
    if (!(on0 > 0 && on1 > 0 && on0 + on1 == NCASE)) {
      fprintf(stderr, "schedule %s: ranks %g %g %g %g %g\n%s%s", kSchedules[k], m.rank[0],
              m.rank[1], m.rank[2], m.rank[3], m.rank[4], r.out, r.err);
    }
    CS_EXPECT(on0 > 0 && on1 > 0 && on0 + on1 == NCASE);
  }
}


int main(int argc, char** argv) {
  if (argc < 3) {
    fprintf(stderr, "usage: test_study_cli CRAWLSIM MPIEXEC|none [filter]\n");
    return 2;
  }
  g_exe = argv[1];
  g_mpiexec = argv[2];
  cs_test_state_.filter = argc > 3 ? argv[3] : NULL;
  /* the same arithmetic in every run; root in CI may start mpirun (debian-deps.md) */
  setenv("OMP_NUM_THREADS", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  CS_RUN(refuses_bad_study_files);
  CS_RUN(runs_sequentially_then_resumes);
  CS_RUN(interrupted_or_killed_then_resumed_gives_the_same_results);
  CS_RUN(mpirun_two_ranks_gives_the_same_results);
  system("rm -rf seq_cases seq.h5 mpi_cases mpi.h5 small.study");
  return cs_testSummary();
}

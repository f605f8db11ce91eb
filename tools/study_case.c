/* study_case.c: one case of a study run in-process, its case file, the merge (study_case.h).
 *
 * Why in-process and not a child `crawlsim` per case: a case is exactly what the command does
 * on the command line (the same parser, checks and output), an MPI rank stays one process (a
 * fork under mpirun is fragile), and there is nothing to find on PATH. Each step is the
 * command's step function (csxStepFn): the command's parser builds its definition from the
 * case's words, the command writes its lines to a log stream this file opens and owns, and its
 * results come back in a struct; nothing is redirected and no log is read for results (the log
 * is only copied into the case file). A command must not keep state between calls (none does:
 * each builds its model and data and frees them).
 *
 * The HDF5 C API is used directly here (object copy, reading attributes and the last row of a
 * dataset), which core_h5.h, a writer, does not offer. All HDF5 calls are made from the thread
 * that runs the cases (debian-deps.md P5). */
#define _POSIX_C_SOURCE 200809L
#include <ctype.h>
#include <errno.h>
#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "core_clock.h"
#include "core_text.h"
#include "study_case.h"

#define LOG_KEEP_BYTES (1 << 20) /* a step's log kept in the case file: its last 1 MiB */
#define STRING_SIZE_NAME CSX_STUDY_NAME_SIZE
#define STRING_SIZE_STATUS 16
#define VERSION "0.1.0" /* = CSR_OUTPUT_VERSION (robot_bend_io.h) and project(VERSION) */

/* a case or study file (`part`) that HDF5 could not create or write: removed, and the cause
 * named (errno from the write HDF5 made, and the free space: HDF5 hides the first behind its
 * own error stack) */
static csStatus writeFailed(const char* part, const char* what, csError* err) {
  int e = errno;
  char space[96];
  csu_freeSpace(part, space, sizeof space);
  remove(part);
  return cs_errorSet(err, CS_ERR_IO, "%s: cannot %s: %s (%s)", part, what,
                     e ? strerror(e) : "HDF5 write failed", space);
}

/* a step's output file in the work directory, and what the runner adds to its words */
static const char* const kOutName[CSX_STUDY_NCMD] = {"bend.h5", "run.h5", "calibration.h5",
                                                     "gait.csv"};
static const char* const kArgv0[CSX_STUDY_NCMD] = {"bend", "run", "calibrate", "design"};
static const char* const kGroup[CSX_STUDY_NCMD] = {"bend", "run", "calibrate", "gait_design"};

/* key results of a case, NaN where none */
typedef struct {
  double p_until, angle_total, p_end, t_final, x_final[3];
  char verdict[CSX_STUDY_SUMMARY_SIZE];
} Results;

/* "<dir>/<name><suffix>" into out; -1 if it does not fit */
static int joinPath(char* out, size_t size, const char* dir, const char* name,
                    const char* suffix);
/* a whole text file (the last `keep` bytes); NULL if unreadable; *len its length */
static char* readText(const char* path, size_t keep, size_t* len);
/* HDF5 helpers: attributes, text datasets, the last row of a dataset */
static int attrString(hid_t obj, const char* name, const char* value);
static int attrDoubles(hid_t obj, const char* name, const double* v, int n);
static int readAttrString(hid_t obj, const char* name, char* out, size_t size);
static int readAttrDouble(hid_t obj, const char* name, double* v);
static int writeText(hid_t loc, const char* name, const char* text, size_t len);
/* key results from the steps' result structs */
static void collectResults(const csxStudyCase* c, const csxStepResult* sr, int nran,
                           Results* r);
/* the case file */
static csStatus writeCaseFile(const csxStudy* s, int i, const char* dir, const char* work,
                              int nran, const csxCaseResult* res, const char* message,
                              const Results* r, csError* err);


const char* csx_caseStateName(csxCaseState s) {
  switch (s) {
    case CSX_CASE_PENDING:
      return "pending";
    case CSX_CASE_COMPLETE:
      return "complete";
    case CSX_CASE_STOPPED:
      return "stopped";
    case CSX_CASE_FAILED:
      return "failed";
    case CSX_CASE_STALE:
      return "stale";
  }
  return "?";
}


static int joinPath(char* out, size_t size, const char* dir, const char* name,
                    const char* suffix) {
  int k = snprintf(out, size, "%s/%s%s", dir, name, suffix);
  return k >= 0 && (size_t)k < size ? 0 : -1;
}


csStatus csx_studyMakeDir(const char* path, csError* err) {
  if (mkdir(path, 0777) != 0 && errno != EEXIST) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot create directory: %s", path, strerror(errno));
  }
  struct stat sb;
  if (stat(path, &sb) != 0 || !S_ISDIR(sb.st_mode)) {
    return cs_errorSet(err, CS_ERR_IO, "%s: exists and is not a directory", path);
  }
  return CS_OK;
}


void csx_stepFailed(csxStepResult* res, FILE* log, const char* cmd, const char* msg) {
  char line[CS_ERROR_MSG_SIZE];
  snprintf(line, sizeof line, "crawlsim %s: %s", cmd, msg && *msg ? msg : "failed");
  for (char* c = line; *c; c++) {
    if (iscntrl((unsigned char)*c)) {
      *c = '?'; /* one line, whatever the words held (as csx_optReport) */
    }
  }
  if (res) {
    memcpy(res->message, line, sizeof res->message);
  }
  if (log) {
    fprintf(log, "%s\n", line);
  }
}


/* a step's result before the step: nothing known */
static void stepResultInit(csxStepResult* r) {
  memset(r, 0, sizeof *r);
  r->p_until = r->angle_total = r->p_end = r->t_final = NAN;
  r->x_final[0] = r->x_final[1] = r->x_final[2] = NAN;
}


static char* readText(const char* path, size_t keep, size_t* len) {
  FILE* f = fopen(path, "rb");
  if (!f) {
    return NULL;
  }
  long size = -1;
  if (fseek(f, 0, SEEK_END) == 0) {
    size = ftell(f);
  }
  long from = size > (long)keep ? size - (long)keep : 0;
  char* buf = size >= 0 ? malloc((size_t)(size - from) + 1) : NULL;
  size_t n = 0;
  if (buf && fseek(f, from, SEEK_SET) == 0) {
    n = fread(buf, 1, (size_t)(size - from), f);
  }
  fclose(f);
  if (!buf) {
    return NULL;
  }
  buf[n] = '\0';
  *len = n;
  return buf;
}


static int attrString(hid_t obj, const char* name, const char* value) {
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, strlen(value) + 1);
  hid_t sp = H5Screate(H5S_SCALAR);
  hid_t a = H5Acreate2(obj, name, t, sp, H5P_DEFAULT, H5P_DEFAULT);
  int ok = a >= 0 && H5Awrite(a, t, value) >= 0;
  if (a >= 0) {
    H5Aclose(a);
  }
  H5Sclose(sp);
  H5Tclose(t);
  return ok;
}


static int attrDoubles(hid_t obj, const char* name, const double* v, int n) {
  hsize_t dim = (hsize_t)n;
  hid_t sp = n == 1 ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, &dim, NULL);
  hid_t a = H5Acreate2(obj, name, H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT);
  int ok = a >= 0 && H5Awrite(a, H5T_NATIVE_DOUBLE, v) >= 0;
  if (a >= 0) {
    H5Aclose(a);
  }
  H5Sclose(sp);
  return ok;
}


static int readAttrString(hid_t obj, const char* name, char* out, size_t size) {
  out[0] = '\0';
  if (H5Aexists(obj, name) <= 0) {
    return 0;
  }
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  hid_t ft = a >= 0 ? H5Aget_type(a) : -1;
  int ok = 0;
  if (ft >= 0 && H5Tget_class(ft) == H5T_STRING && !H5Tis_variable_str(ft)) {
    size_t n = H5Tget_size(ft);
    char* buf = malloc(n + 1);
    hid_t mt = H5Tcopy(H5T_C_S1);
    H5Tset_size(mt, n + 1);
    H5Tset_cset(mt, H5Tget_cset(ft)); /* run files write UTF-8; HDF5 converts no charsets */
    if (buf && H5Aread(a, mt, buf) >= 0) {
      buf[n] = '\0';
      snprintf(out, size, "%s", buf);
      ok = 1;
    }
    H5Tclose(mt);
    free(buf);
  }
  if (ft >= 0) {
    H5Tclose(ft);
  }
  if (a >= 0) {
    H5Aclose(a);
  }
  return ok;
}


static int readAttrDouble(hid_t obj, const char* name, double* v) {
  if (H5Aexists(obj, name) <= 0) {
    return 0;
  }
  hid_t a = H5Aopen(obj, name, H5P_DEFAULT);
  hid_t sp = a >= 0 ? H5Aget_space(a) : -1;
  int ok = sp >= 0 && H5Sget_simple_extent_npoints(sp) == 1 &&
           H5Aread(a, H5T_NATIVE_DOUBLE, v) >= 0;
  if (sp >= 0) {
    H5Sclose(sp);
  }
  if (a >= 0) {
    H5Aclose(a);
  }
  return ok;
}


static int writeText(hid_t loc, const char* name, const char* text, size_t len) {
  hid_t lcpl = H5Pcreate(H5P_LINK_CREATE);
  H5Pset_create_intermediate_group(lcpl, 1);
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, len > 0 ? len : 1);
  H5Tset_strpad(t, H5T_STR_NULLPAD);
  hid_t sp = H5Screate(H5S_SCALAR);
  hid_t d = H5Dcreate2(loc, name, t, sp, lcpl, H5P_DEFAULT, H5P_DEFAULT);
  int ok = d >= 0 && H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, len > 0 ? text : "") >= 0;
  if (d >= 0) {
    H5Dclose(d);
  }
  H5Sclose(sp);
  H5Tclose(t);
  H5Pclose(lcpl);
  return ok;
}


/* open an HDF5 file read-only, or -1 (no message: HDF5's error stack is off) */
static hid_t openRead(const char* path) {
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  if (access(path, R_OK) != 0 || H5Fis_hdf5(path) <= 0) {
    return -1;
  }
  return H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
}


csxCaseState csx_studyCaseState(const csxStudy* s, int i, const char* dir, csxCaseResult* res) {
  char path[CSX_STUDY_PATH_SIZE];
  if (res) {
    memset(res, 0, sizeof *res);
    res->wall_s = NAN;
    res->rank = -1;
  }
  if (joinPath(path, sizeof path, dir, s->cases[i].name, ".h5") != 0) {
    return CSX_CASE_PENDING;
  }
  hid_t f = openRead(path);
  if (f < 0) {
    return CSX_CASE_PENDING;
  }
  char fmt[64], status[32];
  size_t nsig = strlen(s->cases[i].signature) + 2;
  char* sig = malloc(nsig);
  csxCaseState st = CSX_CASE_PENDING;
  if (sig && readAttrString(f, "format", fmt, sizeof fmt) &&
      !strcmp(fmt, CSX_STUDY_CASE_FORMAT) && readAttrString(f, "status", status, sizeof status)) {
    /* a longer recorded signature is cut at nsig - 1 and differs from ours all the same */
    readAttrString(f, "signature", sig, nsig);
    if (strcmp(sig, s->cases[i].signature)) {
      st = CSX_CASE_STALE;
    } else if (!strcmp(status, "complete")) {
      st = CSX_CASE_COMPLETE;
    } else if (!strcmp(status, "stopped")) {
      st = CSX_CASE_STOPPED;
    } else if (!strcmp(status, "failed")) {
      st = CSX_CASE_FAILED;
    }
  }
  if (res) {
    res->state = st;
    readAttrString(f, "summary", res->summary, sizeof res->summary);
    readAttrDouble(f, "wall_time_s", &res->wall_s);
    double rk = -1;
    readAttrDouble(f, "rank", &rk);
    res->rank = (int)rk;
  }
  free(sig);
  H5Fclose(f);
  return st;
}


static void collectResults(const csxStudyCase* c, const csxStepResult* sr, int nran,
                           Results* r) {
  r->p_until = r->angle_total = r->p_end = r->t_final = NAN;
  r->x_final[0] = r->x_final[1] = r->x_final[2] = NAN;
  r->verdict[0] = '\0';
  for (int k = 0; k < nran; k++) {
    if (c->step[k].cmd == CSX_STUDY_BEND) {
      r->p_until = sr[k].p_until;
      r->angle_total = sr[k].angle_total;
      r->p_end = sr[k].p_end;
    } else if (c->step[k].cmd == CSX_STUDY_RUN) {
      r->t_final = sr[k].t_final;
      memcpy(r->x_final, sr[k].x_final, sizeof r->x_final);
      memcpy(r->verdict, sr[k].verdict, sizeof r->verdict); /* the same size, NUL-ended */
    }
  }
}


/* append "; piece" (or "piece") to the summary */
static void addSummary(char* sum, const char* piece) {
  size_t n = strlen(sum);
  if (n + 1 < CSX_STUDY_SUMMARY_SIZE) {
    snprintf(sum + n, CSX_STUDY_SUMMARY_SIZE - n, "%s%s", n ? "; " : "", piece);
  }
}


static csStatus writeCaseFile(const csxStudy* s, int i, const char* dir, const char* work,
                              int nran, const csxCaseResult* res, const char* message,
                              const Results* r, csError* err) {
  const csxStudyCase* c = &s->cases[i];
  char path[CSX_STUDY_PATH_SIZE], part[CSX_STUDY_PATH_SIZE];
  if (joinPath(path, sizeof path, dir, c->name, ".h5") != 0 ||
      joinPath(part, sizeof part, dir, c->name, ".h5.part") != 0) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: case file path too long", dir);
  }
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  errno = 0;
  hid_t f = H5Fcreate(part, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (f < 0) {
    return writeFailed(part, "create the case file", err);
  }
  /* the steps' outputs and logs */
  int ok = 1;
  hid_t ocpy = H5Pcreate(H5P_OBJECT_COPY);
  for (int k = 0; k < nran && ok; k++) {
    csxStudyCmd cmd = c->step[k].cmd;
    char out[CSX_STUDY_PATH_SIZE], log[CSX_STUDY_PATH_SIZE], name[64];
    if (joinPath(out, sizeof out, work, kOutName[cmd], "") != 0 ||
        joinPath(log, sizeof log, work, kArgv0[cmd], ".log") != 0) {
      continue;
    }
    size_t n = 0;
    char* text = readText(log, LOG_KEEP_BYTES, &n);
    snprintf(name, sizeof name, "/log/%s", kGroup[cmd]);
    ok = writeText(f, name, text ? text : "", text ? n : 0);
    free(text);
    if (cmd == CSX_STUDY_GAIT_DESIGN) {
      text = readText(out, (size_t)64 << 20, &n);
      if (text) {
        ok = ok && writeText(f, "/gait_design/csv", text, n);
        free(text);
      }
      continue;
    }
    hid_t src = openRead(out);
    if (src >= 0) {
      ok = ok && H5Ocopy(src, "/", f, kGroup[cmd], ocpy, H5P_DEFAULT) >= 0;
      H5Fclose(src);
    }
  }
  H5Pclose(ocpy);
  /* root attributes */
  char host[256] = "?", when[32] = "?";
  if (gethostname(host, sizeof host) != 0) {
    snprintf(host, sizeof host, "?");
  }
  host[sizeof host - 1] = '\0';
  time_t now = time(NULL);
  struct tm tmv;
  if (gmtime_r(&now, &tmv)) {
    strftime(when, sizeof when, "%Y-%m-%dT%H:%M:%SZ", &tmv);
  }
  double rank = res->rank;
  ok = ok && attrString(f, "format", CSX_STUDY_CASE_FORMAT) && attrString(f, "study", s->name) &&
       attrString(f, "case", c->name) && attrString(f, "signature", c->signature) &&
       attrString(f, "status", csx_caseStateName(res->state)) &&
       attrString(f, "message", message) && attrString(f, "summary", res->summary) &&
       attrDoubles(f, "wall_time_s", &res->wall_s, 1) && attrDoubles(f, "rank", &rank, 1) &&
       attrString(f, "host", host) && attrString(f, "finished", when) &&
       attrString(f, "version", VERSION);
  if (ok && !isnan(r->p_until)) ok = attrDoubles(f, "p_until_angle_MPa", &r->p_until, 1);
  if (ok && !isnan(r->angle_total)) ok = attrDoubles(f, "angle_total_deg", &r->angle_total, 1);
  if (ok && !isnan(r->p_end)) ok = attrDoubles(f, "p_end_MPa", &r->p_end, 1);
  if (ok && !isnan(r->t_final)) ok = attrDoubles(f, "t_final_s", &r->t_final, 1);
  if (ok && !isnan(r->x_final[0])) ok = attrDoubles(f, "x_final_mm", r->x_final, 3);
  if (ok && r->verdict[0]) ok = attrString(f, "verdict", r->verdict);
  errno = ok ? 0 : errno;
  if (H5Fclose(f) < 0 || !ok) {
    return writeFailed(part, "write the case file", err);
  }
  if (rename(part, path) != 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot rename to %s: %s", part, path,
                       strerror(errno));
  }
  return CS_OK;
}


csStatus csx_studyRunCase(const csxStudy* s, int i, const char* dir, const csxStudyCommands* cmd,
                          int rank, csxCaseResult* res, csError* err) {
  const csxStudyCase* c = &s->cases[i];
  char work[CSX_STUDY_PATH_SIZE];
  memset(res, 0, sizeof *res);
  res->rank = rank;
  if (joinPath(work, sizeof work, dir, c->name, "") != 0) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: case directory path too long", dir);
  }
  csStatus st = csx_studyMakeDir(work, err);
  if (st != CS_OK) {
    return st;
  }
  if (cmd->cancel && *cmd->cancel) {
    return cs_errorSet(err, CS_ERR_INTERRUPTED, "case %s: not started (interrupted)", c->name);
  }
  const double t0 = csu_wallSeconds();
  char message[CS_ERROR_MSG_SIZE] = "";
  res->state = CSX_CASE_COMPLETE;
  int nran = 0;
  csxStepResult sr[CSX_STUDY_NCMD]; /* what each step that ran reported */
  for (int k = 0; k < c->nstep && res->state == CSX_CASE_COMPLETE; k++) {
    const csxStudyStep* sp = &c->step[k];
    if (!cmd->fn[sp->cmd]) {
      res->state = CSX_CASE_FAILED;
      snprintf(message, sizeof message, "%s: not available in this build",
               csx_studyCmdName(sp->cmd));
      break;
    }
    /* argv: the command, the words (paths resolved), then the outputs the runner owns */
    enum { EXTRA = 6 };
    char** argv = calloc((size_t)sp->nword + EXTRA, sizeof(char*));
    char* store = malloc(((size_t)sp->nword + EXTRA) * CSX_STUDY_PATH_SIZE);
    if (!argv || !store) {
      free(argv);
      free(store);
      return cs_errorSet(err, CS_ERR_MEMORY, "case %s: out of memory", c->name);
    }
    int argc = 0;
    argv[argc++] = (char*)kArgv0[sp->cmd];
    for (int w = 0; w < sp->nword; w++) {
      char* slot = store + (size_t)argc * CSX_STUDY_PATH_SIZE;
      if (csx_studyWordIsPath(sp, w)) {
        csx_studyResolvePath(s, work, sp->word[w], slot, CSX_STUDY_PATH_SIZE);
        argv[argc++] = slot;
      } else {
        argv[argc++] = sp->word[w];
      }
    }
    char out[CSX_STUDY_PATH_SIZE], log[CSX_STUDY_PATH_SIZE], cdir[CSX_STUDY_PATH_SIZE];
    if (joinPath(out, sizeof out, work, kOutName[sp->cmd], "") != 0 ||
        joinPath(log, sizeof log, work, kArgv0[sp->cmd], ".log") != 0 ||
        joinPath(cdir, sizeof cdir, work, "calibration", "") != 0) {
      free(argv);
      free(store);
      return cs_errorSet(err, CS_ERR_RANGE, "%s: case directory path too long", work);
    }
    argv[argc++] = "--out";
    argv[argc++] = out;
    if (sp->cmd == CSX_STUDY_CALIBRATE) {
      argv[argc++] = "--dir";
      argv[argc++] = cdir;
    }
    /* an output left by a killed earlier attempt must not pass for this one's */
    remove(out);
    FILE* lf = fopen(log, "w");
    if (!lf) {
      free(argv);
      free(store);
      return cs_errorSet(err, CS_ERR_IO, "%s: cannot create log: %s", log, strerror(errno));
    }
    stepResultInit(&sr[k]);
    int rc = cmd->fn[sp->cmd](argc, argv, lf, &sr[k]);
    fclose(lf); /* the log is a record for the reader; the results are in sr[k] */
    free(argv);
    free(store);
    if (cmd->cancel && *cmd->cancel) {
      /* a signal ended the step: its result is no result; no case file, the case stays pending */
      return cs_errorSet(err, CS_ERR_INTERRUPTED, "case %s: interrupted in %s (exit %d); it "
                         "runs again with --resume", c->name, csx_studyCmdName(sp->cmd), rc);
    }
    nran++;
    if (rc == 0) {
      continue;
    }
    /* a run that ended early but wrote its samples (the robot fell) is a result */
    res->state = sp->cmd == CSX_STUDY_RUN && sr[k].wrote_samples && k == c->nstep - 1
                     ? CSX_CASE_STOPPED : CSX_CASE_FAILED;
    snprintf(message, sizeof message, "%s (exit %d): %s", csx_studyCmdName(sp->cmd), rc,
             sr[k].message[0] ? sr[k].message : "no message");
  }
  res->wall_s = csu_wallSeconds() - t0;
  /* the summary: one piece per step that has something to say */
  Results r;
  collectResults(c, sr, nran, &r);
  res->summary[0] = '\0';
  for (int k = 0; k < nran; k++) {
    if (sr[k].summary[0]) {
      addSummary(res->summary, sr[k].summary);
    }
  }
  if (res->state == CSX_CASE_FAILED) {
    addSummary(res->summary, message);
  }
  return writeCaseFile(s, i, dir, work, nran, res, message, &r, err);
}


/* write a [n] array of fixed-length strings (each `size` bytes, NUL-padded) */
static int writeStrings(hid_t loc, const char* name, const char* data, int n, size_t size) {
  hsize_t dim = (hsize_t)n;
  hid_t t = H5Tcopy(H5T_C_S1);
  H5Tset_size(t, size);
  hid_t sp = H5Screate_simple(1, &dim, NULL);
  hid_t d = H5Dcreate2(loc, name, t, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  int ok = d >= 0 && H5Dwrite(d, t, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) >= 0;
  if (d >= 0) {
    H5Dclose(d);
  }
  H5Sclose(sp);
  H5Tclose(t);
  return ok;
}


static int writeDoubles(hid_t loc, const char* name, const double* v, int n, int ncol) {
  hsize_t dim[2] = {(hsize_t)n, (hsize_t)ncol};
  hid_t sp = H5Screate_simple(ncol == 1 ? 1 : 2, dim, NULL);
  hid_t d = H5Dcreate2(loc, name, H5T_NATIVE_DOUBLE, sp, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  int ok = d >= 0 && H5Dwrite(d, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, v) >= 0;
  if (d >= 0) {
    H5Dclose(d);
  }
  H5Sclose(sp);
  return ok;
}


csStatus csx_studyMerge(const csxStudy* s, const char* dir, const char* out,
                        const csxStudyRunInfo* info, int counts[4], csError* err) {
  char part[CSX_STUDY_PATH_SIZE];
  if (snprintf(part, sizeof part, "%s.part", out) >= (int)sizeof part) {
    return cs_errorSet(err, CS_ERR_RANGE, "%s: path too long", out);
  }
  int n = s->ncase;
  /* per-case summary columns */
  char* names = calloc((size_t)n, STRING_SIZE_NAME);
  char* status = calloc((size_t)n, STRING_SIZE_STATUS);
  char* sums = calloc((size_t)n, CSX_STUDY_SUMMARY_SIZE);
  double* col = malloc((size_t)n * 9 * sizeof(double));
  if (!names || !status || !sums || !col) {
    free(names);
    free(status);
    free(sums);
    free(col);
    return cs_errorSet(err, CS_ERR_MEMORY, "%s: out of memory", out);
  }
  double *wall = col, *pu = col + n, *ang = col + 2 * n, *pend = col + 3 * n;
  double *tfin = col + 4 * n, *rank = col + 5 * n, *xf = col + 6 * n; /* xf: n x 3 */
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  errno = 0;
  hid_t f = H5Fcreate(part, H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (f < 0) {
    free(names);
    free(status);
    free(sums);
    free(col);
    return writeFailed(part, "create the study file", err);
  }
  hid_t cases = H5Gcreate2(f, "cases", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  hid_t ocpy = H5Pcreate(H5P_OBJECT_COPY);
  int cnt[4] = {0, 0, 0, 0};
  int ok = cases >= 0;
  for (int i = 0; i < n && ok; i++) {
    csxCaseResult res;
    csxCaseState st = csx_studyCaseState(s, i, dir, &res);
    snprintf(names + (size_t)i * STRING_SIZE_NAME, STRING_SIZE_NAME, "%s", s->cases[i].name);
    wall[i] = pu[i] = ang[i] = pend[i] = tfin[i] = rank[i] = NAN;
    xf[3 * i] = xf[3 * i + 1] = xf[3 * i + 2] = NAN;
    int done = st == CSX_CASE_COMPLETE || st == CSX_CASE_STOPPED || st == CSX_CASE_FAILED;
    snprintf(status + (size_t)i * STRING_SIZE_STATUS, STRING_SIZE_STATUS, "%s",
             done ? csx_caseStateName(st) : "missing");
    cnt[done ? (int)st - 1 : 3]++;
    if (!done) {
      continue;
    }
    snprintf(sums + (size_t)i * CSX_STUDY_SUMMARY_SIZE, CSX_STUDY_SUMMARY_SIZE, "%s",
             res.summary);
    wall[i] = res.wall_s;
    rank[i] = res.rank;
    char path[CSX_STUDY_PATH_SIZE];
    joinPath(path, sizeof path, dir, s->cases[i].name, ".h5");
    hid_t src = openRead(path);
    if (src < 0) {
      ok = 0;
      break;
    }
    readAttrDouble(src, "p_until_angle_MPa", &pu[i]);
    readAttrDouble(src, "angle_total_deg", &ang[i]);
    readAttrDouble(src, "p_end_MPa", &pend[i]);
    readAttrDouble(src, "t_final_s", &tfin[i]);
    if (H5Aexists(src, "x_final_mm") > 0) {
      hid_t a = H5Aopen(src, "x_final_mm", H5P_DEFAULT);
      H5Aread(a, H5T_NATIVE_DOUBLE, xf + 3 * i);
      H5Aclose(a);
    }
    ok = H5Ocopy(src, "/", cases, s->cases[i].name, ocpy, H5P_DEFAULT) >= 0;
    H5Fclose(src);
  }
  H5Pclose(ocpy);
  if (cases >= 0) {
    H5Gclose(cases);
  }
  hid_t sg = ok ? H5Gcreate2(f, "summary", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT) : -1;
  ok = ok && sg >= 0 && writeStrings(sg, "case", names, n, STRING_SIZE_NAME) &&
       writeStrings(sg, "status", status, n, STRING_SIZE_STATUS) &&
       writeStrings(sg, "summary", sums, n, CSX_STUDY_SUMMARY_SIZE) &&
       writeDoubles(sg, "wall_time_s", wall, n, 1) &&
       writeDoubles(sg, "p_until_angle_MPa", pu, n, 1) &&
       writeDoubles(sg, "angle_total_deg", ang, n, 1) && writeDoubles(sg, "p_end_MPa", pend, n, 1) &&
       writeDoubles(sg, "t_final_s", tfin, n, 1) && writeDoubles(sg, "rank", rank, n, 1) &&
       writeDoubles(sg, "x_final_mm", xf, n, 3);
  if (sg >= 0) {
    H5Gclose(sg);
  }
  double v[6] = {n, cnt[0], cnt[1], cnt[2], cnt[3], info ? info->ranks : 1};
  double w = info ? info->wall_s : NAN, wsum = 0;
  for (int i = 0; i < n; i++) {
    wsum += isnan(wall[i]) ? 0 : wall[i];
  }
  ok = ok && attrString(f, "format", CSX_STUDY_FORMAT) && attrString(f, "study", s->name) &&
       attrString(f, "study_file", s->path) && attrDoubles(f, "ncase", &v[0], 1) &&
       attrDoubles(f, "ncomplete", &v[1], 1) && attrDoubles(f, "nstopped", &v[2], 1) &&
       attrDoubles(f, "nfailed", &v[3], 1) && attrDoubles(f, "nmissing", &v[4], 1) &&
       attrDoubles(f, "ranks", &v[5], 1) && attrDoubles(f, "wall_time_s", &w, 1) &&
       attrDoubles(f, "case_wall_time_s", &wsum, 1) &&
       attrString(f, "schedule", info && info->schedule ? info->schedule : "sequential") &&
       attrString(f, "version", VERSION);
  free(names);
  free(status);
  free(sums);
  free(col);
  if (H5Fclose(f) < 0 || !ok) {
    return writeFailed(part, "write the study file", err);
  }
  if (rename(part, out) != 0) {
    return cs_errorSet(err, CS_ERR_IO, "%s: cannot rename to %s: %s", part, out,
                       strerror(errno));
  }
  if (counts) {
    memcpy(counts, cnt, sizeof cnt);
  }
  return CS_OK;
}

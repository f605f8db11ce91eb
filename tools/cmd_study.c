/* cmd_study.c: `crawlsim study`: run a design study (a table of cases, study_file.h), one case
 * per MPI rank under mpirun or one after the other without it, resumable, into one HDF5 file.
 *
 *   crawlsim study FILE [--out FILE.h5] [--dir DIR] [--resume] [--retry-failed] [--case NAME]...
 *                  [--schedule dynamic|static] [--list] [--check] [--merge-only]
 *
 * Every rank reads and checks the study file; rank 0 decides which cases are pending (from the
 * case files in DIR, study_case.h) and broadcasts the list; the cases run (study_sched.h); rank
 * 0 merges every finished case file into FILE.h5 and prints the totals. Without --resume a DIR
 * that already holds finished cases of this study is refused (they may be hours of FE work),
 * with --resume they are kept and only the rest runs. Exit status 0 when every selected case
 * has a result (complete, or a run that stopped with its samples written), 1 otherwise. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "core_clock.h"
#include "cs_commands.h"
#include "cs_opts.h"
#include "cs_signal.h"
#include "study_case.h"
#include "study_file.h"
#include "study_sched.h"

/* the options of `crawlsim study`, for parsing and --help (cs_opts.h) */
static const csxOpt kStudyOpts[] = {
    {"--out", "FILE.h5", "the study's name + .h5", "the merged results"},
    {"--dir", "DIR", "the output's stem + _cases", "where each case's files go"},
    {"--resume", NULL, "off", "keep finished cases (a killed study continues)"},
    {"--retry-failed", NULL, "off", "--resume, and rerun failed cases too"},
    {"--case", "NAME", "every case", "run only the named case, repeatable"},
    {"--schedule", "dynamic|static", "dynamic (static without MPI_THREAD_SERIALIZED)",
     "under mpirun: rank 0 hands the cases out (dynamic) or case k runs on rank k mod n "
     "(static)"},
    {"--list", NULL, "off", "print the cases and their state, run nothing"},
    {"--check", NULL, "off", "only check the study file"},
    {"--merge-only", NULL, "off", "merge what is finished (while a long study runs elsewhere)"},
};

static const csxOptTable kStudyTable = {
    "study", "FILE",
    "Run the cases of a study file (docs/reference/study.md): each case is one or more crawlsim "
    "commands (bend, run, calibrate, gait-design) run in this process; under mpirun one case per "
    "rank. One progress line per finished case.",
    kStudyOpts, CSX_NOPT(kStudyOpts), NULL};

enum { MAX_PICK = 256 };

/* progress lines go to the terminal's stderr even while a step's output is captured */
typedef struct {
  FILE* out;
  const csxStudy* s;
} Progress;


static void progressLine(void* user, int done, int total, int index, const csxCaseResult* res) {
  const Progress* p = user;
  fprintf(p->out, "crawlsim study: [%d/%d] %s %s in %.1f s (rank %d): %s\n", done, total,
          p->s->cases[index].name, csx_caseStateName(res->state), res->wall_s, res->rank,
          res->summary[0] ? res->summary : "-");
  fflush(p->out);
}


int csx_cmdStudy(int argc, char** argv) {
  /* SIGINT/SIGTERM end the work after the step in progress (cs_signal.h); this command
   * polls the flag */
  csx_signalInstall();
  const char* file = NULL;
  const char* out = NULL;
  const char* dir = NULL;
  const char* pick[MAX_PICK];
  int npick = 0, resume = 0, retry = 0, list = 0, check = 0, merge_only = 0;
  csxSchedule kind = CSX_SCHEDULE_DYNAMIC;
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kStudyTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kStudyTable, k, &it);
    if (end >= 0) {
      return end;
    }
    if (k == CSX_OPT_OPERAND) {
      if (file) {
        fprintf(stderr, "crawlsim study: unexpected argument '%s'\n", it.value);
        return 1;
      }
      file = it.value;
      continue;
    }
    const char* a = it.opt->name;
    const char* v = it.value;
    if (!strcmp(a, "--resume")) {
      resume = 1;
    } else if (!strcmp(a, "--retry-failed")) {
      retry = resume = 1;
    } else if (!strcmp(a, "--list")) {
      list = 1;
    } else if (!strcmp(a, "--check")) {
      check = 1;
    } else if (!strcmp(a, "--merge-only")) {
      merge_only = 1;
    } else if (!strcmp(a, "--out")) {
      out = v;
    } else if (!strcmp(a, "--dir")) {
      dir = v;
    } else if (!strcmp(a, "--case")) {
      if (npick == MAX_PICK) {
        fprintf(stderr, "crawlsim study: more than %d --case options\n", MAX_PICK);
        return 1;
      }
      pick[npick++] = v;
    } else if (!strcmp(a, "--schedule")) {
      if (!strcmp(v, "dynamic") || !strcmp(v, "static")) {
        kind = v[0] == 'd' ? CSX_SCHEDULE_DYNAMIC : CSX_SCHEDULE_STATIC;
      } else {
        fprintf(stderr, "crawlsim study: unknown schedule '%s' (expected dynamic or static)\n",
                v);
        return 1;
      }
    }
  }
  if (!file) {
    fprintf(stderr, "crawlsim study: missing the study FILE (see crawlsim study --help)\n");
    return 1;
  }

  csError err;
  cs_errorClear(&err);
  csxStudyMpi mpi;
  if (csx_studyMpiInit(&argc, &argv, &mpi, &err) != CS_OK) {
    fprintf(stderr, "crawlsim study: %s\n", err.msg);
    return 1;
  }
  const int root = mpi.rank == 0;
  const double t0 = csu_wallSeconds();
  int rc = 1;
  int* pending = NULL;
  csxStudy* s = csx_studyRead(file, &err);
  if (!s) {
    if (root) {
      fprintf(stderr, "crawlsim study: %s\n", err.msg);
    }
    goto done;
  }
  for (int k = 0; k < npick; k++) {
    if (csx_studyFindCase(s, pick[k]) < 0) {
      if (root) {
        fprintf(stderr, "crawlsim study: --case '%s': no such case in %s\n", pick[k], file);
      }
      goto done;
    }
  }
  /* outputs: FILE.h5 (default NAME.h5) and DIR (default FILE.h5's stem + _cases) */
  char outbuf[CSX_STUDY_PATH_SIZE], dirbuf[CSX_STUDY_PATH_SIZE];
  if (!out) {
    snprintf(outbuf, sizeof outbuf, "%s.h5", s->name);
    out = outbuf;
  }
  if (!dir) {
    size_t n = strlen(out);
    int cut = n > 3 && !strcmp(out + n - 3, ".h5") ? (int)n - 3 : (int)n;
    snprintf(dirbuf, sizeof dirbuf, "%.*s_cases", cut, out);
    dir = dirbuf;
  }
  if (check) {
    int nstep = 0;
    for (int i = 0; i < s->ncase; i++) {
      nstep += s->cases[i].nstep;
    }
    if (root) {
      printf("crawlsim study: %s: study %s, %d cases, %d steps: ok\n", file, s->name, s->ncase,
             nstep);
    }
    rc = 0;
    goto done;
  }

  /* rank 0: the state of every case and what runs now; broadcast as [go, n, indices...] */
  pending = malloc(((size_t)s->ncase + 2) * sizeof(int));
  if (!pending) {
    if (root) {
      fprintf(stderr, "crawlsim study: out of memory\n");
    }
    goto done;
  }
  int head[3] = {0, 0, 1}; /* go (1) or stop (0), pending count, exit status when stopping */
  if (root) {
    int nfinished = 0, nstale = 0, nfailed = 0, first_done = -1;
    int ok = csx_studyMakeDir(dir, &err) == CS_OK;
    for (int i = 0; ok && i < s->ncase; i++) {
      int chosen = npick == 0;
      for (int k = 0; k < npick; k++) {
        chosen |= !strcmp(pick[k], s->cases[i].name);
      }
      csxCaseResult res;
      csxCaseState st = csx_studyCaseState(s, i, dir, &res);
      if (list) {
        printf("%-24s %-9s %s%s%s\n", s->cases[i].name, csx_caseStateName(st),
               s->cases[i].signature, res.summary[0] ? "\n    -> " : "", res.summary);
        continue;
      }
      if (!chosen) {
        continue;
      }
      int finished = st == CSX_CASE_COMPLETE || st == CSX_CASE_STOPPED ||
                     (st == CSX_CASE_FAILED && !retry);
      nstale += st == CSX_CASE_STALE;
      nfailed += st == CSX_CASE_FAILED;
      if (finished) {
        nfinished++;
        first_done = first_done < 0 ? i : first_done;
      } else {
        pending[2 + head[1]++] = i;
      }
    }
    if (!ok) {
      fprintf(stderr, "crawlsim study: %s\n", err.msg);
    } else if (list) {
      head[2] = 0;
    } else if (merge_only) {
      head[1] = 0;
      head[0] = 1;
    } else if (nfinished > 0 && !resume) {
      fprintf(stderr, "crawlsim study: %s: %d case%s finished by an earlier run (%s%s): continue "
              "with --resume, or remove the directory\n", dir, nfinished,
              nfinished > 1 ? "s are" : " is", s->cases[first_done].name,
              nfinished > 1 ? ", ..." : "");
    } else {
      head[0] = 1;
      printf("crawlsim study: %s: %d case%s, %d to run (%d finished%s%s), %d rank%s (%s), "
             "case files in %s\n", s->name, npick ? npick : s->ncase,
             (npick ? npick : s->ncase) == 1 ? "" : "s", head[1], nfinished,
             nstale ? ", stale ones rerun" : "",
             retry && nfailed ? ", failed ones rerun" : "", mpi.size, mpi.size == 1 ? "" : "s",
             mpi.size == 1 ? "sequential"
             : kind == CSX_SCHEDULE_STATIC || !mpi.threads_ok ? "static" : "dynamic",
             dir);
      fflush(stdout);
    }
  }
  csx_studyMpiBcastInts(&mpi, head, 3);
  if (!head[0]) {
    rc = head[2];
    goto done;
  }
  csx_studyMpiBcastInts(&mpi, pending + 2, head[1]);
  /* the dynamic schedule needs a second thread on rank 0 */
  if (kind == CSX_SCHEDULE_DYNAMIC && mpi.size > 1 && !mpi.threads_ok) {
    kind = CSX_SCHEDULE_STATIC;
  }
  /* the progress lines go to stderr; the steps write only to their logs (csxStepFn) */
  Progress prog = {stderr, s};
  int nfailed = 0;
  csStatus st = csx_studyRunPending(s, pending + 2, head[1], dir, &(csxStudyCommands){{
      csx_stepBend, csx_stepRun, csx_stepCalibrate, csx_stepGaitDesign}, csx_signalFlag()}, kind,
      &mpi, progressLine, &prog, &nfailed, &err);
  if (st != CS_OK) {
    fprintf(stderr, "crawlsim study: rank %d: %s\n", mpi.rank, err.msg);
  }
  if (root) {
    csxStudyRunInfo info = {mpi.size,
                            mpi.size == 1 ? "sequential"
                            : kind == CSX_SCHEDULE_STATIC ? "static" : "dynamic",
                            csu_wallSeconds() - t0};
    int counts[4];
    /* with --case only the chosen cases count for the exit status; the merge has all */
    if (csx_studyMerge(s, dir, out, &info, counts, &err) != CS_OK) {
      fprintf(stderr, "crawlsim study: %s\n", err.msg);
      goto done;
    }
    int bad = 0;
    for (int i = 0; i < s->ncase; i++) {
      int chosen = npick == 0;
      for (int k = 0; k < npick; k++) {
        chosen |= !strcmp(pick[k], s->cases[i].name);
      }
      csxCaseState cs = csx_studyCaseState(s, i, dir, NULL);
      bad += chosen && !(cs == CSX_CASE_COMPLETE || cs == CSX_CASE_STOPPED);
    }
    printf("crawlsim study: %s: %d complete, %d stopped, %d failed, %d missing; %.1f s; wrote "
           "%s\n", s->name, counts[0], counts[1], counts[2], counts[3], info.wall_s, out);
    if (bad) {
      fprintf(stderr, "crawlsim study: %d selected case%s without a result (failed or missing): "
              "see crawlsim study %s --list\n", bad, bad > 1 ? "s" : "", file);
    }
    rc = bad || st != CS_OK ? 1 : 0;
    if (csx_signalExitCode()) {
      rc = csx_signalExitCode(); /* interrupted: 128 + the signal */
    }
  } else {
    rc = st != CS_OK ? 1 : 0;
  }

done:
  free(pending);
  csx_studyDestroy(s);
  csx_studyMpiFinalize(&mpi);
  return rc;
}

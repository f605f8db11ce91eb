/* study_case.h: running one case of a study in this process, its result file, and the merge of
 * all case files into the study's one HDF5 file.
 *
 * Owns: the case directory layout, the step runner (a crawlsim command's step function called
 * in-process: it writes its lines to the case's log stream and returns a result struct), the
 * case file (written as
 * NAME.h5.part and renamed when complete, so a killed process never leaves a file that looks
 * finished), the finished-case test of a resumed study, and the merge. Library part of the
 * study layer (cs_study); the commands themselves are injected (csxStudyCommands), so the
 * library does not depend on the executable's cmd_*.c files.
 *
 * Layout under the case directory DIR:
 *   DIR/NAME.h5     the case file (below), present only once the case has finished
 *   DIR/NAME/       the case's work directory (@case/): the steps' outputs bend.h5, run.h5 and
 *                   run.xdmf, calibration.h5 and calibration/, gait.csv, and <command>.log with
 *                   every line the step wrote to its log stream
 * Case file (HDF5), root attributes: format "crawlsim-study-case 1", study, case, signature
 * (the steps as written, study_file.h), status ("complete": every step exited 0; "stopped":
 * the last step was a run that ended early with its output written, e.g. the robot fell: a
 * result, not an error; "failed": a step failed, its message says why), message (the failing
 * step's one-line message), summary (one line of key results), wall_time_s, rank, host,
 * finished (UTC), version; key results where the steps give them: p_until_angle_MPa,
 * angle_total_deg and p_end_MPa (the bend's last row), x_final_mm [3] and t_final_s (where the
 * run ended), verdict (the run's verdict line); all from the steps' result structs
 * (csxStepResult). Groups: /<command> (bend, run, calibrate) a copy of that step's whole output
 * file; /log/<command> the step's log text; /gait_design/csv the table.
 * Study file (the merge, HDF5): root attributes format "crawlsim-study 1", study, study_file,
 * ncase, ncomplete, nstopped, nfailed, nmissing, case_wall_time_s (the cases' wall times summed),
 * ranks, schedule, wall_time_s (of the invocation that merged: csxStudyRunInfo); /cases/NAME a
 * copy of each finished case file; /summary/{case, status, summary} strings [ncase],
 * /summary/{wall_time_s, p_until_angle_MPa, angle_total_deg, p_end_MPa, t_final_s, rank}
 * [ncase] and /summary/x_final_mm [ncase,3], NaN where a case has no such result. */
#ifndef CS_TOOLS_STUDY_CASE_H
#define CS_TOOLS_STUDY_CASE_H

#include <signal.h>
#include <stdio.h>
#include "core_status.h"
#include "study_file.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSX_STUDY_CASE_FORMAT "crawlsim-study-case 1"
#define CSX_STUDY_FORMAT "crawlsim-study 1"
#define CSX_STUDY_SUMMARY_SIZE 256

/* What a step reports to the runner: the command's result struct, read instead of its log.
 * The runner fills it with NaN and "" before the step; a step fills what it has. */
typedef struct csxStepResult_ {
  double p_until;        /* bend: pressure at --until-angle (MPa; NaN: not asked or not reached) */
  double angle_total;    /* bend: the last row's total angle (deg) */
  double p_end;          /* bend: the last row's pressure (MPa) */
  double t_final;        /* run: the time the run reached (s) */
  double x_final[3];     /* run: the support's displacement from t = 0 then (mm, world) */
  int wrote_samples;     /* run: its file holds samples (a run that ended early is a result) */
  char verdict[CSX_STUDY_SUMMARY_SIZE]; /* run: its verdict line, as `crawlsim run` prints it */
  char summary[CSX_STUDY_SUMMARY_SIZE]; /* the step's piece of the case summary ("": none) */
  char message[CS_ERROR_MSG_SIZE];      /* a failed step: its one line ("crawlsim bend: ...") */
} csxStepResult;

/* A step: the command's own parser over argv (argv[0] is its name; the same parser as on the
 * command line builds the command's definition), then the command with every line it has to
 * say written to `log` (a stream the runner owns: nothing goes to stdout or stderr) and its
 * results in *res. Returns the command's exit status (0, 1, or 128 + a signal). */
typedef int (*csxStepFn)(int argc, char** argv, FILE* log, csxStepResult* res);

/* A failed command's end: "crawlsim <cmd>: <msg>" (control characters shown as '?') as a line
 * of `log` (NULL: none) and as res->message (res NULL: the command line, the line alone). */
void csx_stepFailed(csxStepResult* res, FILE* log, const char* cmd, const char* msg);

/* The commands a step can run, indexed by csxStudyCmd (NULL: not available in this build). */
typedef struct csxStudyCommands_ {
  csxStepFn fn[CSX_STUDY_NCMD];
  const volatile sig_atomic_t* cancel; /* NULL, or the application's signal flag: once set, a
                                          case whose command was interrupted writes no case file
                                          (it stays pending, so --resume runs it again) and no
                                          further case starts (CS_ERR_INTERRUPTED) */
} csxStudyCommands;

/* What a case file says about a case. */
typedef enum csxCaseState_ {
  CSX_CASE_PENDING = 0,  /* no case file: not run yet, or killed while it ran */
  CSX_CASE_COMPLETE = 1,
  CSX_CASE_STOPPED = 2,
  CSX_CASE_FAILED = 3,
  CSX_CASE_STALE = 4     /* a case file for another signature (the case was edited) */
} csxCaseState;

const char* csx_caseStateName(csxCaseState s);

/* The outcome of a case, as a progress line needs it. */
typedef struct csxCaseResult_ {
  csxCaseState state;
  double wall_s;
  int rank;
  char summary[CSX_STUDY_SUMMARY_SIZE];
} csxCaseResult;

/* The state of case i from its case file in dir; *res (may be NULL) gets its recorded result. */
csxCaseState csx_studyCaseState(const csxStudy* s, int i, const char* dir, csxCaseResult* res);

/* Run case i: every step in order in this process, outputs in dir/NAME/, then its case file.
 * A step that fails ends the case (state FAILED in *res, the step's message in the summary);
 * that is a result of the case, not an error of this call, which returns CS_OK. Errors (the
 * work directory or case file cannot be written) return a status with err filled. `rank` is
 * recorded. Writes nothing to stdout or stderr: the steps write to their logs. */
csStatus csx_studyRunCase(const csxStudy* s, int i, const char* dir, const csxStudyCommands* cmd,
                          int rank, csxCaseResult* res, csError* err);

/* What the merged file records about the run of the study. */
typedef struct csxStudyRunInfo_ {
  int ranks;            /* processes that ran cases */
  const char* schedule; /* "sequential", "dynamic" or "static" */
  double wall_s;        /* wall time of this invocation (s) */
} csxStudyRunInfo;

/* Merge the finished case files of s in dir into `out` (written as out.part, renamed): cases
 * without a finished case file are listed as "missing" in /summary. *counts (may be NULL) gets
 * ncomplete, nstopped, nfailed, nmissing. */
csStatus csx_studyMerge(const csxStudy* s, const char* dir, const char* out,
                        const csxStudyRunInfo* info, int counts[4], csError* err);

/* Create a directory if it does not exist (one level). */
csStatus csx_studyMakeDir(const char* path, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_TOOLS_STUDY_CASE_H */

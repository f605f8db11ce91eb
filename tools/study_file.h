/* study_file.h: design-study descriptions for `crawlsim study`: a table of cases, each one or
 * more crawlsim commands (FE bends, calibrations, gait designs, crawl runs) with their options.
 *
 * Owns: csxStudy (the cases of a study file, read once, constant afterwards), its reader with
 * "<file>:<line>: <cause>" errors, and the path rules of the words in a case. Library part of
 * the study layer (target cs_study in tools/): it sits on top of every module because a case may
 * drive any of them; it never prints and never exits. Running the cases is study_case.h's.
 *
 * Format (one statement per line; '#' starts a comment, also after a statement; words are
 * separated by whitespace; lines of at most 4096 bytes; LF or CRLF):
 *   study NAME                  the study's name (letters, digits, _ . -; default: the file's
 *                               stem); at most once, before the first case
 *   defaults COMMAND WORDS...   WORDS go before the own words of every step of COMMAND in the
 *                               cases that follow (a later `defaults COMMAND` replaces it;
 *                               `defaults COMMAND` alone clears it)
 *   case NAME COMMAND WORDS...  a case (NAME as for `study`, unique) and its first step
 *   then COMMAND WORDS...       a further step of the case above: the steps of a case run in
 *                               order in one process; a step runs only if the one before it
 *                               succeeded; one step per COMMAND in a case
 * COMMAND is one of
 *   bend         crawlsim bend ...         (its output: @case/bend.h5)
 *   run          crawlsim run ...          (@case/run.h5 and run.xdmf)
 *   calibrate    crawlsim calibrate ...    (@case/calibration.h5, cases in @case/calibration/)
 *   gait-design  crawlsim gait design FILE.gait ...   (@case/gait.csv)
 * and WORDS are that command's options as on the command line, `--name value` (not
 * `--name=value`), except the ones the study runner gives: --out and --dir (where the outputs
 * go), --help, --list and --merge-only. Options are checked when the file is read: unknown
 * options, missing values, numbers that are not finite, `--set NAME=VALUE` with an unknown NAME
 * or a parameter set that is not a valid actuator (csr_actuatorValidate, on the --actuator
 * preset or the command's default), files that do not exist. Ranges are the command's own: a
 * case the command refuses fails when it runs, with the command's one-line message.
 * Paths (options that take a file, and gait-design's FILE.gait):
 *   @data/REL   the shipped data (gaits/, terrains/, robot/: $CRAWLSIM_DATA_DIR or the source
 *               tree, tools/cs_paths.h)
 *   @case/REL   the case's own work directory (an earlier step's output, e.g. @case/gait.csv)
 *   /ABS        as written
 *   REL         relative to the study file's directory
 * A case's signature is its steps' words as written, defaults included, one step per line: a
 * finished case is recognised by it (study_case.h), so editing a case re-runs it. */
#ifndef CS_TOOLS_STUDY_FILE_H
#define CS_TOOLS_STUDY_FILE_H

#include <stddef.h>

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSX_STUDY_MAX_LINE 4096  /* bytes per line, ending excluded */
#define CSX_STUDY_MAX_WORDS 256  /* words per step, defaults included */
#define CSX_STUDY_MAX_CASES 4096 /* cases per study */
#define CSX_STUDY_NAME_SIZE 64   /* study and case names: at most 63 characters */
#define CSX_STUDY_PATH_SIZE 1024 /* resolved paths */

/* The commands a step can run (the order of csxStudyCommandTable). */
typedef enum csxStudyCmd_ {
  CSX_STUDY_BEND = 0,
  CSX_STUDY_RUN = 1,
  CSX_STUDY_CALIBRATE = 2,
  CSX_STUDY_GAIT_DESIGN = 3,
  CSX_STUDY_NCMD = 4
} csxStudyCmd;

/* One step of a case: a command and its words (defaults first, then the step's own). */
typedef struct csxStudyStep_ {
  csxStudyCmd cmd;
  int nword;
  char** word; /* (nword) NUL-terminated, owned by the study */
  long line;   /* line of the step in the study file */
} csxStudyStep;

/* One case: a name and one step per command at most, in running order. */
typedef struct csxStudyCase_ {
  char name[CSX_STUDY_NAME_SIZE];
  long line; /* line of its `case` statement */
  int nstep;
  csxStudyStep step[CSX_STUDY_NCMD];
  char* signature; /* the steps as written, one line each ("bend --model fe ..."), owned */
} csxStudyCase;

/* A study: constant once read. */
typedef struct csxStudy_ {
  char name[CSX_STUDY_NAME_SIZE];
  char path[CSX_STUDY_PATH_SIZE]; /* the study file as given */
  char dir[CSX_STUDY_PATH_SIZE];  /* its directory ("." for a bare name) */
  int ncase;
  csxStudyCase* cases; /* (ncase) in file order */
} csxStudy;

/* The command's name in study files ("bend", "run", "calibrate", "gait-design"). */
const char* csx_studyCmdName(csxStudyCmd c);

/* Read and check a study file. Returns NULL and fills err ("<file>:<line>: <cause>") on any
 * error; the caller destroys the study. */
csxStudy* csx_studyRead(const char* path, csError* err);

/* Free a study; NULL-safe. */
void csx_studyDestroy(csxStudy* s);

/* Index of the case called `name`, or -1. */
int csx_studyFindCase(const csxStudy* s, const char* name);

/* Resolve a path word of a step (rules above) into out[size]; case_dir is the case's work
 * directory. Returns 0, or -1 when the result does not fit. */
int csx_studyResolvePath(const csxStudy* s, const char* case_dir, const char* word, char* out,
                         size_t size);

/* 1 if `word` at position i of step `st` is a path (an option's file value or gait-design's
 * FILE.gait), so the runner resolves it; 0 otherwise. */
int csx_studyWordIsPath(const csxStudyStep* st, int i);

#ifdef __cplusplus
}
#endif
#endif /* CS_TOOLS_STUDY_FILE_H */

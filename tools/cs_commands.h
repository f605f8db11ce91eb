/* cs_commands.h: the subcommands of the `crawlsim` executable (one file each, cmd_<name>.c).
 * Each takes the arguments after its name (argv[0] is the subcommand) and returns the process
 * exit status: 0 on success, 1 on bad input or failure, after printing one line
 * "crawlsim <cmd>: <file:line:> cause" to stderr. None of them calls exit(). */
#ifndef CS_TOOLS_COMMANDS_H
#define CS_TOOLS_COMMANDS_H

#include <stdio.h>

#include "cs_opts.h"
#include "study_case.h" /* csxStepResult */

int csx_cmdRun(int argc, char** argv);       /* cmd_run.c: crawlsim run ... */
int csx_cmdBend(int argc, char** argv);      /* cmd_bend.c: crawlsim bend ... */
int csx_cmdGait(int argc, char** argv);      /* cmd_gait.c: crawlsim gait check|... */
int csx_cmdCalibrate(int argc, char** argv); /* cmd_calibrate.c: crawlsim calibrate ... */
int csx_cmdGaitFlatRoad(int argc, char** argv); /* cmd_gaitdesign.c: crawlsim gait flat-road */
int csx_cmdGaitDesign(int argc, char** argv);   /* cmd_gaitdesign.c: crawlsim gait design */
int csx_cmdStudy(int argc, char** argv);        /* cmd_study.c: crawlsim study FILE ... */
int csx_cmdExport(int argc, char** argv);       /* cmd_export.c: crawlsim export FILE.h5 */
int csx_cmdRom(int argc, char** argv);          /* cmd_rom.c: crawlsim rom snapshots ... */

/* The steps of a study (study_case.h csxStepFn): the command's parser over argv, then the
 * command with its lines written to `log` (never to stdout or stderr) and its results in *res;
 * returns the exit status the command would. */
int csx_stepRun(int argc, char** argv, FILE* log, csxStepResult* res);       /* cmd_run.c */
int csx_stepBend(int argc, char** argv, FILE* log, csxStepResult* res);      /* cmd_bend.c */
int csx_stepCalibrate(int argc, char** argv, FILE* log, csxStepResult* res); /* cmd_calibrate.c */
int csx_stepGaitDesign(int argc, char** argv, FILE* log, csxStepResult* res);
/* cmd_gaitdesign.c */

/* The end of a command's parse (cmd_step.c): its parser returned p (0 parsed; 1 err filled; 2
 * `it` holds --help or an option error of table t, `kind`). Returns -1 to go on, else the exit
 * status after the help on stdout (the command line, res NULL) or after one line "crawlsim
 * <cmd>: <cause>" on `notes` (stderr, or a step's log with res->message filled). */
int csx_parseEnd(const csxOptTable* t, int p, csxOptKind kind, const csxOptIter* it,
                 const csError* err, FILE* notes, csxStepResult* res);

#endif

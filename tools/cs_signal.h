/* cs_signal.h: the `crawlsim` process's SIGINT/SIGTERM handling (the application's, not the
 * library's: the library only reads a cancel flag it is handed through its options).
 *
 * Owns: the one process-wide flag the handler sets. The first SIGINT or SIGTERM sets it (the
 * step in progress finishes, the output is closed with its status saying "interrupted at ...",
 * and the command exits 128 + signal number); a second one of either ends the process at once
 * with the default action (the output file on disk is then complete as of its last flush). A
 * signal the parent set to be ignored (a shell's background job ignores SIGINT) stays ignored.
 * A signal that comes after the last step lets the command finish normally (exit 0, status
 * "ok"): the work it would have cut short is done. */
#ifndef CS_TOOLS_SIGNAL_H
#define CS_TOOLS_SIGNAL_H

#include <signal.h>

/* Install the handlers: only commands whose work loops poll the flag call it (run, bend,
 * calibrate, study); the others keep the default actions, so Ctrl-C still ends them at once.
 * Calling it again changes nothing. */
void csx_signalInstall(void);

/* The flag to hand to the library (csOptions.cancel, csfBendOptions.cancel): nonzero once a
 * signal came. */
const volatile sig_atomic_t* csx_signalFlag(void);

/* 128 + the signal's number once one came (130 SIGINT, 143 SIGTERM); 0 before. */
int csx_signalExitCode(void);

#endif

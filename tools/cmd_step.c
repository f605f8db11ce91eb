/* cmd_step.c: the end of a command's option parsing, shared by the commands that a study runs
 * as steps (cs_commands.h: csx_parseEnd). */
#include <stdio.h>

#include "cs_commands.h"


int csx_parseEnd(const csxOptTable* t, int p, csxOptKind kind, const csxOptIter* it,
                 const csError* err, FILE* notes, csxStepResult* res) {
  if (p == 0) {
    return -1;
  }
  if (p == 2 && kind == CSX_OPT_HELP && !res) {
    return csx_optReport(t, kind, it); /* the help on stdout, exit 0 */
  }
  csx_stepFailed(res, notes, t->cmd,
                 p == 1 ? err->msg : kind == CSX_OPT_HELP ? "--help is not a step" : it->error);
  return 1;
}

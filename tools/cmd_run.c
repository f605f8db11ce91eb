/* cmd_run.c: `crawlsim run` (placeholder until its issue lands). */
#include <stdio.h>

#include "cs_commands.h"

int csx_cmdRun(int argc, char** argv) {
  (void)argc;
  (void)argv;
  fprintf(stderr, "crawlsim run: not implemented yet\n");
  return 1;
}

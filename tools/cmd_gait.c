/* cmd_gait.c: `crawlsim gait` (placeholder until its issue lands). */
#include <stdio.h>

#include "cs_commands.h"

int csx_cmdGait(int argc, char** argv) {
  (void)argc;
  (void)argv;
  fprintf(stderr, "crawlsim gait: not implemented yet\n");
  return 1;
}

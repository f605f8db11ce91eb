/* cmd_bend.c: `crawlsim bend` (placeholder until its issue lands). */
#include <stdio.h>

#include "cs_commands.h"

int csx_cmdBend(int argc, char** argv) {
  (void)argc;
  (void)argv;
  fprintf(stderr, "crawlsim bend: not implemented yet\n");
  return 1;
}

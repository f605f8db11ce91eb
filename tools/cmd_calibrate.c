/* cmd_calibrate.c: `crawlsim calibrate` (placeholder until its issue lands). */
#include <stdio.h>

#include "cs_commands.h"

int csx_cmdCalibrate(int argc, char** argv) {
  (void)argc;
  (void)argv;
  fprintf(stderr, "crawlsim calibrate: not implemented yet\n");
  return 1;
}

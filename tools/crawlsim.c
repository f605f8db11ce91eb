/* crawlsim.c: entry point of the `crawlsim` command; dispatches to the subcommands
 * (cs_commands.h). The command-line contract is DESIGN.md's. */
#include <stdio.h>
#include <string.h>

#include "cs_commands.h"

static const char kUsage[] =
    "usage: crawlsim <command> [options]\n"
    "  run       [--scene flat-road|obstacle] [--gait FILE.csv] [--legs auto|prb|rod|rom]\n"
    "            [--friction MU] [--pressure-scale K] [--t-end S] [--out FILE.h5] ...\n"
    "  bend      [--model analytic|fe|rod|prb|rom] [--actuator fig1|baseline|leg]\n"
    "            [--set NAME=VALUE]... [--chambers 1,2] [--p-max MPA] [--p-step MPA]\n"
    "            [--until-angle DEG] [--mesh-size MM] [--out FILE.h5]\n"
    "  gait      check FILE.csv | write-flat-road FILE.csv [...]\n"
    "  calibrate [--out FILE.h5]\n"
    "Run 'crawlsim <command> --help' for the options of one command.\n";


int main(int argc, char** argv) {
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 1 : 0;
  }
  const char* cmd = argv[1];
  if (!strcmp(cmd, "run")) {
    return csx_cmdRun(argc - 1, argv + 1);
  }
  if (!strcmp(cmd, "bend")) {
    return csx_cmdBend(argc - 1, argv + 1);
  }
  if (!strcmp(cmd, "gait")) {
    return csx_cmdGait(argc - 1, argv + 1);
  }
  if (!strcmp(cmd, "calibrate")) {
    return csx_cmdCalibrate(argc - 1, argv + 1);
  }
  fprintf(stderr, "crawlsim: unknown command '%s' (expected run, bend, gait or calibrate)\n", cmd);
  return 1;
}

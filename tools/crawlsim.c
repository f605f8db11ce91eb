/* crawlsim.c: entry point of the `crawlsim` command; dispatches to the subcommands
 * (cs_commands.h). The command-line contract is DESIGN.md's. */
#define _POSIX_C_SOURCE 200809L /* setenv, unsetenv, execv */
#include <ode/ode.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "cs_commands.h"

static const char kUsage[] =
    "usage: crawlsim <command> [options]\n"
    "  run       [--scene flat-road|obstacle] [--gait FILE.csv] [--legs auto|prb|rod|rom]\n"
    "            [--friction MU] [--pressure-scale K] [--t-end S] [--out FILE.h5] ...\n"
    "  bend      [--model analytic|fe|rod|prb|rom] [--actuator fig1|baseline|leg]\n"
    "            [--set NAME=VALUE]... [--chambers 1,2] [--p-max MPA] [--p-step MPA]\n"
    "            [--until-angle DEG] [--mesh-size MM] [--out FILE.h5]\n"
    "  gait      check FILE.csv | design FILE.gait [--out FILE.csv] [--check] ...\n"
    "            | flat-road FILE.csv [--stroke MM] [--crouch] ...\n"
    "  calibrate [--out FILE.h5]\n"
    "  study     FILE [--out FILE.h5] [--resume] ...  (under mpirun: one case per rank)\n"
    "Run 'crawlsim <command> --help' for the options of one command.\n";


/* ODE's informational messages: not errors of ours; CRAWLSIM_ODE_MESSAGES=1 shows them */
static void odeMessage(int num, const char* msg, va_list ap) {
  /* ODE warns "zero length vector in dRFrom2Axes" when a universal joint is attached before its
   * axes are set, which ODE's own API order requires; shown only on request */
  if (!getenv("CRAWLSIM_ODE_MESSAGES")) {
    return;
  }
  fprintf(stderr, "crawlsim: ODE message %d: ", num);
  vfprintf(stderr, msg, ap);
  fputc('\n', stderr);
}


static int dispatch(int argc, char** argv);


/* OpenMP threads that sleep when they wait (issue 38). libgomp reads OMP_WAIT_POLICY once, when
 * it is loaded, before main(); its default spins up to 300 000 rounds at every barrier of
 * MUMPS's and OpenBLAS's small parallel regions, taking cores that other processes hold
 * (measured 3.3x slower with one other busy process, fem/README.md). So, unless the user chose a
 * policy, set PASSIVE and start this program again, which libgomp then reads. OpenMPI's idle
 * waits yield too (read at MPI_Init). If the restart fails the policy is unset again, so that
 * what the output records (fe_omp_wait_policy) is what ran. */
static void passiveWaits(char** argv) {
  if (!getenv("OMPI_MCA_mpi_yield_when_idle")) {
    setenv("OMPI_MCA_mpi_yield_when_idle", "1", 1);
  }
  if (getenv("OMP_WAIT_POLICY") || getenv("GOMP_SPINCOUNT")) {
    return;
  }
  setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
  execv("/proc/self/exe", argv);
  unsetenv("OMP_WAIT_POLICY");
}


int main(int argc, char** argv) {
  passiveWaits(argv);
  /* the one process-wide ODE initialisation site (debian-deps.md P1) */
  dInitODE2(0);
  dSetMessageHandler(odeMessage);
  int rc = dispatch(argc, argv);
  dCloseODE();
  return rc;
}


static int dispatch(int argc, char** argv) {
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
  if (!strcmp(cmd, "gait") && argc > 2 && !strcmp(argv[2], "flat-road")) {
    return csx_cmdGaitFlatRoad(argc - 2, argv + 2);
  }
  if (!strcmp(cmd, "gait") && argc > 2 && !strcmp(argv[2], "design")) {
    return csx_cmdGaitDesign(argc - 2, argv + 2);
  }
  if (!strcmp(cmd, "gait")) {
    return csx_cmdGait(argc - 1, argv + 1);
  }
  if (!strcmp(cmd, "calibrate")) {
    return csx_cmdCalibrate(argc - 1, argv + 1);
  }
  if (!strcmp(cmd, "study")) {
    return csx_cmdStudy(argc - 1, argv + 1);
  }
  fprintf(stderr,
          "crawlsim: unknown command '%s' (expected run, bend, gait, calibrate or study)\n", cmd);
  return 1;
}

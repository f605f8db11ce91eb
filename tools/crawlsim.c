/* crawlsim.c: entry point of the `crawlsim` command; dispatches to the subcommands
 * (cs_commands.h). The command-line contract is docs/design.md's. */
#define _POSIX_C_SOURCE 200809L /* setenv, unsetenv, execv */
#include <hdf5.h>
#include <ode/ode.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sundials/sundials_version.h>
#include <unistd.h>

#include "cmd_fe_threads.h"
#include "cs_commands.h"
#ifdef CS_FEM_MPI
#include <mpi.h>

#include "fem_linsolve.h"
#endif

#ifndef CS_VERSION_STRING
#define CS_VERSION_STRING "unknown"
#endif
#ifndef CS_ODE_VERSION
#define CS_ODE_VERSION "unknown"
#endif
#ifndef CS_MUMPS_VERSION
#define CS_MUMPS_VERSION "none"
#endif

static const char kUsage[] =
    "usage: crawlsim <command> [options]\n"
    "       crawlsim --version | --help\n"
    "  run       [--scene flat-road|obstacle] [--gait FILE.csv] [--legs auto|rod|strain]\n"
    "            [--friction MU] [--pressure-scale K] [--t-end S] [--out FILE.h5] ...\n"
    "  bend      [--model analytic|fe|rod|rom] [--actuator fig1|baseline|leg]\n"
    "            [--set NAME=VALUE]... [--chambers 1,2] [--p-max MPA] [--p-step MPA]\n"
    "            [--until-angle DEG] [--mesh-size MM] [--out FILE.h5]\n"
    "  gait      check FILE.csv | design FILE.gait [--out FILE.csv] [--check] ...\n"
    "            | flat-road FILE.csv [--stroke MM] [--crouch] ...\n"
    "  calibrate [--out FILE.h5] ...\n"
    "  study     FILE [--out FILE.h5] [--resume] ...  (under mpirun: one case per rank)\n"
    "  export    FILE.h5 --csv [--out DIR]  (a run's tracks as CSV)\n"
    "  rom       snapshots [--out DIR] [--ray NAME]... [--list] [--mesh-size MM] ...\n"
    "            | check --snapshots DIR --basis B.h5 [--weights W.h5] [--all] ...\n"
    "            | ecsw-matrix --basis B.h5 --out A.h5 ...  (the reduced FE leg)\n"
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


/* `crawlsim --version`: this build and the libraries it runs on (SUNDIALS and HDF5 asked at
 * run time, ODE and MUMPS as configured: neither has a run-time query) */
static void printVersion(void) {
  char sun[64] = "unknown";
  SUNDIALSGetVersion(sun, (int)sizeof sun);
  unsigned maj = 0, min = 0, rel = 0;
  H5get_libversion(&maj, &min, &rel);
  printf("crawlsim %s\n", CS_VERSION_STRING);
  printf("  ODE %s, SUNDIALS %s, HDF5 %u.%u.%u, MUMPS %s%s\n", CS_ODE_VERSION, sun, maj, min, rel,
         CS_MUMPS_VERSION,
#ifdef CS_FEM_MPI
         " (MPI)"
#else
         ""
#endif
  );
}


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


#ifdef CS_FEM_MPI
/* crawlsim-mpi: MPI for every command (the MPI build's MUMPS needs it even on one rank). An FE
 * command under mpirun runs on rank 0, and the other ranks serve its factorisations
 * (csf_linSolverServe) until it ends; every other command runs as in crawlsim (a study hands
 * out its cases over the ranks and each FE case stays on its rank). */
static int mpiMain(int argc, char** argv) {
  unsetenv(CSX_FE_RANKS_ENV); /* set below for rank 0's FE command only */
  int provided = 0, rank = 0, size = 1;
  if (MPI_Init_thread(&argc, &argv, MPI_THREAD_SERIALIZED, &provided) != MPI_SUCCESS) {
    fprintf(stderr, "crawlsim-mpi: MPI_Init_thread failed\n");
    return 1;
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  int rc = 0;
  if (size > 1 && csx_feCommand(argc, argv)) {
    if (rank == 0) {
      char v[16];
      snprintf(v, sizeof v, "%d", size);
      setenv(CSX_FE_RANKS_ENV, v, 1);
      rc = dispatch(argc, argv);
      csf_linSolverServeStop();
    } else {
      csError err;
      cs_errorClear(&err);
      if (csf_linSolverServe(&err) != CS_OK) {
        fprintf(stderr, "crawlsim-mpi: rank %d: %s\n", rank, err.msg);
        rc = 1;
      }
    }
  } else {
    rc = dispatch(argc, argv);
  }
  MPI_Finalize();
  return rc;
}
#else
/* crawlsim (sequential MUMPS) under an MPI launcher with several ranks: an FE command would run
 * as that many copies writing one output file (issue 38: it could not be opened). Refused on
 * every rank, reported by rank 0; a study is not refused (one case per rank). */
static int refusedUnderMpirun(int argc, char** argv) {
  static const char* const kSize[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"};
  static const char* const kRank[] = {"OMPI_COMM_WORLD_RANK", "PMI_RANK"};
  for (int k = 0; k < 2; k++) {
    const char* n = getenv(kSize[k]);
    const int size = n ? atoi(n) : 0;
    if (size <= 1 || !csx_feCommand(argc, argv)) {
      continue;
    }
    const char* r = getenv(kRank[k]);
    if (!r || atoi(r) == 0) {
      fprintf(stderr, "crawlsim: %s%s under an MPI launcher with %d ranks: this crawlsim's FE "
              "links sequential MUMPS and would run %d copies writing one file; run it without "
              "mpirun, or `mpirun -n %d crawlsim-mpi %s ...` (MUMPS over MPI)\n", argv[1],
              strcmp(argv[1], "bend") ? "" : " --model fe", size, size, size, argv[1]);
    }
    return 1;
  }
  return 0;
}
#endif


int main(int argc, char** argv) {
  passiveWaits(argv);
  /* the one process-wide ODE initialisation site (debian-deps.md P1) */
  dInitODE2(0);
  dSetMessageHandler(odeMessage);
#ifdef CS_FEM_MPI
  int rc = mpiMain(argc, argv);
#else
  int rc = refusedUnderMpirun(argc, argv) ? 1 : dispatch(argc, argv);
#endif
  dCloseODE();
  return rc;
}


static int dispatch(int argc, char** argv) {
  if (argc < 2 || !strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 1 : 0;
  }
  const char* cmd = argv[1];
  if (!strcmp(cmd, "--version") || !strcmp(cmd, "-V")) {
    printVersion();
    return 0;
  }
  if (!strcmp(cmd, "export")) {
    return csx_cmdExport(argc - 1, argv + 1);
  }
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
  if (!strcmp(cmd, "rom")) {
    return csx_cmdRom(argc - 1, argv + 1);
  }
  fprintf(stderr,
          "crawlsim: unknown command '%s' (expected run, bend, gait, calibrate, study, export or "
          "rom; see crawlsim --help)\n", cmd);
  return 1;
}

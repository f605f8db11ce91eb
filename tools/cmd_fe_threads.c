/* cmd_fe_threads.c: the FE commands' thread plan on the command line (cmd_fe_threads.h). */
#include "cmd_fe_threads.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

enum { MAX_THREADS = 1024 };


int csx_feParseThreads(const char* value, int* out, csError* err) {
  char* end = NULL;
  const long v = strtol(value, &end, 10);
  if (!value[0] || !end || *end != '\0' || v < 1 || v > MAX_THREADS) {
    cs_errorSet(err, CS_ERR_ARG, "--threads '%.40s' must be an integer in 1..%d", value,
                MAX_THREADS);
    return 1;
  }
  *out = (int)v;
  return 0;
}



int csx_feCommand(int argc, char** argv) {
  if (argc < 2) {
    return 0;
  }
  if (!strcmp(argv[1], "calibrate") || !strcmp(argv[1], "rom")) {
    return 1;
  }
  if (strcmp(argv[1], "bend") != 0) {
    return 0;
  }
  for (int i = 2; i < argc; i++) {
    if (!strcmp(argv[i], "--model=fe") || (!strcmp(argv[i], "--model") && i + 1 < argc &&
                                           !strcmp(argv[i + 1], "fe"))) {
      return 1;
    }
  }
  return 0;
}


/* a positive integer from the environment, or 0 */
static int envPositive(const char* name) {
  const char* v = getenv(name);
  char* end = NULL;
  const long x = v && v[0] ? strtol(v, &end, 10) : 0;
  return x > 0 && x < 1 << 20 && end && *end == '\0' ? (int)x : 0;
}


int csx_feRanks(int* local) {
  int ranks = envPositive(CSX_FE_RANKS_ENV);
  ranks = ranks > 0 ? ranks : 1;
  int l = envPositive("OMPI_COMM_WORLD_LOCAL_SIZE");
  l = l > 0 ? l : envPositive("MPI_LOCALNRANKS");
  *local = l > 0 && l < ranks ? l : ranks;
  return ranks;
}


#ifdef CS_HAVE_FEM
#include "fem_linsolve.h"


void csx_fePlanThreads(FILE* notes, const char* cmd, int requested, csfThreadPlan* plan) {
  csf_threadPlan(requested, plan);
  char wait[96];
  csf_threadWaitPolicy(wait, sizeof wait);
  int local = 1;
  const int ranks = csx_feRanks(&local);
  if (ranks > 1) {
    fprintf(notes, "crawlsim %s: fe: MUMPS over %d MPI ranks (%d on this machine), rank 0 runs "
            "the rest of the FE and writes the output\n", cmd, ranks, local);
  }
  fprintf(notes, "crawlsim %s: fe: %d thread%s%s (%s); the factorisation takes them from %.0e "
          "flops per factorisation, smaller ones run on one; OpenMP waits: %s\n", cmd,
          plan->threads, plan->threads > 1 ? "s" : "", ranks > 1 ? " per rank" : "", plan->why,
          CSF_MT_MIN_FLOPS, wait);
}


void csx_feReportThreads(FILE* notes, const char* cmd, const csfThreadPlan* plan,
                         const csfBendInfo* info) {
  const int small = info->factor_flops > 0 && info->factor_flops < CSF_MT_MIN_FLOPS;
  fprintf(notes, "crawlsim %s: fe: the factorisation (%s, %.3g flops) ran on %d thread%s%s",
          cmd, info->solver, info->factor_flops, info->factor_threads,
          info->factor_threads > 1 ? "s" : "",
          small && plan->threads > 1 ? " (below the threshold, one thread is faster)" : "");
  if (info->mpi_ranks > 1) {
    fprintf(notes, " on each of %d MPI ranks", info->mpi_ranks);
  }
  fprintf(notes, "; its memory %.0f MB (the most on one rank: %.0f MB)", info->factor_mem_total_mb,
          info->factor_mem_rank_mb);
  fputc('\n', notes);
}


csStatus csx_feThreadAttrs(csH5File* f, const csfThreadPlan* plan, const csfBendInfo* info,
                           csError* err) {
  char wait[96];
  csf_threadWaitPolicy(wait, sizeof wait);
  csStatus st = cs_h5AttrDouble(f, "/", "fe_threads", plan->threads, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "fe_threads_why", plan->why, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fe_factor_threads", info->factor_threads, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fe_factor_flops", info->factor_flops, err);
  if (st == CS_OK) st = cs_h5AttrString(f, "/", "fe_omp_wait_policy", wait, err);
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fe_affinity_cores", plan->env.cores, err);
  if (st == CS_OK) {
    st = cs_h5AttrDouble(f, "/", "fe_mpi_ranks_local", plan->env.ranks_local, err);
  }
  if (st == CS_OK) st = cs_h5AttrDouble(f, "/", "fe_mpi_ranks", info->mpi_ranks, err);
  if (st == CS_OK) {
    st = cs_h5AttrDouble(f, "/", "fe_factor_mem_rank_MB", info->factor_mem_rank_mb, err);
  }
  if (st == CS_OK) {
    st = cs_h5AttrDouble(f, "/", "fe_factor_mem_total_MB", info->factor_mem_total_mb, err);
  }
  return st;
}
#endif /* CS_HAVE_FEM */

/* cmd_fe_threads.c: the FE commands' thread plan on the command line (cmd_fe_threads.h). */
#include "cmd_fe_threads.h"

#include <stdio.h>
#include <stdlib.h>

enum { MAX_THREADS = 1024 };


int csx_feParseThreads(const char* cmd, const char* value, int* out) {
  char* end = NULL;
  const long v = strtol(value, &end, 10);
  if (!value[0] || !end || *end != '\0' || v < 1 || v > MAX_THREADS) {
    fprintf(stderr, "crawlsim %s: --threads '%.40s' must be an integer in 1..%d\n", cmd, value,
            MAX_THREADS);
    return 1;
  }
  *out = (int)v;
  return 0;
}


#ifdef CS_HAVE_FEM
#include "fem_linsolve.h"


void csx_fePlanThreads(const char* cmd, int requested, csfThreadPlan* plan) {
  csf_threadPlan(requested, plan);
  char wait[96];
  csf_threadWaitPolicy(wait, sizeof wait);
  fprintf(stderr, "crawlsim %s: fe: %d thread%s (%s); the factorisation takes them from %.0e "
          "flops per factorisation, smaller ones run on one; OpenMP waits: %s\n", cmd,
          plan->threads, plan->threads > 1 ? "s" : "", plan->why, CSF_MT_MIN_FLOPS, wait);
}


void csx_feReportThreads(const char* cmd, const csfThreadPlan* plan, const csfBendInfo* info) {
  const int small = info->factor_flops > 0 && info->factor_flops < CSF_MT_MIN_FLOPS;
  fprintf(stderr, "crawlsim %s: fe: the factorisation (%s, %.3g flops) ran on %d thread%s%s\n",
          cmd, info->solver, info->factor_flops, info->factor_threads,
          info->factor_threads > 1 ? "s" : "",
          small && plan->threads > 1 ? ": below the threshold, one thread is faster" : "");
  fputc('\n', stderr);
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
  return st;
}
#endif /* CS_HAVE_FEM */

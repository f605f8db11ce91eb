/* cmd_fe_threads.h: the FE commands' thread plan on the command line (`crawlsim bend --model fe`,
 * `crawlsim calibrate`): --threads N, the banner line saying how many threads the FE takes and
 * why, the summary line of what the factorisation used, and the root attributes recording both
 * (fem_threads.h decides). Private to tools/. */
#ifndef CS_TOOLS_CMD_FE_THREADS_H
#define CS_TOOLS_CMD_FE_THREADS_H

/* --threads VALUE: an integer in 1..1024 into *out; 0, or 1 after one error line naming cmd */
int csx_feParseThreads(const char* cmd, const char* value, int* out);

#ifdef CS_HAVE_FEM
#include "core_h5.h"
#include "fem_bend.h"
#include "fem_threads.h"

/* Make the plan (requested 0: the default rule) and print the banner line
 * "crawlsim CMD: fe: N threads (why); the factorisation uses them from 5e9 flops, ...;
 * OpenMP waits: POLICY". */
void csx_fePlanThreads(const char* cmd, int requested, csfThreadPlan* plan);

/* The summary line of what the factorisation used (info filled by csf_bend). */
void csx_feReportThreads(const char* cmd, const csfThreadPlan* plan, const csfBendInfo* info);

/* Root attributes: fe_threads (the plan), fe_threads_why, fe_factor_threads, fe_factor_flops,
 * fe_omp_wait_policy, fe_affinity_cores, fe_mpi_ranks_local. */
csStatus csx_feThreadAttrs(csH5File* f, const csfThreadPlan* plan, const csfBendInfo* info,
                           csError* err);
#endif /* CS_HAVE_FEM */

#endif /* CS_TOOLS_CMD_FE_THREADS_H */

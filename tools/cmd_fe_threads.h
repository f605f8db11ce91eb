/* cmd_fe_threads.h: the FE commands' thread plan on the command line (`crawlsim bend --model fe`,
 * `crawlsim calibrate`): --threads N, the banner line saying how many threads the FE takes and
 * why, the summary line of what the factorisation used, and the root attributes recording both
 * (fem_threads.h decides). Private to tools/. */
#ifndef CS_TOOLS_CMD_FE_THREADS_H
#define CS_TOOLS_CMD_FE_THREADS_H

#include <stdio.h>

#include "core_status.h"

/* --threads VALUE: an integer in 1..1024 into *out; 0, or 1 with err filled */
int csx_feParseThreads(const char* value, int* out, csError* err);

/* 1 if argv (argv[1] the subcommand) is a command that runs the full FE: `bend --model fe`,
 * `calibrate` */
int csx_feCommand(int argc, char** argv);

/* The environment variable by which crawlsim-mpi's main tells the FE command of rank 0 that
 * the other ranks serve its factorisations (csf_linSolverServe): their count. Set only there,
 * so that a study's FE cases (one per rank) stay on their own rank. */
#define CSX_FE_RANKS_ENV "CRAWLSIM_FE_RANKS"

/* MPI ranks of this FE command's factorisation (CSX_FE_RANKS_ENV, 1 when unset) and how many
 * of them run on this machine (*local: the launcher's local size, at most the ranks) */
int csx_feRanks(int* local);

#ifdef CS_HAVE_FEM
#include "core_h5.h"
#include "fem_bend.h"
#include "fem_threads.h"

/* Make the plan (requested 0: the default rule) and print the banner line
 * "crawlsim CMD: fe: N threads (why); the factorisation uses them from 5e9 flops, ...;
 * OpenMP waits: POLICY" on `notes`. */
void csx_fePlanThreads(FILE* notes, const char* cmd, int requested, csfThreadPlan* plan);

/* The summary line of what the factorisation used (info filled by csf_bend), on `notes`. */
void csx_feReportThreads(FILE* notes, const char* cmd, const csfThreadPlan* plan,
                         const csfBendInfo* info);

/* Root attributes: fe_threads (the plan), fe_threads_why, fe_factor_threads, fe_factor_flops,
 * fe_omp_wait_policy, fe_affinity_cores, fe_mpi_ranks (of the factorisation),
 * fe_mpi_ranks_local (launched on this machine), fe_factor_mem_rank_MB, fe_factor_mem_total_MB. */
csStatus csx_feThreadAttrs(csH5File* f, const csfThreadPlan* plan, const csfBendInfo* info,
                           csError* err);
#endif /* CS_HAVE_FEM */

#endif /* CS_TOOLS_CMD_FE_THREADS_H */

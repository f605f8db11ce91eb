/* fem_threads.h: how many threads the FE may use (issue 38: threads that never oversubscribe).
 *
 * Owns: csfThreadPlan, the thread count of the FE's assembly and factorisation, chosen from what
 * this process is given and what the machine is doing:
 *   - the cores of this process's affinity mask (sched_getaffinity: taskset, cgroups' cpusets,
 *     mpirun's binding);
 *   - the MPI ranks started on this node by a launcher (OpenMPI's OMPI_COMM_WORLD_LOCAL_SIZE, MPICH's
 *     MPI_LOCALNRANKS): each rank takes its share, cores / ranks, so that a study under
 *     `mpirun -n 2` on two cores runs one thread per rank;
 *   - the other processes already running (the runnable tasks of /proc/stat, sampled): cores
 *     they hold are left to them. Measured on the 2-core VM (docs/notes/fe_threads.md): with
 *     one other busy process, two FE threads ran a small sweep 1.2-3.3x slower than one;
 *   - an explicit request (--threads N), or else the user's OMP_NUM_THREADS, capped at the
 *     affinity's cores.
 * The library never prints: `why` says in one line how the count was chosen, for the banner
 * and the HDF5 output. The plan is made once per command (before the first solver exists), so a
 * run's thread count, and with one thread its bits, do not depend on load changes during it.
 *
 * OpenMP's wait policy cannot be changed here: libgomp reads OMP_WAIT_POLICY and GOMP_SPINCOUNT
 * once, when it is loaded, before main(). The crawlsim executable therefore sets
 * OMP_WAIT_POLICY=PASSIVE (unless the user set a policy) and re-executes itself before anything
 * else (tools/crawlsim.c); csf_threadWaitPolicy reports what is in effect. */
#ifndef CS_FEM_THREADS_H
#define CS_FEM_THREADS_H

#ifdef __cplusplus
extern "C" {
#endif

/* What the machine and the launcher give this process (csf_threadProbe). */
typedef struct csfThreadEnv_ {
  int cores;       /* CPUs in this process's affinity mask (>= 1) */
  int online;      /* CPUs online on this machine (0: unknown); a mask smaller than that is
                    * already this process's share (taskset, mpirun's binding): not divided
                    * again among the ranks */
  int ranks_local; /* processes of this MPI job on this node (1 without a launcher) */
  int omp_env;     /* OMP_NUM_THREADS as set by the user (its first entry; 0: unset) */
  double busy;     /* runnable tasks of other processes, mean of the samples (>= 0; NAN: not
                    * measured, e.g. no /proc/stat) */
} csfThreadEnv;

/* The decision. */
typedef struct csfThreadPlan_ {
  int threads;      /* threads of the FE's assembly and factorisation (>= 1) */
  int requested;    /* the explicit request (0: none) */
  int share;        /* cores / ranks_local (>= 1): the most a rank takes by default */
  csfThreadEnv env; /* what it was chosen from */
  char why[200];    /* one line: how `threads` was chosen */
} csfThreadPlan;

/* Sampling of the machine's load: this many samples of /proc/stat's procs_running, this many
 * seconds apart (a build or another FE keeps its tasks runnable; a sample alone catches
 * short-lived ones too, the mean smooths them) */
#define CSF_LOAD_SAMPLES 10
#define CSF_LOAD_INTERVAL_S 0.02

/* Read the affinity mask, the launcher's environment and (when sample_load) the machine's load.
 * Takes about CSF_LOAD_SAMPLES x CSF_LOAD_INTERVAL_S seconds with sample_load. */
void csf_threadProbe(int sample_load, csfThreadEnv* env);

/* The thread count from env and an explicit request (0: none, the default rule):
 *   requested > 0: min(requested, cores); else OMP_NUM_THREADS set: min(it, cores);
 *   otherwise: share = max(1, cores / ranks_local) (cores alone when the mask is smaller than
 *   the machine: the launcher bound this rank to its share already), minus the cores held by other processes
 *   (busy, less this job's other ranks, rounded to the nearest core), at least 1. */
void csf_threadPlanCompute(int requested, const csfThreadEnv* env, csfThreadPlan* plan);

/* Probe and compute. */
void csf_threadPlan(int requested, csfThreadPlan* plan);

/* The OpenMP wait policy in effect for this process, as libgomp read it at start-up, into out
 * (sz bytes): "OMP_WAIT_POLICY=passive", "GOMP_SPINCOUNT=N", ... or "default" (libgomp spins
 * 300 000 rounds, then sleeps). */
void csf_threadWaitPolicy(char* out, unsigned long sz);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_THREADS_H */

/* test_fem_threads.c: the FE's thread plan (fem_threads.h) never gives more threads than the
 * cores it is given: an explicit request and OMP_NUM_THREADS are capped at the affinity mask,
 * MPI ranks on one node split it, cores held by other processes are left to them, at least one
 * thread always; and the probe reads the affinity mask and the launcher's environment. */
#define _GNU_SOURCE /* sched_getaffinity, setenv */
#include <math.h>
#include <sched.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "fem_threads.h"


static csfThreadEnv env(int cores, int ranks, double busy) {
  csfThreadEnv e;
  memset(&e, 0, sizeof e);
  e.cores = cores, e.online = cores, e.ranks_local = ranks, e.busy = busy;
  return e;
}


static int plan(int requested, csfThreadEnv e) {
  csfThreadPlan p;
  csf_threadPlanCompute(requested, &e, &p);
  CS_EXPECT(p.why[0] != '\0');
  return p.threads;
}


static void test_explicit_request_is_capped_at_the_affinity_mask(void) {
  CS_EXPECT(plan(1, env(2, 1, NAN)) == 1);
  CS_EXPECT(plan(2, env(2, 1, 3.0)) == 2); /* explicit: the load does not change it */
  CS_EXPECT(plan(8, env(2, 1, 0.0)) == 2);
  csfThreadEnv e = env(4, 1, 0.0);
  e.omp_env = 3; /* OMP_NUM_THREADS=3 */
  CS_EXPECT(plan(0, e) == 3);
  CS_EXPECT(plan(1, e) == 1); /* --threads wins over OMP_NUM_THREADS */
  e.omp_env = 16;
  CS_EXPECT(plan(0, e) == 4);
}


static void test_ranks_on_a_node_share_its_cores(void) {
  CS_EXPECT(plan(0, env(2, 2, NAN)) == 1); /* mpirun -n 2 on two cores */
  CS_EXPECT(plan(0, env(8, 2, NAN)) == 4);
  CS_EXPECT(plan(0, env(2, 4, NAN)) == 1); /* oversubscribed launch: still one each */
  /* the job's own other ranks are busy: not counted as foreign load */
  CS_EXPECT(plan(0, env(8, 2, 1.0)) == 4);
  /* a foreign process on top of them takes a core: 7 free cores for 2 ranks */
  CS_EXPECT(plan(0, env(8, 2, 2.0)) == 3);
  /* mpirun bound each rank to its cores: the mask is the share, not divided again */
  csfThreadEnv b = env(2, 2, NAN);
  b.online = 4;
  CS_EXPECT(plan(0, b) == 2);
  b.cores = 1, b.online = 2; /* mpirun -n 2 on two cores, bound: one each */
  CS_EXPECT(plan(0, b) == 1);
}


static void test_cores_held_by_others_are_left_to_them(void) {
  CS_EXPECT(plan(0, env(2, 1, 0.0)) == 2);  /* quiet */
  CS_EXPECT(plan(0, env(2, 1, 0.3)) == 2);  /* a short-lived task now and then */
  CS_EXPECT(plan(0, env(2, 1, 1.0)) == 1);  /* one other busy process */
  CS_EXPECT(plan(0, env(2, 1, 2.0)) == 1);  /* a build -j2: at least one thread */
  CS_EXPECT(plan(0, env(16, 1, 5.2)) == 11);
}


static void test_probe_reads_affinity_and_launcher(void) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CS_EXPECT(sched_getaffinity(0, sizeof set, &set) == 0);
  unsetenv("OMP_NUM_THREADS");
  setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "3", 1);
  csfThreadEnv e;
  csf_threadProbe(1, &e);
  CS_EXPECT(e.cores == CPU_COUNT(&set));
  CS_EXPECT(e.online >= e.cores);
  CS_EXPECT(e.ranks_local == 3);
  CS_EXPECT(e.omp_env == 0);
  /* runnable tasks of others: a mean of counts, not negative (NAN only without /proc/stat) */
  CS_EXPECT(isnan(e.busy) || e.busy >= 0);
  unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  setenv("OMP_NUM_THREADS", "1,2", 1);
  csf_threadProbe(0, &e);
  CS_EXPECT(e.ranks_local == 1);
  CS_EXPECT(e.omp_env == 1);
  CS_EXPECT(isnan(e.busy)); /* not sampled */
  csfThreadPlan p;
  csf_threadPlan(0, &p);
  CS_EXPECT(p.threads == 1);
  CS_EXPECT(strstr(p.why, "OMP_NUM_THREADS=1") != NULL);
  unsetenv("OMP_NUM_THREADS");
  setenv("OMP_WAIT_POLICY", "PASSIVE", 1);
  char w[96];
  csf_threadWaitPolicy(w, sizeof w);
  CS_EXPECT(!strcmp(w, "OMP_WAIT_POLICY=PASSIVE"));
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_explicit_request_is_capped_at_the_affinity_mask);
  CS_RUN(test_ranks_on_a_node_share_its_cores);
  CS_RUN(test_cores_held_by_others_are_left_to_them);
  CS_RUN(test_probe_reads_affinity_and_launcher);
  return cs_testSummary();
}

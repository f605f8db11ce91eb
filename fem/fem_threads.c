/* fem_threads.c: the FE's thread plan (see fem_threads.h). */
#define _GNU_SOURCE /* sched_getaffinity, CPU_COUNT */
#include "fem_threads.h"

#include <math.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

/* the launchers' count of this job's processes on this node */
static const char* const kLocalSizeVars[] = {"OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS"};


/* a positive integer environment variable, or 0 */
static int envInt(const char* name) {
  const char* v = getenv(name);
  if (!v || !v[0]) {
    return 0;
  }
  char* end = NULL;
  const long x = strtol(v, &end, 10);
  return end && *end == '\0' && x > 0 && x < 1 << 20 ? (int)x : 0;
}


/* runnable tasks of the whole machine now (/proc/stat procs_running: running or waiting for a
 * CPU, this sampling thread included), -1 when unreadable */
static int procsRunning(void) {
  FILE* f = fopen("/proc/stat", "r");
  if (!f) {
    return -1;
  }
  char line[256];
  int n = -1;
  while (fgets(line, sizeof line, f)) {
    if (sscanf(line, "procs_running %d", &n) == 1) {
      break;
    }
  }
  fclose(f);
  return n;
}


void csf_threadProbe(int sample_load, csfThreadEnv* env) {
  memset(env, 0, sizeof *env);
  cpu_set_t set;
  CPU_ZERO(&set);
  env->cores = sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : 1;
  if (env->cores < 1) {
    env->cores = 1;
  }
  const long online = sysconf(_SC_NPROCESSORS_ONLN);
  env->online = online > 0 && online < 1 << 20 ? (int)online : 0;
  env->ranks_local = 1;
  for (size_t k = 0; k < sizeof kLocalSizeVars / sizeof kLocalSizeVars[0]; k++) {
    const int v = envInt(kLocalSizeVars[k]);
    if (v > 0) {
      env->ranks_local = v;
      break;
    }
  }
  /* "4" or "4,2" (nested levels): the outer level */
  const char* omp = getenv("OMP_NUM_THREADS");
  if (omp && omp[0]) {
    char* end = NULL;
    const long v = strtol(omp, &end, 10);
    env->omp_env = v > 0 && v < 1 << 20 && (*end == '\0' || *end == ',') ? (int)v : 0;
  }
  env->busy = NAN;
  if (!sample_load) {
    return;
  }
  double sum = 0;
  int n = 0;
  for (int k = 0; k < CSF_LOAD_SAMPLES; k++) {
    const int r = procsRunning();
    if (r >= 1) {
      sum += r - 1; /* this thread is one of them */
      n++;
    }
    const struct timespec ts = {0, (long)(CSF_LOAD_INTERVAL_S * 1e9)};
    nanosleep(&ts, NULL);
  }
  if (n > 0) {
    env->busy = sum / n;
  }
}


void csf_threadPlanCompute(int requested, const csfThreadEnv* env, csfThreadPlan* plan) {
  memset(plan, 0, sizeof *plan);
  plan->env = *env;
  plan->requested = requested > 0 ? requested : 0;
  const int cores = env->cores > 0 ? env->cores : 1;
  const int ranks = env->ranks_local > 0 ? env->ranks_local : 1;
  /* a mask smaller than the machine is this rank's own share already (mpirun --bind-to core) */
  const int bound = env->online > 0 && cores < env->online;
  const int split = bound ? 1 : ranks;
  plan->share = cores / split > 0 ? cores / split : 1;
  char from[96];
  if (ranks > 1 && bound) {
    snprintf(from, sizeof from, "%d core%s of this rank's affinity mask, %d MPI ranks on this "
             "node", cores, cores > 1 ? "s" : "", ranks);
  } else if (ranks > 1) {
    snprintf(from, sizeof from, "%d core%s of the affinity mask shared by %d MPI ranks on this "
             "node", cores, cores > 1 ? "s" : "", ranks);
  } else {
    snprintf(from, sizeof from, "%d core%s in the affinity mask", cores, cores > 1 ? "s" : "");
  }
  if (plan->requested > 0) {
    plan->threads = plan->requested < cores ? plan->requested : cores;
    snprintf(plan->why, sizeof plan->why, "--threads %d%s (%s)", plan->requested,
             plan->requested > cores ? ", capped" : "", from);
    return;
  }
  if (env->omp_env > 0) {
    plan->threads = env->omp_env < cores ? env->omp_env : cores;
    snprintf(plan->why, sizeof plan->why, "OMP_NUM_THREADS=%d%s (%s)", env->omp_env,
             env->omp_env > cores ? ", capped" : "", from);
    return;
  }
  plan->threads = plan->share;
  if (isnan(env->busy)) {
    snprintf(plan->why, sizeof plan->why, "%s; load not measured", from);
    return;
  }
  /* the other ranks of this job are counted by the share already: busy beyond them is held by
   * other processes, rounded to whole cores; what is left is split among this job's ranks */
  double others = env->busy - (ranks - 1);
  others = others > 0 ? floor(others + 0.5) : 0;
  const int free_cores = cores - (int)others;
  int t = free_cores / split;
  t = t < 1 ? 1 : t > plan->share ? plan->share : t;
  plan->threads = t;
  if (t < plan->share) {
    snprintf(plan->why, sizeof plan->why, "%s, %.1f held by other processes", from,
             env->busy - (ranks - 1) > 0 ? env->busy - (ranks - 1) : 0.0);
  } else {
    snprintf(plan->why, sizeof plan->why, "%s, %.1f busy elsewhere", from,
             env->busy - (ranks - 1) > 0 ? env->busy - (ranks - 1) : 0.0);
  }
}


void csf_threadPlan(int requested, csfThreadPlan* plan) {
  csfThreadEnv env;
  csf_threadProbe(requested <= 0 && !getenv("OMP_NUM_THREADS"), &env);
  csf_threadPlanCompute(requested, &env, plan);
}


void csf_threadWaitPolicy(char* out, unsigned long sz) {
  const char* pol = getenv("OMP_WAIT_POLICY");
  const char* spin = getenv("GOMP_SPINCOUNT");
  if (pol && pol[0] && spin && spin[0]) {
    snprintf(out, sz, "OMP_WAIT_POLICY=%s, GOMP_SPINCOUNT=%s", pol, spin);
  } else if (pol && pol[0]) {
    snprintf(out, sz, "OMP_WAIT_POLICY=%s", pol);
  } else if (spin && spin[0]) {
    snprintf(out, sz, "GOMP_SPINCOUNT=%s", spin);
  } else {
    snprintf(out, sz, "default");
  }
}

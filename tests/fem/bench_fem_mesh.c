/* bench_fem_mesh.c: benchmark (not a ctest): mesh statistics of an actuator for a list of mesh
 * sizes l_soft (the paper's Table 1 sweep), or, with --estimate, only the cost the FE's set-up
 * estimates before it runs gmsh (csf_actuatorEstimate: the numbers that refuse a mesh whose
 * factorisation would not fit in this machine's memory).
 * Usage: bench_fem_mesh [--estimate] [--segments 1|3] [actuator] [l_soft]... */
#define _POSIX_C_SOURCE 200809L /* sysconf */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "fem_actuator.h"
#include "fem_mesh.h"

static double now(void) {
  struct timespec ts;
  timespec_get(&ts, TIME_UTC);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

/* the estimate per size, and whether csf_actuatorFECreate would refuse it here (its rule: the
 * factorisation above 75 % of the physical memory, one process) */
static void printEstimates(const csrActuator* act, const double* sizes, int ns) {
  const double mem = (double)sysconf(_SC_PHYS_PAGES) * (double)sysconf(_SC_PAGESIZE);
  printf("| l_soft (mm) | solid volume (mm^3) | Tet10 (at least) | nodes | dofs | factor entries "
         "| factorisation memory (GB) | refused here (%.1f GB) |\n", mem / 1e9);
  printf("|---|---|---|---|---|---|---|---|\n");
  for (int k = 0; k < ns; k++) {
    csfMeshEstimate e;
    csf_actuatorEstimate(act, sizes[k], &e);
    printf("| %g | %.0f | %.0f | %.0f | %.0f | %.3g | %.2f | %s |\n", sizes[k], e.volume, e.tet10,
           e.nodes, e.dofs, e.entries, e.bytes / 1e9, e.bytes > 0.75 * mem ? "yes" : "no");
  }
}

int main(int argc, char** argv) {
  csError err = {0};
  csrActuator act;
  int estimate = 0, single = 0, i = 1;
  for (; i < argc && argv[i][0] == '-' && argv[i][1] == '-'; i++) {
    if (!strcmp(argv[i], "--estimate")) {
      estimate = 1;
    } else if (!strcmp(argv[i], "--segments") && i + 1 < argc &&
               (!strcmp(argv[i + 1], "1") || !strcmp(argv[i + 1], "3"))) {
      single = argv[++i][0] == '1';
    } else {
      fprintf(stderr, "usage: bench_fem_mesh [--estimate] [--segments 1|3] [actuator] "
              "[l_soft]...\n");
      return 1;
    }
  }
  if (csr_actuatorPreset(&act, i < argc ? argv[i] : "baseline", &err) != CS_OK) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  i++;
  if (single) {
    csrActuator one;
    csr_actuatorSingleSegment(&act, &one);
    act = one;
  }
  double sizes[16] = {5, 4.5, 4, 3.5, 3, 2.5, 2, 1.5};
  int ns = 8;
  if (i < argc) {
    ns = 0;
    for (; i < argc && ns < 16; i++) {
      sizes[ns++] = atof(argv[i]);
    }
  }
  if (estimate) {
    printEstimates(&act, sizes, ns);
    return 0;
  }
  printf("| l_soft (mm) | Tet10 | nodes | dofs | folded left after fix | gmsh + read (s) |\n");
  printf("|---|---|---|---|---|---|\n");
  for (int k = 0; k < ns; k++) {
    double t0 = now();
    csfMesh* m = csf_meshActuator(&act, sizes[k], "bench_mesh", &err);
    double t1 = now();
    if (!m) {
      fprintf(stderr, "%s\n", err.msg);
      return 1;
    }
    int nfix = csf_meshFixInverted(m); /* already applied once: counts what remains (0) */
    printf("| %.1f | %d | %d | %d | %d | %.2f |\n", sizes[k], m->ntet, m->nnode, 3 * m->nnode,
           nfix, t1 - t0);
    fflush(stdout);
    csf_meshDestroy(m);
  }
  return 0;
}

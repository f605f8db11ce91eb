/* bench_fem_mesh.c: benchmark (not a ctest): mesh statistics of an actuator for a list of mesh
 * sizes l_soft (the paper's Table 1 sweep). Usage: bench_fem_mesh [actuator] [l_soft]... */
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "fem_mesh.h"

static double now(void) {
  struct timespec ts;
  timespec_get(&ts, TIME_UTC);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

int main(int argc, char** argv) {
  csError err = {0};
  csrActuator act;
  if (csr_actuatorPreset(&act, argc > 1 ? argv[1] : "baseline", &err) != CS_OK) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  double sizes[16] = {5, 4.5, 4, 3.5, 3, 2.5, 2, 1.5};
  int ns = 8;
  if (argc > 2) {
    ns = 0;
    for (int i = 2; i < argc && ns < 16; i++) {
      sizes[ns++] = atof(argv[i]);
    }
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

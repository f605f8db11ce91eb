/* bench_fem_solver.c: benchmark (not a ctest): assembly and KLU factorisation cost on structured
 * Tet10 beams (15 x 15 x 162 mm, the actuator's envelope) of growing size.
 * Usage: bench_fem_solver mumps|klu [nx ny nz] */
#include <string.h>
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#include "fem_linsolve.h"
#include "fem_assembly.h"

static double now(void) {
  struct timespec ts;
  timespec_get(&ts, TIME_UTC);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void scaleMap(void* user, const double xi[3], double x[3]) {
  const double* s = user;
  for (int i = 0; i < 3; i++) {
    x[i] = s[i] * xi[i];
  }
}

int main(int argc, char** argv) {
  int sizes[][3] = {{3, 3, 20}, {4, 4, 30}, {5, 5, 40}, {6, 6, 50}};
  int ns = 4;
  csfSolverKind kind = (argc > 1 && !strcmp(argv[1], "klu")) ? CSF_SOLVER_KLU : CSF_SOLVER_MUMPS;
  if (argc >= 5) {
    sizes[0][0] = atoi(argv[2]), sizes[0][1] = atoi(argv[3]), sizes[0][2] = atoi(argv[4]);
    ns = 1;
  }
  for (int s = 0; s < ns; s++) {
    csError err = {0};
    double sc[3] = {15, 15, 162};
    csfMesh* me = csf_meshCreateBox(sizes[s], scaleMap, sc, 0.0, &err);
    csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
    csfModel* m = csf_modelCreate(me, &mat, &err);
    for (int i = 0; i < me->nnode; i++) {
      if (me->x[3 * i + 2] < 1e-9) {
        m->fixed[3 * i] = m->fixed[3 * i + 1] = m->fixed[3 * i + 2] = 1;
      }
    }
    csf_modelAddPressure(m, 2, 1.0);
    m->solver.kind = kind;
    csf_modelFinalize(m, &err);
    double t0 = now();
    csfData* d = csf_dataCreate(m, &err);
    double t1 = now();
    csf_assemble(m, d, 0.01, 1);
    double t2 = now();
    csf_linSolverFactor(d->ls, d->kval);
    double t3 = now();
    for (int i = 0; i < m->ndof; i++) {
      d->du[i] = -d->r[i];
    }
    csf_linSolverSolve(d->ls, d->du);
    double t4 = now();
    printf("%s tets %6d nodes %6d dofs %6d nnz %8d | analyse %.3f s  assemble %.3f s  factor %.3f s "
           "(LU nnz %.3g)  solve %.3f s\n",
           csf_linSolverName(d->ls), me->ntet, me->nnode, m->ndof, m->nnz, t1 - t0, t2 - t1, t3 - t2,
           csf_linSolverFactorNnz(d->ls), t4 - t3);
    fflush(stdout);
    csf_dataDestroy(d);
    csf_modelDestroy(m);
    csf_meshDestroy(me);
  }
  return 0;
}

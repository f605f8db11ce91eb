/* bench_fem_linsolve.c: benchmark command (not a ctest): the sparse direct solver on an
 * actuator mesh: analysis, numeric factorisation and solve times for each solver mode,
 * ordering and thread count, on the tangent of the pressurised actuator at u = 0.
 * Usage: bench_fem_linsolve MESH.msh [pressure MPa] [repeats]
 * Prints one line per configuration: mode, ordering used, threads, pivot threshold (CNTL(1);
 * -1: the library's default, for LDL^T unpivoted with a checked solve), analysis s, factor s
 * (median of the repeats), solve s, factor entries, flops, and the relative difference of the
 * solution from the first configuration's. BENCH_LINSOLVE_CONFIGS=1,12 runs a subset (here:
 * LDL^T on one thread, unpivoted and with MUMPS's threshold 0.01). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fem_linsolve.h"
#include "fem_assembly.h"

static int cmpd(const void* a, const void* b) {
  double x = *(const double*)a, y = *(const double*)b;
  return (x > y) - (x < y);
}


int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: bench_fem_linsolve MESH.msh [pressure] [repeats]\n");
    return 1;
  }
  const double p = argc > 2 ? atof(argv[2]) : 0.05;
  const int rep = argc > 3 ? atoi(argv[3]) : 3;
  csError err = {0};
  csfMesh* me = csf_meshReadMsh(argv[1], &err);
  if (!me) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
  csfModel* m = csf_modelCreate(me, &mat, &err);
  for (int i = 0; i < me->nnode; i++) {
    if (fabs(me->x[3 * i + 2]) < 1e-6) {
      m->fixed[3 * i] = m->fixed[3 * i + 1] = m->fixed[3 * i + 2] = 1;
    }
  }
  for (int s = 0; s < 3; s++) {
    csf_modelAddPressure(m, CSF_TAG_CHAMBER(s, 1), 1.0);
    csf_modelAddPressure(m, CSF_TAG_CHAMBER(s, 2), 1.0);
  }
  if (csf_modelFinalize(m, &err) != CS_OK) {
    fprintf(stderr, "%s\n", err.msg);
    return 1;
  }
  printf("mesh %s: %d Tet10, %d dofs, %d nonzeros; tangent symmetric (closed chambers): %d\n",
         argv[1], me->ntet, m->ndof, m->nnz, csf_modelSymmetric(m));
  m->solver.symmetric = 0;
  csfData* d = csf_dataCreate(m, &err);
  csf_assemble(m, d, p, 1);
  double* b0 = malloc((size_t)m->ndof * sizeof(double));
  double* x = malloc((size_t)m->ndof * sizeof(double));
  double* xref = malloc((size_t)m->ndof * sizeof(double));
  for (int i = 0; i < m->ndof; i++) {
    b0[i] = m->fixed[i] ? 0.0 : -d->r[i];
  }
  struct {
    int sym, ord, thr;
    double piv; /* CNTL(1); < 0: the library's default (LDL^T: checked unpivoted, LU: MUMPS's) */
  } cfg[] = {{0, 7, 1, -1}, {2, 7, 1, -1},  {0, 7, 2, -1},  {2, 7, 2, -1},  {2, 3, 1, -1},
             {2, 4, 1, -1}, {2, 2, 1, -1},  {2, 6, 1, -1},  {2, 0, 1, -1},  {2, 3, 2, -1},
             {2, 4, 2, -1}, {2, 7, 2, .01}, {2, 7, 1, .01}, {2, 4, 2, .01}, {2, 4, 1, .01}};
  const char* only = getenv("BENCH_LINSOLVE_CONFIGS"); /* e.g. "1,3,11": a subset */
  const int ncfg = (int)(sizeof cfg / sizeof cfg[0]);
  int have_ref = 0;
  for (int c = 0; c < ncfg; c++) {
    if (only) {
      char key[16];
      snprintf(key, sizeof key, ",%d,", c);
      char list[256];
      snprintf(list, sizeof list, ",%s,", only);
      if (!strstr(list, key)) {
        continue;
      }
    }
    csfLinSolverOptions o = csf_linSolverDefault();
    o.symmetric = cfg[c].sym != 0;
    o.ordering = cfg[c].ord;
    o.threads = cfg[c].thr;
    o.pivot_threshold = cfg[c].piv;
    double t0 = csf_wallTime();
    csfLinSolver* s = csf_linSolverCreate(&o, m->ndof, m->row_ptr, m->col, &err);
    double ta = csf_wallTime() - t0;
    if (!s) {
      printf("config %d: %s\n", c, err.msg);
      continue;
    }
    double tf[16], ts = 0;
    int bad = 0;
    for (int r = 0; r < rep && r < 16; r++) {
      t0 = csf_wallTime();
      bad |= csf_linSolverFactor(s, d->kval);
      tf[r] = csf_wallTime() - t0;
    }
    qsort(tf, (size_t)(rep < 16 ? rep : 16), sizeof(double), cmpd);
    memcpy(x, b0, (size_t)m->ndof * sizeof(double));
    t0 = csf_wallTime();
    bad |= csf_linSolverSolve(s, x);
    ts = csf_wallTime() - t0;
    double num = 0, den = 0;
    if (!have_ref) {
      memcpy(xref, x, (size_t)m->ndof * sizeof(double));
      have_ref = 1;
    }
    for (int i = 0; i < m->ndof; i++) {
      num += (x[i] - xref[i]) * (x[i] - xref[i]);
      den += xref[i] * xref[i];
    }
    printf("%-10s ordering %d (asked %d) threads %d pivot %5.2f | analysis %6.2f s  factor %6.2f s  solve "
           "%5.3f s | factors %.3g entries, %.3g flops | rel diff %.2e%s\n",
           csf_linSolverName(s), csf_linSolverOrdering(s), cfg[c].ord, cfg[c].thr, cfg[c].piv, ta,
           tf[(rep < 16 ? rep : 16) / 2], ts, csf_linSolverFactorNnz(s), csf_linSolverFlops(s),
           sqrt(num / (den > 0 ? den : 1)), bad ? "  FAILED" : "");
    fflush(stdout);
    csf_linSolverDestroy(s);
  }
  free(b0), free(x), free(xref);
  csf_dataDestroy(d);
  csf_modelDestroy(m);
  csf_meshDestroy(me);
  return 0;
}

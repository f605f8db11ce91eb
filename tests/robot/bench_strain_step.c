/* bench_strain_step.c: the wall time of one strain-leg step (csr_strainPrepare +
 * csr_strainFinish, base held), the leg hanging with its foot pressed 0.3 mm into the flat road
 * or without terrain, swung by a tip force of 0.05 N along x at 2 Hz (so the velocity products
 * and the foot's friction work as in a gait) (issue 32; built, not registered).
 *
 * Usage: bench_strain_step [BEND_ORDER] [CONTACT 0|1] [STEPS] [AXIAL_ORDER] [JOINT_ORDER]
 *        [SHEAR 0|1] [NSUB]
 * (defaults 2, 1, 2000, then csr_strainDefaultParams' axial_order, joint_order, shear, nsub; the
 * last four measure how the cost grows with the strain modes, docs/notes/strain_leg.md "Cost
 * against modes and legs") */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "core_clock.h"
#include "robot_strain.h"
#include "rod_test_road.h"

/* the process's CPU time (s): on a shared machine the wall time counts the waits for a core */
static double cpuSeconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}


int main(int argc, char** argv) {
  int order = argc > 1 ? atoi(argv[1]) : 2, contact = argc > 2 ? atoi(argv[2]) : 1;
  int nstep = argc > 3 ? atoi(argv[3]) : 2000;
  csError err;
  cs_errorClear(&err);
  csrActuator act;
  if (csr_actuatorPreset(&act, "leg", &err) != CS_OK) {
    fprintf(stderr, "bench_strain_step: %s\n", err.msg);
    return 1;
  }
  cstTerrain tr = csTestFlatRoad();
  cscSoftParams soft = csc_softDefaultParams();
  csrStrainParams par = csr_strainDefaultParams();
  par.bend_order = order;
  if (argc > 4) par.axial_order = atoi(argv[4]);
  if (argc > 5) par.joint_order = atoi(argv[5]);
  if (argc > 6) par.shear = atoi(argv[6]);
  if (argc > 7) par.nsub = atoi(argv[7]);
  csrStrainSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.act = &act;
  sp.params = &par;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(sp.frame, F, sizeof F);
  sp.hip[1] = csr_actuatorLength(&act) - 0.3;
  sp.weightless = 1;
  if (contact) {
    sp.terrain = &tr;
    sp.soft = &soft;
  }
  csrStrainModel* m = csr_strainModelCreate(&sp, &err);
  csrStrainData* d = m ? csr_strainDataCreate(m, &err) : NULL;
  if (!d) {
    fprintf(stderr, "bench_strain_step: %s\n", err.msg);
    csr_strainModelDestroy(m);
    return 1;
  }
  double Z[36], rho[6];
  const double dV[6] = {0, 0, 0, 0, 0, 0};
  int status = 0;
  double t0 = csu_wallSeconds(), c0 = cpuSeconds();
  for (int i = 0; i < nstep; i++) {
    const double f[3] = {0.05 * sin(2 * CS_PI * 2.0 * 5e-3 * i), 0, 0}, mo[3] = {0, 0, 0};
    csr_strainSetTipLoad(d, f, mo);
    if (csr_strainPrepare(m, d, 5e-3, Z, rho) != 0 || csr_strainFinish(m, d, dV, NULL) != 0) {
      printf("step %d failed\n", i);
      status = 1;
      break;
    }
  }
  double t1 = csu_wallSeconds(), c1 = cpuSeconds();
  printf("bend order %d (axial %d, joints %d, shear %d, %d sub-intervals), contact %d: %d "
         "unknowns, %.1f us CPU (%.1f us wall) per leg step (%d steps of 5 ms)\n", order,
         par.axial_order, par.joint_order, par.shear, par.nsub, contact, csr_strainDofs(m),
         1e6 * (c1 - c0) / nstep, 1e6 * (t1 - t0) / nstep, nstep);
  /* STRAIN_DUMP=FILE: the leg's final state as raw doubles (to compare two builds) */
  const char* dump = getenv("STRAIN_DUMP");
  FILE* fd = dump ? fopen(dump, "wb") : NULL;
  if (fd) {
    int ns = csr_strainStateSize(m);
    double* y = calloc((size_t)ns, sizeof(double));
    if (y) {
      csr_strainGetState(m, d, y);
      fwrite(y, sizeof(double), (size_t)ns, fd);
      free(y);
    }
    fclose(fd);
  }
  csr_strainDataDestroy(d);
  csr_strainModelDestroy(m);
  return status;
}

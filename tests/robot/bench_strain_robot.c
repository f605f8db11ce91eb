/* bench_strain_robot.c: the flat road on eight strain legs stepped as one tree without ODE
 * (strain_test_robot.h; issue 32; built, not registered). Prints the support's displacement at
 * whole seconds, the horizontal excursion of the centre of mass, and the wall time split into
 * the legs (condense, back-substitute, contact) and the support's solve.
 *
 * Usage: bench_strain_robot [GAIT.csv] [MU] [H_S] [T_END_S] [BEND_ORDER] [MAXIT] [TOL]
 *        [STEP_ORDER]
 * (defaults: gaits/flat_road.csv under CS_SOURCE_DIR, 0.8, 5e-3, 9, 2, 8, 1e-7, 1: backward
 * Euler, 2: BDF2 for the legs and the support, strain_test_robot.h; conditions
 * `paper`, the shipped calibration robot/calibration_fe_leg.h5). MAXIT 1 is the one linearised
 * pass; more are Newton iterations of the whole tree to TOL (rad or mm of a mode's or the
 * support's move against the last iterate). A step that fails (not converged in MAXIT passes,
 * a pose sinking past a shape's radius, a singular matrix) is rejected: the robot is restored
 * and the step taken as two halves (at most 6 halvings), as the driver's rollback does. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <time.h>

#include "core_clock.h"
#include "strain_test_robot.h"

/* the process's CPU time (s): on a shared machine the wall time counts the waits for a core */
static double cpuSeconds(void) {
  struct timespec ts;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return ts.tv_sec + 1e-9 * ts.tv_nsec;
}


int main(int argc, char** argv) {
  const char* src = getenv("CS_SOURCE_DIR") ? getenv("CS_SOURCE_DIR") : ".";
  char gpath[1024];
  snprintf(gpath, sizeof gpath, "%s/gaits/flat_road.csv", src);
  const char* gait_path = argc > 1 ? argv[1] : gpath;
  double mu = argc > 2 ? atof(argv[2]) : 0.8, h = argc > 3 ? atof(argv[3]) : 5e-3;
  double t_end = argc > 4 ? atof(argv[4]) : 9.0;
  int order = argc > 5 ? atoi(argv[5]) : 2;
  int maxit = argc > 6 ? atoi(argv[6]) : 8;
  double tol = argc > 7 ? atof(argv[7]) : 1e-7;
  int step_order = argc > 8 ? atoi(argv[8]) : 1;
  csError err;
  cs_errorClear(&err);
  csgGait* g = csg_gaitRead(gait_path, NULL, &err);
  if (!g) {
    fprintf(stderr, "bench_strain_robot: %s\n", err.msg);
    return 1;
  }
  StrainRobot* r = calloc(1, sizeof *r);
  if (!r || strainRobotCreateOrder(r, mu, order, step_order, &err) != 0) {
    fprintf(stderr, "bench_strain_robot: %s\n", err.msg);
    return 1;
  }
  double x0[3], com0[3];
  memcpy(x0, r->x, sizeof x0);
  strainRobotCom(r, com0);
  double leg_s = 0, tree_s = 0, drift = 0, w0 = csu_wallSeconds(), c0 = cpuSeconds();
  int nstep = (int)(t_end / h + 0.5), status = 0;
  long passes = 0, steps = 0, rejected = 0;
  int ns = strainRobotStateSize(r);
  double* save = calloc((size_t)ns, sizeof(double));
  printf("gait %s, mu %.3g, h %.4g s, bend order %d, %d unknowns per leg, passes <= %d to %.3g, "
         "step order %d\n", gait_path, mu, h, order, csr_strainDofs(r->m[0]), maxit, tol,
         step_order);
  for (int i = 0; i < nstep; i++) {
    /* [i h, (i + 1) h]: a rejected piece is restored and halved */
    int fail = strainRobotAdvance(r, g, i * h, (i + 1) * h, maxit, tol, 6, save, &steps,
                                  &rejected, &passes, &leg_s, &tree_s);
    if (fail) {
      printf("step %d (t = %.4f s) failed after 6 halvings\n", i, (i + 1) * h);
      status = 1;
      break;
    }
    double com[3];
    strainRobotCom(r, com);
    drift = fmax(drift, hypot(com[0] - com0[0], com[2] - com0[2]));
    double tt = (i + 1) * h;
    if (getenv("STRAIN_TRACE") && i % 5 == 0) {
      double f[3], mo[3], N = 0;
      for (int k = 0; k < CSR_NLEG; k++) {
        cscSoftReport rep;
        csr_strainContactWrench(r->m[k], r->d[k], f, mo, &rep);
        N += f[1];
      }
      printf("  t %.3f y %+.5f vy %+.4f wx %+.4f wz %+.4f legs' N %.4f N (weight %.4f)\n", tt,
             r->x[1] - x0[1], r->V[4], r->V[0], r->V[2], N, r->ms * 9810);
    }
    if (fabs(tt - round(tt)) < 0.5 * h) {
      printf("t %.0f s: support x %+9.4f y %+8.4f z %+8.4f mm; horizontal centre-of-mass "
             "excursion so far %.4g mm\n", tt, r->x[0] - x0[0], r->x[1] - x0[1], r->x[2] - x0[2],
             drift);
    }
  }
  double wall = csu_wallSeconds() - w0, cpu = cpuSeconds() - c0;
  printf("wall %.3f s (CPU %.3f s) for %.3g s simulated: %.3fx real time (%.3fx on CPU time); "
         "legs %.3f s, support solve %.4f s (wall); %ld steps taken (%ld rejected and halved), "
         "%.2f passes per step\n", wall, cpu, t_end, t_end / wall, t_end / cpu, leg_s, tree_s,
         steps, rejected, steps ? (double)passes / steps : 0.0);
  /* STRAIN_DUMP=FILE: the robot's whole final state as raw doubles (to compare two builds) */
  const char* dump = getenv("STRAIN_DUMP");
  FILE* fd = dump ? fopen(dump, "wb") : NULL;
  if (fd) {
    strainRobotSave(r, save);
    fwrite(save, sizeof(double), (size_t)ns, fd);
    fclose(fd);
  }
  free(save);
  strainRobotDestroy(r);
  free(r);
  csg_gaitDestroy(g);
  return status;
}

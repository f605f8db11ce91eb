/* bench_strain_robot.c: the flat road on eight strain legs stepped as one tree without ODE
 * (strain_test_robot.h; issue 32; built, not registered). Prints the support's displacement at
 * whole seconds, the horizontal excursion of the centre of mass, and the wall time split into
 * the legs (condense, back-substitute, contact) and the support's solve.
 *
 * Usage: bench_strain_robot [GAIT.csv] [MU] [H_S] [T_END_S] [BEND_ORDER]
 * (defaults: gaits/flat_road.csv under CS_SOURCE_DIR, 0.8, 5e-3, 9, 2; conditions `paper`,
 * the shipped calibration robot/calibration_fe_leg.h5). */
#include <stdio.h>

#include "core_clock.h"
#include "strain_test_robot.h"

int main(int argc, char** argv) {
  const char* src = getenv("CS_SOURCE_DIR") ? getenv("CS_SOURCE_DIR") : ".";
  char gpath[1024];
  snprintf(gpath, sizeof gpath, "%s/gaits/flat_road.csv", src);
  const char* gait_path = argc > 1 ? argv[1] : gpath;
  double mu = argc > 2 ? atof(argv[2]) : 0.8, h = argc > 3 ? atof(argv[3]) : 5e-3;
  double t_end = argc > 4 ? atof(argv[4]) : 9.0;
  int order = argc > 5 ? atoi(argv[5]) : 2;
  csError err;
  cs_errorClear(&err);
  csgGait* g = csg_gaitRead(gait_path, NULL, &err);
  if (!g) {
    fprintf(stderr, "bench_strain_robot: %s\n", err.msg);
    return 1;
  }
  StrainRobot* r = calloc(1, sizeof *r);
  if (!r || strainRobotCreate(r, mu, order, &err) != 0) {
    fprintf(stderr, "bench_strain_robot: %s\n", err.msg);
    return 1;
  }
  double x0[3], com0[3];
  memcpy(x0, r->x, sizeof x0);
  strainRobotCom(r, com0);
  double leg_s = 0, tree_s = 0, drift = 0, w0 = csu_wallSeconds();
  int nstep = (int)(t_end / h + 0.5), status = 0;
  printf("gait %s, mu %.3g, h %.4g s, bend order %d, %d unknowns per leg\n", gait_path, mu, h,
         order, csr_strainDofs(r->m[0]));
  for (int i = 0; i < nstep; i++) {
    double p96[96];
    csg_scheduleEval(g, NULL, (i + 1) * h, p96);
    if (strainRobotStep(r, h, p96, &leg_s, &tree_s) != 0) {
      printf("step %d (t = %.4f s) failed\n", i, (i + 1) * h);
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
  double wall = csu_wallSeconds() - w0;
  printf("wall %.3f s for %.3g s simulated: %.3fx real time; legs %.3f s, support solve %.4f s\n",
         wall, t_end, t_end / wall, leg_s, tree_s);
  strainRobotDestroy(r);
  free(r);
  csg_gaitDestroy(g);
  return status;
}

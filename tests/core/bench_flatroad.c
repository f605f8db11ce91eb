/* bench_flatroad.c: cost of the flat-road scene through the driver (not a test: prints numbers).
 *
 *   bench_flatroad [level|sweep] [links] [dt_s] [t_end_s] [gait.csv|-] [coupling] [macro_steps]
 *                  [carry] [tol_scale] [mu]
 *
 * level: rod (default) or strain: one run of the scene (default gait, `paper` conditions, the
 * level's default coupling: stabilised for rod, one ODE step per macro step) to t_end (9 s),
 * written to a scratch HDF5 file through cs_run, as `crawlsim run` does. Prints the real-time
 * factor on one core from the process CPU time (insensitive to other jobs sharing the machine)
 * and from wall time, the stage split (legs, support, contact, output, ...), the legs' cost per
 * leg and per macro step, and the support displacement at the end.
 * sweep: rod at 2, 3, 4, 6 and 8 elements per segment, each to t_end: how the cost
 * grows with the rod's elements; the legs stage is the sum of eight independent leg advances,
 * so its cost is linear in the number of legs (printed per leg).
 * coupling: staggered, stabilised or gs (default: the level's), macro_steps ODE steps per
 * exchange (1), carry 0/1 (Gauss-Seidel's impulse carry, csOptions.coupling_carry). The run's
 * file is written to, and kept at, $CS_BENCH_KEEP when it is set (for the track).
 * The data files come from $CS_SOURCE_DIR (default ../../..). */
#include <hdf5.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "robot_rod.h"
#include "sim_model.h"

static double cpu(void) { return (double)clock() / CLOCKS_PER_SEC; }


/* ODE's informational messages are noise here */
static void quiet(int num, const char* msg, va_list ap) {
  (void)num;
  (void)msg;
  (void)ap;
}


/* the bench's coupling settings (arguments 6-8) */
typedef struct BenchCoupling_ {
  const char* name; /* NULL: the level's default */
  int macro_steps;
  int carry;
  double tol_scale; /* rod tolerances x this */
  double mu;        /* friction coefficient; NAN: the conditions' */
} BenchCoupling;


/* the support's x (mm) at every whole second (from 1 s) of the run's file: one line */
static void printTrack(const char* file) {
  hid_t f = H5Fopen(file, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) {
    return;
  }
  hid_t dt = H5Dopen2(f, "/time", H5P_DEFAULT), dp = H5Dopen2(f, "/support/position", H5P_DEFAULT);
  if (dt >= 0 && dp >= 0) {
    hid_t sp = H5Dget_space(dt);
    size_t n = (size_t)H5Sget_simple_extent_npoints(sp);
    H5Sclose(sp);
    double* t = malloc(n * sizeof *t);
    double* p = malloc(3 * n * sizeof *p);
    if (t && p && H5Dread(dt, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, t) >= 0 &&
        H5Dread(dp, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, p) >= 0) {
      printf("  x at whole seconds (mm):");
      for (size_t i = 0; i < n; i++) {
        double r = t[i] - round(t[i]);
        if (t[i] > 0.5 && fabs(r) < 1e-9) {
          printf(" %.2f", p[3 * i] - p[0]);
        }
      }
      printf("\n");
    }
    free(t);
    free(p);
  }
  if (dt >= 0) H5Dclose(dt);
  if (dp >= 0) H5Dclose(dp);
  H5Fclose(f);
}


static int bench(const char* src, const char* level, int links, double dt, double t_end,
                 const char* gait_arg, const BenchCoupling* bc) {
  char terr[600], gait[600], cal[600];
  snprintf(terr, sizeof terr, "%s/terrains/flat_road.terrain", src);
  snprintf(gait, sizeof gait, "%s", gait_arg ? gait_arg : "");
  if (!gait_arg) {
    snprintf(gait, sizeof gait, "%s/gaits/flat_road.csv", src);
  }
  snprintf(cal, sizeof cal, "%s/robot/calibration_fe_leg.h5", src);
  csModel m;
  cs_modelInit(&m);
  csError err;
  cs_errorClear(&err);
  if (cs_modelLoad(&m, "flat-road", terr, gait, cal, &err) != CS_OK) {
    fprintf(stderr, "bench_flatroad: %s\n", err.msg);
    cs_modelDestroy(&m);
    return 1;
  }
  const csrLegType* type = csr_legTypeFind(level, NULL);
  if (!type) {
    fprintf(stderr, "bench_flatroad: unknown level '%s'\n", level);
    cs_modelDestroy(&m);
    return 1;
  }
  cs_modelSetConditions(&m, CS_CONDITIONS_PAPER);
  cs_modelSetLegLevel(&m, type);
  /* the level's own settings by name: links for every level, the tolerance scale where the
   * level has one (rod) */
  csError serr;
  cs_errorClear(&serr);
  if (csr_legSettingSet(type, &m.robot.leg_settings, "links", links, &serr) != CS_OK ||
      (csr_legSettingFind(type, "rod_tol") &&
       csr_legSettingSet(type, &m.robot.leg_settings, "rod_tol", bc->tol_scale, &serr) != CS_OK)) {
    fprintf(stderr, "bench_flatroad: %s\n", serr.msg);
    cs_modelDestroy(&m);
    return 1;
  }
  if (!isnan(bc->mu)) {
    m.contact.mu = bc->mu;
  }
  m.opt.h = dt;
  m.opt.t_end = t_end;
  if (bc->name) {
    m.opt.coupling = !strcmp(bc->name, "gs")           ? CS_COUPLING_GAUSS_SEIDEL
                     : !strcmp(bc->name, "stabilised") ? CS_COUPLING_STABILISED
                                                       : CS_COUPLING_STAGGERED;
  }
  m.opt.macro_steps = bc->macro_steps;
  m.opt.coupling_carry = bc->carry;
  m.opt.output_dt = fmax(m.opt.output_dt, cs_modelMacroStep(&m));
  csData* d = cs_dataCreate(&m, &err);
  if (!d || cs_settle(&m, d, &err) != CS_OK) {
    fprintf(stderr, "bench_flatroad: %s\n", err.msg);
    cs_dataDestroy(d);
    cs_modelDestroy(&m);
    return 1;
  }
  char out[256];
  const char* keep = getenv("CS_BENCH_KEEP");
  snprintf(out, sizeof out, "%s", keep ? keep : "");
  if (!keep) {
    snprintf(out, sizeof out, "bench_flatroad_%s.h5", level);
  }
  double c0 = cpu(), wall = 0;
  csStatus st = cs_runWrite(&m, d, out, &wall, &err);
  double c = cpu() - c0;
  double x[3];
  cs_supportDisplacement(d, x);
  const csuTimer* tm = cs_timers(d);
  double steps = t_end / cs_modelMacroStep(&m);
  printf("%s, %d per segment, h = %g ms, H = %g ms, coupling %d (carry %d), %g s%s: CPU %.2f s "
         "-> real-time factor %.3f (wall %.2f s: %.3f); x(end) = %.2f mm\n", level, links,
         dt * 1e3, cs_modelMacroStep(&m) * 1e3, (int)m.opt.coupling, m.opt.coupling_carry, t_end,
         st == CS_OK ? "" : " (stopped)", c, t_end / c, wall, t_end / wall, x[0]);
  printf("  split (wall s):");
  for (int i = 0; i < CS_NTIMER; i++) {
    printf(" %s %.3f", cs_timerName((csTimerId)i), tm[i].wall);
  }
  /* the CPU time shared out by the stages' wall-time fractions */
  double legs_share = tm[CS_TIMER_STEP].wall > 0 ? tm[CS_TIMER_LEGS].wall / tm[CS_TIMER_STEP].wall
                                                  : 0;
  printf("\n  legs %.0f %% of the step: %.1f us of CPU per leg and macro step (%d legs, %.0f "
         "macro steps)\n", 100 * legs_share, 1e6 * c * legs_share / (CSR_NLEG * steps),
         CSR_NLEG, steps);
  if (!strcmp(type->name, "rod")) {
    /* CVODE's work per leg and macro step, summed over the legs (the rod's own counters) */
    csrRodStats sum, s;
    memset(&sum, 0, sizeof sum);
    for (int k = 0; k < CSR_NLEG; k++) {
      csr_rodLegStats(cs_leg(d, k), &s);
      sum.steps += s.steps;
      sum.rhs_evals += s.rhs_evals;
      sum.jac_evals += s.jac_evals;
      sum.lin_setups += s.lin_setups;
      sum.newton_iters += s.newton_iters;
      sum.err_fails += s.err_fails;
      sum.conv_fails += s.conv_fails;
      sum.reinits += s.reinits;
      sum.advances += s.advances;
    }
    double a = sum.advances > 0 ? (double)sum.advances : 1;
    printf("  per leg advance: %.2f CVODE steps, %.2f right-hand sides (Jacobians' included), "
           "%.3f Jacobians, %.2f setups, %.2f Newton iterations, %.3f error / %.3f convergence "
           "failures, %.4f restarts\n", sum.steps / a, sum.rhs_evals / a, sum.jac_evals / a,
           sum.lin_setups / a, sum.newton_iters / a, sum.err_fails / a, sum.conv_fails / a,
           sum.reinits / a);
  }
  if (st != CS_OK) {
    printf("  stopped: %s\n", err.msg);
  }
  printTrack(out);
  /* every digit, for checking that a change keeps the same bits */
  printf("  x(end) = %.17g mm\n", x[0]);
  if (!keep) {
    remove(out);
  }
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  return 0;
}


int main(int argc, char** argv) {
  const char* src = getenv("CS_SOURCE_DIR");
  if (!src) {
    src = "../../..";
  }
  const char* what = argc > 1 ? argv[1] : "rod";
  int links = argc > 2 ? atoi(argv[2]) : 4;
  double dt = argc > 3 ? atof(argv[3]) : 1e-3;
  double t_end = argc > 4 ? atof(argv[4]) : 9.0;
  const char* gait = argc > 5 && strcmp(argv[5], "-") ? argv[5] : NULL;
  BenchCoupling bc = {argc > 6 && strcmp(argv[6], "-") ? argv[6] : NULL,
                      argc > 7 ? atoi(argv[7]) : 1, argc > 8 ? atoi(argv[8]) : 1,
                      argc > 9 ? atof(argv[9]) : 1, argc > 10 ? atof(argv[10]) : NAN};
  dInitODE2(0);
  dSetMessageHandler(quiet);
  int rc = 0;
  if (!strcmp(what, "sweep")) {
    const int n[] = {2, 3, 4, 6, 8};
    for (int i = 0; i < 5 && rc == 0; i++) {
      rc = bench(src, "rod", n[i], dt, t_end, gait, &bc);
    }
  } else {
    rc = bench(src, what, links, dt, t_end, gait, &bc);
  }
  dCloseODE();
  return rc;
}

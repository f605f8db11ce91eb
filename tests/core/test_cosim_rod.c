/* test_cosim_rod.c: the coupling of the support with eight Cosserat-rod legs (csr_leg_rod) on
 * the flat road, against a tightly coupled reference (issue 9, "Coupling"):
 *  - the reference: staggered coupling at a tiny macro step, H = h = 25 µs, where it is
 *    converged (20 µs moves x(1 s) by 0.02 mm);
 *  - the staggered scheme fails beyond its explicit limit: at H = 40 µs the run diverges while
 *    settling, 35 µs runs (the rod's hip element is a stiff Kelvin-Voigt damper, 0.26 N s/mm
 *    per leg, on a 50 g support: 8 c H / M < 2 needs H < 48 µs);
 *  - the stabilised scheme (the legs' condensed gains solved implicitly with the support,
 *    core/sim_coupling.c) runs at 10x that macro step and at 2 ms, and at 10x stays within
 *    1 mm of the reference;
 *  - the Gauss-Seidel scheme (the default: the support first, then the legs along its actual
 *    motion) at H = h = 1 ms, 25x the staggered limit, follows the reference on the shipped
 *    gait within 1 mm over the first 2 s, where the stabilised scheme at 1 ms is 6 mm behind.
 * Scene of the first case: the paper's table (gaits/flat_road_paper.csv) under `paper`
 * conditions, 0.3 s of settling and the first 0.5 s of the gait (ACFH lift and swing, BDEG
 * stand: the support is pulled back); compared: the support's displacement at t = 0.5 s
 * (reference: x = -7.95, y = 0.08, z = 0.75 mm). The second: the shipped gait
 * (gaits/flat_road.csv), 2 s, the displacement then (reference x = 41.01 mm). Labelled slow
 * (the references take 32 k and 92 k steps: ~20 s and ~40 s; 93 s for the first under the
 * sanitizers). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "sim_model.h"

static char g_src[512];
static const double kTEnd = 0.5; /* s of gait after settling */
/* s of the shipped gait in the second case (its first stride and the start of the second:
 * where the stabilised scheme falls behind) */
static const double kTEndShipped = 2.0;


/* run the flat road on rod legs with a gait of gaits/ (file name), ODE step h = H (one ODE
 * step per macro step) and the given coupling to t_end; the support displacement then (NAN if
 * the run failed) and its status */
static csStatus runRodGait(const char* gait_file, double t_end, double h, csCoupling coupling,
                           double x[3]) {
  char terr[600], gait[600], cal[600];
  snprintf(terr, sizeof terr, "%s/terrains/flat_road.terrain", g_src);
  snprintf(gait, sizeof gait, "%s/gaits/%s", g_src, gait_file);
  snprintf(cal, sizeof cal, "%s/robot/calibration_fe_leg.h5", g_src);
  x[0] = x[1] = x[2] = NAN;
  csModel m;
  cs_modelInit(&m);
  csError err;
  cs_errorClear(&err);
  csStatus st = cs_modelLoad(&m, "flat-road", terr, gait, cal, &err);
  if (st != CS_OK) {
    fprintf(stderr, "  load: %s\n", err.msg);
    cs_modelDestroy(&m);
    return st;
  }
  cs_modelSetConditions(&m, CS_CONDITIONS_PAPER);
  cs_modelSetLegLevel(&m, csr_legTypeFind("rod", NULL));
  m.opt.coupling = coupling;
  m.opt.h = h;
  m.opt.macro_steps = 1;
  m.opt.output_dt = h;
  csData* d = cs_dataCreate(&m, &err);
  st = d ? cs_settle(&m, d, &err) : err.status;
  long n = lround(t_end / h);
  for (long i = 0; i < n && st == CS_OK; i++) {
    st = cs_step(&m, d, &err);
  }
  if (st == CS_OK) {
    cs_supportDisplacement(d, x);
  } else {
    printf("  h = %g s: %s\n", h, err.msg);
  }
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  return st;
}


/* the paper's table to kTEnd */
static csStatus runRod(double h, csCoupling coupling, double x[3]) {
  return runRodGait("flat_road_paper.csv", kTEnd, h, coupling, x);
}


/* distance of two support displacements (mm) */
static double dist3(const double a[3], const double b[3]) {
  return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
              (a[2] - b[2]) * (a[2] - b[2]));
}


static void staggered_fails_where_stabilised_holds_the_reference(void) {
  double ref[3], x[3];
  CS_EXPECT(runRod(25e-6, CS_COUPLING_STAGGERED, ref) == CS_OK);
  printf("  reference (staggered, 25 us): x = %.3f y = %.3f z = %.3f mm\n", ref[0], ref[1],
         ref[2]);
  /* the explicit limit: 40 us diverges while settling (35 us runs) */
  CS_EXPECT(runRod(40e-6, CS_COUPLING_STAGGERED, x) == CS_ERR_DIVERGED);
  /* stabilised at 10 x 25 us and at 2 ms: stable, and at 10x within 1 mm (the bound;
   * measured 0.34 mm at 250 us, 0.67 mm at 2 ms; before the legs' base force was their
   * momentum balance 0.68 and 0.92 mm: the error grows with the gait, README "Rod legs") */
  CS_EXPECT(runRod(250e-6, CS_COUPLING_STABILISED, x) == CS_OK);
  double e = sqrt((x[0] - ref[0]) * (x[0] - ref[0]) + (x[1] - ref[1]) * (x[1] - ref[1]) +
                  (x[2] - ref[2]) * (x[2] - ref[2]));
  printf("  stabilised, 250 us: x = %.3f y = %.3f z = %.3f mm, %.3f mm from the reference\n",
         x[0], x[1], x[2], e);
  CS_EXPECT(e < 1.0);
  CS_EXPECT(runRod(2e-3, CS_COUPLING_STABILISED, x) == CS_OK);
  printf("  stabilised, 2 ms: x = %.3f y = %.3f z = %.3f mm\n", x[0], x[1], x[2]);
  /* stable and on the reference's track (measured 0.13 mm in x; 0.5 mm before) */
  CS_EXPECT(isfinite(x[0]) && fabs(x[0] - ref[0]) < 5);
}


static void gauss_seidel_holds_the_reference_at_1ms(void) {
  double ref[3], gs[3], st[3];
  CS_EXPECT(runRodGait("flat_road.csv", kTEndShipped, 25e-6, CS_COUPLING_STAGGERED, ref) ==
            CS_OK);
  CS_EXPECT(runRodGait("flat_road.csv", kTEndShipped, 1e-3, CS_COUPLING_GAUSS_SEIDEL, gs) ==
            CS_OK);
  CS_EXPECT(runRodGait("flat_road.csv", kTEndShipped, 1e-3, CS_COUPLING_STABILISED, st) ==
            CS_OK);
  double egs = dist3(gs, ref), est = dist3(st, ref);
  printf("  shipped gait, t = %g s: reference (staggered, 25 us) x = %.3f y = %.3f z = %.3f; "
         "Gauss-Seidel 1 ms x = %.3f (%.3f mm off); stabilised 1 ms x = %.3f (%.3f mm off)\n",
         kTEndShipped, ref[0], ref[1], ref[2], gs[0], egs, st[0], est);
  /* the 1 mm; measured 0.18 mm in x (Gauss-Seidel) and 6.2 mm (stabilised); the
   * reference is converged to 0.01 mm (staggered 20 against 25 us; gs at 25 us lands on it),
   * and a change of round-off alone moved the Gauss-Seidel run by 0.12 mm here (the same
   * scheme, its carry summed in another order); the stabilised scheme at least 3x further */
  CS_EXPECT(egs < 1.0);
  CS_EXPECT(est > 3 * egs);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(g_src, sizeof g_src, "%s", src ? src : "../../..");
  dInitODE2(0);
  CS_RUN(staggered_fails_where_stabilised_holds_the_reference);
  CS_RUN(gauss_seidel_holds_the_reference_at_1ms);
  dCloseODE();
  return cs_testSummary();
}

/* test_run.c: end-to-end physics sanity of the flat-road co-simulation with the library's
 * default legs (rod, 4 elements per segment, Gauss-Seidel) on the mission's table (sim_scene.h
 * CS_MISSION_*), the flat-road scene's own gait (designed on that table).
 *
 * The robot of the paper, with its Elastosil legs, stands at 80 % of its sway-buckling load on
 * four legs under Earth gravity and folds when it loads bent legs (docs/studies/earth_gait.md).
 * These tests check the mechanism of friction-driven crawling, so they run at 1 m/s^2, where
 * the stance load is 8 % of the buckling load and the legs keep their shapes; one test runs
 * at 9.81 m/s^2 to check that the collapse ends the run with a clear error and a readable
 * file. Runs are 1.5-6 s of the 9 s gait; labelled slow (the sanitizer pass skips it; the
 * driver runs under ASan in tests/tools/test_run_cli.c). */
#include <hdf5.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "sim_model.h"

static char g_src[512];


static void path(char* buf, size_t n, const char* rel) { snprintf(buf, n, "%s/%s", g_src, rel); }


/* model of the shipped flat-road scene at gravity g (m/s^2) with gait `gait_rel` (NULL: the
 * scene's own) */
static int loadModelGait(csModel* m, double g, const char* gait_rel) {
  char terr[600], gait[600], cal[600];
  path(terr, sizeof terr, "terrains/flat_road.terrain");
  /* the scene's own gait, designed on the mission's table (sim_scene.h) */
  const csScene* sc = cs_sceneFind("flat-road");
  path(gait, sizeof gait, gait_rel ? gait_rel : sc ? sc->gait : "gaits/flat_road_rod.csv");
  path(cal, sizeof cal, CS_MISSION_CALIBRATION);
  cs_modelInit(m);
  csrCalRule rule;
  if (csr_calRuleParse(CS_MISSION_CAL_RULE, &rule)) {
    m->cal_rule = (int)rule;
  }
  m->opt.gravity = g * 1e3;
  csError err;
  cs_errorClear(&err);
  csStatus st = cs_modelLoad(m, "flat-road", terr, gait, cal, &err);
  if (st != CS_OK) {
    fprintf(stderr, "load: %s\n", err.msg);
  }
  return st == CS_OK;
}


static int loadModel(csModel* m, double g) { return loadModelGait(m, g, NULL); }


/* centre of mass at t = 0 and at the end of the last runTo (world, mm) */
static double g_com0[3], g_com1[3];


/* run to t_end writing `out`; returns the status; x_end gets the final displacement */
static csStatus runTo(csModel* m, double t_end, const char* out, double x_end[3], char* msg) {
  csError err;
  cs_errorClear(&err);
  m->opt.t_end = t_end;
  csData* d = cs_dataCreate(m, &err);
  if (!d) {
    snprintf(msg, CS_ERROR_MSG_SIZE, "%s", err.msg);
    return err.status;
  }
  csStatus st = cs_settle(m, d, &err);
  cs_robotCenterOfMass(m, d, g_com0);
  if (st == CS_OK) {
    st = cs_runWrite(m, d, out, NULL, &err);
  }
  cs_supportDisplacement(d, x_end);
  cs_robotCenterOfMass(m, d, g_com1);
  snprintf(msg, CS_ERROR_MSG_SIZE, "%s", err.msg);
  cs_dataDestroy(d);
  return st;
}


/* read a whole double dataset; returns the element count (caller frees *out) */
static size_t readDataset(const char* file, const char* name, double** out) {
  hid_t f = H5Fopen(file, H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return 0;
  hid_t ds = H5Dopen2(f, name, H5P_DEFAULT);
  if (ds < 0) {
    H5Fclose(f);
    return 0;
  }
  hid_t sp = H5Dget_space(ds);
  hssize_t n = H5Sget_simple_extent_npoints(sp);
  *out = malloc((size_t)n * sizeof(double));
  H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, *out);
  H5Sclose(sp);
  H5Dclose(ds);
  H5Fclose(f);
  return (size_t)n;
}


/* two runs of the same model give bit-identical output (fixed step, fixed solver iterations,
 * one thread, same geom order: ODE and CVODE are deterministic) */
static void test_run_is_deterministic(void) {
  csModel m;
  CS_EXPECT(loadModel(&m, 1.0));
  double xa[3], xb[3];
  char msg[CS_ERROR_MSG_SIZE];
  CS_EXPECT(runTo(&m, 1.5, "det_a.h5", xa, msg) == CS_OK);
  CS_EXPECT(runTo(&m, 1.5, "det_b.h5", xb, msg) == CS_OK);
  double *a = NULL, *b = NULL;
  size_t na = readDataset("det_a.h5", "/legs/C/centerline", &a);
  size_t nb = readDataset("det_b.h5", "/legs/C/centerline", &b);
  CS_EXPECT(na > 0 && na == nb);
  CS_EXPECT(na > 0 && na == nb && memcmp(a, b, na * sizeof(double)) == 0);
  CS_EXPECT(memcmp(xa, xb, sizeof xa) == 0);
  free(a);
  free(b);
  cs_modelDestroy(&m);
}


/* sampling is read-only: samples at 100 Hz and 20 Hz agree exactly at common times */
static void test_run_output_rate_does_not_change_result(void) {
  csModel m;
  CS_EXPECT(loadModel(&m, 1.0));
  double x[3];
  char msg[CS_ERROR_MSG_SIZE];
  m.opt.output_dt = 0.01;
  CS_EXPECT(runTo(&m, 1.5, "rate_100.h5", x, msg) == CS_OK);
  m.opt.output_dt = 0.05;
  CS_EXPECT(runTo(&m, 1.5, "rate_20.h5", x, msg) == CS_OK);
  double *a = NULL, *b = NULL;
  size_t na = readDataset("rate_100.h5", "/support/position", &a);
  size_t nb = readDataset("rate_20.h5", "/support/position", &b);
  CS_EXPECT(na == 3 * 151 && nb == 3 * 31);
  for (size_t i = 0; nb == 3 * 31 && na == 3 * 151 && i < 31; i++) {
    for (int k = 0; k < 3; k++) {
      CS_EXPECT(a[3 * (5 * i) + k] == b[3 * i + k]);
    }
  }
  free(a);
  free(b);
  cs_modelDestroy(&m);
}


/* displacement at 3 s and 6 s of the shipped gait at full and half pressure (one run each,
 * shared by the tests below) */
static double g_x3[2], g_x6[2];
static int g_have_strides;


static void stridesOnce(void) {
  if (g_have_strides) {
    return;
  }
  g_have_strides = 1;
  for (int k = 0; k < 2; k++) {
    csModel m;
    CS_EXPECT(loadModel(&m, 1.0));
    m.sched.pressure_scale = k == 0 ? 1.0 : 0.5;
    double x[3];
    char msg[CS_ERROR_MSG_SIZE];
    const char* out = k == 0 ? "p1_6.h5" : "p05_6.h5";
    CS_EXPECT(runTo(&m, 6.0, out, x, msg) == CS_OK);
    g_x6[k] = x[0];
    /* x at t = 3 s from the file: sample 300 at the default 100 Hz */
    double* pos = NULL;
    size_t n = readDataset(out, "/support/position", &pos);
    CS_EXPECT(n == 3 * 601);
    g_x3[k] = n == 3 * 601 ? pos[3 * 300] : NAN;
    free(pos);
    cs_modelDestroy(&m);
  }
  printf("  x(3 s), x(6 s): full pressure %.2f, %.2f mm; half %.2f, %.2f mm\n", g_x3[0],
         g_x6[0], g_x3[1], g_x6[1]);
}


/* the stroke S (mm) of the scene's searched design: the first number of the `# params:` line
 * of gaits/flat_road_rod.gait (the description its table was made from); NAN if not found */
static double strokeOfDesign(void) {
  char p[600], line[512];
  path(p, sizeof p, "gaits/flat_road_rod.gait");
  FILE* f = fopen(p, "r");
  double S = NAN;
  while (f && fgets(line, sizeof line, f)) {
    if (sscanf(line, "# params: %lf", &S) == 1) break;
  }
  if (f) fclose(f);
  return S;
}


/* the support moves only through leg-ground friction: with friction the strides carry it
 * forward; without friction no horizontal force acts on the robot, so its centre of mass
 * stays put whatever the legs do (the support itself may swing against the legs) */
static void test_run_advances_only_with_friction(void) {
  stridesOnce();
  /* three strides (3..6 s): the design moves the stance feet S mm back per second (the first
   * of the `# params:` line of gaits/flat_road_rod.gait, tools/gait_search.py); half of the
   * three strides' 3 S is the floor */
  double S = strokeOfDesign();
  CS_EXPECT(S > 0);
  CS_EXPECT(g_x6[0] - g_x3[0] > 0.5 * 3 * S);
  csModel m;
  CS_EXPECT(loadModel(&m, 1.0));
  m.contact.mu = 0;
  double x[3];
  char msg[CS_ERROR_MSG_SIZE];
  CS_EXPECT(runTo(&m, 4.0, "nofric.h5", x, msg) == CS_OK);
  /* 0.5 mm: contact normals on the flat road are vertical, so only the settling's residual
   * velocity (< 0.1 mm/s after 0.3 s) and the solver's constraint drift move the centre */
  CS_EXPECT_NEAR(g_com1[0], g_com0[0], 0.5, 0);
  CS_EXPECT_NEAR(g_com1[2], g_com0[2], 0.5, 0);
  printf("  without friction: centre of mass moved %.4f mm (x), support %.2f mm\n",
         g_com1[0] - g_com0[0], x[0]);
  cs_modelDestroy(&m);
}


/* halving the pressures shortens the stride (the S-shape bends less); measured over the three
 * strides 3..6 s, after the start-up stride */
static void test_run_half_pressure_shortens_stride(void) {
  stridesOnce();
  double full = g_x6[0] - g_x3[0], half = g_x6[1] - g_x3[1];
  /* the half-size poses no longer lift the swinging feet clear, so the groups' pushes cancel
   * (docs/notes/flat_road.md); "shorter" is the physical claim */
  CS_EXPECT(half < 0.5 * full);
}


/* at Earth gravity the paper's table (four S-bent stance legs) folds its legs and the robot
 * leaves the road (docs/studies/earth_gait.md; the scene's own gait folds too but stays on the
 * road): the run stops with an error naming the time and the cause, and the file holds every
 * sample up to it */
static void test_run_collapse_is_reported_and_file_stays_readable(void) {
  csModel m;
  CS_EXPECT(loadModelGait(&m, 9.81, "gaits/flat_road_paper.csv"));
  double x[3];
  char msg[CS_ERROR_MSG_SIZE] = "";
  csStatus st = runTo(&m, 9.0, "collapse.h5", x, msg);
  CS_EXPECT(st == CS_ERR_DIVERGED);
  CS_EXPECT(strstr(msg, "t = ") != NULL);
  printf("  %s\n", msg);
  double* t = NULL;
  size_t n = readDataset("collapse.h5", "/time", &t);
  CS_EXPECT(n > 10);
  double t_stop = n > 0 ? t[n - 1] : 0;
  CS_EXPECT(t_stop > 0 && t_stop < 9.0);
  free(t);
  cs_modelDestroy(&m);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(g_src, sizeof g_src, "%s", src ? src : ".");
  dInitODE2(0);
  CS_RUN(test_run_is_deterministic);
  CS_RUN(test_run_output_rate_does_not_change_result);
  CS_RUN(test_run_advances_only_with_friction);
  CS_RUN(test_run_half_pressure_shortens_stride);
  CS_RUN(test_run_collapse_is_reported_and_file_stays_readable);
  dCloseODE();
  return cs_testSummary();
}

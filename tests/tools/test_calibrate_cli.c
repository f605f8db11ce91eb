/* test_calibrate_cli.c: `crawlsim calibrate` end to end on a small actuator (argv[1] is the
 * executable): the FE sweep runs, the table it writes opens as the legs' calibration and its
 * readback equals the FE angles on the rows; `crawlsim run` with that table refuses a gait whose
 * pressures lie above the table (naming time, chamber and range) instead of extrapolating; bad
 * options exit 1 with one line. The actuator is the `leg` shortened to 15 mm segments (9 fibre
 * turns, c = 3 mm) at l_soft 5 mm, two load steps: ~20 s. Needs POSIX for tests/cs_cli.h. */
#define _POSIX_C_SOURCE 200809L

#include <hdf5.h>
#include <hdf5_hl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cli.h"
#include "cs_test.h"
#include "robot_calibration.h"

static const char* exe_path = NULL;

#define SMALL_SETS                                                                           \
  "--set S1=15 --set S2=15 --set S3=15 --set n1=9 --set n2=9 --set n3=9 --set c=3 "          \
  "--mesh-size 5 --p-max 0.1 --p-step 0.05"


static void test_calibrate_writes_a_usable_table(void) {
  remove("calib_small.h5");
  csCliResult r;
  cs_cliRun(exe_path, "calibrate --out calib_small.h5 " SMALL_SETS, "calibrate", &r);
  CS_EXPECT(r.status == 0);
  CS_EXPECT(strstr(r.out, "fe calibration table (chambers 1,2, 0..0.1 MPa, 3 rows") != NULL);
  /* the table opens for the same actuator, and the map reproduces the FE rows */
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "leg", &err) == CS_OK);
  const char* sets[] = {"S1=15", "S2=15", "S3=15", "n1=9", "n2=9", "n3=9", "c=3"};
  for (int k = 0; k < 7; k++) {
    CS_EXPECT(csr_actuatorSetString(&act, sets[k], &err) == CS_OK);
  }
  csrCalibration* cal = csr_calibrationOpen("calib_small.h5", &act, &err);
  CS_EXPECT(cal != NULL);
  hid_t f = H5Fopen("calib_small.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (cal && f >= 0) {
    double p[3], ang[9];
    CS_EXPECT(H5LTread_dataset_double(f, "/pressure", p) >= 0);
    CS_EXPECT(H5LTread_dataset_double(f, "/angle_deg", ang) >= 0);
    csrBendMap map = csr_calibrationMap(cal);
    for (int i = 1; i < 3; i++) {
      for (int s = 0; s < 3; s++) {
        double P[4] = {p[i], p[i], 0, 0}, b[2], stretch;
        CS_EXPECT(map.eval(map.ctx, s, P, b, &stretch) == 0);
        /* on a row the interpolation weight is 0 or 1: round-off only */
        CS_EXPECT_NEAR(hypot(b[0], b[1]) * 180 / 3.14159265358979323846, ang[3 * i + s], 1e-9,
                       1e-12);
        /* a pair-mode sweep bends forward, and the FE bends more than 0 */
        CS_EXPECT(ang[3 * i + s] > 0);
      }
    }
  }
  if (f >= 0) H5Fclose(f);
  /* the wrong actuator (the unmodified leg) is refused */
  csrActuator leg;
  CS_EXPECT(csr_actuatorPreset(&leg, "leg", &err) == CS_OK);
  csrCalibration* wrong = csr_calibrationOpen("calib_small.h5", &leg, &err);
  CS_EXPECT(wrong == NULL && strstr(err.msg, "calibrated for another actuator") != NULL);
  csr_calibrationClose(cal);

  /* the leg's table must cover the gait: an analytic sweep of the leg to 0.1 MPa is a valid
   * table (same layout), and the shipped gait ramps to 0.149 MPa in its first 0.2 s, so the
   * run stops there with time, chamber and range, and keeps what it wrote */
  cs_cliRun(exe_path, "bend --model analytic --actuator leg --chambers 1,2 --p-max 0.1 "
            "--p-step 0.05 --out calib_leg.h5", "calibrate", &r);
  CS_EXPECT(r.status == 0);
  cs_cliRun(exe_path, "run --t-end 0.5 --calibration calib_leg.h5 --out calib_run.h5 --quiet",
            "calibrate", &r);
  CS_EXPECT(r.status == 1 && strstr(r.err, "is above the calibrated range (up to 0.1 MPa)"));
  CS_EXPECT(strstr(r.err, "crawlsim run: t = 0.") != NULL);
  hid_t g = H5Fopen("calib_run.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(g >= 0);
  if (g >= 0) H5Fclose(g);
  /* the table for another actuator is refused by the run too */
  cs_cliRun(exe_path, "run --t-end 0.1 --calibration calib_small.h5 --out calib_run.h5 --quiet",
            "calibrate", &r);
  CS_EXPECT(r.status == 1 && strstr(r.err, "calibrated for another actuator") != NULL);
  remove("calib_leg.h5");
  remove("calib_run.h5");
  remove("calib_small.h5");
  remove("calib_small.vtu");
  remove("calib_small.inp");
}


static void expectFailure(const char* args, const char* want) {
  csCliResult r;
  char full[1024];
  snprintf(full, sizeof full, "calibrate %s", args);
  cs_cliRun(exe_path, full, "calibrate", &r);
  int one_line = r.err[0] && strchr(r.err, '\n') == r.err + strlen(r.err) - 1;
  int ok = r.status == 1 && one_line && strstr(r.err, want) != NULL;
  CS_EXPECT(ok);
  if (!ok) {
    fprintf(stderr, "  args '%s': status %d, stderr '%s', want '%s'\n", args, r.status, r.err,
            want);
  }
}


static void test_bad_options(void) {
  expectFailure("--bogus 1", "crawlsim calibrate: unknown option '--bogus'");
  expectFailure("--out", "crawlsim calibrate: --out needs a value");
  expectFailure("stray", "crawlsim calibrate: unexpected argument 'stray'");
  expectFailure("--p-max 2", "--p-max '2' must be a number > 0 and at most 1 MPa");
  expectFailure("--p-step x", "--p-step 'x' must be a number > 0");
  expectFailure("--mesh-size -1", "--mesh-size '-1' must be a number > 0");
  expectFailure("--p-max 0.1 --p-step 0.2", "--p-step 0.2 is larger than --p-max 0.1");
  expectFailure("--set S1=-3", "S1 = -3 must be > 0 mm");
  expectFailure("--set Q=3", "unknown actuator parameter 'Q'");
  expectFailure("--actuator moon", "moon");
}


int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_calibrate_cli PATH_TO_CRAWLSIM\n");
    return 2;
  }
  exe_path = argv[1];
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  CS_RUN(test_bad_options);
  CS_RUN(test_calibrate_writes_a_usable_table);
  return cs_testSummary();
}

/* cmd_calibrate.c: `crawlsim calibrate`: the FE calibration table of the legs.
 *   crawlsim calibrate [--out FILE.h5] [--actuator leg|baseline|fig1] [--set NAME=VALUE]...
 *                      [--mesh-size MM] [--p-max MPA] [--p-step MPA]
 * Runs the full FE model (`crawlsim bend --model fe`, fem/) on the pair mode Ω1&Ω2 of every
 * segment from 0 to p-max, writes the sweep in the bend layout (robot_bend_io.h), and opens
 * the result as a calibration (robot_calibration.h: csr_feCalibrationCreate) to check it and
 * print the FE / analytic bend ratios (range) and the segment bends the legs will use. `crawlsim run --calibration FILE.h5` and
 * `crawlsim gait flat-road --calibration FILE.h5` then use it. The pressure range must cover
 * the gaits that will use the table: the runs refuse pressures above its last row. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "cs_commands.h"
#include "robot_actuator.h"
#include "robot_calibration.h"

static const char kUsage[] =
    "usage: crawlsim calibrate [--out FILE.h5] [--actuator leg|baseline|fig1] "
    "[--set NAME=VALUE]... [--mesh-size MM] [--p-max MPA] [--p-step MPA]\n";

enum { MAX_SETS = 32 };


int csx_cmdCalibrate(int argc, char** argv) {
  const char* out = "calibration_fe.h5";
  const char* actname = "leg";
  const char* sets[MAX_SETS];
  int nset = 0;
  const char* num_flag[3] = {"--mesh-size", "--p-max", "--p-step"};
  const char* num_text[3] = {"4", "0.3", "0.025"};
  for (int i = 1; i < argc; i++) {
    const char* a = argv[i];
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      fputs(kUsage, stdout);
      return 0;
    }
    if (i + 1 >= argc || a[0] != '-') {
      fprintf(stderr, a[0] == '-' ? "crawlsim calibrate: %s needs a value\n"
                                  : "crawlsim calibrate: unexpected argument '%s'\n", a);
      return 1;
    }
    const char* v = argv[++i];
    int k = 0;
    while (k < 3 && strcmp(a, num_flag[k])) k++;
    if (k < 3) {
      char* end;
      double x = strtod(v, &end);
      if (end == v || *end || !isfinite(x) || x <= 0 || (k > 0 && x > 1.0)) {
        fprintf(stderr, "crawlsim calibrate: %s '%s' must be a number > 0%s\n", a, v,
                k > 0 ? " and at most 1 MPa" : "");
        return 1;
      }
      num_text[k] = v;
    } else if (!strcmp(a, "--out")) {
      out = v;
    } else if (!strcmp(a, "--actuator")) {
      actname = v;
    } else if (!strcmp(a, "--set")) {
      if (nset == MAX_SETS) {
        fprintf(stderr, "crawlsim calibrate: more than %d --set options\n", MAX_SETS);
        return 1;
      }
      sets[nset++] = v;
    } else {
      fprintf(stderr, "crawlsim calibrate: unknown option '%s'\n", a);
      return 1;
    }
  }
  /* check the actuator here, so that a bad --set is reported by this command */
  csError err;
  cs_errorClear(&err);
  csrActuator act;
  if (csr_actuatorPreset(&act, actname, &err) != CS_OK) {
    fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
    return 1;
  }
  for (int k = 0; k < nset; k++) {
    if (csr_actuatorSetString(&act, sets[k], &err) != CS_OK) {
      fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
      return 1;
    }
  }
  if (csr_actuatorValidate(&act, &err) != CS_OK) {
    fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
    return 1;
  }
  if (strtod(num_text[2], NULL) > strtod(num_text[1], NULL)) {
    fprintf(stderr, "crawlsim calibrate: --p-step %s is larger than --p-max %s\n", num_text[2],
            num_text[1]);
    return 1;
  }

  /* the FE sweep: `crawlsim bend --model fe --chambers 1,2 ...` */
  char* bargv[16 + 2 * MAX_SETS];
  int bargc = 0;
  bargv[bargc++] = "bend";
  bargv[bargc++] = "--model";
  bargv[bargc++] = "fe";
  bargv[bargc++] = "--actuator";
  bargv[bargc++] = (char*)actname;
  bargv[bargc++] = "--chambers";
  bargv[bargc++] = "1,2";
  for (int k = 0; k < 3; k++) {
    bargv[bargc++] = (char*)num_flag[k];
    bargv[bargc++] = (char*)num_text[k];
  }
  for (int k = 0; k < nset; k++) {
    bargv[bargc++] = "--set";
    bargv[bargc++] = (char*)sets[k];
  }
  bargv[bargc++] = "--out";
  bargv[bargc++] = (char*)out;
  bargv[bargc] = NULL;
  printf("crawlsim calibrate: FE sweep of the %s actuator, chambers 1,2, 0..%s MPa, l_soft %s "
         "mm -> %s\n", actname, num_text[1], num_text[0], out);
  fflush(stdout);
  int rc = csx_cmdBend(bargc, bargv);
  if (rc != 0) {
    fprintf(stderr, "crawlsim calibrate: the FE sweep failed (above); no table written\n");
    return rc;
  }
  /* read it back as the legs will */
  csrCalibration* cal = csr_calibrationOpen(out, &act, &err);
  if (!cal) {
    fprintf(stderr, "crawlsim calibrate: %s\n", err.msg);
    return 1;
  }
  csrBendMap map = csr_calibrationMap(cal);
  printf("crawlsim calibrate: %s\n", map.name);
  /* the legs' segment bends read back through the map at the sweep's pressures (they equal
   * the FE angles there: the ratio is interpolated between rows, exact on them) */
  printf("  p (MPa)   segment bend II1, II2, II3 (deg) as the legs will use it\n");
  double step = strtod(num_text[2], NULL);
  for (int i = 1; i * step <= map.p_max * (1 + 1e-12); i++) {
    double p = fmin(i * step, map.p_max);
    printf("  %7.4f", p);
    for (int s = 0; s < 3; s++) {
      double P[4] = {p, p, 0, 0}, b[2], stretch;
      if (map.eval(map.ctx, s, P, b, &stretch) != 0) {
        fprintf(stderr, "crawlsim calibrate: %s: the map fails at %g MPa\n", out, p);
        csr_calibrationClose(cal);
        return 1;
      }
      printf("  %8.3f", hypot(b[0], b[1]) / CS_DEG);
    }
    printf("\n");
  }
  printf("crawlsim calibrate: use it with `crawlsim run --calibration %s` and `crawlsim gait "
         "flat-road FILE.csv --calibration %s`\n", out, out);
  csr_calibrationClose(cal);
  return 0;
}

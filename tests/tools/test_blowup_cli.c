/* test_blowup_cli.c: runs made to fail stop cleanly (issue 11's stability map, end to end).
 * Each case runs the real `crawlsim run` past a stability limit found by tools/stability_map.py
 * and checks the contract: exit status 1, exactly one error line on stderr naming the time
 * ("t = ...") and the cause, and an output file that stays readable: its /time series ends
 * before the requested end, every sample it holds is finite, and its status attribute is the
 * same message. The limits themselves are not asserted (where a run fails is the map's
 * measurement); only that a failure, when it comes, is reported this way.
 *  - rod legs at h = H = 10 ms with the stabilised coupling (its limit is 2 ms): the support
 *    runs away after the settling ("simulation diverged: support speed ...");
 *  - rod legs with the staggered coupling at 1 ms (its limit is 35 µs), which diverges already
 *    while settling, before the first sample: the file holds the header, empty series, the
 *    status and failed_at_s (< 0);
 *  - rod legs on a contact 1000x softer than default: the feet sink until the soft contact's
 *    hook refuses the state and CVODE gives up ("CVODE ... contact hook").
 * argv[1] is the crawlsim executable. */
#define _POSIX_C_SOURCE 200809L

#include <hdf5.h>
#include <hdf5_hl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cli.h"
#include "cs_test.h"

static const char* exe_path = NULL;
static char g_gait[1024];

#define T_END 2.0 /* s asked for: both cases fail well before it (0.35 s, 0.12 s measured) */


static void expectCleanFailure(const char* extra, const char* cause) {
  const char* out = "blowup.h5";
  remove(out);
  char args[2048];
  snprintf(args, sizeof args, "run --quiet --gait %s --conditions paper --t-end %g --out %s %s",
           g_gait, T_END, out, extra);
  csCliResult r;
  cs_cliRun(exe_path, args, "blowup", &r);
  printf("  %s -> %d: %s", extra, r.status, r.err);
  CS_EXPECT(r.status == 1);
  CS_EXPECT(cs_cliOneLine(r.err));
  CS_EXPECT(strstr(r.err, "crawlsim run: ") == r.err);
  CS_EXPECT(strstr(r.err, "t = ") != NULL);
  CS_EXPECT(strstr(r.err, cause) != NULL);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen(out, H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f < 0) {
    return;
  }
  hsize_t dims[2] = {0, 0};
  CS_EXPECT(H5LTget_dataset_info(f, "/time", dims, NULL, NULL) >= 0);
  size_t n = (size_t)dims[0];
  CS_EXPECT(n >= 2);
  double* t = calloc(n ? n : 1, sizeof *t);
  double* p = calloc(n ? 3 * n : 3, sizeof *p);
  CS_EXPECT(t && p);
  if (t && p && n >= 2) {
    CS_EXPECT(H5LTread_dataset_double(f, "/time", t) >= 0);
    CS_EXPECT(H5LTread_dataset_double(f, "/support/position", p) >= 0);
    CS_EXPECT(t[n - 1] > 0 && t[n - 1] < T_END);
    int finite = 1;
    for (size_t i = 0; i < 3 * n; i++) {
      finite &= isfinite(p[i]) != 0;
    }
    CS_EXPECT(finite);
    /* the reported time is at or after the last sample kept (the step that failed) */
    const char* at = strstr(r.err, "t = ");
    double t_fail = at ? atof(at + 4) : NAN;
    CS_EXPECT(t_fail >= t[n - 1] - 1e-9 && t_fail < T_END);
    printf("  last sample t = %.3f s of %zu, failure at t = %.4f s\n", t[n - 1], n, t_fail);
  }
  free(t);
  free(p);
  char status[1024] = "";
  H5T_class_t cls;
  size_t sz = 0;
  hsize_t ad[1] = {0};
  CS_EXPECT(H5LTget_attribute_info(f, "/", "status", ad, &cls, &sz) >= 0 && sz < sizeof status);
  if (sz < sizeof status) {
    CS_EXPECT(H5LTget_attribute_string(f, "/", "status", status) >= 0);
    CS_EXPECT(status[0] && strstr(r.err, status) != NULL); /* the file says what stderr says */
  }
  H5Fclose(f);
  remove(out);
  remove("blowup.xdmf");
}


static void test_blowup_large_step_diverges_with_time_and_cause(void) {
  expectCleanFailure("--legs rod --coupling stabilised --dt 0.01", "diverged");
}


/* the staggered coupling at h = H = 1 ms (stable to 35 µs) diverges while the robot settles
 * (t < 0, measured -0.294 s), before any sample:
 * the file still exists with the header, empty series, the status and the time it failed */
static void test_blowup_while_settling_leaves_a_file_saying_so(void) {
  const char* out = "blowup_settle.h5";
  remove(out);
  char args[2048];
  snprintf(args, sizeof args, "run --quiet --gait %s --conditions paper --t-end %g --out %s "
           "--legs rod --coupling staggered", g_gait, T_END, out);
  csCliResult r;
  cs_cliRun(exe_path, args, "blowup_settle", &r);
  printf("  -> %d: %s", r.status, r.err);
  CS_EXPECT(r.status == 1);
  CS_EXPECT(cs_cliOneLine(r.err));
  const char* at = strstr(r.err, "t = ");
  CS_EXPECT(at != NULL && atof(at + 4) < 0); /* while settling */
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen(out, H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f < 0) {
    return;
  }
  hsize_t dims[2] = {1, 1};
  CS_EXPECT(H5LTget_dataset_info(f, "/time", dims, NULL, NULL) >= 0 && dims[0] == 0);
  CS_EXPECT(H5LTget_dataset_info(f, "/support/position", dims, NULL, NULL) >= 0 &&
            dims[0] == 0);
  char status[1024] = "", model[64] = "";
  H5T_class_t cls;
  size_t sz = 0;
  hsize_t ad[1] = {0};
  CS_EXPECT(H5LTget_attribute_info(f, "/", "status", ad, &cls, &sz) >= 0 && sz < sizeof status);
  if (sz < sizeof status) {
    CS_EXPECT(H5LTget_attribute_string(f, "/", "status", status) >= 0);
    CS_EXPECT(status[0] && strstr(r.err, status) != NULL);
  }
  CS_EXPECT(H5LTget_attribute_string(f, "/", "leg_model", model) >= 0 && !strcmp(model, "rod"));
  double failed = NAN;
  CS_EXPECT(H5LTget_attribute_double(f, "/", "failed_at_s", &failed) >= 0);
  /* the state (and its time) is the failed step's start: a failed step changes nothing; the
   * message names where the divergence was found, at most one 1 ms step later */
  printf("  failed_at_s = %.4f s\n", failed);
  CS_EXPECT(failed < 0 && fabs(failed - atof(at ? at + 4 : "nan")) <= 1e-3 + 1e-9);
  H5Fclose(f);
  remove(out);
}


static void test_blowup_soft_contact_fails_with_time_and_cause(void) {
  expectCleanFailure("--legs rod --contact-scale 1e-3", "contact");
}


int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_blowup_cli <path of crawlsim> [case filter]\n");
    return 1;
  }
  exe_path = argv[1];
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(g_gait, sizeof g_gait, "%s/gaits/flat_road_paper.csv", src ? src : ".");
  cs_testInit(argc - 1, argv + 1);
  CS_RUN(test_blowup_large_step_diverges_with_time_and_cause);
  CS_RUN(test_blowup_soft_contact_fails_with_time_and_cause);
  CS_RUN(test_blowup_while_settling_leaves_a_file_saying_so);
  return cs_testSummary();
}

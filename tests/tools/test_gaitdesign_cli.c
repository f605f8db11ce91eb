/* test_gaitdesign_cli.c: `crawlsim gait flat-road` end to end (argv[1] is the executable).
 *
 * Proves: (1) the shipped gaits/flat_road.csv and gaits/flat_road_crouch.csv are what the
 * command regenerates from the shipped calibration today (so a calibration change that is not
 * carried to the shipped gaits fails here), (2) a generated table passes `crawlsim gait check`,
 * (3) every bad option or input exits 1 with one line "crawlsim gait flat-road: ..." on stderr
 * naming the cause, and writes no file. Needs POSIX for tests/cs_cli.h. */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cli.h"
#include "cs_test.h"

static const char* exe_path = NULL;


static void run(const char* args, csCliResult* r) {
  char full[2048];
  snprintf(full, sizeof full, "gait %s", args);
  cs_cliRun(exe_path, full, "gaitdesign", r);
}


/* the whole file as a malloc'd string (NULL if unreadable) */
static char* slurp(const char* path) {
  FILE* f = fopen(path, "rb");
  if (!f) {
    return NULL;
  }
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char* s = n >= 0 ? malloc((size_t)n + 1) : NULL;
  if (s) {
    size_t got = fread(s, 1, (size_t)n, f);
    s[got] = '\0';
  }
  fclose(f);
  return s;
}


/* regenerate a shipped gait and compare byte for byte (the comment header included: it records
 * the command and the derived pressures) */
static void expectRegenerates(const char* shipped, const char* flags) {
  char path[1024], args[1200];
  const char* src = getenv("CS_SOURCE_DIR"); /* set by cs_add_test */
  CS_EXPECT(src != NULL);
  if (!src) {
    return;
  }
  snprintf(path, sizeof path, "%s/gaits/%s", src, shipped);
  remove("gaitdesign_regen.csv");
  csCliResult r;
  snprintf(args, sizeof args, "flat-road gaitdesign_regen.csv %s", flags);
  run(args, &r);
  CS_EXPECT(r.status == 0 && r.err[0] == '\0');
  char* want = slurp(path);
  char* got = slurp("gaitdesign_regen.csv");
  CS_EXPECT(want != NULL && got != NULL);
  if (want && got) {
    CS_EXPECT(strcmp(want, got) == 0);
    if (strcmp(want, got) != 0) {
      fprintf(stderr, "  %s differs from what `crawlsim gait flat-road %s` writes today\n",
              shipped, flags);
    }
  }
  free(want);
  free(got);
  /* the generated table is a valid gait */
  run("check gaitdesign_regen.csv", &r);
  CS_EXPECT(r.status == 0);
  remove("gaitdesign_regen.csv");
}


static void test_shippedGaitsAreRegenerable(void) {
  expectRegenerates("flat_road.csv", "");
  expectRegenerates("flat_road_crouch.csv", "--crouch");
}


/* a bad invocation: exit 1, nothing on stdout, one line on stderr containing `want`, no file */
static void expectFailure(const char* args, const char* want) {
  remove("gaitdesign_bad.csv");
  csCliResult r;
  run(args, &r);
  int one_line = strchr(r.err, '\n') == r.err + strlen(r.err) - 1;
  int ok = r.status == 1 && r.out[0] == '\0' && one_line && strstr(r.err, want) != NULL;
  FILE* f = fopen("gaitdesign_bad.csv", "rb");
  if (f) {
    fclose(f);
    ok = 0;
  }
  CS_EXPECT(ok);
  if (!ok) {
    fprintf(stderr, "  args '%s': status %d, stderr '%s', want '%s'\n", args, r.status, r.err,
            want);
  }
  remove("gaitdesign_bad.csv");
}


static void test_badOptions(void) {
  expectFailure("flat-road", "usage: crawlsim gait flat-road");
  expectFailure("flat-road gaitdesign_bad.csv --bogus", "unknown option '--bogus'");
  expectFailure("flat-road gaitdesign_bad.csv other.csv", "unexpected argument 'other.csv'");
  expectFailure("flat-road gaitdesign_bad.csv --stroke", "--stroke needs a value");
  expectFailure("flat-road gaitdesign_bad.csv --stroke -1", "--stroke '-1' must be a number > 0");
  expectFailure("flat-road gaitdesign_bad.csv --stroke abc", "--stroke 'abc'");
  expectFailure("flat-road gaitdesign_bad.csv --stroke nan", "--stroke 'nan'");
  expectFailure("flat-road gaitdesign_bad.csv --strokes 0.5", "--strokes 0.5 must be a whole");
  expectFailure("flat-road gaitdesign_bad.csv --strokes 1e30", "--strokes 1e+30 must be a whole");
  expectFailure("flat-road gaitdesign_bad.csv --t-land 5", "t_land (5 s)");
  expectFailure("flat-road gaitdesign_bad.csv --calibration", "--calibration needs a file");
}


static void test_badInputs(void) {
  /* a stroke the actuator cannot reach below --p-max or the calibration's last row: the
   * design says how far it gets (the shipped FE table ends at 0.3 MPa) */
  expectFailure("flat-road gaitdesign_bad.csv --stroke 500",
                "needs more than 0.3 MPa (the calibration's range)");
  expectFailure("flat-road gaitdesign_bad.csv --p-max 0.01", "needs more than 0.01 MPa");
  expectFailure("flat-road gaitdesign_bad.csv --calibration gaitdesign_missing.txt",
                "gaitdesign_missing.txt: cannot open calibration file");
  /* a calibration file that is not one: names the file and the line */
  cs_cliWriteText("gaitdesign_calib.txt", "actuator baseline\nchambers 1,2\npressure_MPa x\n");
  expectFailure("flat-road gaitdesign_bad.csv --calibration gaitdesign_calib.txt",
                "gaitdesign_calib.txt:3");
  remove("gaitdesign_calib.txt");
  expectFailure("flat-road gaitdesign_no_such_dir/x.csv", "cannot open for writing");
}


int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_gaitdesign_cli PATH_TO_CRAWLSIM\n");
    return 2;
  }
  exe_path = argv[1];
  CS_RUN(test_shippedGaitsAreRegenerable);
  CS_RUN(test_badOptions);
  CS_RUN(test_badInputs);
  return cs_testSummary();
}

/* test_gaitdesign_cli.c: `crawlsim gait design` and `crawlsim gait flat-road` end to end
 * (argv[1] is the executable).
 *
 * Proves: (1) the shipped gaits are what the commands regenerate from their descriptions and
 * the shipped calibration today, byte for byte (gaits/flat_road.csv from flat_road.gait,
 * gaits/flat_road_paper.csv from flat_road_paper.gait, both on the pair-mode table they were
 * designed on, named with --calibration since the default is the mission's table; gaits/obstacle.csv from obstacle.gait
 * (with --stretch), gaits/flat_road_rod.csv from flat_road_rod.gait (with --stretch on the
 * mission's table under rbf-pair), gaits/flat_road_earth.csv from flat_road_earth.gait (the
 * same), gaits/flat_road_crouch.csv from
 * `gait flat-road --crouch` on the pair-mode table; a calibration or design change that is not carried to the
 * shipped gaits fails here), (2) a generated table passes `crawlsim gait check`, (3) every bad
 * option, description or input exits 1 with one line "crawlsim gait <sub>: ..." on stderr
 * naming the file, line and cause, and writes no file. Needs POSIX for tests/cs_cli.h. */
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
static void expectRegenerates(const char* shipped, const char* flags, const char* design) {
  char path[1024], args[1200];
  const char* src = getenv("CS_SOURCE_DIR"); /* set by cs_add_test */
  CS_EXPECT(src != NULL);
  if (!src) {
    return;
  }
  snprintf(path, sizeof path, "%s/gaits/%s", src, shipped);
  remove("gaitdesign_regen.csv");
  csCliResult r;
  if (design) {
    /* from the gaits/ directory, as the shipped files were made (their headers name the
     * description by its base name) */
    snprintf(args, sizeof args, "design %s/gaits/%s --out gaitdesign_regen.csv %s", src, design,
             flags);
  } else {
    snprintf(args, sizeof args, "flat-road gaitdesign_regen.csv %s", flags);
  }
  run(args, &r);
  CS_EXPECT(r.status == 0 && r.err[0] == '\0');
  if (r.status != 0) {
    fprintf(stderr, "  %s: %s\n", args, r.err);
  }
  char* want = slurp(path);
  char* got = slurp("gaitdesign_regen.csv");
  CS_EXPECT(want != NULL && got != NULL);
  if (want && got) {
    CS_EXPECT(strcmp(want, got) == 0);
    if (strcmp(want, got) != 0) {
      fprintf(stderr, "  %s differs from what `crawlsim gait %s` writes today\n", shipped,
              args);
    }
  }
  free(want);
  free(got);
  /* the generated table is a valid gait */
  run("check gaitdesign_regen.csv", &r);
  CS_EXPECT(r.status == 0);
  remove("gaitdesign_regen.csv");
}


/* a bad invocation (below): exit 1, one line on stderr containing `want`, no file */
static void expectFailure(const char* args, const char* want);


static void test_shippedGaitsAreRegenerable(void) {
  /* the gaits designed on the pair-mode table (its documented purpose since the default became
   * the mission's table, docs/calibration.md) name it */
  char pair[600];
  const char* src0 = getenv("CS_SOURCE_DIR");
  snprintf(pair, sizeof pair, "--calibration %s/robot/calibration_fe_leg.h5", src0 ? src0 : ".");
  expectRegenerates("flat_road.csv", pair, "flat_road.gait");
  expectRegenerates("flat_road_paper.csv", pair, "flat_road_paper.gait");
  /* the flat road's default gait (the searched design) and the obstacle's (stretched legs: the
   * all-four mode, to 0.4 MPa, the table's range), both solved on the mission's map (the
   * 23-mode symmetric-mesh table under rbf-pair) with its stretch */
  char flags[1400];
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(flags, sizeof flags, "--stretch --calibration %s/robot/calibration_fe_leg_modes_sym.h5 "
           "--cal-rule rbf-pair --p-max 0.4", src ? src : ".");
  expectRegenerates("obstacle.csv", flags, "obstacle.gait");
  expectRegenerates("flat_road_rod.csv", flags, "flat_road_rod.gait");
  /* the flat road's wave gait for `earth` (tools/earth_gait.py), on the same map */
  expectRegenerates("flat_road_earth.csv", flags, "flat_road_earth.gait");
  snprintf(flags, sizeof flags, "--crouch %s", pair);
  expectRegenerates("flat_road_crouch.csv", flags, NULL);
}


/* a bad description: exit 1, one line "crawlsim gait design: <file>:<line>: <cause>" */
static void expectBadDesign(const char* text, int line, const char* cause) {
  cs_cliWriteText("gaitdesign_bad.gait", text);
  char want[512];
  snprintf(want, sizeof want, "gaitdesign_bad.gait:%d: %s", line, cause);
  expectFailure("design gaitdesign_bad.gait --out gaitdesign_bad.csv", want);
  remove("gaitdesign_bad.gait");
}


static void test_badDesigns(void) {
  const char* pose = "pose S II1:3,4 II2:1,2 stroke 39\n";
  char t[2048];
  expectBadDesign("nmae x\n", 1, "unknown statement 'nmae'");
  expectBadDesign("ramp 0\n", 1, "ramp 0 s is outside");
  expectBadDesign("ramp 0.2 0.3\n", 1, "'ramp' needs one number (s), once");
  expectBadDesign("ramp 0.2\nramp 0.3\n", 2, "'ramp' needs one number (s), once");
  expectBadDesign("pose S II4:1 stroke 3\n", 1, "chamber set 'II4:1' is not II<1..3>");
  expectBadDesign("pose S II1:1,5 stroke 3\n", 1, "chamber set 'II1:1,5'");
  expectBadDesign("pose S II1:1 II1:1 stroke 3\n", 1, "chamber II1:1 is in the set twice");
  expectBadDesign("pose S II1:3,4 height 3\n", 1, "unknown target 'height'");
  expectBadDesign("pose S II1:3,4 stroke x\n", 1, "stroke value 'x' is not a finite number");
  expectBadDesign("pose S II1:3,4 pressure 2\n", 1, "pressure 2 MPa is outside");
  expectBadDesign("pose S II1:3,4 pressure-of T\n", 1, "pressure-of 'T': no earlier pose");
  expectBadDesign("pose straight II1:3,4 stroke 3\n", 1, "'straight' is the built-in");
  expectBadDesign("pose F foot 1\n", 1, "'pose NAME foot X LIFT [plus|minus]' needs two numbers");
  expectBadDesign("pose F foot 1 2 sideways\n", 1, "foot X LIFT: 'sideways' is not plus or minus");
  expectBadDesign("pose F foot 1 2 plus 3\n", 1, "'pose NAME foot X LIFT [plus|minus]' needs");
  snprintf(t, sizeof t, "%smove 0 1 ACFX S\n", pose);
  expectBadDesign(t, 2, "leg set 'ACFX': 'X' is not a leg A..H");
  snprintf(t, sizeof t, "%smove 0 1 AA S\n", pose);
  expectBadDesign(t, 2, "leg set 'AA' names leg A twice");
  snprintf(t, sizeof t, "%smove 0 1 A T\n", pose);
  expectBadDesign(t, 2, "unknown pose 'T'");
  snprintf(t, sizeof t, "%smove 0 1 A S\nmove 0.5 1 AB straight\n", pose);
  expectBadDesign(t, 3, "legs A move at 0.5..1.5 s, overlapping their move of line 2");
  snprintf(t, sizeof t, "%sphase 0 1 swing S\n", pose);
  expectBadDesign(t, 2, "'phase' outside a stride");
  snprintf(t, sizeof t, "%sstride 2 1 0 ACFH BDEG\nphase 0 1 walk S\n", pose);
  expectBadDesign(t, 3, "role 'walk' is not swing or stand");
  snprintf(t, sizeof t, "%sstride 2 1 0 ACFH ABDE\n", pose);
  expectBadDesign(t, 2, "the two leg sets of a stride share legs");
  /* the foothold line (gaits_design.h): its words, legs, offsets and margin */
  snprintf(t, sizeof t, "%sfoothold 1 DH\n", pose);
  expectBadDesign(t, 2, "'foothold' needs T LEGS OFFSETS [margin MM]");
  snprintf(t, sizeof t, "%sfoothold 1 DX 0,10\n", pose);
  expectBadDesign(t, 2, "leg set 'DX': 'X' is not a leg A..H");
  snprintf(t, sizeof t, "%sfoothold 1 DH 0,,10\n", pose);
  expectBadDesign(t, 2, "OFFSETS '0,,10' must be 1..12 numbers (mm) separated by commas");
  snprintf(t, sizeof t, "%sfoothold 1 DH 0,10 margin -1\n", pose);
  expectBadDesign(t, 2, "foothold needs T in 0..");
  snprintf(t, sizeof t, "%sfoothold 1 DH 0,10 width 3\n", pose);
  expectBadDesign(t, 2, "'foothold' needs T LEGS OFFSETS [margin MM]");
  snprintf(t, sizeof t, "%smove 0 1 A S\nend 0.5\n", pose);
  expectBadDesign(t, 3, "end 0.5 s is before the last move ends (1 s)");
  expectBadDesign(pose, 1, "end of file without a 'move'");
  /* a target the actuator cannot reach names its line and what it reaches */
  expectBadDesign("pose S II1:3,4 II2:1,2 stroke 500\nmove 0 1 A S\n", 1,
                  "pose S: stroke 500 is not reachable with this chamber set in 0..0.3 MPa");
  expectBadDesign("pose F foot 0 150\nmove 0 1 A F\n", 1, "pose F:");
  /* with the legs' stretch a 30 / 20 mm reach needs II2 past what 0.3 MPa gives (the bends and
   * stretches solved together; an inextensible leg reached it) */
  cs_cliWriteText("gaitdesign_bad.gait", "pose F foot 30 20\nmove 0 1 A F\n");
  expectFailure("design gaitdesign_bad.gait --stretch --out gaitdesign_bad.csv",
                "gaitdesign_bad.gait:1: pose F: II2 must bend");
  remove("gaitdesign_bad.gait");
  expectFailure("design gaitdesign_missing.gait", "gaitdesign_missing.gait: cannot open");
  expectFailure("design", "missing FILE.gait");
  expectFailure("design x.gait --p-max -1", "--p-max '-1' must be a number > 0");
  expectFailure("design x.gait --bogus", "unknown option --bogus");
  expectFailure("design x.gait --cal-rule bogus", "unknown --cal-rule 'bogus' (expected prism");
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
  expectFailure("flat-road", "missing FILE.csv");
  expectFailure("flat-road gaitdesign_bad.csv --bogus", "unknown option --bogus");
  expectFailure("flat-road gaitdesign_bad.csv other.csv", "unexpected argument 'other.csv'");
  expectFailure("flat-road gaitdesign_bad.csv --stroke", "--stroke needs a value");
  expectFailure("flat-road gaitdesign_bad.csv --stroke -1", "--stroke '-1' must be a number > 0");
  expectFailure("flat-road gaitdesign_bad.csv --stroke abc", "--stroke 'abc'");
  expectFailure("flat-road gaitdesign_bad.csv --stroke nan", "--stroke 'nan'");
  expectFailure("flat-road gaitdesign_bad.csv --strokes 0.5", "--strokes 0.5 must be a whole");
  expectFailure("flat-road gaitdesign_bad.csv --strokes 1e30", "--strokes 1e+30 must be a whole");
  expectFailure("flat-road gaitdesign_bad.csv --t-land 5", "t_land (5 s)");
  expectFailure("flat-road gaitdesign_bad.csv --calibration", "option --calibration needs a value");
}


static void test_badInputs(void) {
  /* a stroke the actuator cannot reach below --p-max or the calibration's last row: the
   * design says how far it gets (the default, the mission's table, ends at 0.4 MPa) */
  expectFailure("flat-road gaitdesign_bad.csv --stroke 500",
                "needs more than 0.4 MPa (the calibration's range)");
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


/* the foot pose's branch (the obstacle gait's swing): `plus` keeps II1 on Ω3&Ω4 behind the
 * hip, where the solver's own choice is Ω1&Ω2, `minus` the mirror in front of it; both reach
 * their target. A move between two `plus` poses on opposite sides of the hip stays on the
 * branch: no row of its table passes a straight leg (every row bends II1 on Ω3&Ω4 and II2 on
 * Ω1&Ω2), where the solver's own choice changes pairs at the hip. Read from the header, which
 * prints each pose's pressures, and from the table. */
static void test_footPoseBranch(void) {
  const char* src = getenv("CS_SOURCE_DIR");
  char args[1200];
  cs_cliWriteText("gaitdesign_branch.gait",
                  "name branch\n"
                  "sample 0.05\n"
                  "ramp 0.3\n"
                  "pose AUTO foot -25 12\n"
                  "pose PLUS foot -25 12 plus\n"
                  "pose MINUS foot 25 12 minus\n"
                  "pose FRONT foot 25 12 plus\n"
                  "move 0 0.5 A PLUS\n"
                  "move 0.5 1 A FRONT\n"
                  "move 0 0.5 B AUTO\n"
                  "move 0.5 1 B MINUS\n");
  snprintf(args, sizeof args, "design gaitdesign_branch.gait --stretch --out gaitdesign_branch.csv "
           "--calibration %s/robot/calibration_fe_leg_modes.h5 --p-max 0.4", src ? src : ".");
  csCliResult r;
  run(args, &r);
  CS_EXPECT(r.status == 0);
  CS_EXPECT(strstr(r.out, "pose AUTO: II1:1,2 ") != NULL);
  const char* plus = strstr(r.out, "pose PLUS: II1:3,4 ");
  const char* minus = strstr(r.out, "pose MINUS: II1:1,2 ");
  CS_EXPECT(plus && strstr(plus, "foot stroke -25.00, side 0.00, lift 12.00 mm"));
  CS_EXPECT(minus && strstr(minus, "foot stroke 25.00, side 0.00, lift 12.00 mm"));
  if (r.status != 0 || !plus || !minus) {
    fprintf(stderr, "  %s\n  out: %s\n  err: %s\n", args, r.out, r.err);
  }
  /* leg A's swing PLUS -> FRONT: every row of 0.5..1.5 s has II1 on Ω3&Ω4 only and II2 on
   * Ω1&Ω2 only, both inflated (columns 1..4 A_II1_O1..O4, 5..8 A_II2_O1..O4) */
  FILE* f = fopen("gaitdesign_branch.csv", "r");
  CS_EXPECT(f != NULL);
  int rows = 0, on_branch = 0, stated = 0;
  char line[8192];
  while (f && fgets(line, sizeof line, f)) {
    stated += !strcmp(line, "# @ramp 0.3\n"); /* the description's `ramp`, not its sample */
    if (line[0] == '#' || line[0] == 't') continue;
    double v[9];
    if (sscanf(line, "%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4],
               &v[5], &v[6], &v[7], &v[8]) != 9 || v[0] < 0.5 - 1e-9 || v[0] > 1.5 + 1e-9) {
      continue;
    }
    rows++;
    on_branch += v[1] == 0 && v[2] == 0 && v[3] > 0.05 && v[4] > 0.05 && v[5] > 0.05 &&
                 v[6] > 0.05 && v[7] == 0 && v[8] == 0;
  }
  if (f) fclose(f);
  CS_EXPECT(rows == 21 && on_branch == rows);
  CS_EXPECT(stated == 1);
  if (on_branch != rows) {
    fprintf(stderr, "  %d of %d rows of the plus swing on the branch\n", on_branch, rows);
  }
  remove("gaitdesign_branch.gait");
  remove("gaitdesign_branch.csv");
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
  CS_RUN(test_badDesigns);
  CS_RUN(test_footPoseBranch);
  return cs_testSummary();
}

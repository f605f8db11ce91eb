/* test_run_cli.c: `crawlsim run` with bad input, end to end: runs the real executable (its
 * path is argv[1], from $<TARGET_FILE:crawlsim>) and checks that every bad flag, terrain,
 * gait, calibration or output path exits 1 with exactly ONE line "crawlsim run: <cause>" on
 * stderr, nothing on stdout (--quiet: no progress lines), and no output file, i.e. it failed
 * before simulating (docs/design.md command-line contract). One short good run exits 0. */
#define _POSIX_C_SOURCE 200809L

#include <hdf5.h>
#include <hdf5_hl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cli.h"
#include "cs_test.h"

static const char* exe_path = NULL; /* the crawlsim executable (set once in main) */

/* the output file of every bad run: it must never appear */
#define BAD_OUT "runcli_bad.h5"


/* `crawlsim run --quiet --t-end 0.01 --out BAD_OUT <args>`: exit 1, one stderr line starting
 * with `want`, stdout empty, no output file. --t-end 0.01 keeps a run that wrongly starts
 * short; the missing output file shows it did not start. */
/* the run file `path` has the root string attribute `name` equal to `want` */
static void expectAttrString(const char* path, const char* name, const char* want) {
  hid_t f = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    char v[64] = "";
    CS_EXPECT(H5LTget_attribute_string(f, "/", name, v) >= 0 && !strcmp(v, want));
    H5Fclose(f);
  }
}


static void expectFailure(const char* args, const char* want) {
  remove(BAD_OUT);
  char full[2048];
  snprintf(full, sizeof full, "run --quiet --t-end 0.01 --out " BAD_OUT " %s", args);
  csCliResult r;
  cs_cliRun(exe_path, full, "runcli", &r);
  CS_EXPECT(r.status == 1);
  CS_EXPECT(r.out[0] == '\0');
  CS_EXPECT(cs_cliOneLine(r.err));
  CS_EXPECT(strstr(r.err, want) == r.err);
  CS_EXPECT(!cs_cliFileExists(BAD_OUT));
  if (r.status != 1 || strstr(r.err, want) != r.err || !cs_cliOneLine(r.err) || r.out[0]) {
    fprintf(stderr, "  args '%s': status %d\n  stdout: %s\n  stderr: %s\n  wanted: %s\n", args,
            r.status, r.out, r.err, want);
  }
  remove(BAD_OUT);
}


static void test_badOptions(void) {
  expectFailure("--frobnicate 1", "crawlsim run: unknown option --frobnicate");
  expectFailure("stray", "crawlsim run: unexpected argument 'stray'");
  expectFailure("--friction", "crawlsim run: option --friction needs a value");
  expectFailure("--gait --quiet", "crawlsim run: option --gait needs a value");
  expectFailure("--friction abc", "crawlsim run: --friction 'abc' is not a finite number");
  expectFailure("--friction nan", "crawlsim run: --friction 'nan' is not a finite number");
  expectFailure("--friction -0.5", "crawlsim run: --friction -0.5 must be >= 0");
  expectFailure("--t-end -1", "crawlsim run: --t-end -1 s must be >= 0");
  /* the default strain legs step adaptively on a 5 ms grid (cs_rundef.c stepAdaptive) */
  expectFailure("--t-end 1e300", "crawlsim run: a run to t = 1e+300 s at --dt 0.005 s takes");
  expectFailure("--pressure-scale -1", "crawlsim run: --pressure-scale -1 must be >= 0");
  /* the shipped gait peaks near 0.3 MPa: x 100 is far above the 1 MPa limit */
  expectFailure("--pressure-scale 100", "crawlsim run: --pressure-scale 100 takes ");
  expectFailure("--scene moon", "crawlsim run: unknown scene 'moon'");
  /* slopes and scene files (terrains_scenefile.h): one line naming the file and line */
  expectFailure("--scene slope --slope-deg 50", "crawlsim run: --slope-deg 50 must be within");
  expectFailure("--scene-file runcli_missing.scene",
                "crawlsim run: runcli_missing.scene: cannot open scene file:");
  CS_EXPECT(cs_cliWriteText("runcli_bad.scene", "scene slope\nslope 60\n") == 1);
  expectFailure("--scene-file runcli_bad.scene",
                "crawlsim run: runcli_bad.scene:2: 'slope' value 60");
  CS_EXPECT(cs_cliWriteText("runcli_bad.scene", "start 5000 5\n") == 1);
  expectFailure("--scene-file runcli_bad.scene",
                "crawlsim run: runcli_bad.scene: start (5000, 5) is not above any box of ");
  remove("runcli_bad.scene");
  expectFailure("--conditions mars", "crawlsim run: unknown conditions 'mars' (expected earth or");
  expectFailure("--conditions", "crawlsim run: option --conditions needs a value");
  /* the rom level reads its leg file (robot/rom/robot_rom_file.h): refused in one line */
  expectFailure("--legs rom", "crawlsim run: --legs rom needs --rom-file LEG.h5");
  expectFailure("--rom-file x.h5", "crawlsim run: --rom-file goes with --legs rom (not strain)");
  expectFailure("--legs rom --rom-file runcli_missing.h5",
                "crawlsim run: runcli_missing.h5: cannot open as an HDF5 file");
  CS_EXPECT(cs_cliWriteText("runcli_notleg.h5", "not hdf5\n") == 1);
  expectFailure("--legs rom --rom-file runcli_notleg.h5",
                "crawlsim run: runcli_notleg.h5: cannot open as an HDF5 file");
  remove("runcli_notleg.h5");
  expectFailure("--legs bogus", "crawlsim run: unknown leg model 'bogus'");
  expectFailure("--support-mass 0", "crawlsim run: --support-mass 0 kg must be > 0");
  expectFailure("--macro-steps 0", "crawlsim run: --macro-steps 0 must be an integer in 1..");
  expectFailure("--macro-steps 2.5", "crawlsim run: --macro-steps 2.5 must be an integer in");
  expectFailure("--legs rod --macro-steps 20 --output-dt 0.01",
                "crawlsim run: --output-dt 0.01 s must be >= the macro step 0.02 s");
  expectFailure("--coupling tight", "crawlsim run: unknown coupling 'tight'");
  expectFailure("--links 0", "crawlsim run: --links 0 must be an integer in 1..64");
  expectFailure("--links 2.5", "crawlsim run: --links 2.5 must be an integer in 1..64");
  expectFailure("--iterations 0", "crawlsim run: --iterations 0 must be an integer in 1..10000");
  expectFailure("--iterations 1e30", "crawlsim run: --iterations 1e+30 must be an integer");
  expectFailure("--dt 0", "crawlsim run: --dt 0 s must be > 0 and <= 0.01 s");
  expectFailure("--dt 0.002 --output-dt 0.001",
                "crawlsim run: --output-dt 0.001 s must be >= the step 0.002 s (--dt)");
  expectFailure("--output-dt 0.0001", "crawlsim run: --output-dt 0.0001 s must be >= the step");
  expectFailure("--gravity -9.81", "crawlsim run: --gravity -9.81 m/s^2 must be >= 0");
  expectFailure("--tau -1", "crawlsim run: --tau -1 s must be >= 0");
  expectFailure("--ramp -1", "crawlsim run: --ramp -1 s must be >= 0");
  expectFailure("--legs rod --rod-tol 0", "crawlsim run: --rod-tol 0 must be > 0 and <= 1000");
  expectFailure("--legs rod --rod-tol 1e4",
                "crawlsim run: --rod-tol 10000 must be > 0 and <= 1000");
  expectFailure("--cal-rule hats",
                "crawlsim run: unknown --cal-rule 'hats' (expected prism, rbf or rbf-pair)");
  expectFailure("--legs rod --cal-drop stretch,ei",
                "crawlsim run: bad --cal-drop 'stretch,ei' (expected stretch, stiffness, "
                "stretch,stiffness or none)");
  /* a leg level's own setting, for a level that has none of that name (robot_leg.h
   * csrLegSetting): one line naming the levels that take it */
  expectFailure("--legs strain --cal-drop stretch",
                "crawlsim run: --cal-drop is for rod legs, not strain (their setting cal_drop)");
  /* a retired level: one line saying so and naming what to use */
  expectFailure("--legs prb", "crawlsim run: --legs prb: the prb level was retired (2026-12-06): "
                "off the speed/accuracy front (docs/studies/speed_accuracy.md); use rod (the "
                "default) or strain");
  expectFailure("--legs strain --rod-tol 2",
                "crawlsim run: --rod-tol is for rod, rom legs, not strain (their setting rod_tol)");
  expectFailure("--legs rod --step-order 2",
                "crawlsim run: --step-order is for strain legs, not rod (their setting "
                "step_order)");
  /* the pair-mode table (named: the scenes default to a mode table): a rule applies to mode
   * tables only */
  {
    csCliResult r;
    remove(BAD_OUT);
    char args[1024];
    snprintf(args, sizeof args, "run --quiet --t-end 0.01 --cal-rule rbf --calibration "
             "%s/robot/calibration_fe_leg.h5 --out " BAD_OUT,
             getenv("CS_SOURCE_DIR") ? getenv("CS_SOURCE_DIR") : ".");
    cs_cliRun(exe_path, args, "runcli", &r);
    CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err) && strstr(r.err, "crawlsim run: ") == r.err);
    CS_EXPECT(strstr(r.err, "robot/calibration_fe_leg.h5: a calibration rule applies only to an "
                     "FE mode table (this is a pair-mode table)") != NULL);
    CS_EXPECT(!cs_cliFileExists(BAD_OUT));
  }
}


static void test_badFiles(void) {
  remove("runcli_missing.csv");
  expectFailure("--gait runcli_missing.csv",
                "crawlsim run: runcli_missing.csv: cannot open gait CSV: No such file or directory");
  CS_EXPECT(cs_cliWriteText("runcli_neg.csv", "time,A_II1_O1,A_II1_O2\n0,0,0\n1,0,-0.1\n"));
  expectFailure("--gait runcli_neg.csv",
                "crawlsim run: runcli_neg.csv:3: column 3 (A_II1_O2): negative");
  remove("runcli_neg.csv");
  remove("runcli_missing.terrain");
  expectFailure("--terrain runcli_missing.terrain",
                "crawlsim run: runcli_missing.terrain: cannot open terrain file: No such file");
  CS_EXPECT(cs_cliWriteText("runcli_bad.terrain", "name bad\nbox 0 -20 0 600 0 nan\n"));
  expectFailure("--terrain runcli_bad.terrain",
                "crawlsim run: runcli_bad.terrain:2: 'box' value 6 'nan' is not a finite number");
  CS_EXPECT(cs_cliWriteText("runcli_off.terrain", "box 0 -20 0 600 0 300\nstart 900 100\n"));
  expectFailure("--terrain runcli_off.terrain",
                "crawlsim run: runcli_off.terrain:2: start (900, 100) is not above any box");
  remove("runcli_bad.terrain");
  remove("runcli_off.terrain");
  /* the output file cannot be created: found before settling, not after */
  remove(BAD_OUT);
  csCliResult r;
  cs_cliRun(exe_path, "run --quiet --t-end 0.01 --out /nonexistent/x.h5", "runcli", &r);
  CS_EXPECT(r.status == 1 && r.out[0] == '\0' && cs_cliOneLine(r.err));
  CS_EXPECT(strstr(r.err, "crawlsim run: --out /nonexistent/x.h5: cannot create output file") ==
            r.err);
}


/* a calibration file with `text`, run with it: the message names the file and line */
static void expectBadCalibration(const char* text, const char* want) {
  CS_EXPECT(cs_cliWriteText("runcli_calib.txt", text));
  expectFailure("--calibration runcli_calib.txt", want);
  remove("runcli_calib.txt");
}


static void test_badCalibration(void) {
  remove("runcli_nocalib.txt");
  expectFailure("--calibration runcli_nocalib.txt",
                "crawlsim run: runcli_nocalib.txt: cannot open calibration file: No such file");
  const char* ok3 = "chambers 1,2\npressure_MPa 0.403\ntotal_angle_deg 360\n";
  char text[512];
  snprintf(text, sizeof text, "# comment\nactuator baseline\nfoo 1\n%s", ok3);
  expectBadCalibration(text, "crawlsim run: runcli_calib.txt:3: unknown key 'foo'");
  expectBadCalibration("actuator baseline\nchambers 5\npressure_MPa 0.403\ntotal_angle_deg 360\n",
                       "crawlsim run: runcli_calib.txt:2: chambers '5': chamber 5 is not in 1..4");
  expectBadCalibration("actuator baseline\nchambers 1,5\n",
                       "crawlsim run: runcli_calib.txt:2: chambers '1,5': chamber 5 is not in");
  expectBadCalibration("actuator baseline\nchambers 1,2\npressure_MPa -1\ntotal_angle_deg 360\n",
                       "crawlsim run: runcli_calib.txt:3: pressure_MPa '-1' must be a finite "
                       "number > 0");
  expectBadCalibration("actuator baseline\nchambers 1,2\npressure_MPa 0.4\ntotal_angle_deg inf\n",
                       "crawlsim run: runcli_calib.txt:4: total_angle_deg 'inf' must be a finite");
  expectBadCalibration("actuator baseline\nchambers 1,2\n\n",
                       "crawlsim run: runcli_calib.txt:3: end of file: missing 'pressure_MPa', "
                       "'total_angle_deg'");
  expectBadCalibration("", "crawlsim run: runcli_calib.txt:1: end of file: missing 'actuator'");
  snprintf(text, sizeof text, "actuator bogus\n%s", ok3);
  expectBadCalibration(text, "crawlsim run: runcli_calib.txt:1: unknown actuator 'bogus'");
  snprintf(text, sizeof text, "actuator baseline leg\n%s", ok3);
  expectBadCalibration(text, "crawlsim run: runcli_calib.txt:1: 'actuator' needs exactly one "
                             "value, got 2");
  snprintf(text, sizeof text, "actuator baseline\n%sactuator leg\n", ok3);
  expectBadCalibration(text, "crawlsim run: runcli_calib.txt:5: second 'actuator' (the first is "
                             "on line 1)");
  /* numbers that parse but describe no sensible reference */
  expectBadCalibration("actuator baseline\nchambers 1,2,3,4\npressure_MPa 0.4\n"
                       "total_angle_deg 360\n",
                       "crawlsim run: runcli_calib.txt:2: the reference chambers do not bend");
  expectBadCalibration("actuator baseline\nchambers 1,2\npressure_MPa 1e-300\n"
                       "total_angle_deg 360\n",
                       "crawlsim run: runcli_calib.txt:4: total_angle_deg 360 at 1e-300 MPa "
                       "needs a factor");
}


/* issue 33 item 1: the banner states the default discretisation's measured track error, read
 * from the shipped level table's row of the configuration that runs, or that it was not
 * measured (the banner is on stderr), and the run file records the same (track_error,
 * track_error_mm) */
static void test_bannerStatesTrackError(void) {
  csCliResult r;
  /* the default steps adaptively (2.5e-4 mm): a row of the table (step_tol_mm), quoted in the
   * banner and the run file */
  remove("runcli_banner.h5");
  cs_cliRun(exe_path, "run --t-end 0.01 --out runcli_banner.h5", "runcli", &r);
  const char* line0 =
      strstr(r.err, "crawlsim run: legs strain, 2 bending modes per segment: track error ");
  CS_EXPECT(r.status == 0 && line0 != NULL);
  double mm0 = -1;
  CS_EXPECT(line0 && sscanf(line0, "crawlsim run: legs strain, 2 bending modes per segment: "
                                   "track error %lf mm", &mm0) == 1 && mm0 >= 0);
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen("runcli_banner.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    double te = -1;
    char what[800] = "";
    CS_EXPECT(H5LTget_attribute_double(f, "/", "track_error_mm", &te) >= 0);
    /* the banner prints 3 significant digits of the same row's value */
    CS_EXPECT(fabs(te - mm0) <= 0.0051 * fmax(1, te));
    CS_EXPECT(H5LTget_attribute_string(f, "/", "track_error", what) >= 0 &&
              strstr(line0, what) != NULL && what[0]);
    H5Fclose(f);
  }
  /* the adaptive step at a tolerance the table has no row for: not measured, and no number in
   * the file */
  cs_cliRun(exe_path, "run --t-end 0.01 --step-tol 1e-3 --out runcli_banner.h5", "runcli", &r);
  CS_EXPECT(r.status == 0 &&
            strstr(r.err, "crawlsim run: legs strain, 2 bending modes per segment: track error "
                          "of the adaptive step at 0.001 mm per step (longest 0.005 s) not "
                          "measured") != NULL);
  f = H5Fopen("runcli_banner.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    CS_EXPECT(H5Aexists(f, "track_error") > 0 && H5Aexists(f, "track_error_mm") == 0);
    H5Fclose(f);
  }
  /* the rows are measured under paper on the scene's own files: under earth (the flat road's
   * Earth gait) or on a user's gait the banner quotes the row as the scene's, says this run's
   * error is not measured, and the run file records no number */
  const char* why[2] = {"this run's conditions differ, so its own error is not measured",
                        "this run's terrain or gait differ, so its own error is not measured"};
  for (int k = 0; k < 2; k++) {
    char cmd[1024];
    if (k == 0) {
      snprintf(cmd, sizeof cmd, "run --t-end 0.01 --conditions earth --out runcli_banner.h5");
    } else {
      snprintf(cmd, sizeof cmd, "run --t-end 0.01 --gait %s/gaits/flat_road_paper.csv "
               "--conditions paper --out runcli_banner.h5",
               getenv("CS_SOURCE_DIR") ? getenv("CS_SOURCE_DIR") : ".");
    }
    cs_cliRun(exe_path, cmd, "runcli", &r);
    const char* l = strstr(r.err, "crawlsim run: legs strain, 2 bending modes per segment: "
                                  "track error ");
    CS_EXPECT(r.status == 0 && l != NULL && strstr(l, why[k]) != NULL);
    f = H5Fopen("runcli_banner.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
    CS_EXPECT(f >= 0);
    if (f >= 0) {
      CS_EXPECT(H5Aexists(f, "track_error") > 0 && H5Aexists(f, "track_error_mm") == 0);
      H5Fclose(f);
    }
  }
  /* a fixed step is a row of the table */
  cs_cliRun(exe_path, "run --t-end 0.01 --strain-step fixed --out runcli_banner.h5", "runcli", &r);
  CS_EXPECT(r.status == 0);
  const char* line =
      strstr(r.err, "crawlsim run: legs strain, 2 bending modes per segment: track error ");
  CS_EXPECT(line != NULL);
  double mm = -1;
  CS_EXPECT(line && sscanf(line, "crawlsim run: legs strain, 2 bending modes per segment: track "
                                 "error %lf mm", &mm) == 1 && mm >= 0);
  CS_EXPECT(line && strstr(line, "robot/levels.csv (line ") != NULL);
  /* the rod asked for: the scene's converged elements (8 on the flat road) */
  cs_cliRun(exe_path, "run --t-end 0.01 --legs rod --out runcli_banner.h5", "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.err, "crawlsim run: legs rod, 8 elements per segment: "
                                           "track error ") != NULL);
  cs_cliRun(exe_path, "run --t-end 0.01 --legs rod --links 3 --out runcli_banner.h5", "runcli",
            &r);
  CS_EXPECT(r.status == 0 && strstr(r.err, "legs rod, 3 elements per segment: track error of "
                                           "this configuration not measured") != NULL);
  remove("runcli_banner.h5");
  remove("runcli_banner.xdmf");
}


static void test_goodRun(void) {
  remove("runcli_ok.h5");
  csCliResult r;
  cs_cliRun(exe_path, "run --t-end 0.05 --quiet --out runcli_ok.h5", "runcli", &r);
  CS_EXPECT(r.status == 0);
  CS_EXPECT(r.err[0] == '\0'); /* --quiet: no progress lines */
  CS_EXPECT(strstr(r.out, "final t = 0.050 s") == r.out);
  /* the summary's time split names every stage */
  CS_EXPECT(strstr(r.out, "time split (s): schedule ") != NULL);
  CS_EXPECT(strstr(r.out, " legs ") && strstr(r.out, " support ") && strstr(r.out, " check "));
  CS_EXPECT(cs_cliFileExists("runcli_ok.h5"));
  if (r.status != 0) {
    fprintf(stderr, "  status %d\n  stdout: %s\n  stderr: %s\n", r.status, r.out, r.err);
  }
  /* the file names the level that ran (the one place it is stored: the robot's leg type),
   * the default model (strain legs at 2 bending modes per segment on the 23-mode
   * symmetric-mesh table under rbf-pair) and keeps the stage timers: the strain level's
   * adaptive step crosses 0.05 s in at least the 10 steps of its 5 ms grid, and the tree stage
   * runs at least once per grid step */
  H5Eset_auto2(H5E_DEFAULT, NULL, NULL);
  hid_t f = H5Fopen("runcli_ok.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    char level[32] = "";
    CS_EXPECT(H5LTget_attribute_string(f, "/", "leg_model", level) >= 0);
    CS_EXPECT(!strcmp(level, "strain"));
    char cal[1024] = "", rule[32] = "";
    double links = 0;
    CS_EXPECT(H5LTget_attribute_string(f, "/", "calibration", cal) >= 0 &&
              strstr(cal, "robot/calibration_fe_leg_modes_sym.h5") != NULL);
    CS_EXPECT(H5LTget_attribute_string(f, "/", "calibration_rule", rule) >= 0 &&
              !strcmp(rule, "rbf-pair"));
    CS_EXPECT(H5LTget_attribute_double(f, "/", "links_per_segment", &links) >= 0 && links == 2);
    double calls = 0, wall = -1, steps = 0;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "timer_legs_calls", &calls) >= 0);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "timer_support_s", &wall) >= 0);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "steps", &steps) >= 0);
    CS_EXPECT(steps >= 10 && calls >= 10 && wall >= 0);
    /* the paper's scene under its own default conditions, recorded */
    char cond[32] = "";
    double weightless = -1;
    CS_EXPECT(H5LTget_attribute_string(f, "/", "conditions", cond) >= 0 && !strcmp(cond, "paper"));
    CS_EXPECT(H5LTget_attribute_double(f, "/", "legs_weightless", &weightless) >= 0 &&
              weightless == 1);
    H5Fclose(f);
  }
  CS_EXPECT(strstr(r.out, "verdict (paper, strain legs): stands") != NULL);
  CS_EXPECT(cs_cliFileExists("runcli_ok.xdmf"));
  remove("runcli_ok.h5");
  remove("runcli_ok.xdmf");
  /* a user's gait defaults to earth; --conditions overrides (the banner says which) */
  char gargs[1024];
  snprintf(gargs, sizeof gargs, "run --t-end 0.02 --out runcli_earth.h5 --gait %s/gaits/"
           "flat_road_paper.csv", getenv("CS_SOURCE_DIR") ? getenv("CS_SOURCE_DIR") : ".");
  cs_cliRun(exe_path, gargs, "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.err, "conditions earth (default for user files)") != NULL);
  strncat(gargs, " --conditions paper", sizeof gargs - strlen(gargs) - 1);
  cs_cliRun(exe_path, gargs, "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.err, "conditions paper (--conditions)") != NULL);
  /* the flat road's own gait follows the conditions: under `earth` the wave designed for them
   * (gaits/flat_road_earth.csv), under `paper` the searched one (sim_scene.c) */
  cs_cliRun(exe_path, "run --t-end 0.02 --out runcli_earth.h5 --conditions earth", "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.err, "gaits/flat_road_earth.csv") != NULL &&
            strstr(r.err, "conditions earth (--conditions)") != NULL);
  cs_cliRun(exe_path, "run --t-end 0.02 --out runcli_earth.h5 --conditions paper", "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.err, "gaits/flat_road_rod.csv") != NULL);
  remove("runcli_earth.h5");
  remove("runcli_earth.xdmf");
  /* a macro step of 20 ODE steps: the output interval follows it (0.02 s > 0.01 s) */
  cs_cliRun(exe_path, "run --t-end 0.04 --quiet --legs rod --macro-steps 20 --coupling stabilised "
            "--out runcli_macro.h5", "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.out, "final t = 0.040 s") == r.out);
  f = H5Fopen("runcli_macro.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    double H = 0;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "macro_step_s", &H) >= 0);
    CS_EXPECT_NEAR(H, 0.02, 1e-15, 0);
    hsize_t dims[1] = {0};
    CS_EXPECT(H5LTget_dataset_info(f, "/time", dims, NULL, NULL) >= 0 && dims[0] == 3);
    H5Fclose(f);
  }
  remove("runcli_macro.h5");
  remove("runcli_macro.xdmf");
  /* --rod-tol: the rod legs' CVODE tolerances x K, recorded in the output */
  cs_cliRun(exe_path, "run --t-end 0.01 --quiet --legs rod --rod-tol 10 --out runcli_rodtol.h5",
            "runcli", &r);
  CS_EXPECT(r.status == 0);
  f = H5Fopen("runcli_rodtol.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    double k = 0;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "rod_tolerance_scale", &k) >= 0 && k == 10);
    H5Fclose(f);
  }
  remove("runcli_rodtol.h5");
  remove("runcli_rodtol.xdmf");
  /* --cal-rule: the obstacle scene's FE mode table with another rule than its rbf-pair,
   * recorded in the output and the banner */
  cs_cliRun(exe_path, "run --scene obstacle --t-end 0.01 --cal-rule prism "
            "--out runcli_calrule.h5", "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.err, "calibration (rule prism): FE mode table "
                                    "(superposition") != NULL);
  expectAttrString("runcli_calrule.h5", "calibration_rule", "prism");
  remove("runcli_calrule.h5");
  remove("runcli_calrule.xdmf");
  /* --cal-drop: the rod legs leave the stretch out; the banner and the output say so */
  cs_cliRun(exe_path, "run --legs rod --t-end 0.01 --cal-drop stretch --out runcli_caldrop.h5",
            "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.err, "calibration parts left out (--cal-drop): stretch\n"));
  expectAttrString("runcli_caldrop.h5", "calibration_dropped", "stretch");
  remove("runcli_caldrop.h5");
  remove("runcli_caldrop.xdmf");
  /* --legs auto picks from the measured table and needs a tolerance (tests/tools/
   * test_levels_cli.c checks the pick); without --tol it is one error line */
  cs_cliRun(exe_path, "run --t-end 0.01 --quiet --legs auto --out runcli_auto.h5", "runcli", &r);
  CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err) && strstr(r.err, "needs --tol MM") != NULL);
  CS_EXPECT(!cs_cliFileExists("runcli_auto.h5"));
  /* --help: usage on stdout, exit 0 */
  cs_cliRun(exe_path, "run --help", "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.out, "usage: crawlsim run") == r.out && !r.err[0]);
}


/* issue 36: `gait check` checks a gait against the calibration `run` loads with the same
 * options, so the two agree: a chamber at 0.45 MPa is refused by both (the flat road's table
 * ends at 0.4 MPa), one at 0.35 MPa accepted by both; --pressure-scale counts in the check and
 * --calibration none skips it */
static void test_gaitCheckAgreesWithRun(void) {
  CS_EXPECT(cs_cliWriteText("runcli_hi.csv", "time,A_II1_O1\n0,0.45\n0.5,0.45\n"));
  CS_EXPECT(cs_cliWriteText("runcli_lo.csv", "time,A_II1_O1\n0,0.35\n0.5,0.35\n"));
  csCliResult r;
  cs_cliRun(exe_path, "gait check runcli_hi.csv", "runcli", &r);
  CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err) &&
            strstr(r.err, "crawlsim gait check: runcli_hi.csv: row at t = 0 s: chamber A_II1_O1 "
                          "at 0.45 MPa is above the calibrated range (up to 0.4 MPa)") == r.err);
  cs_cliRun(exe_path, "run --legs rod --links 2 --rod-tol 20 --t-end 0.5 --quiet --gait "
            "runcli_hi.csv --out "
            "runcli_hi.h5", "runcli", &r);
  CS_EXPECT(r.status == 1 && strstr(r.err, "is above the calibrated range (up to 0.4 MPa)"));
  cs_cliRun(exe_path, "gait check runcli_lo.csv", "runcli", &r);
  CS_EXPECT(r.status == 0 && strstr(r.out, "within the calibrated range (up to 0.4 MPa)"));
  cs_cliRun(exe_path, "run --legs rod --links 2 --rod-tol 20 --t-end 0.5 --quiet --gait "
            "runcli_lo.csv --out "
            "runcli_lo.h5", "runcli", &r);
  CS_EXPECT(r.status == 0);
  cs_cliRun(exe_path, "gait check runcli_lo.csv --pressure-scale 1.2", "runcli", &r);
  CS_EXPECT(r.status == 1 && strstr(r.err, "at 0.42 MPa is above the calibrated range"));
  cs_cliRun(exe_path, "gait check runcli_hi.csv --calibration none", "runcli", &r);
  CS_EXPECT(r.status == 0 && !strstr(r.out, "calibrated range"));
  const char* files[] = {"runcli_hi.csv", "runcli_lo.csv", "runcli_hi.h5", "runcli_hi.xdmf",
                         "runcli_lo.h5", "runcli_lo.xdmf"};
  for (size_t k = 0; k < sizeof files / sizeof files[0]; k++) remove(files[k]);
}


/* `--legs strain`: the tree coupling at the level's adaptive step (its default, cs_rundef.c
 * stepAdaptive) and bending modes, recorded in the file (leg_model, coupling, step_s,
 * leg_step_s, leg_step_adaptive and its tolerance, leg_step_order, links_per_segment, the
 * basis); --dt fixes the step (the tree timer's calls), --step-order 2 as run (fixed),
 * --strain-step adaptive with a tolerance recorded (its counts), --strain-sub recorded, and
 * their words refused; the coupling refused for other levels and with more than one ODE step
 * per macro step */
static void test_strainRun(void) {
  csCliResult r;
  cs_cliRun(exe_path, "run --t-end 0.02 --quiet --legs strain --out runcli_strain.h5", "runcli",
            &r);
  CS_EXPECT(r.status == 0);
  CS_EXPECT(strstr(r.out, "verdict (paper, strain legs): stands") != NULL);
  if (r.status != 0) {
    fprintf(stderr, "  status %d\n  stdout: %s\n  stderr: %s\n", r.status, r.out, r.err);
  }
  expectAttrString("runcli_strain.h5", "leg_model", "strain");
  expectAttrString("runcli_strain.h5", "coupling", "tree");
  hid_t f = H5Fopen("runcli_strain.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    double step = 0, leg_step = 0, links = 0, ada = 0, tol = 0;
    /* the adaptive step by default: its longest step and cs_step's grid 5 ms (cs_rundef.c
     * CS_ADAPTIVE_MAX_STEP_S), its tolerance sim_driver.c's default (cs_defaultOptions
     * step_tol, 2.5e-4 mm) */
    CS_EXPECT(H5LTget_attribute_double(f, "/", "step_s", &step) >= 0 && step == 5e-3);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_s", &leg_step) >= 0 &&
              leg_step == 5e-3);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_adaptive", &ada) >= 0 && ada == 1);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_tol_mm", &tol) >= 0 &&
              tol == 2.5e-4);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "links_per_segment", &links) >= 0 && links == 2);
    /* the level's default basis (robot_strain_leg.c: 2 bending modes per segment,
     * constant-curvature joints, shears as unknowns, sub-intervals by the basis:
     * csr_strainSubIntervals, 2 per flexible piece at 2 modes) */
    double joints = -9, shear = -9, sub = -9;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "strain_joint_order", &joints) >= 0 &&
              joints == 0);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "strain_shear", &shear) >= 0 && shear == 1);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "strain_sub_intervals", &sub) >= 0 && sub == 2);
    /* the calibration exact by default (robot_strain.h cal_quantum 0: no pressure lattice) */
    double calq = -9;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "strain_cal_quantum", &calq) >= 0 && calq == 0);
    double order = 0;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_order", &order) >= 0 && order == 1);
    H5Fclose(f);
  }
  remove("runcli_strain.h5");
  remove("runcli_strain.xdmf");
  /* --dt fixes the step: every step 0.5 ms (0.02 s: 40 tree steps), no adaptive record; and
   * --strain-sub 4 as run */
  cs_cliRun(exe_path,
            "run --t-end 0.02 --quiet --legs strain --dt 5e-4 --strain-sub 4 "
            "--out runcli_strain1.h5", "runcli", &r);
  CS_EXPECT(r.status == 0);
  f = H5Fopen("runcli_strain1.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    double step = 0, tree_calls = 0, sub = -9;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "step_s", &step) >= 0 && step == 5e-4);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "timer_tree_calls", &tree_calls) >= 0 &&
              tree_calls == 40);
    double ada = -9;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_adaptive", &ada) >= 0 && ada == 0);
    CS_EXPECT(H5Aexists(f, "leg_step_tol_mm") == 0);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "strain_sub_intervals", &sub) >= 0 && sub == 4);
    H5Fclose(f);
  }
  remove("runcli_strain1.h5");
  remove("runcli_strain1.xdmf");
  /* --step-order 2 runs BDF2 (a fixed step: the estimate is backward Euler's) and the file
   * says so */
  cs_cliRun(exe_path,
            "run --t-end 0.02 --quiet --legs strain --step-order 2 --out runcli_strain2.h5",
            "runcli", &r);
  CS_EXPECT(r.status == 0);
  f = H5Fopen("runcli_strain2.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    double order = 0;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_order", &order) >= 0 && order == 2);
    double ada = -9;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_adaptive", &ada) >= 0 && ada == 0);
    H5Fclose(f);
  }
  remove("runcli_strain2.h5");
  remove("runcli_strain2.xdmf");
  /* --strain-step adaptive: its longest step 5 ms (the macro step, the file's step_s), its
   * tolerance and counts in the file; its words refused in one line each */
  cs_cliRun(exe_path,
            "run --t-end 0.02 --quiet --legs strain --strain-step adaptive --step-tol 0.002 "
            "--out runcli_strain3.h5", "runcli", &r);
  CS_EXPECT(r.status == 0);
  f = H5Fopen("runcli_strain3.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    double ada = 0, tol = 0, step = 0, nacc = 0, hmax = 0;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_adaptive", &ada) >= 0 && ada == 1);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "leg_step_tol_mm", &tol) >= 0 && tol == 0.002);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "step_s", &step) >= 0 && step == 5e-3);
    /* settling and run: 64 macro steps of 5 ms, each one or more accepted steps */
    CS_EXPECT(H5LTget_attribute_double(f, "/", "adaptive_steps", &nacc) >= 0 && nacc >= 64);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "adaptive_h_max_s", &hmax) >= 0 &&
              hmax > 0 && hmax <= 5e-3 * (1 + 1e-9));
    H5Fclose(f);
  }
  remove("runcli_strain3.h5");
  remove("runcli_strain3.xdmf");
  expectFailure("--legs strain --strain-step sometimes",
                "crawlsim run: unknown --strain-step 'sometimes' (expected fixed or adaptive)");
  expectFailure("--legs strain --dt 0.001 --step-tol 0.01",
                "crawlsim run: --step-tol goes with the adaptive strain step");
  expectFailure("--legs strain --strain-step fixed --step-tol 0.01",
                "crawlsim run: --step-tol goes with the adaptive strain step");
  expectFailure("--legs rod --strain-sub 2",
                "crawlsim run: --strain-sub is for strain legs, not rod");
  /* a count is whole and in the level's range (0: by the basis) */
  expectFailure("--legs strain --strain-sub 1.5",
                "crawlsim run: --strain-sub 1.5 must be a whole number");
  expectFailure("--legs strain --strain-sub 17",
                "crawlsim run: legs strain: sub 17 must be a whole number in 0..16");
  expectFailure("--legs strain --strain-sub 2.5",
                "crawlsim run: --strain-sub 2.5 must be a whole number");
  expectFailure("--legs strain --strain-sub 17", "crawlsim run: legs strain: sub 17");
  expectFailure("--legs strain --strain-step adaptive --step-tol 0",
                "crawlsim run: --step-tol 0 mm must be > 0 and <= 100");
  expectFailure("--legs rod --strain-step adaptive",
                "crawlsim run: --strain-step adaptive needs a tree-stepped leg level");
  expectFailure("--legs strain --strain-step adaptive --step-order 2",
                "crawlsim run: --strain-step adaptive estimates backward Euler's error");
  expectFailure("--legs strain --step-order 3", "crawlsim run: --step-order 3 must be 1 or 2");
  expectFailure("--legs rod --coupling tree", "crawlsim run: --coupling tree needs a tree-stepped");
  expectFailure("--legs strain --macro-steps 2", "crawlsim run: the tree coupling needs");
  expectFailure("--legs strain --links 8",
                "crawlsim run: legs strain: links 8 must be a whole number in 1..7 (bending "
                "modes per segment)");
}


int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_run_cli <path of crawlsim> [case filter]\n");
    return 1;
  }
  exe_path = argv[1];
  cs_testInit(argc - 1, argv + 1); /* argv[2], if any, is the case filter */
  CS_RUN(test_badOptions);
  CS_RUN(test_badFiles);
  CS_RUN(test_badCalibration);
  CS_RUN(test_goodRun);
  CS_RUN(test_bannerStatesTrackError);
  CS_RUN(test_gaitCheckAgreesWithRun);
  CS_RUN(test_strainRun);
  return cs_testSummary();
}

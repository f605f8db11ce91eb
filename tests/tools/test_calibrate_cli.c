/* test_calibrate_cli.c: `crawlsim calibrate` end to end on a small actuator (argv[1] is the
 * executable): two calibration cases run into their own files, a second call skips them
 * (resume), the merged table carries the format, the actuator and the cases; with modes still
 * to run the table is not yet usable by the legs, which the command says (exit 0) and the
 * reader refuses naming the missing mode; `crawlsim run` with a table that does not cover the
 * gait's pressures stops naming time, chamber and range instead of extrapolating; bad options
 * exit 1 with one line. The actuator is the `leg` shortened to 15 mm segments (9 fibre turns,
 * c = 3 mm) at l_soft 5 mm, cases O12 and G capped at 0.05 MPa in one row: ~30 s.
 * merge_reports_the_model: synthetic case files of every case (tests/robot/
 * test_calibration_synth.h: an exact single-chamber superposition, which the default rule
 * returns everywhere) merged with --merge-only: the command prints the model's report (fitted
 * modes, held-out cases meeting the target, the rules compared, stiffness) and --model-out
 * writes the predictions. Needs POSIX for tests/cs_cli.h and mkdir. */
#define _POSIX_C_SOURCE 200809L

#include <hdf5.h>
#include <hdf5_hl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include <sys/stat.h>

#include "cs_cli.h"
#include "cs_test.h"
#include "fem_calibration.h"
#include "robot/test_calibration_synth.h"
#include "robot_calibration.h"

static const char* exe_path = NULL;

#define SMALL_BASE                                                                           \
  "--set S1=15 --set S2=15 --set S3=15 --set n1=9 --set n2=9 --set n3=9 --set c=3 "           \
  "--mesh-size 5 --p-max 0.05 --p-step 0.05 --dir calib_cases"
#define SMALL_SETS SMALL_BASE " --case O12 --case G"


static int fileExists(const char* path) {
  FILE* f = fopen(path, "rb");
  if (f) {
    fclose(f);
  }
  return f != NULL;
}


static void test_calibrate_runs_resumes_and_merges(void) {
  remove("calib_cases/O12.h5");
  remove("calib_cases/G.h5");
  remove("calib_small.h5");
  csCliResult r;
  cs_cliRun(exe_path, "calibrate --out calib_small.h5 " SMALL_SETS, "calibrate", &r);
  CS_EXPECT(r.status == 0);
  CS_EXPECT(strstr(r.out, "2 cases run, 0 already done") != NULL);
  /* two of twelve cases: the modes the model needs are still to run */
  CS_EXPECT(strstr(r.out, "not usable by the legs until every mode is finished") != NULL);
  CS_EXPECT(strstr(r.out, "has no finished mode case O1 ") != NULL);
  CS_EXPECT(fileExists("calib_cases/O12.h5") && fileExists("calib_cases/G.h5"));
  CS_EXPECT(!fileExists("calib_cases/O12.h5.part"));
  /* a second call finds both cases finished and only merges */
  cs_cliRun(exe_path, "calibrate --out calib_small.h5 " SMALL_SETS, "calibrate", &r);
  CS_EXPECT(r.status == 0);
  CS_EXPECT(strstr(r.out, "0 cases run, 2 already done") != NULL);
  /* the merged table: format, the actuator, both cases with their rows */
  hid_t f = H5Fopen("calib_small.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    char fmt[64] = "";
    CS_EXPECT(H5LTget_attribute_string(f, "/", "format", fmt) >= 0 &&
              !strcmp(fmt, "crawlsim-fe-calibration 1"));
    double S1 = 0, p[2] = {NAN, NAN};
    CS_EXPECT(H5LTget_attribute_double(f, "/", "S1", &S1) >= 0 && S1 == 15);
    char law[32] = "";
    CS_EXPECT(H5LTget_attribute_string(f, "/", "fe_fibre_law", law) >= 0 &&
              !strcmp(law, "tension-only")); /* the default */
    CS_EXPECT(H5LTread_dataset_double(f, "/cases/O12/pressure", p) >= 0);
    CS_EXPECT(p[0] == 0 && fabs(p[1] - 0.05) < 1e-12);
    double bend[12];
    CS_EXPECT(H5LTread_dataset_double(f, "/cases/O12/bend", bend) >= 0);
    /* Omega1&Omega2 bend each segment towards -e1 (docs/reference.md: towards Omega3&Omega4) */
    for (int s = 0; s < 3; s++) {
      CS_EXPECT(bend[6 + 2 * s] < 0);
      /* ... with a side component of mesh asymmetry only (measured < 2 % of the bend) */
      CS_EXPECT(fabs(bend[6 + 2 * s + 1]) < 0.05 * fabs(bend[6 + 2 * s]));
    }
    H5Fclose(f);
  }
  /* for the same actuator the reader refuses it only for the modes it lacks */
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "leg", &err) == CS_OK);
  const char* sets[] = {"S1=15", "S2=15", "S3=15", "n1=9", "n2=9", "n3=9", "c=3"};
  for (int k = 0; k < 7; k++) {
    CS_EXPECT(csr_actuatorSetString(&act, sets[k], &err) == CS_OK);
  }
  csrCalibration* cal = csr_calibrationOpen("calib_small.h5", &act, &err);
  CS_EXPECT(cal == NULL && strstr(err.msg, "calib_small.h5: the table has no finished mode case "
                                  "O1 (chambers at 1:0:0:0)") != NULL);
  csr_calibrationClose(cal);
  /* the wrong actuator (the unmodified leg) is refused */
  csrActuator leg;
  CS_EXPECT(csr_actuatorPreset(&leg, "leg", &err) == CS_OK);
  csrCalibration* wrong = csr_calibrationOpen("calib_small.h5", &leg, &err);
  CS_EXPECT(wrong == NULL && strstr(err.msg, "another actuator") != NULL);
  csr_calibrationClose(wrong);
  /* another fibre law: the finished G (tension-only) is not reused but runs again, and the
   * table holds only the case files of that law (O12 is left out) */
  cs_cliRun(exe_path, "calibrate --out calib_small.h5 --fibre-law linear --case G " SMALL_BASE,
            "calibrate", &r);
  int ncase = 0;
  (void)csf_calibrationCases(&ncase);
  char want1[64];
  snprintf(want1, sizeof want1, "1 cases run, 0 already done, 1 of %d", ncase);
  CS_EXPECT(r.status == 0 && strstr(r.out, want1) != NULL);
  f = H5Fopen("calib_small.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    char law[32] = "";
    CS_EXPECT(H5LTget_attribute_string(f, "/", "fe_fibre_law", law) >= 0 &&
              !strcmp(law, "linear"));
    CS_EXPECT(H5Lexists(f, "/cases/G", H5P_DEFAULT) > 0 &&
              H5Lexists(f, "/cases/O12", H5P_DEFAULT) <= 0);
    H5Fclose(f);
  }

  /* a table must cover the gait: an analytic sweep of the leg to 0.1 MPa is a valid table, and
   * the shipped gait's pressures are above it, so the run stops naming time, chamber and range,
   * and keeps what it wrote */
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
  remove("calib_leg.h5");
  remove("calib_run.h5");
  remove("calib_small.h5");
}


/* a linear single-chamber response superposed: the default rule returns it everywhere */
static void truthLinear(const void* ctx, int seg, const double p[4], double bend[2],
                        double* stretch, double* radial, double* radmax) {
  (void)ctx;
  const double g1 = (1.2 + 0.1 * seg) * (p[0] - p[2]), g2 = (1.2 + 0.1 * seg) * (p[1] - p[3]);
  bend[0] = -(g1 + g2) / sqrt(2.0);
  bend[1] = -(g1 - g2) / sqrt(2.0);
  *stretch = 1 + 0.02 * (p[0] + p[1] + p[2] + p[3]);
  *radial = 0.004 * (p[0] + p[1] + p[2] + p[3]);
  *radmax = 0.3 * (p[0] + p[1] + p[2] + p[3]);
}

static void stiffLinear(const void* ctx, int seg, double pbar, double* EI, double* EA) {
  (void)ctx;
  *EI = (3000 + 100 * seg) * (1 + pbar);
  *EA = 200 * (1 + 2 * pbar);
}


static void test_merge_reports_the_model(void) {
  csrActuator leg;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&leg, "leg", &err) == CS_OK);
  /* one file per case with the command's default FE settings (l_soft 4, rows 0.025 MPa) */
  mkdir("calib_synth_cases", 0777);
  SynthSpec sp = {truthLinear, stiffLinear, NULL, 0.025, 0, 0, 0};
  for (int k = 0; k < SYNTH_NCASE; k++) {
    char path[128];
    snprintf(path, sizeof path, "calib_synth_cases/%s.h5", kSynthCases[k].name);
    synthWriteCases(path, &leg, &sp, kSynthCases[k].name);
  }
  csCliResult r;
  cs_cliRun(exe_path, "calibrate --merge-only --dir calib_synth_cases --out calib_synth.h5 "
            "--model-out calib_synth_pred.h5", "calibrate", &r);
  CS_EXPECT(r.status == 0);
  if (r.status != 0) {
    fprintf(stderr, "  status %d, stderr:\n%s\n", r.status, r.err);
  }
  /* every case of fem_calibration.c's list has its synthetic file */
  int ncase = 0;
  (void)csf_calibrationCases(&ncase);
  CS_EXPECT(ncase == SYNTH_NCASE);
  char all[64];
  snprintf(all, sizeof all, "0 cases run, 0 already done, %d of %d finished", ncase, ncase);
  const char* want[] = {all,
                        "FE mode table (superposition + interpolated interactions; 12 modes; "
                        "0..0.5 MPa",
                        "left out of the fit one at a time", "rules compared",
                        "held out (never fitted", "stiffness (probes",
                        "model predictions calib_synth_pred.h5"};
  for (size_t k = 0; k < sizeof want / sizeof want[0]; k++) {
    CS_EXPECT(strstr(r.out, want[k]) != NULL);
    if (!strstr(r.out, want[k])) {
      fprintf(stderr, "  missing '%s' in:\n%s\n", want[k], r.out);
    }
  }
  /* each held-out case meets the target (the truth is the rule's own form) */
  const char* held[8] = {"    H1        holdout ", "    H2        holdout ",
                         "    H3        holdout ", "    H4        holdout ",
                         "    H5        holdout ", "    H6        holdout ",
                         "    H7        holdout ", "    H8        holdout "};
  for (int k = 0; k < 8; k++) {
    const char* line = strstr(r.out, held[k]);
    const char* eol = line ? strchr(line, '\n') : NULL;
    const char* meets = line ? strstr(line, "meets it") : NULL;
    CS_EXPECT(line && eol && meets && meets < eol);
  }
  /* the predictions: every case but the gravity one, H1's 13 rows */
  hid_t f = H5Fopen("calib_synth_pred.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    double tip[13 * 3];
    CS_EXPECT(H5LTread_dataset_double(f, "/cases/H1/tip", tip) >= 0);
    CS_EXPECT(H5Lexists(f, "/cases/G", H5P_DEFAULT) <= 0);
    double a = 0;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "EI_8C10I_Nmm2", &a) >= 0 && a > 0);
    H5Fclose(f);
  }
  /* --report reads the merged table alone and prints the same report (no case files needed) */
  csCliResult rr;
  cs_cliRun(exe_path, "calibrate --report calib_synth.h5", "calibrate", &rr);
  CS_EXPECT(rr.status == 0 && strstr(rr.out, "held out (never fitted") != NULL &&
            strstr(rr.out, "    H8        holdout ") != NULL);
  {
    const char* a = strstr(r.out, "calibration model:");
    const char* b = strstr(rr.out, "calibration model:");
    const size_t n = a && b ? (strlen(a) < strlen(b) ? strlen(a) : strlen(b)) : 0;
    CS_EXPECT(n > 1000 && !strncmp(a, b, n)); /* the same report text (to the buffer's cut) */
  }
  /* --cal-rule: the report is of that rule's model */
  cs_cliRun(exe_path, "calibrate --report calib_synth.h5 --cal-rule rbf-pair", "calibrate", &rr);
  CS_EXPECT(rr.status == 0 && strstr(rr.out, "calibration model: FE mode table (pair-factor "
                                             "superposition + RBF-interpolated") != NULL);
  /* a mode past the prism's hierarchy is an RBF node, left out in the cross-validation, but
   * no part of the prism rule's fit (so not "left out" of it) */
  CS_EXPECT(strstr(rr.out, "    O12O4r05  bend ") != NULL);
  cs_cliRun(exe_path, "calibrate --report calib_synth.h5", "calibrate", &rr);
  CS_EXPECT(rr.status == 0 && strstr(rr.out, "    O12O4r05  not a node of this rule") != NULL);
  cs_cliRun(exe_path, "calibrate --report calib_synth.h5 --cal-rule spline", "calibrate", &rr);
  CS_EXPECT(rr.status == 1 && strstr(rr.err, "unknown --cal-rule 'spline'") != NULL &&
            strchr(rr.err, '\n') == rr.err + strlen(rr.err) - 1);
  cs_cliRun(exe_path, "calibrate --report no_such_table.h5", "calibrate", &rr);
  CS_EXPECT(rr.status == 1 && strstr(rr.err, "no_such_table.h5") != NULL &&
            strchr(rr.err, '\n') == rr.err + strlen(rr.err) - 1);
  /* the cases ran at the default Newton tolerance (1e-6, recorded as fe_newton_rtol): under
   * another one none of them counts as done, so nothing is merged */
  cs_cliRun(exe_path, "calibrate --merge-only --newton-rtol 1e-8 --dir calib_synth_cases "
            "--out calib_synth.h5", "calibrate", &r);
  CS_EXPECT(r.status == 1 && strstr(r.err, "no finished case to merge") != NULL);
  /* nor under turned fibres (the symmetry check's setting; the synthetic files have no
   * fe_fibre_turn_deg, which reads as 0), and a merge of two turns is refused, as is one of two
   * meshes */
  cs_cliRun(exe_path, "calibrate --merge-only --fibre-turn 90 --dir calib_synth_cases "
            "--out calib_synth.h5", "calibrate", &r);
  CS_EXPECT(r.status == 1 && strstr(r.err, "no finished case to merge") != NULL);
  /* nor on the symmetric mesh (fe_mesh_symmetric, absent = 0) */
  cs_cliRun(exe_path, "calibrate --merge-only --mesh-symmetric 1 --dir calib_synth_cases "
            "--out calib_synth.h5", "calibrate", &r);
  CS_EXPECT(r.status == 1 && strstr(r.err, "no finished case to merge") != NULL);
  {
    hid_t t = H5Fopen("calib_synth_cases/O1.h5", H5F_ACC_RDWR, H5P_DEFAULT);
    const double deg = 90;
    CS_EXPECT(t >= 0 && H5LTset_attribute_double(t, "/", "fe_fibre_turn_deg", &deg, 1) >= 0);
    if (t >= 0) H5Fclose(t);
    const char* two[] = {"calib_synth_cases/O12.h5", "calib_synth_cases/O1.h5"};
    CS_EXPECT(csf_calibrationMerge(two, 2, "calib_synth_mixed.h5", &err) == CS_ERR_PARSE);
    CS_EXPECT(strstr(err.msg, "calib_synth_cases/O1.h5: fe_fibre_turn_deg differs from "
                              "calib_synth_cases/O12.h5's (90 against 0)") != NULL);
    const double one = 1, zero = 0;
    t = H5Fopen("calib_synth_cases/O1.h5", H5F_ACC_RDWR, H5P_DEFAULT);
    CS_EXPECT(t >= 0 && H5LTset_attribute_double(t, "/", "fe_fibre_turn_deg", &zero, 1) >= 0 &&
              H5LTset_attribute_double(t, "/", "fe_mesh_symmetric", &one, 1) >= 0);
    if (t >= 0) H5Fclose(t);
    CS_EXPECT(csf_calibrationMerge(two, 2, "calib_synth_mixed.h5", &err) == CS_ERR_PARSE);
    CS_EXPECT(strstr(err.msg, "calib_synth_cases/O1.h5: fe_mesh_symmetric differs from "
                              "calib_synth_cases/O12.h5's (1 against 0)") != NULL);
    remove("calib_synth_mixed.h5");
  }
  for (int k = 0; k < SYNTH_NCASE; k++) {
    char path[128];
    snprintf(path, sizeof path, "calib_synth_cases/%s.h5", kSynthCases[k].name);
    remove(path);
  }
  remove("calib_synth_cases");
  remove("calib_synth.h5");
  remove("calib_synth_pred.h5");
}


static void test_list_names_every_case(void) {
  csCliResult r;
  cs_cliRun(exe_path, "calibrate --list", "calibrate", &r);
  CS_EXPECT(r.status == 0);
  const char* names[] = {"O12", "O1", "O124", "O1234", "O13", "O12r05", "O12O34r3",
                         "O1O234r05", "O1O234r075", "O124O3r05", "O1O23r05O4r025",
                         "O1O3r05", "O12O4r05", "O1O24r05", "O13O2r05", "O1O2r067O4r033",
                         "O13O2r067O4r033", "O1O23r05", "O12O34r05", "O2", "H4t", "H6t", "H7t", "H1", "H2", "H3", "H4", "H5", "H6", "H7", "H8", "G"};
  for (size_t k = 0; k < sizeof names / sizeof names[0]; k++) {
    char want[32];
    snprintf(want, sizeof want, "%s ", names[k]);
    CS_EXPECT(strstr(r.out, want) != NULL);
  }
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
  expectFailure("--bogus 1", "crawlsim calibrate: unknown option --bogus");
  expectFailure("--out", "crawlsim calibrate: option --out needs a value");
  expectFailure("stray", "crawlsim calibrate: unexpected argument 'stray'");
  expectFailure("--p-max 2", "--p-max '2' must be a number in [0.0001, 1]");
  expectFailure("--p-step x", "--p-step 'x' must be a number in");
  expectFailure("--mesh-size -1", "--mesh-size '-1' must be a number in [0.5, 20]");
  expectFailure("--fibre-split 2", "crawlsim calibrate: --fibre-split '2' must be 0 or 1");
  expectFailure("--fibre-turn 45", "calibrate: --fibre-turn '45' must be a multiple of 90");
  expectFailure("--mesh-symmetric 2", "calibrate: --mesh-symmetric '2' must be 0 or 1");
  expectFailure("--fibre-turn 360", "--fibre-turn '360' must be a number in [-270, 270]");
  expectFailure("--fibre-law elastic",
                "crawlsim calibrate: --fibre-law 'elastic' must be linear or tension-only");
  expectFailure("--case Q7", "--case 'Q7': no such case (see --list)");
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
  CS_RUN(test_list_names_every_case);
  CS_RUN(test_merge_reports_the_model);
  CS_RUN(test_calibrate_runs_resumes_and_merges);
  return cs_testSummary();
}

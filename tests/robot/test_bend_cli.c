/* test_bend_cli.c: `crawlsim bend` end to end: runs the real executable (its path is argv[1],
 * from $<TARGET_FILE:crawlsim>) and checks the HDF5 output contract (docs/design.md), that
 * --until-angle is the model's own root of Θ(p) = DEG, and that bad input exits 1 with exactly
 * one line "crawlsim bend: ..." on stderr, nothing on stdout and no output file.
 * The run/capture helpers are tests/cs_cli.h, which needs POSIX (the project builds with
 * C_EXTENSIONS OFF). */
#define _POSIX_C_SOURCE 200809L

#include <hdf5.h>
#include <hdf5_hl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cli.h"
#include "cs_test.h"
#include "robot_analytic.h"

static const char* exe_path = NULL; /* the crawlsim executable (set once in main) */


/* run `crawlsim bend <args>`, stdout/stderr captured via bend_*.txt in the working directory */
static void run(const char* args, csCliResult* r) {
  char full[2048];
  snprintf(full, sizeof full, "bend %s", args);
  cs_cliRun(exe_path, full, "bend", r);
}


/* Θ(p) of the analytic model, Ω1&Ω2 in all segments of the baseline actuator (degrees) */
static double totalAngle(double p) {
  csrActuator act;
  csError err;
  csr_actuatorPreset(&act, "baseline", &err);
  double P[CSR_NSEG * CSR_NCHAMBER] = {p, p, 0, 0, p, p, 0, 0, p, p, 0, 0};
  csrSegmentStrain st[CSR_NSEG];
  CS_EXPECT(csr_analyticActuator(&act, P, st, &err) == CS_OK);
  return (st[0].theta + st[1].theta + st[2].theta) / CS_DEG;
}


static void test_defaultSweep(void) {
  remove("bend_ok.h5");
  csCliResult r;
  run("--out bend_ok.h5 --until-angle 30", &r);
  CS_EXPECT(r.status == 0 && r.err[0] == '\0');
  CS_EXPECT(strstr(r.out, "until-angle: total angle 30 deg at p = ") != NULL);
  hid_t f = H5Fopen("bend_ok.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f < 0) {
    return;
  }
  /* the contract's datasets: p = 0, 0.05, ..., 0.4 MPa (the paper's sweep) */
  hsize_t dims[2] = {0, 0};
  H5T_class_t cls;
  size_t tsize;
  CS_EXPECT(H5LTget_dataset_info(f, "/pressure", dims, &cls, &tsize) >= 0 && dims[0] == 9);
  CS_EXPECT(H5LTget_dataset_info(f, "/tip_position", dims, &cls, &tsize) >= 0 && dims[0] == 9 &&
            dims[1] == 3);
  double p[9], total[9], ang[27];
  CS_EXPECT(H5LTread_dataset_double(f, "/pressure", p) >= 0);
  CS_EXPECT(H5LTread_dataset_double(f, "/angle_total_deg", total) >= 0);
  CS_EXPECT(H5LTread_dataset_double(f, "/angle_deg", ang) >= 0);
  CS_EXPECT_NEAR(p[8], 0.4, 1e-15, 0); /* 8 * 0.05 in binary floating point */
  for (int i = 1; i < 9; i++) {
    CS_EXPECT(total[i] > total[i - 1]);
    /* the total is the sum of the segment angles (paper Eq. 11), to round-off */
    CS_EXPECT_NEAR(total[i], ang[3 * i] + ang[3 * i + 1] + ang[3 * i + 2], 1e-12, 0);
  }
  /* --until-angle: bisection to 1e-9 MPa on the model itself; dΘ/dp ≈ 280 deg/MPa here, so
   * Θ at the reported pressure is 30 deg within 3e-7 deg */
  double pu = 0;
  CS_EXPECT(H5LTget_attribute_double(f, "/", "p_until_angle_MPa", &pu) >= 0);
  CS_EXPECT(pu > 0.1 && pu < 0.15);
  CS_EXPECT_NEAR(totalAngle(pu), 30.0, 1e-6, 0);
  double v = 0;
  CS_EXPECT(H5LTget_attribute_double(f, "/", "mesh_size_mm", &v) >= 0 && isnan(v));
  CS_EXPECT(H5LTget_attribute_double(f, "/", "n_elements_soft", &v) >= 0 && v == 0);
  CS_EXPECT(H5LTget_attribute_double(f, "/", "r1", &v) >= 0 && v == 2);
  CS_EXPECT(H5LTget_attribute_double(f, "/", "wall_time_s", &v) >= 0 && v >= 0);
  char s[64] = "";
  CS_EXPECT(H5LTget_attribute_string(f, "/", "model", s) >= 0 && !strcmp(s, "analytic"));
  CS_EXPECT(H5LTget_attribute_string(f, "/", "actuator", s) >= 0 && !strcmp(s, "baseline"));
  CS_EXPECT(H5LTget_attribute_string(f, "/", "version", s) >= 0 && !strcmp(s, "0.1.0"));
  H5Fclose(f);
  remove("bend_ok.h5");
}


/* --fibre-size / --fibre-split / --fibre-law reach the FE and are stored, with the tangent's
 * inertia: a 12 mm segment variant with two fibre turns, one 0.02 MPa step on a 5 mm mesh
 * (about 2 s each) */
static void test_feFibreOptions(void) {
  const char* tiny = "--model fe --set S1=12 --set S2=12 --set S3=12 --set c=3 --set LS12=4 "
                     "--set LS23=4 --set n1=2 --set n2=2 --set n3=2 --mesh-size 5 --p-max 0.02 "
                     "--p-step 0.02";
  double nfib[2] = {0, 0};
  for (int split = 0; split <= 1; split++) {
    remove("bend_fib.h5");
    char args[512];
    snprintf(args, sizeof args, "%s --fibre-split %d --fibre-size 0.75 --fibre-law %s --out "
             "bend_fib.h5", tiny, split, split ? "tension-only" : "linear");
    csCliResult r;
    run(args, &r);
    CS_EXPECT(r.status == 0);
    hid_t f = H5Fopen("bend_fib.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
    CS_EXPECT(f >= 0);
    if (f < 0) {
      continue;
    }
    double v = -1;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "fe_fibre_size_mm", &v) >= 0 && v == 0.75);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "fe_fibre_split", &v) >= 0 && v == split);
    char law[32] = "";
    CS_EXPECT(H5LTget_attribute_string(f, "/", "fe_fibre_law", law) >= 0 &&
              !strcmp(law, split ? "tension-only" : "linear"));
    /* one small step from rest: a stable state, positive definite tangent */
    CS_EXPECT(H5LTget_attribute_double(f, "/", "fe_neg_pivots_max", &v) >= 0 && v == 0);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "fe_p_indefinite_MPa", &v) >= 0 && isnan(v));
    CS_EXPECT(H5LTget_attribute_double(f, "/", "n_elements_fibre", &nfib[split]) >= 0);
    /* the free surfaces (fem_wall.h): one 0.02 MPa step bends this actuator ~1 deg, so the
     * vented chambers' walls are barely compressed (measured lam_eq 0.99) and far from the
     * crease onset, and their gap has not closed (it shrinks by ~1 %) */
    double crease = NAN, leq = NAN, gap = NAN, gap0 = NAN;
    CS_EXPECT(H5LTget_attribute_double(f, "/", "fe_crease_stretch", &crease) >= 0);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "fe_vented_lam_eq", &leq) >= 0);
    CS_EXPECT(leq > crease && leq <= 1.0);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "fe_p_crease_MPa", &v) >= 0 && isnan(v));
    CS_EXPECT(H5LTget_attribute_double(f, "/", "fe_vented_gap_mm", &gap) >= 0);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "fe_vented_gap0_mm", &gap0) >= 0);
    CS_EXPECT(gap > 0.9 * gap0 && gap0 > 0);
    CS_EXPECT(strstr(r.err, "vented chambers' walls at the end") != NULL);
    H5Fclose(f);
  }
  /* split at the tets' faces: more, shorter pieces than one element per 0.75 mm */
  CS_EXPECT(nfib[1] > nfib[0] && nfib[0] > 0);
  remove("bend_fib.h5");
  /* a mesh-free model writes none of them */
  csCliResult r;
  run("--out bend_fib.h5", &r);
  hid_t f = H5Fopen("bend_fib.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    CS_EXPECT(H5Aexists(f, "fe_fibre_split") == 0 && H5Aexists(f, "fe_neg_pivots_max") == 0);
    H5Fclose(f);
  }
  remove("bend_fib.h5");
}


static void test_sweepOptions(void) {
  /* p-max off the step grid is the last row; --set and --chambers reach the model */
  remove("bend_opt.h5");
  csCliResult r;
  run("--actuator fig1 --set r1=2.5 --set b=3 --chambers 4,1 --p-max 0.12 --p-step 0.05 "
      "--out=bend_opt.h5",
      &r);
  CS_EXPECT(r.status == 0);
  CS_EXPECT(strstr(r.out, "chambers 1,4") != NULL);
  hid_t f = H5Fopen("bend_opt.h5", H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(f >= 0);
  if (f >= 0) {
    double p[4] = {0}, tip[12] = {0}, v = 0;
    CS_EXPECT(H5LTread_dataset_double(f, "/pressure", p) >= 0);
    CS_EXPECT(p[2] == 0.1 && p[3] == 0.12);
    CS_EXPECT(H5LTget_attribute_double(f, "/", "r1", &v) >= 0 && v == 2.5);
    /* Ω1&Ω4 sit at +e2: the tip moves to -e2 only */
    CS_EXPECT(H5LTread_dataset_double(f, "/tip_position", tip) >= 0);
    CS_EXPECT(tip[3 * 3 + 1] < 0 && fabs(tip[3 * 3]) < 1e-9 * fabs(tip[3 * 3 + 1]));
    H5Fclose(f);
  }
  remove("bend_opt.h5");
  /* a target above the search ceiling: NaN and a line saying so, still exit 0 */
  run("--until-angle 5000 --out bend_far.h5", &r);
  CS_EXPECT(r.status == 0);
  CS_EXPECT(strstr(r.out, "total angle 5000 deg not reached up to 2 MPa") != NULL);
  remove("bend_far.h5");
  run("--help", &r);
  CS_EXPECT(r.status == 0 && strstr(r.out, "usage: crawlsim bend") == r.out);
}


/* bad input: exit 1, one line on stderr starting with `want`, nothing on stdout, no file */
static void expectFailure(const char* args, const char* want) {
  remove("bend_bad.h5");
  char full[1024];
  snprintf(full, sizeof full, "%s --out bend_bad.h5", args);
  csCliResult r;
  run(full, &r);
  CS_EXPECT(r.status == 1);
  CS_EXPECT(r.out[0] == '\0');
  CS_EXPECT(cs_cliOneLine(r.err));
  CS_EXPECT(strstr(r.err, want) == r.err);
  CS_EXPECT(!cs_cliFileExists("bend_bad.h5"));
  if (r.status != 1 || strstr(r.err, want) != r.err) {
    fprintf(stderr, "  args '%s': status %d, stderr: %s", args, r.status, r.err);
  }
}


static void test_badInput(void) {
  expectFailure("--model prb", "crawlsim bend: --model prb: the prb level was retired "
                "(2026-12-06): off the speed/accuracy front (docs/studies/speed_accuracy.md); "
                "use rod (the default) or strain");
  /* the reduced FE needs its basis (tools/rom_basis.py; test_rom_cli has the rest) */
  expectFailure("--model rom", "crawlsim bend: --model rom needs --rom-basis FILE");
  expectFailure("--model xyz", "crawlsim bend: unknown model 'xyz'");
  expectFailure("--frobnicate 1", "crawlsim bend: unknown option --frobnicate");
  expectFailure("stray", "crawlsim bend: unexpected argument 'stray'");
  expectFailure("--branch-switch 2", "crawlsim bend: --branch-switch '2' must be 0 or 1");
  expectFailure("--model analytic --branch-switch 1",
                "crawlsim bend: --branch-switch is for --model fe");
  expectFailure("--mesh-symmetric 2", "crawlsim bend: --mesh-symmetric '2' must be 0 or 1");
  expectFailure("--model rod --mesh-symmetric 1",
                "crawlsim bend: --mesh-symmetric is for --model fe");
  expectFailure("--segments 2", "crawlsim bend: --segments '2' must be 1 or 3");
  expectFailure("--model rod --segments 1", "crawlsim bend: --segments is for --model fe");
  /* a single segment by hand reaches the three-segment models' validation */
  expectFailure("--set S2=0", "crawlsim bend: actuator: S2 = 0 must be > 0 mm");
  expectFailure("--p-max abc", "crawlsim bend: --p-max 'abc' is not a finite number");
  expectFailure("--p-max nan", "crawlsim bend: --p-max 'nan' is not a finite number");
  expectFailure("--p-step 0", "crawlsim bend: --p-step 0 must be > 0 MPa");
  expectFailure("--p-step -0.1", "crawlsim bend: --p-step -0.1 must be > 0 MPa");
  expectFailure("--until-angle 0", "crawlsim bend: --until-angle 0 must be > 0 degrees");
  expectFailure("--chambers 1,5", "crawlsim bend: --chambers '1,5': chamber 5 is not in 1..4");
  expectFailure("--chambers 0", "crawlsim bend: --chambers '0': chamber 0 is not in 1..4");
  expectFailure("--chambers 2,2", "crawlsim bend: --chambers '2,2': chamber 2 is repeated");
  expectFailure("--chambers 1,", "crawlsim bend: --chambers '1,': expected a comma-separated");
  expectFailure("--actuator big", "crawlsim bend: unknown actuator 'big'");
  expectFailure("--set q=1", "crawlsim bend: unknown actuator parameter 'q'");
  expectFailure("--set r1=x", "crawlsim bend: --set 'r1=x': 'x' is not a number");
  expectFailure("--set r1=3.6", "crawlsim bend: actuator: chamber breaks the outer wall");
  expectFailure("--set c=30", "crawlsim bend: actuator: c = 30 mm must be > 0 and < S1/2");
  expectFailure("--fibre-split 0", "crawlsim bend: --fibre-split is for --model fe");
  expectFailure("--fibre-size 1.5", "crawlsim bend: --fibre-size is for --model fe");
  expectFailure("--model fe --fibre-split 2", "crawlsim bend: --fibre-split '2' must be 0 or 1");
  expectFailure("--model fe --fibre-size 0", "crawlsim bend: --fibre-size 0 must be > 0 mm");
  expectFailure("--fibre-law linear", "crawlsim bend: --fibre-law is for --model fe");
  expectFailure("--model fe --fibre-law elastic",
                "crawlsim bend: --fibre-law 'elastic' must be linear or tension-only");
  /* the output path itself: the file cannot be created, and the message says why (errno) */
  csCliResult r;
  run("--out no_such_dir/x.h5", &r);
  CS_EXPECT(r.status == 1 && cs_cliOneLine(r.err) && r.out[0] == '\0');
  CS_EXPECT(strstr(r.err, "crawlsim bend: no_such_dir/x.h5: cannot create (No such file or "
                          "directory)") == r.err);
  run("--chambers", &r); /* a flag without its value */
  CS_EXPECT(r.status == 1 && strstr(r.err, "crawlsim bend: option --chambers needs a value"));
}


int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_bend_cli <path of crawlsim> [case filter]\n");
    return 1;
  }
  exe_path = argv[1];
  cs_testInit(argc - 1, argv + 1); /* argv[2], if any, is the case filter */
  CS_RUN(test_defaultSweep);
  CS_RUN(test_sweepOptions);
  CS_RUN(test_feFibreOptions);
  CS_RUN(test_badInput);
  return cs_testSummary();
}

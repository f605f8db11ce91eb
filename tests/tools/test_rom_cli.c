/* test_rom_cli.c: `crawlsim rom` and `crawlsim bend --model rom` on the command line (argv[1] is
 * the executable), without running the FE.
 *
 * Proves: the ray list holds training and held-out rays; every bad stage, option or file exits
 * 1 with one line on stderr naming the cause (and the file where there is one), and no crash;
 * the subcommands parse from their option tables (--name=VALUE, the nearest option named, a
 * missing value, an operand refused; the rest in tests/tools/test_cli_help.py); rom check's
 * --checkpoint refused with --states and where its directory cannot be made.
 * Needs POSIX for tests/cs_cli.h. */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <string.h>

#include "cs_cli.h"
#include "cs_test.h"

static const char* exe_path = NULL;

/* one line on stderr (its only newline at the end) */
static int oneLine(const char* s) {
  const char* nl = strchr(s, '\n');
  return nl && nl[1] == '\0';
}

static void expectRefused(const char* args, const char* needle) {
  csCliResult r;
  cs_cliRun(exe_path, args, "romcli", &r);
  const int ok = r.status == 1 && oneLine(r.err) && strstr(r.err, needle) != NULL;
  if (!ok) {
    fprintf(stderr, "  `%s`: status %d, stderr: %s\n", args, r.status, r.err);
  }
  CS_EXPECT(ok);
}


static void test_ray_list_has_training_and_held_out_rays(void) {
  csCliResult r;
  cs_cliRun(exe_path, "rom snapshots --list", "romcli", &r);
  CS_EXPECT(r.status == 0);
  int train = 0, test = 0;
  for (const char* p = r.out; (p = strstr(p, " train ")) != NULL; p++) {
    train++;
  }
  for (const char* p = r.out; (p = strstr(p, " test ")) != NULL; p++) {
    test++;
  }
  printf("  %d training rays, %d held-out rays\n", train, test);
  CS_EXPECT(train >= 30 && test >= 5);
  CS_EXPECT(strstr(r.out, "T_H4") != NULL && strstr(r.out, "Fzc") != NULL);
}


static void test_bad_input_is_one_line_and_exit_1(void) {
  expectRefused("rom frobnicate", "unknown stage 'frobnicate'");
  expectRefused("rom snapshots --ray NOPE", "--ray 'NOPE': no such ray");
  expectRefused("rom snapshots --mesh-size 0", "--mesh-size '0'");
  expectRefused("rom snapshots --mesh-size=0", "--mesh-size '0'");
  expectRefused("rom snapshots --mesh-sise 3", "did you mean --mesh-size?");
  expectRefused("rom snapshots --threads", "--threads needs a value");
  expectRefused("rom snapshots stray", "unexpected argument 'stray'");
  expectRefused("rom check --ray NOPE --snapshots . --basis x.h5", "--ray 'NOPE': no such ray");
  expectRefused("rom check --wieghts w.h5", "did you mean --weights?");
  expectRefused("rom ecsw-matrix --basis", "--basis needs a value");
  expectRefused("rom ecsw-matrix --out x.h5", "needs --basis FILE and --out FILE");
  expectRefused("rom ecsw-matrix --basis x.h5 --out x.h5 --stride 0", "--stride '0'");
  expectRefused("rom ecsw-matrix --basis x.h5 --out x.h5 --stride 2.5", "--stride 2.5: not a whole");
  expectRefused("rom ecsw-matrix --basis x.h5 --out x.h5 --only faces", "--only 'faces'");
  expectRefused("rom check --snapshots .", "needs --snapshots DIR and --basis FILE");
  expectRefused("rom check --snapshots . --basis x.h5 --leg-file y.h5", "(or --leg-file FILE");
  expectRefused("rom check --snapshots . --leg-file romcli_missing.h5", "romcli_missing.h5");
  expectRefused("rom check --snapshots . --basis romcli_missing.h5", "romcli_missing.h5");
  /* the check's checkpoints (session romacc, 2026-12-07): refused before any model is read */
  expectRefused("rom check --snapshots . --basis x.h5 --checkpoint ck --states st",
                "--checkpoint and --states together");
  expectRefused("rom check --snapshots . --basis x.h5 --checkpoint romcli_missing/ck",
                "romcli_missing/ck: cannot create the checkpoint directory");
  expectRefused("rom ecsw-matrix --basis romcli_missing.h5 --out x.h5", "romcli_missing.h5");
  expectRefused("rom modes --out x.h5", "needs --basis FILE and --out FILE");
  expectRefused("rom modes --basis x.h5 --out x.h5 --pressure 0.9", "--pressure '0.9'");
  expectRefused("rom modes --basis x.h5 --out x.h5 --ray NOPE", "--ray 'NOPE': no such ray");
  expectRefused("rom modes --basis romcli_missing.h5 --out x.h5", "romcli_missing.h5");
  expectRefused("rom modes --basis x.h5 --out x.h5 --fd-check 2.5",
                "--fd-check '2.5' must be a whole");
  expectRefused("rom modes --basis x.h5 --out x.h5 --fd-check 65",
                "--fd-check '65' must be a number");
  expectRefused("rom leg-file --basis x.h5", "leg-file needs --basis and --out");
  expectRefused("rom leg-file --basis x.h5 --out x.h5 stray", "unexpected argument 'stray'");
  expectRefused("rom leg-file --wieghts w.h5", "did you mean --weights?");
  expectRefused("rom leg-file --basis romcli_missing.h5 --out romcli_leg.h5", "romcli_missing.h5");
  /* a leg file from another one (session romecsw, 2026-12-07): refused before any model is read */
  expectRefused("rom leg-file --leg-file x.h5", "leg-file needs --basis and --out");
  expectRefused("rom leg-file --basis x.h5 --leg-file y.h5 --out z.h5",
                "--basis and --leg-file together");
  expectRefused("rom leg-file --leg-file x.h5 --out x.h5", "--out x.h5 is the --leg-file");
  expectRefused("rom leg-file --leg-file romcli_missing.h5 --out romcli_leg.h5",
                "romcli_missing.h5");
  expectRefused("rom ecsw-matrix --basis x.h5 --leg-file romcli_missing.h5 --out x.h5",
                "romcli_missing.h5");
  expectRefused("rom modes --presure 0.1", "did you mean --pressure?");
  expectRefused("rom sway --load 11", "--load '11'");
  expectRefused("rom sway --load 0.4 --load 0.2", "--load 0.2: the loads must ascend");
  expectRefused("rom sway --fe-load 0.8", "--fe-load needs --leg-file");
  expectRefused("rom sway --rod-elements 2.5", "--rod-elements '2.5' must be a whole number");
  expectRefused("rom sway --fe-fibres 0.5 --fe-mesh-size 8", "--fe-fibres '0.5' must be a whole");
  expectRefused("rom sway --fe-mesh-size 0.5 --fe-load 0.8", "--fe-mesh-size '0.5'");
  expectRefused("rom sway --leg-file romcli_missing.h5 --load 0", "romcli_missing.h5");
  expectRefused("rom sway --lod 0.8", "did you mean --load?");
  expectRefused("bend --model rom --p-max 0.1 --out romcli.h5", "--rom-basis");
  expectRefused("bend --model rom --rom-basis romcli_missing.h5 --out romcli.h5",
                "romcli_missing.h5");
  expectRefused("bend --model analytic --rom-basis x.h5 --out romcli.h5", "--model rom");
  /* a leg file instead of the basis (session romsweep) */
  expectRefused("bend --model rom --rom-file romcli_missing.h5 --p-max 0.1 --out romcli.h5",
                "romcli_missing.h5");
  expectRefused("bend --model rom --rom-file x.h5 --rom-basis y.h5 --out romcli.h5",
                "--rom-file holds the basis and the weights");
  expectRefused("bend --model fe --rom-file x.h5 --out romcli.h5", "--model rom");
  remove("romcli.h5");
}


int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_rom_cli CRAWLSIM\n");
    return 2;
  }
  exe_path = argv[1];
  CS_RUN(test_ray_list_has_training_and_held_out_rays);
  CS_RUN(test_bad_input_is_one_line_and_exit_1);
  return cs_testSummary();
}

/* test_gaits_cli.c: `crawlsim gait check` end to end: runs the real executable (its path is
 * argv[1], from $<TARGET_FILE:crawlsim>) on a good file and on bad ones, and checks the exit
 * status, that a failure prints exactly one line "crawlsim gait check: <file>:<line>: column
 * <c> ..." to stderr and nothing to stdout, and that success prints one summary line.
 * The run/capture helpers are tests/cs_cli.h, which needs POSIX (the project builds with
 * C_EXTENSIONS OFF). */
#define _POSIX_C_SOURCE 200809L

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_cli.h"
#include "cs_test.h"

static const char* exe_path = NULL; /* the crawlsim executable (set once in main) */


/* run `crawlsim <args>`, stdout/stderr captured via gaitcli_*.txt in the working directory */
static void run(const char* args, csCliResult* r) {
  cs_cliRun(exe_path, args, "gaitcli", r);
}


static void test_goodFile(void) {
  CS_EXPECT(cs_cliWriteText("cli_good.csv", "# two rows\ntime,A_II1_O3,22\n0,0.18,0\n1,0,0.3\n"));
  csCliResult r;
  run("gait check cli_good.csv", &r);
  CS_EXPECT(r.status == 0);
  CS_EXPECT(cs_cliOneLine(r.out) && r.err[0] == '\0');
  CS_EXPECT(strstr(r.out, "2 rows") && strstr(r.out, "2 of 96 chambers used") &&
            strstr(r.out, "max pressure 0.3 MPa") && strstr(r.out, "duration 1 s"));
  if (r.status != 0) {
    fprintf(stderr, "  stdout: %s  stderr: %s\n", r.out, r.err);
  }
}


/* a bad file: exit 1, one line on stderr naming file, line and column, nothing on stdout */
static void expectFailure(const char* args, const char* want) {
  csCliResult r;
  run(args, &r);
  CS_EXPECT(r.status == 1);
  CS_EXPECT(r.out[0] == '\0');
  CS_EXPECT(cs_cliOneLine(r.err));
  CS_EXPECT(strstr(r.err, want) == r.err);
  if (r.status != 1 || strstr(r.err, want) != r.err) {
    fprintf(stderr, "  status %d, stderr: %s", r.status, r.err);
  }
}


static void test_badFiles(void) {
  CS_EXPECT(cs_cliWriteText("cli_bad_pressure.csv", "time,A_II1_O1,A_II1_O2\n0,0,0\n1,0,-0.1\n"));
  expectFailure("gait check cli_bad_pressure.csv",
                "crawlsim gait check: cli_bad_pressure.csv:3: column 3 (A_II1_O2): negative");
  CS_EXPECT(cs_cliWriteText("cli_bad_time.csv", "time,1\r\n0,0\r\n0,0\r\n"));
  expectFailure("gait check cli_bad_time.csv", "crawlsim gait check: cli_bad_time.csv:3: column 1");
  CS_EXPECT(cs_cliWriteText("cli_bad_column.csv", "time,A_II1_O1,X\n0,0,0\n"));
  expectFailure("gait check cli_bad_column.csv",
                "crawlsim gait check: cli_bad_column.csv:1: column 3: unknown column 'X'");
  /* the limit flag moves the pressure check */
  CS_EXPECT(cs_cliWriteText("cli_high.csv", "time,1\n0,0.5\n"));
  expectFailure("gait check cli_high.csv --max-pressure 0.4",
                "crawlsim gait check: cli_high.csv:2: column 2 (A_II1_O1): pressure above");
  remove("cli_missing.csv");
  expectFailure("gait check cli_missing.csv", "crawlsim gait check: cli_missing.csv: cannot open");
}


static void test_badUsage(void) {
  expectFailure("gait check", "crawlsim gait check: missing FILE.csv");
  expectFailure("gait check a.csv b.csv", "crawlsim gait check: more than one file");
  expectFailure("gait check --frobnicate cli_good.csv", "crawlsim gait check: unknown option");
  expectFailure("gait check cli_good.csv --max-pressure", "crawlsim gait check: option --max-pressure needs a value");
  expectFailure("gait check cli_good.csv --max-rows 1.5", "crawlsim gait check: --max-rows");
  expectFailure("gait", "crawlsim gait: missing subcommand");
  expectFailure("gait frob", "crawlsim gait: unknown subcommand 'frob'");
  csCliResult r;
  run("gait --help", &r);
  CS_EXPECT(r.status == 0 && strstr(r.out, "check FILE.csv"));
}


int main(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "usage: test_gaits_cli <path of crawlsim> [case filter]\n");
    return 1;
  }
  exe_path = argv[1];
  cs_testInit(argc - 1, argv + 1); /* argv[2], if any, is the case filter */
  CS_RUN(test_goodFile);
  CS_RUN(test_badFiles);
  CS_RUN(test_badUsage);
  return cs_testSummary();
}

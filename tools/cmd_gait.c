/* cmd_gait.c: `crawlsim gait <sub> ...`, the gait-table subcommands.
 *
 *   crawlsim gait check FILE.csv [--max-pressure MPA] [--max-rows N]
 *     reads and validates a gait CSV (gaits_csv.h); prints one summary line to stdout and
 *     returns 0, or prints "crawlsim gait check: <file>:<line>: ..." to stderr and returns 1.
 *
 * Each subcommand is one function in kSubcommands below, so adding one (e.g. a generator's
 * write-<name>) is one entry. */
#include <ctype.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_commands.h"
#include "gaits_csv.h"

static const char kUsage[] =
    "usage: crawlsim gait <subcommand> ...\n"
    "  check FILE.csv [--max-pressure MPA] [--max-rows N]\n"
    "      validate a gait table (time s, 96 chamber pressures MPa) and summarise it;\n"
    "      --max-pressure: largest accepted pressure (default 1 MPa),\n"
    "      --max-rows: largest accepted number of data rows (default 100000)\n";

/* print "crawlsim gait <sub>: <msg>" on one line, control characters shown as '?' */
static void printError(const char* sub, const char* msg);
/* parse a whole-string finite number; 1 = ok */
static int parseDouble(const char* s, double* out);
static int cmdCheck(int argc, char** argv);

typedef struct {
  const char* name;
  int (*run)(int argc, char** argv); /* argv[0] is the subcommand's name */
} subcommand;

static const subcommand kSubcommands[] = {
    {"check", cmdCheck},
};


static void printError(const char* sub, const char* msg) {
  fprintf(stderr, "crawlsim gait%s%s: ", sub ? " " : "", sub ? sub : "");
  for (const char* c = msg; *c; c++) {
    fputc(iscntrl((unsigned char)*c) ? '?' : *c, stderr);
  }
  fputc('\n', stderr);
}


static int parseDouble(const char* s, double* out) {
  char* end = NULL;
  double v = strtod(s, &end);
  if (end == s || *end != '\0' || !isfinite(v)) {
    return 0;
  }
  *out = v;
  return 1;
}


static int cmdCheck(int argc, char** argv) {
  csgReadOptions opt = csg_defaultReadOptions();
  const char* path = NULL;
  char msg[CS_ERROR_MSG_SIZE];

  /* arguments: one file and the reader limits */
  for (int i = 1; i < argc; i++) {
    const char* a = argv[i];
    if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
      fputs(kUsage, stdout);
      return 0;
    }
    if (!strcmp(a, "--max-pressure") || !strcmp(a, "--max-rows")) {
      double v;
      if (i + 1 >= argc || !parseDouble(argv[i + 1], &v) || !(v > 0.0)) {
        snprintf(msg, sizeof msg, "%s needs a positive number", a);
        printError("check", msg);
        return 1;
      }
      i++;
      if (!strcmp(a, "--max-pressure")) {
        opt.max_pressure = v;
      } else if (v != floor(v) || v > INT_MAX) {
        snprintf(msg, sizeof msg, "--max-rows %.64s must be a whole number up to %d", argv[i],
                 INT_MAX);
        printError("check", msg);
        return 1;
      } else {
        opt.max_rows = (long)v;
      }
      continue;
    }
    if (a[0] == '-' && a[1] != '\0') {
      snprintf(msg, sizeof msg, "unknown option '%.64s' (see crawlsim gait --help)", a);
      printError("check", msg);
      return 1;
    }
    if (path) {
      snprintf(msg, sizeof msg, "more than one file given ('%.64s' and '%.64s')", path, a);
      printError("check", msg);
      return 1;
    }
    path = a;
  }
  if (!path) {
    printError("check", "missing FILE.csv (usage: crawlsim gait check FILE.csv)");
    return 1;
  }

  /* read, validate, summarise */
  csError err;
  cs_errorClear(&err);
  csgGait* g = csg_gaitRead(path, &opt, &err);
  if (!g) {
    printError("check", err.msg);
    return 1;
  }
  csgGaitSummary s;
  if (csg_gaitComputeSummary(g, &s, &err) != CS_OK) {
    csg_gaitDestroy(g);
    printError("check", err.msg);
    return 1;
  }
  char where[64] = "";
  if (s.p_max_label) {
    char name[CSG_LABEL_NAME_SIZE];
    csg_labelName(s.p_max_label, name, sizeof name);
    snprintf(where, sizeof where, " (%s at t = %g s)", name, g->time[s.p_max_row]);
  }
  printf("%s: ok: %d row%s, t = %g .. %g s (duration %g s), %d of %d chambers used, ", path, s.nrow,
         s.nrow == 1 ? "" : "s", s.t_first, s.t_last, s.t_last - s.t_first, s.nused, CSG_NLABEL);
  printf("max pressure %g MPa%s\n", s.p_max, where);
  csg_gaitDestroy(g);
  return 0;
}


int csx_cmdGait(int argc, char** argv) {
  if (argc < 2) {
    printError(NULL, "missing subcommand (usage: crawlsim gait check FILE.csv; see --help)");
    return 1;
  }
  const char* sub = argv[1];
  if (!strcmp(sub, "--help") || !strcmp(sub, "-h")) {
    fputs(kUsage, stdout);
    return 0;
  }
  for (size_t i = 0; i < sizeof kSubcommands / sizeof kSubcommands[0]; i++) {
    if (!strcmp(sub, kSubcommands[i].name)) {
      return kSubcommands[i].run(argc - 1, argv + 1);
    }
  }
  char msg[CS_ERROR_MSG_SIZE];
  snprintf(msg, sizeof msg, "unknown subcommand '%.64s' (expected check; see --help)", sub);
  printError(NULL, msg);
  return 1;
}

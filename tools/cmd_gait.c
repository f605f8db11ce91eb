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
#include "cs_gaitrange.h"
#include "cs_opts.h"
#include "cs_paths.h"
#include "gaits_csv.h"
#include "robot_actuator.h"
#include "robot_calibration.h"
#include "robot_calibration_model.h"
#include "robot_leg.h"
#include "sim_scene.h"

/* `crawlsim gait --help`: the subcommands (each has its own --help) */
static const char kUsage[] =
    "usage: crawlsim gait <subcommand> ...\n"
    "  check FILE.csv      validate a gait table and check it against the calibration run uses\n"
    "  design FILE.gait    build a gait table from a design description\n"
    "  flat-road FILE.csv  the older generator of the paper-style two-group gait\n"
    "Run 'crawlsim gait <subcommand> --help' for its options.\n";

/* the options of `crawlsim gait check`, for parsing and --help (cs_opts.h) */
static const csxOpt kCheckOpts[] = {
    {"--max-pressure", "MPA", "1", "largest accepted pressure of the table, in MPa"},
    {"--max-rows", "N", "100000", "largest accepted number of data rows"},
    {"--scene", "flat-road|obstacle", "flat-road",
     "whose default calibration (and rule) to check against, as crawlsim run picks it"},
    {"--calibration", "FILE|none", "the scene's (as crawlsim run)",
     "the calibration whose pressure range the gait must stay in; none skips the range check"},
    {"--cal-rule", "prism|rbf|rbf-pair", "the scene's (as crawlsim run)",
     "the FE mode table's model rule"},
    {"--pressure-scale", "K", "1", "multiplies every pressure first (as crawlsim run)"},
    {"--legs", "rod|strain", "rod",
     "both levels also read the mode table's stiffness probes: their segments' mean pressure must "
     "stay within the probes' range too"},
    {"--cal-drop", "stretch[,stiffness]", "none",
     "as crawlsim run: with stiffness, the probes' range is not checked"},
};

static const csxOptTable kCheckTable = {
    "gait check", "FILE.csv",
    "Validate a gait table (time s, 96 chamber pressures MPa; docs/reference/formats.md), check "
    "that every pressure stays inside the pressure range of the calibration crawlsim run would "
    "use with the same options, and print one summary line (rows, duration, chambers used, max "
    "pressure); or one error line naming file, line (or row time) and cause, exit 1.",
    kCheckOpts, CSX_NOPT(kCheckOpts), NULL};

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
  const char* scene = "flat-road";
  const char* calib = NULL;
  const char* legs = "rod";
  double scale = 1.0;
  int cal_rule = -1;
  unsigned cal_drop = 0;
  char msg[CS_ERROR_MSG_SIZE];

  /* arguments: one file, the reader limits and the calibration run would use */
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kCheckTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int end = csx_optReport(&kCheckTable, k, &it);
    if (end >= 0) {
      return end;
    }
    const char* a = it.opt ? it.opt->name : "";
    const char* v = it.value;
    if (k == CSX_OPT_OPERAND) {
      if (path) {
        snprintf(msg, sizeof msg, "more than one file given ('%.64s' and '%.64s')", path, v);
        printError("check", msg);
        return 1;
      }
      path = v;
    } else if (!strcmp(a, "--max-pressure") || !strcmp(a, "--max-rows") ||
               !strcmp(a, "--pressure-scale")) {
      double x;
      if (!parseDouble(v, &x) || !(x > 0.0)) {
        snprintf(msg, sizeof msg, "%s '%.64s' needs a positive number", a, v);
        printError("check", msg);
        return 1;
      }
      if (!strcmp(a, "--max-pressure")) {
        opt.max_pressure = x;
      } else if (!strcmp(a, "--pressure-scale")) {
        scale = x;
      } else if (x != floor(x) || x > INT_MAX) {
        snprintf(msg, sizeof msg, "--max-rows %.64s must be a whole number up to %d", v, INT_MAX);
        printError("check", msg);
        return 1;
      } else {
        opt.max_rows = (long)x;
      }
    } else if (!strcmp(a, "--scene")) {
      scene = v;
    } else if (!strcmp(a, "--calibration")) {
      calib = v;
    } else if (!strcmp(a, "--legs")) {
      if (csr_legRetired(v)) {
        snprintf(msg, sizeof msg, "--legs %.16s: %s", v, csr_legRetired(v));
        printError("check", msg);
        return 1;
      }
      if (strcmp(v, "rod") && strcmp(v, "strain")) {
        snprintf(msg, sizeof msg, "--legs '%.64s' must be rod or strain", v);
        printError("check", msg);
        return 1;
      }
      legs = v;
    } else if (!strcmp(a, "--cal-rule")) {
      csrCalRule rule;
      if (!csr_calRuleParse(v, &rule)) {
        snprintf(msg, sizeof msg, "unknown --cal-rule '%.60s' (expected prism, rbf or rbf-pair)",
                 v);
        printError("check", msg);
        return 1;
      }
      cal_rule = (int)rule;
    } else if (!strcmp(a, "--cal-drop")) {
      if (!csr_calDropParse(v, &cal_drop)) {
        snprintf(msg, sizeof msg, "bad --cal-drop '%.60s' (expected stretch, stiffness, "
                 "stretch,stiffness or none)", v);
        printError("check", msg);
        return 1;
      }
    }
  }
  if (!path) {
    printError("check", "missing FILE.csv (usage: crawlsim gait check FILE.csv)");
    return 1;
  }
  const csScene* sc = cs_sceneFind(scene);
  if (!sc) {
    snprintf(msg, sizeof msg, "unknown --scene '%.60s' (expected flat-road or obstacle)", scene);
    printError("check", msg);
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
  /* the calibration run would load with the same options (run: the scene's table under the
   * scene's rule, or --calibration under its own rule unless --cal-rule) */
  char range[CS_ERROR_MSG_SIZE] = "";
  if (!calib || strcmp(calib, "none")) {
    char buf[512];
    if (!calib) {
      calib = csx_dataPath(sc->calibration, buf, sizeof buf);
      csrCalRule rule;
      if (cal_rule < 0 && sc->cal_rule && csr_calRuleParse(sc->cal_rule, &rule)) {
        cal_rule = (int)rule;
      }
    }
    csrActuator leg;
    csrCalOptions copt = csr_calModelDefaultOptions();
    copt.rule = (csrCalRule)cal_rule;
    csrCalibration* cal = NULL;
    if (csr_actuatorPreset(&leg, CSX_MISSION_ACTUATOR, &err) == CS_OK) {
      cal = csr_calibrationOpenWith(calib, &leg, cal_rule >= 0 ? &copt : NULL, &err);
    }
    /* rod and strain legs both read the probes (csr_calibrationRodFromMap) */
    const int stiffness = legs && !(cal_drop & CSR_CAL_DROP_STIFFNESS);
    if (!cal || csx_gaitRangeCheck(g, path, scale, cal, stiffness, &err) != CS_OK) {
      csr_calibrationClose(cal);
      csg_gaitDestroy(g);
      printError("check", err.msg);
      return 1;
    }
    csrBendMap map = csr_calibrationMap(cal);
    snprintf(range, sizeof range, "; within the calibrated range (up to %g MPa) of %.400s",
             map.p_max, calib);
    csr_calibrationClose(cal);
  }
  char where[64] = "";
  if (s.p_max_label) {
    char name[CSG_LABEL_NAME_SIZE];
    csg_labelName(s.p_max_label, name, sizeof name);
    snprintf(where, sizeof where, " (%s at t = %g s)", name, g->time[s.p_max_row]);
  }
  printf("%s: ok: %d row%s, t = %g .. %g s (duration %g s), %d of %d chambers used, ", path, s.nrow,
         s.nrow == 1 ? "" : "s", s.t_first, s.t_last, s.t_last - s.t_first, s.nused, CSG_NLABEL);
  printf("max pressure %g MPa%s%s\n", s.p_max, where, range);
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

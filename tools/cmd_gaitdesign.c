/* cmd_gaitdesign.c: `crawlsim gait flat-road FILE.csv`: derive the flat-road gait's pressures
 * from the calibrated leg model and write the gait table.
 *   crawlsim gait flat-road FILE.csv [--stroke MM] [--strokes N] [--crouch] [--t-land S]
 *                                    [--calibration FILE] [--p-max MPA]
 * --stroke is the foot travel per stride the gait is designed for (the paper's gait: 39 mm);
 * the pressures that give it follow from the calibration (robot_gaitdesign.h). Without
 * --crouch it writes the paper's table (groups swap at every whole second); --crouch lets the
 * standing legs crouch before the forward feet land (gaits_generate.h). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_commands.h"
#include "cs_opts.h"
#include "cs_paths.h"
#include "gaits_generate.h"
#include "robot_calibration.h"
#include "robot_gaitdesign.h"
#include "sim_model.h"


/* the options of `crawlsim gait flat-road`, for parsing and --help (cs_opts.h) */
static const csxOpt kFlatOpts[] = {
    {"--stroke", "MM", "39", "the foot travel per stride the gait is designed for, in mm"},
    {"--strokes", "N", "8", "strides, a whole number 1..1000"},
    {"--crouch", NULL, "off",
     "the standing legs crouch before the forward feet land (else the paper's table: the groups "
     "swap at every whole second)"},
    {"--t-land", "S", "0.35", "when the swinging group lands and vents, s into each 1 s period"},
    {"--calibration", "FILE", CS_MISSION_CALIBRATION " under " CS_MISSION_CAL_RULE,
     "the calibrated leg the pressures are solved on"},
    {"--p-max", "MPA", "0.5", "highest pressure a solve may use, in MPa"},
};

static const csxOptTable kFlatTable = {
    "gait flat-road", "FILE.csv",
    "The older generator of the paper-style two-group gait (Sec. 5.1): derive the pressures that "
    "give --stroke from the calibrated leg model and write the gait table FILE.csv.",
    kFlatOpts, CSX_NOPT(kFlatOpts), NULL};


int csx_cmdGaitFlatRoad(int argc, char** argv) {
  const char* out = NULL;
  const char* calib = NULL;
  double stroke = 39.0, p_max = 0.5, nstroke = 8, t_land = NAN;
  int crouch = 0;
  csxOptIter it;
  csx_optBegin(&it);
  for (csxOptKind k; (k = csx_optNext(&kFlatTable, argc, argv, &it)) != CSX_OPT_END;) {
    const int stop = csx_optReport(&kFlatTable, k, &it);
    if (stop >= 0) {
      return stop;
    }
    if (k == CSX_OPT_OPERAND) {
      if (out) {
        fprintf(stderr, "crawlsim gait flat-road: unexpected argument '%s'\n", it.value);
        return 1;
      }
      out = it.value;
      continue;
    }
    const char* a = it.opt->name;
    double* num = NULL;
    if (!strcmp(a, "--crouch")) {
      crouch = 1;
      continue;
    } else if (!strcmp(a, "--calibration")) {
      calib = it.value;
      continue;
    } else if (!strcmp(a, "--stroke")) {
      num = &stroke;
    } else if (!strcmp(a, "--p-max")) {
      num = &p_max;
    } else if (!strcmp(a, "--t-land")) {
      num = &t_land;
    } else {
      num = &nstroke; /* --strokes */
    }
    char* end;
    *num = strtod(it.value, &end);
    if (*end || end == it.value || !isfinite(*num) || *num <= 0) {
      fprintf(stderr, "crawlsim gait flat-road: %s '%s' must be a number > 0\n", a, it.value);
      return 1;
    }
  }
  /* a stride count is a whole number; checked here, before the (int) conversion, which is
   * undefined for values outside int's range */
  if (nstroke != floor(nstroke) || nstroke > 1000) {
    fprintf(stderr, "crawlsim gait flat-road: --strokes %g must be a whole number in 1..1000\n",
            nstroke);
    return 1;
  }
  if (!out) {
    fprintf(stderr, "crawlsim gait flat-road: missing FILE.csv (see crawlsim gait flat-road "
                    "--help)\n");
    return 1;
  }
  char buf[512];
  const int calib_given = calib != NULL;
  /* the mission's calibration under its rule (core/sim_scene.h), as `crawlsim run` uses it */
  if (!calib) calib = csx_dataPath(CS_MISSION_CALIBRATION, buf, sizeof buf);
  csrCalOptions cal_opt = csr_calModelDefaultOptions();
  const int mission_rule = !calib_given && csr_calRuleParse(CS_MISSION_CAL_RULE, &cal_opt.rule);
  csError err;
  cs_errorClear(&err);
  int rc = 1;
  csrActuator leg;
  csrCalibration* cal = NULL;
  csgGait* g = NULL;
  csrFlatRoadDesign des;
  if (csr_actuatorPreset(&leg, "leg", &err) != CS_OK) goto done;
  cal = csr_calibrationOpenWith(calib, &leg, mission_rule ? &cal_opt : NULL, &err);
  if (!cal) goto done;
  csrBendMap map = csr_calibrationMap(cal);
  if (csr_designFlatRoad(&leg, &map, stroke, p_max, &des, &err) != CS_OK) goto done;
  csgFlatRoadSpec spec = csg_defaultFlatRoadSpec();
  spec.nstroke = (int)nstroke;
  if (!isnan(t_land)) spec.t_land = t_land;
  spec.p_stroke = des.p_stroke;
  spec.p_crouch_II2 = des.p_crouch_II2;
  spec.crouch = crouch;
  g = csg_generateFlatRoad(&spec, &err);
  if (!g) goto done;
  char comment[2048];
  snprintf(comment, sizeof comment,
           "crawlsim flat-road gait (paper Sec. 5.1), generated by: crawlsim gait flat-road "
           "--stroke %g%s%s%.600s\n"
           "groups ACFH / BDEG alternate; %s\n"
           "pressures from the calibration: %s\n"
           "S-shape %.4f MPa: stroke %.2f mm, segment bend %.2f deg, lift %.2f mm; "
           "crouch II2 %.4f MPa: lift %.2f mm, foot offset %.2f mm",
           stroke, crouch ? " --crouch" : "", calib_given ? " --calibration " : "",
           calib_given ? calib : "",
           crouch ? "standing legs crouch before the forward feet land (gaits_generate.h)"
                  : "the paper's table: the groups swap at every whole second",
           map.name, des.p_stroke, des.stroke, des.theta_stroke_deg, des.lift_stroke,
           des.p_crouch_II2, des.lift_crouch, des.crouch_offset);
  /* the shipped file must not carry this machine's paths: drop the source-tree prefix */
  for (char* src; (src = strstr(comment, CS_SOURCE_DIR "/")) != NULL;) {
    size_t cut = strlen(CS_SOURCE_DIR "/");
    memmove(src, src + cut, strlen(src + cut) + 1);
  }
  if (csg_gaitWrite(g, out, comment, &err) != CS_OK) goto done;
  printf("%s: %d rows; S-shape %.4f MPa (stroke %.2f mm, bend %.2f deg/segment, lift %.2f mm); "
         "crouch II2 %.4f MPa (lift %.2f mm, offset %.2f mm)\n",
         out, g->nrow, des.p_stroke, des.stroke, des.theta_stroke_deg, des.lift_stroke,
         des.p_crouch_II2, des.lift_crouch, des.crouch_offset);
  rc = 0;
done:
  if (rc) fprintf(stderr, "crawlsim gait flat-road: %s\n", err.msg);
  csg_gaitDestroy(g);
  csr_calibrationClose(cal);
  return rc;
}


/* ---- crawlsim gait design ------------------------------------------------------------------ */

/* the options of `crawlsim gait design`, for parsing and --help (cs_opts.h) */
static const csxOpt kDesignOpts[] = {
    {"--out", "FILE.csv", "the description's name with .csv", "the gait table written"},
    {"--calibration", "FILE", CS_MISSION_CALIBRATION,
     "the calibrated leg the poses are solved on"},
    {"--cal-rule", "prism|rbf|rbf-pair",
     CS_MISSION_CAL_RULE " on the default calibration, else the table's own (prism)",
     "the FE mode table's model rule, for the poses and the check runs; refused for other "
     "calibrations"},
    {"--p-max", "MPA", "0.3, capped by the calibration's range",
     "highest pressure a solve may use, in MPa"},
    {"--stretch", NULL, "off",
     "forward kinematics with the map's axial stretch (leg levels that stretch; needed by rise "
     "targets)"},
    {"--check", NULL, "off",
     "short runs of the table (its own ramp, then ramps 0.1 and 0.5 s) printing the stride per "
     "cycle of each"},
    {"--check-scene", "flat-road|obstacle", "flat-road",
     "the scene of the --check runs, under its default conditions"},
    {"--check-t", "S", "the first stride's start + 3 periods", "length of each --check run, s"},
    {"--set", "NAME=VALUE", NULL,
     "a leg actuator parameter, repeatable (as crawlsim bend): the poses are solved for that leg "
     "(its calibration must be of that actuator); not with --check"},
};

static const csxOptTable kDesignTable = {
    "gait design", "FILE.gait",
    "Build a gait table from a design description (docs/reference/formats.md: poses as chamber "
    "sets with a target stroke/side/lift/rise/bend/pressure, moves with durations, strides with "
    "phases); pressures from the calibrated leg model.",
    kDesignOpts, CSX_NOPT(kDesignOpts), NULL};


/* the definition of a gait design: the parsed options (the strings point into argv) */
typedef struct {
  const char* in;          /* the design description FILE.gait */
  const char* out;         /* the table; NULL: in with .csv */
  const char* calib;       /* NULL: the default calibration */
  const char* check_scene; /* the --check runs' scene */
  double p_max, check_t;   /* MPa, s; NaN: the defaults */
  int cal_rule;            /* csrCalRule of --cal-rule, -1: not given */
  int stretch, check, nset;
  const char* sets[32];
  FILE* table;             /* where the lines go (the command: stdout; a study's step: its log) */
} DesignDef;

/* what a design gives back besides its table */
typedef struct {
  char rows_line[1024]; /* "<out>: N rows, t = 0 .. T s, from <in>" */
  char summary[256];    /* the same without the output's directory */
} DesignResult;


/* the stride per cycle of a short run of `gait_csv` with schedule ramp `ramp`; prints a line
 * on table; 0, or 1 with *err filled */
static int checkRun(FILE* table, const char* gait_csv, const char* scene_name, double ramp,
                    double t_end, const csgDesign* des, const char* calib, int cal_rule,
                    csError* cerr) {
  const csScene* sc = cs_sceneFind(scene_name);
  if (!sc) {
    cs_errorSet(cerr, CS_ERR_ARG, "unknown --check-scene '%s'", scene_name);
    return 1;
  }
  char terr[512];
  csx_dataPath(sc->terrain, terr, sizeof terr);
  csModel m;
  cs_modelInit(&m);
  cs_modelSetConditions(&m, sc->conditions);
  m.sched.ramp = ramp;
  m.ramp_given = 1; /* the check's ramp, not the table's */
  m.opt.t_end = t_end;
  m.opt.output_dt = 0.05;
  m.cal_rule = cal_rule;
  csError err;
  cs_errorClear(&err);
  csData* d = NULL;
  int rc = 1;
  if (cs_modelLoad(&m, sc->name, terr, gait_csv, calib, &err) != CS_OK) goto done;
  d = cs_dataCreate(&m, &err);
  if (!d || cs_settle(&m, d, &err) != CS_OK) goto done;
  double period = des->nstride ? des->stride_period : 1.0;
  double t_mark = des->nstride ? des->stride_t0 : 0.0;
  double x_prev = 0, x[3];
  fprintf(table, "  check %s (%s), ramp %.2f s: x at stride starts (mm):", sc->name,
          cs_conditionsName(m.conditions), ramp);
  int nstr = 0;
  double sum = 0;
  while (cs_time(d) < t_end - 1e-9) {
    csStatus st = cs_step(&m, d, &err);
    if (st != CS_OK) {
      fprintf(table, "\n");
      goto done;
    }
    if (cs_time(d) >= t_mark - 1e-9) {
      cs_supportDisplacement(d, x);
      fprintf(table, " %.1f", x[0]);
      if (t_mark > (des->nstride ? des->stride_t0 : 0) + 1e-9) {
        sum += x[0] - x_prev;
        nstr++;
      }
      x_prev = x[0];
      t_mark += period;
    }
  }
  cs_supportDisplacement(d, x);
  fprintf(table, "; stride per cycle %.1f mm over %d strides; z %.1f mm\n", nstr ? sum / nstr : 0.0,
          nstr, x[2]);
  rc = 0;
done:
  if (rc) cs_errorSet(cerr, err.status ? err.status : CS_ERR_SOLVER, "check run: %.450s", err.msg);
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  return rc;
}


/* argv into d: 0; 1 with err filled; 2 when `it` holds --help or an option error (*kind) */
static int parseDesign(int argc, char** argv, DesignDef* d, csxOptIter* it, csxOptKind* kind,
                       csError* err) {
  memset(d, 0, sizeof *d);
  d->check_scene = "flat-road";
  d->p_max = d->check_t = NAN;
  d->cal_rule = -1;
  csx_optBegin(it);
  while ((*kind = csx_optNext(&kDesignTable, argc, argv, it)) != CSX_OPT_END) {
    if (*kind == CSX_OPT_HELP || *kind == CSX_OPT_ERROR) {
      return 2;
    }
    if (*kind == CSX_OPT_OPERAND) {
      if (d->in) {
        cs_errorSet(err, CS_ERR_ARG, "unexpected argument '%s'", it->value);
        return 1;
      }
      d->in = it->value;
      continue;
    }
    const char* a = it->opt->name;
    const char* v = it->value;
    if (!strcmp(a, "--set")) {
      if (d->nset == 32) {
        cs_errorSet(err, CS_ERR_ARG, "more than 32 --set options");
        return 1;
      }
      d->sets[d->nset++] = v;
    } else if (!strcmp(a, "--stretch")) {
      d->stretch = 1;
    } else if (!strcmp(a, "--check")) {
      d->check = 1;
    } else if (!strcmp(a, "--out")) {
      d->out = v;
    } else if (!strcmp(a, "--calibration")) {
      d->calib = v;
    } else if (!strcmp(a, "--check-scene")) {
      d->check_scene = v;
    } else if (!strcmp(a, "--cal-rule")) {
      csrCalRule rule;
      if (!csr_calRuleParse(v, &rule)) {
        cs_errorSet(err, CS_ERR_ARG, "unknown --cal-rule '%.60s' (expected prism, rbf "
                    "or rbf-pair)", v);
        return 1;
      }
      d->cal_rule = (int)rule;
    } else {
      char* end;
      double x = strtod(v, &end);
      if (*end || end == v || !isfinite(x) || !(x > 0)) {
        cs_errorSet(err, CS_ERR_ARG, "%s '%s' must be a number > 0", a, v);
        return 1;
      }
      if (!strcmp(a, "--p-max")) d->p_max = x; else d->check_t = x; /* --check-t */
    }
  }
  if (!d->in) {
    cs_errorSet(err, CS_ERR_ARG, "missing FILE.gait (see --help)");
    return 1;
  }
  return 0;
}



/* build the gait table d defines, its lines on d->table: 0, or 1 with err filled; *res */
static int executeDesign(const DesignDef* d, DesignResult* res, csError* err) {
  const char* const in = d->in;
  const char* out = d->out;
  const char* calib = d->calib;
  const double p_max = d->p_max;
  const int cal_rule = d->cal_rule, stretch = d->stretch, check = d->check, nset = d->nset;
  char outbuf[1024], calbuf[512];
  if (!out) {
    snprintf(outbuf, sizeof outbuf, "%s", in);
    char* dot = strrchr(outbuf, '.');
    char* slash = strrchr(outbuf, '/');
    if (dot && (!slash || dot > slash)) *dot = '\0';
    strncat(outbuf, ".csv", sizeof outbuf - strlen(outbuf) - 1);
    out = outbuf;
  }
  const int calib_given = calib != NULL;
  /* the mission's calibration under its rule (core/sim_scene.h), as `crawlsim run` uses it;
   * the header records --cal-rule only when given */
  if (!calib) calib = csx_dataPath(CS_MISSION_CALIBRATION, calbuf, sizeof calbuf);
  csrCalRule mission_rule = CSR_CAL_RULE_SUPERPOSITION;
  const int run_rule = cal_rule >= 0 ? cal_rule
                       : !calib_given && csr_calRuleParse(CS_MISSION_CAL_RULE, &mission_rule)
                           ? (int)mission_rule
                           : -1;
  int rc = 1;
  csgDesign* des = malloc(sizeof *des);
  csrDesignedPoses* poses = malloc(sizeof *poses);
  char* comment = malloc(20000);
  csrCalibration* cal = NULL;
  csgGait* g = NULL;
  csrActuator leg;
  if (!des || !poses || !comment) {
    cs_errorSet(err, CS_ERR_MEMORY, "out of memory");
    goto done;
  }
  if (csg_designRead(des, in, err) != CS_OK) goto done;
  if (csr_actuatorPreset(&leg, "leg", err) != CS_OK) goto done;
  /* --set: the design study's leg (the check runs would build the shipped one) */
  if (nset > 0 && check) {
    cs_errorSet(err, CS_ERR_ARG, "--check runs the shipped leg: with --set, run the table with "
                "crawlsim run --set ... instead");
    goto done;
  }
  for (int k = 0; k < nset; k++) {
    if (csr_actuatorSetString(&leg, d->sets[k], err) != CS_OK) goto done;
  }
  if (csr_actuatorValidate(&leg, err) != CS_OK) goto done;
  csrCalOptions cal_opt = csr_calModelDefaultOptions();
  cal_opt.rule = (csrCalRule)run_rule;
  cal = csr_calibrationOpenWith(calib, &leg, run_rule >= 0 ? &cal_opt : NULL, err);
  if (!cal) goto done;
  csrBendMap map = csr_calibrationMap(cal);
  csrGaitDesignOptions opt = csr_defaultGaitDesignOptions();
  if (!isnan(p_max)) opt.p_max = p_max;
  opt.stretch = stretch;
  if (csr_designPoses(&leg, &map, des, &opt, poses, err) != CS_OK) goto done;
  g = csr_designGait(&leg, &map, des, &opt, poses, err);
  if (!g) goto done;
  /* the header says where the table came from; no machine paths (the source-tree prefix and
   * the data directory are dropped, so regenerating on another machine gives the same bytes) */
  char posetext[16384];
  csr_designPosesFormat(des, poses, posetext, sizeof posetext);
  const char* base = strrchr(in, '/');
  base = base ? base + 1 : in;
  /* the options that change the table: a calibration given on the command line (its path
   * as given, the source-tree prefix dropped below) and --p-max */
  char extra[700] = "";
  if (calib_given) {
    snprintf(extra, sizeof extra, " --calibration %.600s", calib);
  }
  if (!isnan(p_max)) {
    size_t n = strlen(extra);
    snprintf(extra + n, sizeof extra - n, " --p-max %g", p_max);
  }
  if (cal_rule >= 0) {
    size_t n = strlen(extra);
    snprintf(extra + n, sizeof extra - n, " --cal-rule %s", csr_calRuleName((csrCalRule)cal_rule));
  }
  snprintf(comment, 20000,
           "crawlsim gait %s, generated by: crawlsim gait design %s%s%s\n"
           "a row every %g s; each move follows its shape path with a smoothstep (or at constant "
           "speed) in time (robot_gaitdesign.h)\n"
           "pressures from the calibration: %s\n%s",
           des->name, base, stretch ? " --stretch" : "", extra, des->sample, map.name, posetext);
  for (char* src; (src = strstr(comment, CS_SOURCE_DIR "/")) != NULL;) {
    size_t cut = strlen(CS_SOURCE_DIR "/");
    memmove(src, src + cut, strlen(src + cut) + 1);
  }
  if (csg_gaitWrite(g, out, comment, err) != CS_OK) goto done;
  snprintf(res->rows_line, sizeof res->rows_line, "%s: %d rows, t = 0 .. %g s, from %s", out,
           g->nrow, g->time[g->nrow - 1], in);
  {
    /* the line without the output's directory (a study's case summary) */
    const char* slash = strrchr(out, '/');
    snprintf(res->summary, sizeof res->summary, "%s: %d rows, t = 0 .. %g s, from %s",
             slash ? slash + 1 : out, g->nrow, g->time[g->nrow - 1], in);
  }
  fprintf(d->table, "%s\n%s\n", res->rows_line, posetext);
  if (des->nfoothold > 0) {
    /* the table holds the plan's candidates; the others need the generator (gaits_design.h) */
    fprintf(d->table, "%d foothold line%s (the table holds the plan's landing; the candidates' "
            "tables and NAME.foothold: tools/obstacle_gait.py --foothold-out)\n", des->nfoothold,
            des->nfoothold > 1 ? "s" : "");
  }
  rc = 0;
  if (check) {
    double t_end = isnan(d->check_t)
                       ? (des->nstride ? des->stride_t0 + 3 * des->stride_period : 4.0)
                       : d->check_t;
    /* the table's own ramp (its nominal), then the robustness set's actuation times */
    const double ramps[3] = {isnan(g->ramp) ? CSG_DEFAULT_RAMP : g->ramp, 0.1, 0.5};
    for (int i = 0; i < 3 && rc == 0; i++) {
      rc = checkRun(d->table, out, d->check_scene, ramps[i], t_end, des, calib, run_rule, err);
    }
  }
done:
  csg_gaitDestroy(g);
  csr_calibrationClose(cal);
  free(des);
  free(poses);
  free(comment);
  return rc;
}


/* `crawlsim gait design` with its lines on `table`, a failure's on `notes` and its results in
 * *sres (NULL: the command line; else a study's step, both streams its log) */
static int designCommand(int argc, char** argv, FILE* table, FILE* notes, csxStepResult* sres) {
  DesignDef d;
  csxOptIter it;
  csxOptKind kind;
  csError err;
  cs_errorClear(&err);
  int rc = parseDesign(argc, argv, &d, &it, &kind, &err);
  rc = csx_parseEnd(&kDesignTable, rc, kind, &it, &err, notes, sres);
  if (rc >= 0) {
    return rc;
  }
  d.table = table;
  DesignResult res;
  memset(&res, 0, sizeof res);
  rc = executeDesign(&d, &res, &err);
  if (sres) {
    snprintf(sres->summary, sizeof sres->summary, "%s", res.summary);
  }
  if (rc && (sres || err.msg[0])) {
    csx_stepFailed(sres, notes, "gait design", err.msg);
  }
  return rc;
}


int csx_cmdGaitDesign(int argc, char** argv) {
  return designCommand(argc, argv, stdout, stderr, NULL);
}


int csx_stepGaitDesign(int argc, char** argv, FILE* log, csxStepResult* res) {
  return designCommand(argc, argv, log, log, res);
}

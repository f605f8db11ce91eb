/* cs_rundef.c: the run definition: defaults, the one validation, and its resolution into a
 * loaded model (crawlsim.h, cs_rundef.h). What `crawlsim run` (tools/cmd_run.c) did between
 * its option parser and the run, moved here unchanged so that the command, the study runner
 * and the Python package resolve a run alike. Messages name a field by the `crawlsim run`
 * option it mirrors. */
#define _GNU_SOURCE /* dladdr: where this library is, to find the data installed beside it */
#include "cs_rundef.h"

#include <dlfcn.h>
#include <inttypes.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "robot_calibration.h"
#include "robot_levels.h"
#include "terrains_scenefile.h"

#ifndef CS_SOURCE_DIR
#define CS_SOURCE_DIR "." /* set by core/CMakeLists.txt */
#endif
#ifndef CS_INSTALL_DATA_DIR
#define CS_INSTALL_DATA_DIR "/usr/local/share/crawlsim" /* set by core/CMakeLists.txt */
#endif

/* the longest run one definition may ask for: beyond this t_end / dt is a typo, and the step
 * count would overflow the driver's step counter on 32-bit longs */
#define MAX_STEPS 1e9
/* the longest step the driver accepts (sim_driver.c validateOptions) */
#define MAX_DT_S 0.01
/* --strain-step adaptive without --dt: the longest step and cs_step's grid (s); the fixed
 * step's measured ceiling of accuracy on the flat road (docs/notes/strain_leg.md "An
 * error-controlled macro step") */
#define CS_ADAPTIVE_MAX_STEP_S 0.005
/* --set assignments of one run */
#define MAX_SET 32


csRunDef cs_defaultRunDef(void) {
  csRunDef d;
  memset(&d, 0, sizeof d);
  d.legs_tol_mm = NAN;
  d.friction = NAN;
  d.pressure_scale = 1.0;
  d.t_end = 0;
  d.dt = d.output_dt = d.ramp = d.tau = d.gravity = d.support_mass_kg = NAN;
  d.slope_deg = d.links = d.iterations = d.macro_steps = NAN;
  d.contact_scale = d.rod_tol = d.step_order = d.step_tol = d.strain_sub = NAN;
  d.checkpoint_every = NAN;
  return d;
}


/* an object of this library, whose address dladdr turns into the library's file */
static const char kDataAnchor = 0;

/* does dir hold the shipped data (its flat road's terrain)? */
static int hasData(const char* dir) {
  char probe[1200];
  snprintf(probe, sizeof probe, "%s/terrains/flat_road.terrain", dir);
  FILE* f = fopen(probe, "rb");
  if (f) {
    fclose(f);
  }
  return f != NULL;
}


const char* cs_runDataPath(const csRunDef* def, const char* rel, char* buf, size_t size) {
  const char* dir = def && def->data_dir && def->data_dir[0] ? def->data_dir : NULL;
  if (!dir) {
    const char* env = getenv("CRAWLSIM_DATA_DIR");
    dir = env && env[0] ? env : NULL;
  }
  char beside[1024] = "", found[1100];
  if (!dir) {
    /* an installed library: <prefix>/lib[/...]/libcrawlsim.so finds <prefix>/share/crawlsim
     * (the install may have been moved: cmake --install --prefix) */
    Dl_info info;
    if (dladdr(&kDataAnchor, &info) && info.dli_fname) {
      snprintf(beside, sizeof beside, "%s", info.dli_fname);
      for (int up = 0; up < 3 && !dir; up++) {
        char* slash = strrchr(beside, '/');
        if (!slash) break;
        *slash = '\0';
        snprintf(found, sizeof found, "%s/share/crawlsim", beside);
        dir = hasData(found) ? found : NULL;
      }
    }
  }
  if (!dir) {
    /* the build tree's sources when they are there (the command and the tests), else the
     * configured install prefix's data */
    dir = hasData(CS_SOURCE_DIR) ? CS_SOURCE_DIR : CS_INSTALL_DATA_DIR;
  }
  snprintf(buf, size, "%s/%s", dir, rel);
  return buf;
}


/* the leg level a name asks for (NULL for "auto" and unknown names) */
static const csrLegType* legTypeNamed(const char* legs) {
  return legs && strcmp(legs, "auto") ? csr_legTypeFind(legs, NULL) : NULL;
}


/* An option that sets a leg level's own setting `name` (robot_leg.h csrLegSetting) is refused,
 * in one line naming the levels that have it, for a level that has none */
static csStatus levelTakes(const csrLegType* T, const char* flag, const char* name,
                           csError* err) {
  if (csr_legSettingFind(T, name)) {
    return CS_OK;
  }
  char names[128] = "";
  for (int i = 0, n = 0; i < csr_legTypeCount() && n < (int)sizeof names; i++) {
    const csrLegType* L = csr_legTypeAt(i);
    if (csr_legSettingFind(L, name)) {
      int w = snprintf(names + n, sizeof names - n, "%s%s", n ? ", " : "", L->name);
      n += w > 0 ? w : 0;
    }
  }
  return cs_errorSet(err, CS_ERR_ARG, "%s is for %s legs, not %s (their setting %s)", flag,
                     names[0] ? names : "no", T->name, name);
}


/* Every check of the definition that needs no file, with the scene that gives the defaults
 * (the definition's, or a scene file's) */
/* does the run take the adaptive tree step (sim_adaptive.c)? For a tree-stepped level (strain)
 * it is the default: its tolerance bounds the error where the motion turns fast, a fixed step
 * spends the worst moment's length everywhere (docs/notes/strain_leg.md "The strain level's
 * default step"). Fixed where the definition says so, names the step (dt: the fixed step it
 * asks for), or asks for what the estimate does not cover (step order 2, another coupling).
 * dt and order: the definition's. (--legs auto: its row says, robot_levels.h step_tol_mm.) */
static int stepAdaptive(const csRunDef* def, const csrLegType* type, double dt, double order) {
  if (!type || !type->prepare) {
    return 0;
  }
  if (def->strain_step) {
    return !strcmp(def->strain_step, "adaptive");
  }
  return isnan(dt) && (isnan(order) || order == 1) &&
         (!def->coupling || !strcmp(def->coupling, "tree"));
}


static csStatus checkDef(const csRunDef* def, const char* scene_name, csError* err) {
  const csScene* sc = cs_sceneFind(scene_name);
  if (!sc) {
    return cs_errorSet(err, CS_ERR_ARG, "unknown scene '%.60s' (expected flat-road, obstacle or "
                       "slope)", scene_name ? scene_name : "(null)");
  }
  if (def->conditions) {
    csConditions c;
    if (cs_conditionsParse(def->conditions, &c, err) != CS_OK) return err ? err->status : CS_ERR_ARG;
  }
  const char* legs = def->legs ? def->legs : sc->legs;
  const csrLegType* type = NULL;
  if (!strcmp(legs, "auto")) {
    if (isnan(def->legs_tol_mm)) {
      return cs_errorSet(err, CS_ERR_ARG, "--legs auto needs --tol MM (the track error allowed "
                         "against the reference, see robot/levels.csv)");
    }
    if (!isnan(def->links) || !isnan(def->macro_steps) || !isnan(def->dt) ||
        !isnan(def->rod_tol) || !isnan(def->step_order) || !isnan(def->step_tol)) {
      return cs_errorSet(err, CS_ERR_ARG, "--legs auto sets --links, --macro-steps, --dt, "
                         "--rod-tol, --step-order and --step-tol from its table: give them with "
                         "--legs rod or strain instead");
    }
    if (!(def->legs_tol_mm >= 0)) {
      return cs_errorSet(err, CS_ERR_RANGE, "--tol %g mm must be >= 0", def->legs_tol_mm);
    }
  } else {
    int planned = 0;
    type = csr_legTypeFind(legs, &planned);
    if (!type && planned) {
      char names[128] = "";
      for (int i = 0, n = 0; i < csr_legTypeCount() && n < (int)sizeof names; i++) {
        int w = snprintf(names + n, sizeof names - n, "%s%s", i ? ", " : "",
                         csr_legTypeAt(i)->name);
        n += w > 0 ? w : 0;
      }
      return cs_errorSet(err, CS_ERR_ARG, "leg model '%s' is not available yet (available: %s)",
                         legs, names);
    }
    if (!type && csr_legRetired(legs)) {
      return cs_errorSet(err, CS_ERR_ARG, "--legs %s: %s", legs, csr_legRetired(legs));
    }
    if (!type) {
      return cs_errorSet(err, CS_ERR_ARG, "unknown leg model '%.60s' (expected auto, rod, "
                         "strain or rom)", legs);
    }
    if (!isnan(def->legs_tol_mm) || def->levels) {
      return cs_errorSet(err, CS_ERR_ARG, "--tol and --levels go with --legs auto");
    }
    if (!strcmp(type->name, "rom") && !def->rom_file) {
      return cs_errorSet(err, CS_ERR_ARG, "--legs rom needs --rom-file LEG.h5 (the reduced "
                         "leg's file: crawlsim rom leg-file)");
    }
  }
  if (def->rom_file && (!type || strcmp(type->name, "rom") != 0)) {
    return cs_errorSet(err, CS_ERR_ARG, "--rom-file goes with --legs rom (not %s)", legs);
  }
  if (def->cal_rule) {
    csrCalRule rule;
    if (!csr_calRuleParse(def->cal_rule, &rule)) {
      return cs_errorSet(err, CS_ERR_ARG, "unknown --cal-rule '%.60s' (expected prism, rbf or "
                         "rbf-pair)", def->cal_rule);
    }
  }
  unsigned drop = 0;
  if (def->cal_drop && !csr_calDropParse(def->cal_drop, &drop)) {
    return cs_errorSet(err, CS_ERR_ARG, "bad --cal-drop '%.60s' (expected stretch, stiffness, "
                       "stretch,stiffness or none)", def->cal_drop);
  }
  /* the options that set a level's own settings, against the level (auto: after its pick) */
  const struct {
    const char* flag;
    const char* name;
    int given;
  } own[] = {{"--links", "links", !isnan(def->links)},
             {"--rod-tol", "rod_tol", !isnan(def->rod_tol)},
             {"--cal-drop", "cal_drop", drop != 0},
             {"--step-order", "step_order", !isnan(def->step_order)},
             {"--strain-sub", "sub", !isnan(def->strain_sub)}};
  for (size_t k = 0; type && k < sizeof own / sizeof own[0]; k++) {
    if (own[k].given && levelTakes(type, own[k].flag, own[k].name, err) != CS_OK) {
      return err ? err->status : CS_ERR_ARG;
    }
  }
  if (def->n_actuator_set < 0 || def->n_actuator_set > MAX_SET ||
      (def->n_actuator_set > 0 && !def->actuator_set)) {
    return cs_errorSet(err, CS_ERR_ARG, "%d --set options: 0..%d, each a NAME=VALUE string",
                       def->n_actuator_set, MAX_SET);
  }
  for (int k = 0; k < def->n_actuator_set; k++) {
    if (!def->actuator_set[k]) {
      return cs_errorSet(err, CS_ERR_ARG, "--set number %d is NULL", k + 1);
    }
  }
  /* numbers: NaN is "the default", an infinity is never meant */
  const struct {
    const char* flag;
    double v;
  } nums[] = {{"--tol", def->legs_tol_mm}, {"--friction", def->friction},
              {"--pressure-scale", def->pressure_scale}, {"--t-end", def->t_end},
              {"--dt", def->dt}, {"--output-dt", def->output_dt}, {"--ramp", def->ramp},
              {"--tau", def->tau}, {"--gravity", def->gravity},
              {"--support-mass", def->support_mass_kg}, {"--slope-deg", def->slope_deg},
              {"--links", def->links}, {"--iterations", def->iterations},
              {"--macro-steps", def->macro_steps}, {"--contact-scale", def->contact_scale},
              {"--rod-tol", def->rod_tol}, {"--step-order", def->step_order},
              {"--step-tol", def->step_tol}, {"--strain-sub", def->strain_sub},
              {"--checkpoint-every", def->checkpoint_every}};
  for (size_t k = 0; k < sizeof nums / sizeof nums[0]; k++) {
    if (isinf(nums[k].v)) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s %g is not a finite number", nums[k].flag,
                         nums[k].v);
    }
  }
  /* each against its field's range */
  if (!isnan(def->friction) && !(def->friction >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--friction %g must be >= 0", def->friction);
  }
  if (!(def->pressure_scale >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--pressure-scale %g must be >= 0",
                       def->pressure_scale);
  }
  if (!(def->t_end >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--t-end %g s must be >= 0 (0: the gait's length)",
                       def->t_end);
  }
  if (!isnan(def->dt) && !(def->dt > 0 && def->dt <= MAX_DT_S)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--dt %g s must be > 0 and <= %g s", def->dt,
                       MAX_DT_S);
  }
  /* a tree-stepped level's step is its own unless dt says (csrLegType.step); the adaptive
   * step's grid is its longest step */
  double h = !isnan(def->dt) ? def->dt
             : stepAdaptive(def, type, def->dt, def->step_order) ? CS_ADAPTIVE_MAX_STEP_S
             : type && type->prepare && type->step > 0 ? type->step
                                                       : cs_defaultOptions().h;
  if (!isnan(def->output_dt) && !(def->output_dt >= h)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--output-dt %g s must be >= the step %g s (--dt)",
                       def->output_dt, h);
  }
  if (!isnan(def->ramp) && !(def->ramp >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--ramp %g s must be >= 0", def->ramp);
  }
  if (!isnan(def->tau) && !(def->tau >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--tau %g s must be >= 0 (0: no pressure lag)",
                       def->tau);
  }
  if (!isnan(def->gravity) && !(def->gravity >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--gravity %g m/s^2 must be >= 0", def->gravity);
  }
  if (!isnan(def->support_mass_kg) && !(def->support_mass_kg > 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--support-mass %g kg must be > 0",
                       def->support_mass_kg);
  }
  double links = def->links, iters = def->iterations, macro = def->macro_steps;
  if (!isnan(links) && (links != floor(links) || links < 1 || links > 64)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--links %g must be an integer in 1..64", links);
  }
  /* checked before any conversion to int, which would be undefined for 1e30 */
  if (!isnan(iters) && (iters != floor(iters) || iters < 1 || iters > 10000)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--iterations %g must be an integer in 1..10000",
                       iters);
  }
  if (!isnan(macro) && (macro != floor(macro) || macro < 1 || macro > 100000)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--macro-steps %g must be an integer in 1..100000",
                       macro);
  }
  if (!isnan(macro) && !isnan(def->output_dt) && !(def->output_dt >= macro * h)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--output-dt %g s must be >= the macro step %g s "
                       "(--macro-steps x --dt)", def->output_dt, macro * h);
  }
  /* 1e6: a contact a million times stiffer than the default is a typo, not a study */
  if (!isnan(def->contact_scale) && !(def->contact_scale > 0 && def->contact_scale <= 1e6)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--contact-scale %g must be > 0 and <= 1e6",
                       def->contact_scale);
  }
  /* 1000: CVODE's relative tolerance (1e-4 shipped) near 0.1, where the steps are bounded by
   * the macro step alone and the track is no longer an integration of anything */
  if (!isnan(def->step_order) && def->step_order != 1 && def->step_order != 2) {
    return cs_errorSet(err, CS_ERR_RANGE, "--step-order %g must be 1 or 2", def->step_order);
  }
  const char* ss = def->strain_step;
  if (ss && strcmp(ss, "fixed") && strcmp(ss, "adaptive")) {
    return cs_errorSet(err, CS_ERR_ARG, "unknown --strain-step '%.60s' (expected fixed or "
                       "adaptive)", ss);
  }
  const int adaptive = ss && !strcmp(ss, "adaptive");
  if (!isnan(def->step_tol) && !stepAdaptive(def, type, def->dt, def->step_order)) {
    return cs_errorSet(err, CS_ERR_ARG, "--step-tol goes with the adaptive strain step (--legs "
                       "strain without --dt, or --strain-step adaptive)");
  }
  if (!isnan(def->step_tol) && !(def->step_tol > 0 && def->step_tol <= 100)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--step-tol %g mm must be > 0 and <= 100",
                       def->step_tol);
  }
  if (adaptive && type && !type->prepare) {
    return cs_errorSet(err, CS_ERR_ARG, "--strain-step adaptive needs a tree-stepped leg level "
                       "(--legs strain, not %s)", type->name);
  }
  /* beside --legs auto, --strain-step picks among the table's rows of that step kind
   * (pickAuto; robot_levels.h step_tol_mm) */
  if (adaptive && def->coupling && strcmp(def->coupling, "tree")) {
    return cs_errorSet(err, CS_ERR_ARG, "--strain-step adaptive needs --coupling tree (the "
                       "strain level's own)");
  }
  if (!isnan(def->strain_sub) && def->strain_sub != floor(def->strain_sub)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--strain-sub %g must be a whole number",
                       def->strain_sub);
  }
  if (!isnan(def->rod_tol) && !(def->rod_tol > 0 && def->rod_tol <= 1000)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--rod-tol %g must be > 0 and <= 1000", def->rod_tol);
  }
  const char* cp = def->coupling;
  if (cp && strcmp(cp, "staggered") && strcmp(cp, "stabilised") && strcmp(cp, "gs") &&
      strcmp(cp, "tree")) {
    return cs_errorSet(err, CS_ERR_ARG, "unknown coupling '%.60s' (expected staggered, "
                       "stabilised, gs or tree)", cp);
  }
  if (cp && !strcmp(cp, "tree") && type && !type->prepare) {
    return cs_errorSet(err, CS_ERR_ARG, "--coupling tree needs a tree-stepped leg level (--legs "
                       "strain)");
  }
  if (cp && !strcmp(cp, "tree") && type && type->prepare && !isnan(macro) && macro != 1) {
    return cs_errorSet(err, CS_ERR_ARG, "--coupling tree takes one ODE step per macro step "
                       "(--macro-steps 1)");
  }
  /* the terrain file's limit (terrains_terrain.h) */
  if (!isnan(def->slope_deg) && !(fabs(def->slope_deg) <= 45)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--slope-deg %g must be within +-45 deg",
                       def->slope_deg);
  }
  if (!(def->no_gait == 0 || def->no_gait == 1)) {
    return cs_errorSet(err, CS_ERR_RANGE, "no_gait is 0 or 1");
  }
  /* resumable runs (cs_api.c, sim_run.c) */
  if (!isnan(def->checkpoint_every) && !(def->checkpoint_every > 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "--checkpoint-every %g must be > 0 s",
                       def->checkpoint_every);
  }
  if (!isnan(def->checkpoint_every) && !def->checkpoint && !def->resume) {
    return cs_errorSet(err, CS_ERR_ARG, "--checkpoint-every needs --checkpoint FILE");
  }
  if ((def->checkpoint || def->resume) && !def->out) {
    return cs_errorSet(err, CS_ERR_ARG, "--%s needs an output file (--out)",
                       def->resume ? "resume" : "checkpoint");
  }
  if ((def->checkpoint && !def->checkpoint[0]) || (def->resume && !def->resume[0])) {
    return cs_errorSet(err, CS_ERR_ARG, "--%s needs a file name",
                       def->resume && !def->resume[0] ? "resume" : "checkpoint");
  }
  return CS_OK;
}


csStatus cs_runDefValidate(const csRunDef* def, csError* err) {
  if (!def) {
    return cs_errorSet(err, CS_ERR_ARG, "no run definition (NULL)");
  }
  /* a scene file may name the scene: its defaults are checked again once it is read */
  return checkDef(def, def->scene ? def->scene : "flat-road", err);
}


/* one line "name value" of the identity into out at *len (the value's file contents hashed
 * when `file`): -1 once out is full */
static int identityLine(char* out, size_t size, size_t* len, const char* name, const char* v,
                        int file) {
  char val[1100];
  uint64_t h;
  if (!v) {
    snprintf(val, sizeof val, "default");
  } else if (file && cs_hashFile(v, &h) == 0) {
    /* the file's contents, not its path: the same file by another path is the same run */
    snprintf(val, sizeof val, "file %016" PRIx64, h);
  } else {
    snprintf(val, sizeof val, "%.1060s", v);
  }
  const int n = snprintf(out + *len, size - *len, "%s %s\n", name, val);
  if (n < 0 || (size_t)n >= size - *len) {
    return -1;
  }
  *len += (size_t)n;
  return 0;
}


static int identityNum(char* out, size_t size, size_t* len, const char* name, double v) {
  char val[40];
  if (isnan(v)) {
    snprintf(val, sizeof val, "default");
  } else {
    snprintf(val, sizeof val, "%.17g", v);
  }
  return identityLine(out, size, len, name, val, 0);
}


int cs_runDefIdentity(const csRunDef* def, const csModel* m, const csRunPlan* plan, char* out,
                      size_t size) {
  size_t len = 0;
  out[0] = '\0';
  int rc = 0;
  /* the definition's words and numbers as given (NaN, NULL: "default") */
  const struct {
    const char* name;
    const char* v;
  } words[] = {{"scene", def->scene},           {"foothold", def->foothold},
               {"gate", def->gate},             {"conditions", def->conditions},
               {"legs", def->legs},
               {"cal_rule", def->cal_rule},     {"cal_drop", def->cal_drop},
               {"coupling", def->coupling},
               {"strain_step", def->strain_step}};
  for (size_t k = 0; k < sizeof words / sizeof words[0]; k++) {
    rc |= identityLine(out, size, &len, words[k].name, words[k].v, 0);
  }
  const struct {
    const char* name;
    double v;
  } nums[] = {{"no_gait", def->no_gait},
              {"legs_tol_mm", def->legs_tol_mm},
              {"friction", def->friction},
              {"pressure_scale", def->pressure_scale},
              {"dt", def->dt},
              {"output_dt", def->output_dt},
              {"ramp", def->ramp},
              {"tau", def->tau},
              {"gravity", def->gravity},
              {"support_mass_kg", def->support_mass_kg},
              {"slope_deg", def->slope_deg},
              {"links", def->links},
              {"iterations", def->iterations},
              {"macro_steps", def->macro_steps},
              {"contact_scale", def->contact_scale},
              {"rod_tol", def->rod_tol},
              {"step_order", def->step_order},
              {"step_tol", def->step_tol},
              {"strain_sub", def->strain_sub}};
  for (size_t k = 0; k < sizeof nums / sizeof nums[0]; k++) {
    rc |= identityNum(out, size, &len, nums[k].name, nums[k].v);
  }
  for (int k = 0; k < def->n_actuator_set; k++) {
    rc |= identityLine(out, size, &len, "set", def->actuator_set[k], 0);
  }
  /* the files the run read, by their contents (whoever named them: the definition, a scene
   * file or the scene's defaults) */
  rc |= identityLine(out, size, &len, "scene_file", def->scene_file, 1);
  rc |= identityLine(out, size, &len, "terrain_file", plan->terrain[0] ? plan->terrain : NULL,
                     1);
  rc |= identityLine(out, size, &len, "gait_file", plan->gait[0] ? plan->gait : NULL, 1);
  rc |= identityLine(out, size, &len, "foothold_file", plan->foothold[0] ? plan->foothold : NULL,
                     1);
  rc |= identityLine(out, size, &len, "gate_file", plan->gate[0] ? plan->gate : NULL, 1);
  rc |= identityLine(out, size, &len, "calibration_file",
                     plan->calibration[0] ? plan->calibration : NULL, 1);
  rc |= identityLine(out, size, &len, "leg_file", m->robot.leg_file[0] ? m->robot.leg_file : NULL,
                     1);
  /* and what they resolved to */
  rc |= identityLine(out, size, &len, "leg_level", cs_modelLegLevel(m), 0);
  rc |= identityLine(out, size, &len, "legs_auto_choice", m->legs_auto_choice, 0);
  return rc ? -1 : 0;
}


int cs_runDefTrackError(const csRunDef* def, const csModel* m, char* out, size_t size,
                        double* error_mm) {
  char levels_buf[512];
  const char* levels = def->levels ? def->levels
                                   : cs_runDataPath(def, "robot/levels.csv", levels_buf,
                                                    sizeof levels_buf);
  csrLevelTable* table = malloc(sizeof *table); /* ~40 KB: not on the stack */
  csError e;
  cs_errorClear(&e);
  if (error_mm) {
    *error_mm = NAN;
  }
  if (!table || csr_levelTableRead(levels, table, &e) != CS_OK) {
    snprintf(out, size, "track error not known (%s)", table ? e.msg : "out of memory");
    free(table);
    return 0;
  }
  const csrLegType* lt = m->robot.leg_type;
  const csrLegSettings* ls = &m->robot.leg_settings;
  const int links = (int)csr_legSettingGet(lt, ls, "links", 0);
  const double rod_tol = csr_legSettingGet(lt, ls, "rod_tol", 1);
  const int order = (int)csr_legSettingGet(lt, ls, "step_order", 0);
  int found = 0;
  /* a fixed step matches a row without a step tolerance; the adaptive step (dt its longest) a
   * row at its own tolerance (robot_levels.h step_tol_mm) */
  const double step_tol = m->opt.step_adaptive ? m->opt.step_tol : 0;
  /* the rows are measured on the scene's own terrain and gait under `paper` (the table's
   * header): a run on other files or conditions quotes the row as the configuration's error
   * there, not as its own, and records no number (a user's gait, or `earth`, which also swaps
   * the flat road's gait, can sit anywhere relative to the reference) */
  const int other_files = def->terrain || def->gait || def->no_gait || def->scene_file;
  const int elsewhere = other_files || m->conditions != CS_CONDITIONS_PAPER;
  for (int i = 0; i < table->nrow && !found; i++) {
    const csrLevelRow* r = &table->row[i];
    /* a row's step order 0 is the level's default formula, which is what an unset one runs */
    const int row_order = r->step_order > 0 ? r->step_order : order;
    if (!strcmp(r->scene, m->scene) && !strcmp(r->level, cs_modelLegLevel(m)) &&
        r->links == links && r->macro_steps == m->opt.macro_steps && r->dt_s == m->opt.h &&
        r->rod_tol == rod_tol && row_order == order && r->step_tol_mm == step_tol) {
      if (elsewhere) {
        snprintf(out, size, "track error %.3g mm against the reference of %s (line %d), measured "
                 "on the scene's own terrain and gait under paper; this run's %s, so its own "
                 "error is not measured", r->error_mm, levels, r->line,
                 other_files ? "terrain or gait differ" : "conditions differ");
      } else {
        snprintf(out, size, "track error %.3g mm against the reference of %s (line %d; measured "
                 "on the scene's own gait and conditions)%s", r->error_mm, levels, r->line,
                 r->whole_run == 0 ? "; warning: in the table this configuration's whole run "
                                     "of the scene fails (whole_run 0)"
                                   : "");
        if (error_mm) {
          *error_mm = r->error_mm;
        }
      }
      found = 1;
    }
  }
  if (!found && m->opt.step_adaptive) {
    snprintf(out, size, "track error of the adaptive step at %g mm per step (longest %g s) not "
             "measured (%s has no row for it)", m->opt.step_tol, m->opt.h, levels);
  } else if (!found) {
    snprintf(out, size, "track error of this configuration not measured (%s has no row for it)",
             levels);
  }
  free(table);
  return found;
}


/* the leg level `auto` picked from the measured table (issue 11): sets the level and its
 * configuration in m and the choice's explanation */
static csStatus pickAuto(const csRunDef* def, const char* scene, int user_files, csModel* m,
                         double* links, double* macro, double* dt, double* rodtol,
                         double* order, double* steptol, const csrLegType** leg_type,
                         csError* err) {
  char levels_buf[512];
  const char* levels = def->levels ? def->levels
                                   : cs_runDataPath(def, "robot/levels.csv", levels_buf,
                                                    sizeof levels_buf);
  csrLevelTable* table = malloc(sizeof *table); /* ~40 KB: not on the stack */
  if (!table) {
    return cs_errorSet(err, CS_ERR_MEMORY, "out of memory for the level table");
  }
  csStatus st = csr_levelTableRead(levels, table, err);
  /* --strain-step beside auto: the rows of that step kind only */
  const csrStepKind kind = !def->strain_step                       ? CSR_STEP_ANY
                           : !strcmp(def->strain_step, "adaptive") ? CSR_STEP_ADAPTIVE
                                                                   : CSR_STEP_FIXED;
  int k = st == CS_OK ? csr_levelTablePickStep(table, scene, def->legs_tol_mm, kind, err) : -1;
  if (k < 0) {
    free(table);
    return err ? err->status : CS_ERR_ARG;
  }
  const double tol = def->legs_tol_mm;
  const csrLevelRow* row = &table->row[k];
  const csrLevelRow* fin = &table->row[csr_levelTableFinest(table, scene)];
  /* the scene's costliest row: what always running the dearest configuration would cost */
  const csrLevelRow* top = &table->row[csr_levelTableCostliest(table, scene)];
  *leg_type = csr_legTypeFind(row->level, NULL);
  *links = row->links;
  *macro = row->macro_steps;
  *dt = row->dt_s;
  *rodtol = row->rod_tol;
  if (row->step_order > 0) {
    *order = row->step_order;
  }
  /* a row with a step tolerance is the adaptive step, dt its longest (robot_levels.h) */
  *steptol = row->step_tol_mm > 0 ? row->step_tol_mm : NAN;
  m->legs_auto_tol_mm = tol;
  char tolnote[128] = "";
  if (row->rod_tol != 1) {
    snprintf(tolnote, sizeof tolnote, ", rod tol %g", row->rod_tol);
  }
  if (row->step_order > 0) {
    snprintf(tolnote + strlen(tolnote), sizeof tolnote - strlen(tolnote), ", step order %d",
             row->step_order);
  }
  if (row->step_tol_mm > 0) {
    snprintf(tolnote + strlen(tolnote), sizeof tolnote - strlen(tolnote), ", adaptive step at "
             "%g mm per step (dt its longest)", row->step_tol_mm);
  }
  snprintf(m->legs_auto_choice, sizeof m->legs_auto_choice,
           "%s, links %d, macro steps %d, dt %g s%s: the cheapest of %d configurations measured "
           "on %.31s within --tol %g mm (error %.3g mm against the reference, %.3g CPU s per "
           "simulated s); the most accurate (%s, links %d, macro steps %d, dt %g s%s: %.3g mm) "
           "costs %.3g, the costliest (%s, links %d, macro steps %d, dt %g s%s: %.3g mm) %.3g "
           "CPU s per simulated s, %.2fx; %.200s line %d, measured on %.63s%s",
           row->level, row->links, row->macro_steps, row->dt_s, tolnote,
           csr_levelTableCount(table, scene), scene, tol, row->error_mm, row->cpu_s_per_s,
           fin->level, fin->links, fin->macro_steps, fin->dt_s,
           fin->step_tol_mm > 0 ? ", adaptive" : "", fin->error_mm, fin->cpu_s_per_s,
           top->level, top->links, top->macro_steps, top->dt_s,
           top->step_tol_mm > 0 ? ", adaptive" : "", top->error_mm,
           top->cpu_s_per_s, top->cpu_s_per_s / row->cpu_s_per_s, levels, row->line,
           row->machine,
           user_files || def->conditions
               ? " (measured with the scene's own terrain, gait and conditions, not this run's)"
               : "");
  /* the whole run: what the table says of this row beyond its measured window, and what the
   * pick passed over for failing it (robot_levels.h whole_run) */
  const int passed = csr_levelTableFailing(table, scene, tol, kind, row->cpu_s_per_s);
  size_t len = strlen(m->legs_auto_choice);
  snprintf(m->legs_auto_choice + len, sizeof m->legs_auto_choice - len, "; its whole run %s",
           row->whole_run > 0 ? "reaches the scene's goal in the table"
                              : "is not judged in the table (whole_run -1)");
  if (passed > 0) {
    len = strlen(m->legs_auto_choice);
    snprintf(m->legs_auto_choice + len, sizeof m->legs_auto_choice - len, "; %d cheaper "
             "row%s within --tol passed over: %s whole run fails (whole_run 0)", passed,
             passed == 1 ? "" : "s", passed == 1 ? "its" : "their");
  }
  if (!*leg_type) {
    st = cs_errorSet(err, CS_ERR_ARG, "%s: level '%.30s' is not a registered leg level",
                     levels, row->level);
  }
  free(table);
  return st;
}


csStatus cs_runDefBuild(const csRunDef* def, csModel* m, csRunPlan* plan, csError* err) {
  csStatus st = cs_runDefValidate(def, err);
  if (st != CS_OK) return st;
  memset(plan, 0, sizeof *plan);
  const char* scene = def->scene ? def->scene : "flat-road";
  const char* terrain = def->terrain;
  const char* gait = def->no_gait ? NULL : def->gait;
  const char* conditions = def->conditions;
  double t_end = def->t_end;
  /* a scene file (terrains_scenefile.h) fills what the definition left out */
  cstSceneFile* sf = NULL;
  if (def->scene_file) {
    sf = malloc(sizeof *sf); /* ~1.5 KB of paths */
    if (!sf) return cs_errorSet(err, CS_ERR_MEMORY, "out of memory for the scene file");
    if (cst_sceneFileLoad(sf, def->scene_file, err) != CS_OK) {
      free(sf);
      return err ? err->status : CS_ERR_PARSE;
    }
    if (!def->scene && sf->scene[0]) scene = sf->scene;
    if (!terrain && sf->terrain[0]) terrain = sf->terrain;
    if (!gait && !def->no_gait && sf->gait[0]) gait = sf->gait;
    if (!conditions && sf->conditions[0]) conditions = sf->conditions;
    if (t_end == 0 && sf->has_t_end) t_end = sf->t_end;
    st = checkDef(def, scene, err); /* the scene file's scene gives the defaults */
  }
  /* scene -> default terrain, gait and conditions (sim_scene.h) */
  const csScene* sc = cs_sceneFind(scene);
  plan->scene = sc;
  int user_files = terrain != NULL || gait != NULL || def->no_gait;
  const char* legs = def->legs ? def->legs : sc ? sc->legs : "rod";
  if (st == CS_OK) {
    if (terrain) {
      snprintf(plan->terrain, sizeof plan->terrain, "%s", terrain);
    } else {
      cs_runDataPath(def, sc->terrain, plan->terrain, sizeof plan->terrain);
    }
    int requested = -1;
    if (conditions) {
      csConditions c = CS_CONDITIONS_EARTH;
      st = cs_conditionsParse(conditions, &c, err);
      requested = (int)c;
    }
    csConditions cond = cs_sceneConditions(sc, requested, user_files, &plan->cond_src);
    if (st == CS_OK) {
      cs_modelSetConditions(m, cond);
    }
    if (gait) {
      snprintf(plan->gait, sizeof plan->gait, "%s", gait);
    } else if (!def->no_gait) {
      /* the scene's gait for the conditions it runs under (sim_scene.h) */
      const char* g = cond == CS_CONDITIONS_EARTH && sc->gait_earth ? sc->gait_earth : sc->gait;
      cs_runDataPath(def, g, plan->gait, sizeof plan->gait);
    }
  }
  /* the leg level: the table of registered levels is robot_robot.c's (one line per level) */
  const csrLegType* leg_type = legTypeNamed(legs);
  double links = def->links, macro = def->macro_steps, dt = def->dt, rodtol = def->rod_tol;
  double order = def->step_order, steptol = NAN;
  const int is_auto = !strcmp(legs, "auto");
  if (st == CS_OK && is_auto) {
    st = pickAuto(def, scene, user_files, m, &links, &macro, &dt, &rodtol, &order, &steptol,
                  &leg_type, err);
    if (st == CS_OK && def->coupling && !strcmp(def->coupling, "tree") && !leg_type->prepare) {
      st = cs_errorSet(err, CS_ERR_ARG, "--coupling tree needs a tree-stepped leg level (--legs "
                       "auto picked %s)", leg_type->name);
    }
  }
  if (st == CS_OK && def->cal_rule) {
    csrCalRule rule;
    csr_calRuleParse(def->cal_rule, &rule);
    m->cal_rule = (int)rule;
  }
  /* the scene's calibration (its gait was designed on it) under the scene's rule, overridable
   * with calibration (which then keeps that table's own default rule) and cal_rule */
  if (st == CS_OK) {
    if (def->calibration) {
      snprintf(plan->calibration, sizeof plan->calibration, "%s", def->calibration);
    } else {
      cs_runDataPath(def, sc->calibration, plan->calibration, sizeof plan->calibration);
      csrCalRule rule;
      if (m->cal_rule < 0 && sc->cal_rule && csr_calRuleParse(sc->cal_rule, &rule)) {
        m->cal_rule = (int)rule;
      }
    }
  }
  /* the actuator of a design study (--set); the legs' stiffness and mass follow from it */
  for (int k = 0; st == CS_OK && k < def->n_actuator_set; k++) {
    st = csr_actuatorSetString(&m->robot.leg, def->actuator_set[k], err);
  }
  if (st == CS_OK && def->n_actuator_set > 0) {
    st = csr_actuatorValidate(&m->robot.leg, err);
    m->robot.leg_params = csr_defaultLegParams(&m->robot.leg);
  }
  if (st != CS_OK) {
    free(sf);
    return st;
  }
  cs_modelSetLegLevel(m, leg_type); /* the one place the level is stored (and its coupling) */
  if (def->rom_file) {
    if (strlen(def->rom_file) >= sizeof m->robot.leg_file) {
      free(sf);
      return cs_errorSet(err, CS_ERR_ARG, "--rom-file: a path of %zu characters (at most %zu)",
                         strlen(def->rom_file), sizeof m->robot.leg_file - 1);
    }
    snprintf(m->robot.leg_file, sizeof m->robot.leg_file, "%s", def->rom_file);
  }
  /* the level's own settings: its defaults, then the scene's and the definition's values (a
   * level that has none of a given setting was refused above, or by levelTakes for auto) */
  csrLegSettings* ls = &m->robot.leg_settings;
  csr_legSettingsDefault(leg_type, ls);
  unsigned cal_drop = 0;
  if (def->cal_drop) csr_calDropParse(def->cal_drop, &cal_drop);
  if (cal_drop) {
    st = levelTakes(leg_type, "--cal-drop", "cal_drop", err);
    if (st == CS_OK) st = csr_legSettingSet(leg_type, ls, "cal_drop", cal_drop, err);
  }
  /* step_order: the definition's, or auto's row (strain rows carry one) */
  if (st == CS_OK && !isnan(order)) {
    if (!isnan(def->step_order)) st = levelTakes(leg_type, "--step-order", "step_order", err);
    if (st == CS_OK) st = csr_legSettingSet(leg_type, ls, "step_order", order, err);
  }
  if (st == CS_OK && !isnan(links)) {
    st = csr_legSettingSet(leg_type, ls, "links", links, err);
  } else if (st == CS_OK && sc->rod_links > 0 && !strcmp(leg_type->name, "rod")) {
    /* the scene's table is for the rod level by name (sim_scene.h rod_links): converged on it */
    st = csr_legSettingSet(leg_type, ls, "links", sc->rod_links, err);
  }
  /* rod_tol: the definition's (refused above for a level without it), or auto's row (every
   * row has one: it applies where the level has the setting) */
  if (st == CS_OK && !isnan(rodtol) && csr_legSettingFind(leg_type, "rod_tol")) {
    st = csr_legSettingSet(leg_type, ls, "rod_tol", rodtol, err);
  }
  if (st == CS_OK && !isnan(def->strain_sub)) {
    st = csr_legSettingSet(leg_type, ls, "sub", def->strain_sub, err);
  }
  if (st != CS_OK) {
    free(sf);
    return st;
  }
  if (!isnan(def->friction)) m->contact.mu = def->friction;
  if (!isnan(def->contact_scale)) {
    m->contact.kp *= def->contact_scale;
    m->contact.stiffness_scale = def->contact_scale;
  }
  m->sched.pressure_scale = def->pressure_scale;
  if (!isnan(def->ramp)) {
    m->sched.ramp = def->ramp;
    m->ramp_given = 1;
  }
  /* a tree-stepped level's step is its own unless dt says (csrLegType.step) */
  m->opt.h = !isnan(dt) ? dt : leg_type->prepare && leg_type->step > 0 ? leg_type->step
                                                                       : m->opt.h;
  if (!isnan(def->output_dt)) m->opt.output_dt = def->output_dt;
  if (!isnan(def->tau)) m->opt.pneumatic_tau = def->tau;
  if (!isnan(def->iterations)) m->opt.solver_iterations = (int)def->iterations;
  if (!isnan(macro)) m->opt.macro_steps = (int)macro;
  /* --legs auto: its row says (a tolerance: the adaptive step; none: the fixed dt) */
  if (is_auto ? !isnan(steptol) : stepAdaptive(def, leg_type, dt, order)) {
    m->opt.step_adaptive = 1;
    if (!isnan(def->step_tol)) m->opt.step_tol = def->step_tol;
    if (!isnan(steptol)) m->opt.step_tol = steptol;
    /* the longest step, and the grid of cs_step: 5 ms unless dt says (the level's fixed step
     * is the shortest its error needs; the adaptive step finds its own) */
    if (isnan(dt)) m->opt.h = CS_ADAPTIVE_MAX_STEP_S;
  }
  if (def->coupling) {
    const char* cp = def->coupling;
    m->opt.coupling = !strcmp(cp, "stabilised") ? CS_COUPLING_STABILISED
                      : !strcmp(cp, "gs")       ? CS_COUPLING_GAUSS_SEIDEL
                      : !strcmp(cp, "tree")     ? CS_COUPLING_TREE
                                                : CS_COUPLING_STAGGERED;
  }
  /* the default output interval must hold a whole macro step */
  if (isnan(def->output_dt) && m->opt.output_dt < cs_modelMacroStep(m)) {
    m->opt.output_dt = cs_modelMacroStep(m);
  }
  if (!isnan(def->gravity)) m->opt.gravity = def->gravity * 1e3; /* m/s^2 -> mm/s^2 */
  if (!isnan(def->support_mass_kg)) m->robot.support_mass = def->support_mass_kg * 1e-3;
  m->opt.t_end = t_end;
  m->opt.progress = def->progress;
  m->opt.progress_user = def->progress_user;
  m->opt.cancel = def->cancel;
  st = csc_contactParamsValidate(&m->contact, err);
  if (st == CS_OK) st = csg_scheduleCheckOptions(&m->sched, err);
  if (st == CS_OK) {
    st = cs_modelLoad(m, scene, plan->terrain, plan->gait[0] ? plan->gait : NULL,
                      plan->calibration, err);
  }
  if (st == CS_OK && sf) st = cs_modelApplySceneFile(m, sf, err);
  free(sf);
  if (st != CS_OK) return st;
  /* the gait's footholds: the option's file; none by default (no scene ships one) */
  if (def->foothold && strcmp(def->foothold, "none") != 0) {
    if (def->no_gait) {
      return cs_errorSet(err, CS_ERR_ARG, "--foothold %s needs a gait table (no_gait is set)",
                         def->foothold);
    }
    st = cs_modelLoadFoothold(m, def->foothold, err);
    if (st != CS_OK) return st;
    snprintf(plan->foothold, sizeof plan->foothold, "%s", def->foothold);
  }
  /* the landing gate: the option's file, else the scene's for its own gait (sim_scene.h) */
  const char* gate = def->gate;
  char gate_path[512];
  if (!gate && !gait && !def->no_gait && sc && sc->gate) {
    gate = cs_runDataPath(def, sc->gate, gate_path, sizeof gate_path);
  }
  if (gate && strcmp(gate, "none") != 0) {
    if (def->no_gait) {
      return cs_errorSet(err, CS_ERR_ARG, "--gate %s needs a gait table (no_gait is set)", gate);
    }
    st = cs_modelLoadGate(m, gate, err);
    if (st != CS_OK) return st;
    snprintf(plan->gate, sizeof plan->gate, "%s", gate);
  }
  if (!isnan(def->slope_deg)) m->terrain.slope_deg = def->slope_deg;
  if (m->gait) {
    csgGaitSummary gs;
    csg_gaitComputeSummary(m->gait, &gs, NULL);
    if (gs.p_max * def->pressure_scale > csg_defaultReadOptions().max_pressure) {
      return cs_errorSet(err, CS_ERR_RANGE, "--pressure-scale %g takes %s to %g MPa, above the "
                         "%g MPa limit of gait pressures", def->pressure_scale, plan->gait,
                         gs.p_max * def->pressure_scale, csg_defaultReadOptions().max_pressure);
    }
  }
  if (cs_modelEndTime(m) / m->opt.h > MAX_STEPS) {
    return cs_errorSet(err, CS_ERR_RANGE, "a run to t = %g s at --dt %g s takes more than %g "
                       "steps", cs_modelEndTime(m), m->opt.h, MAX_STEPS);
  }
  /* the configuration's measured error, for the banner and the run file (issue 33 item 1) */
  cs_runDefTrackError(def, m, m->track_error, sizeof m->track_error, &m->track_error_mm);
  return CS_OK;
}

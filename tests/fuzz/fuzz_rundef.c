/* fuzz_rundef.c: fuzz harness of the run definition (core/crawlsim.h csRunDef,
 * cs_runDefValidate, and its resolution into a loaded model, core/cs_rundef.h cs_runDefBuild).
 *
 * An input is text, one field a line, "name value" (the `crawlsim run` option without its
 * dashes: "friction -0.5", "legs auto", "tol 3"). Numbers go through strtod as they are (nan,
 * inf, 1e308, hex floats: the validator must refuse what is out of range, never convert it).
 * Words (scene, legs, conditions, coupling, cal-rule, cal-drop, set) are the input's own
 * bytes. File fields (gait, terrain, calibration, levels, scene-file) take an index into a
 * list of shipped files and missing ones, so the harness reads no file the fuzzer names.
 *
 * Per input: validation's error contract (a status and a one-line message exactly when it
 * refuses; fuzz_common.h); a definition it accepts is built (files read, no robot settled)
 * and must give a model within the driver's ranges, or fail with the same contract. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cs_rundef.h"
#include "fuzz_common.h"

#ifndef CS_SOURCE_DIR
#define CS_SOURCE_DIR "."
#endif

/* the files a file field may name (index mod count): shipped ones and ones that are not there */
static const char* const kFiles[] = {
    CS_SOURCE_DIR "/gaits/flat_road.csv",
    CS_SOURCE_DIR "/gaits/obstacle.csv",
    CS_SOURCE_DIR "/terrains/flat_road.terrain",
    CS_SOURCE_DIR "/terrains/obstacle.terrain",
    CS_SOURCE_DIR "/robot/calibration_fe_leg_modes_sym.h5",
    CS_SOURCE_DIR "/robot/calibration_provisional.txt",
    CS_SOURCE_DIR "/robot/levels.csv",
    CS_SOURCE_DIR "/terrains/slope_earth.scene",
    CS_SOURCE_DIR "/no/such/file",
};
enum { NFILE = sizeof kFiles / sizeof kFiles[0] };

/* an input's copy, cut into NUL-terminated words (the definition points into it) */
static char g_text[4096];
static const char* g_sets[32];


int csz_harnessInit(void) {
  csError err;
  /* NULL is refused, once */
  if (cs_runDefValidate(NULL, &err) != CS_ERR_ARG || !err.msg[0]) {
    csz_fail("cs_runDefValidate(NULL) did not refuse");
  }
  return 0;
}


static const char* filePick(const char* v) {
  long k = strtol(v, NULL, 10);
  return kFiles[(unsigned long)labs(k % NFILE)];
}


/* one "name value" line into the definition */
static void setLine(csRunDef* d, char* name, char* v) {
  static const struct {
    const char* name;
    size_t off;
  } kNum[] = {
      {"friction", offsetof(csRunDef, friction)},
      {"pressure-scale", offsetof(csRunDef, pressure_scale)},
      {"t-end", offsetof(csRunDef, t_end)},
      {"dt", offsetof(csRunDef, dt)},
      {"output-dt", offsetof(csRunDef, output_dt)},
      {"ramp", offsetof(csRunDef, ramp)},
      {"tau", offsetof(csRunDef, tau)},
      {"gravity", offsetof(csRunDef, gravity)},
      {"support-mass", offsetof(csRunDef, support_mass_kg)},
      {"slope-deg", offsetof(csRunDef, slope_deg)},
      {"links", offsetof(csRunDef, links)},
      {"iterations", offsetof(csRunDef, iterations)},
      {"macro-steps", offsetof(csRunDef, macro_steps)},
      {"contact-scale", offsetof(csRunDef, contact_scale)},
      {"rod-tol", offsetof(csRunDef, rod_tol)},
      {"step-order", offsetof(csRunDef, step_order)},
      {"step-tol", offsetof(csRunDef, step_tol)},
      {"strain-sub", offsetof(csRunDef, strain_sub)},
      {"tol", offsetof(csRunDef, legs_tol_mm)},
  };
  for (size_t k = 0; k < sizeof kNum / sizeof kNum[0]; k++) {
    if (!strcmp(name, kNum[k].name)) {
      double x = strtod(v, NULL);
      memcpy((char*)d + kNum[k].off, &x, sizeof x);
      return;
    }
  }
  if (!strcmp(name, "scene")) d->scene = v;
  else if (!strcmp(name, "legs")) d->legs = v;
  else if (!strcmp(name, "conditions")) d->conditions = v;
  else if (!strcmp(name, "coupling")) d->coupling = v;
  else if (!strcmp(name, "strain-step")) d->strain_step = v;
  else if (!strcmp(name, "cal-rule")) d->cal_rule = v;
  else if (!strcmp(name, "cal-drop")) d->cal_drop = v;
  else if (!strcmp(name, "no-gait")) d->no_gait = atoi(v);
  else if (!strcmp(name, "gait")) d->gait = filePick(v);
  else if (!strcmp(name, "terrain")) d->terrain = filePick(v);
  else if (!strcmp(name, "calibration")) d->calibration = filePick(v);
  else if (!strcmp(name, "levels")) d->levels = filePick(v);
  else if (!strcmp(name, "scene-file")) d->scene_file = filePick(v);
  else if (!strcmp(name, "set") && d->n_actuator_set < 32) {
    g_sets[d->n_actuator_set++] = v;
    d->actuator_set = g_sets;
  } else if (!strcmp(name, "nset")) {
    d->n_actuator_set = atoi(v); /* may disagree with the list: must be refused, not read */
  }
}


/* the contract of a refusal: a known negative status, the same in err, one line */
static void checkRefusal(csStatus st, const csError* err) {
  if (st >= 0 || st < CS_ERR_INTERRUPTED || err->status != st) {
    csz_fail("refusal with status %d (err %d)", (int)st, (int)err->status);
  }
  if (!memchr(err->msg, '\0', sizeof err->msg) || !err->msg[0] || strchr(err->msg, '\n') ||
      strchr(err->msg, '\r')) {
    csz_fail("refusal message empty or not one line");
  }
}


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  if (size >= sizeof g_text) {
    size = sizeof g_text - 1;
  }
  memcpy(g_text, data, size);
  g_text[size] = '\0';
  csRunDef d = cs_defaultRunDef();
  d.data_dir = CS_SOURCE_DIR;
  for (char* line = g_text; line && *line;) {
    char* next = strchr(line, '\n');
    if (next) *next++ = '\0';
    char* sp = strchr(line, ' ');
    if (sp) {
      *sp = '\0';
      setLine(&d, line, sp + 1);
    }
    line = next;
  }
  cs_errorClear(err);
  csStatus st = cs_runDefValidate(&d, err);
  if (st != CS_OK) {
    checkRefusal(st, err);
    return st;
  }
  /* accepted: resolve it and load its files; the model must be within the driver's ranges */
  csModel* m = malloc(sizeof *m);
  if (!m) csz_fail("out of memory");
  cs_modelInit(m);
  csRunPlan plan;
  st = cs_runDefBuild(&d, m, &plan, err);
  if (st != CS_OK) {
    checkRefusal(st, err);
  } else {
    const csOptions* o = &m->opt;
    if (!(o->h > 0 && o->h <= 0.01) || o->macro_steps < 1 || !(o->output_dt > 0) ||
        !(m->contact.mu >= 0) || !(o->gravity >= 0) || !(m->robot.support_mass > 0) ||
        !m->robot.leg_type || !(cs_modelEndTime(m) >= 0) || !isfinite(cs_modelEndTime(m))) {
      csz_fail("accepted definition gave a model out of range (h %g, macro %d, out %g)", o->h,
               o->macro_steps, o->output_dt);
    }
  }
  cs_modelDestroy(m);
  free(m);
  return st;
}

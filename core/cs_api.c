/* cs_api.c: the public API of crawlsim.h over the driver (sim_model.h): a whole run with its
 * result, and a simulation stepped by the caller with the chamber commands set between steps
 * or by a controller.
 *
 * Pressure sources. The driver asks the model's pressure source (csModel.pressure_source)
 * wherever it evaluates the schedule: at the step's end and at the pneumatic integrator's inner
 * times. A held command answers with the held vector; a controller is called there with the
 * time asked, so a controller that evaluates the gait table at t reproduces the table's run
 * bit for bit (tests/core/test_api.c). A controller's failure (non-zero return, a value out of
 * range) is recorded here and fails the step: the integrator sees the source fail (its
 * right-hand side returns -1), and where the schedule is evaluated outside it (no pneumatic
 * lag) the state saved before the step is put back. */
#include <errno.h>
#include <stdarg.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crawlsim.h"
#include "cs_rundef.h"
#include "gaits_labels.h"
#include "robot_strain.h"
#include "sim_model.h"

#ifndef CS_VERSION_STRING
#define CS_VERSION_STRING "unknown" /* set by core/CMakeLists.txt */
#endif

/* the largest chamber command (MPa): the gait reader's limit (gaits_csv.h) */
#define P_CMD_MAX 1.0
/* read-out limit of leg centrelines (sim_run.c's MAX_CENTERLINE) */
#define MAX_CENTERLINE 201

typedef enum { SRC_GAIT = 0, SRC_COMMAND = 1, SRC_CONTROLLER = 2 } SourceKind;

struct csSim {
  csModel m;            /* the model (constant during a step); m.pressure_source set here */
  csData* d;
  csRunPlan plan;
  int nstate;
  double* x_settled;    /* [nstate] the state at t = 0 after settling (cs_simReset) */
  double* x_save;       /* [nstate] the state before a controller's step */
  int failed;           /* a step failed: further steps are refused until reset / state set */
  char fail_msg[CS_ERROR_MSG_SIZE];
  SourceKind source;
  double p_hold[CSR_NCHAMBER_TOTAL]; /* held command (MPa) */
  csController ctrl;
  void* ctrl_user;
  int source_failed;    /* the controller failed during the current step */
  char source_msg[CS_ERROR_MSG_SIZE];
};


/* ---- the pressure source ---------------------------------------------------------------- */

/* a command vector's first bad entry (index), or -1 when every one is finite in [0, P_CMD_MAX] */
static int badCommand(const double* p) {
  for (int i = 0; i < CSR_NCHAMBER_TOTAL; i++) {
    if (!(p[i] >= 0 && p[i] <= P_CMD_MAX)) {
      return i;
    }
  }
  return -1;
}


static int sourceEval(void* ctx, double t, double* p_cmd) {
  csSim* s = ctx;
  if (s->source == SRC_COMMAND) {
    memcpy(p_cmd, s->p_hold, sizeof s->p_hold);
    return 0;
  }
  int rc = s->ctrl(s, t, p_cmd, s->ctrl_user);
  int bad = rc == 0 ? badCommand(p_cmd) : -1;
  if (rc == 0 && bad < 0) {
    return 0;
  }
  if (!s->source_failed) {
    s->source_failed = 1;
    if (rc != 0) {
      snprintf(s->source_msg, sizeof s->source_msg, "t = %.6g s: the controller returned %d", t,
               rc);
    } else {
      char label[16] = "";
      csg_labelName(bad + 1, label, sizeof label);
      snprintf(s->source_msg, sizeof s->source_msg, "t = %.6g s: the controller's command for "
               "chamber %s is %g MPa (must be finite, 0..%g MPa)", t, label, p_cmd[bad],
               P_CMD_MAX);
    }
  }
  return -1;
}


/* ---- shared by cs_run and cs_simCreate ------------------------------------------------------ */

/* ODE's informational messages ("zero length vector in dRFrom2Axes"): not errors, and the
 * library prints nothing; a host's own handler (crawlsim.c's) is kept */
static void odeQuiet(int num, const char* msg, va_list ap) {
  (void)num;
  (void)msg;
  (void)ap;
}


/* ODE's per-process and per-thread data: dInitODE2 is counted, so this nests in a caller's own
 * initialisation; paired with dCloseODE when the run or the simulation ends */
static void odeOpen(void) {
  dInitODE2(0);
  if (!dGetMessageHandler()) {
    dSetMessageHandler(odeQuiet);
  }
}

static void logLine(const csRunDef* def, const char* fmt, ...)
    __attribute__((format(printf, 2, 3)));
static void logLine(const csRunDef* def, const char* fmt, ...) {
  if (!def->log) {
    return;
  }
  char line[1536];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(line, sizeof line, fmt, ap);
  va_end(ap);
  def->log(def->log_user, line);
}


/* what the run is, before it settles (the banner of `crawlsim run`) */
static void logPlan(const csRunDef* def, const csModel* m, const csData* d,
                    const csRunPlan* plan) {
  if (!def->log) {
    return;
  }
  logLine(def, "scene %s, gait %s, legs %s, friction %.3g, t_end %.3g s, robot mass %.1f g",
        m->scene, m->gait ? plan->gait : "none (commands)", cs_modelLegLevel(m), m->contact.mu,
        cs_modelTableEnd(m), cs_robotMass(d) * 1e6);
  if (cs_modelEndTime(m) > cs_modelTableEnd(m)) {
    logLine(def, "the run ends when the table's clock reaches t_end (the gate holds it): %.4g s "
            "at the latest", cs_modelEndTime(m));
  }
  logLine(def, "conditions %s (%s): %s", cs_conditionsName(m->conditions),
        cs_conditionsSourceName(plan->cond_src), cs_conditionsWhat(m->conditions));
  if (m->gait) {
    logLine(def, "pressure ramp %.4g s (%s), %s", m->sched.ramp,
          m->ramp_given                ? "--ramp"
          : !isnan(m->gait->ramp)      ? "the gait's @ramp"
                                       : "default",
          "each row's change takes it to arrive (gaits_schedule.h)");
  }
  logLine(def, "calibration (rule %s): %s", csr_calibrationRuleName(m->calibration),
        m->robot.map.name);
  const csrLegType* lt = m->robot.leg_type;
  const csrLegSetting* links = csr_legSettingFind(lt, "links");
  logLine(def, "legs %s, %d %s: %s", cs_modelLegLevel(m),
        (int)csr_legSettingGet(lt, &m->robot.leg_settings, "links", 0),
        links ? links->what : "links per segment", m->track_error);
  if (!lt->in_world && m->opt.coupling == CS_COUPLING_TREE) {
    /* what the tree step is (cs_rundef.c stepAdaptive: adaptive unless a step is named) */
    char sub[64] = "";
    if (csr_legSettingFind(lt, "sub")) {
      /* the count the setting stands for (0: by the basis, csr_strainSubIntervals) */
      const csrLegSettings* ls = &m->robot.leg_settings;
      snprintf(sub, sizeof sub, "; %d Magnus sub-intervals per flexible piece",
               csr_strainSubIntervals((int)csr_legSettingGet(lt, ls, "links", 2),
                                      (int)csr_legSettingGet(lt, ls, "sub", 0)));
    }
    if (m->opt.step_adaptive) {
      const int order = (int)csr_legSettingGet(lt, &m->robot.leg_settings, "step_order",
                                               lt->step_order ? lt->step_order : 1);
      logLine(def, "tree step: adaptive, %s, local error %g mm per step, longest step %g s "
              "(sim_adaptive.c)%s", order == 2 ? "BDF2" : "backward Euler", m->opt.step_tol,
              m->opt.h, sub);
    } else {
      logLine(def, "tree step: fixed %g s, order %d%s", m->opt.h,
              (int)csr_legSettingGet(lt, &m->robot.leg_settings, "step_order",
                                     lt->step_order ? lt->step_order : 1), sub);
    }
  }
  const unsigned drop = (unsigned)csr_legSettingGet(lt, &m->robot.leg_settings, "cal_drop", 0);
  if (drop) {
    char what[32];
    csr_calDropFormat(drop, what, sizeof what);
    logLine(def, "calibration parts left out (--cal-drop): %s", what);
  }
  if (m->legs_auto_choice[0]) {
    logLine(def, "--legs auto picked %s", m->legs_auto_choice);
  }
  if (m->foothold) {
    logLine(def, "footholds %s: %d landings chosen from the measured support (%d terrain edges)",
            plan->foothold, m->foothold->n, m->fh_nedge);
  }
  if (m->gate) {
    logLine(def, "gate %s: closed loop (a sensing controller): %d lifts wait until the pair "
            "before is down, read from the chamber pressures against the design's (ramp %g s, "
            "lag %g s, within %g MPa, at most %g s a gate; gaits_gate.h)", plan->gate,
            m->gate->n, m->gate->ramp, m->gate->lag, m->gate->ptol, m->gate->maxwait);
    int nx = 0;
    for (int k = 0; k < m->gate->n; k++) nx += isfinite(m->gate->gate[k].xmin);
    if (nx > 0) {
      logLine(def, "gate %s: %d of them also wait until the measured support stands at their x "
              "(gaits_gate.h `x XMIN`)", plan->gate, nx);
    }
    if (m->gate->crawl_n > 0) {
      logLine(def, "gate %s: the lateral crawl (%d slots of %g s from %g s) ends on the measured "
              "support z: at a boundary of the release's phase when z + %g mm >= %g mm less half "
              "the last two slots' advance (gaits_gate.h `crawl`); without --t-end the run ends "
              "when the table's clock reaches its end (t_end at the latest)", plan->gate,
              m->gate->crawl_n, m->gate->crawl_tpz, m->gate->crawl_t0, m->gate->crawl_carry,
              m->gate->crawl_zend);
    }
    if (m->gate->walk_n > 0) {
      logLine(def, "gate %s: the walk (%d slots of %g s from %g s, then its end) ends on the "
              "measured support x: at a boundary of its end's phase when x + %g mm >= %g mm less "
              "half the last two slots' advance (gaits_gate.h `walk`)", plan->gate,
              m->gate->walk_n, m->gate->walk_tp, m->gate->walk_t0, m->gate->walk_carry,
              m->gate->walk_xend);
    }
  } else if (m->gait) {
    logLine(def, "gate none: open loop (the table on time)");
  }
  double load, pcr;
  cs_modelStanceCheck(m, cs_robotMass(d), &load, &pcr);
  logLine(def, "stance check: %.2f N per leg on half the legs vs sway-buckling load %.2f N per "
        "leg (%.0f %%)%s", load, pcr, 100 * load / pcr,
        load > 0.5 * pcr ? ": bent stance legs will sway and fold; nearly straight ones, six "
                           "or more down, can stand (docs/studies/earth_gait.md)"
                         : "");
}


/* fail now, not after settling, if the output file cannot be written: open it for appending
 * (which neither truncates an existing file nor needs HDF5) and remove it again if it is new */
static csStatus checkWritable(const char* path, csError* err) {
  FILE* f = fopen(path, "rb");
  int existed = f != NULL;
  if (f) {
    fclose(f);
  }
  errno = 0;
  f = fopen(path, "ab");
  if (!f) {
    return cs_errorSet(err, CS_ERR_IO, "--out %s: cannot create output file: %s", path,
                       strerror(errno));
  }
  fclose(f);
  if (!existed) {
    remove(path);
  }
  return CS_OK;
}


/* what the model resolved to, into the result */
static void resultPlan(const csModel* m, csRunResult* res) {
  snprintf(res->scene, sizeof res->scene, "%s", m->scene);
  snprintf(res->conditions, sizeof res->conditions, "%s", cs_conditionsName(m->conditions));
  snprintf(res->legs, sizeof res->legs, "%s", cs_modelLegLevel(m));
  res->links = (int)csr_legSettingGet(m->robot.leg_type, &m->robot.leg_settings, "links", 0);
  res->macro_steps = m->opt.macro_steps;
  res->dt = m->opt.h;
  snprintf(res->calibration, sizeof res->calibration, "%s", m->robot.map.name);
  snprintf(res->calibration_rule, sizeof res->calibration_rule, "%s",
           m->calibration ? csr_calibrationRuleName(m->calibration) : "none");
  snprintf(res->legs_auto_choice, sizeof res->legs_auto_choice, "%s", m->legs_auto_choice);
}


/* how the run ended, into the result: the verdict (issue 10) falls (off the terrain), stops
 * (any other failure: the message says which), tips over, crawls or stands */
static void resultEnd(const csData* d, csStatus st, const csError* err, double wall,
                      csRunResult* res) {
  res->status = st;
  snprintf(res->message, sizeof res->message, "%s", st != CS_OK && err ? err->msg : "");
  res->t_end = cs_time(d);
  cs_supportDisplacement(d, res->position);
  cs_supportOrientation(d, res->quat);
  const double* q = res->quat;
  /* tilt: angle between the support's up axis and world up */
  res->tilt_deg = acos(fmin(1.0, 1 - 2 * (q[1] * q[1] + q[3] * q[3]))) * 180 / 3.14159265358979;
  res->wall_s = wall;
  res->real_time_factor = wall > 0 ? cs_time(d) / wall : 0;
  res->robot_mass_g = cs_robotMass(d) * 1e6;
  res->steps = cs_stepCount(d);
  res->rejected_steps = cs_rejectCount(d);
  res->gain_projections = cs_gainProjectionCount(d);
  const csuTimer* tm = cs_timers(d);
  res->ntimer = (int)CS_NTIMER < (int)CS_RUN_MAX_TIMERS ? (int)CS_NTIMER : (int)CS_RUN_MAX_TIMERS;
  for (int k = 0; k < res->ntimer; k++) {
    snprintf(res->timer_name[k], sizeof res->timer_name[k], "%s", cs_timerName((csTimerId)k));
    res->timer_s[k] = tm[k].wall;
  }
  const double* x = res->position;
  res->interrupted = st == CS_ERR_INTERRUPTED;
  snprintf(res->verdict, sizeof res->verdict, "%s",
           st != CS_OK ? (err && strstr(err->msg, "fell off") ? "falls" : "stops")
           : res->tilt_deg > 30              ? "tips over"
           : fabs(x[0]) >= 20 || fabs(x[2]) >= 20 ? "crawls"
                                                  : "stands");
}


/* steps to t_end without an output file (def.out NULL): cs_runWrite's loop less the file */
static csStatus runNoFile(const csModel* m, csData* d, double* wall, csError* err) {
  double H = cs_modelMacroStep(m);
  long nsteps = lround(cs_modelEndTime(m) / H);
  double w0 = csu_wallSeconds();
  csStatus st = CS_OK;
  for (long i = 1; i <= nsteps && st == CS_OK; i++) {
    if (m->opt.cancel && *m->opt.cancel) {
      st = cs_errorSet(err, CS_ERR_INTERRUPTED, "interrupted at t = %.6g s", cs_time(d));
      break;
    }
    st = cs_step(m, d, err);
    if (st == CS_OK && cs_runOverAt(m, d, i)) {
      break; /* the gait is over on the table's clock (cs_runWrite's end too) */
    }
  }
  *wall = csu_wallSeconds() - w0;
  return st;
}


csStatus cs_run(const csRunDef* def, csRunResult* res, csError* err) {
  csRunResult local;
  if (!res) {
    res = &local;
  }
  memset(res, 0, sizeof *res);
  if (!def) {
    res->status = cs_errorSet(err, CS_ERR_ARG, "no run definition (NULL)");
    snprintf(res->message, sizeof res->message, "no run definition (NULL)");
    return res->status;
  }
  csError e; /* the run's own record: err may be NULL */
  cs_errorClear(&e);
  csModel* m = malloc(sizeof *m);
  if (!m) {
    return cs_errorSet(err, CS_ERR_MEMORY, "out of memory for the model");
  }
  odeOpen(); /* closed below */
  cs_modelInit(m);
  csRunPlan plan;
  csData* d = NULL;
  csStatus st = cs_runDefBuild(def, m, &plan, &e);
  if (st == CS_OK && !m->gait && !(cs_modelEndTime(m) > 0)) {
    st = cs_errorSet(&e, CS_ERR_ARG, "a run without a gait (no_gait) needs --t-end > 0");
  }
  if (st == CS_OK && def->out) st = checkWritable(def->out, &e);
  /* a resumable run: what it is, for its checkpoints (the leg file is read by its contents) */
  char* identity = NULL;
  if (st == CS_OK && (def->checkpoint || def->resume)) {
    identity = malloc(CS_CHECKPOINT_IDENTITY);
    if (!identity) {
      st = cs_errorSet(&e, CS_ERR_MEMORY, "out of memory for the run's identity");
    } else if (cs_runDefIdentity(def, m, &plan, identity, CS_CHECKPOINT_IDENTITY) != 0) {
      st = cs_errorSet(&e, CS_ERR_ARG, "the run definition is too long for a checkpoint "
                       "(more than %d bytes)", CS_CHECKPOINT_IDENTITY);
    }
  }
  if (st == CS_OK) {
    resultPlan(m, res);
    d = cs_dataCreate(m, &e);
    st = d ? CS_OK : e.status;
  }
  if (st == CS_OK) {
    logPlan(def, m, d, &plan);
    int settling = 0; /* the failure, if any, came while settling */
    double wall = 0;
    if (identity) {
      /* a resumable run settles with its checkpoints too; a resumed one continues from its
       * checkpoint (cs_runWriteCheckpointed loads it) and does not settle again */
      const csCheckpointInfo ck = {identity,
                                   isnan(def->checkpoint_every) && !def->resume
                                       ? CS_CHECKPOINT_EVERY_S
                                       : def->checkpoint_every,
                                   0, 0};
      st = cs_runWriteCheckpointed(m, d, def->out, &ck,
                                   def->checkpoint ? def->checkpoint : def->resume, def->resume,
                                   &settling, &wall, &e);
    } else {
      settling = 1;
      st = cs_settle(m, d, &e);
      if (st == CS_OK) {
        settling = 0;
        st = def->out ? cs_runWrite(m, d, def->out, &wall, &e) : runNoFile(m, d, &wall, &e);
      }
    }
    if (st != CS_OK && settling && def->out) {
      /* the output file says so too (the contract: what was written stays readable) */
      csError ferr;
      cs_errorClear(&ferr);
      if (cs_runRecordFailure(m, d, def->out, &e, &ferr) != CS_OK) {
        char cause[sizeof e.msg];
        memcpy(cause, e.msg, sizeof cause);
        cs_errorSet(&e, e.status, "%.300s (output file not written: %.150s)", cause, ferr.msg);
      }
    }
    if (st != CS_OK && settling) {
      res->status = st;
      snprintf(res->message, sizeof res->message, "%s", e.msg);
    } else {
      resultEnd(d, st, &e, wall, res);
      if (m->gate) {
        double held;
        int rel, waited;
        cs_gateHeld(m, d, &held, &rel, &waited);
        logLine(def, "gate %s: closed loop, held %.3f s in total; %d of %d gates released, %d "
                "of them waited; the table's clock at %.3f s", plan.gate, held, rel, m->gate->n,
                waited, cs_gateTableTime(m, d, cs_time(d)));
      }
    }
  } else {
    res->status = st;
    snprintf(res->message, sizeof res->message, "%s", e.msg);
  }
  free(identity);
  cs_dataDestroy(d);
  cs_modelDestroy(m);
  free(m);
  dCloseODE();
  if (err) {
    *err = e;
  }
  return st;
}


/* ---- the stepped simulation ----------------------------------------------------------------- */

csSim* cs_simCreate(const csRunDef* def, csError* err) {
  if (!def) {
    cs_errorSet(err, CS_ERR_ARG, "no run definition (NULL)");
    return NULL;
  }
  csSim* s = calloc(1, sizeof *s);
  if (!s) {
    cs_errorSet(err, CS_ERR_MEMORY, "out of memory for the simulation");
    return NULL;
  }
  odeOpen(); /* closed by cs_simDestroy */
  cs_modelInit(&s->m);
  csStatus st = cs_runDefBuild(def, &s->m, &s->plan, err);
  if (st == CS_OK) {
    s->d = cs_dataCreate(&s->m, err);
    st = s->d ? CS_OK : err ? err->status : CS_ERR_MEMORY;
  }
  if (st == CS_OK) {
    logPlan(def, &s->m, s->d, &s->plan);
    st = cs_settle(&s->m, s->d, err);
  }
  if (st == CS_OK) {
    s->nstate = cs_stateSize(&s->m, s->d);
    s->x_settled = malloc(sizeof(double) * (size_t)s->nstate);
    s->x_save = malloc(sizeof(double) * (size_t)s->nstate);
    if (!s->x_settled || !s->x_save) {
      st = cs_errorSet(err, CS_ERR_MEMORY, "out of memory for %d state values", s->nstate);
    } else {
      cs_stateGet(&s->m, s->d, s->x_settled);
    }
  }
  if (st != CS_OK) {
    cs_simDestroy(s);
    return NULL;
  }
  return s;
}


void cs_simDestroy(csSim* s) {
  if (!s) {
    return;
  }
  cs_dataDestroy(s->d);
  cs_modelDestroy(&s->m);
  free(s->x_settled);
  free(s->x_save);
  free(s);
  dCloseODE();
}


csStatus cs_simStep(csSim* s, csError* err) {
  if (!s) {
    return cs_errorSet(err, CS_ERR_ARG, "no simulation (NULL)");
  }
  if (s->failed) {
    return cs_errorSet(err, CS_ERR_ARG, "a step after a failed step (%.200s): reset or set a "
                       "state first", s->fail_msg);
  }
  const int guard = s->source == SRC_CONTROLLER;
  if (guard) {
    cs_stateGet(&s->m, s->d, s->x_save);
  }
  s->source_failed = 0;
  csError e;
  cs_errorClear(&e);
  csStatus st = cs_step(&s->m, s->d, &e);
  if (guard && s->source_failed) {
    if (st == CS_OK) {
      /* the schedule was evaluated outside the integrator (no lag): put the state back */
      cs_stateSet(&s->m, s->d, s->x_save, NULL);
    }
    st = cs_errorSet(&e, CS_ERR_EXTERNAL, "%s", s->source_msg);
  }
  if (st != CS_OK) {
    s->failed = 1;
    snprintf(s->fail_msg, sizeof s->fail_msg, "%s", e.msg);
  }
  if (err) {
    *err = e;
  }
  return st;
}


csStatus cs_simRunUntil(csSim* s, double t, csError* err) {
  if (!s) {
    return cs_errorSet(err, CS_ERR_ARG, "no simulation (NULL)");
  }
  if (!isfinite(t)) {
    return cs_errorSet(err, CS_ERR_RANGE, "run until t = %g s: not a finite time", t);
  }
  const double H = cs_modelMacroStep(&s->m);
  if ((t - cs_time(s->d)) / H > 1e9) {
    return cs_errorSet(err, CS_ERR_RANGE, "run until t = %g s: more than 1e9 steps of %g s", t,
                       H);
  }
  csStatus st = CS_OK;
  while (st == CS_OK && cs_time(s->d) < t - 0.5 * H) {
    if (s->m.opt.cancel && *s->m.opt.cancel) {
      return cs_errorSet(err, CS_ERR_INTERRUPTED, "interrupted at t = %.6g s", cs_time(s->d));
    }
    st = cs_simStep(s, err);
  }
  return st;
}


csStatus cs_simReset(csSim* s, csError* err) {
  if (!s) {
    return cs_errorSet(err, CS_ERR_ARG, "no simulation (NULL)");
  }
  return cs_simStateSet(s, s->x_settled, err);
}


double cs_simTime(const csSim* s) { return s ? cs_time(s->d) : NAN; }
double cs_simMacroStep(const csSim* s) { return s ? cs_modelMacroStep(&s->m) : NAN; }
int cs_simChamberCount(const csSim* s) { return s ? CSR_NCHAMBER_TOTAL : 0; }
int cs_simLegCount(const csSim* s) { return s ? CSR_NLEG : 0; }
long cs_simStepCount(const csSim* s) { return s ? cs_stepCount(s->d) : 0; }


csStatus cs_simSetPressureCommand(csSim* s, const double* p_cmd, csError* err) {
  if (!s || !p_cmd) {
    return cs_errorSet(err, CS_ERR_ARG, "cs_simSetPressureCommand: %s is NULL",
                       s ? "the command" : "the simulation");
  }
  int bad = badCommand(p_cmd);
  if (bad >= 0) {
    char label[16] = "";
    csg_labelName(bad + 1, label, sizeof label);
    return cs_errorSet(err, CS_ERR_RANGE, "pressure command for chamber %s (index %d) is %g "
                       "MPa: must be finite, 0..%g MPa", label, bad, p_cmd[bad], P_CMD_MAX);
  }
  memcpy(s->p_hold, p_cmd, sizeof s->p_hold);
  s->source = SRC_COMMAND;
  s->m.pressure_source = sourceEval;
  s->m.pressure_ctx = s;
  return CS_OK;
}


csStatus cs_simSetController(csSim* s, csController f, void* user, csError* err) {
  if (!s) {
    return cs_errorSet(err, CS_ERR_ARG, "cs_simSetController: the simulation is NULL");
  }
  s->ctrl = f;
  s->ctrl_user = user;
  s->source = f ? SRC_CONTROLLER : SRC_GAIT;
  s->m.pressure_source = f ? sourceEval : NULL;
  s->m.pressure_ctx = f ? s : NULL;
  return CS_OK;
}


void cs_simGaitCommand(const csSim* s, double t, double* p_cmd) {
  if (!s || !p_cmd) {
    return;
  }
  if (!(t >= 0) || !s->m.gait) {
    memset(p_cmd, 0, CSR_NCHAMBER_TOTAL * sizeof(double));
    return;
  }
  csg_scheduleEval(s->m.gait, &s->m.sched, t, p_cmd);
}


void cs_simSupportPose(const csSim* s, double pos[3], double quat[4]) {
  if (!s) {
    return;
  }
  if (pos) cs_supportDisplacement(s->d, pos);
  if (quat) cs_supportOrientation(s->d, quat);
}


void cs_simSupportTwist(const csSim* s, double v[3], double w[3]) {
  if (!s) {
    return;
  }
  if (v) cs_supportVelocity(s->d, v);
  if (w) cs_supportAngularVelocity(s->d, w);
}


void cs_simFootForces(const csSim* s, double* f) {
  if (!s || !f) {
    return;
  }
  for (int k = 0; k < CSR_NLEG; k++) {
    cs_footForce(&s->m, s->d, k, f + 3 * k);
  }
}


void cs_simPressures(const csSim* s, double* p) {
  if (!s || !p) {
    return;
  }
  memcpy(p, cs_pressures(s->d), CSR_NCHAMBER_TOTAL * sizeof(double));
}


int cs_simLegCenterline(const csSim* s, int leg, int npts, double* xyz) {
  if (!s || !xyz || leg < 0 || leg >= CSR_NLEG || npts < 2 || npts > MAX_CENTERLINE) {
    return -1;
  }
  cs_legCenterline(&s->m, s->d, leg, npts, xyz);
  return 0;
}


int cs_simStateSize(const csSim* s) { return s ? s->nstate : 0; }


void cs_simStateGet(const csSim* s, double* x) {
  if (s && x) {
    cs_stateGet(&s->m, s->d, x);
  }
}


csStatus cs_simStateSet(csSim* s, const double* x, csError* err) {
  if (!s || !x) {
    return cs_errorSet(err, CS_ERR_ARG, "cs_simStateSet: %s is NULL",
                       s ? "the state" : "the simulation");
  }
  csStatus st = cs_stateSet(&s->m, s->d, x, err);
  if (st == CS_OK) {
    s->failed = 0;
    s->fail_msg[0] = '\0';
  }
  return st;
}


const char* cs_version(void) { return CS_VERSION_STRING; }

/* sim_driver.c: model/data life cycle and read-outs (see sim_model.h); the stages are in
 * sim_step.c, the state in sim_state.c, the scheduled pressures in sim_schedule.c, the
 * co-simulation interface in sim_coupling.c.
 *
 * Rationale. ODE owns the rigid support, the leg links and the terrain; the chamber pressures
 * are the continuous state handed to SUNDIALS. Their dynamics here are the simplest physical
 * supply model, a first-order lag per chamber (valve + tube filling, time constant tau), which
 * CVODE integrates across each macro step with a stop time at t + h (it must not step past the
 * exchange point, debian-deps.md "Co-simulation stepping"); CVODE's diagonal linear solver fits
 * the decoupled chambers exactly. Later supply models (valves, tubing, gas per chamber) replace
 * the right-hand side and keep this structure.
 *
 * ODE's QuickStep (projected Gauss-Seidel) is used because the robot is one island of ~100
 * bodies and ~700 constraint rows: the Dantzig solver of dWorldStep is O(rows^3) per step. */
#include <cvode/cvode.h>
#include <cvode/cvode_diag.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "core_nvector.h"
#include "core_sun.h"
#include "sim_internal.h"

_Static_assert(sizeof(dReal) == sizeof(double), "crawlsim needs ODE built in double precision");
_Static_assert(sizeof(sunrealtype) == sizeof(double), "crawlsim needs double SUNDIALS");

csOptions cs_defaultOptions(void) {
  csOptions o;
  /* 1 ms resolves the 0.2 s pressure ramps; the rod legs' tracks are converged in it (0.73 mm
   * from 0.25 ms over the 9 s flat road, docs/studies/speed_accuracy.md) */
  o.h = 1e-3;
  /* one ODE step per exchange (the coupling study, issue 9: a longer exchange costs accuracy
   * on the flat road, docs/studies/speed_accuracy.md) */
  o.macro_steps = 1;
  o.coupling = CS_COUPLING_STAGGERED;
  /* Gauss-Seidel's momentum carry on: without it the scheme loses the impulse its
   * prediction misses (sim_coupling.c) */
  o.coupling_carry = 1;
  /* the tree coupling's Newton passes before a step is rejected and halved: 24, where the
   * flat road's 9 s at 5 ms rejects 2 steps (the same 2 at 32 and 48) against 20 at 16, in
   * 3.96 passes per step against 4.16 (a rejection costs its passes and the halves'), the
   * track 0.06 mm from 16's; at 1 ms 1 rejected against 2, the same 2.64 passes per step
   * (docs/notes/strain_leg.md, "Passes per step"). A pass converges when no leg mode (as a
   * length, robot_strain.h) and no support twist component times h moves by more than
   * tree_tol. 1e-6 mm: on the 9 s flat road it moves the track by 0.02 mm at 1 ms and 0.09 mm
   * at 5 ms from 1e-7, below the run-to-run noise floor (the step +-10 %: 0.07-0.12 / 0.28-0.37
   * mm), for 17-18 % fewer passes; the frictionless centre of mass drifts 1.1e-5 mm in 1 s at
   * 1 ms, 100x below the 0.01 mm in 9 s (docs/notes/strain_leg.md, "Passes per step") */
  o.tree_iterations = 24;
  o.tree_tol = 1e-6;
  o.tree_carry = 0;
  /* the tree step's length: fixed (H) unless asked (a run definition asks for the strain
   * level: cs_rundef.c stepAdaptive); the tolerance is the largest whose track is within 1 mm
   * of the half tolerance's (issue 32's convergence rule; 5e-4 is 1.05 mm from 2.5e-4 on the
   * obstacle's crawl start): docs/notes/strain_leg.md "The strain level's default step" */
  o.step_adaptive = 0;
  o.step_tol = 2.5e-4;
  o.t_end = 0;
  o.output_dt = 0.01;
  /* long enough for the 100 Hz leg modes to die out under 5 ms material damping */
  o.settle = 0.3;
  o.gravity = 9810.0;
  o.legs_weightless = 0; /* conditions `earth` (docs/reference.md "Scene conditions") */
  /* PGS iterations: loads pass from the feet to the support through chains of 13 links,
   * which a Gauss-Seidel sweep propagates one link per iteration. Measured on the crouch gait
   * at 1 m/s^2 (9 s end point): 60 -> 286 mm, 120 -> 334, 240 -> 301, 500 -> 304 mm; 240 is
   * converged to 1 % (README "Earlier findings", item 3) */
  o.solver_iterations = 240;
  /* valve + tube filling of a ~0.5 ml chamber: tens of ms (assumption, documented) */
  o.pneumatic_tau = 0.02;
  o.pneumatic_rtol = 1e-6;
  o.pneumatic_atol = 1e-8;
  o.centerline_points = 25;
  /* 10 m/s: nothing in a crawling gait comes near it */
  o.max_speed = 1e4;
  o.progress = NULL;
  o.progress_user = NULL;
  o.cancel = NULL;
  return o;
}


void cs_modelInit(csModel* m) {
  memset(m, 0, sizeof *m);
  m->opt = cs_defaultOptions();
  m->conditions = CS_CONDITIONS_EARTH; /* as opt.legs_weightless = 0 */
  m->sched = csg_defaultScheduleOptions();
  m->contact = csc_defaultContactParams();
  csr_robotDefaultModel(&m->robot, NULL);
  /* rod legs are co-simulated: their coupling (Gauss-Seidel) comes with the level */
  cs_modelSetLegLevel(m, m->robot.leg_type);
  m->legs_auto_tol_mm = NAN;
  m->track_error_mm = NAN;
  m->cal_rule = -1;
}


void cs_modelSetConditions(csModel* m, csConditions c) {
  m->conditions = c;
  m->opt.legs_weightless = c == CS_CONDITIONS_PAPER;
}


const char* cs_modelLegLevel(const csModel* m) {
  return m->robot.leg_type ? m->robot.leg_type->name : "none";
}


double cs_modelMacroStep(const csModel* m) { return m->opt.macro_steps * m->opt.h; }


long cs_modelOutputEvery(const csModel* m) {
  const long n = lround(m->opt.output_dt / cs_modelMacroStep(m));
  return n < 1 ? 1 : n;
}


csStatus cs_modelLoad(csModel* m, const char* scene, const char* terrain_path,
                      const char* gait_path, const char* calibration_path, csError* err) {
  snprintf(m->scene, sizeof m->scene, "%s", scene);
  snprintf(m->gait_path, sizeof m->gait_path, "%s", gait_path ? gait_path : "");
  csStatus st = cst_terrainLoad(&m->terrain, terrain_path, err);
  if (st != CS_OK) {
    return st;
  }
  csg_gaitDestroy(m->gait);
  m->gait = NULL;
  if (gait_path) {
    m->gait = csg_gaitRead(gait_path, NULL, err);
  }
  if (gait_path && !m->gait) {
    return err ? err->status : CS_ERR_PARSE;
  }
  /* a table that states its ramp (a designed motion sampled every `ramp` s) plays with it
   * unless the caller chose one (gaits_csv.h, gaits_schedule.h) */
  if (m->gait && !m->ramp_given && !isnan(m->gait->ramp)) {
    m->sched.ramp = m->gait->ramp;
  }
  csr_calibrationClose(m->calibration);
  /* a rule given (--cal-rule) applies to an FE mode table only: other kinds are refused */
  csrCalOptions cal_opt = csr_calModelDefaultOptions();
  cal_opt.rule = (csrCalRule)m->cal_rule;
  m->calibration = csr_calibrationOpenWith(calibration_path, &m->robot.leg,
                                           m->cal_rule >= 0 ? &cal_opt : NULL, err);
  if (!m->calibration) {
    return err ? err->status : CS_ERR_PARSE;
  }
  m->robot.map = csr_calibrationMap(m->calibration);
  return CS_OK;
}


double cs_modelTableEnd(const csModel* m) {
  if (m->opt.t_end > 0 || !m->gait || m->gait->nrow == 0) {
    return m->opt.t_end;
  }
  /* the last row holds for ever: the run ends when its change has finished, or at the last
   * row's time if that is later than every change (an end-marker row) */
  int n = m->gait->nrow;
  double t_last = m->gait->time[n - 1];
  if (n >= 2 && !memcmp(m->gait->pressure + (size_t)CSG_NLABEL * (n - 1),
                        m->gait->pressure + (size_t)CSG_NLABEL * (n - 2),
                        CSG_NLABEL * sizeof(double))) {
    return t_last;
  }
  return t_last + m->sched.ramp;
}


double cs_modelEndTime(const csModel* m) {
  const double T = cs_modelTableEnd(m);
  if (m->opt.t_end > 0 || !m->gait || !m->gate) {
    return T;
  }
  /* a gate holds the table's clock, each of its n gates for maxwait at most (gaits_gate.h): the
   * longest the run can last; cs_runOverAt ends it when the table is over */
  return T + m->gate->n * m->gate->maxwait;
}


csStatus cs_modelApplySceneFile(csModel* m, const cstSceneFile* s, csError* err) {
  cstTerrain* t = &m->terrain;
  if (s->has_start) {
    if (!isfinite(cst_terrainHeightAt(t, s->start[0], s->start[1]))) {
      return cs_errorSet(err, CS_ERR_RANGE, "%s: start (%g, %g) is not above any box of %s",
                         s->source, s->start[0], s->start[1], t->source);
    }
    t->start[0] = s->start[0];
    t->start[1] = s->start[1];
  }
  if (s->has_heading) t->heading_deg = s->heading_deg;
  if (s->has_slope) t->slope_deg = s->slope_deg;
  return CS_OK;
}


void cs_modelStanceCheck(const csModel* m, double mass_total, double* load_per_leg,
                         double* p_critical) {
  double EI = m->robot.leg_params.E_bend * csr_legSectionI(&m->robot.leg);
  double L = csr_actuatorLength(&m->robot.leg);
  *p_critical = CS_PI * CS_PI * EI / (L * L);
  /* under `paper` the legs feel no gravity: the stance legs carry the support's weight only */
  double weight_mass = m->opt.legs_weightless ? m->robot.support_mass : mass_total;
  *load_per_leg = weight_mass * m->opt.gravity / (CSR_NLEG / 2);
}


void cs_modelDestroy(csModel* m) {
  if (m) {
    csg_gaitDestroy(m->gait);
    m->gait = NULL;
    csg_footholdDestroy(m->foothold);
    m->foothold = NULL;
    csg_gateDestroy(m->gate);
    m->gate = NULL;
    csr_calibrationClose(m->calibration);
    m->calibration = NULL;
  }
}


/* CVODE right-hand side: dp/dt = (p_cmd(t) - p) / tau; 0 = ok (SUNDIALS convention) */
static int pneumaticRhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  csData* d = user;
  double pc[CSR_NCHAMBER_TOTAL];
  if (cs_schedule(d->m, d, t, pc) != 0) {
    return -1; /* the pressure source failed: the step fails (cs_api.c says why) */
  }
  d->pn_count[1]++; /* cs_pneumaticCounts */
  const double* p = N_VGetArrayPointer(y);
  double* dp = N_VGetArrayPointer(ydot);
  double inv_tau = 1.0 / d->m->opt.pneumatic_tau;
  for (int i = 0; i < CSR_NCHAMBER_TOTAL; i++) {
    if (!isfinite(p[i])) {
      return -1;
    }
    dp[i] = (pc[i] - p[i]) * inv_tau;
  }
  return 0;
}


static csStatus validateOptions(const csOptions* o, csError* err) {
  if (!(o->h > 0 && o->h <= 0.01)) {
    return cs_errorSet(err, CS_ERR_RANGE, "step h = %g s must be in (0, 0.01]", o->h);
  }
  if (o->macro_steps < 1 || o->macro_steps > 100000) {
    return cs_errorSet(err, CS_ERR_RANGE, "macro step of %d ODE steps must be 1..100000",
                       o->macro_steps);
  }
  if (o->coupling != CS_COUPLING_STAGGERED && o->coupling != CS_COUPLING_STABILISED &&
      o->coupling != CS_COUPLING_GAUSS_SEIDEL && o->coupling != CS_COUPLING_TREE) {
    return cs_errorSet(err, CS_ERR_RANGE, "unknown coupling scheme %d", (int)o->coupling);
  }
  if (o->coupling_carry != 0 && o->coupling_carry != 1) {
    return cs_errorSet(err, CS_ERR_RANGE, "coupling_carry %d must be 0 or 1", o->coupling_carry);
  }
  if (o->tree_carry != 0 && o->tree_carry != 1) {
    return cs_errorSet(err, CS_ERR_RANGE, "tree_carry %d must be 0 or 1", o->tree_carry);
  }
  if (o->tree_iterations < 1 || o->tree_iterations > 1000 || !(o->tree_tol > 0) ||
      !isfinite(o->tree_tol)) {
    return cs_errorSet(err, CS_ERR_RANGE, "tree coupling: %d Newton passes must be 1..1000 and "
                       "the tolerance %g mm > 0", o->tree_iterations, o->tree_tol);
  }
  if ((o->step_adaptive != 0 && o->step_adaptive != 1) || !(o->step_tol > 0) ||
      !isfinite(o->step_tol)) {
    return cs_errorSet(err, CS_ERR_RANGE, "adaptive step %d must be 0 or 1 and its tolerance %g "
                       "mm > 0", o->step_adaptive, o->step_tol);
  }
  double H = o->macro_steps * o->h;
  if (!(o->output_dt >= H) || !isfinite(o->output_dt)) {
    return cs_errorSet(err, CS_ERR_RANGE, "output interval %g s must be >= the macro step %g s",
                       o->output_dt, H);
  }
  if (!(o->settle >= 0 && o->gravity >= 0 && (o->legs_weightless == 0 ||
                                               o->legs_weightless == 1) &&
        o->solver_iterations >= 1 &&
        o->pneumatic_tau >= 0 && o->centerline_points >= 2 && o->max_speed > 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "invalid simulation options");
  }
  return CS_OK;
}


csData* cs_dataCreate(const csModel* m, csError* err) {
  if (validateOptions(&m->opt, err) != CS_OK ||
      csc_contactParamsValidate(&m->contact, err) != CS_OK) {
    return NULL;
  }
  csData* d = calloc(1, sizeof *d);
  if (!d) {
    cs_errorSet(err, CS_ERR_MEMORY, "out of memory");
    return NULL;
  }
  d->m = m;
  for (int k = 0; k < CSG_FOOTHOLD_MAX; k++) {
    d->fh_choice[k] = -1; /* not decided */
  }
  d->gate_issued = INFINITY; /* the gate (sim_gate.c): nothing held, every row issued */
  /* QuickStep shuffles its constraint rows with ODE's one process-wide generator; each data
   * keeps its own seed, starting at 0, and puts it in for its steps only (cs_step), so a run's
   * result is independent of what else ran in the same process (the determinism test).
   * Stepping stays on one thread at a time, as ODE requires for collision (debian-deps.md P3). */
  d->rng_seed = 0;
  d->world = dWorldCreate();
  /* a sloped terrain turns gravity, not the terrain (terrains_terrain.h `slope`) */
  double gdir[3];
  cst_terrainGravityDir(&m->terrain, gdir);
  dWorldSetGravity(d->world, m->opt.gravity * gdir[0], m->opt.gravity * gdir[1],
                   m->opt.gravity * gdir[2]);
  dWorldSetQuickStepNumIterations(d->world, m->opt.solver_iterations);
  d->terrain_space = dSimpleSpaceCreate(0);
  d->robot_space = dSimpleSpaceCreate(0);
  d->contacts = dJointGroupCreate(0);
  cst_terrainBuildOde(&m->terrain, d->terrain_space);

  /* the support's hip plane sits one leg length above the ground at the start, plus a
   * 0.5 mm gap so nothing starts in penetration; settling closes it */
  double ground = cst_terrainHeightAt(&m->terrain, m->terrain.start[0], m->terrain.start[1]);
  double c[3] = {m->terrain.start[0], ground + csr_actuatorLength(&m->robot.leg) + 0.5,
                 m->terrain.start[1]};
  csrRobotEnv env = {d->world, d->robot_space, m->opt.h,
                     {m->opt.gravity * gdir[0], m->opt.gravity * gdir[1], m->opt.gravity * gdir[2]},
                     m->opt.legs_weightless, &m->terrain, &m->contact,
                     /* the terrain's heading (terrains_terrain.h: degrees about +y, 0 = +x):
                      * the robot is built turned, every level alike (robot_robot.h) */
                     m->terrain.heading_deg * CS_PI / 180.0};
  d->robot = csr_robotCreate(&m->robot, &env, c, err);
  if (!d->robot) {
    cs_dataDestroy(d);
    return NULL;
  }
  d->t = -m->opt.settle;
  d->cosim.active = !m->robot.leg_type->in_world;
  if (d->cosim.active && m->opt.coupling == CS_COUPLING_TREE &&
      (!m->robot.leg_type->prepare || !m->robot.leg_type->finish || m->opt.macro_steps != 1)) {
    cs_errorSet(err, CS_ERR_ARG, "the tree coupling needs a tree-stepped leg level (strain) and "
                "one ODE step per macro step (legs %s, %d macro steps)", cs_modelLegLevel(m),
                m->opt.macro_steps);
    cs_dataDestroy(d);
    return NULL;
  }
  if (m->opt.step_adaptive && !(d->cosim.active && m->opt.coupling == CS_COUPLING_TREE)) {
    cs_errorSet(err, CS_ERR_ARG, "the adaptive step needs the tree coupling (strain legs; legs "
                "%s)", cs_modelLegLevel(m));
    cs_dataDestroy(d);
    return NULL;
  }
  d->h_try = cs_modelMacroStep(m);
  if (cs_couplingCreate(m, d, err) != CS_OK) {
    cs_dataDestroy(d);
    return NULL;
  }
  /* the state buffer of step rollback: allocated once (no allocation in the step loop) */
  d->nstate = cs_stateSize(m, d);
  d->save = malloc((size_t)(CS_MAX_SPLIT + 2) * (size_t)d->nstate * sizeof(double));
  d->fb = calloc(CS_MAX_FEEDBACK, sizeof *d->fb);
  if (!d->save || !d->fb) {
    cs_errorSet(err, CS_ERR_MEMORY, "out of memory");
    cs_dataDestroy(d);
    return NULL;
  }

  /* pneumatics */
  if (m->opt.pneumatic_tau > 0) {
    /* a context that never prints: a failed pneumatic step is returned as a status with its
     * own message (the controller's, the gait's) instead */
    if (cs_sunContextCreate(&d->sun) != 0) {
      cs_errorSet(err, CS_ERR_SOLVER, "SUNDIALS: cannot create a context");
      cs_dataDestroy(d);
      return NULL;
    }
    d->y = N_VNew_Serial(CSR_NCHAMBER_TOTAL, d->sun);
    if (d->y) {
      /* SUNDIALS' vector kernels compiled here, the same bits (core_nvector.h): the library's
       * own were most of CVODE's cost on the 96 pressures (docs/notes/performance.md "Fixed
       * costs"); CVODE's work vectors are cloned from y and inherit them */
      cs_nvectorFastOps(d->y);
      N_VConst(0.0, d->y);
    }
    d->cvode = CVodeCreate(CV_BDF, d->sun);
    if (!d->y || !d->cvode || CVodeInit(d->cvode, pneumaticRhs, d->t, d->y) != CV_SUCCESS ||
        CVodeSStolerances(d->cvode, m->opt.pneumatic_rtol, m->opt.pneumatic_atol) !=
            CV_SUCCESS ||
        CVodeSetUserData(d->cvode, d) != CV_SUCCESS || CVDiag(d->cvode) != CVDIAG_SUCCESS ||
        CVodeSetMaxNumSteps(d->cvode, 100000) != CV_SUCCESS || cs_cvodeSilence(d->cvode) != 0) {
      cs_errorSet(err, CS_ERR_SOLVER, "CVODE: cannot set up the pneumatic integrator");
      cs_dataDestroy(d);
      return NULL;
    }
  }
  return d;
}


void cs_dataDestroy(csData* d) {
  if (!d) {
    return;
  }
  if (d->cvode) {
    CVodeFree(&d->cvode);
  }
  if (d->y) {
    N_VDestroy(d->y);
  }
  if (d->sun) {
    SUNContext_Free(&d->sun);
  }
  if (d->robot) {
    csr_robotDestroy(d->robot);
  }
  free(d->save);
  free(d->fb);
  if (d->contacts) {
    dJointGroupDestroy(d->contacts);
  }
  if (d->robot_space) {
    dSpaceDestroy(d->robot_space);
  }
  if (d->terrain_space) {
    cst_hfReleaseOde(d->terrain_space); /* the heightfield's data is not the geom's */
    dSpaceDestroy(d->terrain_space);
  }
  if (d->world) {
    dWorldDestroy(d->world);
  }
  free(d);
}


double cs_time(const csData* d) { return d->t; }


void cs_supportDisplacement(const csData* d, double pos[3]) {
  const dReal* x = dBodyGetPosition(d->robot->support);
  csu_set3(pos, x[0] - d->x0[0], x[1] - d->x0[1], x[2] - d->x0[2]);
}


void cs_supportOrientation(const csData* d, double q[4]) {
  const dReal* Q = dBodyGetQuaternion(d->robot->support);
  for (int i = 0; i < 4; i++) {
    q[i] = Q[i];
  }
}


const double* cs_pressures(const csData* d) { return d->p; }


void cs_supportVelocity(const csData* d, double v[3]) {
  const dReal* V = dBodyGetLinearVel(d->robot->support);
  csu_set3(v, V[0], V[1], V[2]);
}


void cs_supportAngularVelocity(const csData* d, double w[3]) {
  const dReal* W = dBodyGetAngularVel(d->robot->support);
  csu_set3(w, W[0], W[1], W[2]);
}


void cs_legCenterline(const csModel* m, const csData* d, int k, int npts, double* out) {
  m->robot.leg_type->centerline(d->robot->legs[k], npts, out);
}


void cs_legWrench(const csData* d, int k, csrWrench* w) { *w = d->cosim.w[k]; }


void cs_robotCenterOfMass(const csModel* m, const csData* d, double com[3]) {
  (void)m;
  csr_robotCenterOfMass(d->robot, com);
}


long cs_stepCount(const csData* d) { return d->nstep; }


long cs_rejectCount(const csData* d) { return d->nreject; }
long cs_treePassCount(const csData* d) { return d->cosim.tree_passes; }
long cs_treeReleaseCount(const csData* d) { return d->cosim.tree_released; }


long cs_treeLimitCount(const csData* d) { return d->cosim.tree_limited; }
long cs_gainProjectionCount(const csData* d) { return d->ngain_proj; }


void cs_pneumaticCounts(const csData* d, long counts[2]) {
  counts[0] = d->pn_count[0];
  counts[1] = d->pn_count[1];
}


const csrLeg* cs_leg(const csData* d, int k) { return d->robot->legs[k]; }


const csuTimer* cs_timers(const csData* d) { return d->timer; }


const char* cs_timerName(csTimerId id) {
  switch (id) {
#define CS_TIMER_CASE(tid, name, what) \
  case tid:                            \
    return name;
    CS_TIMER_LIST(CS_TIMER_CASE)
#undef CS_TIMER_CASE
    case CS_NTIMER:
      break;
  }
  return "unknown";
}


int cs_contactCount(const csData* d) { return d->cstats.npoints; }


void cs_contactForce(const csData* d, double f[3]) { csu_copy3(f, d->contact_force); }


double cs_contactDepth(const csData* d) { return d->cstats.max_depth; }


double cs_legContactDepth(const csModel* m, const csData* d) {
  const csrLegType* lt = m->robot.leg_type;
  double depth = 0.0;
  for (int k = 0; lt->contactDepth && k < CSR_NLEG; k++) {
    depth = fmax(depth, lt->contactDepth(d->robot->legs[k]));
  }
  return depth;
}


void cs_supportCorners(const csModel* m, const csData* d, double corners[24]) {
  const dReal* P = dBodyGetPosition(d->robot->support);
  const dReal* R = dBodyGetRotation(d->robot->support); /* 3x4 row-major */
  const double* L = m->robot.support_size;
  /* VTK hexahedron order: (-,-,-) (+,-,-) (+,-,+) (-,-,+) then the same at +y */
  static const double kSign[8][3] = {{-1, -1, -1}, {1, -1, -1}, {1, -1, 1}, {-1, -1, 1},
                                     {-1, 1, -1},  {1, 1, -1},  {1, 1, 1},  {-1, 1, 1}};
  for (int c = 0; c < 8; c++) {
    double l[3] = {0.5 * L[0] * kSign[c][0], 0.5 * L[1] * kSign[c][1], 0.5 * L[2] * kSign[c][2]};
    for (int i = 0; i < 3; i++) {
      corners[3 * c + i] = P[i] + R[4 * i] * l[0] + R[4 * i + 1] * l[1] + R[4 * i + 2] * l[2];
    }
  }
}


double cs_robotMass(const csData* d) { return d->robot->mass_total; }

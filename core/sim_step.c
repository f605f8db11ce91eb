/* sim_step.c: the staged macro step with rollback, and settling (see sim_model.h).
 *
 * Rationale. The step is a fixed list of stage functions (schedule, pneumatics, legs, support,
 * check), each timed into d->timer[] (Box2D's b2SolverStage and world profile, MuJoCo's
 * mjData.timer). Before the stages run, the whole state is copied into a buffer allocated with
 * the data (cs_stateGet); when a stage fails it is copied back (cs_stateSet), so a failed step
 * changes nothing, as MuJoCo's mj_RungeKutta saves and restores around its stages. The copy is
 * ~2 k doubles for the rod robot at 4 elements per segment: a small part of a step (timer
 * "save").
 *
 * Retried smaller. A tree-coupled step (CS_COUPLING_TREE) that a stage rejects (a leg's step
 * that did not converge, a foot sunk past its bound: CS_ERR_REJECTED) is restored and tried
 * again as two halves, each again halved when it is rejected, down to CS_MAX_SPLIT halvings;
 * each depth saves into its own slot of d->save, so a half that fails for good restores the
 * whole step (cs_stepTry). With opt.step_adaptive the macro step is crossed in steps of the
 * error controller's length (sim_adaptive.c), each one such try. The other couplings exchange at a fixed macro step and return the
 * rejection to the caller, as before.
 *
 * Order of the arithmetic. With in-world legs and one ODE step per macro step the stages do
 * exactly what the pre-stage driver did, in the same order (pressures at t + h, joint targets
 * from them, contacts, QuickStep), so a run's track is bit-identical to it (test_state). */
#include <cvode/cvode.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "core_math.h"
#include "gaits_labels.h"
#include "sim_internal.h"

/* stage functions: each returns CS_OK or a failure status with err filled */
static csStatus stageSchedule(const csModel* m, csData* d, double t1, csError* err);
static csStatus stagePneumatics(const csModel* m, csData* d, double t1, csError* err);
static csStatus stageLegs(const csModel* m, csData* d, double t1, double H, csError* err);
static csStatus stageLegsAfter(const csModel* m, csData* d, csError* err);
static csStatus stageSupport(const csModel* m, csData* d, double H, csError* err);

/* the tree coupling is on (a tree-stepped level, CS_COUPLING_TREE) */
static int treeStep(const csModel* m, const csData* d) {
  return d->cosim.active && m->opt.coupling == CS_COUPLING_TREE;
}
static csStatus stageCheck(const csModel* m, const csData* d, double t1, csError* err);


static csStatus stageSchedule(const csModel* m, csData* d, double t1, csError* err) {
  (void)err;
  cs_schedule(m, d, t1, d->p_cmd);
  return CS_OK;
}


/* advance the chamber pressures to t1 (CVODE with a stop time: it must not step past the
 * exchange point, debian-deps.md "Co-simulation stepping") */
static csStatus stagePneumatics(const csModel* m, csData* d, double t1, csError* err) {
  memcpy(d->p0, d->p, sizeof d->p0);
  if (m->opt.pneumatic_tau <= 0) {
    cs_schedule(m, d, t1, d->p);
    return CS_OK;
  }
  sunrealtype tret;
  /* CVODE's step counter restarts with it (CVodeReInit after a restore): the call's share */
  long nst0 = 0, nst1 = 0;
  CVodeGetNumSteps(d->cvode, &nst0);
  CVodeSetStopTime(d->cvode, t1);
  int rc = CVode(d->cvode, t1, d->y, &tret, CV_NORMAL);
  CVodeGetNumSteps(d->cvode, &nst1);
  d->pn_count[0] += nst1 - nst0;
  if (rc < 0) {
    return cs_errorSet(err, CS_ERR_SOLVER, "t = %.4f s: CVODE failed on the chamber pressures "
                       "(flag %d)", d->t, rc);
  }
  memcpy(d->p, N_VGetArrayPointer(d->y), sizeof d->p);
  return CS_OK;
}


/* the status of a co-simulated legs' advance that returned rc (0, > 0 recoverable, < 0) */
static csStatus advanceStatus(const csModel* m, const csData* d, int rc, csError* err);


/* every leg's actuation for [t, t1]; co-simulated legs then advance across it (Gauss-Seidel:
 * after the support stage, stageLegsAfter) */
static csStatus stageLegs(const csModel* m, csData* d, double t1, double H, csError* err) {
  int rc = csr_robotActuate(d->robot, d->t, d->p0, t1, d->p);
  if (rc == CSR_MAP_OUT_OF_RANGE) {
    int worst = 0;
    for (int i = 1; i < CSR_NCHAMBER_TOTAL; i++) {
      worst = d->p[i] > d->p[worst] ? i : worst;
    }
    char label[16] = "";
    csg_labelName(worst + 1, label, sizeof label);
    return cs_errorSet(err, CS_ERR_RANGE, "t = %.4f s: chamber %s at %.4f MPa is above the "
                       "calibrated range (up to %g MPa) of %s", d->t, label, d->p[worst],
                       m->robot.map.p_max, m->robot.map.name);
  }
  if (rc > 0) {
    return cs_errorSet(err, CS_ERR_REJECTED, "t = %.4f s: leg actuation asks for a smaller "
                       "step (code %d)", d->t, rc);
  }
  if (rc < 0) {
    return cs_errorSet(err, CS_ERR_SOLVER, "t = %.4f s: leg actuation failed (code %d)", d->t,
                       rc);
  }
  if (!d->cosim.active || cs_couplingGS(m, d)) {
    return CS_OK;
  }
  if (treeStep(m, d)) {
    /* the legs condense their step (the step may be a part of the macro step: cs_step) */
    return advanceStatus(m, d, cs_couplingTreePrepare(m, d, H, err), err);
  }
  return advanceStatus(m, d, cs_couplingAdvance(m, d, cs_modelMacroStep(m), err), err);
}


/* Gauss-Seidel: the co-simulated legs advance along the support's motion of this step; tree:
 * they finish their condensed step along it */
static csStatus stageLegsAfter(const csModel* m, csData* d, csError* err) {
  if (treeStep(m, d)) {
    return advanceStatus(m, d, cs_couplingTreeFinish(m, d, err), err);
  }
  return advanceStatus(m, d, cs_couplingAdvanceGS(m, d, cs_modelMacroStep(m), err), err);
}


static csStatus advanceStatus(const csModel* m, const csData* d, int rc, csError* err) {
  if (rc == 0) {
    return CS_OK;
  }
  /* a leg that named the cause in err keeps its words (cs_couplingAdvance cleared err first)
   * and, when fatal, its status; a recoverable one is always CS_ERR_REJECTED */
  csStatus st = rc > 0 ? CS_ERR_REJECTED : CS_ERR_SOLVER;
  if (err && err->status != CS_OK) {
    if (rc > 0) {
      err->status = st;
    }
    return err->status;
  }
  return cs_errorSet(err, st, "t = %.4f s: a %s leg %s (code %d)", d->t, cs_modelLegLevel(m),
                     rc > 0 ? "asks for a smaller step" : "failed", rc);
}


/* the in-world leg (0..7) that body b belongs to, -1 for the support or a co-simulated level */
static int bodyLeg(const csData* d, dBodyID b) {
  const csrLegType* lt = d->robot->type;
  for (int k = 0; lt->ownsBody && b != d->robot->support && k < CSR_NLEG; k++) {
    if (lt->ownsBody(d->robot->legs[k], b)) {
      return k;
    }
  }
  return -1;
}


/* ask ODE for the force of every contact joint on a robot body (the joints of this step are
 * the only contact joints: the group is emptied after every step). Each body is visited once,
 * through its first geom; a contact joint joins a robot body and the static terrain. */
static void contactFeedbackAttach(csData* d) {
  d->nfb = 0;
  d->nfb_over = 0;
  int ng = dSpaceGetNumGeoms(d->robot_space);
  for (int i = 0; i < ng; i++) {
    dGeomID g = dSpaceGetGeom(d->robot_space, i);
    dBodyID b = dGeomGetBody(g);
    if (!b || dBodyGetFirstGeom(b) != g) {
      continue;
    }
    int nj = dBodyGetNumJoints(b);
    const int leg = bodyLeg(d, b);
    for (int k = 0; k < nj; k++) {
      dJointID j = dBodyGetJoint(b, k);
      if (dJointGetType(j) != dJointTypeContact) {
        continue;
      }
      if (d->nfb < CS_MAX_FEEDBACK) {
        memset(&d->fb[d->nfb], 0, sizeof d->fb[d->nfb]);
        d->fb_leg[d->nfb] = (signed char)leg;
        dJointSetFeedback(j, &d->fb[d->nfb++]);
      } else {
        d->nfb_over++;
      }
    }
  }
}


/* sum the measured contact forces on the robot. csc_collide attaches (terrain, robot body);
 * ODE stores a joint whose first body is 0 reversed and reports the force on its one body in
 * f1; f2 stays as cleared (zero), since no contact joint has a second moving body */
static void contactFeedbackSum(csData* d) {
  csu_set3(d->contact_force, 0, 0, 0);
  memset(d->leg_contact_force, 0, sizeof d->leg_contact_force);
  for (int i = 0; i < d->nfb; i++) {
    for (int k = 0; k < 3; k++) {
      d->contact_force[k] += d->fb[i].f1[k] + d->fb[i].f2[k];
      if (d->fb_leg[i] >= 0) {
        d->leg_contact_force[d->fb_leg[i]][k] += d->fb[i].f1[k] + d->fb[i].f2[k];
      }
    }
  }
}


/* macro_steps ODE steps: the legs' wrenches and rows, contacts, QuickStep; with the tree
 * coupling one ODE step of H with the legs' condensed step solved into it */
static csStatus stageSupport(const csModel* m, csData* d, double H, csError* err) {
  if (treeStep(m, d)) {
    double w = csu_wallSeconds();
    int rc = cs_couplingApplyTree(m, d, H, err);
    w = csu_timerAdd(&d->timer[CS_TIMER_TREE], w);
    if (rc != 0) {
      return advanceStatus(m, d, rc, err);
    }
    csc_collide(&m->contact, d->world, d->terrain_space, d->robot_space, d->contacts, H,
                &d->cstats);
    contactFeedbackAttach(d);
    csu_timerAdd(&d->timer[CS_TIMER_CONTACT], w);
    dWorldQuickStep(d->world, H);
    contactFeedbackSum(d);
    dJointGroupEmpty(d->contacts);
    return CS_OK;
  }
  if (d->cosim.active && cs_couplingGS(m, d)) {
    cs_couplingBegin(m, d);
  }
  for (int j = 0; j < m->opt.macro_steps; j++) {
    if (d->cosim.active) {
      cs_couplingApply(m, d, j);
    }
    double tc = csu_wallSeconds();
    csc_collide(&m->contact, d->world, d->terrain_space, d->robot_space, d->contacts, m->opt.h,
                &d->cstats);
    contactFeedbackAttach(d);
    csu_timerAdd(&d->timer[CS_TIMER_CONTACT], tc);
    dWorldQuickStep(d->world, m->opt.h);
    contactFeedbackSum(d);
    dJointGroupEmpty(d->contacts);
  }
  return CS_OK;
}


/* a non-finite or runaway support, or one below the terrain, means the run diverged; t1 is
 * the time the state belongs to */
static csStatus stageCheck(const csModel* m, const csData* d, double t1, csError* err) {
  const dReal* x = dBodyGetPosition(d->robot->support);
  const dReal* v = dBodyGetLinearVel(d->robot->support);
  for (int i = 0; i < 3; i++) {
    if (!isfinite(x[i]) || !isfinite(v[i])) {
      return cs_errorSet(err, CS_ERR_DIVERGED,
                         "t = %.4f s: simulation diverged: support state is not finite", t1);
    }
  }
  /* below every terrain box: the robot left the terrain (fell off an edge) */
  double floor_y = INFINITY;
  for (int i = 0; i < m->terrain.nbox; i++) {
    const cstBox* b = &m->terrain.box[i];
    floor_y = fmin(floor_y, b->oriented ? b->wlo[1] : b->lo[1]);
  }
  if (m->terrain.has_hf) {
    floor_y = fmin(floor_y, m->terrain.hf.hmin - m->terrain.hf.thickness);
  }
  if (x[1] < floor_y) {
    return cs_errorSet(err, CS_ERR_DIVERGED,
                       "t = %.4f s: the support fell off the terrain (y = %.1f mm, below the "
                       "lowest terrain surface %.1f mm)",
                       t1, x[1], floor_y);
  }
  double speed = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  if (speed > m->opt.max_speed) {
    return cs_errorSet(err, CS_ERR_DIVERGED,
                       "t = %.4f s: simulation diverged: support speed %.3g mm/s exceeds %.3g "
                       "(try a smaller step)",
                       t1, speed, m->opt.max_speed);
  }
  return CS_OK;
}


/* One try of the step [d->t, t1] of length H from the state saved in `save`: the stages in order; on
 * success d->t = t1, else the state is restored from `save` (nreject counts it). A rejected
 * tree-coupled step is then retried as two halves, each saved into the next slot of d->save,
 * down to CS_MAX_SPLIT halvings; when a half fails for good, the whole step is restored. */
csStatus cs_stepTry(const csModel* m, csData* d, double t1, double H, int depth,
                   csError* err) {
  double w = csu_wallSeconds();
  if (depth == 0) {
    d->h_try = H; /* the tree's rules for the halvings of this try (sim_coupling.c) */
  }
  double* save = d->save + (size_t)depth * (size_t)d->nstate;
  cs_stateGet(m, d, save);
  w = csu_timerAdd(&d->timer[CS_TIMER_SAVE], w);
  /* this data's place in ODE's random sequence (sim_internal.h rng_seed) */
  dRandSetSeed(d->rng_seed);
  /* the landing gate decides from the state at the step's start (sim_gate.c) */
  cs_gateDecide(m, d);
  /* the stages in order; each is timed whether it succeeds or not */
  csStatus st = stageSchedule(m, d, t1, err);
  w = csu_timerAdd(&d->timer[CS_TIMER_SCHEDULE], w);
  if (st == CS_OK) {
    st = stagePneumatics(m, d, t1, err);
    w = csu_timerAdd(&d->timer[CS_TIMER_PNEUMATICS], w);
  }
  if (st == CS_OK) {
    st = stageLegs(m, d, t1, H, err);
    w = csu_timerAdd(&d->timer[CS_TIMER_LEGS], w);
  }
  if (st == CS_OK) {
    st = stageSupport(m, d, H, err);
    w = csu_timerAdd(&d->timer[CS_TIMER_SUPPORT], w);
  }
  if (st == CS_OK && d->cosim.active && (cs_couplingGS(m, d) || treeStep(m, d))) {
    st = stageLegsAfter(m, d, err);
    w = csu_timerAdd(&d->timer[CS_TIMER_LEGS], w);
  } else if (st == CS_OK && d->cosim.active && m->opt.coupling == CS_COUPLING_GAUSS_SEIDEL) {
    cs_couplingPrime(m, d); /* this first step ran stabilised */
  }
  if (st == CS_OK) {
    st = stageCheck(m, d, t1, err);
    w = csu_timerAdd(&d->timer[CS_TIMER_CHECK], w);
  }
  if (st == CS_OK) {
    cs_gateCommit(m, d, H);
    d->t = t1;
    d->rng_seed = dRandGetSeed();
    return CS_OK;
  }
  /* a failed step changes nothing: everything back as it was before the stages ran; the
   * saved state was written by this data, so restoring it cannot be refused */
  dJointGroupEmpty(d->contacts);
  cs_stateSet(m, d, save, NULL);
  d->nreject++;
  csu_timerAdd(&d->timer[CS_TIMER_SAVE], w);
  if (st != CS_ERR_REJECTED || !treeStep(m, d) || depth >= CS_MAX_SPLIT) {
    return st;
  }
  /* smaller: two halves (each retried smaller in turn) */
  const double tm = d->t + 0.5 * H;
  st = cs_stepTry(m, d, tm, 0.5 * H, depth + 1, err);
  if (st == CS_OK) {
    st = cs_stepTry(m, d, t1, 0.5 * H, depth + 1, err);
  }
  if (st != CS_OK) {
    dJointGroupEmpty(d->contacts);
    cs_stateSet(m, d, save, NULL);
  }
  return st;
}


csStatus cs_step(const csModel* m, csData* d, csError* err) {
  double w0 = csu_wallSeconds();
  const double H = cs_modelMacroStep(m), t1 = d->t + H;
  csStatus st = m->opt.step_adaptive && treeStep(m, d) ? cs_adaptiveStep(m, d, t1, err)
                                                       : cs_stepTry(m, d, t1, H, 0, err);
  if (st == CS_OK) {
    d->t = t1; /* exactly, however many halves it took */
    d->nstep++;
  }
  csu_timerAdd(&d->timer[CS_TIMER_STEP], w0);
  return st;
}


csStatus cs_settle(const csModel* m, csData* d, csError* err) {
  long n = cs_settleSteps(m);
  for (long i = 0; i < n; i++) {
    csStatus st = cs_step(m, d, err);
    if (st != CS_OK) {
      return st;
    }
  }
  cs_settleFinish(m, d);
  return CS_OK;
}


long cs_settleSteps(const csModel* m) { return lround(m->opt.settle / cs_modelMacroStep(m)); }


void cs_settleFinish(const csModel* m, csData* d) {
  (void)m;
  /* snap time to exactly 0 so output times are multiples of the step */
  d->t = 0;
  if (d->cvode) {
    CVodeReInit(d->cvode, 0.0, d->y);
  }
  const dReal* x = dBodyGetPosition(d->robot->support);
  csu_set3(d->x0, x[0], x[1], x[2]);
  /* the timers measure the run, not the settling */
  memset(d->timer, 0, sizeof d->timer);
}

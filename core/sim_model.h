/* sim_model.h: the co-simulation driver: model (constant during a run) and data (everything a
 * run changes), the staged step that advances data with a model (MuJoCo's mjModel/mjData),
 * the whole simulation state as a flat array, and the run with HDF5 output.
 *
 * Owns: csOptions (steps, end time, output rate, gravity, solver, pneumatic and coupling
 * settings, with units and defaults), csModel (options + terrain + gait + robot model + contact
 * law), csData (opaque: the ODE world with the support and any in-world legs, the chamber
 * pressures and their CVODE integrator, time, stage timers, statistics), and the pipeline.
 *
 * One step (cs_step) is a macro step H = macro_steps * h, a fixed sequence of named stages,
 * each timed into the data's timers (Box2D's solver stages, MuJoCo's mjData timers):
 *   schedule   p_cmd(t + H) from the gait (gaits_schedule.h), times --pressure-scale
 *   pneumatics chamber pressures p follow p_cmd through a first-order lag
 *              dp/dt = (p_cmd - p)/tau, integrated by CVODE (BDF, diagonal solver) to t + H
 *   legs       every leg's actuate(t, p(t), t + H, p(t + H)) (robot_leg.h); co-simulated legs
 *              then advance across [t, t + H] given the hip's motion and hand back their base
 *              wrench (and, for the stabilised scheme, their interface gains); an in-world
 *              level (none is registered since prb was retired) would do nothing more here
 *   support    macro_steps ODE steps of h: the legs' wrenches applied to the support body (with
 *              the stabilised scheme corrected by their gains, solved implicitly with the
 *              support's step), contacts of the support and the in-world legs with the terrain
 *              (contact_ode.h), QuickStep
 *   check      non-finite or runaway state, or the support below the terrain -> CS_ERR_DIVERGED
 * The support is never driven: it moves only through the legs' contact forces.
 *
 * A failed step changes nothing: the whole state (cs_stateGet) is saved before the stages run
 * and restored when one fails, as MuJoCo's mj_RungeKutta saves and restores; cs_step then
 * returns the stage's status (CS_ERR_REJECTED when the failure was recoverable, e.g. a leg
 * integrator's > 0 return: a caller may retry with a smaller step).
 *
 * Ownership: csModel owns its gait and calibration (freed by cs_modelDestroy); csData owns the
 * ODE world, the robot and the CVODE memory. cs_dataCreate allocates everything; cs_step and
 * the state functions allocate nothing. */
#ifndef CS_CORE_SIM_MODEL_H
#define CS_CORE_SIM_MODEL_H

#include <ode/ode.h>
#include <signal.h>
#include <stddef.h>
#include <stdint.h>

#include "contact_ode.h"
#include "core_clock.h"
#include "core_status.h"
#include "gaits_csv.h"
#include "gaits_foothold.h"
#include "gaits_gate.h"
#include "gaits_schedule.h"
#include "robot_calibration.h"
#include "robot_robot.h"
#include "sim_scene.h"
#include "terrains_scenefile.h"
#include "terrains_terrain.h"

#ifdef __cplusplus
extern "C" {
#endif

/* How co-simulated legs (csrLegType.in_world = 0) are coupled to the support. In-world legs
 * are coupled inside ODE and ignore this. */
typedef enum csCoupling_ {
  /* staggered (Jacobi): the legs advance across the macro step with the hip motion predicted
   * from the support's twist at its start; their averaged wrench is applied to the support,
   * constant over the step */
  CS_COUPLING_STAGGERED = 0,
  /* stabilised: as staggered, plus each leg's interface stiffness/damping (interfaceGains,
   * over one ODE step) correcting its wrench for the support's deviation from the prediction,
   * solved implicitly with the support's backward-Euler step (sim_coupling.c); the default for
   * co-simulated levels (cs_modelSetLegLevel) */
  CS_COUPLING_STABILISED = 1,
  /* Gauss-Seidel: the support steps first, with the legs' wrench of the last macro step
   * corrected by their gains for the support's motion since (the stabilised scheme's implicit
   * solve), plus the impulse the legs gave and the support did not get; then every leg
   * advances along the support's actual motion over the step, so a hip's path is C1 across
   * exchanges (sim_coupling.c). Rod legs on the flat road at h = H = 1 ms: within 1 mm of the
   * tightly coupled reference over 9 s, at the stabilised scheme's cost */
  CS_COUPLING_GAUSS_SEIDEL = 2,
  /* tree: one linearly implicit step of h for the support and the legs together, solved as
   * the tree it is (issue 32): every leg condenses its step onto its hip (csrLegType.prepare:
   * its impedance Z and impulse ρ), the support's backward-Euler step (M + Σ Tᵀ Z T) Δq' = ...
   * is solved with them, every leg back-substitutes its hip's motion (finish). Tree-stepped
   * levels only (strain), with macro_steps 1; their default (cs_modelSetLegLevel). A step that
   * fails recoverably is retried as two halves (sim_step.c) */
  CS_COUPLING_TREE = 3
} csCoupling;

typedef struct csOptions_ {
  double h;               /* ODE's fixed step (s) */
  int macro_steps;        /* ODE steps per macro step (>= 1): cs_step advances H = macro_steps h,
                             co-simulated legs exchange with the support once per macro step */
  csCoupling coupling;    /* co-simulated legs only (see csCoupling) */
  int coupling_carry;     /* Gauss-Seidel only: 1 (default) carries the impulse by which the
                             legs' actual wrench differed from the one the support was given
                             into the next macro step (momentum conserved across the interface);
                             0 drops it (measured: the flat road then walks 176 mm instead of
                             298 by 9 s) */
  int tree_iterations;    /* tree coupling: Newton passes of the whole tree per step (1: one
                             linearised pass; more: until tree_tol, else the step is rejected and
                             retried in halves); the level must implement update/iterate */
  double tree_tol;        /* tree coupling: a pass converges when nothing moves by more (mm) */
  int tree_carry;         /* tree coupling with tree_iterations 1 (a prototype, default 0): 1
                             the legs' momentum residual of a step (their level's
                             momentumResidual) is the support's in its next step, so one
                             linearised pass conserves the discrete momentum (core/sim_tree.c;
                             docs/notes/strain_leg.md "event17") */
  int step_adaptive;      /* tree coupling: 0 every step is H (fixed); 1 each macro step H is
                             crossed in steps chosen by a local error estimate (sim_adaptive.c:
                             H is then the longest step and the output's grid) */
  double step_tol;        /* step_adaptive 1: the local error allowed per step, a weighted RMS
                             over the watched positions (mm) and velocities (tol / 0.01 s,
                             mm/s) (sim_adaptive.c) */
  double t_end;           /* end time (s); <= 0: the gait's last row time + ramp */
  double output_dt;       /* output sampling interval (s), a multiple of H after rounding */
  double settle;          /* s of unactuated settling under gravity before t = 0 */
  double gravity;         /* mm/s^2 (9.81 m/s^2), along -y */
  int legs_weightless;    /* 0: gravity acts on the legs (`earth`); 1: only on the support
                             (`paper`: the legs keep mass and inertia) */
  int solver_iterations;  /* ODE QuickStep iterations per step */
  double pneumatic_tau;   /* s: chamber pressure lag; 0 = pressures follow p_cmd exactly */
  double pneumatic_rtol;  /* CVODE relative tolerance */
  double pneumatic_atol;  /* CVODE absolute tolerance (MPa) */
  int centerline_points;  /* samples per leg centreline in the output */
  double max_speed;       /* mm/s: a body faster than this means the run diverged */
  /* NULL, or called by cs_runWrite once per simulated second with the time t (s), the
   * support's displacement from t = 0 x[3] (mm, world) and the stepping loop's wall time (s):
   * the caller prints or keeps it; the library itself never writes to stdout or stderr */
  void (*progress)(void* user, double t, const double x[3], double wall_s);
  void* progress_user;
  const volatile sig_atomic_t* cancel; /* NULL, or a flag the caller sets (e.g. from its signal
                             handler): cs_runWrite then ends after the step in progress, writes the
                             status "interrupted at t = ..." and returns CS_ERR_INTERRUPTED */
} csOptions;

/* Defaults with reasons (sim_driver.c). */
csOptions cs_defaultOptions(void);

/* A source of the chamber commands for time t >= 0 (s): fills p_cmd [96] (MPa, label order)
 * and returns 0, or non-zero when it cannot (the command is then zero and the pneumatic
 * integrator fails, so the step fails). Asked wherever the schedule is (cs_schedule): at the
 * end of each step and at the pneumatic integrator's inner times. */
typedef int (*csPressureSource)(void* ctx, double t, double* p_cmd);

typedef struct csModel_ {
  csOptions opt;
  cstTerrain terrain;
  csgGait* gait;              /* owned */
  csgScheduleOptions sched;   /* ramp length, pressure scale */
  int ramp_given;             /* 1: sched.ramp was set by the caller (--ramp) and stands; 0:
                                 cs_modelLoad takes the gait's stated ramp (`# @ramp`) if any */
  csrRobotModel robot;        /* robot.leg_type is the leg level: the one place it is stored */
  cscContactParams contact;
  csrCalibration* calibration; /* owned; robot.map points into it */
  int cal_rule;               /* the FE mode table's rule (csrCalRule, `--cal-rule`), or -1: not
                                 given (the table's default; any calibration kind) */
  char scene[32];
  char gait_path[512];
  csConditions conditions;    /* earth | paper (sim_scene.h); set with cs_modelSetConditions so
                                 that opt.legs_weightless agrees */
  char legs_auto_choice[1024]; /* `--legs auto`: what was picked and why (the output's
                                 legs_auto_choice attribute); "" when the level was named */
  double legs_auto_tol_mm;    /* `--legs auto`: the tolerance asked for (mm); NaN otherwise */
  char track_error[768];      /* the measured track error of this configuration, one sentence
                                 (cs_runDefTrackError: the banner and the run file's
                                 track_error attribute); "" when not built from a definition */
  double track_error_mm;      /* that error (mm), NaN when the level table has no row for it */
  /* What commands the chambers instead of the gait table (crawlsim.h's pressure command and
   * controller, cs_api.c): NULL, the table. The model's choice of source is fixed during a
   * step; what the source returns is the caller's input (MuJoCo's mjcb_control). */
  csPressureSource pressure_source;
  void* pressure_ctx;
  /* The gait's footholds (gaits_foothold.h; `--foothold`): NULL, none (the table alone). Each
   * is decided once, from the state at the start of the first step that reaches its lift,
   * and its choice is part of the state (cs_stateGet); the player is sim_foothold.c. */
  csgFootholdSet* foothold;   /* owned */
  int fh_nedge;
  double fh_edge[2 * CST_MAX_BOXES]; /* mm, terrain x: the edges of the raised boxes */
  /* The landing gate (gaits_gate.h; `--gate`): NULL, none (the table plays on time, open
   * loop). With one the run is closed-loop: each gate is decided at a step's start from the
   * measured chamber pressures and the state (gate index, hold, wait, released holds: part of
   * cs_stateGet), the table's clock held while it waits; the player is sim_gate.c. */
  csgGateSet* gate;           /* owned; its design pressures filled at load */
} csModel;

/* Fill a model with the defaults of every part (no files read, no map yet): rod legs (the
 * mission's surrogate, co-simulated Gauss-Seidel) at the level's default settings. The caller
 * names the calibration to cs_modelLoad: the mission's is CS_MISSION_CALIBRATION under
 * CS_MISSION_CAL_RULE (sim_scene.h; set cal_rule to it), as the scenes run it. */
void cs_modelInit(csModel* m);

/* Load a scene's files into an initialised model: terrain description, gait table (none when
 * gait_path is NULL: the pressures are zero unless m->pressure_source commands them), and the
 * calibration bound to the leg actuator. Options may be changed before and after. On failure
 * err names the file and line. */
csStatus cs_modelLoad(csModel* m, const char* scene, const char* terrain_path,
                      const char* gait_path, const char* calibration_path, csError* err);

/* After cs_modelLoad: a scene file's start, heading and slope (terrains_scenefile.h) replace
 * the terrain's; a start above no box is CS_ERR_RANGE naming the scene file ("<file>: start
 * (x, z) is not above any box of <terrain>"). */
csStatus cs_modelApplySceneFile(csModel* m, const cstSceneFile* s, csError* err);

/* Set the conditions (sim_scene.h) and what they decide in the options: `paper` makes the
 * legs weightless (opt.legs_weightless = 1), `earth` does not. */
void cs_modelSetConditions(csModel* m, csConditions c);

/* Set the leg level (m->robot.leg_type) and its default coupling: a co-simulated level
 * (in_world = 0) is coupled Gauss-Seidel (sim_coupling.c), a tree-stepped one (prepare set:
 * strain) `tree` with one ODE step per macro step and the level's own step (csrLegType.step)
 * as h; options set afterwards override them. */
void cs_modelSetLegLevel(csModel* m, const csrLegType* type);

/* Name of the leg level that runs (m->robot.leg_type->name): what the output records. */
const char* cs_modelLegLevel(const csModel* m);

/* The table's end: opt.t_end if > 0, else the gait's last row plus one ramp (s), on the table's
 * own clock (cs_gateTableTime). */
double cs_modelTableEnd(const csModel* m);
/* End time of a run (s), the longest it can last: opt.t_end if > 0; else the table's end, plus,
 * with a gate, every gate's longest hold (n maxwait: the gate holds the table's clock). A gated
 * run without opt.t_end ends sooner, when the table is over (cs_runOverAt). */
double cs_modelEndTime(const csModel* m);

/* Macro step H = macro_steps * h (s). */
double cs_modelMacroStep(const csModel* m);
/* Macro steps per output row (>= 1): output_dt / H rounded; the run file's rows and a gated
 * run's end (cs_runOverAt) fall on its multiples. */
long cs_modelOutputEvery(const csModel* m);

/* Sway-buckling check of the stance (DESIGN "model no more than a scene needs", a designer's
 * first question): P_cr = π² E I / L² is the critical axial load of one leg clamped at the hip
 * and at a flat foot with the support free to sway (a sway frame of identical columns); the
 * load is the weight gravity puts on the legs (the whole robot's under `earth`, the support's
 * under `paper`) shared by half the legs, as in an alternating gait. Both in N. */
void cs_modelStanceCheck(const csModel* m, double mass_total, double* load_per_leg,
                         double* p_critical);

/* After cs_modelLoad with a gait: read the gait's companion .foothold file (gaits_foothold.h)
 * into m->foothold and take the terrain's edges along x (the x ends of every box whose top
 * stands above the lowest box top). Refused (CS_ERR_RANGE, naming the file) on a terrain
 * turned or inclined (the footholds measure along the terrain's x) or without a gait. */
csStatus cs_modelLoadFoothold(csModel* m, const char* path, csError* err);

/* After cs_modelLoad with a gait and the schedule options final: read the gait's companion
 * .gate file (gaits_gate.h) into m->gate and integrate the design's chamber pressures at each
 * gate's time (the table on time through the file's ramp and lag, with the run's ramp shape
 * and pressure scale; sim_gate.c). Refused (CS_ERR_ARG) without a gait. */
csStatus cs_modelLoadGate(csModel* m, const char* path, csError* err);

/* Free what the model owns (gait, calibration, footholds, gate). NULL-safe. */
void cs_modelDestroy(csModel* m);

typedef struct csData_ csData; /* opaque: ODE world, robot, CVODE memory, state, timers */

/* The gate's record of a data (zeros without a gate): the hold so far (s, the table's clock
 * behind the run's), the gates released and how many of them waited. */
void cs_gateHeld(const csModel* m, const csData* d, double* hold_s, int* released, int* waited);
/* Released gate k's wait (s; 0 for a gate not released). */
double cs_gateReleasedWait(const csData* d, int k);
/* The table's clock at the run's time t (s): t less the gate's hold plus the crawl's skip (t
 * itself without a gate; the footholds', the rows' and the gates' clock). */
double cs_gateTableTime(const csModel* m, const csData* d, double t);

/* The run's end decided in the step loop (1: stop after macro step i, 0: go on). Only a gated
 * run without opt.t_end ends before cs_modelEndTime: at the first output row (i a multiple of
 * output_dt / H) where the table's own clock, t - hold + skip (the state's; the skip of a crawl
 * statement, gaits_gate.h `crawl`), has reached cs_modelTableEnd: the gait is over. A function of
 * the state, so a resumed run ends where the uncut one does. */
int cs_runOverAt(const csModel* m, const csData* d, long i);

/* Build the world for a model: terrain geoms, the robot standing on the terrain at the
 * terrain's start, the pneumatic integrator, the coupling rows. Returns NULL with err. */
csData* cs_dataCreate(const csModel* m, csError* err);
void cs_dataDestroy(csData* d);

/* Settle the robot under gravity with all chambers vented for opt.settle seconds (time runs
 * from -settle to 0), then record the support's reference position and zero the timers. */
csStatus cs_settle(const csModel* m, csData* d, csError* err);
/* cs_settle in parts (a checkpointed run's, sim_run.c): its macro steps, and what it does
 * after them (the time snapped to 0, the pneumatic integrator restarted there, the support's
 * origin taken, the timers cleared) */
long cs_settleSteps(const csModel* m);
void cs_settleFinish(const csModel* m, csData* d);

/* Advance by one macro step H (the stages above). On failure returns the status with err
 * naming the time and the cause, and the state is as before the call. */
csStatus cs_step(const csModel* m, csData* d, csError* err);

/* ---- the whole simulation state (docs/style.md 5) -----------------------------------------------
 * A flat array of doubles: time t (s); the data's random seed (QuickStep reorders its rows with
 * ODE's one process-wide generator; each data keeps its own place in it, so the seed is part of
 * what its next step does); the 96 chamber
 * pressures p (MPa, the CVODE state); then the robot (csr_robotStateGet: the support body and
 * every leg's own state, co-simulated legs' contact/friction history included). ODE's contact
 * joints are rebuilt every step and carry no history. Not in it: the reference position x0 of
 * cs_supportDisplacement (set once by cs_settle) and the timers and statistics.
 * cs_stateSet restarts the pneumatic integrator from the restored pressures (CVodeReInit): a
 * step after cs_stateSet is bit-identical to any other step after cs_stateSet of the same state;
 * CVODE's step-size history is not state, so it may differ at the level of CVODE's tolerance
 * from a step that continued without the restore. */
int cs_stateSize(const csModel* m, const csData* d);
void cs_stateGet(const csModel* m, const csData* d, double* x);
/* Returns CS_OK, or CS_ERR_ARG (state unchanged) if x is not a state of this data. */
csStatus cs_stateSet(const csModel* m, csData* d, const double* x, csError* err);

/* ---- timers: one per stage plus the parts worth seeing (wall seconds and call counts) ------ */
#define CS_TIMER_LIST(X)                                                            \
  X(CS_TIMER_SCHEDULE, "schedule", "stage: scheduled pressures p_cmd(t + H)")       \
  X(CS_TIMER_PNEUMATICS, "pneumatics", "stage: chamber pressures by CVODE")         \
  X(CS_TIMER_LEGS, "legs", "stage: actuation and co-simulated legs' advance")       \
  X(CS_TIMER_SUPPORT, "support", "stage: ODE steps of the support (contact incl.)") \
  X(CS_TIMER_CONTACT, "contact", "part of support: collision and contact joints")   \
  X(CS_TIMER_TREE, "tree", "part of support: the tree coupling's condensed 6 x 6 solve") \
  X(CS_TIMER_CHECK, "check", "stage: divergence and fall checks")                   \
  X(CS_TIMER_SAVE, "save", "the state saved before each step (and restores)")       \
  X(CS_TIMER_OUTPUT, "output", "cs_run: samples written to the output file")        \
  X(CS_TIMER_STEP, "step", "whole cs_step calls")

typedef enum csTimerId_ {
#define CS_TIMER_ENUM(id, name, what) id,
  CS_TIMER_LIST(CS_TIMER_ENUM)
#undef CS_TIMER_ENUM
  CS_NTIMER
} csTimerId;

/* Name of a timer ("legs"), static string. */
const char* cs_timerName(csTimerId id);
/* The data's timers (CS_NTIMER entries), accumulated since cs_settle finished. */
const csuTimer* cs_timers(const csData* d);

/* ---- read-outs (valid until the next cs_step) ---------------------------------------------- */
double cs_time(const csData* d);
/* The adaptive step's counts since cs_dataCreate (sim_adaptive.c; zeros with a fixed step):
 * accepted steps, steps rejected by the error test, and the accepted steps' smallest, median
 * (from a histogram in 1/16 octaves) and largest length (s). Not state. */
typedef struct csAdaptiveStats_ {
  long accepted, rejected;
  double h_min, h_median, h_max;
} csAdaptiveStats;
void cs_adaptiveStats(const csData* d, csAdaptiveStats* s);
/* steps taken and steps rejected (failed and restored) since cs_dataCreate */
long cs_stepCount(const csData* d);
long cs_rejectCount(const csData* d);
/* Newton passes of the tree coupling so far (accepted and rejected tries, settling included). */
long cs_treePassCount(const csData* d);
/* contact ghosts the tree step's legs released when their passes converged (each sent the
 * passes on; robot_leg.h release), settling and rejected tries included */
long cs_treeReleaseCount(const csData* d);
/* Newton passes of the tree step whose move a leg's globalisation shortened (robot_leg.h
 * stepLimit), settling and rejected tries included */
long cs_treeLimitCount(const csData* d);
/* macro steps in which the co-simulated legs' interface gains were not passive and their
 * implicit part was projected (sim_coupling.c; 0 for legs in ODE) */
long cs_gainProjectionCount(const csData* d);
/* the pneumatic integrator's work so far (settling included, across its restarts): counts[0]
 * CVODE's internal steps, counts[1] its right-hand side evaluations (the difference quotient of
 * its diagonal Jacobian included); zeros without the pneumatic lag */
void cs_pneumaticCounts(const csData* d, long counts[2]);
/* support centre displacement from its position at t = 0, world frame, mm */
void cs_supportDisplacement(const csData* d, double pos[3]);
/* support orientation quaternion (w, x, y, z) */
void cs_supportOrientation(const csData* d, double q[4]);
/* support centre velocity, world, mm/s */
void cs_supportVelocity(const csData* d, double v[3]);
/* support angular velocity, world, rad/s */
void cs_supportAngularVelocity(const csData* d, double w[3]);
/* actual chamber pressures (96, MPa) */
const double* cs_pressures(const csData* d);
/* centreline of leg k (0..7) at `npts` points, (npts x 3) world mm */
void cs_legCenterline(const csModel* m, const csData* d, int k, int npts, double* out);
/* leg k (0..7) itself, for the level's own read-outs (csr_rodLegStats) */
const csrLeg* cs_leg(const csData* d, int k);
/* the last macro step's base wrench of co-simulated leg k (zero for in-world legs) */
void cs_legWrench(const csData* d, int k, csrWrench* w);
/* centre of mass of the robot, world frame, mm */
void cs_robotCenterOfMass(const csModel* m, const csData* d, double com[3]);
/* number of contact points in the last ODE step */
int cs_contactCount(const csData* d);
/* total force (N, world) the terrain exerted on the robot in the last ODE step, summed over
 * every contact joint's feedback: its y component is the load on the ground */
void cs_contactForce(const csData* d, double f[3]);
/* The terrain's force on leg k (0..7 = A..H; N, world) now: for in-world legs the feedback
 * of the last ODE step's contact joints on the leg's bodies, for co-simulated legs their own
 * contact law at the current state (csrLegType.contactForce; zero for a level that does not
 * report it) (sim_feet.c) */
void cs_footForce(const csModel* m, const csData* d, int k, double f[3]);
/* The force above which a leg counts as standing (N): a tenth of one leg's share of the
 * support's weight when four legs carry it (the paper's gaits stand on four), so that the
 * soft contact's grazing forces of a swinging foot do not count (sim_feet.c) */
double cs_stanceForceThreshold(const csModel* m);
/* deepest contact penetration of the last ODE step (mm) */
double cs_contactDepth(const csData* d);
/* Deepest penetration of the co-simulated legs' own (soft) terrain contact at the current
 * state, over the eight legs (mm; 0 out of contact, and for legs whose contacts ODE handles:
 * those are in cs_contactDepth). */
double cs_legContactDepth(const csModel* m, const csData* d);
/* the support box's 8 corners now, world mm, (8 x 3) in VTK hexahedron order (bottom face
 * -y then top face, each counter-clockwise seen from +y) */
void cs_supportCorners(const csModel* m, const csData* d, double corners[24]);
/* total mass of the robot (t) */
double cs_robotMass(const csData* d);

/* Run from t = 0 to opt.t_end, sampling into an HDF5 file per docs/design.md's output contract.
 * Writes as it goes and flushes every simulated second, at most once per wall second
 * (sim_run.c says why; core_h5.h: the file on disk is always
 * complete as of its last flush, even after kill -9), so a run that stops on an error leaves a
 * readable file with the samples so far; the root attributes status ("running", "ok",
 * "interrupted at t = ... s" or the error), samples and flushed_t_s say how far it reaches; the
 * timers go in as attributes at the end. opt.cancel set: ends after the step in progress with
 * CS_ERR_INTERRUPTED. `wall_s` gets the wall time of the loop. */
csStatus cs_runWrite(const csModel* m, csData* d, const char* out_path, double* wall_s,
                     csError* err);

/* ---- resumable runs (sim_checkpoint.c, sim_run.c; docs/notes/cli_output.md) ------------- */

/* the largest run identity (bytes, NUL included) */
#define CS_CHECKPOINT_IDENTITY 8192
/* the default interval of checkpoints (s of simulated time): a second of the flat road costs a
 * restart of the integrators and a write of the output's image, small against its steps */
#define CS_CHECKPOINT_EVERY_S 1.0

/* what a checkpoint carries beside the data's state */
typedef struct csCheckpointInfo_ {
  const char* identity; /* the run definition as lines "name value" (cs_runDefIdentity) */
  double every;         /* s of simulated time between checkpoints (NaN on load: the file's) */
  long nsample;         /* the output's rows at this state */
  double wall_s;        /* wall time of the stepping loops so far (s) */
} csCheckpointInfo;

/* FNV-1a 64 of n bytes continuing from h (0: a new hash) */
uint64_t cs_hashBytes(uint64_t h, const void* p, size_t n);
/* FNV-1a 64 of a file's contents into *h: 0, or -1 when it cannot be read */
int cs_hashFile(const char* path, uint64_t* h);

/* Write d's state (through x, cs_stateSize doubles, the caller's) with the info to `path`
 * atomically (written to path.tmp, renamed). Allocates only in HDF5's file image. */
csStatus cs_checkpointSave(const csModel* m, const csData* d, const csCheckpointInfo* info,
                           const char* path, double* x, csError* err);

/* Read the checkpoint at `path` into d (the state, the support's origin, the step counters,
 * the timers) and info (nsample, wall_s; every when NaN), x (cs_stateSize) getting the state;
 * refused (d unchanged, one line naming the file and the cause) when the file is not a whole
 * checkpoint (unreadable, truncated, a corrupt state), another program version's, or of
 * another run (info->identity or info->every differ, another state size). */
csStatus cs_checkpointLoad(const csModel* m, csData* d, const char* path,
                           csCheckpointInfo* info, double* x, csError* err);

/* The run and its output as cs_runWrite, checkpointed: ck_path (NULL: none) gets the state
 * every ck->every s of simulated time (the output flushed first: the file on disk then holds
 * every row the checkpoint counts), at the end and when cancelled; at each periodic checkpoint
 * the data is set to the state it saved (cs_stateSet), so its integrators restart there as a
 * resumed run's do and a run cut at a checkpoint and resumed equals the uncut run bit for bit.
 * settling NULL: d is settled (cs_settle), as cs_runWrite's; else d is as created and settles
 * here, checkpointed as the run (*settling 1 when it returns from a failure while settling).
 * resume (NULL: a new run) is a checkpoint to continue from (d as created, not settled): of
 * the settling (t < 0) it settles the rest first; of the run, the output's rows up to it are
 * read from out_path and written again into the new file (the old one kept as out_path.prev
 * until the new one's first flush). */
csStatus cs_runWriteCheckpointed(const csModel* m, csData* d, const char* out_path,
                                 const csCheckpointInfo* ck, const char* ck_path,
                                 const char* resume, int* settling, double* wall_s,
                                 csError* err);

/* A run that failed before t = 0 (while settling, `cause`) still leaves its output file: the
 * header (every attribute cs_runWrite writes first), the contract's series with no samples, the
 * `status` attribute saying what stderr says and `failed_at_s`, the time of the failure
 * (negative: settling runs from -opt.settle to 0). No XDMF (there is nothing to show). */
csStatus cs_runRecordFailure(const csModel* m, const csData* d, const char* out_path,
                             const csError* cause, csError* err);

#ifdef __cplusplus
}
#endif
#endif

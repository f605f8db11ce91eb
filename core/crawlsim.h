/* crawlsim.h: the public C API of crawlsim, the one header a program outside the project
 * includes (as MuJoCo's mujoco.h): a run definition with defaults and one validation, a whole
 * run with its HDF5 output and a result struct, and a simulation to step from the caller's
 * loop with the chamber pressures set between steps or by a controller callback.
 *
 * Owns: csRunDef (everything `crawlsim run` takes; docs/reference/commands.md), csRunResult,
 * csBendDef (one actuator's bend by the mesh-free models; core/cs_bend.c),
 * the opaque csSim (a model, constant during a run, and its data, the state a run changes),
 * csController. Implemented in core/cs_api.c over the driver (sim_model.h).
 *
 * Conventions (docs/reference.md): lengths mm, time s, pressure MPa (gauge), force N, mass as
 * each field says; world frame x the crawl direction, y up, z lateral (right-handed);
 * quaternions (w, x, y, z), body to world. The 96 chambers are in label order (the gait CSV's
 * columns, label - 1: A_II1_O1 first; gaits/gaits_labels.h); legs 0..7 are A..H.
 *
 * Ownership: the caller owns every string and array it passes and every buffer it reads into;
 * a csRunDef's strings are read during the call they are passed to (cs_simCreate copies what
 * it keeps). csSim is created by cs_simCreate and freed by cs_simDestroy. The library never
 * writes to stdout or stderr (what a run has to say goes to the caller's callbacks,
 * csRunDef.log and csRunDef.progress), never exits, and returns a status with a one-line
 * message in the caller's csError on every failure.
 * Thread safety: distinct csSim objects may be used from distinct threads only one at a time
 * (ODE keeps one process-wide random generator, which each step sets from its own seed).
 *
 * Link: pkg-config --cflags --libs crawlsim (include <crawlsim/crawlsim.h>), or CMake
 * find_package(crawlsim) and target crawlsim::crawlsim. */
#ifndef CRAWLSIM_H
#define CRAWLSIM_H

#include <signal.h>

#include "core_status.h" /* csStatus, csError, cs_statusString, cs_errorClear, CS_API */

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the run definition (Box2D's b2WorldDef / b2DefaultWorldDef) ---------------------------
 * Start from cs_defaultRunDef() and set what differs. A string NULL and a number NaN (doubles)
 * mean "the default": the scene's own (docs/design.md "Scenes") or the driver's. Each field
 * is named in messages by the `crawlsim run` option it mirrors ("--friction -0.5 must be >=
 * 0"): field `friction` is --friction, `t_end` --t-end, `support_mass_kg` --support-mass ...
 * Integer-valued fields are doubles so that a non-integer is refused with a message, not
 * silently truncated. */
typedef struct csRunDef {
  const char* scene;         /* "flat-road" (default), "obstacle" or "slope" */
  const char* scene_file;    /* NULL, or a scene file (terrain, gait, conditions, start,
                                heading, slope, t_end); the fields below win over it */
  const char* terrain;       /* terrain file; NULL: the scene's */
  const char* gait;          /* gait CSV; NULL: the scene's (ignored when no_gait is set) */
  int no_gait;               /* 1: no gait table; the pressures are zero until a command or a
                                controller sets them (cs_simSetPressureCommand/Controller);
                                cs_run needs t_end > 0 then. Counts as a user's file for the
                                default conditions (earth) */
  const char* foothold;      /* the gait's companion .foothold file (landings chosen from the
                                measured support, gaits_foothold.h); NULL: the scene's (none
                                today; never with a user's gait); "none": none */
  const char* gate;          /* the gait's companion .gate file (the landing gate: lifts held
                                until the last pair is down, read from the chamber pressures,
                                gaits_gate.h; the run is closed-loop); NULL: the scene's
                                (gaits/obstacle.gate for the obstacle's own gait, none
                                otherwise); "none": none (the table on time, open loop) */
  const char* conditions;    /* "earth" | "paper"; NULL: the scene's with its own files, earth
                                with a user's terrain or gait */
  const char* legs;          /* leg level "rod" | "strain" | "rom" | "auto"; NULL: the scene's */
  const char* rom_file;      /* legs "rom": the reduced leg's file (`crawlsim rom leg-file`),
                                needed; refused with another level */
  double legs_tol_mm;        /* legs "auto": the track error allowed against the rod
                                reference (mm, needed) */
  const char* levels;        /* legs "auto": the measured table; NULL: robot/levels.csv */
  const char* calibration;   /* calibration table; NULL: the scene's */
  const char* cal_rule;      /* "prism" | "rbf" | "rbf-pair"; NULL: the scene's or the table's */
  const char* cal_drop;      /* rod legs: "stretch", "stiffness", "stretch,stiffness"; NULL or
                                "none": nothing left out */
  const char* const* actuator_set; /* n_actuator_set "NAME=VALUE" strings (as `bend --set`):
                                the legs' actuator; NULL: the calibration's */
  int n_actuator_set;        /* 0..32 */
  double friction;           /* Coulomb coefficient of every contact (NaN: 0.8) */
  double pressure_scale;     /* multiplies every gait pressure (1) */
  double t_end;              /* s; 0: the gait's last row plus one ramp (with a gate: when
                                the table's clock reaches it, sim_model.h cs_runOverAt) */
  double dt;                 /* ODE step, s, (0, 0.01] (NaN: 1e-3, strain: its own) */
  double output_dt;          /* output sampling interval, s (NaN: 0.01) */
  double ramp;               /* pressure ramp: each gait row's change takes it, s (NaN: the
                                gait's `# @ramp`, else 0.2; gaits_schedule.h) */
  double tau;                /* pneumatic lag, s; 0: none (NaN: 0.02) */
  double gravity;            /* m/s^2 (NaN: 9.81) */
  double support_mass_kg;    /* kg (NaN: 0.05) */
  double slope_deg;          /* incline of the terrain about z, +x uphill, within +-45 (NaN:
                                the terrain's or the scene file's) */
  double links;              /* elements (rod) / bending modes - 1 (strain) per
                                segment, integer 1..64 (NaN: the scene's / the level's) */
  double iterations;         /* ODE QuickStep iterations, integer 1..10000 (NaN: 240) */
  double macro_steps;        /* ODE steps per exchange with co-simulated legs, 1..100000 */
  const char* coupling;      /* "staggered" | "stabilised" | "gs" | "tree"; NULL: the level's */
  double contact_scale;      /* multiplies every contact stiffness, (0, 1e6] (NaN: 1) */
  double rod_tol;            /* multiplies rod legs' CVODE tolerances, (0, 1000] (NaN: 1) */
  double step_order;         /* strain legs' tree step: 1 backward Euler, 2 BDF2 (NaN: the
                                level's, 1) */
  const char* strain_step;   /* strain legs' tree step: "fixed" (every step dt) | "adaptive"
                                (each dt crossed in steps a local error estimate chooses, dt
                                then the longest; either step_order); NULL: adaptive for a
                                tree-stepped level (strain) unless dt is given (the fixed step
                                it names) or step_order is 2; fixed otherwise; legs "auto": the
                                picked row's (a row with a step tolerance is the adaptive step),
                                and "fixed" | "adaptive" picks among the rows of that kind */
  double step_tol;           /* strain_step adaptive: the local error allowed per step, mm (and
                                mm per 10 ms on velocities) (NaN: 2.5e-4) */
  double strain_sub;         /* strain legs: Magnus sub-intervals per flexible piece (the
                                points of the kinematics, inertia and contact), integer 1..16
                                (NaN: the level's, 2) */
  const char* out;           /* cs_run's HDF5 file (and FILE.xdmf beside it); NULL: none.
                                cs_simCreate ignores it */
  const char* checkpoint;    /* cs_run: NULL, or a file that gets the run's state every
                                checkpoint_every s, at the end and when cancelled, written
                                atomically (needs out; docs/notes/cli_output.md "Resumable
                                runs"); cs_simCreate ignores it */
  double checkpoint_every;   /* s of simulated time between checkpoints, > 0 (NaN: 1, or the
                                resumed checkpoint's). The integrators restart at each one, so
                                it is part of the run (a resume with another is refused) */
  const char* resume;        /* cs_run: NULL, or a checkpoint to continue from instead of
                                settling: the same definition (t_end may differ), appending to
                                the same out; checkpoint NULL then means this file again.
                                cs_simCreate ignores it */
  void (*progress)(void* user, double t, const double x[3], double wall_s); /* NULL, or
                                called by cs_run once per simulated second with the time (s),
                                the support's displacement from t = 0 x[3] (mm, world) and the
                                stepping loop's wall time (s); `crawlsim run` prints its
                                progress line from it */
  void* progress_user;
  const volatile sig_atomic_t* cancel; /* NULL, or a flag the caller sets (a signal handler):
                                cs_run ends after the step in progress, CS_ERR_INTERRUPTED */
  const char* data_dir;      /* where the shipped gaits/, terrains/, robot/ are; NULL:
                                $CRAWLSIM_DATA_DIR, else share/crawlsim beside the installed
                                library (<prefix>/lib/../share/crawlsim), else the source tree
                                it was built from */
  void (*log)(void* user, const char* line); /* NULL, or called with each line of what the run
                                is (scene, conditions, calibration, legs, the auto pick, the
                                stance check) before it settles; `line` has no newline */
  void* log_user;
} csRunDef;

/* Every field at its default (strings NULL, numbers NaN, pressure_scale 1, t_end 0). */
CS_API csRunDef cs_defaultRunDef(void);

/* Check every field that can be checked without reading a file (ranges, words, combinations),
 * all in one place; CS_ERR_ARG / CS_ERR_RANGE with a message naming the field otherwise.
 * def NULL: CS_ERR_ARG. cs_simCreate and cs_run call it first and check the files after. */
CS_API csStatus cs_runDefValidate(const csRunDef* def, csError* err);

/* ---- a whole run (what `crawlsim run` does) -------------------------------------------------- */

enum { CS_RUN_MAX_TIMERS = 16, CS_RUN_TEXT = 256 };

typedef struct csRunResult {
  csStatus status;           /* as cs_run returned */
  char verdict[16];          /* "crawls" (|x| or |z| >= 20 mm), "stands", "tips over" (tilt >
                                30 deg), "falls" (fell off the terrain), "stops" (any other
                                failure: message says which); "" when the run never started */
  char message[CS_ERROR_MSG_SIZE]; /* the failure's message, "" on success */
  double t_end;              /* s: the time reached */
  double position[3];        /* mm: support displacement from t = 0 (world) */
  double quat[4];            /* support orientation (w, x, y, z) */
  double tilt_deg;           /* angle between the support's up axis and world up */
  double wall_s;             /* wall time of the stepping loop (s) */
  double real_time_factor;   /* simulated s per wall s */
  double robot_mass_g;       /* support and legs */
  long steps, rejected_steps;/* macro steps accepted and rejected since the robot was built
                                (the settling's included, as the file's attributes) */
  long gain_projections;     /* steps whose legs' interface gains were projected */
  int ntimer;                /* stage timers (sim_model.h CS_TIMER_LIST) */
  char timer_name[CS_RUN_MAX_TIMERS][16];
  double timer_s[CS_RUN_MAX_TIMERS];
  char scene[32];
  char conditions[16];       /* "earth" | "paper" */
  char legs[16];             /* the leg level that ran */
  int links;                 /* its links / elements / modes per segment */
  int macro_steps;
  double dt;                 /* s */
  char calibration[CS_RUN_TEXT];     /* the calibration's name */
  char calibration_rule[16];
  char legs_auto_choice[1024];       /* legs "auto": what was picked and why; "" otherwise */
  int interrupted;           /* 1 when def.cancel ended the run */
} csRunResult;

/* Load, build, settle and run from t = 0 to t_end, writing def.out (if not NULL) as
 * docs/reference/output.md says (a run that stops early keeps its samples and its status;
 * one that fails while settling still leaves its header). res (may be NULL) is filled as far
 * as the run got, also on failure. */
CS_API csStatus cs_run(const csRunDef* def, csRunResult* res, csError* err);

/* ---- a simulation stepped by the caller (mjModel + mjData) ---------------------------------- */

typedef struct csSim csSim; /* opaque */

/* Validate, load the scene's files, build the robot on the terrain and settle it under
 * gravity (time runs from -settle to 0): returns a simulation at t = 0, or NULL with err.
 * The pressures follow the gait table unless def.no_gait or a command/controller is set. */
CS_API csSim* cs_simCreate(const csRunDef* def, csError* err);
/* NULL-safe. */
CS_API void cs_simDestroy(csSim* s);

/* Advance by one macro step H (cs_simMacroStep). A step that fails changes nothing and
 * returns its status with the time and the cause; after a failure every further step returns
 * CS_ERR_ARG ("a step after a failed step") until cs_simReset or cs_simStateSet. */
CS_API csStatus cs_simStep(csSim* s, csError* err);
/* Step until the time reaches t (s; within half a step); t in the past: nothing. */
CS_API csStatus cs_simRunUntil(csSim* s, double t, csError* err);
/* Back to the settled state at t = 0 (the state, not the step counters), clearing a failure;
 * the pressure source (gait, command or controller) is kept. */
CS_API csStatus cs_simReset(csSim* s, csError* err);

CS_API double cs_simTime(const csSim* s);       /* s */
CS_API double cs_simMacroStep(const csSim* s);  /* H, s */
CS_API int cs_simChamberCount(const csSim* s);  /* 96 */
CS_API int cs_simLegCount(const csSim* s);      /* 8 */
CS_API long cs_simStepCount(const csSim* s);    /* accepted steps since cs_simCreate */

/* Hold the 96 chamber commands p_cmd (MPa, label order) from now until changed: they replace
 * the gait (and a controller). The chambers follow them through the pneumatic lag. Each must
 * be finite and in [0, 1] MPa (the gait reader's limit), else CS_ERR_RANGE and nothing
 * changes. */
CS_API csStatus cs_simSetPressureCommand(csSim* s, const double* p_cmd, csError* err);

/* A controller: fills p_cmd [96] (MPa) for time t (s). It is asked wherever the pressures
 * need their command, exactly as the gait table is: at the end of each step and at the
 * pneumatic integrator's inner times within it (t in (t_n, t_n + H]), so it must be a function
 * of t and of the state read-outs at the step's start (t_n), which are what the cs_sim*
 * read-outs return during the step. Returns 0, or non-zero to fail the step (the state is
 * restored, the step returns CS_ERR_EXTERNAL). A p_cmd outside [0, 1] MPa or not finite
 * fails the step the same way. The table is one such controller: replaying it gives its
 * track bit for bit. */
typedef int (*csController)(csSim* s, double t, double* p_cmd, void* user);
/* Register f (NULL: back to the gait table, or zero without one); user is passed to it. */
CS_API csStatus cs_simSetController(csSim* s, csController f, void* user, csError* err);

/* The gait table's command at t (MPa, [96]): zero without a table or before t = 0. For a
 * controller that replays or modifies the table. */
CS_API void cs_simGaitCommand(const csSim* s, double t, double* p_cmd);

/* ---- read-outs (of the state now; NULL-safe: a NULL s leaves the outputs untouched) ------- */
/* support centre's displacement from its position at t = 0 (mm, world) and orientation */
CS_API void cs_simSupportPose(const csSim* s, double pos[3], double quat[4]);
/* support centre's linear (mm/s) and angular (rad/s) velocity, world frame */
CS_API void cs_simSupportTwist(const csSim* s, double v[3], double w[3]);
/* the terrain's force on each leg, f [8][3] (N, world) */
CS_API void cs_simFootForces(const csSim* s, double* f);
/* chamber pressures now, p [96] (MPa) */
CS_API void cs_simPressures(const csSim* s, double* p);
/* leg `leg` (0..7)'s centreline from hip to foot at npts (2..201) points equally spaced in arc
 * length, xyz [npts][3] (mm, world). Returns 0, or -1 for a bad leg, npts or NULL. */
CS_API int cs_simLegCenterline(const csSim* s, int leg, int npts, double* xyz);

/* ---- the whole state (time, seed, pressures, support, legs; sim_model.h) ----------------- */
CS_API int cs_simStateSize(const csSim* s);
/* x [cs_simStateSize] */
CS_API void cs_simStateGet(const csSim* s, double* x);
/* CS_ERR_ARG (nothing changes) if x is not a state of this simulation; clears a failure */
CS_API csStatus cs_simStateSet(csSim* s, const double* x, csError* err);

/* ---- one actuator bent (what `crawlsim bend --model analytic|rod|strain` computes) --------
 * The listed chambers of all three segments of one actuator at equal pressure p = 0, p_step,
 * ... up to p_max (p_max itself always the last row), by the analytic model (paper Eqs. 1-11),
 * the Cosserat rod or the strain-coordinate leg (the leg of `crawlsim run --legs strain`) with
 * the calibration and rule `bend --model rod` takes (both solved statically at each row,
 * continued from the last, gravity off). The FE models (fe,
 * rom) are only in `crawlsim bend`: libcrawlsim does not link the FE (fem/). Start from
 * cs_defaultBendDef(); strings NULL and numbers NaN mean the default; messages name the `bend`
 * option a field mirrors (`p_max` is --p-max). Units: mm, MPa, deg, N. */
typedef struct csBendDef {
  const char* model;         /* "analytic" (default) | "rod" | "strain" */
  const char* actuator;      /* preset "fig1" | "baseline" | "leg"; NULL: baseline (analytic),
                                leg (rod, strain: the default calibration's) */
  const char* const* actuator_set; /* n_actuator_set "NAME=VALUE" strings (`bend --set`),
                                applied in order after the preset */
  int n_actuator_set;        /* 0..64 */
  const char* chambers;      /* inflated chambers (1..4), e.g. "1,2" (NULL: "1,2") */
  double p_max;              /* MPa, > 0 (NaN: 0.4) */
  double p_step;             /* MPa, > 0 (NaN: 0.05) */
  double tip_load[3];        /* rod, strain: a dead tip force, N, base frame (0, 0, 0) */
  const char* calibration;   /* rod, strain: an FE table or "analytic"; NULL: the mission's */
  const char* cal_rule;      /* rod, strain: "prism" | "rbf" | "rbf-pair"; NULL: rbf-pair on
                                the default table, a given table's own */
  const char* cal_drop;      /* rod, strain: "stretch", "stiffness", "stretch,stiffness"; NULL or
                                "none": nothing left out */
  double mesh_size;          /* rod: element length in mm (NaN: 4 per segment) */
  const char* data_dir;      /* where the shipped robot/ tables are, as csRunDef.data_dir */
  double links;              /* strain: bending modes per segment, integer 1..7 (NaN: the strain
                                level's default, as `crawlsim run --legs strain`) */
} csBendDef;

/* Every field at its default (strings NULL, numbers NaN, tip_load 0). */
CS_API csBendDef cs_defaultBendDef(void);

/* Check every field without reading a file (the model's word, the actuator with its sets,
 * the chambers, the ranges, the rod-only fields on the rod only): CS_OK or CS_ERR_ARG /
 * CS_ERR_RANGE with a message naming the option. def NULL: CS_ERR_ARG. */
CS_API csStatus cs_bendDefValidate(const csBendDef* def, csError* err);

/* The number of rows def's sweep has, or -1 (err filled) if def is not valid. */
CS_API int cs_bendRowCount(const csBendDef* def, csError* err);

/* Run def's sweep into the caller's arrays of `capacity` rows: pressure [n] (MPa),
 * angle_deg [n][3] (the segments II1..II3, deg; their sum is the total angle, Eq. 11) and
 * tip [n][3] (mm, the actuator's base frame); *n the rows written. A capacity below
 * cs_bendRowCount: CS_ERR_RANGE, nothing computed. A failure part way keeps the rows so far
 * in the arrays and *n and returns its status with the pressure in the message. */
CS_API csStatus cs_bend(const csBendDef* def, int capacity, double* pressure, double* angle_deg,
                        double* tip, int* n, csError* err);

/* "0.1.0 (git ...)": the version every output records */
CS_API const char* cs_version(void);

#ifdef __cplusplus
}
#endif
#endif /* CRAWLSIM_H */

/* robot_leg.h: the one leg interface every dynamic leg level implements (rod, strain,
 * rom), and the pressure -> segment-bend map (the calibration) the levels share.
 *
 * Owns: csrBendMap (pressures of one segment's four chambers -> bend vector of that segment),
 * csrLegSpec (everything a leg needs to build itself), the exchange records of the support
 * interface (csrBaseState in, csrWrench out), csrContactShape, and csrLegType: a const table of
 * operations over a leg's own flat state (docs/style.md 11; SUNDIALS' SUNStepper, MuJoCo plugins).
 * The driver (core/) only ever calls the table; a level is registered in one line of
 * robot_robot.c (csr_legTypeFind).
 *
 * Two kinds of level (csrLegType.in_world):
 *  - in_world = 1 (none registered since prb was retired, 2026-12-06; the driver keeps the
 *    path): the leg's bodies live in the ODE world, jointed to the support body;
 *    ODE steps them together with the support and resolves their contacts. advance() is a
 *    no-op returning a zero wrench; the leg's state is its ODE bodies' states.
 *  - in_world = 0 (rod, strain, rom): the leg is co-simulated with its own integrator. Each
 *    macro step [t, t + H] the driver hands it the hip's motion at both ends (b0, b1), the leg
 *    integrates itself across the step (its own contact with the terrain included) and returns
 *    the base wrench it exerts on the support; ODE then steps the support with that wrench
 *    applied. A tree-stepped level (strain: prepare, finish below) is instead condensed into
 *    the support's own implicit step.
 *
 * Frames and units: world frame of docs/reference.md (x crawl direction, y up, z lateral); mm, s,
 * MPa, N, N mm, t. A leg's frame (e1, e2, e3): e3 runs from the hip (base of II1) to the foot
 * along the undeformed leg; e1, e2 span the cross-section with the chamber layout of
 * docs/reference.md (Ω1 = (+b,+b), Ω2 = (+b,-b), Ω3 = (-b,-b), Ω4 = (-b,+b)). Matrices are row-major
 * 3x3 (9 doubles); a frame matrix holds e1, e2, e3 as its columns, in world coordinates.
 *
 * Ownership: the creator destroys (destroy is NULL-safe); a leg keeps pointers to spec->act's
 * copy, spec->map, spec->terrain and spec->contact, which must outlive it. No operation
 * except create allocates; none prints or exits. */
#ifndef CS_ROBOT_LEG_H
#define CS_ROBOT_LEG_H

#include <ode/ode.h>

#include "contact_ode.h"
#include "core_status.h"
#include "robot_actuator.h"
#include "terrains_terrain.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The calibration: pressures p[4] (MPa) of segment `seg` (0..2) -> bend vector bend[2] (rad):
 * the segment's end tangent turns by |bend| towards the cross-section direction
 * (bend[0] e1 + bend[1] e2)/|bend|; and the axial stretch of the segment's centreline (-).
 * Returns 0 on success, > 0 recoverable, < 0 fatal (as SUNDIALS right-hand sides do). */
typedef int (*csrBendMapFn)(const void* ctx, int seg, const double p[4], double bend[2],
                            double* stretch);

typedef struct csrBendMap_ {
  csrBendMapFn eval;
  const void* ctx;   /* owned by whoever built the map; must outlive the legs */
  const char* name;  /* e.g. "analytic x scale (provisional)" */
  double p_max;      /* MPa: highest chamber pressure the map is calibrated for (INFINITY: any) */
} csrBendMap;

/* eval's return for a pressure above csrBendMap.p_max (fatal: the run must not extrapolate) */
#define CSR_MAP_OUT_OF_RANGE (-2)

/* The leg's material and shape, the same for every level (model side; defaults from the
 * actuator, csr_defaultLegParams). What one level alone takes is its own setting (below). */
typedef struct csrLegParams_ {
  double E_bend;          /* effective bending modulus of the silicone section (MPa) */
  double damping_time;    /* material damping as a time constant: kd = k * damping_time (s) */
  double contact_radius;  /* radius of the leg's collision capsules (mm) */
} csrLegParams;

/* One of a level's own settings (csrLegType.settings): a number a run may set by name, with the
 * level's default and the values it accepts. Names shared by several levels mean the same knob
 * ("links": the discretisation per segment, whatever the level's unit of it). */
typedef struct csrLegSetting_ {
  const char* name;   /* "links", "rod_tol", "cal_drop", "step_order", ... */
  const char* what;   /* what a value counts, for messages ("elements per segment") */
  double value;       /* the level's default */
  double lo, hi;      /* accepted values, closed; integral settings say so (integer) */
  int integer;        /* 1: only whole numbers */
} csrLegSetting;

#define CSR_LEG_MAX_SETTINGS 10

/* The values of one level's settings, in the order of its table (csrLegType.settings). A block
 * for another level than the one reading it (or none) reads as that level's defaults, so that a
 * zeroed model or spec means "the defaults" (csr_legSettingsRead). */
typedef struct csrLegSettings_ {
  const struct csrLegType_* type; /* the level the values are for; NULL: none set */
  double v[CSR_LEG_MAX_SETTINGS];
} csrLegSettings;

/* Parts of a calibration a rod leg can leave out (the rod's setting cal_drop), to measure what
 * each does: the segments' axial stretch (the rod's intrinsic stretch strain stays 0) and a mode
 * table's probed section stiffness EI, EA (the rod keeps its default section). */
#define CSR_CAL_DROP_STRETCH 1u
#define CSR_CAL_DROP_STIFFNESS 2u

/* Everything a leg needs to build itself. Pointers are borrowed (see Ownership above). */
typedef struct csrLegSpec_ {
  const csrActuator* act;        /* copied by the leg */
  const csrLegParams* params;    /* copied by the leg */
  const csrLegSettings* settings; /* the level's own settings, copied; NULL: its defaults */
  const char* leg_file;          /* a level's own data file (rom: the reduced leg, robot_rom_file.h);
                                    NULL: none; read by sharedCreate */
  const csrBendMap* map;         /* kept: pressures -> segment bends */
  double hip[3];                 /* hip position at creation, world mm */
  double frame[9];               /* leg frame at creation (columns e1, e2, e3), world */
  double h;                      /* ODE's fixed step (s): in-world springs map to ERP/CFM with it;
                                    a co-simulated leg's macro step H is a multiple of it */
  double gravity[3];             /* the scene's gravitational acceleration, world mm/s^2 */
  int weightless;                /* 0: gravity acts on the leg's mass (conditions `earth`, and
                                    what a zeroed spec means); 1: it does not (`paper`: the
                                    leg keeps its mass and inertia) */
  /* in-world levels only (in_world = 1): the ODE objects the leg is built in */
  dWorldID world;
  dSpaceID space;                /* robot space: the leg's collision geoms go here */
  dBodyID support;               /* body the leg's base (hip) is clamped to */
  /* co-simulated levels only (in_world = 0): what their own contact needs */
  const cstTerrain* terrain;     /* kept: the shapes a leg touches */
  const cscContactParams* contact; /* kept: friction coefficient (and, later, the soft law) */
  /* what the level shares across one robot's legs (csrLegType.sharedCreate), or NULL; kept */
  void* shared;
} csrLegSpec;

/* The hip's motion handed to a co-simulated leg at one end of a macro step (world frame). The
 * hip is the base point of II1 on the support; it moves rigidly with the support. */
typedef struct csrBaseState_ {
  double x[3];  /* hip position, mm */
  double R[9];  /* leg frame at the hip: columns e1, e2, e3 in world coordinates (row-major) */
  double v[3];  /* velocity of the hip point, mm/s */
  double w[3];  /* angular velocity of the support (= of the leg's base frame), rad/s */
} csrBaseState;

/* The base wrench a leg exerts on the support (world frame): force f at the hip point and the
 * moment m about the hip point. advance() returns it AVERAGED over the macro step (the impulse
 * the leg gives the support in [t, t + H] divided by H), so the support receives exactly the
 * momentum the leg's base reaction carried: the interface conserves momentum for any H. */
typedef struct csrWrench_ {
  double f[3];  /* N */
  double m[3];  /* N mm, about the hip point */
} csrWrench;

/* A convex collision shape of a leg in world coordinates, for co-simulated contact (libccd
 * support functions are built from these in contact/). */
typedef enum csrShapeKind_ { CSR_SHAPE_CAPSULE = 1, CSR_SHAPE_BOX = 2 } csrShapeKind;
typedef struct csrContactShape_ {
  csrShapeKind kind;
  double a[3];      /* capsule: first end point of its axis; box: centre (mm) */
  double b[3];      /* capsule: second end point of its axis (mm); box: unused */
  double radius;    /* capsule radius (mm); box: 0 */
  double R[9];      /* box: its axes as columns, world (row-major); capsule: unused */
  double half[3];   /* box: half extents along its axes (mm); capsule: unused */
  double s;         /* arc length of the shape's centre along the leg from the hip (mm) */
} csrContactShape;

typedef struct csrLeg_ csrLeg; /* opaque, per level */

/* One leg level: a const table of operations over a leg's own flat state. Every pointer is
 * non-NULL (a level with nothing to do implements the no-op), but contactDepth, prepare and
 * finish (see there). Return codes of the int
 * operations: 0 ok, > 0 recoverable (the driver rejects the step: it restores the state saved
 * before it and may retry with a smaller step), < 0 fatal (the run stops). */
typedef struct csrLegType_ {
  const char* name;  /* the level's name as the CLI and the output's leg_model attribute spell it */
  int in_world;      /* 1: bodies in the ODE world (see top); 0: co-simulated, own integrator */
  /* the level's own settings, with their defaults and ranges (at most CSR_LEG_MAX_SETTINGS) */
  const csrLegSetting* settings;
  int nsettings;
  /* 1: the level builds its legs from a data file (csrLegSpec.leg_file: rom), so the speed
   * table (robot/levels.csv) measures it only where such a file is given */
  int needs_file;
  /* 1: a co-simulated level that is coupled `stabilised` unless the run names a scheme (rom:
   * its interface gains carry the sole's contact stiffness, which Gauss-Seidel's carry hands
   * the support a step late; docs/notes/rom.md "Settling on rom legs"); 0: Gauss-Seidel, or
   * tree for a tree-stepped level (core/sim_tree.c) */
  int coupling_stabilised;

  /* Build the leg hanging straight from spec->hip along spec->frame's e3, at rest, vented.
   * Returns NULL and fills err on failure. */
  csrLeg* (*create)(const csrLegSpec* spec, csError* err);
  /* Free the leg (NULL-safe). An in-world leg's ODE bodies and joints belong to the world and
   * are destroyed with it; destroy frees only the leg's own memory. */
  void (*destroy)(csrLeg* leg);
  /* What the legs of one robot (one actuator, one calibration) may share, created before them
   * and handed to each in csrLegSpec.shared: a cache of pure functions (not state), e.g. the
   * rod's calibration tables. *shared = NULL when the level shares nothing. 0 ok, else err
   * says why. sharedDestroy frees it after the legs (NULL-safe). */
  int (*sharedCreate)(const csrLegSpec* spec, void** shared, csError* err);
  void (*sharedDestroy)(void* shared);

  /* Size (doubles) of the leg's whole state: everything a step changes, so that
   * setState(getState()) followed by a step gives bit-identical results. For an in-world
   * level: its bodies' positions, quaternions, linear and angular velocities (13 each) and what
   * else it last set; for rod: its integrator's state vector plus contact/friction history (stick
   * points). Constant for a leg's lifetime. */
  int (*stateSize)(const csrLeg* leg);
  /* Copy the state into x[stateSize] (no side effects). */
  void (*getState)(const csrLeg* leg, double* x);
  /* Restore a state written by getState of this leg (bit-exact: getState afterwards returns
   * the same bytes). Returns 0, or < 0 (leg unchanged) if x is not a valid state (non-finite
   * values). An integrator's step-size history is not state: the leg restarts its integrator
   * from x (CVodeReInit) and documents what that costs. */
  int (*setState)(csrLeg* leg, const double* x);
  /* Back to the state right after create (straight, at rest, vented). */
  void (*reset)(csrLeg* leg);

  /* Set the actuation for the coming macro step from the 12 chamber pressures (MPa,
   * segment-major: p[4 s + j] is segment II(s+1) chamber Ω(j+1)) at its start (t0, p0) and end
   * (t1, p1); pressures are linear in between. May return CSR_MAP_OUT_OF_RANGE (fatal) when a pressure
   * is above the calibrated range. Called once per macro step, before advance. */
  int (*actuate)(csrLeg* leg, double t0, const double p0[12], double t1, const double p1[12]);
  /* Advance the leg from t to t + H with the hip moving from b0 (at t) to b1 (at t + H); fill
   * *w with the base wrench averaged over the step (csrWrench). Co-simulated levels only: an
   * in-world level returns 0 and a zero wrench (ODE steps it). err may be NULL; on < 0 it names
   * the time and cause. On > 0 or < 0 the leg's state is undefined: the driver restores it. */
  int (*advance)(csrLeg* leg, double t, double H, const csrBaseState* b0,
                 const csrBaseState* b1, csrWrench* w, csError* err);
  /* Linearised response of the base wrench at the current state (world frame, at the hip):
   * W ≈ W0 - K [u; φ] - C [u'; φ'], where u (mm) is a displacement of the hip point and φ (rad)
   * a small rotation vector of the base frame, away from where the hip is, over one implicit
   * step of spec->h: the leg's own degrees of freedom respond within that step (inertia,
   * damping, contact), so for a leg with internal dynamics these are its condensed (Schur
   * complement) gains, not those of its stiffest part alone. K (6 x 6: N/mm, N/rad, N mm/mm,
   * N mm/rad blocks) and C (the same over velocity, N s/mm ...) row-major, [f; m] rows by
   * [u; φ] columns. The driver solves them implicitly with the support (the stabilised
   * coupling scheme, core/sim_coupling.c). In-world levels return zeros. */
  void (*interfaceGains)(const csrLeg* leg, double K[36], double C[36]);

  /* The leg's convex collision shapes now (world frame): writes at most `max` of them and
   * returns how many the leg has (call with max = 0 to size the array). */
  int (*contactShapes)(const csrLeg* leg, csrContactShape* shapes, int max);
  /* Sample the centreline from hip to foot at k >= 2 points equally spaced in arc length
   * (world, mm): out is (k x 3). */
  void (*centerline)(const csrLeg* leg, int k, double* out);
  /* Total mass of the leg (t). */
  double (*mass)(const csrLeg* leg);
  /* First mass moment: sum of m_i x_i over the leg's mass (t mm, world). */
  void (*massMoment)(const csrLeg* leg, double mx[3]);
  /* Deepest penetration of the leg's own contact with the terrain at the current state (mm; 0
   * out of contact). NULL for a level whose contacts ODE handles (in_world: their depth is in
   * ODE's contact report). */
  double (*contactDepth)(const csrLeg* leg);
  /* The terrain's force on the leg at the current state (N, world): its foot and any other
   * part of it in contact, friction included (the run file's per-foot force, issue 36). NULL
   * for in-world levels, whose contacts are ODE's joints (the driver sums their feedback per
   * leg through ownsBody), and for a level that does not report it. */
  void (*contactForce)(const csrLeg* leg, double f[3]);
  /* In-world levels: 1 when `body` is one of the leg's ODE bodies, else 0. NULL for
   * co-simulated levels. */
  int (*ownsBody)(const csrLeg* leg, dBodyID body);

  /* ---- tree-stepped levels (issue 32; the strain leg, robot_strain_leg.c) ------------------
   * A tree-stepped level steps with the support in ONE linearly implicit step of the driver's
   * h, solved as the tree it is (core/sim_tree.c, coupling `tree`): every leg condenses its
   * step onto its hip (prepare), the support solves its 6 x 6 with the legs' condensed
   * impedances, every leg back-substitutes the hip's motion (finish). prepare and finish are
   * NULL for the levels that advance on their own (rod); a tree-stepped level still
   * implements advance (one step along a prescribed hip motion) and interfaceGains, so the
   * other coupling schemes can drive it. */
  /* s: the level's default step h for the tree coupling (0: the driver's default) */
  double step;
  /* the level's default step formula for the tree coupling (its setting step_order, where it
   * has one): 1 backward Euler, 2 BDF2 (0: backward Euler, as stepCoeffs NULL) */
  int step_order;
  /* Condense one step of h from the current state with the hip at b0 (its pose and velocity
   * now): the leg's impulse on the support over the step is ρ - Z ΔV, with ΔV = [Δv; Δω] the
   * change over the step of the hip point's velocity (mm/s) and of the base frame's angular
   * velocity (rad/s), world; ρ (6: N s, N mm s) and Z (6 x 6 row-major: t, t mm, t mm, t mm²)
   * in the world frame at the hip, rows [force; moment about the hip], the columns and rows of
   * robot_leg.h's interfaceGains. The state is not changed. 0, > 0 recoverable (the driver
   * rejects the step and retries it smaller), < 0 fatal. */
  int (*prepare)(csrLeg* leg, double h, const csrBaseState* b0, double Z[36], double rho[6]);
  /* Finish the prepared step with the hip's state at its end b1 (after the support's step):
   * the leg's state moves, *w gets its base wrench averaged over the step (its impulse / h).
   * 0, > 0 recoverable (e.g. a foot sunk past its bound: the driver restores the state saved
   * before the step and retries smaller), < 0 fatal. */
  int (*finish)(csrLeg* leg, const csrBaseState* b1, csrWrench* w);
  /* Newton passes over the prepared step (NULL: one linearised pass only). update moves the
   * leg's iterate to the end of the step for the hip's end state b1 (the support's solve:
   * ΔV its twist change from b0), only alpha (0 < alpha <= 1) of the way from the last iterate
   * when b1_alpha (the hip for that damped move; NULL with alpha 1) is given; *change the
   * full move's largest change of a coordinate against the last iterate, as a length (mm).
   * iterate linearises the step again at the iterate: Z, ρ as prepare's (same frame and
   * columns: the impulse is ρ - Z ΔV for the whole step's ΔV). finish then ends the step at
   * the support's actual end state. 0, > 0 recoverable (retry smaller), < 0 fatal. */
  int (*update)(csrLeg* leg, const csrBaseState* b1, double alpha, const csrBaseState* b1_alpha,
                double* change);
  int (*iterate)(csrLeg* leg, double Z[36], double rho[6]);
  /* The passes converged (NULL: nothing to do): drop what only steered them (the strain leg's
   * active set: contact shapes out of contact held by their last linearisation's affine
   * load) and return how many; > 0: the converged iterate is not the leg's law, the caller
   * goes on with the passes (iterate linearises afresh). */
  int (*release)(csrLeg* leg);
  /* Before update with the same b1 (NULL: no limit): the largest fraction (0, 1] of the move
   * from the last iterate toward b1's that the level's globalisation allows (the strain
   * leg's slot_trust: a foot slot moves at most two stick ranges); the caller damps
   * the whole tree's move by the least of its legs'. */
  double (*stepLimit)(csrLeg* leg, const csrBaseState* b1);
  /* The multistep formula the leg's next step of h takes (NULL: backward Euler): the step is
   * y1 = c[0] y0 + c[1] y_-1 + c[2] h f(y1) on positions and velocities (y_-1 the last step's
   * start), and prepare's Z, ρ are impulses over c[2] h (the force at the step's end times
   * c[2] h). The support takes the same formula (core/sim_tree.c); c depends on the leg's
   * state (its last step), the same for every leg of a run. */
  void (*stepCoeffs)(const csrLeg* leg, double h, double c[3]);
  /* After finish (NULL: the level has none): the leg's discrete linear momentum residual of
   * the step it finished, by that step's linear model (t mm/s, world): the change of its
   * Σ m x per step less h (weight + contact + tip force) and the hip's impulse, the contact
   * force the step's linearisation at the step's end. A converged Newton step leaves it below
   * its tolerance; after one linearised pass the support takes it in its next step
   * (csOptions.tree_carry, core/sim_tree.c). 0, or < 0 when the leg cannot give it. */
  int (*momentumResidual)(const csrLeg* leg, double eps[3]);
} csrLegType;

/* The Cosserat rod level (robot_rod*.c, robot_rod.h), registered in robot_robot.c. */
extern const csrLegType csr_leg_rod;
/* The strain-coordinate Cosserat rod level (robot_strain*.c, robot_strain.h), tree-stepped. */
extern const csrLegType csr_leg_strain;
/* The reduced-order FE level (robot/rom/robot_rom_leg.c): needs spec->leg_file. */
extern const csrLegType csr_leg_rom;

/* The registered level called `name` ("rod", "strain", "rom"), or NULL. Levels the design
 * names but that are not registered yet (none today) give NULL with *planned = 1 (planned may
 * be NULL). */
const csrLegType* csr_legTypeFind(const char* name, int* planned);
/* For a level that was retired ("prb", 2026-12-06: off the speed/accuracy front, docs/studies/
 * speed_accuracy.md), one sentence saying so and what to use instead (static string); NULL for
 * any other name. Every reader of a level's name (the run definition, the commands, the level
 * table) refuses it with this sentence. */
const char* csr_legRetired(const char* name);
/* The registered levels, cheapest first: how many, and the i-th (NULL outside 0..count-1). */
int csr_legTypeCount(void);
const csrLegType* csr_legTypeAt(int i);

/* Second moment of area of the chambered section about a principal axis (mm^4). */
double csr_legSectionI(const csrActuator* act);

/* Default leg parameters for an actuator (E_bend from C10, robot_leg.c). */
csrLegParams csr_defaultLegParams(const csrActuator* act);

/* ---- a level's own settings (robot_leg.c) ---- */
/* The setting `name` of level T, or NULL when T has none of that name. */
const csrLegSetting* csr_legSettingFind(const csrLegType* T, const char* name);
/* s = T's defaults. */
void csr_legSettingsDefault(const csrLegType* T, csrLegSettings* s);
/* Set T's setting `name` to v in s (s becomes T's defaults first when it holds another level's
 * values). CS_ERR_ARG when T has no such setting, CS_ERR_RANGE when v is outside its values;
 * err names the level, the setting and the range. */
csStatus csr_legSettingSet(const csrLegType* T, csrLegSettings* s, const char* name, double v,
                           csError* err);
/* The value of T's setting `name` in s (T's default when s is NULL or another level's), or
 * `fallback` when T has no such setting. */
double csr_legSettingGet(const csrLegType* T, const csrLegSettings* s, const char* name,
                         double fallback);
/* T's values out of s, in the order of T's table, into v[CSR_LEG_MAX_SETTINGS] (T's defaults
 * when s is NULL or another level's; a block of a table sharing T's settings, a wrapper of T,
 * is T's): what a level reads in create. */
void csr_legSettingsRead(const csrLegType* T, const csrLegSettings* s, double* v);

#ifdef __cplusplus
}
#endif
#endif

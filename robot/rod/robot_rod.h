/* robot_rod.h: the Cosserat-rod leg level (`rod`): one leg as a discrete geometrically exact
 * (Simo-Reissner) rod with stretch, shear, bending and twist, actuated by pressure-dependent
 * intrinsic strains, integrated implicitly by CVODE (BDF, banded Newton) between exchanges with
 * the support, and solved statically (Newton, load stepping) for `crawlsim bend --model rod`.
 *
 * Owns: csrRodParams (discretisation, material, damping, tolerances; defaults with reasons in
 * robot_rod_model.c), csrRodPiece (a uniform stretch of rod: the leg is five of them),
 * csrRodCalibration (the actuation interface: pressures -> intrinsic strains and, optionally,
 * section stiffness per segment; the FE calibration of issue 8 fills it, a csrBendMap is
 * adapted to it by default), csrRodContact (the hook through which a contact law applies forces
 * to the rod's shapes and keeps its history variables inside the rod's state), csrRodModel
 * (constant during a run) and csrRodData (state, integrator, scratch), the state get/set/reset,
 * advance over a macro step with the base driven by the support, the base wrench and interface
 * gains, the static solver, centreline, energy and bend angles.
 *
 * Layers (one file each): robot_rod_model.c: pieces, discretisation, kinematics, strains,
 * internal forces and energy (one kernel shared by dynamics and statics); robot_rod_dyn.c: the
 * CVODE integration, base motion, wrench and gains; robot_rod_static.c: the static solver and
 * the bend curve point; robot_rod_internal.h: what those files share (not public).
 *
 * Discretisation (PyElastica / DisMech style, chosen by measurement: see robot_rod_model.c):
 * nodes 0..N at rest arc lengths s_0 = 0 (hip) .. s_N = L (foot), element e = 1..N between
 * nodes e-1 and e with a material frame Q_e = (d1, d2, d3) (a unit quaternion). Node 0 and the
 * base frame Q_0 are the clamp, moved by the support. Shear/stretch strain per element
 * σ_e = Q_eᵀ(x_e - x_{e-1})/l_e - e3; curvature at node i from the relative rotation
 * log(Q_iᵀQ_{i+1}) over the Voronoi length (half an element at the hip). Forces are the exact
 * gradients of the discrete energy, so without damping and input the energy is conserved by
 * the semi-discrete equations (and not increased by BDF).
 *
 * Frames and units: world mm, s, N, N mm, t (tonne), MPa. Material frame at rest = the leg
 * frame of robot_leg.h: e1 = d1, e2 = d2, e3 = d3 down the leg (docs/reference.md chamber layout).
 * Intrinsic curvature u0 is the Darboux vector in the material frame (1/mm): u0 = (κ1, κ2, τ)
 * with κ2 > 0 turning d3 towards +d1. A csrBendMap's bend[2] (rad over the segment, towards
 * bend[0] e1 + bend[1] e2) gives u0 = (-bend[1], bend[0], 0) / S and σ0 = (0, 0, stretch - 1).
 *
 * State (csr_rodStateSize doubles): per element e = 1..N one block, at csr_rodStateOffset(e),
 *   [x_e (3, node e, mm), q_e (4, (w,x,y,z)), v_e (3, mm/s), ω_e (3, body frame, rad/s),
 *    h_e (csrRodContact.nhist, or nhist_foot for e = N: the contact law's history of shape e)]
 * so the whole leg, contact history included, saves and restores as one vector. */
#ifndef CS_ROBOT_ROD_H
#define CS_ROBOT_ROD_H

#include "core_status.h"
#include "robot_actuator.h"
#include "robot_leg.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- parameters ----------------------------------------------------------------------------- */

typedef struct csrRodParams_ {
  int elements_per_segment; /* elements per actuated segment II1..II3 (-) */
  int elements_per_joint;   /* elements per solid joint LS12, LS23 (-) */
  double E;                 /* axial/bending modulus of the silicone (MPa): E' = 8 C10 */
  double G;                 /* shear modulus (MPa): μ0 = 2 C10 */
  double shear_coeff;       /* Timoshenko shear coefficient of the square section (-) */
  double damping_time;      /* Kelvin-Voigt time constant on every strain rate (s) */
  double rtol;              /* CVODE relative tolerance (-) */
  double atol_pos;          /* absolute tolerance of positions (mm) */
  double atol_rot;          /* absolute tolerance of quaternion components (-) */
  double atol_vel;          /* absolute tolerance of velocities (mm/s) */
  double atol_omega;        /* absolute tolerance of angular velocities (rad/s) */
  double atol_hist;         /* absolute tolerance of contact history variables (their unit) */
  double atol_wrench;       /* absolute tolerance of the base wrench averaged over an advance
                               (N; robot_rod_dyn.c) */
  long max_steps;           /* CVODE internal steps allowed per advance (-) */
  int max_order;            /* highest BDF order (1..5); 2 makes BDF A-stable, for undamped
                               rods whose stiff modes sit on the imaginary axis */
  double contact_radius;    /* radius of the leg's contact capsules (mm) */
  double static_tol;        /* static Newton: scaled residual norm at convergence (-) */
  int static_max_iter;      /* static Newton iterations per load step (-) */
  unsigned cal_drop;        /* parts of the calibration left out (CSR_CAL_DROP_*; 0: none): a
                               study knob for what each part does to a run */
} csrRodParams;

/* Defaults for an actuator (reasons in robot_rod_model.c). */
csrRodParams csr_rodDefaultParams(const csrActuator* act);

/* ---- pieces: the rod is a sequence of uniform pieces --------------------------------------- */

/* Section stiffness in the material frame (d1, d2, d3). */
typedef struct csrRodSection_ {
  double EA;    /* axial stiffness (N) */
  double GA[2]; /* shear stiffness k G A along d1, d2 (N) */
  double EI[2]; /* bending stiffness about d1, d2 (N mm^2) */
  double GJ;    /* torsional stiffness about d3 (N mm^2) */
} csrRodSection;

typedef struct csrRodPiece_ {
  double length;         /* rest length (mm) */
  int nelem;             /* elements in this piece (>= 1) */
  int segment;           /* actuated segment 0..2 whose calibration drives it, -1 = passive */
  csrRodSection section; /* default (unactuated) section */
  double rhoA;           /* mass per length (t/mm) */
  double rhoI[3];        /* rotary inertia per length about d1, d2, d3 (t mm) */
} csrRodPiece;

#define CSR_ROD_MAX_PIECES 16

/* The five pieces of a leg (II1, LS12, II2, LS23, II3) from the actuator's section (header of
 * robot_rod_model.c: homogenised segment, caps and joints as full sections). Returns 5. */
int csr_rodLegPieces(const csrActuator* act, const csrRodParams* par,
                     csrRodPiece pieces[CSR_ROD_MAX_PIECES]);

/* ---- actuation: pressures -> intrinsic strains (and stiffness) of a segment ---------------- */

typedef struct csrRodSegmentActuation_ {
  double u0[3];          /* intrinsic Darboux vector, material frame (1/mm) */
  double sigma0[3];      /* intrinsic shear and stretch strain (shear1, shear2, stretch - 1) */
  int has_section;       /* 1: `section` replaces the piece's section (calibrated stiffness) */
  csrRodSection section; /* section stiffness at these pressures */
} csrRodSegmentActuation;

/* Segment seg (0..2) under chamber pressures p[4] (MPa): fills out (zeroed by the caller, so a
 * calibration without stiffness leaves has_section = 0). 0 ok, > 0 recoverable, < 0 fatal
 * (CSR_MAP_OUT_OF_RANGE for a pressure outside the calibration). */
typedef int (*csrRodActuationFn)(const void* ctx, int seg, const double p[4],
                                 csrRodSegmentActuation* out);

typedef struct csrRodCalibration_ {
  csrRodActuationFn eval;
  const void* ctx;  /* owned by the caller; must outlive the rod */
  const char* name; /* for reports */
} csrRodCalibration;

/* ---- contact hook --------------------------------------------------------------------------- */

typedef enum { CSR_ROD_SHAPE_CAPSULE = 0, CSR_ROD_SHAPE_BOX = 1 } csrRodShapeKind;

/* One contact shape of the rod at one instant (world frame). Shape e-1 belongs to element e:
 * elements 1..N-1 are capsules of radius contact_radius around the chord node e-1 -> node e;
 * element N is the foot, a box of the square section (half sides a, a, l_N / 2) whose +d3 face
 * is the flat sole at the tip node. */
typedef struct csrRodShape_ {
  int kind;           /* csrRodShapeKind */
  int element;        /* 1..N */
  double p0[3], p1[3]; /* chord ends: node e-1 and node e (mm) */
  double v0[3], v1[3]; /* their velocities (mm/s) */
  double centre[3];   /* (p0 + p1) / 2 (mm) */
  double R[9];        /* material frame Q_e, columns d1 d2 d3, row-major */
  double omega[3];    /* angular velocity of the frame (rad/s, world) */
  double radius;      /* capsule radius (mm); 0 for the box */
  double half[3];     /* box half extents along d1, d2, d3 (mm); capsule: 0, 0, |p1 - p0| / 2 */
} csrRodShape;

/* The terrain's action on element e's shape, as the forces on its two nodes, f0 on node e-1
 * (p0) and f1 on node e (p1) (N, world), and a couple `moment` on its frame (N mm, world):
 * contact_soft.h's cscShapeLoad form, which carries any distribution of contact forces along
 * the element exactly in the rod's nodal forces (a force at axis parameter s splits (1 - s),
 * s; what is off the axis goes into the couple). hist (read) is this element's history (e.g.
 * the elastic tangential displacement of a friction bristle), dhist (write) its time
 * derivative, which CVODE integrates with the rod; csr_rodStateHist(m, e) doubles each.
 * Outputs are zeroed before the call; hist is a zero vector and dhist scratch where the rod
 * evaluates forces outside its integrator (energy, wrench queries). 0 ok, > 0 recoverable
 * (CVODE cuts the step: deep penetration, NaN), < 0 fatal. */
typedef int (*csrRodContactFn)(void* ctx, const csrRodShape* shape, const double* hist,
                               double* dhist, double f0[3], double f1[3], double moment[3]);

typedef struct csrRodContact_ {
  csrRodContactFn eval; /* NULL: no contact */
  void* ctx;
  int nhist;            /* history variables of each element 1..N-1 (0..CSR_ROD_MAX_HIST) */
  int nhist_foot;       /* of the foot element N (its side and sole: may need more) */
} csrRodContact;

#define CSR_ROD_MAX_HIST 12

/* ---- model ---------------------------------------------------------------------------------- */

typedef struct csrRodSpec_ {
  const csrActuator* act;          /* the leg actuator (NULL only with csr_rodModelCreatePieces) */
  const csrRodParams* params;      /* NULL: csr_rodDefaultParams(act) */
  const csrBendMap* map;           /* pressure -> bend calibration (NULL: no actuation) */
  const csrRodCalibration* calib;  /* richer calibration; used instead of map when not NULL */
  double hip[3];                   /* hip (node 0) at rest, world mm */
  double frame[9];                 /* base frame at rest, columns e1 e2 e3, row-major */
  double gravity[3];               /* gravitational acceleration, world (mm/s^2) */
  int weightless;                  /* 1: the leg keeps its mass and inertia but feels no gravity
                                      (docs/reference.md conditions `paper`); 0: `earth` (as
                                      csrLegSpec.weightless) */
  csrRodContact contact;           /* leg-terrain contact hook */
} csrRodSpec;

typedef struct csrRodModel_ csrRodModel; /* constant during a run */
typedef struct csrRodData_ csrRodData;   /* state, integrator, scratch */

/* The leg of spec->act with its five pieces. NULL and err on invalid input. */
csrRodModel* csr_rodModelCreate(const csrRodSpec* spec, csError* err);
/* A rod of arbitrary pieces (tests: uniform rods against closed forms). spec->act may be NULL
 * (then spec->params must be given); pieces with segment >= 0 need a calibration. */
csrRodModel* csr_rodModelCreatePieces(const csrRodPiece* pieces, int npiece,
                                      const csrRodSpec* spec, csError* err);
void csr_rodModelDestroy(csrRodModel* m);

/* Sizes and constants. */
int csr_rodElements(const csrRodModel* m);           /* N */
int csr_rodStateSize(const csrRodModel* m);          /* doubles in the state vector */
double csr_rodMass(const csrRodModel* m);            /* total mass (t); the hip node has none */
double csr_rodLength(const csrRodModel* m);          /* rest length (mm) */
const double* csr_rodNodeArc(const csrRodModel* m);  /* (N + 1) rest arc lengths (mm) */
int csr_rodStateOffset(const csrRodModel* m, int e); /* element e's block in the state */
int csr_rodStateHist(const csrRodModel* m, int e);   /* its history variables */

/* ---- data ----------------------------------------------------------------------------------- */

/* The calibration's lazily filled tables (a segment's actuation along a chamber pattern, and
 * at two chamber groups' levels, robot_rod_dyn.c): a memo of a pure function of the actuator,
 * its calibration, the segment and the pressures, so the legs of one robot (one actuator, one
 * map) may share one and evaluate each node once instead of eight times (measured: the
 * calibration's Newton solves were 17 % of a 9 s flat-road run at --rod-tol 20, each leg
 * filling its own tables). Not state: what a leg computes does not depend on who filled a
 * node. The creator destroys it after the legs that use it. */
typedef struct csrRodActCache_ csrRodActCache;
csrRodActCache* csr_rodActCacheCreate(csError* err);
void csr_rodActCacheDestroy(csrRodActCache* c);
/* d's tables from now on: c (which must outlive d and belong to legs of d's actuator and
 * calibration; d's own tables are freed), or NULL for tables of its own (allocated again if
 * needed). 0 ok, -1 out of memory (d then has no tables: do not advance it). */
int csr_rodDataUseCache(csrRodData* d, csrRodActCache* c);

/* Allocates everything the step needs (CVODE, band matrices, scratch); the state is reset. */
csrRodData* csr_rodDataCreate(const csrRodModel* m, csError* err);
void csr_rodDataDestroy(csrRodData* d);

/* Straight, unstrained, at rest at the spec's hip and frame; actuation off; history zero. */
void csr_rodReset(const csrRodModel* m, csrRodData* d);
void csr_rodGetState(const csrRodModel* m, const csrRodData* d, double* y);
/* Any state (it is checked when used); the integrator restarts from it. */
void csr_rodSetState(const csrRodModel* m, csrRodData* d, const double* y);

/* The base (hip) motion is robot_leg.h's csrBaseState (x, R, v, w; world frame). */

/* The base at rest at the spec's hip and frame. */
csrBaseState csr_rodRestBase(const csrRodModel* m);

/* The 12 chamber pressures (MPa, segment-major [3][4]) at t0 and t1 of the coming macro step;
 * the intrinsic strains (and stiffness) are evaluated at both ends and interpolated linearly in
 * time in between (the pressures are linear there). 0 ok, > 0 recoverable, < 0 fatal (the
 * calibration's code, e.g. CSR_MAP_OUT_OF_RANGE). */
int csr_rodActuate(const csrRodModel* m, csrRodData* d, double t0, const double p0[12],
                   double t1, const double p1[12]);

/* A constant tip force (N) and moment (N mm), world frame, on the foot (dynamics and statics). */
void csr_rodSetTipLoad(csrRodData* d, const double force[3], const double moment[3]);

/* The base wrench is robot_leg.h's csrWrench: force f (N) and moment m about the hip point
 * (N mm) that the leg exerts on the support, world frame. */

/* Advance from t to t + H with the base at b0 (t) and b1 (t + H), interpolated by cubic
 * Hermite (position and rotation, with the given velocities: C1 across consecutive steps when
 * b0 is where the last step ended; the small jumps of a coupling's predictor are integrated
 * across, a jump beyond 0.1 mm or 1e-3 rad restarts the integrator).
 * w (may be NULL): the base wrench averaged over the step (impulse / H, integrated with the
 * state: exact momentum exchange for a staggered scheme). The integrator restarts (CVodeReInit)
 * when the state was set, the pressures or the base jump between steps, or t is not where the
 * last step ended. Returns 0, > 0 recoverable (CVODE could not complete the step: convergence,
 * error test, recoverable callback failures; the driver may retry with a smaller H), < 0 fatal
 * (bad arguments, fatal callback); on any failure the state is unchanged and err says why. */
int csr_rodAdvance(const csrRodModel* m, csrRodData* d, double t, double H, const csrBaseState* b0,
                   const csrBaseState* b1, csrWrench* w, csError* err);

/* Base wrench at the current state and base (instantaneous; evaluates only the hip element and
 * the hip node's spring, so the gains below cost 24 of those instead of 24 whole-rod kernels:
 * under the stabilised coupling that was 100 µs per leg and macro step). */
void csr_rodBaseWrench(const csrRodModel* m, csrRodData* d, csrWrench* w);

/* Interface gains at the current state: K = -∂W/∂(hip displacement, rotation) and
 * C = -∂W/∂(hip velocity, angular velocity), W = (force, moment about the hip) on the support,
 * 6x6 row-major, world frame; instantaneous (the rod's state held fixed): the stiffness and
 * damping of the hip's first element, which an implicit spring in ODE can take over. */
void csr_rodInterfaceGains(const csrRodModel* m, csrRodData* d, double K[36], double C[36]);

/* Interface gains over one implicit (backward Euler) step of g seconds (g > 0; g = 0: the
 * instantaneous gains above): how the base wrench at the step's end changes with a base
 * displacement δX and velocity δV there, W ≈ W0 - K δX - C δV, the rest of the rod responding
 * through its own implicit step (inertia, damping, stiffness, contact): the Schur complement of
 * the rod's step matrix onto the hip, from the last Jacobian CVODE asked for (the instantaneous
 * gains when there is none yet). This is what an implicit spring on the support can stand in
 * for: the hip element alone is stiff and heavily damped (13 N/mm, 0.26 N s/mm axially) but
 * moves a node of ~1 g, which follows the hip within ~5 µs, so over a 1 ms step the support
 * feels the whole leg's response, measured ~25 times weaker in damping (robot_rod_leg.c). */
void csr_rodInterfaceGainsStep(const csrRodModel* m, csrRodData* d, double g, double K[36],
                               double C[36]);

/* ---- queries -------------------------------------------------------------------------------- */

/* Contact shapes at the current state (max >= N fills all); returns the number written. */
int csr_rodContactShapes(const csrRodModel* m, const csrRodData* d, csrRodShape* shapes,
                         int max);
/* k points (k >= 2) equally spaced in rest arc length from hip to foot, (k x 3) world mm. */
void csr_rodCenterline(const csrRodModel* m, const csrRodData* d, int k, double* out);
/* Node positions (N + 1) x 3 (world mm); row 0 is the hip. */
void csr_rodNodes(const csrRodModel* m, const csrRodData* d, double* x);
/* Σ m_i x_i over the nodes (t mm, world). */
void csr_rodMassMoment(const csrRodModel* m, const csrRodData* d, double mx[3]);
/* The leg's linear momentum P[3] (t mm/s, world): every node's, the hip node's moving with the
 * base (the base wrench's force is the impulse of the external forces less the change of P) */
void csr_rodMomentum(const csrRodModel* m, const csrRodData* d, double P[3]);

/* Kinetic, elastic and gravitational (relative to the origin) energy (N mm) at the current
 * state, base and actuation. */
typedef struct csrRodEnergy_ {
  double kinetic, elastic, gravity;
} csrRodEnergy;
void csr_rodEnergy(const csrRodModel* m, csrRodData* d, csrRodEnergy* e);

/* Bending angle of each segment (rad): |Σ of the relative rotation vectors between its end
 * faces| (exact for plane bending, where it may exceed π), and the tip (foot-centre) position
 * in the base frame (mm). */
void csr_rodSegmentAngles(const csrRodModel* m, csrRodData* d, double angle[CSR_NSEG],
                          double tip_base[3]);

/* Integrator counters since the data was created. */
typedef struct csrRodStats_ {
  long steps, rhs_evals, jac_evals, lin_setups, newton_iters, err_fails, conv_fails, reinits;
  long advances, failed_advances;
} csrRodStats;
void csr_rodGetStats(const csrRodData* d, csrRodStats* s);

/* ---- statics -------------------------------------------------------------------------------- */

typedef struct csrRodStaticLoad_ {
  double p[CSR_NSEG * CSR_NCHAMBER]; /* chamber pressures (MPa), segment-major */
  double tip_force[3];               /* N, world */
  double tip_moment[3];              /* N mm, world */
  int gravity;                       /* 1: the model's gravity acts (if on the legs) */
} csrRodStaticLoad;

typedef struct csrRodStaticInfo_ {
  int load_steps;     /* converged load increments */
  int cutbacks;       /* halved increments */
  int newton_iters;   /* total Newton iterations */
  double residual;    /* final scaled residual norm (-) */
} csrRodStaticInfo;

/* Equilibrium of the rod, base at rest, under `load`, continued from the current state (which
 * must be in equilibrium with the last static load, or be the reset state: unloaded), by load
 * stepping: the intrinsic strains, tip load and gravity move linearly from the last load to
 * the new one, the increment halves when Newton fails. Velocities are set to zero. On failure
 * the state is unchanged (CS_ERR_SOLVER naming the load fraction reached). */
csStatus csr_rodStatic(const csrRodModel* m, csrRodData* d, const csrRodStaticLoad* load,
                       csrRodStaticInfo* info, csError* err);

/* ---- the leg level -------------------------------------------------------------------------- */

/* A constant force (N) and moment (N mm), world frame, on the foot of a csr_leg_rod leg (its
 * rod's tip load, csr_rodSetTipLoad; a change restarts the integrator): a foot pushed along the
 * road (tests/robot/test_rod_friction.c). */
void csr_rodLegSetTipLoad(csrLeg* leg, const double force[3], const double moment[3]);
/* The integrator counters of a csr_leg_rod leg's rod (csr_rodGetStats; the benchmarks). */
void csr_rodLegStats(const csrLeg* leg, csrRodStats* s);

/* Solve the rod statically for one bend-curve point: all 12 pressures p (MPa), tip force
 * (N, base frame); angles (deg) per segment and tip position (mm, base frame e1 e2 e3). The
 * csrRodData carries the equilibrium from call to call (continuation). Gravity off. */
csStatus csr_rodBendPoint(const csrRodModel* m, csrRodData* d, const double p[12],
                          const double tip_force_base[3], double angle_deg[CSR_NSEG],
                          double tip[3], csError* err);

/* The foot's compliance under an axial load (the sway-buckling procedure,
 * actuator/robot_sway.h): from the current state (the straight, unloaded leg or the
 * equilibrium of a smaller such load) the dead load -P d3 on the foot (d3 the foot's axis
 * before the call, N), then central differences of the static solves under +-dH d1 (N) and
 * +-dM d2 (N mm) added: C[0] = d delta / dH (mm/N), C[1] the mean of d delta / dM and
 * d theta / dH (1/N; equal by reciprocity), C[2] = d theta / dM (1/(N mm)), delta the foot
 * node's displacement along d1, theta its frame's d3 turned towards d1 (rad). The state ends
 * in equilibrium with -P d3. y: scratch of csr_rodStateSize doubles. Statics' errors pass. */
csStatus csr_rodSwayCompliance(const csrRodModel* m, csrRodData* d, double P, double dH,
                               double dM, double* y, double C[3], csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_ROD_H */

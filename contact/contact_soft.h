/* contact_soft.h: the soft leg-terrain contact law of the co-simulated legs (rod, rom): normal
 * force, elasto-plastic friction and its history, called from inside the leg's implicit
 * integrator (CVODE BDF). The support's own contacts stay in ODE (contact_ode.h).
 *
 * Owns: cscSoftParams (the law's parameters, units and defaults), cscShape (a leg's contact
 * shapes: capsules along the leg, the flat foot), cscSoftModel (parameters + shapes + a copy of
 * the terrain's boxes; constant during a run), the flat history state (caller-owned), and the
 * functions that turn the shapes' poses and velocities plus the history into forces (and, for
 * a leg that linearises the law in an implicit step, a foot's force derivatives:
 * contact_soft_jac.c).
 *
 * Model, per shape against every nearby terrain box (geometry: contact_geom.h, closed forms):
 * - Normal force: an elastic foundation (Winkler; Johnson, Contact Mechanics, ch. 4.3) with
 *   modulus k_area (N/mm^3, pressure per mm of depth), the one parameter for every shape:
 *     foot sole, element of area A at depth d:    F = k_area A g(d)
 *     capsule of radius r, per mm of axis:         f = k_area (4/3) sqrt(2 r) g(d)^(3/2)
 *   (the foundation under a cylinder at depth d << r, contact half-width sqrt(2 r d)); a
 *   capsule crossing an edge integrates to the sphere's pi r k_area d^2. g(d) is d with a C1
 *   onset over d_onset (g = 0 for d <= 0, = d for d >= d_onset). Damping is Hunt-Crossley's,
 *   F (1 + c_hc d'), so the force is continuous at touch-down; the factor is clipped smoothly
 *   at 0, so the normal force never pulls (Hunt & Crossley 1975; Marhefka & Orin 1999).
 *   The foot is an (nside x nside) Gauss-Lobatto grid of sole points on [-a, a]^2, each a
 *   sphere of radius rho (the sole's rounded rim) whose pressure element is its quadrature
 *   weight of the 2a x 2a sole: on a flat face the sole is a patch whose force and moments are
 *   exact for the linear pressure of a tilted rigid sole, so it rests without rocking. A
 *   capsule's line load is integrated by nquad Gauss-Legendre points over the exact stretch of
 *   its axis within reach of the box (the level set of the segment-box distance,
 *   contact_geom.h): smooth in the pose, no bumps when it slides over an edge, no double
 *   counting between neighbouring capsules. End caps carry no load (the neighbours and the
 *   foot cover them).
 * - Friction: elasto-plastic, with a tangential "bristle" z (mm, world vector) per slot (a
 *   capsule, a foot, or with CSC_FOOT_POINTS each sole point). Force F_t = -(N / delta_t) (z_t +
 *   tau_t z_t'), so the tangential stiffness is N / delta_t and the stick range is
 *   |z_t| <= mu delta_t, whatever the load; z_t is z in the contact's tangent plane; a patch
 *   foot adds a torsional bristle phi about the normal (stiffness J / delta_t, Coulomb couple
 *   mu sum N_i r_i over its sole points). Two ways to evolve z (`history`):
 *   * CSC_HISTORY_INTEGRATED (default): z is state the leg integrates with the rest of its
 *     state; compute() returns z'. The single-state elasto-plastic law of Dupont et al. (2002),
 *     in vector form: z' = w - alpha(u) <u_hat . w>+ u_hat, w the tangential slip velocity of
 *     the contact point, u = |z_t| / (mu delta_t): alpha = 0 below u_elastic (pure elastic
 *     stick: a stance foot holds with zero drift, including under vibration), rising C1 to 1 at
 *     u = 1 (and beyond, so u = 1 attracts): sliding holds the force at mu N. Smooth (C1) in
 *     the state, so BDF with error control integrates it.
 *   * CSC_HISTORY_STEP: z is an anchor point fixed within a step (Cundall & Strack 1979) and
 *     moved by csc_softUpdate() at the end of each accepted step; within a step the damped
 *     force -(N / delta_t)(z_t + tau_t w) is return-mapped onto |F_t| <= mu N as a whole,
 *     smoothly (continuous and C1; contact_soft_internal.h csc_softFrictionStep), so no slip
 *     rate takes it past mu N; the update keeps it continuous. A slot that touches down
 *     mid-step has no friction until the next update.
 *   Measured on a 40 g foot block under 0.8 N in CVODE BDF (tests/contact/test_contact_soft.c,
 *   table in its header): both hold at 0.9 mu N (creep <= 1.2e-5 um/s) and slide at 1.1 and
 *   2 mu N at mu N to 1e-5 (ODE's contacts: 0.483 mu N at 2 mu N); integrated needs 770-1800
 *   right-hand sides for a 2.1 s run, step mode 5k-110k (10 ms / 1 ms macro steps: every update
 *   restarts BDF at order 1 with a new Jacobian). Hence the default: integrated, with the patch
 *   foot (4 history doubles per foot).
 *   Out of contact (and for the stretch of depth 0 ... -d_onset) z relaxes to 0 with time
 *   constant tau_reset, so a foot touches down with a fresh bristle.
 *
 * Reentrant and allocation-free after create: compute() reads the model and the state given
 * and writes only its outputs (so a leg can evaluate it from many threads or save/restore its
 * state as one vector). Cost: per shape, a scan of the terrain's boxes (at most 32, see
 * terrains_ccd.h) and per touching box a segment-box distance plus nquad points (capsule) or
 * one point-box distance per sole point.
 *
 * Frames and units: world frame of docs/reference.md (y up), mm, s, N, N mm. */
#ifndef CS_CONTACT_SOFT_H
#define CS_CONTACT_SOFT_H

#include "contact_geom.h"
#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* How the friction history evolves (header). */
typedef enum cscHistoryMode_ {
  CSC_HISTORY_INTEGRATED = 0, /* z is integrated state, compute() gives z' */
  CSC_HISTORY_STEP = 1        /* anchors moved by csc_softUpdate at step ends, z' = 0 */
} cscHistoryMode;

/* How a foot's friction is resolved (its normal force always comes from every sole point). */
typedef enum cscFootFriction_ {
  CSC_FOOT_PATCH = 0, /* one bristle z (3) + one torsional bristle phi (1) for the whole sole,
                         acting at its pressure centre: 4 history doubles (integrated only) */
  CSC_FOOT_POINTS = 1 /* one bristle per sole point: 3 nside^2 doubles (4 nside^2 in step
                         mode, which always uses points: anchors need material points) */
} cscFootFriction;

/* Parameters of the law (model side). Defaults and their reasons: csc_softDefaultParams. */
typedef struct cscSoftParams_ {
  double mu;          /* -: Coulomb friction coefficient */
  double k_area;      /* N/mm^3: foundation modulus (normal pressure per mm of depth) */
  double c_hc;        /* s/mm: Hunt-Crossley damping (force factor 1 + c_hc * depth rate) */
  double d_onset;     /* mm: width of the C1 onset of the normal force and of the bristle */
  double delta_t;     /* mm: tangential compliance length: stiffness N/delta_t, stick range
                         mu*delta_t */
  double tau_t;       /* s: tangential damping time (bristle damping = tau_t * stiffness) */
  double u_elastic;   /* -: fraction of mu N below which sticking is purely elastic, [0, 1) */
  double tau_reset;   /* s: relaxation time of the bristle out of contact */
  double v_plastic;   /* mm/s: the outward slip speed's positive part is smoothed below this */
  int nquad;          /* Gauss-Legendre points per capsule-box line load, 1..8 */
  cscHistoryMode history;
  cscFootFriction foot;
} cscSoftParams;

/* Defaults (contact_soft.c gives the numbers behind each). */
cscSoftParams csc_softDefaultParams(void);

/* Check every field; CS_ERR_RANGE with "soft contact: <field> <value> must be ..." otherwise. */
csStatus csc_softParamsValidate(const cscSoftParams* p, csError* err);

/* One contact shape of a leg (model side). */
typedef enum cscShapeKind_ {
  CSC_SHAPE_CAPSULE = 0, /* axis x0 -> x1 of the pose, radius `radius` */
  CSC_SHAPE_FOOT = 1     /* square sole 2 half_side wide, centred at x0, normal e3 of R */
} cscShapeKind;

typedef struct cscShape_ {
  cscShapeKind kind;
  double radius;    /* mm: capsule radius; foot: radius rho of the sole's rounded rim */
  double half_side; /* mm: foot: half side a of the sole (unused for capsules) */
  int nside;        /* foot: sole points per side, 2..5 (Gauss-Lobatto; unused for capsules) */
} cscShape;

/* A capsule of radius r; a foot of half side a with a 1 mm rim and 3 x 3 sole points (the
 * nine points keep the middle of the sole in contact when a step edge runs under it). */
cscShape csc_softCapsule(double r);
cscShape csc_softFoot(double a);

/* Pose and velocity of one shape, per evaluation (data side). */
typedef struct cscShapeState_ {
  double x0[3], x1[3]; /* mm: capsule axis ends; foot: centre of the sole face (x1 unused) */
  double R[9];         /* foot: orientation, row-major; columns e1, e2 span the sole, e3 is its
                          outward normal (from the leg towards the ground); capsule: unused */
  double v0[3], v1[3]; /* mm/s: velocities of x0 and x1 (foot: v1 unused) */
  double w[3];         /* rad/s: angular velocity (foot: of the foot; capsule: of its cross-
                          section, for the velocity of the surface point in contact; 0 if
                          unknown, which makes a rolling capsule's contact point slip) */
} cscShapeState;

/* Load on one shape: forces on x0 and x1 and a couple; together equivalent (same resultant,
 * same moment about any point) to all its contact forces. Capsule: each point force at axis
 * parameter s goes (1 - s) to x0 and s to x1, m is the moment of the offsets of the friction
 * forces' surface points from the axis; foot: f0 is the resultant, f1 = 0, m the moment about
 * x0. */
typedef struct cscShapeLoad_ {
  double f0[3], f1[3]; /* N */
  double m[3];         /* N mm */
} cscShapeLoad;

/* Per-slot diagnostics (a slot = a capsule, a foot patch, or one sole point of a foot). */
typedef struct cscSlotInfo_ {
  int shape;        /* owning shape */
  double depth;     /* mm: deepest penetration (< 0: gap, -INFINITY: no box within reach) */
  double N;         /* N: normal force (projected resultant) */
  double normal[3]; /* unit, terrain -> shape (0 when out of contact) */
  double point[3];  /* mm: load centroid on the shape's surface */
  double ft[3];     /* N: friction force */
  double torsion;   /* N mm: torsional friction couple about the normal (foot patch) */
  double ratio;     /* -: |z_t| / (mu delta_t), 1 at the Coulomb limit (0 if mu = 0); step
                       mode: of the damped deflection, |z_t + tau_t w| / (mu delta_t) */
  int sliding;      /* at the Coulomb limit and slipping outwards */
} cscSlotInfo;

/* Summary of one evaluation. */
typedef struct cscSoftReport_ {
  int ncontact;     /* slots touching (depth > 0) */
  int nsliding;     /* of those, sliding */
  int ndeep;        /* samples beyond the shapes' radius (compute then returns > 0) */
  double max_depth; /* mm: deepest penetration (0 if none) */
  double max_ratio; /* -: largest friction ratio among touching slots */
} cscSoftReport;

typedef struct cscSoftModel_ cscSoftModel; /* opaque */

/* Build a model for `nshape` shapes (copied) against the boxes of `terrain` (copied). Returns
 * NULL and fills err on bad parameters or shapes ("soft contact: shape <i>: ..."). */
cscSoftModel* csc_softCreate(const cscSoftParams* p, const cstTerrain* terrain, int nshape,
                             const cscShape* shapes, csError* err);
void csc_softDestroy(cscSoftModel* m); /* NULL-safe */

int csc_softNShape(const cscSoftModel* m);
int csc_softNSlot(const cscSoftModel* m);
/* length of the history state (doubles): the shapes' blocks one after the other; integrated:
 * 3 per capsule, 4 per patch foot, 3 per sole point of a point foot; step: 4 per slot */
int csc_softNState(const cscSoftModel* m);
/* first slot and number of slots of shape i */
void csc_softShapeSlots(const cscSoftModel* m, int i, int* first, int* count);
/* offset and length of shape i's block in the history state */
void csc_softShapeState(const cscSoftModel* m, int i, int* offset, int* count);
const cscSoftParams* csc_softParams(const cscSoftModel* m);

/* Fresh history (no stored deflection, every slot untouched): z is (nstate); the shape
 * version fills shape i's block only (z points at it). */
void csc_softStateInit(const cscSoftModel* m, double* z);
void csc_softShapeStateInit(const cscSoftModel* m, int i, double* z);

/* Forces of all shapes. s: (nshape) poses; z: (nstate) history; load: (nshape) out; zdot:
 * (nstate) out or NULL (always 0 in step mode); slot: (nslot) out or NULL; rep: out or NULL.
 * Returns 0; > 0 (recoverable: the integrator should cut its step) when a pose is not finite or
 * a shape sinks beyond its radius (a capsule's axis or a sole point's centre inside a box),
 * with the outputs still filled as far as they are defined; < 0 for NULL arguments. */
int csc_softCompute(const cscSoftModel* m, const cscShapeState* s, const double* z,
                    cscShapeLoad* load, double* zdot, cscSlotInfo* slot, cscSoftReport* rep);

/* End of an accepted step at poses s: step mode moves each touching slot's anchor so that its
 * deflection is at most the stick range (the force stays continuous), anchors slots that
 * touched down, frees slots out of contact; integrated mode changes nothing. Returns as
 * compute. */
int csc_softUpdate(const cscSoftModel* m, const cscShapeState* s, double* z);

/* The same for one shape i, for a leg that evaluates its shapes one at a time (a rod's
 * per-element contact hook): s is that shape's pose, z and zdot its block of the history
 * (csc_softShapeState), load its load (required), slot its slots (csc_softShapeSlots) or NULL,
 * and rep, if not NULL, is added to (zero it before the first shape). */
int csc_softComputeShape(const cscSoftModel* m, int i, const cscShapeState* s, const double* z,
                         cscShapeLoad* load, double* zdot, cscSlotInfo* slot,
                         cscSoftReport* rep);
int csc_softUpdateShape(const cscSoftModel* m, int i, const cscShapeState* s, double* z);
/* csc_softUpdateShape, then the load, slots and report (each may be NULL but load) that
 * csc_softComputeShape gives at the updated history, from one evaluation of the shape's
 * geometry (the same bits as the two calls: the friction at the new anchors is summed in the
 * same order). Returns as csc_softUpdateShape. */
int csc_softUpdateShapeLoad(const cscSoftModel* m, int i, const cscShapeState* s, double* z,
                            cscShapeLoad* load, cscSlotInfo* slot, cscSoftReport* rep);

/* What csc_softShapeJacobian returns for a shape or law it does not differentiate. */
#define CSC_SOFT_NO_JACOBIAN (-2)

/* The load of shape i at pose s and history z (its block) with its derivatives, for a leg that
 * linearises the law inside an implicit step (contact_soft_jac.c). Covered: a foot (step-mode
 * sole points) against terrain boxes with one friction; otherwise returns CSC_SOFT_NO_JACOBIAN
 * and the caller differences csc_softComputeShape. L (6) = (f0, m): the resultant (N) and the
 * moment about x0 (N mm), as csc_softComputeShape's load to round-off; K (6 x 6, row-major) its
 * derivative with respect to (x0 (mm), φ (rad): R turned to exp(φ^) R about x0, the world
 * rotation vector), C (6 x 6) with respect to (v0 (mm/s), w (rad/s)). Returns 0, > 0 as
 * csc_softComputeShape (a non-finite pose or history, a sole point's centre inside a box),
 * -1 for bad arguments. */
int csc_softShapeJacobian(const cscSoftModel* m, int i, const cscShapeState* s, const double* z,
                          double L[6], double K[36], double C[36]);

/* The load of shape i (pose s) as one force f (N) at a point P (mm) plus a couple M (N mm),
 * statically equivalent (same resultant, same moment about any point), for a per-element hook
 * that takes that form: a capsule's P is on its axis at the parameter that carries f0 and f1
 * best by the lever rule (xi = f1 . f / f . f, clamped to [0, 1]; exact when f0 and f1 are
 * parallel), M the remainder; a foot's P is the sole's centre x0. */
void csc_softLoadAsPointForce(const cscSoftModel* m, int i, const cscShapeState* s,
                              const cscShapeLoad* load, double f[3], double P[3], double M[3]);

#ifdef __cplusplus
}
#endif
#endif

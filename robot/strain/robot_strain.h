/* robot_strain.h: the strain-coordinate Cosserat leg (issue 32: model, statics and the implicit
 * step condensed onto the base, one linearised pass or Newton iterations with the base's linear
 * rows in a discrete momentum form; docs/notes/strain_leg.md): one leg as a geometrically
 * exact Cosserat rod whose unknowns are the strains of its pieces (SoRoSim's geometric
 * variable strain), the solid joints LS12, LS23
 * at a constant curvature (or rigid).
 *
 * Owns: csrStrainParams (basis, quadrature, static solver; defaults with reasons in
 * robot_strain.c), csrStrainSpec, csrStrainModel (constant during a run) and csrStrainData
 * (generalised coordinates and velocities, the rest strains of the current actuation, the
 * base, the contact anchors, scratch), the kinematics (pose and geometric Jacobian along the
 * rod, robot_strain_lie.c), the generalised elastic, tip and gravity forces, the generalised
 * mass matrix and the static solver (robot_strain.c), the step condensed onto the base
 * (robot_strain_dyn.c, its inertia in robot_strain_inertia.c) and the leg-terrain contact inside it (robot_strain_contact.c).
 *
 * Strain field (body frame of the cross-section, angular part first, SE(3) twist per unit rest
 * arc length X): ξ = (u; ν) with u = (κ1, κ2, τ) the Darboux vector and ν = e3 + σ the
 * shear-stretch vector, exactly the nodal rod's (robot_rod.h) strains u and e3 + σ. In a
 * flexible piece of length S,
 *   ξ(X) = ξ* + Φ(X) q,   ξ* = (0, 0, 0, 0, 0, 1) (straight, unstretched),
 * where κ1 and κ2 each have Legendre modes P_0..P_n of the local coordinate 2X/S - 1
 * (n = csrStrainParams.bend_order in the segments, joint_order in the joints), twist τ and
 * stretch σ3 modes P_0..P_a (a = axial_order), and the shears σ1, σ2 as many when
 * csrStrainParams.shear is set (else they are 0: Kirchhoff). The unknowns of piece k are, in
 * this order, [κ1 modes, κ2 modes, τ modes, (σ1 modes, σ2 modes), σ3 modes]. A rigid piece
 * (joint_order -1) has no unknowns: ξ = ξ*.
 *
 * Kinematics: g(X) = (R, x) in SE(3), g' = g ξ^ from the clamp g(0) = (frame, hip), integrated
 * by the 4th-order Magnus expansion with two Gauss points per sub-interval (Zanna):
 *   Ω = h/2 (ξ_a + ξ_b) + √3 h²/12 ad(ξ_a) ξ_b,   g_{k+1} = g_k exp(Ω^),
 * and the body geometric Jacobian J(X) (6 x n, body twist = J q̇) by the same recursion:
 *   J_{k+1} = Ad(exp(-Ω)) J_k + T(Ω) ∂Ω/∂q,  T(Ω) = Σ_j (-ad Ω)^j / (j + 1)! = dexp(-Ω).
 * Elastic force: ∂/∂q ½∫(ξ - ξ0)ᵀ C (ξ - ξ0) dX = K q - b, K = ∫ΦᵀCΦ (diagonal: the Legendre
 * modes are orthogonal and C = diag(EI1, EI2, GJ, GA1, GA2, EA) is diagonal), b = ∫ΦᵀC(ξ0 - ξ*)
 * with ξ0 the calibration's intrinsic strains (u0, e3 + σ0) of the current pressures.
 * Loads: a wrench F (body) at X enters as J(X)ᵀ F.
 *
 * Units: mm, s, N, N mm, t, MPa; the world frame of robot_leg.h (x crawl direction, y up, z
 * lateral); matrices row-major. */
#ifndef CS_ROBOT_STRAIN_H
#define CS_ROBOT_STRAIN_H

#include "contact_soft.h"
#include "core_status.h"
#include "robot_actuator.h"
#include "robot_leg.h"
#include "robot_rod.h"

#ifdef __cplusplus
extern "C" {
#endif

/* highest Legendre order of a strain component's modes */
#define CSR_STRAIN_MAX_ORDER 6
/* highest number of Magnus sub-intervals per flexible piece */
#define CSR_STRAIN_MAX_SUB 64

typedef struct csrStrainParams_ {
  int bend_order;      /* Legendre order of κ1, κ2 in each actuated segment (0..MAX_ORDER) */
  int axial_order;     /* Legendre order of τ, σ1, σ2, σ3 in every flexible piece (0..MAX_ORDER) */
  int joint_order;     /* Legendre order of κ1, κ2 in the solid joints LS12, LS23 (-1: rigid
                          joints, no unknowns; 0..MAX_ORDER) */
  int shear;           /* 1: the shears σ1, σ2 are unknowns; 0: they are zero (Kirchhoff) */
  int nsub;            /* Magnus sub-intervals per flexible piece (1..MAX_SUB); a piece whose
                          strains are all constant takes one (its exponential is exact) */
  double static_tol;   /* static Newton: largest update of a mode at convergence, as rotation
                          (rad) or strain (-) over its piece */
  int static_max_iter; /* static Newton iterations per load increment */
  int step_order;      /* the dynamic step (robot_strain_dyn.c): 1 backward Euler linearised at
                          the step's start (inertia, velocity products and weight there); 2
                          BDF2 (variable step, a backward-Euler first step) with the whole
                          residual at the iterate */
  int step_refresh;    /* step_order 2: 1 assembles the inertia, velocity products and weight
                          at every Newton iterate (Newton on BDF2's whole residual); 0 once,
                          at the step's first iterate (a linearly implicit BDF2: the iterates
                          as backward Euler's, only the contact and the momentum rows at the
                          iterate; robot_strain_dyn.c, Step) */
  int active_set;      /* 1: the Newton iterates hold a contact shape that touched at its last
                          linearisation and is out at the iterate by that linearisation's
                          affine load (a "ghost", allowed to pull) until the passes converge,
                          then drop it (csr_strainRelease) and go on: the converged step is the
                          law's (robot_strain_contact.c, Active set); 0: the law alone.
                          Backward Euler's only: step_order 2 ignores it */
  int friction_tangent; /* the stick-anchor friction in the Newton iterates' matrix
                          (robot_strain_contact.c, anchorSecant): 0 the anchors' secant on
                          every saturated slot of the foot; 1 the law's consistent tangent
                          (the return map differentiated: no secant). Only the matrix:
                          converged, the step is the law's either way (docs/notes/
                          strain_leg.md, "The friction's tangent") */
  int slot_trust;      /* globalisation of the Newton passes at the friction's saturation
                          (robot_strain_contact.c, Slot trust region): 1 a pass moves the
                          whole tree (support and every leg) at most as far as takes a
                          touching foot slot two stick ranges (2 mu delta_t) along the
                          surface (csr_strainStepLimit); 0 the full Newton move. Backward
                          Euler only. Only the path: converged, the step is the law's */
  int keep_matrix;     /* 1: the leg's factored iteration matrix (W_ll with the contact's
                          linearisation, its Schur complement Z onto the base) is kept across
                          steps and refreshed by keep_strain, a contact slot changing state, a
                          Newton iterate contracting less than 4x, a new step length or a
                          restored state; the residual is exact whatever the factor's age (the
                          inertia's product M(q0) Δu formed matrix-free; robot_strain_dyn.c,
                          Kept matrix). 0: a new factor every step. Backward Euler only. A
                          cache, not state: a restored run refactors where the uninterrupted
                          one kept, so its steps agree to the passes' tolerance, not bit for
                          bit */
  double cal_quantum;  /* the calibration's pressure lattice (MPa): > 0 maps each segment's four
                          chamber pressures to rest strains and sections by linear
                          interpolation on the simplex (Kuhn's triangulation) of the lattice of
                          this spacing that holds them, from the calibration at its five
                          vertices (kept per segment and reused while the pressures stay near):
                          continuous in the pressures, exact for a linear field, a function of
                          the pressures alone (a restored state needs nothing more); a vertex
                          outside the calibration's range falls back to the exact evaluation
                          (robot_strain_cal.c; docs/notes/strain_leg.md "The cost of
                          one leg step"). 0: the calibration at the pressures as given (exact) */
  double keep_strain;  /* keep_matrix: a step refactors when a mode moved more than this since
                          the factorisation (rad or strain over its piece, the measure of
                          csr_strainUpdate's change without h); < 0: every step (the
                          matrix-free residual with a fresh factor) */
  int artic;           /* 1: a backward-Euler step's first pass of a leg that touches nothing
                          condenses onto the base by the articulated recursion over the pieces
                          (robot_strain_artic.c: no n x n inertia, no dense factor); 0: the
                          dense assembly and factor; 2: a leg that touches too (the
                          contact's unsymmetric blocks in the recursion, its kept iterates
                          solved through the pieces' factors). The same step to round-off;
                          with keep_matrix (which keeps the dense factor) the dense path */
} csrStrainParams;

/* Defaults (reasons in robot_strain.c). */
csrStrainParams csr_strainDefaultParams(void);

typedef struct csrStrainSpec_ {
  const csrActuator* act;         /* the leg (NULL only with csr_strainModelCreatePieces) */
  const csrRodParams* rod_params; /* material (E, G, shear coefficient) and cal_drop, as for the
                                     nodal rod (NULL: csr_rodDefaultParams(act)) */
  const csrStrainParams* params;  /* NULL: csr_strainDefaultParams() */
  const csrBendMap* map;          /* pressure -> bend calibration (NULL: no actuation) */
  const csrRodCalibration* calib; /* richer calibration, used instead of map when not NULL */
  double hip[3];                  /* clamp position, world mm */
  double frame[9];                /* clamp frame (columns e1 e2 e3), world, row-major */
  double gravity[3];              /* world mm/s^2 */
  int weightless;                 /* 1: mass and inertia but no weight (conditions `paper`) */
  /* leg-terrain contact (NULL terrain: none): contact_soft.h's law on the leg's shapes, a
   * capsule of radius rod_params->contact_radius on every Magnus sub-interval's chord but the
   * last, and the flat foot (the sole, side 2a) at the tip; its friction in step mode (stick
   * anchors fixed within a step and return-mapped after it), whatever soft->history says */
  const cstTerrain* terrain;      /* copied by the contact model */
  const cscSoftParams* soft;      /* NULL: csc_softDefaultParams() */
} csrStrainSpec;

typedef struct csrStrainModel_ csrStrainModel;
typedef struct csrStrainData_ csrStrainData;

/* The leg of spec->act: the nodal rod's five pieces (csr_rodLegPieces), the segments at
 * bend_order, the joints at joint_order. NULL and err on invalid input. */
csrStrainModel* csr_strainModelCreate(const csrStrainSpec* spec, csError* err);
/* A rod of arbitrary pieces (tests): order[k] is piece k's bending order (-1: rigid; order NULL:
 * bend_order for every piece); nelem is ignored; pieces with segment >= 0 are actuated through
 * the spec's calibration. */
csrStrainModel* csr_strainModelCreatePieces(const csrRodPiece* pieces, const int* order,
                                            int npiece, const csrStrainSpec* spec, csError* err);
void csr_strainModelDestroy(csrStrainModel* m);

int csr_strainDofs(const csrStrainModel* m);     /* n: generalised coordinates */
double csr_strainLength(const csrStrainModel* m); /* rest length (mm) */
double csr_strainMass(const csrStrainModel* m);   /* total mass (t) */
/* the first unknown of piece k and how many it has (0 for a rigid piece) */
void csr_strainPieceDofs(const csrStrainModel* m, int k, int* first, int* count);

csrStrainData* csr_strainDataCreate(const csrStrainModel* m, csError* err);
void csr_strainDataDestroy(csrStrainData* d);
/* Straight and unstrained (q = 0), actuation off, no tip load. */
void csr_strainReset(const csrStrainModel* m, csrStrainData* d);
/* The generalised coordinates q (n). */
void csr_strainGetQ(const csrStrainModel* m, const csrStrainData* d, double* q);
/* Set q (n finite values); -1 (nothing changed) otherwise. */
int csr_strainSetQ(const csrStrainModel* m, csrStrainData* d, const double* q);

/* The 12 chamber pressures (MPa, segment-major): the rest strains ξ0 and, where the calibration
 * gives it, the section stiffness of each actuated piece, through the nodal rod's own
 * calibration path (the same strains and stiffness). 0 ok, else the calibration's code (err
 * says which segment and pressures); on failure the actuation is unchanged. */
int csr_strainActuate(const csrStrainModel* m, csrStrainData* d, const double p[12],
                      csError* err);

/* Pose at rest arc length X (0..L): position x (mm) and frame R (columns d1 d2 d3), world. */
void csr_strainPose(const csrStrainModel* m, csrStrainData* d, double X, double x[3],
                    double R[9]);
/* k >= 2 points equally spaced in rest arc length from hip to tip, (k x 3) world mm. */
void csr_strainCenterline(const csrStrainModel* m, csrStrainData* d, int k, double* out);
/* The body Jacobian at the tip (6 x n, row-major; rows ω (body), v (body)). */
void csr_strainTipJacobian(const csrStrainModel* m, csrStrainData* d, double* J);

/* Generalised force of the current state under a world tip force (N) and moment (N mm) and,
 * if gravity is set and the spec is not weightless, the weight: Q = -(K q - b) + Σ Jᵀ F (n). */
void csr_strainForce(const csrStrainModel* m, csrStrainData* d, const double tip_force[3],
                     const double tip_moment[3], int gravity, double* Q);
/* The diagonal of K (n). */
void csr_strainStiffness(const csrStrainModel* m, const csrStrainData* d, double* Kdiag);
/* Generalised mass matrix M(q) = ∫ Jᵀ M_s J dX (n x n, row-major) with M_s the section's
 * mass and rotary inertia per length, plus the rigid pieces' mass and inertia. */
void csr_strainMassMatrix(const csrStrainModel* m, csrStrainData* d, double* M);

/* Equilibrium with the base at rest under `load` (the nodal rod's csrRodStaticLoad: pressures,
 * tip force and moment, gravity), continued from the current state and actuation by load
 * stepping (rest strains, stiffness, tip load and weight move linearly from the last load, the
 * increment halves when Newton fails). On failure the state and actuation are unchanged and
 * err names the load fraction reached (CS_ERR_SOLVER) or the calibration's failure. */
csStatus csr_strainStatic(const csrStrainModel* m, csrStrainData* d, const csrRodStaticLoad* load,
                          csrRodStaticInfo* info, csError* err);

/* ---- dynamics: one linearly implicit step, condensed onto the base ------------------------
 * The leg's state is (q, η = q̇); the base (hip) moves with the support. One step of h on
 * velocities, backward Euler linearised at the step's start (robot_strain_dyn.c):
 *   [W_bb W_bl; W_lb W_ll] [ΔV; Δη] = h [r_b; r_l],  W = M + h D + h² K (D, K on the strains),
 * with ΔV the change of the base's body twist over the step. csr_strainPrepare condenses the
 * leg onto ΔV: Z = W_bb - W_bl W_ll⁻¹ W_lb and ρ = h r_b - W_bl W_ll⁻¹ h r_l, so the base solves
 * (its own W + Σ Z) ΔV = its own h r + Σ ρ; csr_strainFinish back-substitutes
 * Δη = W_ll⁻¹ (h r_l - W_lb ΔV) and moves q by h η. Z and ρ are in the hip's body coordinates
 * (angular first): Z (6 x 6: t mm², t mm, t) and ρ (N mm s, N s).
 * Momentum: in the Newton iterations (csr_strainIterate), the base's three linear rows are the
 * discrete momentum balance (X1 - X0) / h - D_prev = h f (X = Σ m x the leg's mass moment,
 * world; D_prev the last step's (X1 - X0) / h; f the contact's force at the step's end, the
 * weight and the tip force), exact at the iterate, in place of backward Euler's velocity form.
 * A support written the same way (tests/robot/strain_test_robot.h) makes the whole robot's
 * Σ m x move by exactly h Σ D per step: with no horizontal force its centre of mass moves at
 * a constant velocity to the iterations' tolerance, whatever h (backward Euler's velocity form
 * moves it by O(h) of the velocity products every step). */

/* Doubles in the state [q, η, contact anchors, D, history] (2n + the soft model's history + 3
 * + 2n + 13; D the discrete linear momentum of the last step, see Momentum above; the history
 * is BDF2's (step_order 2): the last step's start q, η, base twist, mass moment and D, and its
 * length, 0 before the first step). */
int csr_strainStateSize(const csrStrainModel* m);
void csr_strainGetState(const csrStrainModel* m, const csrStrainData* d, double* y);
/* 0, or -1 (nothing changed) for non-finite values. */
int csr_strainSetState(const csrStrainModel* m, csrStrainData* d, const double* y);
/* The base (hip) pose and velocity now (world; robot_leg.h csrBaseState). */
void csr_strainSetBase(const csrStrainModel* m, csrStrainData* d, const csrBaseState* b);
/* A constant tip force (N) and moment (N mm), world, for the dynamics. */
void csr_strainSetTipLoad(csrStrainData* d, const double force[3], const double moment[3]);
/* Condense the step of h (s) at the current state, base and actuation: Z (36) and ρ (6) as
 * above. 0 ok, > 0 recoverable (W_ll not positive definite, non-finite forces: a smaller step
 * may pass), < 0 bad arguments; the state is not changed. */
int csr_strainPrepare(const csrStrainModel* m, csrStrainData* d, double h, double Z[36],
                      double rho[6]);
/* Finish the prepared step with the base's twist change dV (6, hip body coordinates) and the
 * base's new pose and velocity b1 (NULL: the base did not move): η and q move, then the
 * friction anchors are return-mapped at the new poses (csc_softUpdateShape). 0, or > 0 when
 * the new pose is not finite or sinks past a shape's radius (the caller restores the state
 * saved before the step and retries smaller). */
int csr_strainFinish(const csrStrainModel* m, csrStrainData* d, const double dV[6],
                     const csrBaseState* b1);
/* Newton iterations on the same step (the contact's force and linearisation at the step's
 * end, backward Euler converged; the rest of the step is linear in (ΔV, Δη) and exact after one
 * pass). After csr_strainPrepare, the caller may loop
 *   solve the base with Z, ρ -> csr_strainUpdate(ΔV, b1) -> csr_strainIterate -> Z, ρ
 * until every leg's and the base's change is small, then csr_strainCommit. ΔV is always the
 * whole step's (from the step's start), b1 the base at the end of the step for that ΔV.
 * csr_strainFinish is csr_strainUpdate + csr_strainCommit (one pass: the contact linearised
 * at the start, as before).
 * csr_strainUpdate: back-substitute, the leg's iterate and base move to the end of the step
 * for dV, b1 (NULL: V_b0 + ΔV, pose unchanged); *change (if not NULL) the largest move of a
 * mode against the last iterate (rad or strain over its piece, times h: a position). 0, > 0
 * not finite, < 0 no prepared step.
 * csr_strainIterate: linearise the prepared step again at the iterate: Z, ρ as in
 * csr_strainPrepare (affine in the whole step's ΔV). 0, > 0 (a pose sinks past a shape's
 * radius, W_ll singular, non-finite), < 0 no prepared step.
 * csr_strainCommit: end the step at the iterate: return-map the friction anchors. 0 or > 0 as
 * csr_strainFinish; the state saved before csr_strainPrepare restores a rejected step. */
int csr_strainUpdate(const csrStrainModel* m, csrStrainData* d, const double dV[6],
                     const csrBaseState* b1, double* change);
/* csr_strainUpdate moving the iterate only alpha (0 < alpha <= 1) of the way to the solve's
 * (the base's ΔV_it + alpha (dV - ΔV_it); b1 the base for that ΔV): a damped Newton step where
 * the contact set changes and the full one cycles. *change is the full step's move. */
int csr_strainUpdateDamped(const csrStrainModel* m, csrStrainData* d, const double dV[6],
                           double alpha, const csrBaseState* b1, double* change);
int csr_strainIterate(const csrStrainModel* m, csrStrainData* d, double Z[36], double rho[6]);
int csr_strainCommit(const csrStrainModel* m, csrStrainData* d);
/* The Newton passes converged: drop the ghosts of the last iterate (active_set; shapes out of
 * contact held by their last linearisation's affine load) for the rest of the step. Returns
 * how many were dropped: 0, the converged iterate is the law's step; > 0, it is not, and the
 * caller goes on with the passes (csr_strainIterate linearises afresh without them). */
int csr_strainRelease(const csrStrainModel* m, csrStrainData* d);
/* Before csr_strainUpdateDamped with the same dV (the support's solve, the base's twist change
 * from the step's start, body coordinates): the largest fraction alpha (0 < alpha <= 1) of the
 * move from the last iterate that slot_trust allows (1 when it is off, no foot slot touches,
 * or the last linearisation was the step's start: a sliding foot's first move is millimetres).
 * The caller damps the whole tree's move by the least alpha of its legs. */
double csr_strainStepLimit(const csrStrainModel* m, csrStrainData* d, const double dV[6]);
/* The wrench the leg exerted on the support over the last finished step, averaged (its impulse
 * / h: -(Z ΔV - ρ) / h, the discrete step's own), world, force at and moment about the hip
 * (robot_leg.h csrWrench); zero before the first step. */
void csr_strainBaseWrench(const csrStrainModel* m, const csrStrainData* d, csrWrench* w);
/* The terrain's force (N) and moment about the hip (N mm) on the leg at the current state
 * (world), and the contact report (deepest penetration, sliding slots). 0 or the law's code. */
int csr_strainContactWrench(const csrStrainModel* m, csrStrainData* d, double f[3], double mo[3],
                            cscSoftReport* rep);
/* BDF2's coefficients for a step of h after a step of h_prev (variable step, ω = h / h_prev):
 * y1 = c[0] y0 + c[1] y_-1 + c[2] h f(y1), c = ((1+ω)²/(1+2ω), -ω²/(1+2ω), (1+ω)/(1+2ω));
 * backward Euler (1, 0, 1) for the first step (h_prev 0) and after a step more than doubles
 * (ω > 2: variable-step BDF2 is zero-stable only below 1 + √2). A support stepped with the
 * legs (tests/robot/strain_test_robot.h) takes the same coefficients. */
void csr_strainBdf2Coeffs(double h, double h_prev, double c[3]);
/* The coefficients the next step of h takes at the current state: csr_strainBdf2Coeffs with
 * the last step's length under step_order 2, (1, 0, 1) under step_order 1. */
void csr_strainStepCoeffs(const csrStrainModel* m, const csrStrainData* d, double h, double c[3]);
/* Steps prepared, factorisations of W_ll and steps prepared on an earlier step's factor
 * (keep_matrix) since the data's creation (counts, not state). */
void csr_strainCounts(const csrStrainData* d, long* steps, long* factors, long* kept);
/* The discrete linear momentum residual of the last committed step by its linear model
 * (robot_leg.h momentumResidual; robot_strain_carry.c): 0, or -1 without a committed backward-
 * Euler step, with contact without the active set, or with keep_matrix (a kept matrix's start
 * records no linear model of its own). */
int csr_strainMomentumResidual(const csrStrainModel* m, const csrStrainData* d, double eps[3]);
/* The same of a leg of the strain level (robot_leg.h csr_leg_strain). */
void csr_legStrainCounts(const csrLeg* leg, long* steps, long* factors, long* kept);
/* The Magnus sub-intervals per flexible piece that the level's setting `sub` stands for at
 * `links` bending modes per segment: sub itself when > 0; 0 (the default) chooses by the
 * basis, 2 for linear curvature (links <= 2), 4 above. Two are enough for linear curvature:
 * against 4 the first bending frequency moves 0.06 %, the loaded tip 0.003 mm, the 9 s flat
 * road and the obstacle's 4 s 0.013 / 0.004 mm, for 24 % fewer instructions
 * (docs/notes/strain_leg.md "The quadrature"); above, 2 is not measured. */
int csr_strainSubIntervals(int links, int sub);
/* Kinetic energy (leg and base motion) and elastic energy relative to the rest strains (N mm). */
void csr_strainEnergy(const csrStrainModel* m, csrStrainData* d, double* kinetic,
                      double* elastic);
/* Σ m x (t mm) and the linear momentum Σ m v (t mm/s) of the leg's mass, world. */
void csr_strainMassMoment(const csrStrainModel* m, csrStrainData* d, double mx[3]);
void csr_strainMomentum(const csrStrainModel* m, csrStrainData* d, double P[3]);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_STRAIN_H */

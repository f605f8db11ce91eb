/* robot_rom.h: the reduced-order FE leg's dynamics in the floating frame of the hip (issue 34,
 * the `rom` level's model, registered behind robot_leg.h by robot_rom_leg.c over a leg file,
 * robot_rom_file.h; docs/notes/rom.md "--legs rom").
 *
 * Owns: csrRomParams (density, Kelvin-Voigt damping time, CVODE tolerances), csrRomModel (the
 * constant reduced inertia operators of a csfRom: the consistent Tet10 mass projected on the
 * basis and its couplings with the moving base; the damping matrix), csrRomData (the state
 * y = [q, q'], CVODE BDF with a dense reduced Jacobian, the impulse quadratures, scratch) and
 * the step across one macro step with the hip moving from b0 to b1, returning the base wrench
 * by momentum balance as robot_leg.h's csrWrench.
 *
 * Kinematics. The hip frame (x_h, R) moves with the support; a material point at reference
 * position X (hip frame, mm) is at x = x_h + R (X + u), u = V q (csfRom.V, the basis in the
 * hip frame, clamped rows zero). ω, α: the frame's angular velocity and acceleration in the hip
 * frame (rad/s, rad/s²); a_h: the hip point's acceleration (world).
 * Equations (Galerkin of the FE's nodal equations with its consistent mass M, scalar Tet10 mass
 * per node times I3, exact by a collapsed Gauss rule of degree 7 as tools/rom_basis.py):
 *   M_r q'' + C q' + r(q, p) = T Rᵀ(g - a_h) - Σ_k α_k (e_k + Q_k q)
 *                              - Σ_ij c_ij(ω) (d_ij + S_ij q) - 2 Σ_k ω_k Q_k q'
 * with r the reduced FE residual (fem_rom.h: internal forces minus the chamber pressures'
 * follower loads), M_r = VᵀMV, T = VᵀM[1_1 1_2 1_3], e_k = VᵀM E_k X, Q_k = VᵀM E_k V
 * (E_k: e_k × at every node; Q_k skew), ω×(ω×r) = Σ c_ij D_ij r with D_ij = (e_i e_jᵀ +
 * e_j e_iᵀ)/2 (c_ii = ω_i² - |ω|², c_ij = 2 ω_i ω_j, i < j), d_ij = VᵀM D_ij X,
 * S_ij = VᵀM D_ij V. Gravity takes the consistent mass too (T and the first moment), not the
 * FE's body-force rule, so that the weight and the inertia are one mass.
 * Damping: C = τ_d K_r(0) (Kelvin-Voigt on the reduced tangent at rest, stiffness-proportional:
 * the rod's kd = k τ_d, robot_leg.h csrLegParams.damping_time).
 * Base wrench (robot_leg.h csrWrench, averaged over the step), by momentum balance as the rod's
 * (robot_rod_dyn.c): with P the leg's linear momentum and L_h its angular momentum about the
 * moving hip point (world), s(q) = ∫ρ (X + u) dV its first mass moment (hip frame),
 *   H f = m g H - ΔP,   H m = ∫ (R s(q) × g - v_h × P) dt - ΔL_h,
 * the time integral a CVODE quadrature: the support receives exactly the momentum the leg's
 * state lost, whatever the integration error. The sole's contact forces (csr_romModelSetSole)
 * add their impulse to f and their moment about the hip to m, integrated in y alike.
 * Base motion across a step: the hip point by cubic Hermite interpolation of (x, v) at both
 * ends; the frame R(t) = R0 exp(φ(t)) with φ the cubic Hermite of the rotation vector from
 * φ(0) = 0, φ'(0) = R0ᵀw0 to φ(H) = log(R0ᵀR1), φ'(H) = R0ᵀw1, and ω ≈ φ', α ≈ φ'' (exact for
 * a rotation about a fixed axis; the error is O(|φ| |φ'|) otherwise, |φ| the rotation within
 * one macro step).
 * Units: mm, s, t, N, MPa. Shapes: row-major; q (n). */
#ifndef CS_ROBOT_ROM_H
#define CS_ROBOT_ROM_H

#include "contact_soft.h"
#include "core_status.h"
#include "fem_rom.h"
#include "robot_leg.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct csrRomParams_ {
  double rho;          /* density, t/mm^3 (silicone: 1.07e-9) */
  double damping_time; /* τ_d (s): C = τ_d K_r(0) */
  double rtol;         /* CVODE relative tolerance */
  double atol_u;       /* CVODE absolute tolerance as a displacement (mm): q_k's is atol_u
                          over the largest nodal displacement of a unit q_k (max_i |V_ik|), so
                          it means the same for any scaling of the basis (M-orthonormal bases
                          have q in mm t^0.5); q_k' gets 1e3 times that (per ms) */
  double atol_wrench;  /* N: absolute tolerance of the step-averaged base wrench */
  long max_steps;      /* CVODE steps per macro step */
  double tangent_lag;  /* mm: a Jacobian reuses the last reduced FE tangent K_r while no node
                          has moved more than this since it was computed (the bound
                          Σ_k |Δq_k| max_i |V_ik|) and no chamber pressure by more than
                          1e-3 MPa; its contact and frame parts are always fresh. 0: a new
                          K_r at every Jacobian. CVODE asks for a Jacobian after every Newton
                          failure, which in contact the sole's law causes, not K_r */
  double gravity[3];   /* the scene's gravitational acceleration, world, mm/s² (0: none) */
} csrRomParams;

csrRomParams csr_romDefaultParams(void);

typedef struct csrRomModel_ {
  const csfRom* rom;   /* borrowed; must outlive the model */
  int n;
  csrRomParams par;
  double mass;         /* t */
  double s0[3];        /* ∫ρ X dV, t mm (hip frame) */
  double J0[6];        /* ∫ρ X_i X_j dV, (00 11 22 01 02 12), t mm² */
  double* Mr;          /* (n x n) VᵀMV */
  double* Minv;        /* (n x n) its inverse */
  double* C;           /* (n x n) damping, N s/mm per unit q */
  double* T;           /* (n x 3) VᵀM 1_k, t */
  double* e;           /* (3 x n) VᵀM E_k X, t mm */
  double* Q;           /* (3 x n x n) VᵀM E_k V, t */
  double* d;           /* (6 x n) VᵀM D_ij X, (00 11 22 01 02 12), t mm */
  double* S;           /* (6 x n x n) VᵀM D_ij V, t */
  /* chamber follower pressures: face f of the FE mesh carries chamber face_ch[f]'s pressure
   * (0..11, segment-major as robot_leg.h's actuate; -1: none); nface faces */
  int nface;
  int* face_ch;
  /* contact at the sole (csr_romModelSetSole; contact NULL: the leg touches nothing) */
  const cscSoftModel* contact; /* borrowed: one foot shape against the terrain */
  int nz;              /* its friction history length (doubles, integrated in y) */
  int nsole;           /* the sole's nodes */
  double Xs[3];        /* their centroid at rest, hip frame, mm */
  double Rs0[9];       /* the sole's frame at rest in the hip frame (columns e1 e2 in the sole,
                          e3 its outward normal), row-major */
  double* Us;          /* (3 x n) the centroid's displacement per unit q, mm */
  double* Ws;          /* (3 x n) the sole's rotation vector per unit q, rad */
} csrRomModel;

/* Build the model on `rom` (borrowed). face_ch (nface, copied) maps the mesh's faces to the
 * twelve chambers (NULL: no pressure loads). Computes the consistent mass operators (one pass
 * over the Tet10s, O(ntet (30 n² + ...))) and K_r(0). NULL and err on failure. */
csrRomModel* csr_romModelCreate(const csfRom* rom, const csrRomParams* par, const int* face_ch,
                                csError* err);
void csr_romModelDestroy(csrRomModel* m);

/* Contact at the sole (issue 34, item 3): the sole is the foot shape of `contact` (borrowed,
 * exactly one shape, a CSC_SHAPE_FOOT, integrated history; the terrain is the model's), its
 * pose carried by the `nsole` mesh nodes `sole` (the tip face's, copied into the operators):
 *   centre   x0 = x_h + R (X̄ + Ū q),        Ū = mean over the sole nodes of V's rows,
 *   frame    R_f = R exp(θ) Rs0,  θ = W q,   W = J⁻¹ Σ_a r_a × V_a,  J = Σ_a (|r_a|² 1 - r_a r_aᵀ),
 * r_a = X_a - X̄: θ is the least-squares rotation of the sole's nodes (exact for a rigid
 * rotation of the sole to first order; its virtual work is that of the nodal forces
 * f_a = (J⁻¹ m) × r_a, which have the couple m). The foot's load (f0 at x0, couple m, world)
 * enters the reduced equations as Ūᵀ Rᵀ f0 + Wᵀ Rᵀ m; its history z rides in y after the moment
 * impulse, with the force's impulse (for the base wrench). Rs0: the sole's frame at rest (hip
 * frame, row-major, orthonormal, e3 out of the leg). CS_ERR_ARG / CS_ERR_RANGE on a bad shape,
 * fewer than three nodes or nodes on a line. Call before creating data. */
csStatus csr_romModelSetSole(csrRomModel* m, const cscSoftModel* contact, int nsole,
                             const int* sole, const double Rs0[9], csError* err);

/* The sole's pose and load at one state (used inside the integration; exposed for tests): the
 * hip frame R, hip point x_h and velocity v_h (world), ω (hip frame, rad/s), q, q' (n) and the
 * history z (nz). Fills Fc (n, the reduced contact force, N per unit q, added to the right-hand
 * side), zdot (nz), and if not NULL the foot's load (world, f0 at the foot centre x0, couple
 * about it) and the slot report. Returns csc_softCompute's code (> 0 recoverable). */
int csr_romSoleLoad(const csrRomModel* m, const double R[9], const double xh[3],
                    const double vh[3], const double w[3], const double* q, const double* qd,
                    const double* z, double* Fc, double* zdot, cscShapeLoad* load, double x0[3],
                    cscSlotInfo* slot);

/* The sole's load at one state as csr_romSoleLoad gives it, L = (f0, m) (world, the couple about
 * the foot's centre) and zdot (nz), with its derivatives G ((6 + nz) x (2n + nz), row-major):
 * rows f0, m, z', columns q, q', z. The law's part by central differences in the foot's twelve
 * coordinates (centre, world rotation vector of its frame, their rates) and in z (2 (12 + nz)
 * law calls); the pose's dependence on q, q' analytic (x0 = x_h + R (X̄ + Ū q), the frame
 * R exp(W q) Rs0 through the left Jacobian of SO(3), v0 = v_h + R (ω × x̄ + Ū q'),
 * ω_f = R (ω + W q')). The reduced force's derivatives are [Ūᵀ Rᵀ, Wᵀ Rᵀ] times G's first six
 * rows (the integration's Jacobian, robot_rom.c). work: csr_romSoleWorkSize(m) doubles.
 * Returns csc_softCompute's code (> 0 recoverable). */
int csr_romSoleWorkSize(const csrRomModel* m);
int csr_romSoleJacobian(const csrRomModel* m, const double R[9], const double xh[3],
                        const double vh[3], const double w[3], const double* q,
                        const double* qd, const double* z, double L[6], double* zdot,
                        double* G, double* work);

/* The data of one leg: the state y = [q (n), q' (n)], its time, the hip state the last step
 * ended at, the pressures of the step, CVODE and scratch. */
typedef struct csrRomData_ csrRomData;

csrRomData* csr_romDataCreate(const csrRomModel* m, csError* err);
void csr_romDataDestroy(csrRomData* d); /* NULL-safe */

/* At rest, undeformed, vented, at time t with the hip at b. */
void csr_romReset(const csrRomModel* m, csrRomData* d, double t, const csrBaseState* b);

/* The pressures of the coming step (MPa, p[4 s + j] segment s chamber j), linear from p0 at t0
 * to p1 at t1 (held outside [t0, t1]). */
void csr_romActuate(csrRomData* d, double t0, const double p0[12], double t1,
                    const double p1[12]);

/* A dead load fixed in the hip frame, as reduced forces fr (n, N per unit q: csf_romProject of a
 * nodal force); NULL: none. Copied. */
void csr_romSetDeadLoad(const csrRomModel* m, csrRomData* d, const double* fr);

/* Advance from t to t + H with the hip moving from b0 to b1 (see the base motion above); *w
 * (may be NULL) gets the base wrench averaged over the step. CVODE carries its history (order,
 * step size, Jacobian) from one advance to the next, as the rod's does; it restarts from the
 * state after create, reset, set and a failed step, and when t is not where the last advance
 * ended or the hip jumped (> 0.1 mm, > 1e-3 rad), and retries a continued step that failed
 * once from the state (a kink of the hip's acceleration at the step's start that the history
 * cannot cross at a tight tolerance): two restores of one state step bit for bit alike (a
 * restart costs a first-order start and a Jacobian). 0, > 0 recoverable (CVODE's error test or
 * Newton failed; the state is unchanged), < 0 fatal (err says why). */
int csr_romAdvance(const csrRomModel* m, csrRomData* d, double t, double H,
                   const csrBaseState* b0, const csrBaseState* b1, csrWrench* w, csError* err);

/* The leg's linear momentum P (t mm/s) and angular momentum L about the hip point (t mm²/s),
 * world frame, at the current state and hip state. */
void csr_romMomentum(const csrRomModel* m, const csrRomData* d, double P[3], double L[3]);

/* The current q and q' (n each; pointers into the data, valid for its lifetime). */
const double* csr_romQ(const csrRomData* d);
const double* csr_romQdot(const csrRomData* d);
double csr_romTime(const csrRomData* d);

/* The sole's friction history (nz doubles, pointer into the data; NULL without contact). */
const double* csr_romZ(const csrRomData* d);

/* The whole state as a flat vector (doubles): time, y (2n), the hip state (18), the pressures'
 * t0, t1, p0 (12), p1 (12), the sole's history (nz). setState returns < 0 (data unchanged) on a non-finite entry. */
int csr_romStateSize(const csrRomModel* m);
void csr_romGetState(const csrRomModel* m, const csrRomData* d, double* x);
int csr_romSetState(const csrRomModel* m, csrRomData* d, const double* x);

/* CVODE's counters summed over the data's life: steps, right-hand sides, Jacobians, restarts
 * (the retries of failed continued steps included). */
void csr_romStats(const csrRomData* d, long* steps, long* rhs, long* jacs, long* restarts);

/* The integration's counters summed over the data's life (CVODE's own summed across its
 * restarts), to see where a step's cost goes: rhs counts the reduced evaluations without the
 * tangent (0.0142 s each on the real leg's b10 file), tangents those with it (0.128 s), sole the
 * sole's contact-law calls (2 (12 + nz) + 1 per Jacobian: csr_romSoleJacobian). */
typedef struct csrRomStats_ {
  long steps;       /* CVODE's accepted internal steps */
  long rhs;         /* right-hand sides (reduced evaluations without the tangent) */
  long jacs;        /* Jacobians */
  long tangents;    /* reduced evaluations with the tangent (jacs less the lagged ones) */
  long lin_setups;  /* CVODE's linear solver set-ups (a new LU of I - γJ) */
  long nl_iters;    /* Newton iterations */
  long nl_fails;    /* Newton convergence failures */
  long err_fails;   /* local error test failures */
  long restarts;    /* CVODE restarts (order 1, new Jacobian), retries included */
  long retries;     /* continued steps that failed and were redone from a restart */
  long sole;        /* the sole's contact-law calls */
} csrRomStats;

void csr_romGetStats(const csrRomData* d, csrRomStats* s);

/* The same for a leg of the `rom` level (csr_leg_rom; robot_rom_leg.c), e.g. cs_leg(d, k) of a
 * run with --legs rom. Only for legs of that level. */
void csr_romLegStats(const csrLeg* leg, csrRomStats* s);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_ROM_H */

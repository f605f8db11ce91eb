/* robot_rod_internal.h: INTERNAL to robot_rod_*.c (not a public header). The model and data
 * layouts of the Cosserat-rod leg, the rotation helpers the three layers share, and the force
 * kernel's interface.
 *
 * Index conventions (robot_rod.h): nodes 0..N, frames 0..N where frame 0 is the base (clamp)
 * frame and frame e the material frame of element e = 1..N (between nodes e-1 and e). The
 * kernel works on unpacked arrays of N + 1 rows so that the base is just row 0. */
#ifndef CS_ROBOT_ROD_INTERNAL_H
#define CS_ROBOT_ROD_INTERNAL_H

#include <math.h>

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_linearsolver.h>
#include <sundials/sundials_matrix.h>

#include "core_math.h"
#include "robot_rod.h"

/* state block of one element: x(3) q(4) v(3) ω(3) hist(nhist) */
#define CSR_ROD_BX 0
#define CSR_ROD_BQ 3
#define CSR_ROD_BV 7
#define CSR_ROD_BW 10
#define CSR_ROD_BH 13
/* the CVODE vector holds the base impulse (force 3, moment 3) in front of the leg state */
#define CSR_ROD_NIMP 6

struct csrRodModel_ {
  csrRodParams par;
  csrActuator act;
  int has_act;
  const csrBendMap* map;
  const csrRodCalibration* calib;
  csrRodContact contact;
  int npiece;
  csrRodPiece piece[CSR_ROD_MAX_PIECES];
  int N;          /* elements */
  int* boff;      /* (N + 2) offset of element e's block in the state; boff[N + 1] = nstate */
  int* nh;        /* (N + 1) history variables of element e (index 0 unused) */
  int nhmax;      /* the largest of them */
  int nstate;     /* doubles in the state */
  double L;       /* rest length (mm) */
  double seg_len[CSR_NSEG]; /* rest length of the pieces of each actuated segment (mm) */
  double* s;      /* (N + 1) rest arc length of the nodes (mm) */
  double* l;      /* (N + 1) rest length of element e at index e (index 0 unused) (mm) */
  int* ep;        /* (N + 1) piece of element e (index 0 unused) */
  double* mnode;  /* (N + 1) lumped node masses (t) */
  double* Jel;    /* ((N + 1) x 3) element rotary inertia about d1, d2, d3 (t mm^2) */
  double mass;    /* total (t) */
  double hip[3], frame[9];
  double gravity[3]; /* acting on the legs (zero under `paper` conditions), mm/s^2 */
};

/* the loads and material state the kernel evaluates at one instant */
typedef struct csrRodLoads_ {
  double u0[CSR_ROD_MAX_PIECES][3];     /* intrinsic Darboux vector per piece (1/mm) */
  double sigma0[CSR_ROD_MAX_PIECES][3]; /* intrinsic shear/stretch per piece (-) */
  double Sd[CSR_ROD_MAX_PIECES][3];     /* shear/axial stiffness (GA1, GA2, EA) (N) */
  double B[CSR_ROD_MAX_PIECES][3];      /* bending/torsion stiffness (EI1, EI2, GJ) (N mm^2) */
  double gravity[3];                    /* mm/s^2 */
  double tip_force[3], tip_moment[3];   /* N, N mm, world */
  double damping;                       /* Kelvin-Voigt time (s); 0 in statics */
  int contact;                          /* 1: call the contact hook */
} csrRodLoads;

/* unpacked configuration and the kernel's outputs, rows 0..N (scratch in the data) */
typedef struct csrRodWork_ {
  double* x;  /* (N + 1) x 3 node positions (mm) */
  double* q;  /* (N + 1) x 4 unit quaternions of the frames */
  double* R;  /* (N + 1) x 9 their matrices */
  double* v;  /* (N + 1) x 3 node velocities (mm/s) */
  double* w;  /* (N + 1) x 3 body angular velocities (rad/s) */
  double* F;  /* (N + 1) x 3 node forces (N, world); row 0 = on the hip node */
  double* T;  /* (N + 1) x 3 frame torques (N mm, body frames); row 0 = on the base frame */
  double* m_node; /* (N + 1) x 3: elastic moment at node i (N mm, frame i's material axes);
                     row N: the tip moment in frame N */
  const double* hist; /* a state vector whose blocks hold the history (may be NULL) */
  double* dhist;      /* where the history rates go (may be NULL) */
  double elastic;     /* elastic energy (N mm), when requested */
  int last;           /* elements 1..last are unpacked and evaluated (N: the whole rod) */
} csrRodWork;

/* a block-tridiagonal matrix of n rows of 6 x 6 blocks (row-major blocks): B_i below, D_i on,
 * C_i above the diagonal; csr_rodBtFactor_ overwrites D with the inverses of the eliminated
 * diagonal blocks and C with D⁻¹C */
typedef struct csrRodBt_ {
  int n;
  double* B; /* (n x 36), B_0 unused */
  double* D; /* (n x 36) */
  double* C; /* (n x 36), C_{n-1} unused */
  int* piv;  /* (n x 6), unused (kept for a pivoted LU variant) */
} csrRodBt;

/* actuation of a macro step: strains at both ends, linear in time in between */
typedef struct csrRodActState_ {
  double ta, tb;
  csrRodSegmentActuation a[CSR_NSEG], b[CSR_NSEG];
  double pa[12], pb[12];
  int set;
} csrRodActState;

/* remembered evaluations of one segment's actuation (a ring): a gait repeats its pressure
 * samples from cycle to cycle, and a calibration evaluation costs a Newton solve (~30 µs) */
#define CSR_ROD_MEMO 64
typedef struct csrRodActMemo_ {
  double p[CSR_ROD_MEMO][CSR_NCHAMBER];
  csrRodSegmentActuation a[CSR_ROD_MEMO];
  int n, next;
} csrRodActMemo;

/* a segment's actuation along one chamber pattern (the chambers inflated together at equal
 * pressure, as every shipped gait does): the calibration evaluated lazily at levels k dP and
 * interpolated linearly (robot_rod_dyn.c actuationAt). Under the pneumatic lag the pressures
 * change at every macro step, so the ring memo above misses and each step costs the
 * calibration's Newton solve per segment and end: 19 % of the flat-road run. */
#define CSR_ROD_TAB_DP 5e-3  /* MPa between table levels */
#define CSR_ROD_TAB_N 201    /* levels 0 .. 1 MPa (gait CSVs stop at 1 MPa) */
#define CSR_ROD_TAB_SLOTS 4  /* patterns kept per segment (round robin) */
typedef struct csrRodActTable_ {
  int mask[CSR_ROD_TAB_SLOTS];             /* chambers of the pattern (bit j: Ω(j+1)); 0 free */
  int next;
  unsigned char known[CSR_ROD_TAB_SLOTS][CSR_ROD_TAB_N];
  csrRodSegmentActuation a[CSR_ROD_TAB_SLOTS][CSR_ROD_TAB_N];
} csrRodActTable;

/* a segment's actuation with two chamber groups at two levels (x, y), the pressures of every
 * pattern change under the pneumatic lag (one group venting while the other fills: 103 000 of
 * the 9 s flat road's 216 000 segment evaluations were of this kind, each the calibration's
 * Newton solve, 20 % of the run): the calibration at grid nodes (i dP, j dP), evaluated lazily,
 * interpolated linearly on the two triangles of each cell split along x = y (robot_rod_dyn.c
 * actuationAt2). The nodes live in a hash of fixed capacity (cleared when full). */
#define CSR_ROD_TAB2_CAP 2048 /* nodes per segment (a power of two); the flat road visits ~250 */
typedef struct csrRodActTable2_ {
  unsigned long long key[CSR_ROD_TAB2_CAP]; /* (maskA, maskB, i, j) + 1; 0 = empty */
  int n;                                    /* nodes stored */
  csrRodSegmentActuation a[CSR_ROD_TAB2_CAP];
} csrRodActTable2;

/* the lazily filled tables of one leg actuator's calibration, per segment: a memo of a pure
 * function of (actuator, calibration, segment, pressures), so legs of one actuator and
 * calibration may share one (robot_rod.h csr_rodActCacheCreate) */
struct csrRodActCache_ {
  csrRodActTable table[CSR_NSEG];
  csrRodActTable2 table2[CSR_NSEG];
};

/* base motion over a macro step: cubic Hermite in position and in the rotation vector */
typedef struct csrRodBaseMotion_ {
  double ta, H;
  csrBaseState a, b;
  double qa[4];      /* base quaternion at ta */
  double Phi[3];     /* rotation vector from frame a to frame b, in frame a */
  double dphi0[3];   /* H × body angular velocity at ta (frame a) */
  double dphi1[3];   /* H × J_r(Φ)^-1 × body angular velocity at tb */
  int moving;        /* 0: base at rest at a for all t */
} csrRodBaseMotion;

struct csrRodData_ {
  const csrRodModel* m;
  double t;          /* time of the state (s) */
  double* y;         /* the CVODE vector's data: NIMP impulse then the state */
  double* backup;    /* (NIMP + nstate) copy taken before each advance */
  csrRodWork wk;
  csrRodActState act;
  csrRodActMemo memo[CSR_NSEG];
  csrRodActCache* cache;  /* the calibration's tables: own_cache, or one shared by the legs of
                             a robot (csr_rodDataUseCache) */
  csrRodActCache* own_cache;
  csrRodBaseMotion base;
  csrBaseState cur_base; /* the base at time t */
  double tip_force[3], tip_moment[3];
  double imp0[CSR_ROD_NIMP]; /* the impulse at the current advance's start (error weights) */
  double imp_atol;           /* its absolute tolerance in this advance (N s) */
  int need_reinit;   /* 1: the next advance restarts CVODE */
  int no_contact;    /* 1: the right-hand side leaves the contact hook out (Jacobian's
                        internal part) */
  int started;       /* CVODE initialised at least once */
  int cb_status;     /* last non-zero return of a callback inside the RHS */
  char cb_msg[400];  /* and what it was */
  /* statics: the load the current state is in equilibrium with */
  int static_valid;
  csrRodStaticLoad static_load;
  csrRodSegmentActuation static_act[CSR_NSEG];
  /* SUNDIALS */
  SUNContext sun;
  void* cvode;
  N_Vector yv, atol;
  SUNMatrix A;        /* a shell: the system lives in the fields below (robot_rod_linsol.c) */
  SUNLinearSolver LS; /* the reduced block-tridiagonal solver */
  double* jac;        /* (N x 3) Jacobian blocks of (u̇, ḣ) by (x, ψ, v, ω, h): int + con */
  double* jac_int;    /* the same without the contact hook (internal forces, gravity) */
  double* jac_con;    /* the contact hook's part */
  double* con_y;      /* (NIMP + nstate) scratch state for the hook's differences */
  long jac_int_step;  /* CVODE step of the last internal Jacobian (-1: none) */
  long jac_last_step; /* CVODE step of the last Jacobian request */
  double* ls_q;       /* (N x 4) normalised quaternions at the last linear-system state */
  double* ls_qn;      /* (N) their norms */
  double* ls_den;     /* (N) 1 / (1 + γ²|ω|²/4) at the last setup's γ */
  double* ls_w;       /* (N x 3) body angular velocities there */
  int* ls_hact;       /* (N) 1: element's history couples to the motion (in contact) */
  double* ls_bpsi;    /* (N x 3) scratch */
  double* ls_r;       /* (N x 6) scratch: reduced right-hand side and solution */
  double* ls_hb;      /* (N x nhist) scratch */
  double* ls_Mhinv;   /* (N x nhist²) (I - γ ∂ḣ/∂h)⁻¹ */
  double ls_gamma;
  int ls_have_jac;
  long ls_last;
  csrRodBt bt_dyn;    /* the reduced Newton matrix of the implicit step */
  csrRodBt bt_gain;   /* the same at the condensed gains' step (csr_rodCondensedHip_) */
  double* gain_Mhinv; /* (N x nhist²) its history blocks */
  double* gain_r;     /* (N x 6) scratch of its solves */
  long jac_version;   /* counts the Jacobians CVODE had computed */
  double gain_K[36], gain_C[36]; /* the last condensed gains, */
  long gain_version;  /* ... of that Jacobian */
  double gain_g;      /* ... and step */
  int gain_valid;
  /* static solver: block-tridiagonal system of 6N unknowns */
  csrRodBt bt_static;
  double* sres;   /* (6N) residual */
  double* sres2;  /* (6N) perturbed residual */
  double* sdel;   /* (6N) Newton update */
  double* sy;     /* (nstate) trial state */
  double* sy0;    /* (nstate) state at the start of a load step */
  csrRodStats stats;
};

/* ---- rotation helpers (quaternions (w, x, y, z), rotation vectors) --------------------------- */

/* r = a ⊗ b (r must not alias) */
static inline void csr_rodQmul(double r[4], const double a[4], const double b[4]) {
  r[0] = a[0] * b[0] - a[1] * b[1] - a[2] * b[2] - a[3] * b[3];
  r[1] = a[0] * b[1] + a[1] * b[0] + a[2] * b[3] - a[3] * b[2];
  r[2] = a[0] * b[2] - a[1] * b[3] + a[2] * b[0] + a[3] * b[1];
  r[3] = a[0] * b[3] + a[1] * b[2] - a[2] * b[1] + a[3] * b[0];
}

/* r = conj(a) ⊗ b (r must not alias) */
static inline void csr_rodQmulConj(double r[4], const double a[4], const double b[4]) {
  const double c[4] = {a[0], -a[1], -a[2], -a[3]};
  csr_rodQmul(r, c, b);
}

/* quaternion of the rotation by the rotation vector phi (exact; series below 1e-4 rad where
 * the truncation is below 1e-18) */
static inline void csr_rodQexp(double q[4], const double phi[3]) {
  double th = csu_norm3(phi);
  double c, k;
  if (th < 1e-4) {
    c = 1 - th * th / 8;
    k = 0.5 - th * th / 48;
  } else {
    c = cos(0.5 * th);
    k = sin(0.5 * th) / th;
  }
  q[0] = c;
  q[1] = k * phi[0];
  q[2] = k * phi[1];
  q[3] = k * phi[2];
}

/* rotation vector of a unit quaternion, |phi| <= π (the shorter way) */
static inline void csr_rodQlog(double phi[3], const double q[4]) {
  double w = q[0], sgn = 1;
  if (w < 0) {
    w = -w;
    sgn = -1;
  }
  double s = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  /* θ/s = 2 atan2(s, w)/s; for s -> 0: 2/w (1 - s²/(3w²)) */
  double k = (s < 1e-8) ? 2.0 / w : 2.0 * atan2(s, w) / s;
  phi[0] = sgn * k * q[1];
  phi[1] = sgn * k * q[2];
  phi[2] = sgn * k * q[3];
}

/* normalise in place; returns the old norm */
static inline double csr_rodQnormalize(double q[4]) {
  double n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n > 0) {
    for (int k = 0; k < 4; k++) {
      q[k] /= n;
    }
  }
  return n;
}

/* r = Rᵀ a for row-major R (r must not alias a) */
static inline void csr_rodMulMatTVec(double r[3], const double R[9], const double a[3]) {
  r[0] = R[0] * a[0] + R[3] * a[1] + R[6] * a[2];
  r[1] = R[1] * a[0] + R[4] * a[1] + R[7] * a[2];
  r[2] = R[2] * a[0] + R[5] * a[1] + R[8] * a[2];
}

/* coefficient c(θ) of [θ]² in the inverse right Jacobian J_r^-1 = I + ½[θ] + c [θ]²,
 * c = 1/θ² - (1 + cos θ)/(2 θ sin θ); series 1/12 + θ²/720 + θ⁴/30240 below 1e-2 rad
 * (truncation < 1e-15 relative) */
static inline double csr_rodJrInvCoeff(double th) {
  if (th < 1e-2) {
    double t2 = th * th;
    return 1.0 / 12 + t2 / 720 + t2 * t2 / 30240;
  }
  return 1.0 / (th * th) - (1 + cos(th)) / (2 * th * sin(th));
}

/* the same with c = csr_rodJrInvCoeff(|θ|) given (one node applies both J_r^-1 and J_r^-T) */
static inline void csr_rodJrInvWith(double r[3], double c, const double th[3], const double a[3],
                                    double sgn) {
  double ta[3], tta[3];
  csu_cross3(ta, th, a);
  csu_cross3(tta, th, ta);
  for (int k = 0; k < 3; k++) {
    r[k] = a[k] + sgn * 0.5 * ta[k] + c * tta[k];
  }
}

/* r = J_r^-1(θ) a (sgn = +1) or J_r^-T(θ) a (sgn = -1); r must not alias a */
static inline void csr_rodJrInv(double r[3], const double th[3], const double a[3], double sgn) {
  double c = csr_rodJrInvCoeff(csu_norm3(th));
  double ta[3], tta[3];
  csu_cross3(ta, th, a);
  csu_cross3(tta, th, ta);
  for (int k = 0; k < 3; k++) {
    r[k] = a[k] + sgn * 0.5 * ta[k] + c * tta[k];
  }
}

/* r = J_r(θ) a = a - (1 - cos θ)/θ² θ×a + (θ - sin θ)/θ³ θ×(θ×a) (series below 1e-3 rad) */
static inline void csr_rodJr(double r[3], const double th[3], const double a[3]) {
  double t = csu_norm3(th), c1, c2;
  if (t < 1e-3) {
    c1 = 0.5 - t * t / 24;
    c2 = 1.0 / 6 - t * t / 120;
  } else {
    c1 = (1 - cos(t)) / (t * t);
    c2 = (t - sin(t)) / (t * t * t);
  }
  double ta[3], tta[3];
  csu_cross3(ta, th, a);
  csu_cross3(tta, th, ta);
  for (int k = 0; k < 3; k++) {
    r[k] = a[k] - c1 * ta[k] + c2 * tta[k];
  }
}

/* ---- shared between the layers ------------------------------------------------------------- */

/* Actuation of segment seg at pressures p through the model's calibration (or map); zero
 * strains when the model has none. */
int csr_rodActuationEval_(const csrRodModel* m, int seg, const double p[4],
                          csrRodSegmentActuation* out, char* msg, size_t msg_size);

/* Fill ld's per-piece strains and stiffness from segment actuations act[3] (NULL: none). */
void csr_rodLoadsFromActuation_(const csrRodModel* m, const csrRodSegmentActuation* act,
                                csrRodLoads* ld);

/* Unpack a state vector (N blocks) into wk rows 1..N (normalising quaternions) with the base
 * (x0, q0, v0, w0 body) in row 0. Returns 0, or 1 if the state is not finite or a quaternion
 * is degenerate (recoverable: CVODE cuts the step). */
int csr_rodUnpack_(const csrRodModel* m, csrRodWork* wk, const double* state, const double x0[3],
                   const double q0[4], const double v0[3], const double w0[3]);
/* The same for elements 1..last only; the kernel then evaluates only the terms they carry:
 * with last = 1 the forces on the hip node and base frame (the wrench) are exact. */
int csr_rodUnpackPart_(const csrRodModel* m, csrRodWork* wk, const double* state, int last,
                       const double x0[3], const double q0[4], const double v0[3],
                       const double w0[3]);

/* The force kernel: node forces wk->F and frame torques wk->T (body) of the unpacked
 * configuration under ld: internal elastic + Kelvin-Voigt forces, gravity on every node
 * (including the hip node 0), tip load, contact; history rates to wk->dhist when ld->contact.
 * want_energy: also wk->elastic. Returns 0, or the contact hook's non-zero code (its message
 * in msg). */
int csr_rodForces_(const csrRodModel* m, csrRodWork* wk, const csrRodLoads* ld, int want_energy,
                   char* msg, size_t msg_size);

/* Frame of node i (world, quaternion): frame i carried by the part of the node's relative
 * rotation that lies in element i (intrinsic + elastic share by compliance). Needs the
 * kernel's wk->m_node from the last call. */
void csr_rodNodeFrame_(const csrRodModel* m, const csrRodWork* wk, const csrRodLoads* ld, int i,
                       double q[4]);

/* The base position and velocity at time t of the current macro step (robot_rod_dyn.c). */
void csr_rodBaseAt_(const csrRodData* d, double t, double x[3], double v[3]);

/* Contact accelerations of element e's shape at a state vector (robot_rod_model.c): out =
 * [Δv̇ of node e-1 (3; 0 for e = 1), Δv̇ of node e (3), Δω̇ of frame e (3), ḣ_e (nh_e)];
 * x0, v0: the hip node for e = 1. Returns the hook's code. *active: the hook gave a force or
 * couple. */
int csr_rodContactAccel_(const csrRodModel* m, const double* state, int e, const double x0[3],
                         const double v0[3], double* out, int* active);

/* CVODE's right-hand side (robot_rod_dyn.c) over [impulse, state]; user = the csrRodData. */
int csr_rodRhs_(sunrealtype t, N_Vector y, N_Vector ydot, void* user);

/* The block-tridiagonal solver (robot_rod_linsol.c): 1 on success for Alloc, 0 on success for
 * Factor (1: a singular diagonal block); Solve overwrites x (6n) with the solution. */
int csr_rodBtAlloc_(csrRodBt* bt, int n);
void csr_rodBtFree_(csrRodBt* bt);
void csr_rodBtZero_(csrRodBt* bt);
int csr_rodBtFactor_(csrRodBt* bt);
void csr_rodBtSolve_(const csrRodBt* bt, double* x);

/* CVODE's linear system function (CVLsLinSysFn, robot_rod_linsol.c): stores γ and the
 * quaternions at y, new Jacobian blocks when CVODE asks for them (jok false); user = the data.
 * d->LS's setup then factors the reduced matrix, its solve applies (I - γJ)⁻¹. */
int csr_rodLinSys_(sunrealtype t, N_Vector y, N_Vector fy, SUNMatrix A, sunbooleantype jok,
                   sunbooleantype* jcur, sunrealtype gamma, void* user, N_Vector tmp1,
                   N_Vector tmp2, N_Vector tmp3);

/* The condensed response of element 1 to a load on it alone, over one implicit (backward
 * Euler) step of g: the reduced matrix S(g) = I - g ∂u̇/∂u - g² ∂u̇/∂(x, ψ) (- history) of the
 * stored Jacobian blocks is assembled and factored in the gains' storage and solved for ncol
 * right-hand sides rhs (ncol x 6, column-major: the 6 velocity-level rows of element 1, zero
 * elsewhere); out (ncol x 6) gets element 1's (δv, δω) of each. The rest of the rod (its
 * inertia, damping, stiffness, contact) is eliminated exactly by the block LU. 0 ok; 1 when no
 * Jacobian is stored yet or a block is singular (out untouched). */
#define CSR_ROD_GAIN_COLS 12
int csr_rodCondensedHip_(csrRodData* d, double g, const double* rhs, int ncol, double* out);
/* The position map of element j's rotation at step g: δψ = g W δω (robot_rod_linsol.c). */
void csr_rodKinW_(const csrRodData* d, double g, int j, double W[9]);

/* Attach the reduced linear solver to d->cvode (0 ok); free its arrays. */
int csr_rodLinsolAttach_(csrRodData* d);
void csr_rodLinsolFree_(csrRodData* d);

/* The actuation interpolated between two (robot_rod_act.c): out = (1 - u) a + u b, u in [0, 1]. */
void csr_rodActuationLerp_(const csrRodSegmentActuation* a, const csrRodSegmentActuation* b,
                           double u, csrRodSegmentActuation* out);

/* Rest state vector (straight along the frame's e3 from the hip, at rest). */
void csr_rodRestState_(const csrRodModel* m, double* state);

#endif /* CS_ROBOT_ROD_INTERNAL_H */

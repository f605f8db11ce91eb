/* robot_strain_internal.h: INTERNAL to robot_strain*.c and their tests (not a public header).
 * The model and data layouts of the strain-coordinate leg (robot_strain.h) and the SE(3)
 * helpers of robot_strain_lie.c.
 *
 * Twists and wrenches are 6-vectors with the angular part first, (ω; v) and (m; f); a pose is
 * (R (3 x 3 row-major), x (3)). ad(ξ) = [ω^ 0; v^ ω^] (6 x 6 row-major). */
#ifndef CS_ROBOT_STRAIN_INTERNAL_H
#define CS_ROBOT_STRAIN_INTERNAL_H

#include "robot_rod.h"
#include "robot_strain.h"

/* strain components of ξ - ξ*: bending about d1, d2, twist, shear along d1, d2, stretch */
/* the most history doubles of one contact shape (a 5 x 5 point foot in step mode: 100) */
#define CSR_STRAIN_MAX_SHAPE_HIST 100
/* the most unknowns of one piece: 6 components of MAX_ORDER + 1 modes */
#define CSR_STRAIN_MAX_PIECE_DOF (6 * (CSR_STRAIN_MAX_ORDER + 1))

enum { CSR_STRAIN_K1 = 0, CSR_STRAIN_K2, CSR_STRAIN_TW, CSR_STRAIN_S1, CSR_STRAIN_S2,
       CSR_STRAIN_S3 };

/* One contact shape's last linearisation in the step's Newton passes (the active set,
 * robot_strain_contact.c): the shape's state y there (pose and rates, world), its load L, and
 * K_y = ∂L/∂y, C_y = ∂L/∂ẏ (6 x 6 row-major, the coordinates of the linearisation's
 * differences). Out of contact at an iterate, the shape's "ghost" load is the affine
 * L + K_y (y_it - y) + C_y (ẏ_it - ẏ). */
typedef struct csrStrainGhost_ {
  cscShapeState y;
  double L[6], K[36], C[36];
  unsigned char state; /* 0: not touching at any linearisation of this step; 1: touching at its
                          last one (L, K, C valid); 2: released (csr_strainRelease) */
  unsigned char on;    /* 1: held by its ghost load at the last evaluation */
} csrStrainGhost;

/* One contact shape's last evaluation of the law (robot_strain_shape.c csr_strainShapeLoad_):
 * the law is a function of the shape's state and its history block alone, so an evaluation at
 * the same bits (the output's read-out after a commit, the next prepare at the committed
 * state, an iterate that linearises afresh after reading its loads) returns these. A cache, not state: keyed by
 * the bits of st and of the history (csrStrainData.memo_z), it cannot change a result. */
typedef struct csrStrainLoadMemo_ {
  int valid;          /* 1: st, ld, rep and the slots are an evaluation's */
  int rc;             /* its return code */
  cscShapeState st;   /* the state it was evaluated at */
  cscShapeLoad ld;    /* the law's load there */
  cscSoftReport rep;  /* this shape's part of a report */
} csrStrainLoadMemo;

struct csrStrainModel_ {
  csrStrainParams par;
  csrRodParams rpar;
  int npiece;
  csrRodPiece piece[CSR_ROD_MAX_PIECES];
  int rigid[CSR_ROD_MAX_PIECES];
  int bord[CSR_ROD_MAX_PIECES];      /* bending order of piece k (-1: rigid) */
  int pmax;                          /* the highest Legendre order of any unknown */
  double X0[CSR_ROD_MAX_PIECES + 1]; /* rest arc length where piece k starts; X0[npiece] = L */
  int dof0[CSR_ROD_MAX_PIECES];      /* first unknown of piece k */
  int ndof[CSR_ROD_MAX_PIECES];      /* its unknowns (0: rigid) */
  int nsub[CSR_ROD_MAX_PIECES];      /* its Magnus sub-intervals (1 for a rigid piece) */
  int pt0[CSR_ROD_MAX_PIECES + 1];   /* its first quadrature point; pt0[npiece] = np - 1 */
  int* pcol;                         /* (np) the unknowns that move point p: its Jacobian's
                                        columns >= pcol[p] are zero */
  double* gleg;                      /* Legendre values P_0..P_pmax at the two Gauss points of
                                        every Zanna step of the kinematics (piece k,
                                        sub-interval i, the half step to the midpoint and the
                                        whole one): csr_strainLegendreAt_ */
  int gleg0[CSR_ROD_MAX_PIECES];     /* piece k's first sub-interval in gleg */
  int n;                             /* unknowns */
  int np;                            /* quadrature points: the ends and midpoints of every
                                        sub-interval (Simpson), shared at piece ends */
  int* dcomp;                        /* (n) strain component of unknown j (CSR_STRAIN_*) */
  int* dorder;                       /* (n) its Legendre order */
  int* dpiece;                       /* (n) its piece */
  double* dscale;                    /* (n) its size as a rotation or strain over its piece:
                                        the piece length for κ, τ modes, 1 for σ modes */
  double* Ms;                        /* (np x 6) Simpson weight x section mass per length
                                        (ρI1, ρI2, ρI3, ρA, ρA, ρA) summed at each point (t mm²,
                                        t) */
  cscSoftModel* soft;                /* leg-terrain contact (NULL: none), step-mode history */
  int nshape;                        /* its shapes: capsules, then the foot */
  int* shape_a;                      /* (nshape) quadrature point of a capsule's first end
                                        (the foot: the tip) */
  int* shape_b;                      /* (nshape) of its second end (the foot: the tip) */
  int nhist;                         /* the contact history's doubles */
  csrRodModel* rod;                  /* a one-element-per-piece nodal rod of the same pieces:
                                        the calibration path (csr_rodActuationEval_) */
  double hip[3], frame[9];
  double gravity[3];                 /* acting on the leg (zero when weightless) */
  double L, mass;
};

/* the lattice vertices of the interpolated calibration kept per segment (a cache) */
#define CSR_STRAIN_CAL_VERTS 32

/* The calibration's evaluations kept per segment (robot_strain_cal.c): the last exact
 * one (its pressures and what the calibration returned there) and, with a pressure lattice
 * (cal_quantum > 0), the last lattice vertices evaluated (their integer coordinates p / δ). A
 * cache, not state: the calibration is a function of the pressures alone (exact, or
 * interpolated on the lattice), so the same bits give the same result with or without it. */
typedef struct csrStrainCalMemo_ {
  int valid[CSR_NSEG];
  double p[CSR_NSEG][4];
  csrRodSegmentActuation act[CSR_NSEG];
  int nv[CSR_NSEG];                          /* vertices held (<= CSR_STRAIN_CAL_VERTS) */
  int vnext[CSR_NSEG];                       /* the next slot to replace (round robin) */
  long vkey[CSR_NSEG][CSR_STRAIN_CAL_VERTS][4];
  csrRodSegmentActuation vact[CSR_NSEG][CSR_STRAIN_CAL_VERTS];
} csrStrainCalMemo;

struct csrStrainData_ {
  double* q;      /* (n) generalised coordinates */
  double* Kd;     /* (n) diagonal of K at the current actuation */
  double* b;      /* (n) ∫ΦᵀC(ξ0 - ξ*) at the current actuation */
  double p[CSR_NSEG * CSR_NCHAMBER]; /* pressures of the current actuation (MPa) */
  csrStrainCalMemo cal; /* the calibration's last evaluation per segment (a cache) */
  long ncal;            /* segment evaluations of the calibration since creation (a count) */
  double tip_f[3], tip_m[3];         /* the last static load's tip force and moment */
  int grav;                          /* and whether its weight acted */
  double* eta;    /* (n) generalised velocities q̇ */
  double Rb[9], xb[3]; /* the base (hip) frame and position, world */
  double Vb[6];   /* the base's body twist (ω; v) in the hip frame (rad/s, mm/s) */
  /* kinematics at the quadrature points relative to the base, valid while kin_valid */
  double* R;      /* (np x 9) */
  double* x;      /* (np x 3) */
  double* J;      /* (np x 6 x n) body Jacobians */
  int kin_valid;  /* 0 not valid, 1 the poses (and the chain points' J if kin_chain), 2 every J */
  int kin_chain;  /* 1: the last kinematics with Jacobians formed them at the chain points at
                     least (want_J 1, 2 or 4; csr_strainChainJ_) */
  int kin_midown; /* 1 (with kin_valid 1): the last kinematics (want_J 4) also formed the
                     midpoints' own piece's columns L_p = J_p[:, dof0[k]..] (their earlier
                     columns are stale): what backward Euler's start by the recursion reads */
  double* Rs_save; /* (np x 9) scratch: the poses kept over a kinematics elsewhere */
  double* xs_save; /* (np x 3) */
  long kin_gen;   /* counts csr_strainKinematics_'s calls: R, x, J change only there */
  /* scratch of the static solver */
  double *Q, *Qp, *Qm, *A, *dq, *q_save, *q_start, *K1, *b1, *K0, *b0;
  int* piv;
  /* the prepared step (robot_strain_dyn.c) */
  double tipd_f[3], tipd_m[3]; /* the dynamics' tip load (world) */
  double* Wll;    /* (n x n) LU factor of W_ll (with piv) */
  double* Wlb;    /* (n x 6) W_lb = W_blᵀ */
  double* X;      /* (n x 6) W_ll⁻¹ W_lb */
  double* y;      /* (n) W_ll⁻¹ h r_l */
  double* rl;     /* (n) */
  double* Vp;     /* (np x 6) point twists */
  /* what csr_strainPointTwists_ last computed Vp from (kin_gen, Vb, η; vp_gen -1: nothing): the
   * same inputs give the same bits, so it is not done again (the output's contact read-out
   * after a step's commit, docs/notes/performance.md "Fixed costs") */
  long vp_gen;
  double vp_Vb[6];
  double* vp_eta; /* (n) */
  double* Vs;     /* (np x 6) scratch: the velocity products' twists */
  double* kst;    /* (np x CSR_STRAIN_KST) at each flexible chain step's end point: T(Ω)
                     (6 x 6) and ∂Ω/∂q (6 x nd), kept by the kinematics' want_J 5 */
  int kst_ok;     /* 1: kst holds the last kinematics' steps (want_J 5, at ks_q) */
  double* Fc;     /* (np x 6) scratch: a kept iterate's contact wrenches at the chain points
                     (csr_strainContactLoads_ without the chain Jacobians) */
  /* the kinematics' steps (csr_strainKinematics_, every point but the chain-only poses of want_J
   * 3): for each point p > 0 the step into it, exp(Ω) = (Re 9, pe 3) and θ², θ, sin θ, cos θ
   * (16 a point), which the velocity products reuse where ks_q is their q (ks_ok 1) */
  double* ks;
  double* ks_q; /* (n) */
  int ks_ok;
  double* Ab;     /* (np x 6) Ȧu at the points (the velocity-product accelerations) */
  double h;       /* the prepared step (s); 0: none prepared */
  double* Wbl;    /* (6 x n) W_bl (= W_lbᵀ without contact) */
  double Zp[36], rhop[6], Rbp[9]; /* the prepared Z, ρ and the base frame they are in */
  csrWrench wbase; /* the last finished step's base wrench (csr_strainBaseWrench) */
  /* the step's start and its constant part (robot_strain_dyn.c assembleStart) */
  double* q0;     /* (n) */
  double* eta0;   /* (n) */
  double Vb0[6];  /* the base's body twist at the start */
  double* WMll;   /* (n x n) inertia + (h τ_d + h²) K */
  double* WMlb;   /* (n x 6) */
  double WMbb[36];
  double* rMl;    /* (n) forces at the start, elastic and damping at the end */
  double rMb[6];
  double* du;     /* (6 + n) the iterate's Δu = (ΔV, Δη) */
  double X0m[3];  /* Σ m x of the leg at the step's start, world (t mm) */
  double Dm[3];   /* the leg's discrete linear momentum: Σ m x's change over the last step / h,
                     world (t mm/s; state) */
  double fcw[3];  /* the contact's force on the leg at the linearisation point, world (N) */
  int ntouch;     /* shapes the last contact assembly found touching */
  int lu_plain;   /* 1: d->Wll's factor, X and y are W_M's alone (no contact in them) */
  /* the iteration matrix kept over a step's Newton iterates (robot_strain_condense.c) */
  double* Wu;     /* (n x n) W_ll as factored, unfactored (with the contact's part) */
  double Wbbp[36]; /* W_bb as condensed */
  unsigned char* csig; /* (the contact's slots) their state where W was linearised: bit 0
                          touching, bit 1 past the friction's saturation */
  double* fl;     /* (n) scratch: the contact's generalised force at an iterate */
  double chg_last, chg_prev; /* the leg's last two iterate moves (csr_strainUpdateDamped) */
  int nreuse;     /* iterates in a row that kept the iteration matrix */
  /* the iteration matrix kept across steps (keep_matrix; robot_strain_dyn.c, Kept matrix) */
  double* R0;     /* (np x 9) the step's start kinematics: M(q0) Δu = Σ G_pᵀ M_p G_p Δu */
  double* x0;     /* (np x 3) */
  double* J0;     /* (np x 6 x n) */
  double* Mu;     /* (6 + n) scratch: M(q0) Δu */
  double* qf;     /* (n) q where the kept factor was linearised */
  double kf_h;    /* its step (s) */
  int kf;         /* 1: d->Wll, piv, X, Wu, Wlb, Wbl, Wbbp, Zp are a factorisation the next
                     step may keep */
  int chol;       /* 1: d->Wll holds a Cholesky factor (no contact in it), 0 an LU */
  int wm_step;    /* 1: d->WM* are this step's W_M (0: a kept step's prepare skipped them) */
  int art_pass;   /* 1: this pass's BDF2 assembly at the iterate left W_M out for the
                     recursion (articStep): condenseStart condenses it) */
  int w_lag;      /* 1: the factor is an earlier step's */
  long nfactor;   /* factorisations of W_ll since the data's creation (a count, not state) */
  long nstep;     /* prepared steps since then */
  long nkept;     /* of them, prepared on an earlier step's factor */
  int w_step;     /* 1: W_M, r_M and the factor are this step's (a linearly implicit BDF2's
                     prepare sets it after its full condensation) */
  /* BDF2 (step_order 2): the last step's start (state) and this step's coefficients */
  double* qm1;    /* (n) q at the last step's start */
  double* etam1;  /* (n) η there */
  double Vbm1[6]; /* the base's body twist there */
  double Xm1[3];  /* Σ m x there, world (t mm) */
  double Dm1[3];  /* D of the step before the last (t mm/s) */
  double hprev;   /* the last step's length (s); 0: none (the next is backward Euler) */
  double bc[3];   /* this step's coefficients (csr_strainBdf2Coeffs) */
  double he;      /* c[2] h: the implicit part's step (s) */
  /* the active set of the step's Newton passes (not state: reset by every prepare) */
  csrStrainGhost* ghost; /* (nshape) */
  int nghost;     /* shapes held by their ghost load at the last evaluation */
  int fresh;      /* 1: the next iterate linearises afresh (a ghost was released) */
  int ghost_hold; /* 1: BDF2's start records stand (csr_strainGhostStart_): the linearisations
                     until the step's first iterate do not replace them */
  int at_iterate; /* 1: the step was last linearised at a Newton iterate (csr_strainIterate),
                     0 at its start (prepare): csr_strainStepLimit limits only the former */
  double* z;      /* (nhist) contact anchors (state) */
  csrStrainLoadMemo* memo; /* (nshape) the law's last evaluation per shape (a cache) */
  double* memo_z;          /* (nhist) the history each shape's memo was evaluated with */
  cscSlotInfo* memo_slot;  /* (the contact's slots) their report at the memo */
  cscShapeState* sst; /* (nshape) scratch; in a prepare with pred set, every shape's pose at
                          the predicted end of the step (csr_strainPredictShapes_) */
  int pred;       /* 1: sst holds the predicted poses (backward Euler's prepare); 2: they
                     are wanted, formed at the first shape that touches */
  int wl_pending; /* 1: a step's start left Wll, Wlb, Wbl, rl uncleared (condenseStart): the
                     first shape that touches zeroes them first */
  double* Gs;     /* (22 x (6 + n)) scratch of the contact's linearisation and u0 */
  /* the stance legs' start by the articulated recursion (artic 2; robot_strain_artic.c) */
  int wc_sparse;  /* 1: the contact's start assembly leaves W_ll's block out and keeps each
                     touching shape's S and A (cS, cA) for the recursion */
  int nct;        /* touching shapes kept there */
  int* ct;        /* (nshape) their indices */
  double* cS;     /* (nshape x 6 x (6 + n)) their S (world rates of the shape's ends) */
  double* cA;     /* (nshape x 36) their A = h K_y + C_y: W -= h Sᵀ A S */
  /* the contact's force in the start's linear model (csr_strainContactAssemble_ at the step's
   * start, read by the one-pass carry, robot_strain_carry.c): world force = fcl + fcA Δu */
  double fcl[3];  /* Σ the touching shapes' affine load at the start (N, world) */
  double* fcA;    /* (3 x (6 + n)) Σ their force rows of A S */
  int fcl_ok;     /* 1: fcl, fcA are this step's start's (0: a kept matrix's loads, or none) */
  int art_f;      /* 1: the iteration matrix is factored piece by piece by the recursion (the
                     kept iterates solve through artLU ...; d->Wll, Wu are not formed) */
  double* artLU;  /* (n x MAX_PIECE_DOF) piece k's Z_ηη LU-factored, at MAX_PIECE_DOF dof0[k] */
  int* artPiv;    /* (n) its pivots, at dof0[k] */
  double* artZsn; /* (6 n) piece k's Z_sη (6 x nd, at 6 dof0[k]) */
  double* artY;   /* (n x 6) Z_ηη⁻¹ Z_ηs (rows of the piece's unknowns) */
  double* artL;   /* (6 n) L_e = J_e[:, own] (6 x nd, at 6 dof0[k]) at the factor's poses */
  double* artA;   /* (npiece x 36) each piece's Ad(g_se⁻¹) */
  int k0;         /* 1: d->R0, x0, J0 hold this step's start kinematics (a recursion's start
                     with contact swapped them there; an iterate that refactors reads them) */
  /* an iterate that refactors after such a start (robot_strain_woodbury.c): the start's
   * pieces' factor updated by the start's and the iterate's touching shapes */
  int wb_f;       /* 1: the iteration matrix is the Woodbury update of the start's recursion
                     (d->art* with cS, cA) by the iterate's shapes (wS, wA); d->Wll not formed */
  int nwt;        /* the iterate's touching shapes kept there */
  double* wS;     /* (nshape x 6 x (6 + n)) their S, as cS */
  double* wA;     /* (nshape x 36) their A, as cA */
  double* wbQ;    /* (n x 12 nshape) R U_lᵀ: the start's W_ll⁻¹ on each row of the stacked S_l
                     (column i the row i's) */
  double* wbK;    /* (12 nshape)² the capacitance I + C U_l R U_lᵀ, LU-factored (wbPiv), then
                     12 x 12 nshape of scratch */
  int* wbPiv;
  double* wbX;    /* (n x 6) the start's X = R W_lb (d->X is the update's) */
};

/* ---- calibration (robot_strain_cal.c) ---- */
/* rest strains (b) and stiffness (Kd) of every piece at pressures p (MPa, 12), exactly
 * (cal_quantum 0) or on the pressure lattice, through d's memo (d->cal); 0 or the calibration's
 * code with msg filled */
int csr_strainActuation_(const csrStrainModel* m, csrStrainData* d, const double p[12],
                         double* Kd, double* b, char* msg, size_t msg_size);

/* ---- SE(3) helpers (robot_strain_lie.c) ---------------------------------------------------- */

/* ad(ξ) (6 x 6) */
void csr_strainAd_(const double xi[6], double ad[36]);
/* y[j] = Σ_r g[r] B[r][j] (add 0) or y[j] += Σ_r g[r] B[r][j] (add 1) for j < len, r over the
 * six rows of B (leading dimension ld): each entry's terms added one at a time in r's order to
 * +0 or to y[j] (the bits of a six-term dot product, or of six axpy passes over y in r's order:
 * no contraction into fused multiply-adds, which the build does not ask for), vectorised over j
 * (y and B distinct). The inertia's, the contact's and the velocity products' row products */
static inline void csr_strainRows6_(double* restrict y, const double* restrict B, int ld,
                                    const double g[6], int len, int add) {
  const double g0 = g[0], g1 = g[1], g2 = g[2], g3 = g[3], g4 = g[4], g5 = g[5];
  const double *b0 = B, *b1 = B + ld, *b2 = B + 2 * ld, *b3 = B + 3 * ld, *b4 = B + 4 * ld,
               *b5 = B + 5 * ld;
  for (int j = 0; j < len; j++) {
    double t = add ? y[j] : 0;
    t += g0 * b0[j];
    t += g1 * b1[j];
    t += g2 * b2[j];
    t += g3 * b3[j];
    t += g4 * b4[j];
    t += g5 * b5[j];
    y[j] = t;
  }
}
/* the Legendre values at the Gauss points a, b (ab 0, 1) of piece k's sub-interval i, its half
 * step (whole 0: to the midpoint) or whole one (1), as csr_strainMagnus_ evaluates them for
 * s = i h, step whole ? h : h / 2 with h the piece's length over its sub-intervals (the same
 * bits: tabulated by csr_strainLegendreTable_) */
const double* csr_strainLegendreAt_(const csrStrainModel* m, int k, int i, int whole, int ab);
/* fills m->gleg (allocated by it); 0 ok, else out of memory */
int csr_strainLegendreTable_(csrStrainModel* m);
/* Ad(g⁻¹) = [Rᵀ 0; -Rᵀ x^ Rᵀ] (6 x 6) of the pose g = (R, x) */
void csr_strainAdInv_(const double R[9], const double x[3], double A[36]);
/* exp(Ω^) = (R, x) */
void csr_strainExp_(const double Om[6], double R[9], double x[3]);
/* T(Ω) = dexp(-Ω) = Σ_j (-ad Ω)^j / (j + 1)! (6 x 6), closed form (Selig's polynomial in ad of
 * degree 4) or, for |ω| small, the series */
void csr_strainTangent_(const double Om[6], double T[36]);
/* Legendre P_0..P_n at s in [-1, 1] */
void csr_strainLegendre_(int n, double s, double* P);
/* one Zanna step of length h from local arc length s (of flexible piece k, at q): Ω (6) and,
 * if dOm is not NULL, ∂Ω/∂q over the piece's unknowns (6 x ndof[k], row-major) */
void csr_strainMagnus_(const csrStrainModel* m, const double* q, int k, double s, double h,
                       double Om[6], double* dOm);
/* T(Ω) v without forming T (6) */
void csr_strainTangentApply_(const double Om[6], const double v[6], double out[6]);
/* the body twists V_p = G_p (V_b, η) of every quadrature point (np x 6) at q, by the twist
 * recursion V_{k+1} = Ad(exp(-Ω)) V_k + T(Ω) Ω̇ (the Jacobian recursion applied to one
 * velocity: no poses or Jacobians kept) */
void csr_strainTwists_(const csrStrainModel* m, const double* q, const double* eta,
                       const double Vb[6], double* V);
/* the same twists V (np x 6) and their rates along q, A_p = (∂V_p/∂q) η at fixed η and V_b
 * (np x 6): the velocity products Ġ_p u of the dynamics, by the recursion's directional
 * derivative (one pass; exact to round-off, where central differences of csr_strainTwists_
 * carry their O(ε²) truncation); ks: the kinematics' steps at this q (csr_strainStepsAt_) or
 * NULL (each step's exponential formed here) */
void csr_strainTwistRates_(const csrStrainModel* m, const double* q, const double* eta,
                           const double Vb[6], const double* ks, double* V, double* A);
/* d->ks if it holds the steps at d->q (the kinematics formed them there), else NULL */
const double* csr_strainStepsAt_(const csrStrainModel* m, const csrStrainData* d);
/* strain ξ (6) of piece k at local arc length s */
void csr_strainAt_(const csrStrainModel* m, const double* q, int k, double s, double xi[6]);
/* ---- dense factorisations (robot_strain_linalg.c) ---- */
/* LU with partial pivoting in place (n x n); 0 ok, 1 singular; and its solve */
int csr_strainLuFactor_(double* A, int n, int* piv);
void csr_strainLuSolve_(const double* A, int n, const int* piv, double* x);
/* the same for nrhs right-hand sides at once, B (n x nrhs, row-major) in place */
void csr_strainLuSolveMulti_(const double* A, int n, const int* piv, double* B, int nrhs);
/* Cholesky Uᵀ U of a symmetric positive definite A (n x n) in place (U upper, row-major, the
 * strict lower triangle overwritten);
 * 0 ok, 1 not positive definite (A then partly overwritten); its solve, and the solve of six
 * right-hand sides B (n x 6, row-major) in place */
int csr_strainCholFactor_(double* A, int n);
void csr_strainCholSolve_(const double* U, int n, double* x);
void csr_strainCholSolve6_(const double* U, int n, double* B);
/* Σ_p G_pᵀ F_p for body wrenches F (np x 6: each (m; f) in its point's body frame, N mm and
 * N) at coordinates q, by the adjoint of the Jacobian recursion (no Jacobians, no kinematics
 * needed): Fb (6) = Σ_p Ad(g_p⁻¹)ᵀ F_p onto the base's body twist, Q (n, overwritten) =
 * Σ_p J_pᵀ F_p */
void csr_strainProject_(const csrStrainModel* m, const double* q, const double* F, double Fb[6],
                        double* Q);
/* G_p = [Ad(g_p⁻¹), J_p] of point p (6 x (6 + n), row-major) at the current kinematics */
void csr_strainPointG_(const csrStrainModel* m, const csrStrainData* d, int p, double* G);

/* ---- the articulated condensation (robot_strain_artic.c) ---- */
/* piece k's own sums over its points s < p <= e (s, e its first and last), at the current
 * kinematics (J at every point): I = Σ Aᵀ M_p A (6 x 6), F = Σ Aᵀ M_p L_p (6 x nd, L_p the
 * Jacobian's columns of the piece's own unknowns), D = Σ L_pᵀ M_p L_p (nd x nd), with
 * A = Ad(g_sp⁻¹) in s's body frame; A left as Ad(g_se⁻¹). By the block form of M_p
 * (robot_strain_artic.c) */
void csr_strainPieceSums_(const csrStrainModel* m, const csrStrainData* d, int k, double I[36],
                          double* F, double* D, double A[36]);
/* Z, ρ, d->X, d->y of the step's W (step h) by the recursion over the pieces, at the current
 * kinematics (with J at every point), from the forces rl (n), rb (6) (h r's r) and d->Kd:
 * W_M's alone when d->nct is 0, else with the d->nct touching shapes' -h Sᵀ A S (d->cS, cA;
 * unsymmetric: LU of each piece's block, the factors kept in d->art* for the kept iterates).
 * d->WMbb, d->WMlb filled from the composite inertias of W_M (d->WMll not: the dense path
 * forms it when it needs it). 0 ok, 1 a piece's block not positive definite (no contact) or
 * singular, a shape across two pieces, or ρ not finite */
int csr_strainCondenseArtic_(const csrStrainModel* m, csrStrainData* d, double h,
                             const double* rl, const double rb[6], double Z[36], double rho[6]);
/* the kept iterates' solve through the recursion's factors (d->art*, art_f): y (n) holds the
 * leg's right-hand side in, W_ll⁻¹ of it out; w (6) = W_bl W_ll⁻¹ of it */
void csr_strainArticSolve_(const csrStrainModel* m, csrStrainData* d, double* y, double w[6]);
/* the same on nc columns at once: B (n x nc, row-major) in, W_ll⁻¹ B out; work 12 nc */
void csr_strainArticSolveMulti_(const csrStrainModel* m, csrStrainData* d, double* B, int nc,
                                double* work);

/* ---- an iterate's refactor on the start's recursion (robot_strain_woodbury.c) ---- */
/* Z, ρ, d->X, d->y of W = W_f,start - the start's shapes' part (d->cS, cA: +h Sᵀ A S) + the
 * iterate's (d->wS, wA: -h Sᵀ A S), from the start's pieces' factors (art_f or wb_f) by the
 * Woodbury identity; Wbb, d->Wlb, d->Wbl, rb, d->rl the new W's and h r's other blocks.
 * 0 ok (d->wb_f set), 1 the update's capacitance singular or a result not finite */
int csr_strainCondenseWoodbury_(const csrStrainModel* m, csrStrainData* d, double h,
                                const double Wbb[36], const double rb[6], double Z[36],
                                double rho[6]);
/* y (n) in, the update's W_ll⁻¹ y out (wb_f; h the step the update was formed at) */
void csr_strainWoodburySolve_(const csrStrainModel* m, csrStrainData* d, double h, double* y);

/* ---- inertia (robot_strain_inertia.c; the step in robot_strain_dyn.c) ---- */
/* V = G_p (V_b, η) at point p of the current kinematics (d->R, d->x, d->J), body frame */
void csr_strainPointTwist_(const csrStrainModel* m, const csrStrainData* d, int p, const double Vb[6],
                           const double* eta, double V[6]);
/* Σ_p m_p x_p of the leg, world (t mm), at the current kinematics and base */
void csr_strainMassMomentAt_(const csrStrainModel* m, const csrStrainData* d, double X[3]);
/* W_M's inertia Σ_p G_pᵀ M_p G_p at the kinematics R, x, J into d->WMll, d->WMlb, d->WMbb */
void csr_strainInertiaFrom_(const csrStrainModel* m, csrStrainData* d, const double* Rk,
                            const double* xk, const double* Jk);
/* out (6 + n) = M u, M = Σ_p G_pᵀ M_p G_p the inertia at the kinematics R, x, J (np x 9,
 * np x 3, np x 6 x n, as d->R, d->x, d->J with Jacobians at every point), u = (V_b, η) (6 + n):
 * matrix-free, O(6 Σ_p pcol[p]) (no assembly) */
void csr_strainInertiaApply_(const csrStrainModel* m, const double* R, const double* x,
                             const double* J, const double* u, double* out);
/* the inertia Σ_p G_pᵀ M_p G_p at the current kinematics (with J) into d->WMll (n x n, full),
 * d->WMlb (n x 6) and d->WMbb, by composite inertias per piece */
void csr_strainInertia_(const csrStrainModel* m, csrStrainData* d);

/* the shapes' poses at the predicted end of a backward-Euler step, q0 + h η0 and the hip at
 * g_b exp(h V_b), into d->sst (pred 1); the state and its kinematics unchanged
 * (robot_strain_dyn.c) */
void csr_strainPredictShapes_(const csrStrainModel* m, csrStrainData* d, double h);
/* one touching shape's W -= h Sᵀ A S into Wbb, d->Wlb, d->Wbl, d->Wll (S 6 x (6 + n), AS and
 * row scratch of 6 (6 + n) and 6 + n): part 0 every block, 1 all but W_ll's, 2 W_ll's alone
 * (the same operations on each entry as part 0) */
void csr_strainShapeW_(const csrStrainModel* m, csrStrainData* d, double h, const double* S,
                       const double A[36], double* AS, double* row, double* Wbb, int part);

/* ---- the step condensed onto the base (robot_strain_condense.c; the step's assembly,
 * prepare and iterates: robot_strain_dyn.c) ---- */
/* 1: a backward-Euler step's start, and each BDF2 pass that assembles at its iterate, is
 * condensed by the articulated recursion when its leg touches nothing (robot_strain.h artic;
 * the dense factor stays where keep_matrix keeps it) */
static inline int csr_strainArticStep_(const csrStrainModel* m) {
  return m->par.artic && !m->par.keep_matrix;
}
/* BDF2 with its whole residual assembled at every iterate (step_refresh) */
static inline int csr_strainBdfFull_(const csrStrainModel* m) {
  return m->par.step_order == 2 && m->par.step_refresh;
}
/* W = W_M + the contact's linearisation at the current kinematics and point twists (du NULL:
 * the step's start; else the iterate Δu = du, 6 + n), condensed onto the base: Z, ρ (and
 * d->X, d->y), by the recursion, its Woodbury update, a kept factor or the dense LU; 0 ok,
 * > 0 failed (not finite, a singular factor, a pose past a shape's radius) */
int csr_strainCondense_(const csrStrainModel* m, csrStrainData* d, double h, const double* du,
                        double Z[36], double rho[6]);
/* an iterate without contact on a factor without it: Z the last pass's, ρ with the iterate's
 * momentum rows (du its Δu); 0 ok, 1 ρ not finite */
int csr_strainCondensePlain_(const csrStrainModel* m, csrStrainData* d, double h,
                             const double* du, double Z[36], double rho[6]);
/* a chord iterate on the kept factor (d->Wll or the recursion's pieces, their blocks d->Wu,
 * Wlb, Wbl, Wbbp; Z = d->Zp) with the contact's load at the iterate fb (6), d->fl (n);
 * 0 ok, 1 not finite */
int csr_strainCondenseKept_(const csrStrainModel* m, csrStrainData* d, double h,
                            const double* du, const double fb[6], double Z[36], double rho[6]);
/* d->Wll, Wlb, Wbl, rl zeroed if a step's start left them pending (wl_pending), else nothing
 * (d->Wll not while wc_sparse: the recursion's start does not form it) */
void csr_strainClearStart_(const csrStrainModel* m, csrStrainData* d);

/* ---- contact shapes (robot_strain_shape.c) ---- */
/* the shapes (a capsule per Magnus sub-interval, the foot's sole last) and their law */
int csr_strainContactCreate_(csrStrainModel* m, const csrStrainSpec* spec, csError* err);
/* shape s's pose and velocity in the world from the current kinematics and point twists */
void csr_strainShapeState_(const csrStrainModel* m, const csrStrainData* d, int s,
                           cscShapeState* st);
/* the law at shape s's state st, not remembered (L: foot (force, couple), capsule (f0, f1);
 * couple, slot out or NULL) */
int csr_strainShapeLaw_(const csrStrainModel* m, const csrStrainData* d, int s,
                        const cscShapeState* st, double L[6], double couple[3],
                        cscSlotInfo* slot);
/* shape s's memo set to the state st and the history now (its load, report and slots already
 * written) */
void csr_strainShapeMemoKeep_(const csrStrainModel* m, csrStrainData* d, int s,
                              const cscShapeState* st, int rc);
/* the law at shape s's state st through the shape's memo (the same bits as anew); slot: its
 * slots' report or NULL; rep: added to, or NULL */
int csr_strainShapeLoad_(const csrStrainModel* m, csrStrainData* d, int s,
                         const cscShapeState* st, double L[6], double couple[3],
                         cscSlotInfo* slot, cscSoftReport* rep);
/* K_y, C_y (6 x 6 each, row-major) of shape s at state st, where the law's load is L0 */
void csr_strainShapeTangent_(const csrStrainModel* m, csrStrainData* d, int s,
                             const cscShapeState* st, const double L0[6], double Ky[36],
                             double Cy[36]);

/* ---- contact in the step (robot_strain_contact.c) ---- */
/* the contact's force, its linearisation over a step of h added to W (the four blocks, W_ll
 * full) and h r (r_b, r_l: forces, added), at the current kinematics (with J) and point
 * twists d->Vp; 0 or > 0 (a pose sinks past a shape's radius or is not finite) */
int csr_strainContactAssemble_(const csrStrainModel* m, csrStrainData* d, double h,
                               const double* du, double* Wbb, double* rb, double* G);
/* the contact's force alone at the current kinematics and point twists (no linearisation):
 * Σ Sᵀ L added to fb (6) and fl (n) (N, N mm), d->fcw and d->ntouch set; *same 1 when every
 * slot's state (touching, saturated) is d->csig's. 0 or > 0 as csr_strainContactAssemble_. */
int csr_strainContactLoads_(const csrStrainModel* m, csrStrainData* d, double fb[6], double* fl,
                            int* same);
/* 1 when no shape touches at the current poses (d->R, d->x: the kinematics without J is
 * enough) with the shapes at rest: the law's force is zero wherever its elastic part is, at
 * any velocity, so then none touches at the shapes' real velocities either; 0 otherwise */
int csr_strainContactNone_(const csrStrainModel* m, const csrStrainData* d);
/* every shape's active-set record cleared (a step's start) */
void csr_strainGhostReset_(const csrStrainModel* m, csrStrainData* d);
/* BDF2's prepare: every touching shape's record (y, L, K_y, C_y) at the current state, the
 * step's start (the last step's converged end), held until the step's first iterate (d->
 * ghost_hold); the kinematics with J at the chain points and d->Vp there valid. 0 or > 0 as
 * csr_strainContactAssemble_ */
int csr_strainGhostStart_(const csrStrainModel* m, csrStrainData* d);
/* drop the shapes held by their ghost at the last evaluation: how many (csr_strainRelease) */
int csr_strainGhostRelease_(const csrStrainModel* m, csrStrainData* d);
/* the largest fraction (0, 1] of the iterate's move (db: the base's twist change, body
 * coordinates; dl (n): the rates' change) that moves no touching foot slot with friction more
 * than the trust radius along the surface (slot_trust; the kinematics with J at the iterate
 * valid) */
double csr_strainContactLimit_(const csrStrainModel* m, csrStrainData* d, double h,
                               const double db[6], const double* dl);
/* return-map the anchors at the current state (kinematics with J valid, d->Vp set) */
int csr_strainContactUpdate_(const csrStrainModel* m, csrStrainData* d);
/* the point twists d->Vp at the current kinematics; chain 1: at the chain points alone (even
 * p, after csr_strainKinematics_ with want_J 2) */
void csr_strainPointTwists_(const csrStrainModel* m, csrStrainData* d);
void csr_strainPointTwistsChain_(const csrStrainModel* m, csrStrainData* d);
/* pose relative to the base (Rr, xr) -> world (R, x) */
void csr_strainWorld_(const csrStrainData* d, const double Rr[9], const double xr[3],
                      double R[9], double x[3]);
/* the kinematics at every quadrature point relative to the base (poses and, with want_J 1,
 * Jacobians: kin_valid 2). want_J 2: the Jacobians at the chain points alone (the sub-
 * intervals' ends, even p: the contact's shapes are there), not at the midpoints (odd p,
 * leaves of the recursion, needed by the inertia and the step's forces only), kin_valid 1:
 * for a Newton iterate's contact (docs/notes/strain_leg.md, "Kernel, round 3"). want_J 3:
 * the poses at the chain points alone, no Jacobians, the midpoints' poses left as they were,
 * kin_valid 0 (the predicted shapes' poses: csr_strainPredictShapes_). want_J 5: the poses
 * (kin_valid 1, no Jacobians) and each flexible chain step's T(Ω) and ∂Ω/∂q into d->kst
 * (kst_ok): a kept iterate's twists and Sᵀ L without Jacobians */
void csr_strainKinematics_(const csrStrainModel* m, csrStrainData* d, int want_J);
/* Ad(exp(-Ω))ᵀ W of one step, exp(Ω) = (Re, pe) (csr_strainStepsAt_'s first 12 numbers of the
 * step's end point): a wrench W (μ; φ) at the step's end point taken to its start,
 * (Re μ + pe × Re φ; Re φ) */
void csr_strainAdExpTApply_(const double Re[9], const double pe[3], const double W[6],
                            double out[6]);
/* The chain points' twists V_p = G_p (V_b, η) (d->Vp at even p) at d->q, d->eta, d->Vb by the
 * twist recursion over the chain steps alone, on the kinematics' steps d->ks (which must be at
 * d->q: csr_strainStepsAt_): no Jacobians; J_p η's value to round-off (a kept iterate's
 * contact: docs/notes/strain_leg.md, kept20) */
void csr_strainChainTwistsNoJ_(const csrStrainModel* m, csrStrainData* d);
/* Q (n, added to) += Σ_p J_pᵀ F_p over the chain points p <= plast, F (np x 6) body wrenches
 * (m; f) read at the even points, by the adjoint of the chain's Jacobian recursion on the
 * kinematics' steps d->ks, d->kst (at d->q: want_J 5): no Jacobians; J_pᵀ F_p's value to round-off */
void csr_strainChainProjectNoJ_(const csrStrainModel* m, const csrStrainData* d, const double* F,
                                int plast, double* Q);
/* csr_strainCondense_'s code for an iterate without the chain points' Jacobians that cannot
 * keep its matrix: the caller forms them (want_J 2, the point twists) and condenses again */
#define CSR_STRAIN_NEED_J (-2)
/* doubles a chain step keeps in d->kst: T(Ω) and ∂Ω/∂q */
#define CSR_STRAIN_KST (36 + 6 * CSR_STRAIN_MAX_PIECE_DOF)
/* want_J 4 (kin_valid 1, kin_midown 1): as 2, and the midpoints' own piece's columns (not the
 * columns of the pieces before: a midpoint is a leaf, and backward Euler's start by the
 * recursion reads its L_p alone, its step force through the chain point before it; the
 * columns formed are want_J 1's bits) */
/* 1 when the poses and the chain points' Jacobians are valid (kin_valid 2, or 1 from a
 * want_J 2): what the contact's loads and the point twists at the chain points read */
static inline int csr_strainChainJ_(const csrStrainData* d) {
  return d->kin_valid == 2 || (d->kin_valid == 1 && d->kin_chain);
}

#endif /* CS_ROBOT_STRAIN_INTERNAL_H */

/* sim_internal.h: INTERNAL to core/sim_*.c: the layout of csData and the functions the driver's
 * files share. Nothing outside core/sim_*.c includes it; the public API is sim_model.h.
 *
 * Who writes what in csData during a step (docs/style.md 7):
 *   schedule   p_cmd
 *   pneumatics p (and the CVODE memory), p0 keeps the pressures at the step's start
 *   legs       the legs' actuation; cosim.b0, b1, w, K, C (co-simulated legs' exchange)
 *   support    the ODE bodies, cstats (the stabilised scheme's implicit force per ODE step)
 *   check      nothing (reads the support)
 *   cs_step    t, nstep, nreject, save (the state before the step), timer[]
 * With the tree coupling the legs stage only condenses the legs (cosim.w, A); the support stage
 * solves the support with them; the legs then finish after it (cosim.w, the legs' state). */
#ifndef CS_CORE_SIM_INTERNAL_H
#define CS_CORE_SIM_INTERNAL_H

#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>

#include "sim_model.h"

/* the exchange with co-simulated legs and the stabilised scheme's implicit spring (all world
 * frame; sim_coupling.c) */
typedef struct csCosim_ {
  int active;                       /* the leg level is co-simulated (in_world = 0) */
  csrBaseState b0[CSR_NLEG];        /* hip motion at the macro step's start */
  csrBaseState b1[CSR_NLEG];        /* predicted hip motion at its end */
  csrWrench w[CSR_NLEG];            /* base wrenches of the last advance (step average) */
  double K[CSR_NLEG][36];           /* interface stiffness of each leg at its hip */
  double C[CSR_NLEG][36];           /* interface damping of each leg at its hip */
  /* stabilised scheme: the legs' gains summed at the support's centre of mass and the motion
   * the legs were given (constant twist from the step's start) */
  double t0;                        /* s: start of the macro step */
  double P0[3], R0[9], v0[3], w0[3];/* support centre, rotation, twist at t0 */
  double Pm[3], Rm[9];              /* predicted mean pose: W0's linearisation point */
  double Kc[36];                    /* summed stiffness at the centre (6 x 6, [f; m] x [u; φ]) */
  double A[36];                     /* h Kc + Cc: the implicit part (6 x 6) */
  /* Gauss-Seidel scheme. Carried from one macro step to the next (with w, Kc and A: the state
   * block of cs_couplingStateGet): the linearisation point of w, i.e. the mean start pose of
   * the last macro step's ODE steps and their mean end twist, and the impulse carry */
  double gs_P[3], gs_R[9];          /* mean start pose of the last macro step's ODE steps */
  double gs_qd[6];                  /* their mean end twist [v; w] */
  double gs_qd_prev[6];             /* the same a macro step earlier */
  double carry[6];                  /* legs' actual minus applied wrench, last step (centre) */
  double gs_primed;                 /* 1 once a macro step has left the above (0 before: that
                                       step runs stabilised, cs_couplingPrime) */
  /* within a macro step (reset at its start, cs_couplingBegin): sums over the ODE steps */
  double sum_P[3], sum_phi[3];      /* start poses (rotation relative to R0) */
  double sum_qd[6];                 /* twists at the starts of steps 1..n-1 */
  double sum_F[6];                  /* the force applied at the centre */
  /* tree coupling: Newton passes taken by the accepted and rejected tries (a counter, not
   * state: cs_treePassCount) */
  long tree_passes;
  /* and the contact ghosts the legs released at converged passes (csrLegType.release: each
   * sends the passes on; a counter, not state: cs_treeReleaseCount) */
  long tree_released;
  /* and the passes whose move a leg's globalisation shortened (csrLegType.stepLimit; a
   * counter, not state: cs_treeLimitCount) */
  long tree_limited;
  /* and the leg linearisations the passes skipped (tree_skip; a counter, not state) */
  long tree_skipped;
  /* tree coupling, within a try (scratch, not state): each leg's last linearisation (Z, ρ as
   * prepare/iterate return them, world at the hip, before sim_tree.c's correction to the
   * iterate) */
  double tk_Z[CSR_NLEG][36], tk_rho[CSR_NLEG][6];
  /* 1: the leg kept an earlier linearisation at the try's converged pass (its finish checks
   * that nothing touches at the step's end) */
  int tk_kept[CSR_NLEG];
  /* tries rejected because a kept leg touched at the step's end (a counter, not state) */
  long tree_caught;
  /* tree coupling with the legs' multistep formula (csrLegType.stepCoeffs, BDF2): the support
   * at the last step's start (state) and this step's coefficients */
  double tb_P[3], tb_R[9], tb_v[3], tb_w[3];
  double tb_c[3], tb_h;             /* and this step's length (s) */
} csCosim;

/* doubles in the coupling's state block (cs_couplingStateGet): w, Kc, A, gs_P, gs_R, gs_qd,
 * carry, gs_qd_prev, the tree's tb_P, tb_R, tb_v, tb_w, gs_primed (last) */
#define CS_COSIM_STATE (6 * CSR_NLEG + 36 + 36 + 3 + 9 + 6 + 6 + 6 + 18 + 1)

/* contact joints whose force is measured per ODE step (each ~100 bytes) */
#define CS_MAX_FEEDBACK 4096

/* The adaptive macro step (sim_adaptive.c): the watched state is the support's centre (3,
 * mm), its velocity (3, mm/s), its angular velocity times CS_ADA_LEVER (3, mm/s) and every
 * foot's position (3 per leg, mm); its state part is the next step h_prop (s), the last
 * accepted step h_prev (s; 0: no history) and that step's change of the watched state; under
 * BDF2 (step_order 2) also the step before it, h_prev2 (s; 0: none), and its change
 * (CS_ADA_STATE2: the predictor's third point) */
enum {
  CS_ADA_NY = 9 + 3 * CSR_NLEG,
  CS_ADA_STATE = 2 + CS_ADA_NY,
  CS_ADA_STATE2 = CS_ADA_STATE + 1 + CS_ADA_NY,
  CS_ADA_NBIN = 256
};
typedef struct csAdaptive_ {
  double h_prop, h_prev, h_prev2;
  double dy_prev[CS_ADA_NY], dy_prev2[CS_ADA_NY];
  /* not state: counts and the accepted steps' lengths (bins of 1/16 octave below H) */
  long accepted, rejected;
  double h_min, h_max;
  long bins[CS_ADA_NBIN];
} csAdaptive;

struct csData_ {
  const csModel* m;                 /* for the pneumatic right-hand side */
  dWorldID world;
  dSpaceID terrain_space;
  dSpaceID robot_space;
  dJointGroupID contacts;
  csrRobot* robot;
  double t;                         /* s */
  unsigned long rng_seed;           /* this data's ODE random seed (QuickStep's row order): set
                                       into ODE's one process-wide generator for each step and
                                       read back after it, so interleaved datas stay
                                       independent and each is deterministic */
  long nstep;                       /* successful macro steps */
  long nreject;                     /* failed (and restored) macro steps */
  long ngain_proj;                  /* macro steps whose legs' implicit part was projected
                                       onto passive gains (sim_coupling.c implicitPart) */
  double p_cmd[CSR_NCHAMBER_TOTAL]; /* scheduled pressures at t (MPa) */
  double p[CSR_NCHAMBER_TOTAL];     /* chamber pressures at t (MPa) */
  double p0[CSR_NCHAMBER_TOTAL];    /* chamber pressures at the current step's start (MPa) */
  double x0[3];                     /* support centre at t = 0 (mm) */
  cscContactStats cstats;
  /* contact joint feedback of the last ODE step (sim_step.c): preallocated, at most
   * CS_MAX_FEEDBACK joints are measured (nfb_over counts the rest) */
  dJointFeedback* fb;               /* (CS_MAX_FEEDBACK) */
  int nfb, nfb_over;
  signed char fb_leg[CS_MAX_FEEDBACK]; /* the in-world leg of each measured joint, -1: none */
  double contact_force[3];          /* N, world: terrain on robot, last ODE step */
  double leg_contact_force[CSR_NLEG][3]; /* N, world: its part on each in-world leg */
  csuTimer timer[CS_NTIMER];
  int nstate;                       /* cs_stateSize */
  double* save;                     /* (CS_MAX_SPLIT + 2) x nstate: the state before the
                                       current step, then before each of its halves when a
                                       tree-coupled step is retried smaller (sim_step.c), and
                                       the adaptive step's macro step start (sim_adaptive.c) */
  csCosim cosim;
  /* CVODE */
  SUNContext sun;
  void* cvode;
  N_Vector y;
  double fh_choice[CSG_FOOTHOLD_MAX]; /* the footholds' latched candidates (-1: not yet
                                       decided), in the state after the coupling's block */
  /* the landing gate (sim_gate.c), in the state after the footholds' latches: the next gate
   * not released, the hold so far (s), the current gate's wait so far (s), each released
   * gate's wait (s) */
  double gate_i, gate_hold, gate_wait;
  double gate_rel[CSG_GATE_MAX];
  /* its decision at the current step's start (cs_gateDecide; not state: a function of it):
   * the gates below gate_next are released, gate_holding 1 when gate gate_next holds; the
   * offsets of the rows (gate_off[s]: rows after gate s - 1) and the last issued table time */
  int gate_next, gate_holding;
  double gate_off[CSG_GATE_MAX + 1];
  double gate_issued;
  /* the gate file's crawl (sim_gate.c), in the state after the gate's part when the file has
   * one: the decision boundaries passed (the i-th is slot j = (N - 1) % 2 + 2 i's end), the
   * support's z at the last of them (mm) and the table clock's skip (s); and the decision at
   * the current step's start (not state: a function of it, written by cs_gateCommit) */
  double crawl_i, crawl_z, crawl_skip;
  double crawl_i_next, crawl_z_next, crawl_skip_next;
  /* the gate file's walk (`walk`, sim_gate.c), the same three on x, in the state after the
   * crawl's part; the table's clock is t - gate_hold + walk_skip + crawl_skip */
  double walk_i, walk_x, walk_skip;
  double walk_i_next, walk_x_next, walk_skip_next;
  csAdaptive ada;  /* the adaptive step (opt.step_adaptive; sim_adaptive.c) */
  /* the step the current try started as before its halvings (s): H with a fixed step, the
   * adaptive step's length with step_adaptive (the tree's rules for a retried step) */
  double h_try;
  long pn_count[2]; /* CVODE's internal steps and right-hand sides on the pressures so far
                       (cs_pneumaticCounts), across its restarts */
};

/* how often a rejected tree-coupled step is halved before the step fails (sim_step.c): down
 * to 1/256 of it. 8, not the earlier 4 (1/16): where a leg is struck onto an edge at a
 * fraction of a m/s (the earth collapse off the road's start edge), Hunt-Crossley's damping
 * and the friction's bristle damping, both scaled by the normal force, change the leg's
 * velocity within 1/16 of the 1 ms step by more than Newton's linear model of the law holds
 * over: the passes cycle there and converge at 1/64 (docs/notes/strain_leg.md "The road's
 * edge"). A step that converges at 1/16 or above is tried exactly as before. */
#define CS_MAX_SPLIT 8

/* from this halving on (1/16 of the step, the last one before CS_MAX_SPLIT was 8) a try gets
 * twice the Newton passes (core/sim_tree.c cs_couplingApplyTree), so every step that
 * converged with 4 halvings at most is tried with the same passes as then */
#define CS_SPLIT_MORE_PASSES 4

/* the adaptive step (sim_adaptive.c): its part of the state (0 with a fixed step), its
 * get/set/check, and one macro step [d->t, t1] crossed in error-controlled steps */
int cs_adaptiveStateSize(const csModel* m);
void cs_adaptiveStateGet(const csData* d, double* x);
int cs_adaptiveStateCheck(const csModel* m, const double* x);
void cs_adaptiveStateSet(csData* d, const double* x);
csStatus cs_adaptiveStep(const csModel* m, csData* d, double t1, csError* err);
/* the controller's parts (unit-tested on a closed form, tests/core/test_strain_adaptive.c):
 * the weighted RMS of the trapezoid-minus-backward-Euler estimate (dy[i] - r dy_prev[i]) / 2
 * over tol[i] for the step's change dy after a step of change dy_prev, r = h / h_prev; and
 * the factor on h for that error E (0.9 / sqrt(E), within [0.2, 2]) */
double cs_adaptiveErrorNorm(int n, const double* dy, const double* dy_prev, const double* tol,
                            double r);
double cs_adaptiveFactor(double E);
/* BDF2's (step_order 2): the weighted RMS over tol[i] of its local error estimated from the
 * step's change dy (length h) and the two before it, dy1 (h1) and dy2 (h2): the difference of
 * the step's end to the quadratic predictor through the last three points, scaled to BDF2's
 * error constant for the formula's ratio w = h / (the legs' last step) (sim_adaptive.c); and
 * the factor on h for that error (0.9 E^(-1/3), within [0.2, 2]) */
double cs_adaptiveErrorNorm2(int n, const double* dy, const double* dy1, const double* dy2,
                             const double* tol, double h, double h1, double h2, double w);
double cs_adaptiveFactor2(double E);
/* one try of [d->t, t1] of length H with its halvings (sim_step.c) */
csStatus cs_stepTry(const csModel* m, csData* d, double t1, double H, int depth, csError* err);

/* scheduled pressures at time t (zero before t = 0), 96 MPa: the model's pressure source if
 * it has one, else the gait table with its footholds' chosen candidates (sim_schedule.c,
 * sim_foothold.c; a foothold reached at t is decided here, from d's state, which is the
 * step's start wherever the schedule is asked). Returns 0, or -1 when the source failed
 * (p_cmd is then zero; the pneumatic integrator fails the step, cs_api.c checks the rest) */
int cs_schedule(const csModel* m, csData* d, double t, double* p_cmd);

/* the footholds' part of the schedule (sim_foothold.c): decides the footholds whose lift t
 * has reached, then writes each open window's chosen candidate into its legs' columns of
 * p_cmd (the table's command at t) */
void cs_footholdApply(const csModel* m, csData* d, double t, double* p_cmd);

/* the landing gate (sim_gate.c). Decide: from d's state at the step's start (t, the chamber
 * pressures, the gate's part), which gates release and whether one holds, into d's decision
 * fields (a pure function of the state: a retried or restored step decides again the same).
 * Commit: after an accepted step of length h, the decision into the state (released waits,
 * the next gate) and, while holding, h onto the hold and the wait. Eval: the table g's
 * command at t under the decision (csg_scheduleEval itself while nothing has been held).
 * Table time (cs_gateTableTime, sim_model.h): t less the hold plus the skip. */
void cs_gateDecide(const csModel* m, csData* d);
void cs_gateCommit(const csModel* m, csData* d, double h);
void cs_gateEval(const csModel* m, const csData* d, const csgGait* g, double t, double* p_cmd);
/* cs_gateTableTime: sim_model.h */

/* ---- sim_coupling.c: the support interface of co-simulated legs (staggered, stabilised,
 * Gauss-Seidel) ---- */

/* Set up the coupling of co-simulated legs (nothing to create today: the stabilised scheme
 * solves its implicit part in cs_couplingApply). */
csStatus cs_couplingCreate(const csModel* m, csData* d, csError* err);

/* The legs stage's co-simulation part: hip motion b0 now and b1 predicted at t + H, every
 * leg's advance, its wrench and (stabilised) gains. 0, > 0 recoverable, < 0 fatal (err). */
int cs_couplingAdvance(const csModel* m, csData* d, double H, csError* err);

/* Before ODE sub-step j (0..macro_steps-1) of the support stage: the legs' force on the
 * support: staggered, their averaged wrenches; stabilised, those corrected by their gains for
 * the support's deviation from the predicted motion, solved implicitly with the support's step;
 * Gauss-Seidel, the last step's wrenches corrected by their gains for the support's motion
 * since, solved the same way (sim_coupling.c). */
void cs_couplingApply(const csModel* m, csData* d, int j);

/* 1 when this macro step runs Gauss-Seidel: the coupling asks for it and a step has left the
 * legs' wrench and gains (the first one runs stabilised and primes it, cs_couplingPrime). */
int cs_couplingGS(const csModel* m, const csData* d);

/* Gauss-Seidel's first macro step, after its support stage: what it carries from the
 * stabilised step just run (the wrench along the prediction holds at the predicted motion). */
void cs_couplingPrime(const csModel* m, csData* d);

/* Gauss-Seidel: before the support stage, record the support's state at the macro step's
 * start (the legs' b0) and clear the step's sums. */
void cs_couplingBegin(const csModel* m, csData* d);

/* Gauss-Seidel: after the support stage, every leg advances across [t, t + H] along the
 * support's actual motion; their wrenches, gains, the linearisation point and the impulse
 * carry for the next macro step. 0, > 0 recoverable, < 0 fatal (err). */
int cs_couplingAdvanceGS(const csModel* m, csData* d, double H, csError* err);

/* The stabilised schemes' pieces the tree scheme (sim_tree.c) shares:
 * the support's backward-Euler step with the legs' force linearised, F = W0 - Kc dq - A (q' -
 * q'_pred) (sim_coupling.c's header), solved for its end twist qd1 (may be NULL); F gets the
 * legs' force along it (N, N mm at the centre, world). 0, or 1 when M + h A is singular
 * (F = W0 then). */
int cs_couplingSupportSolve(const csData* d, double h, double mass, const double Iw[9],
                            const double qd[6], const double W0[6], const double Kdq[6],
                            const double A[36], const double qd_pred[6], double F[6],
                            double qd1[6]);
/* the support's mass and its inertia about its centre in the world frame at rotation R (ODE's
 * units: the model's kg and mm) */
void cs_couplingSupportInertia(const csData* d, const double R[9], double* mass,
                               double Iw[9]);
/* a leg's wrench (and gains K, C if K is not NULL) finite: 0; else 1 and err names the leg
 * (the step is rejected: a smaller one may keep the leg in its valid range) */
int cs_couplingCheckFinite(const csData* d, int k, const csrWrench* w, const double* K,
                           const double* C, csError* err);
/* M += Tᵀ G T for the hip-to-centre map T = [[I, -[r]x], [0, I]] (G at the hip, 6 x 6, row
 * major; r = hip - centre, mm) */
void cs_couplingAddAtCentre(double M[36], const double G[36], const double r[3]);

/* ---- sim_tree.c: the tree coupling (CS_COUPLING_TREE, tree-stepped levels) ----
 * Before the support stage: every leg condenses its step of h onto its hip (prepare) at the
 * support's state now; their impulses ρ/h go into cosim.w, their impedances Σ Tᵀ Z T / h at
 * the support's centre into cosim.A. 0, > 0 recoverable, < 0 fatal (err names the leg). */
int cs_couplingTreePrepare(const csModel* m, csData* d, double h, csError* err);
/* Before the support's one ODE step of h: the support's backward-Euler step with the legs'
 * condensed step solved (the stabilised scheme's solve with Kc = 0 and the prediction the
 * support's twist now); with tree_iterations > 1 and a level that has update/iterate, Newton
 * passes of the whole tree (solve, every leg back-substitutes, every leg linearises again)
 * until nothing moves by more than tree_tol; then the legs' force on the support along the
 * last solve is added to the body. 0, > 0 (err filled: singular, not converged, a leg's pass
 * failed recoverably: the step is rejected), < 0 fatal. */
int cs_couplingApplyTree(const csModel* m, csData* d, double h, csError* err);
/* After it: every leg back-substitutes the support's actual motion (finish); cosim.w gets the
 * legs' base wrenches of the step. 0, > 0 recoverable, < 0 fatal (err). */
int cs_couplingTreeFinish(const csModel* m, csData* d, csError* err);

/* The coupling's part of the state (CS_COSIM_STATE doubles, co-simulated legs only): what the
 * Gauss-Seidel scheme carries across macro steps. Check returns 0 when x is a valid block. */
void cs_couplingStateGet(const csData* d, double* x);
int cs_couplingStateCheck(const double* x);
void cs_couplingStateSet(csData* d, const double* x);

#endif /* CS_CORE_SIM_INTERNAL_H */

/* test_strain_driver.c: the strain leg level through the driver (`--legs strain`, the tree
 * coupling, sim_tree.c), on the flat-road scene's own terrain, gait, calibration and rule
 * (paper conditions):
 *  - it runs end to end through cs_step, and the legs carry the support: after settling the
 *    eight legs' base wrenches hold its weight (their vertical sum against m_s g, the support
 *    not touching the terrain; the tree's momentum balance, not a fitted force), every foot
 *    reports its ground force (the run file's /contact datasets) and they sum to the weight;
 *  - two datas of one model stepped alike are bit-identical, and so is a run continued from a
 *    restored state (cs_stateGet / cs_stateSet, the driver's rollback);
 *  - frictionless, the centre of mass stays (1e-4 mm in 1 s at 2 and 1 ms, the Newton passes'
 *    discrete momentum form through the support's ODE step), with BDF2 (--step-order 2) too,
 *    whose restored runs are bit-identical, with the legs' iteration matrix kept across
 *    steps (keep_matrix) at 2 and 5 ms, and on the level's default adaptive step (0.01 mm in
 *    9 s, per second);
 *  - a step the legs reject (prepare > 0, what the kernel returns when its step does not
 *    converge) is restored and retried in halves through the rollback: the time still advances
 *    by exactly one step, each rejection is counted, the legs see steps of h/2, and the track
 *    stays near the unrejected one; a step rejected at every size fails with CS_ERR_REJECTED
 *    and changes nothing.
 * The rejecting level is csr_leg_strain with its prepare wrapped (a test double in this file).
 * ~0.4 s simulated per data at 1 ms steps (the level's step); release ~7 s of CPU, under the
 * sanitizers ~50 s. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "strain_flat_fixture.h"
#include "robot_strain.h"
#include "sim_internal.h" /* CS_MAX_SPLIT, CS_SPLIT_MORE_PASSES: the retry rules tested */
#include "sim_model.h"

static char g_src[512];

/* the wrapped prepare: rejects steps of at least g_reject_from s (INFINITY: none) and counts
 * the steps of each size it sees (the test owns this state: one model at a time) */
static double g_reject_from = INFINITY;
static long g_calls_full, g_calls_half;
static double g_h_full;

static int prepareRejecting(csrLeg* leg, double h, const csrBaseState* b0, double Z[36],
                            double rho[6]) {
  if (h == g_h_full) {
    g_calls_full++;
  } else if (h == 0.5 * g_h_full) {
    g_calls_half++;
  }
  if (h >= g_reject_from) {
    return 1;
  }
  return csr_leg_strain.prepare(leg, h, b0, Z, rho);
}


/* the flat road as the scene sets it up, on strain legs of `type` (3 modes; 1 ms, the level's
 * step set here for the tests' own) */
static int loadModel(csModel* m, const csrLegType* type) {
  return csTestLoadFlatStrain(m, g_src, type, 1e-3, 3, 0, 0.0);
}




static int stepN(const csModel* m, csData* d, int n) {
  csError err;
  for (int i = 0; i < n; i++) {
    if (cs_step(m, d, &err) != CS_OK) {
      printf("  step at t = %g s: %s\n", cs_time(d), err.msg);
      return 0;
    }
  }
  return 1;
}


static int sameState(const csModel* m, const csData* a, const csData* b) {
  int n = cs_stateSize(m, a);
  double* xa = malloc(2 * (size_t)n * sizeof(double));
  if (!xa) {
    return 0;
  }
  cs_stateGet(m, a, xa);
  cs_stateGet(m, b, xa + n);
  int same = memcmp(xa, xa + n, (size_t)n * sizeof(double)) == 0;
  free(xa);
  return same;
}


static void test_strain_runs_through_the_driver_and_legs_carry_the_support(void) {
  csModel m;
  CS_EXPECT(loadModel(&m, &csr_leg_strain));
  CS_EXPECT(m.opt.coupling == CS_COUPLING_TREE && m.opt.macro_steps == 1);
  {
    /* the level sets its own step (loadModel then takes 1 ms) */
    csModel m0;
    cs_modelInit(&m0);
    m0.opt.macro_steps = 3;
    cs_modelSetLegLevel(&m0, &csr_leg_strain);
    CS_EXPECT(m0.opt.h == csr_leg_strain.step && m0.opt.macro_steps == 1 &&
              m0.opt.coupling == CS_COUPLING_TREE);
    cs_modelDestroy(&m0);
  }
  csData* d = csTestSettledData(&m);
  if (!d) {
    cs_modelDestroy(&m);
    return;
  }
  /* after settling (0.3 s, before the gait's first ramp moves anything): the legs' vertical
   * wrench against the support's weight; the support itself does not touch the road */
  double fy = 0;
  for (int k = 0; k < CSR_NLEG; k++) {
    csrWrench w;
    cs_legWrench(d, k, &w);
    fy += w.f[1];
  }
  double v[3], cf[3];
  cs_supportVelocity(d, v);
  cs_contactForce(d, cf);
  const double weight = m.robot.support_mass * m.opt.gravity;
  printf("  settled: legs' vertical force %.5f N, support weight %.5f N (%.3f %%), support "
         "speed %.3g mm/s, its own contact %.3g N, deepest foot %.4f mm\n", fy, weight,
         100 * (fy - weight) / weight, sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]), cf[1],
         cs_legContactDepth(&m, d));
  /* 1 %: what is left of the settling's 0.3 s transient (damped leg modes of ~100 Hz) */
  CS_EXPECT(fabs(fy - weight) < 0.01 * weight);
  CS_EXPECT(cf[1] == 0);
  /* the run file's /contact/foot_force and /contact/stance (cs_footForce, the level's
   * contactForce): standing, every foot carries, and the terrain's forces on the feet sum to
   * the legs' vertical wrench (weightless legs under `paper`: the same 1 % of the weight) */
  double ff[3] = {0, 0, 0};
  int stance = 0;
  for (int k = 0; k < CSR_NLEG; k++) {
    double f[3];
    cs_footForce(&m, d, k, f);
    for (int i = 0; i < 3; i++) {
      ff[i] += f[i];
    }
    stance += f[1] > cs_stanceForceThreshold(&m);
    printf("  foot %c: (%.5f, %.5f, %.5f) N\n", 'A' + k, f[0], f[1], f[2]);
  }
  printf("  feet: sum (%.5f, %.5f, %.5f) N, %d in stance (threshold %.4f N)\n", ff[0], ff[1],
         ff[2], stance, cs_stanceForceThreshold(&m));
  CS_EXPECT(stance == CSR_NLEG);
  CS_EXPECT(fabs(ff[1] - weight) < 0.01 * weight);
  /* and it runs on into the gait */
  CS_EXPECT(stepN(&m, d, 100));
  CS_EXPECT(cs_rejectCount(d) == 0);
  double x[3];
  cs_supportDisplacement(d, x);
  printf("  t = %.3f s: support (%.4f, %.4f, %.4f) mm, %ld steps\n", cs_time(d), x[0], x[1],
         x[2], cs_stepCount(d));
  CS_EXPECT(isfinite(x[0]) && isfinite(x[1]) && isfinite(x[2]));
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
}


/* Two datas stepped alike; then a data restored to a saved state and stepped on against the
 * same data not restored. With the pneumatic lag (CVODE) a restore restarts CVODE, whose step
 * history is not state (sim_model.h), so there the restored run is compared with itself
 * (restore, step; restore, step); with tau = 0 every part of the step is state and the
 * restored run must equal the unrestored one. */
static void restoreCase(double tau) {
  csModel m;
  CS_EXPECT(loadModel(&m, &csr_leg_strain));
  m.opt.pneumatic_tau = tau;
  csData* a = csTestSettledData(&m);
  csData* b = csTestSettledData(&m);
  const int n = a ? cs_stateSize(&m, a) : 0;
  double* x0 = n ? malloc(3 * (size_t)n * sizeof(double)) : NULL;
  if (!a || !b || !x0) {
    CS_EXPECT(0);
    free(x0);
    cs_dataDestroy(a);
    cs_dataDestroy(b);
    cs_modelDestroy(&m);
    return;
  }
  CS_EXPECT(sameState(&m, a, b));
  CS_EXPECT(stepN(&m, a, 60) && stepN(&m, b, 60));
  const int same = sameState(&m, a, b);
  CS_EXPECT(same);
  double* x1 = x0 + n;
  double* x2 = x0 + 2 * n;
  csError err;
  cs_stateGet(&m, a, x0);
  CS_EXPECT(stepN(&m, a, 40));
  if (tau > 0) {
    /* the reference is a restored run too (CVODE restarted) */
    CS_EXPECT(cs_stateSet(&m, a, x0, &err) == CS_OK);
    CS_EXPECT(stepN(&m, a, 40));
  }
  cs_stateGet(&m, a, x1);
  CS_EXPECT(cs_stateSet(&m, a, x0, &err) == CS_OK);
  /* the restored data reads as the state says: its legs are where b's are */
  double c0[3 * 25], c1[3 * 25];
  cs_legCenterline(&m, a, 0, 25, c0);
  cs_legCenterline(&m, b, 0, 25, c1);
  CS_EXPECT(memcmp(c0, c1, sizeof c0) == 0);
  CS_EXPECT(stepN(&m, a, 40));
  cs_stateGet(&m, a, x2);
  const int restored = memcmp(x1, x2, (size_t)n * sizeof(double)) == 0;
  CS_EXPECT(restored);
  printf("  tau %g s, %d doubles of state: two datas %s; restored and stepped 40 %s the %s\n",
         tau, n, same ? "bit-identical" : "DIFFER", restored ? "bit-identical to" : "DIFFERS from",
         tau > 0 ? "same restored again" : "unrestored run");
  free(x0);
  cs_dataDestroy(a);
  cs_dataDestroy(b);
  cs_modelDestroy(&m);
}


static void test_strain_repeats_and_restores_bit_identically(void) {
  restoreCase(0.0);
  restoreCase(0.02);
}


/* the horizontal drift of the centre of mass over 1 s of the gait with frictionless feet at
 * step h, and how far the support moved meanwhile (mm) */
static double gKeepMatrix = 0; /* the level's setting keep_matrix for the drift runs */
/* > 0: the drift runs take the adaptive step at this tolerance (mm), h its longest step */
static double gStepTol = 0;
static int gCarry = 0; /* csOptions.tree_carry for the drift runs */


static double frictionlessDriftOrder(double h, int passes, int order, double* moved) {
  csModel m;
  CS_EXPECT(loadModel(&m, &csr_leg_strain));
  m.contact.mu = 0;
  m.opt.h = h;
  m.opt.tree_iterations = passes;
  if (gKeepMatrix > 0) {
    CS_EXPECT(csr_legSettingSet(m.robot.leg_type, &m.robot.leg_settings, "keep_matrix",
                                gKeepMatrix, NULL) == CS_OK);
  }
  if (order > 0) { /* 0: the level's default */
    CS_EXPECT(csr_legSettingSet(m.robot.leg_type, &m.robot.leg_settings, "step_order", order,
                                NULL) == CS_OK);
  }
  if (gStepTol > 0) {
    m.opt.step_adaptive = 1;
    m.opt.step_tol = gStepTol;
  }
  m.opt.tree_carry = gCarry;
  csData* d = csTestSettledData(&m);
  if (!d) {
    cs_modelDestroy(&m);
    return NAN;
  }
  double c0[3], c1[3], x0[3], x1[3];
  *moved = 0;
  cs_robotCenterOfMass(&m, d, c0);
  cs_supportDisplacement(d, x0);
  for (int i = 0; i < 10; i++) {
    CS_EXPECT(stepN(&m, d, (int)lround(0.1 / h)));
    cs_supportDisplacement(d, x1);
    *moved = fmax(*moved, hypot(x1[0] - x0[0], x1[2] - x0[2]));
  }
  cs_robotCenterOfMass(&m, d, c1);
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  return hypot(c1[0] - c0[0], c1[2] - c0[2]);
}


static double frictionlessDrift(double h, int passes, double* moved) {
  return frictionlessDriftOrder(h, passes, 0, moved);
}


/* Frictionless feet: nothing pushes the robot horizontally (the support does not touch the
 * road), so its centre of mass stays but for the step's momentum error. The legs' Newton
 * passes close their linear rows in a discrete momentum form, and the support's ODE step
 * x1 = x0 + h v1 is the same form, so what the support takes from the legs each step must be
 * what they balanced: their impulse exact at the iterate (cs_couplingApplyTree's
 * treeAtIterate: the hip's twist change with the arm turned, the leg's rows in the iterate's
 * frame) and ODE landing on the solved twist (the gyroscopic torque the solve's). Before those
 * (docs/notes/strain_leg.md, "Drift") the drift was first order, 1.21e-3 / 6.04e-4 mm at 2 / 1
 * ms in this 1 s; then 7.2e-7 / 5.9e-8 mm at tree_tol 1e-7, and 2.7e-6 / 1.1e-5 mm at the
 * default 1e-6 since 2026-12-06 (what is left is the passes' tolerance: a move below tree_tol
 * left unresolved per step, so the bound scales with it). One linearised pass
 * (tree_iterations 1) still drifts at first order (the leg's velocity products at the step's
 * start: 1.4e-2 mm at 1 ms). The bounds: 1e-4 mm in 1 s at both steps (the 0.01 mm in
 * 9 s is 1.1e-3 mm per s), and one pass at least 100 times more than Newton at 1 ms. */
static void test_strain_frictionless_centre_of_mass_stays(void) {
  double moved2, moved1, moved1p;
  const double d2 = frictionlessDrift(2e-3, 16, &moved2);
  const double d1 = frictionlessDrift(1e-3, 16, &moved1);
  const double d1p = frictionlessDrift(1e-3, 1, &moved1p);
  printf("  frictionless, 1 s of the gait: the support moved up to %.2f / %.2f mm, the centre of "
         "mass %.3e / %.3e mm horizontally at h = 2 / 1 ms; one pass at 1 ms %.3e mm\n",
         moved2, moved1, d2, d1, d1p);
  /* the support must have moved for this to mean anything */
  CS_EXPECT(moved1 > 5 && moved2 > 5 && moved1p > 5);
  CS_EXPECT(d2 < 1e-4 && d1 < 1e-4);
  CS_EXPECT(d1p > 100 * d1);
}


/* The legs' iteration matrix kept across steps (keep_matrix 0.05) changes the passes, not the
 * step's momentum form: frictionless, 1 s of the gait at 1, 2 and 5 ms, the centre of mass stays
 * within the rate (0.01 mm in 9 s). Measured 2.4e-4 / 8.0e-5 / 1.8e-6 mm in this 1 s at
 * 1 / 2 / 5 ms (the default's 1.1e-5 / 2.7e-6 mm at 1 / 2 ms: a chord iteration stopped at the
 * same move leaves more of its residual, every step; docs/notes/strain_leg.md "A kept iteration
 * matrix"). */
static void test_strain_kept_matrix_keeps_momentum(void) {
  double moved1, moved2, moved5;
  gKeepMatrix = 0.05;
  const double d1 = frictionlessDrift(1e-3, 16, &moved1);
  const double d2 = frictionlessDrift(2e-3, 16, &moved2);
  const double d5 = frictionlessDrift(5e-3, 24, &moved5);
  gKeepMatrix = 0;
  printf("  keep_matrix 0.05, frictionless, 1 s of the gait: the support moved up to %.2f / %.2f "
         "/ %.2f mm, the centre of mass %.3e / %.3e / %.3e mm horizontally at h = 1 / 2 / 5 ms\n",
         moved1, moved2, moved5, d1, d2, d5);
  CS_EXPECT(moved1 > 5 && moved2 > 5 && moved5 > 5);
  CS_EXPECT(d1 < 0.01 / 9 && d2 < 0.01 / 9 && d5 < 0.01 / 9);
}


/* The strain level's default step (the adaptive step at 2.5e-4 mm, its longest 5 ms: cs_rundef.c
 * stepAdaptive) keeps the momentum form too: every step the controller takes inside a macro step
 * is a tree step like a fixed one, and a rejected one is rolled back whole. Frictionless, 1 s of
 * the gait, the centre of mass within the rate (0.01 mm in 9 s, per second); the fixed
 * steps' bound of 1e-4 mm in 1 s (above) is not asked here: the controller's steps reach 5 ms,
 * where the passes' tolerance leaves more per step (docs/notes/issue32_status.md has the
 * measured drift). */
static void test_strain_adaptive_step_keeps_momentum(void) {
  double moved;
  gStepTol = 2.5e-4;
  const double d = frictionlessDrift(5e-3, 16, &moved);
  gStepTol = 0;
  printf("  the adaptive step (2.5e-4 mm, longest 5 ms), frictionless, 1 s of the gait: the "
         "support moved up to %.2f mm, the centre of mass %.3e mm horizontally\n", moved, d);
  CS_EXPECT(moved > 5);
  CS_EXPECT(d < 0.01 / 9);
}


/* One linearised pass per step (tree_iterations 1) on the default's adaptive step: the legs'
 * discrete momentum is not their linear model's (Σ m x is not linear in the strains), and
 * without the carry the frictionless centre of mass drifts 1.9e-2 mm in 1 s, 17x the issue's
 * rate; with the legs' residual carried into the support's next step (tree_carry) 1.7e-4 mm
 * (docs/notes/strain_leg.md "event17", "carry18"; robot/strain/robot_strain_carry.c). Both are
 * asserted: the carry is what meets the bound. */
static void test_strain_one_pass_carry_keeps_momentum(void) {
  double moved0, moved1;
  gStepTol = 2.5e-4;
  const double d0 = frictionlessDrift(5e-3, 1, &moved0);
  gCarry = 1;
  const double d1 = frictionlessDrift(5e-3, 1, &moved1);
  gCarry = 0;
  gStepTol = 0;
  printf("  one linearised pass, the adaptive step (2.5e-4 mm), frictionless, 1 s of the gait: "
         "the support moved up to %.2f / %.2f mm, the centre of mass %.3e mm without the carry, "
         "%.3e mm with it\n", moved0, moved1, d0, d1);
  CS_EXPECT(moved0 > 5 && moved1 > 5);
  CS_EXPECT(d0 > 0.01 / 9);
  CS_EXPECT(d1 < 0.01 / 9);
}


/* A run of m settled, stepped 150 steps, saved, stepped 20, restored and stepped 20 again,
 * against one stepped 170 straight: 1 bit-identical, 0 not (what printed with `what`); the model
 * is destroyed. */
static int restoredRepeats(csModel* m, const char* what) {
  int same = 0;
  csData* a = csTestSettledData(m);
  csData* b = csTestSettledData(m);
  if (a && b) {
    const int n = cs_stateSize(m, a);
    double* x = malloc((size_t)n * sizeof(double));
    CS_EXPECT(x != NULL && stepN(m, a, 150) && stepN(m, b, 150));
    if (x) {
      cs_stateGet(m, a, x);
      CS_EXPECT(stepN(m, a, 20));
      csError err;
      CS_EXPECT(cs_stateSet(m, a, x, &err) == CS_OK);
      CS_EXPECT(stepN(m, a, 20) && stepN(m, b, 20));
      same = sameState(m, a, b);
      printf("  %s: restored after 150 steps of the gait and stepped 20: %s\n", what,
             same ? "bit-identical to the unrestored run" : "DIFFERENT");
    }
    free(x);
  }
  cs_dataDestroy(a);
  cs_dataDestroy(b);
  cs_modelDestroy(m);
  return same;
}


/* The largest impulse the one-pass carry hands the support in a step (|cosim.carry|, t mm/s)
 * over 1 s of the gait at 2 ms, with the paper's friction or frictionless. */
static double largestCarry(double mu) {
  csModel m;
  CS_EXPECT(loadModel(&m, &csr_leg_strain));
  if (mu >= 0) {
    m.contact.mu = mu;
  }
  m.opt.h = 2e-3;
  m.opt.tree_iterations = 1;
  m.opt.tree_carry = 1;
  csData* d = csTestSettledData(&m);
  double big = NAN;
  if (d) {
    big = 0;
    for (int i = 0; i < 500 && stepN(&m, d, 1); i++) {
      const double* c = d->cosim.carry;
      big = fmax(big, sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]));
    }
  }
  cs_dataDestroy(d);
  cs_modelDestroy(&m);
  return big;
}


/* The carry is the legs' discrete momentum against the one linear model the step solved, so
 * its contact term must be the force that model applied (robot_strain_carry.c): then what is
 * carried is Σ m x's nonlinearity in the strains, set by the motion and not by the contact
 * law, and friction leaves it the size it has frictionless. The shapes' ghosts evaluated at
 * the end state (the first form, event17) added the stick anchors' stiffness N/delta_t times
 * the end's kinematic error: measured in docs/notes/strain_leg.md "carry18". */
static void test_strain_one_pass_carry_is_the_model_force(void) {
  const double c0 = largestCarry(0);
  const double cf = largestCarry(-1);
  printf("  one pass with the carry at 2 ms, 1 s of the gait: the largest carried impulse "
         "%.3e t mm/s frictionless, %.3e with the friction (ratio %.2f)\n", c0, cf, cf / c0);
  CS_EXPECT(c0 > 0 && cf < 10 * c0);
}


/* The carry is the coupling's state (cs_couplingStateGet's `carry`): a run with tree_carry
 * restored mid-way repeats the unrestored one bit for bit (one linearised pass, 2 ms). */
static void test_strain_one_pass_carry_restores(void) {
  csModel m;
  CS_EXPECT(loadModel(&m, &csr_leg_strain));
  m.opt.h = 2e-3;
  m.opt.tree_iterations = 1;
  m.opt.tree_carry = 1;
  m.opt.pneumatic_tau = 0;
  CS_EXPECT(restoredRepeats(&m, "one pass with the carry at 2 ms"));
}


/* BDF2 through the driver (--step-order 2): the support's ODE step takes the legs' formula
 * (its pose set to BDF2's after the step), its history is in the coupling's state. Frictionless
 * at 2 ms the centre of mass stays as with backward Euler (measured 4.3e-7 mm in 1 s; 1.1e-7 with
 * the whole residual at every iterate, step_refresh 1 before branch bdf13), and a
 * run restored mid-way repeats the unrestored one bit for bit (tau 0). */
static void test_strain_bdf2_keeps_momentum_and_restores(void) {
  double moved;
  const double d2 = frictionlessDriftOrder(2e-3, 16, 2, &moved);
  printf("  BDF2, frictionless, 1 s of the gait at 2 ms: the support moved up to %.2f mm, the "
         "centre of mass %.3e mm\n", moved, d2);
  CS_EXPECT(moved > 5);
  CS_EXPECT(d2 < 1e-5);
  csModel m;
  CS_EXPECT(loadModel(&m, &csr_leg_strain));
  CS_EXPECT(csr_legSettingSet(m.robot.leg_type, &m.robot.leg_settings, "step_order", 2, NULL) ==
            CS_OK);
  m.opt.h = 2e-3;
  m.opt.pneumatic_tau = 0;
  CS_EXPECT(restoredRepeats(&m, "BDF2 at 2 ms"));
}


static void test_strain_rejected_step_is_retried_in_halves(void) {
  csrLegType rejecting = csr_leg_strain;
  rejecting.prepare = prepareRejecting;
  csModel m, m_ref;
  CS_EXPECT(loadModel(&m, &rejecting) && loadModel(&m_ref, &csr_leg_strain));
  g_h_full = m.opt.h;
  g_reject_from = INFINITY;
  csData* d = csTestSettledData(&m);
  csData* ref = csTestSettledData(&m_ref);
  if (!d || !ref) {
    cs_dataDestroy(d);
    cs_dataDestroy(ref);
    cs_modelDestroy(&m);
    cs_modelDestroy(&m_ref);
    return;
  }
  CS_EXPECT(stepN(&m, d, 50) && stepN(&m_ref, ref, 50));
  CS_EXPECT(sameState(&m, d, ref)); /* the wrapper changes nothing by itself */
  /* every full step is rejected for 20 steps: each runs as two halves */
  g_reject_from = g_h_full;
  g_calls_full = g_calls_half = 0;
  const double t0 = cs_time(d);
  const long rej0 = cs_rejectCount(d), st0 = cs_stepCount(d);
  CS_EXPECT(stepN(&m, d, 20));
  CS_EXPECT(stepN(&m_ref, ref, 20));
  printf("  20 steps from t = %.3f s, full steps rejected: t = %.6f s, %ld steps, %ld rejected, "
         "prepares of h %ld and h/2 %ld\n", t0, cs_time(d), cs_stepCount(d) - st0,
         cs_rejectCount(d) - rej0, g_calls_full, g_calls_half);
  CS_EXPECT(cs_time(d) == cs_time(ref));
  CS_EXPECT(cs_stepCount(d) - st0 == 20 && cs_rejectCount(d) - rej0 == 20);
  CS_EXPECT(g_calls_half == 2 * 20 * CSR_NLEG);
  double x[3], xr[3];
  cs_supportDisplacement(d, x);
  cs_supportDisplacement(ref, xr);
  const double dev = sqrt((x[0] - xr[0]) * (x[0] - xr[0]) + (x[1] - xr[1]) * (x[1] - xr[1]) +
                          (x[2] - xr[2]) * (x[2] - xr[2]));
  printf("  support after the halved steps vs unrejected: %.3g mm apart (x %.4f / %.4f mm)\n",
         dev, x[0], xr[0]);
  /* 0.05 mm: the support moves ~0.1 mm over these 20 ms; halving the step changes its track
   * by the step's first-order error, a fraction of that */
  CS_EXPECT(dev < 0.05);
  /* every size rejected: the step fails after CS_MAX_SPLIT halvings and changes nothing */
  g_reject_from = 0;
  const int n = cs_stateSize(&m, d);
  double* before = malloc(2 * (size_t)n * sizeof(double));
  CS_EXPECT(before != NULL);
  if (before) {
    cs_stateGet(&m, d, before);
    const long rej1 = cs_rejectCount(d), st1 = cs_stepCount(d);
    csError err;
    cs_errorClear(&err);
    CS_EXPECT(cs_step(&m, d, &err) == CS_ERR_REJECTED);
    cs_stateGet(&m, d, before + n);
    const int unchanged = memcmp(before, before + n, (size_t)n * sizeof(double)) == 0;
    CS_EXPECT(unchanged);
    CS_EXPECT(cs_stepCount(d) == st1 && cs_rejectCount(d) > rej1);
    printf("  rejected at every size: %s, %ld tries rejected, state unchanged: %s\n", err.msg,
           cs_rejectCount(d) - rej1, unchanged ? "yes" : "NO");
    free(before);
  }
  /* and it goes on when the legs accept again */
  g_reject_from = INFINITY;
  CS_EXPECT(stepN(&m, d, 5));
  /* Newton passes that do not converge (2 allowed, a tolerance no move meets): every try is
   * rejected after exactly its 2 passes, from halving CS_SPLIT_MORE_PASSES on after twice
   * that, 4; the first half of every size fails, so one try per size, CS_MAX_SPLIT + 1; the
   * step fails as above and changes nothing */
  {
    double* y = malloc(2 * (size_t)n * sizeof(double));
    CS_EXPECT(y != NULL);
    if (y) {
      m.opt.tree_iterations = 2;
      m.opt.tree_tol = 1e-300;
      cs_stateGet(&m, d, y);
      const long rej1 = cs_rejectCount(d), pass1 = cs_treePassCount(d);
      csError err;
      cs_errorClear(&err);
      CS_EXPECT(cs_step(&m, d, &err) == CS_ERR_REJECTED);
      cs_stateGet(&m, d, y + n);
      const int unchanged = memcmp(y, y + n, (size_t)n * sizeof(double)) == 0;
      const long tries = cs_rejectCount(d) - rej1, passes = cs_treePassCount(d) - pass1;
      printf("  Newton not converged: %s; %ld tries, %ld passes, state unchanged: %s\n",
             err.msg, tries, passes, unchanged ? "yes" : "NO");
      const long deep = CS_MAX_SPLIT - CS_SPLIT_MORE_PASSES + 1; /* tries with 4 passes */
      CS_EXPECT(unchanged && tries == CS_MAX_SPLIT + 1 && passes == 2 * (tries - deep) + 4 * deep);
      CS_EXPECT(strstr(err.msg, "did not converge in 4 Newton passes") != NULL);
      m.opt.tree_iterations = 16;
      m.opt.tree_tol = 1e-7;
      CS_EXPECT(stepN(&m, d, 2));
      free(y);
    }
  }
  cs_dataDestroy(d);
  cs_dataDestroy(ref);
  cs_modelDestroy(&m);
  cs_modelDestroy(&m_ref);
}


/* The level's basis settings (joints, shear, sub: robot_strain_leg.c) reach the legs: rigid
 * joints, Kirchhoff segments and 2 sub-intervals per segment take a leg of the default joints
 * and shears at 4 sub-intervals (set here: the level's default is 2) from 42 unknowns, 13
 * capsules to 24 and 7 (robot_strain.h: a segment's bending 2 x 3 modes and twist and stretch,
 * 4 with the shears; a joint's constant curvature 2 and its 4 axial; the capsules one per
 * sub-interval but the foot's, 4 history doubles each, the constant pieces one), so each leg's
 * state (4 n + the contact's history + 16 + the hip's 18: csr_strainStateSize, BDF2's history
 * holding a second q, η) shrinks by 4 x 18 + 6 x 4 = 96 doubles; the lean legs then step through
 * the driver; a value outside a setting's range is refused. */
static void test_strain_basis_settings_change_the_legs(void) {
  const csrLegType* type = &csr_leg_strain;
  csModel m, ml;
  int ok = loadModel(&m, type);
  ok = loadModel(&ml, type) && ok;
  CS_EXPECT(ok);
  if (!ok) {
    return;
  }
  csError err;
  cs_errorClear(&err);
  CS_EXPECT(csr_legSettingSet(type, &m.robot.leg_settings, "sub", 4, &err) == CS_OK);
  CS_EXPECT(csr_legSettingSet(type, &ml.robot.leg_settings, "joints", -1, &err) == CS_OK);
  CS_EXPECT(csr_legSettingSet(type, &ml.robot.leg_settings, "shear", 0, &err) == CS_OK);
  CS_EXPECT(csr_legSettingSet(type, &ml.robot.leg_settings, "sub", 2, &err) == CS_OK);
  CS_EXPECT(csr_legSettingSet(type, &ml.robot.leg_settings, "joints", -2, &err) != CS_OK);
  CS_EXPECT(csr_legSettingSet(type, &ml.robot.leg_settings, "sub", -1, &err) != CS_OK);
  CS_EXPECT(csr_legSettingSet(type, &ml.robot.leg_settings, "shear", 2, &err) != CS_OK);
  csData* d = csTestSettledData(&m);
  csData* dl = csTestSettledData(&ml);
  if (d && dl) {
    const int n = cs_stateSize(&m, d), nl = cs_stateSize(&ml, dl);
    printf("  state: %d doubles at 4 sub-intervals, %d with rigid joints, no shear, 2 "
           "sub-intervals\n", n, nl);
    CS_EXPECT(n - nl == CSR_NLEG * 96);
    CS_EXPECT(stepN(&ml, dl, 50));
  }
  cs_dataDestroy(d);
  cs_dataDestroy(dl);
  cs_modelDestroy(&m);
  cs_modelDestroy(&ml);
}


/* The setting sub's default (0) stands for 2 sub-intervals per flexible piece at 2 bending modes
 * per segment and 4 at 3 (csr_strainSubIntervals): each leg's state is the one the explicit
 * count gives, and 2 against 4 differ by the capsules' history (one capsule per sub-interval, 4
 * history doubles each; the joints' constant curvature takes one sub-interval whatever sub is,
 * robot_strain.c, so only the 3 segments count: 8 legs x 3 x 2 capsules x 4 = 192 doubles) */
static void test_strain_default_sub_intervals_follow_the_basis(void) {
  const csrLegType* type = &csr_leg_strain;
  int size[2][3] = {{0}}; /* [links 2, 3][default, 2, 4] */
  const int sub[3] = {-1, 2, 4};
  for (int l = 0; l < 2; l++) {
    for (int k = 0; k < 3; k++) {
      csModel m;
      if (!csTestLoadFlatStrain(&m, g_src, type, 1e-3, 2 + l, 0, 0.0)) {
        CS_EXPECT(0);
        continue;
      }
      csError err;
      if (sub[k] > 0) {
        CS_EXPECT(csr_legSettingSet(type, &m.robot.leg_settings, "sub", sub[k], &err) == CS_OK);
      }
      csData* d = cs_dataCreate(&m, &err);
      CS_EXPECT(d != NULL);
      if (d) {
        size[l][k] = cs_stateSize(&m, d);
      }
      cs_dataDestroy(d);
      cs_modelDestroy(&m);
    }
  }
  printf("  state (doubles): links 2 default %d, sub 2 %d, sub 4 %d; links 3 default %d, sub 2 "
         "%d, sub 4 %d\n", size[0][0], size[0][1], size[0][2], size[1][0], size[1][1],
         size[1][2]);
  CS_EXPECT(size[0][0] == size[0][1] && size[0][0] > 0);
  CS_EXPECT(size[1][0] == size[1][2] && size[1][0] > 0);
  CS_EXPECT(size[0][2] - size[0][1] == CSR_NLEG * 3 * 2 * 4);
  CS_EXPECT(size[1][2] - size[1][1] == CSR_NLEG * 3 * 2 * 4);
  CS_EXPECT(csr_strainSubIntervals(2, 0) == 2 && csr_strainSubIntervals(3, 0) == 4 &&
            csr_strainSubIntervals(2, 3) == 3);
}


int main(int argc, char** argv) {
  const char* src = getenv("CS_SOURCE_DIR");
  snprintf(g_src, sizeof g_src, "%s", src ? src : ".");
  cs_testInit(argc, argv);
  dInitODE2(0);
  CS_RUN(test_strain_runs_through_the_driver_and_legs_carry_the_support);
  CS_RUN(test_strain_repeats_and_restores_bit_identically);
  CS_RUN(test_strain_rejected_step_is_retried_in_halves);
  CS_RUN(test_strain_frictionless_centre_of_mass_stays);
  CS_RUN(test_strain_adaptive_step_keeps_momentum);
  CS_RUN(test_strain_bdf2_keeps_momentum_and_restores);
  CS_RUN(test_strain_kept_matrix_keeps_momentum);
  CS_RUN(test_strain_one_pass_carry_keeps_momentum);
  CS_RUN(test_strain_one_pass_carry_restores);
  CS_RUN(test_strain_one_pass_carry_is_the_model_force);
  CS_RUN(test_strain_basis_settings_change_the_legs);
  CS_RUN(test_strain_default_sub_intervals_follow_the_basis);
  dCloseODE();
  return cs_testSummary();
}

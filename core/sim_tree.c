/* sim_tree.c: the tree coupling of tree-stepped legs (CS_COUPLING_TREE, `--coupling tree`, the
 * default of the strain level; sim_internal.h; the legs' prepare/update/iterate/finish are
 * csrLegType's, robot_leg.h).
 *
 * One linearly implicit step of h = H for the support and the legs together, solved as the tree
 * it is, so nothing lags: every leg condenses its step onto its hip (csrLegType.prepare: its
 * impulse on the support over the step is ρ - Z ΔV, ΔV the hip's twist change, world at the
 * hip), the support solves its backward-Euler step with Σ Tᵀ Z T and Σ Tᵀ ρ moved to its centre,
 * and every leg back-substitutes the support's actual motion (finish). That is the stabilised
 * scheme's solve (sim_coupling.c) with W0 = Σ ρ / h, A = Σ Tᵀ Z T / h, Kc = 0 and the
 * prediction the twist now: (M + Σ Tᵀ Z T) Δq' = h m g + Σ Tᵀ ρ, the force
 * F = (Σ Tᵀ ρ - Σ Tᵀ Z T Δq') / h handed to ODE, whose step lands on it up to the support's
 * gyroscopic term and its own terrain contacts (ODE resolves those with F held). A is not
 * projected onto passive gains (sim_coupling.c implicitPart): the legs' Z comes from their own
 * Newton matrix and the solve is the tree's own. The legs then finish with their hips' exact
 * body-twist change from the support's actual end state (the solve linearised it about the
 * start frame; robot_strain_leg.c). */
#include <math.h>
#include <string.h>

#include "core_math.h"
#include "sim_internal.h"

static void mat6Zero(double M[36]) { memset(M, 0, 36 * sizeof(double)); }


/* a leg's condensed step (Z, ρ at its hip, world) as the stabilised scheme's W0 and A: the
 * impulse as the wrench it averages to over the step, the impedance per h, summed into c->A */
static int treeGather(csData* d, int k, double h, double Z[36], const double rho[6],
                      csError* err) {
  csCosim* c = &d->cosim;
  for (int i = 0; i < 3; i++) {
    c->w[k].f[i] = rho[i] / h;
    c->w[k].m[i] = rho[3 + i] / h;
  }
  for (int i = 0; i < 36; i++) {
    Z[i] /= h;
  }
  if (cs_couplingCheckFinite(d, k, &c->w[k], Z, Z, err) != 0) {
    return 1;
  }
  double r[3];
  csu_sub3(r, c->b0[k].x, c->P0);
  cs_couplingAddAtCentre(c->A, Z, r);
  return 0;
}


int cs_couplingTreePrepare(const csModel* m, csData* d, double h, csError* err) {
  csCosim* c = &d->cosim;
  const csrLegType* type = m->robot.leg_type;
  cs_errorClear(err); /* whatever err holds after this came from these legs */
  csr_robotSupportPose(d->robot, c->P0, c->R0, c->v0, c->w0);
  c->t0 = d->t;
  /* the support's gyroscopic torque is the tree solve's (cs_couplingApplyTree), so that ODE's
   * step lands on the solved twist: with ODE's own (implicit) term the two differed by ~1e-8
   * rad/s per step, and the legs, finishing along ODE's twist, took an impulse the support did
   * not give (docs/notes/strain_leg.md, "Drift") */
  dBodySetGyroscopicMode(d->robot->support, 0);
  mat6Zero(c->Kc);
  mat6Zero(c->A);
  /* the legs' formula for this step (the same for all: they share their steps) */
  c->tb_c[0] = 1, c->tb_c[1] = 0, c->tb_c[2] = 1;
  if (type->stepCoeffs) {
    type->stepCoeffs(d->robot->legs[0], h, c->tb_c);
  }
  const double he = c->tb_c[2] * h;
  c->tb_h = h;
  for (int k = 0; k < CSR_NLEG; k++) {
    double Z[36], rho[6];
    csr_robotBaseStateAt(d->robot, k, c->P0, c->R0, c->v0, c->w0, &c->b0[k]);
    int rc = type->prepare(d->robot->legs[k], h, &c->b0[k], Z, rho);
    if (rc != 0) {
      cs_errorSet(err, rc > 0 ? CS_ERR_REJECTED : CS_ERR_SOLVER, "t = %.4f s: leg %c's step "
                  "of %g s %s (code %d)", d->t, 'A' + k, h,
                  rc > 0 ? "did not converge" : "failed", rc);
      return rc;
    }
    if (treeGather(d, k, he, Z, rho, err) != 0) {
      return 1;
    }
  }
  return 0;
}


/* BDF2's step (c->tb_c not backward Euler's) */
static int treeBdf(const csCosim* c) {
  return c->tb_c[0] != 1 || c->tb_c[1] != 0 || c->tb_c[2] != 1;
}


/* The legs' momentum residual carried (csOptions.tree_carry): one linearised pass of backward
 * Euler, a level that gives it. The carry is the coupling's `carry` (in the state, so a
 * rejected or restored step takes the one before it; Gauss-Seidel's own use of it is another
 * coupling's). Why: robot/strain/robot_strain_carry.c. */
static int treeCarry(const csModel* m, const csCosim* c) {
  return m->opt.tree_carry && m->opt.tree_iterations == 1 && !treeBdf(c) &&
         m->robot.leg_type->momentumResidual;
}


/* The support's end pose for its end twist q' = (v; ω) (world). Backward Euler: the centre
 * moved by h v, the rotation by exp(h [ω]) (ODE's own update to O(h² ω²)). BDF2 (the legs'
 * coefficients c, he = c2 h): P1 = c0 P0 + c1 P_-1 + he v, R1 = exp(c1 ψ_-1 + he ω) R0 with
 * ψ_-1 = log(R_-1 R0ᵀ), the formula on the rotation vector about R0 (its dexp⁻¹ correction
 * enters at O(h³)); the driver sets ODE's body there after its step (cs_couplingTreeFinish) */
static void treeEndPose(const csCosim* c, double h, const double qd1[6], double P1[3],
                        double R1[9]) {
  double phi[3], dR[9];
  if (!treeBdf(c)) {
    for (int i = 0; i < 3; i++) {
      P1[i] = c->P0[i] + h * qd1[i];
      phi[i] = h * qd1[3 + i];
    }
  } else {
    const double he = c->tb_c[2] * h;
    double RRt[9], R0t[9], psi[3];
    csu_transpose3(R0t, c->R0);
    csu_mulMat3(RRt, c->tb_R, R0t);
    csu_mat3ToRotVec(psi, RRt);
    for (int i = 0; i < 3; i++) {
      P1[i] = c->tb_c[0] * c->P0[i] + c->tb_c[1] * c->tb_P[i] + he * qd1[i];
      phi[i] = c->tb_c[1] * psi[i] + he * qd1[3 + i];
    }
  }
  csu_rotVecToMat3(dR, phi);
  csu_mulMat3(R1, dR, c->R0);
}


/* every hip's state at the end of the step for the support's end twist q' = (v; ω) (world), the
 * support at treeEndPose (the legs finish along ODE's actual end state) */
static void treeHipsAt(const csData* d, double h, const double qd1[6],
                       csrBaseState b[CSR_NLEG]) {
  const csCosim* c = &d->cosim;
  double P1[3], R1[9];
  treeEndPose(c, h, qd1, P1, R1);
  for (int k = 0; k < CSR_NLEG; k++) {
    csr_robotBaseStateAt(d->robot, k, P1, R1, qd1, qd1 + 3, &b[k]);
  }
}


/* An iterate's ρ made exact there: the leg's impulse is ρ - Z Δu for its hip's world twist
 * change Δu, and the leg linearised at the hip's exact end state b_it (treeHipsAt: the arm
 * turned with the support), where the support's solve maps its centre's twist change Δq to
 * the hip by T Δq with the arm at the step's start. The two differ at the iterate by
 * ω1 × (r1 - r0), O(h): left in, the support took a different impulse from the one the leg
 * balanced, and the frictionless centre of mass drifted at first order (docs/notes/
 * strain_leg.md, "Drift"). So ρ -= Z (Δu_it - T Δq_it): the support's linear model passes
 * through the leg's impulse at the iterate, Z its slope. */
static void treeAtIterate(const csCosim* c, int k, const double qd0[6], const double qit[6],
                          const csrBaseState* bit, const double Z[36], double rho[6]) {
  double r[3], dq[6], e[6], t[3];
  csu_sub3(r, c->b0[k].x, c->P0);
  for (int i = 0; i < 6; i++) {
    dq[i] = qit[i] - qd0[i];
  }
  /* e = Δu_it - T Δq_it: (Δv_hip - Δv_c - Δω × r0; Δω_hip - Δω) */
  csu_cross3(t, dq + 3, r);
  for (int i = 0; i < 3; i++) {
    e[i] = (bit->v[i] - c->b0[k].v[i]) - dq[i] - t[i];
    e[3 + i] = (bit->w[i] - c->b0[k].w[i]) - dq[3 + i];
  }
  for (int i = 0; i < 6; i++) {
    double s = 0;
    for (int j = 0; j < 6; j++) {
      s += Z[6 * i + j] * e[j];
    }
    rho[i] -= s;
  }
}


int cs_couplingApplyTree(const csModel* m, csData* d, double h, csError* err) {
  csCosim* c = &d->cosim;
  const csrLegType* type = m->robot.leg_type;
  cs_errorClear(err);
  double mass, Iw[9];
  cs_couplingSupportInertia(d, c->R0, &mass, Iw);
  double qd[6], gyro[6] = {0, 0, 0, 0, 0, 0}, F[6], qd1[6], qit[6];
  for (int i = 0; i < 3; i++) {
    qd[i] = c->v0[i];
    qd[3 + i] = c->w0[i];
  }
  /* ω × I ω at the start (explicit, as ODE's own would be without its implicit correction),
   * subtracted from the support's torque in the solve and handed to ODE with the rest */
  {
    double Iw0[3];
    csu_mulMatVec3(Iw0, Iw, c->w0);
    csu_cross3(gyro + 3, c->w0, Iw0);
  }
  /* BDF2 (the legs' formula, cs_couplingTreePrepare): the solve is backward Euler's with he =
   * c2 h for h and the history's q̄' = c0 q'0 + c1 q'_-1 for q'0 on the mass side:
   *   (M + he A) q'1 = M q̄' + he (m g + W0 - ω × I ω + A q'_pred) */
  const int bdf = treeBdf(c);
  const double he = c->tb_c[2] * h;
  double qbar[6], qm1[6];
  memcpy(qm1, c->tb_v, sizeof c->tb_v);
  memcpy(qm1 + 3, c->tb_w, sizeof c->tb_w);
  for (int i = 0; i < 6; i++) {
    qbar[i] = bdf ? c->tb_c[0] * qd[i] + c->tb_c[1] * qm1[i] : qd[i];
  }
  memcpy(qit, qd, sizeof qit);
  const int newton = m->opt.tree_iterations > 1 && type->update && type->iterate;
  const int carry = treeCarry(m, c);
  /* damping of the passes (as tests/robot/strain_test_robot.h): a pass whose full move did not
   * shrink below 0.9 of the last one's halves the next move (down to 1/8), a shrinking one
   * restores the full step; where a foot's stick/slip changes within the step the full
   * Newton step can cycle between the two sides */
  double alpha = 1, chg_last = INFINITY;
  int it = 0, released_late = 0;
  /* the halvings from CS_SPLIT_MORE_PASSES on (sim_internal.h; it was the last one): their
   * passes go on to twice the budget before the try is halved again or the run stops (the
   * earth collapse on strain legs at 0.853 s: a damped pass contracting at 0.5 a pass reached
   * 4.9e-6 mm at the 24th; docs/notes/strain_leg.md "The earth collapse") */
  const int pass_limit = h < 1.5 * d->h_try / (1 << CS_SPLIT_MORE_PASSES)
                             ? 2 * m->opt.tree_iterations : m->opt.tree_iterations;
  if (bdf && newton) {
    /* BDF2's first iterate where the support's twist is unchanged: the legs back-substitute
     * their hips' end states for it (treeEndPose of q'0) and linearise there, so the first
     * solve sees the legs and the support at one consistent end of the step (prepare left
     * the legs' bases at the start, a first residual of their whole momentum) */
    csrBaseState bp[CSR_NLEG];
    treeHipsAt(d, h, qd, bp);
    mat6Zero(c->A);
    for (int k = 0; k < CSR_NLEG; k++) {
      double Z[36], rho[6], ck = 0;
      int rc = type->update(d->robot->legs[k], &bp[k], 1.0, NULL, &ck);
      if (rc == 0) {
        rc = type->iterate(d->robot->legs[k], Z, rho);
      }
      if (rc != 0) {
        cs_errorSet(err, rc > 0 ? CS_ERR_REJECTED : CS_ERR_SOLVER, "t = %.4f s: leg %c's "
                    "first BDF2 iterate %s (code %d)", d->t, 'A' + k,
                    rc > 0 ? "left its valid range" : "failed", rc);
        return rc;
      }
      treeAtIterate(c, k, qd, qd, &bp[k], Z, rho);
      if (treeGather(d, k, he, Z, rho, err) != 0) {
        return 1;
      }
    }
    c->tree_passes++;
  }
  for (;;) {
    /* W0 at the centre from the hips where the step started (prepare's and iterate's frame) */
    double W0[6] = {0, 0, 0, 0, 0, 0};
    for (int k = 0; k < CSR_NLEG; k++) {
      double r[3], rxf[3];
      csu_sub3(r, c->b0[k].x, c->P0);
      csu_cross3(rxf, r, c->w[k].f);
      for (int i = 0; i < 3; i++) {
        W0[i] += c->w[k].f[i];
        W0[3 + i] += c->w[k].m[i] + rxf[i];
      }
    }
    /* the legs' momentum residual of the last step (tree_carry; cs_couplingTreeFinish): the
     * support takes it as an impulse over this step */
    for (int i = 0; carry && i < 3; i++) {
      W0[i] -= c->carry[i] / he;
    }
    /* Kc = 0 and the prediction the twist now: (M + Σ Tᵀ Z T) Δq' = h m g + Σ Tᵀ ρ, the tree's
     * own equation (robot_leg.h prepare), and F = (Σ Tᵀ ρ - Σ Tᵀ Z T Δq') / h. Its linear rows
     * are already the discrete momentum balance the legs' iterations use (robot_strain.h):
     * in the world frame at the support's centre of mass, ODE's step x1 = x0 + h v1 makes
     * m (v1 - v0) = m (x1 - x0) / h - D with D = m (x0 - x_prev) / h the last step's */
    if (cs_couplingSupportSolve(d, he, mass, Iw, qbar, W0, gyro, c->A, qd, F, qd1) != 0) {
      cs_errorSet(err, CS_ERR_REJECTED, "t = %.4f s: the support's condensed step matrix is "
                  "singular", d->t);
      return 1;
    }
    if (!newton) {
      c->tree_passes++;
      break;
    }
    /* the iterate: the support's end twist moved alpha of the way, every leg back-substitutes
     * its hip's end state (its full move measured against the last iterate) */
    double qa[6], chg = 0;
    csrBaseState b1[CSR_NLEG], b1a[CSR_NLEG];
    treeHipsAt(d, h, qd1, b1);
    /* the legs' globalisation (robot_leg.h stepLimit): the whole tree's move damped by the
     * least fraction any leg allows; the damping's memory (alpha) is not changed by it */
    double amove = alpha;
    for (int k = 0; it > 0 && type->stepLimit && k < CSR_NLEG; k++) {
      amove = fmin(amove, type->stepLimit(d->robot->legs[k], &b1[k]));
    }
    if (amove < alpha) {
      c->tree_limited++;
    }
    for (int i = 0; i < 6; i++) {
      chg = fmax(chg, h * fabs(qd1[i] - qit[i]));
      qa[i] = qit[i] + amove * (qd1[i] - qit[i]);
    }
    if (amove < 1) {
      treeHipsAt(d, h, qa, b1a);
    }
    for (int k = 0; k < CSR_NLEG; k++) {
      double ck = 0;
      int rc = type->update(d->robot->legs[k], &b1[k], amove, amove < 1 ? &b1a[k] : NULL,
                            &ck);
      if (rc != 0) {
        cs_errorSet(err, rc > 0 ? CS_ERR_REJECTED : CS_ERR_SOLVER, "t = %.4f s: leg %c's "
                    "Newton pass %d %s (code %d)", d->t, 'A' + k, it + 1,
                    rc > 0 ? "is not finite" : "failed", rc);
        return rc;
      }
      chg = fmax(chg, ck);
    }
    memcpy(qit, qa, sizeof qit);
    const csrBaseState* bit = amove < 1 ? b1a : b1;
    it++;
    c->tree_passes++;
    /* converged: this move is below the tolerance. (Accepting when the contracting passes'
     * estimated remaining move, chg rate / (1 - rate), is below it saved 6 % of the passes
     * but left each step's momentum rows unconverged by up to that much: the frictionless
     * centre of mass then drifted 1.9e-4 mm per s instead of 3e-7; docs/notes/strain_leg.md).
     * In the retry of a rejected step (h below the macro step), past half the passes allowed,
     * a shrinking move keeps the damping instead of restoring the full step: a foot on a
     * nonsmooth point of the law (a stick/slip, a landing) can hold the full and the halved
     * moves in a cycle (2.0, 2.4, 0.94, 0.54, 2.0 ... e-4 mm, period four, at every halving
     * of the step down to 1/16: the obstacle on strain legs stopped at 26.846 s; docs/notes/
     * strain_leg.md "The obstacle's stop"). Applied to every step it rejected more steps of
     * the flat road (11 against 2 at 5 ms), so steps at the macro step are as before */
    const int keep_damping = it > m->opt.tree_iterations / 2 && h <= 0.75 * d->h_try;
    if (it > 1 && chg > 0.9 * chg_last) {
      alpha = fmax(0.125, 0.5 * alpha);
    } else if (!keep_damping) {
      alpha = 1.0;
    } else if (released_late && it > 1 && chg < (1 - 0.5 * alpha) * chg_last) {
      /* after such a release the damped passes contracted at about 1 - alpha (0.73-0.78 at
       * 1/4: the Newton direction right, the full move overshooting): a move that shrinks at
       * least that well doubles the fraction (applied without a release it stopped the earth
       * run at 0.824 s again) */
      alpha = fmin(1.0, 2 * alpha);
    }
    chg_last = chg;
    if (it > 1 && chg <= m->opt.tree_tol) {
      /* converged; a leg that held a contact shape by its ghost (robot_leg.h release) drops
       * it and the passes go on from here, undamped, so the step that ends is the law's */
      int released = 0;
      for (int k = 0; type->release && k < CSR_NLEG; k++) {
        released += type->release(d->robot->legs[k]);
      }
      if (released == 0) {
        break;
      }
      c->tree_released += released;
      /* the same rule after a release: a retried step's passes past half go on damped (the
       * earth collapse on strain legs at 0.824 s: leg D's converged pass released a capsule
       * held by its ghost, the full moves after it grew 4e-5 -> 6e-5 mm and the step ran out
       * of passes at every halving; docs/notes/strain_leg.md "The earth collapse") */
      if (!keep_damping) {
        alpha = 1.0;
      }
      chg_last = INFINITY;
      released_late = keep_damping;
    }
    if (it >= pass_limit) {
      cs_errorSet(err, CS_ERR_REJECTED, "t = %.4f s: the tree step of %g s did not converge "
                  "in %d Newton passes (last move %.3g mm)", d->t, h, it, chg);
      return 1;
    }
    /* every leg linearises again at the iterate; the support's sums anew */
    mat6Zero(c->A);
    for (int k = 0; k < CSR_NLEG; k++) {
      double Z[36], rho[6];
      int rc = type->iterate(d->robot->legs[k], Z, rho);
      if (rc != 0) {
        cs_errorSet(err, rc > 0 ? CS_ERR_REJECTED : CS_ERR_SOLVER, "t = %.4f s: leg %c's "
                    "Newton pass %d %s (code %d)", d->t, 'A' + k, it + 1,
                    rc > 0 ? "left its valid range" : "failed", rc);
        return rc;
      }
      treeAtIterate(c, k, qd, qit, &bit[k], Z, rho);
      if (treeGather(d, k, he, Z, rho, err) != 0) {
        return 1;
      }
    }
  }
  if (bdf) {
    /* ODE steps v1 = v0 + h (F + m g) / m (its gyroscopic term off): the force that lands on
     * the solved twist; its position update is replaced by BDF2's in cs_couplingTreeFinish */
    dVector3 grav;
    dWorldGetGravity(d->world, grav);
    const int gmode = dBodyGetGravityMode(d->robot->support);
    double dw[3];
    for (int i = 0; i < 3; i++) {
      F[i] = mass * (qd1[i] - qd[i]) / h - (gmode ? mass * grav[i] : 0);
      dw[i] = (qd1[3 + i] - qd[3 + i]) / h;
    }
    csu_mulMatVec3(F + 3, Iw, dw);
  }
  dBodyAddForce(d->robot->support, F[0], F[1], F[2]);
  dBodyAddTorque(d->robot->support, F[3], F[4], F[5]);
  return 0;
}


int cs_couplingTreeFinish(const csModel* m, csData* d, csError* err) {
  csCosim* c = &d->cosim;
  const csrLegType* type = m->robot.leg_type;
  cs_errorClear(err);
  double P1[3], R1[9], v1[3], w1[3];
  csr_robotSupportPose(d->robot, P1, R1, v1, w1);
  if (treeBdf(c)) {
    /* BDF2's pose for ODE's end twist (treeEndPose) in place of ODE's x0 + h v1 */
    double qd1[6];
    memcpy(qd1, v1, sizeof v1);
    memcpy(qd1 + 3, w1, sizeof w1);
    treeEndPose(c, c->tb_h, qd1, P1, R1);
    dMatrix3 Rd;
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        Rd[4 * i + j] = R1[3 * i + j];
      }
      Rd[4 * i + 3] = 0;
    }
    dBodySetPosition(d->robot->support, P1[0], P1[1], P1[2]);
    dBodySetRotation(d->robot->support, Rd);
    /* R from the body's quaternion, as ODE's own step leaves it and a restored state sets
     * it: otherwise a restored run differs in the last bits */
    const dReal* qb = dBodyGetQuaternion(d->robot->support);
    dQuaternion qq = {qb[0], qb[1], qb[2], qb[3]};
    dBodySetQuaternion(d->robot->support, qq);
    csr_robotSupportPose(d->robot, P1, R1, v1, w1);
  }
  /* the history for the next step's formula */
  memcpy(c->tb_P, c->P0, sizeof c->tb_P);
  memcpy(c->tb_R, c->R0, sizeof c->tb_R);
  memcpy(c->tb_v, c->v0, sizeof c->tb_v);
  memcpy(c->tb_w, c->w0, sizeof c->tb_w);
  for (int k = 0; k < CSR_NLEG; k++) {
    csr_robotBaseStateAt(d->robot, k, P1, R1, v1, w1, &c->b1[k]);
    int rc = type->finish(d->robot->legs[k], &c->b1[k], &c->w[k]);
    if (rc != 0) {
      cs_errorSet(err, rc > 0 ? CS_ERR_REJECTED : CS_ERR_SOLVER, "t = %.4f s: leg %c's step "
                  "%s (code %d)", d->t, 'A' + k,
                  rc > 0 ? "left its valid range (a foot sunk past its bound or a non-finite "
                  "pose)" : "failed", rc);
      return rc;
    }
    if (cs_couplingCheckFinite(d, k, &c->w[k], NULL, NULL, err) != 0) {
      return 1;
    }
  }
  if (treeCarry(m, c)) {
    double e[3] = {0, 0, 0};
    for (int k = 0; k < CSR_NLEG; k++) {
      double ek[3];
      if (type->momentumResidual(d->robot->legs[k], ek) != 0) {
        cs_errorSet(err, CS_ERR_SOLVER, "t = %.4f s: leg %c has no momentum residual for "
                    "tree_carry", d->t, 'A' + k);
        return -1;
      }
      csu_add3(e, e, ek);
    }
    memcpy(c->carry, e, sizeof e);
  }
  return 0;
}

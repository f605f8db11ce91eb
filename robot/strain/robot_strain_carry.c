/* robot_strain_carry.c: the leg's discrete linear momentum residual of its last step by that
 * step's linear model (robot_strain.h csr_strainMomentumResidual, robot_leg.h
 * momentumResidual), for the tree step's one linearised pass with the residual carried
 * (csOptions.tree_carry, core/sim_tree.c).
 *
 * Why. The tree step's Newton passes drive every leg's base rows of linear momentum, in the
 * discrete form (robot_strain_condense.c momentumRows)
 *   R = (X1 - X0) / h - D_prev - h (m g + f_c + f_tip) - J_hip,
 * X = Σ m x the leg's mass moment (world, t mm), D_prev the last step's (X0 - X_-1) / h, J_hip
 * the hip's impulse on the leg, to below tree_tol. One linearised pass solves R's linear model
 * exactly, so the support and the leg exchange one impulse, but X(q) is not linear in q and
 * the leg's committed D = (X1 - X0) / h differs from the model's by O(h |u|²) a step: left
 * alone the frictionless centre of mass drifts 17x the rate (test_strain_driver
 * `one_pass_carry_keeps_momentum`). The residual, handed to the support in its next step,
 * conserves the robot's discrete momentum up to one step's lag.
 *
 * The contact force in R is the one the step's linear model applied, exactly: the start's
 * assembly (robot_strain_contact.c csr_strainContactAssemble_, du NULL) gives each touching
 * shape's load as L1 = L(y_p) + K_y (y_q - y_p) + A S Δu (A = h K_y + C_y, y_p the slid
 * prediction, y_q the shape's predicted end) and records Σ of its force rows, fcl + fcA Δu;
 * with the solved Δu (d->du, which the finish leaves) that is the impulse / h the leg's base
 * rows balanced, so R is the kinematic nonlinearity of Σ m x alone. Any other force (the
 * shapes' linearisation re-evaluated at the end state, or the law there) puts the contact's
 * linearisation error times the stick anchors' stiffness into the carry, lagged a step: the
 * paper's table, whose feet slide, then leaves the rod's track (docs/notes/strain_leg.md
 * "event17", "carry18"). A kept matrix's start (keep_matrix) assembles no linear model of its
 * own, so the level gives no residual there.
 *
 * Units: mm, s, N (t mm/s^2); the residual is an impulse (t mm/s, N s). */
#include <string.h>

#include "core_math.h"
#include "robot_strain_internal.h"


int csr_strainMomentumResidual(const csrStrainModel* m, const csrStrainData* d, double eps[3]) {
  memset(eps, 0, 3 * sizeof(double));
  /* a committed backward-Euler step (hprev its length): BDF2's D is the formula's, not this */
  if (!(d->hprev > 0) || m->par.step_order != 1) {
    return -1;
  }
  /* the contact's linear model is the active set's (robot_strain_contact.c), recorded by this
   * step's own start assembly (not a kept matrix's) */
  if (m->soft && (!m->par.active_set || m->par.keep_matrix || !d->fcl_ok)) {
    return -1;
  }
  const double h = d->hprev;
  /* the contact force the step's one linear model applied: its affine load at the start and
   * A S Δu of the solved Δu (d->du, kept by the finish), recorded by the start's assembly */
  const int nu = 6 + m->n;
  double fc[3] = {0, 0, 0};
  for (int i = 0; m->soft && i < 3; i++) {
    double t = d->fcl[i];
    for (int k = 0; k < nu; k++) {
      t += d->fcA[i * nu + k] * d->du[k];
    }
    fc[i] = t;
  }
  /* commit moved D on (robot_strain_dyn.c csr_strainCommit): d->Dm the step's (X1 - X0) / h,
   * d->Dm1 the one before; the hip's impulse on the leg is -h wbase.f (wbase the leg's force
   * on the support averaged over the step, csr_strainUpdateDamped) */
  for (int i = 0; i < 3; i++) {
    eps[i] = (d->Dm[i] - d->Dm1[i]) -
             h * (m->gravity[i] * m->mass + fc[i] + d->tipd_f[i]) + h * d->wbase.f[i];
  }
  return 0;
}

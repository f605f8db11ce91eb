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
 * The contact force in R is the step's linear model's at the end (the shapes' last
 * linearisations, csr_strainContactLinForce_): the model's impulse, which the support already
 * balanced. The law evaluated at the end (its nonlinearity and the friction's return mapping)
 * instead put the contact's linearisation error into the carry, lagged a step, and moved the
 * obstacle's first 4 s 5x further off the default (docs/notes/strain_leg.md "event17").
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
  /* the contact's linear model is the active set's ghosts (robot_strain_contact.c) */
  if (m->soft && !m->par.active_set) {
    return -1;
  }
  const double h = d->hprev;
  double fc[3];
  csr_strainContactLinForce_(m, d, fc);
  /* commit moved D on (robot_strain_dyn.c csr_strainCommit): d->Dm the step's (X1 - X0) / h,
   * d->Dm1 the one before; the hip's impulse on the leg is -h wbase.f (wbase the leg's force
   * on the support averaged over the step, csr_strainUpdateDamped) */
  for (int i = 0; i < 3; i++) {
    eps[i] = (d->Dm[i] - d->Dm1[i]) -
             h * (m->gravity[i] * m->mass + fc[i] + d->tipd_f[i]) + h * d->wbase.f[i];
  }
  return 0;
}

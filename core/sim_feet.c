/* sim_feet.c: the terrain's force on each leg and its stance state (see sim_model.h
 * cs_footForce, cs_stanceForceThreshold): the run file's per-foot series (issue 36). */
#include <math.h>
#include <string.h>

#include "sim_internal.h"

/* the legs that carry the support in the paper's gaits (two groups of four alternate) */
static const double kStanceLegs = 4.0;
/* the share of one stance leg's load below which a contact is grazing, not standing */
static const double kStanceShare = 0.1;


void cs_footForce(const csModel* m, const csData* d, int k, double f[3]) {
  f[0] = f[1] = f[2] = 0.0;
  if (k < 0 || k >= CSR_NLEG) {
    return;
  }
  const csrLegType* lt = m->robot.leg_type;
  if (lt->in_world) {
    memcpy(f, d->leg_contact_force[k], 3 * sizeof(double));
  } else if (lt->contactForce) {
    lt->contactForce(d->robot->legs[k], f);
  }
}


double cs_stanceForceThreshold(const csModel* m) {
  /* support mass t x gravity mm/s^2 = N */
  return kStanceShare * m->robot.support_mass * fabs(m->opt.gravity) / kStanceLegs;
}

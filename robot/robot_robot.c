/* robot_robot.c: robot assembly (see robot_robot.h). */
#include "robot_robot.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"


csStatus csr_robotDefaultModel(csrRobotModel* m, csError* err) {
  memset(m, 0, sizeof *m);
  csStatus st = csr_actuatorPreset(&m->leg, "leg", err);
  if (st != CS_OK) {
    return st;
  }
  m->leg_params = csr_defaultLegParams(&m->leg);
  m->leg_type = &csr_leg_prb;
  /* assumption: the paper says only "lightweight"; 50 g for a 210 x 145 mm printed frame */
  m->support_mass = 50e-6;
  /* 210 mm long (paper); 10 mm thick; as wide as the two rows of legs (130 + 15 mm) */
  m->support_size[0] = 210;
  m->support_size[1] = 10;
  m->support_size[2] = 145;
  m->l_EF = 50;
  m->l_AE = 130;
  return CS_OK;
}


void csr_robotHipOffset(const csrRobotModel* m, int k, double off[3]) {
  int row = k / 4;  /* 0: A..D, 1: E..H */
  int col = k % 4;  /* 0 = front */
  off[0] = (1.5 - col) * m->l_EF;
  off[1] = 0;
  off[2] = (row == 0 ? -0.5 : 0.5) * m->l_AE;
}


csrRobot* csr_robotCreate(const csrRobotModel* m, dWorldID world, dSpaceID space,
                          const double c[3], double h, csError* err) {
  if (!m->map.eval || !m->leg_type) {
    cs_errorSet(err, CS_ERR_ARG, "robot: no calibration map or leg level");
    return NULL;
  }
  if (!(m->support_mass > 0) || !(m->support_size[0] > 0 && m->support_size[1] > 0 &&
                                  m->support_size[2] > 0)) {
    cs_errorSet(err, CS_ERR_RANGE, "robot: support mass and size must be > 0");
    return NULL;
  }
  csrRobot* r = calloc(1, sizeof *r);
  if (!r) {
    cs_errorSet(err, CS_ERR_MEMORY, "robot: out of memory");
    return NULL;
  }
  r->support = dBodyCreate(world);
  dBodySetPosition(r->support, c[0], c[1] + 0.5 * m->support_size[1], c[2]);
  dMass ms;
  dMassSetBoxTotal(&ms, m->support_mass, m->support_size[0], m->support_size[1],
                   m->support_size[2]);
  dBodySetMass(r->support, &ms);
  r->support_geom = dCreateBox(space, m->support_size[0], m->support_size[1], m->support_size[2]);
  dGeomSetBody(r->support_geom, r->support);
  r->mass_total = m->support_mass;

  /* leg frame: e1 = +x, e2 = +z, e3 = -y (hanging), right-handed: e1 x e2 = e3 */
  csrLegSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.act = &m->leg;
  spec.params = &m->leg_params;
  spec.map = &m->map;
  spec.world = world;
  spec.space = space;
  spec.support = r->support;
  spec.h = h;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(spec.frame, F, sizeof F);
  for (int k = 0; k < CSR_NLEG; k++) {
    double off[3];
    csr_robotHipOffset(m, k, off);
    csu_add3(spec.hip, c, off);
    r->legs[k] = m->leg_type->create(&spec, err);
    if (!r->legs[k]) {
      csr_robotDestroy(m, r);
      return NULL;
    }
    r->mass_total += m->leg_type->mass(r->legs[k]);
  }
  return r;
}


void csr_robotDestroy(const csrRobotModel* m, csrRobot* r) {
  if (!r) {
    return;
  }
  for (int k = 0; k < CSR_NLEG; k++) {
    if (r->legs[k]) {
      m->leg_type->destroy(r->legs[k]);
    }
  }
  free(r);
}


void csr_robotCenterOfMass(const csrRobotModel* m, const csrRobot* r, double com[3]) {
  const dReal* p = dBodyGetPosition(r->support);
  double mx[3] = {m->support_mass * p[0], m->support_mass * p[1], m->support_mass * p[2]};
  for (int k = 0; k < CSR_NLEG; k++) {
    double leg_mx[3];
    m->leg_type->massMoment(r->legs[k], leg_mx);
    csu_add3(mx, mx, leg_mx);
  }
  csu_scale3(com, mx, 1.0 / r->mass_total);
}


int csr_robotActuate(const csrRobotModel* m, csrRobot* r, const double p[CSR_NCHAMBER_TOTAL]) {
  for (int k = 0; k < CSR_NLEG; k++) {
    /* label = 12 k + 4 (s - 1) + j: leg k's 12 chambers are contiguous */
    int rc = m->leg_type->actuate(r->legs[k], p + 12 * k);
    if (rc != 0) {
      return rc;
    }
  }
  return 0;
}

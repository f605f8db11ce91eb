/* robot_robot.c: robot assembly, the robot's state, the support interface and the table of
 * leg levels (see robot_robot.h). */
#include "robot_robot.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"

/* The registered leg levels, cheapest first. Registering a level is one line here (its
 * csrLegType is declared in robot_leg.h). */
static const csrLegType* const kLegLevels[] = {
    &csr_leg_rod,
    &csr_leg_strain, /* docs/notes/strain_leg.md */
    &csr_leg_rom,    /* the reduced FE leg from its file (docs/notes/rom.md): the dearest */
};
/* Levels docs/design.md names ("Model levels") that are not registered yet: known to the CLI,
 * "not available yet" until they are in kLegLevels. */
static const char* const kPlannedLevels[] = {NULL}; /* none today */
enum { NLEVEL = sizeof kLegLevels / sizeof kLegLevels[0] };
/* Levels that were retired, with what to use instead (csr_legRetired). */
static const struct {
  const char* name;
  const char* why;
} kRetiredLevels[] = {
    {"prb", "the prb level was retired (2026-12-06): off the speed/accuracy front "
            "(docs/studies/speed_accuracy.md); use rod (the default) or strain"},
};


const char* csr_legRetired(const char* name) {
  for (size_t i = 0; name && i < sizeof kRetiredLevels / sizeof kRetiredLevels[0]; i++) {
    if (!strcmp(kRetiredLevels[i].name, name)) {
      return kRetiredLevels[i].why;
    }
  }
  return NULL;
}


const csrLegType* csr_legTypeFind(const char* name, int* planned) {
  if (planned) {
    *planned = 0;
  }
  if (!name) {
    return NULL;
  }
  for (int i = 0; i < NLEVEL; i++) {
    if (!strcmp(kLegLevels[i]->name, name)) {
      return kLegLevels[i];
    }
  }
  for (size_t i = 0; i < sizeof kPlannedLevels / sizeof kPlannedLevels[0]; i++) {
    if (planned && kPlannedLevels[i] && !strcmp(kPlannedLevels[i], name)) {
      *planned = 1;
    }
  }
  return NULL;
}


int csr_legTypeCount(void) { return NLEVEL; }


const csrLegType* csr_legTypeAt(int i) { return i >= 0 && i < NLEVEL ? kLegLevels[i] : NULL; }


csStatus csr_robotDefaultModel(csrRobotModel* m, csError* err) {
  memset(m, 0, sizeof *m);
  csStatus st = csr_actuatorPreset(&m->leg, "leg", err);
  if (st != CS_OK) {
    return st;
  }
  m->leg_params = csr_defaultLegParams(&m->leg);
  /* the mission's surrogate: the nodal rod (docs/models.md; issue 33 item 1) */
  m->leg_type = &csr_leg_rod;
  csr_legSettingsDefault(m->leg_type, &m->leg_settings);
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


csrRobot* csr_robotCreate(const csrRobotModel* m, const csrRobotEnv* env, const double c[3],
                          csError* err) {
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
  r->type = m->leg_type;
  r->support = dBodyCreate(env->world);
  dBodySetPosition(r->support, c[0], c[1] + 0.5 * m->support_size[1], c[2]);
  /* the heading Rh turns the robot about the vertical through the hip plane's centre */
  const double up[3] = {0, 1, 0};
  double Rh[9];
  csu_axisAngleToMat3(Rh, up, env->heading);
  const dMatrix3 R4 = {Rh[0], Rh[1], Rh[2], 0, Rh[3], Rh[4], Rh[5], 0, Rh[6], Rh[7], Rh[8], 0};
  dBodySetRotation(r->support, R4);
  dMass ms;
  dMassSetBoxTotal(&ms, m->support_mass, m->support_size[0], m->support_size[1],
                   m->support_size[2]);
  dBodySetMass(r->support, &ms);
  r->support_geom = dCreateBox(env->space, m->support_size[0], m->support_size[1],
                               m->support_size[2]);
  dGeomSetBody(r->support_geom, r->support);
  r->mass_total = m->support_mass;

  /* leg frame in the support frame: e1 = +x, e2 = +z, e3 = -y (hanging), right-handed:
   * e1 x e2 = e3; in the world it is turned by the heading Rh, as the hips are */
  csrLegSpec spec;
  memset(&spec, 0, sizeof spec);
  spec.act = &m->leg;
  spec.params = &m->leg_params;
  spec.settings = &m->leg_settings;
  spec.map = &m->map;
  spec.world = env->world;
  spec.space = env->space;
  spec.support = r->support;
  spec.h = env->h;
  csu_copy3(spec.gravity, env->gravity);
  spec.weightless = env->weightless_legs;
  spec.terrain = env->terrain;
  spec.contact = env->contact;
  spec.leg_file = m->leg_file[0] ? m->leg_file : NULL;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  csu_mulMat3(spec.frame, Rh, F);
  memcpy(r->frame_local, F, sizeof F);
  r->nstate = CSR_BODY_STATE;
  if (m->leg_type->sharedCreate(&spec, &r->leg_shared, err) != 0) {
    csr_robotDestroy(r);
    return NULL;
  }
  spec.shared = r->leg_shared;
  for (int k = 0; k < CSR_NLEG; k++) {
    double off[3], off_w[3];
    csr_robotHipOffset(m, k, off);
    csu_mulMatVec3(off_w, Rh, off);
    csu_add3(spec.hip, c, off_w);
    /* from the support's centre, which sits half its thickness above the hip plane */
    csu_set3(r->hip_local[k], off[0], off[1] - 0.5 * m->support_size[1], off[2]);
    r->legs[k] = m->leg_type->create(&spec, err);
    if (!r->legs[k]) {
      csr_robotDestroy(r);
      return NULL;
    }
    r->mass_total += m->leg_type->mass(r->legs[k]);
    r->nstate += m->leg_type->stateSize(r->legs[k]);
  }
  r->scratch = malloc((size_t)r->nstate * sizeof(double));
  if (!r->scratch) {
    cs_errorSet(err, CS_ERR_MEMORY, "robot: out of memory");
    csr_robotDestroy(r);
    return NULL;
  }
  return r;
}


void csr_robotDestroy(csrRobot* r) {
  if (!r) {
    return;
  }
  for (int k = 0; k < CSR_NLEG; k++) {
    if (r->legs[k]) {
      r->type->destroy(r->legs[k]);
    }
  }
  if (r->type) {
    r->type->sharedDestroy(r->leg_shared);
  }
  free(r->scratch);
  free(r);
}


void csr_robotCenterOfMass(const csrRobot* r, double com[3]) {
  dMass ms;
  dBodyGetMass(r->support, &ms);
  const dReal* p = dBodyGetPosition(r->support);
  double mx[3] = {ms.mass * p[0], ms.mass * p[1], ms.mass * p[2]};
  for (int k = 0; k < CSR_NLEG; k++) {
    double leg_mx[3];
    r->type->massMoment(r->legs[k], leg_mx);
    csu_add3(mx, mx, leg_mx);
  }
  csu_scale3(com, mx, 1.0 / r->mass_total);
}


int csr_robotActuate(csrRobot* r, double t0, const double p0[CSR_NCHAMBER_TOTAL], double t1,
                     const double p1[CSR_NCHAMBER_TOTAL]) {
  for (int k = 0; k < CSR_NLEG; k++) {
    /* label = 12 k + 4 (s - 1) + j: leg k's 12 chambers are contiguous */
    int rc = r->type->actuate(r->legs[k], t0, p0 + 12 * k, t1, p1 + 12 * k);
    if (rc != 0) {
      return rc;
    }
  }
  return 0;
}


int csr_robotStateSize(const csrRobot* r) { return r->nstate; }


void csr_robotStateGet(const csrRobot* r, double* x) {
  csr_bodyStateGet(r->support, x);
  x += CSR_BODY_STATE;
  for (int k = 0; k < CSR_NLEG; k++) {
    r->type->getState(r->legs[k], x);
    x += r->type->stateSize(r->legs[k]);
  }
}


/* set every part from x; returns 0 or the first part's refusal (parts before it are set) */
static int setParts(csrRobot* r, const double* x) {
  if (csr_bodyStateSet(r->support, x) != 0) {
    return -1;
  }
  x += CSR_BODY_STATE;
  for (int k = 0; k < CSR_NLEG; k++) {
    if (r->type->setState(r->legs[k], x) != 0) {
      return -1;
    }
    x += r->type->stateSize(r->legs[k]);
  }
  return 0;
}


int csr_robotStateSet(csrRobot* r, const double* x) {
  /* a part may refuse its slice (non-finite, a non-unit quaternion) after earlier parts took
   * theirs: then the state before the call, saved in the preallocated scratch, goes back, which
   * every part accepts since it wrote it */
  csr_robotStateGet(r, r->scratch);
  if (setParts(r, x) != 0) {
    setParts(r, r->scratch);
    return -1;
  }
  return 0;
}


void csr_robotBaseStateAt(const csrRobot* r, int k, const double P[3], const double R[9],
                          const double v[3], const double w[3], csrBaseState* b) {
  double off[3], wxr[3];
  csu_mulMatVec3(off, R, r->hip_local[k]);
  csu_add3(b->x, P, off);
  csu_mulMat3(b->R, R, r->frame_local);
  csu_cross3(wxr, w, off);
  csu_add3(b->v, v, wxr);
  csu_copy3(b->w, w);
}


void csr_robotSupportPose(const csrRobot* r, double P[3], double R[9], double v[3],
                          double w[3]) {
  const dReal* p = dBodyGetPosition(r->support);
  const dReal* R4 = dBodyGetRotation(r->support); /* 3x4 row-major */
  const dReal* V = dBodyGetLinearVel(r->support);
  const dReal* W = dBodyGetAngularVel(r->support);
  for (int i = 0; i < 3; i++) {
    P[i] = p[i];
    v[i] = V[i];
    w[i] = W[i];
    for (int j = 0; j < 3; j++) {
      R[3 * i + j] = R4[4 * i + j];
    }
  }
}


void csr_robotBaseState(const csrRobot* r, int k, csrBaseState* b) {
  double P[3], R[9], v[3], w[3];
  csr_robotSupportPose(r, P, R, v, w);
  csr_robotBaseStateAt(r, k, P, R, v, w, b);
}


void csr_robotApplyWrench(csrRobot* r, int k, const csrWrench* w) {
  const dReal* P = dBodyGetPosition(r->support);
  const dReal* R4 = dBodyGetRotation(r->support);
  double hip[3];
  for (int i = 0; i < 3; i++) {
    hip[i] = P[i] + R4[4 * i] * r->hip_local[k][0] + R4[4 * i + 1] * r->hip_local[k][1] +
             R4[4 * i + 2] * r->hip_local[k][2];
  }
  dBodyAddForceAtPos(r->support, w->f[0], w->f[1], w->f[2], hip[0], hip[1], hip[2]);
  dBodyAddTorque(r->support, w->m[0], w->m[1], w->m[2]);
}

/* contact_ode.c: robot-terrain contacts with Coulomb friction (see contact_ode.h). */
#include "contact_ode.h"

#include <math.h>

#include "core_math.h"

enum { MAX_POINTS = 16 };

typedef struct {
  const cscContactParams* p;
  dWorldID world;
  dJointGroupID group;
  double h;
  cscContactStats* stats;
  dSpaceID terrain; /* to tell the terrain's geom of a pair */
} CollideCtx;


cscContactParams csc_defaultContactParams(void) {
  cscContactParams p;
  /* silicone on a dry road: rubber-like friction is 0.5..1; 0.8 is the documented default */
  p.mu = 0.8;
  /* 100 N/mm: the robot's weight (~3 N) sinks in by ~0.03 mm, far below any length of
   * interest, while keeping the contact soft enough for a 1 ms step */
  p.kp = 100.0;
  /* 0.1 N s/mm: about critical damping for a ~30 g foot-and-share-of-body on kp */
  p.kd = 0.1;
  /* four points let a capsule lying on a box rest without rocking; a standing capsule gives 1 */
  p.max_points = 4;
  /* the soft law's own modulus as tuned (contact_soft.c) */
  p.stiffness_scale = 1.0;
  return p;
}


csStatus csc_contactParamsValidate(const cscContactParams* p, csError* err) {
  if (!(isfinite(p->mu) && p->mu >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "friction coefficient %g must be finite and >= 0",
                       p->mu);
  }
  if (!(isfinite(p->kp) && p->kp > 0 && isfinite(p->kd) && p->kd >= 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "contact stiffness/damping must be > 0 / >= 0");
  }
  if (!(isfinite(p->stiffness_scale) && p->stiffness_scale > 0)) {
    return cs_errorSet(err, CS_ERR_RANGE, "contact stiffness scale %g must be finite and > 0",
                       p->stiffness_scale);
  }
  if (p->max_points < 1 || p->max_points > MAX_POINTS) {
    return cs_errorSet(err, CS_ERR_RANGE, "contact points per pair must be in 1..%d", MAX_POINTS);
  }
  return CS_OK;
}


/* ODE near callback: one terrain geom against one robot geom */
static void nearCallback(void* data, dGeomID o1, dGeomID o2) {
  CollideCtx* c = data;
  dContactGeom cg[MAX_POINTS];
  int n = dCollide(o1, o2, c->p->max_points, cg, sizeof(dContactGeom));
  if (n == 0) {
    return;
  }
  /* the n points of one geom pair act as parallel springs: each gets kp/n and kd/n so that
   * the pair's stiffness is kp whatever n the collider returns */
  double kp = c->p->kp / n, kd = c->p->kd / n, erp = 1, cfm = 0;
  /* the terrain geom's own friction (cst_terrainBuildOde: its data points at its box's mu),
   * else the run's */
  dGeomID tg = dGeomGetSpace(o1) == c->terrain ? o1 : o2;
  const double* own_mu = dGeomGetData(tg);
  double mu = own_mu ? *own_mu : c->p->mu;
  csu_springErpCfm(c->h, kp, kd, &erp, &cfm); /* kp > 0, kd >= 0: csc_contactParamsValidate */
  for (int i = 0; i < n; i++) {
    dContact ct;
    ct.geom = cg[i];
    ct.surface.mode = dContactApprox1 | dContactSoftERP | dContactSoftCFM;
    ct.surface.mu = mu;
    ct.surface.soft_erp = erp;
    ct.surface.soft_cfm = cfm;
    ct.surface.bounce = 0;
    ct.surface.bounce_vel = 0;
    dJointID j = dJointCreateContact(c->world, c->group, &ct);
    dJointAttach(j, dGeomGetBody(o1), dGeomGetBody(o2));
    c->stats->npoints++;
    if (cg[i].depth > c->stats->max_depth) {
      c->stats->max_depth = cg[i].depth;
    }
  }
}


void csc_collide(const cscContactParams* p, dWorldID world, dSpaceID terrain, dSpaceID robot,
                 dJointGroupID group, double h, cscContactStats* stats) {
  CollideCtx c = {p, world, group, h, stats, terrain};
  stats->npoints = 0;
  stats->max_depth = 0;
  dSpaceCollide2((dGeomID)terrain, (dGeomID)robot, &c, nearCallback);
}

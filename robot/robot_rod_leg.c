/* robot_rod_leg.c: the Cosserat rod behind the leg interface (csr_leg_rod, robot_leg.h), with the
 * soft leg-terrain contact of contact_soft.h bound to the rod's per-element contact hook.
 *
 * What the table maps to (robot_rod.h):
 *  - create: the leg's rod model and data from csrLegSpec: the actuator, its calibration map,
 *    hip and frame, gravity (spec->weightless: the `paper` conditions), csrLegParams'
 *    E_bend (E' of the rod), damping_time, contact_radius, and the level's settings (kRodSettings:
 *    links as the rod's elements per segment, the resolution knob `--links`;
 *    rod_tol, cal_drop); when spec->terrain is given,
 *    the soft contact model over N capsules (one per element, radius contact_radius) and the
 *    foot's sole (half side a), with csc_softDefaultParams and spec->contact's friction
 *    coefficient. Only the integrated friction history is supported (CSC_HISTORY_STEP needs an
 *    update at every accepted step, which a co-simulated integrator does not expose).
 *  - state: the rod's state vector, whose element blocks carry the contact history: element
 *    e < N holds capsule e's bristle (3 doubles), element N its capsule's and the sole's (3 + 4).
 *    The foot element's capsule ends a radius + 1 mm short of the sole (inside the foot block).
 *  - setState restarts CVODE from the given state (its step history is not state, and the base
 *    impulse it integrates restarts from zero: two restores of one state then step bit for
 *    bit, test_state test_rod_restore_is_bit_identical): measured on
 *    a hanging leg at rest, the next 5 ms advance takes 130 µs instead of 14 µs (order 1, a
 *    fresh Jacobian); a driver that rolls back every step pays that every step.
 *  - advance: csr_rodAdvance (CVODE BDF across the macro step, wrench averaged over it); the
 *    coupling's small corrections of the hip between steps are integrated across, not restarts
 *    (robot_rod_dyn.c).
 *  - interfaceGains: csr_rodInterfaceGains (instantaneous gains of the hip element).
 *  - contactShapes: elements 1..N-1 as capsules, element N as the foot block (box).
 * The hook evaluates one element at a time (csc_softComputeShape) and hands the rod each
 * shape's load in its native form (forces on the axis ends and a couple), so a capsule's line
 * load goes to the element's two nodes exactly; element N adds its sole's resultant on the
 * tip node and the sole's moment to its couple. (Moving the sole's force to a point on the
 * capsule's axis, statically equivalent for a rigid body, put 84 % of it on the node above and
 * bypassed the foot element's axial spring: the leg was measured 7 % stiffer on the road.) */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contact_soft.h"
#include "robot_calibration.h"
#include "robot_rod.h"

/* the level's settings (kRodSettings, at the end) */
enum { ROD_LINKS, ROD_TOL, ROD_CAL_DROP, ROD_JOINT_LINKS };

struct csrLeg_ {
  csrActuator act;
  csrRodModel* m;
  csrRodData* d;
  cscSoftModel* soft; /* NULL: no terrain */
  int N;              /* elements; soft shapes 0..N-1 are their capsules, shape N the sole */
  int hc, hf;         /* history doubles of a capsule and of the sole */
  double radius;      /* capsule radius (mm) */
  double gain_step;   /* s: the step of the interface gains' condensation (spec->h) */
  double* scratch;    /* (state size) */
  csrRodShape* shapes; /* (N) scratch of contactShapes */
  csrRodCalibration rodcal; /* a mode table's actuation with its probed stiffness (else unused) */
};

/* the hook: capsule of element e (and for e = N the sole) through the soft contact law */
static int legContact(void* ctx, const csrRodShape* sh, const double* hist, double* dhist,
                      double f0[3], double f1[3], double moment[3]);
/* the same for one shape, and its deepest penetration (mm) into *depth when not NULL (the
 * larger of it and the value there) */
static int shapeContact(const csrLeg* leg, const csrRodShape* sh, const double* hist,
                        double* dhist, double f0[3], double f1[3], double moment[3],
                        double* depth);
/* add a force f at point P (mm) to the chord p0 -> p1: lever rule on the nodes, the offset
 * from the chord to the couple */
static void addPointForce(const double p0[3], const double p1[3], const double f[3],
                          const double P[3], double f0[3], double f1[3], double moment[3]);


static void addPointForce(const double p0[3], const double p1[3], const double f[3],
                          const double P[3], double f0[3], double f1[3], double moment[3]) {
  double dx[3], rel[3], A[3], arm[3], c[3];
  csu_sub3(dx, p1, p0);
  csu_sub3(rel, P, p0);
  double len2 = csu_dot3(dx, dx);
  double xi = len2 > 0 ? csu_dot3(rel, dx) / len2 : 1.0;
  xi = xi < 0 ? 0 : (xi > 1 ? 1 : xi);
  csu_addScl3(f0, f0, f, 1 - xi);
  csu_addScl3(f1, f1, f, xi);
  csu_addScl3(A, p0, dx, xi);
  csu_sub3(arm, P, A);
  csu_cross3(c, arm, f);
  csu_add3(moment, moment, c);
}


static int legContact(void* ctx, const csrRodShape* sh, const double* hist, double* dhist,
                      double f0[3], double f1[3], double moment[3]) {
  return shapeContact(ctx, sh, hist, dhist, f0, f1, moment, NULL);
}


static int shapeContact(const csrLeg* leg, const csrRodShape* sh, const double* hist,
                        double* dhist, double f0[3], double f1[3], double moment[3],
                        double* depth) {
  const int e = sh->element;
  cscShapeState cs;
  memset(&cs, 0, sizeof cs);
  memcpy(cs.x0, sh->p0, sizeof cs.x0);
  memcpy(cs.x1, sh->p1, sizeof cs.x1);
  memcpy(cs.v0, sh->v0, sizeof cs.v0);
  memcpy(cs.v1, sh->v1, sizeof cs.v1);
  memcpy(cs.w, sh->omega, sizeof cs.w);
  memcpy(cs.R, sh->R, sizeof cs.R);
  int capsule = 1, shortened = 0;
  if (e < leg->N) {
    /* an element within a radius (and 1 mm) of the tip, as the foot element below: when the
     * foot element is shorter than that (8 or more elements per segment: l_N 6.25 mm at 8,
     * radius 7.5 mm), the end of the capsule above it reached the road first and the leg stood
     * on it with its sole up to 5 mm above the road (docs/notes/strain_leg.md "Why the flat
     * road differs"); its axis now stops at arc length L - (radius + 1), or it has no capsule */
    const double* sn = csr_rodNodeArc(leg->m);
    double cut = csr_rodLength(leg->m) - (leg->radius + 1.0);
    if (sn[e] > cut) {
      double u = (cut - sn[e - 1]) / (sn[e] - sn[e - 1]);
      capsule = u > 0;
      shortened = 1;
      for (int c = 0; c < 3; c++) {
        cs.x1[c] = sh->p0[c] + u * (sh->p1[c] - sh->p0[c]);
        cs.v1[c] = sh->v0[c] + u * (sh->v1[c] - sh->v0[c]);
      }
    }
  } else {
    /* the foot element's capsule stops a radius (and 1 mm) short of the sole: its axis would
     * otherwise end on the sole face, and its end region would push the ground with the
     * cap's depth (the foot hovered 0.5 mm above the road under a 1 N stance load); the cap
     * then sits inside the foot block, whose sole carries the ground. A foot element shorter
     * than that has no capsule. */
    double d3[3] = {sh->R[2], sh->R[5], sh->R[8]}, off[3], wv[3], ch[3];
    csu_sub3(ch, sh->p1, sh->p0);
    double back = leg->radius + 1.0;
    capsule = csu_norm3(ch) > back;
    csu_scale3(off, d3, -back);
    csu_add3(cs.x1, sh->p1, off);
    csu_cross3(wv, sh->omega, off);
    csu_add3(cs.v1, sh->v1, wv);
  }
  if (capsule) {
    cscShapeLoad ld;
    cscSoftReport rep;
    memset(&rep, 0, sizeof rep); /* csc_softComputeShape adds to it */
    int rc = csc_softComputeShape(leg->soft, e - 1, &cs, hist, &ld, dhist, NULL,
                                  depth ? &rep : NULL);
    if (rc != 0) {
      return rc > 0 ? rc : -1;
    }
    if (depth) {
      *depth = fmax(*depth, rep.max_depth);
    }
    if (e < leg->N && !shortened) {
      /* the capsule's axis is the element's chord: its node forces are the rod's */
      memcpy(f0, ld.f0, 3 * sizeof(double));
      memcpy(f1, ld.f1, 3 * sizeof(double));
      memcpy(moment, ld.m, 3 * sizeof(double));
    } else {
      /* the shortened axis end x1' lies on the chord (up to the element's shear) */
      memcpy(moment, ld.m, 3 * sizeof(double));
      addPointForce(sh->p0, sh->p1, ld.f0, cs.x0, f0, f1, moment);
      addPointForce(sh->p0, sh->p1, ld.f1, cs.x1, f0, f1, moment);
    }
  } else if (dhist) {
    for (int k = 0; k < leg->hc; k++) {
      dhist[k] = 0;
    }
  }
  if (e == leg->N) {
    /* the sole: centred at the tip node, normal d3 of the last frame (outwards); its
     * resultant acts at the tip node, its moment about it is the couple */
    cscShapeState fs;
    memset(&fs, 0, sizeof fs);
    memcpy(fs.x0, sh->p1, sizeof fs.x0);
    memcpy(fs.v0, sh->v1, sizeof fs.v0);
    memcpy(fs.R, sh->R, sizeof fs.R);
    memcpy(fs.w, sh->omega, sizeof fs.w);
    cscShapeLoad lf;
    cscSoftReport rep;
    memset(&rep, 0, sizeof rep); /* csc_softComputeShape adds to it */
    int rc = csc_softComputeShape(leg->soft, leg->N, &fs, hist + leg->hc, &lf,
                                  dhist ? dhist + leg->hc : NULL, NULL, depth ? &rep : NULL);
    if (rc != 0) {
      return rc > 0 ? rc : -1;
    }
    if (depth) {
      *depth = fmax(*depth, rep.max_depth);
    }
    csu_add3(f1, f1, lf.f0);
    csu_add3(moment, moment, lf.m);
  }
  return 0;
}


static void destroyRod(csrLeg* leg) {
  if (!leg) {
    return;
  }
  csr_rodDataDestroy(leg->d);
  csr_rodModelDestroy(leg->m);
  csc_softDestroy(leg->soft);
  free(leg->scratch);
  free(leg->shapes);
  free(leg);
}


/* fresh contact history in every element block of state y */
static void initHistory(const csrLeg* leg, double* y) {
  if (!leg->soft) {
    return;
  }
  for (int e = 1; e <= leg->N; e++) {
    double* h = y + csr_rodStateOffset(leg->m, e) + 13;
    csc_softShapeStateInit(leg->soft, e - 1, h);
    if (e == leg->N) {
      csc_softShapeStateInit(leg->soft, leg->N, h + leg->hc);
    }
  }
}


static void resetRod(csrLeg* leg) {
  csr_rodReset(leg->m, leg->d);
  if (leg->soft) {
    csr_rodGetState(leg->m, leg->d, leg->scratch);
    initHistory(leg, leg->scratch);
    csr_rodSetState(leg->m, leg->d, leg->scratch);
  }
}


static csrLeg* createRod(const csrLegSpec* spec, csError* err) {
  if (!spec || !spec->act || !spec->params) {
    cs_errorSet(err, CS_ERR_ARG, "rod leg: NULL spec, actuator or parameters");
    return NULL;
  }
  if (csr_actuatorValidate(spec->act, err) != CS_OK) {
    return NULL;
  }
  const csrLegParams* lp = spec->params;
  double set[CSR_LEG_MAX_SETTINGS];
  csr_legSettingsRead(&csr_leg_rod, spec->settings, set);
  const int links = (int)set[ROD_LINKS];
  const double tol_scale = set[ROD_TOL];
  if (links < 1 || links > 64 || !(lp->E_bend > 0) ||
      !(lp->damping_time >= 0) || !(lp->contact_radius > 0) || !(tol_scale >= 0)) {
    cs_errorSet(err, CS_ERR_RANGE, "rod leg: need 1..64 elements per segment (--links), E_bend "
                "> 0, damping >= 0, contact radius > 0, tolerance scale >= 0");
    return NULL;
  }
  csrLeg* leg = calloc(1, sizeof *leg);
  if (!leg) {
    cs_errorSet(err, CS_ERR_MEMORY, "rod leg: out of memory");
    return NULL;
  }
  leg->act = *spec->act;
  leg->gain_step = spec->h;
  csrRodParams par = csr_rodDefaultParams(&leg->act);
  par.elements_per_segment = links;
  par.E = lp->E_bend;
  par.damping_time = lp->damping_time;
  par.contact_radius = lp->contact_radius;
  par.cal_drop = (unsigned)set[ROD_CAL_DROP];
  par.elements_per_joint = (int)set[ROD_JOINT_LINKS];
  /* the bristles deflect by at most mu delta_t (8 µm by default): their error to 1e-5 mm */
  par.atol_hist = 1e-5;
  /* 0: the shipped tolerances (x 1 keeps their bits) */
  const double f = tol_scale > 0 ? tol_scale : 1.0;
  par.rtol *= f;
  par.atol_pos *= f;
  par.atol_rot *= f;
  par.atol_vel *= f;
  par.atol_omega *= f;
  par.atol_hist *= f;
  par.atol_wrench *= f;
  leg->N = CSR_NSEG * par.elements_per_segment + (CSR_NSEG - 1) * par.elements_per_joint;
  csrRodSpec rs;
  memset(&rs, 0, sizeof rs);
  rs.act = &leg->act;
  rs.params = &par;
  rs.map = spec->map;
  /* a map made of an FE mode table also gives the probed section stiffness (robot_calibration.h) */
  if (csr_calibrationRodFromMap(spec->map, &leg->rodcal)) {
    rs.calib = &leg->rodcal;
  }
  memcpy(rs.hip, spec->hip, sizeof rs.hip);
  memcpy(rs.frame, spec->frame, sizeof rs.frame);
  memcpy(rs.gravity, spec->gravity, sizeof rs.gravity);
  rs.weightless = spec->weightless;
  if (spec->terrain) {
    cscSoftParams sp = csc_softDefaultParams();
    if (spec->contact) {
      sp.mu = spec->contact->mu;
      sp.k_area *= spec->contact->stiffness_scale;
    }
    if (sp.history != CSC_HISTORY_INTEGRATED) {
      destroyRod(leg);
      cs_errorSet(err, CS_ERR_ARG, "rod leg: the soft contact's step-anchored friction history is "
                  "not supported (integrated only)");
      return NULL;
    }
    cscShape* shapes = calloc((size_t)leg->N + 1, sizeof *shapes);
    if (!shapes) {
      destroyRod(leg);
      cs_errorSet(err, CS_ERR_MEMORY, "rod leg: out of memory");
      return NULL;
    }
    leg->radius = par.contact_radius;
    for (int e = 0; e < leg->N; e++) {
      shapes[e] = csc_softCapsule(par.contact_radius);
    }
    shapes[leg->N] = csc_softFoot(leg->act.a);
    leg->soft = csc_softCreate(&sp, spec->terrain, leg->N + 1, shapes, err);
    free(shapes);
    if (!leg->soft) {
      destroyRod(leg);
      return NULL;
    }
    int off = 0;
    csc_softShapeState(leg->soft, 0, &off, &leg->hc);
    csc_softShapeState(leg->soft, leg->N, &off, &leg->hf);
    if (leg->hc > CSR_ROD_MAX_HIST || leg->hc + leg->hf > CSR_ROD_MAX_HIST) {
      cs_errorSet(err, CS_ERR_RANGE, "rod leg: contact history of %d + %d doubles exceeds %d",
                  leg->hc, leg->hf, CSR_ROD_MAX_HIST);
      destroyRod(leg);
      return NULL;
    }
    rs.contact.eval = legContact;
    rs.contact.ctx = leg;
    rs.contact.nhist = leg->hc;
    rs.contact.nhist_foot = leg->hc + leg->hf;
  }
  leg->m = csr_rodModelCreate(&rs, err);
  leg->d = leg->m ? csr_rodDataCreate(leg->m, err) : NULL;
  leg->scratch = leg->m ? calloc((size_t)csr_rodStateSize(leg->m), sizeof(double)) : NULL;
  leg->shapes = calloc((size_t)leg->N, sizeof *leg->shapes);
  if (!leg->d || !leg->scratch || !leg->shapes) {
    if (leg->d) {
      cs_errorSet(err, CS_ERR_MEMORY, "rod leg: out of memory");
    }
    destroyRod(leg);
    return NULL;
  }
  if (spec->shared && csr_rodDataUseCache(leg->d, spec->shared) != 0) {
    destroyRod(leg);
    cs_errorSet(err, CS_ERR_MEMORY, "rod leg: out of memory");
    return NULL;
  }
  resetRod(leg);
  return leg;
}


/* the legs of a robot share the calibration's tables (robot_rod.h csrRodActCache) */
static int sharedCreateRod(const csrLegSpec* spec, void** shared, csError* err) {
  (void)spec;
  *shared = csr_rodActCacheCreate(err);
  return *shared ? 0 : -1;
}


static void sharedDestroyRod(void* shared) { csr_rodActCacheDestroy(shared); }


static int stateSizeRod(const csrLeg* leg) { return csr_rodStateSize(leg->m); }


static void getStateRod(const csrLeg* leg, double* x) { csr_rodGetState(leg->m, leg->d, x); }


static int setStateRod(csrLeg* leg, const double* x) {
  const int n = csr_rodStateSize(leg->m);
  for (int i = 0; i < n; i++) {
    if (!isfinite(x[i])) {
      return -1;
    }
  }
  csr_rodSetState(leg->m, leg->d, x);
  return 0;
}


static int actuateRod(csrLeg* leg, double t0, const double p0[12], double t1,
                      const double p1[12]) {
  return csr_rodActuate(leg->m, leg->d, t0, p0, t1, p1);
}


static int advanceRod(csrLeg* leg, double t, double H, const csrBaseState* b0,
                      const csrBaseState* b1, csrWrench* w, csError* err) {
  return csr_rodAdvance(leg->m, leg->d, t, H, b0, b1, w, err);
}


static void interfaceGainsRod(const csrLeg* leg, double K[36], double C[36]) {
  /* the gains evaluate the rod's force kernel in its scratch (the state is untouched), over
   * one ODE step: the stabilised coupling solves them implicitly with the support over it */
  csr_rodInterfaceGainsStep(leg->m, leg->d, leg->gain_step, K, C);
}


static int contactShapesRod(const csrLeg* leg, csrContactShape* shapes, int max) {
  const int N = leg->N;
  const double* s = csr_rodNodeArc(leg->m);
  int n = csr_rodContactShapes(leg->m, leg->d, leg->shapes, max < N ? max : N);
  for (int i = 0; i < n; i++) {
    const csrRodShape* r = &leg->shapes[i];
    csrContactShape* c = &shapes[i];
    memset(c, 0, sizeof *c);
    c->s = 0.5 * (s[r->element - 1] + s[r->element]);
    if (r->kind == CSR_ROD_SHAPE_CAPSULE) {
      c->kind = CSR_SHAPE_CAPSULE;
      memcpy(c->a, r->p0, sizeof c->a);
      memcpy(c->b, r->p1, sizeof c->b);
      c->radius = r->radius;
    } else {
      c->kind = CSR_SHAPE_BOX;
      memcpy(c->a, r->centre, sizeof c->a);
      memcpy(c->R, r->R, sizeof c->R);
      memcpy(c->half, r->half, sizeof c->half);
    }
  }
  return N;
}


void csr_rodLegSetTipLoad(csrLeg* leg, const double force[3], const double moment[3]) {
  csr_rodSetTipLoad(leg->d, force, moment);
}


void csr_rodLegStats(const csrLeg* leg, csrRodStats* s) { csr_rodGetStats(leg->d, s); }


static void centerlineRod(const csrLeg* leg, int k, double* out) {
  csr_rodCenterline(leg->m, leg->d, k, out);
}


static double massRod(const csrLeg* leg) { return csr_rodMass(leg->m); }


/* the shapes at the current state through the contact law with a zero friction history (the
 * depth does not depend on it) */
static double contactDepthRod(const csrLeg* leg) {
  if (!leg->soft) {
    return 0.0;
  }
  const int n = csr_rodContactShapes(leg->m, leg->d, leg->shapes, leg->N);
  double zero[CSR_ROD_MAX_HIST] = {0}, f0[3], f1[3], mo[3], depth = 0.0;
  for (int i = 0; i < n; i++) {
    memset(f0, 0, sizeof f0), memset(f1, 0, sizeof f1), memset(mo, 0, sizeof mo);
    (void)shapeContact(leg, &leg->shapes[i], zero, NULL, f0, f1, mo, &depth);
  }
  return depth;
}


/* every shape through the contact law with its actual friction history (from the state: the
 * tangential force depends on it), the forces on its nodes summed; the law's history
 * derivative goes to a scratch */
static void contactForceRod(const csrLeg* leg, double f[3]) {
  f[0] = f[1] = f[2] = 0.0;
  if (!leg->soft) {
    return;
  }
  csr_rodGetState(leg->m, leg->d, leg->scratch);
  const int n = csr_rodContactShapes(leg->m, leg->d, leg->shapes, leg->N);
  double dhist[2 * CSR_ROD_MAX_HIST], f0[3], f1[3], mo[3];
  for (int i = 0; i < n; i++) {
    const int e = leg->shapes[i].element;
    const double* hist = leg->scratch + csr_rodStateOffset(leg->m, e) + 13;
    memset(f0, 0, sizeof f0), memset(f1, 0, sizeof f1), memset(mo, 0, sizeof mo);
    if (shapeContact(leg, &leg->shapes[i], hist, dhist, f0, f1, mo, NULL) == 0) {
      csu_add3(f, f, f0);
      csu_add3(f, f, f1);
    }
  }
}


static void massMomentRod(const csrLeg* leg, double mx[3]) {
  csr_rodMassMoment(leg->m, leg->d, mx);
}


/* the level's own settings (robot_leg.h csrLegSetting), in the order of ROD_* */
static const csrLegSetting kRodSettings[] = {
    /* the scenes give their converged count (sim_scene.h rod_links) */
    [ROD_LINKS] = {"links", "elements per segment", 4, 1, 64, 1},
    /* every CVODE tolerance (rtol and the atols) times this; 0 or 1: the shipped ones (a
     * convergence knob: `--rod-tol`, bench_flatroad argument 9) */
    [ROD_TOL] = {"rod_tol", "times the shipped CVODE tolerances", 1, 0, 1000, 0},
    /* parts of the calibration left out, CSR_CAL_DROP_* bits (`--cal-drop`) */
    [ROD_CAL_DROP] = {"cal_drop", "CSR_CAL_DROP_* bits", 0, 0,
                      CSR_CAL_DROP_STRETCH | CSR_CAL_DROP_STIFFNESS, 1},
    /* elements per solid joint LS12, LS23 (csrRodParams elements_per_joint). `links` refines
     * the segments only, so a reference converged in `links` keeps each 6-10 mm joint one
     * straight element with its bending at its two end nodes; this refines the joints too
     * (docs/notes/strain_leg.md "The flat gait of the fifth session") */
    [ROD_JOINT_LINKS] = {"joint_links", "elements per solid joint LS12, LS23", 1, 1, 64, 1},
};

const csrLegType csr_leg_rod = {
    .name = "rod",
    .in_world = 0,
    .settings = kRodSettings,
    .nsettings = (int)(sizeof kRodSettings / sizeof kRodSettings[0]),
    .create = createRod,
    .destroy = destroyRod,
    .sharedCreate = sharedCreateRod,
    .sharedDestroy = sharedDestroyRod,
    .stateSize = stateSizeRod,
    .getState = getStateRod,
    .setState = setStateRod,
    .reset = resetRod,
    .actuate = actuateRod,
    .advance = advanceRod,
    .interfaceGains = interfaceGainsRod,
    .contactShapes = contactShapesRod,
    .centerline = centerlineRod,
    .mass = massRod,
    .massMoment = massMomentRod,
    .contactDepth = contactDepthRod,
    .contactForce = contactForceRod,
};

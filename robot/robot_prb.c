/* robot_prb.c: the pseudo-rigid-body (prb) leg level: each segment is a chain of rigid links
 * joined by universal joints whose spring-damper targets come from the calibrated
 * pressure -> bend map.
 *
 * Why this shape. A constant-curvature segment of bend vector β is approximated by n equal
 * links with a joint at the middle of every n-th part of the segment (s = (k + 1/2) S / n),
 * each turning by β/n: the polyline is then tangent-polygon of the arc and its end point is
 * exact to O(β^2/n^2). The solid joints LS12/LS23 are rigid parts of the links that span them.
 * Each joint's stiffness is the section's bending stiffness over its share of length,
 * k = E_bend I / (S/n) (N mm/rad); damping is material damping kd = k * damping_time.
 *
 * Why ODE joint stops as springs. A joint whose low and high stop are equal becomes a two-sided
 * soft constraint with the stop's ERP/CFM; with ERP = h k/(h k + kd), CFM = 1/(h k + kd) it is
 * exactly an implicit spring-damper (ODE manual, "soft constraint"), stable at any step h,
 * whereas explicit joint torques would need h well below the link's 1/ω ~ 1 ms.
 *
 * The base link (hip to the first joint) is clamped to the support with a fixed joint.
 * Elongation (axial stretch from diagonal chambers) is not represented at this level: the map's
 * stretch output is ignored and reported by the bend command only; the rod level carries it.
 *
 * Behind robot_leg.h the chain is an in-world level: ODE steps its bodies with the support, so
 * advance() is a no-op and its interface gains are zero. Its state is its bodies' states
 * (robot_odebody.h, bit-exact) plus the joint targets it last set, which are kept as the
 * pressures and bends of the map cache below: restoring them re-applies the same targets. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "robot_analytic.h"
#include "robot_leg.h"
#include "robot_odebody.h"

/* sign between our bend angle and ODE's universal-joint angle (see actuatePrb) */
#define CSR_PRB_ANGLE_SIGN -1.0

/* the level's settings (kPrbSettings, at the end) */
enum { PRB_LINKS };

struct csrLeg_ {
  csrActuator act;
  csrLegParams par;
  const csrBendMap* map;
  int n;            /* links per segment */
  int nhinge;       /* 3 n */
  int nbody;        /* 3 n + 1 */
  double L;         /* leg length, mm */
  double frame[9];  /* e1, e2, e3 columns */
  double* s_hinge;  /* (nhinge) arc length of each joint, mm */
  double* s_body;   /* (nbody + 1) arc-length bounds of the bodies, mm */
  double* s_mid;    /* (nbody) arc length of each body's centre, mm */
  double* k_hinge;  /* (nhinge) stiffness, N mm/rad */
  double* len_body; /* (nbody) length of each body along the leg, mm */
  double* state0;   /* (nbody x CSR_BODY_STATE) the bodies' states right after create */
  dBodyID* body;    /* (nbody) */
  dJointID* hinge;  /* (nhinge) universal joints */
  dJointID clamp;   /* fixed joint of body 0 to the support */
  double h;
  double total_mass; /* t */
  /* the map is costly (a Newton solve); pressures are constant most of a gait, so each
   * segment keeps its last input and result and re-evaluates only when the input changes */
  double last_p[CSR_NSEG][4];
  double last_bend[CSR_NSEG][2];
  int have_last[CSR_NSEG];
};


csrLegParams csr_defaultLegParams(const csrActuator* act) {
  csrLegParams p;
  /* small-strain bending modulus of the Yeoh law with the fibres holding λ2 = 1:
   * W ≈ 4 C10 ε^2 -> σ = 8 C10 ε (plane-strain-like modulus, 0.88 MPa for Elastosil) */
  p.E_bend = 8.0 * act->C10;
  /* material damping as a Kelvin-Voigt time constant. Silicone's loss is nearly rate
   * independent (loss factor η ~ 0.1-0.2) and the air in chambers and tubes adds more; a
   * time constant τ gives the loss factor ω τ at frequency ω, so τ is chosen for η ≈ 0.3 at
   * the hanging leg's first bending mode, ω1 = 3.516 sqrt(EI / (m' L^4)) ≈ 15 rad/s:
   * τ = 0.3 / 15 = 0.02 s. The 100 Hz link modes are then over-damped, which the implicit
   * joint springs handle at any step. With 5 ms the leg swung for seconds after each move. */
  p.damping_time = 0.02;
  /* the leg's half side: the capsules fill the square section's inscribed circle */
  p.contact_radius = act->a;
  return p;
}


/* second moment of area (mm^4) of the chambered section about a principal axis: the analytic
 * model's exact section quadrature (robot_analytic.h), so both levels share one section */
double csr_legSectionI(const csrActuator* a) {
  csrSectionProps sp;
  if (csr_analyticSectionCompute(a, NULL, &sp, NULL) != CS_OK) {
    return NAN; /* invalid actuator: createPrb validates it first */
  }
  return sp.I_holed;
}


/* silicone mass (t) between arc lengths s0 < s1: chambers are hollow over S - 2c per segment */
static double massBetween(const csrActuator* a, double s0, double s1) {
  double Aout = csr_actuatorOuterArea(a);
  double Ach = 4 * CS_PI * a->r1 * a->r1;
  double vol = Aout * (s1 - s0);
  for (int s = 0; s < CSR_NSEG; s++) {
    double c0 = csr_actuatorSegmentStart(a, s) + a->c;
    double c1 = csr_actuatorSegmentStart(a, s) + a->S[s] - a->c;
    double lo = fmax(s0, c0), hi = fmin(s1, c1);
    if (hi > lo) {
      vol -= Ach * (hi - lo);
    }
  }
  return a->rho * vol;
}


static void destroyPrb(csrLeg* leg) {
  if (!leg) {
    return;
  }
  /* bodies and joints belong to the world and die with it; only our arrays are freed */
  free(leg->s_hinge);
  free(leg->s_body);
  free(leg->s_mid);
  free(leg->k_hinge);
  free(leg->len_body);
  free(leg->state0);
  free(leg->body);
  free(leg->hinge);
  free(leg);
}


/* set both stops of a universal joint axis to `target` (rad): a two-sided soft constraint */
static void setTarget(dJointID j, int axis, double target) {
  if (axis == 0) {
    dJointSetUniversalParam(j, dParamLoStop, target);
    dJointSetUniversalParam(j, dParamHiStop, target);
  } else {
    dJointSetUniversalParam(j, dParamLoStop2, target);
    dJointSetUniversalParam(j, dParamHiStop2, target);
  }
}


static csrLeg* createPrb(const csrLegSpec* spec, csError* err) {
  if (csr_actuatorValidate(spec->act, err) != CS_OK) {
    return NULL;
  }
  const csrLegParams* par = spec->params;
  double set[CSR_LEG_MAX_SETTINGS];
  csr_legSettingsRead(&csr_leg_prb, spec->settings, set);
  const int links = (int)set[PRB_LINKS];
  if (links < 1 || links > 64 || !(par->E_bend > 0) ||
      !(par->damping_time >= 0) || !(par->contact_radius > 0) || !(spec->h > 0)) {
    cs_errorSet(err, CS_ERR_RANGE,
                "prb leg: need 1..64 links per segment, E_bend > 0, damping >= 0, radius > 0");
    return NULL;
  }
  csrLeg* leg = calloc(1, sizeof *leg);
  if (!leg) {
    cs_errorSet(err, CS_ERR_MEMORY, "prb leg: out of memory");
    return NULL;
  }
  leg->act = *spec->act;
  leg->par = *par;
  leg->map = spec->map;
  leg->h = spec->h;
  leg->n = links;
  leg->nhinge = CSR_NSEG * leg->n;
  leg->nbody = leg->nhinge + 1;
  leg->L = csr_actuatorLength(spec->act);
  memcpy(leg->frame, spec->frame, sizeof leg->frame);
  leg->s_hinge = calloc((size_t)leg->nhinge, sizeof(double));
  leg->s_body = calloc((size_t)leg->nbody + 1, sizeof(double));
  leg->s_mid = calloc((size_t)leg->nbody, sizeof(double));
  leg->k_hinge = calloc((size_t)leg->nhinge, sizeof(double));
  leg->len_body = calloc((size_t)leg->nbody, sizeof(double));
  leg->state0 = calloc((size_t)leg->nbody * CSR_BODY_STATE, sizeof(double));
  leg->body = calloc((size_t)leg->nbody, sizeof(dBodyID));
  leg->hinge = calloc((size_t)leg->nhinge, sizeof(dJointID));
  if (!leg->s_hinge || !leg->s_body || !leg->s_mid || !leg->k_hinge || !leg->len_body ||
      !leg->state0 || !leg->body || !leg->hinge) {
    destroyPrb(leg);
    cs_errorSet(err, CS_ERR_MEMORY, "prb leg: out of memory");
    return NULL;
  }

  /* joint positions and stiffness */
  double I = csr_legSectionI(spec->act);
  for (int s = 0; s < CSR_NSEG; s++) {
    double ds = spec->act->S[s] / leg->n;
    for (int k = 0; k < leg->n; k++) {
      int i = s * leg->n + k;
      leg->s_hinge[i] = csr_actuatorSegmentStart(spec->act, s) + (k + 0.5) * ds;
      leg->k_hinge[i] = par->E_bend * I / ds;
    }
  }
  leg->s_body[0] = 0;
  for (int i = 0; i < leg->nhinge; i++) {
    leg->s_body[i + 1] = leg->s_hinge[i];
  }
  leg->s_body[leg->nbody] = leg->L;

  /* bodies: frame (e1, e2, e3) as the body axes, so body-local z runs along the leg */
  const double* F = spec->frame;
  dMatrix3 R = {F[0], F[1], F[2], 0, F[3], F[4], F[5], 0, F[6], F[7], F[8], 0};
  double e3[3] = {F[2], F[5], F[8]};
  for (int i = 0; i < leg->nbody; i++) {
    double s0 = leg->s_body[i], s1 = leg->s_body[i + 1];
    double len = s1 - s0;
    leg->s_mid[i] = 0.5 * (s0 + s1);
    double pos[3];
    csu_addScl3(pos, spec->hip, e3, leg->s_mid[i]);
    dBodyID b = dBodyCreate(spec->world);
    dBodySetPosition(b, pos[0], pos[1], pos[2]);
    dBodySetRotation(b, R);
    dMass m;
    double mass = massBetween(spec->act, s0, s1);
    dMassSetBoxTotal(&m, mass, 2 * spec->act->a, 2 * spec->act->a, len);
    dBodySetMass(b, &m);
    /* conditions `paper` (docs/reference.md): the leg keeps its mass and inertia, gravity does not
     * act on it */
    if (spec->weightless) {
      dBodySetGravityMode(b, 0);
    }
    leg->total_mass += mass;
    leg->len_body[i] = len;
    /* collision shape: capsules whose caps end at the link's ends (a sphere for short links);
     * the foot link is a box so the foot's flat square end face stands on the ground */
    dGeomID g;
    if (i == leg->nbody - 1) {
      g = dCreateBox(spec->space, 2 * spec->act->a, 2 * spec->act->a, len);
    } else {
      double r = par->contact_radius;
      double cyl = fmax(len - 2 * r, 1e-3);
      g = dCreateCapsule(spec->space, r, cyl);
    }
    dGeomSetBody(g, b);
    leg->body[i] = b;
    csr_bodyStateGet(b, leg->state0 + (size_t)CSR_BODY_STATE * i);
  }

  /* clamp the base link to the support */
  leg->clamp = dJointCreateFixed(spec->world, 0);
  dJointAttach(leg->clamp, spec->support, leg->body[0]);
  dJointSetFixed(leg->clamp);

  /* universal joints: axis1 = e2 carries bending towards e1, axis2 = e1 bending towards e2 */
  for (int i = 0; i < leg->nhinge; i++) {
    dJointID j = dJointCreateUniversal(spec->world, 0);
    dJointAttach(j, leg->body[i], leg->body[i + 1]);
    double a[3];
    csu_addScl3(a, spec->hip, e3, leg->s_hinge[i]);
    dJointSetUniversalAnchor(j, a[0], a[1], a[2]);
    dJointSetUniversalAxis1(j, F[1], F[4], F[7]);
    dJointSetUniversalAxis2(j, F[0], F[3], F[6]);
    double k = leg->k_hinge[i], kd = k * par->damping_time, erp = 0, cfm = 0;
    csu_springErpCfm(spec->h, k, kd, &erp, &cfm); /* k > 0, kd >= 0, h > 0: checked above */
    dJointSetUniversalParam(j, dParamStopERP, erp);
    dJointSetUniversalParam(j, dParamStopCFM, cfm);
    dJointSetUniversalParam(j, dParamStopERP2, erp);
    dJointSetUniversalParam(j, dParamStopCFM2, cfm);
    setTarget(j, 0, 0.0);
    setTarget(j, 1, 0.0);
    leg->hinge[i] = j;
  }
  return leg;
}


/* pressures equal within CSR_PRB_P_TOL (MPa): 1e-7 MPa moves a bend by < 1e-6 relative at
 * gait pressures (~0.15 MPa), far below any effect on the track, and lets the cache hit while
 * a chamber's lagging pressure creeps towards its plateau */
#define CSR_PRB_P_TOL 1e-7
static int samePressures(const double a[4], const double b[4]) {
  for (int j = 0; j < 4; j++) {
    if (fabs(a[j] - b[j]) > CSR_PRB_P_TOL) {
      return 0;
    }
  }
  return 1;
}


/* set segment s's joint targets for the bend vector bend[2] (rad) */
static void setSegmentTargets(csrLeg* leg, int s, const double bend[2]) {
  /* rotation vector of a bend towards (β1 e1 + β2 e2) about the axis e3 x β̂:
   * ω = β1 e2 - β2 e1. ODE's universal angles are measured with the sign convention below,
   * fixed by the test "prb bend towards +e1 moves the foot to +e1". */
  double a1 = CSR_PRB_ANGLE_SIGN * bend[0] / leg->n;
  double a2 = -CSR_PRB_ANGLE_SIGN * bend[1] / leg->n;
  for (int k = 0; k < leg->n; k++) {
    dJointID j = leg->hinge[s * leg->n + k];
    setTarget(j, 0, a1);
    setTarget(j, 1, a2);
  }
}


/* implicit joint springs take end-of-step targets: only p1 is used (robot_leg.h) */
static int actuatePrb(csrLeg* leg, double t0, const double p0[12], double t1,
                      const double p1[12]) {
  (void)t0;
  (void)p0;
  (void)t1;
  for (int s = 0; s < CSR_NSEG; s++) {
    double bend[2] = {0, 0}, stretch = 1;
    if (leg->have_last[s] && samePressures(leg->last_p[s], p1 + 4 * s)) {
      continue; /* same pressures: the joint targets are already set */
    }
    int rc = leg->map->eval(leg->map->ctx, s, p1 + 4 * s, bend, &stretch);
    if (rc != 0) {
      return rc;
    }
    memcpy(leg->last_p[s], p1 + 4 * s, sizeof leg->last_p[s]);
    memcpy(leg->last_bend[s], bend, sizeof bend);
    leg->have_last[s] = 1;
    setSegmentTargets(leg, s, bend);
  }
  return 0;
}


/* state layout: the bodies (nbody x CSR_BODY_STATE), then per segment the map cache that
 * holds the joint targets: last_p[4], last_bend[2], have_last (0/1) */
enum { SEG_STATE = 7 };


static int stateSizePrb(const csrLeg* leg) {
  return leg->nbody * CSR_BODY_STATE + CSR_NSEG * SEG_STATE;
}


static void getStatePrb(const csrLeg* leg, double* x) {
  for (int i = 0; i < leg->nbody; i++) {
    csr_bodyStateGet(leg->body[i], x + (size_t)CSR_BODY_STATE * i);
  }
  double* c = x + (size_t)CSR_BODY_STATE * leg->nbody;
  for (int s = 0; s < CSR_NSEG; s++, c += SEG_STATE) {
    memcpy(c, leg->last_p[s], 4 * sizeof(double));
    memcpy(c + 4, leg->last_bend[s], 2 * sizeof(double));
    c[6] = leg->have_last[s];
  }
}


static int setStatePrb(csrLeg* leg, const double* x) {
  /* validate everything first, so an invalid state leaves the leg unchanged */
  int n = stateSizePrb(leg);
  for (int i = 0; i < n; i++) {
    if (!isfinite(x[i])) {
      return -1;
    }
  }
  const double* c = x + (size_t)CSR_BODY_STATE * leg->nbody;
  for (int s = 0; s < CSR_NSEG; s++) {
    if (c[SEG_STATE * s + 6] != 0 && c[SEG_STATE * s + 6] != 1) {
      return -1;
    }
  }
  for (int i = 0; i < leg->nbody; i++) {
    const double* q = x + (size_t)CSR_BODY_STATE * i + 3;
    if (!(fabs(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3] - 1) <= 1e-6)) {
      return -1; /* not a unit quaternion (csr_bodyStateSet's own test, done up front) */
    }
  }
  for (int i = 0; i < leg->nbody; i++) {
    csr_bodyStateSet(leg->body[i], x + (size_t)CSR_BODY_STATE * i);
  }
  for (int s = 0; s < CSR_NSEG; s++, c += SEG_STATE) {
    memcpy(leg->last_p[s], c, 4 * sizeof(double));
    memcpy(leg->last_bend[s], c + 4, 2 * sizeof(double));
    leg->have_last[s] = c[6] != 0;
    /* the targets the cache stands for (0 before the first actuation, as at create) */
    double zero[2] = {0, 0};
    setSegmentTargets(leg, s, leg->have_last[s] ? leg->last_bend[s] : zero);
  }
  return 0;
}


static void resetPrb(csrLeg* leg) {
  for (int i = 0; i < leg->nbody; i++) {
    csr_bodyStateSet(leg->body[i], leg->state0 + (size_t)CSR_BODY_STATE * i);
  }
  double zero[2] = {0, 0};
  for (int s = 0; s < CSR_NSEG; s++) {
    memset(leg->last_p[s], 0, sizeof leg->last_p[s]);
    memset(leg->last_bend[s], 0, sizeof leg->last_bend[s]);
    leg->have_last[s] = 0;
    setSegmentTargets(leg, s, zero);
  }
}


/* in-world: ODE steps the chain with the support; nothing to advance, no wrench to hand back */
static int advancePrb(csrLeg* leg, double t, double H, const csrBaseState* b0,
                      const csrBaseState* b1, csrWrench* w, csError* err) {
  (void)leg;
  (void)t;
  (void)H;
  (void)b0;
  (void)b1;
  (void)err;
  memset(w, 0, sizeof *w);
  return 0;
}


/* in-world: the chain's joints couple it to the support inside ODE; no interface gains */
static void interfaceGainsPrb(const csrLeg* leg, double K[36], double C[36]) {
  (void)leg;
  memset(K, 0, 36 * sizeof(double));
  memset(C, 0, 36 * sizeof(double));
}


/* the ODE geoms as world shapes: capsules along each link, the foot link a box */
static int contactShapesPrb(const csrLeg* leg, csrContactShape* shapes, int max) {
  for (int i = 0; i < leg->nbody && i < max; i++) {
    csrContactShape* sh = &shapes[i];
    memset(sh, 0, sizeof *sh);
    const dReal* pos = dBodyGetPosition(leg->body[i]);
    const dReal* R = dBodyGetRotation(leg->body[i]); /* 3x4 row-major */
    double len = leg->len_body[i];
    sh->s = leg->s_mid[i];
    if (i == leg->nbody - 1) {
      sh->kind = CSR_SHAPE_BOX;
      csu_set3(sh->a, pos[0], pos[1], pos[2]);
      for (int r = 0; r < 3; r++) {
        for (int c = 0; c < 3; c++) {
          sh->R[3 * r + c] = R[4 * r + c];
        }
      }
      csu_set3(sh->half, leg->act.a, leg->act.a, 0.5 * len);
    } else {
      /* as in createPrb: the capsule's caps end at the link's ends */
      double r = leg->par.contact_radius;
      double half = 0.5 * fmax(len - 2 * r, 1e-3);
      double ax[3] = {R[2], R[6], R[10]};
      sh->kind = CSR_SHAPE_CAPSULE;
      sh->radius = r;
      double p[3] = {pos[0], pos[1], pos[2]};
      csu_addScl3(sh->a, p, ax, -half);
      csu_addScl3(sh->b, p, ax, half);
    }
  }
  return leg->nbody;
}


static void centerlinePrb(const csrLeg* leg, int k, double* out) {
  int ib = 0;
  for (int q = 0; q < k; q++) {
    double s = (k > 1) ? leg->L * q / (k - 1) : 0;
    while (ib < leg->nbody - 1 && s > leg->s_body[ib + 1]) {
      ib++;
    }
    const dReal* pos = dBodyGetPosition(leg->body[ib]);
    const dReal* R = dBodyGetRotation(leg->body[ib]); /* 3x4 row-major */
    double d = s - leg->s_mid[ib];
    /* body-local z is the leg axis: world offset = R[:,2] * d */
    out[3 * q + 0] = pos[0] + R[2] * d;
    out[3 * q + 1] = pos[1] + R[6] * d;
    out[3 * q + 2] = pos[2] + R[10] * d;
  }
}


static double massPrb(const csrLeg* leg) { return leg->total_mass; }


static void massMomentPrb(const csrLeg* leg, double mx[3]) {
  mx[0] = mx[1] = mx[2] = 0;
  for (int i = 0; i < leg->nbody; i++) {
    dMass m;
    dBodyGetMass(leg->body[i], &m);
    const dReal* p = dBodyGetPosition(leg->body[i]);
    for (int k = 0; k < 3; k++) {
      mx[k] += m.mass * p[k];
    }
  }
}


/* a prb leg shares nothing with its siblings */
static int sharedCreatePrb(const csrLegSpec* spec, void** shared, csError* err) {
  (void)spec;
  (void)err;
  *shared = NULL;
  return 0;
}


static void sharedDestroyPrb(void* shared) { (void)shared; }


static int ownsBodyPrb(const csrLeg* leg, dBodyID body) {
  for (int i = 0; i < leg->nbody; i++) {
    if (leg->body[i] == body) {
      return 1;
    }
  }
  return 0;
}


/* the level's own settings (robot_leg.h csrLegSetting), in the order of PRB_* */
static const csrLegSetting kPrbSettings[] = {
    /* 4 links per 50 mm segment: 12.5 mm joints; the tip error of the tangent polygon is
     * ~θ^2/(24 n^2) relative, 0.2 % at θ = 47°, well below the calibration's uncertainty */
    [PRB_LINKS] = {"links", "links per segment", 4, 1, 64, 1},
};

const csrLegType csr_leg_prb = {
    .name = "prb",
    .in_world = 1,
    .settings = kPrbSettings,
    .nsettings = (int)(sizeof kPrbSettings / sizeof kPrbSettings[0]),
    .create = createPrb,
    .destroy = destroyPrb,
    .sharedCreate = sharedCreatePrb,
    .sharedDestroy = sharedDestroyPrb,
    .stateSize = stateSizePrb,
    .getState = getStatePrb,
    .setState = setStatePrb,
    .reset = resetPrb,
    .actuate = actuatePrb,
    .advance = advancePrb,
    .interfaceGains = interfaceGainsPrb,
    .contactShapes = contactShapesPrb,
    .centerline = centerlinePrb,
    .mass = massPrb,
    .massMoment = massMomentPrb,
    .ownsBody = ownsBodyPrb,
};

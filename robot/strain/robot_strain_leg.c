/* robot_strain_leg.c: the strain-coordinate Cosserat rod behind the leg interface
 * (csr_leg_strain, robot_leg.h): a tree-stepped level, condensed into the support's implicit
 * step by the driver (core/sim_tree.c, coupling `tree`).
 *
 * What the table maps to (robot_strain.h):
 *  - create: the strain model of the actuator with the nodal rod's material and calibration
 *    path (csrLegParams' E_bend, damping_time, contact_radius into csrRodParams; a
 *    map made of an FE mode table also gives its probed section stiffness), the resolution
 *    knob, the level's setting links (`--links`), as the number of Legendre modes of each bending
 *    curvature per segment (bend_order = links - 1, 1..7: the strain level's "elements"); the
 *    leg-terrain contact of contact_soft.h with spec->contact's friction and stiffness scale.
 *  - state: the strain state [q, η, friction anchors] and the hip's last pose and velocity
 *    (x 3, R 9, v 3, ω 3): the centreline and the contact depth read the leg in the world, and
 *    a restored state must put the leg back where it was, not where the failed step left it.
 *  - actuate: the rest strains of the pressures at the step's end (the linearly implicit step
 *    takes its elastic force at its end: robot_strain_dyn.c).
 *  - prepare / finish: csr_strainPrepare and csr_strainFinish, their hip body coordinates
 *    ((angular; linear), the frame of the hip) mapped to the world frame at the hip that the
 *    driver sums at the support's centre ((linear; angular), robot_leg.h). With ΔV_b = P ΔV_w,
 *    P = [[0, Rᵀ], [Rᵀ, 0]] (R the hip's frame at the step's start), the impulse ρ_b - Z_b ΔV_b
 *    in body coordinates is Pᵀ(ρ_b - Z_b P ΔV_w) in world ones: ρ_w = Pᵀ ρ_b, Z_w = Pᵀ Z_b P.
 *    finish hands the leg the EXACT change of the hip's body twist, (Rᵀ₁ ω₁, Rᵀ₁ v₁) -
 *    (Rᵀ₀ ω₀, Rᵀ₀ v₀), from the support's actual motion (ODE's step; the support's solve used
 *    the linearisation P ΔV_w: the two differ by the frame's turn over the step, O(h ω |V|)).
 *  - advance: one step of H along a prescribed hip motion b0 -> b1 (prepare, then finish with
 *    b1), for the other coupling schemes; interfaceGains: K = 0, C = Z_w / h of the last
 *    prepared step (the impulse's dependence on the hip's velocity change).
 *  - contactShapes: capsules between points of the centreline, for drawing (the contact model
 *    itself works on the Magnus sub-interval chords and the flat foot, robot_strain.h).
 *  - contactForce, contactDepth: one evaluation of the contact at the current state serves
 *    both (the run file asks for each per leg and sample: each is the point twists and the law
 *    on every shape, ~2/3 of the output's cost at 5 ms before they were shared). The state
 *    changes only through this table's calls, each of which counts a generation (gen); the
 *    evaluation is kept with the generation it was made at (ContactCache). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "robot_calibration.h"
#include "robot_strain.h"

/* the hip's pose and velocity in the leg's state (x, R, v, ω) */
enum { BASE_DOUBLES = 18 };
/* capsules drawn along the centreline (contactShapes) */
enum { DRAWN_CAPSULES = 15 };
/* the level's step formula (the default of its setting step_order, csrLegType.step_order):
 * backward Euler until BDF2 is cheaper through the driver (docs/notes/strain_leg.md, "Second
 * order") */
enum { STRAIN_STEP_ORDER = 1 };
/* BDF2's iterates: 1 Newton on the whole residual; 0 the linearly implicit step (the inertia,
 * velocity products and weight assembled once, at the step's first iterate, refreshed where
 * the iteration stalls). 0 since branch bdf13 (docs/notes/strain_leg.md "bdf13"): the
 * robot-level defect that kept 1 ("Fast step": 24.7 mm off the rod at a fixed 5 ms) no longer
 * stands on today's level (0.16 mm from the whole-residual BDF2 at a fixed 5 ms on the flat
 * road), and each try costs 0.73x the instructions (the adaptive BDF2 at 1e-3 mm: 3.17e9
 * against 4.37e9 per simulated s for the same steps) */
enum { STRAIN_STEP_REFRESH = 0 };
/* the level's settings (kStrainSettings, at the end) */
enum {
  STRAIN_LINKS,
  STRAIN_ORDER,
  STRAIN_ACTIVE,
  STRAIN_FRICTION,
  STRAIN_TRUST,
  STRAIN_KEEP,
  STRAIN_JOINTS,
  STRAIN_SHEAR,
  STRAIN_SUB,
  STRAIN_CALQ
};

/* the contact at the current state for contactForce and contactDepth (header) */
typedef struct {
  long gen;      /* the leg's generation it was evaluated at (-1: none) */
  int rc;        /* csr_strainContactWrench's code */
  double f[3];   /* the terrain's force on the leg (N, world) */
  double depth;  /* deepest penetration (mm) */
} ContactCache;

struct csrLeg_ {
  csrActuator act;
  csrStrainModel* m;
  csrStrainData* d;
  csrRodParams rp;           /* the nodal rod's material and calibration switches */
  csrStrainParams sp;
  cscSoftParams soft;
  csrRodCalibration rodcal;  /* a mode table's actuation with its probed stiffness */
  csrBaseState b;            /* the hip now (the prepared step's start between prepare and
                                finish) */
  csrBaseState b_init;       /* the hip at creation (reset) */
  csrBaseState b_it;         /* the hip where the last Newton update left the leg (iterate's
                                frame) */
  double Zw[36];             /* the last prepared step's Z in the world frame at the hip */
  double hz;                 /* its step (s); 0 before the first */
  int ns;                    /* doubles of the strain state */
  long gen;                  /* counts the calls that may change the state (header) */
  ContactCache* cc;          /* its own allocation: filled by the const queries */
};


static void destroyStrain(csrLeg* leg) {
  if (!leg) {
    return;
  }
  csr_strainDataDestroy(leg->d);
  csr_strainModelDestroy(leg->m);
  free(leg->cc);
  free(leg);
}


int csr_strainSubIntervals(int links, int sub) {
  return sub > 0 ? sub : links <= 2 ? 2 : 4;
}


static csrLeg* createStrain(const csrLegSpec* spec, csError* err) {
  if (!spec || !spec->act || !spec->params) {
    cs_errorSet(err, CS_ERR_ARG, "strain leg: NULL spec, actuator or parameters");
    return NULL;
  }
  if (csr_actuatorValidate(spec->act, err) != CS_OK) {
    return NULL;
  }
  const csrLegParams* lp = spec->params;
  double set[CSR_LEG_MAX_SETTINGS];
  csr_legSettingsRead(&csr_leg_strain, spec->settings, set);
  const int links = (int)set[STRAIN_LINKS], step_order = (int)set[STRAIN_ORDER];
  if (links < 1 || links > CSR_STRAIN_MAX_ORDER + 1 ||
      !(lp->E_bend > 0) || !(lp->damping_time >= 0) || !(lp->contact_radius > 0) ||
      step_order < 0 || step_order > 2) {
    cs_errorSet(err, CS_ERR_RANGE, "strain leg: need 1..%d bending modes per segment (--links), "
                "E_bend > 0, damping >= 0, contact radius > 0, step order 0, 1 or 2",
                CSR_STRAIN_MAX_ORDER + 1);
    return NULL;
  }
  csrLeg* leg = calloc(1, sizeof *leg);
  if (!leg) {
    cs_errorSet(err, CS_ERR_MEMORY, "strain leg: out of memory");
    return NULL;
  }
  leg->act = *spec->act;
  leg->rp = csr_rodDefaultParams(&leg->act);
  leg->rp.E = lp->E_bend;
  leg->rp.damping_time = lp->damping_time;
  leg->rp.contact_radius = lp->contact_radius;
  leg->sp = csr_strainDefaultParams();
  leg->sp.bend_order = links - 1;
  /* the rest of the basis (robot_strain.h csrStrainParams; the settings' ranges are the
   * model's own, which csr_strainModelCreate checks again) */
  leg->sp.joint_order = (int)set[STRAIN_JOINTS];
  leg->sp.shear = (int)set[STRAIN_SHEAR];
  leg->sp.nsub = csr_strainSubIntervals(links, (int)set[STRAIN_SUB]);
  leg->sp.cal_quantum = set[STRAIN_CALQ];
  leg->sp.step_order = step_order ? step_order : STRAIN_STEP_ORDER;
  leg->sp.step_refresh = STRAIN_STEP_REFRESH;
  leg->sp.active_set = set[STRAIN_ACTIVE] != 0;
  leg->sp.friction_tangent = (int)set[STRAIN_FRICTION];
  leg->sp.slot_trust = (int)set[STRAIN_TRUST];
  leg->sp.keep_matrix = set[STRAIN_KEEP] > 0;
  if (set[STRAIN_KEEP] > 0) {
    leg->sp.keep_strain = set[STRAIN_KEEP];
  }
  leg->soft = csc_softDefaultParams();
  if (spec->contact) {
    leg->soft.mu = spec->contact->mu;
    leg->soft.k_area *= spec->contact->stiffness_scale;
  }
  csrStrainSpec ss;
  memset(&ss, 0, sizeof ss);
  ss.act = &leg->act;
  ss.rod_params = &leg->rp;
  ss.params = &leg->sp;
  ss.map = spec->map;
  if (csr_calibrationRodFromMap(spec->map, &leg->rodcal)) {
    ss.calib = &leg->rodcal;
  }
  memcpy(ss.hip, spec->hip, sizeof ss.hip);
  memcpy(ss.frame, spec->frame, sizeof ss.frame);
  memcpy(ss.gravity, spec->gravity, sizeof ss.gravity);
  ss.weightless = spec->weightless;
  ss.terrain = spec->terrain;
  ss.soft = spec->terrain ? &leg->soft : NULL;
  leg->m = csr_strainModelCreate(&ss, err);
  leg->d = leg->m ? csr_strainDataCreate(leg->m, err) : NULL;
  if (!leg->d) {
    destroyStrain(leg);
    return NULL;
  }
  leg->cc = malloc(sizeof *leg->cc);
  if (!leg->cc) {
    destroyStrain(leg);
    cs_errorSet(err, CS_ERR_MEMORY, "strain leg: out of memory");
    return NULL;
  }
  leg->cc->gen = -1;
  leg->ns = csr_strainStateSize(leg->m);
  memset(&leg->b_init, 0, sizeof leg->b_init);
  memcpy(leg->b_init.x, spec->hip, sizeof leg->b_init.x);
  memcpy(leg->b_init.R, spec->frame, sizeof leg->b_init.R);
  leg->b = leg->b_init;
  csr_strainReset(leg->m, leg->d);
  csr_strainSetBase(leg->m, leg->d, &leg->b);
  return leg;
}


static int sharedCreateStrain(const csrLegSpec* spec, void** shared, csError* err) {
  (void)spec;
  (void)err;
  *shared = NULL; /* the strain leg evaluates its calibration per leg (robot_strain.c) */
  return 0;
}


static void sharedDestroyStrain(void* shared) { (void)shared; }


static int stateSizeStrain(const csrLeg* leg) { return leg->ns + BASE_DOUBLES; }


static void baseToArray(const csrBaseState* b, double* x) {
  memcpy(x, b->x, 3 * sizeof(double));
  memcpy(x + 3, b->R, 9 * sizeof(double));
  memcpy(x + 12, b->v, 3 * sizeof(double));
  memcpy(x + 15, b->w, 3 * sizeof(double));
}


static void getStateStrain(const csrLeg* leg, double* x) {
  csr_strainGetState(leg->m, leg->d, x);
  baseToArray(&leg->b, x + leg->ns);
}


static int setStateStrain(csrLeg* leg, const double* x) {
  leg->gen++;
  const double* xb = x + leg->ns;
  for (int i = 0; i < BASE_DOUBLES; i++) {
    if (!isfinite(xb[i])) {
      return -1;
    }
  }
  if (csr_strainSetState(leg->m, leg->d, x) != 0) {
    return -1;
  }
  memcpy(leg->b.x, xb, 3 * sizeof(double));
  memcpy(leg->b.R, xb + 3, 9 * sizeof(double));
  memcpy(leg->b.v, xb + 12, 3 * sizeof(double));
  memcpy(leg->b.w, xb + 15, 3 * sizeof(double));
  csr_strainSetBase(leg->m, leg->d, &leg->b);
  return 0;
}


static void resetStrain(csrLeg* leg) {
  leg->gen++;
  csr_strainReset(leg->m, leg->d);
  leg->b = leg->b_init;
  csr_strainSetBase(leg->m, leg->d, &leg->b);
  leg->hz = 0;
  memset(leg->Zw, 0, sizeof leg->Zw);
}


static int actuateStrain(csrLeg* leg, double t0, const double p0[12], double t1,
                         const double p1[12]) {
  (void)t0;
  (void)p0;
  (void)t1;
  leg->gen++;
  return csr_strainActuate(leg->m, leg->d, p1, NULL);
}


/* the body twist (ω; v) of a hip state, in its own frame */
static void bodyTwist(const csrBaseState* b, double V[6]) {
  csu_mulMatTVec3(V, b->R, b->w);
  csu_mulMatTVec3(V + 3, b->R, b->v);
}


static void mapToWorld(csrLeg* leg, double h, const double R[9], const double Zb[36],
                       const double rb[6], double Z[36], double rho[6]);


/* the leg's condensed step (Zb, rb: hip body coordinates, robot_strain.h) as the driver's
 * world Z, ρ at the hip (robot_leg.h prepare), for the step of h from the hip's state b0 */
static void toWorld(csrLeg* leg, double h, const csrBaseState* b0, const double Zb[36],
                    double rb[6], double Z[36], double rho[6]) {
  /* The leg's step is in its hip's body coordinates: ΔV_b = R1ᵀ u1 - R0ᵀ u0 for the hip's
   * world twist u = (v, ω), and R1ᵀ = R0ᵀ (I - h [ω]×) + O(h²), so ΔV_b = P Δu + δ with
   * δ = (0; -h R0ᵀ (ω0 × v0)) + O(h Δu, h²) (ω × ω = 0 in the angular part). δ goes into the
   * impulse, ρ_b - Z_b δ: left out, the support's world solve and the leg's body step differ
   * by Z_b δ every step, a force that does not vanish with h (measured through the driver,
   * frictionless: the centre of mass drifted 0.0067 / 0.0077 / 0.0096 mm in 1 s at h = 2 / 1 /
   * 0.5 ms) */
  double wxv[3], dlin[3];
  csu_cross3(wxv, b0->w, b0->v);
  csu_mulMatTVec3(dlin, b0->R, wxv);
  for (int i = 0; i < 6; i++) {
    for (int e = 0; e < 3; e++) {
      rb[i] += h * Zb[6 * i + 3 + e] * dlin[e];
    }
  }
  mapToWorld(leg, h, b0->R, Zb, rb, Z, rho);
}


/* Z_w = Pᵀ Z_b P, ρ_w = Pᵀ ρ_b with P = [[0, Rᵀ], [Rᵀ, 0]] (world hip twist (v; ω) -> body
 * (ω_b; v_b) in the frame R) */
static void mapToWorld(csrLeg* leg, double h, const double R[9], const double Zb[36],
                       const double rb[6], double Z[36], double rho[6]) {
  double P[36];
  memset(P, 0, sizeof P);
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      const double RT = R[3 * j + i];
      P[6 * i + 3 + j] = RT;
      P[6 * (3 + i) + j] = RT;
    }
  }
  csu_congruence6(Z, P, Zb);
  for (int i = 0; i < 6; i++) {
    double r = 0;
    for (int e = 0; e < 6; e++) {
      r += P[6 * e + i] * rb[e];
    }
    rho[i] = r;
  }
  memcpy(leg->Zw, Z, sizeof leg->Zw);
  leg->hz = h;
}


static int prepareStrain(csrLeg* leg, double h, const csrBaseState* b0, double Z[36],
                         double rho[6]) {
  double Zb[36], rb[6];
  leg->gen++;
  leg->b = *b0;
  csr_strainSetBase(leg->m, leg->d, b0);
  int rc = csr_strainPrepare(leg->m, leg->d, h, Zb, rb);
  if (rc != 0) {
    return rc;
  }
  toWorld(leg, h, b0, Zb, rb, Z, rho);
  return 0;
}


/* the prepared step's Newton passes (robot_leg.h update, iterate): the hip's body-twist change
 * from the step's start (leg->b) to b1, exact as in finish */
static int updateStrain(csrLeg* leg, const csrBaseState* b1, double alpha,
                        const csrBaseState* b1_alpha, double* change) {
  double V0[6], V1[6], dV[6];
  leg->gen++;
  bodyTwist(&leg->b, V0);
  bodyTwist(b1, V1);
  for (int i = 0; i < 6; i++) {
    dV[i] = V1[i] - V0[i];
  }
  leg->b_it = b1_alpha ? *b1_alpha : *b1;
  return csr_strainUpdateDamped(leg->m, leg->d, dV, alpha, &leg->b_it, change);
}


static int releaseStrain(csrLeg* leg) { return csr_strainRelease(leg->m, leg->d); }


static int momentumResidualStrain(const csrLeg* leg, double eps[3]) {
  return csr_strainMomentumResidual(leg->m, leg->d, eps);
}


static double stepLimitStrain(csrLeg* leg, const csrBaseState* b1) {
  double V0[6], V1[6], dV[6];
  bodyTwist(&leg->b, V0);
  bodyTwist(b1, V1);
  for (int i = 0; i < 6; i++) {
    dV[i] = V1[i] - V0[i];
  }
  return csr_strainStepLimit(leg->m, leg->d, dV);
}


/* An iterate's Z, ρ in the world: the leg linearised its step at the iterate, its hip's frame
 * R_it there (its rows, the momentum and contact ones, are in that frame), so the support's
 * world twist change maps to the hip's body-twist change as ΔV_b = R_itᵀ Δu + δ_it with
 * δ_it = (R_itᵀ - R0ᵀ) u0 exact (u0 the hip's world twist at the step's start) and the impulse
 * back by R_it. Mapped with the start's frame R0 instead (before 2026-12-05), the leg's linear
 * momentum rows reached the support turned by the step's rotation, and the frictionless centre
 * of mass drifted at first order through the driver (docs/notes/strain_leg.md, "Drift"). */
static int iterateStrain(csrLeg* leg, double Z[36], double rho[6]) {
  double Zb[36], rb[6];
  leg->gen++;
  int rc = csr_strainIterate(leg->m, leg->d, Zb, rb);
  if (rc != 0) {
    return rc;
  }
  const csrBaseState* b0 = &leg->b;
  const double* Ri = leg->b_it.R;
  double dw[3], dv[3], a[3], c[3], delta[6];
  csu_mulMatTVec3(a, Ri, b0->w);
  csu_mulMatTVec3(c, b0->R, b0->w);
  csu_sub3(dw, a, c);
  csu_mulMatTVec3(a, Ri, b0->v);
  csu_mulMatTVec3(c, b0->R, b0->v);
  csu_sub3(dv, a, c);
  memcpy(delta, dw, sizeof dw);
  memcpy(delta + 3, dv, sizeof dv);
  for (int i = 0; i < 6; i++) {
    for (int e = 0; e < 6; e++) {
      rb[i] -= Zb[6 * i + e] * delta[e];
    }
  }
  mapToWorld(leg, leg->hz, Ri, Zb, rb, Z, rho);
  return 0;
}


static void stepCoeffsStrain(const csrLeg* leg, double h, double c[3]) {
  csr_strainStepCoeffs(leg->m, leg->d, h, c);
}


static int finishStrain(csrLeg* leg, const csrBaseState* b1, csrWrench* w) {
  double V0[6], V1[6], dV[6];
  leg->gen++;
  bodyTwist(&leg->b, V0);
  bodyTwist(b1, V1);
  for (int i = 0; i < 6; i++) {
    dV[i] = V1[i] - V0[i];
  }
  int rc = csr_strainFinish(leg->m, leg->d, dV, b1);
  leg->b = *b1;
  csr_strainBaseWrench(leg->m, leg->d, w);
  return rc;
}


static int advanceStrain(csrLeg* leg, double t, double H, const csrBaseState* b0,
                         const csrBaseState* b1, csrWrench* w, csError* err) {
  double Z[36], rho[6];
  int rc = prepareStrain(leg, H, b0, Z, rho);
  if (rc == 0) {
    rc = finishStrain(leg, b1, w);
  }
  if (rc != 0) {
    cs_errorSet(err, rc > 0 ? CS_ERR_REJECTED : CS_ERR_SOLVER, "t = %.4f s: a strain leg's "
                "step of %g s %s (code %d)", t, H, rc > 0 ? "did not converge" : "failed", rc);
  }
  return rc;
}


static void interfaceGainsStrain(const csrLeg* leg, double K[36], double C[36]) {
  for (int i = 0; i < 36; i++) {
    K[i] = 0;
    C[i] = leg->hz > 0 ? leg->Zw[i] / leg->hz : 0;
  }
}


static int contactShapesStrain(const csrLeg* leg, csrContactShape* shapes, int max) {
  double pts[3 * (DRAWN_CAPSULES + 1)];
  const int n = max < DRAWN_CAPSULES ? max : DRAWN_CAPSULES;
  if (n <= 0) {
    return DRAWN_CAPSULES;
  }
  csr_strainCenterline(leg->m, leg->d, DRAWN_CAPSULES + 1, pts);
  const double L = csr_strainLength(leg->m);
  for (int i = 0; i < n; i++) {
    csrContactShape* c = &shapes[i];
    memset(c, 0, sizeof *c);
    c->kind = CSR_SHAPE_CAPSULE;
    memcpy(c->a, pts + 3 * i, sizeof c->a);
    memcpy(c->b, pts + 3 * (i + 1), sizeof c->b);
    c->radius = leg->rp.contact_radius;
    c->s = (i + 0.5) * L / DRAWN_CAPSULES;
  }
  return DRAWN_CAPSULES;
}


static void centerlineStrain(const csrLeg* leg, int k, double* out) {
  csr_strainCenterline(leg->m, leg->d, k, out);
}


static double massStrain(const csrLeg* leg) { return csr_strainMass(leg->m); }


static void massMomentStrain(const csrLeg* leg, double mx[3]) {
  csr_strainMassMoment(leg->m, leg->d, mx);
}


/* the contact at the current state, evaluated once per generation (header) */
static const ContactCache* contactNow(const csrLeg* leg) {
  ContactCache* c = leg->cc;
  if (c->gen != leg->gen) {
    double mo[3];
    cscSoftReport rep;
    memset(&rep, 0, sizeof rep);
    c->rc = csr_strainContactWrench(leg->m, leg->d, c->f, mo, &rep);
    c->depth = rep.max_depth;
    c->gen = leg->gen;
  }
  return c;
}


/* the terrain's force on the leg now (robot_leg.h contactForce): every touching shape through
 * the law with the friction anchors of the state (return-mapped at the last step's end), so a
 * stance foot reports its stick force, not only the normal one */
static void contactForceStrain(const csrLeg* leg, double f[3]) {
  const ContactCache* c = contactNow(leg);
  for (int i = 0; i < 3; i++) {
    f[i] = c->rc != 0 ? 0.0 : c->f[i];
  }
}


static double contactDepthStrain(const csrLeg* leg) {
  const ContactCache* c = contactNow(leg);
  return c->rc != 0 ? 0.0 : c->depth;
}


/* the level's own settings (robot_leg.h csrLegSetting), in the order of STRAIN_* */
static const csrLegSetting kStrainSettings[] = {
    /* 2: bend_order 1, one mode less than the model's default (robot_strain.c
     * csr_strainDefaultParams): on both scenes within the bounds of the nodal rod at 16
     * elements and 0.25 ms (flat road 9 s 2.16 mm of 3, obstacle 4 s 1.82 mm of 2; 3 modes:
     * 2.69, 1.99), first bending frequency +0.43 %, 0.87x the instructions of 3 modes
     * (docs/notes/strain_leg.md "Friction cap and a lean basis"); 1 mode is cheaper still but
     * its constant curvature misses the 1 % on the frequency (Rayleigh on a uniform cantilever:
     * +27 %) */
    [STRAIN_LINKS] = {"links", "bending modes per segment", 2, 1, CSR_STRAIN_MAX_ORDER + 1, 1},
    /* the tree step's formula: 1 backward Euler, 2 BDF2 */
    [STRAIN_ORDER] = {"step_order", "1 backward Euler, 2 BDF2", STRAIN_STEP_ORDER, 1, 2, 1},
    /* the Newton passes' active set for the stance feet (robot_strain.h active_set) */
    [STRAIN_ACTIVE] = {"active_set", "1 contact ghosts in the Newton passes, 0 the law alone",
                       1, 0, 1, 1},
    /* the friction in the Newton iterates' matrix (robot_strain.h friction_tangent) */
    [STRAIN_FRICTION] = {"friction_tangent",
                         "0 the anchors' secant in the Newton iterates, 1 the law's tangent",
                         0, 0, 1, 1},
    /* the passes' globalisation at the friction's saturation (robot_strain.h slot_trust) */
    [STRAIN_TRUST] = {"slot_trust",
                      "1 a Newton pass moves a foot slot at most two stick ranges, "
                      "0 the full move", 0, 0, 1, 1},
    /* the legs' iteration matrix across steps (robot_strain.h keep_matrix, keep_strain) */
    [STRAIN_KEEP] = {"keep_matrix",
                     "0 a new iteration matrix every step, > 0 each leg's factor kept across "
                     "steps until a mode moves this far (rad or strain over its piece)",
                     0, 0, 1, 0},
    /* the solid joints LS12, LS23: constant curvature (robot_strain.c csr_strainDefaultParams:
     * their bending under the leg's loads is not negligible) or rigid */
    [STRAIN_JOINTS] = {"joints", "the joints' bending modes less one (-1 rigid, 0 constant "
                       "curvature)", 0, -1, CSR_STRAIN_MAX_ORDER, 1},
    /* the shears σ1, σ2 as unknowns (1) or zero (0, Kirchhoff) */
    [STRAIN_SHEAR] = {"shear", "1 the shears are unknowns, 0 Kirchhoff (no shear)", 1, 0, 1, 1},
    /* Magnus sub-intervals per flexible piece (the kinematics' and the capsules' resolution);
     * 0: by the basis (csr_strainSubIntervals: 2 at links <= 2, 4 above) */
    [STRAIN_SUB] = {"sub", "Magnus sub-intervals per flexible piece (0: 2 at links <= 2, 4 above)",
                    0, 0, 16, 1},
    /* the calibration's pressure resolution (robot_strain.h cal_quantum): 0 the pressures as
     * given */
    [STRAIN_CALQ] = {"cal_quantum",
                     "the calibration's pressure resolution in MPa (0: exact; the pressures "
                     "rounded to its multiples, a segment's calibration reused while they hold)",
                     0, 0, 0.1, 0},
};

const csrLegType csr_leg_strain = {
    .name = "strain",
    .settings = kStrainSettings,
    .nsettings = (int)(sizeof kStrainSettings / sizeof kStrainSettings[0]),
    .in_world = 0,
    .create = createStrain,
    .destroy = destroyStrain,
    .sharedCreate = sharedCreateStrain,
    .sharedDestroy = sharedDestroyStrain,
    .stateSize = stateSizeStrain,
    .getState = getStateStrain,
    .setState = setStateStrain,
    .reset = resetStrain,
    .actuate = actuateStrain,
    .advance = advanceStrain,
    .interfaceGains = interfaceGainsStrain,
    .contactShapes = contactShapesStrain,
    .centerline = centerlineStrain,
    .mass = massStrain,
    .massMoment = massMomentStrain,
    .contactDepth = contactDepthStrain,
    .contactForce = contactForceStrain,
    /* 0.5 ms: the largest step whose track is within 1 mm of the half-step run on both scenes
     * (issue 32's rule), on the scenes' current tables and gaits: the obstacle's first 4 s
     * (k3 table) at 1 ms are 1.69 mm from 0.5 ms (0.75 ms: 0.79 from 0.5 ms), at 0.5 ms
     * 0.52 mm from 0.25 ms; the flat road's 9 s at 1 ms are 0.21 mm from 0.5 ms
     * (docs/notes/strain_leg.md "The flat gait of the fifth session"). On the obstacle's
     * earlier 9-mode table 1 ms was 0.23 mm from 0.5 ms. */
    .step = 5e-4,
    .step_order = STRAIN_STEP_ORDER,
    .prepare = prepareStrain,
    .finish = finishStrain,
    .update = updateStrain,
    .iterate = iterateStrain,
    .release = releaseStrain,
    .stepLimit = stepLimitStrain,
    .stepCoeffs = stepCoeffsStrain,
    .momentumResidual = momentumResidualStrain,
};


void csr_legStrainCounts(const csrLeg* leg, long* steps, long* factors, long* kept) {
  csr_strainCounts(leg->d, steps, factors, kept);
}

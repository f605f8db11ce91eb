/* robot_rod_model.c: the Cosserat-rod leg's model layer: parameters, pieces from the actuator's
 * section, the discretisation, kinematics, strains, internal forces and energy (one kernel
 * shared by the CVODE right-hand side and the static solver), and the shape queries.
 *
 * ---- Discretisation (rationale) -------------------------------------------------------------
 * Nodal (PyElastica, DisMech): node positions x_0..x_N and one material frame per element,
 * rather than strain-parameterised (SoRoSim PCS/variable strain), for three measured reasons
 * (tests/robot/bench_rod pcs prints them):
 *  - accuracy per unknown: both are second order; on a uniform Timoshenko cantilever under a
 *    tip force PCS has half the nodal rod's tip error at equal unknowns (48 unknowns: 3.9e-3
 *    against 7.7e-3; 96: 9.7e-4 against 1.9e-3), i.e. the nodal rod needs √2 times the
 *    unknowns for the same error. The pure-curvature actuation that favours PCS is exact in the
 *    nodal rod too: its elements rest as chords of the calibrated arcs, so the unloaded
 *    actuated nodes lie on them at any N (test_rod_static);
 *  - cost: the nodal right-hand side is O(N) with a diagonal mass matrix (the leg's 14
 *    elements, 84 unknowns: 1.6 µs) and its Newton matrix is block tridiagonal; PCS couples all
 *    strain modes through a dense configuration-dependent mass matrix: its assembly with two
 *    Gauss points per piece and Cholesky solve alone take 12 µs (5 pieces, 30 unknowns) and
 *    79 µs (10 pieces, 60 unknowns, the nodal leg's accuracy), 50 times the nodal cost at equal
 *    accuracy, and its Jacobian is dense (6n right-hand sides per difference Jacobian against
 *    3 x 12 here);
 *  - contact: a capsule touching a step edge anywhere along the leg is a force on two nodes
 *    here; in PCS it needs the geometric Jacobian at the contact point, and the strain basis
 *    must be refined where contacts move.
 * Elements: 4 per segment and 1 per joint by default (bench_rod: the foot path of the
 * flat-road gait is within 0.36 mm of 16 elements per segment, 0.66 mm at 3, 1.5 mm at 2).
 *
 * ---- Energy and forces ----------------------------------------------------------------------
 *   E = Σ_e ½ l_e (σ_e - σ0)ᵀ S (σ_e - σ0) + Σ_i ½ (θ_i - θ0_i)ᵀ C_i⁻¹ (θ_i - θ0_i),
 * σ_e = Q_eᵀ(x_e - x_{e-1})/l_e - e3, S = diag(GA1, GA2, EA); θ_i = log(Q_iᵀQ_{i+1}) the
 * rotation vector between frames i and i+1 (frame 0: the clamp), C_i the series compliance of
 * the two half elements, (l_i/2)/B_a + (l_{i+1}/2)/B_b with B = (EI1, EI2, GJ) (at the hip only
 * element 1's half), θ0_i = (l_i/2) u0_a + (l_{i+1}/2) u0_b the intrinsic rotation. Forces are
 * the exact gradients, with frame variations δQ = Q[δψ] (body): ∂θ/∂ψ_{i+1} = J_r⁻¹(θ),
 * ∂θ/∂ψ_i = -J_r⁻¹(θ) R_relᵀ, and the shear torque on element e is l_e (e3 + σ_e) × S(σ_e - σ0).
 * (PyElastica takes the moment itself as the torque; the J_r⁻¹ factor makes the discrete forces
 * conservative, which the energy test checks.)
 * Kelvin-Voigt damping adds τ_d times the strain rate to every strain in the force laws:
 * σ̇ = Qᵀ(v_e - v_{e-1})/l - ω_e × (e3 + σ), θ̇ = J_r⁻¹(θ)(ω_{i+1} - R_relᵀ ω_i); the same
 * Jacobians map the viscous stresses back, so the dissipation τ_d ε̇ᵀKε̇ is never negative.
 *
 * ---- Sections (the default, before the FE calibration supplies EI(p), EA(p), ...) ----------
 * E' = 8 C10: the small-strain modulus of the Yeoh law with the fibres holding λ2 = 1, the one
 * the analytic model uses (robot_analytic.h D2; csr_defaultLegParams, robot_leg.c); G = 2 C10 = μ0
 * of the incompressible silicone; Timoshenko coefficient of a rectangle, Cowper's
 * k = 10(1 + ν)/(12 + 11ν) = 0.857 at ν = 1/2. Areas and second moments come from the
 * analytic model's exact section quadrature. Each actuated segment is one uniform piece whose
 * stiffness is the series (compliance-weighted) mean of its chambered length Lc = S - 2c
 * (holed section) and its two solid caps c (full section): EA = S / (Lc/(E'A_h) + 2c/(E'A_f)),
 * the same for EI, kGA and GJ, so the calibration's per-segment curvature acts on a uniform
 * piece; with the presets this is 4 % stiffer in bending than the holed section alone (which
 * the retired prb level used over all of S). Joints LS12, LS23: solid blocks of the full section (docs/reference.md
 * assumption), passive. Torsion: St-Venant's J = 0.1406 (2a)^4 of the square (Roark), the holed
 * section scaled by its polar-moment ratio (an estimate: twist is barely loaded in this robot).
 * Mass and rotary inertia: the silicone density over the filleted square, chambers hollow
 * over Lc, averaged over each piece (exact total and centre
 * of mass per piece: the segment is symmetric). Nodes carry the lumped masses of their half
 * elements, elements their rotary inertia. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "robot_analytic.h"
#include "robot_rod_internal.h"

/* St-Venant torsion constant of a square of side h: J = 0.1406 h^4 (Roark, Table 10.7) */
#define CSR_ROD_TORSION_SQUARE 0.1406


csrRodParams csr_rodDefaultParams(const csrActuator* act) {
  csrRodParams p;
  /* 4 elements per 50 mm segment and 1 per 8 mm joint (14 elements, 182 states): a tip load's
   * deflection is within 0.27 % of the piecewise Timoshenko cantilever (test_rod_bend_cli), the
   * gait's foot path within 0.36 mm (0.2 % of the leg) of 16 elements per segment (bench_rod),
   * well inside the 2 %-of-leg target against FE; 3 per segment are 25 % cheaper (0.66 mm) */
  p.elements_per_segment = 4;
  p.elements_per_joint = 1;
  double C10 = act ? act->C10 : 0.11;
  p.E = 8.0 * C10;
  p.G = 2.0 * C10;
  p.shear_coeff = 10.0 * 1.5 / (12.0 + 11.0 * 0.5);
  /* the legs' material damping (csr_defaultLegParams, robot_leg.c: loss factor ≈ 0.3 at the
   * first mode) */
  p.damping_time = 0.02;
  /* tolerances, chosen by the foot path of a leg in the flat-road gait against an rtol 1e-8
   * run (bench_rod gait): these give 0.19 mm over 1.5 s at ~300 steps per simulated second,
   * about the discretisation error of 4 elements per segment (0.36 mm against 16); the
   * previous 1 µm / 1e-6 / 0.01 mm/s / 1e-3 rad/s gave 0.03 mm at 2.3 times the steps. The
   * angular velocity of the stiff elements' overdamped shear-rotation modes (their slow branch
   * relaxes with τ_d) is what limits the step, so atol_omega matters most. */
  p.rtol = 1e-4;
  p.atol_pos = 1e-2;
  p.atol_rot = 1e-5;
  p.atol_vel = 0.5;
  p.atol_omega = 5e-3;
  p.atol_hist = 1e-3;
  p.atol_wrench = 1e-3;
  p.max_steps = 20000;
  /* all five orders: with Kelvin-Voigt damping the stiff modes are overdamped (real
   * eigenvalues), where BDF 3-5 are stable; undamped runs should use 2 (A-stable) */
  p.max_order = 5;
  p.contact_radius = act ? act->a : 1.0;
  /* scaled residual (forces / characteristic force, moments / (force x length)) at
   * convergence: 1e-10 is ~1e4 above round-off for N ~ 14..100 elements */
  p.static_tol = 1e-10;
  p.static_max_iter = 40;
  p.cal_drop = 0;
  return p;
}


int csr_rodLegPieces(const csrActuator* act, const csrRodParams* par,
                     csrRodPiece pieces[CSR_ROD_MAX_PIECES]) {
  csrSectionProps sp;
  memset(&sp, 0, sizeof sp);
  if (csr_analyticSectionCompute(act, NULL, &sp, NULL) != CS_OK) {
    return 0;
  }
  const double E = par->E, G = par->G, k = par->shear_coeff;
  /* torsion: square of side 2a, holed section scaled by its polar moment ratio */
  double side = 2 * act->a;
  double Jf = CSR_ROD_TORSION_SQUARE * side * side * side * side;
  double Jh = Jf * sp.I_holed / sp.I_full;
  /* full-section piece (joints) */
  csrRodPiece full;
  memset(&full, 0, sizeof full);
  full.section.EA = E * sp.area_full;
  full.section.GA[0] = full.section.GA[1] = k * G * sp.area_full;
  full.section.EI[0] = full.section.EI[1] = E * sp.I_full;
  full.section.GJ = G * Jf;
  full.rhoA = act->rho * sp.area_full;
  full.rhoI[0] = full.rhoI[1] = act->rho * sp.I_full;
  full.rhoI[2] = 2 * act->rho * sp.I_full;
  full.segment = -1;
  int n = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    double S = act->S[s], Lc = S - 2 * act->c, cc = 2 * act->c;
    csrRodPiece p = full;
    p.length = S;
    p.nelem = par->elements_per_segment;
    p.segment = s;
    /* series (compliance) mean over the chambered length and the caps */
    p.section.EA = S / (Lc / (E * sp.area_holed) + cc / (E * sp.area_full));
    p.section.GA[0] = p.section.GA[1] =
        S / (Lc / (k * G * sp.area_holed) + cc / (k * G * sp.area_full));
    p.section.EI[0] = p.section.EI[1] = S / (Lc / (E * sp.I_holed) + cc / (E * sp.I_full));
    p.section.GJ = S / (Lc / (G * Jh) + cc / (G * Jf));
    /* mass and rotary inertia averaged over the piece */
    p.rhoA = act->rho * (sp.area_full * cc + sp.area_holed * Lc) / S;
    p.rhoI[0] = p.rhoI[1] = act->rho * (sp.I_full * cc + sp.I_holed * Lc) / S;
    p.rhoI[2] = 2 * p.rhoI[0];
    pieces[n++] = p;
    if (s < CSR_NSEG - 1) {
      csrRodPiece j = full;
      j.length = act->LS[s];
      j.nelem = par->elements_per_joint;
      pieces[n++] = j;
    }
  }
  return n;
}


void csr_rodModelDestroy(csrRodModel* m) {
  if (!m) {
    return;
  }
  free(m->s);
  free(m->l);
  free(m->ep);
  free(m->mnode);
  free(m->Jel);
  free(m->boff);
  free(m->nh);
  free(m);
}


/* checks of the spec and parameters shared by both constructors */
static csStatus checkSpec(const csrRodPiece* pieces, int npiece, const csrRodSpec* spec,
                          const csrRodParams* par, csError* err);


static csStatus checkSpec(const csrRodPiece* pieces, int npiece, const csrRodSpec* spec,
                          const csrRodParams* par, csError* err) {
  if (npiece < 1 || npiece > CSR_ROD_MAX_PIECES) {
    return cs_errorSet(err, CS_ERR_ARG, "rod: %d pieces (need 1..%d)", npiece,
                       CSR_ROD_MAX_PIECES);
  }
  int need_act = 0;
  for (int k = 0; k < npiece; k++) {
    const csrRodPiece* p = &pieces[k];
    const csrRodSection* S = &p->section;
    if (!(p->length > 0) || p->nelem < 1 || p->nelem > 1000 || p->segment < -1 ||
        p->segment >= CSR_NSEG) {
      return cs_errorSet(err, CS_ERR_RANGE,
                         "rod: piece %d: need length > 0, 1..1000 elements, segment -1..2", k);
    }
    if (!(S->EA > 0) || !(S->GA[0] > 0) || !(S->GA[1] > 0) || !(S->EI[0] > 0) ||
        !(S->EI[1] > 0) || !(S->GJ > 0) || !(p->rhoA > 0) || !(p->rhoI[0] > 0) ||
        !(p->rhoI[1] > 0) || !(p->rhoI[2] > 0) || !isfinite(S->EA + S->GA[0] + S->GA[1] +
                                                              S->EI[0] + S->EI[1] + S->GJ)) {
      return cs_errorSet(err, CS_ERR_RANGE,
                         "rod: piece %d: stiffness, mass and rotary inertia must be > 0 and "
                         "finite", k);
    }
    need_act |= p->segment >= 0;
  }
  (void)need_act; /* pieces with a segment but no calibration stay at their rest strains */
  if (!(par->damping_time >= 0) || !(par->rtol > 0) || !(par->atol_pos > 0) ||
      !(par->atol_rot > 0) || !(par->atol_vel > 0) || !(par->atol_omega > 0) ||
      !(par->atol_hist > 0) || !(par->atol_wrench > 0) || par->max_steps < 1 ||
      par->max_order < 1 || par->max_order > 5 || !(par->contact_radius > 0) ||
      !(par->static_tol > 0) || par->static_max_iter < 1 ||
      (par->cal_drop & ~(CSR_CAL_DROP_STRETCH | CSR_CAL_DROP_STIFFNESS))) {
    return cs_errorSet(err, CS_ERR_RANGE,
                       "rod: parameters: need damping_time >= 0, tolerances > 0, max_steps >= "
                       "1, max_order 1..5, contact_radius > 0, static_max_iter >= 1, cal_drop "
                       "of CSR_CAL_DROP_* only");
  }
  if (spec->contact.eval && (spec->contact.nhist < 0 || spec->contact.nhist > CSR_ROD_MAX_HIST ||
                             spec->contact.nhist_foot < 0 ||
                             spec->contact.nhist_foot > CSR_ROD_MAX_HIST)) {
    return cs_errorSet(err, CS_ERR_RANGE, "rod: contact history of %d / %d (foot) variables per "
                       "element (0..%d)", spec->contact.nhist, spec->contact.nhist_foot,
                       CSR_ROD_MAX_HIST);
  }
  const double* F = spec->frame;
  double e1[3] = {F[0], F[3], F[6]}, e2[3] = {F[1], F[4], F[7]}, e3[3] = {F[2], F[5], F[8]};
  double c[3];
  csu_cross3(c, e1, e2);
  if (fabs(csu_dot3(e1, e1) - 1) > 1e-9 || fabs(csu_dot3(e2, e2) - 1) > 1e-9 ||
      fabs(csu_dot3(e1, e2)) > 1e-9 || fabs(csu_dot3(c, e3) - 1) > 1e-9) {
    return cs_errorSet(err, CS_ERR_ARG, "rod: the base frame is not a right-handed rotation");
  }
  for (int k = 0; k < 3; k++) {
    if (!isfinite(spec->hip[k]) || !isfinite(spec->gravity[k])) {
      return cs_errorSet(err, CS_ERR_ARG, "rod: hip and gravity must be finite");
    }
  }
  return CS_OK;
}


csrRodModel* csr_rodModelCreatePieces(const csrRodPiece* pieces, int npiece,
                                      const csrRodSpec* spec, csError* err) {
  if (!pieces || !spec || (!spec->act && !spec->params)) {
    cs_errorSet(err, CS_ERR_ARG, "rod: NULL pieces or spec (or neither actuator nor params)");
    return NULL;
  }
  csrRodParams par = spec->params ? *spec->params : csr_rodDefaultParams(spec->act);
  if (checkSpec(pieces, npiece, spec, &par, err) != CS_OK) {
    return NULL;
  }
  csrRodModel* m = calloc(1, sizeof *m);
  if (!m) {
    cs_errorSet(err, CS_ERR_MEMORY, "rod: out of memory");
    return NULL;
  }
  m->par = par;
  if (spec->act) {
    m->act = *spec->act;
    m->has_act = 1;
  }
  m->map = spec->map;
  m->calib = spec->calib;
  m->contact = spec->contact;
  if (!m->contact.eval) {
    m->contact.nhist = m->contact.nhist_foot = 0;
  }
  m->npiece = npiece;
  memcpy(m->piece, pieces, (size_t)npiece * sizeof *pieces);
  memcpy(m->hip, spec->hip, sizeof m->hip);
  memcpy(m->frame, spec->frame, sizeof m->frame);
  if (!spec->weightless) {
    memcpy(m->gravity, spec->gravity, sizeof m->gravity);
  }
  int N = 0;
  for (int k = 0; k < npiece; k++) {
    N += pieces[k].nelem;
    if (pieces[k].segment >= 0) {
      m->seg_len[pieces[k].segment] += pieces[k].length;
    }
  }
  m->N = N;
  m->s = calloc((size_t)N + 1, sizeof(double));
  m->boff = calloc((size_t)N + 2, sizeof(int));
  m->nh = calloc((size_t)N + 1, sizeof(int));
  m->l = calloc((size_t)N + 1, sizeof(double));
  m->ep = calloc((size_t)N + 1, sizeof(int));
  m->mnode = calloc((size_t)N + 1, sizeof(double));
  m->Jel = calloc(3 * ((size_t)N + 1), sizeof(double));
  if (!m->s || !m->l || !m->ep || !m->mnode || !m->Jel || !m->boff || !m->nh) {
    csr_rodModelDestroy(m);
    cs_errorSet(err, CS_ERR_MEMORY, "rod: out of memory");
    return NULL;
  }
  /* the state's blocks: 13 + the element's contact history */
  for (int e = 1; e <= N; e++) {
    m->nh[e] = e < N ? m->contact.nhist : m->contact.nhist_foot;
    m->nhmax = m->nh[e] > m->nhmax ? m->nh[e] : m->nhmax;
    m->boff[e + 1] = m->boff[e] + CSR_ROD_BH + m->nh[e];
  }
  m->nstate = m->boff[N + 1];
  /* elements of equal length within each piece; lumped masses and rotary inertia */
  int e = 0;
  double s = 0;
  for (int k = 0; k < npiece; k++) {
    const csrRodPiece* p = &pieces[k];
    double le = p->length / p->nelem;
    for (int j = 0; j < p->nelem; j++) {
      e++;
      m->l[e] = le;
      m->ep[e] = k;
      m->s[e] = s + (j + 1) * le;
      double me = p->rhoA * le;
      m->mnode[e - 1] += 0.5 * me;
      m->mnode[e] += 0.5 * me;
      for (int c = 0; c < 3; c++) {
        m->Jel[3 * e + c] = p->rhoI[c] * le;
      }
    }
    s += p->length;
    m->s[e] = s; /* exact piece boundary (no accumulated round-off) */
  }
  m->L = s;
  /* the clamped hip node carries no mass: its half element goes to node 1. A mass on node 0
   * would ride on the support between exchanges, and under the Jacobi couplings (the legs
   * advance along a predicted hip motion, the support then moves otherwise) its momentum
   * change m0 Δv at each exchange belongs to no advance: the support moved as if 8 m0 (10 g
   * of its 50) were missing. Measured on the paper's table, first second: the staggered
   * scheme converged (10-40 µs) 0.9 mm away from the Gauss-Seidel one (whose hip path is the
   * support's actual motion); charging m0 Δv one exchange late instead made the staggered
   * scheme agree (-3.70 mm at 5 and 10 µs, gs -3.71) but diverge at 20 µs. Moving the mass by
   * half an element is a first-order change of the discretisation, O(l_e / L) */
  m->mnode[1] += m->mnode[0];
  m->mnode[0] = 0;
  for (int i = 0; i <= N; i++) {
    m->mass += m->mnode[i];
  }
  return m;
}


csrRodModel* csr_rodModelCreate(const csrRodSpec* spec, csError* err) {
  if (!spec || !spec->act) {
    cs_errorSet(err, CS_ERR_ARG, "rod: NULL spec or actuator");
    return NULL;
  }
  if (csr_actuatorValidate(spec->act, err) != CS_OK) {
    return NULL;
  }
  csrRodParams par = spec->params ? *spec->params : csr_rodDefaultParams(spec->act);
  if (par.elements_per_segment < 1 || par.elements_per_joint < 1 || !(par.E > 0) ||
      !(par.G > 0) || !(par.shear_coeff > 0)) {
    cs_errorSet(err, CS_ERR_RANGE,
                "rod: need >= 1 element per segment and joint, E > 0, G > 0, shear coeff > 0");
    return NULL;
  }
  csrRodPiece pieces[CSR_ROD_MAX_PIECES];
  int n = csr_rodLegPieces(spec->act, &par, pieces);
  if (n == 0) {
    cs_errorSet(err, CS_ERR_RANGE, "rod: the actuator's section cannot be integrated");
    return NULL;
  }
  csrRodSpec sp = *spec;
  sp.params = &par;
  return csr_rodModelCreatePieces(pieces, n, &sp, err);
}


int csr_rodElements(const csrRodModel* m) { return m->N; }
int csr_rodStateOffset(const csrRodModel* m, int e) { return m->boff[e]; }
int csr_rodStateHist(const csrRodModel* m, int e) { return m->nh[e]; }
int csr_rodStateSize(const csrRodModel* m) { return m->nstate; }
double csr_rodMass(const csrRodModel* m) { return m->mass; }
double csr_rodLength(const csrRodModel* m) { return m->L; }
const double* csr_rodNodeArc(const csrRodModel* m) { return m->s; }


/* segment seg's actuation at p as the calibration gives it: a mode table's own adapter, else
 * the bend map's bend and stretch turned into intrinsic strains */
static int actuationEval(const csrRodModel* m, int seg, const double p[4],
                         csrRodSegmentActuation* out, char* msg, size_t msg_size) {
  memset(out, 0, sizeof *out);
  if (m->calib && m->calib->eval) {
    int rc = m->calib->eval(m->calib->ctx, seg, p, out);
    if (rc != 0 && msg) {
      snprintf(msg, msg_size, "rod calibration '%s' failed (%d) for segment II%d at p = "
               "(%.4g, %.4g, %.4g, %.4g) MPa", m->calib->name ? m->calib->name : "?", rc, seg + 1,
               p[0], p[1], p[2], p[3]);
    }
    return rc;
  }
  if (!m->map || !m->map->eval) {
    return 0; /* no calibration: the segment keeps its rest strains */
  }
  double bend[2] = {0, 0}, stretch = 1;
  int rc = m->map->eval(m->map->ctx, seg, p, bend, &stretch);
  if (rc != 0) {
    if (msg) {
      snprintf(msg, msg_size, "calibration '%s' failed (%d) for segment II%d at p = (%.4g, "
               "%.4g, %.4g, %.4g) MPa%s", m->map->name ? m->map->name : "?", rc, seg + 1, p[0],
               p[1], p[2], p[3], rc == CSR_MAP_OUT_OF_RANGE ? " (above the calibrated range)" : "");
    }
    return rc;
  }
  /* turning d3 towards +e1 by bend[0] is a rotation about +e2, towards +e2 about -e1
   * (robot_rod.h); the bend is spread over the segment's length */
  double S = m->seg_len[seg] > 0 ? m->seg_len[seg] : 1.0;
  out->u0[0] = -bend[1] / S;
  out->u0[1] = bend[0] / S;
  out->u0[2] = 0;
  out->sigma0[2] = stretch - 1;
  return 0;
}


int csr_rodActuationEval_(const csrRodModel* m, int seg, const double p[4],
                          csrRodSegmentActuation* out, char* msg, size_t msg_size) {
  int rc = actuationEval(m, seg, p, out, msg, msg_size);
  /* the parts a study leaves out (csrRodParams.cal_drop): after the evaluation, so the
   * calibration's range checks still apply */
  if (rc == 0 && (m->par.cal_drop & CSR_CAL_DROP_STRETCH)) {
    out->sigma0[2] = 0;
  }
  if (rc == 0 && (m->par.cal_drop & CSR_CAL_DROP_STIFFNESS)) {
    out->has_section = 0;
  }
  return rc;
}


void csr_rodLoadsFromActuation_(const csrRodModel* m, const csrRodSegmentActuation* act,
                                csrRodLoads* ld) {
  for (int k = 0; k < m->npiece; k++) {
    const csrRodPiece* p = &m->piece[k];
    const csrRodSection* S = &p->section;
    memset(ld->u0[k], 0, sizeof ld->u0[k]);
    memset(ld->sigma0[k], 0, sizeof ld->sigma0[k]);
    if (act && p->segment >= 0) {
      const csrRodSegmentActuation* a = &act[p->segment];
      memcpy(ld->u0[k], a->u0, sizeof a->u0);
      memcpy(ld->sigma0[k], a->sigma0, sizeof a->sigma0);
      if (a->has_section) {
        S = &a->section;
      }
    }
    /* an element inside a piece of constant intrinsic bending |κ| is at rest as a chord of
     * that arc: (1 + ε0) l sinc(|κ| l / 2) along its midpoint tangent. With this rest length
     * the unloaded actuated rod puts every node exactly on the calibrated arcs (any N),
     * instead of on the chord polygon of elements of length l (O((κl)²) longer) */
    double kb = hypot(ld->u0[k][0], ld->u0[k][1]) * 0.5 * p->length / p->nelem;
    if (kb > 0) {
      double sinc = kb < 1e-4 ? 1 - kb * kb / 6 : sin(kb) / kb;
      ld->sigma0[k][2] = (1 + ld->sigma0[k][2]) * sinc - 1;
    }
    ld->Sd[k][0] = S->GA[0];
    ld->Sd[k][1] = S->GA[1];
    ld->Sd[k][2] = S->EA;
    ld->B[k][0] = S->EI[0];
    ld->B[k][1] = S->EI[1];
    ld->B[k][2] = S->GJ;
  }
}


void csr_rodRestState_(const csrRodModel* m, double* state) {
  double q[4];
  csu_mat3ToQuat(q, m->frame);
  const double e3[3] = {m->frame[2], m->frame[5], m->frame[8]};
  memset(state, 0, (size_t)m->nstate * sizeof(double));
  for (int e = 1; e <= m->N; e++) {
    double* b = state + m->boff[e];
    csu_addScl3(b + CSR_ROD_BX, m->hip, e3, m->s[e]);
    memcpy(b + CSR_ROD_BQ, q, sizeof q);
  }
}


int csr_rodUnpack_(const csrRodModel* m, csrRodWork* wk, const double* state, const double x0[3],
                   const double q0[4], const double v0[3], const double w0[3]) {
  return csr_rodUnpackPart_(m, wk, state, m->N, x0, q0, v0, w0);
}


int csr_rodUnpackPart_(const csrRodModel* m, csrRodWork* wk, const double* state, int last,
                       const double x0[3], const double q0[4], const double v0[3],
                       const double w0[3]) {
  wk->last = last < 1 ? 1 : (last > m->N ? m->N : last);
  memcpy(wk->x, x0, 3 * sizeof(double));
  memcpy(wk->q, q0, 4 * sizeof(double));
  memcpy(wk->v, v0, 3 * sizeof(double));
  memcpy(wk->w, w0, 3 * sizeof(double));
  csu_quatToMat3(wk->R, wk->q);
  for (int e = 1; e <= wk->last; e++) {
    const double* b = state + m->boff[e];
    double* q = wk->q + 4 * e;
    double sum = 0;
    for (int k = 0; k < CSR_ROD_BH; k++) {
      sum += b[k];
    }
    if (!isfinite(sum)) {
      return 1;
    }
    memcpy(wk->x + 3 * e, b + CSR_ROD_BX, 3 * sizeof(double));
    memcpy(q, b + CSR_ROD_BQ, 4 * sizeof(double));
    /* the quaternion is normalised where it is used; a norm far from 1 means the state is
     * not a rotation any more (a wild Newton iterate), which the step must not accept */
    double n = csr_rodQnormalize(q);
    if (!(n > 0.5 && n < 2.0)) {
      return 1;
    }
    csu_quatToMat3(wk->R + 9 * e, q);
    memcpy(wk->v + 3 * e, b + CSR_ROD_BV, 3 * sizeof(double));
    memcpy(wk->w + 3 * e, b + CSR_ROD_BW, 3 * sizeof(double));
  }
  return 0;
}


/* node i's intrinsic rotation θ0 and series compliance C (see the header's energy) */
static void nodeSpring(const csrRodModel* m, const csrRodLoads* ld, int i, double th0[3],
                       double C[3]) {
  int pb = m->ep[i + 1];
  double hb = 0.5 * m->l[i + 1];
  for (int k = 0; k < 3; k++) {
    th0[k] = hb * ld->u0[pb][k];
    C[k] = hb / ld->B[pb][k];
  }
  if (i > 0) {
    int pa = m->ep[i];
    double ha = 0.5 * m->l[i];
    for (int k = 0; k < 3; k++) {
      th0[k] += ha * ld->u0[pa][k];
      C[k] += ha / ld->B[pa][k];
    }
  }
}


/* one contact shape of element e from its chord ends, their velocities, its frame R and its
 * body angular velocity wb */
static void fillShape(const csrRodModel* m, int e, const double x0[3], const double x1[3],
                      const double v0[3], const double v1[3], const double R[9],
                      const double wb[3], csrRodShape* sh) {
  memset(sh, 0, sizeof *sh);
  sh->element = e;
  double dx[3];
  csu_sub3(dx, x1, x0);
  memcpy(sh->p0, x0, sizeof sh->p0);
  memcpy(sh->p1, x1, sizeof sh->p1);
  memcpy(sh->v0, v0, sizeof sh->v0);
  memcpy(sh->v1, v1, sizeof sh->v1);
  csu_addScl3(sh->centre, x0, dx, 0.5);
  memcpy(sh->R, R, sizeof sh->R);
  csu_mulMatVec3(sh->omega, R, wb);
  if (e == m->N) {
    /* the foot: a block of the square section whose +d3 face is the sole */
    sh->kind = CSR_ROD_SHAPE_BOX;
    sh->half[0] = sh->half[1] = m->has_act ? m->act.a : m->par.contact_radius;
  } else {
    sh->kind = CSR_ROD_SHAPE_CAPSULE;
    sh->radius = m->par.contact_radius;
  }
  sh->half[2] = 0.5 * csu_norm3(dx);
}


/* the contact hook on every shape: its node forces to the element's two nodes, its couple to
 * the element's frame */
static int applyContact(const csrRodModel* m, csrRodWork* wk, int last, char* msg,
                        size_t msg_size) {
  static const double kZeroHist[CSR_ROD_MAX_HIST] = {0};
  double dh_local[CSR_ROD_MAX_HIST];
  for (int e = 1; e <= last; e++) {
    const double* x0 = wk->x + 3 * (e - 1);
    const double* Re = wk->R + 9 * e;
    csrRodShape sh;
    fillShape(m, e, x0, wk->x + 3 * e, wk->v + 3 * (e - 1), wk->v + 3 * e, Re, wk->w + 3 * e,
              &sh);
    size_t off = (size_t)m->boff[e] + CSR_ROD_BH;
    const double* hist = wk->hist ? wk->hist + off : NULL;
    double* dhist = wk->dhist ? wk->dhist + off : dh_local;
    for (int k = 0; k < m->nh[e]; k++) {
      dhist[k] = 0;
    }
    double f0[3] = {0, 0, 0}, f1[3] = {0, 0, 0}, mc[3] = {0, 0, 0};
    int rc = m->contact.eval(m->contact.ctx, &sh, hist ? hist : kZeroHist, dhist, f0, f1, mc);
    if (rc != 0) {
      if (msg) {
        snprintf(msg, msg_size, "contact hook returned %d on element %d", rc, e);
      }
      return rc;
    }
    double tb[3];
    csu_add3(wk->F + 3 * (e - 1), wk->F + 3 * (e - 1), f0);
    csu_add3(wk->F + 3 * e, wk->F + 3 * e, f1);
    csr_rodMulMatTVec(tb, Re, mc);
    csu_add3(wk->T + 3 * e, wk->T + 3 * e, tb);
  }
  return 0;
}


int csr_rodContactAccel_(const csrRodModel* m, const double* state, int e, const double x0[3],
                         const double v0[3], double* out, int* active) {
  static const double kZeroHist[CSR_ROD_MAX_HIST] = {0};
  const double* b = state + m->boff[e];
  const double* bp = e > 1 ? state + m->boff[e - 1] : NULL;
  double q[4], R[9];
  memcpy(q, b + CSR_ROD_BQ, sizeof q);
  if (!(csr_rodQnormalize(q) > 0)) {
    return 1;
  }
  csu_quatToMat3(R, q);
  csrRodShape sh;
  fillShape(m, e, bp ? bp + CSR_ROD_BX : x0, b + CSR_ROD_BX, bp ? bp + CSR_ROD_BV : v0,
            b + CSR_ROD_BV, R, b + CSR_ROD_BW, &sh);
  double f0[3] = {0, 0, 0}, f1[3] = {0, 0, 0}, mc[3] = {0, 0, 0};
  double* dh = out + 9;
  for (int k = 0; k < m->nh[e]; k++) {
    dh[k] = 0;
  }
  int rc = m->contact.eval(m->contact.ctx, &sh, m->nh[e] ? b + CSR_ROD_BH : kZeroHist, dh, f0,
                           f1, mc);
  if (rc != 0) {
    return rc;
  }
  double tb[3];
  csr_rodMulMatTVec(tb, R, mc);
  const double* J = m->Jel + 3 * e;
  for (int k = 0; k < 3; k++) {
    out[k] = e > 1 ? f0[k] / m->mnode[e - 1] : 0;
    out[3 + k] = f1[k] / m->mnode[e];
    out[6 + k] = tb[k] / J[k];
  }
  *active = f0[0] != 0 || f0[1] != 0 || f0[2] != 0 || f1[0] != 0 || f1[1] != 0 || f1[2] != 0 ||
            mc[0] != 0 || mc[1] != 0 || mc[2] != 0;
  return 0;
}


int csr_rodForces_(const csrRodModel* m, csrRodWork* wk, const csrRodLoads* ld, int want_energy,
                   char* msg, size_t msg_size) {
  /* the elements unpacked: the whole rod, or its first `last` (then nodes 0..last-1's forces
   * and frames 0..last-1's torques are complete) */
  const int N = wk->last > 0 && wk->last < m->N ? wk->last : m->N;
  const double tau = ld->damping;
  double* F = wk->F;
  double* T = wk->T;
  double U = 0;
  memset(F, 0, 3 * ((size_t)N + 1) * sizeof(double));
  memset(T, 0, 3 * ((size_t)N + 1) * sizeof(double));

  /* gravity on every node, the hip node included (its weight goes to the support) */
  for (int i = 0; i <= N; i++) {
    csu_addScl3(F + 3 * i, F + 3 * i, ld->gravity, m->mnode[i]);
  }

  /* elements: shear and stretch, n = Q S (σ - σ0 + τ σ̇) */
  for (int e = 1; e <= N; e++) {
    const int p = m->ep[e];
    const double l = m->l[e];
    const double* Re = wk->R + 9 * e;
    double dx[3], w3[3], sig[3], nb[3], n[3], t[3];
    csu_sub3(dx, wk->x + 3 * e, wk->x + 3 * (e - 1));
    csr_rodMulMatTVec(w3, Re, dx);
    csu_scale3(w3, w3, 1.0 / l); /* e3 + σ */
    sig[0] = w3[0] - ld->sigma0[p][0];
    sig[1] = w3[1] - ld->sigma0[p][1];
    sig[2] = w3[2] - 1.0 - ld->sigma0[p][2];
    if (want_energy) {
      for (int k = 0; k < 3; k++) {
        U += 0.5 * l * ld->Sd[p][k] * sig[k] * sig[k];
      }
    }
    if (tau > 0) {
      double dv[3], rdv[3], wx[3];
      csu_sub3(dv, wk->v + 3 * e, wk->v + 3 * (e - 1));
      csr_rodMulMatTVec(rdv, Re, dv);
      csu_cross3(wx, wk->w + 3 * e, w3);
      for (int k = 0; k < 3; k++) {
        sig[k] += tau * (rdv[k] / l - wx[k]);
      }
    }
    for (int k = 0; k < 3; k++) {
      nb[k] = ld->Sd[p][k] * sig[k];
    }
    csu_mulMatVec3(n, Re, nb);
    csu_sub3(F + 3 * e, F + 3 * e, n);
    csu_add3(F + 3 * (e - 1), F + 3 * (e - 1), n);
    csu_cross3(t, w3, nb);
    csu_addScl3(T + 3 * e, T + 3 * e, t, l);
  }

  /* nodes: bending and twist, m = C⁻¹ (θ - θ0 + τ θ̇) */
  for (int i = 0; i < N; i++) {
    double th0[3], C[3], qrel[4], th[3], dth[3], mm[3], a[3];
    nodeSpring(m, ld, i, th0, C);
    csr_rodQmulConj(qrel, wk->q + 4 * i, wk->q + 4 * (i + 1));
    csr_rodQlog(th, qrel);
    csu_sub3(dth, th, th0);
    double Rrel[9];
    csu_quatToMat3(Rrel, qrel);
    for (int k = 0; k < 3; k++) {
      wk->m_node[3 * i + k] = dth[k] / C[k];
    }
    if (want_energy) {
      for (int k = 0; k < 3; k++) {
        U += 0.5 * dth[k] * dth[k] / C[k];
      }
    }
    /* J_r^-1's coefficient, shared by the rate below and the torque map (a cos and a sin) */
    const double jc = csr_rodJrInvCoeff(csu_norm3(th));
    if (tau > 0) {
      double wi[3], rel[3], thdot[3];
      csr_rodMulMatTVec(wi, Rrel, wk->w + 3 * i);
      csu_sub3(rel, wk->w + 3 * (i + 1), wi);
      csr_rodJrInvWith(thdot, jc, th, rel, +1);
      for (int k = 0; k < 3; k++) {
        dth[k] += tau * thdot[k];
      }
    }
    for (int k = 0; k < 3; k++) {
      mm[k] = dth[k] / C[k];
    }
    double ra[3];
    csr_rodJrInvWith(a, jc, th, mm, -1);
    csu_sub3(T + 3 * (i + 1), T + 3 * (i + 1), a);
    csu_mulMatVec3(ra, Rrel, a);
    csu_add3(T + 3 * i, T + 3 * i, ra);
  }

  /* tip load on the foot node and the last frame */
  if (N == m->N) {
    double tb[3];
    csr_rodMulMatTVec(tb, wk->R + 9 * N, ld->tip_moment);
    csu_add3(F + 3 * N, F + 3 * N, ld->tip_force);
    csu_add3(T + 3 * N, T + 3 * N, tb);
    memcpy(wk->m_node + 3 * N, tb, sizeof tb);
  }

  if (want_energy) {
    wk->elastic = U;
  }
  if (ld->contact && m->contact.eval) {
    return applyContact(m, wk, N, msg, msg_size);
  }
  return 0;
}


void csr_rodNodeFrame_(const csrRodModel* m, const csrRodWork* wk, const csrRodLoads* ld, int i,
                       double q[4]) {
  if (i == 0) {
    memcpy(q, wk->q, 4 * sizeof(double));
    return;
  }
  /* the part of node i's relative rotation in element i's half: intrinsic plus the elastic
   * share (l_i/2)/B_a of the node's moment (at the tip: the applied tip moment) */
  int pa = m->ep[i];
  double ha = 0.5 * m->l[i], phi[3], dq[4];
  for (int k = 0; k < 3; k++) {
    phi[k] = ha * (ld->u0[pa][k] + wk->m_node[3 * i + k] / ld->B[pa][k]);
  }
  csr_rodQexp(dq, phi);
  csr_rodQmul(q, wk->q + 4 * i, dq);
}


/* the state's block of element e (1..N) */
static const double* blockOf(const csrRodModel* m, const csrRodData* d, int e) {
  return d->y + CSR_ROD_NIMP + m->boff[e];
}


void csr_rodNodes(const csrRodModel* m, const csrRodData* d, double* x) {
  memcpy(x, d->cur_base.x, 3 * sizeof(double));
  for (int e = 1; e <= m->N; e++) {
    memcpy(x + 3 * e, blockOf(m, d, e) + CSR_ROD_BX, 3 * sizeof(double));
  }
}


void csr_rodCenterline(const csrRodModel* m, const csrRodData* d, int k, double* out) {
  int e = 1;
  for (int j = 0; j < k; j++) {
    double s = (k > 1) ? m->L * j / (k - 1) : 0;
    while (e < m->N && s > m->s[e]) {
      e++;
    }
    const double* x0 = (e == 1) ? d->cur_base.x : blockOf(m, d, e - 1) + CSR_ROD_BX;
    const double* x1 = blockOf(m, d, e) + CSR_ROD_BX;
    double u = (s - m->s[e - 1]) / m->l[e];
    u = u < 0 ? 0 : (u > 1 ? 1 : u);
    for (int c = 0; c < 3; c++) {
      out[3 * j + c] = x0[c] + u * (x1[c] - x0[c]);
    }
  }
}


void csr_rodMassMoment(const csrRodModel* m, const csrRodData* d, double mx[3]) {
  csu_scale3(mx, d->cur_base.x, m->mnode[0]);
  for (int e = 1; e <= m->N; e++) {
    csu_addScl3(mx, mx, blockOf(m, d, e) + CSR_ROD_BX, m->mnode[e]);
  }
}


int csr_rodContactShapes(const csrRodModel* m, const csrRodData* d, csrRodShape* shapes,
                         int max) {
  int n = 0;
  for (int e = 1; e <= m->N && n < max; e++, n++) {
    const double* b = blockOf(m, d, e);
    const double* x0 = (e == 1) ? d->cur_base.x : blockOf(m, d, e - 1) + CSR_ROD_BX;
    const double* v0 = (e == 1) ? d->cur_base.v : blockOf(m, d, e - 1) + CSR_ROD_BV;
    double q[4], R[9];
    memcpy(q, b + CSR_ROD_BQ, sizeof q);
    csr_rodQnormalize(q);
    csu_quatToMat3(R, q);
    fillShape(m, e, x0, b + CSR_ROD_BX, v0, b + CSR_ROD_BV, R, b + CSR_ROD_BW, &shapes[n]);
  }
  return n;
}

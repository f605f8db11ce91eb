/* robot_rod_dyn.c: the Cosserat-rod leg's dynamics layer: the data (state, CVODE, scratch), the
 * right-hand side, the base motion over a macro step, advance, the base wrench, energy and bend
 * angles at the current state (the interface gains: robot_rod_gains.c).
 *
 * ---- Integration (rationale) ----------------------------------------------------------------
 * The rod is stiff: its axial and shear modes sit at 1e4 rad/s against the 15 rad/s of the
 * first bending mode, and Kelvin-Voigt damping turns them into real eigenvalues near
 * -ω²τ_d ~ -1e6 s⁻¹. An explicit integrator would need steps below 1 µs; CVODE's BDF (orders
 * 1-5, error control) with a modified Newton iteration takes steps set by the slow dynamics.
 * The Newton matrix I - γ J is banded: element e's block (x, q, v, ω, history) couples only to
 * blocks e-1 and e+1; robot_rod_linsol.c eliminates the positions and solves the remaining
 * block-tridiagonal system on the velocities (6 x 6 blocks), with Jacobian blocks from
 * column-grouped difference quotients (3 x 12 right-hand sides without contact history, no
 * allocation); it replaced SUNBandMatrix/SUNLinSol_Band after measurement (see there).
 * Jacobians are reused across steps
 * (CVODE re-evaluates them when Newton converges slowly or γ changes), and the integrator
 * carries its history across macro steps: the base moves by cubic Hermite interpolation of
 * the support's pose and twist at both ends of each macro step, so consecutive steps join
 * with continuous position and velocity and no restart is needed; CVodeReInit happens only
 * after a discontinuity (state set, base or pressure jump, a failed step).
 *
 * Orientation: each element's quaternion is integrated (q̇ = ½ q ⊗ (0, ω), ω in the body
 * frame) and normalised where it is used; the continuous flow keeps |q| = 1 and BDF's drift
 * stays far below the 0.5..2 band the right-hand side accepts.
 *
 * The actuation (pressures -> intrinsic curvature and stretch, the calibration's tables and
 * their cache) is robot_rod_act.c.
 *
 * Base wrench: the force and moment the rod's hip element and hip-node spring exert on the
 * clamp, plus the hip node's own weight and inertia (m_0 (g - a_0); m_0 = 0 since the hip
 * node's half element was lumped on node 1, robot_rod_model.c says why). Over a macro step
 * the support receives its time integral. The moment's integral is 3 extra components of the
 * CVODE vector under error control. The force's impulse comes from the leg's momentum balance
 * instead: with P = Σ m_i v_i over
 * every node (the hip node moving with the base) and F_ext = Σ_i F_i the external forces
 * (the internal ones cancel in pairs: contact and weight remain), the clamp gives the support
 * ∫ F_ext dt - (P(t + H) - P(t)); 3 extra CVODE components integrate F_ext. Why: the support
 * then receives exactly the momentum the leg's own states lost, whatever the leg's
 * integration error, so the support plus the legs change momentum only through the terrain.
 * Integrating the clamp force itself left the integration error in the exchange: frictionless
 * (horizontal F_ext = 0) under Gauss-Seidel coupling the robot's centre of mass drifted 24 mm
 * in 9 s at the shipped tolerances (docs/bench/gs_coupling_2026-12-02). */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_nvector.h"
#include "core_sun.h"
#include "robot_rod_internal.h"

_Static_assert(sizeof(sunrealtype) == sizeof(double), "crawlsim needs double SUNDIALS");

/* csrRodParams.atol_wrench, absolute tolerance of the base wrench averaged over an advance
 * (N, 1e-3): the impulse is under
 * CVODE's error control with atol = this x H, measured from the advance's start. (Uncontrolled,
 * as the impulse first was, the step-averaged wrench of a stance leg under the driver scattered
 * by +-0.3 N around its 0.12 N mean from step to step: the hip element's stiff damper, 0.26
 * N s/mm, turns any velocity error of node 1 into force, and nothing bounded that error in the
 * impulse; the noise shook the light support and let stance feet slip.) */
/* a hip that starts a macro step more than this away from where the last one ended (mm, rad)
 * has jumped (a teleport, a different driver): the integrator restarts. Smaller jumps are the
 * coupling's normal business: the support's actual motion corrects the predicted end pose of
 * the last step by O(a H²) in position and O(a H) in velocity; CVODE carries on across them
 * (its error control absorbs them), where restarting at every macro step took 4x the steps and
 * 7x the right-hand sides (flat road, stabilised coupling, 5 ms macro steps) */
#define CSR_ROD_BASE_JUMP_X 0.1
#define CSR_ROD_BASE_JUMP_PHI 1e-3

/* base position, quaternion, velocity, acceleration and body angular velocity at time t */
static void baseAt(const csrRodBaseMotion* bm, double t, double x[3], double q[4], double v[3],
                   double a[3], double wb[3]);


void csr_rodBaseAt_(const csrRodData* d, double t, double x[3], double v[3]) {
  double q[4], a[3], wb[3];
  baseAt(&d->base, t, x, q, v, a, wb);
}
/* the base motion of a macro step from the support's states at both ends */
static void setBaseMotion(csrRodBaseMotion* bm, double ta, double H, const csrBaseState* b0,
                          const csrBaseState* b1);
/* the loads at time t: actuation interpolated, gravity, tip load, damping, contact */
static void loadsAt(const csrRodModel* m, const csrRodData* d, double t, csrRodLoads* ld);
/* unpack the current state at the current base and time and run the kernel (elements
 * 1..last: N for the whole rod, 1 for the wrench alone) */
static int refresh(const csrRodModel* m, csrRodData* d, csrRodLoads* ld, int want_energy,
                   int last);
/* the wrench of the unpacked configuration in d->wk after the kernel (a0: hip acceleration) */
static void wrenchOf(const csrRodModel* m, const csrRodData* d, const double a0[3],
                     csrWrench* w);
/* add CVODE's counters to the accumulated statistics (before a restart) */
static void accumulateStats(csrRodData* d);
void csr_rodDataDestroy(csrRodData* d) {
  if (!d) {
    return;
  }
  CVodeFree(&d->cvode);
  SUNLinSolFree(d->LS);
  SUNMatDestroy(d->A);
  csr_rodLinsolFree_(d);
  csr_rodBtFree_(&d->bt_static);
  N_VDestroy(d->yv);
  N_VDestroy(d->atol);
  if (d->sun) {
    SUNContext_Free(&d->sun);
  }
  free(d->backup);
  free(d->wk.x);
  free(d->wk.q);
  free(d->wk.R);
  free(d->wk.v);
  free(d->wk.w);
  free(d->wk.F);
  free(d->wk.T);
  free(d->wk.m_node);
  free(d->sres);
  free(d->sres2);
  free(d->sdel);
  free(d->sy);
  free(d->sy0);
  free(d->own_cache);
  free(d);
}


/* CVODE's error weights (CVEwtFn): 1 / (rtol |y_i| + atol_i) for the leg's state, as
 * CVodeSVtolerances would give; for the base impulse 1 / (rtol |I - I0| + atol_I), relative to
 * its value I0 at the start of the current advance, with atol_I = atol_wrench H (set in
 * csr_rodAdvance) */
static int errorWeights(N_Vector y, N_Vector ewt, void* user) {
  const csrRodData* d = user;
  const double* Y = N_VGetArrayPointer(y);
  const double* at = N_VGetArrayPointer(d->atol);
  double* w = N_VGetArrayPointer(ewt);
  const double rtol = d->m->par.rtol;
  const sunindextype n = N_VGetLength(y);
  for (int k = 0; k < CSR_ROD_NIMP; k++) {
    double tol = rtol * fabs(Y[k] - d->imp0[k]) + d->imp_atol;
    if (!(tol > 0)) {
      return -1;
    }
    w[k] = 1.0 / tol;
  }
  for (sunindextype k = CSR_ROD_NIMP; k < n; k++) {
    double tol = rtol * fabs(Y[k]) + at[k];
    if (!(tol > 0)) {
      return -1;
    }
    w[k] = 1.0 / tol;
  }
  return 0;
}


csrRodData* csr_rodDataCreate(const csrRodModel* m, csError* err) {
  if (!m) {
    cs_errorSet(err, CS_ERR_ARG, "rod: NULL model");
    return NULL;
  }
  csrRodData* d = calloc(1, sizeof *d);
  if (!d) {
    cs_errorSet(err, CS_ERR_MEMORY, "rod: out of memory");
    return NULL;
  }
  d->m = m;
  d->imp_atol = m->par.atol_wrench * 1e-3; /* until the first advance sets it */
  const size_t N1 = (size_t)m->N + 1;
  const sunindextype ny = CSR_ROD_NIMP + m->nstate;
  const sunindextype ns = 6 * (sunindextype)m->N;
  d->wk.x = calloc(3 * N1, sizeof(double));
  d->wk.q = calloc(4 * N1, sizeof(double));
  d->wk.R = calloc(9 * N1, sizeof(double));
  d->wk.v = calloc(3 * N1, sizeof(double));
  d->wk.w = calloc(3 * N1, sizeof(double));
  d->wk.F = calloc(3 * N1, sizeof(double));
  d->wk.T = calloc(3 * N1, sizeof(double));
  d->wk.m_node = calloc(3 * N1, sizeof(double));
  d->backup = calloc((size_t)ny, sizeof(double));
  d->sres = calloc((size_t)ns, sizeof(double));
  d->sres2 = calloc((size_t)ns, sizeof(double));
  d->sdel = calloc((size_t)ns, sizeof(double));
  d->sy = calloc((size_t)m->nstate, sizeof(double));
  d->sy0 = calloc((size_t)m->nstate, sizeof(double));
  d->own_cache = calloc(1, sizeof *d->own_cache);
  d->cache = d->own_cache;
  if (!d->wk.x || !d->wk.q || !d->wk.R || !d->wk.v || !d->wk.w || !d->wk.F || !d->wk.T ||
      !d->wk.m_node || !d->backup || !d->sres || !d->sres2 || !d->sdel || !d->sy || !d->sy0 ||
      !d->own_cache) {
    csr_rodDataDestroy(d);
    cs_errorSet(err, CS_ERR_MEMORY, "rod: out of memory");
    return NULL;
  }
  /* a context that never prints: CVODE's messages end up in the csError of the call */
  if (cs_sunContextCreate(&d->sun) != 0) {
    d->sun = NULL;
    csr_rodDataDestroy(d);
    cs_errorSet(err, CS_ERR_SOLVER, "rod: cannot create a SUNDIALS context");
    return NULL;
  }
  d->yv = N_VNew_Serial(ny, d->sun);
  d->atol = N_VNew_Serial(ny, d->sun);
  if (!d->yv || !d->atol || !csr_rodBtAlloc_(&d->bt_static, m->N)) {
    csr_rodDataDestroy(d);
    cs_errorSet(err, CS_ERR_MEMORY, "rod: cannot allocate SUNDIALS vectors");
    return NULL;
  }
  /* CVODE clones its work vectors from yv: they all get the optimised kernels */
  cs_nvectorFastOps(d->yv);
  cs_nvectorFastOps(d->atol);
  d->y = N_VGetArrayPointer(d->yv);
  /* per-component absolute tolerances */
  double* at = N_VGetArrayPointer(d->atol);
  for (int k = 0; k < CSR_ROD_NIMP; k++) {
    at[k] = 0; /* set per advance (impulseWeights) */
  }
  const csrRodParams* p = &m->par;
  for (int e = 0; e < m->N; e++) {
    double* b = at + CSR_ROD_NIMP + m->boff[e + 1];
    for (int k = 0; k < CSR_ROD_BH + m->nh[e + 1]; k++) {
      b[k] = k < CSR_ROD_BQ   ? p->atol_pos
             : k < CSR_ROD_BV ? p->atol_rot
             : k < CSR_ROD_BW ? p->atol_vel
             : k < CSR_ROD_BH ? p->atol_omega
                              : p->atol_hist;
    }
  }
  csr_rodReset(m, d);
  d->cvode = CVodeCreate(CV_BDF, d->sun);
  if (!d->cvode || CVodeInit(d->cvode, csr_rodRhs_, 0.0, d->yv) != CV_SUCCESS ||
      CVodeWFtolerances(d->cvode, errorWeights) != CV_SUCCESS ||
      CVodeSetUserData(d->cvode, d) != CV_SUCCESS || csr_rodLinsolAttach_(d) != 0 ||
      CVodeSetMaxNumSteps(d->cvode, p->max_steps) != CV_SUCCESS ||
      CVodeSetMaxOrd(d->cvode, p->max_order) != CV_SUCCESS) {
    csr_rodDataDestroy(d);
    cs_errorSet(err, CS_ERR_SOLVER, "rod: cannot set up CVODE (BDF, reduced linear solver): "
                "out of memory, or a setting CVODE refused");
    return NULL;
  }
  cs_cvodeSilence(d->cvode);
  d->started = 1;
  d->need_reinit = 1;
  return d;
}


csrBaseState csr_rodRestBase(const csrRodModel* m) {
  csrBaseState b;
  memset(&b, 0, sizeof b);
  memcpy(b.x, m->hip, sizeof b.x);
  memcpy(b.R, m->frame, sizeof b.R);
  return b;
}


void csr_rodReset(const csrRodModel* m, csrRodData* d) {
  memset(d->y, 0, CSR_ROD_NIMP * sizeof(double));
  csr_rodRestState_(m, d->y + CSR_ROD_NIMP);
  d->t = 0;
  d->cur_base = csr_rodRestBase(m);
  setBaseMotion(&d->base, 0, 0, &d->cur_base, &d->cur_base);
  memset(&d->act, 0, sizeof d->act);
  memset(d->tip_force, 0, sizeof d->tip_force);
  memset(d->tip_moment, 0, sizeof d->tip_moment);
  /* the rest state is the equilibrium of the unloaded rod (no pressure, load or gravity) */
  d->static_valid = 1;
  memset(&d->static_load, 0, sizeof d->static_load);
  memset(d->static_act, 0, sizeof d->static_act);
  d->need_reinit = 1;
  d->ls_have_jac = 0;
  d->cb_status = 0;
}


void csr_rodGetState(const csrRodModel* m, const csrRodData* d, double* y) {
  memcpy(y, d->y + CSR_ROD_NIMP, (size_t)m->nstate * sizeof(double));
}


void csr_rodSetState(const csrRodModel* m, csrRodData* d, const double* y) {
  memcpy(d->y + CSR_ROD_NIMP, y, (size_t)m->nstate * sizeof(double));
  d->need_reinit = 1;
  d->static_valid = 0;
  /* the stored Jacobian belongs to another state: the condensed gains wait for a new one
   * (until then the instantaneous gains), so a step after a set depends on the state alone */
  d->ls_have_jac = 0;
}


void csr_rodSetTipLoad(csrRodData* d, const double force[3], const double moment[3]) {
  for (int k = 0; k < 3; k++) {
    if (d->tip_force[k] != force[k] || d->tip_moment[k] != moment[k]) {
      d->need_reinit = 1; /* a load step is a discontinuity */
    }
  }
  memcpy(d->tip_force, force, sizeof d->tip_force);
  memcpy(d->tip_moment, moment, sizeof d->tip_moment);
}


static void setBaseMotion(csrRodBaseMotion* bm, double ta, double H, const csrBaseState* b0,
                          const csrBaseState* b1) {
  memset(bm, 0, sizeof *bm);
  bm->ta = ta;
  bm->H = H;
  bm->a = *b0;
  bm->b = *b1;
  csu_mat3ToQuat(bm->qa, b0->R);
  if (!(H > 0)) {
    return; /* at rest at b0 */
  }
  bm->moving = 1;
  double qb[4], qab[4], wa[3], wb[3], t[3];
  csu_mat3ToQuat(qb, b1->R);
  csr_rodQmulConj(qab, bm->qa, qb);
  csr_rodQlog(bm->Phi, qab);
  csr_rodMulMatTVec(wa, b0->R, b0->w);
  csr_rodMulMatTVec(wb, b1->R, b1->w);
  csu_scale3(bm->dphi0, wa, H);
  /* φ̇ = J_r(φ)⁻¹ ω_body at the end, where φ = Φ */
  csr_rodJrInv(t, bm->Phi, wb, +1);
  csu_scale3(bm->dphi1, t, H);
}


static void baseAt(const csrRodBaseMotion* bm, double t, double x[3], double q[4], double v[3],
                   double a[3], double wb[3]) {
  if (!bm->moving) {
    memcpy(x, bm->a.x, 3 * sizeof(double));
    memcpy(q, bm->qa, 4 * sizeof(double));
    memset(v, 0, 3 * sizeof(double));
    memset(a, 0, 3 * sizeof(double));
    memset(wb, 0, 3 * sizeof(double));
    return;
  }
  const double H = bm->H, u = (t - bm->ta) / H, u2 = u * u, u3 = u2 * u;
  /* cubic Hermite basis, its first and second derivatives in u */
  const double h00 = 2 * u3 - 3 * u2 + 1, h10 = u3 - 2 * u2 + u, h01 = -2 * u3 + 3 * u2,
               h11 = u3 - u2;
  const double d00 = 6 * u2 - 6 * u, d10 = 3 * u2 - 4 * u + 1, d01 = -d00, d11 = 3 * u2 - 2 * u;
  const double s00 = 12 * u - 6, s10 = 6 * u - 4, s01 = -s00, s11 = 6 * u - 2;
  for (int k = 0; k < 3; k++) {
    const double p0 = bm->a.x[k], p1 = bm->b.x[k];
    const double m0 = H * bm->a.v[k], m1 = H * bm->b.v[k];
    x[k] = h00 * p0 + h10 * m0 + h01 * p1 + h11 * m1;
    v[k] = (d00 * p0 + d10 * m0 + d01 * p1 + d11 * m1) / H;
    a[k] = (s00 * p0 + s10 * m0 + s01 * p1 + s11 * m1) / (H * H);
  }
  /* rotation vector relative to frame a: φ(0) = 0, φ(1) = Φ */
  double phi[3], dphi[3], dq[4];
  for (int k = 0; k < 3; k++) {
    phi[k] = h10 * bm->dphi0[k] + h01 * bm->Phi[k] + h11 * bm->dphi1[k];
    dphi[k] = (d10 * bm->dphi0[k] + d01 * bm->Phi[k] + d11 * bm->dphi1[k]) / H;
  }
  csr_rodQexp(dq, phi);
  csr_rodQmul(q, bm->qa, dq);
  csr_rodJr(wb, phi, dphi);
}


static void loadsAt(const csrRodModel* m, const csrRodData* d, double t, csrRodLoads* ld) {
  csrRodSegmentActuation act[CSR_NSEG];
  const csrRodActState* as = &d->act;
  if (as->set) {
    double al = (as->tb > as->ta) ? (t - as->ta) / (as->tb - as->ta) : 1.0;
    al = al < 0 ? 0 : (al > 1 ? 1 : al);
    for (int s = 0; s < CSR_NSEG; s++) {
      csr_rodActuationLerp_(&as->a[s], &as->b[s], al, &act[s]);
    }
    csr_rodLoadsFromActuation_(m, act, ld);
  } else {
    csr_rodLoadsFromActuation_(m, NULL, ld);
  }
  memcpy(ld->gravity, m->gravity, sizeof ld->gravity);
  memcpy(ld->tip_force, d->tip_force, sizeof ld->tip_force);
  memcpy(ld->tip_moment, d->tip_moment, sizeof ld->tip_moment);
  ld->damping = m->par.damping_time;
  ld->contact = !d->no_contact;
}


static void wrenchOf(const csrRodModel* m, const csrRodData* d, const double a0[3],
                     csrWrench* w) {
  for (int k = 0; k < 3; k++) {
    w->f[k] = d->wk.F[k] - m->mnode[0] * a0[k];
  }
  csu_mulMatVec3(w->m, d->wk.R, d->wk.T);
}


int csr_rodRhs_(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
  csrRodData* d = user;
  const csrRodModel* m = d->m;
  const double* Y = N_VGetArrayPointer(y);
  double* Yd = N_VGetArrayPointer(ydot);
  double x0[3], q0[4], v0[3], a0[3], w0[3];
  baseAt(&d->base, t, x0, q0, v0, a0, w0);
  if (csr_rodUnpack_(m, &d->wk, Y + CSR_ROD_NIMP, x0, q0, v0, w0) != 0) {
    return 1; /* not a rod configuration: CVODE cuts the step */
  }
  csrRodLoads ld;
  loadsAt(m, d, t, &ld);
  d->wk.hist = Y + CSR_ROD_NIMP;
  d->wk.dhist = Yd + CSR_ROD_NIMP;
  int rc = csr_rodForces_(m, &d->wk, &ld, 0, d->cb_msg, sizeof d->cb_msg);
  if (rc != 0) {
    d->cb_status = rc;
    return rc;
  }
  if (!ld.contact) {
    /* without the hook nothing writes the history rates */
    for (int e = 1; e <= m->N; e++) {
      memset(Yd + CSR_ROD_NIMP + m->boff[e] + CSR_ROD_BH, 0, (size_t)m->nh[e] * sizeof(double));
    }
  }
  /* the blocks: ẋ = v, q̇ = ½ q ⊗ (0, ω), m v̇ = F, J ω̇ = T - ω × J ω */
  const csrRodWork* wk = &d->wk;
  double check = 0;
  for (int e = 1; e <= m->N; e++) {
    const double* b = Y + CSR_ROD_NIMP + m->boff[e];
    double* o = Yd + CSR_ROD_NIMP + m->boff[e];
    const double* q = b + CSR_ROD_BQ;
    const double* w = b + CSR_ROD_BW;
    const double* J = m->Jel + 3 * e;
    const double wq[4] = {0, w[0], w[1], w[2]};
    double qd[4], Jw[3], gyro[3];
    memcpy(o + CSR_ROD_BX, b + CSR_ROD_BV, 3 * sizeof(double));
    csr_rodQmul(qd, q, wq);
    for (int k = 0; k < 4; k++) {
      o[CSR_ROD_BQ + k] = 0.5 * qd[k];
    }
    for (int k = 0; k < 3; k++) {
      o[CSR_ROD_BV + k] = wk->F[3 * e + k] / m->mnode[e];
      Jw[k] = J[k] * w[k];
    }
    csu_cross3(gyro, w, Jw);
    for (int k = 0; k < 3; k++) {
      o[CSR_ROD_BW + k] = (wk->T[3 * e + k] - gyro[k]) / J[k];
      check += o[CSR_ROD_BV + k] + o[CSR_ROD_BW + k];
    }
  }
  csrWrench wr;
  wrenchOf(m, d, a0, &wr);
  /* the external force on the whole leg: the sum of every node's force, hip node included
   * (csr_rodAdvance turns its impulse and the momentum change into the base's impulse) */
  double Fext[3] = {0, 0, 0};
  for (int i = 0; i <= m->N; i++) {
    for (int k = 0; k < 3; k++) {
      Fext[k] += wk->F[3 * i + k];
    }
  }
  memcpy(Yd, Fext, 3 * sizeof(double));
  memcpy(Yd + 3, wr.m, 3 * sizeof(double));
  if (!isfinite(check + Fext[0] + wr.m[0])) {
    return 1;
  }
  return 0;
}


/* add CVODE's counters since its last (re)initialisation to s */
static void addCvodeCounters(void* cv, csrRodStats* s) {
  long v = 0, lrhs = 0;
  CVodeGetNumSteps(cv, &v);
  s->steps += v;
  CVodeGetNumRhsEvals(cv, &v);
  /* the Jacobian's difference quotients are right-hand sides too */
  CVodeGetNumLinRhsEvals(cv, &lrhs);
  s->rhs_evals += v + lrhs;
  CVodeGetNumJacEvals(cv, &v);
  s->jac_evals += v;
  CVodeGetNumLinSolvSetups(cv, &v);
  s->lin_setups += v;
  CVodeGetNumNonlinSolvIters(cv, &v);
  s->newton_iters += v;
  CVodeGetNumErrTestFails(cv, &v);
  s->err_fails += v;
  CVodeGetNumNonlinSolvConvFails(cv, &v);
  s->conv_fails += v;
}


static void accumulateStats(csrRodData* d) { addCvodeCounters(d->cvode, &d->stats); }


void csr_rodGetStats(const csrRodData* d, csrRodStats* s) {
  *s = d->stats;
  if (d->cvode) {
    addCvodeCounters(d->cvode, s);
  }
}


/* the hip at a within the jump thresholds of b (position and rotation) */
static int nearBase(const csrBaseState* a, const csrBaseState* b) {
  double dx[3], qa[4], qb[4], qr[4], phi[3];
  csu_sub3(dx, a->x, b->x);
  csu_mat3ToQuat(qa, a->R);
  csu_mat3ToQuat(qb, b->R);
  csr_rodQmulConj(qr, qb, qa);
  csr_rodQlog(phi, qr);
  return csu_norm3(dx) <= CSR_ROD_BASE_JUMP_X && csu_norm3(phi) <= CSR_ROD_BASE_JUMP_PHI;
}


/* the leg's linear momentum P[3] (t mm/s) in the CVODE vector y: every element node's, and the
 * hip node's moving with the base at velocity vb */
static void legMomentum(const csrRodModel* m, const double* y, const double vb[3], double P[3]) {
  for (int k = 0; k < 3; k++) {
    P[k] = m->mnode[0] * vb[k];
  }
  for (int e = 1; e <= m->N; e++) {
    const double* v = y + CSR_ROD_NIMP + m->boff[e] + CSR_ROD_BV;
    for (int k = 0; k < 3; k++) {
      P[k] += m->mnode[e] * v[k];
    }
  }
}


void csr_rodMomentum(const csrRodModel* m, const csrRodData* d, double P[3]) {
  legMomentum(m, d->y, d->cur_base.v, P);
}


/* finite base state */
static int finiteBase(const csrBaseState* b) {
  double s = 0;
  for (int k = 0; k < 3; k++) {
    s += b->x[k] + b->v[k] + b->w[k];
  }
  for (int k = 0; k < 9; k++) {
    s += b->R[k];
  }
  return isfinite(s);
}


int csr_rodAdvance(const csrRodModel* m, csrRodData* d, double t, double H, const csrBaseState* b0,
                   const csrBaseState* b1, csrWrench* w, csError* err) {
  if (!m || !d || !b0 || !b1) {
    cs_errorSet(err, CS_ERR_ARG, "rod advance: NULL argument");
    return -1;
  }
  if (!(H > 0) || !isfinite(H) || !isfinite(t) || !finiteBase(b0) || !finiteBase(b1)) {
    cs_errorSet(err, CS_ERR_ARG, "rod advance: need a finite t, H > 0 and finite base states "
                "(t = %g s, H = %g s)", t, H);
    return -1;
  }
  d->stats.advances++;
  const size_t ny = CSR_ROD_NIMP + (size_t)m->nstate;
  int restart = d->need_reinit || fabs(t - d->t) > 1e-12 * (1 + fabs(t)) ||
                !nearBase(b0, &d->cur_base);
  csrRodBaseMotion keep = d->base;
  setBaseMotion(&d->base, t, H, b0, b1);
  memcpy(d->backup, d->y, ny * sizeof(double));
  if (restart) {
    accumulateStats(d);
    d->stats.reinits++;
    /* the base impulse restarts from zero: only its change over an advance is used, but its
     * absolute value, accumulated since the last restart, sets the rounding of that change
     * and of CVODE's corrections on it, so a restart from a restored state (which does not
     * hold the impulse) would otherwise depend on the history before the restore (measured:
     * two restores of one state on the flat road differed by 0.57 in 1027 of 1336 entries
     * after 25 steps; test_state test_rod_restore_is_bit_identical) */
    memset(d->y, 0, CSR_ROD_NIMP * sizeof(double));
    if (CVodeReInit(d->cvode, t, d->yv) != CV_SUCCESS) {
      d->base = keep;
      d->stats.failed_advances++;
      cs_errorSet(err, CS_ERR_SOLVER, "rod advance: CVodeReInit failed at t = %g s", t);
      return -1;
    }
    d->need_reinit = 0;
    d->jac_int_step = -1; /* the state may have jumped: the whole Jacobian anew */
  }
  double I0[CSR_ROD_NIMP], P0[3];
  memcpy(I0, d->y, sizeof I0);
  legMomentum(m, d->y, b0->v, P0);
  /* the impulse's error is measured from here: the wrench averaged over this step to
   * atol_wrench */
  memcpy(d->imp0, I0, sizeof I0);
  d->imp_atol = d->m->par.atol_wrench * H;
  d->cb_status = 0;
  d->cb_msg[0] = '\0';
  CVodeSetStopTime(d->cvode, t + H);
  sunrealtype tret = t;
  int flag = CVode(d->cvode, t + H, d->yv, &tret, CV_NORMAL);
  if (flag < 0) {
    /* a failed step changes nothing: state, time and base as before; restart next time */
    memcpy(d->y, d->backup, ny * sizeof(double));
    d->base = keep;
    d->need_reinit = 1;
    d->stats.failed_advances++;
    char* name = CVodeGetReturnFlagName(flag);
    int fatal = d->cb_status < 0 || flag == CV_RHSFUNC_FAIL || flag == CV_ILL_INPUT ||
                flag == CV_MEM_FAIL || flag == CV_MEM_NULL;
    cs_errorSet(err, fatal ? CS_ERR_SOLVER : CS_ERR_DIVERGED,
                "rod advance from t = %.6g s by H = %.3g s failed at t = %.6g s: CVODE %s%s%s",
                t, H, (double)tret, name ? name : "?", d->cb_msg[0] ? "; " : "", d->cb_msg);
    free(name);
    if (fatal) {
      return d->cb_status < 0 ? d->cb_status : -1;
    }
    return 1;
  }
  if (w) {
    double P1[3];
    legMomentum(m, d->y, b1->v, P1);
    for (int k = 0; k < 3; k++) {
      w->f[k] = ((d->y[k] - I0[k]) - (P1[k] - P0[k])) / H;
      w->m[k] = (d->y[3 + k] - I0[3 + k]) / H;
    }
  }
  d->t = t + H;
  d->cur_base = *b1;
  d->static_valid = 0;
  return 0;
}


static int refresh(const csrRodModel* m, csrRodData* d, csrRodLoads* ld, int want_energy,
                   int last) {
  double x0[3], q0[4], wb[3];
  csu_mat3ToQuat(q0, d->cur_base.R);
  memcpy(x0, d->cur_base.x, sizeof x0);
  csr_rodMulMatTVec(wb, d->cur_base.R, d->cur_base.w);
  if (csr_rodUnpackPart_(m, &d->wk, d->y + CSR_ROD_NIMP, last, x0, q0, d->cur_base.v, wb) !=
      0) {
    return 1;
  }
  loadsAt(m, d, d->t, ld);
  d->wk.hist = d->y + CSR_ROD_NIMP;
  d->wk.dhist = NULL;
  return csr_rodForces_(m, &d->wk, ld, want_energy, d->cb_msg, sizeof d->cb_msg);
}


void csr_rodBaseWrench(const csrRodModel* m, csrRodData* d, csrWrench* w) {
  csrRodLoads ld;
  const double a0[3] = {0, 0, 0};
  memset(w, 0, sizeof *w);
  if (refresh(m, d, &ld, 0, 1) == 0) {
    wrenchOf(m, d, a0, w);
  }
}


void csr_rodEnergy(const csrRodModel* m, csrRodData* d, csrRodEnergy* e) {
  csrRodLoads ld;
  memset(e, 0, sizeof *e);
  if (refresh(m, d, &ld, 1, m->N) != 0) {
    e->kinetic = e->elastic = e->gravity = NAN;
    return;
  }
  const csrRodWork* wk = &d->wk;
  e->elastic = wk->elastic;
  for (int i = 0; i <= m->N; i++) {
    const double* v = wk->v + 3 * i;
    e->kinetic += 0.5 * m->mnode[i] * csu_dot3(v, v);
    e->gravity -= m->mnode[i] * csu_dot3(ld.gravity, wk->x + 3 * i);
    if (i > 0) {
      const double* w = wk->w + 3 * i;
      const double* J = m->Jel + 3 * i;
      e->kinetic += 0.5 * (J[0] * w[0] * w[0] + J[1] * w[1] * w[1] + J[2] * w[2] * w[2]);
    }
  }
}


void csr_rodSegmentAngles(const csrRodModel* m, csrRodData* d, double angle[CSR_NSEG],
                          double tip_base[3]) {
  csrRodLoads ld;
  for (int s = 0; s < CSR_NSEG; s++) {
    angle[s] = NAN;
  }
  if (refresh(m, d, &ld, 0, m->N) != 0) {
    tip_base[0] = tip_base[1] = tip_base[2] = NAN;
    return;
  }
  const csrRodWork* wk = &d->wk;
  /* per node: the whole relative rotation θ_i and its part in the left element */
  double tot[CSR_NSEG][3];
  memset(tot, 0, sizeof tot);
  for (int i = 0; i <= m->N; i++) {
    double th[3] = {0, 0, 0}, left[3] = {0, 0, 0};
    if (i < m->N) {
      double qrel[4];
      csr_rodQmulConj(qrel, wk->q + 4 * i, wk->q + 4 * (i + 1));
      csr_rodQlog(th, qrel);
    }
    if (i > 0) {
      int pa = m->ep[i];
      for (int k = 0; k < 3; k++) {
        left[k] = 0.5 * m->l[i] * (ld.u0[pa][k] + wk->m_node[3 * i + k] / ld.B[pa][k]);
      }
      int sa = m->piece[pa].segment;
      if (sa >= 0) {
        csu_add3(tot[sa], tot[sa], left);
      }
    }
    if (i < m->N) {
      int sb = m->piece[m->ep[i + 1]].segment;
      if (sb >= 0) {
        double right[3];
        csu_sub3(right, th, left);
        if (i == 0) {
          csu_copy3(right, th);
        }
        csu_add3(tot[sb], tot[sb], right);
      }
    }
  }
  for (int s = 0; s < CSR_NSEG; s++) {
    angle[s] = csu_norm3(tot[s]);
  }
  double dx[3];
  csu_sub3(dx, wk->x + 3 * m->N, wk->x);
  csr_rodMulMatTVec(tip_base, wk->R, dx);
}

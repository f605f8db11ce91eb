/* strain_test_robot.h: a robot of eight strain legs on a free rigid support, stepped as one
 * tree without ODE (tests and benchmarks only; issue 32's stage 3 puts the same solve into the
 * driver's support step).
 *
 * The support is the robot's (robot_robot.c): a 210 x 10 x 145 mm box of 50 g, its body frame
 * at its centre, world-aligned at the start, the hips on its bottom face at
 * csr_robotHipOffset, the legs' frame (e1 = +x, e2 = +z, e3 = -y) fixed in it. One step of h:
 *  1. every leg condenses its step onto its hip (csr_strainPrepare: Z_i, ρ_i in hip body
 *     coordinates);
 *  2. the support solves (M_s + Σ A_iᵀ Z_i A_i) ΔV = h (F_s + ad(V)ᵀ M_s V) + Σ A_iᵀ ρ_i in its
 *     body coordinates (A_i = Ad(T_i⁻¹), T_i the hip's fixed pose in the support; F_s its
 *     weight), V += ΔV, g_s <- g_s exp(h V);
 *  3. every leg back-substitutes its hip's ΔV_i = A_i ΔV and takes its hip's new state
 *     (csr_strainUpdate); with Newton iterations, every leg linearises again at the iterate
 *     (csr_strainIterate) and 1-3 repeat until nothing moves, then the legs commit.
 * The support does not touch the terrain (only the legs do, through their own contact). */
#ifndef CS_TESTS_STRAIN_TEST_ROBOT_H
#define CS_TESTS_STRAIN_TEST_ROBOT_H

#include <stdlib.h>
#include <string.h>

#include "core_clock.h"
#include "core_math.h"
#include "gaits_csv.h"
#include "gaits_schedule.h"
#include "robot_calibration.h"
#include "robot_robot.h"
#include "robot_strain_internal.h"
#include "rod_test_road.h"

typedef struct {
  csrActuator act;
  csrCalibration* cal;
  csrBendMap map;
  csrRodCalibration rodcal;
  cstTerrain tr;
  cscSoftParams soft;
  csrStrainParams sp;
  csrStrainModel* m[CSR_NLEG];
  csrStrainData* d[CSR_NLEG];
  double A[CSR_NLEG][36];  /* Ad(T_i⁻¹): support body twist -> hip body twist */
  double hip[CSR_NLEG][3]; /* hip in the support frame (mm) */
  double F[9];             /* the legs' frame in the support frame */
  double ms, Is[3];        /* support mass (t) and principal inertia at its centre (t mm²) */
  double R[9], x[3], V[6]; /* support pose (centre) and body twist */
  double D[3];             /* its discrete linear momentum m (x1 - x0) / h of the last step */
  double g[3];             /* gravity on the support (mm/s²) */
  double t;
  /* BDF2 (the legs' step_order 2): the last step's start pose, twist, D and length (0: none) */
  double Rm1[9], xm1[3], Vm1[6], Dm1[3], hprev;
  long released; /* contact ghosts the legs released at converged passes (a counter) */
  long limited;  /* passes whose move the legs' slot trust region shortened (a counter) */
} StrainRobot;


/* 1 when the n numbers of a are all finite (a read of a NaN-poisoned entry shows here) */
static inline int strainFinite(const double* a, int n) {
  for (int i = 0; i < n; i++) {
    if (!isfinite(a[i])) {
      return 0;
    }
  }
  return 1;
}


static inline void strainRobotHip(const StrainRobot* r, int k, csrBaseState* b) {
  double t[3], Vh[6];
  csu_mulMat3(b->R, r->R, r->F);
  csu_mulMatVec3(t, r->R, r->hip[k]);
  csu_add3(b->x, r->x, t);
  for (int i = 0; i < 6; i++) {
    Vh[i] = 0;
    for (int j = 0; j < 6; j++) {
      Vh[i] += r->A[k][6 * i + j] * r->V[j];
    }
  }
  csu_mulMatVec3(b->w, b->R, Vh);
  csu_mulMatVec3(b->v, b->R, Vh + 3);
}


/* the robot standing with its feet on the flat road (hips at the leg's length), friction mu,
 * bending order `order`, the legs' and the support's step_order (1 backward Euler, 2 BDF2),
 * the legs' active_set (csrStrainParams); 0 ok */
static inline int strainRobotCreateParams(StrainRobot* r, double mu, const csrStrainParams* sp,
                                          csError* err);
static inline int strainRobotCreateActive(StrainRobot* r, double mu, int order, int step_order,
                                          int active_set, csError* err) {
  csrStrainParams sp = csr_strainDefaultParams();
  sp.bend_order = order;
  sp.step_order = step_order;
  sp.active_set = active_set;
  return strainRobotCreateParams(r, mu, &sp, err);
}


/* the same with the legs' parameters sp (csrStrainParams) */
static inline int strainRobotCreateParams(StrainRobot* r, double mu, const csrStrainParams* sp,
                                          csError* err) {
  memset(r, 0, sizeof *r);
  if (csr_actuatorPreset(&r->act, "leg", err) != CS_OK) {
    return 1;
  }
  char path[1024];
  snprintf(path, sizeof path, "%s/robot/calibration_fe_leg.h5",
           getenv("CS_SOURCE_DIR") ? getenv("CS_SOURCE_DIR") : ".");
  r->cal = csr_calibrationOpen(path, &r->act, err);
  if (!r->cal) {
    return 1;
  }
  r->map = csr_calibrationMap(r->cal);
  int has_rodcal = csr_calibrationRod(r->cal, &r->rodcal);
  r->tr = csTestFlatRoad();
  r->soft = csc_softDefaultParams();
  r->soft.mu = mu;
  r->sp = *sp;
  csrRobotModel rm;
  if (csr_robotDefaultModel(&rm, err) != CS_OK) {
    return 1;
  }
  r->ms = rm.support_mass;
  const double* S = rm.support_size;
  r->Is[0] = r->ms * (S[1] * S[1] + S[2] * S[2]) / 12;
  r->Is[1] = r->ms * (S[0] * S[0] + S[2] * S[2]) / 12;
  r->Is[2] = r->ms * (S[0] * S[0] + S[1] * S[1]) / 12;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(r->F, F, sizeof F);
  csu_eye3(r->R);
  const double L = csr_actuatorLength(&r->act);
  csu_set3(r->x, 0, L + 0.5 * S[1], 0);
  csu_set3(r->g, 0, -9810, 0);
  for (int k = 0; k < CSR_NLEG; k++) {
    double off[3];
    csr_robotHipOffset(&rm, k, off);
    csu_set3(r->hip[k], off[0], -0.5 * S[1], off[2]);
    csr_strainAdInv_(r->F, r->hip[k], r->A[k]);
    csrStrainSpec spec;
    memset(&spec, 0, sizeof spec);
    spec.act = &r->act;
    spec.params = &r->sp;
    spec.map = &r->map;
    spec.calib = has_rodcal ? &r->rodcal : NULL;
    csrBaseState b;
    strainRobotHip(r, k, &b);
    memcpy(spec.frame, b.R, sizeof spec.frame);
    memcpy(spec.hip, b.x, sizeof spec.hip);
    spec.weightless = 1; /* conditions `paper` */
    spec.terrain = &r->tr;
    spec.soft = &r->soft;
    r->m[k] = csr_strainModelCreate(&spec, err);
    r->d[k] = r->m[k] ? csr_strainDataCreate(r->m[k], err) : NULL;
    if (!r->d[k]) {
      return 1;
    }
  }
  return 0;
}


/* a new robot (strainRobotCreateParams, friction 0.8) with the parameters sp; NULL (the
 * cause on stderr) if it cannot be made */
static inline StrainRobot* strainRobotNew(const csrStrainParams* sp) {
  csError err;
  cs_errorClear(&err);
  StrainRobot* r = calloc(1, sizeof *r);
  if (r && strainRobotCreateParams(r, 0.8, sp, &err) == 0) {
    return r;
  }
  fprintf(stderr, "  %s\n", err.msg);
  free(r);
  return NULL;
}


/* the same with the legs' default active set (csrStrainParams.active_set 1) */
static inline int strainRobotCreateOrder(StrainRobot* r, double mu, int order, int step_order,
                                         csError* err) {
  return strainRobotCreateActive(r, mu, order, step_order, 1, err);
}


static inline int strainRobotCreate(StrainRobot* r, double mu, int order, csError* err) {
  return strainRobotCreateOrder(r, mu, order, 1, err);
}


static inline void strainRobotDestroy(StrainRobot* r) {
  for (int k = 0; k < CSR_NLEG; k++) {
    csr_strainDataDestroy(r->d[k]);
    csr_strainModelDestroy(r->m[k]);
  }
  csr_calibrationClose(r->cal);
}


/* the support's own part of the step from its start state (R0, V0): W (36) and h r (6) */
static inline void strainRobotOwn(const StrainRobot* r, double h, const double R0[9],
                                  const double V0[6], double W[36], double rhs[6]) {
  const double Ms[6] = {r->Is[0], r->Is[1], r->Is[2], r->ms, r->ms, r->ms};
  double mu[3] = {Ms[0] * V0[0], Ms[1] * V0[1], Ms[2] * V0[2]};
  double pi[3] = {Ms[3] * V0[3], Ms[4] * V0[4], Ms[5] * V0[5]};
  double a1[3], a2[3], gb[3];
  csu_cross3(a1, V0, mu);
  csu_cross3(a2, V0 + 3, pi);
  csu_mulMatTVec3(gb, R0, r->g);
  memset(W, 0, 36 * sizeof(double));
  for (int i = 0; i < 3; i++) {
    rhs[i] = h * (-a1[i] - a2[i]);
    W[7 * i] = Ms[i];
    W[7 * (i + 3)] = Ms[3 + i];
  }
  csu_cross3(a1, V0, pi);
  for (int i = 0; i < 3; i++) {
    rhs[3 + i] = h * (-a1[i] + r->ms * gb[i]);
  }
}


/* the support's end pose (R, x) for its end twist V from the start (R0, x0): backward Euler
 * g0 exp(h V) (c NULL); BDF2 with coefficients c (csr_strainBdf2Coeffs, he = c[2] h) on the
 * rotation vector about R0 and the centre's world position:
 *   R = R0 exp(φ), φ = c1 log(R0ᵀ R_-1) + he ω;   x = c0 x0 + c1 x_-1 + he R v
 * (the dexp⁻¹ correction of φ' is O(h²) there and enters at O(h³): ω × ω = 0) */
static inline void strainRobotPose(const StrainRobot* r, double h, const double* c,
                                   const double R0[9], const double x0[3], const double V[6],
                                   double R[9], double x[3]) {
  double Om[6], Re[9], pe[3], t[3];
  if (!c) {
    for (int i = 0; i < 6; i++) {
      Om[i] = h * V[i];
    }
    csr_strainExp_(Om, Re, pe);
    csu_mulMat3(R, R0, Re);
    csu_mulMatVec3(t, R0, pe);
    csu_add3(x, x0, t);
    return;
  }
  const double he = c[2] * h;
  double Rr[9], phi[3];
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      Rr[3 * i + j] = R0[i] * r->Rm1[j] + R0[3 + i] * r->Rm1[3 + j] + R0[6 + i] * r->Rm1[6 + j];
    }
  }
  csu_mat3ToRotVec(phi, Rr);
  for (int i = 0; i < 3; i++) {
    phi[i] = c[1] * phi[i] + he * V[i];
  }
  csu_rotVecToMat3(Re, phi);
  csu_mulMat3(R, R0, Re);
  csu_mulMatVec3(t, R, V + 3);
  for (int i = 0; i < 3; i++) {
    x[i] = c[0] * x0[i] + c[1] * r->xm1[i] + he * t[i];
  }
}


/* W += Aᵀ Z A, rhs += Aᵀ ρ */
static inline void strainRobotAddLeg(const double A[36], const double Z[36], const double rho[6],
                                     double W[36], double rhs[6]) {
  double ZA[36];
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int e = 0; e < 6; e++) {
        s += Z[6 * i + e] * A[6 * e + j];
      }
      ZA[6 * i + j] = s;
    }
  }
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int e = 0; e < 6; e++) {
        s += A[6 * e + i] * ZA[6 * e + j];
      }
      W[6 * i + j] += s;
    }
    double s = 0;
    for (int e = 0; e < 6; e++) {
      s += A[6 * e + i] * rho[e];
    }
    rhs[i] += s;
  }
}


/* One step of h with the legs' 96 pressures p96 at its end; 0 ok, 1 failed (the robot is then
 * mid-step: the caller restores what it saved). maxit 1: one linearised pass (the legs'
 * contact linearised at the start); maxit > 1: Newton iterations of the whole tree
 * (csr_strainIterate/Update) until no mode and no support coordinate moves by more than tol
 * (rad or mm) against the last iterate, failing after maxit passes. *iters (if not NULL) the
 * passes taken; leg_s and tree_s (if not NULL) accumulate the wall time of the legs' and the
 * support's parts. */
static inline int strainRobotStepIter(StrainRobot* r, double h, const double p96[96], int maxit,
                                      double tol, int* iters, double* leg_s, double* tree_s) {
  double W[36], rhs[6], Zs[CSR_NLEG][36], rhos[CSR_NLEG][6];
  double R0[9], x0[3], V0[6], dVp[6] = {0, 0, 0, 0, 0, 0};
  memcpy(R0, r->R, sizeof R0);
  memcpy(x0, r->x, sizeof x0);
  memcpy(V0, r->V, sizeof V0);
  /* BDF2 (the legs' step_order 2): every pass an iterate, the support's whole residual at it */
  const int bdf = r->sp.step_order == 2;
  double c[3] = {1, 0, 1};
  if (bdf) {
    csr_strainBdf2Coeffs(h, r->hprev, c);
    strainRobotPose(r, h, c, R0, x0, V0, r->R, r->x);
  }
  const double he = c[2] * h;
  double t0 = csu_wallSeconds(), tl = 0, tt = 0;
  for (int k = 0; k < CSR_NLEG; k++) {
    if (csr_strainActuate(r->m[k], r->d[k], p96 + 12 * k, NULL) != 0 ||
        csr_strainPrepare(r->m[k], r->d[k], h, Zs[k], rhos[k]) != 0) {
      return 1;
    }
  }
  /* damping: a pass whose full move did not shrink below 0.9 of the last one's halves the
   * next move (down to 1/8); a shrinking one restores the full step */
  int it = 0, ok = 0;
  double alpha = 1, chg_last = INFINITY;
  for (;;) {
    double t1 = csu_wallSeconds();
    tl += t1 - t0;
    if (bdf) {
      /* the support's BDF residual at the iterate: h r = M_s (V̄ - V0) + he F(R_it, V_it) (its
       * own rows; the gyroscopic term's Jacobian left out of W), V̄ = c0 V0 + c1 V_-1 */
      strainRobotOwn(r, he, r->R, r->V, W, rhs);
      for (int i = 0; i < 6; i++) {
        rhs[i] += W[7 * i] * ((c[0] - 1) * V0[i] + c[1] * r->Vm1[i]);
      }
      /* the linear rows in BDF2's momentum form: R_itᵀ (m (x_it - x̄) / he - D̄ - he m g) */
      double Rw[3], Rl[3];
      for (int i = 0; i < 3; i++) {
        const double xb = c[0] * x0[i] + c[1] * r->xm1[i];
        const double Db = c[0] * r->D[i] + c[1] * r->Dm1[i];
        Rw[i] = r->ms * ((r->x[i] - xb) / he - he * r->g[i]) - Db;
      }
      csu_mulMatTVec3(Rl, r->R, Rw);
      for (int i = 0; i < 3; i++) {
        rhs[3 + i] = r->ms * dVp[3 + i] - Rl[i];
      }
    } else {
      strainRobotOwn(r, h, R0, V0, W, rhs);
    }
    if (it > 0 && !bdf) {
      /* an iterate: the support's linear momentum rows in the legs' discrete momentum form
       * (robot_strain.h): R_1ᵀ (m (x1 - x0) / h - D - h m g) = 0 at the iterate's end pose,
       * its rows of W m I, so h r = m ΔV_it - R */
      double Rw[3], Rl[3];
      for (int i = 0; i < 3; i++) {
        Rw[i] = r->ms * ((r->x[i] - x0[i]) / h - h * r->g[i]) - r->D[i];
      }
      csu_mulMatTVec3(Rl, r->R, Rw);
      for (int i = 0; i < 3; i++) {
        rhs[3 + i] = r->ms * dVp[3 + i] - Rl[i];
      }
    }
    for (int k = 0; k < CSR_NLEG; k++) {
      strainRobotAddLeg(r->A[k], Zs[k], rhos[k], W, rhs);
    }
    if (csu_solve6(W, rhs) != 0) {
      return 1; /* the support's condensed matrix is singular */
    }
    const double* dV = rhs;
    double chg = 0, dVk[CSR_NLEG][6];
    for (int k = 0; k < CSR_NLEG; k++) {
      for (int i = 0; i < 6; i++) {
        dVk[k][i] = 0;
        for (int j = 0; j < 6; j++) {
          dVk[k][i] += r->A[k][6 * i + j] * dV[j];
        }
      }
    }
    /* the legs' globalisation (slot_trust; core/sim_tree.c the same): the whole move
     * damped by the least fraction a leg allows */
    double amove = alpha;
    for (int k = 0; it > 0 && k < CSR_NLEG; k++) {
      amove = fmin(amove, csr_strainStepLimit(r->m[k], r->d[k], dVk[k]));
    }
    r->limited += amove < alpha;
    for (int i = 0; i < 6; i++) {
      chg = fmax(chg, h * fabs(dV[i] - dVp[i]));
      dVp[i] += amove * (dV[i] - dVp[i]);
      r->V[i] = V0[i] + dVp[i];
    }
    strainRobotPose(r, h, bdf ? c : NULL, R0, x0, r->V, r->R, r->x);
    t0 = csu_wallSeconds();
    tt += t0 - t1;
    for (int k = 0; k < CSR_NLEG; k++) {
      double c = 0;
      csrBaseState b;
      strainRobotHip(r, k, &b);
      if (csr_strainUpdateDamped(r->m[k], r->d[k], dVk[k], amove, &b, &c) != 0) {
        return 1;
      }
      chg = fmax(chg, c);
    }
    it++;
    /* converged as the driver's tree step (core/sim_tree.c): this move, or what is left
     * of the moves after it when an undamped pass contracts at a rate < 1 (chg rate /
     * (1 - rate)), is below tol */
    const double rate = chg / chg_last;
    const int full = amove == 1;
    alpha = it > 1 && chg > 0.9 * chg_last ? fmax(0.125, 0.5 * alpha) : 1.0;
    chg_last = chg;
    int conv = chg <= tol || (full && rate > 0 && rate < 1 && chg * rate / (1 - rate) <= tol);
    if (maxit > 1 && it > 1 && conv) {
      /* a leg that held a contact shape by its ghost drops it and the passes go on, undamped
       * (csr_strainRelease; core/sim_tree.c the same) */
      int released = 0;
      for (int k = 0; k < CSR_NLEG; k++) {
        released += csr_strainRelease(r->m[k], r->d[k]);
      }
      if (released > 0) {
        r->released += released;
        conv = 0;
        alpha = 1.0;
        chg_last = INFINITY;
      }
    }
    if (maxit <= 1 || (it > 1 && conv)) {
      ok = 1;
      break;
    }
    if (it >= maxit) {
      break;
    }
    for (int k = 0; k < CSR_NLEG; k++) {
      if (csr_strainIterate(r->m[k], r->d[k], Zs[k], rhos[k]) != 0) {
        return 1;
      }
    }
  }
  if (iters) {
    *iters = it;
  }
  if (!ok) {
    return 1;
  }
  for (int i = 0; i < 3; i++) {
    const double Dn = bdf ? r->ms * (r->x[i] - c[0] * x0[i] - c[1] * r->xm1[i]) / he
                          : r->ms * (r->x[i] - x0[i]) / h;
    r->Dm1[i] = r->D[i];
    r->D[i] = Dn;
  }
  memcpy(r->Rm1, R0, sizeof R0);
  memcpy(r->xm1, x0, sizeof x0);
  memcpy(r->Vm1, V0, sizeof V0);
  r->hprev = h;
  for (int k = 0; k < CSR_NLEG; k++) {
    if (csr_strainCommit(r->m[k], r->d[k]) != 0) {
      return 1;
    }
  }
  tl += csu_wallSeconds() - t0;
  if (leg_s) {
    *leg_s += tl;
  }
  if (tree_s) {
    *tree_s += tt;
  }
  r->t += h;
  return 0;
}


/* one linearised pass (strainRobotStepIter with maxit 1) */
static inline int strainRobotStep(StrainRobot* r, double h, const double p96[96],
                                  double* leg_s, double* tree_s) {
  return strainRobotStepIter(r, h, p96, 1, 0, NULL, leg_s, tree_s);
}


/* the robot's whole state: the support and every leg's state (a caller-owned buffer of
 * strainRobotStateSize doubles) */
static inline int strainRobotStateSize(const StrainRobot* r) {
  int n = 9 + 3 + 6 + 1 + 3 + 22;
  for (int k = 0; k < CSR_NLEG; k++) {
    n += csr_strainStateSize(r->m[k]);
  }
  return n;
}


static inline void strainRobotSave(const StrainRobot* r, double* y) {
  memcpy(y, r->R, 9 * sizeof(double));
  memcpy(y + 9, r->x, 3 * sizeof(double));
  memcpy(y + 12, r->V, 6 * sizeof(double));
  y[18] = r->t;
  memcpy(y + 19, r->D, 3 * sizeof(double));
  memcpy(y + 22, r->Rm1, 9 * sizeof(double));
  memcpy(y + 31, r->xm1, 3 * sizeof(double));
  memcpy(y + 34, r->Vm1, 6 * sizeof(double));
  memcpy(y + 40, r->Dm1, 3 * sizeof(double));
  y[43] = r->hprev;
  y += 44;
  for (int k = 0; k < CSR_NLEG; k++) {
    csr_strainGetState(r->m[k], r->d[k], y);
    y += csr_strainStateSize(r->m[k]);
  }
}


static inline void strainRobotRestore(StrainRobot* r, const double* y) {
  memcpy(r->R, y, 9 * sizeof(double));
  memcpy(r->x, y + 9, 3 * sizeof(double));
  memcpy(r->V, y + 12, 6 * sizeof(double));
  r->t = y[18];
  memcpy(r->D, y + 19, 3 * sizeof(double));
  memcpy(r->Rm1, y + 22, 9 * sizeof(double));
  memcpy(r->xm1, y + 31, 3 * sizeof(double));
  memcpy(r->Vm1, y + 34, 6 * sizeof(double));
  memcpy(r->Dm1, y + 40, 3 * sizeof(double));
  r->hprev = y[43];
  y += 44;
  for (int k = 0; k < CSR_NLEG; k++) {
    csr_strainSetState(r->m[k], r->d[k], y);
    csrBaseState b;
    strainRobotHip(r, k, &b);
    csr_strainSetBase(r->m[k], r->d[k], &b);
    y += csr_strainStateSize(r->m[k]);
  }
}


/* ref's state (into y0) given to a and b, and the gait's pressures at t (p96) */
static inline void strainRobotSameStart(const StrainRobot* ref, StrainRobot* a, StrainRobot* b,
                                        const csgGait* g, double t, double* y0,
                                        double p96[96]) {
  csg_scheduleEval(g, NULL, t, p96);
  strainRobotSave(ref, y0);
  strainRobotRestore(a, y0);
  strainRobotRestore(b, y0);
}


/* leg k of a and of b actuated at the pressures p96 and prepared for a step h (Za, ra; Zb,
 * rb): the step's start both ways from the same state (the condensation tests) */
static inline int strainRobotPrepareBoth(StrainRobot* a, StrainRobot* b, int k,
                                         const double p96[96], double h, double Za[36],
                                         double ra[6], double Zb[36], double rb[6]) {
  const int rc = csr_strainActuate(a->m[k], a->d[k], p96 + 12 * k, NULL) != 0 ||
                 csr_strainActuate(b->m[k], b->d[k], p96 + 12 * k, NULL) != 0 ||
                 csr_strainPrepare(a->m[k], a->d[k], h, Za, ra) != 0 ||
                 csr_strainPrepare(b->m[k], b->d[k], h, Zb, rb) != 0;
  return rc;
}


/* Advance from ta to tb with Newton steps (strainRobotStepIter, maxit passes to tol), the
 * gait g giving the pressures at each piece's end: a piece that fails is restored from save
 * (strainRobotStateSize doubles) and halved, at most max_halve times. 0 ok, 1 failed; the
 * counters (if not NULL) accumulate steps taken, rejected pieces and passes. */
static inline int strainRobotAdvance(StrainRobot* r, const csgGait* g, double ta, double tb,
                                     int maxit, double tol, int max_halve, double* save,
                                     long* steps, long* rejected, long* passes, double* leg_s,
                                     double* tree_s) {
  const double h = tb - ta;
  int depth = 0;
  while (ta < tb - 1e-12 * h) {
    double te = fmin(tb, ta + h / (1 << depth)), p96[96];
    int it = 0;
    csg_scheduleEval(g, NULL, te, p96);
    strainRobotSave(r, save);
    if (strainRobotStepIter(r, te - ta, p96, maxit, tol, &it, leg_s, tree_s) != 0) {
      strainRobotRestore(r, save);
      if (rejected) {
        (*rejected)++;
      }
      if (++depth > max_halve) {
        return 1;
      }
      continue;
    }
    if (passes) {
      *passes += it;
    }
    if (steps) {
      (*steps)++;
    }
    ta = te;
  }
  return 0;
}


/* centre of mass of support and legs (world mm) */
static inline void strainRobotCom(StrainRobot* r, double com[3]) {
  double M = r->ms, mx[3];
  csu_scale3(com, r->x, r->ms);
  for (int k = 0; k < CSR_NLEG; k++) {
    csr_strainMassMoment(r->m[k], r->d[k], mx);
    csu_add3(com, com, mx);
    M += csr_strainMass(r->m[k]);
  }
  csu_scale3(com, com, 1 / M);
}

#endif /* CS_TESTS_STRAIN_TEST_ROBOT_H */

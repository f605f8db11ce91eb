/* sim_coupling.c: the support interface of co-simulated legs (see sim_model.h, robot_leg.h).
 *
 * Staggered scheme (Jacobi with a predictor). At the macro step's start every hip's motion b0
 * is read from the support; b1 at t + H is predicted from the support's twist held constant
 * (centre P0 + v0 H, rotation exp([w0] H) R0). Each leg advances across [t, t + H] with b0 -> b1
 * and returns its base wrench averaged over the step; during the macro_steps ODE steps the
 * wrench is applied constant at the hip's current position. The impulse the support receives
 * is then exactly the one the leg's base reaction carried (momentum is conserved across the
 * interface for any H); what the scheme gets wrong is that the legs saw the predicted, not the
 * actual, motion: explicit in the interface, so it can go unstable for a light support on
 * stiff legs as H grows.
 *
 * Stabilised scheme. Each leg also hands back K, C (interfaceGains): how its wrench would
 * change if its hip left the motion it was given. Moved to the support's centre of mass
 * (hip twist = T [v; w], T = [[I, -[r]x], [0, I]], r = hip - centre, so a hip wrench W acts as
 * T^T W) and summed, they give Kc, Cc; the force on the support over ODE step j -> j + 1 is
 *   F = W0 - Kc dq_j - A (q'_{j+1} - q'_pred),  A = h Kc + Cc,
 * with q' = [v; w] and dq the deviation of the support's pose from the predicted motion's mean
 * pose: W0 is the wrench averaged over the predicted motion, which for a leg linear in its
 * hip's motion is its wrench at the mean pose and twist, so that point is where W0's
 * linearisation holds (measured: linearising about the prediction at each sub-step's own time
 * instead shifts the force by K v0 (H/2 - t) and, at w H = 4, threw the stance oscillator
 * 2.7e3 mm off). The mean is taken over the poses the ODE steps start from (prepared in
 * cs_couplingAdvance). For linear stance legs this is the backward-Euler spring-damper at any
 * H, up to a pose offset of h v0 / 2 (ODE's own first order). ODE has no joint
 * that holds a general 6x6 A, so the part of A within the linear and within the angular block
 * goes to ODE as rows: an LMotor (3 linear rows on the centre's velocity) and an AMotor (3
 * angular rows, user mode), along the eigenvectors u of each symmetric block with eigenvalue
 * a > 0: a motor row with target velocity c and constraint-force mixing CFM ends the step with
 * u.v' = c - CFM lambda (ODE's row equation), so CFM = 1/a and c = (u.g)/a give exactly the
 * force lambda = u.g - a u.v' (the ERP/CFM spring of csu_springErpCfm written in velocity
 * form). The linear-angular coupling block of A, and directions with a <= 0, are applied
 * explicitly with the current velocity. The rows converge with QuickStep's iterations like any
 * constraint.
 *
 * Rejected: sub-iterating the legs to convergence every step (the tightly coupled reference:
 * the driver's state save/restore makes it possible, at several advances per step); handing
 * the legs' gains to ODE through fixed joints (one scalar ERP/CFM per joint: isotropic only). */
#include <math.h>
#include <string.h>

#include "core_math.h"
#include "sim_internal.h"

/* an eigenvalue below this fraction of the block's largest is treated as zero (explicit):
 * CFM = 1/a would be ~1e12 times the others' and the row carries no stiffness worth solving */
#define MIN_EIG_RATIO 1e-12

/* 6x6 row-major helpers */
static void mat6Zero(double M[36]) { memset(M, 0, 36 * sizeof(double)); }


/* M += T^T G T for the hip-to-centre map T = [[I, -[r]x], [0, I]] (G at the hip, 6x6) */
static void addAtCentre(double M[36], const double G[36], const double r[3]) {
  /* T as a dense 6x6 (small: clarity over speed, once per macro step and leg) */
  double T[36];
  mat6Zero(T);
  for (int i = 0; i < 6; i++) {
    T[6 * i + i] = 1;
  }
  /* -[r]x in the upper right block: -[r]x a = a x r */
  T[6 * 0 + 4] = r[2];
  T[6 * 0 + 5] = -r[1];
  T[6 * 1 + 3] = -r[2];
  T[6 * 1 + 5] = r[0];
  T[6 * 2 + 3] = r[1];
  T[6 * 2 + 4] = -r[0];
  double GT[36];
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int k = 0; k < 6; k++) {
        s += G[6 * i + k] * T[6 * k + j];
      }
      GT[6 * i + j] = s;
    }
  }
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      double s = 0;
      for (int k = 0; k < 6; k++) {
        s += T[6 * k + i] * GT[6 * k + j];
      }
      M[6 * i + j] += s;
    }
  }
}


/* y = M x for 6x6 M */
static void mat6Vec(double y[6], const double M[36], const double x[6]) {
  for (int i = 0; i < 6; i++) {
    double s = 0;
    for (int k = 0; k < 6; k++) {
      s += M[6 * i + k] * x[k];
    }
    y[i] = s;
  }
}


csStatus cs_couplingCreate(const csModel* m, csData* d, csError* err) {
  (void)err;
  if (!d->cosim.active || m->opt.coupling != CS_COUPLING_STABILISED) {
    return CS_OK;
  }
  csCosim* c = &d->cosim;
  c->lmotor = dJointCreateLMotor(d->world, 0);
  dJointAttach(c->lmotor, d->robot->support, 0);
  dJointSetLMotorNumAxes(c->lmotor, 3);
  c->amotor = dJointCreateAMotor(d->world, 0);
  dJointAttach(c->amotor, d->robot->support, 0);
  dJointSetAMotorMode(c->amotor, dAMotorUser);
  dJointSetAMotorNumAxes(c->amotor, 3);
  /* rows off until the first macro step sets them (FMax 0 disables a motor row) */
  for (int i = 0; i < 3; i++) {
    dJointSetLMotorAxis(c->lmotor, i, 0, i == 0, i == 1, i == 2);
    dJointSetAMotorAxis(c->amotor, i, 0, i == 0, i == 1, i == 2);
    dJointSetLMotorParam(c->lmotor, dParamFMax + dParamGroup * i, 0);
    dJointSetAMotorParam(c->amotor, dParamFMax + dParamGroup * i, 0);
  }
  return CS_OK;
}


/* stabilised scheme: sum the legs' gains at the centre and set up the ODE rows */
static void prepareImplicit(const csModel* m, csData* d) {
  csCosim* c = &d->cosim;
  double Cc[36];
  mat6Zero(c->Kc);
  mat6Zero(Cc);
  for (int k = 0; k < CSR_NLEG; k++) {
    double r[3];
    csu_sub3(r, c->b0[k].x, c->P0);
    addAtCentre(c->Kc, c->K[k], r);
    addAtCentre(Cc, c->C[k], r);
  }
  for (int i = 0; i < 36; i++) {
    c->A[i] = m->opt.h * c->Kc[i] + Cc[i];
  }
  for (int b = 0; b < 2; b++) {
    double blk[9];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        blk[3 * i + j] = c->A[6 * (3 * b + i) + 3 * b + j];
      }
    }
    csu_symEigen3(blk, c->eig[b], c->axis[b]);
    double amax = fmax(fabs(c->eig[b][0]), fmax(fabs(c->eig[b][1]), fabs(c->eig[b][2])));
    for (int i = 0; i < 3; i++) {
      double a = c->eig[b][i];
      const double* V = c->axis[b];
      c->implicit[b][i] = a > MIN_EIG_RATIO * amax && a > 0;
      dJointID j = b == 0 ? c->lmotor : c->amotor;
      int grp = dParamGroup * i;
      /* FMax 0 switches a row off; an implicit row is unbounded with CFM = 1/a */
      double fmax = c->implicit[b][i] ? dInfinity : 0, cfm = c->implicit[b][i] ? 1.0 / a : 0;
      if (b == 0) {
        dJointSetLMotorAxis(j, i, 0, V[i], V[3 + i], V[6 + i]);
        dJointSetLMotorParam(j, dParamFMax + grp, fmax);
        dJointSetLMotorParam(j, dParamCFM + grp, cfm);
      } else {
        dJointSetAMotorAxis(j, i, 0, V[i], V[3 + i], V[6 + i]);
        dJointSetAMotorParam(j, dParamFMax + grp, fmax);
        dJointSetAMotorParam(j, dParamCFM + grp, cfm);
      }
    }
  }
}


int cs_couplingAdvance(const csModel* m, csData* d, double H, csError* err) {
  csCosim* c = &d->cosim;
  const csrLegType* type = m->robot.leg_type;
  double P1[3], R1[9], dR[9], phi[3];
  cs_errorClear(err); /* whatever err holds after this came from these legs */
  csr_robotSupportPose(d->robot, c->P0, c->R0, c->v0, c->w0);
  c->t0 = d->t;
  /* the predictor: the support's twist held over the step (end pose, and the mean pose below) */
  csu_addScl3(P1, c->P0, c->v0, H);
  csu_scale3(phi, c->w0, H);
  csu_rotVecToMat3(dR, phi);
  csu_mulMat3(R1, dR, c->R0);
  /* the linearisation point: the mean of the predicted poses at the starts of the ODE steps,
   * t0 + j h, j = 0..n-1, i.e. t0 + (H - h)/2. The force of step j is -Kc (dq_j + h dq'_{j+1})
   * with dq' a deviation from the predicted twist, so a support that follows the prediction gets
   * no correction impulse at all with this point, while the mid-step pose t0 + H/2 left a
   * spurious -Kc h v0 / 2 (measured on free feet: 2.5 % momentum drift; t0 + (H + h)/2: 5 %) */
  double tm = 0.5 * (H - m->opt.h);
  csu_addScl3(c->Pm, c->P0, c->v0, tm);
  csu_scale3(phi, c->w0, tm);
  csu_rotVecToMat3(dR, phi);
  csu_mulMat3(c->Rm, dR, c->R0);
  for (int k = 0; k < CSR_NLEG; k++) {
    csr_robotBaseStateAt(d->robot, k, c->P0, c->R0, c->v0, c->w0, &c->b0[k]);
    csr_robotBaseStateAt(d->robot, k, P1, R1, c->v0, c->w0, &c->b1[k]);
    int rc = type->advance(d->robot->legs[k], d->t, H, &c->b0[k], &c->b1[k], &c->w[k], err);
    if (rc != 0) {
      return rc;
    }
    int finite = 1;
    for (int i = 0; i < 3; i++) {
      finite &= isfinite(c->w[k].f[i]) && isfinite(c->w[k].m[i]);
    }
    if (m->opt.coupling == CS_COUPLING_STABILISED) {
      type->interfaceGains(d->robot->legs[k], c->K[k], c->C[k]);
      for (int i = 0; i < 36; i++) {
        finite &= isfinite(c->K[k][i]) && isfinite(c->C[k][i]);
      }
    }
    if (!finite) {
      /* a leg that hands back NaN has left its valid range: a smaller step may keep it in */
      cs_errorSet(err, CS_ERR_REJECTED, "t = %.4f s: leg %c returned a non-finite wrench or "
                  "interface gain", d->t, 'A' + k);
      return 1;
    }
  }
  if (m->opt.coupling == CS_COUPLING_STABILISED) {
    prepareImplicit(m, d);
  }
  return 0;
}


void cs_couplingApply(const csModel* m, csData* d, int j) {
  csCosim* c = &d->cosim;
  for (int k = 0; k < CSR_NLEG; k++) {
    csr_robotApplyWrench(d->robot, k, &c->w[k]);
  }
  if (m->opt.coupling != CS_COUPLING_STABILISED) {
    return;
  }
  /* deviation of the support at the start of ODE step j from the predicted mean pose */
  (void)j;
  double P[3], R[9], v[3], w[3], dR[9], RmT[9];
  csr_robotSupportPose(d->robot, P, R, v, w);
  csu_transpose3(RmT, c->Rm);
  csu_mulMat3(dR, R, RmT);
  double dq[6], qd[6], qd_pred[6];
  for (int i = 0; i < 3; i++) {
    dq[i] = P[i] - c->Pm[i];
    qd[i] = v[i];
    qd[3 + i] = w[i];
    qd_pred[i] = c->v0[i];
    qd_pred[3 + i] = c->w0[i];
  }
  csu_mat3ToRotVec(dq + 3, dR);
  /* g = -Kc dq + A q'_pred - A_offdiag q' : all but the block-diagonal implicit part */
  double g[6], Kdq[6], Aq[6], Aoff[36];
  mat6Vec(Kdq, c->Kc, dq);
  mat6Vec(Aq, c->A, qd_pred);
  memcpy(Aoff, c->A, sizeof Aoff);
  for (int b = 0; b < 2; b++) {
    for (int i = 0; i < 3; i++) {
      for (int k = 0; k < 3; k++) {
        Aoff[6 * (3 * b + i) + 3 * b + k] = 0;
      }
    }
  }
  double Aoq[6];
  mat6Vec(Aoq, Aoff, qd);
  for (int i = 0; i < 6; i++) {
    g[i] = -Kdq[i] + Aq[i] - Aoq[i];
  }
  /* per block and eigen-direction: an ODE row (implicit) or an explicit force */
  double fex[6] = {0, 0, 0, 0, 0, 0};
  for (int b = 0; b < 2; b++) {
    const double* V = c->axis[b];
    for (int i = 0; i < 3; i++) {
      double u[3] = {V[i], V[3 + i], V[6 + i]};
      double ug = csu_dot3(u, g + 3 * b), a = c->eig[b][i];
      if (c->implicit[b][i]) {
        int grp = dParamGroup * i;
        if (b == 0) {
          dJointSetLMotorParam(c->lmotor, dParamVel + grp, ug / a);
        } else {
          dJointSetAMotorParam(c->amotor, dParamVel + grp, ug / a);
        }
      } else {
        double f = ug - a * csu_dot3(u, qd + 3 * b);
        csu_addScl3(fex + 3 * b, fex + 3 * b, u, f);
      }
    }
  }
  dBodyAddForce(d->robot->support, fex[0], fex[1], fex[2]);
  dBodyAddTorque(d->robot->support, fex[3], fex[4], fex[5]);
}

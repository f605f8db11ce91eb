/* sim_coupling.c: the support interface of co-simulated legs (see sim_model.h, robot_leg.h).
 *
 * Staggered scheme (Jacobi with a predictor). At the macro step's start every hip's motion b0
 * is read from the support; b1 at t + H is predicted from the support's twist held constant
 * (centre P0 + v0 H, rotation exp([w0] H) R0). Each leg advances across [t, t + H] with b0 -> b1
 * and returns its base wrench averaged over the step; during the macro_steps ODE steps the
 * wrench is applied constant at the hip's current position. The impulse the support receives
 * is then exactly the one the leg's base reaction carried (momentum is conserved across the
 * interface for any H); what the scheme gets wrong is that the legs saw the predicted, not the
 * actual, motion: explicit in the interface, so it goes unstable for a light support on stiff
 * legs as H grows. With rod legs the limit is the hip element's Kelvin-Voigt damper (0.26 N s/mm
 * axially per leg): an explicit damper c on the 50 g support needs 8 c H / M < 2, H < 48 µs
 * (measured: the flat road diverges while settling at H = 50 µs, runs at 25 µs).
 *
 * Stabilised scheme (linearly implicit in the interface). Each leg also hands back K, C
 * (interfaceGains): how its wrench would change if its hip left the motion it was given, over
 * one implicit step of ODE's h (robot_leg.h; for the rod the Schur complement of its own step
 * onto the hip, robot_rod.h). Moved to the support's centre of mass (hip twist = T [v; w],
 * T = [[I, -[r]x], [0, I]], r = hip - centre, so a hip wrench W acts as T^T W) and summed,
 * they give Kc, Cc; the legs' force on the support over ODE step j -> j + 1 is
 *   F = W0 - Kc dq_j - A (q'_{j+1} - q'_pred),  A = h Kc + Cc,
 * with q' = [v; w] and dq the deviation of the support's pose from the predicted motion's mean
 * pose: W0 is the wrench averaged over the predicted motion, which for a leg linear in its
 * hip's motion is its wrench at the mean pose and twist, so that point is where W0's
 * linearisation holds (measured: linearising about the prediction at each sub-step's own time
 * instead shifts the force by K v0 (H/2 - t) and, at w H = 4, threw the stance oscillator
 * 2.7e3 mm off). The mean is taken over the poses the ODE steps start from (prepared in
 * cs_couplingAdvance). For linear stance legs this is the backward-Euler spring-damper at any
 * H, up to a pose offset of h v0 / 2 (ODE's own first order).
 * The implicit part is solved here, for the whole 6 x 6 A: the support's backward-Euler step
 *   (M + h A) q'_{j+1} = M q'_j + h (m g + W0 - Kc dq_j + A q'_pred)
 * (M = diag(m I, I_world), gyroscopic and terrain-contact forces left to ODE) gives q'_{j+1},
 * and the force F above, evaluated with it, is added to the support as an ordinary force: ODE's
 * step then lands on q'_{j+1} (to its gyroscopic term, and exactly unless the support itself
 * touches the terrain, which ODE resolves with F held). An earlier version handed only A's
 * symmetric 3 x 3 diagonal blocks to ODE as motor rows (LMotor/AMotor with CFM = 1/eigenvalue)
 * and the rest explicitly: with the rod's condensed gains, which are not symmetric and couple
 * the centre's translation and rotation through the hips' lever arms (8 legs at 65-75 mm), it
 * diverged at h = 2 ms on the flat road, where the full solve runs.
 *
 * Gauss-Seidel scheme (`--coupling gs`). The support steps FIRST, then every leg advances along
 * the support's ACTUAL motion over [t, t + H] (cubic Hermite between the support's states at
 * both ends, the same states the next step starts from: a hip's path is C1 across exchanges,
 * where the Jacobi schemes restart each advance from the actual hip and jump off the predicted
 * end by the predictor's error). The support cannot know the legs' wrench of the step yet; it
 * takes the last step's, W0 = W_{n-1}, linearised with the last advance's gains Kc, A in the
 * same implicit solve as above about the motion that gave it: the mean start pose of the last
 * step's ODE steps and a twist that continues the last step's at its acceleration,
 * q'_ref = q'_{n} + (q'_{n} - q'_{n-1}) (mean end twists). That extrapolation is what the
 * legs' inertia needs: their condensed gains over 1 ms are mostly the inertia that follows the
 * hip (C h ~ 22 g of a 35 g leg, axially), whose reaction -m a_{n-1} is in W_{n-1} and holds at
 * the last acceleration, not the last velocity. For a massless damper the same extrapolation
 * is wrong by c h a: on such legs the scheme is first order in H (test_cosim). The legs'
 * actual wrench then differs from what the support was given; that impulse is carried into
 * the next step's force (carry, csOptions.coupling_carry), so the interface conserves momentum
 * to one step's difference. Measured on the flat road (shipped gait, `paper`, h = H = 1 ms):
 * unextrapolated without the carry it diverged at t = 4.6 s, with the carry while settling
 * (the carried inertial reaction comes a step late: the legs' ~173 g of condensed inertia on
 * the 50 g support amplified it 1.8x a step), half extrapolated with the carry while settling;
 * extrapolated without the carry it ran but walked 176 mm instead of the reference's 298.
 * The first macro step (nothing carried yet, gs_primed = 0) runs stabilised and leaves what it
 * carries (cs_couplingPrime). Everything carried is in the state (cs_couplingStateGet), so a
 * failed step restores it. With the rods' base force their momentum balance and their hip
 * node massless (robot_rod_dyn.c, robot_rod_model.c), gs at H = h = 1 ms follows the converged
 * staggered reference and the paper's table on the flat road to within a few mm, and keeps the
 * frictionless centre of mass where the stabilised scheme's momentum error moves it: hence the
 * default for co-simulated legs. Longer macro steps lose accuracy, and h = H = 2 ms diverged
 * while settling (the numbers: docs/notes/code_measurements.md "Gauss-Seidel coupling").
 *
 * Rejected: sub-iterating the legs to convergence every step (the tightly coupled reference:
 * the driver's state save/restore makes it possible, at several advances per step; a tiny macro
 * step is the reference used, README "Coupling"); handing the legs' gains to ODE through fixed
 * joints (one scalar ERP/CFM per joint: isotropic only). */
#include <math.h>
#include <string.h>

#include "core_math.h"
#include "sim_internal.h"

/* 6x6 row-major helpers */
static void mat6Zero(double M[36]) { memset(M, 0, 36 * sizeof(double)); }


void cs_couplingAddAtCentre(double M[36], const double G[36], const double r[3]) {
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
  double C[36];
  csu_congruence6(C, T, G);
  for (int i = 0; i < 36; i++) {
    M[i] += C[i];
  }
}


/* C = A B (C may not alias A or B) */
static void mat6Mul(double C[36], const double A[36], const double B[36]) {
  for (int i = 0; i < 6; i++) {
    for (int k = 0; k < 6; k++) {
      double s = 0;
      for (int e = 0; e < 6; e++) {
        s += A[6 * i + e] * B[6 * e + k];
      }
      C[6 * i + k] = s;
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


void cs_modelSetLegLevel(csModel* m, const csrLegType* type) {
  m->robot.leg_type = type;
  /* co-simulated legs default to Gauss-Seidel: momentum exact, and 0.6 mm from the converged
   * staggered reference over the 9 s flat road where the stabilised scheme is 22 mm off (top) */
  m->opt.coupling = type && !type->in_world ? CS_COUPLING_GAUSS_SEIDEL : CS_COUPLING_STAGGERED;
  if (type && !type->in_world && type->coupling_stabilised) {
    /* a level whose gains hold its contact's stiffness (rom): the implicit solve with them */
    m->opt.coupling = CS_COUPLING_STABILISED;
  }
  if (type && !type->in_world && type->prepare) {
    /* a tree-stepped level: one step for the support and the legs (bottom), at its own step */
    m->opt.coupling = CS_COUPLING_TREE;
    m->opt.macro_steps = 1;
    if (type->step > 0) {
      m->opt.h = type->step;
    }
  }
}


csStatus cs_couplingCreate(const csModel* m, csData* d, csError* err) {
  /* the stabilised scheme solves its implicit part itself (cs_couplingApply): no ODE rows.
   * Gauss-Seidel's first macro step has no legs' wrench yet (zero wrench and gains, the data is
   * zeroed): its linearisation point only needs to be a rotation */
  (void)m;
  (void)err;
  csu_eye3(d->cosim.gs_R);
  return CS_OK;
}


/* The carried coupling data as (field, length) in the order of the state vector
 * (CS_COSIM_STATE doubles, sim_internal.h): one list for get and set, so the two cannot
 * disagree on the layout. Returns the number of fields. */
typedef struct {
  double* p;
  int n;
} CosimField;
enum { COSIM_NFIELD = 2 * CSR_NLEG + 12 };
#define COSIM_LEN(f) (sizeof(((csCosim*)0)->f) / sizeof(double))
_Static_assert(CS_COSIM_STATE == CSR_NLEG * (COSIM_LEN(w[0].f) + COSIM_LEN(w[0].m)) +
                                     COSIM_LEN(Kc) + COSIM_LEN(A) + COSIM_LEN(gs_P) +
                                     COSIM_LEN(gs_R) + COSIM_LEN(gs_qd) + COSIM_LEN(carry) +
                                     COSIM_LEN(gs_qd_prev) + COSIM_LEN(tb_P) + COSIM_LEN(tb_R) +
                                     COSIM_LEN(tb_v) + COSIM_LEN(tb_w) + 1,
               "CS_COSIM_STATE must be the length of cosimFields' list");
static int cosimFields(csCosim* c, CosimField f[COSIM_NFIELD]) {
  int q = 0;
  for (int k = 0; k < CSR_NLEG; k++) {
    f[q++] = (CosimField){c->w[k].f, (int)COSIM_LEN(w[0].f)};
    f[q++] = (CosimField){c->w[k].m, (int)COSIM_LEN(w[0].m)};
  }
  f[q++] = (CosimField){c->Kc, (int)COSIM_LEN(Kc)};
  f[q++] = (CosimField){c->A, (int)COSIM_LEN(A)};
  f[q++] = (CosimField){c->gs_P, (int)COSIM_LEN(gs_P)};
  f[q++] = (CosimField){c->gs_R, (int)COSIM_LEN(gs_R)};
  f[q++] = (CosimField){c->gs_qd, (int)COSIM_LEN(gs_qd)};
  f[q++] = (CosimField){c->carry, (int)COSIM_LEN(carry)};
  f[q++] = (CosimField){c->gs_qd_prev, (int)COSIM_LEN(gs_qd_prev)};
  f[q++] = (CosimField){c->tb_P, (int)COSIM_LEN(tb_P)};
  f[q++] = (CosimField){c->tb_R, (int)COSIM_LEN(tb_R)};
  f[q++] = (CosimField){c->tb_v, (int)COSIM_LEN(tb_v)};
  f[q++] = (CosimField){c->tb_w, (int)COSIM_LEN(tb_w)};
  f[q++] = (CosimField){&c->gs_primed, 1};
  return q;
}


void cs_couplingStateGet(const csData* d, double* x) {
  CosimField f[COSIM_NFIELD];
  const int nf = cosimFields((csCosim*)&d->cosim, f); /* read only here */
  for (int i = 0; i < nf; i++) {
    memcpy(x, f[i].p, (size_t)f[i].n * sizeof(double));
    x += f[i].n;
  }
}


int cs_couplingStateCheck(const double* x) {
  for (int i = 0; i < CS_COSIM_STATE; i++) {
    if (!isfinite(x[i])) {
      return 1;
    }
  }
  const double primed = x[CS_COSIM_STATE - 1];
  return primed == 0 || primed == 1 ? 0 : 1;
}


void cs_couplingStateSet(csData* d, const double* x) {
  CosimField f[COSIM_NFIELD];
  const int nf = cosimFields(&d->cosim, f);
  for (int i = 0; i < nf; i++) {
    memcpy(f[i].p, x, (size_t)f[i].n * sizeof(double));
    x += f[i].n;
  }
}


void cs_couplingSupportInertia(const csData* d, const double R[9], double* mass,
                               double Iw[9]) {
  dMass ms;
  dBodyGetMass(d->robot->support, &ms);
  double Ib[9], RI[9], RT[9];
  for (int a = 0; a < 3; a++) {
    for (int b = 0; b < 3; b++) {
      Ib[3 * a + b] = ms.I[4 * a + b]; /* dMatrix3 rows are 4 wide */
    }
  }
  csu_mulMat3(RI, R, Ib);
  csu_transpose3(RT, R);
  csu_mulMat3(Iw, RI, RT);
  *mass = ms.mass;
}


/* The implicit part of the support's step, A = h Kc + Cc, kept passive. The step solves
 * (M + h A) q' = ... (cs_couplingApply), which has one bounded solution for any twist when the
 * symmetric part of A is positive semi-definite (then x^T (M + h A) x >= x^T M x > 0). A leg's
 * condensed gains are not always so: they come from its Newton matrix, and a loaded leg near
 * its sway-buckling load, or a foot between stick and slip, can give a direction of negative
 * stiffness and damping. The obstacle gait on the full table (rbf-pair) met one at
 * t = 59.54 s: leg D's gains had eigenvalues -6.3 N/mm and -0.13 N s/mm against +0.1..+1.1 and
 * +0.002..+0.02 for every other leg, M + h A became singular (condition 1.4e7) and the
 * support's step returned 9.5 N m of torque from 0.55 N of legs' wrench. So the symmetric part
 * is projected onto the positive semi-definite matrices in the support's inertia metric
 * (B = M^-1/2 sym(A) M^-1/2 with its negative eigenvalues set to 0; the antisymmetric part,
 * which does no work, is kept): in that direction the legs' wrench acts explicitly (W0 and
 * Kc dq are applied as they are), and where A is passive the step is unchanged to the bit.
 * Where it projected on the obstacle scene, M + h A itself was indefinite; the flat road at the
 * default tolerances needed none (docs/notes/code_measurements.md "Projection of the legs'
 * gains"). Returns 1 when it projected. */
/* the symmetric part of a 6 x 6 matrix is positive definite: its Cholesky factorisation has
 * positive pivots throughout (whether a matrix is definite does not depend on the metric) */
static int symPositiveDefinite6(const double A[36]) {
  double L[36];
  for (int i = 0; i < 6; i++) {
    for (int k = 0; k <= i; k++) {
      double s = 0.5 * (A[6 * i + k] + A[6 * k + i]);
      for (int e = 0; e < k; e++) {
        s -= L[6 * i + e] * L[6 * k + e];
      }
      if (k == i) {
        if (!(s > 0)) {
          return 0;
        }
        L[6 * i + i] = sqrt(s);
      } else {
        L[6 * i + k] = s / L[6 * k + k];
      }
    }
  }
  return 1;
}


static int implicitPart(const csData* d, const double R[9], double h, const double Kc[36],
                        const double Cc[36], double A[36]) {
  for (int i = 0; i < 36; i++) {
    A[i] = h * Kc[i] + Cc[i];
  }
  /* the usual case, decided by one Cholesky instead of the two eigen decompositions below
   * (those were 1.9 % of the 9 s flat road at --rod-tol 20) */
  if (symPositiveDefinite6(A)) {
    return 0;
  }
  double mass, Iw[9], lam[3], U[9];
  cs_couplingSupportInertia(d, R, &mass, Iw);
  csu_symEigen3(Iw, lam, U);
  if (!(mass > 0) || !(lam[0] > 0) || !(lam[1] > 0) || !(lam[2] > 0)) {
    return 0; /* no inertia metric (cannot happen: ODE refuses such masses) */
  }
  /* T = M^-1/2 and Ti = M^1/2, block diagonal (translation, rotation) */
  double T[36], Ti[36];
  mat6Zero(T);
  mat6Zero(Ti);
  for (int a = 0; a < 3; a++) {
    T[7 * a] = 1 / sqrt(mass);
    Ti[7 * a] = sqrt(mass);
    for (int b = 0; b < 3; b++) {
      double s = 0, si = 0;
      for (int k = 0; k < 3; k++) {
        s += U[3 * a + k] * U[3 * b + k] / sqrt(lam[k]);
        si += U[3 * a + k] * U[3 * b + k] * sqrt(lam[k]);
      }
      T[6 * (3 + a) + 3 + b] = s;
      Ti[6 * (3 + a) + 3 + b] = si;
    }
  }
  double Sy[36], B[36], tmp[36], w[6], V[36];
  for (int i = 0; i < 6; i++) {
    for (int k = 0; k < 6; k++) {
      Sy[6 * i + k] = 0.5 * (A[6 * i + k] + A[6 * k + i]);
    }
  }
  mat6Mul(tmp, T, Sy);
  mat6Mul(B, tmp, T);
  csu_symEigenN(6, B, w, V);
  int negative = 0;
  for (int i = 0; i < 6; i++) {
    negative |= w[i] < 0;
  }
  if (!negative) {
    return 0;
  }
  /* B+ = V diag(max(w, 0)) V^T, sym(A) = M^1/2 B+ M^1/2, plus the antisymmetric part */
  for (int i = 0; i < 6; i++) {
    for (int k = 0; k < 6; k++) {
      double s = 0;
      for (int e = 0; e < 6; e++) {
        s += V[6 * i + e] * fmax(w[e], 0) * V[6 * k + e];
      }
      B[6 * i + k] = s;
    }
  }
  mat6Mul(tmp, Ti, B);
  mat6Mul(Sy, tmp, Ti);
  for (int i = 0; i < 6; i++) {
    for (int k = 0; k < 6; k++) {
      const double skew = 0.5 * (A[6 * i + k] - A[6 * k + i]);
      tmp[6 * i + k] = Sy[6 * i + k] + skew;
    }
  }
  memcpy(A, tmp, sizeof tmp);
  return 1;
}


int cs_couplingCheckFinite(const csData* d, int k, const csrWrench* w, const double* K,
                           const double* C, csError* err) {
  int finite = 1;
  for (int i = 0; i < 3; i++) {
    finite &= isfinite(w->f[i]) && isfinite(w->m[i]);
  }
  for (int i = 0; K && i < 36; i++) {
    finite &= isfinite(K[i]) && isfinite(C[i]);
  }
  if (finite) {
    return 0;
  }
  /* a leg that hands back NaN has left its valid range: a smaller step may keep it in */
  cs_errorSet(err, CS_ERR_REJECTED, "t = %.4f s: leg %c returned a non-finite wrench or "
              "interface gain", d->t, 'A' + k);
  return 1;
}


int cs_couplingAdvance(const csModel* m, csData* d, double H, csError* err) {
  csCosim* c = &d->cosim;
  const csrLegType* type = m->robot.leg_type;
  const int stab = m->opt.coupling == CS_COUPLING_STABILISED ||
                   (m->opt.coupling == CS_COUPLING_GAUSS_SEIDEL && !cs_couplingGS(m, d));
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
  double Cc[36];
  mat6Zero(c->Kc);
  mat6Zero(Cc);
  for (int k = 0; k < CSR_NLEG; k++) {
    csrLeg* leg = d->robot->legs[k];
    csr_robotBaseStateAt(d->robot, k, c->P0, c->R0, c->v0, c->w0, &c->b0[k]);
    csr_robotBaseStateAt(d->robot, k, P1, R1, c->v0, c->w0, &c->b1[k]);
    int rc = type->advance(leg, d->t, H, &c->b0[k], &c->b1[k], &c->w[k], err);
    if (rc != 0) {
      return rc;
    }
    if (stab) {
      /* the gains at the end of the advance, over one ODE step (robot_leg.h) */
      type->interfaceGains(leg, c->K[k], c->C[k]);
    }
    if (cs_couplingCheckFinite(d, k, &c->w[k], stab ? c->K[k] : NULL, c->C[k], err) != 0) {
      return 1;
    }
    if (stab) {
      double r[3];
      csu_sub3(r, c->b0[k].x, c->P0);
      cs_couplingAddAtCentre(c->Kc, c->K[k], r);
      cs_couplingAddAtCentre(Cc, c->C[k], r);
    }
  }
  d->ngain_proj += implicitPart(d, c->R0, m->opt.h, c->Kc, Cc, c->A);
  return 0;
}


int cs_couplingGS(const csModel* m, const csData* d) {
  return m->opt.coupling == CS_COUPLING_GAUSS_SEIDEL && d->cosim.gs_primed == 1;
}


void cs_couplingPrime(const csModel* m, csData* d) {
  csCosim* c = &d->cosim;
  (void)m;
  memcpy(c->gs_P, c->Pm, sizeof c->gs_P);
  memcpy(c->gs_R, c->Rm, sizeof c->gs_R);
  memcpy(c->gs_qd, c->v0, sizeof c->v0);
  memcpy(c->gs_qd + 3, c->w0, sizeof c->w0);
  memcpy(c->gs_qd_prev, c->gs_qd, sizeof c->gs_qd);
  memset(c->carry, 0, sizeof c->carry);
  c->gs_primed = 1;
}


void cs_couplingBegin(const csModel* m, csData* d) {
  csCosim* c = &d->cosim;
  (void)m;
  csr_robotSupportPose(d->robot, c->P0, c->R0, c->v0, c->w0);
  c->t0 = d->t;
  memset(c->sum_P, 0, sizeof c->sum_P);
  memset(c->sum_phi, 0, sizeof c->sum_phi);
  memset(c->sum_qd, 0, sizeof c->sum_qd);
  memset(c->sum_F, 0, sizeof c->sum_F);
}


int cs_couplingAdvanceGS(const csModel* m, csData* d, double H, csError* err) {
  csCosim* c = &d->cosim;
  const csrLegType* type = m->robot.leg_type;
  const int n = m->opt.macro_steps;
  double P1[3], R1[9], v1[3], w1[3];
  cs_errorClear(err);
  /* the support where its step ended: the legs' b1, and the next step's b0 bit for bit */
  csr_robotSupportPose(d->robot, P1, R1, v1, w1);
  double Cc[36], Wc[6] = {0, 0, 0, 0, 0, 0};
  mat6Zero(c->Kc);
  mat6Zero(Cc);
  for (int k = 0; k < CSR_NLEG; k++) {
    csrLeg* leg = d->robot->legs[k];
    csr_robotBaseStateAt(d->robot, k, c->P0, c->R0, c->v0, c->w0, &c->b0[k]);
    csr_robotBaseStateAt(d->robot, k, P1, R1, v1, w1, &c->b1[k]);
    int rc = type->advance(leg, c->t0, H, &c->b0[k], &c->b1[k], &c->w[k], err);
    if (rc != 0) {
      return rc;
    }
    type->interfaceGains(leg, c->K[k], c->C[k]);
    if (cs_couplingCheckFinite(d, k, &c->w[k], c->K[k], c->C[k], err) != 0) {
      return 1;
    }
    /* at the centre where the next step starts (its ODE steps move the hips from here) */
    double r[3], rxf[3];
    csu_sub3(r, c->b1[k].x, P1);
    cs_couplingAddAtCentre(c->Kc, c->K[k], r);
    cs_couplingAddAtCentre(Cc, c->C[k], r);
    csu_cross3(rxf, r, c->w[k].f);
    for (int i = 0; i < 3; i++) {
      Wc[i] += c->w[k].f[i];
      Wc[3 + i] += c->w[k].m[i] + rxf[i];
    }
  }
  d->ngain_proj += implicitPart(d, R1, m->opt.h, c->Kc, Cc, c->A);
  /* where these wrenches hold: the mean start pose of this step's ODE steps and their mean end
   * twist (the ODE step j's force is taken at its end pose q_j + h q'_{j+1}, so the mean end
   * pose of the step is gs_P + h gs_qd; cs_couplingApply) */
  double phi[3], dR[9];
  memcpy(c->gs_qd_prev, c->gs_qd, sizeof c->gs_qd);
  for (int i = 0; i < 3; i++) {
    c->gs_P[i] = c->sum_P[i] / n;
    phi[i] = c->sum_phi[i] / n;
    c->gs_qd[i] = (c->sum_qd[i] + v1[i]) / n;
    c->gs_qd[3 + i] = (c->sum_qd[3 + i] + w1[i]) / n;
  }
  csu_rotVecToMat3(dR, phi);
  csu_mulMat3(c->gs_R, dR, c->R0);
  /* the legs' impulse (over H) the support has not been given yet: the last carry, paid into
   * this step's force, plus the legs' actual wrench less the force applied. The support's
   * impulse up to step k is then the legs' less H carry_k: a bounded, not a growing, error */
  for (int i = 0; i < 6; i++) {
    c->carry[i] = m->opt.coupling_carry ? c->carry[i] + Wc[i] - c->sum_F[i] / n : 0;
  }
  return 0;
}


void cs_couplingApply(const csModel* m, csData* d, int j) {
  csCosim* c = &d->cosim;
  const int gs = cs_couplingGS(m, d);
  if (m->opt.coupling == CS_COUPLING_STAGGERED) {
    for (int k = 0; k < CSR_NLEG; k++) {
      csr_robotApplyWrench(d->robot, k, &c->w[k]);
    }
    return;
  }
  /* the support now: pose, twist, mass and world inertia */
  double P[3], R[9], v[3], w[3], dR[9], RmT[9];
  csr_robotSupportPose(d->robot, P, R, v, w);
  double mass, Iw[9];
  cs_couplingSupportInertia(d, R, &mass, Iw);
  /* W0: the legs' step-averaged wrenches at the centre (moments about it, hips where they are
   * now, as csr_robotApplyWrench applies them) */
  double W0[6] = {0, 0, 0, 0, 0, 0};
  for (int k = 0; k < CSR_NLEG; k++) {
    csrBaseState b;
    double r[3], rxf[3];
    csr_robotBaseStateAt(d->robot, k, P, R, v, w, &b);
    csu_sub3(r, b.x, P);
    csu_cross3(rxf, r, c->w[k].f);
    for (int i = 0; i < 3; i++) {
      W0[i] += c->w[k].f[i];
      W0[3 + i] += c->w[k].m[i] + rxf[i];
    }
  }
  /* deviation of the support at the start of ODE step j from the point where W0 holds:
   * stabilised, the predicted mean pose and twist; Gauss-Seidel, the mean start pose and end
   * twist of the last macro step's ODE steps, the motion that gave W0 (and the impulse the
   * support was not given in it joins W0) */
  const double* Pref = gs ? c->gs_P : c->Pm;
  const double* Rref = gs ? c->gs_R : c->Rm;
  csu_transpose3(RmT, Rref);
  csu_mulMat3(dR, R, RmT);
  double dq[6], qd[6], qd_pred[6];
  for (int i = 0; i < 3; i++) {
    dq[i] = P[i] - Pref[i];
    qd[i] = v[i];
    qd[3 + i] = w[i];
    qd_pred[i] = gs ? c->gs_qd[i] : c->v0[i];
    qd_pred[3 + i] = gs ? c->gs_qd[3 + i] : c->w0[i];
  }
  if (gs) {
    /* the twist W0 holds at is the last step's continued at its acceleration (see top) */
    for (int i = 0; i < 6; i++) {
      qd_pred[i] += c->gs_qd[i] - c->gs_qd_prev[i];
    }
  }
  csu_mat3ToRotVec(dq + 3, dR);
  if (gs) {
    for (int i = 0; i < 6; i++) {
      W0[i] += c->carry[i];
    }
    /* this step's sums for the next linearisation point (cs_couplingAdvanceGS) */
    double R0T[9], dR0[9], phi[3];
    csu_transpose3(R0T, c->R0);
    csu_mulMat3(dR0, R, R0T);
    csu_mat3ToRotVec(phi, dR0);
    for (int i = 0; i < 3; i++) {
      c->sum_P[i] += P[i];
      c->sum_phi[i] += phi[i];
    }
    for (int i = 0; j > 0 && i < 6; i++) {
      c->sum_qd[i] += qd[i];
    }
  }
  double Kdq[6], F[6];
  mat6Vec(Kdq, c->Kc, dq);
  (void)cs_couplingSupportSolve(d, m->opt.h, mass, Iw, qd, W0, Kdq, c->A, qd_pred, F, NULL);
  if (gs) {
    for (int i = 0; i < 6; i++) {
      c->sum_F[i] += F[i];
    }
  }
  dBodyAddForce(d->robot->support, F[0], F[1], F[2]);
  dBodyAddTorque(d->robot->support, F[3], F[4], F[5]);
}


int cs_couplingSupportSolve(const csData* d, double h, double mass, const double Iw[9],
                            const double qd[6], const double W0[6], const double Kdq[6],
                            const double A[36], const double qd_pred[6], double F[6],
                            double qd1[6]) {
  /* the support's backward-Euler step with the legs' linearised wrench (header):
   *   (M + h A) q'_{j+1} = M q'_j + h (m g + W0 - Kc dq_j + A q'_pred) */
  dVector3 grav;
  dWorldGetGravity(d->world, grav);
  const int gmode = dBodyGetGravityMode(d->robot->support);
  double Aqp[6], rhs[6], S[36];
  mat6Vec(Aqp, A, qd_pred);
  for (int i = 0; i < 6; i++) {
    double Mq;
    if (i < 3) {
      Mq = mass * qd[i];
    } else {
      const double* I = Iw + 3 * (i - 3);
      Mq = I[0] * qd[3] + I[1] * qd[4] + I[2] * qd[5];
    }
    double fg = (i < 3 && gmode) ? mass * grav[i] : 0;
    rhs[i] = Mq + h * (fg + W0[i] - Kdq[i] + Aqp[i]);
    for (int k = 0; k < 6; k++) {
      double Mik = 0;
      if (i < 3 && k < 3) {
        Mik = i == k ? mass : 0;
      } else if (i >= 3 && k >= 3) {
        Mik = Iw[3 * (i - 3) + (k - 3)];
      }
      S[6 * i + k] = Mik + h * A[6 * i + k];
    }
  }
  if (csu_solve6(S, rhs) != 0) {
    /* singular (cannot happen with a positive mass): the legs' wrench as staggered */
    memcpy(F, W0, 6 * sizeof(double));
    return 1;
  }
  if (qd1) {
    memcpy(qd1, rhs, 6 * sizeof(double));
  }
  /* F = W0 - Kc dq - A (q'_{j+1} - q'_pred) at the solved q'_{j+1} */
  double dqd[6], Ad[6];
  for (int i = 0; i < 6; i++) {
    dqd[i] = rhs[i] - qd_pred[i];
  }
  mat6Vec(Ad, A, dqd);
  for (int i = 0; i < 6; i++) {
    F[i] = W0[i] - Kdq[i] - Ad[i];
  }
  return 0;
}

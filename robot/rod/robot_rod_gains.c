/* robot_rod_gains.c: the rod leg's interface gains (robot_leg.h, interfaceGains): how its base
 * wrench changes when the hip leaves the motion it was given, instantaneously (the hip
 * element's kernel by central differences in the base's pose and twist) and over one implicit
 * step of the coupling's ODE step (the same condensed through the rod's own implicit step, the
 * Schur complement onto the hip: robot_rod.h, csr_rodInterfaceGainsStep). The coupling schemes
 * that use them are described in core/sim_coupling.c. */
#include <math.h>
#include <string.h>

#include "robot_rod_internal.h"

/* finite-difference steps of the interface gains: mm, rad, mm/s, rad/s (central differences,
 * error ~h² × third derivative: < 1e-8 relative for the hip element's smooth laws) */
#define CSR_ROD_GAIN_DX 1e-6
#define CSR_ROD_GAIN_DPHI 1e-7
#define CSR_ROD_GAIN_DV 1e-4
#define CSR_ROD_GAIN_DW 1e-5


/* element 1's accelerations (v̇ 3, ω̇ 3 body) from the hip element's kernel in d->wk (its
 * forces on node 1 and frame 1; the parts of elements 2.. do not depend on the base and cancel
 * in differences) */
static void hipAccel(const csrRodModel* m, const csrRodData* d, double a[6]) {
  const double* J = m->Jel + 3;
  for (int k = 0; k < 3; k++) {
    a[k] = d->wk.F[3 + k] / m->mnode[1];
    a[3 + k] = d->wk.T[3 + k] / J[k];
  }
}


/* the instantaneous gains K, C and, when P is not NULL, P (6 x 12, row-major): element 1's
 * accelerations by the base's (x, φ, v, ω) (world), all by central differences of the hip
 * element's kernel */
static void baseDifferences(const csrRodModel* m, csrRodData* d, double K[36], double C[36],
                            double* P) {
  const csrBaseState keep = d->cur_base;
  const double h[4] = {CSR_ROD_GAIN_DX, CSR_ROD_GAIN_DPHI, CSR_ROD_GAIN_DV, CSR_ROD_GAIN_DW};
  memset(K, 0, 36 * sizeof(double));
  memset(C, 0, 36 * sizeof(double));
  /* central differences of the instantaneous wrench in each of the 12 base coordinates */
  for (int kind = 0; kind < 4; kind++) {
    for (int j = 0; j < 3; j++) {
      double W[2][6], acc[2][6];
      for (int side = 0; side < 2; side++) {
        double sg = side ? -1.0 : 1.0;
        csrBaseState b = keep;
        if (kind == 0) {
          b.x[j] += sg * h[0];
        } else if (kind == 1) {
          double ax[3] = {0, 0, 0}, dR[9];
          ax[j] = 1;
          csu_axisAngleToMat3(dR, ax, sg * h[1]);
          csu_mulMat3(b.R, dR, keep.R);
        } else if (kind == 2) {
          b.v[j] += sg * h[2];
        } else {
          b.w[j] += sg * h[3];
        }
        d->cur_base = b;
        csrWrench w;
        csr_rodBaseWrench(m, d, &w);
        memcpy(W[side], w.f, 3 * sizeof(double));
        memcpy(W[side] + 3, w.m, 3 * sizeof(double));
        hipAccel(m, d, acc[side]);
      }
      double* M = kind < 2 ? K : C;
      int col = 3 * (kind % 2) + j;
      for (int i = 0; i < 6; i++) {
        M[6 * i + col] = -(W[0][i] - W[1][i]) / (2 * h[kind]);
        if (P) {
          P[12 * i + 3 * kind + j] = (acc[0][i] - acc[1][i]) / (2 * h[kind]);
        }
      }
    }
  }
  d->cur_base = keep;
}


void csr_rodInterfaceGains(const csrRodModel* m, csrRodData* d, double K[36], double C[36]) {
  baseDifferences(m, d, K, C, NULL);
}


/* G (6 x 12, row-major): the base wrench by element 1's (x, ψ body, v, ω body), central
 * differences of the hip element's kernel with the state's block 1 perturbed and restored */
static void stateDifferences(const csrRodModel* m, csrRodData* d, double* G) {
  double* b = d->y + CSR_ROD_NIMP + m->boff[1];
  double keep[CSR_ROD_BH];
  memcpy(keep, b, sizeof keep);
  const double h[4] = {CSR_ROD_GAIN_DX, CSR_ROD_GAIN_DPHI, CSR_ROD_GAIN_DV, CSR_ROD_GAIN_DW};
  for (int kind = 0; kind < 4; kind++) {
    for (int j = 0; j < 3; j++) {
      double W[2][6];
      for (int side = 0; side < 2; side++) {
        double sg = side ? -1.0 : 1.0;
        memcpy(b, keep, sizeof keep);
        if (kind == 0) {
          b[CSR_ROD_BX + j] += sg * h[0];
        } else if (kind == 1) {
          /* a body-frame increment, as the Jacobian's ψ columns (q ⊗ exp(ψ)) */
          double phi[3] = {0, 0, 0}, dq[4], q[4];
          phi[j] = sg * h[1];
          csr_rodQexp(dq, phi);
          csr_rodQmul(q, keep + CSR_ROD_BQ, dq);
          memcpy(b + CSR_ROD_BQ, q, sizeof q);
        } else if (kind == 2) {
          b[CSR_ROD_BV + j] += sg * h[2];
        } else {
          b[CSR_ROD_BW + j] += sg * h[3];
        }
        csrWrench w;
        csr_rodBaseWrench(m, d, &w);
        memcpy(W[side], w.f, 3 * sizeof(double));
        memcpy(W[side] + 3, w.m, 3 * sizeof(double));
      }
      for (int i = 0; i < 6; i++) {
        G[12 * i + 3 * kind + j] = (W[0][i] - W[1][i]) / (2 * h[kind]);
      }
    }
  }
  memcpy(b, keep, sizeof keep);
}


void csr_rodInterfaceGainsStep(const csrRodModel* m, csrRodData* d, double g, double K[36],
                               double C[36]) {
  /* the condensed gains change with the Jacobian: while CVODE keeps its Jacobian, so do they
   * (the flat road: CVODE refreshes it every ~5 macro steps of 1 ms; the gains' differences and
   * solve were a fifth of a leg's cost) */
  if (g > 0 && d->ls_have_jac && d->gain_valid && d->gain_version == d->jac_version &&
      d->gain_g == g) {
    memcpy(K, d->gain_K, sizeof d->gain_K);
    memcpy(C, d->gain_C, sizeof d->gain_C);
    return;
  }
  double P[72], G[72];
  baseDifferences(m, d, K, C, g > 0 ? P : NULL);
  if (!(g > 0) || !d->ls_have_jac) {
    return; /* no step, or no Jacobian yet: the instantaneous gains */
  }
  stateDifferences(m, d, G);
  /* right-hand sides of element 1 for a unit base displacement (columns 0..5) and velocity
   * (6..11) at the step's end: g P (the implicit step's load on element 1) */
  double rhs[6 * CSR_ROD_GAIN_COLS], du[6 * CSR_ROD_GAIN_COLS];
  for (int c = 0; c < 12; c++) {
    for (int r = 0; r < 6; r++) {
      rhs[6 * c + r] = g * P[12 * r + c];
    }
  }
  if (csr_rodCondensedHip_(d, g, rhs, 12, du) != 0) {
    return;
  }
  /* the wrench's change through element 1's motion (δx = g δv, δψ = g W δω):
   * D = [G_v + g G_x, G_ω + g G_ψ W] (6 x 6 on (δv, δω)) */
  double Wk[9], D[36];
  csr_rodKinW_(d, g, 1, Wk);
  for (int i = 0; i < 6; i++) {
    const double* Gi = G + 12 * i;
    for (int c = 0; c < 3; c++) {
      D[6 * i + c] = Gi[6 + c] + g * Gi[c];
      double s = 0;
      for (int k = 0; k < 3; k++) {
        s += Gi[3 + k] * Wk[3 * k + c];
      }
      D[6 * i + 3 + c] = Gi[9 + c] + g * s;
    }
  }
  /* K_eff = K - D δu(δX), C_eff = C - D δu(δV) */
  for (int i = 0; i < 6; i++) {
    for (int c = 0; c < 6; c++) {
      double sx = 0, sv = 0;
      for (int k = 0; k < 6; k++) {
        sx += D[6 * i + k] * du[6 * c + k];
        sv += D[6 * i + k] * du[6 * (6 + c) + k];
      }
      K[6 * i + c] -= sx;
      C[6 * i + c] -= sv;
    }
  }
  memcpy(d->gain_K, K, sizeof d->gain_K);
  memcpy(d->gain_C, C, sizeof d->gain_C);
  d->gain_version = d->jac_version;
  d->gain_g = g;
  d->gain_valid = 1;
}

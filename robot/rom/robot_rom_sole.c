/* robot_rom_sole.c: the rom leg's sole in contact (robot_rom.h csr_romModelSetSole,
 * csr_romSoleLoad): the sole's pose affine in q (centroid and least-squares rotation of its
 * nodes), the foot of contact_soft.h on that pose, and its load back onto q by the same
 * operators (virtual work), and its derivatives (csr_romSoleJacobian: the law's by central
 * differences in the foot's twelve coordinates and its history, the pose's analytic). The
 * integration (robot_rom.c) adds the load to the right-hand side and its derivatives to the
 * Jacobian. The law's own analytic derivatives (contact_soft_jac.c) cover a step-mode foot of
 * sole points only, not this integrated patch foot. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "fem_mesh.h"
#include "robot_rom.h"

/* inverse of a symmetric positive definite 3 x 3 by cofactors; 0, or -1 when singular */
static int inverse3(const double A[9], double B[9]) {
  const double c00 = A[4] * A[8] - A[5] * A[7], c01 = A[5] * A[6] - A[3] * A[8],
               c02 = A[3] * A[7] - A[4] * A[6];
  const double det = A[0] * c00 + A[1] * c01 + A[2] * c02;
  const double scale = fabs(A[0]) + fabs(A[4]) + fabs(A[8]);
  if (!(fabs(det) > 1e-12 * scale * scale * scale)) {
    return -1;
  }
  B[0] = c00 / det;
  B[1] = (A[2] * A[7] - A[1] * A[8]) / det;
  B[2] = (A[1] * A[5] - A[2] * A[4]) / det;
  B[3] = c01 / det;
  B[4] = (A[0] * A[8] - A[2] * A[6]) / det;
  B[5] = (A[2] * A[3] - A[0] * A[5]) / det;
  B[6] = c02 / det;
  B[7] = (A[1] * A[6] - A[0] * A[7]) / det;
  B[8] = (A[0] * A[4] - A[1] * A[3]) / det;
  return 0;
}


csStatus csr_romModelSetSole(csrRomModel* m, const cscSoftModel* contact, int nsole,
                             const int* sole, const double Rs0[9], csError* err) {
  if (!m || !contact || !sole || !Rs0) {
    cs_errorSet(err, CS_ERR_ARG, "rom sole: need a model, a contact model, nodes and a frame");
    return CS_ERR_ARG;
  }
  if (csc_softNShape(contact) != 1 ||
      csc_softParams(contact)->history != CSC_HISTORY_INTEGRATED) {
    cs_errorSet(err, CS_ERR_ARG, "rom sole: the contact model must hold one foot with an "
                                 "integrated history");
    return CS_ERR_ARG;
  }
  const csfMesh* me = m->rom->fem->mesh;
  const int n = m->n;
  if (nsole < 3) {
    cs_errorSet(err, CS_ERR_RANGE, "rom sole: %d nodes, need at least 3", nsole);
    return CS_ERR_RANGE;
  }
  for (int a = 0; a < nsole; a++) {
    if (sole[a] < 0 || sole[a] >= me->nnode) {
      cs_errorSet(err, CS_ERR_RANGE, "rom sole: node %d outside the mesh's %d", sole[a],
                  me->nnode);
      return CS_ERR_RANGE;
    }
  }
  /* the frame must be orthonormal (1e-9) */
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      double dot = 0;
      for (int k = 0; k < 3; k++) {
        dot += Rs0[3 * k + i] * Rs0[3 * k + j];
      }
      if (fabs(dot - (i == j)) > 1e-9) {
        cs_errorSet(err, CS_ERR_RANGE, "rom sole: the sole's frame is not orthonormal");
        return CS_ERR_RANGE;
      }
    }
  }
  double Xs[3] = {0, 0, 0};
  for (int a = 0; a < nsole; a++) {
    for (int i = 0; i < 3; i++) {
      Xs[i] += me->x[3 * (size_t)sole[a] + i] / nsole;
    }
  }
  double J[9] = {0}, Jinv[9];
  for (int a = 0; a < nsole; a++) {
    double r[3];
    csu_sub3(r, me->x + 3 * (size_t)sole[a], Xs);
    const double r2 = csu_dot3(r, r);
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        J[3 * i + j] += (i == j ? r2 : 0.0) - r[i] * r[j];
      }
    }
  }
  if (inverse3(J, Jinv) != 0) {
    cs_errorSet(err, CS_ERR_RANGE, "rom sole: the %d sole nodes lie on a line", nsole);
    return CS_ERR_RANGE;
  }
  double* Us = calloc(3 * (size_t)n, sizeof(double));
  double* Ws = calloc(3 * (size_t)n, sizeof(double));
  if (!Us || !Ws) {
    free(Us), free(Ws);
    cs_errorSet(err, CS_ERR_MEMORY, "rom sole: out of memory");
    return CS_ERR_MEMORY;
  }
  for (int k = 0; k < n; k++) {
    double u[3] = {0, 0, 0}, c[3] = {0, 0, 0};
    for (int a = 0; a < nsole; a++) {
      const size_t node = (size_t)sole[a];
      double v[3], r[3], rv[3];
      for (int i = 0; i < 3; i++) {
        v[i] = m->rom->V[(3 * node + i) * n + k];
      }
      csu_sub3(r, me->x + 3 * node, Xs);
      csu_cross3(rv, r, v);
      for (int i = 0; i < 3; i++) {
        u[i] += v[i] / nsole;
        c[i] += rv[i];
      }
    }
    double th[3];
    csu_mulMatVec3(th, Jinv, c);
    for (int i = 0; i < 3; i++) {
      Us[(size_t)i * n + k] = u[i];
      Ws[(size_t)i * n + k] = th[i];
    }
  }
  free(m->Us), free(m->Ws);
  m->Us = Us;
  m->Ws = Ws;
  m->contact = contact;
  m->nz = csc_softNState(contact);
  m->nsole = nsole;
  memcpy(m->Xs, Xs, sizeof Xs);
  memcpy(m->Rs0, Rs0, 9 * sizeof(double));
  return CS_OK;
}


/* the sole's pose (st) at the hip state and q, q' (robot_rom.h csr_romModelSetSole): centre,
 * frame, their rates; xb the centre and th the rotation vector in the hip frame */
static void solePose(const csrRomModel* m, const double R[9], const double xh[3],
                     const double vh[3], const double w[3], const double* q, const double* qd,
                     cscShapeState* st, double xb[3], double th[3]) {
  const int n = m->n;
  double vb[3], thd[3];
  for (int i = 0; i < 3; i++) {
    const double* U = m->Us + (size_t)i * n;
    const double* W = m->Ws + (size_t)i * n;
    double a = m->Xs[i], b = 0, c = 0, e = 0;
    for (int k = 0; k < n; k++) {
      a += U[k] * q[k];
      b += U[k] * qd[k];
      c += W[k] * q[k];
      e += W[k] * qd[k];
    }
    xb[i] = a, vb[i] = b, th[i] = c, thd[i] = e;
  }
  memset(st, 0, sizeof *st);
  double Rx[3], wx[3], vr[3], Rth[9], Rf[9];
  csu_mulMatVec3(Rx, R, xb);
  csu_add3(st->x0, xh, Rx);
  /* velocity: v_h + R (ω × x̄ + x̄'); angular velocity R (ω + θ') (θ' for exp's tangent: exact
   * to first order in |θ|) */
  csu_cross3(wx, w, xb);
  csu_add3(vr, wx, vb);
  csu_mulMatVec3(Rx, R, vr);
  csu_add3(st->v0, vh, Rx);
  csu_add3(vr, w, thd);
  csu_mulMatVec3(st->w, R, vr);
  csu_rotVecToMat3(Rth, th);
  csu_mulMat3(Rf, R, Rth);
  csu_mulMat3(st->R, Rf, m->Rs0);
}


int csr_romSoleLoad(const csrRomModel* m, const double R[9], const double xh[3],
                    const double vh[3], const double w[3], const double* q, const double* qd,
                    const double* z, double* Fc, double* zdot, cscShapeLoad* load, double x0[3],
                    cscSlotInfo* slot) {
  const int n = m->n;
  cscShapeState st;
  double xb[3], th[3];
  solePose(m, R, xh, vh, w, q, qd, &st, xb, th);
  cscShapeLoad ld;
  const int rc = csc_softCompute(m->contact, &st, z, &ld, zdot, slot, NULL);
  /* back onto q: Ūᵀ Rᵀ f0 + Wᵀ Rᵀ m */
  double fb[3], mb[3];
  csu_mulMatTVec3(fb, R, ld.f0);
  csu_mulMatTVec3(mb, R, ld.m);
  for (int k = 0; k < n; k++) {
    double a = 0;
    for (int i = 0; i < 3; i++) {
      a += m->Us[(size_t)i * n + k] * fb[i] + m->Ws[(size_t)i * n + k] * mb[i];
    }
    Fc[k] = a;
  }
  if (load) {
    *load = ld;
  }
  if (x0) {
    csu_copy3(x0, st.x0);
  }
  return rc;
}


int csr_romSoleWorkSize(const csrRomModel* m) {
  const int nz = m->contact ? m->nz : 0;
  return (6 + nz) * (12 + nz) + 3 * (nz + 1);
}


/* The law's central difference steps in the foot's coordinates: well inside its smoothing
 * lengths (d_onset 1e-3 mm, v_plastic 1e-3 mm/s: the truncation near a C1 seam is ~1e-3 of
 * the derivative), well above the round-off of poses of hundreds of mm and speeds of hundreds
 * of mm/s (1e-7 of the step) */
#define SOLE_DX 1e-6   /* mm */
#define SOLE_DPHI 1e-7 /* rad (1e-6 mm at a 10 mm rim) */
#define SOLE_DV 1e-6   /* mm/s */
#define SOLE_DW 1e-7   /* rad/s */
#define SOLE_DZ 1e-8   /* mm of bristle (rad of the torsional one) */

int csr_romSoleJacobian(const csrRomModel* m, const double R[9], const double xh[3],
                        const double vh[3], const double w[3], const double* q,
                        const double* qd, const double* z, double L[6], double* zdot,
                        double* G, double* work) {
  const int n = m->n, nz = m->nz, nc = 2 * n + nz, nl = 12 + nz, nr = 6 + nz;
  cscShapeState st;
  double xb[3], th[3];
  solePose(m, R, xh, vh, w, q, qd, &st, xb, th);
  cscShapeLoad ld;
  int rc = csc_softCompute(m->contact, &st, z, &ld, zdot, NULL, NULL);
  if (rc != 0) {
    return rc;
  }
  csu_copy3(L, ld.f0);
  csu_copy3(L + 3, ld.m);
  /* the law's derivatives in the foot's coordinates y = (x0, φ, v0, ω_f) and in z, by central
   * differences: Dl ((6 + nz) x (12 + nz)), rows (f0, m, z'); φ turns R_f about the world axes */
  double* Dl = work;
  double* zp = work + (size_t)nr * nl;
  double* zm = zp + nz + 1;
  double* zz = zm + nz + 1; /* z, one entry moved at a time */
  memcpy(zz, z, (size_t)nz * sizeof(double));
  for (int c = 0; c < nl; c++) {
    double f[2][6];
    double hstep = 0;
    for (int side = 0; side < 2; side++) {
      const double sg = side ? -1.0 : 1.0;
      cscShapeState sp = st;
      if (c < 3) {
        hstep = SOLE_DX;
        sp.x0[c] += sg * hstep;
      } else if (c < 6) {
        hstep = SOLE_DPHI;
        double ph[3] = {0, 0, 0}, dR[9];
        ph[c - 3] = sg * hstep;
        csu_rotVecToMat3(dR, ph);
        csu_mulMat3(sp.R, dR, st.R);
      } else if (c < 9) {
        hstep = SOLE_DV;
        sp.v0[c - 6] += sg * hstep;
      } else if (c < 12) {
        hstep = SOLE_DW;
        sp.w[c - 9] += sg * hstep;
      } else {
        hstep = SOLE_DZ;
        zz[c - 12] = z[c - 12] + sg * hstep;
      }
      cscShapeLoad lp;
      rc = csc_softCompute(m->contact, &sp, zz, &lp, side ? zm : zp, NULL, NULL);
      if (c >= 12) {
        zz[c - 12] = z[c - 12];
      }
      if (rc != 0) {
        return rc;
      }
      csu_copy3(f[side], lp.f0);
      csu_copy3(f[side] + 3, lp.m);
    }
    for (int r = 0; r < 6; r++) {
      Dl[(size_t)r * nl + c] = (f[0][r] - f[1][r]) / (2 * hstep);
    }
    for (int i = 0; i < nz; i++) {
      Dl[(size_t)(6 + i) * nl + c] = (zp[i] - zm[i]) / (2 * hstep);
    }
  }
  /* the foot's coordinates in (q, q'), analytic (solePose): x0 = x_h + R (X̄ + Ū q),
   * R_f = R exp(θ) Rs0 with θ = W q, so δφ = R J_l(θ) W δq (J_l the left Jacobian of SO(3):
   * exp(θ + δθ) = exp(J_l δθ) exp(θ)), v0 = v_h + R (ω × x̄ + Ū q'), ω_f = R (ω + W q') */
  double Jl[9];
  {
    const double t2 = csu_dot3(th, th), t = sqrt(t2);
    double a, b; /* (1 - cos t) / t², (t - sin t) / t³, by their series below 1e-4 */
    if (t < 1e-4) {
      a = 0.5 - t2 / 24, b = 1.0 / 6 - t2 / 120;
    } else {
      a = (1 - cos(t)) / t2, b = (t - sin(t)) / (t2 * t);
    }
    const double S[9] = {0, -th[2], th[1], th[2], 0, -th[0], -th[1], th[0], 0};
    double S2[9];
    csu_mulMat3(S2, S, S);
    for (int i = 0; i < 9; i++) {
      Jl[i] = (i % 4 == 0 ? 1.0 : 0.0) + a * S[i] + b * S2[i];
    }
  }
  double RJ[9];
  csu_mulMat3(RJ, R, Jl);
  for (int k = 0; k < n; k++) {
    double u[3], wv[3], dx[3], dphi[3], dv[3], wu[3], dvd[3], dwd[3];
    for (int i = 0; i < 3; i++) {
      u[i] = m->Us[(size_t)i * n + k];
      wv[i] = m->Ws[(size_t)i * n + k];
    }
    csu_mulMatVec3(dx, R, u);
    csu_mulMatVec3(dphi, RJ, wv);
    csu_cross3(wu, w, u);
    csu_mulMatVec3(dv, R, wu);
    csu_mulMatVec3(dvd, R, u);
    csu_mulMatVec3(dwd, R, wv);
    for (int r = 0; r < nr; r++) {
      const double* D = Dl + (size_t)r * nl;
      double gq = 0, gqd = 0;
      for (int i = 0; i < 3; i++) {
        gq += D[i] * dx[i] + D[3 + i] * dphi[i] + D[6 + i] * dv[i];
        gqd += D[6 + i] * dvd[i] + D[9 + i] * dwd[i];
      }
      G[(size_t)r * nc + k] = gq;
      G[(size_t)r * nc + n + k] = gqd;
    }
  }
  for (int r = 0; r < nr; r++) {
    for (int j = 0; j < nz; j++) {
      G[(size_t)r * nc + 2 * n + j] = Dl[(size_t)r * nl + 12 + j];
    }
  }
  return 0;
}

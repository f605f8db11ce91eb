/* robot_rom_sole.c: the rom leg's sole in contact (robot_rom.h csr_romModelSetSole,
 * csr_romSoleLoad): the sole's pose affine in q (centroid and least-squares rotation of its
 * nodes), the foot of contact_soft.h on that pose, and its load back onto q by the same
 * operators (virtual work). The integration (robot_rom.c) adds the load to the right-hand side
 * and its derivatives, by differences of this cheap function, to the Jacobian. */
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


int csr_romSoleLoad(const csrRomModel* m, const double R[9], const double xh[3],
                    const double vh[3], const double w[3], const double* q, const double* qd,
                    const double* z, double* Fc, double* zdot, cscShapeLoad* load, double x0[3],
                    cscSlotInfo* slot) {
  const int n = m->n;
  /* hip-frame centre, its rate, the rotation vector and its rate */
  double xb[3], vb[3], th[3], thd[3];
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
  cscShapeState st;
  memset(&st, 0, sizeof st);
  double Rx[3], wx[3], vr[3], Rth[9], Rf[9];
  csu_mulMatVec3(Rx, R, xb);
  csu_add3(st.x0, xh, Rx);
  /* velocity: v_h + R (ω × x̄ + x̄'); angular velocity R (ω + θ') (θ' for exp's tangent: exact
   * to first order in |θ|) */
  csu_cross3(wx, w, xb);
  csu_add3(vr, wx, vb);
  csu_mulMatVec3(Rx, R, vr);
  csu_add3(st.v0, vh, Rx);
  csu_add3(vr, w, thd);
  csu_mulMatVec3(st.w, R, vr);
  csu_rotVecToMat3(Rth, th);
  csu_mulMat3(Rf, R, Rth);
  csu_mulMat3(st.R, Rf, m->Rs0);
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

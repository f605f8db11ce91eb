/* core_math.h: small fixed-size math used everywhere (vec3, quat, mat3), header-only.
 *
 * Owns: csReal (the one scalar type, equal to ODE's dReal and SUNDIALS' sunrealtype, asserted
 * where those headers are included), vec3 as csReal[3], quaternions as csReal[4] = (w, x, y, z),
 * row-major mat3 as csReal[9], rotation vectors, and the spring-damper -> ODE ERP/CFM mapping
 * (csu_springErpCfm, pure math). Functions allow aliasing of output and input unless noted. */
#ifndef CS_CORE_MATH_H
#define CS_CORE_MATH_H

#include <math.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef double csReal;

#define CS_PI 3.14159265358979323846
#define CS_DEG (CS_PI / 180.0) /* radians per degree */

static inline void csu_set3(csReal r[3], csReal x, csReal y, csReal z) {
  r[0] = x;
  r[1] = y;
  r[2] = z;
}
static inline void csu_copy3(csReal r[3], const csReal a[3]) {
  r[0] = a[0];
  r[1] = a[1];
  r[2] = a[2];
}
static inline void csu_add3(csReal r[3], const csReal a[3], const csReal b[3]) {
  r[0] = a[0] + b[0];
  r[1] = a[1] + b[1];
  r[2] = a[2] + b[2];
}
static inline void csu_sub3(csReal r[3], const csReal a[3], const csReal b[3]) {
  r[0] = a[0] - b[0];
  r[1] = a[1] - b[1];
  r[2] = a[2] - b[2];
}
static inline void csu_scale3(csReal r[3], const csReal a[3], csReal s) {
  r[0] = a[0] * s;
  r[1] = a[1] * s;
  r[2] = a[2] * s;
}
/* r = a + s*b */
static inline void csu_addScl3(csReal r[3], const csReal a[3], const csReal b[3], csReal s) {
  r[0] = a[0] + s * b[0];
  r[1] = a[1] + s * b[1];
  r[2] = a[2] + s * b[2];
}
static inline csReal csu_dot3(const csReal a[3], const csReal b[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline csReal csu_norm3(const csReal a[3]) { return sqrt(csu_dot3(a, a)); }
/* r = a x b (r must not alias a or b) */
static inline void csu_cross3(csReal r[3], const csReal a[3], const csReal b[3]) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}
/* normalise in place; returns the old norm (0 leaves a unchanged) */
static inline csReal csu_normalize3(csReal a[3]) {
  csReal n = csu_norm3(a);
  if (n > 0) {
    csu_scale3(a, a, 1.0 / n);
  }
  return n;
}

/* r = M a for row-major 3x3 M (r must not alias a) */
static inline void csu_mulMatVec3(csReal r[3], const csReal M[9], const csReal a[3]) {
  r[0] = M[0] * a[0] + M[1] * a[1] + M[2] * a[2];
  r[1] = M[3] * a[0] + M[4] * a[1] + M[5] * a[2];
  r[2] = M[6] * a[0] + M[7] * a[1] + M[8] * a[2];
}
/* R = A B for row-major 3x3 (R must not alias A or B) */
static inline void csu_mulMat3(csReal R[9], const csReal A[9], const csReal B[9]) {
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      R[3 * i + j] = A[3 * i] * B[j] + A[3 * i + 1] * B[3 + j] + A[3 * i + 2] * B[6 + j];
    }
  }
}
static inline void csu_eye3(csReal R[9]) {
  for (int i = 0; i < 9; i++) {
    R[i] = (i % 4 == 0) ? 1.0 : 0.0;
  }
}
/* rotation matrix of angle th (rad) about unit axis u (Rodrigues) */
static inline void csu_axisAngleToMat3(csReal R[9], const csReal u[3], csReal th) {
  csReal c = cos(th), s = sin(th), t = 1 - c;
  R[0] = t * u[0] * u[0] + c;
  R[1] = t * u[0] * u[1] - s * u[2];
  R[2] = t * u[0] * u[2] + s * u[1];
  R[3] = t * u[0] * u[1] + s * u[2];
  R[4] = t * u[1] * u[1] + c;
  R[5] = t * u[1] * u[2] - s * u[0];
  R[6] = t * u[0] * u[2] - s * u[1];
  R[7] = t * u[1] * u[2] + s * u[0];
  R[8] = t * u[2] * u[2] + c;
}
/* rotation matrix of a unit quaternion q = (w, x, y, z) */
static inline void csu_quatToMat3(csReal R[9], const csReal q[4]) {
  csReal w = q[0], x = q[1], y = q[2], z = q[3];
  R[0] = 1 - 2 * (y * y + z * z);
  R[1] = 2 * (x * y - w * z);
  R[2] = 2 * (x * z + w * y);
  R[3] = 2 * (x * y + w * z);
  R[4] = 1 - 2 * (x * x + z * z);
  R[5] = 2 * (y * z - w * x);
  R[6] = 2 * (x * z - w * y);
  R[7] = 2 * (y * z + w * x);
  R[8] = 1 - 2 * (x * x + y * y);
}

/* unit quaternion q = (w, x, y, z) of a rotation matrix (row-major), Shepperd's method: the
 * largest of 4 w^2, 4 x^2, 4 y^2, 4 z^2 is taken first (stable for every R), then normalised
 * (inverse of csu_quatToMat3 up to the sign of q) */
static inline void csu_mat3ToQuat(csReal q[4], const csReal R[9]) {
  const csReal tr = R[0] + R[4] + R[8];
  if (tr > R[0] && tr > R[4] && tr > R[8]) {
    const csReal s = 2 * sqrt(1 + tr);
    q[0] = 0.25 * s, q[1] = (R[7] - R[5]) / s, q[2] = (R[2] - R[6]) / s, q[3] = (R[3] - R[1]) / s;
  } else if (R[0] >= R[4] && R[0] >= R[8]) {
    const csReal s = 2 * sqrt(1 + R[0] - R[4] - R[8]);
    q[0] = (R[7] - R[5]) / s, q[1] = 0.25 * s, q[2] = (R[1] + R[3]) / s, q[3] = (R[2] + R[6]) / s;
  } else if (R[4] >= R[8]) {
    const csReal s = 2 * sqrt(1 + R[4] - R[0] - R[8]);
    q[0] = (R[2] - R[6]) / s, q[1] = (R[1] + R[3]) / s, q[2] = 0.25 * s, q[3] = (R[5] + R[7]) / s;
  } else {
    const csReal s = 2 * sqrt(1 + R[8] - R[0] - R[4]);
    q[0] = (R[3] - R[1]) / s, q[1] = (R[2] + R[6]) / s, q[2] = (R[5] + R[7]) / s, q[3] = 0.25 * s;
  }
  const csReal n = sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  if (n > 0) {
    for (int k = 0; k < 4; k++) {
      q[k] /= n;
    }
  }
}

/* r = M^T a for row-major 3x3 M (r must not alias a) */
static inline void csu_mulMatTVec3(csReal r[3], const csReal M[9], const csReal a[3]) {
  r[0] = M[0] * a[0] + M[3] * a[1] + M[6] * a[2];
  r[1] = M[1] * a[0] + M[4] * a[1] + M[7] * a[2];
  r[2] = M[2] * a[0] + M[5] * a[1] + M[8] * a[2];
}
/* R = A^T (R must not alias A) */
static inline void csu_transpose3(csReal R[9], const csReal A[9]) {
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      R[3 * i + j] = A[3 * j + i];
    }
  }
}
/* rotation vector φ (rad, axis times angle) of a rotation matrix R, angle in [0, π]: the
 * inverse of csu_rotVecToMat3. Below π/2 the axis comes from the skew part (well conditioned
 * there, exact as the angle -> 0), above it from the symmetric part (R + R^T)/2 - cos θ I =
 * (1 - cos θ) u u^T, whose conditioning does not degrade towards π; the angle is
 * atan2(|skew|, cos θ) in both. */
static inline void csu_mat3ToRotVec(csReal phi[3], const csReal R[9]) {
  csReal s[3] = {0.5 * (R[7] - R[5]), 0.5 * (R[2] - R[6]), 0.5 * (R[3] - R[1])};
  csReal sn = csu_norm3(s), c = 0.5 * (R[0] + R[4] + R[8] - 1);
  csReal th = atan2(sn, c);
  if (c > 0) {
    /* th/sin(th) in [1, π/2): well conditioned, -> 1 as th -> 0 */
    csReal f = sn > 0 ? th / sn : 1.0;
    csu_scale3(phi, s, f);
    return;
  }
  int k = (R[0] >= R[4] && R[0] >= R[8]) ? 0 : (R[4] >= R[8] ? 1 : 2);
  csReal oc = 1 - c; /* >= 1 here */
  csReal u[3];
  u[k] = sqrt(fmax(0.0, (R[4 * k] - c) / oc));
  for (int i = 0; i < 3; i++) {
    if (i != k) {
      u[i] = 0.5 * (R[3 * i + k] + R[3 * k + i]) / (oc * u[k]);
    }
  }
  csu_normalize3(u);
  if (csu_dot3(u, s) < 0) {
    csu_scale3(u, u, -1.0);
  }
  csu_scale3(phi, u, th);
}

/* rotation matrix exp([φ]x) of a rotation vector φ (rad); the identity for φ = 0 */
static inline void csu_rotVecToMat3(csReal R[9], const csReal phi[3]) {
  csReal th = csu_norm3(phi);
  if (!(th > 0)) {
    csu_eye3(R);
    return;
  }
  csReal u[3];
  csu_scale3(u, phi, 1.0 / th);
  csu_axisAngleToMat3(R, u, th);
}

/* Eigen decomposition of a symmetric n x n matrix A, n <= 6 (row-major; only its symmetric
 * part is used): A = V diag(w) V^T with the eigenvectors as the columns of V (orthonormal, n x n
 * row-major), by cyclic Jacobi rotations (Golub & Van Loan 8.5), converged to round-off in a few
 * sweeps for these sizes (capped at 50). Eigenvalues are not sorted. */
#define CSU_SYMEIGEN_MAXN 6
static inline void csu_symEigenN(int n, const csReal* A, csReal* w, csReal* V) {
  csReal a[CSU_SYMEIGEN_MAXN * CSU_SYMEIGEN_MAXN];
  if (n < 1 || n > CSU_SYMEIGEN_MAXN) {
    return; /* outside the work array: a caller's error, outputs untouched */
  }
  for (int i = 0; i < n; i++) {
    for (int j = 0; j < n; j++) {
      a[n * i + j] = 0.5 * (A[n * i + j] + A[n * j + i]);
      V[n * i + j] = i == j ? 1.0 : 0.0;
    }
  }
  for (int sweep = 0; sweep < 50; sweep++) {
    csReal off = 0, diag = 0;
    for (int p = 0; p < n; p++) {
      for (int q = p + 1; q < n; q++) {
        off += a[n * p + q] * a[n * p + q];
      }
    }
    for (int p = 0; p < n; p++) {
      diag += a[n * p + p] * a[n * p + p];
    }
    if (!(off > 1e-36 * diag)) {
      break; /* off-diagonal below round-off of the diagonal (or exactly zero) */
    }
    for (int p = 0; p < n - 1; p++) {
      for (int q = p + 1; q < n; q++) {
        csReal apq = a[n * p + q];
        if (apq == 0) {
          continue;
        }
        /* the rotation that zeroes a_pq: tan(2θ) = 2 a_pq / (a_qq - a_pp), smaller root */
        csReal tau = (a[n * q + q] - a[n * p + p]) / (2 * apq);
        csReal t = (tau >= 0 ? 1.0 : -1.0) / (fabs(tau) + sqrt(1 + tau * tau));
        csReal c = 1 / sqrt(1 + t * t), sn = t * c;
        for (int k = 0; k < n; k++) {
          /* a <- J^T a J with J the (p, q) rotation, columns then rows */
          csReal akp = a[n * k + p], akq = a[n * k + q];
          a[n * k + p] = c * akp - sn * akq;
          a[n * k + q] = sn * akp + c * akq;
        }
        for (int k = 0; k < n; k++) {
          csReal apk = a[n * p + k], aqk = a[n * q + k];
          a[n * p + k] = c * apk - sn * aqk;
          a[n * q + k] = sn * apk + c * aqk;
        }
        for (int k = 0; k < n; k++) {
          csReal vkp = V[n * k + p], vkq = V[n * k + q];
          V[n * k + p] = c * vkp - sn * vkq;
          V[n * k + q] = sn * vkp + c * vkq;
        }
      }
    }
  }
  for (int i = 0; i < n; i++) {
    w[i] = a[n * i + i];
  }
}

/* the 3 x 3 case (csu_symEigenN) */
static inline void csu_symEigen3(const csReal A[9], csReal w[3], csReal V[9]) {
  csu_symEigenN(3, A, w, V);
}

/* The congruence C = Tᵀ G T of 6 x 6 row-major matrices (G T first, then Tᵀ times it): a
 * 6 x 6 impedance or stiffness G carried through the twist map T (the support's implicit step
 * moves each leg's gains to its centre, sim_coupling.c; the strain leg's hip frame change,
 * robot_strain_leg.c). C may not alias T or G. */
static inline void csu_congruence6(csReal C[36], const csReal T[36], const csReal G[36]) {
  csReal GT[36];
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      csReal s = 0;
      for (int k = 0; k < 6; k++) {
        s += G[6 * i + k] * T[6 * k + j];
      }
      GT[6 * i + j] = s;
    }
  }
  for (int i = 0; i < 6; i++) {
    for (int j = 0; j < 6; j++) {
      csReal s = 0;
      for (int k = 0; k < 6; k++) {
        s += T[6 * k + i] * GT[6 * k + j];
      }
      C[6 * i + j] = s;
    }
  }
}

/* Solve A x = b for a 6 x 6 A (row-major, destroyed) by Gaussian elimination with partial
 * pivoting; x overwrites b. Returns 1 (b partly overwritten) if A is singular, else 0. The
 * support's implicit step (sim_coupling.c) and the strain leg's tree tests use it. */
static inline int csu_solve6(csReal A[36], csReal b[6]) {
  for (int k = 0; k < 6; k++) {
    int p = k;
    for (int i = k + 1; i < 6; i++) {
      if (fabs(A[6 * i + k]) > fabs(A[6 * p + k])) {
        p = i;
      }
    }
    if (!(fabs(A[6 * p + k]) > 0)) {
      return 1;
    }
    if (p != k) {
      for (int j = 0; j < 6; j++) {
        csReal t = A[6 * k + j];
        A[6 * k + j] = A[6 * p + j];
        A[6 * p + j] = t;
      }
      csReal t = b[k];
      b[k] = b[p];
      b[p] = t;
    }
    for (int i = k + 1; i < 6; i++) {
      csReal f = A[6 * i + k] / A[6 * k + k];
      for (int j = k; j < 6; j++) {
        A[6 * i + j] -= f * A[6 * k + j];
      }
      b[i] -= f * b[k];
    }
  }
  for (int k = 5; k >= 0; k--) {
    csReal s = b[k];
    for (int j = k + 1; j < 6; j++) {
      s -= A[6 * k + j] * b[j];
    }
    b[k] = s / A[6 * k + k];
  }
  return 0;
}

/* The implicit spring-damper of ODE's soft constraints (ODE manual, "Soft constraint and
 * constraint force mixing"): a row with error-reduction ERP and constraint-force mixing CFM at
 * step h acts as a spring kp with damper kd integrated implicitly when
 *   ERP = h kp / (h kp + kd),  CFM = 1 / (h kp + kd).
 * Units: h s, kp N/mm (or N mm/rad), kd N s/mm (N mm s/rad); CFM in ODE's (mm/s)/N. kd = 0 is
 * a pure spring (ERP = 1), kp = 0 a pure damper (ERP = 0). Returns 0, or -1 (outputs untouched)
 * unless h > 0, kp >= 0, kd >= 0, h kp + kd > 0 and all are finite. Pure math, no ODE: the one
 * place contact_ode.c and the coupling hooks get the mapping from. */
static inline int csu_springErpCfm(csReal h, csReal kp, csReal kd, csReal* erp, csReal* cfm) {
  if (!(h > 0 && kp >= 0 && kd >= 0 && isfinite(h) && isfinite(kp) && isfinite(kd))) {
    return -1;
  }
  csReal hk = h * kp;
  if (!(hk + kd > 0)) {
    return -1;
  }
  *erp = hk / (hk + kd);
  *cfm = 1.0 / (hk + kd);
  return 0;
}

#ifdef __cplusplus
}
#endif
#endif /* CS_CORE_MATH_H */

/* robot_strain_linalg.c: the strain leg's dense factorisations (robot_strain_internal.h): the
 * LU with partial pivoting of the step's leg block W_ll (and of the statics' Newton matrix),
 * the Cholesky factor of a W_ll without contact, and their solves for one and for six
 * right-hand sides (the condensation onto the base's six unknowns). Row-major n x n; each
 * kernel's loops written so the compiler vectorises them without reassociating a sum
 * (docs/notes/strain_leg.md, "Kernel and fixed costs" and "Kernel, round 3"). */
#include <math.h>
#include <stddef.h>

#include "robot_strain_internal.h"

/* a[j] -= l p[j] for j in [j0, n) on rows a of the factor below its pivot row p (distinct
 * rows: restrict lets the compiler vectorise without a run-time overlap test) */
static void elimRow(double* restrict a, const double* restrict p, double l, int j0, int n) {
  for (int j = j0; j < n; j++) {
    a[j] -= l * p[j];
  }
}


/* the same on four rows at once, each entry the same operation: the pivot row's entries are
 * loaded once for the four (17-23 % fewer instructions in the factor, measured on a 42 x 42
 * matrix: docs/notes/strain_leg.md "Kernel and fixed costs"; the same bits) */
static void elimRows4(double* restrict a0, double* restrict a1, double* restrict a2,
                      double* restrict a3, const double* restrict p, const double l[4], int j0,
                      int n) {
  const double l0 = l[0], l1 = l[1], l2 = l[2], l3 = l[3];
  for (int j = j0; j < n; j++) {
    const double pj = p[j];
    a0[j] -= l0 * pj;
    a1[j] -= l1 * pj;
    a2[j] -= l2 * pj;
    a3[j] -= l3 * pj;
  }
}


/* LU with partial pivoting of A (n x n) in place; 0 ok, 1 singular */
int csr_strainLuFactor_(double* A, int n, int* piv) {
  for (int k = 0; k < n; k++) {
    int p = k;
    for (int i = k + 1; i < n; i++) {
      if (fabs(A[i * n + k]) > fabs(A[p * n + k])) {
        p = i;
      }
    }
    piv[k] = p;
    if (!(fabs(A[p * n + k]) > 0)) {
      return 1;
    }
    if (p != k) {
      for (int j = 0; j < n; j++) {
        double t = A[k * n + j];
        A[k * n + j] = A[p * n + j];
        A[p * n + j] = t;
      }
    }
    const double* pk = A + k * n;
    int i = k + 1;
    for (; i + 3 < n; i += 4) {
      double* r[4];
      double l[4];
      for (int q = 0; q < 4; q++) {
        r[q] = A + (i + q) * n;
        l[q] = r[q][k] /= pk[k];
      }
      elimRows4(r[0], r[1], r[2], r[3], pk, l, k + 1, n);
    }
    for (; i < n; i++) {
      double* a = A + i * n;
      const double l = a[k] /= pk[k];
      elimRow(a, pk, l, k + 1, n);
    }
  }
  return 0;
}


void csr_strainLuSolve_(const double* A, int n, const int* piv, double* x) {
  /* the factor swapped whole rows (its multipliers too): P first, then L and U */
  for (int k = 0; k < n; k++) {
    if (piv[k] != k) {
      double t = x[k];
      x[k] = x[piv[k]];
      x[piv[k]] = t;
    }
  }
  for (int k = 0; k < n; k++) {
    for (int i = k + 1; i < n; i++) {
      x[i] -= A[i * n + k] * x[k];
    }
  }
  for (int k = n - 1; k >= 0; k--) {
    for (int j = k + 1; j < n; j++) {
      x[k] -= A[k * n + j] * x[j];
    }
    x[k] /= A[k * n + k];
  }
}


/* b[c] -= l r[c] over nrhs columns (distinct rows of B) */
static void rowAxpy(double* restrict b, const double* restrict r, double l, int nrhs) {
  for (int c = 0; c < nrhs; c++) {
    b[c] -= l * r[c];
  }
}


/* rowAxpy for six columns (the condensation's W_ll⁻¹ W_lb), unrolled: the same operation on
 * every entry, without the call and loop overhead of six-entry loops */
static inline void rowAxpy6(double* restrict b, const double* restrict r, double l) {
  b[0] -= l * r[0];
  b[1] -= l * r[1];
  b[2] -= l * r[2];
  b[3] -= l * r[3];
  b[4] -= l * r[4];
  b[5] -= l * r[5];
}


void csr_strainLuSolveMulti_(const double* A, int n, const int* piv, double* B, int nrhs) {
  for (int k = 0; k < n; k++) {
    if (piv[k] != k) {
      double* a = B + (size_t)k * nrhs;
      double* b = B + (size_t)piv[k] * nrhs;
      for (int c = 0; c < nrhs; c++) {
        double t = a[c];
        a[c] = b[c];
        b[c] = t;
      }
    }
  }
  /* every entry the same operations in the same order as one right-hand side at a time */
  if (nrhs == 6) {
    for (int k = 0; k < n; k++) {
      const double* bk = B + (size_t)k * 6;
      for (int i = k + 1; i < n; i++) {
        rowAxpy6(B + (size_t)i * 6, bk, A[i * n + k]);
      }
    }
    for (int k = n - 1; k >= 0; k--) {
      double* bk = B + (size_t)k * 6;
      for (int j = k + 1; j < n; j++) {
        rowAxpy6(bk, B + (size_t)j * 6, A[k * n + j]);
      }
      for (int c = 0; c < 6; c++) {
        bk[c] /= A[k * n + k];
      }
    }
    return;
  }
  for (int k = 0; k < n; k++) {
    const double* bk = B + (size_t)k * nrhs;
    for (int i = k + 1; i < n; i++) {
      rowAxpy(B + (size_t)i * nrhs, bk, A[i * n + k], nrhs);
    }
  }
  for (int k = n - 1; k >= 0; k--) {
    double* bk = B + (size_t)k * nrhs;
    for (int j = k + 1; j < n; j++) {
      rowAxpy(bk, B + (size_t)j * nrhs, A[k * n + j], nrhs);
    }
    for (int c = 0; c < nrhs; c++) {
      bk[c] /= A[k * n + k];
    }
  }
}


/* Cholesky A = Uᵀ U of a symmetric positive definite A (n x n) in place: U in the upper
 * triangle (row-major; the strict lower triangle is scratch, never read); half the LU's
 * operations, each row update a contiguous loop (elimRow); 0 ok, 1 a pivot not positive */
int csr_strainCholFactor_(double* A, int n) {
  for (int k = 0; k < n; k++) {
    double* Ak = A + (size_t)k * n;
    if (!(Ak[k] > 0) || !isfinite(Ak[k])) {
      return 1;
    }
    const double dk = sqrt(Ak[k]);
    Ak[k] = dk;
    for (int j = k + 1; j < n; j++) {
      Ak[j] /= dk;
    }
    /* rows i > k: a_ij -= u_ki u_kj for j >= i, four rows at a time sharing the pivot row's
     * loads (from the block's first column: the entries left of a row's diagonal are never
     * read again) */
    int i = k + 1;
    for (; i + 3 < n; i += 4) {
      const double l[4] = {Ak[i], Ak[i + 1], Ak[i + 2], Ak[i + 3]};
      elimRows4(A + (size_t)i * n, A + (size_t)(i + 1) * n, A + (size_t)(i + 2) * n,
                A + (size_t)(i + 3) * n, Ak, l, i, n);
    }
    for (; i < n; i++) {
      elimRow(A + (size_t)i * n, Ak, Ak[i], i, n);
    }
  }
  return 0;
}


void csr_strainCholSolve_(const double* U, int n, double* x) {
  /* Uᵀ y = b, then U x = y */
  for (int k = 0; k < n; k++) {
    const double* Uk = U + (size_t)k * n;
    x[k] /= Uk[k];
    for (int j = k + 1; j < n; j++) {
      x[j] -= Uk[j] * x[k];
    }
  }
  for (int k = n - 1; k >= 0; k--) {
    const double* Uk = U + (size_t)k * n;
    for (int j = k + 1; j < n; j++) {
      x[k] -= Uk[j] * x[j];
    }
    x[k] /= Uk[k];
  }
}


void csr_strainCholSolve6_(const double* U, int n, double* B) {
  for (int k = 0; k < n; k++) {
    const double* Uk = U + (size_t)k * n;
    double* bk = B + (size_t)k * 6;
    for (int c = 0; c < 6; c++) {
      bk[c] /= Uk[k];
    }
    for (int j = k + 1; j < n; j++) {
      rowAxpy6(B + (size_t)j * 6, bk, Uk[j]);
    }
  }
  for (int k = n - 1; k >= 0; k--) {
    const double* Uk = U + (size_t)k * n;
    double* bk = B + (size_t)k * 6;
    for (int j = k + 1; j < n; j++) {
      rowAxpy6(bk, B + (size_t)j * 6, Uk[j]);
    }
    for (int c = 0; c < 6; c++) {
      bk[c] /= Uk[k];
    }
  }
}

/* robot_rod_bt.c: the rod's block-tridiagonal matrices with 6 x 6 blocks (csrRodBt,
 * robot_rod_internal.h): allocation, block LU factorisation (Thomas algorithm with pivoted
 * inverses of the eliminated diagonal blocks) and the solve. Shared by the static solver
 * (robot_rod_static.c) and the implicit step's reduced Newton matrix (robot_rod_linsol.c), which
 * says why block LU factors these mass-damping-stiffness-like matrices stably. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "robot_rod_internal.h"


/* in-place inverse of a row-major 6 x 6 matrix by Gauss-Jordan with partial pivoting; 1 if
 * singular or not finite. An explicit inverse makes every later use a fixed-size
 * matrix-vector product (the solves run once per Newton iteration, the factorisation once per
 * γ): measured faster than LU solves with row swaps for these 6 x 6 blocks. */
static int inv6(double A[36]) {
  double W[6][12];
  for (int r = 0; r < 6; r++) {
    for (int c = 0; c < 6; c++) {
      W[r][c] = A[6 * r + c];
      W[r][6 + c] = (r == c) ? 1.0 : 0.0;
    }
  }
  for (int k = 0; k < 6; k++) {
    int p = k;
    double big = fabs(W[k][k]);
    for (int i = k + 1; i < 6; i++) {
      if (fabs(W[i][k]) > big) {
        big = fabs(W[i][k]);
        p = i;
      }
    }
    if (!(big > 0) || !isfinite(big)) {
      return 1;
    }
    if (p != k) {
      for (int c = 0; c < 12; c++) {
        double t = W[k][c];
        W[k][c] = W[p][c];
        W[p][c] = t;
      }
    }
    /* columns < k of the left half are never read again (pivots and multipliers come from
     * columns >= k, and the result is the right half): they are left as they are */
    double inv = 1.0 / W[k][k];
    for (int c = k; c < 12; c++) {
      W[k][c] *= inv;
    }
    for (int i = 0; i < 6; i++) {
      if (i != k) {
        double f = W[i][k];
        for (int c = k; c < 12; c++) {
          W[i][c] -= f * W[k][c];
        }
      }
    }
  }
  for (int r = 0; r < 6; r++) {
    for (int c = 0; c < 6; c++) {
      A[6 * r + c] = W[r][6 + c];
    }
  }
  return 0;
}


/* y = A x for 6 x 6 A (y must not alias x) */
static void mv6(const double A[36], const double x[6], double y[6]) {
  for (int r = 0; r < 6; r++) {
    const double* a = A + 6 * r;
    y[r] = a[0] * x[0] + a[1] * x[1] + a[2] * x[2] + a[3] * x[3] + a[4] * x[4] + a[5] * x[5];
  }
}


int csr_rodBtAlloc_(csrRodBt* bt, int n) {
  memset(bt, 0, sizeof *bt);
  bt->n = n;
  bt->B = calloc(36 * (size_t)n, sizeof(double));
  bt->D = calloc(36 * (size_t)n, sizeof(double));
  bt->C = calloc(36 * (size_t)n, sizeof(double));
  bt->piv = calloc(6 * (size_t)n, sizeof(int));
  return bt->B && bt->D && bt->C && bt->piv;
}


void csr_rodBtFree_(csrRodBt* bt) {
  free(bt->B);
  free(bt->D);
  free(bt->C);
  free(bt->piv);
  memset(bt, 0, sizeof *bt);
}


void csr_rodBtZero_(csrRodBt* bt) {
  memset(bt->B, 0, 36 * (size_t)bt->n * sizeof(double));
  memset(bt->D, 0, 36 * (size_t)bt->n * sizeof(double));
  memset(bt->C, 0, 36 * (size_t)bt->n * sizeof(double));
}


int csr_rodBtFactor_(csrRodBt* bt) {
  for (int i = 0; i < bt->n; i++) {
    double* D = bt->D + 36 * i;
    if (i > 0) {
      /* D_i -= B_i U_{i-1} */
      const double* B = bt->B + 36 * i;
      const double* U = bt->C + 36 * (i - 1);
      for (int r = 0; r < 6; r++) {
        for (int k = 0; k < 6; k++) {
          double b = B[6 * r + k];
          for (int c = 0; c < 6; c++) {
            D[6 * r + c] -= b * U[6 * k + c];
          }
        }
      }
    }
    /* D holds D_i'⁻¹ from here on */
    if (inv6(D) != 0) {
      return 1;
    }
    if (i < bt->n - 1) {
      /* U_i = D_i'⁻¹ C_i */
      double* C = bt->C + 36 * i;
      double T[36];
      memcpy(T, C, sizeof T);
      for (int r = 0; r < 6; r++) {
        for (int c = 0; c < 6; c++) {
          double sum = 0;
          for (int k = 0; k < 6; k++) {
            sum += D[6 * r + k] * T[6 * k + c];
          }
          C[6 * r + c] = sum;
        }
      }
    }
  }
  return 0;
}


void csr_rodBtSolve_(const csrRodBt* bt, double* x) {
  double t[6];
  for (int i = 0; i < bt->n; i++) {
    double* xi = x + 6 * i;
    if (i > 0) {
      mv6(bt->B + 36 * i, x + 6 * (i - 1), t);
      for (int r = 0; r < 6; r++) {
        xi[r] -= t[r];
      }
    }
    mv6(bt->D + 36 * i, xi, t);
    memcpy(xi, t, sizeof t);
  }
  for (int i = bt->n - 2; i >= 0; i--) {
    mv6(bt->C + 36 * i, x + 6 * (i + 1), t);
    for (int r = 0; r < 6; r++) {
      x[6 * i + r] -= t[r];
    }
  }
}

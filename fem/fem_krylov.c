/* fem_krylov.c: restarted right-preconditioned GMRES (fem_krylov.h).
 *
 * Arnoldi with modified Gram-Schmidt and one re-orthogonalisation pass when the new vector lost
 * more than half its norm (Daniel-Gragg-Kaufman-Stewart criterion: with an almost exact
 * preconditioner the Krylov vectors are nearly dependent after a few steps), Givens rotations
 * on the Hessenberg matrix so the residual norm is known at every step without forming x.
 * Workspace layout: V (restart + 1 vectors), Z (one vector: M^-1 of the update), H
 * ((restart + 1) x restart), cs, sn, g (restart + 1 each). */
#include "fem_krylov.h"

#include <math.h>
#include <string.h>

size_t csf_gmresWorkSize(int n, int restart) {
  const size_t m = (size_t)restart;
  return (m + 2) * (size_t)n + (m + 1) * m + 3 * (m + 1);
}


static double dot(int n, const double* a, const double* b) {
  double s = 0;
  for (int i = 0; i < n; i++) {
    s += a[i] * b[i];
  }
  return s;
}


int csf_gmres(int n, int restart, int maxit, double rtol, csfLinOp A, csfLinOp Minv, void* ctx,
              const double* b, double* x, double* work, int* its, double* relres) {
  const int m = restart < 1 ? 1 : (restart > CSF_GMRES_MAX_RESTART ? CSF_GMRES_MAX_RESTART : restart);
  double* V = work;
  double* Z = V + (size_t)(m + 1) * n;
  double* H = Z + n;
  double* cs = H + (size_t)(m + 1) * m;
  double* sn = cs + m + 1;
  double* g = sn + m + 1;
  const double bnorm = sqrt(dot(n, b, b));
  *its = 0;
  *relres = 0;
  if (bnorm == 0) {
    memset(x, 0, (size_t)n * sizeof(double));
    return 0;
  }
  int total = 0;
  for (;;) {
    /* r = b - A x into V[0] */
    if (A(ctx, x, V) != 0) {
      return -1;
    }
    for (int i = 0; i < n; i++) {
      V[i] = b[i] - V[i];
    }
    double beta = sqrt(dot(n, V, V));
    *relres = beta / bnorm;
    if (*relres <= rtol) {
      *its = total;
      return 0;
    }
    if (total >= maxit) {
      *its = total;
      return 1;
    }
    for (int i = 0; i < n; i++) {
      V[i] /= beta;
    }
    memset(g, 0, (size_t)(m + 1) * sizeof(double));
    g[0] = beta;
    int k = 0;
    for (; k < m && total < maxit; k++, total++) {
      double* vk = V + (size_t)k * n;
      double* w = V + (size_t)(k + 1) * n;
      /* w = A M^-1 v_k */
      if (Minv(ctx, vk, Z) != 0 || A(ctx, Z, w) != 0) {
        return -1;
      }
      const double w0 = sqrt(dot(n, w, w));
      for (int pass = 0; pass < 2; pass++) {
        for (int j = 0; j <= k; j++) {
          const double* vj = V + (size_t)j * n;
          const double h = dot(n, w, vj);
          H[(size_t)j * m + k] = (pass ? H[(size_t)j * m + k] : 0.0) + h;
          for (int i = 0; i < n; i++) {
            w[i] -= h * vj[i];
          }
        }
        if (sqrt(dot(n, w, w)) > 0.5 * w0) {
          break; /* no re-orthogonalisation needed */
        }
      }
      const double hn = sqrt(dot(n, w, w));
      H[(size_t)(k + 1) * m + k] = hn;
      if (hn > 0) {
        for (int i = 0; i < n; i++) {
          w[i] /= hn;
        }
      }
      /* apply the earlier rotations to column k, then a new one that zeroes H(k+1, k) */
      for (int j = 0; j < k; j++) {
        const double a = H[(size_t)j * m + k], c = H[(size_t)(j + 1) * m + k];
        H[(size_t)j * m + k] = cs[j] * a + sn[j] * c;
        H[(size_t)(j + 1) * m + k] = -sn[j] * a + cs[j] * c;
      }
      const double a = H[(size_t)k * m + k], c = H[(size_t)(k + 1) * m + k];
      const double r = hypot(a, c);
      cs[k] = r > 0 ? a / r : 1.0;
      sn[k] = r > 0 ? c / r : 0.0;
      H[(size_t)k * m + k] = r;
      H[(size_t)(k + 1) * m + k] = 0;
      g[k + 1] = -sn[k] * g[k];
      g[k] = cs[k] * g[k];
      *relres = fabs(g[k + 1]) / bnorm;
      if (*relres <= rtol || hn == 0) {
        k++;
        total++;
        break;
      }
    }
    /* y = H^-1 g (upper triangular k x k), x += M^-1 (V y) */
    double y[CSF_GMRES_MAX_RESTART];
    const int kk = k;
    for (int i = kk - 1; i >= 0; i--) {
      double s = g[i];
      for (int j = i + 1; j < kk; j++) {
        s -= H[(size_t)i * m + j] * y[j];
      }
      y[i] = H[(size_t)i * m + i] != 0 ? s / H[(size_t)i * m + i] : 0.0;
    }
    double* u = V + (size_t)m * n; /* the last basis slot: v_m never enters the update */
    memset(u, 0, (size_t)n * sizeof(double));
    for (int j = 0; j < kk; j++) {
      const double* vj = V + (size_t)j * n;
      for (int i = 0; i < n; i++) {
        u[i] += y[j] * vj[i];
      }
    }
    if (Minv(ctx, u, Z) != 0) {
      return -1;
    }
    for (int i = 0; i < n; i++) {
      x[i] += Z[i];
    }
    if (*relres <= rtol) {
      *its = total;
      /* the recurrence's residual; the true one is checked at the next cycle's start by callers
       * that need it (Newton re-assembles R anyway) */
      return 0;
    }
  }
}

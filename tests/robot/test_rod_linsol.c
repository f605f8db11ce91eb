

/* test_rod_linsol.c: the rod's reduced Newton solver (robot_rod_linsol.c) solves CVODE's system
 * (I - γJ) x = b as a dense LU of the full finite-difference Jacobian does, with contact history
 * in the state; and the 6 x 6 block-tridiagonal LU against a dense solve.
 *
 * Cases:
 *  - block_tridiagonal_solve: a random diagonally dominated block-tridiagonal system, solved
 *    by csr_rodBtFactor_/Solve_ and by dense Gaussian elimination.
 *  - reduced_solve_matches_dense: the leg at a strained, moving state (random positions,
 *    rotations, angular velocities up to 3 rad/s, history), with a contact hook whose forces
 *    depend on positions, velocities and history and whose history rates depend on velocities,
 *    positions and the history itself (as a friction bristle's); for γ = 1e-4 .. 1e-2 s, the
 *    reduced solution of (I - γJ) x = b equals the dense one. */
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "robot_rod_internal.h"

static double rnd(unsigned* s) {
  *s = *s * 1664525u + 1013904223u;
  return (double)(*s >> 8) / (double)(1u << 24) * 2.0 - 1.0;
}


/* dense Gaussian elimination with partial pivoting: A (n x n, row-major) x = b, in place */
static int denseSolve(int n, double* A, double* b) {
  for (int k = 0; k < n; k++) {
    int p = k;
    for (int i = k + 1; i < n; i++) {
      if (fabs(A[(size_t)n * i + k]) > fabs(A[(size_t)n * p + k])) {
        p = i;
      }
    }
    if (A[(size_t)n * p + k] == 0) {
      return 1;
    }
    if (p != k) {
      for (int j = 0; j < n; j++) {
        double t = A[(size_t)n * k + j];
        A[(size_t)n * k + j] = A[(size_t)n * p + j];
        A[(size_t)n * p + j] = t;
      }
      double t = b[k];
      b[k] = b[p];
      b[p] = t;
    }
    for (int i = k + 1; i < n; i++) {
      double l = A[(size_t)n * i + k] / A[(size_t)n * k + k];
      if (l != 0) {
        for (int j = k; j < n; j++) {
          A[(size_t)n * i + j] -= l * A[(size_t)n * k + j];
        }
        b[i] -= l * b[k];
      }
    }
  }
  for (int k = n - 1; k >= 0; k--) {
    for (int j = k + 1; j < n; j++) {
      b[k] -= A[(size_t)n * k + j] * b[j];
    }
    b[k] /= A[(size_t)n * k + k];
  }
  return 0;
}


static void block_tridiagonal_solve(void) {
  const int nb = 7, n = 6 * nb;
  csrRodBt bt;
  CS_EXPECT(csr_rodBtAlloc_(&bt, nb));
  double* A = calloc((size_t)n * n, sizeof(double));
  double *x = calloc((size_t)n, sizeof(double)), *b = calloc((size_t)n, sizeof(double));
  unsigned s = 3u;
  for (int i = 0; i < nb; i++) {
    for (int r = 0; r < 6; r++) {
      for (int c = 0; c < 6; c++) {
        double d = rnd(&s) + (r == c ? 8.0 : 0.0);
        bt.D[36 * i + 6 * r + c] = d;
        A[(size_t)n * (6 * i + r) + 6 * i + c] = d;
        if (i > 0) {
          double v = rnd(&s);
          bt.B[36 * i + 6 * r + c] = v;
          A[(size_t)n * (6 * i + r) + 6 * (i - 1) + c] = v;
        }
        if (i < nb - 1) {
          double v = rnd(&s);
          bt.C[36 * i + 6 * r + c] = v;
          A[(size_t)n * (6 * i + r) + 6 * (i + 1) + c] = v;
        }
      }
    }
  }
  for (int k = 0; k < n; k++) {
    b[k] = x[k] = rnd(&s);
  }
  CS_EXPECT(csr_rodBtFactor_(&bt) == 0);
  csr_rodBtSolve_(&bt, x);
  CS_EXPECT(denseSolve(n, A, b) == 0);
  for (int k = 0; k < n; k++) {
    /* both backward stable on a well-conditioned system (cond ~ 2): ~1e-15 */
    CS_EXPECT_NEAR(x[k], b[k], 1e-12, 0);
  }
  free(A);
  free(x);
  free(b);
  csr_rodBtFree_(&bt);
}


/* a contact-like hook with history: the node force of element e pulls towards a spring anchor
 * h (positions and history), is damped (velocities); the history relaxes towards the node's
 * motion (ḣ = v - h/τ, as a bristle's rate); the foot element adds a couple */
static int historyHook(void* ctx, const csrRodShape* sh, const double* hist, double* dhist,
                       double f0[3], double f1[3], double moment[3]) {
  (void)ctx;
  const int nh = sh->kind == CSR_ROD_SHAPE_BOX ? 3 : 2;
  for (int k = 0; k < 2; k++) {
    f1[k] = -0.3 * (sh->p1[k] - hist[k]) - 2e-3 * sh->v1[k];
    f0[k] = -0.1 * (sh->p0[k] - hist[k]) * 0.5;
    dhist[k] = sh->v1[k] - hist[k] / 0.01;
  }
  if (nh == 3) {
    moment[2] = -0.5 * hist[2];
    dhist[2] = sh->omega[2] - 20 * hist[2] + 0.1 * sh->p1[0];
  }
  return 0;
}


static void reduced_solve_matches_dense(void) {
  csrActuator act;
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(&act, "leg", &err);
  csrRodParams par = csr_rodDefaultParams(&act);
  par.elements_per_segment = 2;
  csrRodSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.act = &act;
  sp.params = &par;
  csu_eye3(sp.frame);
  sp.gravity[0] = -9810;
  sp.contact.eval = historyHook;
  sp.contact.nhist = 2;
  sp.contact.nhist_foot = 3;
  csrRodModel* m = csr_rodModelCreate(&sp, &err);
  csrRodData* d = m ? csr_rodDataCreate(m, &err) : NULL;
  CS_EXPECT(d != NULL);
  if (!d) {
    csr_rodModelDestroy(m);
    return;
  }
  /* a strained, moving state */
  const int ny = CSR_ROD_NIMP + m->nstate;
  double* Y = d->y;
  unsigned s = 17u;
  for (int e = 1; e <= m->N; e++) {
    double* b = Y + CSR_ROD_NIMP + m->boff[e];
    double phi[3], dq[4], q[4];
    for (int k = 0; k < 3; k++) {
      b[CSR_ROD_BX + k] += 0.5 * rnd(&s);
      phi[k] = 0.1 * rnd(&s);
      b[CSR_ROD_BV + k] = 20 * rnd(&s);
      b[CSR_ROD_BW + k] = 3.0 * rnd(&s); /* rad/s: γ|ω| up to 0.05 */
    }
    csr_rodQexp(dq, phi);
    csr_rodQmul(q, b + CSR_ROD_BQ, dq);
    memcpy(b + CSR_ROD_BQ, q, sizeof q);
    for (int k = 0; k < m->nh[e]; k++) {
      b[CSR_ROD_BH + k] = 0.2 * rnd(&s);
    }
  }
  N_Vector fy = N_VClone(d->yv), t1 = N_VClone(d->yv), t2 = N_VClone(d->yv);
  N_Vector t3 = N_VClone(d->yv), xv = N_VClone(d->yv), bv = N_VClone(d->yv);
  double* M = calloc((size_t)ny * ny, sizeof(double));
  double* Fp = N_VGetArrayPointer(t1);
  double* Fm = N_VGetArrayPointer(t2);
  double* Yp = N_VGetArrayPointer(t3);
  CS_EXPECT(csr_rodRhs_(0.0, d->yv, fy, d) == 0);
  const double gammas[3] = {1e-4, 1e-3, 1e-2};
  for (int gi = 0; gi < 3; gi++) {
    const double g = gammas[gi];
    /* dense M = I - γ J by central differences on every state component (the quaternion's
     * four as they are: the reduced solver must handle CVODE's coordinates) */
    for (int j = 0; j < ny; j++) {
      double h = 1e-6 * fmax(1.0, fabs(Y[j]));
      memcpy(Yp, Y, (size_t)ny * sizeof(double));
      Yp[j] = Y[j] + h;
      csr_rodRhs_(0.0, t3, t1, d);
      Yp[j] = Y[j] - h;
      csr_rodRhs_(0.0, t3, t2, d);
      for (int i = 0; i < ny; i++) {
        M[(size_t)ny * i + j] = (i == j ? 1.0 : 0.0) - g * (Fp[i] - Fm[i]) / (2 * h);
      }
    }
    sunbooleantype jcur = 0;
    CS_EXPECT(csr_rodLinSys_(0.0, d->yv, fy, d->A, 0, &jcur, g, d, t1, t2, t3) == 0);
    CS_EXPECT(d->LS->ops->setup(d->LS, d->A) == 0);
    double* B = N_VGetArrayPointer(bv);
    double* ref = calloc((size_t)ny, sizeof(double));
    for (int i = 0; i < ny; i++) {
      B[i] = ref[i] = rnd(&s);
    }
    CS_EXPECT(d->LS->ops->solve(d->LS, d->A, xv, bv, 0.0) == 0);
    CS_EXPECT(denseSolve(ny, M, ref) == 0);
    const double* X = N_VGetArrayPointer(xv);
    double worst = 0, scale = 0;
    for (int i = CSR_ROD_NIMP; i < ny; i++) {
      worst = fmax(worst, fabs(X[i] - ref[i]));
      scale = fmax(scale, fabs(ref[i]));
    }
    /* the impulse rows take x = b (their weight is zero); the rest is exact algebra, so it
     * agrees to the difference quotients' accuracy (forward steps ~√eps in the reduced solver,
     * central 1e-6 in the dense one): measured 6e-8 .. 1e-7 relative; tolerance 1e-5 */
    printf("  γ = %.0e: max |x - x_dense| = %.3g of %.3g\n", g, worst, scale);
    CS_EXPECT(worst <= 1e-5 * scale);
    free(ref);
  }
  free(M);
  N_VDestroy(fy);
  N_VDestroy(t1);
  N_VDestroy(t2);
  N_VDestroy(t3);
  N_VDestroy(xv);
  N_VDestroy(bv);
  csr_rodDataDestroy(d);
  csr_rodModelDestroy(m);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(block_tridiagonal_solve);
  CS_RUN(reduced_solve_matches_dense);
  return cs_testSummary();
}

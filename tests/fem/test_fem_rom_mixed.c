/* test_fem_rom_mixed.c: the mixed reduced model (fem_rom.h csfRom.m: element pressures on
 * their own reduced basis) against the displacement-only one and the full FE on a clamped,
 * nearly incompressible block (kappa = CSF_KAPPA_RATIO mu0, the FE's default) bent by gravity
 * in two directions: trained on the two directions, held out along the diagonal between them.
 * Shows that the displacement-only POD model locks there (its error many times the basis' best
 * projection) and the mixed one does not; the mixed residual's tangent against central
 * differences; with every element's pressure free (P = I) the mixed model is the FE's P2/P0
 * model: the same residual and tangent, and the full displacement basis lands on the FE's
 * equilibrium. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "fem_assembly.h"
#include "fem_element.h"
#include "fem_rom.h"
#include "fem_test_util.h"

#define C10 0.11
/* mm/s^2: the 8 mm block's tip deflects about 1 mm (7 deg at the tip: moderately nonlinear, so
 * the held-out diagonal state is not the sum of the trained ones) */
#define GMAX 1e5
#define NSTEP 4    /* FE and rom load steps per ray; the snapshots are the FE's four states */

typedef struct Block_ {
  csfMesh* me;
  csfModel* m;
  csfData* d;
} Block;

/* a block 2 x 1.5 x L mm clamped at z = 0 (nx x nx x nz cubes of six Tet10s), bulk modulus
 * kappa_ratio mu0 */
static void blockCreate(Block* b, int nx, int nz, double L, double kappa_ratio) {
  csError err = {0};
  int n[3] = {nx, nx, nz};
  double sc[3] = {2.0, 1.5, L};
  b->me = csf_meshCreateBox(n, ftScaleMap, sc, 0.0, &err);
  csfMaterial mat = csf_materialDefault(C10, 0.02, 1130e-12);
  mat.kappa = kappa_ratio * 2 * C10;
  b->m = csf_modelCreate(b->me, &mat, &err);
  for (int dir = 0; dir < 3; dir++) {
    ftFix(b->m, 2, 0.0, dir, 0.0);
  }
  CS_EXPECT(csf_modelFinalize(b->m, &err) == CS_OK);
  b->d = csf_dataCreate(b->m, &err);
  CS_EXPECT(b->d != NULL);
}

static void blockDestroy(Block* b) {
  csf_dataDestroy(b->d);
  csf_modelDestroy(b->m);
  csf_meshDestroy(b->me);
}

/* the FE's states along gravity g_end s / NSTEP, s = 1..NSTEP, into U (ndof x NSTEP, column s-1) */
static void feRay(Block* b, const double g_end[3], double* U) {
  csError err = {0};
  const int nd = b->m->ndof;
  csfNewtonOptions o = csf_newtonDefault();
  memset(b->d->u, 0, (size_t)nd * sizeof(double));
  csf_dataSyncVolume(b->m, b->d);
  for (int s = 1; s <= NSTEP; s++) {
    for (int i = 0; i < 3; i++) {
      b->m->gravity[i] = g_end[i] * s / NSTEP;
    }
    const csStatus st = csf_newtonSolve(b->m, b->d, 0.0, &o, NULL, &err);
    if (st != CS_OK) {
      printf("  FE step %d: %s\n", s, err.msg);
    }
    CS_EXPECT(st == CS_OK);
    for (int i = 0; i < nd; i++) {
      U[(size_t)i * NSTEP + (s - 1)] = b->d->u[i];
    }
  }
}

/* the element pressures kappa (v_e / V_e - 1) of displacement u (the FE's condensed P0 field) */
static void elementPressures(const csfModel* m, const double* u, double* p) {
  for (int e = 0; e < m->mesh->ntet; e++) {
    double ue[30], re[30], gv[30], vr, jm;
    for (int a = 0; a < 10; a++) {
      for (int i = 0; i < 3; i++) {
        ue[3 * a + i] = u[3 * m->mesh->tet[10 * e + a] + i];
      }
    }
    CS_EXPECT(csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e,
                            m->vol[e], ue, 1.0, re, NULL, &vr, gv, &jm) == 0);
    p[e] = m->mat.kappa * (vr - 1.0);
  }
}

/* Gram-Schmidt (twice) of the columns of X (rows x cols) in the inner product sum_i w_i x_i y_i
 * (w NULL: Euclidean) into Q (rows x ncol_max); columns whose remainder is below 1e-8 of their
 * norm are dropped; returns the number kept */
static int orthonormal(int rows, int cols, const double* X, const double* w, double* Q, int qmax) {
  int k = 0;
  double* v = malloc((size_t)rows * sizeof(double));
  for (int c = 0; c < cols && k < qmax; c++) {
    double n0 = 0;
    for (int i = 0; i < rows; i++) {
      v[i] = X[(size_t)i * cols + c];
      n0 += (w ? w[i] : 1.0) * v[i] * v[i];
    }
    for (int pass = 0; pass < 2; pass++) {
      for (int j = 0; j < k; j++) {
        double s = 0;
        for (int i = 0; i < rows; i++) {
          s += (w ? w[i] : 1.0) * Q[(size_t)i * qmax + j] * v[i];
        }
        for (int i = 0; i < rows; i++) {
          v[i] -= s * Q[(size_t)i * qmax + j];
        }
      }
    }
    double n1 = 0;
    for (int i = 0; i < rows; i++) {
      n1 += (w ? w[i] : 1.0) * v[i] * v[i];
    }
    if (!(n1 > 1e-16 * n0) || n0 == 0.0) {
      continue;
    }
    for (int i = 0; i < rows; i++) {
      Q[(size_t)i * qmax + k] = v[i] / sqrt(n1);
    }
    k++;
  }
  free(v);
  return k;
}

/* compact the first k of qmax columns of Q into a (rows x k) array */
static double* compact(int rows, int qmax, int k, const double* Q) {
  double* V = malloc((size_t)rows * (size_t)k * sizeof(double));
  for (int i = 0; i < rows; i++) {
    memcpy(V + (size_t)i * k, Q + (size_t)i * qmax, (size_t)k * sizeof(double));
  }
  return V;
}

/* The supremizers of the pressure modes P (ntet x mp): s_k = X^-1 B^T P_k with B^T p = sum_e p_e
 * g_e (g_e = dv_e/du at rest, the discrete divergence) and X the H1 product of the displacement
 * (the vector Laplacian sum_e int grad N_a . grad N_b delta_ij over the free dofs: the supremizer
 * of reduced Stokes, Rozza and Veroy 2007, Ballarin et al. 2015), by a dense Cholesky (the
 * block has < 1000 free dofs), into S (ndof x mp). */
static void supremizers(const csfModel* m, int mp, const double* P, double* S) {
  const int nd = m->ndof, ntet = m->mesh->ntet;
  int* idx = malloc((size_t)nd * sizeof(int));
  int nf = 0;
  for (int i = 0; i < nd; i++) {
    idx[i] = m->fixed[i] ? -1 : nf++;
  }
  double* X = calloc((size_t)nf * nf, sizeof(double));
  double* R = calloc((size_t)nf * mp, sizeof(double));
  const double zero[30] = {0};
  for (int e = 0; e < ntet; e++) {
    const int* tv = m->mesh->tet + 10 * e;
    const double* dN = m->dNdX + 120 * (size_t)e;
    const double* wq = m->wq + 4 * (size_t)e;
    for (int g = 0; g < 4; g++) {
      for (int a = 0; a < 10; a++) {
        for (int c = 0; c < 10; c++) {
          const double* da = dN + 30 * g + 3 * a;
          const double* dc = dN + 30 * g + 3 * c;
          const double k = wq[g] * (da[0] * dc[0] + da[1] * dc[1] + da[2] * dc[2]);
          for (int i = 0; i < 3; i++) {
            const int r = idx[3 * tv[a] + i], cc = idx[3 * tv[c] + i];
            if (r >= 0 && cc >= 0) {
              X[(size_t)r * nf + cc] += k;
            }
          }
        }
      }
    }
    double re[30], gv[30], vr, jm;
    CS_EXPECT(csf_tetKernel(&m->mat, dN, wq, m->vol[e], zero, 1.0, re, NULL, &vr, gv, &jm) == 0);
    for (int a = 0; a < 30; a++) {
      const int r = idx[3 * tv[a / 3] + a % 3];
      for (int k = 0; r >= 0 && k < mp; k++) {
        R[(size_t)r * mp + k] += P[(size_t)e * mp + k] * gv[a];
      }
    }
  }
  for (int j = 0; j < nf; j++) { /* Cholesky, lower */
    double sj = X[(size_t)j * nf + j];
    for (int k = 0; k < j; k++) {
      sj -= X[(size_t)j * nf + k] * X[(size_t)j * nf + k];
    }
    CS_EXPECT(sj > 0);
    X[(size_t)j * nf + j] = sqrt(sj);
    for (int i = j + 1; i < nf; i++) {
      double t = X[(size_t)i * nf + j];
      for (int k = 0; k < j; k++) {
        t -= X[(size_t)i * nf + k] * X[(size_t)j * nf + k];
      }
      X[(size_t)i * nf + j] = t / X[(size_t)j * nf + j];
    }
  }
  for (int k = 0; k < mp; k++) {
    for (int i = 0; i < nf; i++) {
      double t = R[(size_t)i * mp + k];
      for (int l = 0; l < i; l++) {
        t -= X[(size_t)i * nf + l] * R[(size_t)l * mp + k];
      }
      R[(size_t)i * mp + k] = t / X[(size_t)i * nf + i];
    }
    for (int i = nf - 1; i >= 0; i--) {
      double t = R[(size_t)i * mp + k];
      for (int l = i + 1; l < nf; l++) {
        t -= X[(size_t)l * nf + i] * R[(size_t)l * mp + k];
      }
      R[(size_t)i * mp + k] = t / X[(size_t)i * nf + i];
    }
  }
  for (int i = 0; i < nd; i++) {
    for (int k = 0; k < mp; k++) {
      S[(size_t)i * mp + k] = idx[i] >= 0 ? R[(size_t)idx[i] * mp + k] : 0.0;
    }
  }
  free(idx), free(X), free(R);
}

/* the rom's states along gravity g_end (the FE's load steps, each from the last); CS_OK or the
 * failing step's status */
static csStatus romRay(const csfRom* r, csfRomData* d, const double g_end[3], csError* err) {
  csfRomNewtonOptions o = csf_romNewtonDefault();
  csf_romDataReset(r, d);
  for (int s = 1; s <= NSTEP; s++) {
    csfRomLoad ld = {NULL, {g_end[0] * s / NSTEP, g_end[1] * s / NSTEP, g_end[2] * s / NSTEP},
                     NULL};
    csStatus st = csf_romNewton(r, d, &ld, &o, NULL, err);
    if (st != CS_OK) {
      printf("  rom step %d: %s\n", s, err->msg);
      return st;
    }
  }
  return CS_OK;
}

static double norm2(int n, const double* a) {
  double s = 0;
  for (int i = 0; i < n; i++) {
    s += a[i] * a[i];
  }
  return sqrt(s);
}

/* Trained on gravity along -e1 and -e2 (four FE states each), held out along their diagonal:
 * the basis' best projection of the held-out state is close, the displacement-only Galerkin
 * solution is many times farther (locking), the mixed one is near the best projection. */
static void lockingStudy(double kappa_ratio, double res[4]) {
  Block b;
  blockCreate(&b, 2, 6, 8.0, kappa_ratio);
  const csfModel* m = b.m;
  const int nd = m->ndof, ntet = m->mesh->ntet;
  double* U = malloc((size_t)nd * 2 * NSTEP * sizeof(double));
  double* Ur = malloc((size_t)nd * NSTEP * sizeof(double));
  const double gx[3] = {-GMAX, 0, 0}, gy[3] = {0, -GMAX, 0};
  feRay(&b, gx, Ur);
  for (int i = 0; i < nd; i++) {
    memcpy(U + (size_t)i * 2 * NSTEP, Ur + (size_t)i * NSTEP, NSTEP * sizeof(double));
  }
  feRay(&b, gy, Ur);
  for (int i = 0; i < nd; i++) {
    memcpy(U + (size_t)i * 2 * NSTEP + NSTEP, Ur + (size_t)i * NSTEP, NSTEP * sizeof(double));
  }
  const double gd[3] = {-GMAX / sqrt(2.0), -GMAX / sqrt(2.0), 0};
  feRay(&b, gd, Ur);
  double* u_fe = malloc((size_t)nd * sizeof(double));
  for (int i = 0; i < nd; i++) {
    u_fe[i] = Ur[(size_t)i * NSTEP + NSTEP - 1];
  }
  /* displacement basis: the 8 training states (Euclidean) */
  double* Q = malloc((size_t)nd * 2 * NSTEP * sizeof(double));
  const int n = orthonormal(nd, 2 * NSTEP, U, NULL, Q, 2 * NSTEP);
  double* V = compact(nd, 2 * NSTEP, n, Q);
  /* pressure basis: the training states' element pressures (volume-weighted) */
  double* Pp = malloc((size_t)ntet * 2 * NSTEP * sizeof(double));
  double* pe = malloc((size_t)ntet * sizeof(double));
  double* col = malloc((size_t)nd * sizeof(double));
  for (int c = 0; c < 2 * NSTEP; c++) {
    for (int i = 0; i < nd; i++) {
      col[i] = U[(size_t)i * 2 * NSTEP + c];
    }
    elementPressures(m, col, pe);
    for (int e = 0; e < ntet; e++) {
      Pp[(size_t)e * 2 * NSTEP + c] = pe[e];
    }
  }
  double* QP = malloc((size_t)ntet * 2 * NSTEP * sizeof(double));
  const int mp0 = orthonormal(ntet, 2 * NSTEP, Pp, m->vol, QP, 2 * NSTEP);
  const int mp = mp0;
  double* P = compact(ntet, 2 * NSTEP, mp, QP);
  /* best projection V V^T u_fe */
  double* q = calloc((size_t)n, sizeof(double));
  double* u = malloc((size_t)nd * sizeof(double));
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < nd; i++) {
      q[j] += V[(size_t)i * n + j] * u_fe[i];
    }
  }
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  csf_romExpand(r, q, u);
  for (int i = 0; i < nd; i++) {
    u[i] -= u_fe[i];
  }
  const double e_best = norm2(nd, u), un = norm2(nd, u_fe);
  /* displacement-only */
  csfRomData* d = csf_romDataCreate(r, &err);
  CS_EXPECT(romRay(r, d, gd, &err) == CS_OK);
  csf_romExpand(r, d->q, u);
  for (int i = 0; i < nd; i++) {
    u[i] -= u_fe[i];
  }
  const double e_disp = norm2(nd, u);
  csf_romDataDestroy(d);
  /* mixed */
  CS_EXPECT(csf_romSetPressureBasis(r, mp, P, &err) == CS_OK);
  d = csf_romDataCreate(r, &err);
  CS_EXPECT(romRay(r, d, gd, &err) == CS_OK);
  csf_romExpand(r, d->q, u);
  for (int i = 0; i < nd; i++) {
    u[i] -= u_fe[i];
  }
  const double e_mixed = norm2(nd, u);
  csf_romDataDestroy(d);
  csf_romDestroy(r);
  /* mixed, the displacement basis enriched by the pressure modes' supremizers */
  double* S = malloc((size_t)nd * mp * sizeof(double));
  supremizers(m, mp, P, S);
  double* US = malloc((size_t)nd * (2 * NSTEP + mp) * sizeof(double));
  const int ns = 2 * NSTEP + mp;
  for (int i = 0; i < nd; i++) {
    memcpy(US + (size_t)i * ns, U + (size_t)i * 2 * NSTEP, 2 * NSTEP * sizeof(double));
    memcpy(US + (size_t)i * ns + 2 * NSTEP, S + (size_t)i * mp, (size_t)mp * sizeof(double));
  }
  double* QS = malloc((size_t)nd * ns * sizeof(double));
  const int n2 = orthonormal(nd, ns, US, NULL, QS, ns);
  double* V2 = compact(nd, ns, n2, QS);
  r = csf_romCreate(m, n2, V2, &err);
  CS_EXPECT(csf_romSetPressureBasis(r, mp, P, &err) == CS_OK);
  d = csf_romDataCreate(r, &err);
  CS_EXPECT(romRay(r, d, gd, &err) == CS_OK);
  csf_romExpand(r, d->q, u);
  for (int i = 0; i < nd; i++) {
    u[i] -= u_fe[i];
  }
  const double e_sup = norm2(nd, u);
  /* the trained rays come back with the mixed model too (their states lie in the span) */
  double e_train = 0;
  CS_EXPECT(romRay(r, d, gy, &err) == CS_OK);
  csf_romExpand(r, d->q, u);
  for (int i = 0; i < nd; i++) {
    e_train = fmax(e_train, fabs(u[i] - U[(size_t)i * 2 * NSTEP + 2 * NSTEP - 1]));
  }
  CS_EXPECT(romRay(r, d, gx, &err) == CS_OK);
  csf_romExpand(r, d->q, u);
  for (int i = 0; i < nd; i++) {
    e_train = fmax(e_train, fabs(u[i] - U[(size_t)i * 2 * NSTEP + NSTEP - 1]));
  }
  printf("  kappa = %g mu0: n = %d displacement modes, m = %d pressure modes; held-out |u_fe| = "
         "%.3f mm (l2)\n    best projection %.3e mm, displacement-only %.3e (%.1fx the best), "
         "mixed %.3e (%.1fx), mixed + supremizers (n = %d) %.3e (%.1fx); trained states, mixed + "
         "supremizers: max %.2e mm\n", kappa_ratio, n, mp, un, e_best, e_disp, e_disp / e_best,
         e_mixed, e_mixed / e_best, n2, e_sup, e_sup / e_best, e_train);
  /* the trained states lie in the span and their pressures in P's: Newton's tolerance */
  CS_EXPECT_NEAR(e_train / un, 0.0, 1e-6, 0);
  res[0] = e_best, res[1] = e_disp, res[2] = e_mixed, res[3] = e_sup;
  csf_romDataDestroy(d);
  csf_romDestroy(r);
  free(U), free(Ur), free(u_fe), free(Q), free(V), free(Pp), free(pe), free(col), free(QP);
  free(P), free(q), free(u), free(S), free(US), free(QS), free(V2);
  blockDestroy(&b);
}

/* The locking ratio: the Galerkin solution's error over the basis' best projection on the
 * held-out state. At kappa = 2 mu0 (nu = 0.4: nothing to lock) it measures what any Galerkin
 * model on this span loses to the nonlinearity; at the FE's kappa the displacement-only model
 * loses much more (volumetric locking), and the mixed model does not. */
static void test_displacement_pod_locks_and_the_mixed_model_does_not(void) {
  double comp[4], inc[4];
  lockingStudy(2.0, comp);
  lockingStudy(CSF_KAPPA_RATIO, inc);
  const double ratio_comp = comp[1] / comp[0], ratio_disp = inc[1] / inc[0],
               ratio_mixed = inc[2] / inc[0], ratio_sup = inc[3] / inc[0];
  printf("  locking ratio (error / best projection): compressible %.1f; incompressible: "
         "displacement-only %.1f, mixed %.1f, mixed + supremizers %.1f\n", ratio_comp, ratio_disp,
         ratio_mixed, ratio_sup);
  /* measured 14.5 / 21.1 / 9.7 / 9.8: the displacement-only model locks (its ratio 1.45x the
   * compressible one) and the mixed models do not (at or below the compressible ratio, less
   * than half the displacement-only error); margins of a third of the measured gaps */
  CS_EXPECT(ratio_disp > 1.3 * ratio_comp);
  CS_EXPECT(ratio_mixed < ratio_comp && ratio_sup < ratio_comp);
  CS_EXPECT(inc[2] < 0.6 * inc[1] && inc[3] < 0.6 * inc[1]);
}

/* a random basis (ndof x n, zero on clamped dofs) that grows with z from the clamp */
static double* randomBasis(const csfModel* m, int n, unsigned seed, double amp) {
  double* V = calloc((size_t)m->ndof * n, sizeof(double));
  srand(seed);
  for (int i = 0; i < m->ndof; i++) {
    for (int j = 0; !m->fixed[i] && j < n; j++) {
      V[(size_t)i * n + j] = amp * ((double)rand() / RAND_MAX - 0.5) * m->mesh->x[3 * (i / 3) + 2];
    }
  }
  return V;
}

/* With one free pressure per element (P = I) the mixed model is the FE's condensed P2/P0 model:
 * r and K equal the displacement-only rom's (itself V^T R, V^T K V of the FE, test_fem_rom);
 * with a smaller random pressure basis, K equals the central differences of r and is symmetric */
static void test_mixed_residual_and_tangent_against_p2p0_and_finite_differences(void) {
  Block b;
  blockCreate(&b, 1, 3, 4.0, 50.0); /* moderate kappa: a well-conditioned FD check */
  const csfModel* m = b.m;
  const int n = 5, ntet = m->mesh->ntet;
  double* V = randomBasis(m, n, 7, 0.05);
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  csfRomData* d = csf_romDataCreate(r, &err);
  d->sync = 1;
  const double q[5] = {0.8, -0.6, 0.5, 0.3, -0.7};
  memcpy(d->q, q, sizeof q);
  csfRomLoad ld = {NULL, {0, -GMAX, 2e4}, NULL};
  CS_EXPECT(csf_romEvaluate(r, d, &ld, 1) == 0);
  double r0[5], K0[25];
  memcpy(r0, d->r, sizeof r0);
  memcpy(K0, d->K, sizeof K0);
  csf_romDataDestroy(d);
  double* P = calloc((size_t)ntet * ntet, sizeof(double));
  for (int e = 0; e < ntet; e++) {
    P[(size_t)e * ntet + e] = 1.0;
  }
  CS_EXPECT(csf_romSetPressureBasis(r, ntet, P, &err) == CS_OK);
  d = csf_romDataCreate(r, &err);
  d->sync = 1;
  memcpy(d->q, q, sizeof q);
  CS_EXPECT(csf_romEvaluate(r, d, &ld, 1) == 0);
  double er = 0, ek = 0, mr = 0, mk = 0;
  for (int i = 0; i < n; i++) {
    er = fmax(er, fabs(d->r[i] - r0[i]));
    mr = fmax(mr, fabs(r0[i]));
    for (int j = 0; j < n; j++) {
      ek = fmax(ek, fabs(d->K[i * n + j] - K0[i * n + j]));
      mk = fmax(mk, fabs(K0[i * n + j]));
    }
  }
  printf("  P = I (%d elements): |r - r_P2P0| %.2e of %.2e, |K - K_P2P0| %.2e of %.2e\n", ntet,
         er, mr, ek, mk);
  /* the same sums regrouped: round-off */
  CS_EXPECT_NEAR(er / mr, 0.0, 1e-12, 0);
  CS_EXPECT_NEAR(ek / mk, 0.0, 1e-12, 0);
  csf_romDataDestroy(d);
  /* a random pressure basis of 4 modes */
  const int mp = 4;
  srand(3);
  for (int e = 0; e < ntet; e++) {
    for (int k = 0; k < mp; k++) {
      P[(size_t)e * mp + k] = (double)rand() / RAND_MAX - 0.3;
    }
  }
  CS_EXPECT(csf_romSetPressureBasis(r, mp, P, &err) == CS_OK);
  d = csf_romDataCreate(r, &err);
  d->sync = 1;
  memcpy(d->q, q, sizeof q);
  CS_EXPECT(csf_romEvaluate(r, d, &ld, 1) == 0);
  double K[25], rp[5];
  memcpy(K, d->K, sizeof K);
  mk = 0;
  for (int i = 0; i < n * n; i++) {
    mk = fmax(mk, fabs(K[i]));
  }
  const double h = 1e-6; /* truncation ~h^2 |d3r|, round-off ~1e-16 |r| / h */
  double efd = 0, asym = 0;
  for (int j = 0; j < n; j++) {
    d->q[j] = q[j] + h;
    csf_romEvaluate(r, d, &ld, 0);
    memcpy(rp, d->r, sizeof rp);
    d->q[j] = q[j] - h;
    csf_romEvaluate(r, d, &ld, 0);
    d->q[j] = q[j];
    for (int i = 0; i < n; i++) {
      efd = fmax(efd, fabs((rp[i] - d->r[i]) / (2 * h) - K[i * n + j]));
      asym = fmax(asym, fabs(K[i * n + j] - K[j * n + i]));
    }
  }
  printf("  m = %d random pressure modes: max |K - K_fd| / max |K| = %.2e, asymmetry %.2e\n", mp,
         efd / mk, asym / mk);
  /* as test_fem_rom: a missing or wrong term is 1e-2 or more */
  CS_EXPECT_NEAR(efd / mk, 0.0, 1e-6, 0);
  CS_EXPECT_NEAR(asym / mk, 0.0, 1e-12, 0);
  /* a pressure mode without support in the kept elements is refused: mode 0 lives on element
   * 0 alone, and only element 1 is kept */
  memset(P, 0, (size_t)ntet * 2 * sizeof(double));
  P[0] = 1.0;
  for (int e = 0; e < ntet; e++) {
    P[(size_t)e * 2 + 1] = 1.0;
  }
  CS_EXPECT(csf_romSetPressureBasis(r, 2, P, &err) == CS_OK);
  int one = 1;
  double w1 = 1.0;
  CS_EXPECT(csf_romSetWeights(r, CSF_ROM_SET_TET, 1, &one, &w1, &err) == CS_ERR_ARG);
  free(V), free(P);
  csf_romDataDestroy(d);
  csf_romDestroy(r);
  blockDestroy(&b);
}

/* The mixed model's ECSW rows (csf_romElementForces, n + m per Tet10): their column sums are the
 * unreduced residual and b = A p^; every Tet10 at weight 1 in another order is the unreduced
 * model; on a hyper-reduced set (half the Tet10s, uneven weights) r and K stay conservative: K
 * equals r's central differences and is symmetric */
static void test_mixed_ecsw_rows_sum_to_the_model_and_weights_keep_the_tangent_exact(void) {
  Block b;
  blockCreate(&b, 1, 3, 4.0, 50.0);
  const csfModel* m = b.m;
  const int n = 5, mp = 4, ntet = m->mesh->ntet, wd = n + mp;
  double* V = randomBasis(m, n, 11, 0.05);
  double* P = malloc((size_t)ntet * mp * sizeof(double));
  srand(5);
  for (int i = 0; i < ntet * mp; i++) {
    P[i] = (double)rand() / RAND_MAX - 0.3;
  }
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  CS_EXPECT(csf_romSetPressureBasis(r, mp, P, &err) == CS_OK);
  CS_EXPECT(csf_romElementForcesWidth(r, CSF_ROM_SET_TET) == wd);
  CS_EXPECT(csf_romElementForcesWidth(r, CSF_ROM_SET_FIBRE) == n);
  csfRomData* d = csf_romDataCreate(r, &err);
  d->sync = 1;
  const double q[5] = {0.7, -0.5, 0.6, -0.2, 0.4};
  memcpy(d->q, q, sizeof q);
  csfRomLoad ld = {NULL, {0, 0, 0}, NULL}; /* no load: r is the Tet10s' internal force */
  CS_EXPECT(csf_romEvaluate(r, d, &ld, 1) == 0);
  double r_all[5], ph[4], K_all[25];
  memcpy(r_all, d->r, sizeof r_all);
  memcpy(ph, d->ph, sizeof ph);
  memcpy(K_all, d->K, sizeof K_all);
  double* G = malloc((size_t)ntet * wd * sizeof(double));
  CS_EXPECT(csf_romElementForces(r, d, &ld, CSF_ROM_SET_TET, G) == 0);
  double sr[5] = {0}, sb[4] = {0}, Ab[4] = {0};
  for (int e = 0; e < ntet; e++) {
    for (int j = 0; j < n; j++) {
      sr[j] += G[(size_t)e * wd + j];
    }
    for (int i = 0; i < mp; i++) {
      sb[i] += G[(size_t)e * wd + n + i];
      /* A p^ with A = sum_e (V_e / kappa) P_e P_e^T, from its definition */
      for (int j = 0; j < mp; j++) {
        Ab[i] += m->vol[e] / m->mat.kappa * P[(size_t)e * mp + i] * P[(size_t)e * mp + j] * ph[j];
      }
    }
  }
  double er = 0, mr = 0, eb = 0, mb = 0;
  for (int j = 0; j < n; j++) {
    er = fmax(er, fabs(sr[j] - r_all[j]));
    mr = fmax(mr, fabs(r_all[j]));
  }
  for (int i = 0; i < mp; i++) {
    eb = fmax(eb, fabs(sb[i] - Ab[i]));
    mb = fmax(mb, fabs(Ab[i]));
  }
  printf("  ECSW rows: sum of the force rows - r %.2e of %.2e, sum of the constraint rows - "
         "A p^ %.2e of %.2e\n", er, mr, eb, mb);
  /* the same sums regrouped (and A p^ = b through a Cholesky solve of m = 4): round-off */
  CS_EXPECT(mr > 0 && mb > 0);
  CS_EXPECT_NEAR(er / mr, 0.0, 1e-12, 0);
  CS_EXPECT_NEAR(eb / mb, 0.0, 1e-10, 0);
  /* every Tet10 at weight 1, in reversed order: the unreduced model */
  int* idx = malloc((size_t)ntet * sizeof(int));
  double* w = malloc((size_t)ntet * sizeof(double));
  for (int e = 0; e < ntet; e++) {
    idx[e] = ntet - 1 - e, w[e] = 1.0;
  }
  CS_EXPECT(csf_romSetWeights(r, CSF_ROM_SET_TET, ntet, idx, w, &err) == CS_OK);
  CS_EXPECT(csf_romEvaluate(r, d, &ld, 1) == 0);
  double e1 = 0, ek1 = 0, mk = 0;
  for (int j = 0; j < n; j++) {
    e1 = fmax(e1, fabs(d->r[j] - r_all[j]));
  }
  for (int i = 0; i < n * n; i++) {
    ek1 = fmax(ek1, fabs(d->K[i] - K_all[i]));
    mk = fmax(mk, fabs(K_all[i]));
  }
  printf("  every Tet10 at weight 1 (reversed): |r - r_all| %.2e, |K - K_all| %.2e of %.2e\n",
         e1 / mr, ek1, mk);
  CS_EXPECT_NEAR(e1 / mr, 0.0, 1e-12, 0);
  CS_EXPECT_NEAR(ek1 / mk, 0.0, 1e-12, 0);
  /* half the Tet10s with weights in [0.5, 2.5): r changes, K stays its exact derivative */
  int nk = 0;
  for (int e = 0; e < ntet; e += 2) {
    idx[nk] = e, w[nk] = 0.5 + 2.0 * rand() / RAND_MAX;
    nk++;
  }
  CS_EXPECT(csf_romSetWeights(r, CSF_ROM_SET_TET, nk, idx, w, &err) == CS_OK);
  CS_EXPECT(csf_romEvaluate(r, d, &ld, 1) == 0);
  double K[25], rp[5], dr = 0;
  memcpy(K, d->K, sizeof K);
  for (int j = 0; j < n; j++) {
    dr = fmax(dr, fabs(d->r[j] - r_all[j]));
  }
  mk = 0;
  for (int i = 0; i < n * n; i++) {
    mk = fmax(mk, fabs(K[i]));
  }
  const double h = 1e-6; /* as the test above */
  double efd = 0, asym = 0;
  for (int j = 0; j < n; j++) {
    d->q[j] = q[j] + h;
    csf_romEvaluate(r, d, &ld, 0);
    memcpy(rp, d->r, sizeof rp);
    d->q[j] = q[j] - h;
    csf_romEvaluate(r, d, &ld, 0);
    d->q[j] = q[j];
    for (int i = 0; i < n; i++) {
      efd = fmax(efd, fabs((rp[i] - d->r[i]) / (2 * h) - K[i * n + j]));
      asym = fmax(asym, fabs(K[i * n + j] - K[j * n + i]));
    }
  }
  printf("  %d of %d Tet10s kept, uneven weights: r moved %.2e of %.2e (the weights act); max |K - "
         "K_fd| / max |K| = %.2e, asymmetry %.2e\n", nk, ntet, dr, mr, efd / mk, asym / mk);
  CS_EXPECT(dr > 1e-3 * mr);
  CS_EXPECT_NEAR(efd / mk, 0.0, 1e-6, 0);
  CS_EXPECT_NEAR(asym / mk, 0.0, 1e-12, 0);
  free(G), free(idx), free(w), free(V), free(P);
  csf_romDataDestroy(d);
  csf_romDestroy(r);
  blockDestroy(&b);
}

/* The full displacement basis (every free dof) and P = I: the reduced Newton lands on the FE's
 * equilibrium (the same nearly incompressible block, gravity across) */
static void test_full_bases_reproduce_the_fe_solution(void) {
  Block b;
  blockCreate(&b, 1, 4, 6.0, CSF_KAPPA_RATIO);
  const csfModel* m = b.m;
  const int nd = m->ndof, ntet = m->mesh->ntet;
  const double g[3] = {-0.5 * GMAX, -GMAX, 0};
  double* U = malloc((size_t)nd * NSTEP * sizeof(double));
  feRay(&b, g, U);
  int n = 0;
  for (int i = 0; i < nd; i++) {
    n += !m->fixed[i];
  }
  double* V = calloc((size_t)nd * n, sizeof(double));
  for (int i = 0, j = 0; i < nd; i++) {
    if (!m->fixed[i]) {
      V[(size_t)i * n + j++] = 1.0;
    }
  }
  double* P = calloc((size_t)ntet * ntet, sizeof(double));
  for (int e = 0; e < ntet; e++) {
    P[(size_t)e * ntet + e] = 1.0;
  }
  csError err = {0};
  csfRom* r = csf_romCreate(m, n, V, &err);
  CS_EXPECT(csf_romSetPressureBasis(r, ntet, P, &err) == CS_OK);
  csfRomData* d = csf_romDataCreate(r, &err);
  CS_EXPECT(romRay(r, d, g, &err) == CS_OK);
  double* u = malloc((size_t)nd * sizeof(double));
  csf_romExpand(r, d->q, u);
  double e = 0, umax = 0;
  for (int i = 0; i < nd; i++) {
    e = fmax(e, fabs(u[i] - U[(size_t)i * NSTEP + NSTEP - 1]));
    umax = fmax(umax, fabs(U[(size_t)i * NSTEP + NSTEP - 1]));
  }
  printf("  full bases (n = %d, m = %d): max |u_rom - u_fe| = %.2e mm of %.3f mm (%ld Newton "
         "iterations)\n", n, ntet, e, umax, d->n_newton);
  /* both Newton solves stop at |R| <= 1e-8 (|f_int| + |f_ext|) */
  CS_EXPECT_NEAR(e / umax, 0.0, 1e-6, 0);
  free(U), free(V), free(P), free(u);
  csf_romDataDestroy(d);
  csf_romDestroy(r);
  blockDestroy(&b);
}

int main(void) {
  CS_RUN(test_mixed_residual_and_tangent_against_p2p0_and_finite_differences);
  CS_RUN(test_mixed_ecsw_rows_sum_to_the_model_and_weights_keep_the_tangent_exact);
  CS_RUN(test_full_bases_reproduce_the_fe_solution);

  CS_RUN(test_displacement_pod_locks_and_the_mixed_model_does_not);
  return cs_testSummary();
}

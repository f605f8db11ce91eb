/* robot_rom_model.c: the reduced-order FE leg's model (robot_rom.h): its parameters' defaults,
 * the consistent mass operators of the reduced span in the hip's floating frame (one pass over
 * the Tet10s with a collapsed Gauss rule), the damping and the model's lifetime. What a run
 * changes (the state, CVODE, the base motion) is robot_rom.c's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "fem_mesh.h"
#include "robot_rom.h"


csrRomParams csr_romDefaultParams(void) {
  csrRomParams p;
  p.rho = 1.07e-9;          /* the silicone's density (fem_material.h's default rho) */
  p.damping_time = 2e-3;    /* s: the rod's csrLegParams default is of this order */
  p.rtol = 1e-6;
  p.atol_u = 1e-5; /* mm: 10 nm of displacement */
  p.atol_wrench = 1e-4;
  p.max_steps = 20000;
  p.tangent_lag = 0;
  p.gravity[0] = p.gravity[1] = p.gravity[2] = 0;
  return p;
}


/* ---- mass operators --------------------------------------------------------------------- */

/* collapsed Gauss rule on the unit tetrahedron: 4 Gauss-Legendre points per direction (64
 * points, exact for polynomials of degree 7: N_a N_b is of degree 4, times the Jacobian of a
 * curved Tet10 of degree 6), as tools/rom_basis.py's tet_rule(4) */
static void tetRule(double pts[64][3], double wts[64]) {
  static const double g[4] = {0.5 - 0.5 * 0.8611363115940526, 0.5 - 0.5 * 0.3399810435848563,
                              0.5 + 0.5 * 0.3399810435848563, 0.5 + 0.5 * 0.8611363115940526};
  static const double w[4] = {0.5 * 0.3478548451374538, 0.5 * 0.6521451548625461,
                              0.5 * 0.6521451548625461, 0.5 * 0.3478548451374538};
  int k = 0;
  for (int i = 0; i < 4; i++) {
    for (int j = 0; j < 4; j++) {
      for (int l = 0; l < 4; l++) {
        const double a = g[i], b = g[j], c = g[l];
        pts[k][0] = a;
        pts[k][1] = b * (1 - a);
        pts[k][2] = c * (1 - a) * (1 - b);
        wts[k] = w[i] * w[j] * w[l] * (1 - a) * (1 - a) * (1 - b);
        k++;
      }
    }
  }
}


static double det3(const double J[9]) {
  return J[0] * (J[4] * J[8] - J[5] * J[7]) - J[1] * (J[3] * J[8] - J[5] * J[6]) +
         J[2] * (J[3] * J[7] - J[4] * J[6]);
}


/* the scalar consistent mass of Tet10 e (10 x 10, t) */
static int elementMass(const csfMesh* me, int e, double rho, double pts[64][3],
                       const double* wts, double Me[100]) {
  const int* tv = me->tet + 10 * e;
  memset(Me, 0, 100 * sizeof(double));
  for (int p = 0; p < 64; p++) {
    double N[10], dN[30], J[9] = {0};
    csf_tet10Shape(pts[p], N, dN);
    for (int a = 0; a < 10; a++) {
      const double* x = me->x + 3 * tv[a];
      for (int i = 0; i < 3; i++) {
        for (int d = 0; d < 3; d++) {
          J[3 * i + d] += x[i] * dN[3 * a + d];
        }
      }
    }
    const double det = det3(J);
    if (!(det > 0)) {
      return -1;
    }
    const double f = rho * wts[p] * det;
    for (int a = 0; a < 10; a++) {
      for (int b = 0; b < 10; b++) {
        Me[10 * a + b] += f * N[a] * N[b];
      }
    }
  }
  return 0;
}


/* in-place inverse of an SPD matrix (n x n) by Cholesky; -1 when not positive definite */
static int spdInverse(int n, const double* A, double* Ainv, double* L) {
  memcpy(L, A, (size_t)n * n * sizeof(double));
  for (int j = 0; j < n; j++) {
    double s = L[j * n + j];
    for (int k = 0; k < j; k++) {
      s -= L[j * n + k] * L[j * n + k];
    }
    if (!(s > 0)) {
      return -1;
    }
    L[j * n + j] = sqrt(s);
    for (int i = j + 1; i < n; i++) {
      double t = L[i * n + j];
      for (int k = 0; k < j; k++) {
        t -= L[i * n + k] * L[j * n + k];
      }
      L[i * n + j] = t / L[j * n + j];
    }
  }
  for (int c = 0; c < n; c++) {
    double* x = Ainv + (size_t)c * n; /* column c of the inverse, stored as row c (symmetric) */
    for (int i = 0; i < n; i++) {
      double t = i == c ? 1.0 : 0.0;
      for (int k = 0; k < i; k++) {
        t -= L[i * n + k] * x[k];
      }
      x[i] = t / L[i * n + i];
    }
    for (int i = n - 1; i >= 0; i--) {
      double t = x[i];
      for (int k = i + 1; k < n; k++) {
        t -= L[k * n + i] * x[k];
      }
      x[i] = t / L[i * n + i];
    }
  }
  return 0;
}


void csr_romModelDestroy(csrRomModel* m) {
  if (!m) {
    return;
  }
  free(m->Mr), free(m->Minv), free(m->C), free(m->T), free(m->e), free(m->Q), free(m->d);
  free(m->S), free(m->face_ch), free(m->Us), free(m->Ws);
  free(m);
}


/* the index of the pair (i, j), i <= j, in the order (00 11 22 01 02 12) */
static int pairIndex(int i, int j) {
  if (i == j) {
    return i;
  }
  return (i + j == 1) ? 3 : (i + j == 2 ? 4 : 5);
}


csrRomModel* csr_romModelCreate(const csfRom* rom, const csrRomParams* par, const int* face_ch,
                                csError* err) {
  if (!rom || !rom->fem || rom->n <= 0) {
    cs_errorSet(err, CS_ERR_ARG, "rom leg: no reduced model");
    return NULL;
  }
  csrRomParams p = par ? *par : csr_romDefaultParams();
  if (!(p.rho > 0) || !(p.damping_time >= 0) || !(p.rtol > 0) || !(p.atol_u > 0) ||
      !(p.atol_wrench > 0) || p.max_steps < 1 || !(p.tangent_lag >= 0) ||
      !isfinite(p.gravity[0] + p.gravity[1] + p.gravity[2])) {
    cs_errorSet(err, CS_ERR_RANGE, "rom leg: need rho > 0, damping_time >= 0, rtol, atol_u, "
                "atol_wrench > 0, max_steps >= 1, tangent_lag >= 0");
    return NULL;
  }
  const csfMesh* me = rom->fem->mesh;
  const int n = rom->n;
  const size_t nn = (size_t)n * n;
  csrRomModel* m = calloc(1, sizeof *m);
  double* P = calloc(9 * nn, sizeof(double)); /* P_ij = Σ_a (Me V)_{a,i}ᵀ V_{a,j} */
  double* pv = calloc(9 * (size_t)n, sizeof(double)); /* p_ij = Σ_a (Me V)_{a,i} X_{a,j} */
  double* MV = calloc(30 * (size_t)n, sizeof(double));
  double* L = calloc(nn, sizeof(double));
  if (!m || !P || !pv || !MV || !L) {
    free(P), free(pv), free(MV), free(L), free(m);
    cs_errorSet(err, CS_ERR_MEMORY, "rom leg: out of memory");
    return NULL;
  }
  m->rom = rom;
  m->n = n;
  m->par = p;
  m->nface = me->nface;
  m->Mr = calloc(nn, sizeof(double));
  m->Minv = calloc(nn, sizeof(double));
  m->C = calloc(nn, sizeof(double));
  m->T = calloc(3 * (size_t)n, sizeof(double));
  m->e = calloc(3 * (size_t)n, sizeof(double));
  m->Q = calloc(3 * nn, sizeof(double));
  m->d = calloc(6 * (size_t)n, sizeof(double));
  m->S = calloc(6 * nn, sizeof(double));
  m->face_ch = malloc((size_t)(me->nface > 0 ? me->nface : 1) * sizeof(int));
  csStatus st = CS_OK;
  if (!m->Mr || !m->Minv || !m->C || !m->T || !m->e || !m->Q || !m->d || !m->S || !m->face_ch) {
    st = cs_errorSet(err, CS_ERR_MEMORY, "rom leg: out of memory (n = %d)", n);
  }
  for (int f = 0; st == CS_OK && f < me->nface; f++) {
    m->face_ch[f] = face_ch ? face_ch[f] : -1;
    if (m->face_ch[f] < -1 || m->face_ch[f] >= 12) {
      st = cs_errorSet(err, CS_ERR_ARG, "rom leg: face %d in chamber %d (0..11 or -1)", f,
                       m->face_ch[f]);
    }
  }
  /* one pass over the Tet10s: the nine P_ij, the p_ij, mass, first and second moments */
  double pts[64][3], wts[64];
  tetRule(pts, wts);
  const double* V = rom->V;
  for (int e = 0; st == CS_OK && e < me->ntet; e++) {
    double Me[100];
    if (elementMass(me, e, p.rho, pts, wts, Me) != 0) {
      st = cs_errorSet(err, CS_ERR_ARG, "rom leg: Tet10 %d is inverted", e);
      break;
    }
    const int* tv = me->tet + 10 * e;
    memset(MV, 0, 30 * (size_t)n * sizeof(double));
    for (int a = 0; a < 10; a++) {
      const double* Xa = me->x + 3 * tv[a];
      for (int b = 0; b < 10; b++) {
        const double mab = Me[10 * a + b];
        const double* Xb = me->x + 3 * tv[b];
        m->mass += mab;
        for (int i = 0; i < 3; i++) {
          m->s0[i] += mab * Xb[i];
          for (int j = i; j < 3; j++) {
            m->J0[pairIndex(i, j)] += mab * Xa[i] * Xb[j];
          }
        }
        for (int i = 0; i < 3; i++) {
          const double* Vb = V + ((size_t)3 * tv[b] + i) * n;
          double* out = MV + ((size_t)3 * a + i) * n;
          for (int k = 0; k < n; k++) {
            out[k] += mab * Vb[k];
          }
        }
      }
    }
    for (int a = 0; a < 10; a++) {
      const double* Xa = me->x + 3 * tv[a];
      for (int i = 0; i < 3; i++) {
        const double* mv = MV + ((size_t)3 * a + i) * n;
        for (int j = 0; j < 3; j++) {
          double* pij = pv + (size_t)(3 * i + j) * n;
          for (int k = 0; k < n; k++) {
            pij[k] += mv[k] * Xa[j];
          }
          const double* Va = V + ((size_t)3 * tv[a] + j) * n;
          double* Pij = P + (size_t)(3 * i + j) * nn;
          for (int k = 0; k < n; k++) {
            if (mv[k] != 0) {
              for (int l = 0; l < n; l++) {
                Pij[(size_t)k * n + l] += mv[k] * Va[l];
              }
            }
          }
        }
      }
    }
  }
  if (st == CS_OK) {
#define PIJ(i, j) (P + (size_t)(3 * (i) + (j)) * nn)
#define PVIJ(i, j) (pv + (size_t)(3 * (i) + (j)) * n)
    for (size_t k = 0; k < nn; k++) {
      m->Mr[k] = PIJ(0, 0)[k] + PIJ(1, 1)[k] + PIJ(2, 2)[k];
      /* E_0 y = (0, -y2, y1), E_1 y = (y2, 0, -y0), E_2 y = (-y1, y0, 0) */
      m->Q[k] = -PIJ(1, 2)[k] + PIJ(2, 1)[k];
      m->Q[nn + k] = PIJ(0, 2)[k] - PIJ(2, 0)[k];
      m->Q[2 * nn + k] = -PIJ(0, 1)[k] + PIJ(1, 0)[k];
      for (int i = 0; i < 3; i++) {
        for (int j = i; j < 3; j++) {
          m->S[(size_t)pairIndex(i, j) * nn + k] = 0.5 * (PIJ(i, j)[k] + PIJ(j, i)[k]);
        }
      }
    }
    for (int k = 0; k < n; k++) {
      /* T[:, i] = Σ_a (Me V)_{a,i}: the p_ij with X replaced by 1; from the mass rows */
      m->e[k] = -PVIJ(1, 2)[k] + PVIJ(2, 1)[k];
      m->e[n + k] = PVIJ(0, 2)[k] - PVIJ(2, 0)[k];
      m->e[2 * n + k] = -PVIJ(0, 1)[k] + PVIJ(1, 0)[k];
      for (int i = 0; i < 3; i++) {
        for (int j = i; j < 3; j++) {
          m->d[(size_t)pairIndex(i, j) * n + k] = 0.5 * (PVIJ(i, j)[k] + PVIJ(j, i)[k]);
        }
      }
    }
#undef PIJ
#undef PVIJ
  }
  /* T = VᵀM 1_i: a second, cheap pass (Σ_b Me_ab summed over a) */
  for (int e = 0; st == CS_OK && e < me->ntet; e++) {
    double Me[100];
    elementMass(me, e, p.rho, pts, wts, Me);
    const int* tv = me->tet + 10 * e;
    for (int b = 0; b < 10; b++) {
      double mb = 0;
      for (int a = 0; a < 10; a++) {
        mb += Me[10 * a + b];
      }
      for (int i = 0; i < 3; i++) {
        const double* Vb = V + ((size_t)3 * tv[b] + i) * n;
        for (int k = 0; k < n; k++) {
          m->T[(size_t)k * 3 + i] += mb * Vb[k];
        }
      }
    }
  }
  if (st == CS_OK && spdInverse(n, m->Mr, m->Minv, L) != 0) {
    st = cs_errorSet(err, CS_ERR_ARG, "rom leg: the reduced mass VᵀMV is not positive definite "
                     "(a basis vector without mass, or dependent vectors)");
  }
  /* C = τ_d K_r(0): the reduced tangent at rest, vented, no load */
  if (st == CS_OK) {
    csfRomData* fd = csf_romDataCreate(rom, err);
    if (!fd) {
      st = CS_ERR_MEMORY;
    } else {
      csf_romDataReset(rom, fd);
      fd->sync = 1;
      csfRomLoad ld;
      memset(&ld, 0, sizeof ld);
      if (csf_romEvaluate(rom, fd, &ld, 1) != 0) {
        st = cs_errorSet(err, CS_ERR_ARG, "rom leg: the reduced tangent at rest failed");
      } else {
        for (size_t k = 0; k < nn; k++) {
          m->C[k] = p.damping_time * fd->K[k];
        }
      }
      csf_romDataDestroy(fd);
    }
  }
  free(P), free(pv), free(MV), free(L);
  if (st != CS_OK) {
    csr_romModelDestroy(m);
    return NULL;
  }
  return m;
}

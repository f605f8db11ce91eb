/* fem_model.c: Yeoh Tet10 kernels, follower pressure, fibres, assembly, Newton (fem_model.h).
 *
 * Rationale.
 * Element: quadratic tetrahedra (Tet10, as ABAQUS C3D10H in the paper), 4-point rule.
 * Incompressibility: mean dilatation (three-field Hu-Washizu with element-constant dilatation
 * theta = v_e / V_e and pressure p = U'(theta)), i.e. the P2/P0 pair, which is inf-sup stable on
 * tetrahedra. Because theta and p are element-local they are condensed exactly, so the global
 * unknowns are the displacements only and the discrete problem is the minimum of
 *   Pi(u) = sum_e [ int_e W_dev(C_bar) dV + V_e U(theta_e) ] - W_ext(u),
 *   W_dev = C10 (I1b - 3) + C20 (I1b - 3)^2, I1b = J^(-2/3) tr C, U = kappa/2 (theta - 1)^2,
 * whose Hessian is the (symmetric) consistent tangent:
 *   K_e = int G^T (A_dev + p d2J/dFdF) G dV + (kappa / V_e) g g^T,  g = int cof(F) : G dV.
 * Rejected: plain P2 with pointwise U(J) (locks for kappa >> mu: measured in test_fem_locking),
 * Taylor-Hood P2/P1 (continuous pressure unknowns make the global system a saddle point; more
 * unknowns and an indefinite factorisation for the same accuracy here).
 * Pressure: follower load on the deformed faces, f_a = -p int N_a (x_,s x x_,t) ds dt with the
 * outward (body) normal; its load stiffness is assembled exactly (non-symmetric per face,
 * symmetric in sum over a closed chamber). 6-point degree-4 rule on Tri6.
 * Fibres: 2-node trusses with Green strain, E_f S = E_f E, energy EA L0 E^2 / 2, whose end points
 * are interpolated from the host tetrahedra (embedded, tied), tension only by default.
 * Assembly: OpenMP over elements with atomic scatter into a fixed CSR pattern (no allocation in
 * the Newton loop). Sparse solve: see fem_linsolve.c. */
#include "fem_model.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "fem_linsolve.h"

/* 4-point degree-2 rule on the reference tetrahedron (volume 1/6): abscissae and weight */
#define QA 0.5854101966249685
#define QB 0.1381966011250105
static const double kTetQ[4][3] = {{QB, QB, QB}, {QA, QB, QB}, {QB, QA, QB}, {QB, QB, QA}};
static const double kTetW = 1.0 / 24.0;

/* 6-point degree-4 rule on the reference triangle (area 1/2), Dunavant */
static const double kTriQ[6][3] = {
    {0.445948490915965, 0.445948490915965, 0.223381589678011 / 2},
    {0.108103018168070, 0.445948490915965, 0.223381589678011 / 2},
    {0.445948490915965, 0.108103018168070, 0.223381589678011 / 2},
    {0.091576213509771, 0.091576213509771, 0.109951743655322 / 2},
    {0.816847572980459, 0.091576213509771, 0.109951743655322 / 2},
    {0.091576213509771, 0.816847572980459, 0.109951743655322 / 2}};

/* line search: the first Newton step of a load level is accepted unless an element inverts or the
 * residual grows by more than CSF_LS_GROWTH_FIRST; later steps must not grow it by more than
 * CSF_LS_GROWTH, else the step is halved. An Armijo (decrease) test is wrong for the first step:
 * with kappa = 2000 mu the linearised step leaves a volumetric residual O(kappa eps^2) that the
 * next iteration removes (measured on the tube: residual x120 after the full step, then quadratic
 * convergence), while an Armijo test cut every step to 1/16 and stalled. */
#define CSF_LS_GROWTH_FIRST 1e4
/* half width delta of the smoothed tension-only law of the fibres (Green strain); the force at
 * E = 0 is EA delta / 4 = 0.1 N for Kevlar, r = 0.0889 mm */
#define CSF_FIBRE_SLACK 5e-4
#define CSF_LS_GROWTH 2.0

static void fibreLaw(const csfModel* m, double E, double* S, double* dS);

double csf_wallTime(void) {
  struct timespec ts;
  timespec_get(&ts, TIME_UTC);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}


csfMaterial csf_materialDefault(double C10, double C20, double rho) {
  csfMaterial m;
  m.C10 = C10;
  m.C20 = C20;
  m.kappa = CSF_KAPPA_RATIO * 2.0 * C10;
  m.kappa_pt = 0.0;
  m.rho = rho;
  m.form = CSF_FORM_MIXED_P0;
  return m;
}


/* det and inverse of a 3x3 row-major matrix; returns det */
static double inv3(const double F[9], double Fi[9]) {
  double c0 = F[4] * F[8] - F[5] * F[7];
  double c1 = F[5] * F[6] - F[3] * F[8];
  double c2 = F[3] * F[7] - F[4] * F[6];
  double det = F[0] * c0 + F[1] * c1 + F[2] * c2;
  if (det == 0.0) {
    return 0.0;
  }
  double id = 1.0 / det;
  Fi[0] = c0 * id;
  Fi[1] = (F[2] * F[7] - F[1] * F[8]) * id;
  Fi[2] = (F[1] * F[5] - F[2] * F[4]) * id;
  Fi[3] = c1 * id;
  Fi[4] = (F[0] * F[8] - F[2] * F[6]) * id;
  Fi[5] = (F[2] * F[3] - F[0] * F[5]) * id;
  Fi[6] = c2 * id;
  Fi[7] = (F[1] * F[6] - F[0] * F[7]) * id;
  Fi[8] = (F[0] * F[4] - F[1] * F[3]) * id;
  return det;
}


double csf_yeohDev(double C10, double C20, const double F[9], double* W, double P[9],
                   double A[81]) {
  double Fi[9];
  double J = inv3(F, Fi);
  if (!(J > 0)) {
    return J;
  }
  double I1 = 0;
  for (int i = 0; i < 9; i++) {
    I1 += F[i] * F[i];
  }
  const double g = pow(J, -2.0 / 3.0);
  const double e = g * I1 - 3.0;              /* I1b - 3 */
  const double d1 = C10 + 2.0 * C20 * e;      /* dW/dI1b, MPa */
  const double d2 = 2.0 * C20;                /* d2W/dI1b2, MPa */
  if (W) {
    *W = C10 * e + C20 * e * e;
  }
  /* D = dI1b/dF = g (2 F - 2/3 I1 F^-T); Fi is row-major F^-1, so (F^-T)_iJ = Fi[3J+i] */
  double D[9];
  for (int i = 0; i < 3; i++) {
    for (int J2 = 0; J2 < 3; J2++) {
      D[3 * i + J2] = g * (2.0 * F[3 * i + J2] - (2.0 / 3.0) * I1 * Fi[3 * J2 + i]);
    }
  }
  if (P) {
    for (int i = 0; i < 9; i++) {
      P[i] = d1 * D[i];
    }
  }
  if (A) {
    /* A = d2 D x D + d1 H, H_iJkL = -2/3 Fi_Lk D_iJ - 4/3 g F_kL Fi_Ji + 2 g d_ik d_JL
     *                                 + 2/3 g I1 Fi_Jk Fi_Li */
    for (int i = 0; i < 3; i++) {
      for (int J2 = 0; J2 < 3; J2++) {
        const int iJ = 3 * i + J2;
        for (int k = 0; k < 3; k++) {
          for (int L = 0; L < 3; L++) {
            const int kL = 3 * k + L;
            double H = -(2.0 / 3.0) * Fi[3 * L + k] * D[iJ] -
                       (4.0 / 3.0) * g * F[kL] * Fi[3 * J2 + i] +
                       (2.0 / 3.0) * g * I1 * Fi[3 * J2 + k] * Fi[3 * L + i];
            if (i == k && J2 == L) {
              H += 2.0 * g;
            }
            A[9 * iJ + kL] = d2 * D[iJ] * D[kL] + d1 * H;
          }
        }
      }
    }
  }
  return J;
}


/* add s * d2J/dFdF (J = det F) to A; Fi = F^-1 */
static void addD2J(double A[81], const double Fi[9], double J, double s) {
  for (int i = 0; i < 3; i++) {
    for (int J2 = 0; J2 < 3; J2++) {
      for (int k = 0; k < 3; k++) {
        for (int L = 0; L < 3; L++) {
          A[9 * (3 * i + J2) + 3 * k + L] +=
              s * J * (Fi[3 * J2 + i] * Fi[3 * L + k] - Fi[3 * J2 + k] * Fi[3 * L + i]);
        }
      }
    }
  }
}


csfModel* csf_modelCreate(const csfMesh* mesh, const csfMaterial* mat, csError* err) {
  if (!mesh || !mat || mesh->ntet <= 0) {
    cs_errorSet(err, CS_ERR_ARG, "fem_model: empty mesh or no material");
    return NULL;
  }
  if (!(mat->C10 > 0) || !(mat->C20 >= 0) || !(mat->kappa > 0)) {
    cs_errorSet(err, CS_ERR_ARG, "fem_model: need C10 > 0, C20 >= 0, kappa > 0 (got %g %g %g)",
                mat->C10, mat->C20, mat->kappa);
    return NULL;
  }
  csfModel* m = calloc(1, sizeof *m);
  if (!m) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory");
    return NULL;
  }
  m->mesh = mesh;
  m->mat = *mat;
  m->ndof = 3 * mesh->nnode;
  m->fib_tension_only = 1; /* smoothed tension-only law (fibKernel) */
  const size_t nt = (size_t)mesh->ntet;
  m->dNdX = malloc(nt * 120 * sizeof(double));
  m->wq = malloc(nt * 4 * sizeof(double));
  m->vol = malloc(nt * sizeof(double));
  m->face_p = calloc((size_t)(mesh->nface > 0 ? mesh->nface : 1), sizeof(double));
  m->fixed = calloc((size_t)m->ndof, 1);
  m->u_fix = calloc((size_t)m->ndof, sizeof(double));
  m->face_local = malloc((size_t)(mesh->nface > 0 ? mesh->nface : 1) * 6 * sizeof(int));
  if (!m->dNdX || !m->wq || !m->vol || !m->face_p || !m->fixed || !m->u_fix || !m->face_local) {
    csf_modelDestroy(m);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory for %d elements", mesh->ntet);
    return NULL;
  }
  /* reference shape gradients and weights: dN/dX = dN/dxi J0^-1, J0 = dX/dxi */
  for (size_t e = 0; e < nt; e++) {
    const int* tv = mesh->tet + 10 * e;
    m->vol[e] = 0;
    for (int g = 0; g < 4; g++) {
      double dN[30], J0[9] = {0}, Ji[9];
      csf_tet10Shape(kTetQ[g], NULL, dN);
      for (int a = 0; a < 10; a++) {
        const double* xa = mesh->x + 3 * tv[a];
        for (int i = 0; i < 3; i++) {
          for (int d = 0; d < 3; d++) {
            J0[3 * i + d] += xa[i] * dN[3 * a + d];
          }
        }
      }
      double det = inv3(J0, Ji);
      if (!(det > 0)) {
        csf_modelDestroy(m);
        cs_errorSet(err, CS_ERR_ARG, "fem_model: element %zu is inverted or degenerate (det %g)",
                    e, det);
        return NULL;
      }
      double* out = m->dNdX + 120 * e + 30 * g;
      for (int a = 0; a < 10; a++) {
        for (int J2 = 0; J2 < 3; J2++) {
          out[3 * a + J2] = dN[3 * a] * Ji[J2] + dN[3 * a + 1] * Ji[3 + J2] +
                            dN[3 * a + 2] * Ji[6 + J2];
        }
      }
      m->wq[4 * e + g] = kTetW * det;
      m->vol[e] += kTetW * det;
    }
  }
  /* local index of each face node inside its owning tetrahedron */
  for (int f = 0; f < mesh->nface; f++) {
    const int* tv = mesh->tet + 10 * mesh->face_tet[f];
    for (int k = 0; k < 6; k++) {
      m->face_local[6 * f + k] = -1;
      for (int a = 0; a < 10; a++) {
        if (tv[a] == mesh->face[6 * f + k]) {
          m->face_local[6 * f + k] = a;
        }
      }
    }
  }
  return m;
}


void csf_modelDestroy(csfModel* m) {
  if (!m) {
    return;
  }
  free(m->dNdX), free(m->wq), free(m->vol), free(m->face_p), free(m->fixed), free(m->u_fix);
  free(m->fib_node), free(m->fib_coef), free(m->fib_L0), free(m->fib_EA);
  free(m->adj_ptr), free(m->adj), free(m->row_ptr), free(m->col), free(m->tet_map);
  free(m->fib_map), free(m->face_local);
  free(m);
}


int csf_modelAddPressure(csfModel* m, int tag, double p_unit) {
  int n = 0;
  for (int f = 0; f < m->mesh->nface; f++) {
    if (m->mesh->face_tag[f] == tag) {
      m->face_p[f] += p_unit;
      n++;
    }
  }
  return n;
}


/* position of node j in the sorted adjacency row of node i (binary search), -1 if absent */
static int adjSlot(const csfModel* m, int i, int j) {
  int lo = m->adj_ptr[i], hi = m->adj_ptr[i + 1] - 1;
  while (lo <= hi) {
    int mid = (lo + hi) / 2;
    if (m->adj[mid] == j) {
      return mid - m->adj_ptr[i];
    }
    if (m->adj[mid] < j) {
      lo = mid + 1;
    } else {
      hi = mid - 1;
    }
  }
  return -1;
}


static int cmpInt(const void* a, const void* b) {
  int x = *(const int*)a, y = *(const int*)b;
  return (x > y) - (x < y);
}


csStatus csf_modelFinalize(csfModel* m, csError* err) {
  const csfMesh* me = m->mesh;
  const int nn = me->nnode;
  /* node pairs per row: count upper bounds, fill, sort, unique */
  int* cnt = calloc((size_t)nn + 1, sizeof(int));
  if (!cnt) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory (pattern)");
  }
  for (int e = 0; e < me->ntet; e++) {
    for (int a = 0; a < 10; a++) {
      cnt[me->tet[10 * e + a] + 1] += 10;
    }
  }
  for (int f = 0; f < m->nfib; f++) {
    for (int a = 0; a < 20; a++) {
      cnt[m->fib_node[20 * f + a] + 1] += 20;
    }
  }
  for (int i = 0; i < nn; i++) {
    cnt[i + 1] += cnt[i];
  }
  int* tmp = malloc((size_t)cnt[nn] * sizeof(int));
  int* fill = calloc((size_t)nn, sizeof(int));
  m->adj_ptr = malloc(((size_t)nn + 1) * sizeof(int));
  if (!tmp || !fill || !m->adj_ptr) {
    free(cnt), free(tmp), free(fill);
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory (pattern)");
  }
  for (int e = 0; e < me->ntet; e++) {
    const int* tv = me->tet + 10 * e;
    for (int a = 0; a < 10; a++) {
      for (int b = 0; b < 10; b++) {
        tmp[cnt[tv[a]] + fill[tv[a]]++] = tv[b];
      }
    }
  }
  for (int f = 0; f < m->nfib; f++) {
    const int* fv = m->fib_node + 20 * f;
    for (int a = 0; a < 20; a++) {
      for (int b = 0; b < 20; b++) {
        tmp[cnt[fv[a]] + fill[fv[a]]++] = fv[b];
      }
    }
  }
  int nadj = 0;
  m->adj_ptr[0] = 0;
  for (int i = 0; i < nn; i++) {
    int* row = tmp + cnt[i];
    qsort(row, (size_t)fill[i], sizeof(int), cmpInt);
    int k = 0;
    for (int q = 0; q < fill[i]; q++) {
      if (q == 0 || row[q] != row[q - 1]) {
        row[k++] = row[q];
      }
    }
    fill[i] = k;
    nadj += k;
    m->adj_ptr[i + 1] = nadj;
  }
  m->adj = malloc((size_t)nadj * sizeof(int));
  if (!m->adj) {
    free(cnt), free(tmp), free(fill);
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory (pattern)");
  }
  for (int i = 0; i < nn; i++) {
    memcpy(m->adj + m->adj_ptr[i], tmp + cnt[i], (size_t)fill[i] * sizeof(int));
  }
  free(cnt), free(tmp), free(fill);
  /* scalar CSR with 3x3 blocks: row 3i+c starts at 9 adj_ptr[i] + 3 c deg_i */
  m->nnz = 9 * nadj;
  m->row_ptr = malloc(((size_t)m->ndof + 1) * sizeof(int));
  m->col = malloc((size_t)m->nnz * sizeof(int));
  m->tet_map = malloc((size_t)me->ntet * 100 * sizeof(int));
  m->fib_map = malloc((size_t)(m->nfib > 0 ? m->nfib : 1) * 400 * sizeof(int));
  if (!m->row_ptr || !m->col || !m->tet_map || !m->fib_map) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory (pattern)");
  }
  for (int i = 0; i < nn; i++) {
    int deg = m->adj_ptr[i + 1] - m->adj_ptr[i];
    for (int c = 0; c < 3; c++) {
      int r0 = 9 * m->adj_ptr[i] + 3 * c * deg;
      m->row_ptr[3 * i + c] = r0;
      for (int k = 0; k < deg; k++) {
        for (int d = 0; d < 3; d++) {
          m->col[r0 + 3 * k + d] = 3 * m->adj[m->adj_ptr[i] + k] + d;
        }
      }
    }
  }
  m->row_ptr[m->ndof] = m->nnz;
  for (int e = 0; e < me->ntet; e++) {
    const int* tv = me->tet + 10 * e;
    for (int a = 0; a < 10; a++) {
      for (int b = 0; b < 10; b++) {
        m->tet_map[100 * e + 10 * a + b] = adjSlot(m, tv[a], tv[b]);
      }
    }
  }
  for (int f = 0; f < m->nfib; f++) {
    const int* fv = m->fib_node + 20 * f;
    for (int a = 0; a < 20; a++) {
      for (int b = 0; b < 20; b++) {
        m->fib_map[400 * f + 20 * a + b] = adjSlot(m, fv[a], fv[b]);
      }
    }
  }
  m->finalized = 1;
  return CS_OK;
}


csfData* csf_dataCreate(const csfModel* m, csError* err) {
  if (!m->finalized) {
    cs_errorSet(err, CS_ERR_ARG, "fem_model: csf_modelFinalize must run before csf_dataCreate");
    return NULL;
  }
  csfData* d = calloc(1, sizeof *d);
  if (!d) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory");
    return NULL;
  }
  const size_t n = (size_t)m->ndof, nt = (size_t)m->mesh->ntet;
  d->ndof = m->ndof;
  d->u = calloc(n, sizeof(double));
  d->r = calloc(n, sizeof(double));
  d->du = calloc(n, sizeof(double));
  d->u_save = calloc(n, sizeof(double));
  d->kval = calloc((size_t)m->nnz, sizeof(double));
  d->theta = calloc(nt, sizeof(double));
  d->pel = calloc(nt, sizeof(double));
  d->vratio = calloc(nt, sizeof(double));
  d->theta_save = calloc(nt, sizeof(double));
  d->vr0 = calloc(nt, sizeof(double));
  d->gel = calloc(nt * 30, sizeof(double));
  d->g0 = calloc(nt * 30, sizeof(double));
  const size_t nfb = (size_t)(m->nfib > 0 ? m->nfib : 1);
  d->fib_S = calloc(nfb, sizeof(double));
  d->fib_E = calloc(nfb, sizeof(double));
  d->fib_d = calloc(3 * nfb, sizeof(double));
  d->fib_S_save = calloc(nfb, sizeof(double));
  d->fib_E0 = calloc(nfb, sizeof(double));
  d->fib_d0 = calloc(3 * nfb, sizeof(double));
  d->fib_zone = calloc(nfb, 1);
  d->fext1 = calloc(n, sizeof(double));
  d->du2 = calloc(n, sizeof(double));
  if (!d->fib_zone || !d->fext1 || !d->du2 || !d->u || !d->r || !d->du || !d->u_save ||
      !d->kval || !d->theta || !d->pel || !d->vratio || !d->theta_save || !d->vr0 || !d->gel || !d->g0 || !d->fib_S || !d->fib_E ||
      !d->fib_d || !d->fib_S_save || !d->fib_E0 || !d->fib_d0) {
    csf_dataDestroy(d);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory (%zu dofs)", n);
    return NULL;
  }
  for (size_t e = 0; e < nt; e++) {
    d->theta[e] = d->vratio[e] = 1.0; /* reference state: p = 0 */
  }
  for (int f = 0; f < m->nfib; f++) {
    double dS;
    fibreLaw(m, 0.0, &d->fib_S[f], &dS); /* reference state: E = 0 */
    d->fib_zone[f] = 1;
  }
  d->ls = csf_linSolverCreate(m->solver, m->ndof, m->row_ptr, m->col, err);
  if (!d->ls) {
    csf_dataDestroy(d);
    return NULL;
  }
  return d;
}


void csf_dataDestroy(csfData* d) {
  if (!d) {
    return;
  }
  free(d->u), free(d->r), free(d->du), free(d->u_save), free(d->kval), free(d->theta);
  free(d->pel), free(d->vratio), free(d->theta_save), free(d->vr0), free(d->gel), free(d->g0);
  free(d->fib_S), free(d->fib_E), free(d->fib_d), free(d->fib_S_save), free(d->fib_E0);
  free(d->fib_d0), free(d->fib_zone), free(d->fext1), free(d->du2);
  csf_linSolverDestroy(d->ls);
  free(d);
}


/* F = I + grad u at quadrature point g of element e; u gathered in ue (30) */
static void defGrad(const double* dNdX, const double ue[30], double F[9]) {
  for (int i = 0; i < 9; i++) {
    F[i] = (i % 4 == 0) ? 1.0 : 0.0;
  }
  for (int a = 0; a < 10; a++) {
    for (int i = 0; i < 3; i++) {
      for (int J2 = 0; J2 < 3; J2++) {
        F[3 * i + J2] += ue[3 * a + i] * dNdX[3 * a + J2];
      }
    }
  }
}


/* element residual re (30) and tangent ke (900) of tetrahedron e at displacement u and element
 * dilatation state theta_e (mixed form); outputs v/V, g = int cof(F):G dV (30) and min J.
 * Returns 1 if an element is inverted. */
static int tetKernel(const csfModel* m, int e, const double* u, double theta_e, double re[30],
                     double* ke, double* vratio_out, double gvec[30], double* jmin_out) {
  const csfMaterial* mat = &m->mat;
  const int* tv = m->mesh->tet + 10 * e;
  double ue[30];
  for (int a = 0; a < 10; a++) {
    for (int i = 0; i < 3; i++) {
      ue[3 * a + i] = u[3 * tv[a] + i];
    }
  }
  memset(re, 0, 30 * sizeof(double));
  if (ke) {
    memset(ke, 0, 900 * sizeof(double));
  }
  const double* dNe = m->dNdX + 120 * (size_t)e;
  const double* we = m->wq + 4 * (size_t)e;
  double F[4][9], Fi[4][9], J[4];
  double jmin = INFINITY;
  /* pass 1: deformation and element dilatation theta = v / V */
  double vcur = 0;
  for (int g = 0; g < 4; g++) {
    defGrad(dNe + 30 * g, ue, F[g]);
    J[g] = inv3(F[g], Fi[g]);
    if (!(J[g] > 0)) {
      return 1;
    }
    jmin = fmin(jmin, J[g]);
    vcur += we[g] * J[g];
  }
  const double vratio = vcur / m->vol[e];
  const int mixed = mat->form == CSF_FORM_MIXED_P0;
  /* three-field u-theta-p with theta, p condensed: the residual carries the condensed pressure
   * p_state + kappa (v/V - theta_e) = kappa (v/V - 1); the geometric stiffness uses the state
   * pressure p_state = kappa (theta_e - 1), which Newton updates by the linearised constraint
   * (csf_newtonSolve). At convergence theta_e = v/V and both agree. */
  const double p_res = mixed ? mat->kappa * (vratio - 1.0) : 0.0;
  const double p_tan = mixed ? mat->kappa * (theta_e - 1.0) : 0.0;
  memset(gvec, 0, 30 * sizeof(double));
  for (int g = 0; g < 4; g++) {
    const double* dN = dNe + 30 * g;
    double P[9], A[81];
    csf_yeohDev(mat->C10, mat->C20, F[g], NULL, P, ke ? A : NULL);
    /* volumetric part: mixed p (element constant) or pointwise U'(J), U''(J) */
    const double ppt = mixed ? mat->kappa_pt * (J[g] - 1.0) : mat->kappa * (J[g] - 1.0);
    const double pv = p_res + ppt;
    const double kcc = mixed ? mat->kappa_pt : mat->kappa; /* pointwise bulk stiffness */
    for (int i = 0; i < 3; i++) {
      for (int J2 = 0; J2 < 3; J2++) {
        P[3 * i + J2] += pv * J[g] * Fi[g][3 * J2 + i];
      }
    }
    if (ke) {
      addD2J(A, Fi[g], J[g], p_tan + ppt);
      if (kcc != 0.0) {
        /* pointwise bulk term kcc cof x cof */
        for (int iJ = 0; iJ < 9; iJ++) {
          double ci = J[g] * Fi[g][3 * (iJ % 3) + iJ / 3];
          for (int kL = 0; kL < 9; kL++) {
            double ck = J[g] * Fi[g][3 * (kL % 3) + kL / 3];
            A[9 * iJ + kL] += kcc * ci * ck;
          }
        }
      }
    }
    const double w = we[g];
    for (int a = 0; a < 10; a++) {
      for (int i = 0; i < 3; i++) {
        double s = 0;
        for (int J2 = 0; J2 < 3; J2++) {
          s += P[3 * i + J2] * dN[3 * a + J2];
        }
        re[3 * a + i] += w * s;
        if (mixed) {
          double c = 0;
          for (int J2 = 0; J2 < 3; J2++) {
            c += J[g] * Fi[g][3 * J2 + i] * dN[3 * a + J2];
          }
          gvec[3 * a + i] += w * c;
        }
      }
    }
    if (ke) {
      /* M_a[i][kL] = sum_J dN_aJ A[iJ][kL]; K_ab,ik += w sum_L M_a[i][kL] dN_bL */
      for (int a = 0; a < 10; a++) {
        double M[3][9];
        for (int i = 0; i < 3; i++) {
          for (int kL = 0; kL < 9; kL++) {
            M[i][kL] = dN[3 * a] * A[9 * (3 * i) + kL] + dN[3 * a + 1] * A[9 * (3 * i + 1) + kL] +
                       dN[3 * a + 2] * A[9 * (3 * i + 2) + kL];
          }
        }
        for (int b = 0; b < 10; b++) {
          const double* db = dN + 3 * b;
          for (int i = 0; i < 3; i++) {
            for (int k = 0; k < 3; k++) {
              ke[30 * (3 * a + i) + 3 * b + k] +=
                  w * (M[i][3 * k] * db[0] + M[i][3 * k + 1] * db[1] + M[i][3 * k + 2] * db[2]);
            }
          }
        }
      }
    }
  }
  if (mixed && ke) {
    const double s = mat->kappa / m->vol[e];
    for (int q = 0; q < 30; q++) {
      for (int r = 0; r < 30; r++) {
        ke[30 * q + r] += s * gvec[q] * gvec[r];
      }
    }
  }
  *vratio_out = vratio;
  *jmin_out = jmin;
  return 0;
}


/* atomic add into shared arrays (OpenMP when enabled) */
static inline void atomicAdd(double* dst, double v) {
#ifdef _OPENMP
#pragma omp atomic
#endif
  *dst += v;
}


/* CSR value index of (dof row 3i+c, block slot k of node i, component d) */
static inline int csrIndex(const csfModel* m, int i, int c, int k, int d) {
  return m->row_ptr[3 * i + c] + 3 * k + d;
}


/* fibre element f: residual (60) and tangent (3600); returns 0 */
/* smoothed tension-only stress measure S(E) and S'(E) (see fibKernel) */
static void fibreLaw(const csfModel* m, double E, double* S, double* dS) {
  *S = E, *dS = 1.0;
  if (m->fib_tension_only) {
    const double dl = CSF_FIBRE_SLACK;
    if (E <= -dl) {
      *S = 0, *dS = 0;
    } else if (E < dl) {
      *S = (E + dl) * (E + dl) / (4.0 * dl);
      *dS = (E + dl) / (2.0 * dl);
    }
  }
}


/* fibre element f: residual (60) with the actual stress S(E(u)); tangent (3600) with the state
 * stress S_state in the geometric term (mixed treatment of the nearly inextensible fibre, as the
 * three-field treatment of incompressibility); outputs E (Green strain) and d = x2 - x1 */
static void fibKernel(const csfModel* m, int f, const double* u, double S_state, double rf[60],
                      double* kf, int* active, double* E_out, double d_out[3]) {
  const int* fv = m->fib_node + 20 * f;
  const double* c = m->fib_coef + 20 * f;
  double dvec[3] = {0, 0, 0};
  for (int a = 0; a < 20; a++) {
    const double* X = m->mesh->x + 3 * fv[a];
    for (int i = 0; i < 3; i++) {
      dvec[i] += c[a] * (X[i] + u[3 * fv[a] + i]);
    }
  }
  const double L0 = m->fib_L0[f], EA = m->fib_EA[f];
  const double E = 0.5 * ((dvec[0] * dvec[0] + dvec[1] * dvec[1] + dvec[2] * dvec[2]) /
                              (L0 * L0) -
                          1.0);
  /* tension only, smoothed: stress measure S(E) = E above +delta, (E + delta)^2 / (4 delta) in
   * |E| < delta, 0 below -delta (C1: no on/off chatter). The geometric term uses the state
   * stress S_state updated by the linearised strain (csf_newtonSolve): with the actual S the
   * first Newton step of a bending increment stretches every rotated fibre at second order
   * (E ~ phi^2 / 2, force EA E ~ N), the residual explodes and Newton cycles (measured on the
   * baseline actuator); a compression-carrying truss adds a negative geometric stiffness that
   * lets the thin embedded fibre buckle element by element. */
  double S, dS;
  fibreLaw(m, E, &S, &dS);
  *E_out = E;
  d_out[0] = dvec[0], d_out[1] = dvec[1], d_out[2] = dvec[2];
  *active = S != 0.0 || dS != 0.0 || S_state != 0.0;
  if (!*active) {
    return;
  }
  /* dW/dd = EA S d / L0; tangent EA / L0 (S_state I + S'(E) d d^T / L0^2) */
  double fd[3], H[9];
  /* optional: the compressive part of the geometric stiffness is left out of the tangent (the
   * residual keeps it): an embedded truss in compression is held laterally by the matrix, which
   * the truss element does not know of, so its -EA|S|/L0 lateral stiffness would only make K
   * indefinite (modified Newton, same solution) */
  const double Sg = m->fib_geo_tension ? fmax(S_state, 0.0) : S_state;
  for (int i = 0; i < 3; i++) {
    fd[i] = EA * S * dvec[i] / L0;
    for (int k = 0; k < 3; k++) {
      H[3 * i + k] = EA / L0 * ((i == k ? Sg : 0.0) + dS * dvec[i] * dvec[k] / (L0 * L0));
    }
  }
  for (int a = 0; a < 20; a++) {
    for (int i = 0; i < 3; i++) {
      rf[3 * a + i] = c[a] * fd[i];
    }
  }
  if (kf) {
    for (int a = 0; a < 20; a++) {
      for (int b = 0; b < 20; b++) {
        for (int i = 0; i < 3; i++) {
          for (int k = 0; k < 3; k++) {
            kf[60 * (3 * a + i) + 3 * b + k] = c[a] * c[b] * H[3 * i + k];
          }
        }
      }
    }
  }
}


/* Tri6 shape functions and derivatives at (s, t) */
static void tri6Shape(double s, double t, double N[6], double dN[12]) {
  const double L0 = 1 - s - t, L1 = s, L2 = t;
  N[0] = L0 * (2 * L0 - 1), N[1] = L1 * (2 * L1 - 1), N[2] = L2 * (2 * L2 - 1);
  N[3] = 4 * L0 * L1, N[4] = 4 * L1 * L2, N[5] = 4 * L2 * L0;
  /* d/ds, d/dt */
  dN[0] = -(4 * L0 - 1), dN[1] = -(4 * L0 - 1);
  dN[2] = 4 * L1 - 1, dN[3] = 0;
  dN[4] = 0, dN[5] = 4 * L2 - 1;
  dN[6] = 4 * (L0 - L1), dN[7] = -4 * L1;
  dN[8] = 4 * L2, dN[9] = 4 * L1;
  dN[10] = -4 * L2, dN[11] = 4 * (L0 - L2);
}


static void cross(const double a[3], const double b[3], double r[3]) {
  r[0] = a[1] * b[2] - a[2] * b[1];
  r[1] = a[2] * b[0] - a[0] * b[2];
  r[2] = a[0] * b[1] - a[1] * b[0];
}


int csf_assemble(const csfModel* m, csfData* d, double load, int want_k) {
  const double t0 = csf_wallTime();
  const csfMesh* me = m->mesh;
  const size_t n = (size_t)m->ndof;
  memset(d->r, 0, n * sizeof(double));
  if (want_k) {
    memset(d->kval, 0, (size_t)m->nnz * sizeof(double));
  }
  int bad = 0;
  double jmin = INFINITY;
  /* gravity: f_a = rho g int N_a dV (4-point rule, shape values at the points) */
  double Nq[4][10];
  for (int g = 0; g < 4; g++) {
    csf_tet10Shape(kTetQ[g], Nq[g], NULL);
  }
  const int grav = m->gravity[0] != 0 || m->gravity[1] != 0 || m->gravity[2] != 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : bad) reduction(min : jmin)
#endif
  for (int e = 0; e < me->ntet; e++) {
    double re[30], ke[900], vr, jm;
    if (tetKernel(m, e, d->u, d->theta[e], re, want_k ? ke : NULL, &vr, d->gel + 30 * (size_t)e,
                  &jm)) {
      bad++;
      continue;
    }
    d->vratio[e] = vr;
    jmin = fmin(jmin, jm);
    const int* tv = me->tet + 10 * e;
    if (grav) {
      for (int g = 0; g < 4; g++) {
        double w = m->mat.rho * m->wq[4 * e + g];
        for (int a = 0; a < 10; a++) {
          for (int i = 0; i < 3; i++) {
            re[3 * a + i] -= w * Nq[g][a] * m->gravity[i];
          }
        }
      }
    }
    for (int a = 0; a < 10; a++) {
      for (int i = 0; i < 3; i++) {
        atomicAdd(&d->r[3 * tv[a] + i], re[3 * a + i]);
      }
    }
    if (want_k) {
      const int* map = m->tet_map + 100 * (size_t)e;
      for (int a = 0; a < 10; a++) {
        for (int b = 0; b < 10; b++) {
          const int k = map[10 * a + b];
          for (int i = 0; i < 3; i++) {
            for (int c = 0; c < 3; c++) {
              atomicAdd(&d->kval[csrIndex(m, tv[a], i, k, c)], ke[30 * (3 * a + i) + 3 * b + c]);
            }
          }
        }
      }
    }
  }
  if (bad) {
    d->stats.t_assemble += csf_wallTime() - t0;
    return 1;
  }
  /* fibres (serial: a few thousand small elements) */
  {
    double rf[60];
    double* kf = want_k ? malloc(3600 * sizeof(double)) : NULL;
    for (int f = 0; f < m->nfib; f++) {
      int active;
      fibKernel(m, f, d->u, d->fib_S[f], rf, kf, &active, &d->fib_E[f], d->fib_d + 3 * (size_t)f);
      if (!active) {
        continue;
      }
      const int* fv = m->fib_node + 20 * f;
      for (int a = 0; a < 20; a++) {
        for (int i = 0; i < 3; i++) {
          d->r[3 * fv[a] + i] += rf[3 * a + i];
        }
      }
      if (kf) {
        const int* map = m->fib_map + 400 * (size_t)f;
        for (int a = 0; a < 20; a++) {
          for (int b = 0; b < 20; b++) {
            for (int i = 0; i < 3; i++) {
              for (int c = 0; c < 3; c++) {
                d->kval[csrIndex(m, fv[a], i, map[20 * a + b], c)] +=
                    kf[60 * (3 * a + i) + 3 * b + c];
              }
            }
          }
        }
      }
    }
    free(kf);
  }
  double fint2 = 0;
  for (size_t i = 0; i < n; i++) {
    fint2 += d->r[i] * d->r[i];
  }
  /* follower pressure on faces: R -= f_ext, f_a = -p int N_a (x_s x x_t); per unit load the
   * same force is the gradient of the weighted chamber volume Vw = sum p1 1/3 int x . (-n) da
   * (n = x_s x x_t points out of the body, into the chamber) */
  double fext2 = 0, volw = 0;
  memset(d->fext1, 0, n * sizeof(double));
  for (int f = 0; f < me->nface; f++) {
    const double p1 = m->face_p[f];
    const double p = p1 * load;
    if (p1 == 0.0) {
      continue;
    }
    const int* fn = me->face + 6 * f;
    double xf[6][3];
    for (int a = 0; a < 6; a++) {
      for (int i = 0; i < 3; i++) {
        xf[a][i] = me->x[3 * fn[a] + i] + d->u[3 * fn[a] + i];
      }
    }
    double fe[18] = {0}, fe1[18] = {0}, kfe[18 * 18] = {0};
    for (int q = 0; q < 6; q++) {
      double N[6], dN[12], xs[3] = {0, 0, 0}, xt[3] = {0, 0, 0}, nrm[3];
      tri6Shape(kTriQ[q][0], kTriQ[q][1], N, dN);
      const double w = kTriQ[q][2];
      for (int a = 0; a < 6; a++) {
        for (int i = 0; i < 3; i++) {
          xs[i] += dN[2 * a] * xf[a][i];
          xt[i] += dN[2 * a + 1] * xf[a][i];
        }
      }
      cross(xs, xt, nrm);
      double xq[3] = {0, 0, 0};
      for (int a = 0; a < 6; a++) {
        for (int i = 0; i < 3; i++) {
          fe[3 * a + i] -= p * w * N[a] * nrm[i];
          fe1[3 * a + i] -= p1 * w * N[a] * nrm[i];
          xq[i] += N[a] * xf[a][i];
        }
      }
      volw -= p1 * w * (xq[0] * nrm[0] + xq[1] * nrm[1] + xq[2] * nrm[2]) / 3.0;
      if (want_k) {
        /* d(f_a)/d(x_bk) = -p w N_a (dN_b,s e_k x x_t + dN_b,t x_s x e_k); K = -df/dx */
        for (int b = 0; b < 6; b++) {
          for (int k = 0; k < 3; k++) {
            double ek[3] = {0, 0, 0}, c1[3], c2[3];
            ek[k] = 1.0;
            cross(ek, xt, c1);
            cross(xs, ek, c2);
            for (int a = 0; a < 6; a++) {
              for (int i = 0; i < 3; i++) {
                kfe[18 * (3 * a + i) + 3 * b + k] +=
                    p * w * N[a] * (dN[2 * b] * c1[i] + dN[2 * b + 1] * c2[i]);
              }
            }
          }
        }
      }
    }
    const int* loc = m->face_local + 6 * f;
    const int* map = m->tet_map + 100 * (size_t)me->face_tet[f];
    for (int a = 0; a < 6; a++) {
      for (int i = 0; i < 3; i++) {
        d->r[3 * fn[a] + i] -= fe[3 * a + i];
        d->fext1[3 * fn[a] + i] += fe1[3 * a + i];
        fext2 += fe[3 * a + i] * fe[3 * a + i];
      }
      if (want_k) {
        for (int b = 0; b < 6; b++) {
          const int k = map[10 * loc[a] + loc[b]];
          for (int i = 0; i < 3; i++) {
            for (int c = 0; c < 3; c++) {
              d->kval[csrIndex(m, fn[a], i, k, c)] += kfe[18 * (3 * a + i) + 3 * b + c];
            }
          }
        }
      }
    }
  }
  /* fixed rows/columns of K become identity rows/columns */
  if (want_k) {
    /* lift: free rows see the linearised effect of moving fixed dofs to their targets,
     * r_i += K_ij (load u_fix_j - u_j); zero once the Dirichlet values are met */
    for (int i = 0; i < m->ndof; i++) {
      if (m->fixed[i]) {
        continue;
      }
      for (int q = m->row_ptr[i]; q < m->row_ptr[i + 1]; q++) {
        const int j = m->col[q];
        if (m->fixed[j]) {
          d->r[i] += d->kval[q] * (load * m->u_fix[j] - d->u[j]);
        }
      }
    }
    for (int i = 0; i < m->ndof; i++) {
      for (int q = m->row_ptr[i]; q < m->row_ptr[i + 1]; q++) {
        const int j = m->col[q];
        if (m->fixed[i] || m->fixed[j]) {
          d->kval[q] = (i == j) ? 1.0 : 0.0;
        }
      }
    }
  }
  double r2 = 0;
  for (size_t i = 0; i < n; i++) {
    if (!m->fixed[i]) {
      r2 += d->r[i] * d->r[i];
    }
  }
  for (size_t i = 0; i < n; i++) {
    if (m->fixed[i]) {
      d->fext1[i] = 0.0;
    }
  }
  d->vol_w = volw;
  d->rnorm = sqrt(r2);
  d->fnorm = sqrt(fint2) + sqrt(fext2);
  d->jmin = jmin;
  d->load = load;
  d->stats.n_assemble++;
  d->stats.t_assemble += csf_wallTime() - t0;
  return isfinite(d->rnorm) ? 0 : 1;
}


csfNewtonOptions csf_newtonDefault(void) {
  csfNewtonOptions o;
  o.max_iter = 25;
  o.rtol = 1e-8;
  o.atol = 1e-10;
  o.max_ls = 6;
  o.line_search = CSF_LS_RESIDUAL;
  o.ls_eta = 0.5;
  o.threads = 0;
  o.monitor = NULL;
  o.monitor_user = NULL;
  return o;
}


/* theta_e = (v_e + alpha g_e . du_e) / V_e: the linearised volume constraint of the three-field
 * form (element pressure p_e = kappa (theta_e - 1) follows) */
static void updateTheta(const csfModel* m, csfData* d, double alpha) {
  /* fibres: E_lin = E0 + d0 . (alpha dd) / L0^2, S_state = S(E_lin) */
  for (int f = 0; f < m->nfib; f++) {
    const int* fv = m->fib_node + 20 * (size_t)f;
    const double* c = m->fib_coef + 20 * (size_t)f;
    double dd[3] = {0, 0, 0};
    for (int a = 0; a < 20; a++) {
      for (int i = 0; i < 3; i++) {
        dd[i] += c[a] * d->du[3 * fv[a] + i];
      }
    }
    const double* d0 = d->fib_d0 + 3 * (size_t)f;
    const double L0 = m->fib_L0[f];
    double El = d->fib_E0[f] + alpha * (d0[0] * dd[0] + d0[1] * dd[1] + d0[2] * dd[2]) / (L0 * L0);
    double dS;
    fibreLaw(m, El, &d->fib_S[f], &dS);
  }
  if (m->mat.form != CSF_FORM_MIXED_P0) {
    return;
  }
  for (int e = 0; e < m->mesh->ntet; e++) {
    const int* tv = m->mesh->tet + 10 * e;
    const double* g = d->g0 + 30 * (size_t)e;
    double s = 0;
    for (int a = 0; a < 10; a++) {
      for (int i = 0; i < 3; i++) {
        s += g[3 * a + i] * d->du[3 * tv[a] + i];
      }
    }
    d->theta[e] = d->vr0[e] + alpha * s / m->vol[e];
    d->pel[e] = m->mat.kappa * (d->theta[e] - 1.0);
  }
}


size_t csf_stateSize(const csfModel* m) {
  return (size_t)m->ndof + 2 * (size_t)m->mesh->ntet + (size_t)m->nfib + 1;
}


void csf_stateGet(const csfModel* m, const csfData* d, double* state) {
  const size_t n = (size_t)m->ndof, nt = (size_t)m->mesh->ntet, nf = (size_t)m->nfib;
  memcpy(state, d->u, n * sizeof(double));
  memcpy(state + n, d->theta, nt * sizeof(double));
  memcpy(state + n + nt, d->pel, nt * sizeof(double));
  memcpy(state + n + 2 * nt, d->fib_S, nf * sizeof(double));
  state[n + 2 * nt + nf] = d->load;
}


void csf_stateSet(const csfModel* m, csfData* d, const double* state) {
  const size_t n = (size_t)m->ndof, nt = (size_t)m->mesh->ntet, nf = (size_t)m->nfib;
  memcpy(d->u, state, n * sizeof(double));
  memcpy(d->theta, state + n, nt * sizeof(double));
  memcpy(d->pel, state + n + nt, nt * sizeof(double));
  memcpy(d->fib_S, state + n + 2 * nt, nf * sizeof(double));
  d->load = state[n + 2 * nt + nf];
}


void csf_dataSyncVolume(const csfModel* m, csfData* d) {
  csf_assemble(m, d, d->load, 0);
  for (int f = 0; f < m->nfib; f++) {
    double dS;
    fibreLaw(m, d->fib_E[f], &d->fib_S[f], &dS);
  }
  for (int e = 0; e < m->mesh->ntet; e++) {
    d->theta[e] = d->vratio[e];
    d->pel[e] = m->mat.kappa * (d->theta[e] - 1.0);
  }
}


/* energy slope g = R . du over the free dofs at the last assembly (N mm) */
static double slope(const csfModel* m, const csfData* d) {
  double g = 0;
  for (int i = 0; i < m->ndof; i++) {
    if (!m->fixed[i]) {
      g += d->r[i] * d->du[i];
    }
  }
  return g;
}


/* Line search on the energy slope g(s) = R(u + s du) . du (Crisfield 1991, Sec. 9.3; FEBio's
 * line search): with closed chambers the follower pressure is conservative, so g is the slope of
 * the total potential along du, and the best step is its root. s = 1 is accepted when
 * g(1) <= 0 (energy still falls: the step is not too long) or |g(1)| <= eta |g(0)|; otherwise the
 * root is bracketed in (0, 1) and found by Illinois regula falsi until |g(s)| <= eta |g(0)|
 * (eta = 0.5: a loose search, the Newton step does the rest). An inverted element halves s.
 * Trial residuals are assembled without K; the accepted point is assembled with K. On entry d->r
 * is the residual at u (s = 0) and d->du the Newton step; on success d->u = u + s du. Returns 1
 * on success, 0 when no acceptable s was found (d->u is then left at some trial point). */
static int energyLineSearch(const csfModel* m, csfData* d, double load,
                            const csfNewtonOptions* opt, double* alpha_out, double* g0_out,
                            double* g1_out, int* neval) {
  const size_t n = (size_t)m->ndof;
  const double g0 = slope(m, d);
  *g0_out = g0;
  double moved = 0.0, s = 1.0;
  double sa = 0.0, ga = g0, sb = NAN, gb = NAN; /* bracket: g(sa) < 0 < g(sb) */
  int side = 0, accepted = 0, last_ok = 0;
  double g = NAN;
  for (int k = 0; k <= opt->max_ls + 4; k++) {
    for (size_t i = 0; i < n; i++) {
      d->u[i] += (s - moved) * d->du[i];
    }
    moved = s;
    updateTheta(m, d, s);
    (*neval)++;
    if (csf_assemble(m, d, load, 0) != 0) {
      sb = s, gb = NAN; /* inverted: too long */
      s = 0.5 * (sa + s);
      last_ok = 0;
      continue;
    }
    g = slope(m, d);
    last_ok = 1;
    if (!(g0 < 0.0)) {
      /* not a descent direction of the potential (modified tangent): keep the Newton step */
      accepted = 1;
      break;
    }
    if ((s == 1.0 && g <= 0.0) || fabs(g) <= opt->ls_eta * fabs(g0)) {
      accepted = 1;
      break;
    }
    if (g < 0.0) {
      sa = s, ga = g;
      if (side == -1 && isfinite(gb)) {
        gb *= 0.5; /* Illinois: the same end moved twice */
      }
      side = -1;
    } else {
      sb = s, gb = g;
      if (side == 1) {
        ga *= 0.5;
      }
      side = 1;
    }
    s = isfinite(gb) ? sa - ga * (sb - sa) / (gb - ga) : 0.5 * (sa + sb);
    /* keep the trial inside the bracket, away from its ends */
    const double w = sb - sa;
    s = fmin(fmax(s, sa + 0.05 * w), sb - 0.05 * w);
  }
  if (!accepted && !last_ok) {
    return 0;
  }
  /* budget spent on a valid point: take it, Newton continues from there */
  *alpha_out = moved;
  *g1_out = g;
  return csf_assemble(m, d, load, 1) == 0;
}


csStatus csf_newtonSolve(const csfModel* m, csfData* d, double load, const csfNewtonOptions* opt,
                         int* iters, csError* err) {
  const size_t n = (size_t)m->ndof;
#ifdef _OPENMP
  if (opt->threads > 0) {
    omp_set_num_threads(opt->threads);
  }
#endif
  memcpy(d->u_save, d->u, n * sizeof(double));
  const size_t nt = (size_t)m->mesh->ntet;
  memcpy(d->theta_save, d->theta, nt * sizeof(double));
  const size_t nfb = (size_t)m->nfib;
  memcpy(d->fib_S_save, d->fib_S, nfb * sizeof(double));
  int it = 0;
  if (csf_assemble(m, d, load, 1) != 0) {
    memcpy(d->u, d->u_save, n * sizeof(double));
    memcpy(d->theta, d->theta_save, nt * sizeof(double));
    memcpy(d->fib_S, d->fib_S_save, nfb * sizeof(double));
    if (iters) {
      *iters = 0;
    }
    return cs_errorSet(err, CS_ERR_DIVERGED, "fem: inverted element at the start of load %g",
                       load);
  }
  for (it = 1; it <= opt->max_iter; it++) {
    if (d->rnorm <= fmax(opt->atol, opt->rtol * d->fnorm)) {
      break;
    }
    /* solve K du = -R */
    for (size_t i = 0; i < n; i++) {
      d->du[i] = m->fixed[i] ? load * m->u_fix[i] - d->u[i] : -d->r[i];
    }
    double t0 = csf_wallTime();
    int fst = csf_linSolverFactor(d->ls, d->kval);
    d->stats.t_factor += csf_wallTime() - t0;
    d->stats.n_factor++;
    if (fst != 0) {
      memcpy(d->u, d->u_save, n * sizeof(double));
    memcpy(d->theta, d->theta_save, nt * sizeof(double));
    memcpy(d->fib_S, d->fib_S_save, nfb * sizeof(double));
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: singular tangent at load %g (iter %d)",
                         load, it);
    }
    t0 = csf_wallTime();
    csf_linSolverSolve(d->ls, d->du);
    d->stats.t_solve += csf_wallTime() - t0;
    d->stats.n_newton++;
    /* base of the linearised dilatation update: v/V and g at the current iterate */
    memcpy(d->vr0, d->vratio, nt * sizeof(double));
    memcpy(d->g0, d->gel, nt * 30 * sizeof(double));
    memcpy(d->fib_E0, d->fib_E, nfb * sizeof(double));
    memcpy(d->fib_d0, d->fib_d, 3 * nfb * sizeof(double));
    /* line search */
    double alpha = 1.0, g0 = 0.0, g1 = 0.0;
    int ok = 0, neval = 0;
    int moves_fixed = 0;
    for (size_t i = 0; i < n; i++) {
      if (m->fixed[i] && d->du[i] != 0.0) {
        moves_fixed = 1;
        break;
      }
    }
    if (opt->line_search == CSF_LS_ENERGY && !moves_fixed) {
      ok = energyLineSearch(m, d, load, opt, &alpha, &g0, &g1, &neval);
    } else {
      /* backtracking on ||R|| */
      const double r0 = d->rnorm;
      double moved = 0.0;
      for (int ls = 0; ls <= opt->max_ls; ls++) {
        for (size_t i = 0; i < n; i++) {
          d->u[i] += (alpha - moved) * d->du[i];
        }
        moved = alpha;
        updateTheta(m, d, alpha);
        int st = csf_assemble(m, d, load, 1);
        neval++;
        if (st == 0 && d->rnorm < (it == 1 ? CSF_LS_GROWTH_FIRST : CSF_LS_GROWTH) * r0) {
          ok = 1;
          break;
        }
        alpha *= 0.5;
      }
    }
    if (!ok) {
      memcpy(d->u, d->u_save, n * sizeof(double));
      memcpy(d->theta, d->theta_save, nt * sizeof(double));
      memcpy(d->fib_S, d->fib_S_save, nfb * sizeof(double));
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: line search failed at load %g (iter %d)",
                         load, it);
    }
    /* fibre law zones: how many fibres changed zone in this step (diagnostics) */
    csfNewtonIter rep = {load, it, alpha, neval, g0, g1, d->rnorm, d->fnorm, 0, 0, 0};
    for (int f = 0; f < m->nfib; f++) {
      const double E = d->fib_E[f];
      const unsigned char z = E <= -CSF_FIBRE_SLACK ? 0 : (E < CSF_FIBRE_SLACK ? 1 : 2);
      rep.fib_switch += z != d->fib_zone[f];
      rep.fib_smooth += z == 1;
      rep.fib_taut += z == 2;
      d->fib_zone[f] = z;
    }
    if (opt->monitor) {
      opt->monitor(opt->monitor_user, &rep);
    }
  }
  if (iters) {
    *iters = it - 1;
  }
  if (d->rnorm > fmax(opt->atol, opt->rtol * d->fnorm)) {
    memcpy(d->u, d->u_save, n * sizeof(double));
    memcpy(d->theta, d->theta_save, nt * sizeof(double));
    memcpy(d->fib_S, d->fib_S_save, nfb * sizeof(double));
    csf_assemble(m, d, d->load, 0);
    return cs_errorSet(err, CS_ERR_DIVERGED,
                       "fem: Newton did not converge at load %g in %d iterations (|R| %.3g N)",
                       load, opt->max_iter, d->rnorm);
  }
  return CS_OK;
}


/* restore the Newton entry state (u, dilatation and fibre states, load) */
static void restoreEntry(const csfModel* m, csfData* d, double load0) {
  memcpy(d->u, d->u_save, (size_t)m->ndof * sizeof(double));
  memcpy(d->theta, d->theta_save, (size_t)m->mesh->ntet * sizeof(double));
  memcpy(d->fib_S, d->fib_S_save, (size_t)m->nfib * sizeof(double));
  csf_assemble(m, d, load0, 0);
}


csStatus csf_newtonSolveVolume(const csfModel* m, csfData* d, double vol_target,
                               const csfNewtonOptions* opt, int* iters, csError* err) {
  const size_t n = (size_t)m->ndof, nt = (size_t)m->mesh->ntet, nfb = (size_t)m->nfib;
#ifdef _OPENMP
  if (opt->threads > 0) {
    omp_set_num_threads(opt->threads);
  }
#endif
  const double load0 = d->load;
  memcpy(d->u_save, d->u, n * sizeof(double));
  memcpy(d->theta_save, d->theta, nt * sizeof(double));
  memcpy(d->fib_S_save, d->fib_S, nfb * sizeof(double));
  double load = load0;
  int it = 0;
  if (iters) {
    *iters = 0;
  }
  if (csf_assemble(m, d, load, 1) != 0) {
    restoreEntry(m, d, load0);
    return cs_errorSet(err, CS_ERR_DIVERGED, "fem: inverted element at the start of volume %g",
                       vol_target);
  }
  const double vtol = opt->rtol * fabs(vol_target);
  for (it = 1; it <= opt->max_iter; it++) {
    const double c = d->vol_w - vol_target;
    if (d->rnorm <= fmax(opt->atol, opt->rtol * d->fnorm) && fabs(c) <= vtol) {
      break;
    }
    /* K x1 = -R (fixed dofs moved to their targets), K x2 = b = dVw/du */
    for (size_t i = 0; i < n; i++) {
      d->du[i] = m->fixed[i] ? load * m->u_fix[i] - d->u[i] : -d->r[i];
      d->du2[i] = d->fext1[i];
    }
    double t0 = csf_wallTime();
    int fst = csf_linSolverFactor(d->ls, d->kval);
    d->stats.t_factor += csf_wallTime() - t0;
    d->stats.n_factor++;
    if (fst != 0) {
      restoreEntry(m, d, load0);
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: singular tangent at volume %g (iter %d)",
                         vol_target, it);
    }
    t0 = csf_wallTime();
    csf_linSolverSolve(d->ls, d->du);
    csf_linSolverSolve(d->ls, d->du2);
    d->stats.t_solve += csf_wallTime() - t0;
    d->stats.n_newton++;
    /* constraint b . du = -c with du = x1 + dload x2 */
    double bx1 = 0, bx2 = 0;
    for (size_t i = 0; i < n; i++) {
      bx1 += d->fext1[i] * d->du[i];
      bx2 += d->fext1[i] * d->du2[i];
    }
    if (!(fabs(bx2) > 0)) {
      restoreEntry(m, d, load0);
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: volume control: b.K^-1.b = 0 (iter %d)", it);
    }
    const double dload = -(c + bx1) / bx2;
    for (size_t i = 0; i < n; i++) {
      d->du[i] += dload * d->du2[i];
    }
    memcpy(d->vr0, d->vratio, nt * sizeof(double));
    memcpy(d->g0, d->gel, nt * 30 * sizeof(double));
    memcpy(d->fib_E0, d->fib_E, nfb * sizeof(double));
    memcpy(d->fib_d0, d->fib_d, 3 * nfb * sizeof(double));
    /* step, halved while an element inverts */
    double alpha = 1.0, moved = 0.0;
    int ok = 0;
    for (int ls = 0; ls <= opt->max_ls; ls++) {
      for (size_t i = 0; i < n; i++) {
        d->u[i] += (alpha - moved) * d->du[i];
      }
      load += (alpha - moved) * dload;
      moved = alpha;
      updateTheta(m, d, alpha);
      if (csf_assemble(m, d, load, 1) == 0) {
        ok = 1;
        break;
      }
      alpha *= 0.5;
    }
    if (!ok) {
      restoreEntry(m, d, load0);
      if (iters) {
        *iters = it;
      }
      return cs_errorSet(err, CS_ERR_DIVERGED, "fem: inverted elements at volume %g (iter %d)",
                         vol_target, it);
    }
    if (opt->monitor) {
      csfNewtonIter rep = {load, it, alpha, 1, 0, 0, d->rnorm, d->fnorm, 0, 0, 0};
      opt->monitor(opt->monitor_user, &rep);
    }
  }
  if (iters) {
    *iters = it - 1;
  }
  if (d->rnorm > fmax(opt->atol, opt->rtol * d->fnorm) ||
      fabs(d->vol_w - vol_target) > vtol) {
    restoreEntry(m, d, load0);
    return cs_errorSet(err, CS_ERR_DIVERGED,
                       "fem: volume control did not converge at volume %g in %d iterations "
                       "(|R| %.3g N)", vol_target, opt->max_iter, d->rnorm);
  }
  return CS_OK;
}


void csf_tetCauchy(const csfModel* m, const csfData* d, int e, double sigma[6]) {
  const int* tv = m->mesh->tet + 10 * e;
  double ue[30];
  for (int a = 0; a < 10; a++) {
    for (int i = 0; i < 3; i++) {
      ue[3 * a + i] = d->u[3 * tv[a] + i];
    }
  }
  memset(sigma, 0, 6 * sizeof(double));
  for (int g = 0; g < 4; g++) {
    double F[9], Fi[9], P[9];
    defGrad(m->dNdX + 120 * (size_t)e + 30 * g, ue, F);
    double J = inv3(F, Fi);
    if (!(J > 0)) {
      continue;
    }
    csf_yeohDev(m->mat.C10, m->mat.C20, F, NULL, P, NULL);
    const double pv = m->mat.form == CSF_FORM_MIXED_P0
                          ? m->mat.kappa * (d->vratio[e] - 1.0) + m->mat.kappa_pt * (J - 1.0)
                          : m->mat.kappa * (J - 1.0);
    /* sigma = P F^T / J + pv I */
    double s[9];
    for (int i = 0; i < 3; i++) {
      for (int k = 0; k < 3; k++) {
        s[3 * i + k] = (P[3 * i] * F[3 * k] + P[3 * i + 1] * F[3 * k + 1] +
                        P[3 * i + 2] * F[3 * k + 2]) /
                           J +
                       (i == k ? pv : 0.0);
      }
    }
    sigma[0] += 0.25 * s[0], sigma[1] += 0.25 * s[4], sigma[2] += 0.25 * s[8];
    sigma[3] += 0.25 * s[1], sigma[4] += 0.25 * s[5], sigma[5] += 0.25 * s[2];
  }
}


double csf_reactionSum(const csfModel* m, const csfData* d, int dir) {
  double s = 0;
  for (int i = dir; i < m->ndof; i += 3) {
    if (m->fixed[i]) {
      s += d->r[i];
    }
  }
  return s;
}


csStatus csf_loadRamp(const csfModel* m, csfData* d, double load_end, int nstep,
                      const csfNewtonOptions* opt, int* iters, csError* err) {
  double load = d->load, dl = (load_end - load) / nstep;
  const double dl_min = 1e-4 * fabs(load_end - load);
  int total = 0;
  while ((dl > 0 && load < load_end) || (dl < 0 && load > load_end)) {
    double target = (dl > 0) ? fmin(load + dl, load_end) : fmax(load + dl, load_end);
    int it = 0;
    csStatus st = csf_newtonSolve(m, d, target, opt, &it, err);
    total += it;
    if (st != CS_OK) {
      dl *= 0.5;
      if (fabs(dl) < dl_min) {
        if (iters) {
          *iters = total;
        }
        return st;
      }
      continue;
    }
    load = target;
    if (it <= 5) {
      dl *= 1.5;
    }
  }
  if (iters) {
    *iters = total;
  }
  return CS_OK;
}

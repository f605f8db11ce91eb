/* fem_assembly.c: the sparse pattern and the assembly of residual and tangent
 * (fem_assembly.h).
 *
 * Rationale. Elements scatter into one fixed CSR pattern of 3x3 node blocks, built once with
 * per-element maps to the value slots, so that assembly allocates nothing and touches each
 * value by index. Tetrahedra run in parallel (OpenMP) with atomic adds; fibres and pressure
 * faces, a few thousand small elements, run serially. Dirichlet dofs become identity rows and
 * columns after the free rows received the linearised lift of the prescribed values, which keeps
 * K symmetric where the physics is. */
#include "fem_assembly.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_element.h"

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
  /* fibres inside one host (fib_single), as a kernels-only model has them */
  const csStatus st = csf_modelFinalizeKernels(m, err);
  if (st == CS_OK) {
    m->finalized = 1;
  }
  return st;
}


csStatus csf_modelFinalizeKernels(csfModel* m, csError* err) {
  /* fibres inside one host: both halves name the same 10 nodes */
  free(m->fib_single);
  m->fib_single = malloc((size_t)(m->nfib > 0 ? m->nfib : 1));
  if (!m->fib_single) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_model: out of memory (fibres)");
  }
  for (int f = 0; f < m->nfib; f++) {
    m->fib_single[f] = !memcmp(m->fib_node + 20 * f, m->fib_node + 20 * f + 10, 10 * sizeof(int));
  }
  m->finalized = CSF_MODEL_KERNELS;
  return CS_OK;
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


/* gather the 10 nodal displacements of tetrahedron e */
static void gatherTet(const csfModel* m, const double* u, int e, double ue[30]) {
  const int* tv = m->mesh->tet + 10 * e;
  for (int a = 0; a < 10; a++) {
    for (int i = 0; i < 3; i++) {
      ue[3 * a + i] = u[3 * tv[a] + i];
    }
  }
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
  double Nq[CSF_TET_NQ][10];
  csf_tetQuadratureShape(Nq);
  const int grav = m->gravity[0] != 0 || m->gravity[1] != 0 || m->gravity[2] != 0;
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 64) reduction(+ : bad) reduction(min : jmin)
#endif
  for (int e = 0; e < me->ntet; e++) {
    double ue[30], re[30], ke[900], vr, jm;
    gatherTet(m, d->u, e, ue);
    if (csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e, m->vol[e], ue,
                      d->theta[e], re, want_k ? ke : NULL, &vr, d->gel + 30 * (size_t)e, &jm)) {
      bad++;
      continue;
    }
    d->vratio[e] = vr;
    d->jel[e] = jm;
    jmin = fmin(jmin, jm);
    const int* tv = me->tet + 10 * e;
    if (grav) {
      for (int g = 0; g < CSF_TET_NQ; g++) {
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
  /* fibres: in parallel like the tetrahedra (tens of thousands of elements once split at
   * faces); each thread's element matrix lives on its stack. A fibre inside one host
   * (csfModel.fib_split) couples its 10 nodes: its two coefficient halves are summed into one
   * 10-node chord (4x fewer matrix entries than the 20-node form) */
#ifdef _OPENMP
#pragma omp parallel for schedule(dynamic, 256)
#endif
  for (int f = 0; f < m->nfib; f++) {
    const int* fv = m->fib_node + 20 * f;
    const double* cf = m->fib_coef + 20 * (size_t)f;
    const int nn = m->fib_single[f] ? 10 : 20;
    double x[60], rf[60], c10[10], kf[3600];
    for (int a = 0; a < nn; a++) {
      for (int i = 0; i < 3; i++) {
        x[3 * a + i] = me->x[3 * fv[a] + i] + d->u[3 * fv[a] + i];
      }
    }
    if (nn == 10) {
      for (int a = 0; a < 10; a++) {
        c10[a] = cf[a] + cf[10 + a];
      }
      cf = c10;
    }
    if (!csf_fibreKernel(nn, cf, x, m->fib_L0[f], m->fib_EA[f], d->fib_S[f],
                         m->fib_tension_only, m->fib_geo_tension, rf, want_k ? kf : NULL,
                         &d->fib_E[f], d->fib_d + 3 * (size_t)f)) {
      continue;
    }
    for (int a = 0; a < nn; a++) {
      for (int i = 0; i < 3; i++) {
        atomicAdd(&d->r[3 * fv[a] + i], rf[3 * a + i]);
      }
    }
    if (want_k) {
      /* the 10 x 10 top-left block of the 20 x 20 map addresses the single host's pairs */
      const int* map = m->fib_map + 400 * (size_t)f;
      const int ld = 3 * nn;
      for (int a = 0; a < nn; a++) {
        for (int b = 0; b < nn; b++) {
          for (int i = 0; i < 3; i++) {
            for (int c = 0; c < 3; c++) {
              atomicAdd(&d->kval[csrIndex(m, fv[a], i, map[20 * a + b], c)],
                        kf[ld * (3 * a + i) + 3 * b + c]);
            }
          }
        }
      }
    }
  }
  /* dead loads (a tip force): conservative, no stiffness */
  for (size_t i = 0; i < n; i++) {
    d->r[i] -= m->f_dead[i];
  }
  double fint2 = 0;
  for (size_t i = 0; i < n; i++) {
    fint2 += d->r[i] * d->r[i];
  }
  /* follower pressure on faces: R -= f_ext, with f_ext = load * f1 and f1 the force per unit
   * load, which is also the gradient of the weighted chamber volume Vw = sum p1 V_f */
  double fext2 = 0, volw = 0;
  memset(d->fext1, 0, n * sizeof(double));
  for (int f = 0; f < me->nface; f++) {
    const double p1 = m->face_p[f];
    if (p1 == 0.0) {
      continue;
    }
    const int* fn = me->face + 6 * f;
    double xf[18], fe1[18], kfe[18 * 18], vf;
    for (int a = 0; a < 6; a++) {
      for (int i = 0; i < 3; i++) {
        xf[3 * a + i] = me->x[3 * fn[a] + i] + d->u[3 * fn[a] + i];
      }
    }
    csf_faceKernel(xf, p1, fe1, want_k ? kfe : NULL, &vf);
    volw += p1 * vf;
    const int* loc = m->face_local + 6 * f;
    const int* map = m->tet_map + 100 * (size_t)me->face_tet[f];
    for (int a = 0; a < 6; a++) {
      for (int i = 0; i < 3; i++) {
        const double fe = load * fe1[3 * a + i];
        d->r[3 * fn[a] + i] -= fe;
        d->fext1[3 * fn[a] + i] += fe1[3 * a + i];
        fext2 += fe * fe;
      }
      if (want_k) {
        for (int b = 0; b < 6; b++) {
          const int k = map[10 * loc[a] + loc[b]];
          for (int i = 0; i < 3; i++) {
            for (int c = 0; c < 3; c++) {
              d->kval[csrIndex(m, fn[a], i, k, c)] += load * kfe[18 * (3 * a + i) + 3 * b + c];
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


void csf_dataSyncVolume(const csfModel* m, csfData* d) {
  csf_assemble(m, d, d->load, 0);
  for (int f = 0; f < m->nfib; f++) {
    double dS;
    csf_fibreLaw(m->fib_tension_only, d->fib_E[f], &d->fib_S[f], &dS);
  }
  for (int e = 0; e < m->mesh->ntet; e++) {
    d->theta[e] = d->vratio[e];
    d->pel[e] = m->mat.kappa * (d->theta[e] - 1.0);
  }
}


void csf_tangentApply(const csfModel* m, const csfData* d, const double* x, double* y) {
#ifdef _OPENMP
#pragma omp parallel for schedule(static)
#endif
  for (int i = 0; i < m->ndof; i++) {
    double s = 0;
    for (int q = m->row_ptr[i]; q < m->row_ptr[i + 1]; q++) {
      s += d->kval[q] * x[m->col[q]];
    }
    y[i] = s;
  }
}


void csf_tetCauchyAt(const csfModel* m, const csfData* d, int e, double sigma[6]) {
  double ue[30];
  gatherTet(m, d->u, e, ue);
  csf_tetCauchy(&m->mat, m->dNdX + 120 * (size_t)e, ue, d->vratio[e], sigma);
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


double csf_worstElement(const csfModel* m, const csfData* d, double X[3]) {
  const csfMesh* me = m->mesh;
  int emin = 0;
  for (int e = 1; e < me->ntet; e++) {
    emin = d->jel[e] < d->jel[emin] ? e : emin;
  }
  for (int i = 0; i < 3; i++) {
    double c = 0;
    for (int a = 0; a < 4; a++) {
      c += 0.25 * me->x[3 * me->tet[10 * emin + a] + i];
    }
    X[i] = c;
  }
  return d->jel[emin];
}

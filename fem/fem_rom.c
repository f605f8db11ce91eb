/* fem_rom.c: the reduced-order FE model (fem_rom.h): the basis V and its element sets and
 * weights, the kept fibres' chord operators, the gravity projection G, the chambers' volume
 * tensors, and the per-solve data (csfRomData). The evaluation of the reduced forces is
 * fem_rom_eval.c, the reduced Newton fem_rom_newton.c; what they share with this file is
 * declared in fem_rom_internal.h.
 *
 * Rationale.
 * Gravity and dead loads are linear in the load and constant in q, so they are projected once,
 * exactly, over every element (G, here at creation) and never hyper-reduced. */
#include "fem_rom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_element.h"
#include "fem_material.h"
#include "fem_rom_fibre.h"
#include "fem_rom_internal.h"
#include "fem_rom_mixed.h"

/* the kept fibres' chord operators D_k and reference chords X_k (fem_rom.h csfRom.fib_D); a
 * fibre inside one host lists its ten nodes twice (fem_model.h fib_single), so the sum over all
 * 20 coefficients is its chord in both cases. 0, or -1 out of memory. */
static int fibreOperators(csfRom* r) {
  const csfModel* m = r->fem;
  const int n = r->n, nel = r->nel[CSF_ROM_SET_FIBRE];
  free(r->fib_D), free(r->fib_X);
  r->fib_D = calloc((size_t)(nel > 0 ? nel : 1) * 3 * (size_t)n, sizeof(double));
  r->fib_X = calloc((size_t)(nel > 0 ? nel : 1) * 3, sizeof(double));
  if (!r->fib_D || !r->fib_X) {
    return -1;
  }
  for (int k = 0; k < nel; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    const int* fv = m->fib_node + 20 * (size_t)f;
    const double* c = m->fib_coef + 20 * (size_t)f;
    double* D = r->fib_D + (size_t)k * 3 * (size_t)n;
    for (int a = 0; a < 20; a++) {
      if (c[a] == 0.0) {
        continue;
      }
      for (int i = 0; i < 3; i++) {
        const double* row = r->V + (size_t)(3 * fv[a] + i) * (size_t)n;
        double* Di = D + (size_t)i * (size_t)n;
        for (int j = 0; j < n; j++) {
          Di[j] += c[a] * row[j];
        }
        r->fib_X[3 * k + i] += c[a] * m->mesh->x[3 * fv[a] + i];
      }
    }
  }
  return 0;
}

csfRom* csf_romCreate(const csfModel* fem, int n, const double* V, csError* err) {
  if (!fem || !fem->finalized || n < 1 || !V) {
    cs_errorSet(err, CS_ERR_ARG, "fem_rom: a finalised FE model and a basis of n >= 1 columns "
                "are needed (n = %d)", n);
    return NULL;
  }
  const size_t nd = (size_t)fem->ndof;
  for (size_t i = 0; i < nd; i++) {
    for (int j = 0; j < n; j++) {
      const double v = V[i * (size_t)n + (size_t)j];
      if (!isfinite(v) || (fem->fixed[i] && v != 0.0)) {
        cs_errorSet(err, CS_ERR_ARG, "fem_rom: basis row %zu (node %zu, %c) column %d is %g: "
                    "the basis must be finite and zero on clamped dofs", i, i / 3,
                    "xyz"[i % 3], j, v);
        return NULL;
      }
    }
  }
  csfRom* r = calloc(1, sizeof *r);
  if (!r) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_rom: out of memory");
    return NULL;
  }
  r->fem = fem, r->ndof = fem->ndof, r->n = n;
  r->V = malloc(nd * (size_t)n * sizeof(double));
  r->G = calloc((size_t)n * 3, sizeof(double));
  const int count[CSF_ROM_NSET] = {fem->mesh->ntet, fem->nfib, fem->mesh->nface};
  int ok = r->V && r->G;
  for (int s = 0; s < CSF_ROM_NSET && ok; s++) {
    r->nel[s] = count[s];
    r->el[s] = malloc((size_t)(count[s] > 0 ? count[s] : 1) * sizeof(int));
    r->w[s] = malloc((size_t)(count[s] > 0 ? count[s] : 1) * sizeof(double));
    ok = r->el[s] && r->w[s];
    for (int e = 0; ok && e < count[s]; e++) {
      r->el[s][e] = e, r->w[s][e] = 1.0;
    }
  }
  if (!ok) {
    csf_romDestroy(r);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_rom: out of memory (basis %zu x %d)", nd, n);
    return NULL;
  }
  memcpy(r->V, V, nd * (size_t)n * sizeof(double));
  if (fibreOperators(r) != 0) {
    csf_romDestroy(r);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_rom: out of memory (the fibres' chord operators, %d x "
                "3 x %d)", fem->nfib, n);
    return NULL;
  }
  /* G = V^T f_g(e_i): f_g,a = rho int N_a dV (the FE's 4-point rule, fem_assembly.c) */
  double Nq[CSF_TET_NQ][10];
  csf_tetQuadratureShape(Nq);
  const csfMesh* me = fem->mesh;
  for (int e = 0; e < me->ntet; e++) {
    for (int a = 0; a < 10; a++) {
      double m = 0;
      for (int g = 0; g < CSF_TET_NQ; g++) {
        m += fem->mat.rho * fem->wq[4 * e + g] * Nq[g][a];
      }
      const int node = me->tet[10 * e + a];
      for (int i = 0; i < 3; i++) {
        const double* row = r->V + (size_t)(3 * node + i) * (size_t)n;
        for (int j = 0; j < n; j++) {
          r->G[3 * j + i] += m * row[j];
        }
      }
    }
  }
  return r;
}


void csf_romDestroy(csfRom* r) {
  if (!r) {
    return;
  }
  free(r->V);
  free(r->G);
  free(r->face_ch), free(r->ch_V0), free(r->ch_g0), free(r->ch_H);
  free(r->P), free(r->A_chol);
  free(r->Qf), free(r->Gf_chol);
  free(r->fib_D), free(r->fib_X);
  for (int s = 0; s < CSF_ROM_NSET; s++) {
    free(r->el[s]);
    free(r->w[s]);
  }
  free(r);
}


/* one face's share at q: volume (mm^3), gradient g (+= V_f^T fe, p = 1) and Hessian H
 * (+= V_f^T (-kfe) V_f) */
static void faceShare(const csfRom* r, const double* q, int f, double* vol, double* g, double* H,
                      double* T) {
  const csfMesh* me = r->fem->mesh;
  const int n = r->n;
  const int* fn = me->face + 6 * (size_t)f;
  double xf[18], fe[18], kfe[324], vf;
  for (int a = 0; a < 6; a++) {
    for (int i = 0; i < 3; i++) {
      const double* row = r->V + (size_t)(3 * fn[a] + i) * (size_t)n;
      double s = me->x[3 * fn[a] + i];
      for (int j = 0; j < n; j++) {
        s += row[j] * q[j];
      }
      xf[3 * a + i] = s;
    }
  }
  csf_faceKernel(xf, 1.0, fe, kfe, &vf);
  *vol += vf;
  for (int k = 0; k < 18; k++) {
    const double* row = r->V + (size_t)(3 * fn[k / 3] + k % 3) * (size_t)n;
    for (int j = 0; j < n; j++) {
      g[j] += row[j] * fe[k];
      double t = 0;
      for (int l = 0; l < 18; l++) {
        t -= kfe[18 * k + l] * r->V[(size_t)(3 * fn[l / 3] + l % 3) * (size_t)n + j];
      }
      T[(size_t)k * n + j] = t;
    }
  }
  for (int k = 0; k < 18; k++) {
    const double* row = r->V + (size_t)(3 * fn[k / 3] + k % 3) * (size_t)n;
    for (int i = 0; i < n; i++) {
      for (int j = 0; j < n; j++) {
        H[(size_t)i * n + j] += row[i] * T[(size_t)k * n + j];
      }
    }
  }
}

csStatus csf_romChamberTensors(csfRom* r, int nch, const int* face_ch, csError* err) {
  const csfMesh* me = r->fem->mesh;
  const size_t n = (size_t)r->n, nn = n * n;
  for (int f = 0; f < me->nface; f++) {
    if (face_ch[f] < -1 || face_ch[f] >= nch) {
      return cs_errorSet(err, CS_ERR_ARG, "fem_rom: face %d in chamber %d of %d", f, face_ch[f],
                         nch);
    }
  }
  free(r->face_ch), free(r->ch_V0), free(r->ch_g0), free(r->ch_H);
  r->nch = 0;
  r->face_ch = malloc((size_t)(me->nface + 1) * sizeof(int));
  r->ch_V0 = calloc((size_t)nch + 1, sizeof(double));
  r->ch_g0 = calloc((size_t)nch * n + 1, sizeof(double));
  r->ch_H = calloc((size_t)nch * (n + 1) * nn + 1, sizeof(double));
  double* q = calloc(n, sizeof(double));
  double* g = calloc(n, sizeof(double));
  double* T = calloc(18 * n, sizeof(double));
  if (!r->face_ch || !r->ch_V0 || !r->ch_g0 || !r->ch_H || !q || !g || !T) {
    free(q), free(g), free(T);
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_rom: out of memory (%d chambers, n = %zu)", nch,
                       n);
  }
  memcpy(r->face_ch, face_ch, (size_t)me->nface * sizeof(int));
  for (int c = 0; c < nch; c++) {
    double* H0 = r->ch_H + (size_t)c * (n + 1) * nn;
    for (int f = 0; f < me->nface; f++) {
      if (face_ch[f] == c) {
        faceShare(r, q, f, &r->ch_V0[c], r->ch_g0 + (size_t)c * n, H0, T);
      }
    }
    /* H is linear in q: H_k = H(e_k) - H(0) exactly (up to round-off) */
    for (size_t k = 0; k < n; k++) {
      double* Hk = H0 + (k + 1) * nn;
      double vol = 0;
      q[k] = 1.0;
      for (int f = 0; f < me->nface; f++) {
        if (face_ch[f] == c) {
          faceShare(r, q, f, &vol, g, Hk, T);
        }
      }
      q[k] = 0.0;
      for (size_t i = 0; i < nn; i++) {
        Hk[i] -= H0[i];
      }
    }
  }
  free(q), free(g), free(T);
  r->nch = nch;
  return CS_OK;
}

/* H(q) = H0 + sum_k q_k H_k of chamber c into Hq (n x n) */
void csf_romChamberHessian(const csfRom* r, int c, const double* q, double* Hq) {
  const size_t n = (size_t)r->n, nn = n * n;
  const double* H0 = r->ch_H + (size_t)c * (n + 1) * nn;
  memcpy(Hq, H0, nn * sizeof(double));
  for (size_t k = 0; k < n; k++) {
    if (q[k] == 0.0) {
      continue;
    }
    const double* Hk = H0 + (k + 1) * nn;
    for (size_t i = 0; i < nn; i++) {
      Hq[i] += q[k] * Hk[i];
    }
  }
}

double csf_romChamberVolume(const csfRom* r, int c, const double* q) {
  const size_t n = (size_t)r->n, nn = n * n;
  const double* H0 = r->ch_H + (size_t)c * (n + 1) * nn;
  const double* g0 = r->ch_g0 + (size_t)c * n;
  double v = r->ch_V0[c];
  for (size_t i = 0; i < n; i++) {
    double h0 = 0, h3 = 0;
    for (size_t j = 0; j < n; j++) {
      h0 += H0[i * n + j] * q[j];
    }
    for (size_t k = 0; k < n; k++) {
      const double* Hk = H0 + (k + 1) * nn + i * n;
      double s = 0;
      for (size_t j = 0; j < n; j++) {
        s += Hk[j] * q[j];
      }
      h3 += q[k] * s;
    }
    v += q[i] * (g0[i] + 0.5 * h0 + h3 / 6.0);
  }
  return v;
}

csStatus csf_romSetWeights(csfRom* r, csfRomSet set, int nel, const int* idx, const double* w,
                           csError* err) {
  const csfModel* m = r->fem;
  const int count[CSF_ROM_NSET] = {m->mesh->ntet, m->nfib, m->mesh->nface};
  if ((int)set < 0 || set >= CSF_ROM_NSET || nel < 0 || nel > count[set] || (nel && (!idx || !w))) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_rom: element set %d: %d weights for %d elements",
                       (int)set, nel, (int)set >= 0 && set < CSF_ROM_NSET ? count[set] : -1);
  }
  for (int e = 0; e < nel; e++) {
    if (idx[e] < 0 || idx[e] >= count[set] || !(w[e] >= 0.0) || !isfinite(w[e])) {
      return cs_errorSet(err, CS_ERR_ARG, "fem_rom: element set %d, entry %d: element %d of %d, "
                         "weight %g (a weight must be finite and >= 0)", (int)set, e, idx[e],
                         count[set], w[e]);
    }
  }
  if (nel > 0) { /* an empty set may come with NULL arrays (memcpy's arguments must not be NULL) */
    memcpy(r->el[set], idx, (size_t)nel * sizeof(int));
    memcpy(r->w[set], w, (size_t)nel * sizeof(double));
  }
  r->nel[set] = nel;
  if (set == CSF_ROM_SET_FIBRE && fibreOperators(r) != 0) {
    return cs_errorSet(err, CS_ERR_MEMORY, "fem_rom: out of memory (the fibres' chord operators, "
                       "%d x 3 x %d)", nel, r->n);
  }
  if (set == CSF_ROM_SET_FIBRE && r->mf > 0) {
    return csf_romFibreFactor(r, err);
  }
  return set == CSF_ROM_SET_TET && r->m > 0 ? csf_romMixedFactor(r, err) : CS_OK;
}


void csf_romProject(const csfRom* r, const double* f, double* fr) {
  memset(fr, 0, (size_t)r->n * sizeof(double));
  for (int i = 0; i < r->ndof; i++) {
    if (f[i] == 0.0) {
      continue;
    }
    const double* row = r->V + (size_t)i * (size_t)r->n;
    for (int j = 0; j < r->n; j++) {
      fr[j] += row[j] * f[i];
    }
  }
}


void csf_romExpand(const csfRom* r, const double* q, double* u) {
  for (int i = 0; i < r->ndof; i++) {
    const double* row = r->V + (size_t)i * (size_t)r->n;
    double s = 0;
    for (int j = 0; j < r->n; j++) {
      s += row[j] * q[j];
    }
    u[i] = s;
  }
}


csfRomData* csf_romDataCreate(const csfRom* r, csError* err) {
  csfRomData* d = calloc(1, sizeof *d);
  if (!d) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_rom: out of memory");
    return NULL;
  }
  const size_t n = (size_t)r->n, nt = (size_t)r->fem->mesh->ntet + 1,
               nf = (size_t)r->fem->nfib + 1;
  d->n = r->n;
  d->m = r->m;
  d->mf = r->mf;
  const size_t m = (size_t)r->m, mf = (size_t)r->mf;
  d->fq_e = calloc(3 * mf + 1, sizeof(double));
  d->fq_B = calloc(3 * mf * n + 1, sizeof(double));
  d->fq_C = calloc(mf * mf + 1, sizeof(double));
  d->fq_E = mf ? calloc(nf, sizeof(double)) : calloc(1, sizeof(double));
  d->ph = calloc(m + 1, sizeof(double));
  d->Bm = calloc(2 * m * n + 1, sizeof(double));
  d->mtmp = calloc(m + n, sizeof(double));
  d->rel = m ? calloc(30 * nt, sizeof(double)) : calloc(1, sizeof(double));
  d->q = calloc(n, sizeof(double));
  d->r = calloc(n, sizeof(double));
  d->K = calloc(n * n, sizeof(double));
  d->Ku = calloc(n * n, sizeof(double));
  d->theta = calloc(nt, sizeof(double));
  d->fib_S = calloc(nf, sizeof(double));
  d->vr = calloc(nt, sizeof(double));
  d->gel = calloc(30 * nt, sizeof(double));
  d->fib_E = calloc(nf, sizeof(double));
  d->fib_d = calloc(3 * nf, sizeof(double));
  d->vr0 = calloc(nt, sizeof(double));
  d->g0 = calloc(30 * nt, sizeof(double));
  d->fib_E0 = calloc(nf, sizeof(double));
  d->fib_d0 = calloc(3 * nf, sizeof(double));
  d->theta_save = calloc(nt, sizeof(double));
  d->fib_S_save = calloc(nf, sizeof(double));
  d->theta_best = calloc(nt, sizeof(double));
  d->fib_S_best = calloc(nf, sizeof(double));
  d->dq = calloc(n, sizeof(double));
  d->q_save = calloc(n, sizeof(double));
  d->q_best = calloc(n, sizeof(double));
  d->q0 = calloc(n, sizeof(double));
  d->lu = calloc(n * n, sizeof(double));
  d->tmp = calloc(2 * n, sizeof(double));
  d->piv = calloc(n, sizeof(int));
  d->ke_v = calloc(61 * n, sizeof(double));
  d->bf_s = calloc(CSF_ROM_BFGS_MAX * n, sizeof(double));
  d->bf_y = calloc(CSF_ROM_BFGS_MAX * n, sizeof(double));
  d->bf_rho = calloc(CSF_ROM_BFGS_MAX, sizeof(double));
  d->bf_a = calloc(CSF_ROM_BFGS_MAX, sizeof(double));
  d->bf_r0 = calloc(n, sizeof(double));
  if (!d->q || !d->r || !d->K || !d->Ku || !d->theta || !d->fib_S || !d->vr || !d->gel || !d->fib_E ||
      !d->fib_d || !d->vr0 || !d->g0 || !d->fib_E0 || !d->fib_d0 || !d->theta_save ||
      !d->fib_S_save || !d->theta_best || !d->fib_S_best || !d->dq || !d->q_save ||
      !d->q_best || !d->q0 || !d->lu || !d->tmp || !d->piv || !d->ke_v || !d->ph || !d->Bm ||
      !d->mtmp || !d->rel || !d->bf_s || !d->bf_y || !d->bf_rho || !d->bf_a || !d->bf_r0 ||
      !d->fq_e || !d->fq_B || !d->fq_C || !d->fq_E) {
    csf_romDataDestroy(d);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_rom: out of memory (reduced data, n = %d)", r->n);
    return NULL;
  }
  csf_romDataReset(r, d);
  return d;
}


void csf_romDataReset(const csfRom* r, csfRomData* d) {
  memset(d->q, 0, (size_t)d->n * sizeof(double));
  d->lu_valid = 0;
  d->bf_k = 0;
  for (int e = 0; e < r->fem->mesh->ntet; e++) {
    d->theta[e] = 1.0;
  }
  for (int f = 0; f < r->fem->nfib; f++) {
    double dS;
    csf_fibreLaw(r->fem->fib_tension_only, 0.0, &d->fib_S[f], &dS); /* as csf_dataCreate */
  }
}


void csf_romDataDestroy(csfRomData* d) {
  if (!d) {
    return;
  }
  double* bufs[] = {d->q, d->r, d->K, d->Ku, d->theta, d->fib_S, d->vr, d->gel, d->fib_E, d->fib_d,
                    d->vr0, d->g0, d->fib_E0, d->fib_d0, d->theta_save, d->fib_S_save,
                    d->theta_best, d->fib_S_best, d->dq, d->q_save, d->q_best, d->q0, d->lu,
                    d->tmp, d->ke_v, d->ph, d->Bm, d->mtmp, d->rel, d->bf_s, d->bf_y,
                    d->bf_rho, d->bf_a, d->bf_r0, d->fq_e, d->fq_B, d->fq_C, d->fq_E};
  for (size_t k = 0; k < sizeof bufs / sizeof bufs[0]; k++) {
    free(bufs[k]);
  }
  free(d->piv);
  free(d);
}

/* fem_rom.c: the reduced-order FE model: reduced forces from fem's kernels, Newton on q
 * (fem_rom.h).
 *
 * Rationale.
 * Every element term is gathered through its own rows of the basis: u_e = V_e q (30 rows for a
 * Tet10 or a fibre inside one host, 60 for a fibre tied to two, 18 for a pressure face), the
 * kernel gives f_e and k_e, and r += w_e V_e^T f_e, K += w_e V_e^T k_e V_e. The cost per element
 * is O(m n + m^2 n + m n^2) for m element dofs and n reduced coordinates, independent of the
 * FE's size: a hyper-reduced model evaluates a few hundred elements instead of tens of
 * thousands. Gravity and dead loads are linear in the load and constant in q, so they are
 * projected once, exactly, over every element (G) and never hyper-reduced.
 * The kernels' state variables: the mixed Tet10 takes the element dilatation state theta_e in
 * its geometric stiffness; here theta_e = v/V of the current q (one residual-only kernel call
 * gives v/V, a second one the tangent), the converged value of the FE's three-field Newton, so
 * the reduced tangent is the exact derivative of the reduced residual (tested against finite
 * differences). The fibres likewise take S_state = S(E(q)).
 * The dense n x n system is solved by LU with partial pivoting (n is tens to a few hundred; the
 * tangent may be indefinite past a limit point). */
#include "fem_rom.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_element.h"
#include "fem_material.h"
#include "fem_rom_fibre.h"
#include "fem_rom_mixed.h"

#define ROM_LS_SHRINK 0.5 /* line-search step factor */
/* the FE's watchdog line search (fem_newton.c CSF_LS_GROWTH_FIRST, CSF_LS_WATCH) */
#define ROM_LS_GROWTH_FIRST 1e4
#define ROM_LS_WATCH 3

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
static void chamberHessian(const csfRom* r, int c, const double* q, double* Hq) {
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


/* ---- evaluation ---------------------------------------------------------------------------- */

/* element displacement ue (3 nn) = V_e q over the element's nodes */
static void gather(const csfRom* r, const double* q, int nn, const int* nodes, double* ue) {
  const int n = r->n;
  for (int a = 0; a < nn; a++) {
    for (int i = 0; i < 3; i++) {
      const double* row = r->V + (size_t)(3 * nodes[a] + i) * (size_t)n;
      double s = 0;
      for (int j = 0; j < n; j++) {
        s += row[j] * q[j];
      }
      ue[3 * a + i] = s;
    }
  }
}

/* fibre f's current host-node positions x (3 nn) at q and its chord coefficients (a fibre
 * inside one host: its two coefficient halves summed into c10, fem_assembly.c); returns nn */
static int fibreGeometry(const csfRom* r, const double* q, int f, double x[60], double c10[10],
                         const double** cf) {
  const csfModel* m = r->fem;
  const int* fv = m->fib_node + 20 * (size_t)f;
  const int nn = m->fib_single[f] ? 10 : 20;
  *cf = m->fib_coef + 20 * (size_t)f;
  gather(r, q, nn, fv, x);
  for (int a = 0; a < nn; a++) {
    for (int i = 0; i < 3; i++) {
      x[3 * a + i] += m->mesh->x[3 * fv[a] + i];
    }
  }
  if (nn == 10) {
    for (int a = 0; a < 10; a++) {
      c10[a] = (*cf)[a] + (*cf)[10 + a];
    }
    *cf = c10;
  }
  return nn;
}

/* rr += w V_e^T fe; K += w V_e^T ke V_e (ke: 3nn x 3nn row-major, may be NULL) */
static void scatter(const csfRom* r, csfRomData* d, int nn, const int* nodes, double w,
                    const double* fe, const double* ke, double* rr) {
  const int n = r->n, m = 3 * nn;
  for (int k = 0; k < m; k++) {
    const double* row = r->V + (size_t)(3 * nodes[k / 3] + k % 3) * (size_t)n;
    const double f = w * fe[k];
    for (int j = 0; j < n; j++) {
      rr[j] += row[j] * f;
    }
  }
  if (!ke) {
    return;
  }
  /* T = ke V_e (m x n), then K += w V_e^T T */
  double* T = d->ke_v;
  memset(T, 0, (size_t)m * (size_t)n * sizeof(double));
  for (int k = 0; k < m; k++) {
    double* Tk = T + (size_t)k * (size_t)n;
    for (int l = 0; l < m; l++) {
      const double kv = ke[(size_t)k * (size_t)m + (size_t)l];
      if (kv == 0.0) {
        continue;
      }
      const double* row = r->V + (size_t)(3 * nodes[l / 3] + l % 3) * (size_t)n;
      for (int j = 0; j < n; j++) {
        Tk[j] += kv * row[j];
      }
    }
  }
  for (int k = 0; k < m; k++) {
    const double* row = r->V + (size_t)(3 * nodes[k / 3] + k % 3) * (size_t)n;
    const double* Tk = T + (size_t)k * (size_t)n;
    for (int i = 0; i < n; i++) {
      const double vi = w * row[i];
      if (vi == 0.0) {
        continue;
      }
      double* Ki = d->K + (size_t)i * (size_t)n;
      for (int j = 0; j < n; j++) {
        Ki[j] += vi * Tk[j];
      }
    }
  }
}

/* A Tet10's share, its tangent symmetric (the mixed kernel's is: fem_element.h): rr += w V_e^T fe
 * as scatter(), and the upper triangle of w V_e^T ke V_e into d->Ku (csf_romEvaluate mirrors it):
 * T = ke V_e (30 x n) row by row, then each row i of the triangle summed over the 30 element
 * dofs in a row buffer (L1-resident) and added to Ku once: half scatter()'s O(30 n^2) and no
 * pass over Ku per element dof. */
static void scatterTetSym(const csfRom* r, csfRomData* d, const int* nodes, double w,
                          const double* fe, const double* ke, double* rr) {
  const int n = r->n;
  const double* row[30];
  for (int k = 0; k < 30; k++) {
    row[k] = r->V + (size_t)(3 * nodes[k / 3] + k % 3) * (size_t)n;
    const double f = w * fe[k];
    for (int j = 0; j < n; j++) {
      rr[j] += row[k][j] * f;
    }
  }
  if (!ke) {
    return;
  }
  double* T = d->ke_v;
  for (int k = 0; k < 30; k++) {
    double* Tk = T + (size_t)k * (size_t)n;
    memset(Tk, 0, (size_t)n * sizeof(double));
    for (int l = 0; l < 30; l++) {
      const double kv = w * ke[30 * k + l];
      if (kv == 0.0) {
        continue;
      }
      for (int j = 0; j < n; j++) {
        Tk[j] += kv * row[l][j];
      }
    }
  }
  double* acc = d->ke_v + 60 * (size_t)n; /* (n) row buffer */
  for (int i = 0; i < n; i++) {
    memset(acc + i, 0, (size_t)(n - i) * sizeof(double));
    for (int k = 0; k < 30; k++) {
      const double vi = row[k][i];
      if (vi == 0.0) {
        continue;
      }
      const double* Tk = T + (size_t)k * (size_t)n;
      for (int j = i; j < n; j++) {
        acc[j] += vi * Tk[j];
      }
    }
    double* Ki = d->Ku + (size_t)i * (size_t)n;
    for (int j = i; j < n; j++) {
      Ki[j] += acc[j];
    }
  }
}

/* v = V_e^T g (n) over a Tet10's rows: the element's volume gradient in reduced coordinates */
static void reduceVector(const csfRom* r, const int* nodes, const double* g, double* v) {
  const int n = r->n;
  memset(v, 0, (size_t)n * sizeof(double));
  for (int k = 0; k < 30; k++) {
    const double* row = r->V + (size_t)(3 * nodes[k / 3] + k % 3) * (size_t)n;
    for (int j = 0; j < n; j++) {
      v[j] += row[j] * g[k];
    }
  }
}

/* The Tet10s of the mixed model (fem_rom.h csfRom.m) into rint and d->K: pass 1 the element
 * volumes and b = sum_e w_e P_e (v_e - V_e), p^ = A^-1 b; pass 2 each element's force with its
 * pressure p_e = P_e . p^ in place of the kernel's own kappa (v_e / V_e - 1) and, for the
 * tangent, the kernel's matrix at theta_e = 1 + p_e,state / kappa (the geometric term of the
 * state pressure, as the FE's three-field Newton; sync: p_e) less its element bulk term
 * kappa / V_e g g^T, which the reduced one B^T A^-1 B replaces. Returns 1 on an inverted
 * element. */
static int mixedTets(const csfRom* r, csfRomData* d, int want_k, double* rint) {
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  const int n = r->n, mm = r->m;
  const double kappa = m->mat.kappa;
  double* b = d->ph;
  memset(b, 0, (size_t)mm * sizeof(double));
  for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    double ue[30], gv[30], vr, jm;
    gather(r, d->q, 10, me->tet + 10 * e, ue);
    if (csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e, m->vol[e], ue,
                      1.0, d->rel + 30 * (size_t)e, NULL, &vr, gv, &jm)) {
      return 1;
    }
    d->vr[e] = vr;
    memcpy(d->gel + 30 * (size_t)e, gv, sizeof gv);
    const double c = r->w[CSF_ROM_SET_TET][k] * (vr - 1.0) * m->vol[e];
    const double* Pe = r->P + (size_t)e * (size_t)mm;
    for (int i = 0; i < mm; i++) {
      b[i] += c * Pe[i];
    }
  }
  csf_romMixedSolve(r, b); /* now p^ */
  if (want_k) {
    memset(d->Bm, 0, (size_t)mm * (size_t)n * sizeof(double));
  }
  for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    const int* tv = me->tet + 10 * e;
    const double* Pe = r->P + (size_t)e * (size_t)mm;
    const double* gv = d->gel + 30 * (size_t)e;
    const double w = r->w[CSF_ROM_SET_TET][k];
    double pe = 0;
    for (int i = 0; i < mm; i++) {
      pe += Pe[i] * b[i];
    }
    double fe[30], ke[900];
    const double dp = pe - kappa * (d->vr[e] - 1.0);
    const double* re = d->rel + 30 * (size_t)e;
    for (int a = 0; a < 30; a++) {
      fe[a] = re[a] + dp * gv[a];
    }
    if (want_k) {
      double ue[30], rtmp[30], gtmp[30], vr, jm;
      gather(r, d->q, 10, tv, ue);
      const double th = d->sync ? 1.0 + pe / kappa : d->theta[e];
      if (csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e, m->vol[e],
                        ue, th, rtmp, ke, &vr, gtmp, &jm)) {
        return 1;
      }
      const double s = kappa / m->vol[e];
      for (int a = 0; a < 30; a++) {
        for (int c = 0; c < 30; c++) {
          ke[30 * a + c] -= s * gv[a] * gv[c];
        }
      }
      double* vg = d->mtmp + mm; /* (n) V_e^T g_e */
      reduceVector(r, tv, gv, vg);
      for (int i = 0; i < mm; i++) {
        const double c = w * Pe[i];
        if (c == 0.0) {
          continue;
        }
        double* Bi = d->Bm + (size_t)i * (size_t)n;
        for (int j = 0; j < n; j++) {
          Bi[j] += c * vg[j];
        }
      }
    }
    scatterTetSym(r, d, tv, w, fe, want_k ? ke : NULL, rint);
  }
  if (want_k) {
    /* K += B^T A^-1 B, column by column of B */
    double* col = d->mtmp;
    double* ab = d->Bm + (size_t)mm * n; /* (m x n) A^-1 B */
    for (int j = 0; j < n; j++) {
      for (int i = 0; i < mm; i++) {
        col[i] = d->Bm[(size_t)i * n + j];
      }
      csf_romMixedSolve(r, col);
      for (int i = 0; i < mm; i++) {
        ab[(size_t)i * n + j] = col[i];
      }
    }
    for (int i = 0; i < mm; i++) {
      const double* Bi = d->Bm + (size_t)i * n;
      const double* ABi = ab + (size_t)i * n;
      for (int a = 0; a < n; a++) {
        double* Ka = d->K + (size_t)a * n;
        for (int c = 0; c < n; c++) {
          Ka[c] += Bi[a] * ABi[c];
        }
      }
    }
  }
  return 0;
}

int csf_romEvaluate(const csfRom* r, csfRomData* d, const csfRomLoad* load, int want_k) {
  if (!r || !d || !load || d->n != r->n || d->m != r->m || d->mf != r->mf) {
    return -1;
  }
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  const int n = r->n;
  double* rint = d->tmp; /* internal part, then the external one into d->r */
  memset(rint, 0, (size_t)n * sizeof(double));
  memset(d->r, 0, (size_t)n * sizeof(double));
  if (want_k) {
    memset(d->K, 0, (size_t)n * (size_t)n * sizeof(double));
    memset(d->Ku, 0, (size_t)n * (size_t)n * sizeof(double));
  }
  /* Tet10 bodies */
  if (r->m > 0) {
    if (mixedTets(r, d, want_k, rint)) {
      return 1;
    }
  }
  for (int k = 0; r->m == 0 && k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    const int* tv = me->tet + 10 * e;
    double ue[30], re[30], ke[900], gv[30], vr, jm;
    gather(r, d->q, 10, tv, ue);
    const double* dN = m->dNdX + 120 * (size_t)e;
    const double* wq = m->wq + 4 * (size_t)e;
    /* the residual does not depend on theta_e; the tangent takes the state, or v/V (sync:
     * a residual call first gives it) */
    double th = d->theta[e];
    if (want_k && d->sync) {
      if (csf_tetKernel(&m->mat, dN, wq, m->vol[e], ue, 1.0, re, NULL, &vr, gv, &jm)) {
        return 1;
      }
      th = vr;
    }
    if (csf_tetKernel(&m->mat, dN, wq, m->vol[e], ue, th, re, want_k ? ke : NULL, &vr, gv, &jm)) {
      return 1;
    }
    d->vr[e] = vr;
    memcpy(d->gel + 30 * (size_t)e, gv, sizeof gv);
    scatterTetSym(r, d, tv, r->w[CSF_ROM_SET_TET][k], re, want_k ? ke : NULL, rint);
  }
  /* fibres through their chord operators (csfRom.fib_D): the kernel on the chord alone (one
   * "node" of coefficient 1: its force f_d = dW/dd and 3 x 3 tangent H), then
   * r += w D^T f_d, K += w D^T H D; the mixed fibre field (csfRom.mf) in fem_rom_fibre.c */
  if (r->mf > 0) {
    csf_romFibresMixed(r, d, want_k, rint);
  }
  for (int k = 0; r->mf == 0 && k < r->nel[CSF_ROM_SET_FIBRE]; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    const double* D = r->fib_D + (size_t)k * 3 * (size_t)n;
    const double one = 1.0;
    double dch[3], fd[3], H[9], E = 0, dout[3], S, dS;
    for (int i = 0; i < 3; i++) {
      const double* Di = D + (size_t)i * (size_t)n;
      double s = r->fib_X[3 * k + i];
      for (int j = 0; j < n; j++) {
        s += Di[j] * d->q[j];
      }
      dch[i] = s;
    }
    S = d->fib_S[f];
    if (want_k && d->sync) {
      csf_fibreKernel(1, &one, dch, m->fib_L0[f], m->fib_EA[f], S, m->fib_tension_only,
                      m->fib_geo_tension, fd, NULL, &E, dout);
      csf_fibreLaw(m->fib_tension_only, E, &S, &dS);
    }
    const int loaded = csf_fibreKernel(1, &one, dch, m->fib_L0[f], m->fib_EA[f], S,
                                       m->fib_tension_only, m->fib_geo_tension, fd,
                                       want_k ? H : NULL, &E, dout);
    d->fib_E[f] = E;
    memcpy(d->fib_d + 3 * (size_t)f, dout, sizeof dout);
    if (!loaded) {
      continue;
    }
    const double w = r->w[CSF_ROM_SET_FIBRE][k];
    for (int j = 0; j < n; j++) {
      rint[j] += w * (D[j] * fd[0] + D[n + j] * fd[1] + D[2 * (size_t)n + j] * fd[2]);
    }
    if (!want_k) {
      continue;
    }
    /* T = w H D (3 x n), K += D^T T */
    double* T = d->ke_v;
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < n; j++) {
        T[(size_t)i * n + j] = w * (H[3 * i] * D[j] + H[3 * i + 1] * D[n + j] +
                                    H[3 * i + 2] * D[2 * (size_t)n + j]);
      }
    }
    for (int a = 0; a < n; a++) { /* the upper triangle (symmetric: H is) */
      const double d0 = D[a], d1 = D[n + a], d2 = D[2 * (size_t)n + a];
      double* Ka = d->Ku + (size_t)a * n;
      for (int j = a; j < n; j++) {
        Ka[j] += d0 * T[j] + d1 * T[n + j] + d2 * T[2 * (size_t)n + j];
      }
    }
  }
  /* the bodies' and fibres' symmetric tangent from its upper triangle */
  for (int i = 0; want_k && i < n; i++) {
    const double* Ui = d->Ku + (size_t)i * (size_t)n;
    double* Ki = d->K + (size_t)i * (size_t)n;
    Ki[i] += Ui[i];
    for (int j = i + 1; j < n; j++) {
      Ki[j] += Ui[j];
      d->K[(size_t)j * n + i] += Ui[j];
    }
  }
  /* follower pressure: R -= f_ext, K += kfe (= -d f_ext / dx) */
  if (load->face_p) {
    for (int k = 0; k < r->nel[CSF_ROM_SET_FACE]; k++) {
      const int f = r->el[CSF_ROM_SET_FACE][k];
      const double p = load->face_p[f];
      if (p == 0.0 || (r->nch > 0 && r->face_ch[f] >= 0)) {
        continue; /* vented, or a chamber in closed form (below) */
      }
      const int* fn = me->face + 6 * (size_t)f;
      double xf[18], fe[18], kfe[324], vf;
      gather(r, d->q, 6, fn, xf);
      for (int a = 0; a < 6; a++) {
        for (int i = 0; i < 3; i++) {
          xf[3 * a + i] += me->x[3 * fn[a] + i];
        }
      }
      csf_faceKernel(xf, p, fe, want_k ? kfe : NULL, &vf);
      for (int a = 0; a < 18; a++) {
        fe[a] = -fe[a];
      }
      scatter(r, d, 6, fn, r->w[CSF_ROM_SET_FACE][k], fe, want_k ? kfe : NULL, d->r);
    }
  }
  /* chambers in closed form: r -= p g_c(q), K -= p H_c(q) (the Ku scratch holds H(q); lu
   * holds the Newton's kept factor) */
  for (int c = 0; load->face_p && c < r->nch; c++) {
    double p = 0.0;
    for (int f = 0; f < me->nface; f++) {
      if (r->face_ch[f] == c) {
        p = load->face_p[f];
        break;
      }
    }
    if (p == 0.0) {
      continue;
    }
    double* Hq = d->Ku;
    chamberHessian(r, c, d->q, Hq);
    const double* H0 = r->ch_H + (size_t)c * (size_t)(n + 1) * (size_t)n * (size_t)n;
    const double* g0 = r->ch_g0 + (size_t)c * (size_t)n;
    for (int i = 0; i < n; i++) {
      double s = 0;
      for (int j = 0; j < n; j++) {
        s += (H0[(size_t)i * n + j] + Hq[(size_t)i * n + j]) * d->q[j];
      }
      d->r[i] -= p * (g0[i] + 0.5 * s);
    }
    if (want_k) {
      for (size_t i = 0; i < (size_t)n * (size_t)n; i++) {
        d->K[i] -= p * Hq[i];
      }
    }
  }
  /* gravity and dead loads, exact */
  for (int j = 0; j < n; j++) {
    d->r[j] -= r->G[3 * j] * load->gravity[0] + r->G[3 * j + 1] * load->gravity[1] +
               r->G[3 * j + 2] * load->gravity[2];
    if (load->f_dead) {
      d->r[j] -= load->f_dead[j];
    }
  }
  double ni = 0, ne = 0, nr = 0;
  for (int j = 0; j < n; j++) {
    ni += rint[j] * rint[j];
    ne += d->r[j] * d->r[j];
    d->r[j] += rint[j];
    nr += d->r[j] * d->r[j];
  }
  d->fnorm = sqrt(ni) + sqrt(ne);
  d->rnorm = sqrt(nr);
  d->n_eval++;
  d->n_tangent += want_k != 0;
  return isfinite(d->rnorm) ? 0 : 1;
}


int csf_romElementForcesWidth(const csfRom* r, csfRomSet set) {
  return r->n + (set == CSF_ROM_SET_TET ? r->m : 0) +
         (set == CSF_ROM_SET_FIBRE ? 4 * r->mf : 0);
}

/* The mixed model's Tet10 rows (csf_romElementForces): the unreduced model's p^ (every Tet10 at
 * weight 1: b over all of them, A over all of them), then per element the reduced force with
 * its pressure p_e = P_e . p^ and its constraint share P_e (v_e - V_e). */
static int mixedElementForces(const csfRom* r, csfRomData* d, double* G) {
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  const int n = r->n, mm = r->m, wd = n + mm;
  const double kappa = m->mat.kappa;
  double* L = malloc((size_t)mm * (size_t)mm * sizeof(double));
  double* ph = calloc((size_t)mm, sizeof(double));
  csError err;
  if (!L || !ph || csf_romMixedFactorInto(r, 1, L, &err) != CS_OK) {
    free(L), free(ph);
    return -1;
  }
  memset(G, 0, (size_t)me->ntet * (size_t)wd * sizeof(double));
  for (int e = 0; e < me->ntet; e++) {
    double ue[30], vr, jm;
    gather(r, d->q, 10, me->tet + 10 * (size_t)e, ue);
    if (csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e, m->vol[e], ue,
                      1.0, d->rel + 30 * (size_t)e, NULL, &vr, d->gel + 30 * (size_t)e, &jm)) {
      free(L), free(ph);
      return 1;
    }
    d->vr[e] = vr;
    const double* Pe = r->P + (size_t)e * (size_t)mm;
    double* row = G + (size_t)e * wd + n;
    for (int i = 0; i < mm; i++) {
      row[i] = Pe[i] * (vr - 1.0) * m->vol[e];
      ph[i] += row[i];
    }
  }
  csf_romMixedSolveWith(mm, L, ph);
  for (int e = 0; e < me->ntet; e++) {
    const double* Pe = r->P + (size_t)e * (size_t)mm;
    double pe = 0, fe[30];
    for (int i = 0; i < mm; i++) {
      pe += Pe[i] * ph[i];
    }
    const double dp = pe - kappa * (d->vr[e] - 1.0);
    const double* re = d->rel + 30 * (size_t)e;
    const double* gv = d->gel + 30 * (size_t)e;
    for (int a = 0; a < 30; a++) {
      fe[a] = re[a] + dp * gv[a];
    }
    scatter(r, d, 10, me->tet + 10 * (size_t)e, 1.0, fe, NULL, G + (size_t)e * wd);
  }
  free(L), free(ph);
  return 0;
}

int csf_romElementForces(const csfRom* r, csfRomData* d, const csfRomLoad* load, csfRomSet set,
                         double* G) {
  if (!r || !d || !load || !G || (int)set < 0 || set >= CSF_ROM_NSET || d->n != r->n ||
      d->m != r->m) {
    return -1;
  }
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  const size_t n = (size_t)r->n;
  const int count[CSF_ROM_NSET] = {me->ntet, m->nfib, me->nface};
  if (set == CSF_ROM_SET_TET && r->m > 0) {
    return mixedElementForces(r, d, G);
  }
  if (set == CSF_ROM_SET_FIBRE && r->mf > 0) {
    return csf_romFibreElementForces(r, d->q, G);
  }
  memset(G, 0, (size_t)count[set] * n * sizeof(double));
  for (int e = 0; e < count[set]; e++) {
    double* row = G + (size_t)e * n;
    if (set == CSF_ROM_SET_TET) {
      double ue[30], re[30], gv[30], vr, jm;
      gather(r, d->q, 10, me->tet + 10 * (size_t)e, ue);
      if (csf_tetKernel(&m->mat, m->dNdX + 120 * (size_t)e, m->wq + 4 * (size_t)e, m->vol[e], ue,
                        1.0, re, NULL, &vr, gv, &jm)) {
        return 1;
      }
      scatter(r, d, 10, me->tet + 10 * (size_t)e, 1.0, re, NULL, row);
    } else if (set == CSF_ROM_SET_FIBRE) {
      const int* fv = m->fib_node + 20 * (size_t)e;
      const double* cf;
      double x[60], rf[60], c10[10], E, dch[3];
      const int nn = fibreGeometry(r, d->q, e, x, c10, &cf);
      if (csf_fibreKernel(nn, cf, x, m->fib_L0[e], m->fib_EA[e], 0.0, m->fib_tension_only,
                          m->fib_geo_tension, rf, NULL, &E, dch)) {
        scatter(r, d, nn, fv, 1.0, rf, NULL, row);
      }
    } else if (load->face_p && load->face_p[e] != 0.0) {
      const int* fn = me->face + 6 * (size_t)e;
      double xf[18], fe[18], vf;
      gather(r, d->q, 6, fn, xf);
      for (int a = 0; a < 6; a++) {
        for (int i = 0; i < 3; i++) {
          xf[3 * a + i] += me->x[3 * fn[a] + i];
        }
      }
      csf_faceKernel(xf, load->face_p[e], fe, NULL, &vf);
      for (int a = 0; a < 18; a++) {
        fe[a] = -fe[a];
      }
      scatter(r, d, 6, fn, 1.0, fe, NULL, row);
    }
  }
  return 0;
}


/* ---- Newton ------------------------------------------------------------------------------- */

csfRomNewtonOptions csf_romNewtonDefault(void) {
  csfRomNewtonOptions o;
  o.max_iter = 40;
  o.rtol = 1e-8; /* the FE's element tests' default (csf_newtonDefault) */
  o.atol = 1e-12;
  o.max_ls = 8;
  o.k_lag = 0.0;
  o.bfgs = 0;
  o.bfgs_keep = 0;
  return o;
}

/* LU with partial pivoting of A (n x n row-major) in place, the row swaps in piv; -1 singular */
static int luFactor(int n, double* A, int* piv) {
  for (int k = 0; k < n; k++) {
    int p = k;
    for (int i = k + 1; i < n; i++) {
      p = fabs(A[(size_t)i * n + k]) > fabs(A[(size_t)p * n + k]) ? i : p;
    }
    piv[k] = p;
    if (A[(size_t)p * n + k] == 0.0) {
      return -1;
    }
    if (p != k) {
      for (int j = 0; j < n; j++) {
        const double t = A[(size_t)k * n + j];
        A[(size_t)k * n + j] = A[(size_t)p * n + j], A[(size_t)p * n + j] = t;
      }
    }
    for (int i = k + 1; i < n; i++) {
      const double l = A[(size_t)i * n + k] / A[(size_t)k * n + k];
      A[(size_t)i * n + k] = l;
      for (int j = k + 1; j < n; j++) {
        A[(size_t)i * n + j] -= l * A[(size_t)k * n + j];
      }
    }
  }
  return 0;
}

/* solve with luFactor's factor: b becomes x */
static void luSolveFactored(int n, const double* LU, const int* piv, double* b) {
  for (int k = 0; k < n; k++) {
    if (piv[k] != k) {
      const double t = b[k];
      b[k] = b[piv[k]], b[piv[k]] = t;
    }
  }
  for (int i = 1; i < n; i++) {
    double s = b[i];
    for (int j = 0; j < i; j++) {
      s -= LU[(size_t)i * n + j] * b[j];
    }
    b[i] = s;
  }
  for (int i = n - 1; i >= 0; i--) {
    double s = b[i];
    for (int j = i + 1; j < n; j++) {
      s -= LU[(size_t)i * n + j] * b[j];
    }
    b[i] = s / LU[(size_t)i * n + i];
  }
}

/* the three-field update along alpha dq (fem_newton.c updateTheta): theta_e = (v_e + alpha g_e .
 * du_e) / V_e, the fibres' S = S(E0 + alpha d0 . dd / L0^2), over the kept elements */
static void updateStates(const csfRom* r, csfRomData* d, double alpha) {
  const csfModel* m = r->fem;
  const csfMesh* me = m->mesh;
  if (r->m > 0) {
    /* mixed: p^_state = A^-1 sum_e w_e P_e (v_e + alpha g_e . du_e - V_e), linearised at the
     * iterate, and theta_e = 1 + P_e . p^_state / kappa carries it into the kernel */
    const int mm = r->m;
    double* ps = d->mtmp;
    memset(ps, 0, (size_t)mm * sizeof(double));
    for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
      const int e = r->el[CSF_ROM_SET_TET][k];
      double due[30];
      gather(r, d->dq, 10, me->tet + 10 * (size_t)e, due);
      const double* g = d->g0 + 30 * (size_t)e;
      double sg = 0;
      for (int a = 0; a < 30; a++) {
        sg += g[a] * due[a];
      }
      const double c = r->w[CSF_ROM_SET_TET][k] * ((d->vr0[e] - 1.0) * m->vol[e] + alpha * sg);
      const double* Pe = r->P + (size_t)e * (size_t)mm;
      for (int i = 0; i < mm; i++) {
        ps[i] += c * Pe[i];
      }
    }
    csf_romMixedSolve(r, ps);
    for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
      const int e = r->el[CSF_ROM_SET_TET][k];
      const double* Pe = r->P + (size_t)e * (size_t)mm;
      double pe = 0;
      for (int i = 0; i < mm; i++) {
        pe += Pe[i] * ps[i];
      }
      d->theta[e] = 1.0 + pe / m->mat.kappa;
    }
  }
  for (int k = 0; r->m == 0 && k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    double due[30];
    gather(r, d->dq, 10, me->tet + 10 * (size_t)e, due);
    const double* g = d->g0 + 30 * (size_t)e;
    double s = 0;
    for (int a = 0; a < 30; a++) {
      s += g[a] * due[a];
    }
    d->theta[e] = d->vr0[e] + alpha * s / m->vol[e];
  }
  if (r->mf > 0) {
    csf_romFibreStates(r, d, alpha);
  }
  for (int k = 0; r->mf == 0 && k < r->nel[CSF_ROM_SET_FIBRE]; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    const double* D = r->fib_D + (size_t)k * 3 * (size_t)r->n;
    double dd[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < r->n; j++) {
        dd[i] += D[(size_t)i * r->n + j] * d->dq[j];
      }
    }
    const double* d0 = d->fib_d0 + 3 * (size_t)f;
    const double L0 = m->fib_L0[f];
    const double El = d->fib_E0[f] + alpha * (d0[0] * dd[0] + d0[1] * dd[1] + d0[2] * dd[2]) /
                                         (L0 * L0);
    double dS;
    csf_fibreLaw(m->fib_tension_only, El, &d->fib_S[f], &dS);
  }
}

/* copy the states of the kept elements between buffers (dst <- src) */
static void copyStates(const csfRom* r, double* th_dst, const double* th_src, double* S_dst,
                       const double* S_src) {
  for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    th_dst[e] = th_src[e];
  }
  for (int k = 0; k < r->nel[CSF_ROM_SET_FIBRE]; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    S_dst[f] = S_src[f];
  }
}

/* the update's base: v/V, g, E and d of the kept elements at the iterate */
static void keepBase(const csfRom* r, csfRomData* d) {
  for (int k = 0; k < r->nel[CSF_ROM_SET_TET]; k++) {
    const int e = r->el[CSF_ROM_SET_TET][k];
    d->vr0[e] = d->vr[e];
    memcpy(d->g0 + 30 * (size_t)e, d->gel + 30 * (size_t)e, 30 * sizeof(double));
  }
  for (int k = 0; k < r->nel[CSF_ROM_SET_FIBRE]; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    d->fib_E0[f] = d->fib_E[f];
    memcpy(d->fib_d0 + 3 * (size_t)f, d->fib_d + 3 * (size_t)f, 3 * sizeof(double));
  }
}

static csStatus newtonFail(const csfRom* r, csfRomData* d, const csfRomLoad* load, int it,
                           csError* err, const char* why) {
  d->lu_valid = 0;
  memcpy(d->q, d->q_save, (size_t)r->n * sizeof(double));
  copyStates(r, d->theta, d->theta_save, d->fib_S, d->fib_S_save);
  csf_romEvaluate(r, d, load, 0);
  return cs_errorSet(err, CS_ERR_DIVERGED, "fem_rom: %s at iteration %d (|r| %.3g N of %.3g)",
                     why, it, d->rnorm, d->fnorm);
}

/* factor K at the current iterate into d->lu (d->lu_valid); -1 singular. A new factor drops
 * the BFGS pairs of the old one. */
static int factorTangent(const csfRom* r, csfRomData* d) {
  const int n = r->n;
  memcpy(d->lu, d->K, (size_t)n * (size_t)n * sizeof(double));
  d->lu_valid = luFactor(n, d->lu, d->piv) == 0;
  d->bf_k = 0;
  return d->lu_valid ? 0 : -1;
}

void csf_romQuasiNewtonApply(const csfRom* r, csfRomData* d, double* x) {
  /* the two-loop recursion (Nocedal and Wright 2006, alg. 7.4), H0 = K0^-1 (the kept LU) */
  const size_t n = (size_t)r->n;
  for (int k = d->bf_k - 1; k >= 0; k--) {
    const double* s = d->bf_s + (size_t)k * n, *y = d->bf_y + (size_t)k * n;
    double a = 0;
    for (size_t j = 0; j < n; j++) {
      a += s[j] * x[j];
    }
    a *= d->bf_rho[k];
    d->bf_a[k] = a;
    for (size_t j = 0; j < n; j++) {
      x[j] -= a * y[j];
    }
  }
  luSolveFactored(r->n, d->lu, d->piv, x);
  for (int k = 0; k < d->bf_k; k++) {
    const double* s = d->bf_s + (size_t)k * n, *y = d->bf_y + (size_t)k * n;
    double b = 0;
    for (size_t j = 0; j < n; j++) {
      b += y[j] * x[j];
    }
    b = d->bf_a[k] - d->bf_rho[k] * b;
    for (size_t j = 0; j < n; j++) {
      x[j] += b * s[j];
    }
  }
}

int csf_romQuasiNewtonPush(const csfRom* r, csfRomData* d, const double* s, const double* y,
                           int cap) {
  const size_t n = (size_t)r->n;
  cap = cap < CSF_ROM_BFGS_MAX ? cap : CSF_ROM_BFGS_MAX;
  double ys = 0, ss = 0, yy = 0;
  for (size_t j = 0; j < n; j++) {
    ys += y[j] * s[j], ss += s[j] * s[j], yy += y[j] * y[j];
  }
  /* curvature condition: BFGS keeps H positive definite only with y . s > 0; a pair this close
   * to it (round-off of the residual's difference) is not worth storing either */
  if (cap <= 0 || !(ys > 1e-12 * sqrt(ss * yy))) {
    return 0;
  }
  if (d->bf_k == cap) {
    /* the oldest pair leaves (L-BFGS's memory) */
    memmove(d->bf_s, d->bf_s + n, (size_t)(cap - 1) * n * sizeof(double));
    memmove(d->bf_y, d->bf_y + n, (size_t)(cap - 1) * n * sizeof(double));
    memmove(d->bf_rho, d->bf_rho + 1, (size_t)(cap - 1) * sizeof(double));
    d->bf_k--;
  }
  memcpy(d->bf_s + (size_t)d->bf_k * n, s, n * sizeof(double));
  memcpy(d->bf_y + (size_t)d->bf_k * n, y, n * sizeof(double));
  d->bf_rho[d->bf_k] = 1.0 / ys;
  d->bf_k++;
  return 1;
}

csStatus csf_romFactorTangent(const csfRom* r, csfRomData* d, csError* err) {
  if (factorTangent(r, d) != 0) {
    return cs_errorSet(err, CS_ERR_SOLVER, "fem_rom: singular reduced tangent");
  }
  return CS_OK;
}

/* after a step taken on the kept factor: its secant pair (s = q - q0, y = r - r0) */
static void pushStep(const csfRom* r, csfRomData* d, int cap) {
  const size_t n = (size_t)r->n;
  double* s = d->tmp;
  for (size_t j = 0; j < n; j++) {
    s[j] = d->q[j] - d->q0[j];
    d->bf_r0[j] = d->r[j] - d->bf_r0[j]; /* y, in the r0 buffer: it is refilled every step */
  }
  csf_romQuasiNewtonPush(r, d, s, d->bf_r0, cap);
}

csStatus csf_romNewton(const csfRom* r, csfRomData* d, const csfRomLoad* load,
                       const csfRomNewtonOptions* o, int* iters, csError* err) {
  const size_t n = (size_t)r->n;
  const int lag = o->k_lag > 0.0;
  memcpy(d->q_save, d->q, n * sizeof(double));
  copyStates(r, d->theta_save, d->theta, d->fib_S_save, d->fib_S);
  int it = 0, strict = 0, since_best = 0;
  if (iters) {
    *iters = 0;
  }
  if (!lag) {
    d->lu_valid = 0;
  }
  const int bfgs = lag ? o->bfgs : 0;
  if (!o->bfgs_keep || !d->lu_valid) {
    d->bf_k = 0; /* the pairs belong to the last call's load */
  }
  /* the tangent of this iterate is in d->K (fresh) or only the residual was evaluated */
  int fresh = !(lag && d->lu_valid);
  if (csf_romEvaluate(r, d, load, fresh) != 0) {
    return newtonFail(r, d, load, it, err, "the starting state is not physical (an inverted "
                      "element)");
  }
  double r_best = INFINITY; /* the first iterate is the first best one (fem_newton.c) */
  while (!(d->rnorm <= o->rtol * d->fnorm || d->rnorm <= o->atol)) {
    if (it >= o->max_iter) {
      return newtonFail(r, d, load, it, err, "Newton did not converge");
    }
    if (fresh && factorTangent(r, d) != 0) {
      return newtonFail(r, d, load, it, err, "singular reduced tangent");
    }
    for (size_t j = 0; j < n; j++) {
      d->dq[j] = -d->r[j];
    }
    memcpy(d->bf_r0, d->r, n * sizeof(double));
    if (bfgs > 0) {
      csf_romQuasiNewtonApply(r, d, d->dq); /* K0^-1 alone while no pair is stored */
    } else {
      luSolveFactored(r->n, d->lu, d->piv, d->dq);
    }
    keepBase(r, d);
    memcpy(d->q0, d->q, n * sizeof(double));
    const double r0 = d->rnorm;
    if (!fresh) {
      /* a step on the kept factor: taken if it reduces |r|, else taken back; the tangent is
       * formed at this iterate and the step redone as a Newton step */
      for (size_t j = 0; j < n; j++) {
        d->q[j] = d->q0[j] + d->dq[j];
      }
      /* the residual does not depend on the states: they follow only a step that is taken
       * (reset to v/V at q0 instead, the spurious pressure of an overshooting iterate would
       * enter the next tangent: the stall csfRomData describes) */
      const int ev = csf_romEvaluate(r, d, load, 0);
      if (ev == 0 && d->rnorm < r0) {
        updateStates(r, d, 1.0);
        it++;
        d->n_newton++;
        fresh = 0;
        if (bfgs > 0) {
          pushStep(r, d, bfgs);
        }
        if (d->rnorm > o->k_lag * r0) {
          /* slow contraction: a new tangent at the new iterate */
          if (csf_romEvaluate(r, d, load, 1) != 0) {
            return newtonFail(r, d, load, it, err, "the iterate is not physical");
          }
          fresh = 1;
        }
        if (d->rnorm < r_best) {
          r_best = d->rnorm;
          memcpy(d->q_best, d->q, n * sizeof(double));
          copyStates(r, d->theta_best, d->theta, d->fib_S_best, d->fib_S);
        }
        continue;
      }
      memcpy(d->q, d->q0, n * sizeof(double));
      if (csf_romEvaluate(r, d, load, 1) != 0) {
        return newtonFail(r, d, load, it, err, "the iterate is not physical");
      }
      fresh = 1;
      continue;
    }
    /* a full step unless |r| grows past ROM_LS_GROWTH_FIRST (lenient) or at all (strict, after
     * the watchdog's return), halving otherwise (fem_newton.c) */
    const double growth = strict ? 1.0 : ROM_LS_GROWTH_FIRST;
    double alpha = 1.0;
    int ok = 0;
    for (int ls = 0; ls <= o->max_ls; ls++) {
      for (size_t j = 0; j < n; j++) {
        d->q[j] = d->q0[j] + alpha * d->dq[j];
      }
      updateStates(r, d, alpha);
      /* with a lagged tangent the trial evaluates the residual alone first */
      if (csf_romEvaluate(r, d, load, !lag) == 0 && d->rnorm < growth * r0) {
        ok = 1;
        break;
      }
      alpha *= ROM_LS_SHRINK;
    }
    it++;
    d->n_newton++;
    if (!ok) {
      return newtonFail(r, d, load, it, err, "line search failed");
    }
    fresh = !lag;
    if (bfgs > 0 && d->rnorm <= o->k_lag * r0) {
      pushStep(r, d, bfgs); /* the factor is kept: this step's pair corrects it */
    }
    if (lag && d->rnorm > o->k_lag * r0) {
      if (csf_romEvaluate(r, d, load, 1) != 0) {
        return newtonFail(r, d, load, it, err, "the iterate is not physical");
      }
      fresh = 1;
    }
    strict = 0;
    if (d->rnorm < r_best) {
      r_best = d->rnorm;
      since_best = 0;
      memcpy(d->q_best, d->q, n * sizeof(double));
      copyStates(r, d->theta_best, d->theta, d->fib_S_best, d->fib_S);
    } else if (++since_best >= ROM_LS_WATCH) {
      memcpy(d->q, d->q_best, n * sizeof(double));
      copyStates(r, d->theta, d->theta_best, d->fib_S, d->fib_S_best);
      if (csf_romEvaluate(r, d, load, 1) != 0) {
        return newtonFail(r, d, load, it, err, "the best iterate is not physical");
      }
      fresh = 1;
      since_best = 0;
      strict = 1;
    }
  }
  if (iters) {
    *iters = it;
  }
  return CS_OK;
}

/* fem_rom_fibre.c: the mixed fibre field of the reduced model (fem_rom.h csfRom.mf,
 * fem_rom_fibre.h).
 *
 * Rationale. The leg's fibres are nearly inextensible trusses (EA 31 kN against a silicone of
 * C10 0.11 MPa); a linear span of snapshot modes, each of which keeps the fibres near their
 * length, combines into displacements that stretch them, and the reduced model pays that energy
 * and stays too stiff (docs/notes/rom.md, session romacc: the best approximation of a held-out
 * state in the span pays 6-260 times the FE's fibre energy). The cure is the one the pressure
 * basis P applies to the bulk (fem_rom_mixed.c): the fibre strain enters the law only through
 * its projection onto a reduced strain space, Ebar = Q E^, E^ = G^-1 sum_f W_f Q_f E_f(q),
 * G = sum_f W_f Q_f Q_f^T, W_f = w_f EA_f L0_f (an L2 projection along the fibres weighted by
 * their axial stiffness). Energy Pi = sum_f W_f psi(Ebar_f), psi' = S (csf_fibreLaw):
 *   dPi/dq  = sum_f W_f S*_f dE_f/dq,  S* = Q G^-1 sum_g W_g Q_g S(Ebar_g)   (each fibre's force
 *             as the FE's, EA S*_f d_f / L0_f, with S* for S),
 *   d2Pi/dq2 = sum_f W_f S*_f d2E_f/dq2 + Z^T C Z,  Z = G^-1 B,  B = sum_f W_f Q_f dE_f/dq,
 *             C = sum_f W_f S'(Ebar_f) Q_f Q_f^T,
 * with E_f = (|d_f|^2 / L0^2 - 1) / 2, d_f = X_f + D_f q (the chord operators of fem_rom.c):
 * dE_f/dq = d_f^T D_f / L0^2, d2E_f/dq2 = D_f^T D_f / L0^2. With Q = I, S* = S(E) and the
 * tangent is the FE's fibre tangent. As the FE's three-field Newton carries the fibres' stress
 * state S_state for the geometric term (fem_element.h csf_fibreKernel), the reduced Newton
 * carries S*_state, updated by the linearised strain through the same projections. Cost per
 * evaluation O(nfib (n + mf)); the tangent adds O(nfib mf n) for B and O(mf n^2) for Z^T C Z to
 * the fibres' O(nfib n^2). */
#include "fem_rom_fibre.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_material.h"
#include "fem_rom_mixed.h"

/* G = sum_f W_f Q_f Q_f^T over the kept fibres and their weights (all = 0) or over every fibre
 * at weight 1 (all = 1: the unreduced model's G, which the ECSW rows need) into its Cholesky
 * factor L (mf x mf); CS_ERR_ARG when singular */
static csStatus factorInto(const csfRom* r, int all, double* L, csError* err) {
  const csfModel* m = r->fem;
  const int mf = r->mf;
  const int nk = all ? m->nfib : r->nel[CSF_ROM_SET_FIBRE];
  memset(L, 0, (size_t)mf * (size_t)mf * sizeof(double));
  for (int k = 0; k < nk; k++) {
    const int f = all ? k : r->el[CSF_ROM_SET_FIBRE][k];
    const double W = (all ? 1.0 : r->w[CSF_ROM_SET_FIBRE][k]) * m->fib_EA[f] * m->fib_L0[f];
    const double* Q = r->Qf + (size_t)f * (size_t)mf;
    for (int i = 0; i < mf; i++) {
      for (int j = 0; j <= i; j++) {
        L[(size_t)i * mf + j] += W * Q[i] * Q[j];
      }
    }
  }
  const int j = csf_romCholesky(mf, L);
  if (j >= 0) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_rom: fibre strain mode %d of %d has no support in "
                       "the %s fibres (the fibre projection matrix is singular)", j, mf,
                       all ? "model's" : "kept");
  }
  return CS_OK;
}

csStatus csf_romFibreFactor(csfRom* r, csError* err) {
  return factorInto(r, 0, r->Gf_chol, err);
}

csStatus csf_romSetFibreBasis(csfRom* r, int mf, const double* Q, csError* err) {
  csStatus st = csf_romBasisReplace(r->fem->nfib, mf, Q, "fibre strain basis", "fibre", &r->Qf,
                                    &r->Gf_chol, err);
  if (st != CS_OK) {
    return st;
  }
  r->mf = mf;
  if (mf == 0) {
    return CS_OK;
  }
  st = csf_romFibreFactor(r, err);
  if (st != CS_OK) {
    free(r->Qf), free(r->Gf_chol);
    r->Qf = NULL, r->Gf_chol = NULL, r->mf = 0;
  }
  return st;
}

/* the kept fibre k's chord d = X_k + D_k q (mm) */
static void chord(const csfRom* r, int k, const double* q, double d[3]) {
  const int n = r->n;
  const double* D = r->fib_D + (size_t)k * 3 * (size_t)n;
  for (int i = 0; i < 3; i++) {
    const double* Di = D + (size_t)i * (size_t)n;
    double s = r->fib_X[3 * k + i];
    for (int j = 0; j < n; j++) {
      s += Di[j] * q[j];
    }
    d[i] = s;
  }
}

/* from the kept fibres' strains E (indexed by fibre): eh = E^ = G^-1 sum W Q E, then
 * sh = G^-1 sum W Q S(Ebar) (the coefficients of S*); with C != NULL also C = sum W S'(Ebar)
 * Q Q^T (mf x mf, full) */
static void project(const csfRom* r, const double* E, double* eh, double* sh, double* C) {
  const csfModel* m = r->fem;
  const int mf = r->mf, nk = r->nel[CSF_ROM_SET_FIBRE];
  memset(eh, 0, (size_t)mf * sizeof(double));
  memset(sh, 0, (size_t)mf * sizeof(double));
  for (int k = 0; k < nk; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    const double c = r->w[CSF_ROM_SET_FIBRE][k] * m->fib_EA[f] * m->fib_L0[f] * E[f];
    const double* Q = r->Qf + (size_t)f * (size_t)mf;
    for (int i = 0; i < mf; i++) {
      eh[i] += c * Q[i];
    }
  }
  csf_romMixedSolveWith(mf, r->Gf_chol, eh);
  if (C) {
    memset(C, 0, (size_t)mf * (size_t)mf * sizeof(double));
  }
  for (int k = 0; k < nk; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    const double W = r->w[CSF_ROM_SET_FIBRE][k] * m->fib_EA[f] * m->fib_L0[f];
    const double* Q = r->Qf + (size_t)f * (size_t)mf;
    double Eb = 0, S, dS;
    for (int i = 0; i < mf; i++) {
      Eb += Q[i] * eh[i];
    }
    csf_fibreLaw(m->fib_tension_only, Eb, &S, &dS);
    for (int i = 0; i < mf; i++) {
      sh[i] += W * S * Q[i];
    }
    if (C && dS != 0.0) {
      for (int i = 0; i < mf; i++) {
        const double ci = W * dS * Q[i];
        for (int j = 0; j < mf; j++) {
          C[(size_t)i * mf + j] += ci * Q[j];
        }
      }
    }
  }
  csf_romMixedSolveWith(mf, r->Gf_chol, sh);
}

static double dot(int k, const double* a, const double* b) {
  double s = 0;
  for (int i = 0; i < k; i++) {
    s += a[i] * b[i];
  }
  return s;
}

void csf_romFibresMixed(const csfRom* r, csfRomData* d, int want_k, double* rint) {
  const csfModel* m = r->fem;
  const int n = r->n, mf = r->mf, nk = r->nel[CSF_ROM_SET_FIBRE];
  double* eh = d->fq_e;
  double* sh = d->fq_e + mf;
  for (int k = 0; k < nk; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    double* dc = d->fib_d + 3 * (size_t)f;
    chord(r, k, d->q, dc);
    const double L0 = m->fib_L0[f];
    d->fib_E[f] = 0.5 * ((dc[0] * dc[0] + dc[1] * dc[1] + dc[2] * dc[2]) / (L0 * L0) - 1.0);
  }
  project(r, d->fib_E, eh, sh, want_k ? d->fq_C : NULL);
  double* B = d->fq_B;                       /* (mf x n) */
  double* Z = d->fq_B + (size_t)mf * n;      /* (mf x n) G^-1 B */
  double* T = d->fq_B + 2 * (size_t)mf * n;  /* (mf x n) C Z */
  if (want_k) {
    memset(B, 0, (size_t)mf * (size_t)n * sizeof(double));
  }
  double* g = d->tmp + n; /* (n) dE_f/dq L0^2 (d->tmp holds 2 n) */
  for (int k = 0; k < nk; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    const double* D = r->fib_D + (size_t)k * 3 * (size_t)n;
    const double* dc = d->fib_d + 3 * (size_t)f;
    const double* Q = r->Qf + (size_t)f * (size_t)mf;
    const double w = r->w[CSF_ROM_SET_FIBRE][k], EA = m->fib_EA[f], L0 = m->fib_L0[f];
    const double Ss = dot(mf, Q, sh);
    for (int j = 0; j < n; j++) {
      g[j] = D[j] * dc[0] + D[n + j] * dc[1] + D[2 * (size_t)n + j] * dc[2];
    }
    /* r += w EA L0 S* dE/dq = w EA S* / L0 D^T d */
    const double cf = w * EA * Ss / L0;
    for (int j = 0; j < n; j++) {
      rint[j] += cf * g[j];
    }
    if (!want_k) {
      continue;
    }
    /* B += W Q dE/dq (W = w EA L0, dE/dq = g / L0^2) */
    const double cb = w * EA / L0;
    for (int i = 0; i < mf; i++) {
      const double c = cb * Q[i];
      if (c == 0.0) {
        continue;
      }
      double* Bi = B + (size_t)i * n;
      for (int j = 0; j < n; j++) {
        Bi[j] += c * g[j];
      }
    }
    /* the geometric term w EA / L0 S*_state D^T D (upper triangle into Ku; only the tensile
     * part with fib_geo_tension, as csf_fibreKernel) */
    double Sg = d->sync ? Ss : d->fib_S[f];
    Sg = m->fib_geo_tension ? fmax(Sg, 0.0) : Sg;
    const double cg = w * EA / L0 * Sg;
    if (cg == 0.0) {
      continue;
    }
    for (int a = 0; a < n; a++) {
      const double d0 = cg * D[a], d1 = cg * D[n + a], d2 = cg * D[2 * (size_t)n + a];
      double* Ka = d->Ku + (size_t)a * n;
      for (int j = a; j < n; j++) {
        Ka[j] += d0 * D[j] + d1 * D[n + j] + d2 * D[2 * (size_t)n + j];
      }
    }
  }
  if (!want_k) {
    return;
  }
  /* K += Z^T C Z, Z = G^-1 B (column by column), T = C Z */
  double* col = d->fq_e + 2 * (size_t)mf; /* (mf) */
  for (int j = 0; j < n; j++) {
    for (int i = 0; i < mf; i++) {
      col[i] = B[(size_t)i * n + j];
    }
    csf_romMixedSolveWith(mf, r->Gf_chol, col);
    for (int i = 0; i < mf; i++) {
      Z[(size_t)i * n + j] = col[i];
    }
  }
  memset(T, 0, (size_t)mf * (size_t)n * sizeof(double));
  for (int i = 0; i < mf; i++) {
    double* Ti = T + (size_t)i * n;
    for (int l = 0; l < mf; l++) {
      const double c = d->fq_C[(size_t)i * mf + l];
      if (c == 0.0) {
        continue;
      }
      const double* Zl = Z + (size_t)l * n;
      for (int j = 0; j < n; j++) {
        Ti[j] += c * Zl[j];
      }
    }
  }
  for (int i = 0; i < mf; i++) {
    const double* Zi = Z + (size_t)i * n;
    const double* Ti = T + (size_t)i * n;
    for (int a = 0; a < n; a++) {
      double* Ka = d->K + (size_t)a * n;
      const double za = Zi[a];
      for (int c = 0; c < n; c++) {
        Ka[c] += za * Ti[c];
      }
    }
  }
}

void csf_romFibreStates(const csfRom* r, csfRomData* d, double alpha) {
  const csfModel* m = r->fem;
  const int n = r->n, mf = r->mf, nk = r->nel[CSF_ROM_SET_FIBRE];
  for (int k = 0; k < nk; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    const double* D = r->fib_D + (size_t)k * 3 * (size_t)n;
    double dd[3] = {0, 0, 0};
    for (int i = 0; i < 3; i++) {
      dd[i] = dot(n, D + (size_t)i * n, d->dq);
    }
    const double* d0 = d->fib_d0 + 3 * (size_t)f;
    const double L0 = m->fib_L0[f];
    d->fq_E[f] = d->fib_E0[f] + alpha * (d0[0] * dd[0] + d0[1] * dd[1] + d0[2] * dd[2]) /
                                    (L0 * L0);
  }
  double* eh = d->fq_e;
  double* sh = d->fq_e + mf;
  project(r, d->fq_E, eh, sh, NULL);
  for (int k = 0; k < nk; k++) {
    const int f = r->el[CSF_ROM_SET_FIBRE][k];
    d->fib_S[f] = dot(mf, r->Qf + (size_t)f * (size_t)mf, sh);
  }
}

int csf_romFibreElementForces(const csfRom* r, const double* q, double* G) {
  const csfModel* m = r->fem;
  const int n = r->n, mf = r->mf, nf = m->nfib, wd = n + 4 * mf;
  double* L = malloc((size_t)mf * (size_t)mf * sizeof(double));
  double* E = malloc((size_t)(nf > 0 ? nf : 1) * 4 * sizeof(double)); /* E, then the chords */
  double* eh = calloc(2 * (size_t)mf, sizeof(double));
  csError err;
  if (!L || !E || !eh || factorInto(r, 1, L, &err) != CS_OK) {
    free(L), free(E), free(eh);
    return -1;
  }
  double* dch = E + nf;
  for (int f = 0; f < nf; f++) {
    const int* fv = m->fib_node + 20 * (size_t)f;
    const double* c = m->fib_coef + 20 * (size_t)f;
    double* d = dch + 3 * (size_t)f;
    d[0] = d[1] = d[2] = 0.0;
    /* d = sum_a c_a (X_a + V_a q) over all 20 coefficients (fibreOperators in fem_rom.c) */
    for (int a = 0; a < 20; a++) {
      if (c[a] == 0.0) {
        continue;
      }
      for (int i = 0; i < 3; i++) {
        const double* row = r->V + (size_t)(3 * fv[a] + i) * (size_t)n;
        d[i] += c[a] * (m->mesh->x[3 * fv[a] + i] + dot(n, row, q));
      }
    }
    const double L0 = m->fib_L0[f];
    E[f] = 0.5 * ((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) / (L0 * L0) - 1.0);
  }
  /* the unreduced projections: E^ = G^-1 sum_f W_f Q_f E_f, then s^ = G^-1 sum W Q S(Ebar) */
  double* sh = eh + mf;
  for (int f = 0; f < nf; f++) {
    const double c = m->fib_EA[f] * m->fib_L0[f] * E[f];
    const double* Q = r->Qf + (size_t)f * (size_t)mf;
    for (int i = 0; i < mf; i++) {
      eh[i] += c * Q[i];
    }
  }
  csf_romMixedSolveWith(mf, L, eh);
  memset(G, 0, (size_t)nf * (size_t)wd * sizeof(double));
  for (int f = 0; f < nf; f++) {
    const double W = m->fib_EA[f] * m->fib_L0[f];
    const double* Q = r->Qf + (size_t)f * (size_t)mf;
    double* row = G + (size_t)f * wd;
    double S, dS;
    const double Eb = dot(mf, Q, eh);
    csf_fibreLaw(m->fib_tension_only, Eb, &S, &dS);
    for (int i = 0; i < mf; i++) {
      row[n + i] = W * Q[i] * E[f];          /* its share of sum W Q E (N) */
      row[n + mf + i] = W * Q[i] * S;        /* its share of sum W Q S(Ebar) (N) */
      row[n + 2 * mf + i] = W * Q[i] * Eb;   /* its share of G E^ (N) */
      sh[i] += row[n + mf + i];
    }
  }
  csf_romMixedSolveWith(mf, L, sh);
  for (int f = 0; f < nf; f++) { /* its share of G s^ (N) */
    const double* Q = r->Qf + (size_t)f * (size_t)mf;
    const double c = m->fib_EA[f] * m->fib_L0[f] * dot(mf, Q, sh);
    for (int i = 0; i < mf; i++) {
      G[(size_t)f * wd + n + 3 * mf + i] = c * Q[i];
    }
  }
  /* each fibre's reduced force at the unreduced S*_f: V_f^T (c (x) EA S*_f d_f / L0) */
  for (int f = 0; f < nf; f++) {
    const int* fv = m->fib_node + 20 * (size_t)f;
    const double* c = m->fib_coef + 20 * (size_t)f;
    const double* d = dch + 3 * (size_t)f;
    const double t = m->fib_EA[f] * dot(mf, r->Qf + (size_t)f * (size_t)mf, sh) / m->fib_L0[f];
    double* row = G + (size_t)f * wd;
    for (int a = 0; a < 20; a++) {
      if (c[a] == 0.0) {
        continue;
      }
      for (int i = 0; i < 3; i++) {
        const double fi = c[a] * t * d[i];
        const double* vr = r->V + (size_t)(3 * fv[a] + i) * (size_t)n;
        for (int j = 0; j < n; j++) {
          row[j] += fi * vr[j];
        }
      }
    }
  }
  free(L), free(E), free(eh);
  return 0;
}

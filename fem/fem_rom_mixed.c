/* fem_rom_mixed.c: the mixed reduced model's pressure basis and the factor of its pressure
 * matrix A (fem_rom_mixed.h, fem_rom.h csfRom.m).
 *
 * Rationale. The FE's Tet10 is the P2/P0 three-field element: per element a constant dilatation
 * theta_e and pressure p_e, condensed to p_e = kappa (v_e / V_e - 1) (fem_element.c). In the
 * reduced model p = P p^ with P from the POD of the training states' element pressures
 * (tools/rom_basis.py --mixed); the constraint sum_e w_e P_e (v_e - V_e - V_e p_e / kappa) = 0
 * is linear in p^ for a fixed q and gives p^ = A^-1 b(q). A is symmetric positive definite as
 * long as every pressure mode has support in the kept elements (kappa > 0, V_e > 0, w_e >= 0):
 * Cholesky, m is a few tens. */
#include "fem_rom_mixed.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

csStatus csf_romMixedFactorInto(const csfRom* r, int all, double* L, csError* err) {
  const int m = r->m;
  const double kappa = r->fem->mat.kappa;
  if (!(kappa > 0.0)) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_rom: the mixed model needs a bulk modulus > 0 "
                       "(kappa %g MPa)", kappa);
  }
  memset(L, 0, (size_t)m * (size_t)m * sizeof(double));
  const int nel = all ? r->fem->mesh->ntet : r->nel[CSF_ROM_SET_TET];
  for (int k = 0; k < nel; k++) {
    const int e = all ? k : r->el[CSF_ROM_SET_TET][k];
    const double c = (all ? 1.0 : r->w[CSF_ROM_SET_TET][k]) * r->fem->vol[e] / kappa;
    const double* Pe = r->P + (size_t)e * (size_t)m;
    for (int i = 0; i < m; i++) {
      for (int j = 0; j <= i; j++) {
        L[(size_t)i * m + j] += c * Pe[i] * Pe[j];
      }
    }
  }
  const int j = csf_romCholesky(m, L);
  if (j >= 0) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_rom: pressure mode %d of %d has no support in "
                       "the kept Tet10s (the mixed pressure matrix is singular)", j, m);
  }
  return CS_OK;
}

int csf_romCholesky(int m, double* L) {
  /* in-place Cholesky of the lower triangle; the scale of the diagonal sets the test */
  double dmax = 0;
  for (int i = 0; i < m; i++) {
    dmax = fmax(dmax, L[(size_t)i * m + i]);
  }
  for (int j = 0; j < m; j++) {
    double s = L[(size_t)j * m + j];
    for (int k = 0; k < j; k++) {
      s -= L[(size_t)j * m + k] * L[(size_t)j * m + k];
    }
    if (!(s > 1e-12 * dmax)) {
      return j;
    }
    const double ljj = sqrt(s);
    L[(size_t)j * m + j] = ljj;
    for (int i = j + 1; i < m; i++) {
      double t = L[(size_t)i * m + j];
      for (int k = 0; k < j; k++) {
        t -= L[(size_t)i * m + k] * L[(size_t)j * m + k];
      }
      L[(size_t)i * m + j] = t / ljj;
    }
  }
  return -1;
}

csStatus csf_romMixedFactor(csfRom* r, csError* err) {
  return csf_romMixedFactorInto(r, 0, r->A_chol, err);
}

void csf_romMixedSolveWith(int m, const double* L, double* x) {
  for (int i = 0; i < m; i++) {
    double s = x[i];
    for (int k = 0; k < i; k++) {
      s -= L[(size_t)i * m + k] * x[k];
    }
    x[i] = s / L[(size_t)i * m + i];
  }
  for (int i = m - 1; i >= 0; i--) {
    double s = x[i];
    for (int k = i + 1; k < m; k++) {
      s -= L[(size_t)k * m + i] * x[k];
    }
    x[i] = s / L[(size_t)i * m + i];
  }
}

void csf_romMixedSolve(const csfRom* r, double* x) {
  csf_romMixedSolveWith(r->m, r->A_chol, x);
}

csStatus csf_romBasisReplace(int rows, int m, const double* B, const char* what,
                             const char* row, double** basis, double** chol, csError* err) {
  if (m < 0 || (m > 0 && (!B || rows <= 0))) {
    return cs_errorSet(err, CS_ERR_ARG, "fem_rom: a %s of %d columns for %d %ss", what, m, rows,
                       row);
  }
  for (size_t i = 0; i < (size_t)rows * (size_t)m; i++) {
    if (!isfinite(B[i])) {
      return cs_errorSet(err, CS_ERR_ARG, "fem_rom: %s entry (%s %zu, column %zu) is not finite",
                         what, row, i / (size_t)m, i % (size_t)m);
    }
  }
  double *b = NULL, *c = NULL;
  if (m > 0) {
    b = malloc((size_t)rows * (size_t)m * sizeof(double));
    c = malloc((size_t)m * (size_t)m * sizeof(double));
    if (!b || !c) {
      free(b), free(c);
      return cs_errorSet(err, CS_ERR_MEMORY, "fem_rom: out of memory (%s %d x %d)", what, rows,
                         m);
    }
    memcpy(b, B, (size_t)rows * (size_t)m * sizeof(double));
  }
  free(*basis), free(*chol);
  *basis = b, *chol = c;
  return CS_OK;
}

csStatus csf_romSetPressureBasis(csfRom* r, int m, const double* P, csError* err) {
  csStatus st = csf_romBasisReplace(r->fem->mesh->ntet, m, P, "pressure basis", "element", &r->P,
                                    &r->A_chol, err);
  if (st != CS_OK) {
    return st;
  }
  r->m = m;
  if (m == 0) {
    return CS_OK;
  }
  st = csf_romMixedFactor(r, err);
  if (st != CS_OK) {
    free(r->P), free(r->A_chol);
    r->P = NULL, r->A_chol = NULL, r->m = 0;
  }
  return st;
}

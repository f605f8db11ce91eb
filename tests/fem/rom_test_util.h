/* rom_test_util.h: helpers shared by the reduced-model tests (header-only, static functions). */
#ifndef CS_ROM_TEST_UTIL_H
#define CS_ROM_TEST_UTIL_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "fem_rom.h"
#include "fem_test_util.h"

/* The tangent K (n x n, formed at q) against central differences of the reduced residual with
 * step h: returns max |K - K_fd| and sets *asym = max |K - K^T| (d->q is q again afterwards) */
static inline double rtFdTangent(const csfRom* r, csfRomData* d, const csfRomLoad* ld,
                                 const double* q, const double* K, double h, double* asym) {
  const int n = r->n;
  double* rp = malloc((size_t)n * sizeof(double));
  double efd = 0;
  *asym = 0;
  memcpy(d->q, q, (size_t)n * sizeof(double));
  for (int j = 0; rp && j < n; j++) {
    d->q[j] = q[j] + h;
    csf_romEvaluate(r, d, ld, 0);
    memcpy(rp, d->r, (size_t)n * sizeof(double));
    d->q[j] = q[j] - h;
    csf_romEvaluate(r, d, ld, 0);
    d->q[j] = q[j];
    for (int i = 0; i < n; i++) {
      efd = fmax(efd, fabs((rp[i] - d->r[i]) / (2 * h) - K[i * n + j]));
      *asym = fmax(*asym, fabs(K[i * n + j] - K[j * n + i]));
    }
  }
  free(rp);
  return rp ? efd : INFINITY;
}

/* The reduced-model tests' block: a clamped block 2 x 1.5 x L (z = 0 clamped), pressure on the
 * face x = 2 (tag 2, open), nfib (1..3) fibres through it (tension-only, or linear: the FE's
 * Newton stagnates on the tension-only fibre in a 2 mm block, whose smoothing zone its 771 N EA
 * crosses at every iterate), gravity across it. */
typedef struct RtBox_ {
  csfMesh* me;
  csfModel* m;
  csfData* d;
} RtBox;

static inline void rtBoxCreate(RtBox* b, int nz, double L, double kappa, int tension_only,
                               int nfib) {
  csError err = {0};
  int n[3] = {1, 1, nz};
  double sc[3] = {2.0, 1.5, L};
  b->me = csf_meshCreateBox(n, ftScaleMap, sc, 0.0, &err);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
  mat.kappa = kappa;
  b->m = csf_modelCreate(b->me, &mat, &err);
  CS_EXPECT(csf_modelAddPressure(b->m, 2, 1.0) > 0);
  const double fib[3][9] = {{0.3, 0.2, 0.1 * L, 1.7, 1.2, 0.5 * L, 0.5, 0.7, 0.9 * L},
                            {1.8, 0.3, 0.05 * L, 0.4, 1.1, 0.6 * L, 1.5, 1.3, 0.95 * L},
                            {1.0, 0.75, 0.02 * L, 1.2, 0.5, 0.5 * L, 0.9, 1.0, 0.97 * L}};
  CS_EXPECT(nfib >= 1 && nfib <= 3);
  for (int k = 0; k < nfib && k < 3; k++) {
    CS_EXPECT(csf_modelAddFibre(b->m, 3, fib[k], 31067.0, 0.0889, &err) == CS_OK);
  }
  for (int dir = 0; dir < 3; dir++) {
    ftFix(b->m, 2, 0.0, dir, 0.0);
  }
  b->m->gravity[1] = -9810.0;
  b->m->fib_tension_only = tension_only;
  CS_EXPECT(csf_modelFinalize(b->m, &err) == CS_OK);
  b->d = csf_dataCreate(b->m, &err);
  CS_EXPECT(b->d != NULL);
}

static inline void rtBoxDestroy(RtBox* b) {
  csf_dataDestroy(b->d);
  csf_modelDestroy(b->m);
  csf_meshDestroy(b->me);
}

/* the rom's per-face pressure at load factor `load` (the FE's face_p per unit load; the caller
 * frees) */
static inline double* rtFacePressure(const csfModel* m, double load) {
  double* p = malloc((size_t)m->mesh->nface * sizeof(double));
  for (int f = 0; p && f < m->mesh->nface; f++) {
    p[f] = load * m->face_p[f];
  }
  return p;
}

#endif /* CS_ROM_TEST_UTIL_H */

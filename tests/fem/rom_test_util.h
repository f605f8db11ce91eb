/* rom_test_util.h: helpers shared by the reduced-model tests (header-only, static functions). */
#ifndef CS_ROM_TEST_UTIL_H
#define CS_ROM_TEST_UTIL_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fem_rom.h"

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

#endif /* CS_ROM_TEST_UTIL_H */

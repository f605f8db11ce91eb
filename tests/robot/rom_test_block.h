/* rom_test_block.h: the rom-leg tests' block (tests only): a clamped silicone block (BX x BY x
 * BZ mm, Tet10) with a reduced basis of its own static responses (tip forces along x, y, z, a
 * tip twist, the pressure face, a force at mid height), Gram-Schmidt orthonormalised. */
#ifndef CS_TESTS_ROM_TEST_BLOCK_H
#define CS_TESTS_ROM_TEST_BLOCK_H

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"
#include "cs_test.h"
#include "fem_assembly.h"
#include "fem_rom.h"
#include "robot_rom.h"

#define BX 2.0
#define BY 1.5
#define BZ 6.0
#define RHO 1.07e-9

/* a precondition of the rest of a case: record and stop */
#define CS_ASSERT(c)    \
  do {                  \
    int ok_ = !!(c);    \
    CS_EXPECT(ok_);     \
    if (!ok_) {         \
      exit(1);          \
    }                   \
  } while (0)

typedef struct Block_ {
  csfMesh* me;
  csfModel* fem;
  csfRom* rom;
  int n;
  double* V;
} Block;

static inline void scaleMap(void* user, const double xi[3], double x[3]) {
  (void)user;
  x[0] = BX * xi[0];
  x[1] = BY * xi[1];
  x[2] = BZ * xi[2];
}

/* solve A x = b (n x n, dense, partial pivoting), A and b overwritten */
static inline void denseSolve(int n, double* A, double* b) {
  for (int k = 0; k < n; k++) {
    int p = k;
    for (int i = k + 1; i < n; i++) {
      if (fabs(A[i * n + k]) > fabs(A[p * n + k])) {
        p = i;
      }
    }
    for (int j = 0; j < n; j++) {
      double t = A[k * n + j];
      A[k * n + j] = A[p * n + j];
      A[p * n + j] = t;
    }
    double t = b[k];
    b[k] = b[p];
    b[p] = t;
    for (int i = k + 1; i < n; i++) {
      const double f = A[i * n + k] / A[k * n + k];
      for (int j = k; j < n; j++) {
        A[i * n + j] -= f * A[k * n + j];
      }
      b[i] -= f * b[k];
    }
  }
  for (int i = n - 1; i >= 0; i--) {
    double s = b[i];
    for (int j = i + 1; j < n; j++) {
      s -= A[i * n + j] * b[j];
    }
    b[i] = s / A[i * n + i];
  }
}

/* the block clamped at z = 0, its open face x = BX (tag 2) pressurised as "chamber 0", and a
 * basis of nb static responses of the linearised model at rest (free dofs: the FE's tangent
 * from the rom with the identity basis), Gram-Schmidt orthonormalised */
static inline void blockCreateFibres(Block* b, int nz, int fibres) {
  csError err = {0};
  int n3[3] = {1, 1, nz};
  b->me = csf_meshCreateBox(n3, scaleMap, NULL, 0.0, &err);
  CS_ASSERT(b->me != NULL);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, RHO);
  mat.kappa = 50.0; /* moderately incompressible: a well-conditioned small test */
  b->fem = csf_modelCreate(b->me, &mat, &err);
  CS_ASSERT(b->fem != NULL);
  CS_ASSERT(csf_modelAddPressure(b->fem, 2, 1.0) > 0);
  for (int i = 0; i < b->me->nnode; i++) {
    if (fabs(b->me->x[3 * i + 2]) < 1e-9) {
      b->fem->fixed[3 * i] = b->fem->fixed[3 * i + 1] = b->fem->fixed[3 * i + 2] = 1;
    }
  }
  if (fibres) { /* a helix-like polyline through the block (the leg's fibres' E and radius) */
    const double pts[12] = {0.3, 0.2, 0.1 * BZ, 1.7, 0.4, 0.4 * BZ, 1.6, 1.3, 0.7 * BZ,
                            0.4, 1.2, 0.95 * BZ};
    CS_ASSERT(csf_modelAddFibre(b->fem, 4, pts, 31067.0, 0.0889, &err) == CS_OK);
  }
  CS_ASSERT(csf_modelFinalize(b->fem, &err) == CS_OK);
  const int ndof = b->fem->ndof;
  int nfree = 0;
  for (int i = 0; i < ndof; i++) {
    nfree += !b->fem->fixed[i];
  }
  double* I = calloc((size_t)ndof * nfree, sizeof(double));
  for (int i = 0, c = 0; i < ndof; i++) {
    if (!b->fem->fixed[i]) {
      I[(size_t)i * nfree + c++] = 1.0;
    }
  }
  csfRom* full = csf_romCreate(b->fem, nfree, I, &err);
  CS_ASSERT(full != NULL);
  csfRomData* fd = csf_romDataCreate(full, &err);
  csf_romDataReset(full, fd);
  fd->sync = 1;
  csfRomLoad ld;
  memset(&ld, 0, sizeof ld);
  CS_ASSERT(csf_romEvaluate(full, fd, &ld, 1) == 0);
  /* loads: tip forces along x, y, z, a tip twist about z, the pressure face, a force along x at
   * mid height */
  enum { NB = 6 };
  double* f = calloc((size_t)NB * ndof, sizeof(double));
  for (int i = 0; i < b->me->nnode; i++) {
    const double* x = b->me->x + 3 * i;
    if (fabs(x[2] - BZ) < 1e-9) {
      f[0 * ndof + 3 * i] = 1;
      f[1 * ndof + 3 * i + 1] = 1;
      f[2 * ndof + 3 * i + 2] = 1;
      f[3 * ndof + 3 * i] = -(x[1] - 0.5 * BY);
      f[3 * ndof + 3 * i + 1] = x[0] - 0.5 * BX;
    }
    if (fabs(x[2] - 0.5 * BZ) < 1e-9) {
      f[5 * ndof + 3 * i] = 1;
    }
  }
  double* face_p = calloc((size_t)b->me->nface, sizeof(double));
  for (int fc = 0; fc < b->me->nface; fc++) {
    face_p[fc] = b->fem->face_p[fc];
  }
  csfRomLoad lp;
  memset(&lp, 0, sizeof lp);
  lp.face_p = face_p;
  CS_ASSERT(csf_romEvaluate(full, fd, &lp, 0) == 0); /* r = -V^T f_p at rest */
  double* rp = malloc((size_t)nfree * sizeof(double));
  memcpy(rp, fd->r, (size_t)nfree * sizeof(double));
  CS_ASSERT(csf_romEvaluate(full, fd, &ld, 1) == 0);
  b->n = NB;
  b->V = calloc((size_t)ndof * NB, sizeof(double));
  double* A = malloc((size_t)nfree * nfree * sizeof(double));
  double* u = malloc((size_t)nfree * sizeof(double));
  double* cols = calloc((size_t)NB * nfree, sizeof(double));
  for (int k = 0; k < NB; k++) {
    memcpy(A, fd->K, (size_t)nfree * nfree * sizeof(double));
    if (k == 4) {
      for (int c = 0; c < nfree; c++) {
        u[c] = -rp[c];
      }
    } else {
      csf_romProject(full, f + (size_t)k * ndof, u);
    }
    denseSolve(nfree, A, u);
    /* Gram-Schmidt, twice */
    for (int pass = 0; pass < 2; pass++) {
      for (int j = 0; j < k; j++) {
        double dot = 0;
        for (int c = 0; c < nfree; c++) {
          dot += u[c] * cols[(size_t)j * nfree + c];
        }
        for (int c = 0; c < nfree; c++) {
          u[c] -= dot * cols[(size_t)j * nfree + c];
        }
      }
    }
    double nrm = 0;
    for (int c = 0; c < nfree; c++) {
      nrm += u[c] * u[c];
    }
    nrm = sqrt(nrm);
    CS_ASSERT(nrm > 0);
    for (int c = 0; c < nfree; c++) {
      cols[(size_t)k * nfree + c] = u[c] / nrm;
    }
  }
  for (int i = 0, c = 0; i < ndof; i++) {
    if (!b->fem->fixed[i]) {
      for (int k = 0; k < NB; k++) {
        b->V[(size_t)i * NB + k] = cols[(size_t)k * nfree + c];
      }
      c++;
    }
  }
  b->rom = csf_romCreate(b->fem, NB, b->V, &err);
  CS_ASSERT(b->rom != NULL);
  free(I), free(f), free(face_p), free(rp), free(A), free(u), free(cols);
  csf_romDataDestroy(fd);
  csf_romDestroy(full);
}

/* the block without fibres */
static inline void blockCreate(Block* b, int nz) {
  blockCreateFibres(b, nz, 0);
}

static inline void blockDestroy(Block* b) {
  csf_romDestroy(b->rom);
  csf_modelDestroy(b->fem);
  csf_meshDestroy(b->me);
  free(b->V);
}

static inline int* chamberFaces(const Block* b) {
  int* ch = malloc((size_t)b->me->nface * sizeof(int));
  for (int f = 0; f < b->me->nface; f++) {
    ch[f] = b->me->face_tag[f] == 2 ? 0 : -1;
  }
  return ch;
}

static inline csrBaseState restBase(void) {
  csrBaseState s;
  memset(&s, 0, sizeof s);
  csu_eye3(s.R);
  return s;
}

#endif /* CS_TESTS_ROM_TEST_BLOCK_H */

/* test_fem_fibre.c: embedded fibres split at element faces (csfModel.fib_split).
 * - Every split fibre element lies in one host tetrahedron (both ends interpolated from the same
 *   10 nodes) and the elements' reference lengths add up to the polyline's, with and without
 *   splitting (a split only inserts points on the chords).
 * - Patch test: under a homogeneous deformation F every fibre element's Green strain is the
 *   closed form E = (|F a|^2 - 1) / 2 of its direction a, split or not (the Tet10 field is exact
 *   for affine displacements). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "fem_test_util.h"

#define NP 120 /* polyline points */

/* a helix inside the 15 x 15 x 50 block, and its length */
static double helix(double* p) {
  double L = 0;
  for (int k = 0; k < NP; k++) {
    const double t = (double)k / (NP - 1);
    p[3 * k] = 7.5 + 6.0 * cos(12.0 * t);
    p[3 * k + 1] = 7.5 + 6.0 * sin(12.0 * t);
    p[3 * k + 2] = 1.0 + 48.0 * t;
    if (k) {
      const double* q = p + 3 * (k - 1);
      L += sqrt(pow(p[3 * k] - q[0], 2) + pow(p[3 * k + 1] - q[1], 2) + pow(p[3 * k + 2] - q[2], 2));
    }
  }
  return L;
}


static csfModel* blockWithFibre(csfMesh** me_out, int split, double* L) {
  csError err = {0};
  int n[3] = {3, 3, 8};
  double sc[3] = {15, 15, 50};
  csfMesh* me = csf_meshCreateBox(n, ftScaleMap, sc, 0.15, &err);
  csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
  csfModel* m = csf_modelCreate(me, &mat, &err);
  m->fib_split = split;
  m->fib_tension_only = 0;
  double p[3 * NP];
  *L = helix(p);
  CS_EXPECT(csf_modelAddFibre(m, NP, p, 31067, 0.0889, &err) == CS_OK);
  *me_out = me;
  return m;
}


static void test_split_elements_lie_in_one_host(void) {
  for (int split = 0; split <= 1; split++) {
    csfMesh* me;
    double L;
    csfModel* m = blockWithFibre(&me, split, &L);
    double sum = 0;
    int single = 0;
    for (int f = 0; f < m->nfib; f++) {
      sum += m->fib_L0[f];
      single += !memcmp(m->fib_node + 20 * f, m->fib_node + 20 * f + 10, 10 * sizeof(int));
    }
    printf("  split %d: %d elements (%d in one host), length %.12f vs polyline %.12f mm\n", split,
           m->nfib, single, sum, L);
    /* each piece's length is interpolated from its host: exact on straight elements up to the
     * locator's tolerance (measured < 1e-12 mm in total) */
    CS_EXPECT_NEAR(sum, L, 1e-9, 0);
    if (split) {
      CS_EXPECT(single == m->nfib);
      CS_EXPECT(m->nfib > NP - 1); /* the helix crosses faces between its points */
    } else {
      CS_EXPECT(m->nfib == NP - 1);
      CS_EXPECT(single < m->nfib); /* some chords span two hosts */
    }
    csf_modelDestroy(m);
    csf_meshDestroy(me);
  }
}


static void test_fibre_strain_patch(void) {
  /* F: stretch, shear and rotation-free mix, well inside the elastic range of the law */
  const double F[9] = {1.05, 0.02, 0.0, -0.01, 0.97, 0.03, 0.015, 0.0, 1.08};
  for (int split = 0; split <= 1; split++) {
    csfMesh* me;
    double L;
    csfModel* m = blockWithFibre(&me, split, &L);
    csError err = {0};
    CS_EXPECT(csf_modelFinalize(m, &err) == CS_OK);
    csfData* d = csf_dataCreate(m, &err);
    for (int i = 0; i < me->nnode; i++) {
      const double* X = me->x + 3 * i;
      for (int a = 0; a < 3; a++) {
        d->u[3 * i + a] = F[3 * a] * X[0] + F[3 * a + 1] * X[1] + F[3 * a + 2] * X[2] - X[a];
      }
    }
    csf_assemble(m, d, 0.0, 0);
    double worst = 0;
    for (int f = 0; f < m->nfib; f++) {
      /* reference direction from the element's interpolated end points */
      double dX[3] = {0, 0, 0};
      for (int a = 0; a < 20; a++) {
        for (int k = 0; k < 3; k++) {
          dX[k] += m->fib_coef[20 * f + a] * me->x[3 * m->fib_node[20 * f + a] + k];
        }
      }
      double Fa[3] = {0, 0, 0};
      for (int a = 0; a < 3; a++) {
        for (int k = 0; k < 3; k++) {
          Fa[a] += F[3 * a + k] * dX[k] / m->fib_L0[f];
        }
      }
      const double E = 0.5 * (Fa[0] * Fa[0] + Fa[1] * Fa[1] + Fa[2] * Fa[2] - 1.0);
      worst = fmax(worst, fabs(d->fib_E[f] - E));
    }
    printf("  split %d: max |E - E_exact| = %.2e over %d fibre elements\n", split, worst, m->nfib);
    /* round-off of |d|^2 / L0^2 for pieces down to 1e-5 mm (measured < 1e-9) */
    CS_EXPECT(worst < 1e-8);
    csf_dataDestroy(d);
    csf_modelDestroy(m);
    csf_meshDestroy(me);
  }
}


/* a fibre on the faceted boundary: a straight fibre along the block's face x = 15 displaced
 * outwards by 0.05 mm (a fraction of the 5 mm elements, like a helix point that the coarse mesh's
 * chords leave outside the faceted fillet) embeds on the surface; the same fibre 3 mm outside is
 * refused with its distance */
static void test_fibre_on_the_faceted_boundary_embeds(void) {
  csError err = {0};
  int n[3] = {3, 3, 8};
  double sc[3] = {15, 15, 50};
  for (int far = 0; far <= 1; far++) {
    csfMesh* me = csf_meshCreateBox(n, ftScaleMap, sc, 0.0, &err);
    csfMaterial mat = csf_materialDefault(0.11, 0.02, 1130e-12);
    csfModel* m = csf_modelCreate(me, &mat, &err);
    const double off = far ? 3.0 : 0.05;
    double p[3 * 11];
    for (int k = 0; k < 11; k++) {
      p[3 * k] = 15.0 + off, p[3 * k + 1] = 7.3, p[3 * k + 2] = 2.0 + 4.6 * k;
    }
    cs_errorClear(&err);
    const csStatus st = csf_modelAddFibre(m, 11, p, 31067, 0.0889, &err);
    if (!far) {
      CS_EXPECT(st == CS_OK);
      CS_EXPECT(m->fib_projected == 11);
      /* projected onto the face: the fibre's length is the polyline's (a translation), less the
       * pieces below CSF_FIBRE_MIN_PIECE = 1e-5 mm dropped where the chord clips element corners
       * on the face (measured: 6e-6 mm in all) */
      double L = 0;
      for (int f = 0; f < m->nfib; f++) {
        L += m->fib_L0[f];
      }
      CS_EXPECT_NEAR(L, 46.0, 1e-4, 0);
      printf("  0.05 mm outside: %d points projected, %d elements, length %.12f mm\n",
             m->fib_projected, m->nfib, L);
    } else {
      CS_EXPECT(st == CS_ERR_RANGE);
      CS_EXPECT(strstr(err.msg, "lies 3 mm outside the meshed body") != NULL);
      printf("  3 mm outside: %s\n", err.msg);
    }
    csf_modelDestroy(m);
    csf_meshDestroy(me);
  }
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_split_elements_lie_in_one_host);
  CS_RUN(test_fibre_strain_patch);
  CS_RUN(test_fibre_on_the_faceted_boundary_embeds);
  return cs_testSummary();
}

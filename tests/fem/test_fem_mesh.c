/* test_fem_mesh.c: actuator geometry -> gmsh -> Tet10 mesh: volume, tags, segment planes; the
 * mesh with the square section's eight symmetries. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cs_test.h"
#include "fem_mesh.h"

static void test_actuator_mesh(void) {
  csError err = {0};
  csrActuator act;
  csr_actuatorPreset(&act, "baseline", &err);
  double t0 = (double)clock() / CLOCKS_PER_SEC;
  csfMesh* m = csf_meshActuator(&act, 5.0, "mesh_baseline_l5", &err);
  if (!m) {
    fprintf(stderr, "%s\n", err.msg);
  }
  CS_EXPECT(m != NULL);
  if (!m) {
    return;
  }
  printf("  baseline l_soft 5: %d Tet10, %d nodes, %d boundary faces (%.2f s cpu)\n", m->ntet,
         m->nnode, m->nface, (double)clock() / CLOCKS_PER_SEC - t0);
  double vol = 0;
  for (int t = 0; t < m->ntet; t++) {
    double v = csf_meshTetVolume(m, t);
    CS_EXPECT(v > 0);
    vol += v;
  }
  double L = csr_actuatorLength(&act);
  double exact = csr_actuatorOuterArea(&act) * L;
  for (int s = 0; s < 3; s++) {
    exact -= 4 * CS_PI * act.r1 * act.r1 * (act.S[s] - 2 * act.c);
  }
  printf("  volume %.3f mm^3 vs exact %.3f (rel %.2e)\n", vol, exact, vol / exact - 1);
  /* coarse elements on r1 = 2 mm chambers: straightened (folded) elements facet the chamber
   * walls; measured -4.3e-4; 5e-3 still catches a missing or doubled chamber (1.7 %) */
  CS_EXPECT_NEAR(vol, exact, 0, 5e-3);
  /* every chamber tagged; its wall area ~ 2 pi r1 Lc + 2 pi r1^2 */
  for (int s = 0; s < 3; s++) {
    for (int j = 1; j <= 4; j++) {
      int nf = 0;
      for (int f = 0; f < m->nface; f++) {
        nf += m->face_tag[f] == CSF_TAG_CHAMBER(s, j);
      }
      CS_EXPECT(nf > 0);
    }
  }
  int nbase = 0, ntip = 0;
  for (int f = 0; f < m->nface; f++) {
    nbase += m->face_tag[f] == CSF_TAG_BASE;
    ntip += m->face_tag[f] == CSF_TAG_TIP;
  }
  CS_EXPECT(nbase > 0 && ntip > 0);
  /* nodes on the segment end planes exist (conformal fragments) */
  for (int s = 0; s < 3; s++) {
    double z0 = csr_actuatorSegmentStart(&act, s), z1 = z0 + act.S[s];
    int n0 = 0, n1 = 0;
    for (int i = 0; i < m->nnode; i++) {
      n0 += fabs(m->x[3 * i + 2] - z0) < 1e-6;
      n1 += fabs(m->x[3 * i + 2] - z1) < 1e-6;
    }
    CS_EXPECT(n0 >= 8 && n1 >= 8);
  }
  csf_meshDestroy(m);
}

/* nodes ordered by coordinates for the image search */
static const double* g_x;
static int cmpNode(const void* pa, const void* pb) {
  const double* a = g_x + 3 * *(const int*)pa;
  const double* b = g_x + 3 * *(const int*)pb;
  for (int d = 2; d >= 0; d--) {
    if (a[d] != b[d]) {
      return a[d] < b[d] ? -1 : 1;
    }
  }
  return 0;
}


/* the node nearest to y among the sorted ones whose z is within tol (linear scan of that slab) */
static double nearestDistance(const csfMesh* m, const int* order, const double y[3], double tol) {
  int lo = 0, hi = m->nnode;
  while (lo < hi) { /* first node with z >= y[2] - tol */
    int mid = (lo + hi) / 2;
    if (m->x[3 * order[mid] + 2] < y[2] - tol) {
      lo = mid + 1;
    } else {
      hi = mid;
    }
  }
  double best = INFINITY;
  for (int k = lo; k < m->nnode && m->x[3 * order[k] + 2] <= y[2] + tol; k++) {
    const double* x = m->x + 3 * order[k];
    best = fmin(best, sqrt(pow(x[0] - y[0], 2) + pow(x[1] - y[1], 2) + pow(x[2] - y[2], 2)));
  }
  return best;
}


/* the area of the faces tagged `tag` */
static double taggedArea(const csfMesh* m, int tag) {
  double A = 0;
  for (int f = 0; f < m->nface; f++) {
    if (m->face_tag[f] != tag) {
      continue;
    }
    const double* a = m->x + 3 * m->face[6 * f];
    const double* b = m->x + 3 * m->face[6 * f + 1];
    const double* c = m->x + 3 * m->face[6 * f + 2];
    const double u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    const double v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    A += 0.5 * sqrt(pow(u[1] * v[2] - u[2] * v[1], 2) + pow(u[2] * v[0] - u[0] * v[2], 2) +
                    pow(u[0] * v[1] - u[1] * v[0], 2));
  }
  return A;
}


/* The symmetric mesh (an eighth meshed, mirrored into a quarter, turned four times): the
 * quarter turn and the two mirrors map its nodes onto its nodes (to round-off, 1e-12 mm; the
 * element size is ~1 mm), its volume is the body's, every chamber is tagged and the four
 * chambers of a segment have the same faceted wall area to round-off (a whole-body mesh differs
 * between chambers by the mesh), and no boundary face is left on the cut planes. */
static void test_symmetric_actuator_mesh(void) {
  csError err = {0};
  csrActuator act;
  csr_actuatorPreset(&act, "leg", &err);
  const char* sets[] = {"S1=15", "S2=15", "S3=15"};
  for (int k = 0; k < 3; k++) {
    CS_EXPECT(csr_actuatorSetString(&act, sets[k], &err) == CS_OK);
  }
  csfMesh* m = csf_meshActuatorSymmetric(&act, 4.0, "mesh_leg_sym", &err);
  if (!m) {
    fprintf(stderr, "%s\n", err.msg);
  }
  CS_EXPECT(m != NULL);
  if (!m) {
    return;
  }
  printf("  leg (15 mm segments), l_soft 4, symmetric: %d Tet10, %d nodes, %d boundary faces\n",
         m->ntet, m->nnode, m->nface);
  CS_EXPECT(m->ntet % 8 == 0);
  double vol = 0;
  for (int t = 0; t < m->ntet; t++) {
    double v = csf_meshTetVolume(m, t);
    CS_EXPECT(v > 0);
    vol += v;
  }
  double exact = csr_actuatorOuterArea(&act) * csr_actuatorLength(&act);
  for (int s = 0; s < 3; s++) {
    exact -= 4 * CS_PI * act.r1 * act.r1 * (act.S[s] - 2 * act.c);
  }
  printf("  volume %.3f mm^3 vs exact %.3f (rel %.2e)\n", vol, exact, vol / exact - 1);
  CS_EXPECT_NEAR(vol, exact, 0, 5e-3);
  int* order = malloc((size_t)m->nnode * sizeof(int));
  for (int i = 0; i < m->nnode; i++) {
    order[i] = i;
  }
  g_x = m->x;
  qsort(order, (size_t)m->nnode, sizeof(int), cmpNode);
  double worst[3] = {0, 0, 0};
  for (int i = 0; i < m->nnode; i++) {
    const double* x = m->x + 3 * i;
    /* the quarter turn, the mirror in x = y and the mirror in y = 0 generate all eight */
    const double y[3][3] = {{-x[1], x[0], x[2]}, {x[1], x[0], x[2]}, {x[0], -x[1], x[2]}};
    for (int g = 0; g < 3; g++) {
      worst[g] = fmax(worst[g], nearestDistance(m, order, y[g], 1e-6));
    }
  }
  printf("  every node's image under the quarter turn / the mirrors in x = y and y = 0: nearest "
         "node within %.2e / %.2e / %.2e mm\n", worst[0], worst[1], worst[2]);
  CS_EXPECT(worst[0] < 1e-12 && worst[1] < 1e-12 && worst[2] < 1e-12);
  free(order);
  for (int s = 0; s < 3; s++) {
    const double A1 = taggedArea(m, CSF_TAG_CHAMBER(s, 1));
    CS_EXPECT(A1 > 2 * CS_PI * act.r1 * (act.S[s] - 2 * act.c) * 0.95);
    for (int j = 2; j <= 4; j++) {
      CS_EXPECT_NEAR(taggedArea(m, CSF_TAG_CHAMBER(s, j)), A1, 0, 1e-12);
    }
  }
  int ncut = 0, nbase = 0, ntip = 0;
  for (int f = 0; f < m->nface; f++) {
    int on = 1;
    for (int v = 0; v < 3; v++) {
      const double* x = m->x + 3 * m->face[6 * f + v];
      on = on && (fabs(x[0]) < 1e-9 || fabs(x[1]) < 1e-9);
    }
    ncut += on;
    nbase += m->face_tag[f] == CSF_TAG_BASE;
    ntip += m->face_tag[f] == CSF_TAG_TIP;
  }
  CS_EXPECT(ncut == 0 && nbase > 0 && ntip > 0 && nbase % 4 == 0 && ntip % 4 == 0);
  csf_meshDestroy(m);
}


/* a quarter whose cut faces do not match node for node is refused (a structured box with
 * different cell counts along x and y) */
static void test_unmatched_quarter_is_refused(void) {
  csError err = {0};
  const int n[3] = {2, 3, 2};
  csfMesh* q = csf_meshCreateBox(n, NULL, NULL, 0, &err);
  CS_EXPECT(q != NULL);
  if (!q) {
    return;
  }
  csfMesh* m = csf_meshTurnCopies(q, NULL, NULL, &err);
  CS_EXPECT(m == NULL && err.status == CS_ERR_EXTERNAL &&
            strstr(err.msg, "cut faces are not periodic") != NULL);
  csf_meshDestroy(m);
  csf_meshDestroy(q);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_actuator_mesh);
  CS_RUN(test_symmetric_actuator_mesh);
  CS_RUN(test_unmatched_quarter_is_refused);
  return cs_testSummary();
}

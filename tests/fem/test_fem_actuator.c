/* test_fem_actuator.c: the actuator set-up refuses geometries the mesh cannot resolve, naming
 * the wall and the parameters, before gmsh runs; the wall thicknesses against closed forms; the
 * mesh-cost estimate against gmsh's own count, and a mesh far too fine refused with it; the
 * helices' turn (the FE's symmetry check) turns the fibres and nothing else; the paper's single
 * segment (II1 alone) meshes, loads and measures II1 and nothing beyond it. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"
#include "fem_actuator.h"
#include "fem_measure.h"
#include "fem_mesh.h"
#include "fem_model.h"

static void test_wall_thicknesses(void) {
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "baseline", &err) == CS_OK);
  csfWalls w;
  csf_actuatorWalls(&act, 4.0, &w);
  /* baseline: a - b - r1 = 7.5 - 4 - 2 (the chamber centre (4, 4) is inside the fillet centre
   * (5.5, 5.5), so the straight side is nearest), 2 (b - r1) = 4, c = 5, walls meshed at
   * min(4, 2 pi 2 / 6) = 2.094 mm */
  CS_EXPECT_NEAR(w.outer, 1.5, 1e-12, 0);
  CS_EXPECT_NEAR(w.between, 4.0, 1e-12, 0);
  CS_EXPECT_NEAR(w.cap, 5.0, 1e-12, 0);
  CS_EXPECT_NEAR(w.mesh, 2.0 * 3.14159265358979323846 * 2.0 / 6.0, 1e-12, 0);
  /* a chamber beyond the fillet centre: b = 6, r2 = 3 -> fillet centre (4.5, 4.5); from the
   * chamber centre along the diagonal to the arc r2 - sqrt(2) (6 - 4.5) = 0.879 mm, so with
   * r1 = 0.5 the wall is 0.379 mm (the straight side alone would give a - b - r1 = 1.0) */
  CS_EXPECT(csr_actuatorSet(&act, "b", 6.0, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r1", 0.5, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r2", 3.0, &err) == CS_OK);
  csf_actuatorWalls(&act, 4.0, &w);
  CS_EXPECT_NEAR(w.outer, 3.0 - sqrt(2.0) * 1.5 - 0.5, 1e-12, 0);
}


static void test_unresolvable_walls_are_refused(void) {
  csrActuator act;
  csError err;
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  spec.work_stem = "actuator_refused"; /* never written: refused before meshing */
  /* adjacent chambers 0.2 mm apart: 2 (3 - 2.9); walls meshed at 2 pi 2.9 / 6 = 3.04 mm */
  CS_EXPECT(csr_actuatorPreset(&act, "baseline", &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "b", 3.0, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r1", 2.9, &err) == CS_OK);
  csfActuatorFE fe;
  CS_EXPECT(csf_actuatorFECreate(&act, &spec, &fe, &err) == CS_ERR_RANGE);
  CS_EXPECT(strstr(err.msg, "wall between adjacent chambers is 0.2 mm thick") != NULL);
  CS_EXPECT(strstr(err.msg, "b = 3, r1 = 2.9") != NULL);
  printf("  %s\n", err.msg);
  /* a chamber 0.05 mm under the outer surface: 7.5 - 4 - 3.45 */
  CS_EXPECT(csr_actuatorPreset(&act, "baseline", &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r1", 3.45, &err) == CS_OK);
  CS_EXPECT(csf_actuatorFECreate(&act, &spec, &fe, &err) == CS_ERR_RANGE);
  CS_EXPECT(strstr(err.msg, "between a chamber and the outer surface is 0.05 mm thick") != NULL);
  printf("  %s\n", err.msg);
}


/* The estimate's Tet10 count is a lower bound that tightens as l_soft falls below the walls'
 * element size (the bulk dominates): checked against gmsh's mesh of a short actuator (three
 * 15 mm segments) at l_soft 1.5 mm, where the chamber walls (2.09 mm elements) no longer set
 * the count. Bounds: at least the estimate (its element volume 0.2 l³ is above the 0.16-0.19 l³
 * measured), at most 1.5x it (the walls' share at 1.5 mm); nodes within 10 % of 1.6 per Tet10. */
static void test_mesh_estimate_bounds_the_count(void) {
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "baseline", &err) == CS_OK);
  const char* names[] = {"S1", "S2", "S3", "n1", "n2", "n3"};
  const double vals[] = {15, 15, 15, 9, 9, 9};
  for (int k = 0; k < 6; k++) {
    CS_EXPECT(csr_actuatorSet(&act, names[k], vals[k], &err) == CS_OK);
  }
  csfMeshEstimate e;
  csf_actuatorEstimate(&act, 1.5, &e);
  csfMesh* m = csf_meshActuator(&act, 1.5, "actuator_estimate", &err);
  CS_EXPECT(m != NULL);
  if (!m) {
    fprintf(stderr, "%s\n", err.msg);
    return;
  }
  double vol = 0;
  for (int t = 0; t < m->ntet; t++) {
    vol += csf_meshTetVolume(m, t);
  }
  printf("  l_soft 1.5, short actuator: %d Tet10, %d nodes (estimate at least %.0f Tet10, "
         "%.0f dofs; ratio %.2f); volume %.1f mm^3 (estimate %.1f)\n", m->ntet, m->nnode,
         e.tet10, e.dofs, m->ntet / e.tet10, vol, e.volume);
  CS_EXPECT_NEAR(vol, e.volume, 0, 5e-3);
  CS_EXPECT(e.tet10 <= m->ntet && m->ntet <= 1.5 * e.tet10);
  CS_EXPECT_NEAR(m->nnode / (double)m->ntet, 1.6, 0, 0.1);
  /* the cost falls with coarser meshes as the model says: bytes ~ l^-4 */
  csfMeshEstimate e2;
  csf_actuatorEstimate(&act, 3.0, &e2);
  CS_EXPECT_NEAR(e.bytes / e2.bytes, 16.0, 0, 1e-12);
  csf_meshDestroy(m);
}


/* A mesh far too fine for any machine (l_soft 0.02 mm: ~1e12 Tet10) is refused before gmsh
 * runs, with the estimate and the finest l_soft that fits */
static void test_far_too_fine_mesh_is_refused(void) {
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "baseline", &err) == CS_OK);
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  spec.mesh_size = 0.02;
  spec.work_stem = "actuator_too_fine"; /* never written: refused before meshing */
  csfActuatorFE fe;
  CS_EXPECT(csf_actuatorFECreate(&act, &spec, &fe, &err) == CS_ERR_RANGE);
  CS_EXPECT(strstr(err.msg, "l_soft 0.02 mm gives at least") != NULL);
  CS_EXPECT(strstr(err.msg, "GB of memory on this machine: refused (l_soft >=") != NULL);
  CS_EXPECT(strstr(err.msg, "mm may fit)") != NULL);
  printf("  %s\n", err.msg);
  FILE* f = fopen("actuator_too_fine.geo", "r");
  CS_EXPECT(f == NULL);
  if (f) {
    fclose(f);
  }
}


/* the factors of a distributed factorisation are spread over the ranks: the refusal compares
 * this machine's share (bytes x local / ranks) with its memory and says so; all ranks on this
 * machine need what one rank needs */
static void test_memory_estimate_counts_the_ranks(void) {
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "baseline", &err) == CS_OK);
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  spec.mesh_size = 0.02;
  spec.work_stem = "actuator_too_fine_ranks"; /* never written: refused before meshing */
  csfActuatorFE fe;
  double gb[3];
  const int ranks[3][2] = {{1, 1}, {4, 1}, {4, 4}}; /* (ranks, of them on this machine) */
  for (int k = 0; k < 3; k++) {
    spec.mpi_ranks = ranks[k][0];
    spec.mpi_ranks_local = ranks[k][1];
    CS_EXPECT(csf_actuatorFECreate(&act, &spec, &fe, &err) == CS_ERR_RANGE);
    const char* at = strstr(err.msg, "needs about ");
    CS_EXPECT(at != NULL && sscanf(at, "needs about %lg GB", &gb[k]) == 1);
    CS_EXPECT((strstr(err.msg, "MPI ranks on this machine") != NULL) == (ranks[k][0] > 1));
    if (k == 1) {
      printf("  %s\n", err.msg);
    }
  }
  /* printed to 3 digits (%.3g) */
  CS_EXPECT_NEAR(gb[1], gb[0] / 4, 0, 5e-3);
  CS_EXPECT_NEAR(gb[2], gb[0], 0, 5e-3);
}


/* the start of the helices turned by a quarter turn (csfActuatorSpec.fibre_turn, the FE's
 * symmetry check) turns every fibre point by 90 deg about the leg axis and changes nothing else:
 * each fibre element's first end, rebuilt from its host nodes (x = -sum coef_a x_a, 20-node ties
 * so that the elements match one to one), against the unturned one turned, to the point
 * location's round-off (Newton on the Tet10 map to 1e-12) */
static void fibrePoints(const csfActuatorFE* fe, double* out) {
  const csfModel* m = fe->model;
  for (int f = 0; f < m->nfib; f++) {
    for (int d = 0; d < 3; d++) {
      double x = 0;
      for (int a = 0; a < 10; a++) {
        x -= m->fib_coef[20 * f + a] * fe->mesh->x[3 * m->fib_node[20 * f + a] + d];
      }
      out[3 * f + d] = x;
    }
  }
}


static void test_turned_fibres_are_the_fibres_turned(void) {
  csrActuator act;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "leg", &err) == CS_OK);
  const char* sets[] = {"S1=15", "S2=15", "S3=15", "n1=3", "n2=3", "n3=3"};
  for (int k = 0; k < 6; k++) {
    CS_EXPECT(csr_actuatorSetString(&act, sets[k], &err) == CS_OK);
  }
  csfActuatorSpec spec = csf_actuatorSpecDefault();
  spec.mesh_size = 4.0;
  spec.fibre_size = 1.0;
  spec.fibre_split = 0;
  spec.work_stem = "actuator_turn";
  csfActuatorFE fe0, fe1;
  CS_EXPECT(csf_actuatorFECreate(&act, &spec, &fe0, &err) == CS_OK);
  spec.fibre_turn = 1;
  CS_EXPECT(csf_actuatorFECreate(&act, &spec, &fe1, &err) == CS_OK);
  CS_EXPECT(fe0.model && fe1.model && fe0.model->nfib > 0 &&
            fe0.model->nfib == fe1.model->nfib);
  if (fe0.model && fe1.model && fe0.model->nfib == fe1.model->nfib) {
    const int n = fe0.model->nfib;
    double* p0 = malloc(3 * (size_t)n * sizeof(double));
    double* p1 = malloc(3 * (size_t)n * sizeof(double));
    fibrePoints(&fe0, p0);
    fibrePoints(&fe1, p1);
    double worst = 0, moved = 0;
    for (int f = 0; f < n; f++) {
      /* +90 deg about e3: (x, y, z) -> (-y, x, z) */
      const double r[3] = {-p0[3 * f + 1], p0[3 * f], p0[3 * f + 2]};
      for (int d = 0; d < 3; d++) {
        worst = fmax(worst, fabs(p1[3 * f + d] - r[d]));
        moved = fmax(moved, fabs(p1[3 * f + d] - p0[3 * f + d]));
      }
      CS_EXPECT_NEAR(fe1.model->fib_L0[f], fe0.model->fib_L0[f], 1e-9, 0);
    }
    printf("  %d fibre elements: turned against the unturned turned %.2e mm (moved up to %.2f "
           "mm)\n", n, worst, moved);
    CS_EXPECT(worst < 1e-9);
    CS_EXPECT(moved > 1.0); /* the turn did move them */
    free(p0);
    free(p1);
  }
  csf_actuatorFEDestroy(&fe0);
  csf_actuatorFEDestroy(&fe1);
  /* only quarter turns up to three are accepted */
  spec.fibre_turn = 4;
  CS_EXPECT(csf_actuatorFECreate(&act, &spec, &fe1, &err) == CS_ERR_ARG);
  CS_EXPECT(strstr(err.msg, "fibre turn 4 quarter turns is outside -3..3") != NULL);
}


/* The paper's single segment (its Sec. 3.3, Table 1: II1 of the Fig. 1a actuator alone, 40 mm,
 * 24 turns): only the FE takes it (the other levels' validation refuses S2 = 0); its mesh is
 * II1's solid (volume = the estimate's closed form, the outer section x S1 less four chambers of
 * S1 - 2c, to gmsh's geometric tolerance), ends at z = S1, has II1's four chambers and no
 * other; the chambers asked for in II2, II3 are not loaded; the fibres lie on II1; at u = 0 the
 * gauges give zero angles (II2 and II3: both faces are the tip face). */
static void test_single_segment_is_II1_alone(void) {
  csrActuator act, one;
  csError err;
  CS_EXPECT(csr_actuatorPreset(&act, "fig1", &err) == CS_OK);
  csr_actuatorSingleSegment(&act, &one);
  CS_EXPECT(csr_actuatorIsSingle(&one) && !csr_actuatorIsSingle(&act));
  CS_EXPECT_NEAR(csr_actuatorLength(&one), 40.0, 1e-12, 0);
  CS_EXPECT(csr_actuatorValidate(&one, &err) == CS_ERR_RANGE);
  CS_EXPECT(strstr(err.msg, "S2 = 0 must be > 0") != NULL);
  CS_EXPECT(csr_actuatorValidateSingle(&one, &err) == CS_OK);
  csrActuator bad = one;
  bad.n[2] = 3;
  CS_EXPECT(csr_actuatorValidateSingle(&bad, &err) == CS_ERR_RANGE);
  CS_EXPECT(strstr(err.msg, "single segment has no fibres on II2, II3") != NULL);
  csfActuatorSpec spec = csf_actuatorSpecDefault(); /* Omega1 & Omega2 asked in all three */
  spec.mesh_size = 5.0;
  spec.fibre_size = 0.8;
  spec.fibre_split = 0; /* one element per fibre segment: its midpoint by fibrePoints */
  spec.work_stem = "actuator_single";
  csfActuatorFE fe;
  CS_EXPECT(csf_actuatorFECreate(&one, &spec, &fe, &err) == CS_OK);
  if (!fe.model) {
    fprintf(stderr, "%s\n", err.msg);
    return;
  }
  const csfMesh* me = fe.mesh;
  double vol = 0, zmax = 0;
  for (int t = 0; t < me->ntet; t++) {
    vol += csf_meshTetVolume(me, t);
  }
  for (int i = 0; i < me->nnode; i++) {
    zmax = fmax(zmax, me->x[3 * i + 2]);
  }
  csfMeshEstimate e;
  csf_actuatorEstimate(&one, 5.0, &e);
  const double a = one.a, r2 = one.r2, r1 = one.r1;
  const double area = (2 * a - 2 * r2) * (2 * a - 2 * r2) + 4 * (2 * a - 2 * r2) * r2 +
                      3.14159265358979323846 * r2 * r2;
  CS_EXPECT_NEAR(e.volume, area * 40.0 - 4 * 3.14159265358979323846 * r1 * r1 * 30.0, 1e-9, 0);
  CS_EXPECT_NEAR(vol, e.volume, 0, 5e-3);
  CS_EXPECT_NEAR(zmax, 40.0, 1e-9, 0);
  int faces[CSR_NSEG][CSR_NCHAMBER] = {{0}};
  for (int f = 0; f < me->nface; f++) {
    for (int s = 0; s < CSR_NSEG; s++) {
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        faces[s][j] += me->face_tag[f] == CSF_TAG_CHAMBER(s, j + 1);
      }
    }
  }
  for (int j = 0; j < CSR_NCHAMBER; j++) {
    CS_EXPECT(faces[0][j] > 0 && faces[1][j] == 0 && faces[2][j] == 0);
  }
  CS_EXPECT(fe.ncham == 2);
  /* the helices run over II1, 0 <= z <= S1, to its end (the last point at S1) */
  const int nf = fe.model->nfib;
  double* pf = malloc(3 * (size_t)(nf > 0 ? nf : 1) * sizeof(double));
  double zf_min = INFINITY, zf_max = -INFINITY;
  if (pf) {
    fibrePoints(&fe, pf);
    for (int f = 0; f < nf; f++) {
      zf_min = fmin(zf_min, pf[3 * f + 2]), zf_max = fmax(zf_max, pf[3 * f + 2]);
    }
    free(pf);
  }
  CS_EXPECT(nf > 0 && zf_min >= -1e-9 && zf_max <= 40.0 + 1e-9 && zf_max > 40.0 - 1.0);
  csfData* d = csf_dataCreate(fe.model, &err);
  CS_EXPECT(d != NULL);
  if (d) {
    double ang[3], tot, tip[3];
    csf_bendMeasure(&one, fe.gauges, fe.model, d, fe.axis, NULL, ang, &tot, tip);
    CS_EXPECT_NEAR(ang[0], 0.0, 1e-9, 0);
    CS_EXPECT_NEAR(ang[1], 0.0, 1e-9, 0);
    CS_EXPECT_NEAR(ang[2], 0.0, 1e-9, 0);
    CS_EXPECT_NEAR(tip[2], 40.0, 1e-9, 0);
    csfSegmentState seg[CSR_NSEG];
    double Rtip[9];
    CS_EXPECT(csf_segmentMeasure(&one, fe.gauges, fe.model, d, seg, tip, Rtip) == 0);
    CS_EXPECT_NEAR(seg[0].stretch, 1.0, 1e-4, 0); /* face-node centroids, not the axis */
    CS_EXPECT(seg[1].stretch == 1.0 && seg[2].stretch == 1.0);
    csf_dataDestroy(d);
  }
  printf("  single segment at l_soft 5: %d Tet10, %d nodes, %d fibre elements, volume %.1f mm^3 "
         "(closed form %.1f)\n", me->ntet, me->nnode, fe.model->nfib, vol, e.volume);
  csf_actuatorFEDestroy(&fe);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_wall_thicknesses);
  CS_RUN(test_unresolvable_walls_are_refused);
  CS_RUN(test_mesh_estimate_bounds_the_count);
  CS_RUN(test_far_too_fine_mesh_is_refused);
  CS_RUN(test_memory_estimate_counts_the_ranks);
  CS_RUN(test_turned_fibres_are_the_fibres_turned);
  CS_RUN(test_single_segment_is_II1_alone);
  return cs_testSummary();
}

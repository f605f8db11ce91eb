/* test_terrains_ccd.c: the terrain's boxes as contact shapes (terrains_ccd.h): libccd support
 * and centre functions, the exact signed distance, the broad phase. Everything is checked
 * against an independent brute force (corners, sampled surfaces, all pairs). */
#include <ccd/ccd.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "terrains_ccd.h"

/* a step road: ground, a 40 mm step, and a far plateau */
static cstTerrain stepTerrain(void) {
  cstTerrain t;
  memset(&t, 0, sizeof t);
  t.nbox = 3;
  t.box[0] = (cstBox){.lo = {-300, -20, -150}, .hi = {300, 0, 150}};
  t.box[1] = (cstBox){.lo = {50, 0, -150}, .hi = {300, 40, 150}};
  t.box[2] = (cstBox){.lo = {400, 0, -150}, .hi = {600, 40, 150}};
  return t;
}


/* deterministic uniform numbers in [-1, 1) (a 64-bit LCG: the test must not vary) */
static double uniform(unsigned long long* s) {
  *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
  return (double)(*s >> 11) / 9007199254740992.0 * 2 - 1;
}


static void test_terrains_ccd_support_is_the_extreme_corner(void) {
  cstTerrain t = stepTerrain();
  unsigned long long seed = 1;
  int bad = 0;
  for (int i = 0; i < 1000; i++) {
    const cstBox* b = &t.box[i % 3];
    ccd_vec3_t dir, sup;
    ccdVec3Set(&dir, uniform(&seed), uniform(&seed), uniform(&seed));
    cst_ccdBoxSupport(b, &dir, &sup);
    /* the support's projection equals the largest over the 8 corners, and it is a corner */
    double best = -INFINITY;
    for (int c = 0; c < 8; c++) {
      double p[3] = {(c & 1) ? b->hi[0] : b->lo[0], (c & 2) ? b->hi[1] : b->lo[1],
                     (c & 4) ? b->hi[2] : b->lo[2]};
      best = fmax(best, p[0] * dir.v[0] + p[1] * dir.v[1] + p[2] * dir.v[2]);
    }
    double got = ccdVec3Dot(&sup, &dir);
    bad += got != best;
  }
  /* exact: the same corner's coordinates enter the same sum */
  CS_EXPECT(bad == 0);
  ccd_vec3_t c;
  cst_ccdBoxCenter(&t.box[1], &c);
  CS_EXPECT(c.v[0] == 175 && c.v[1] == 20 && c.v[2] == 0);
}


static void test_terrains_ccd_mpr_collides_two_boxes(void) {
  /* the support functions drive libccd: the step and the plateau are 100 mm apart; a box
   * overlapping the step's top by 0.5 mm collides with it, with depth 0.5 along +y */
  cstTerrain t = stepTerrain();
  ccd_t ccd;
  CCD_INIT(&ccd);
  ccd.support1 = ccd.support2 = cst_ccdBoxSupport;
  ccd.center1 = ccd.center2 = cst_ccdBoxCenter;
  ccd.mpr_tolerance = 1e-9;
  CS_EXPECT(!ccdMPRIntersect(&t.box[1], &t.box[2], &ccd));
  CS_EXPECT(ccdMPRIntersect(&t.box[0], &t.box[1], &ccd)); /* they share a face */
  cstBox probe = {.lo = {100, 39.5, -10}, .hi = {120, 60, 10}};
  ccd_real_t depth;
  ccd_vec3_t dir, pos;
  CS_EXPECT(ccdMPRPenetration(&t.box[1], &probe, &ccd, &depth, &dir, &pos) == 0);
  /* MPR on two faces: exact to its tolerance (1e-9 mm) */
  CS_EXPECT_NEAR(depth, 0.5, 1e-9, 0);
  CS_EXPECT_NEAR(dir.v[1], 1, 1e-9, 0);
}


static void test_terrains_ccd_signed_distance_exact(void) {
  cstTerrain t = stepTerrain();
  const cstBox* b = &t.box[1];
  unsigned long long seed = 7;
  double worst_rel = 0, worst_in = 0;
  int closer = 0;
  for (int i = 0; i < 300; i++) {
    double x[3] = {175 + 200 * uniform(&seed), 20 + 60 * uniform(&seed),
                   200 * uniform(&seed)};
    double cp[3], n[3];
    double sd = cst_boxSignedDistance(b, x, cp, n);
    /* consistency: x = cp + sd n, n unit, cp on the surface */
    double e = 0;
    for (int k = 0; k < 3; k++) e = fmax(e, fabs(x[k] - (cp[k] + sd * n[k])));
    worst_rel = fmax(worst_rel, e);
    CS_EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1, 1e-14, 0);
    if (sd < 0) {
      /* inside: minus the nearest face gap, by its own formula */
      double gap = INFINITY;
      for (int k = 0; k < 3; k++) gap = fmin(gap, fmin(x[k] - b->lo[k], b->hi[k] - x[k]));
      worst_in = fmax(worst_in, fabs(sd + gap));
    } else {
      /* outside: no point of a 21 x 21 grid on each face is closer than sd */
      for (int f = 0; f < 6; f++) {
        int k = f / 2, k1 = (k + 1) % 3, k2 = (k + 2) % 3;
        for (int a = 0; a <= 20; a++) {
          for (int c = 0; c <= 20; c++) {
            double q[3];
            q[k] = (f % 2) ? b->hi[k] : b->lo[k];
            q[k1] = b->lo[k1] + a * (b->hi[k1] - b->lo[k1]) / 20;
            q[k2] = b->lo[k2] + c * (b->hi[k2] - b->lo[k2]) / 20;
            double d = sqrt((x[0] - q[0]) * (x[0] - q[0]) + (x[1] - q[1]) * (x[1] - q[1]) +
                            (x[2] - q[2]) * (x[2] - q[2]));
            closer += d < sd - 1e-12;
          }
        }
      }
    }
  }
  /* round-off of one multiply-add on ~300 mm numbers: 1e-13 mm */
  CS_EXPECT_NEAR(worst_rel, 0, 1e-12, 0);
  CS_EXPECT_NEAR(worst_in, 0, 0, 0);
  CS_EXPECT(closer == 0);
}


static void test_terrains_ccd_near_query_matches_brute_force(void) {
  cstTerrain t = stepTerrain();
  unsigned long long seed = 3;
  int bad = 0;
  for (int i = 0; i < 2000; i++) {
    double c[3] = {300 * uniform(&seed) + 150, 60 * uniform(&seed), 200 * uniform(&seed)};
    double h = 20 * fabs(uniform(&seed)), margin = 5 * fabs(uniform(&seed));
    double lo[3] = {c[0] - h, c[1] - h, c[2] - h}, hi[3] = {c[0] + h, c[1] + h, c[2] + h};
    int idx[CST_MAX_BOXES];
    int n = cst_terrainBoxesNear(&t, lo, hi, margin, idx, CST_MAX_BOXES);
    /* brute force: gap between the intervals per axis, the boxes overlap within margin */
    int m = 0;
    for (int j = 0; j < t.nbox; j++) {
      int ok = 1;
      for (int k = 0; k < 3; k++) {
        double gap = fmax(t.box[j].lo[k] - hi[k], lo[k] - t.box[j].hi[k]);
        ok = ok && gap <= margin;
      }
      if (ok) {
        bad += m >= n || idx[m] != j;
        m++;
      }
    }
    bad += m != n;
  }
  CS_EXPECT(bad == 0);
  /* the count is returned even when the caller's array is shorter */
  double p[3] = {100, 0, 0};
  int one;
  CS_EXPECT(cst_terrainBoxesNear(&t, p, p, 0, &one, 1) == 2 && one == 0);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_terrains_ccd_support_is_the_extreme_corner);
  CS_RUN(test_terrains_ccd_mpr_collides_two_boxes);
  CS_RUN(test_terrains_ccd_signed_distance_exact);
  CS_RUN(test_terrains_ccd_near_query_matches_brute_force);
  return cs_testSummary();
}

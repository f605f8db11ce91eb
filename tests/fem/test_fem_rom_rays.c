/* test_fem_rom_rays.c: the built-in ray list of the reduced leg's training (fem_rom_snap.h
 * csf_romRays).
 *
 * Proves:
 *  - names_are_unique: no two rays share a name (a ray's file is named after it).
 *  - no_training_ray_follows_a_held_out_one: no training ray's loads (the twelve pressures,
 *    gravity and the tip force at t = 1) are a positive multiple of a held-out ray's; a ray's
 *    loads grow in proportion to t, so such a ray would pass through the held-out states and
 *    train on them (issue 34: the held-out cases are never used in training).
 *  - squeezed_rays_vent_one_chamber_squeezed_by_loaded_ones: in every segment of SQ1-SQ6
 *    exactly one chamber is vented, and it is either diagonally opposite the most loaded one
 *    (Ω1-Ω3, Ω2-Ω4; robot_actuator.h) with both flanks below that, or between two chambers at
 *    the segment's level (the family's definition, fem_rom_snap.c). */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "cs_test.h"
#include "fem_rom_snap.h"

enum { NLOAD = CSR_NSEG * CSR_NCHAMBER + 6 };

static csfRomRay rays[CSF_ROM_MAX_RAYS];
static int nray;

/* a ray's loads at t = 1 as one vector, each kind scaled to its ray family's magnitude (MPa,
 * 9810 mm/s^2, 1 N) so that the cosine weighs them alike */
static void loads(const csfRomRay* y, double* v) {
  for (int s = 0; s < CSR_NSEG; s++) {
    for (int j = 0; j < CSR_NCHAMBER; j++) {
      v[s * CSR_NCHAMBER + j] = y->p[s][j];
    }
  }
  for (int i = 0; i < 3; i++) {
    v[CSR_NSEG * CSR_NCHAMBER + i] = y->gravity[i] / 9810.0;
    v[CSR_NSEG * CSR_NCHAMBER + 3 + i] = y->tip_force[i];
  }
}

static void names_are_unique(void) {
  CS_EXPECT(nray > 0 && nray <= CSF_ROM_MAX_RAYS);
  for (int a = 0; a < nray; a++) {
    for (int b = a + 1; b < nray; b++) {
      CS_EXPECT(strcmp(rays[a].name, rays[b].name) != 0);
    }
  }
}

static void no_training_ray_follows_a_held_out_one(void) {
  int pairs = 0;
  double closest = -1.0;
  for (int a = 0; a < nray; a++) {
    if (rays[a].kind != CSF_ROM_TEST) {
      continue;
    }
    double va[NLOAD];
    loads(rays + a, va);
    for (int b = 0; b < nray; b++) {
      if (rays[b].kind != CSF_ROM_TRAIN) {
        continue;
      }
      double vb[NLOAD], ab = 0, aa = 0, bb = 0;
      loads(rays + b, vb);
      for (int i = 0; i < NLOAD; i++) {
        ab += va[i] * vb[i], aa += va[i] * va[i], bb += vb[i] * vb[i];
      }
      const double c = ab / sqrt(aa * bb);
      /* parallel to round-off (the patterns are products of a few decimals) */
      if (c > 1.0 - 1e-12) {
        fprintf(stderr, "  training ray %s follows held-out ray %s (cosine %.15f)\n",
                rays[b].name, rays[a].name, c);
      }
      CS_EXPECT(c <= 1.0 - 1e-12);
      closest = fmax(closest, c);
      pairs++;
    }
  }
  printf("  %d training / held-out pairs, the closest cosine %.4f\n", pairs, closest);
  CS_EXPECT(pairs >= 30 * 5);
}

static void squeezed_rays_vent_one_chamber_squeezed_by_loaded_ones(void) {
  int nsq = 0;
  for (int r = 0; r < nray; r++) {
    if (strncmp(rays[r].name, "SQ", 2) != 0) {
      continue;
    }
    nsq++;
    CS_EXPECT(rays[r].kind == CSF_ROM_TRAIN);
    for (int s = 0; s < CSR_NSEG; s++) {
      const double* p = rays[r].p[s];
      double top = 0.0;
      int nvent = 0, vent = -1;
      for (int j = 0; j < CSR_NCHAMBER; j++) {
        CS_EXPECT(p[j] >= 0.0);
        top = fmax(top, p[j]);
        if (p[j] == 0.0) {
          nvent++, vent = j;
        }
      }
      CS_EXPECT(top > 0.0 && nvent == 1);
      if (nvent != 1) {
        continue;
      }
      const double opp = p[(vent + 2) % CSR_NCHAMBER], nb1 = p[(vent + 1) % CSR_NCHAMBER],
                   nb3 = p[(vent + 3) % CSR_NCHAMBER];
      /* A, A', B: the vented chamber opposite the dominant one, both flanks below it; C: the
       * vented chamber between two full ones */
      const int opposite = opp == top && nb1 < top && nb3 < top;
      const int between = nb1 == top && nb3 == top;
      if (!(opposite || between)) {
        fprintf(stderr, "  %s segment %d: (%g, %g, %g, %g) MPa\n", rays[r].name, s + 1, p[0],
                p[1], p[2], p[3]);
      }
      CS_EXPECT(opposite || between);
    }
  }
  CS_EXPECT(nsq == 6);
}

int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  nray = csf_romRays(rays, CSF_ROM_MAX_RAYS);
  CS_RUN(names_are_unique);
  CS_RUN(no_training_ray_follows_a_held_out_one);
  CS_RUN(squeezed_rays_vent_one_chamber_squeezed_by_loaded_ones);
  return cs_testSummary();
}

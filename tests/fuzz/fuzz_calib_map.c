/* fuzz_calib_map.c: the bend-map check of the calibration harnesses (fuzz_calib_map.h). */
#include "fuzz_calib_map.h"

#include <math.h>
#include <string.h>

#include "fuzz_common.h"

/* where a map without an upper end (the provisional one) is evaluated up to (MPa) */
#define OPEN_P_MAX 0.4
/* chamber patterns (ratios of the load factor): pair, single, all four, an unequal mix */
static const double kPattern[][4] = {{1, 1, 0, 0}, {1, 0, 0, 0}, {1, 1, 1, 1}, {0, 1, 0.5, 0}};
#define NPATTERN ((int)(sizeof kPattern / sizeof kPattern[0]))


static void evalAt(const csrBendMap* map, const double P[4], int above) {
  for (int seg = 0; seg < 3; seg++) {
    double bend[2] = {NAN, NAN}, stretch = NAN;
    int rc = map->eval(map->ctx, seg, P, bend, &stretch);
    if (above) {
      if (rc != CSR_MAP_OUT_OF_RANGE) {
        csz_fail("map '%s' returned %d at %g MPa, above its p_max %g (must refuse)", map->name, rc,
                 fmax(fmax(P[0], P[1]), fmax(P[2], P[3])), map->p_max);
      }
      continue;
    }
    if (rc < 0) {
      csz_fail("map '%s' failed (%d) at (%g, %g, %g, %g) MPa, segment %d, within p_max %g",
               map->name, rc, P[0], P[1], P[2], P[3], seg, map->p_max);
    }
    if (rc == 0 && (!isfinite(bend[0]) || !isfinite(bend[1]) || !isfinite(stretch) ||
                    !(stretch > 0))) {
      csz_fail("map '%s' at (%g, %g, %g, %g) MPa, segment %d: bend (%g, %g), stretch %g",
               map->name, P[0], P[1], P[2], P[3], seg, bend[0], bend[1], stretch);
    }
  }
}


void csz_checkBendMap(const csrBendMap* map, int points) {
  if (!map->eval || !map->name || !memchr(map->name, '\0', 4096) || !(map->p_max > 0)) {
    csz_fail("accepted calibration: map without eval, name or a p_max > 0 (%g)", map->p_max);
  }
  const double top = isfinite(map->p_max) ? map->p_max : OPEN_P_MAX;
  for (int k = 0; k < points; k++) {
    /* levels from 0 to the top, the top itself last */
    const double p = points > 1 ? top * k / (points - 1) : top;
    for (int q = 0; q < NPATTERN; q++) {
      double P[4];
      for (int j = 0; j < 4; j++) P[j] = kPattern[q][j] * p;
      evalAt(map, P, 0);
    }
  }
  if (isfinite(map->p_max)) {
    /* just above the end, and far above */
    const double above[2] = {map->p_max * (1 + 1e-9) + 1e-12, 2 * map->p_max + 1};
    for (int k = 0; k < 2; k++) {
      for (int q = 0; q < NPATTERN; q++) {
        double P[4];
        for (int j = 0; j < 4; j++) P[j] = kPattern[q][j] * above[k];
        evalAt(map, P, 1);
      }
    }
  }
}


void csz_checkRodCalibration(const csrRodCalibration* rod, double p_max, double k_pmax,
                             int points) {
  if (!rod->eval || !rod->name) {
    csz_fail("rod calibration without eval or name");
  }
  const double top = isfinite(p_max) ? p_max : OPEN_P_MAX;
  for (int k = 0; k < points; k++) {
    const double p = points > 1 ? top * k / (points - 1) : top;
    for (int q = 0; q < NPATTERN; q++) {
      double P[4];
      for (int j = 0; j < 4; j++) P[j] = kPattern[q][j] * p;
      for (int seg = 0; seg < 3; seg++) {
        csrRodSegmentActuation out;
        memset(&out, 0, sizeof out);
        int rc = rod->eval(rod->ctx, seg, P, &out);
        const double pbar = 0.25 * (P[0] + P[1] + P[2] + P[3]);
        if (rc == CSR_MAP_OUT_OF_RANGE && pbar > k_pmax) {
          continue; /* above the stiffness probes: refused, as documented */
        }
        if (rc < 0) {
          csz_fail("rod calibration '%s' failed (%d) at %g MPa (pattern %d), segment %d, within "
                   "%g MPa", rod->name, rc, p, q, seg, p_max);
        }
        const csrRodSection* sc = &out.section;
        if (rc == 0 && (!csz_allFinite(out.u0, 3) || !csz_allFinite(out.sigma0, 3) ||
                        (out.has_section && !(sc->EA > 0 && sc->EI[0] > 0 && sc->EI[1] > 0 &&
                                              isfinite(sc->EA) && isfinite(sc->EI[0]) &&
                                              isfinite(sc->EI[1]))))) {
          csz_fail("rod calibration '%s' at %g MPa (pattern %d), segment %d: u0 (%g, %g, %g), "
                   "stretch %g, EA %g, EI %g", rod->name, p, q, seg, out.u0[0], out.u0[1],
                   out.u0[2], out.sigma0[2], sc->EA, sc->EI[0]);
        }
      }
    }
  }
}

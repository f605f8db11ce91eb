/* rod_test_road.h: the flat road the rod-leg tests stand on (tests only): the box of
 * terrains/flat_road.terrain moved to x = -300..300, z = -150..150, top at y = 0. */
#ifndef CS_TESTS_ROD_TEST_ROAD_H
#define CS_TESTS_ROD_TEST_ROAD_H

#include <string.h>

#include "terrains_terrain.h"

static inline cstTerrain csTestFlatRoad(void) {
  cstTerrain tr;
  memset(&tr, 0, sizeof tr);
  tr.nbox = 1;
  const double lo[3] = {-300, -50, -150}, hi[3] = {300, 0, 150};
  memcpy(tr.box[0].lo, lo, sizeof lo);
  memcpy(tr.box[0].hi, hi, sizeof hi);
  return tr;
}

#endif /* CS_TESTS_ROD_TEST_ROAD_H */

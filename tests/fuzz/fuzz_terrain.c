/* fuzz_terrain.c: fuzz harness of the terrain reader (terrains_terrain.h, cst_terrainLoad).
 *
 * Per input: load it and check the error contract (fuzz_common.h); a terrain the reader accepts
 * must hold what the header promises (1..32 boxes with lo < hi, finite coordinates within
 * +-1e6 mm, a start above a box, a heading within +-360 deg, a NUL-terminated non-empty name)
 * and build its ODE geoms (ODE's own asserts abort on a degenerate box). */
#include <math.h>
#include <string.h>

#include <ode/ode.h>

#include "fuzz_common.h"
#include "terrains_terrain.h"

#define MAX_COORD_MM 1e6
#define MAX_HEADING_DEG 360.0


int csz_harnessInit(void) {
  if (!dInitODE2(0)) {
    return 1;
  }
  return csz_tempPath(0, ".terrain") ? 0 : 1;
}


static void checkTerrain(const cstTerrain* t) {
  if (t->nbox < 1 || t->nbox > CST_MAX_BOXES) {
    csz_fail("accepted terrain has %d boxes", t->nbox);
  }
  for (int i = 0; i < t->nbox; i++) {
    const cstBox* b = &t->box[i];
    for (int k = 0; k < 3; k++) {
      if (!(b->lo[k] < b->hi[k]) || !(fabs(b->lo[k]) <= MAX_COORD_MM) ||
          !(fabs(b->hi[k]) <= MAX_COORD_MM)) {
        csz_fail("accepted terrain: box %d axis %d is %g..%g", i, k, b->lo[k], b->hi[k]);
      }
    }
  }
  if (!isfinite(cst_terrainHeightAt(t, t->start[0], t->start[1]))) {
    csz_fail("accepted terrain: start (%g, %g) above no box", t->start[0], t->start[1]);
  }
  if (!(fabs(t->heading_deg) <= MAX_HEADING_DEG)) {
    csz_fail("accepted terrain: heading %g", t->heading_deg);
  }
  if (!memchr(t->name, '\0', sizeof t->name) || !t->name[0]) {
    csz_fail("accepted terrain: name empty or not terminated");
  }
  dSpaceID space = dSimpleSpaceCreate(0);
  if (cst_terrainBuildOde(t, space) != t->nbox || dSpaceGetNumGeoms(space) != t->nbox) {
    csz_fail("accepted terrain: ODE geoms do not match the %d boxes", t->nbox);
  }
  dSpaceDestroy(space);
}


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  const char* path = csz_tempPath(0, ".terrain");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  cstTerrain t;
  csStatus st = cst_terrainLoad(&t, path, err);
  csz_checkError(st, st == CS_OK, err, path, data, size, CSZ_TEXT);
  if (st == CS_OK) {
    checkTerrain(&t);
  }
  return st;
}

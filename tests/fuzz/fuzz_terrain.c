/* fuzz_terrain.c: fuzz harness of the terrain reader (terrains_terrain.h, cst_terrainLoad).
 *
 * Per input: load it and check the error contract (fuzz_common.h); a terrain the reader accepts
 * must hold what the header promises (1..32 boxes with lo < hi, finite coordinates within
 * +-1e6 mm, an oriented box's rotation orthonormal and its world bounds containing its corners,
 * a box's own friction in 0..10, a heightfield's grid and heights within their limits, a start
 * above the ground, a heading within +-360 deg, a slope within
 * +-45 deg, a unit gravity direction, a NUL-terminated non-empty name) and build its ODE geoms
 * (ODE's own asserts abort on a degenerate box). */
#include <math.h>
#include <string.h>

#include <ode/ode.h>

#include "fuzz_common.h"
#include "terrains_ccd.h"
#include "terrains_terrain.h"

#define MAX_COORD_MM 1e6
#define MAX_HEADING_DEG 360.0
#define MAX_SLOPE_DEG 45.0
#define MAX_MU 10.0


/* an oriented box: R orthonormal, every corner within the world bounds */
static void checkOriented(const cstBox* b, int i) {
  for (int r = 0; r < 3; r++) {
    for (int c = 0; c < 3; c++) {
      double dot = 0;
      for (int k = 0; k < 3; k++) dot += b->R[3 * k + r] * b->R[3 * k + c];
      if (!(fabs(dot - (r == c)) < 1e-12)) {
        csz_fail("accepted terrain: box %d rotation not orthonormal (%d.%d = %g)", i, r, c, dot);
      }
    }
  }
  for (int c = 0; c < 8; c++) {
    double y[3] = {c & 1 ? b->hi[0] : b->lo[0], c & 2 ? b->hi[1] : b->lo[1],
                   c & 4 ? b->hi[2] : b->lo[2]}, x[3];
    cst_boxPointToWorld(b, y, x);
    for (int k = 0; k < 3; k++) {
      double tol = 1e-9 * (1 + fabs(x[k]));
      if (!(x[k] >= b->wlo[k] - tol && x[k] <= b->whi[k] + tol)) {
        csz_fail("accepted terrain: box %d corner %d outside its world bounds", i, c);
      }
    }
  }
}


int csz_harnessInit(void) {
  if (!dInitODE2(0)) {
    return 1;
  }
  return csz_tempPath(0, ".terrain") ? 0 : 1;
}


static void checkHeightfield(const cstHeightfield* hf) {
  if (hf->nx < 2 || hf->nx > CST_HF_MAX || hf->nz < 2 || hf->nz > CST_HF_MAX ||
      !(hf->dx > 0) || !(hf->dz > 0) || !(hf->hmin <= hf->hmax) || !(hf->thickness > 0)) {
    csz_fail("accepted heightfield: %d x %d samples, spacing %g %g, heights %g..%g", hf->nx,
             hf->nz, hf->dx, hf->dz, hf->hmin, hf->hmax);
  }
  for (int i = 0; i < hf->nx * hf->nz; i++) {
    if (!(hf->h[i] >= hf->hmin && hf->h[i] <= hf->hmax && fabs(hf->h[i]) <= MAX_COORD_MM)) {
      csz_fail("accepted heightfield: sample %d height %g", i, hf->h[i]);
    }
  }
  if (hf->own_mu && !(hf->mu >= 0 && hf->mu <= MAX_MU)) {
    csz_fail("accepted heightfield: friction %g", hf->mu);
  }
}


static void checkTerrain(const cstTerrain* t) {
  if (t->has_hf) {
    checkHeightfield(&t->hf);
  }
  if (t->nbox < (t->has_hf ? 0 : 1) || t->nbox > CST_MAX_BOXES) {
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
    if (b->own_mu && !(b->mu >= 0 && b->mu <= MAX_MU)) {
      csz_fail("accepted terrain: box %d friction %g", i, b->mu);
    }
    if (b->oriented) {
      checkOriented(b, i);
    }
  }
  double g[3];
  cst_terrainGravityDir(t, g);
  if (!(fabs(t->slope_deg) <= MAX_SLOPE_DEG) ||
      !(fabs(g[0] * g[0] + g[1] * g[1] + g[2] * g[2] - 1) < 1e-12) || !(g[1] < 0)) {
    csz_fail("accepted terrain: slope %g deg, gravity (%g, %g, %g)", t->slope_deg, g[0], g[1],
             g[2]);
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
  int ngeom = t->nbox + t->has_hf;
  if (cst_terrainBuildOde(t, space) != ngeom || dSpaceGetNumGeoms(space) != ngeom) {
    csz_fail("accepted terrain: ODE geoms do not match the %d boxes and %d heightfield",
             t->nbox, t->has_hf);
  }
  cst_hfReleaseOde(space);
  dSpaceDestroy(space);
}


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  const char* path = csz_tempPath(0, ".terrain");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  static cstTerrain t; /* ~33 KB with its heightfield */
  csStatus st = cst_terrainLoad(&t, path, err);
  csz_checkError(st, st == CS_OK, err, path, data, size, CSZ_TEXT);
  if (st == CS_OK) {
    checkTerrain(&t);
  }
  return st;
}

/* terrains_terrain.h: terrains built from small description files (flat road, L-shaped step).
 *
 * Owns: cstTerrain (the model: solid axis-aligned boxes, the robot's start pose), the
 * description-file parser with line-numbered errors, and building the terrain's ODE geoms.
 *
 * File format (text, one statement per line, '#' starts a comment, units mm, world frame of
 * docs/reference.md: x = crawl direction, y = up, z = lateral):
 *   name  <word>                           terrain name, e.g. flat-road
 *   box   x0 y0 z0  x1 y1 z1               a solid box with opposite corners (x0<x1, ...)
 *   start x z                              start of the support's centre in the ground plane
 *   heading <deg>                          optional: crawl direction, degrees about +y (0 = +x,
 *                                          right-handed: 90 faces -z); the robot is built
 *                                          turned by it (core/sim_driver.c)
 * Ground height under the start is the top of the highest box containing (x, z). */
#ifndef CS_TERRAINS_TERRAIN_H
#define CS_TERRAINS_TERRAIN_H

#include <ode/ode.h>

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CST_MAX_BOXES 32

typedef struct cstBox_ {
  double lo[3], hi[3]; /* corners, mm */
} cstBox;

typedef struct cstTerrain_ {
  char name[64];
  int nbox;
  cstBox box[CST_MAX_BOXES];
  double start[2];     /* support centre start (x, z), mm */
  double heading_deg;  /* crawl direction about +y, degrees */
  char source[256];    /* file it was read from */
} cstTerrain;

/* Parse a terrain file. A file must have at least one box and a start inside a box; each of
 * name, start and heading may appear once; a name has at most 63 characters, a line at most
 * 1023 bytes (LF or CRLF; lines come from core_text.h's reader); numbers must be finite,
 * coordinates within +-1e6 mm and the heading within +-360 deg.
 * Errors: "<file>: cannot open terrain file: <reason>" (CS_ERR_IO), otherwise
 * "<file>:<line>: <cause>" with CS_ERR_PARSE (malformed, NUL bytes) or CS_ERR_RANGE (a value
 * out of range, non-finite, too many boxes, start off every box, a line too long); whole-file
 * checks (no box, no start) name the last line. On failure *t is left zeroed apart from what
 * was read. */
csStatus cst_terrainLoad(cstTerrain* t, const char* path, csError* err);

/* Height (y, mm) of the highest box top containing the ground point (x, z); -INFINITY if none. */
double cst_terrainHeightAt(const cstTerrain* t, double x, double z);

/* Create one static ODE box geom per terrain box in `space` (no bodies). Returns the number
 * of geoms created. The caller owns the space and destroys the geoms with it. */
int cst_terrainBuildOde(const cstTerrain* t, dSpaceID space);

#ifdef __cplusplus
}
#endif
#endif

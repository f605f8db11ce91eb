/* terrains_terrain.h: terrains built from small description files (flat road, L-shaped step).
 *
 * Owns: cstTerrain (the model: solid boxes, axis-aligned or oriented, each with its own
 * friction, the terrain's inclination, the robot's start pose), the description-file parser
 * with line-numbered errors, and building the terrain's ODE geoms.
 *
 * File format (text, one statement per line, '#' starts a comment, units mm, world frame of
 * docs/reference.md: x = crawl direction, y = up, z = lateral):
 *   name  <word>                           terrain name, e.g. flat-road
 *   box   x0 y0 z0  x1 y1 z1 [mu M]        a solid box with opposite corners (x0<x1, ...);
 *                                          `mu M`: its surface's Coulomb friction (-), for the
 *                                          support's ODE contacts and the legs' soft law alike;
 *                                          without it the run's (--friction)
 *   obox  cx cy cz  lx ly lz  ax ay az deg [mu M]
 *                                          an oriented box (an inclined plane, a ramp): centre,
 *                                          edge lengths along its own axes, turned by deg about
 *                                          the axis (ax, ay, az) (right-handed, need not be unit)
 *   slope <deg>                            optional: the whole terrain is inclined by deg about
 *                                          +z, +x uphill for deg > 0 (|deg| <= 45). The
 *                                          terrain's frame stays the simulation's frame and
 *                                          gravity turns instead: g = g (-sin deg, -cos deg, 0),
 *                                          exact for a rigid terrain (cst_terrainGravityDir), so
 *                                          x is the distance along the slope
 *   heightfield x0 z0 dx dz nx nz [mu M]   a heightfield (terrains_hfield.h): nx x nz samples
 *                                          (2..64 each) from (x0, z0), spaced dx along x and
 *                                          dz along z, followed by nz lines `row h_0 ... h_nx-1`
 *                                          (heights, mm, the first row at z0); solid down to
 *                                          20 mm below its lowest sample; at most one
 *   start x z                              start of the support's centre in the ground plane
 *   heading <deg>                          optional: crawl direction, degrees about +y (0 = +x,
 *                                          right-handed: 90 faces -z); the robot is built
 *                                          turned by it (core/sim_driver.c)
 * Ground height under the start is the top of the highest box containing (x, z) (the highest
 * point of an oriented box on the vertical through (x, z)). */
#ifndef CS_TERRAINS_TERRAIN_H
#define CS_TERRAINS_TERRAIN_H

#include <ode/ode.h>

#include "core_status.h"
#include "terrains_hfield.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CST_MAX_BOXES 32

/* A solid box. Axis-aligned (oriented = 0): lo, hi are its corners in the world. Oriented:
 * lo = -hi are its corners in its own frame, centred at c and turned by R; a world point x
 * is y = R^T (x - c) in that frame. wlo, whi bound it in the world (the broad phase). A
 * zeroed box with lo, hi set is a valid axis-aligned box with the run's friction. */
typedef struct cstBox_ {
  double lo[3], hi[3];   /* mm: corners (world, or the box's frame when oriented) */
  int own_mu;            /* 1: mu applies; 0 (a zeroed box): the run's friction */
  double mu;             /* -: its surface's friction when own_mu */
  int oriented;          /* 0: axis-aligned; 1: c and R apply */
  double c[3];           /* mm: centre (oriented) */
  double R[9];           /* row-major rotation, its columns the box axes in the world */
  double wlo[3], whi[3]; /* mm: world bounding box (lo, hi when axis-aligned) */
} cstBox;

typedef struct cstTerrain_ {
  char name[64];
  int nbox;
  cstBox box[CST_MAX_BOXES];
  double start[2];     /* support centre start (x, z), mm */
  double heading_deg;  /* crawl direction about +y, degrees */
  double slope_deg;    /* inclination about +z, degrees (+x uphill) */
  int has_mu;          /* some box or the heightfield has its own friction */
  int has_hf;          /* 1: hf is part of the terrain */
  cstHeightfield hf;   /* the heightfield (has_hf) */
  char source[256];    /* file it was read from */
} cstTerrain;

/* Parse a terrain file. A file must have at least one box or a heightfield and a start above
 * one; each of
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

/* Unit direction of gravity in the terrain's frame: (-sin a, -cos a, 0) for slope a. */
void cst_terrainGravityDir(const cstTerrain* t, double g[3]);

/* Friction of box i: its own, or mu_default when it has none. */
double cst_terrainBoxMu(const cstTerrain* t, int i, double mu_default);

/* Fill an oriented box from centre c (mm), edge lengths len (mm, > 0) and a rotation of deg
 * about axis (need not be unit; a zero axis is refused: returns 0, else 1). mu < 0: none. */
int cst_boxOriented(cstBox* b, const double c[3], const double len[3], const double axis[3],
                    double deg, double mu);

/* Create one static ODE box geom per terrain box in `space` (no bodies), and the heightfield's
 * (cst_hfBuildOde); the geom's data of a surface with its own friction points at its mu
 * (const double*, read by contact_ode.c; NULL: the run's). Returns the number of geoms
 * created. The caller owns the space, calls cst_hfReleaseOde(space) and destroys the geoms
 * with it; the terrain must outlive them. */
int cst_terrainBuildOde(const cstTerrain* t, dSpaceID space);

#ifdef __cplusplus
}
#endif
#endif

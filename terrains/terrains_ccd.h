/* terrains_ccd.h: the terrain's boxes as contact shapes: libccd support functions, the exact
 * point-box distance, and the query "which boxes are near here".
 *
 * Owns: cst_ccdBoxSupport / cst_ccdBoxCenter (libccd's ccd_support_fn / ccd_center_fn for a
 * cstBox, so ccdMPRPenetration and ccdGJK* can collide any convex leg shape against the
 * terrain), cst_boxSignedDistance (closed form, used by the soft contact law where it is exact
 * and cheaper than an iterative query), and cst_terrainBoxesNear (the broad phase).
 *
 * Frames and units: world frame of docs/reference.md (x crawl direction, y up, z lateral), mm. An
 * axis-aligned cstBox's support point is a corner chosen by the signs of the direction; an
 * oriented box's is the same in its own frame (the direction turned by R^T), turned back, and
 * its distances are computed in its frame (exact: distance is invariant under the rigid
 * motion).
 *
 * Cost of the broad phase: a linear scan, 6 comparisons per box; a terrain holds at most
 * CST_MAX_BOXES = 32 boxes, so a query is at most 192 comparisons (~0.1 us). A spatial tree
 * would pay off only for hundreds of boxes. */
#ifndef CS_TERRAINS_CCD_H
#define CS_TERRAINS_CCD_H

#include <ccd/ccd.h>

#include "terrains_terrain.h"

#ifdef __cplusplus
extern "C" {
#endif

_Static_assert(sizeof(ccd_real_t) == sizeof(double), "crawlsim needs libccd built with CCD_DOUBLE");

/* An oriented box's frame (terrains_terrain.h): a world point x to the box frame, y = R^T (x -
 * c); a direction or a point of the box frame back to the world. */
void cst_boxToLocal(const cstBox* b, const double x[3], double y[3]);
void cst_boxDirToWorld(const cstBox* b, const double y[3], double x[3]);
void cst_boxPointToWorld(const cstBox* b, const double y[3], double x[3]);

/* libccd support function of a cstBox (obj is a const cstBox*): the corner furthest along dir
 * (any length, need not be unit). Components of dir that are exactly 0 pick the upper face,
 * which is a valid support point (every point of that face is). */
void cst_ccdBoxSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out);

/* libccd centre function of a cstBox: its centre (an interior point, as MPR needs). */
void cst_ccdBoxCenter(const void* obj, ccd_vec3_t* out);

/* Signed distance (mm) of point x (mm) to box b: > 0 outside (Euclidean distance to the box),
 * < 0 inside (minus the distance to the nearest face), 0 on the surface. cp (may be NULL)
 * receives the closest point of the box surface; n (may be NULL) the outward unit normal at cp,
 * i.e. the direction in which x leaves the box fastest (outside: (x - cp)/|x - cp|; inside: the
 * nearest face's normal; on an edge or corner from inside, the face of lowest index among the
 * tied ones: x-, x+, y-, y+, z-, z+). Exact; continuous everywhere; its gradient n is
 * continuous outside the box and jumps across the inner medial planes. */
double cst_boxSignedDistance(const cstBox* b, const double x[3], double cp[3], double n[3]);

/* The broad phase: indices of the terrain boxes whose extent, grown by margin (mm, >= 0),
 * overlaps the query box [lo, hi] (mm, lo <= hi componentwise; a point is lo = hi). Writes at
 * most max_idx indices to idx (ascending) and returns how many boxes overlap (which may exceed
 * max_idx: the caller sees it and can refuse). Linear in the number of boxes (header). */
int cst_terrainBoxesNear(const cstTerrain* t, const double lo[3], const double hi[3],
                         double margin, int* idx, int max_idx);

#ifdef __cplusplus
}
#endif
#endif

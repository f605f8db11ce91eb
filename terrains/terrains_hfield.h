/* terrains_hfield.h: a heightfield terrain: the surface through a grid of heights, split into
 * two triangles per cell along the same diagonal as ODE's dHeightfield, so the support (ODE)
 * and the legs' soft law (contact/) touch the same surface.
 *
 * Owns: cstHeightfield (the model: grid, heights, friction, its solid depth) and its exact
 * geometry: the surface height under a point, the signed distance of a point to the surface
 * (closest point over the triangles within reach, Ericson, Real-Time Collision Detection,
 * 5.1.5), and building its ODE geom.
 *
 * Grid: sample (i, j), i = 0..nx-1 along x, j = 0..nz-1 along z, at (x0 + i dx, h[j nx + i],
 * z0 + j dz), mm. Cell (i, j) spans samples A = (i, j), B = (i+1, j), C = (i, j+1),
 * D = (i+1, j+1) and is split along B-C into triangles ABC and DBC (ODE's heightfield.cpp,
 * "A--B / C--D" with the diagonal B-C). The solid lies below the surface down to hmin -
 * thickness; outside the grid's x-z footprint there is no terrain.
 * Frames and units: world frame of docs/reference.md (y up), mm. */
#ifndef CS_TERRAINS_HFIELD_H
#define CS_TERRAINS_HFIELD_H

#include <ode/ode.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CST_HF_MAX 64 /* samples per side */

typedef struct cstHeightfield_ {
  int nx, nz;                        /* samples along x and z, 2..CST_HF_MAX */
  double x0, z0, dx, dz;             /* mm: first sample, spacing (> 0) */
  double h[CST_HF_MAX * CST_HF_MAX]; /* mm: height of sample (i, j) at h[j nx + i] */
  double hmin, hmax;                 /* mm: lowest and highest sample */
  double thickness;                  /* mm: the solid reaches hmin - thickness */
  int own_mu;                        /* 1: mu applies; 0: the run's friction */
  double mu;                         /* -: its surface's friction when own_mu */
} cstHeightfield;

/* Surface height (mm) at (x, z) on its triangle; -INFINITY outside the footprint. */
double cst_hfHeightAt(const cstHeightfield* hf, double x, double z);

/* Signed distance (mm) of point p to the surface, looking at the triangles of the cells whose
 * x-z extent comes within `reach` (mm) of p: > 0 above the surface (distance to the nearest
 * triangle), < 0 below it (minus that distance); cp the closest surface point, n the unit
 * normal from the surface towards p (above), or the reverse of that direction (below: the way
 * out). Returns +INFINITY (cp, n untouched) when no triangle is within reach or p is below
 * the solid. Exact; continuous above the surface. */
double cst_hfSignedDistance(const cstHeightfield* hf, const double p[3], double reach,
                            double cp[3], double n[3]);

/* The ODE geom: a placeable dHeightfield in `space` whose data references hf->h (hf must
 * outlive it); its data pointer is hf->mu when own_mu (as cst_terrainBuildOde's boxes).
 * cst_hfReleaseOde destroys the heightfield data of every heightfield geom in `space` (call
 * it before destroying the space). */
dGeomID cst_hfBuildOde(const cstHeightfield* hf, dSpaceID space);
void cst_hfReleaseOde(dSpaceID space);

#ifdef __cplusplus
}
#endif
#endif

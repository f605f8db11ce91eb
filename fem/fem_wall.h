/* fem_wall.h: the state of the actuator's free surfaces (post-processing layer): the in-surface
 * principal stretches of a set of boundary faces, against the crease onset of compressed
 * rubber, and the smallest gap between opposite walls of a chamber, against self-contact.
 *
 * Why: the mesh has no self-contact and cannot represent a crease (a self-contacting fold of a
 * compressed free surface). A sweep that ends where a vented chamber's wall is compressed past
 * the crease onset, or where its opposite walls meet, ends at a physical limit of such a model,
 * not at a limit of its mesh (fem/README.md, "Creases in the vented chambers' walls").
 *
 * Crease onset: an incompressible neo-Hookean half-space compressed in plane strain creases at
 * a compressive stretch of 0.65 (strain 0.35; Hong, Zhao & Suo 2009, Appl. Phys. Lett. 95,
 * 111904), before Biot's wrinkling at 0.54. A general in-surface state (stretches lam_c <= lam_t,
 * normal stretch 1/(lam_c lam_t)) maps onto that plane-strain problem: with lam_t held, the
 * neo-Hookean energy of the (c, normal) plane is that of plane strain scaled by sqrt(lam_t), so
 * the state creases when lam_c sqrt(lam_t) reaches 0.65 (the ratio lam_c / lam_normal = 0.42 of
 * the plane-strain state). csfWallStretch.lam_eq is that plane-strain-equivalent stretch. The
 * Yeoh silicone (C20 > 0) stiffens in compression and delays creasing somewhat; the threshold
 * is the neo-Hookean one.
 *
 * Units: mm; stretches dimensionless. Faces are the mesh's boundary Tri6 (fem_mesh.h). */
#ifndef CS_FEM_WALL_H
#define CS_FEM_WALL_H

#include "core_status.h"
#include "fem_mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* plane-strain crease onset of a neo-Hookean half-space, compressive stretch (-): Hong, Zhao &
 * Suo 2009 (strain 0.35) */
#define CSF_CREASE_STRETCH 0.65

/* csf_wallGap's opposite walls: reference normals at least 120 deg apart (cosine -0.5), so a
 * circular chamber's wall points count from a third of a turn apart */
#define CSF_WALL_COS_OPPOSITE (-0.5)

/* Smallest in-surface stretches of a face set (csf_wallStretch). */
typedef struct csfWallStretch_ {
  int npoint;       /* points sampled (6 per face: the degree-4 triangle rule's points) */
  double lam_eq;    /* smallest plane-strain-equivalent stretch lam_c sqrt(lam_t) (-); INFINITY
                     * with no face */
  double lam_c, lam_t; /* the principal in-surface stretches at that point, lam_c <= lam_t */
  double X[3];      /* its reference position, mm */
  double dir[3];    /* reference direction of lam_c there (unit) */
  int face, tag, tet; /* its face, the face's tag and the tetrahedron owning it (-1: none) */
  double lam_min;   /* smallest lam_c over all points (may sit elsewhere) */
} csfWallStretch;

/* Principal in-surface stretches of every face whose tag is in tags[0..ntag) at the six points
 * of each face: the surface deformation gradient of the Tri6 map (reference mesh x, displacement
 * u, (nnode x 3) mm) gives the metric ratio G^-1 g of the deformed to the reference tangents,
 * whose eigenvalues are the squared principal stretches. Exact for a homogeneous deformation.
 * Fills w. */
void csf_wallStretch(const csfMesh* me, const double* u, int ntag, const int* tags,
                     csfWallStretch* w);

/* Smallest gap between opposite walls of one cavity (csf_wallGap). */
typedef struct csfWallGap_ {
  double gap;      /* smallest deformed distance from a wall node to a wall triangle facing it
                    * (csf_wallGap), mm; INFINITY with no such pair */
  double gap_ref;  /* the same pair's reference distance, mm */
  double X[3];     /* reference position of that node, mm */
  int node;        /* that node (-1: none) */
} csfWallGap;

/* Gap of the cavity bounded by the faces with tags in tags[0..ntag) (one chamber: its tag; two
 * opposite faces of a box: their two tags): over every face node and every face (split into its
 * four straight sub-triangles), the smallest deformed node-triangle distance among the pairs
 * that face each other in the reference state: the cosine between the node's normal (area-
 * weighted over its sub-triangles) and the triangle's is at most `cos_opp` (-0.5: around a
 * circular chamber, wall points at least 120 deg apart; points along the same side of a wall
 * never count, however far apart). When a chamber flattens, this gap closes to zero where its
 * walls meet. The straight sub-triangles of a curved face lie inside it by their sagitta: for a
 * 2 mm chamber with corners every 2 pi / 12 about 0.07 mm (4 % of the radius).
 * Returns CS_OK, or CS_ERR_MEMORY. */
csStatus csf_wallGap(const csfMesh* me, const double* u, int ntag, const int* tags,
                     double cos_opp, csfWallGap* g, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_WALL_H */

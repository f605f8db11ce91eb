/* fem_mesh.h: quadratic tetrahedral meshes for the full FE model (issue 3).
 *
 * Owns: csfMesh (Tet10 volume elements, boundary Tri6 faces with physical tags), a structured
 * mesher for tests (a box, optionally mapped by a callback: tubes, curved blocks), the reader of
 * gmsh MSH 2.2 ASCII files (fem_mesh.c), and the actuator geometry (fem_mesh_actuator.c):
 * csrActuator -> gmsh .geo -> `gmsh` program -> .msh -> csfMesh, whole or as an eighth mirrored
 * and turned into a mesh with the section's symmetry. gmsh is GPL: it is run as a separate
 * program and only its output file is read, so no gmsh code enters our binaries
 * (notes/debian-deps.md, section 5).
 *
 * Units: mm. Frame of the actuator mesh: x = e1, y = e2 (cross-section), z = e3 from the clamped
 * base (z = 0) to the tip (z = L).
 * Node order (VTK): Tet10 = 4 vertices, then edge nodes (0,1) (1,2) (0,2) (0,3) (1,3) (2,3);
 * Tri6 = 3 vertices, then edge nodes (0,1) (1,2) (2,0). Boundary faces are oriented so that
 * (x1 - x0) x (x2 - x0) points out of the body (into a chamber for chamber walls). */
#ifndef CS_FEM_MESH_H
#define CS_FEM_MESH_H

#include "core_status.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* physical tags of the actuator mesh */
#define CSF_TAG_BASE 1 /* clamped base face z = 0 */
#define CSF_TAG_TIP 2  /* free tip face z = L */
/* chamber j (1..4) of segment s (0..2) */
#define CSF_TAG_CHAMBER(s, j) (100 + 10 * ((s) + 1) + (j))

typedef struct csfMesh_ {
  int nnode, ntet, nface;
  double* x;     /* (nnode x 3) reference coordinates, mm */
  int* tet;      /* (ntet x 10) node indices, VTK order */
  int* face;     /* (nface x 6) boundary Tri6 node indices, outward orientation */
  int* face_tet; /* (nface) tetrahedron that owns the face */
  int* face_tag; /* (nface) physical tag, 0 = untagged */
} csfMesh;

/* Map of the unit cube [0,1]^3 to physical space (mm); used by csf_meshCreateBox. */
typedef void (*csfMapFn)(void* user, const double xi[3], double x[3]);

/* Structured Tet10 mesh of [0,1]^3 with n[0] x n[1] x n[2] cubes, each split into 6 tetrahedra
 * (Kuhn split, conforming), mapped by `map` (NULL: identity). Every node, edge nodes included, is
 * placed by the map, so curved maps give curved (isoparametric) elements. Boundary faces are
 * tagged 1..6 for xi0 = 0, xi0 = 1, xi1 = 0, xi1 = 1, xi2 = 0, xi2 = 1. `jitter` (0..0.2) moves
 * interior vertex nodes by a deterministic pseudo-random fraction of the cell size (patch tests).
 * Returns NULL and fills err on failure. */
csfMesh* csf_meshCreateBox(const int n[3], csfMapFn map, void* user, double jitter,
                           csError* err);

/* Read a gmsh MSH 2.2 ASCII file with second-order elements (Tet10 type 11, Tri6 type 9). Tri6
 * elements carry their physical tag; tetrahedra of every physical volume are kept. gmsh's edge-node
 * order is converted to VTK's. */
csfMesh* csf_meshReadMsh(const char* path, csError* err);

/* Minimum number of element edges around a chamber circle (mesh size at chamber walls is
 * min(l_soft, 2 pi r1 / CSF_CHAMBER_SEGMENTS)). */
#define CSF_CHAMBER_SEGMENTS 6

/* Write the actuator's gmsh .geo script (OpenCASCADE kernel): five extruded rounded-square blocks
 * (S1, LS12, S2, LS23, S3) fused conformally, 12 chambers cut (radius r1, length S - 2c),
 * physical surfaces CSF_TAG_* and one physical volume. `l_soft` is the mesh size (mm). */
csStatus csf_meshWriteGeo(const csrActuator* act, double l_soft, const char* path, csError* err);

/* The eighth 0 <= y <= x of the same body (half of chamber Omega1 of each segment). Physical
 * tags as above (Omega1's only). */
csStatus csf_meshWriteGeoEighth(const csrActuator* act, double l_soft, const char* path,
                                csError* err);

/* The mesh made of e and its mirror image in the plane x = y (nodes on the plane shared, the
 * image's elements reoriented, tagged faces mirrored with their tags). For the eighth
 * 0 <= y <= x it is the quarter x, y >= 0 whose cut faces csf_meshTurnCopies needs. */
csfMesh* csf_meshMirrorDiagonal(const csfMesh* e, csError* err);

/* The physical tag a face of the quarter carries in its copy turned by k (0..3) quarter turns. */
typedef int (*csfTagTurnFn)(void* user, int tag, int k);

/* The mesh made of a quarter mesh q (x >= 0, y >= 0, its x = 0 face the y = 0 face turned by
 * 90 deg, node for node, as csf_meshMirrorDiagonal makes it) and its copies turned by 90, 180
 * and 270 deg about e3, nodes on the cut faces and the axis merged; every quarter turn maps it
 * onto itself. Boundary faces are recomputed, each tagged face of q gives four tagged faces
 * (tags through `turn`; NULL keeps them). Returns NULL and fills err when q's cut faces do not
 * match node for node. */
csfMesh* csf_meshTurnCopies(const csfMesh* q, csfTagTurnFn turn, void* user, csError* err);

/* Mesh the actuator with the symmetry of its square section (the eight rotations and mirrors
 * that map the section onto itself): the eighth (`<stem>.geo`, gmsh), mirrored into the quarter
 * (csf_meshMirrorDiagonal), turned into four copies (csf_meshTurnCopies; chamber tags turned: a
 * quarter turn takes Omega_j's place to Omega_(j-1)'s). */
csfMesh* csf_meshActuatorSymmetric(const csrActuator* act, double l_soft, const char* stem,
                                   csError* err);

/* Recompute m's boundary faces from its tetrahedra and tag those whose vertices are one of the
 * ntag triangles tri (ntag x 3 node ids, any order) with tag[i]; the others get 0. */
csStatus csf_meshFacesTagged(csfMesh* m, int ntag, const int* tri, const int* tag, csError* err);

/* Mesh the actuator: write `<stem>.geo`, run `gmsh -3 -order 2 -format msh22`, read `<stem>.msh`.
 * `stem` is a path prefix (its directory must exist). The gmsh program is taken from the
 * environment variable CS_GMSH if set, else "gmsh" on PATH. */
csfMesh* csf_meshActuator(const csrActuator* act, double l_soft, const char* stem,
                          csError* err);

/* Run gmsh (`-3 -order 2 -format msh22`) on the script `geo`, writing `<stem>.msh` and
 * `<stem>.gmsh.log`, read the mesh and straighten folded elements (csf_meshFixInverted). The
 * program is taken from CS_GMSH as for csf_meshActuator. Returns NULL and fills err on failure. */
csfMesh* csf_meshGmsh(const char* geo, const char* stem, csError* err);

/* Straighten curved Tet10 elements whose isoparametric map is not valid (Jacobian <= 0 or below
 * 5 % of the straight element's at a vertex, edge node or quadrature point): their edge nodes move
 * to the chord midpoints. gmsh places edge nodes on the curved geometry, and coarse elements on
 * small-radius chambers (r1 = 2 mm at l_soft >= 3) then fold. Returns the number of elements
 * straightened (edge nodes are shared, so neighbours become slightly straighter too). */
int csf_meshFixInverted(csfMesh* m);

/* Free a mesh; NULL-safe. */
void csf_meshDestroy(csfMesh* m);

/* Tet10 shape functions N (10) at barycentric-like coordinates xi = (L1, L2, L3), L0 = 1 - sum;
 * dN (10 x 3) derivatives with respect to xi (either may be NULL). */
void csf_tet10Shape(const double xi[3], double N[10], double dN[30]);

/* Tri6 shape functions N (6) at (s, t) (L0 = 1 - s - t, L1 = s, L2 = t; VTK node order) and
 * their derivatives dN (6 x 2) with respect to (s, t) (either may be NULL). */
void csf_tri6Shape(double s, double t, double N[6], double dN[12]);

/* Signed volume of tetrahedron t (mm^3), from its Tet10 geometry (4-point rule). */
double csf_meshTetVolume(const csfMesh* m, int t);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_MESH_H */

/* contact_geom.h: narrow phase of the soft leg-terrain contact: how deep a leg shape (sphere,
 * capsule, the foot's box) sits in one terrain box, along which normal, at which point.
 *
 * Owns: cscPenetration (the answer), the closed forms for spheres and capsules against
 * axis-aligned boxes (csc_sphereBoxPenetration, csc_capsuleBoxPenetration, and cscSegBox, the
 * exact squared distance of a segment to a box as a piecewise quadratic, which the capsule's
 * line load integrates), and the general query through libccd (cscCcdShape with its support
 * functions, csc_ccdPenetration) for any convex shape, e.g. the foot's box.
 *
 * Which libccd algorithm, and why closed forms where they exist:
 * - ccdMPRPenetration (Minkowski portal refinement), not ccdGJKPenetration (GJK + EPA): EPA
 *   builds its polytope on the heap (it returns -2 when malloc fails), and the soft law runs
 *   inside a right-hand side that must not allocate; MPR works on a 4-point simplex on the
 *   stack. MPR's depth is the distance of the origin to the final portal along the ray from an
 *   interior point, which equals the minimal penetration for the shallow face contacts of feet
 *   on a road; near edges it may pick another face (measured in tests/contact/test_contact_geom).
 * - MPR is iterative: its depth carries an error up to its tolerance and jumps when the number
 *   of refinement iterations changes, which an error-controlled BDF integrator sees as noise in
 *   the right-hand side. The closed forms below are exact, smooth (C1 outside the box), and
 *   several times cheaper (ratio printed by the test), so the force law (contact_soft.h) uses
 *   them for the terrain's axis-aligned boxes; libccd stays the general path for shapes without
 *   a closed form and the reference the closed forms are tested against.
 *
 * Conventions: mm; normal is a unit vector pointing from the terrain box towards the shape, so
 * translating the shape by depth * normal makes them touch (libccd's convention with obj1 = the
 * box, obj2 = the shape); depth > 0 is overlap, depth <= 0 a gap of -depth (closed forms only:
 * libccd reports nothing for separated shapes); pos is the point midway between the shape's
 * deepest point and the box surface along the normal (as libccd's MPR reports it). */
#ifndef CS_CONTACT_GEOM_H
#define CS_CONTACT_GEOM_H

#include <ccd/ccd.h>

#include "terrains_ccd.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Penetration of one shape in one box. */
typedef struct cscPenetration_ {
  double depth;     /* mm: > 0 overlap, <= 0 minus the gap */
  double normal[3]; /* unit, from the box towards the shape */
  double pos[3];    /* mm: contact point, midway between the surfaces */
} cscPenetration;

/* Sphere (centre c, radius r, mm) against box b, exact. Returns the depth (out may be NULL).
 * With the centre inside the box the normal is the nearest face's (cst_boxSignedDistance). */
double csc_sphereBoxPenetration(const double c[3], double r, const cstBox* b,
                                cscPenetration* out);

/* Squared distance q(s) = dist(x(s), b)^2 of the segment x(s) = p0 + s (p1 - p0), s in [0, 1],
 * to a box: convex, C1 and piecewise quadratic in s, with breakpoints where a coordinate of
 * x(s) crosses a face plane (at most 6). Built exactly by csc_segBoxInit. */
typedef struct cscSegBox_ {
  int npiece;            /* pieces, 1..7 */
  double brk[8];         /* 0 = brk[0] < ... < brk[npiece] = 1 */
  double A[7], B[7], C[7]; /* q(s) = A s^2 + B s + C on [brk[j], brk[j+1]] (mm^2) */
  double q_min;          /* minimum of q over [0, 1] (mm^2) */
  double s_min;          /* middle of the set where q = q_min (unique unless q is flat there) */
} cscSegBox;

/* Build q for segment p0 -> p1 (mm) and box b. */
void csc_segBoxInit(cscSegBox* q, const double p0[3], const double p1[3], const cstBox* b);

/* q(s) (mm^2) for s in [0, 1]. */
double csc_segBoxEval(const cscSegBox* q, double s);

/* The level set {s in [0, 1] : q(s) <= level} (mm^2): an interval [*sa, *sb] because q is
 * convex; returns 0 (empty: level < q_min) or 1. Roots come from each piece's quadratic, so
 * they are exact to round-off. */
int csc_segBoxInterval(const cscSegBox* q, double level, double* sa, double* sb);

/* Capsule (axis p0 -> p1, radius r, mm) against box b, exact: separated or touching
 * (axis outside the box) from the segment-box distance; with the axis inside the box from the
 * separating-axis test over the box's face normals and the axis-cross-edge directions.
 * Returns the depth; s (may be NULL) receives the axis parameter of the deepest axis point
 * (the middle of the closest stretch when the axis lies parallel to a face). */
double csc_capsuleBoxPenetration(const double p0[3], const double p1[3], double r,
                                 const cstBox* b, cscPenetration* out, double* s);

/* A convex leg shape for libccd. */
typedef enum cscCcdKind_ {
  CSC_CCD_SPHERE = 0, /* c, r */
  CSC_CCD_CAPSULE,    /* p0, p1, r */
  CSC_CCD_BOX         /* c, R, h: e.g. the foot's end block */
} cscCcdKind;

typedef struct cscCcdShape_ {
  cscCcdKind kind;
  double c[3];         /* mm: sphere or box centre */
  double p0[3], p1[3]; /* mm: capsule axis */
  double r;            /* mm: sphere or capsule radius */
  double R[9];         /* box orientation, row-major; its columns are the box axes (world) */
  double h[3];         /* mm: box half extents along its axes */
} cscCcdShape;

/* libccd support and centre functions of a cscCcdShape (obj is a const cscCcdShape*). */
void csc_ccdShapeSupport(const void* obj, const ccd_vec3_t* dir, ccd_vec3_t* out);
void csc_ccdShapeCenter(const void* obj, ccd_vec3_t* out);

/* libccd settings for MPR on mm-sized shapes: tolerance 1e-9 mm (the default 1e-4 mm would be
 * 3 % of a foot's 3.6 um sink-in), at most 200 refinement iterations. */
void csc_ccdInit(ccd_t* ccd);

/* Penetration of shape s in box b through libccd's MPR (ccd from csc_ccdInit, or NULL for
 * it). Returns 1 and fills out when they overlap, 0 when libccd finds them separated (out
 * untouched). A touching contact has depth 0 and libccd's zero normal. */
int csc_ccdPenetration(const cscCcdShape* s, const cstBox* b, const ccd_t* ccd,
                       cscPenetration* out);

#ifdef __cplusplus
}
#endif
#endif

/* fem_measure.h: what the FE sweeps measure on a deformed actuator (post-processing layer).
 *
 * Owns: csfGauges, the node sets an actuator's measurements read (the node planes of the
 * segments' end faces and the base/tip faces, the outer lateral surface nodes of each segment's
 * chambered part), built once per mesh; the rigid frame fitted to a node plane; the bend angle
 * about an axis (swing-twist, smooth through full turns); and per segment the full kinematics a
 * rod calibration needs: bend vector, twist, axial stretch of the centreline, radial growth of
 * the cross-section.
 * Frames: the actuator's base frame (e1, e2, e3), e3 along the undeformed axis from the clamped
 * base (z = 0); a segment's bend vector is given in the frame of its own base face, as the leg
 * models' csrBendMap does (robot_leg.h). Units: mm, rad unless a name says deg. */
#ifndef CS_FEM_MEASURE_H
#define CS_FEM_MEASURE_H

#include "core_status.h"
#include "fem_model.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Node sets of one actuator mesh (see the header comment). Caller-owned via create/destroy. */
typedef struct csfGauges_ {
  int nplane;        /* 2 CSR_NSEG: faces z = start(s) and start(s) + S_s of every segment */
  int* plane_ptr;    /* (nplane + 1) */
  int* plane_node;   /* nodes of each plane */
  int base_plane, tip_plane; /* planes of z = 0 and z = L: -1 if not a segment face (joints) */
  int* base_node, nbase;     /* nodes of z = 0 (the clamped face) */
  int* tip_node, ntip;       /* nodes of z = L (the tip face) */
  int* outer_ptr;    /* (CSR_NSEG + 1) */
  int* outer_node;   /* outer lateral surface nodes of each segment's chambered part */
  double* plane_c0;  /* (nplane x 3) reference centroid of each plane's nodes, mm: the
                      * reference axis of a segment's radial measure (an unstructured face's
                      * node centroid is off the geometric axis by up to ~0.06 mm) */
  double* scratch;   /* (6 max plane size) scratch for frame fits */
} csfGauges;

csfGauges* csf_gaugesCreate(const csrActuator* act, const csfMesh* mesh, csError* err);
void csf_gaugesDestroy(csfGauges* g);

/* Per-segment kinematics at the current state. */
typedef struct csfSegmentState_ {
  double bend[2];    /* bend vector (rad) in the segment's base-face frame: the end tangent turns
                      * by |bend| towards bend[0] e1 + bend[1] e2 (csrBendMap convention) */
  double twist;      /* rotation about the axis over the segment, rad */
  double stretch;    /* centreline arc length over S (-): chord between the end-face centroids
                      * and the bend angle of a constant-curvature arc */
  double radial;     /* mean over the outer surface nodes of (distance from the centreline /
                      * reference distance from the axis) - 1 (-) */
  double radial_max; /* largest outward displacement of the outer surface from the centreline,
                      * mm (what a contact capsule's radius must add) */
  double ca[3], cb[3];   /* end-face centroids, base frame, mm */
  double Ra[9], Rb[9];   /* end-face frames (row-major, columns e1 e2 e3 deformed) */
} csfSegmentState;

/* Kinematics of every segment and the tip (centroid, mm; frame) at the current d->u. Returns 0,
 * or -1 if a face frame is degenerate. */
int csf_segmentMeasure(const csrActuator* act, const csfGauges* g, const csfModel* m,
                       const csfData* d, csfSegmentState seg[CSR_NSEG], double tip[3],
                       double Rtip[9]);

/* Angles of the actuator at the current state d->u: per segment and total (deg), and the tip
 * centroid (mm). Each angle is the rotation between two fitted face frames about the reference
 * bending axis `axis` (unit, base frame; csf_bendAxisAngle) and unwrapped against `prev`
 * (previous values: 3 segments then total; may be NULL), so bends beyond 180 and 360 deg are
 * followed continuously. */
void csf_bendMeasure(const csrActuator* act, const csfGauges* g, const csfModel* m,
                     const csfData* d, const double axis[3], const double prev[4],
                     double angle_deg[3], double* total_deg, double tip[3]);

/* Angle (rad) of the relative rotation Ra^T Rb (row-major frames) about the unit `axis`: the
 * twist of its swing-twist decomposition, smooth through full turns, unwrapped to within pi of
 * `prev` (rad). axis NULL: the full rotation angle. */
double csf_bendAxisAngle(const double Ra[9], const double Rb[9], const double axis[3],
                         double prev);

/* Rigid rotation R (row-major 3x3) best fitting the deformed positions of the nodes of a plane
 * z = const (reference X, deformed x, n nodes): least-squares fit of the in-plane directions,
 * polar-orthonormalised; R e3 is the deformed face normal. Returns 0, or -1 if degenerate. */
int csf_fitPlaneFrame(int n, const double* X, const double* x, double R[9], double centroid[3]);

/* Rotation vector (axis x angle, rad, |w| <= pi) of the rotation matrix R (row-major). */
void csf_rotationVector(const double R[9], double w[3]);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_MEASURE_H */

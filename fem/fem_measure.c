/* fem_measure.c: measurements on the deformed actuator (fem_measure.h).
 *
 * Angles: each end face of a segment is a plane of mesh nodes (the geometry is split there); a
 * rigid frame is fitted to each face (least squares on the in-plane directions, polar
 * orthonormalisation), and a segment's angle is the rotation between its two face frames,
 * taken about the bending axis (swing-twist: smooth through full turns) and unwrapped, so
 * angles past 180 and 360 deg are followed. The total angle is measured the same way between
 * the base and the tip faces (it includes the small rotation of the solid joints; the sum of
 * segment angles is the paper's Theta = sum theta_i).
 * Segment kinematics for the rod calibration: the relative rotation of the two face frames as a
 * rotation vector in the base face's frame (bend vector and twist), the centreline length of the
 * constant-curvature arc through both face centroids, and the radial growth of the outer surface
 * measured from that arc: a node at reference height zeta in the segment is compared with the
 * arc point at zeta (uniform stretch) in the arc's local frame. */
#include "fem_measure.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "core_math.h"

#define CSF_PLANE_TOL 1e-6 /* mm: nodes on a face plane */

int csf_fitPlaneFrame(int n, const double* X, const double* x, double R[9], double centroid[3]) {
  if (n < 3) {
    return -1;
  }
  double Xc[3] = {0, 0, 0}, xc[3] = {0, 0, 0};
  for (int i = 0; i < n; i++) {
    for (int d = 0; d < 3; d++) {
      Xc[d] += X[3 * i + d] / n;
      xc[d] += x[3 * i + d] / n;
    }
  }
  /* C2 = sum dX dX^T (in-plane 2x2), H2 = sum dx dX^T (3x2) */
  double C[4] = {0}, H[6] = {0};
  for (int i = 0; i < n; i++) {
    double dX[2] = {X[3 * i] - Xc[0], X[3 * i + 1] - Xc[1]};
    for (int a = 0; a < 2; a++) {
      for (int b = 0; b < 2; b++) {
        C[2 * a + b] += dX[a] * dX[b];
      }
      for (int d = 0; d < 3; d++) {
        H[2 * d + a] += (x[3 * i + d] - xc[d]) * dX[a];
      }
    }
  }
  double det = C[0] * C[3] - C[1] * C[2];
  if (!(det > 0)) {
    return -1;
  }
  const double Ci[4] = {C[3] / det, -C[1] / det, -C[2] / det, C[0] / det};
  double B[6]; /* B = H2 C2^-1 */
  for (int d = 0; d < 3; d++) {
    B[2 * d] = H[2 * d] * Ci[0] + H[2 * d + 1] * Ci[2];
    B[2 * d + 1] = H[2 * d] * Ci[1] + H[2 * d + 1] * Ci[3];
  }
  /* polar: Q = B (B^T B)^-1/2, with sqrt(S) = (S + sqrt(det S) I) / sqrt(tr S + 2 sqrt(det S)) */
  double S[4] = {0};
  for (int d = 0; d < 3; d++) {
    S[0] += B[2 * d] * B[2 * d];
    S[1] += B[2 * d] * B[2 * d + 1];
    S[3] += B[2 * d + 1] * B[2 * d + 1];
  }
  S[2] = S[1];
  double ds = S[0] * S[3] - S[1] * S[2];
  if (!(ds > 0)) {
    return -1;
  }
  double sq = sqrt(ds), t = sqrt(S[0] + S[3] + 2 * sq);
  double Rt[4] = {(S[0] + sq) / t, S[1] / t, S[2] / t, (S[3] + sq) / t};
  double dr = Rt[0] * Rt[3] - Rt[1] * Rt[2];
  double Ri[4] = {Rt[3] / dr, -Rt[1] / dr, -Rt[2] / dr, Rt[0] / dr};
  double q1[3], q2[3], q3[3];
  for (int d = 0; d < 3; d++) {
    q1[d] = B[2 * d] * Ri[0] + B[2 * d + 1] * Ri[2];
    q2[d] = B[2 * d] * Ri[1] + B[2 * d + 1] * Ri[3];
  }
  csu_cross3(q3, q1, q2);
  for (int d = 0; d < 3; d++) {
    R[3 * d] = q1[d];
    R[3 * d + 1] = q2[d];
    R[3 * d + 2] = q3[d];
  }
  if (centroid) {
    csu_copy3(centroid, xc);
  }
  return 0;
}



/* nodes with |z - zp| < tol into a freshly allocated list; returns the count or -1 */
static int collectPlane(const csfMesh* me, double zp, int** out) {
  int n = 0;
  for (int i = 0; i < me->nnode; i++) {
    n += fabs(me->x[3 * i + 2] - zp) < CSF_PLANE_TOL;
  }
  *out = malloc((size_t)(n > 0 ? n : 1) * sizeof(int));
  if (!*out) {
    return -1;
  }
  int k = 0;
  for (int i = 0; i < me->nnode; i++) {
    if (fabs(me->x[3 * i + 2] - zp) < CSF_PLANE_TOL) {
      (*out)[k++] = i;
    }
  }
  return n;
}


csfGauges* csf_gaugesCreate(const csrActuator* act, const csfMesh* me, csError* err) {
  csfGauges* g = calloc(1, sizeof *g);
  if (!g) {
    cs_errorSet(err, CS_ERR_MEMORY, "fem_measure: out of memory");
    return NULL;
  }
  g->nplane = 2 * CSR_NSEG;
  g->plane_ptr = calloc((size_t)g->nplane + 1, sizeof(int));
  g->outer_ptr = calloc(CSR_NSEG + 1, sizeof(int));
  int* lists[2 * CSR_NSEG] = {0};
  int ok = g->plane_ptr && g->outer_ptr;
  int maxn = 0;
  for (int p = 0; p < g->nplane && ok; p++) {
    const int s = p / 2;
    const double z = csr_actuatorSegmentStart(act, s) + (p % 2 ? act->S[s] : 0.0);
    const int n = collectPlane(me, z, &lists[p]);
    ok = n >= 0;
    g->plane_ptr[p + 1] = g->plane_ptr[p] + (n > 0 ? n : 0);
    maxn = n > maxn ? n : maxn;
  }
  if (ok) {
    g->nbase = collectPlane(me, 0.0, &g->base_node);
    g->ntip = collectPlane(me, csr_actuatorLength(act), &g->tip_node);
    ok = g->nbase >= 0 && g->ntip >= 0;
    maxn = g->nbase > maxn ? g->nbase : maxn;
    maxn = g->ntip > maxn ? g->ntip : maxn;
  }
  if (ok) {
    g->plane_node = malloc((size_t)(g->plane_ptr[g->nplane] > 0 ? g->plane_ptr[g->nplane] : 1) *
                           sizeof(int));
    g->scratch = malloc((size_t)(maxn > 0 ? maxn : 1) * 6 * sizeof(double));
    ok = g->plane_node && g->scratch;
  }
  g->plane_c0 = ok ? calloc((size_t)g->nplane * 3, sizeof(double)) : NULL;
  ok = ok && g->plane_c0;
  for (int p = 0; p < g->nplane && ok; p++) {
    const int n = g->plane_ptr[p + 1] - g->plane_ptr[p];
    memcpy(g->plane_node + g->plane_ptr[p], lists[p], (size_t)n * sizeof(int));
    for (int k = 0; k < n; k++) {
      for (int q = 0; q < 3; q++) {
        g->plane_c0[3 * p + q] += me->x[3 * lists[p][k] + q] / n;
      }
    }
  }
  for (int p = 0; p < g->nplane; p++) {
    free(lists[p]);
  }
  /* outer lateral surface nodes: nodes of untagged boundary faces (the outer skin; chamber
   * walls, base and tip are tagged), within the chambered part [start + c, start + S - c] */
  unsigned char* outer = ok ? calloc((size_t)me->nnode, 1) : NULL;
  ok = ok && outer;
  for (int f = 0; ok && f < me->nface; f++) {
    if (me->face_tag[f] == 0) {
      for (int a = 0; a < 6; a++) {
        outer[me->face[6 * f + a]] = 1;
      }
    }
  }
  int nout = 0;
  for (int pass = 0; ok && pass < 2; pass++) {
    nout = 0;
    for (int s = 0; s < CSR_NSEG; s++) {
      const double z0 = csr_actuatorSegmentStart(act, s) + act->c;
      const double z1 = csr_actuatorSegmentStart(act, s) + act->S[s] - act->c;
      for (int i = 0; i < me->nnode; i++) {
        const double z = me->x[3 * i + 2];
        if (outer[i] && z >= z0 && z <= z1) {
          if (pass) {
            g->outer_node[nout] = i;
          }
          nout++;
        }
      }
      if (pass) {
        g->outer_ptr[s + 1] = nout;
      }
    }
    if (!pass) {
      g->outer_node = malloc((size_t)(nout > 0 ? nout : 1) * sizeof(int));
      ok = g->outer_node != NULL;
    }
  }
  free(outer);
  if (!ok) {
    csf_gaugesDestroy(g);
    cs_errorSet(err, CS_ERR_MEMORY, "fem_measure: out of memory (gauges)");
    return NULL;
  }
  return g;
}


void csf_gaugesDestroy(csfGauges* g) {
  if (!g) {
    return;
  }
  free(g->plane_ptr), free(g->plane_node), free(g->base_node), free(g->tip_node);
  free(g->outer_ptr), free(g->outer_node), free(g->scratch), free(g->plane_c0);
  free(g);
}


/* frame and centroid of a node set at the current state */
static int nodeFrame(const csfGauges* g, const csfModel* m, const csfData* d, const int* node,
                     int n, double R[9], double c[3]) {
  const csfMesh* me = m->mesh;
  double* X = g->scratch;
  double* x = X + 3 * n;
  for (int k = 0; k < n; k++) {
    for (int q = 0; q < 3; q++) {
      X[3 * k + q] = me->x[3 * node[k] + q];
      x[3 * k + q] = me->x[3 * node[k] + q] + d->u[3 * node[k] + q];
    }
  }
  return csf_fitPlaneFrame(n, X, x, R, c);
}


static int planeFrame(const csfGauges* g, const csfModel* m, const csfData* d, int p, double R[9],
                      double c[3]) {
  return nodeFrame(g, m, d, g->plane_node + g->plane_ptr[p], g->plane_ptr[p + 1] - g->plane_ptr[p],
                   R, c);
}


/* Rotation angle (rad) of Ra^T Rb about `axis`, unwrapped near `prev` (rad): the twist part of
 * the swing-twist decomposition of the relative rotation, 2 atan2(q_v . axis, q_w) of its unit
 * quaternion (Shepperd's extraction). For a rotation about `axis` alone it is the rotation angle;
 * unlike (rotation angle) x sign(rotation axis . axis), it stays smooth where the bend passes a
 * full turn: there the relative rotation is a small out-of-plane tilt whose axis is arbitrary,
 * and the signed full angle jumped from 360 - eps to 360 + eps (eps = the tilt, ~0.2 deg on the
 * baseline), so a 360 deg target within 0.1 deg could not be bracketed (fem/README.md).
 * axis NULL: the full rotation angle (>= 0). */
double csf_bendAxisAngle(const double Ra[9], const double Rb[9], const double axis[3],
                         double prev) {
  double R[9];
  for (int i = 0; i < 3; i++) {
    for (int j = 0; j < 3; j++) {
      R[3 * i + j] = Ra[i] * Rb[j] + Ra[3 + i] * Rb[3 + j] + Ra[6 + i] * Rb[6 + j];
    }
  }
  double q[4]; /* w, x, y, z */
  csu_mat3ToQuat(q, R);
  double a;
  if (axis) {
    a = 2.0 * atan2(q[1] * axis[0] + q[2] * axis[1] + q[3] * axis[2], q[0]);
  } else {
    a = 2.0 * atan2(sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]), fabs(q[0]));
  }
  /* q and -q are the same rotation: the twist is defined modulo 2 pi, hence the unwrap */
  while (a - prev > CS_PI) {
    a -= 2 * CS_PI;
  }
  while (a - prev < -CS_PI) {
    a += 2 * CS_PI;
  }
  return a;
}


void csf_rotationVector(const double R[9], double w[3]) {
  /* unit quaternion (Shepperd), then w = 2 atan2(|v|, q_w) v / |v| with q_w >= 0 */
  double q[4];
  csu_mat3ToQuat(q, R);
  if (q[0] < 0) {
    for (int i = 0; i < 4; i++) {
      q[i] = -q[i];
    }
  }
  const double v = sqrt(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  const double f = v > 1e-300 ? 2.0 * atan2(v, q[0]) / v : 2.0;
  w[0] = f * q[1], w[1] = f * q[2], w[2] = f * q[3];
}


int csf_segmentMeasure(const csrActuator* act, const csfGauges* g, const csfModel* m,
                       const csfData* d, csfSegmentState seg[CSR_NSEG], double tip[3],
                       double Rtip[9]) {
  const csfMesh* me = m->mesh;
  int bad = 0;
  for (int s = 0; s < CSR_NSEG; s++) {
    csfSegmentState* st = seg + s;
    memset(st, 0, sizeof *st);
    if (planeFrame(g, m, d, 2 * s, st->Ra, st->ca) != 0 ||
        planeFrame(g, m, d, 2 * s + 1, st->Rb, st->cb) != 0) {
      bad = -1;
      continue;
    }
    /* relative rotation in the base face's frame: Rrel = Ra^T Rb; w = theta (e3 x b^) + twist e3 */
    double Rrel[9], w[3];
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        Rrel[3 * i + j] = st->Ra[i] * st->Rb[j] + st->Ra[3 + i] * st->Rb[3 + j] +
                          st->Ra[6 + i] * st->Rb[6 + j];
      }
    }
    csf_rotationVector(Rrel, w);
    st->bend[0] = w[1];
    st->bend[1] = -w[0];
    st->twist = w[2];
    /* centreline: constant-curvature arc of angle theta through both centroids */
    const double S = act->S[s];
    if (!(S > 0)) { /* II2, II3 of a single segment (csr_actuatorSingleSegment): both faces are
                     * the tip face; no length, no stretch */
      st->stretch = 1.0;
      continue;
    }
    double dc[3], cl[3];
    csu_sub3(dc, st->cb, st->ca);
    csu_mulMatTVec3(cl, st->Ra, dc);
    const double chord = csu_norm3(cl);
    const double th = hypot(st->bend[0], st->bend[1]);
    const double arc = th > 1e-8 ? chord * th / (2.0 * sin(0.5 * th)) : chord;
    st->stretch = arc / S;
    /* radial growth from the arc: node at reference height zeta -> arc point and frame there */
    const double z0 = csr_actuatorSegmentStart(act, s);
    const double bx = th > 1e-8 ? st->bend[0] / th : 1.0, by = th > 1e-8 ? st->bend[1] / th : 0.0;
    double sum = 0, rmax = -INFINITY;
    const int n0 = g->outer_ptr[s], n1 = g->outer_ptr[s + 1];
    for (int k = n0; k < n1; k++) {
      const int i = g->outer_node[k];
      const double* X = me->x + 3 * i;
      const double zeta = (X[2] - z0) / S;
      const double phi = th * zeta, sarc = arc * zeta;
      /* arc point and tangent in the base-face frame (bend in direction (bx, by)) */
      double p[3], t[3];
      if (th > 1e-8) {
        const double rho = arc / th;
        p[0] = rho * (1 - cos(phi)) * bx, p[1] = rho * (1 - cos(phi)) * by, p[2] = rho * sin(phi);
      } else {
        p[0] = p[1] = 0, p[2] = sarc;
      }
      t[0] = sin(phi) * bx, t[1] = sin(phi) * by, t[2] = cos(phi);
      /* node in the base-face frame relative to the arc point; its distance from the arc's
       * tangent line is the deformed radius */
      double x[3], r[3];
      for (int q = 0; q < 3; q++) {
        x[q] = X[q] + d->u[3 * i + q] - st->ca[q];
      }
      csu_mulMatTVec3(r, st->Ra, x);
      csu_sub3(r, r, p);
      const double along = csu_dot3(r, t);
      const double rad = sqrt(fmax(csu_dot3(r, r) - along * along, 0.0));
      const double* c0 = g->plane_c0 + 6 * s; /* reference centroid of the base face */
      const double rad0 = hypot(X[0] - c0[0], X[1] - c0[1]);
      if (rad0 > 0) {
        sum += rad / rad0 - 1.0;
        rmax = fmax(rmax, rad - rad0);
      }
    }
    st->radial = n1 > n0 ? sum / (n1 - n0) : 0.0;
    st->radial_max = n1 > n0 ? rmax : 0.0;
  }
  if (nodeFrame(g, m, d, g->tip_node, g->ntip, Rtip, tip) != 0) {
    bad = -1;
  }
  return bad;
}


void csf_bendMeasure(const csrActuator* act, const csfGauges* g, const csfModel* m,
                     const csfData* d, const double axis[3], const double prev[4],
                     double angle_deg[3], double* total_deg, double tip[3]) {
  (void)act;
  double Ra[9], Rb[9], c[3];
  for (int s = 0; s < CSR_NSEG; s++) {
    angle_deg[s] = NAN;
    if (planeFrame(g, m, d, 2 * s, Ra, c) == 0 && planeFrame(g, m, d, 2 * s + 1, Rb, c) == 0) {
      angle_deg[s] = csf_bendAxisAngle(Ra, Rb, axis, prev ? prev[s] * CS_DEG : 0.0) / CS_DEG;
    }
  }
  *total_deg = NAN;
  tip[0] = tip[1] = tip[2] = NAN;
  if (nodeFrame(g, m, d, g->base_node, g->nbase, Ra, c) == 0 &&
      nodeFrame(g, m, d, g->tip_node, g->ntip, Rb, tip) == 0) {
    *total_deg = csf_bendAxisAngle(Ra, Rb, axis, prev ? prev[3] * CS_DEG : 0.0) / CS_DEG;
  }
}

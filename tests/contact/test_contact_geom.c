/* test_contact_geom.c: the narrow phase (contact_geom.h) against exact geometry and against
 * libccd's MPR, on the boxes of a step road: the ground's top face, the step's convex top edge,
 * its corner, the concave corner at its foot. The closed forms must be exact (round-off); MPR
 * must agree with them where its portal lands on the right face, to its tolerance. And the soft
 * law's capsule line load rolled round the step's edge (its normal, depth, force and stiffness
 * in closed form: the normal turns continuously over the edge).
 *
 * Scene (mm, y up): ground [-300, 300] x [-20, 0] x [-150, 150]; step [50, 300] x [0, 40] x
 * [-150, 150]: the step's top edge is the line x = 50, y = 40; its corner (50, 40, 150). */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "contact_geom.h"
#include "contact_soft.h"
#include "core_math.h"
#include "cs_test.h"

static const cstBox kGround = {.lo = {-300, -20, -150}, .hi = {300, 0, 150}};
static const cstBox kStep = {.lo = {50, 0, -150}, .hi = {300, 40, 150}};

/* closed forms are evaluated with a handful of flops on mm-sized numbers: round-off is
 * ~1e-16 * 300 mm; 1e-12 mm leaves 30x margin and still fails on any real formula error */
#define TOL_EXACT 1e-12
/* MPR stops when the portal moves less than its tolerance (1e-9 mm, csc_ccdInit); measured
 * depth errors on these cases are <= 2e-12 mm for faces and up to ~1e-9 for curved (rounded
 * edge) portals, so 1e-8 mm is 10x the tolerance */
#define TOL_MPR 1e-8
/* MPR's normal on a curved part of the Minkowski difference comes from a portal triangle whose
 * size shrinks with the tolerance: measured <= 4e-5 rad; 1e-4 */
#define TOL_MPR_NORMAL 1e-4


/* |a - b| for 3-vectors */
static double dist3(const double a[3], const double b[3]) {
  double d[3];
  csu_sub3(d, a, b);
  return csu_norm3(d);
}


/* worst disagreement of MPR with the exact answer where its portal lands on another face */
static double g_mpr_edge_err = 0;

/* MPR's answer pm against the exact depth and normal: equal on a face contact; elsewhere a
 * separating direction whose depth is not below the minimal one (its excess is recorded) */
static void checkMpr(const cscPenetration* pm, double depth, const double n[3], int on_face) {
  CS_EXPECT(pm->depth >= depth - TOL_MPR);
  if (on_face) {
    CS_EXPECT_NEAR(pm->depth, depth, TOL_MPR, 0);
    CS_EXPECT_NEAR(dist3(pm->normal, n), 0, TOL_MPR_NORMAL, 0);
  } else {
    g_mpr_edge_err = fmax(g_mpr_edge_err, pm->depth - depth);
  }
}


/* the closed form and MPR on one sphere, checked against the exact depth and normal. MPR must
 * equal the exact answer on face contacts (on_face); near edges and corners it may return a
 * non-minimal direction, which is still a separating one: its depth is never below the
 * minimal depth (less its tolerance) */
static void checkSphere(const double c[3], double r, const cstBox* b, double depth,
                        const double n[3], int on_face) {
  cscPenetration pc, pm;
  double d = csc_sphereBoxPenetration(c, r, b, &pc);
  CS_EXPECT_NEAR(d, depth, TOL_EXACT, 0);
  CS_EXPECT_NEAR(dist3(pc.normal, n), 0, TOL_EXACT, 0);
  /* the contact point: depth/2 below the sphere's surface point, along the normal */
  double pos[3];
  for (int k = 0; k < 3; k++) pos[k] = c[k] - (r - 0.5 * depth) * n[k];
  CS_EXPECT_NEAR(dist3(pc.pos, pos), 0, TOL_EXACT, 0);
  cscCcdShape s = {.kind = CSC_CCD_SPHERE, .c = {c[0], c[1], c[2]}, .r = r};
  if (depth <= 0) {
    CS_EXPECT(csc_ccdPenetration(&s, b, NULL, &pm) == 0);
    return;
  }
  CS_EXPECT(csc_ccdPenetration(&s, b, NULL, &pm) == 1);
  checkMpr(&pm, depth, n, on_face);
  printf("  sphere: exact depth %.6f mm, MPR %.6f mm, normal off by %.2g, point off by %.2g mm\n",
         depth, pm.depth, dist3(pm.normal, n), dist3(pm.pos, pos));
}


static void test_geom_sphere_face_edge_corner(void) {
  double r = 7.5;
  /* on the ground's top face, far from the step: depth 0.01 mm, normal +y */
  double n_up[3] = {0, 1, 0};
  checkSphere((double[3]){-100, r - 0.01, 20}, r, &kGround, 0.01, n_up, 1);
  /* a gap of 0.2 mm: depth -0.2, the normal still points up */
  checkSphere((double[3]){-100, r + 0.2, 20}, r, &kGround, -0.2, n_up, 1);
  /* over the step's top edge: distance to the edge line sqrt(u^2 + v^2) */
  double u = -3.0, v = 6.0, e = sqrt(u * u + v * v);
  double n_edge[3] = {u / e, v / e, 0};
  checkSphere((double[3]){50 + u, 40 + v, 0}, r, &kStep, r - e, n_edge, 0);
  /* at the step's corner: distance to the corner point */
  double w = 2.0, ec = sqrt(u * u + v * v + w * w);
  double n_corner[3] = {u / ec, v / ec, w / ec};
  checkSphere((double[3]){50 + u, 40 + v, 150 + w}, r, &kStep, r - ec, n_corner, 0);
  /* against the riser of the step (concave corner, the ground seen separately) */
  double n_left[3] = {-1, 0, 0};
  checkSphere((double[3]){50 - r + 0.05, 3, 0}, r, &kStep, 0.05, n_left, 1);
  checkSphere((double[3]){50 - r + 0.05, 3, 0}, r, &kGround, r - 3, n_up, 1);
}


static void test_geom_sphere_centre_inside(void) {
  /* the centre 0.3 mm inside the top face: depth r + 0.3, normal of the nearest face */
  cscPenetration p;
  double d = csc_sphereBoxPenetration((double[3]){0, -0.3, 0}, 1.0, &kGround, &p);
  CS_EXPECT_NEAR(d, 1.3, TOL_EXACT, 0);
  CS_EXPECT_NEAR(p.normal[1], 1.0, TOL_EXACT, 0);
  /* signed distance on the surface and inside */
  double cp[3], n[3];
  CS_EXPECT(cst_boxSignedDistance(&kGround, (double[3]){10, 0, 0}, cp, n) == 0);
  CS_EXPECT(n[1] == 1.0);
  CS_EXPECT_NEAR(cst_boxSignedDistance(&kGround, (double[3]){299, -10, 0}, cp, n), -1.0,
                 TOL_EXACT, 0);
  CS_EXPECT(n[0] == 1.0 && cp[0] == 300);
}


static void test_geom_segment_distance_exact(void) {
  /* q(s) against the clamp formula at many s, on segments through faces, edges and corners */
  const double seg[4][6] = {
      {20, 55, -30, 80, 35, 170},   /* over the step's top, past its corner */
      {-10, 30, 0, 70, 60, 0},      /* across the top edge */
      {40, -5, -200, 60, 45, 200},  /* through the step (q = 0 on a stretch) */
      {60, 41, -10, 200, 41, 10}};  /* parallel to the top face: flat minimum */
  double worst = 0;
  for (int i = 0; i < 4; i++) {
    cscSegBox q;
    csc_segBoxInit(&q, seg[i], seg[i] + 3, &kStep);
    double qmin_sampled = INFINITY;
    for (int j = 0; j <= 2000; j++) {
      double s = j / 2000.0, x[3], cp[3];
      for (int k = 0; k < 3; k++) x[k] = seg[i][k] + s * (seg[i][3 + k] - seg[i][k]);
      double dist = fmax(0.0, cst_boxSignedDistance(&kStep, x, cp, NULL));
      worst = fmax(worst, fabs(csc_segBoxEval(&q, s) - dist * dist));
      qmin_sampled = fmin(qmin_sampled, dist * dist);
    }
    /* the exact minimum is at or below every sample, and within the sampling error (q is
     * smooth: step 5e-4 in s) of the best one */
    CS_EXPECT(q.q_min <= qmin_sampled + 1e-9);
    CS_EXPECT_NEAR(q.q_min, qmin_sampled, 1e-3, 0);
  }
  /* q is a sum of squares of ~100 mm numbers: round-off ~1e-16 * 1e4 mm^2; 1e-9 mm^2 */
  CS_EXPECT_NEAR(worst, 0, 1e-9, 0);
  /* the flat minimum (segment 4) sits in the middle of the stretch over the top face: the whole
   * segment is above the face, so s_min = 1/2 and q_min = 1 mm^2 */
  cscSegBox q;
  csc_segBoxInit(&q, seg[3], seg[3] + 3, &kStep);
  CS_EXPECT_NEAR(q.s_min, 0.5, TOL_EXACT, 0);
  CS_EXPECT_NEAR(q.q_min, 1.0, TOL_EXACT, 0);
  /* the level set q <= 4 of segment 2 (across the edge) against bisection on the clamp */
  csc_segBoxInit(&q, seg[1], seg[1] + 3, &kStep);
  double sa, sb;
  CS_EXPECT(csc_segBoxInterval(&q, q.q_min + 4.0, &sa, &sb) == 1);
  CS_EXPECT(csc_segBoxInterval(&q, q.q_min - 1e-6, &sa, &sb) == 0 || q.q_min == 0);
  CS_EXPECT(csc_segBoxInterval(&q, q.q_min + 4.0, &sa, &sb) == 1);
  for (int end = 0; end < 2; end++) {
    double lo = end ? q.s_min : 0, hi = end ? 1 : q.s_min;
    for (int it = 0; it < 200; it++) {
      double mid = 0.5 * (lo + hi), x[3];
      for (int k = 0; k < 3; k++) x[k] = seg[1][k] + mid * (seg[1][3 + k] - seg[1][k]);
      double dist = fmax(0.0, cst_boxSignedDistance(&kStep, x, NULL, NULL));
      int inside = dist * dist <= q.q_min + 4.0;
      if (inside == (end == 0)) {
        hi = mid;
      } else {
        lo = mid;
      }
    }
    CS_EXPECT_NEAR(end ? sb : sa, 0.5 * (lo + hi), 1e-12, 0);
  }
}


/* capsule: closed form against the exact distance of a skew/parallel axis, and against MPR
 * (exact on faces, a separating bound elsewhere, as for spheres) */
static void checkCapsule(const double p0[3], const double p1[3], double r, const cstBox* b,
                         double depth, const double n[3], double s_expect, int on_face) {
  cscPenetration pc, pm;
  double s;
  double d = csc_capsuleBoxPenetration(p0, p1, r, b, &pc, &s);
  CS_EXPECT_NEAR(d, depth, TOL_EXACT, 0);
  CS_EXPECT_NEAR(dist3(pc.normal, n), 0, TOL_EXACT, 0);
  CS_EXPECT_NEAR(s, s_expect, 1e-12, 0);
  cscCcdShape c = {.kind = CSC_CCD_CAPSULE, .p0 = {p0[0], p0[1], p0[2]},
                   .p1 = {p1[0], p1[1], p1[2]}, .r = r};
  CS_EXPECT(csc_ccdPenetration(&c, b, NULL, &pm) == (depth > 0));
  if (depth > 0) {
    checkMpr(&pm, depth, n, on_face);
    printf("  capsule: exact depth %.6f mm, MPR %.6f mm, normal off by %.2g\n", depth, pm.depth,
           dist3(pm.normal, n));
  }
}


static void test_geom_capsule_face_edge_corner(void) {
  double r = 7.5;
  /* lying on the ground parallel to the face, 0.02 mm deep: flat minimum, s = 1/2 */
  checkCapsule((double[3]){-100, r - 0.02, 0}, (double[3]){-90, r - 0.02, 0}, r, &kGround,
               0.02, (double[3]){0, 1, 0}, 0.5, 1);
  /* across the step's top edge, rising towards -x: the closest point of the box is the edge;
   * in the xy-plane the axis passes the edge point (50, 40) at the 2D line distance */
  double a0[3] = {30, 40 + 3.0, 0}, a1[3] = {60, 40 + 12.0, 0};
  double dx = a1[0] - a0[0], dy = a1[1] - a0[1], L = hypot(dx, dy);
  double ex = 50 - a0[0], ey = 40 - a0[1];
  double along = (ex * dx + ey * dy) / L;          /* foot of the perpendicular */
  double cross = (dx * ey - dy * ex) / L;           /* signed distance, > 0: edge below-right */
  double e = fabs(cross);
  double foot[2] = {a0[0] + along * dx / L, a0[1] + along * dy / L};
  double n_edge[3] = {(foot[0] - 50) / e, (foot[1] - 40) / e, 0};
  checkCapsule(a0, a1, r, &kStep, r - e, n_edge, along / L, 0);
  /* parallel to the edge line above it: flat along z, s = 1/2 */
  double u = -2.0, v = 5.0, ee = hypot(u, v);
  checkCapsule((double[3]){50 + u, 40 + v, -20}, (double[3]){50 + u, 40 + v, 20}, r, &kStep,
               r - ee, (double[3]){u / ee, v / ee, 0}, 0.5, 0);
  /* an end of the capsule near the step's corner: distance from the axis end to the corner */
  double w = 1.5, ec = sqrt(u * u + v * v + w * w);
  checkCapsule((double[3]){50 + u, 40 + v, 150 + w}, (double[3]){50 + u, 40 + v, 180}, r,
               &kStep, r - ec, (double[3]){u / ec, v / ec, w / ec}, 0.0, 0);
}


static void test_geom_capsule_axis_inside(void) {
  /* the axis 1 mm inside the ground's top face, parallel to it: the separating axis is +y,
   * depth r + 1 (a deep, non-physical state the soft law refuses, but the query must be
   * exact) */
  cscPenetration p;
  double s;
  double d = csc_capsuleBoxPenetration((double[3]){-10, -1, 0}, (double[3]){10, -1, 0}, 7.5,
                                       &kGround, &p, &s);
  CS_EXPECT_NEAR(d, 8.5, TOL_EXACT, 0);
  CS_EXPECT_NEAR(p.normal[1], 1, TOL_EXACT, 0);
  CS_EXPECT_NEAR(s, 0.5, 0, 0);
  /* tilted into the face: the deeper end is the deepest point */
  d = csc_capsuleBoxPenetration((double[3]){-10, 1, 0}, (double[3]){10, -2, 0}, 7.5, &kGround,
                                &p, &s);
  CS_EXPECT_NEAR(d, 9.5, TOL_EXACT, 0);
  CS_EXPECT(s == 1.0);
}


/* exact penetration of two boxes by the separating-axis theorem (15 axes): the reference for
 * the foot's block against a terrain box */
static double boxBoxSat(const cscCcdShape* f, const cstBox* b, double n_out[3]) {
  double c[3], h[3], axes[15][3];
  int na = 0;
  for (int k = 0; k < 3; k++) {
    c[k] = 0.5 * (b->lo[k] + b->hi[k]);
    h[k] = 0.5 * (b->hi[k] - b->lo[k]);
  }
  double fa[3][3];
  for (int k = 0; k < 3; k++) {
    for (int j = 0; j < 3; j++) fa[k][j] = f->R[3 * j + k];
  }
  for (int k = 0; k < 3; k++) {
    csu_set3(axes[na++], k == 0, k == 1, k == 2);
    csu_copy3(axes[na++], fa[k]);
  }
  for (int i = 0; i < 3; i++) {
    for (int k = 0; k < 3; k++) {
      double e[3] = {k == 0, k == 1, k == 2}, a[3];
      csu_cross3(a, fa[i], e);
      if (csu_normalize3(a) > 1e-9) {
        csu_copy3(axes[na++], a);
      }
    }
  }
  double best = INFINITY;
  for (int i = 0; i < na; i++) {
    const double* a = axes[i];
    double rb = h[0] * fabs(a[0]) + h[1] * fabs(a[1]) + h[2] * fabs(a[2]);
    double rf = 0;
    for (int k = 0; k < 3; k++) rf += f->h[k] * fabs(csu_dot3(fa[k], a));
    double cb = csu_dot3(c, a), cf = csu_dot3(f->c, a);
    double up = (cb + rb) - (cf - rf), down = (cf + rf) - (cb - rb);
    if (up < best) {
      best = up;
      csu_copy3(n_out, a);
    }
    if (down < best) {
      best = down;
      csu_scale3(n_out, a, -1);
    }
  }
  return best;
}


static void test_geom_foot_block_ccd(void) {
  /* the foot's end block (15 x 15 x 15 mm) on the ground, 0.004 mm deep: MPR = exact */
  cscCcdShape f = {.kind = CSC_CCD_BOX, .c = {-40, 7.5 - 0.004, 10}, .h = {7.5, 7.5, 7.5}};
  csu_eye3(f.R);
  cscPenetration p;
  double n[3];
  CS_EXPECT(csc_ccdPenetration(&f, &kGround, NULL, &p) == 1);
  CS_EXPECT_NEAR(p.depth, 0.004, TOL_MPR, 0);
  CS_EXPECT_NEAR(p.normal[1], 1, TOL_MPR_NORMAL, 0);
  CS_EXPECT_NEAR(boxBoxSat(&f, &kGround, n), 0.004, TOL_EXACT, 0);
  /* tilted by -10 deg about z with its lowest edge (a sole edge along z) 2 mm beyond the step's
   * edge and 0.05 mm into the step's top; the rest of the sole hangs over the edge, rising
   * 2 tan(10 deg) = 0.35 mm above the top at x = 50 */
  double th = -10 * CS_DEG, axis[3] = {0, 0, 1};
  csu_axisAngleToMat3(f.R, axis, th);
  double corner[3] = {7.5, -7.5, 0}, rc[3]; /* the lowest sole edge in the foot frame */
  csu_mulMatVec3(rc, f.R, corner);
  csu_set3(f.c, 52 - rc[0], 40 - 0.05 - rc[1], 0);
  double sat = boxBoxSat(&f, &kStep, n);
  CS_EXPECT(csc_ccdPenetration(&f, &kStep, NULL, &p) == 1);
  printf("  tilted foot on the step edge: SAT depth %.9f mm normal (%.4f %.4f), MPR %.9f mm"
         " normal (%.4f %.4f)\n", sat, n[0], n[1], p.depth, p.normal[0], p.normal[1]);
  /* the overlap is the wedge between the step's top and the sole near the lowest edge: a push
   * straight up by 0.05 mm clears it (along the sole's normal it would take 0.05 / cos 10 deg,
   * across the step's riser 2 mm); MPR's ray from the centres finds the top face here */
  CS_EXPECT_NEAR(sat, 0.05, TOL_EXACT, 0);
  CS_EXPECT_NEAR(n[1], 1.0, TOL_EXACT, 0);
  CS_EXPECT_NEAR(p.depth, sat, TOL_MPR, 0);
  CS_EXPECT_NEAR(p.normal[1], 1.0, TOL_MPR_NORMAL, 0);
  printf("  MPR on the tilted foot: %.3g mm above the minimal depth\n", p.depth - sat);
}


static void test_geom_cost_closed_form_vs_mpr(void) {
  /* not a timing assertion: the ratio is printed for the report; the check is that both paths
   * agree on every one of the evaluated poses */
  int n = 20000, disagree = 0;
  double r = 7.5, sink = 0;
  clock_t t0 = clock();
  for (int i = 0; i < n; i++) {
    double c[3] = {-100 + 0.01 * i, r - 0.003 - 1e-7 * i, 3};
    sink += csc_sphereBoxPenetration(c, r, &kGround, NULL);
  }
  clock_t t1 = clock();
  ccd_t ccd;
  csc_ccdInit(&ccd);
  for (int i = 0; i < n; i++) {
    cscCcdShape s = {.kind = CSC_CCD_SPHERE, .c = {-100 + 0.01 * i, r - 0.003 - 1e-7 * i, 3},
                     .r = r};
    cscPenetration p;
    if (!csc_ccdPenetration(&s, &kGround, &ccd, &p) || fabs(p.depth - (0.003 + 1e-7 * i)) > TOL_MPR) {
      disagree++;
    }
  }
  clock_t t2 = clock();
  CS_EXPECT(disagree == 0);
  printf("  MPR near edges and corners: up to %.3f mm deeper than the minimal depth\n",
         g_mpr_edge_err);
  printf("  sphere-box: closed form %.3f us, MPR %.3f us per query (sum %.3g)\n",
         1e6 * (double)(t1 - t0) / CLOCKS_PER_SEC / n, 1e6 * (double)(t2 - t1) / CLOCKS_PER_SEC / n,
         sink);
}


/* A capsule lying parallel to the step's top edge (along z, 20 mm) rolled round it: its axis at
 * c(θ) = edge + e (-sin θ, cos θ) for θ in [0°, 90°] (the edge's quadrant), over the top face
 * for θ < 0 and beside the side face for θ > 90° (c the same formula: its distance to the face
 * is e cos θ or e sin θ there). Closed forms of the soft law's capsule line load against the
 * step (contact_soft.h: every axis point at the same depth d = r - ρ, ρ the axis' distance to
 * the box): the slot's normal n = (c - closest point) / ρ, (-sin θ, cos θ, 0) on the edge, the
 * face's normal beyond it, so it turns continuously (the step of θ bounds each turn); depth
 * r - ρ; force F = k_line d^1.5 L n; and its stiffness against a translation of the capsule,
 * K = ∂F/∂c = k_line L (-1.5 d^0.5 n nᵀ + d^1.5 (I - n nᵀ - t tᵀ) / ρ) on the edge (the normal
 * turns with the axis: the second term), -1.5 k_line L d^0.5 n nᵀ on a face (t = e_z, the
 * edge's direction), against central differences of the law. These are what the strain leg's
 * Newton passes linearise (robot_strain_contact.c differences this law): a normal switching
 * faces over the edge would fail the continuity, a face normal on the edge the K's second
 * term (2e-3 of |K| here, the check resolves 1e-6). */
static void test_geom_capsule_round_an_edge_closed_form(void) {
  cscSoftParams p = csc_softDefaultParams();
  p.history = CSC_HISTORY_STEP; /* fresh slots have no anchor: the normal load alone */
  cstTerrain t;
  memset(&t, 0, sizeof t);
  t.nbox = 1;
  t.box[0] = kStep;
  const double r = 6.0, d = 0.02, e = r - d, L = 20;
  const double kline = p.k_area * (4.0 / 3.0) * sqrt(2 * r);
  cscShape sh = csc_softCapsule(r);
  csError err;
  cscSoftModel* m = csc_softCreate(&p, &t, 1, &sh, &err);
  CS_EXPECT(m != NULL);
  if (!m) {
    return;
  }
  double z[4];
  csc_softStateInit(m, z);
  /* load and slot of the capsule with its axis through c (x, y), along z */
  double nprev[3] = {0, 0, 0}, worst_turn = 0, worst_n = 0, worst_d = 0, worst_f = 0;
  double worst_k = 0, worst_kt = 0;
  const double dth = 0.5 * CS_PI / 180;
  int nk = 0;
  for (int i = -40; i <= 220; i++) {
    const double th = i * dth;
    cscShapeState st;
    memset(&st, 0, sizeof st);
    const double cx = 50 - e * sin(th), cy = 40 + e * cos(th);
    csu_set3(st.x0, cx, cy, -L / 2);
    csu_set3(st.x1, cx, cy, L / 2);
    cscShapeLoad ld;
    cscSlotInfo slot;
    CS_EXPECT(csc_softCompute(m, &st, z, &ld, NULL, &slot, NULL) == 0);
    double n[3], rho;
    if (th < 0) {
      csu_set3(n, 0, 1, 0);
      rho = e * cos(th);
    } else if (th > 0.5 * CS_PI) {
      csu_set3(n, -1, 0, 0);
      rho = e * sin(th);
    } else {
      csu_set3(n, -sin(th), cos(th), 0);
      rho = e;
    }
    const double dep = r - rho, Fm = kline * pow(dep, 1.5) * L;
    double dn[3], f[3];
    csu_sub3(dn, slot.normal, n);
    csu_add3(f, ld.f0, ld.f1);
    worst_n = fmax(worst_n, csu_norm3(dn));
    worst_d = fmax(worst_d, fabs(slot.depth - dep));
    for (int k = 0; k < 3; k++) {
      worst_f = fmax(worst_f, fabs(f[k] - Fm * n[k]) / Fm);
    }
    if (i > -40) {
      double tn[3];
      csu_sub3(tn, slot.normal, nprev);
      worst_turn = fmax(worst_turn, csu_norm3(tn));
    }
    csu_copy3(nprev, slot.normal);
    /* the stiffness at a few angles away from the regions' seams (0°, 90°) */
    if (i % 20 != 10) {
      continue;
    }
    nk++;
    double K[9], Kmax = 0;
    for (int a = 0; a < 3; a++) {
      for (int b = 0; b < 3; b++) {
        double P = (a == b) - n[a] * n[b] - (a == 2) * (b == 2);
        int edge = th > 0 && th < 0.5 * CS_PI;
        K[3 * a + b] = kline * L * (-1.5 * sqrt(dep) * n[a] * n[b] +
                                    (edge ? pow(dep, 1.5) * P / rho : 0));
        Kmax = fmax(Kmax, fabs(K[3 * a + b]));
      }
    }
    const double del = 1e-6;
    for (int b = 0; b < 3; b++) {
      double Fp[3], Fn[3];
      for (int sgn = -1; sgn <= 1; sgn += 2) {
        cscShapeState sp = st;
        sp.x0[b] += sgn * del;
        sp.x1[b] += sgn * del;
        cscShapeLoad lp;
        CS_EXPECT(csc_softCompute(m, &sp, z, &lp, NULL, NULL, NULL) == 0);
        csu_add3(sgn > 0 ? Fp : Fn, lp.f0, lp.f1);
      }
      for (int a = 0; a < 3; a++) {
        const double Kd = (Fp[a] - Fn[a]) / (2 * del);
        worst_k = fmax(worst_k, fabs(Kd - K[3 * a + b]) / Kmax);
        /* the normal's turn alone: the tangential row and column of the edge's quadrant */
        if (th > 0 && th < 0.5 * CS_PI && a < 2 && b < 2) {
          const double turn = pow(dep, 1.5) * kline * L / rho;
          worst_kt = fmax(worst_kt, fabs(Kd - K[3 * a + b]) / turn);
        }
      }
    }
  }
  printf("  capsule round an edge (r %.1f mm, %.2f mm deep, 261 angles): normal %.2e, depth "
         "%.2e mm, force %.2e relative, largest turn %.4f per %.4f rad; stiffness at %d angles "
         "%.2e of |K|, %.2e of the turning term\n", r, d, worst_n, worst_d, worst_f, worst_turn,
         dth, nk, worst_k, worst_kt);
  CS_EXPECT(worst_n < TOL_EXACT);
  CS_EXPECT(worst_d < TOL_EXACT);
  CS_EXPECT(worst_f < 1e-12); /* relative: the same depth at every quadrature point */
  /* a unit vector turning by dth moves by 2 sin(dth / 2) <= dth */
  CS_EXPECT(worst_turn <= dth * (1 + 1e-9));
  CS_EXPECT(worst_k < 1e-6);
  CS_EXPECT(worst_kt < 1e-3);
  csc_softDestroy(m);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_geom_sphere_face_edge_corner);
  CS_RUN(test_geom_sphere_centre_inside);
  CS_RUN(test_geom_segment_distance_exact);
  CS_RUN(test_geom_capsule_face_edge_corner);
  CS_RUN(test_geom_capsule_axis_inside);
  CS_RUN(test_geom_capsule_round_an_edge_closed_form);
  CS_RUN(test_geom_foot_block_ccd);
  CS_RUN(test_geom_cost_closed_form_vs_mpr);
  return cs_testSummary();
}

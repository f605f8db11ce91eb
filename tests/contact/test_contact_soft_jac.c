/* test_contact_soft_jac.c: the soft law's analytic load derivatives (csc_softShapeJacobian,
 * contact_soft_jac.c) against central differences of the law itself (csc_softComputeShape),
 * on a step-mode foot whose nine sole points sit across the law's regimes: depths on both
 * sides of the onset (d_onset 1 µm), Hunt-Crossley's clip, anchors in stick (u 0.4), on the
 * saturation's parabola (u 1.0), saturated (u 1.5) and free (touched down in the step), on a
 * level ground, a ground tilted 10° (oriented box) and over a box's edge (sole points whose
 * closest feature is the edge: the normal turns with the point).
 *
 * Tolerance. The law is C1 and piecewise smooth with its narrowest transition w = d_onset =
 * 1e-3 mm (positions) and, for the rates, Hunt-Crossley's clip 0.5 / c_hc = 5 mm/s. Central
 * differences with step δ err by ~(δ/w)² |K| inside a piece (third derivative ~ K / w²) plus
 * round-off ε |L| / δ; with δ = 1e-7 mm (1e-8 rad at the sole's 7.5 mm lever, 1e-6 mm/s)
 * that is ~1e-8 |K| and ~1e-12 |K| (|K| ~ |L| / w): the check asks 1e-6 of the matrix's
 * largest entry, and the test requires every sole point's state to sit farther than 100 δ
 * from a seam of a piece (else a difference straddles a kink and errs by O(δ/w)). The load L
 * itself must be csc_softComputeShape's to round-off (the same operations but for the sums'
 * grouping): 1e-12 of its largest component. The largest errors are printed.
 *
 * Also csc_softUpdateShapeLoad (the return-mapping and the load at the new anchors from one
 * evaluation of the geometry) against the update followed by a new evaluation: bit for bit. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "contact_soft.h"
#include "contact_soft_internal.h"
#include "core_math.h"
#include "cs_test.h"

static const double kHalf = 7.5; /* mm: the leg's sole half side */
static const double kDx = 1e-7;   /* mm: position difference step (above) */
static const double kDphi = 1e-8; /* rad */
static const double kDv = 1e-6;   /* mm/s */


/* the shape's coordinate c (0..2 x0, 3..5 rotation φ: R -> exp(φ^) R, 6..8 v0, 9..11 w) moved
 * by del */
static void perturb(cscShapeState* st, int c, double del) {
  if (c < 3) {
    st->x0[c] += del;
  } else if (c < 6) {
    double phi[3] = {0, 0, 0}, dR[9], Rn[9];
    phi[c - 3] = del;
    csu_rotVecToMat3(dR, phi);
    csu_mulMat3(Rn, dR, st->R);
    memcpy(st->R, Rn, sizeof Rn);
  } else if (c < 9) {
    st->v0[c - 6] += del;
  } else {
    st->w[c - 9] += del;
  }
}


static void loadL(const cscSoftModel* m, const cscShapeState* st, const double* z, double L[6]) {
  cscShapeLoad ld;
  double zd[64];
  csc_softComputeShape(m, 0, st, z, &ld, zd, NULL, NULL);
  memcpy(L, ld.f0, 3 * sizeof(double));
  memcpy(L + 3, ld.m, 3 * sizeof(double));
}


/* the smallest distance of a sole point's state to a seam of the law's pieces, in units of
 * the difference step: depth against 0 and d_onset (and 1 mm: the sphere's centre at the
 * box), the Hunt-Crossley argument against 0 and the clip, the anchor's ratio u against
 * u_elastic and 2 - u_elastic */
static double seamMargin(const cscSoftModel* m, const cscShapeState* st, const double* z) {
  const cscSoftParams* p = csc_softParams(m);
  cscSlotInfo slot[25];
  cscShapeLoad ld;
  double zd[100];
  csc_softComputeShape(m, 0, st, z, &ld, zd, slot, NULL);
  int first, nslot;
  csc_softShapeSlots(m, 0, &first, &nslot);
  double margin = INFINITY;
  for (int k = 0; k < nslot; k++) {
    const double d = slot[k].depth;
    if (!isfinite(d)) {
      continue;
    }
    margin = fmin(margin, fabs(d) / kDx);
    margin = fmin(margin, fabs(d - p->d_onset) / kDx);
    if (d > 0 && z[4 * k + 3] >= 0) {
      /* u's own scale: a step kDx moves u by kDx / (mu delta_t) */
      const double du = kDx / (p->mu * p->delta_t);
      margin = fmin(margin, fabs(slot[k].ratio - p->u_elastic) / du);
      margin = fmin(margin, fabs(slot[k].ratio - (2 - p->u_elastic)) / du);
    }
  }
  return margin;
}


/* the foot's nine slots anchored at ratios u[k % 4] (negative: free) along directions turning
 * with k, in the tangent plane of the normal nrm */
static void anchors(const cscSoftModel* m, const cscShape* sh, const cscShapeState* st,
                    const double nrm[3], double* z) {
  const cscSoftParams* p = csc_softParams(m);
  const double u[4] = {0.4, 1.0, 1.5, -1};
  double t1[3], t2[3], ax[3] = {0.3, 0.2, 0.9};
  csu_cross3(t1, nrm, ax);
  csu_normalize3(t1);
  csu_cross3(t2, nrm, t1);
  for (int k = 0; k < sh->nside * sh->nside; k++) {
    double c[3], A, xm[3];
    csc_softSolePoint(sh, st, k / sh->nside, k % sh->nside, c, &A);
    for (int j = 0; j < 3; j++) xm[j] = c[j] + sh->radius * st->R[3 * j + 2];
    const double uk = u[k % 4], th = 0.9 * k;
    if (uk < 0) {
      csu_set3(z + 4 * k, 0, 0, 0);
      z[4 * k + 3] = CSC_SOFT_FREE;
      continue;
    }
    for (int j = 0; j < 3; j++) {
      z[4 * k + j] = xm[j] - uk * p->mu * p->delta_t * (cos(th) * t1[j] + sin(th) * t2[j]);
    }
    z[4 * k + 3] = 0;
  }
}


/* D (6 x 12, row-major): the load's central differences along the 12 coordinates of perturb */
static void centralDiffs(const cscSoftModel* m, const cscShapeState* st, const double* z,
                         double D[72]) {
  for (int c = 0; c < 12; c++) {
    const double del = c < 3 ? kDx : (c < 6 ? kDphi : kDv);
    cscShapeState sp = *st, sm = *st;
    perturb(&sp, c, del);
    perturb(&sm, c, -del);
    double Lp[6], Lm[6];
    loadL(m, &sp, z, Lp);
    loadL(m, &sm, z, Lm);
    for (int r = 0; r < 6; r++) {
      D[12 * r + c] = (Lp[r] - Lm[r]) / (2 * del);
    }
  }
}


/* K, C against central differences and L against the law at one state; returns the worst
 * error relative to the matrices' largest entry */
static double checkState(const char* name, const cscSoftModel* m, const cscShapeState* st,
                         const double* z) {
  double L[6], K[36], C[36], L0[6];
  int rc = csc_softShapeJacobian(m, 0, st, z, L, K, C);
  CS_EXPECT(rc == 0);
  loadL(m, st, z, L0);
  double lmax = 0, kmax = 0, cmax = 0, el = 0, ek = 0, ec = 0;
  for (int r = 0; r < 6; r++) {
    lmax = fmax(lmax, fabs(L0[r]));
  }
  for (int r = 0; r < 6; r++) {
    el = fmax(el, fabs(L[r] - L0[r]));
  }
  CS_EXPECT(lmax > 0);
  /* round-off of the same sums grouped differently */
  CS_EXPECT(el <= 1e-12 * lmax);
  double D[72];
  centralDiffs(m, st, z, D);
  for (int r = 0; r < 6; r++) {
    for (int c = 0; c < 6; c++) {
      kmax = fmax(kmax, fabs(D[12 * r + c]));
      cmax = fmax(cmax, fabs(D[12 * r + 6 + c]));
    }
  }
  for (int r = 0; r < 6; r++) {
    for (int c = 0; c < 6; c++) {
      ek = fmax(ek, fabs(K[6 * r + c] - D[12 * r + c]));
      ec = fmax(ec, fabs(C[6 * r + c] - D[12 * r + 6 + c]));
    }
  }
  const double margin = seamMargin(m, st, z);
  printf("%-22s |L| %.3e (vs law %.1e), |K| %.3e err %.2e (rel %.1e), |C| %.3e err %.2e "
         "(rel %.1e), seam margin %.0f steps\n", name, lmax, el, kmax, ek, ek / kmax, cmax, ec,
         ec / cmax, margin);
  /* the state must not straddle a seam (header) */
  CS_EXPECT(margin > 100);
  /* central differences' (δ/w)² ~ 1e-8 of |K| (header), asked to 1e-6 */
  CS_EXPECT(ek <= 1e-6 * kmax);
  CS_EXPECT(ec <= 1e-6 * cmax);
  return fmax(ek / kmax, ec / cmax);
}


/* the friction's own derivatives on a level ground: rows 0 and 2 of K and C (the forces along
 * x and z, the tangent plane: friction, and the normal force's share only through the sole's
 * small tilt) against central differences, relative to those rows' largest entry; the
 * normal law's far larger entries do not mask them as they do in checkState's measure */
static void checkTangentRows(const char* name, const cscSoftModel* m, const cscShapeState* st,
                             const double* z) {
  double L[6], K[36], C[36];
  CS_EXPECT(csc_softShapeJacobian(m, 0, st, z, L, K, C) == 0);
  double kmax = 0, cmax = 0, ek = 0, ec = 0, D[72];
  const int rows[2] = {0, 2};
  centralDiffs(m, st, z, D);
  for (int c = 0; c < 12; c++) {
    for (int i = 0; i < 2; i++) {
      const int r = rows[i];
      const double Dr = D[12 * r + c], A = c < 6 ? K[6 * r + c] : C[6 * r + c - 6];
      if (c < 6) {
        kmax = fmax(kmax, fabs(Dr));
        ek = fmax(ek, fabs(A - Dr));
      } else {
        cmax = fmax(cmax, fabs(Dr));
        ec = fmax(ec, fabs(A - Dr));
      }
    }
  }
  printf("%-22s tangential rows: |K| %.3e err %.2e (rel %.1e), |C| %.3e err %.2e (rel %.1e)\n",
         name, kmax, ek, ek / kmax, cmax, ec, ec / cmax);
  CS_EXPECT(kmax > 0 && cmax > 0);
  CS_EXPECT(ek <= 1e-6 * kmax);
  CS_EXPECT(ec <= 1e-6 * cmax);
}


/* a level foot (e1 = +x, e2 = +z, e3 = -y) turned by rotation vector tilt, its sole centre at
 * x0 */
static cscShapeState footPose(const double x0[3], const double tilt[3], const double v0[3],
                              const double w[3]) {
  cscShapeState s;
  memset(&s, 0, sizeof s);
  const double R0[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  double dR[9];
  csu_rotVecToMat3(dR, tilt);
  csu_mulMat3(s.R, dR, R0);
  csu_copy3(s.x0, x0);
  csu_copy3(s.v0, v0);
  csu_copy3(s.w, w);
  return s;
}


static cscSoftModel* footModel(const cstTerrain* t, cscShape* sh) {
  cscSoftParams p = csc_softDefaultParams();
  p.history = CSC_HISTORY_STEP;
  *sh = csc_softFoot(kHalf);
  csError err;
  cscSoftModel* m = csc_softCreate(&p, t, 1, sh, &err);
  CS_EXPECT(m != NULL);
  return m;
}


/* a level ground: a slab whose top is y = 0, ending at x = xend */
static cstTerrain levelGround(double xend) {
  cstTerrain t;
  memset(&t, 0, sizeof t);
  t.nbox = 1;
  t.box[0] = (cstBox){.lo = {-1e3, -20, -150}, .hi = {xend, 0, 150}};
  return t;
}


/* a capsule of radius 2 mm and the foot on terrain t, history mode hist */
static cscSoftModel* capsuleFootModel(const cstTerrain* t, cscHistoryMode hist) {
  cscSoftParams p = csc_softDefaultParams();
  p.history = hist;
  cscShape sh[2] = {csc_softCapsule(2.0), csc_softFoot(kHalf)};
  csError err;
  cscSoftModel* m = csc_softCreate(&p, t, 2, sh, &err);
  CS_EXPECT(m != NULL);
  return m;
}


static void test_soft_jacobian_matches_differences_level_ground(void) {
  cstTerrain t = levelGround(1e3);
  cscShape sh;
  cscSoftModel* m = footModel(&t, &sh);
  if (!m) {
    return;
  }
  double z[36], up[3] = {0, 1, 0};
  /* depths 1.37 µm at the centre, tilted so the sole points span ~0.3..2.4 µm (both sides of
   * the onset); sliding and turning */
  {
    const double x0[3] = {1.0, -1.37e-3, 2.0}, tilt[3] = {0.83e-4, 0, 0.61e-4};
    const double v0[3] = {3.1, -0.23, 1.2}, w[3] = {0.011, 0.023, -0.0047};
    cscShapeState st = footPose(x0, tilt, v0, w);
    anchors(m, &sh, &st, up, z);
    checkState("level, sliding", m, &st, z);
  }
  /* lifting at 6.3 mm/s: Hunt-Crossley's factor 1 - c_hc v_n on its clip's smoothing */
  {
    const double x0[3] = {0.0, -2.13e-3, 0.0}, tilt[3] = {0.37e-4, 0.2, -0.29e-4};
    const double v0[3] = {-0.7, 6.3, 0.4}, w[3] = {-0.02, 0.05, 0.013};
    cscShapeState st = footPose(x0, tilt, v0, w);
    anchors(m, &sh, &st, up, z);
    checkState("level, lifting", m, &st, z);
  }
  csc_softDestroy(m);
}


static void test_soft_jacobian_matches_differences_tilted_ground(void) {
  cstTerrain t;
  memset(&t, 0, sizeof t);
  t.nbox = 1;
  const double c[3] = {0, -10, 0}, len[3] = {400, 20, 300}, axis[3] = {0, 0, 1};
  CS_EXPECT(cst_boxOriented(&t.box[0], c, len, axis, 10, -1) == 1);
  cscShape sh;
  cscSoftModel* m = footModel(&t, &sh);
  if (!m) {
    return;
  }
  /* the top face's normal and a point on it; the foot turned with the ground, 1.61 µm deep at
   * its centre and tilted a little more */
  const double th = 10 * CS_PI / 180;
  double n[3] = {-sin(th), cos(th), 0}, top[3], x0[3], z[36];
  csu_addScl3(top, c, n, 10);
  csu_addScl3(x0, top, n, -1.61e-3);
  x0[2] += 3.0;
  const double tilt[3] = {0.71e-4, 0, th + 0.53e-4};
  const double v0[3] = {2.0, 0.3, -0.8}, w[3] = {0.0, 0.031, 0.012};
  cscShapeState st = footPose(x0, tilt, v0, w);
  anchors(m, &sh, &st, n, z);
  checkState("tilted 10 deg", m, &st, z);
  csc_softDestroy(m);
}


static void test_soft_jacobian_matches_differences_over_an_edge(void) {
  /* the ground ends at x = 7.47: the foot's xi = +7.5 column of spheres (rim radius 1 mm) is
   * 0.03 mm past the edge, its closest feature the edge, its normal turned towards +x */
  cstTerrain t = levelGround(7.47);
  cscShape sh;
  cscSoftModel* m = footModel(&t, &sh);
  if (!m) {
    return;
  }
  double z[36], up[3] = {0, 1, 0};
  const double x0[3] = {0.0, -1.83e-3, 0.0}, tilt[3] = {0.41e-4, 0, 0.17e-4};
  const double v0[3] = {1.3, -0.11, 0.6}, w[3] = {0.004, -0.017, 0.009};
  cscShapeState st = footPose(x0, tilt, v0, w);
  anchors(m, &sh, &st, up, z);
  /* the edge column touches (its normal off the vertical) */
  cscSlotInfo slot[9];
  cscShapeLoad ld;
  double zd[36];
  csc_softComputeShape(m, 0, &st, z, &ld, zd, slot, NULL);
  int edge = 0;
  for (int k = 0; k < 9; k++) {
    edge += slot[k].depth > 0 && fabs(slot[k].normal[0]) > 1e-3;
  }
  CS_EXPECT(edge == 3);
  checkState("over an edge", m, &st, z);
  csc_softDestroy(m);
}


/* The step-mode friction's cap (contact_soft_internal.h csc_softFrictionStep): the damped
 * bristle's force is return-mapped, so no slot's friction passes mu N at any slip rate; a slot
 * sliding at 0.5 m/s (tau_t w = 60 stick ranges) is at mu N whatever its anchor; and the
 * derivatives hold where the damping decides the regime: at 8 mm/s tau_t w is one stick
 * range, so anchors at u 0.4 / 1.0 / 1.5 land in stick, on the parabola and saturated by their
 * direction against the slip; at 0.5 m/s all are saturated (only the transverse stiffness mu N
 * / |g| is left). The law before the cap (the rate added after the saturation) read up to
 * 63 mu N on these states. */
static void test_soft_step_friction_capped_at_mu_N(void) {
  cstTerrain t = levelGround(1e3);
  cscShape sh;
  cscSoftModel* m = footModel(&t, &sh);
  if (!m) {
    return;
  }
  const cscSoftParams* p = csc_softParams(m);
  double z[36], up[3] = {0, 1, 0};
  const double speeds[5] = {0.0, 2.0, 8.0, 40.0, 500.0};
  const double dirs[3][3] = {{1, 0, 0}, {-0.6, 0, 0.8}, {0, 0, -1}};
  double worst = 0;
  for (int i = 0; i < 5; i++) {
    for (int j = 0; j < 3; j++) {
      const double x0[3] = {1.0, -1.37e-3, 2.0}, tilt[3] = {0.83e-4, 0, 0.61e-4};
      const double w[3] = {0.011, 0.023, -0.0047};
      double v0[3];
      csu_scale3(v0, dirs[j], speeds[i]);
      v0[1] = -0.23;
      cscShapeState st = footPose(x0, tilt, v0, w);
      anchors(m, &sh, &st, up, z);
      cscSlotInfo slot[9];
      cscShapeLoad ld;
      double zd[36];
      CS_EXPECT(csc_softComputeShape(m, 0, &st, z, &ld, zd, slot, NULL) == 0);
      for (int k = 0; k < 9; k++) {
        if (!(slot[k].depth > 0) || z[4 * k + 3] < 0) {
          continue;
        }
        CS_EXPECT(slot[k].N > 0);
        const double r = csu_norm3(slot[k].ft) / (p->mu * slot[k].N);
        worst = fmax(worst, r);
        CS_EXPECT(r <= 1 + 1e-12);
        if (speeds[i] >= 500) {
          CS_EXPECT_NEAR(r, 1.0, 0, 1e-12);
        }
      }
    }
  }
  printf("largest |F_t| / (mu N) over the slip rates 0..500 mm/s: %.15f\n", worst);
  /* the derivatives where the damping decides the regime */
  const double x0[3] = {1.0, -1.37e-3, 2.0}, tilt[3] = {0.83e-4, 0, 0.61e-4};
  const double w[3] = {0.011, 0.023, -0.0047};
  const double vmid[3] = {8.0, -0.23, 1.3}, vfast[3] = {-470.0, -0.23, 160.0};
  cscShapeState st = footPose(x0, tilt, vmid, w);
  anchors(m, &sh, &st, up, z);
  checkState("level, 8 mm/s", m, &st, z);
  checkTangentRows("level, 8 mm/s", m, &st, z);
  st = footPose(x0, tilt, vfast, w);
  anchors(m, &sh, &st, up, z);
  checkState("level, 0.5 m/s", m, &st, z);
  checkTangentRows("level, 0.5 m/s", m, &st, z);
  csc_softDestroy(m);
}


static void test_soft_jacobian_declines_what_it_does_not_cover(void) {
  cstTerrain t = levelGround(1e3);
  cscSoftModel* m = capsuleFootModel(&t, CSC_HISTORY_STEP);
  if (!m) {
    return;
  }
  double z[40], L[6], K[36], C[36];
  csc_softStateInit(m, z);
  cscShapeState st;
  memset(&st, 0, sizeof st);
  st.x1[0] = 10;
  /* a capsule: the caller differences */
  CS_EXPECT(csc_softShapeJacobian(m, 0, &st, z, L, K, C) == CSC_SOFT_NO_JACOBIAN);
  /* a non-finite pose: recoverable, as the law */
  const double x0[3] = {0, -1e-3, 0}, zero[3] = {0, 0, 0};
  st = footPose(x0, zero, zero, zero);
  st.v0[1] = NAN;
  CS_EXPECT(csc_softShapeJacobian(m, 1, &st, z + 4, L, K, C) == 1);
  CS_EXPECT(csc_softShapeJacobian(m, 5, &st, z, L, K, C) == -1);
  csc_softDestroy(m);
  /* integrated history: not covered */
  m = capsuleFootModel(&t, CSC_HISTORY_INTEGRATED);
  if (m) {
    st = footPose(x0, zero, zero, zero);
    CS_EXPECT(csc_softShapeJacobian(m, 1, &st, z + 3, L, K, C) == CSC_SOFT_NO_JACOBIAN);
    csc_softDestroy(m);
  }
}


static void test_soft_update_load_is_update_then_compute(void) {
  /* a capsule lying 2 µm deep and a sliding foot with anchors in every regime (free ones
   * anchor at the update, saturated ones are pulled to u = 2 - u_elastic): the load at the
   * updated anchors must be the law's evaluated anew, bit for bit */
  cstTerrain t = levelGround(1e3);
  cscSoftModel* m = capsuleFootModel(&t, CSC_HISTORY_STEP);
  if (!m) {
    return;
  }
  double z[40], up[3] = {0, 1, 0};
  csc_softStateInit(m, z);
  cscShapeState st[2];
  memset(&st[0], 0, sizeof st[0]);
  csu_set3(st[0].x0, -20, 2.0 - 2e-3, 30);
  csu_set3(st[0].x1, -8, 2.0 - 1.5e-3, 30);
  csu_set3(st[0].v0, 4.0, -0.1, 0.5);
  csu_set3(st[0].v1, 3.5, 0.05, 0.2);
  const double x0[3] = {1.0, -1.37e-3, 2.0}, tilt[3] = {0.83e-4, 0, 0.61e-4};
  const double v0[3] = {3.1, -0.23, 1.2}, w[3] = {0.011, 0.023, -0.0047};
  st[1] = footPose(x0, tilt, v0, w);
  cscShape foot = csc_softFoot(kHalf);
  anchors(m, &foot, &st[1], up, z + 4);
  /* a second round from the updated anchors: the capsule anchored now */
  for (int round = 0; round < 2; round++) {
    for (int i = 0; i < 2; i++) {
      int off, cnt, first, nsl;
      csc_softShapeState(m, i, &off, &cnt);
      csc_softShapeSlots(m, i, &first, &nsl);
      double za[40], zb[40];
      memcpy(za, z, sizeof z);
      memcpy(zb, z, sizeof z);
      cscShapeLoad la, lb;
      cscSlotInfo sa[9], sb[9];
      cscSoftReport ra, rb;
      double zd[40];
      memset(sa, 0, sizeof sa);
      memset(sb, 0, sizeof sb);
      memset(&ra, 0, sizeof ra);
      memset(&rb, 0, sizeof rb);
      int rca = csc_softUpdateShape(m, i, &st[i], za + off);
      int rca2 = csc_softComputeShape(m, i, &st[i], za + off, &la, zd, sa, &ra);
      int rcb = csc_softUpdateShapeLoad(m, i, &st[i], zb + off, &lb, sb, &rb);
      CS_EXPECT(rca == 0 && rca2 == 0 && rcb == 0);
      CS_EXPECT(memcmp(za, zb, sizeof za) == 0);
      CS_EXPECT(memcmp(&la, &lb, sizeof la) == 0);
      CS_EXPECT(memcmp(sa, sb, (size_t)nsl * sizeof sa[0]) == 0);
      CS_EXPECT(memcmp(&ra, &rb, sizeof ra) == 0);
      /* something to compare: the shape touches, with friction from the second round */
      CS_EXPECT(ra.ncontact > 0);
      if (round == 1) {
        CS_EXPECT(csu_norm3(la.f0) > 0 && fabs(la.f0[0]) > 0);
      }
    }
    for (int i = 0; i < 2; i++) {
      int off, cnt;
      csc_softShapeState(m, i, &off, &cnt);
      csc_softUpdateShape(m, i, &st[i], z + off);
    }
  }
  csc_softDestroy(m);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_soft_jacobian_matches_differences_level_ground);
  CS_RUN(test_soft_jacobian_matches_differences_tilted_ground);
  CS_RUN(test_soft_jacobian_matches_differences_over_an_edge);
  CS_RUN(test_soft_step_friction_capped_at_mu_N);
  CS_RUN(test_soft_jacobian_declines_what_it_does_not_cover);
  CS_RUN(test_soft_update_load_is_update_then_compute);
  return cs_testSummary();
}

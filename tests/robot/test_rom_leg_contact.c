/* test_rom_leg_contact.c: the rom leg's sole in contact (robot/rom/robot_rom.h
 * csr_romModelSetSole) with the soft contact law and its integrated stick-anchor friction
 * (contact_soft.h) inside the leg's implicit integration: a stance sole pushed along the ground
 * holds below the Coulomb limit and slides at the Coulomb force above it (issue 9's criteria,
 * as test_rod_friction: "pushed at 0.9 mu N it creeps less than 1 um/s; sliding, the friction
 * is mu N within 5 %").
 *
 * Set-up: the test block (rom_test_block.h, 2 x 1.5 x 6 mm, 24 Tet10, a basis of 6 static
 * responses) hangs from a hip turned so that the block points down (hip e3 along world -y), no
 * gravity (the normal load is the press alone), its tip face the sole (a csc foot of half side
 * 0.75 mm, the default law). The hip is lowered from 0.05 mm above touching to 0.02 mm below
 * over 0.05 s and held: the normal load N is the step-averaged vertical base wrench.
 *  - hold: a dead load along x on the sole's nodes ramps to 0.9 mu N (0.02 s) and is held
 *    0.5 s; the sole centroid's drift over the last 0.3 s is the creep.
 *  - slide: the hip is dragged along x at 5 mm/s; once steady, the base wrench is the contact
 *    force (no gravity, the leg's momentum constant), so |f_x| / (mu f_y) over the last 0.1 s
 *    is the friction against the Coulomb force.
 *  - restore: a state saved mid-slide steps bit for bit alike from two restores. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "contact_soft.h"
#include "core_math.h"
#include "cs_test.h"
#include "rom_test_block.h"

static const double kPress = 0.02; /* mm below touching */
static const double kH = 1e-3;     /* macro step, s */

typedef struct Rig_ {
  Block b;
  cscSoftModel* cm;
  csrRomModel* m;
  csrRomData* d;
  int nsole;
  int* sole;
  double t;
  csrBaseState base;
} Rig;


static double smooth(double u) {
  u = u < 0 ? 0 : (u > 1 ? 1 : u);
  return u * u * (3 - 2 * u);
}

static double smoothRate(double u) { return (u < 0 || u > 1) ? 0 : 6 * u * (1 - u); }


/* the hip at height y (world, mm) moving at vy and along x at (x, vx); block pointing down */
static csrBaseState hipAt(double x, double vx, double y, double vy) {
  csrBaseState s;
  memset(&s, 0, sizeof s);
  const double R[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0}; /* hip e3 -> world -y, e2 -> world z */
  memcpy(s.R, R, sizeof R);
  csu_set3(s.x, x, y, 0);
  csu_set3(s.v, vx, vy, 0);
  return s;
}


/* the rig; lag: csrRomParams.tangent_lag (mm, 0: a fresh tangent at every Jacobian) */
static void rigCreateLag(Rig* r, double lag) {
  csError err = {0};
  memset(r, 0, sizeof *r);
  blockCreate(&r->b, 4);
  /* the rod's Kelvin-Voigt time (csr_defaultLegParams, 0.02 s). With the block's critical
   * damping of its lowest mode instead (2 / ω_1 = 2.4 ms) the dragged sole rocks and
   * stick-slips (the normal load dropping by a third every 0.145 s) and the mean friction at
   * 5 mm/s is 0.94 mu N (docs/notes/rom.md "--legs rom") */
  csrRomParams par = csr_romDefaultParams();
  par.rho = RHO;
  par.damping_time = 0.02;
  par.rtol = 1e-8;
  par.atol_u = 1e-9;
  par.tangent_lag = lag;
  r->m = csr_romModelCreate(r->b.rom, &par, NULL, &err);
  CS_ASSERT(r->m != NULL);
  cscSoftParams cp = csc_softDefaultParams();
  cstTerrain tr;
  memset(&tr, 0, sizeof tr);
  tr.nbox = 1;
  tr.box[0] = (cstBox){.lo = {-1e3, -20, -150}, .hi = {1e3, 0, 150}};
  cscShape foot = csc_softFoot(0.75);
  foot.radius = 0.2; /* the rim below the block's half width */
  r->cm = csc_softCreate(&cp, &tr, 1, &foot, &err);
  CS_ASSERT(r->cm != NULL);
  r->sole = malloc((size_t)r->b.me->nnode * sizeof(int));
  for (int i = 0; i < r->b.me->nnode; i++) {
    if (fabs(r->b.me->x[3 * i + 2] - BZ) < 1e-9) {
      r->sole[r->nsole++] = i;
    }
  }
  const double I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}; /* the tip face: e3 = hip +z, out */
  CS_ASSERT(csr_romModelSetSole(r->m, r->cm, r->nsole, r->sole, I, &err) == CS_OK);
  r->d = csr_romDataCreate(r->m, &err);
  CS_ASSERT(r->d != NULL);
  r->base = hipAt(0, 0, BZ + 0.05, 0);
  csr_romReset(r->m, r->d, 0.0, &r->base);
  r->t = 0;
}


static void rigCreate(Rig* r) { rigCreateLag(r, 0.0); }


static void rigDestroy(Rig* r) {
  csr_romDataDestroy(r->d);
  csr_romModelDestroy(r->m);
  csc_softDestroy(r->cm);
  free(r->sole);
  blockDestroy(&r->b);
}


/* one macro step to the hip state b1; *w the step-averaged base wrench */
static void step(Rig* r, const csrBaseState* b1, csrWrench* w) {
  csError err = {0};
  const int rc = csr_romAdvance(r->m, r->d, r->t, kH, &r->base, b1, w, &err);
  if (rc != 0) {
    printf("  advance failed: %s\n", err.msg);
  }
  CS_ASSERT(rc == 0);
  r->t += kH;
  r->base = *b1;
}


/* lower the hip 0.05 mm + kPress over 0.05 s, hold 0.05 s; returns N (the vertical wrench) */
static double press(Rig* r) {
  const double T = 0.05, y0 = BZ + 0.05, dy = 0.05 + kPress;
  csrWrench w;
  while (r->t < 2 * T - 0.5 * kH) {
    const double u = (r->t + kH) / T;
    const csrBaseState b1 = hipAt(0, 0, y0 - dy * smooth(u), -dy * smoothRate(u) / T);
    step(r, &b1, &w);
  }
  return w.f[1];
}


/* the sole's slot report at the current state */
static cscSlotInfo soleSlot(Rig* r) {
  const int n = r->m->n;
  double* Fc = malloc((size_t)n * sizeof(double));
  double zd[8], wb[3];
  csu_mulMatTVec3(wb, r->base.R, r->base.w);
  cscSlotInfo slot;
  csr_romSoleLoad(r->m, r->base.R, r->base.x, r->base.v, wb, csr_romQ(r->d), csr_romQdot(r->d),
                  csr_romZ(r->d), Fc, zd, NULL, NULL, &slot);
  free(Fc);
  return slot;
}


/* the sole centroid's world x (mm) */
static double soleX(const Rig* r) {
  const double* q = csr_romQ(r->d);
  double x = r->base.x[0] + r->m->Xs[0];
  for (int k = 0; k < r->m->n; k++) {
    x += r->m->Us[k] * q[k];
  }
  return x;
}


static void stance_sole_holds_below_the_coulomb_limit(void) {
  Rig r;
  rigCreate(&r);
  const double N = press(&r);
  const double mu = csc_softParams(r.cm)->mu;
  CS_ASSERT(N > 0);
  const int n = r.m->n;
  double* f = calloc(3 * (size_t)r.b.me->nnode, sizeof(double));
  double* fr = malloc((size_t)n * sizeof(double));
  const double t0 = r.t, ramp = 0.02, F = 0.9 * mu * N;
  double x_start = 0, t_start = 0;
  csrWrench w;
  while (r.t < t0 + 0.52 - 0.5 * kH) {
    const double s = smooth((r.t + kH - t0) / ramp);
    for (int a = 0; a < r.nsole; a++) {
      f[3 * r.sole[a]] = F * s / r.nsole; /* hip x = world x */
    }
    csf_romProject(r.b.rom, f, fr);
    csr_romSetDeadLoad(r.m, r.d, fr);
    step(&r, &r.base, &w);
    if (t_start == 0 && r.t > t0 + 0.22 - 0.5 * kH) {
      x_start = soleX(&r);
      t_start = r.t;
    }
  }
  const double creep = (soleX(&r) - x_start) / (r.t - t_start);
  long st, nr, nj, nre;
  csr_romStats(r.d, &st, &nr, &nj, &nre);
  printf("  N = %.5g N, push 0.9 mu N = %.5g N: sole displaced %.4g mm, creep %.3g um/s over "
         "the last 0.3 s (%ld steps, %ld rhs, %ld jacobians)\n",
         N, F, soleX(&r) - r.m->Xs[0], creep * 1e3, st, nr, nj);
  CS_EXPECT(fabs(creep) < 1e-3); /* mm/s */
  free(f), free(fr);
  rigDestroy(&r);
}


static void dragged_sole_slides_at_the_coulomb_force(void) {
  Rig r;
  rigCreate(&r);
  const double N0 = press(&r);
  const double mu = csc_softParams(r.cm)->mu;
  const double v = 5.0, ramp = 0.02, t0 = r.t;
  double fx = 0, fy = 0, x = 0;
  int cnt = 0;
  csrWrench w;
  while (r.t < t0 + 0.3 - 0.5 * kH) {
    const double u = (r.t + kH - t0) / ramp;
    /* the hip's x: v (t - t0) eased in over the ramp (∫ smooth) */
    const double s = u < 1 ? u * u * u * (1 - 0.5 * u) : u - 0.5;
    x = v * ramp * s;
    csrBaseState b1 = hipAt(x, v * smooth(u), BZ - kPress, 0);
    step(&r, &b1, &w);
    if (r.t > t0 + 0.2 - 0.5 * kH) {
      fx += w.f[0];
      fy += w.f[1];
      cnt++;
    }
  }
  fx /= cnt;
  fy /= cnt;
  const double ratio = fabs(fx) / (mu * fy);
  const cscSlotInfo sl = soleSlot(&r);
  printf("  slot: N %.5g ft (%.4g %.4g %.4g) ratio %.4f sliding %d torsion %.3g\n", sl.N,
         sl.ft[0], sl.ft[1], sl.ft[2], sl.ratio, sl.sliding, sl.torsion);
  printf("  N at rest %.5g N; sliding at %g mm/s: f = (%.5g, %.5g) N, |f_x| / (mu f_y) = %.4f; "
         "hip %.3g mm, sole %.3g mm\n", N0, v, fx, fy, ratio, x, soleX(&r) - r.m->Xs[0]);
  CS_EXPECT(fabs(ratio - 1) < 0.05);
  CS_EXPECT(fx < 0); /* against the motion */
  rigDestroy(&r);
}


/* a state saved mid-slide (the bristle at the Coulomb limit, the hip moving) restored into the
 * same data steps bit for bit as from the first restore: the friction history is state */
static void restored_sliding_state_steps_bit_for_bit(void) {
  Rig r;
  rigCreate(&r);
  press(&r);
  const double v = 5.0;
  for (int s = 0; s < 60; s++) {
    const double x = v * (r.t + kH - 0.1) * (r.t + kH > 0.1);
    const csrBaseState b1 = hipAt(x, v, BZ - kPress, 0);
    step(&r, &b1, NULL);
  }
  const int ns = csr_romStateSize(r.m);
  CS_EXPECT(ns == 1 + 2 * r.m->n + 44 + r.m->nz);
  double* x0 = malloc((size_t)ns * sizeof(double));
  double* xa = malloc((size_t)ns * sizeof(double));
  double* xb = malloc((size_t)ns * sizeof(double));
  csr_romGetState(r.m, r.d, x0);
  const csrBaseState base0 = r.base;
  const double t0 = r.t;
  double zmax = 0;
  for (int i = 0; i < r.m->nz; i++) {
    zmax = fmax(zmax, fabs(csr_romZ(r.d)[i]));
  }
  CS_EXPECT(zmax > 0); /* the bristle is loaded: the restore has something to restore */
  for (int pass = 0; pass < 2; pass++) {
    CS_ASSERT(csr_romSetState(r.m, r.d, x0) == 0);
    r.t = t0;
    r.base = base0;
    for (int s = 0; s < 20; s++) {
      const double x = v * (r.t + kH - 0.1);
      const csrBaseState b1 = hipAt(x, v, BZ - kPress, 0);
      step(&r, &b1, NULL);
    }
    csr_romGetState(r.m, r.d, pass == 0 ? xa : xb);
  }
  CS_EXPECT(memcmp(xa, xb, (size_t)ns * sizeof(double)) == 0);
  x0[ns - 1] = NAN;
  CS_EXPECT(csr_romSetState(r.m, r.d, x0) < 0);
  free(x0), free(xa), free(xb);
  rigDestroy(&r);
}


/* the lagged tangent (csrRomParams.tangent_lag): a Jacobian keeps the reduced FE tangent while
 * the leg has moved less than the lag, its contact part always fresh. On the block pressed and
 * then dragged (touch-down, stick, slip) it must follow the run with a fresh tangent at every
 * Jacobian to the integration's tolerance, and take fewer tangents than Jacobians (the fresh
 * run: one per Jacobian) */
static void lagged_tangent_follows_the_fresh_one_with_fewer_tangents(void) {
  Rig r[2];
  csrRomStats st[2];
  double sx[2];
  csrWrench w[2];
  for (int k = 0; k < 2; k++) {
    rigCreateLag(&r[k], k ? 1e-3 : 0.0); /* 1e-3 mm: 5 % of the press */
    press(&r[k]);
    const double v = 5.0, t0 = r[k].t;
    while (r[k].t < t0 + 0.1 - 0.5 * kH) {
      const double x = v * (r[k].t + kH - t0);
      const csrBaseState b1 = hipAt(x, v, BZ - kPress, 0);
      step(&r[k], &b1, &w[k]);
    }
    csr_romGetStats(r[k].d, &st[k]);
    sx[k] = soleX(&r[k]) - r[k].m->Xs[0];
    printf("  tangent lag %g mm: %ld steps, %ld rhs, %ld jacobians, %ld tangents, %ld Newton "
           "failures, %ld error test failures; sole x %.9f mm, wrench (%.9f, %.9f) N\n",
           k ? 1e-3 : 0.0, st[k].steps, st[k].rhs, st[k].jacs, st[k].tangents, st[k].nl_fails,
           st[k].err_fails, sx[k], w[k].f[0], w[k].f[1]);
  }
  const int n = r[0].m->n;
  double dq = 0, qmax = 0;
  for (int i = 0; i < n; i++) {
    dq = fmax(dq, fabs(csr_romQ(r[0].d)[i] - csr_romQ(r[1].d)[i]));
    qmax = fmax(qmax, fabs(csr_romQ(r[0].d)[i]));
  }
  printf("  q differs by %.3g of %.3g; sole x by %.3g mm; wrench y by %.3g N\n", dq, qmax,
         fabs(sx[0] - sx[1]), fabs(w[0].f[1] - w[1].f[1]));
  CS_EXPECT(st[0].tangents == st[0].jacs);
  CS_EXPECT(st[1].jacs > 0 && st[1].tangents < st[1].jacs);
  CS_EXPECT(dq <= 1e-4 * qmax);
  CS_EXPECT(fabs(sx[0] - sx[1]) <= 1e-5); /* mm: 1e-4 of the 0.1 mm the sole slid */
  CS_EXPECT(fabs(w[0].f[1] - w[1].f[1]) <= 1e-4 * fabs(w[0].f[1]));
  for (int k = 0; k < 2; k++) {
    rigDestroy(&r[k]);
  }
}


/* the sole's derivatives of csr_romSoleJacobian (the law's in the foot's coordinates, chained
 * through the sole's pose in q, q') against central differences of csr_romSoleLoad itself in
 * every q, q' and z: pressed and sticking, then dragged and sliding, with the hip turning at
 * 20 rad/s and the sole tilted by 0.02 rad (so that the pose's ω × Ū and exp's left Jacobian
 * terms count). Each block (q, q', z) within 1e-4 of its largest entry */
static void sole_jacobian_matches_differences_of_the_sole_load(void) {
  Rig r;
  rigCreate(&r);
  press(&r);
  const int n = r.m->n, nz = r.m->nz, nc = 2 * n + nz;
  double* G = malloc((size_t)(6 + nz) * nc * sizeof(double));
  double* work = malloc((size_t)csr_romSoleWorkSize(r.m) * sizeof(double));
  double* Fp = malloc((size_t)n * sizeof(double));
  double* Fm = malloc((size_t)n * sizeof(double));
  double* y = malloc((size_t)nc * sizeof(double));
  double* vmax = calloc((size_t)n, sizeof(double));
  for (int k = 0; k < n; k++) {
    for (int i = 0; i < r.b.rom->ndof; i++) {
      vmax[k] = fmax(vmax[k], fabs(r.b.rom->V[(size_t)i * n + k]));
    }
  }
  for (int state = 0; state < 2; state++) {
    if (state == 1) { /* drag: the bristle at the Coulomb limit */
      const double v = 5.0, t0 = r.t;
      while (r.t < t0 + 0.06 - 0.5 * kH) {
        const csrBaseState b1 = hipAt(v * (r.t + kH - t0), v, BZ - kPress, 0);
        step(&r, &b1, NULL);
      }
    }
    memcpy(y, csr_romQ(r.d), (size_t)n * sizeof(double));
    memcpy(y + n, csr_romQdot(r.d), (size_t)n * sizeof(double));
    memcpy(y + 2 * n, csr_romZ(r.d), (size_t)nz * sizeof(double));
    /* tilt the sole by 0.02 rad about the hip's x (least squares on the W rows: the q of
     * smallest norm with W q = θ) */
    {
      const double th[3] = {0.02, 0, 0};
      double WWt[9] = {0}, Wi[9], c[3];
      for (int i = 0; i < 3; i++) {
        for (int j = 0; j < 3; j++) {
          for (int k = 0; k < n; k++) {
            WWt[3 * i + j] += r.m->Ws[(size_t)i * n + k] * r.m->Ws[(size_t)j * n + k];
          }
        }
      }
      const double det = WWt[0] * (WWt[4] * WWt[8] - WWt[5] * WWt[7]) -
                         WWt[1] * (WWt[3] * WWt[8] - WWt[5] * WWt[6]) +
                         WWt[2] * (WWt[3] * WWt[7] - WWt[4] * WWt[6]);
      CS_ASSERT(fabs(det) > 0);
      Wi[0] = (WWt[4] * WWt[8] - WWt[5] * WWt[7]) / det;
      Wi[1] = (WWt[2] * WWt[7] - WWt[1] * WWt[8]) / det;
      Wi[2] = (WWt[1] * WWt[5] - WWt[2] * WWt[4]) / det;
      Wi[3] = (WWt[5] * WWt[6] - WWt[3] * WWt[8]) / det;
      Wi[4] = (WWt[0] * WWt[8] - WWt[2] * WWt[6]) / det;
      Wi[5] = (WWt[2] * WWt[3] - WWt[0] * WWt[5]) / det;
      Wi[6] = (WWt[3] * WWt[7] - WWt[4] * WWt[6]) / det;
      Wi[7] = (WWt[1] * WWt[6] - WWt[0] * WWt[7]) / det;
      Wi[8] = (WWt[0] * WWt[4] - WWt[1] * WWt[3]) / det;
      csu_mulMatVec3(c, Wi, th);
      for (int k = 0; k < n; k++) {
        for (int i = 0; i < 3; i++) {
          y[k] += r.m->Ws[(size_t)i * n + k] * c[i];
        }
      }
    }
    const double w[3] = {20.0, -10.0, 5.0}; /* rad/s, hip frame */
    const double* R = r.base.R;
    double L[6], zd[8], zp[8], zm[8];
    CS_ASSERT(nz <= 8);
    CS_ASSERT(csr_romSoleJacobian(r.m, R, r.base.x, r.base.v, w, y, y + n, y + 2 * n, L, zd, G,
                                  work) == 0);
    CS_EXPECT(fabs(L[1]) > 0); /* the sole is loaded */
    /* A = [Ūᵀ Rᵀ, Wᵀ Rᵀ]: the reduced force's derivatives from G's first six rows */
    double err[3] = {0, 0, 0}, big[3] = {0, 0, 0};
    for (int c = 0; c < nc; c++) {
      const int blk = c < n ? 0 : (c < 2 * n ? 1 : 2);
      const double h = c < 2 * n ? 1e-6 / vmax[c % n] : 1e-8;
      const double y0 = y[c];
      y[c] = y0 + h;
      CS_ASSERT(csr_romSoleLoad(r.m, R, r.base.x, r.base.v, w, y, y + n, y + 2 * n, Fp, zp,
                                NULL, NULL, NULL) == 0);
      y[c] = y0 - h;
      CS_ASSERT(csr_romSoleLoad(r.m, R, r.base.x, r.base.v, w, y, y + n, y + 2 * n, Fm, zm,
                                NULL, NULL, NULL) == 0);
      y[c] = y0;
      for (int k = 0; k < n; k++) {
        double a = 0;
        for (int i = 0; i < 3; i++) {
          for (int j = 0; j < 3; j++) {
            a += r.m->Us[(size_t)i * n + k] * R[3 * j + i] * G[(size_t)j * nc + c] +
                 r.m->Ws[(size_t)i * n + k] * R[3 * j + i] * G[(size_t)(3 + j) * nc + c];
          }
        }
        const double fd = (Fp[k] - Fm[k]) / (2 * h);
        err[blk] = fmax(err[blk], fabs(a - fd));
        big[blk] = fmax(big[blk], fabs(fd));
      }
      for (int i = 0; i < nz; i++) {
        const double fd = (zp[i] - zm[i]) / (2 * h);
        err[blk] = fmax(err[blk], fabs(G[(size_t)(6 + i) * nc + c] - fd));
        big[blk] = fmax(big[blk], fabs(fd));
      }
    }
    printf("  %s: N %.4g N; against differences: q %.2e of %.3g, q' %.2e of %.3g, z %.2e of "
           "%.3g\n", state ? "sliding" : "sticking", L[1], err[0], big[0], err[1], big[1],
           err[2], big[2]);
    for (int b = 0; b < 3; b++) {
      CS_EXPECT(big[b] > 0);
      CS_EXPECT(err[b] <= 1e-4 * big[b]);
    }
  }
  free(G), free(work), free(Fp), free(Fm), free(y), free(vmax);
  rigDestroy(&r);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(stance_sole_holds_below_the_coulomb_limit);
  CS_RUN(dragged_sole_slides_at_the_coulomb_force);
  CS_RUN(restored_sliding_state_steps_bit_for_bit);
  CS_RUN(lagged_tangent_follows_the_fresh_one_with_fewer_tangents);
  CS_RUN(sole_jacobian_matches_differences_of_the_sole_load);
  return cs_testSummary();
}

/* test_rod_friction.c: friction on the rod leg's real foot (csr_leg_rod with the soft contact of
 * contact_soft.h on the flat road, through the leg interface): a stance foot pushed along the
 * road holds below the Coulomb limit and slides at the Coulomb force above it (issue 9: "a
 * stance foot pushed at 0.9 mu N for 2 s creeps less than 1 um/s; at 1.1 mu N and at 2 mu N it
 * slides with the Coulomb force within 5 %").
 *
 * Set-up: one weightless leg (conditions `paper`: no gravity on it, so the normal load is the
 * press alone) hanging from a hip that is lowered 0.5 mm below touching over 0.2 s
 * (quasi-static, as test_rod_leg) and held 0.3 s: the normal load N is then the step-averaged
 * vertical wrench (0.48 N). A tip force F along +x (csr_rodLegSetTipLoad, on the foot node)
 * ramps to k mu N over 0.05 s.
 *  - k = 0.9, hip held: the foot's drift over the last 1.5 s of a 2 s push is the creep.
 *  - k = 1.1 and 2: the foot slides; the hip follows it (its velocity each macro step is the
 *    foot's over the last one), so the leg is carried, not bent, and the friction force comes
 *    from the leg's momentum balance over a window of the slide: F_fric = dP/dt - F - F_hip,
 *    with F_hip = -W the support's force on the leg (W the step-averaged base wrench, impulses
 *    summed over the window) and P the leg's momentum (from the mass moment, central
 *    differences); N alike from the vertical balance. No gravity acts, so nothing else does.
 * The 5 % of the issue is the test's tolerance on |F_fric| / (mu N); measured values are in the
 * cases' comments. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "contact_soft.h"
#include "cs_test.h"
#include "robot_rod.h"
#include "rod_test_road.h"

enum { NCL = 2 };
static const double kH = 5e-3; /* macro step (s) */

typedef struct {
  const csrLegType* T;
  csrLeg* leg;
  csrActuator act;
  csrLegParams lp;
  cstTerrain tr;
  cscContactParams cp;
  csrBaseState b; /* the hip now */
  double t;
} Rig;


static double smooth(double u) {
  u = u < 0 ? 0 : (u > 1 ? 1 : u);
  return u * u * (3 - 2 * u);
}


/* foot (tip node) x, world mm */
static double footX(const Rig* r) {
  double cl[3 * NCL];
  r->T->centerline(r->leg, NCL, cl);
  return cl[3 * (NCL - 1)];
}


/* leg's first mass moment (t mm) */
static void massMoment(const Rig* r, double mx[3]) { r->T->massMoment(r->leg, mx); }


/* one macro step with the hip moving from r->b to b1; the step-averaged wrench in *w */
static int step(Rig* r, const csrBaseState* b1, csrWrench* w) {
  const double p[12] = {0};
  csError err;
  cs_errorClear(&err);
  int rc = r->T->actuate(r->leg, r->t, p, r->t + kH, p);
  if (rc == 0) {
    rc = r->T->advance(r->leg, r->t, kH, &r->b, b1, w, &err);
  }
  if (rc != 0) {
    fprintf(stderr, "  t = %g: %s\n", r->t, err.msg);
    return rc;
  }
  r->b = *b1;
  r->t += kH;
  return 0;
}


/* a leg standing on the road with its hip 0.5 mm below touching at x = x0; the normal load
 * (N) it settles to */
static int rigCreate(Rig* r, double x0, double mu, double* N) {
  memset(r, 0, sizeof *r);
  csError err;
  cs_errorClear(&err);
  csr_actuatorPreset(&r->act, "leg", &err);
  r->lp = csr_defaultLegParams(&r->act);
  r->tr = csTestFlatRoad();
  r->cp = csc_defaultContactParams();
  r->cp.mu = mu;
  csrLegSpec sp;
  memset(&sp, 0, sizeof sp);
  sp.act = &r->act;
  sp.params = &r->lp;
  const double F[9] = {1, 0, 0, 0, 0, -1, 0, 1, 0};
  memcpy(sp.frame, F, sizeof F);
  sp.hip[0] = x0;
  sp.hip[1] = csr_actuatorLength(&r->act);
  sp.h = 1e-3;
  sp.weightless = 1;
  sp.terrain = &r->tr;
  sp.contact = &r->cp;
  r->T = &csr_leg_rod;
  r->leg = r->T->create(&sp, &err);
  if (!r->leg) {
    fprintf(stderr, "  %s\n", err.msg);
    return 1;
  }
  memcpy(r->b.x, sp.hip, sizeof r->b.x);
  memcpy(r->b.R, F, sizeof F);
  /* press 0.5 mm over 0.2 s, hold 0.3 s */
  const double y0 = sp.hip[1], delta = 0.5, ramp = 0.2;
  csrWrench w;
  for (int k = 0; k < 100; k++) {
    csrBaseState b1 = r->b;
    double u = fmin(1, (k + 1) * kH / ramp);
    b1.x[1] = y0 - delta * smooth(u);
    b1.v[1] = u < 1 ? -delta * 6 * u * (1 - u) / ramp : 0;
    if (step(r, &b1, &w) != 0) {
      return 1;
    }
  }
  *N = w.f[1];
  return 0;
}


static void pushAt(Rig* r, double F) {
  const double f[3] = {F, 0, 0}, m[3] = {0, 0, 0};
  csr_rodLegSetTipLoad(r->leg, f, m);
}


static void stance_foot_holds_at_0p9_mu_N(void) {
  Rig r;
  double N = 0;
  CS_EXPECT(rigCreate(&r, 0, 0.8, &N) == 0);
  if (!r.leg) {
    return;
  }
  const double mu = 0.8, ramp = 0.05;
  double x_start = NAN, t_start = NAN;
  csrWrench w;
  for (int k = 0; k < (int)lround(2.0 / kH); k++) {
    double tau = (k + 1) * kH;
    pushAt(&r, 0.9 * mu * N * smooth(tau / ramp));
    csrBaseState b1 = r.b;
    if (step(&r, &b1, &w) != 0) {
      CS_EXPECT(0);
      break;
    }
    if (isnan(x_start) && tau >= 0.5) {
      x_start = footX(&r);
      t_start = tau;
    }
  }
  double creep = (footX(&r) - x_start) / (2.0 - t_start); /* mm/s */
  printf("  N = %.4f N, push 0.9 mu N = %.4f N for 2 s: creep %.3g um/s over the last 1.5 s\n",
         N, 0.9 * mu * N, creep * 1e3);
  /* the bound, 1 um/s; measured 1.6e-14 um/s (the bristle below u_elastic is purely
   * elastic: no plastic flow at 0.9 of the limit) */
  CS_EXPECT(fabs(creep) < 1e-3);
  r.T->destroy(r.leg);
}


/* slide at k mu N: the friction force over [t0, t1] after the ramp, from the momentum balance
 * (header), against mu N */
static void slideAt(double k, double* ratio, double* speed) {
  Rig r;
  double N0 = 0;
  *ratio = NAN;
  CS_EXPECT(rigCreate(&r, -200, 0.8, &N0) == 0);
  if (!r.leg) {
    return;
  }
  const double mu = 0.8, ramp = 0.05, t0 = ramp + 0.02, t1 = ramp + 0.12;
  const double F = k * mu * N0;
  double J[3] = {0, 0, 0};     /* impulse of W over the window */
  double mx_prev[3], mx_a[3] = {0}, mx_b[3] = {0}, P0[3] = {0}, P1[3] = {0};
  double foot_prev = footX(&r), xs = NAN, xe = NAN;
  massMoment(&r, mx_prev);
  csrWrench w;
  const int n = (int)lround((t1 + kH) / kH);
  for (int i = 0; i < n; i++) {
    double tau = (i + 1) * kH;
    pushAt(&r, F * smooth(tau / ramp));
    /* the hip follows the foot: its velocity over this step is the foot's over the last */
    double vf = (footX(&r) - foot_prev) / kH;
    foot_prev = footX(&r);
    csrBaseState b1 = r.b;
    b1.v[0] = i == 0 ? 0 : vf;
    b1.x[0] = r.b.x[0] + 0.5 * kH * (r.b.v[0] + b1.v[0]);
    if (step(&r, &b1, &w) != 0) {
      CS_EXPECT(0);
      r.T->destroy(r.leg);
      return;
    }
    double mx[3];
    massMoment(&r, mx);
    /* P at tau - H/2 by the step's difference; the window's ends are whole steps */
    double P[3];
    for (int c = 0; c < 3; c++) {
      P[c] = (mx[c] - mx_prev[c]) / kH;
    }
    if (fabs(tau - t0) < 1e-9) {
      memcpy(P0, P, sizeof P0);
      memcpy(mx_a, mx, sizeof mx_a);
      xs = footX(&r);
    }
    if (tau > t0 + 1e-9 && tau <= t1 + 1e-9) {
      for (int c = 0; c < 3; c++) {
        J[c] += kH * w.f[c];
      }
    }
    if (fabs(tau - t1) < 1e-9) {
      memcpy(P1, P, sizeof P1);
      memcpy(mx_b, mx, sizeof mx_b);
      xe = footX(&r);
    }
    memcpy(mx_prev, mx, sizeof mx_prev);
  }
  /* the momenta are mid-step values: the balance over the window shifted by H/2 on both ends,
   * with the impulse of the constant push and the hip's impulse over the window */
  const double T = t1 - t0;
  double Ffric = (P1[0] - P0[0]) / T - F + J[0] / T;
  double N = (P1[1] - P0[1]) / T + J[1] / T;
  *ratio = -Ffric / (mu * N);
  *speed = (xe - xs) / T;
  printf("  push %.1f mu N0 = %.4f N: N = %.4f N, friction %.4f N = %.4f mu N, foot speed "
         "%.0f mm/s\n", k, F, N, -Ffric, *ratio, *speed);
  (void)mx_a;
  (void)mx_b;
  r.T->destroy(r.leg);
}


static void pushed_foot_slides_at_the_coulomb_force(void) {
  double ratio = NAN, v = NAN;
  slideAt(1.1, &ratio, &v);
  /* measured 1.012 mu N at 164 mm/s (the Dupont bristle saturates at u = 1: mu N exactly in
   * steady sliding; the rest is its damping while the slide accelerates and the momentum
   * balance's half-step offsets) */
  CS_EXPECT(v > 10);
  CS_EXPECT_NEAR(ratio, 1.0, 0.05, 0);
  slideAt(2.0, &ratio, &v);
  /* measured 1.028 mu N at 1.1 m/s (N rises from 0.48 to 0.72 N: the push on the sole's
   * centre tips the foot onto its front edge) */
  CS_EXPECT(v > 100);
  CS_EXPECT_NEAR(ratio, 1.0, 0.05, 0);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(stance_foot_holds_at_0p9_mu_N);
  CS_RUN(pushed_foot_slides_at_the_coulomb_force);
  return cs_testSummary();
}

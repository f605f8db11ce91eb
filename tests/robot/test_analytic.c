/* test_analytic.c: the analytic actuator model and constant-curvature forward kinematics
 * (robot_analytic.h) against closed-form answers, plus the bend-file writer (robot_bend_io.h).
 *
 * Closed forms used here are derived independently of the library's code paths:
 *  - section area and second moment of the filleted square minus four disks by the
 *    parallel-axis theorem (sectionClosedForm);
 *  - the linear limit of the model (robot_analytic.h D7): λ0 - 1 = Σ p_j A / (E' A_c),
 *    κ_S = Σ p_j A c_j Lc / (S E' I) with E' = 8 C10 (the λ2 = 1 small-strain modulus of
 *    W = C10 (I1-3) + C20 (I1-3)^2: W ≈ 4 C10 ε² = E' ε² / 2);
 *  - pure elongation: A_c dW/dλ = Σ p_j A, solved by bisection with W written through
 *    I1 = λ² + 1 + λ⁻² (not the library's (λ - 1/λ)² form);
 *  - the arc tip (R (1 - cos θ), R sin θ), R = λ0 S / θ. */
#include <hdf5.h>
#include <hdf5_hl.h>
#include <math.h>
#include <stdio.h>

#include "cs_test.h"
#include "robot_analytic.h"
#include "robot_bend_io.h"

/* closed-form section properties (mm^2, mm^4) */
typedef struct {
  double area_holed, I_holed, area_full, I_full;
} ClosedSection;


static ClosedSection sectionClosedForm(const csrActuator* act) {
  double a = act->a, b = act->b, r1 = act->r1, r2 = act->r2, d = a - r2;
  ClosedSection cs;
  cs.area_full = 4 * a * a - (4 - CS_PI) * r2 * r2;
  /* one corner: square [d,a]^2 minus the quarter disk centred (d,d), moments about x1 = 0:
   * ∫ x² over the square = r2 (a³ - d³)/3; over the quarter disk d² A + 2 d r2³/3 + π r2⁴/16 */
  double corner =
      r2 * (a * a * a - d * d * d) / 3 -
      (d * d * CS_PI * r2 * r2 / 4 + 2 * d * r2 * r2 * r2 / 3 + CS_PI * r2 * r2 * r2 * r2 / 16);
  cs.I_full = 4 * a * a * a * a / 3 - 4 * corner;
  cs.area_holed = cs.area_full - 4 * CS_PI * r1 * r1;
  cs.I_holed = cs.I_full - 4 * (CS_PI * r1 * r1 * r1 * r1 / 4 + CS_PI * r1 * r1 * b * b);
  return cs;
}


static csrActuator preset(const char* name) {
  csrActuator act;
  csError err;
  if (csr_actuatorPreset(&act, name, &err) != CS_OK) {
    fprintf(stderr, "preset %s: %s\n", name, err.msg);
  }
  return act;
}


/* dW/dλ of the Yeoh law along λ2 = 1, λ3 = 1/λ, written through I1 */
static double yeohSlope(const csrActuator* act, double lam) {
  double I1 = lam * lam + 1 + 1 / (lam * lam);
  double dI1 = 2 * lam - 2 / (lam * lam * lam);
  return (act->C10 + 2 * act->C20 * (I1 - 3)) * dI1;
}


static void test_sectionQuadrature(void) {
  const char* names[] = {"fig1", "baseline", "leg"};
  for (int i = 0; i < 3; i++) {
    csrActuator act = preset(names[i]);
    csrSectionProps sp;
    csError err;
    CS_EXPECT(csr_analyticSectionCompute(&act, NULL, &sp, &err) == CS_OK);
    ClosedSection cf = sectionClosedForm(&act);
    /* polynomial integrands over exact patches: only the angular rule is inexact; measured
     * relative error at the default order 16 is <= 1.5e-13 for these and the sections below */
    CS_EXPECT_NEAR(sp.area_holed, cf.area_holed, 0, 1e-12);
    CS_EXPECT_NEAR(sp.I_holed, cf.I_holed, 0, 1e-12);
    CS_EXPECT_NEAR(sp.area_full, cf.area_full, 0, 1e-12);
    CS_EXPECT_NEAR(sp.I_full, cf.I_full, 0, 1e-12);
  }
  /* the paper's r1 study geometry (b = 3, r1 = 2.5) and a sharp-cornered section (r2 = 0) */
  csrActuator act = preset("baseline");
  csError err;
  CS_EXPECT(csr_actuatorSet(&act, "b", 3.0, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r1", 2.5, &err) == CS_OK);
  CS_EXPECT(csr_actuatorSet(&act, "r2", 0.0, &err) == CS_OK);
  csrSectionProps sp;
  CS_EXPECT(csr_analyticSectionCompute(&act, NULL, &sp, &err) == CS_OK);
  ClosedSection cf = sectionClosedForm(&act);
  CS_EXPECT_NEAR(sp.area_holed, cf.area_holed, 0, 1e-12); /* as above */
  CS_EXPECT_NEAR(sp.I_holed, cf.I_holed, 0, 1e-12);
}


/* (a) small pressure: linear beam theory */
static void test_linearBeamLimit(void) {
  const char* names[] = {"fig1", "baseline"};
  for (int i = 0; i < 2; i++) {
    csrActuator act = preset(names[i]);
    ClosedSection cf = sectionClosedForm(&act);
    double Ep = 8 * act.C10;          /* C20 enters W only at fourth order in ε */
    const double p = 1e-5;            /* MPa */
    const double P[4] = {p, p, 0, 0}; /* Ω1 & Ω2 */
    double A = CS_PI * act.r1 * act.r1;
    for (int s = 0; s < CSR_NSEG; s++) {
      csrSegmentStrain st;
      csError err;
      CS_EXPECT(csr_analyticSegment(&act, s, P, &st, &err) == CS_OK);
      double S = act.S[s], Lc = S - 2 * act.c;
      double kappa = p * A * (2 * act.b) * Lc / (S * Ep * cf.I_holed);
      double eps = 2 * p * A / (Ep * cf.area_holed);
      /* the model deviates from linear by relative O(3ε/2), ε = |κ_c| a + (λ_c - 1) ≈ 4.4e-6
       * the largest strain at this pressure: measured 5.0e-6 (κ) and 4.6e-6 (ε); 2e-5 */
      CS_EXPECT_NEAR(st.kappa[0], kappa, 0, 2e-5);
      CS_EXPECT_NEAR(st.lambda_c - 1, eps, 0, 2e-5);
      CS_EXPECT_NEAR(st.theta, kappa * S, 0, 2e-5);
      /* by mirror symmetry of the section and the load, κ2 vanishes to round-off */
      CS_EXPECT_NEAR(st.kappa[1], 0, 1e-12 * kappa, 0);
      /* Ω1 & Ω2 bend towards Ω3 & Ω4: the tip moves to -e1 */
      CS_EXPECT(st.kappa[0] > 0);
      CS_EXPECT_NEAR(fabs(st.phi), CS_PI, 1e-12, 0); /* exact angle up to round-off */
    }
  }
}


/* (b) Ω1&Ω3 and all four: zero bending, elongation from the 1-D balance A_c W'(λ) = Σ p A */
static void test_pureElongation(void) {
  csrActuator act = preset("baseline");
  ClosedSection cf = sectionClosedForm(&act);
  const double pressures[] = {0.05, 0.2, 0.4, 1.0};
  for (int k = 0; k < 4; k++) {
    double p = pressures[k];
    const double sets[2][4] = {{p, 0, p, 0}, {p, p, p, p}};
    for (int m = 0; m < 2; m++) {
      csrSegmentStrain st;
      csError err;
      CS_EXPECT(csr_analyticSegment(&act, 1, sets[m], &st, &err) == CS_OK);
      /* 1-D closed form by bisection on λ in [1, 10] */
      double force = (m == 0 ? 2 : 4) * p * CS_PI * act.r1 * act.r1;
      double lo = 1, hi = 10;
      for (int it = 0; it < 200; it++) {
        double mid = 0.5 * (lo + hi);
        if (cf.area_holed * yeohSlope(&act, mid) < force) {
          lo = mid;
        } else {
          hi = mid;
        }
      }
      double lam = 0.5 * (lo + hi);
      /* quadrature error of A_c (~1e-15) and Newton's 1e-12 step bound: 1e-10 */
      CS_EXPECT_NEAR(st.lambda_c, lam, 0, 1e-10);
      double S = act.S[1], Lc = S - 2 * act.c;
      CS_EXPECT_NEAR(st.lambda0, (lam * Lc + 2 * act.c) / S, 0, 1e-10); /* as above */
      /* symmetric load on a symmetric section: κ = 0 up to round-off (|κ| a < 1e-13) */
      CS_EXPECT_NEAR(st.kappa[0] * act.a, 0, 1e-13, 0);
      CS_EXPECT_NEAR(st.kappa[1] * act.a, 0, 1e-13, 0);
      CS_EXPECT(st.phi == 0.0);
    }
  }
}


/* (c) symmetry: opposite pairs give opposite curvature; single chambers bend diagonally, and
 * every set bends towards minus its pressure moment Σ p_j c_j (8 directions) */
static void test_symmetry(void) {
  csrActuator act = preset("baseline");
  const double p = 0.3;
  csrSegmentStrain a12, a34;
  csError err;
  const double P12[4] = {p, p, 0, 0}, P34[4] = {0, 0, p, p};
  CS_EXPECT(csr_analyticSegment(&act, 0, P12, &a12, &err) == CS_OK);
  CS_EXPECT(csr_analyticSegment(&act, 0, P34, &a34, &err) == CS_OK);
  /* mirror-image problems: each solve stops with |dκ| a <= 1e-12, i.e. |dκ| <= 1.3e-13
   * against κ_S ≈ 1.1e-2 (relative 1.2e-11); measured 4e-16; tolerance 1e-10 */
  CS_EXPECT_NEAR(a34.kappa[0], -a12.kappa[0], 0, 1e-10);
  CS_EXPECT_NEAR(a34.theta, a12.theta, 0, 1e-10);
  CS_EXPECT_NEAR(a34.lambda_c, a12.lambda_c, 0, 1e-11); /* |dλ0| <= 1e-12 on λ0 ≈ 1.06 */
  CS_EXPECT(a12.theta > 0);

  /* Ω1 alone: along the diagonal, towards Ω3 at (-b,-b): phi = -135° */
  const double P1[4] = {p, 0, 0, 0};
  csrSegmentStrain a1;
  CS_EXPECT(csr_analyticSegment(&act, 0, P1, &a1, &err) == CS_OK);
  CS_EXPECT_NEAR(a1.kappa[0], a1.kappa[1], 0, 1e-10); /* diagonal symmetry, as above */
  CS_EXPECT_NEAR(a1.phi, -0.75 * CS_PI, 1e-10, 0);    /* angle error ~ |dκ|/|κ| <= 1.2e-11 */

  /* the 8 bending modes: singles and adjacent pairs; direction = -(Σ p_j c_j) */
  const double cx[4] = {1, 1, -1, -1}, cy[4] = {1, -1, -1, 1};
  for (int j = 0; j < 4; j++) {
    for (int n = 1; n <= 2; n++) {
      double P[4] = {0, 0, 0, 0}, mx = 0, my = 0;
      for (int k = 0; k < n; k++) {
        int c = (j + k) % 4;
        P[c] = p;
        mx += cx[c];
        my += cy[c];
      }
      csrSegmentStrain st;
      CS_EXPECT(csr_analyticSegment(&act, 2, P, &st, &err) == CS_OK);
      double expect = atan2(-my, -mx);
      /* angle difference wrapped to (-π, π]; exact by symmetry up to |dκ|/|κ| <= 2e-11 */
      double diff = remainder(st.phi - expect, 2 * CS_PI);
      CS_EXPECT_NEAR(diff, 0, 1e-10, 0);
    }
  }
  /* Ω1&Ω2&Ω4 bends towards Ω3 like Ω1 alone */
  const double P124[4] = {p, p, 0, p};
  csrSegmentStrain a124;
  CS_EXPECT(csr_analyticSegment(&act, 0, P124, &a124, &err) == CS_OK);
  CS_EXPECT_NEAR(a124.phi, -0.75 * CS_PI, 1e-10, 0); /* as above */
  CS_EXPECT(a124.lambda_c > a1.lambda_c);            /* the extra chambers elongate */
}


/* a straight, unstretched strain */
static csrSegmentStrain straight(void) {
  csrSegmentStrain s = {0};
  s.lambda0 = 1;
  s.lambda_c = 1;
  return s;
}


/* (d) forward kinematics: one arc, directions, S-shape, centreline */
static void test_forwardKinematics(void) {
  csrActuator act = preset("baseline");
  csError err;
  const double thetas[] = {1e-9, 0.3, 1.3, 2 * CS_PI - 0.1};
  const double psis[] = {0, 0.7, -2.1};
  for (int i = 0; i < 4; i++) {
    for (int j = 0; j < 3; j++) {
      double th = thetas[i], psi = psis[j], lam = 1.1;
      double S = act.S[2];
      csrSegmentStrain st[3] = {straight(), straight(), straight()};
      st[2].lambda0 = lam;
      st[2].kappa[0] = th / S * cos(psi);
      st[2].kappa[1] = th / S * sin(psi);
      double tip[3], R[9];
      CS_EXPECT(csr_ccForwardKinematics(&act, st, 1, NULL, tip, R, &err) == CS_OK);
      /* R (1 - cos θ) and R sin θ with R = L / θ, L = λ0 S, in cancellation-free form */
      double L = lam * S, z0 = act.S[0] + act.LS[0] + act.S[1] + act.LS[1];
      double lateral = L * 2 * sin(th / 2) * sin(th / 2) / th; /* towards -κ̂ */
      /* trigonometric round-off of the Rodrigues/series forms: 1e-12 mm on ~200 mm */
      CS_EXPECT_NEAR(tip[0], -lateral * cos(psi), 1e-12, 0);
      CS_EXPECT_NEAR(tip[1], -lateral * sin(psi), 1e-12, 0);
      CS_EXPECT_NEAR(tip[2], z0 + L * sin(th) / th, 1e-12, 0);
      /* tip axis (third column) tilted by θ towards -κ̂ */
      CS_EXPECT_NEAR(R[2], -sin(th) * cos(psi), 1e-14, 0);
      CS_EXPECT_NEAR(R[5], -sin(th) * sin(psi), 1e-14, 0);
      CS_EXPECT_NEAR(R[8], cos(th), 1e-14, 0);
    }
  }
  /* S-shape: II1 one way, II2 the other, equal angles -> the foot is vertical again */
  const double th = 0.8;
  csrSegmentStrain st[3] = {straight(), straight(), straight()};
  st[0].kappa[0] = th / act.S[0];
  st[1].kappa[0] = -th / act.S[1];
  int n = 16, K = csr_ccCenterlineCount(n);
  double cl[3 * 3 * 17], tip[3], R[9];
  CS_EXPECT(K == 3 * 17);
  CS_EXPECT(csr_ccForwardKinematics(&act, st, n, cl, tip, R, &err) == CS_OK);
  for (int i = 0; i < 9; i++) {
    CS_EXPECT_NEAR(R[i], (i % 4 == 0) ? 1.0 : 0.0, 1e-15, 0); /* R1 R1^T = I to round-off */
  }
  /* foot offset: -2 R (1 - cos θ) - LS12 sin θ along e1 (both arcs and the tilted joint) */
  double Rr = act.S[0] / th;
  CS_EXPECT_NEAR(tip[0], -2 * Rr * (1 - cos(th)) - act.LS[0] * sin(th), 1e-12, 0);
  CS_EXPECT_NEAR(tip[2], 2 * Rr * sin(th) + act.LS[0] * cos(th) + act.LS[1] + act.S[2], 1e-12,
                 0); /* as above */
  /* centreline: starts at the base, ends at the tip, chords of the arcs add up exactly */
  CS_EXPECT(cl[0] == 0 && cl[1] == 0 && cl[2] == 0);
  for (int k = 0; k < 3; k++) {
    CS_EXPECT_NEAR(cl[3 * (K - 1) + k], tip[k], 1e-12, 0); /* same composition, round-off */
  }
  double len = 0;
  for (int r = 1; r < K; r++) {
    double d[3];
    csu_sub3(d, &cl[3 * r], &cl[3 * (r - 1)]);
    len += csu_norm3(d);
  }
  double chords = 2 * n * 2 * Rr * sin(th / (2 * n)) + act.LS[0] + act.LS[1] + act.S[2];
  CS_EXPECT_NEAR(len, chords, 1e-11, 0); /* sum of 51 lengths, each to ~1e-14 */
}


/* (e) the angle grows monotonically with pressure (Ω1&Ω2, baseline, 0..2 MPa) */
static void test_monotone(void) {
  csrActuator act = preset("baseline");
  double prev = -1, prev_lam = 0;
  for (int i = 0; i <= 100; i++) {
    double p = 0.02 * i;
    const double P[4] = {p, p, 0, 0};
    csrSegmentStrain st;
    csError err;
    CS_EXPECT(csr_analyticSegment(&act, 0, P, &st, &err) == CS_OK);
    CS_EXPECT(st.theta > prev);
    CS_EXPECT(st.lambda_c >= prev_lam);
    CS_EXPECT(st.iterations <= 10); /* 1-5 measured; a regression guard for the solver */
    prev = st.theta;
    prev_lam = st.lambda_c;
  }
}


/* quadrature error of the solution: raising the orders to 24 changes θ by < 1e-12 relative */
static void test_quadratureConvergence(void) {
  csrActuator act = preset("baseline");
  const double P[4] = {1.0, 1.0, 0, 0.3};
  csrAnalyticOptions lo = csr_analyticDefaultOptions(), hi = lo;
  hi.nquad = 24;
  hi.nquad_r = 24;
  csrSegmentStrain a, b;
  csError err;
  CS_EXPECT(csr_analyticSegmentWith(&act, 0, P, &lo, &a, &err) == CS_OK);
  CS_EXPECT(csr_analyticSegmentWith(&act, 0, P, &hi, &b, &err) == CS_OK);
  /* measured 2e-15; 1e-12 is the accuracy the header promises */
  CS_EXPECT_NEAR(a.theta, b.theta, 0, 1e-12);
  CS_EXPECT_NEAR(a.lambda_c, b.lambda_c, 0, 1e-12);
}


/* the paper's single-DOF variant in its linear limit */
static void test_paperVariantLinear(void) {
  csrActuator act = preset("baseline");
  ClosedSection cf = sectionClosedForm(&act);
  double Ep = 8 * act.C10, A = CS_PI * act.r1 * act.r1, p = 1e-5;
  double S = act.S[0], Lc = S - 2 * act.c, h = act.a; /* κ̂ = e1, passive face at -a */
  /* Π(t) ≈ E'/2 t² [Lc (I_c + A_c h²) + 2c (I_o + A_o h²)] - t Σ p A Lc (h + c_j·κ̂) */
  double t = 2 * p * A * Lc * (h + act.b) /
             (Ep * (Lc * (cf.I_holed + cf.area_holed * h * h) +
                    2 * act.c * (cf.I_full + cf.area_full * h * h)));
  const double P[4] = {p, p, 0, 0};
  csrSegmentStrain st;
  csError err;
  CS_EXPECT(csr_analyticSegmentPaper(&act, 0, P, NULL, &st, &err) == CS_OK);
  /* nonlinear terms of relative order 3ε/2 with ε = 2 a t ≈ 2.9e-6: measured 3.3e-6; 2e-5 */
  CS_EXPECT_NEAR(st.theta, t * S, 0, 2e-5);
  /* the constraint λ0 = 1 + h θ/S itself holds to round-off */
  CS_EXPECT_NEAR(st.lambda0, 1 + st.theta / S * h, 0, 1e-14);
  /* and it stays a bending-only model: Ω1&Ω3 give no deformation at all */
  const double P13[4] = {0.2, 0, 0.2, 0};
  CS_EXPECT(csr_analyticSegmentPaper(&act, 0, P13, NULL, &st, &err) == CS_OK);
  CS_EXPECT(st.theta == 0 && st.lambda0 == 1);
}


/* bad arguments come back as status codes with a message, output untouched */
static void test_badInput(void) {
  csrActuator act = preset("baseline");
  csrSegmentStrain st = straight(), keep = st;
  csError err;
  const double P[4] = {0.1, 0.1, 0, 0};
  CS_EXPECT(csr_analyticSegment(&act, 3, P, &st, &err) == CS_ERR_ARG);
  CS_EXPECT(csr_analyticSegment(&act, -1, P, &st, &err) == CS_ERR_ARG);
  const double Pnan[4] = {NAN, 0, 0, 0}, Pneg[4] = {0, -0.1, 0, 0};
  CS_EXPECT(csr_analyticSegment(&act, 0, Pnan, &st, &err) == CS_ERR_RANGE);
  CS_EXPECT(csr_analyticSegment(&act, 0, Pneg, &st, &err) == CS_ERR_RANGE);
  CS_EXPECT(err.msg[0] != '\0');
  /* chamber breaking the outer wall (csr_actuatorValidate) */
  csrActuator bad = act;
  bad.r1 = 3.6;
  CS_EXPECT(csr_analyticSegment(&bad, 0, P, &st, &err) == CS_ERR_RANGE);
  /* chamber passes the straight-wall check but cuts the corner fillet */
  bad = act;
  bad.b = 6;
  bad.r1 = 1.2;
  bad.r2 = 3;
  CS_EXPECT(csr_analyticSegment(&bad, 0, P, &st, &err) == CS_ERR_RANGE);
  /* too few Newton iterations: solver failure, output unchanged */
  csrAnalyticOptions o = csr_analyticDefaultOptions();
  o.max_iter = 1;
  const double Phigh[4] = {1.0, 1.0, 0, 0};
  CS_EXPECT(csr_analyticSegmentWith(&act, 0, Phigh, &o, &st, &err) == CS_ERR_SOLVER);
  CS_EXPECT(memcmp(&st, &keep, sizeof st) == 0);
  o = csr_analyticDefaultOptions();
  o.nquad = 2;
  CS_EXPECT(csr_analyticSegmentWith(&act, 0, P, &o, &st, &err) == CS_ERR_ARG);
  /* forward kinematics */
  csrSegmentStrain s3[3] = {straight(), straight(), straight()};
  double tip[3], cl[9];
  CS_EXPECT(csr_ccForwardKinematics(&act, s3, 0, cl, tip, NULL, &err) == CS_ERR_ARG);
  s3[1].lambda0 = 0;
  CS_EXPECT(csr_ccForwardKinematics(&act, s3, 1, NULL, tip, NULL, &err) == CS_ERR_RANGE);
}


/* the bend file: datasets and attributes read back */
static void test_bendFileRoundTrip(void) {
  csrActuator act = preset("leg");
  csrBendCurve bc;
  csError err;
  CS_EXPECT(csr_bendCurveInit(&bc, 1, &err) == CS_OK);
  const double ang[3] = {1, 2, 3}, tip[3] = {-4, 0, 160};
  for (int i = 0; i < 3; i++) {
    CS_EXPECT(csr_bendCurvePush(&bc, 0.1 * i, ang, tip, &err) == CS_OK);
  }
  bc.p_until_angle = 0.25;
  csrBendMeta meta = {"analytic", "1,2", NAN, 0, 0, 0.5, 360, NAN, NAN, 0, 0, 0, NAN, -1, NAN, 0};
  const char* path = "test_analytic_bend.h5";
  csH5File* f = cs_h5Create(path, &err);
  CS_EXPECT(f != NULL);
  CS_EXPECT(csr_bendCurveWriteH5(f, &act, &bc, &meta, &err) == CS_OK);
  cs_h5Close(f);

  hid_t fid = H5Fopen(path, H5F_ACC_RDONLY, H5P_DEFAULT);
  CS_EXPECT(fid >= 0);
  hsize_t dims[2] = {0, 0};
  H5T_class_t cls;
  size_t tsize;
  CS_EXPECT(H5LTget_dataset_info(fid, "/angle_deg", dims, &cls, &tsize) >= 0);
  CS_EXPECT(dims[0] == 3 && dims[1] == 3);
  double tp[9], total[3];
  CS_EXPECT(H5LTread_dataset_double(fid, "/tip_position", tp) >= 0);
  CS_EXPECT(tp[6] == -4 && tp[8] == 160);
  CS_EXPECT(H5LTread_dataset_double(fid, "/angle_total_deg", total) >= 0);
  CS_EXPECT(total[2] == 6);
  double v = 0;
  CS_EXPECT(H5LTget_attribute_double(fid, "/", "p_until_angle_MPa", &v) >= 0 && v == 0.25);
  CS_EXPECT(H5LTget_attribute_double(fid, "/", "LS12", &v) >= 0 && v == 8);
  CS_EXPECT(H5LTget_attribute_double(fid, "/", "mesh_size_mm", &v) >= 0 && isnan(v));
  char model[32] = "";
  CS_EXPECT(H5LTget_attribute_string(fid, "/", "model", model) >= 0);
  CS_EXPECT(strcmp(model, "analytic") == 0);
  H5Fclose(fid);
  remove(path);
  csr_bendCurveFree(&bc);
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_sectionQuadrature);
  CS_RUN(test_linearBeamLimit);
  CS_RUN(test_pureElongation);
  CS_RUN(test_symmetry);
  CS_RUN(test_forwardKinematics);
  CS_RUN(test_monotone);
  CS_RUN(test_quadratureConvergence);
  CS_RUN(test_paperVariantLinear);
  CS_RUN(test_badInput);
  CS_RUN(test_bendFileRoundTrip);
  return cs_testSummary();
}

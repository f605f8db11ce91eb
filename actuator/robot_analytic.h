/* robot_analytic.h: the analytic (constant-curvature, virtual-work) actuator model of paper
 * Sec. 3, made consistent, and the constant-curvature forward kinematics of paper Eq. (10).
 *
 * Owns: csrSegmentStrain (the strain of one segment: stretch, curvature vector, angle,
 * direction), the equilibrium of one segment or of the three segments of an actuator for any
 * set of chamber pressures (8 bending directions and elongation), the paper's single-DOF
 * variant, the section quadrature, and csr_ccForwardKinematics, which every leg model may call
 * to turn segment strains into a centreline and a tip pose.
 *
 * Units: mm, MPa (N/mm^2), N, rad. Frames: the actuator's base frame has e3 along the
 * undeformed axis from base to tip and (e1, e2) the cross-section frame of robot_actuator.h:
 * Ω1 = (+b,+b), Ω2 = (+b,-b), Ω3 = (-b,-b), Ω4 = (-b,+b); e1 = robot +x when the leg hangs
 * straight, e2 = robot +z. Segments and chambers are 0-based in this API (seg 0 = II1,
 * chamber 0 = Ω1).
 *
 * ---- Sign convention ----------------------------------------------------------------------
 * kappa = (κ1, κ2) is the *stretch-gradient* curvature: the axial stretch of the material line
 * at section point x = (x1, x2) is λ(x) = λ0 + κ·x. The side at +κ is stretched (convex side),
 * so the centreline turns towards -κ and the tip moves towards dir = -κ/|κ|. Example: Ω1&Ω2
 * (at +e1) inflated gives κ1 > 0, κ2 = 0, and the tip moves to -e1 (towards Ω3&Ω4), phi = π.
 * The Darboux (rotation-rate) vector of the centreline in the section frame, per undeformed
 * length, is u = (κ2, -κ1, 0): a Cosserat-rod model uses u, this model uses κ.
 *
 * ---- Derivation (rationale) ---------------------------------------------------------------
 * The paper's Eq. (4) is inconsistent (1 + a/R is the stretch at distance a from a neutral
 * centreline, 1 + 2aθ/S the stretch of the inflated face when the opposite face, at 2a, is
 * inextensible) and its Eq. (5) for the deformed volume is garbled. Eq. (8), P dV2 = V1 dW,
 * evaluates one homogeneous W over the whole silicone although the stretch varies across the
 * section. We derive instead:
 *  (D1) Kinematics. Plane sections stay plane and normal to the centreline; the fibres hold
 *       every circumference (λ2 = 1) and the section keeps its shape and chamber radii. The
 *       chambered length Lc = S - 2c bends into a circular arc of angle θ = |κ| Lc with
 *       centreline length λ0 Lc; the line at x has length (λ0 + κ·x) Lc, so λ(x) = λ0 + κ·x
 *       exactly on the arc.
 *  (D2) Material. Incompressible with λ2 = 1: λ3 = 1/λ, I1 - 3 = λ² + λ⁻² - 2 = (λ - 1/λ)², so
 *       W(λ) = C10 f + C20 f², f = (λ - 1/λ)². W'' = (C10 + 2 C20 f) 2(1 + 3λ⁻⁴) + 2 C20 f'² > 0:
 *       W is strictly convex on λ > 0 and W -> inf as λ -> 0. For λ = 1 + ε, W ≈ 4 C10 ε² =
 *       E'ε²/2 with E' = 8 C10, the plane-strain modulus E/(1 - ν²) of E = 6 C10, ν = 1/2.
 *  (D3) Energy. U = Lc ∫_{A_c} W(λ0 + κ·x) dA over the holed section A_c (filleted square minus
 *       the four chamber disks). The end caps (length c each) store no energy: the gas pressure
 *       on a closed chamber is self-equilibrated, so every cut through a cap leaves a free body
 *       with zero net load; the caps stay straight and unstrained (St-Venant effects aside).
 *  (D4) Chamber volume (replaces Eqs. 5-7). Chamber j keeps its area A = π r1² (λ2 = 1) and its
 *       axis is the material line at c_j, so by Pappus V_j = A Lc (λ0 + κ·c_j). The paper's
 *       V2 = V - V1 - V3 is the same volume obtained by subtraction.
 *  (D5) Equilibrium (virtual work, replaces Eq. 8): Π(λ0, κ) = U - Σ p_j V_j is stationary,
 *         ∫ W'(λ) dA = Σ p_j A,     ∫ W'(λ) x dA = Σ p_j A c_j                      (A5)
 *       (section force and moment balance the chamber end forces p_j A acting at c_j). Π is
 *       strictly convex and coercive: the solution exists, is unique, and a damped Newton
 *       iteration from the straight state converges (3 unknowns λ0, κ1, κ2).
 *  (D6) Segment as one constant-curvature arc (paper Eq. 10): the angle θ = |κ| Lc is spread
 *       over the whole segment, kappa_S = κ Lc / S, lambda_S = (λ0 Lc + 2c) / S (same angle,
 *       same deformed length). Joints LS12, LS23 are unloaded solids: straight, unstretched.
 *  (D7) Linear limit. With I = ∫ x1² dA = ∫ x2² dA (the section is invariant under 90°
 *       rotations, so ∫ x1 x2 dA = 0): λ0 - 1 = Σ p_j A / (E' A_c), κ = Σ p_j A c_j / (E' I),
 *       hence kappa_S = Σ p_j A c_j Lc / (S E' I).
 * Consequences: Ω1&Ω3 or all four at equal pressure give Σ p_j c_j = 0, hence κ = 0 and pure
 * elongation; Ω1 alone bends along the diagonal towards Ω3; Ω1&Ω2&Ω4 bends towards Ω3 less.
 * The fibre turns n_i do not enter: any n > 0 is taken to enforce λ2 = 1 (for n = 0 the model
 * is outside its assumptions).
 *
 * Paper single-DOF variant (csr_analyticSegmentPaper): the consistent reading of Eqs. (3)-(8)
 * is one unknown t = θ/S, the passive extreme fibre inextensible (λ = 1 + t (h + κ̂·x), h the
 * distance from the axis to the section's edge on the -κ̂ side; h = a for Ω1&Ω2, giving the
 * paper's λ1 = 1 + 2aθ/S at the inflated face), uniform curvature over the whole S with the
 * full-section caps bending along (V1 of Eq. 3), energy ∫ W dV instead of V1 W(λ1), and the
 * direction κ̂ fixed along the pressure moment Σ p_j c_j. It cannot elongate (κ = 0 -> λ = 1).
 *
 * Section integrals: each quadrant cell [0,a]² (with its corner fillet) is integrated in polar
 * coordinates about its chamber centre (b,b): r from r1 (holed) or 0 (full) to the cell
 * boundary ρ(φ), φ split at the five boundary kinks, Gauss-Legendre in φ (order nquad) and r
 * (nquad_r); the four quadrants are mirror images. All weights are positive and the geometry is
 * exact, so the error decays exponentially with the order. Measured relative error of area and
 * second moment for the presets / for the paper's b = 3, r1 = 2.5 study: angular order 8:
 * 3e-8 / 1e-6, 12: 2e-12 / 5e-10, 16: 2e-13 / 2e-13, 20: round-off. The radial order matters
 * only for W (λ varies little along a ray): order 4 gives 4e-9 in θ at 5 MPa, 8 round-off.
 * The defaults (16, 8) make 2560 integrand evaluations per section pass; θ changes by < 1e-12
 * relative when both orders are raised to 24 (test_analytic). A segment solve takes 3-8
 * Newton passes, ~0.2 ms on a 2-core VM (~0.08 ms at nquad 6). No allocation; ~1 KB of stack. */
#ifndef CS_ROBOT_ANALYTIC_H
#define CS_ROBOT_ANALYTIC_H

#include "core_status.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Strain of one segment (csr_analyticSegment fills it; any leg model may fill it for FK). */
typedef struct csrSegmentStrain_ {
  double lambda0;    /* centreline stretch over the segment: deformed arc length / S (-) */
  double kappa[2];   /* stretch-gradient curvature over S (1/mm), (e1, e2): λ(x) = lambda0 +
                        kappa·x; the centreline turns towards -kappa; theta = |kappa| S */
  double theta;      /* bending angle of the segment (rad), >= 0 */
  double phi;        /* direction the tip moves, angle from e1 towards e2 (rad, (-π, π]);
                        0 when theta <= the solver's tol_step (straight) */
  double lambda_c;   /* centreline stretch of the chambered part Lc (D1) (-) */
  double kappa_c[2]; /* curvature of the chambered part per undeformed length (1/mm) */
  int iterations;    /* Newton iterations used (0 for strains not from this model) */
} csrSegmentStrain;

/* Solver options; csr_analyticDefaultOptions() gives the values used by the CLI. */
typedef struct csrAnalyticOptions_ {
  int nquad;       /* angular Gauss order per boundary patch, 4..CSR_ANALYTIC_MAX_NQUAD */
  int nquad_r;     /* radial Gauss order, 2..CSR_ANALYTIC_MAX_NQUAD */
  double tol_step; /* convergence: |dλ0| + a |dκ| of the last Newton step (-) */
  int max_iter;    /* Newton iteration limit; exceeding it returns CS_ERR_SOLVER */
} csrAnalyticOptions;

#define CSR_ANALYTIC_MAX_NQUAD 32

/* Defaults: nquad 16, nquad_r 8, tol_step 1e-12, max_iter 100. */
csrAnalyticOptions csr_analyticDefaultOptions(void);

/* Section properties from the model's quadrature (for reports and tests). */
typedef struct csrSectionProps_ {
  double area_holed; /* silicone area of the chambered section A_c (mm^2) */
  double I_holed;    /* ∫ x1² dA = ∫ x2² dA over A_c (mm^4) */
  double area_full;  /* area of the filleted square (caps, joints) (mm^2) */
  double I_full;     /* ∫ x1² dA over the filleted square (mm^4) */
} csrSectionProps;

/* Integrate the section properties with the options' quadrature (opt NULL = defaults). */
csStatus csr_analyticSectionCompute(const csrActuator* act, const csrAnalyticOptions* opt,
                                    csrSectionProps* out, csError* err);

/* Equilibrium (A5) of segment `seg` (0..2) under chamber pressures p[4] (MPa, >= 0, index 0 =
 * Ω1). Fills *out. Returns CS_ERR_ARG / CS_ERR_RANGE for bad arguments or an invalid actuator
 * (csr_actuatorValidate, plus chambers inside the fillets), CS_ERR_SOLVER if Newton does not
 * converge (out is then left unchanged). */
csStatus csr_analyticSegment(const csrActuator* act, int seg, const double p[4],
                             csrSegmentStrain* out, csError* err);

/* Same with explicit options (NULL = defaults). */
csStatus csr_analyticSegmentWith(const csrActuator* act, int seg, const double p[4],
                                 const csrAnalyticOptions* opt, csrSegmentStrain* out,
                                 csError* err);

/* All three segments: p[4 s + j] is the pressure of chamber j of segment s (MPa), row-major
 * (CSR_NSEG x CSR_NCHAMBER). This is the layout of one leg's block of the 96-label pressure
 * vector (label - 1 = 12 k + 4 s + j), so a caller passes &p96[12 k] for leg k. Flat rather
 * than double[3][4] because C17 does not convert double (*)[4] to const double (*)[4]. */
csStatus csr_analyticActuator(const csrActuator* act, const double p[CSR_NSEG * CSR_NCHAMBER],
                              csrSegmentStrain out[CSR_NSEG], csError* err);

/* The paper's single-DOF variant (header rationale): same arguments as csr_analyticSegmentWith;
 * lambda_c/kappa_c equal lambda0/kappa (the curvature is uniform over S). */
csStatus csr_analyticSegmentPaper(const csrActuator* act, int seg, const double p[4],
                                  const csrAnalyticOptions* opt, csrSegmentStrain* out,
                                  csError* err);

/* Pose of a constant-curvature piece of undeformed length s (mm), centreline stretch lambda0
 * and stretch-gradient curvature kappa[2] (1/mm), relative to its start frame: pos[3] (mm) and
 * row-major R[9] whose columns are the end frame's axes. Exact and smooth at kappa -> 0. */
void csr_ccArcPose(double s, double lambda0, const double kappa[2], double pos[3], double R[9]);

/* Number of centreline rows written by csr_ccForwardKinematics: CSR_NSEG * (nsample + 1). */
static inline int csr_ccCenterlineCount(int nsample_per_segment) {
  return CSR_NSEG * (nsample_per_segment + 1);
}

/* Forward kinematics (paper Eq. 10): the base frame times, per segment, a constant-curvature
 * arc of length S_i with strains[i] (lambda0, kappa), with straight unstretched joints LS12,
 * LS23 between segments. Each segment's kappa is read in the frame of its own base section,
 * which the previous pieces carry along without twist (so equal kappa in all segments bends
 * the actuator in one plane). Writes, when centerline != NULL, csr_ccCenterlineCount(n) rows
 * (K x 3, mm): for each segment its start and n points equally spaced in arc length up to its
 * end (consecutive segments' end/start rows are joined by the straight joint). tip[3]: centre
 * of the tip face (mm); R_tip[9] (row-major, may be NULL): the tip frame's axes as columns.
 * CS_ERR_ARG if nsample_per_segment < 1 while centerline != NULL; CS_ERR_RANGE if a stretch is
 * not > 0 or a strain is not finite. */
csStatus csr_ccForwardKinematics(const csrActuator* act, const csrSegmentStrain strains[CSR_NSEG],
                                 int nsample_per_segment, double* centerline, double tip[3],
                                 double R_tip[9], csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_ANALYTIC_H */

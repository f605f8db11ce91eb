/* robot_calibration_model.h: the calibration model the leg levels read: per segment, the bend
 * vector (intrinsic curvature x S), the centreline stretch, the radial growth (contact radius)
 * and the stiffness EI, EA as functions of the segment's FOUR chamber pressures, built from an FE
 * mode table (robot_calibration_table.h).
 *
 * Owns: csrCalModel (built once from a table, constant afterwards, no allocation when
 * evaluated), its evaluation, the stiffness rule, and the comparison of the model with any case
 * of a table (fitted, held out, symmetry) for reports and tests.
 *
 * ---- The rule (rationale; the measured errors are in README "Calibration") ----------------
 * Symmetry. The section (square, four chambers at (±b, ±b), a symmetric pair of helices) is
 * invariant under quarter turns and the four mirror lines. A pattern of pressures is brought to
 * the canonical form p1 >= p2, p3, p4 and p2 >= p4 by a turn (the highest chamber to Ω1) and the
 * mirror Ω2 <-> Ω4; the result is turned and mirrored back. So every chamber set not run is the
 * image of a run one, Ω2 alone is Ω1 alone turned by -90 deg (the table's O2 case checks it),
 * and a pattern invariant under a mirror bends along that mirror's line: the FE's bend component
 * across it is mesh asymmetry and is removed; a pattern with zero pressure moment m = (p1 + p2 -
 * p3 - p4, p1 - p2 - p3 + p4) (Ω1&Ω3, all four) bends by exactly zero.
 * Shape and scale. Canonical pressures are P (the highest, the load factor of every case, which
 * also bounds the table's range) times the shape x = (x2, x3, x4) = (p2, p3, p4) / P, 0 <= x4
 * <= x2 <= 1, 0 <= x3 <= 1: a triangular prism whose six corners are all fitted modes: Ω1
 * (0,0,0), Ω1&Ω3 (0,1,0), Ω1&Ω2 (1,0,0), Ω1&Ω2&Ω4 (1,0,1), its mirror Ω1&Ω2&Ω3 (1,1,0), all four
 * (1,1,1). Four more modes refine it: Ω1&Ω2 at 1 : 0.5 on the edge Ω1 -> Ω1&Ω2 (x2 = 0.5), the
 * paper's case 4 (1, 1, 1/3, 1/3) inside the face x2 = 1, and Ω1 above the other three at 0.5
 * and at 0.75 (1, a, a, a) inside the face x4 = x2, where the leg stretches 25-36 % and the
 * superposition under-predicts the highest chamber's bend (without them held-out H3 missed by
 * 4.4 deg / 20.6 mm; with 0.75 alone Ω1 0.4 + the others 0.2 missed by 7.2 deg / 27.5 mm).
 * Field. Each fitted mode k gives, per segment and row, the bend as a component a along -m̂
 * (towards the vented side, the direction the section's symmetry gives) and b across it, and
 * the changes of stretch, radial growth and largest radial growth from the rest row. These are
 * interpolated over the prism at the point's P (each mode's rows by a monotone cubic in p,
 * Fritsch-Carlson, exact at the rows): trilinear in (x2, x4/x2, x3) between the six corners,
 * plus hierarchical bumps of the refining modes (a hat in x2 on the edge; a tensor hat in
 * (x4, x3) on the face x2 = 1; on the face x4 = x2 tensor hats in (x2, x3) times x4/x2, the
 * one at 0.75 supported on [0.5, 1] when the one at 0.5 exists, as a sparse grid's levels),
 * each zero at the modes before it and on every face where the canonical form is ambiguous (the
 * face x4 = x2 is the mirror's own line: there the bend lies along it), so the field is
 * continuous across them and equivariant.
 * Base. CSR_CAL_RULE_SUPERPOSITION interpolates the difference from the superposition of the
 * single-chamber response (Ω1 alone, turned to each chamber: bend -Σ_j θ1(p_j) ĉ_j, stretch
 * 1 + Σ_j δλ1(p_j), ...); CSR_CAL_RULE_INTERPOLATION interpolates the modes' values directly.
 * Both return every fitted row (to round-off) and zero bend at m = 0; they differ between the
 * modes, where the table's held-out cases decide (robot_calibration.h names the default).
 * CSR_CAL_RULE_RBF (opt-in) keeps the superposition but interpolates the residuals by a
 * Gaussian RBF over the modes' symmetric images instead of the prism's hats
 * (robot_calibration_rbf.c has its rationale and measured errors); CSR_CAL_RULE_RBF_PAIR (opt-in)
 * does the same over a superposition with a fitted factor per opposite chamber pair
 * (robot_calibration_pair.c).
 * Stiffness. EI (the mean of the e1 and e2 probes: the section's second moment is isotropic)
 * and EA per segment as piecewise-linear functions of the mean chamber pressure p̄ = Σ p_j / 4
 * through the probes of every probed mode (probes at equal p̄ averaged); NaN probes skipped.
 * Range. Pressures up to the smallest end among the modes used (a mode that met a pressure limit
 * point ends there: past it a pressure-controlled actuator snaps); above it eval returns
 * CSR_MAP_OUT_OF_RANGE, never an extrapolation. Stiffness: p̄ up to the highest probe's.
 * Cost: a few comparisons, one Hermite cubic per mode in range, no allocation (~1 µs).
 *
 * Units: mm, MPa, N, rad. Segments 0..2 (II1..II3), chambers 0..3 (Ω1..Ω4). */
#ifndef CS_ROBOT_CALIBRATION_MODEL_H
#define CS_ROBOT_CALIBRATION_MODEL_H

#include <stdio.h>

#include "core_status.h"
#include "robot_actuator.h"
#include "robot_calibration_table.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum csrCalRule_ {
  CSR_CAL_RULE_SUPERPOSITION = 0, /* single-chamber superposition + interpolated interactions */
  CSR_CAL_RULE_INTERPOLATION = 1, /* the modes' values interpolated over the shape prism */
  CSR_CAL_RULE_MEAN = 2,          /* scalars only: the all-four response at the mean pressure
                                     + interpolated differences */
  CSR_CAL_RULE_SCALED = 3,        /* bend only: the superposition scaled by a mean-pressure
                                     factor fitted to the bending modes + interpolated
                                     interactions */
  CSR_CAL_RULE_RBF = 4,           /* bend and scalars: the superposition (the scalar rule's base
                                     for the scalars) + the modes' differences from it
                                     interpolated by a Gaussian RBF over the symmetric images
                                     of their shapes (robot_calibration_rbf.c); opt-in */
  CSR_CAL_RULE_RBF_PAIR = 5,      /* as RBF, the bend's superposition with a factor per
                                     opposite chamber pair fitted to the bending modes (the
                                     other pair's pressure stiffens, the pair's lower pressure
                                     stretches: robot_calibration_pair.c); opt-in */
} csrCalRule;

/* The fitted modes by role (csr_calModelModePattern gives their chamber ratios). */
typedef enum csrCalRole_ {
  CSR_CAL_O1 = 0,    /* Ω1 alone (corner, and the superposition's single-chamber response) */
  CSR_CAL_O13,       /* Ω1&Ω3 (corner, elongation) */
  CSR_CAL_O12,       /* Ω1&Ω2 (corner) */
  CSR_CAL_O124,      /* Ω1&Ω2&Ω4 (corner; its mirror image Ω1&Ω2&Ω3 is another corner) */
  CSR_CAL_O1234,     /* all four (corner, elongation) */
  CSR_CAL_O12R05,    /* Ω1&Ω2 at 1 : 0.5 (refines the edge Ω1 -> Ω1&Ω2) */
  CSR_CAL_O12O34R3,  /* Ω1&Ω2 at p, Ω3&Ω4 at p/3 (refines the face x2 = 1) */
  CSR_CAL_O1O234R05,  /* Ω1 at p, the other three at p/2 (refines the face x4 = x2) */
  CSR_CAL_O1O234R075, /* Ω1 at p, the other three at 0.75 p (refines that face next to the
                       * all-four corner) */
  CSR_CAL_O124O3R05,  /* Ω1&Ω2&Ω4 at p, Ω3 at p/2 (the midpoint of the edge Ω1&Ω2&Ω4 -> all
                       * four; its mirror image the midpoint of Ω1&Ω2&Ω3 -> all four) */
  CSR_CAL_O1O23R05O4R025, /* Ω1 at p, Ω2&Ω3 at p/2, Ω4 at p/4 (the centre of the prism) */
  CSR_CAL_O1O3R05,    /* Ω1 at p, Ω3 at p/2 (the midpoint of the edge Ω1 -> Ω1&Ω3) */
  /* the prism's remaining edge midpoints (2026-12-03): nodes of the RBF rules only, the prism
   * rule's hierarchy ends with the centre */
  CSR_CAL_O12O4R05,   /* Ω1&Ω2 at p, Ω4 at p/2 (edge Ω1&Ω2 -> Ω1&Ω2&Ω4) */
  CSR_CAL_O1O24R05,   /* Ω1 at p, Ω2&Ω4 at p/2 (edge Ω1 -> Ω1&Ω2&Ω4) */
  CSR_CAL_O13O2R05,   /* Ω1&Ω3 at p, Ω2 at p/2 (edge Ω1&Ω3 -> Ω1&Ω2&Ω3) */
  /* and its face centres (2026-12-03; O1O234r05 is the centre of the face Ω2 = Ω4) */
  CSR_CAL_F3ZERO,     /* Ω1 at p, Ω2 at 2p/3, Ω4 at p/3 (face Ω3 = 0) */
  CSR_CAL_F3FULL,     /* Ω1&Ω3 at p, Ω2 at 2p/3, Ω4 at p/3 (face Ω3 = p) */
  CSR_CAL_F4ZERO,     /* Ω1 at p, Ω2&Ω3 at p/2 (face Ω4 = 0) */
  CSR_CAL_F2FULL,     /* Ω1&Ω2 at p, Ω3&Ω4 at p/2 (face Ω2 = p) */
  /* the face Ω2 = Ω4's 0.5 grid in (x2, x3) completed (2026-12-03): the face the held-out H4
   * missed on, whose cell centres were empty; the left-out modes were worst beside it */
  CSR_CAL_W1C1,       /* Ω1 at p, Ω2&Ω4 at 0.75 p, Ω3 at p/4 */
  CSR_CAL_W1C0,       /* Ω1 at p, the other three at p/4 */
  CSR_CAL_W1C2,       /* Ω1 at p, Ω2&Ω4 at p/4, Ω3 at 0.75 p */
  CSR_CAL_O13O24R05,  /* Ω1&Ω3 at p, Ω2&Ω4 at p/2 (edge Ω1&Ω3 -> all four) */
  CSR_CAL_NROLE
} csrCalRole;

typedef struct csrCalOptions_ {
  csrCalRule rule;        /* bend: SUPERPOSITION, INTERPOLATION, SCALED, RBF or RBF_PAIR (the
                             RBF rules also interpolate the scalars' residuals) */
  csrCalRule scalar_rule; /* stretch and radial growth: any of the three */
  unsigned exclude; /* bit (1 << role) leaves a refining mode out (cross-validation); corners
                       cannot be left out */
} csrCalOptions;

/* rule CSR_CAL_RULE_SUPERPOSITION, nothing excluded */
csrCalOptions csr_calModelDefaultOptions(void);

/* Chamber ratios of a role's mode (the fem case list's patterns) and its case name there. */
void csr_calModelModePattern(csrCalRole role, double ratio[CSR_NCHAMBER], const char** name);

typedef struct csrCalModel_ csrCalModel;

/* Build the model from a checked table for the leg `leg` (its a is the rest contact radius).
 * The table may be freed afterwards. NULL and err ("<file>: cause") when a corner mode is
 * missing, or the modes cover no pressure range. opt NULL = defaults. */
csrCalModel* csr_calModelCreate(const csrCalTable* t, const csrActuator* leg,
                                const csrCalOptions* opt, csError* err);
void csr_calModelDestroy(csrCalModel* m);

/* The state of one segment under its chamber pressures. */
typedef struct csrCalSegment_ {
  double bend[2];  /* rad: the end tangent turns by |bend| towards bend[0] e1 + bend[1] e2 */
  double stretch;  /* centreline arc length / S (-) */
  double radial;   /* mean relative growth of the outer surface's distance from the axis (-) */
  double radius;   /* contact radius: a + growth of the largest radial distance (mm) */
} csrCalSegment;

/* Segment seg (0..2) at chamber pressures p[4] (MPa). 0 ok; CSR_MAP_OUT_OF_RANGE (fatal) when
 * a pressure is above csr_calModelPMax; 1 (recoverable) for a pressure below -1e-9 MPa or not
 * finite (a non-physical state; tinier negatives are the pneumatics' round-off, taken as 0), or
 * where the table's superposed modes give a stretch <= 0;
 * < 0 for seg outside 0..2. */
int csr_calModelEval(const csrCalModel* m, int seg, const double p[CSR_NCHAMBER],
                     csrCalSegment* out);

/* Bending (N mm^2) and axial (N) stiffness of segment seg at p[4]. 0 ok; CSR_MAP_OUT_OF_RANGE
 * when the mean pressure is above the probes' or a pressure above the bend range; 2 when the
 * table has no usable probes (no stiffness). */
int csr_calModelStiffness(const csrCalModel* m, int seg, const double p[CSR_NCHAMBER],
                          double* EI, double* EA);

/* Range (MPa): highest chamber pressure of the bend model; and the name of the mode ending it. */
double csr_calModelPMax(const csrCalModel* m);
const char* csr_calModelLimitCase(const csrCalModel* m);
/* Highest mean pressure of the stiffness (MPa), NAN without stiffness. */
double csr_calModelStiffnessPMax(const csrCalModel* m);
/* 1 when the role's mode is used (corners always; a refining mode when present, in range and
 * not excluded). */
int csr_calModelUses(const csrCalModel* m, csrCalRole role);
/* The options the model was built with. */
const csrCalOptions* csr_calModelOptions(const csrCalModel* m);
/* The leg actuator the model was built for. */
const csrActuator* csr_calModelLeg(const csrCalModel* m);
/* The mean-pressure factor of CSR_CAL_RULE_SCALED for segment seg: K(p̄) = exp(k[0] p̄ + k[1]
 * p̄^2) (k = 0 for the other rules or when the fit fell back), and the fit's rms of log
 * magnitude over the bending modes' rows (NAN if not fitted). */
void csr_calModelMeanFactor(const csrCalModel* m, int seg, double k[2], double* rms);
/* One-line description (rule, modes, range, FE settings, file). */
const char* csr_calModelName(const csrCalModel* m);

/* The stiffness points of segment seg (the merged probes), which = 0: EI (N mm^2), 1: EA (N):
 * *n, and pointers into the model (valid while it lives) to pbar[n] (mean pressure, MPa) and
 * value[n]; *n = 0 without stiffness. */
void csr_calModelStiffnessPoints(const csrCalModel* m, int seg, int which, int* n,
                                 const double** pbar, const double** value);

/* The model against one case of a table, over the case's rows within the model's range. */
typedef struct csrCalCompare_ {
  int rows;            /* rows compared (p <= csr_calModelPMax) */
  double p_last;       /* MPa: highest row compared */
  double bend_deg;     /* max over rows and segments of |bend_model - bend_FE| (deg) */
  double bend_at_p;    /* MPa and segment (0..2) where it is */
  int bend_at_seg;
  double bend_fe_deg;  /* |bend_FE| there (deg) */
  double bend_score;   /* max of |Δbend| / max(5 % |bend_FE|, 1 deg): <= 1 meets the target */
  double stretch;      /* max |stretch_model - stretch_FE| (-) */
  double tip_mm;       /* max |tip_model - tip_FE| (mm): constant-curvature kinematics of the
                          model's segments and the solid joints against the FE tip */
  double tip_cc_mm;    /* the same kinematics with the FE's own segment bends and stretches:
                          what the constant-curvature description alone misses (mm) */
  double tip_score;    /* max of |Δtip| / (2 % of the leg length): <= 1 meets the target */
  /* For a pattern a mirror of the section maps onto itself the FE's bend across the mirror line
   * is mesh asymmetry (the model gives none, as for the fitted modes): the FE tip with those
   * components removed (the shift taken from the same kinematics of the FE's segments) */
  int mirror;          /* 1 when the pattern is mirror-symmetric (else the next two equal tip_) */
  double tip_sym_mm;   /* max |tip_model - tip_FE,sym| (mm) */
  double tip_sym_score;
  /* MPa: the highest row up to which every row meets the target (bend and tip scores <= 1,
   * or, for a mirror-symmetric pattern, both against the FE's symmetric part): the range over
   * which the case validates the model (0 when the first loaded row misses) */
  double p_meets;
} csrCalCompare;

/* Compare the model with case c (its ratios at every row's p). CS_ERR_RANGE if no row is in
 * range; CS_ERR_SOLVER if the model or the kinematics fail. */
csStatus csr_calModelCompare(const csrCalModel* m, const csrCalCase* c, csrCalCompare* out,
                             csError* err);

/* The FE against itself under the section's symmetry: case c and the other case of its table
 * whose pattern is an image of c's under the square section's eight symmetries (turns by 90 deg
 * and mirrors; the same pattern again is not an image), the partner's bends and tip carried into
 * c's frame. A symmetric mesh would
 * give 0; what it gives is the FE reference's own resolution on that pattern (the unstructured
 * mesh is not symmetric), the floor under any model error measured against the FE. */
typedef struct csrCalSymPair_ {
  const csrCalCase* partner; /* the image case (a mode or held-out case first), NULL if none */
  int rows;                  /* rows at pressures both cases have (to 1e-9 MPa) */
  double p_last;             /* MPa: highest of them */
  double bend_deg;           /* max over rows and segments of |bend_c - T bend_partner| (deg) */
  double bend_at_p;          /* MPa and segment (0..2) where it is */
  int bend_at_seg;
  double bend_fe_deg;        /* |bend_c| there (deg) */
  double tip_mm;             /* max |tip_c - T tip_partner| (mm), T on the section plane */
  double tip_at_p;           /* MPa where it is */
} csrCalSymPair;

/* Find c's image case in t and compare them (out->partner NULL, CS_OK, when there is none; a
 * gravity case has none). CS_ERR_RANGE when they share no row. */
csStatus csr_calSymmetryPair(const csrCalTable* t, const csrCalCase* c, csrCalSymPair* out,
                             csError* err);

/* The FE of held-out case c made symmetric with its image (csr_calSymmetryPair): bends and tip
 * averaged with the partner's carried into c's frame, at the rows both have; the model compared
 * against that mean as csr_calModelCompare compares it against c (mirror parts included). The
 * mean halves the part of the mesh asymmetry that differs between the two images. */
csStatus csr_calModelCompareSymmetrised(const csrCalModel* m, const csrCalCase* c,
                                        const csrCalSymPair* pair, csrCalCompare* out,
                                        csError* err);

/* Print the model's report on table t (the table it was built from) to `out`: per fitted mode
 * the model's difference from the FE rows, the refining modes left out one at a time, per
 * held-out and symmetry case the bend and tip errors against the target, every rule's worst
 * errors side by side, and the probed stiffness against 8 C10 I and 8 C10 A. */
csStatus csr_calReportPrint(const csrCalModel* m, const csrCalTable* t, FILE* out, csError* err);

/* Write the model's predictions for every case of t (rows within the range) to the HDF5 file
 * `path` (truncated): /cases/<name>/pressure [M] (MPa), bend [M,3,2] (rad), stretch [M,3],
 * radius [M,3] (mm, contact radius), tip [M,3] (mm, constant-curvature kinematics, base frame),
 * attribute kind; /stiffness/II<s>/EI, EI_pbar, EA, EA_pbar (the merged probe points); root
 * attributes model, table, p_max_MPa, units. For tools/plot_calibration.py. */
csStatus csr_calReportWrite(const csrCalModel* m, const csrCalTable* t, const char* path,
                            csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_CALIBRATION_MODEL_H */

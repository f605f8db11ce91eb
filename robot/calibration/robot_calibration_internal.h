/* robot_calibration_internal.h: what the calibration model's files share (internal, not a
 * public header): the model's data, the monotone cubic curves of the modes' rows, and the
 * evaluation pieces the builder reuses to form residuals and surpluses.
 *
 * Files (robot_calibration_model.h has the rule): robot_calibration_model.c evaluates (canonical
 * form, prism weights, bases, stiffness, queries); robot_calibration_build.c builds the model
 * from a table (symmetric parts, residuals, surpluses, the mean-pressure factor fit, the
 * stiffness points); robot_calibration_report.c compares it with a table's cases and writes
 * reports. */
#ifndef CS_ROBOT_CALIBRATION_INTERNAL_H
#define CS_ROBOT_CALIBRATION_INTERNAL_H

#include "core_math.h"
#include "robot_calibration_model.h"

/* pressures down to -1e-9 MPa are the pneumatics integrator's round-off around a vented
 * chamber (its lag decays towards 0 from above), so they count as 0; below that the state is
 * non-physical */
#define P_NEG_TOL 1e-9
/* a pressure may exceed the range by round-off of the caller's ratio x p products */
#define P_RANGE_TOL 1e-12
/* probes at equal mean pressure (both probed modes at p = 0) are merged */
#define PBAR_TOL 1e-12

/* components of a mode's field per segment and row */
enum { F_A = 0, F_B, F_STRETCH, F_RADIAL, F_RADMAX, NF };
/* components of the single-chamber base per segment and row */
enum { B_THETA = 0, B_STRETCH, B_RADIAL, B_RADMAX, NB };

/* the vertices of the interpolation, coarse to fine: the six corners of the prism, the edge
 * midpoints (O12r05; O1O3r05; O124O3r05 and its mirror image), the face nodes (O12O34r3 on
 * x2 = 1, O1O234r05 and O1O234r075 on w = 1) and the centre O1O23r05O4r025. Each refining mode
 * is a bump that vanishes on every face of the prism but its own and at every vertex before it
 * (csr_calWeights_) */
enum {
  V_O1 = 0, V_O13, V_O12, V_O124, V_O124M, V_O1234,
  V_R05, V_E13, V_E124, V_E124M,
  V_R3, V_F05, V_F075,
  V_C,
  NV
};

/* coefficients of the pair factor exp(k0 n + k1 l + k2 n^2 + k3 l^2) (CSR_CAL_RULE_RBF_PAIR) */
#define CSR_CAL_NPAIR 4

/* images of the modes' shapes under the eight symmetries (CSR_CAL_RULE_RBF) */
#define RBF_MAXN (8 * CSR_CAL_NROLE)

/* rows of one mode: p (m), y and slopes (m x 3 x nc) */
typedef struct {
  int m, nc;
  double* p;
  double* y;
  double* d;
} csrCalCurve;

struct csrCalModel_ {
  csrActuator leg;
  csrCalOptions opt;
  double p_max;            /* MPa: bend model range */
  char limit_case[64];     /* the mode that ends it */
  int use[NV];             /* vertex in use */
  int role_use[CSR_CAL_NROLE]; /* mode of each role in use (any vertex or RBF node) */
  double coord[NV][3];     /* (x2, w = x4/x2, x3) of each vertex */
  csrCalCurve base;              /* Ω1 alone: θ1 along -ĉ1, δstretch, δradial, δradial_max */
  csrCalCurve mean;              /* all four: the scalar changes at p = the mean pressure (F_ layout) */
  double kfac[CSR_NSEG][2]; /* mean-pressure factor of the scaled superposition (0: none) */
  double kfit_rms[CSR_NSEG]; /* rms of log(a_model / a_FE) of that fit over the bending modes */
  double kpair[CSR_NSEG][CSR_CAL_NPAIR]; /* pair factor of CSR_CAL_RULE_RBF_PAIR (0: none) */
  csrCalCurve field[NV];         /* a, b, δstretch, δradial, δradial_max (residual or value) */
  /* CSR_CAL_RULE_RBF (robot_calibration_rbf.c): per role its residual over the bases (F_A, F_B
   * the bend vector in the mode's frame, rad; m = 0 when unused), the distinct images of the
   * modes' shapes x = ratio (rbf_n x 4) with their role, turns and mirror, and the inverse of
   * the Gaussian kernel matrix (rbf_n x rbf_n) */
  csrCalCurve rbf_res[CSR_CAL_NROLE];
  int rbf_n;
  double rbf_x[RBF_MAXN][4];
  int rbf_role[RBF_MAXN], rbf_k[RBF_MAXN], rbf_mir[RBF_MAXN];
  double* rbf_inv;
  /* the same field tabulated per pressure interval (robot_calibration_rbf.c "Tabulated"):
   * rbf_nb breakpoints rbf_B (the union of the residual curves' rows; 0: not tabulated) and
   * rbf_G ((rbf_nb - 1) x CSR_NSEG x 4 powers x rbf_n x NF): A^-1 times the images' residual
   * cubics in the interval's local pressure */
  int rbf_nb;
  double* rbf_B;
  double* rbf_G;
  int nk[2][CSR_NSEG];     /* stiffness points of EI (0) and EA (1) per segment */
  double* kp[2][CSR_NSEG]; /* (nk) mean pressure, MPa */
  double* kv[2][CSR_NSEG]; /* (nk) EI (N mm^2) or EA (N) */
  double k_pmax;           /* MPa: highest mean pressure of the stiffness (NAN: none) */
  char name[1280];
};

/* unit diagonal directions of the chambers: ĉ1 = d1, ĉ2 = d2, ĉ3 = -d1, ĉ4 = -d2 */
#define RSQ2 0.70710678118654752440


/* ---- curves (robot_calibration_build.c builds, robot_calibration_model.c evaluates) ---- */

/* allocate a curve of m rows and nc components per segment; 0 when out of memory */
int csr_calCurveAlloc_(csrCalCurve* c, int m, int nc);
/* the number of rows of case c needed to reach pressure P (MPa): up to its first row >= P
 * (robot_calibration_build.c) */
int csr_calRowsTo_(const csrCalCase* c, double P);
void csr_calCurveFree_(csrCalCurve* c);
/* the Fritsch-Carlson slopes of every component series, from p and y */
void csr_calCurveSlopes_(csrCalCurve* c);
/* the nc components of segment s at pressure p (clamped to the rows), exact at a row */
void csr_calCurveEval_(const csrCalCurve* c, double p, int s, double* out);
/* segment s's EI from stiffness probe k of case c (N mm^2): the isotropic section's mean of the
 * two bend directions' probes, either one where the other has no reading, NAN when neither has
 * (robot_calibration_build.c) */
double csr_calProbeEI_(const csrCalCase* c, int k, int s);

/* ---- evaluation pieces (robot_calibration_model.c) ------------------------------------- */

/* pressure moment (p1 + p2 - p3 - p4, p1 - p2 - p3 + p4) of a pattern */
void csr_calMoment_(const double p[4], double mvec[2]);
/* 1 when a mirror of the section maps the pattern onto itself */
int csr_calMirrorSymmetric_(const double r[4]);
/* weights of the vertices at prism point (x2, w = x4/x2, x3) */
void csr_calWeights_(const csrCalModel* m, double x2, double w, double x3, double W[NV]);
/* the bend and scalar bases at canonical pressures pc (canonical frame) */
void csr_calBaseBend_(const csrCalModel* m, int s, const double pc[4], double bend[2]);
void csr_calBaseScalars_(const csrCalModel* m, int s, const double pc[4], double sc[3]);
/* the superposition of the single-chamber curve `base` with mean-pressure factor k */
void csr_calSuperposeBend_(const csrCalCurve* base, const double k[2], int s, const double pc[4],
                           double bend[2]);
/* canonical form pc = D^mir R^k p of a pattern: the highest chamber first (the first of equal
 * ones), pc[1] >= pc[3] (R turns the pattern by +90 deg, D swaps Ω2 and Ω4) */
void csr_calCanonical_(const double p[4], double pc[4], int* k, int* mir);
/* bend vector of a canonical pattern back in the pattern's frame (k turns, mirror) */
void csr_calFromCanonical_(const double bc[2], int k, int mir, double b[2]);
/* and its inverse: a vector of the section plane into the canonical frame */
void csr_calToCanonical_(const double b[2], int k, int mir, double bc[2]);

/* ---- the RBF rule (robot_calibration_rbf.c) --------------------------------------------- */

/* residual curves and images of the modes used (mode[r] NULL: unused; the bases must be set
 * up); 1 ok, 0 out of memory, -1 a singular kernel matrix (coincident images) */
int csr_calRbfBuild_(csrCalModel* m, const csrCalCase* const mode[CSR_CAL_NROLE]);
/* the interpolated residual at canonical pc (pc[0] = P > 0): bend (canonical frame, rad) and
 * the changes of stretch, radial and largest radial growth; no allocation */
void csr_calRbfField_(const csrCalModel* m, int s, const double pc[4], double bend[2],
                      double sc[3]);
/* the same by the cardinal weights of every image (the definition; the tabulated field is
 * checked against it, test_calibration_rbf) */
void csr_calRbfFieldDirect_(const csrCalModel* m, int s, const double pc[4], double bend[2],
                            double sc[3]);

/* ---- the pair factor of CSR_CAL_RULE_RBF_PAIR (robot_calibration_pair.c) --------------- */

/* fit segment s's pair factor to the bending modes used (mode[r] NULL: unused; the base must
 * be built); falls back to K = 1 when the fit is ill-posed; 0 when out of memory */
int csr_calPairFit_(csrCalModel* m, const csrCalCase* const mode[CSR_CAL_NROLE], int s);
/* the superposition with the pair factor at canonical pc (canonical frame, rad) */
void csr_calPairBend_(const csrCalModel* m, int s, const double pc[4], double bend[2]);

/* K(x) = exp(k1 x + k2 x^2) */
static inline double csr_calMeanFactor_(const double k[2], double x) {
  return exp(x * (k[0] + k[1] * x));
}

#endif /* CS_ROBOT_CALIBRATION_INTERNAL_H */

/* fem_rom.h: the reduced-order FE model of one actuator (issue 34: the `rom` level).
 *
 * Owns: csfRom (the model, constant once built: a basis V of the displacement, u = V q, over a
 * full FE model's mesh and kernels; the element sets that enter the reduced forces, each element
 * with a non-negative weight (all elements at weight 1 unless hyper-reduced: ECSW, Farhat et
 * al. 2014, per element and not per quadrature point, so each Tet10 keeps its mixed pressure);
 * the exact reduced gravity and dead-load operators), csfRomData (reduced coordinates q,
 * residual, tangent, scratch), the reduced residual and tangent from fem's element kernels
 * (fem_element.h, no FE assembly or Newton), and the reduced statics: Newton on q with a load
 * ramp.
 * Reduced equations: r(q) = V^T f_int(V q) - V^T f_ext(V q) = 0 with the FE's sign convention
 * (fem_model.h: R = f_int - f_ext), K_r = dr/dq = V^T K V. The element dilatation of the mixed
 * form and the fibres' stress state are taken at their converged values theta_e = v/V and
 * S = S(E) (csf_dataSyncVolume), so K_r is the exact derivative of r and, every kernel being
 * conservative on closed chambers, symmetric; a weighted sum of element terms keeps both
 * properties for any non-negative weights.
 * Units: mm, MPa, N, t/mm^3. Basis V: (ndof x n) row-major, zero rows on clamped dofs. */
#ifndef CS_FEM_ROM_H
#define CS_FEM_ROM_H

#include <stddef.h>

#include "core_status.h"
#include "fem_model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Element sets of the reduced forces: Tet10 bodies, fibre trusses, pressure faces. */
typedef enum csfRomSet_ {
  CSF_ROM_SET_TET = 0,
  CSF_ROM_SET_FIBRE = 1,
  CSF_ROM_SET_FACE = 2
} csfRomSet;
#define CSF_ROM_NSET 3

typedef struct csfRom_ {
  const csfModel* fem; /* not owned: mesh, material, reference geometry, fibres, clamp */
  int ndof, n;         /* full and reduced sizes */
  double* V;           /* (ndof x n) basis, mm per unit q, owned */
  int nel[CSF_ROM_NSET];   /* elements kept in each set */
  int* el[CSF_ROM_NSET];   /* (nel) their indices in the FE model */
  double* w[CSF_ROM_NSET]; /* (nel) their weights (>= 0) */
  double* G;           /* (n x 3) reduced body force per unit acceleration, V^T f_g(e_i),
                        * N s^2/mm (exact: every element, linear in g) */
  /* chambers in closed form (csf_romChamberTensors): 0 = none, the faces go through the face
   * set. The volume a chamber's faces enclose is a cubic polynomial of the nodal positions,
   * hence of q: V_c(q) = V0 + g0.q + q.H0 q / 2 + sum_k q_k q.H_k q / 6, its gradient (the
   * reduced pressure load per unit pressure) g0 + (H0 + H(q)) q / 2 and its Hessian
   * H(q) = H0 + sum_k q_k H_k, exactly, from n + 1 evaluations of the faces */
  int nch;
  int* face_ch;        /* (nface) chamber of each face, -1: not in a chamber */
  double* ch_V0;       /* (nch) mm^3 */
  double* ch_g0;       /* (nch x n) mm^3 per unit q */
  double* ch_H;        /* (nch x (n + 1) x n x n): H0, H_1 .. H_n */
  /* mixed reduced model (csf_romSetPressureBasis; m = 0: the displacement-only model). The
   * element pressures of the FE's P2/P0 form are p = P p^ with their own basis P (ntet x m,
   * MPa per unit p^) instead of one free pressure per element: the element constraint
   * v_e - V_e = V_e p_e / kappa holds only in P's span, weighted by the kept elements,
   *   A p^ = b(q),  A = sum_e w_e (V_e / kappa) P_e P_e^T,  b = sum_e w_e P_e (v_e(q) - V_e),
   * so p^ is a function of q and the reduced problem stays one of q alone: the stationary point
   * of sum_e w_e int W_dev + b^T A^-1 b / 2 (the FE's bulk energy sum_e kappa (v_e - V_e)^2 /
   * (2 V_e) when P = I). Its residual V^T (f_dev + G^T p) and tangent V^T (K_dev + sum_e p_e
   * dg_e/du) V + B^T A^-1 B (B = sum_e w_e P_e g_e^T V_e, m x n) are conservative and symmetric.
   * A displacement basis of nearly isochoric snapshot modes no longer pays the bulk energy of
   * every element's small volume change (the locking of the displacement-only POD model,
   * docs/notes/rom.md), only of its m pressure-mode moments. */
  /* the kept fibres' chord operators (built by csf_romCreate and csf_romSetWeights): the chord
   * d = sum_a c_a x_a of fibre el[FIBRE][k] is linear in q, d = X_k + D_k q with D_k =
   * sum_a c_a V_a (3 x n, V_a the host node's three basis rows) and X_k the reference chord, both
   * constant; the fibre's force c (x) f_d and tangent (c c^T) (x) H (fem_element.h
   * csf_fibreKernel) reduce to D_k^T f_d and D_k^T H D_k: O(n^2) per fibre instead of
   * O(nn^2 n + nn n^2) through its 3 nn = 60 basis rows */
  double* fib_D;       /* (nel[FIBRE] x 3 x n), mm per unit q */
  double* fib_X;       /* (nel[FIBRE] x 3), mm */
  int m;
  double* P;           /* (ntet x m) element pressure basis, owned */
  double* A_chol;      /* (m x m) Cholesky factor (lower) of A over the kept elements */
  /* mixed fibre field (csf_romSetFibreBasis; mf = 0: every fibre strains on its own, the FE's
   * law). The nearly inextensible fibres lock a linear span as the bulk does: a combination of
   * snapshot modes stretches the fibres far more than any snapshot did (docs/notes/rom.md,
   * "Locking"). With mf > 0 the fibres' Green strains E_f(q) enter the law only through their
   * projection onto a strain basis Q (nfib x mf, from the training states' fibre strains),
   * weighted by the kept fibres' stiffness W_f = w_f EA_f L0_f (N):
   *   E^ = G^-1 sum_f W_f Q_f E_f(q),  G = sum_f W_f Q_f Q_f^T,  Ebar_f = Q_f . E^,
   * and the fibre energy is sum_f W_f psi(Ebar_f) (psi' = S, fem_material.h csf_fibreLaw): an
   * assumed-strain (B-bar-like) field, conservative, its tangent symmetric. Each fibre's force is
   * the FE kernel's with S(E_f) replaced by the W-projection S*_f = Q_f . G^-1 sum_g W_g Q_g
   * S(Ebar_g) (fem_rom_fibre.c); Q = I is the FE's fibre model, exactly. A strain component
   * outside span(Q) costs no fibre energy, as a dilatation outside span(P) costs no bulk
   * energy. */
  int mf;
  double* Qf;          /* (nfib x mf) fibre strain basis (strain per unit E^), owned */
  double* Gf_chol;     /* (mf x mf) Cholesky factor (lower) of G over the kept fibres, N */
} csfRom;

/* Build a reduced model on the finalised FE model `fem` (not copied; must outlive the rom) with
 * the basis V (ndof x n, copied; rows of clamped dofs must be zero). Every element kept at
 * weight 1. NULL and err on failure. */
csfRom* csf_romCreate(const csfModel* fem, int n, const double* V, csError* err);
void csf_romDestroy(csfRom* r);

/* Replace the element set `set` by the elements idx[0..nel) with weights w (>= 0; copied).
 * CS_ERR_ARG on an index out of range or a negative or non-finite weight, and on a mixed rom
 * when a pressure mode loses all support (the set is then changed: set other weights). */
csStatus csf_romSetWeights(csfRom* r, csfRomSet set, int nel, const int* idx, const double* w,
                           csError* err);

/* Make the rom mixed (see csfRom.m) with the element pressure basis P (ntet x m, copied; m = 0
 * makes it displacement-only again). A is factored over the kept Tet10s (again at every
 * csf_romSetWeights). CS_ERR_ARG when A is not positive definite (a pressure mode without
 * support in the kept elements) or P is not finite. */
csStatus csf_romSetPressureBasis(csfRom* r, int m, const double* P, csError* err);

/* Give the fibres the strain basis Q (nfib x mf, copied; mf = 0: the FE's fibres again; see
 * csfRom.mf). G is factored over the kept fibres (again at every csf_romSetWeights of the fibre
 * set). CS_ERR_ARG when Q is not finite or a mode has no support in the kept fibres. A data set
 * (csf_romDataCreate) serves the mf it was created with. */
csStatus csf_romSetFibreBasis(csfRom* r, int mf, const double* Q, csError* err);

/* Take the chambers' pressure loads in closed form (see csfRom.nch): face f belongs to chamber
 * face_ch[f] (0..nch-1, -1: none; every face of a chamber must carry the same pressure in a
 * load). Afterwards the faces of chambers leave the face set (exact, conservative, a symmetric
 * load stiffness when the chambers are closed: no hyper-reduction needed) and cost O(n^3) per
 * chamber instead of O(faces n^2). CS_ERR_ARG on a bad chamber index. */
csStatus csf_romChamberTensors(csfRom* r, int nch, const int* face_ch, csError* err);

/* The volume chamber c encloses at q (mm^3; csf_romChamberTensors first). */
double csf_romChamberVolume(const csfRom* r, int c, const double* q);

/* Project a full nodal force (ndof, N) onto the basis: fr = V^T f (n). */
void csf_romProject(const csfRom* r, const double* f, double* fr);

/* Reconstruct the displacement u = V q (ndof, mm). */
void csf_romExpand(const csfRom* r, const double* q, double* u);

/* The loads of a reduced equilibrium. */
typedef struct csfRomLoad_ {
  const double* face_p; /* (nface) pressure on every boundary face, MPa (NULL: none) */
  double gravity[3];    /* body acceleration, mm/s^2 */
  const double* f_dead; /* (n) reduced dead load V^T f_dead, N (NULL: none; csf_romProject) */
} csfRomLoad;

/* Reduced state and scratch. The mixed Tet10's dilatation theta_e and the fibres' stress
 * state S enter the tangent's geometric terms (fem_element.h); as in the FE's three-field Newton
 * (fem_newton.c) the reduced Newton carries them as state and updates them by the linearised
 * constraint, so that the spurious volumetric pressure of an overshooting iterate does not
 * enter the tangent (without it the reduced Newton stalled on a clamped block: |r| grew along
 * every step). With `sync` set, an evaluation takes them at their converged values v/V and
 * S(E) instead, and K is the exact derivative of r (tests). */
typedef struct csfRomData_ {
  int n, m;     /* the rom's sizes when created (a data set serves one rom configuration) */
  double* q;    /* (n) reduced coordinates */
  double* r;    /* (n) reduced residual at the last evaluation, N */
  double* K;    /* (n x n) reduced tangent, N/mm */
  double* Ku;   /* (n x n) scratch: the bodies' and fibres' tangent (upper triangle), then a
                 * chamber's Hessian */
  int sync;     /* 1: theta = v/V, S = S(E) at every evaluation (exact tangent); 0: the states */
  double* theta;  /* (ntet) element dilatation state (1 at rest) */
  double* fib_S;  /* (nfib) fibre stress state */
  double* vr, *gel;     /* (ntet), (ntet x 30) v/V and g_e of the last evaluation */
  double* fib_E, *fib_d; /* (nfib), (nfib x 3) fibre strain and chord of the last evaluation */
  double* vr0, *g0, *fib_E0, *fib_d0; /* the same at the Newton iterate (the update's base) */
  double* theta_save, *fib_S_save, *theta_best, *fib_S_best; /* Newton's restore points */
  double* dq, *q_save, *q_best, *q0, *lu, *tmp; /* (n) x 5, (n x n), (n) scratch */
  int* piv;     /* (n) */
  double* ke_v; /* (61 x n) scratch: element matrix times the element's basis rows, a row */
  /* mixed model (csfRom.m > 0): the reduced pressures of the last evaluation, p^ = A^-1 b(q),
   * MPa; the element residuals without the volumetric term; B (m x n); scratch */
  double* ph;   /* (m) */
  double* rel;  /* (ntet x 30) */
  double* Bm;   /* (m x n) */
  double* mtmp; /* (m + n) */
  /* mixed fibres (csfRom.mf > 0): E^ and the projected stress coefficients (2 mf); B =
   * sum_f W_f Q_f dE_f/dq and G^-1 B (2 mf x n); C = sum_f W_f S'(Ebar_f) Q_f Q_f^T (mf x mf);
   * a fibre strain per fibre (the states' update) */
  int mf;
  double* fq_e;
  double* fq_B;
  double* fq_C;
  double* fq_E;
  double rnorm, fnorm; /* |r|, force scale |V^T f_int| + |V^T f_ext| (N) */
  long n_eval, n_newton; /* evaluations, Newton iterations */
  long n_tangent;        /* evaluations that formed K */
  int lu_valid;          /* lu holds the LU factor of a tangent (csfRomNewtonOptions.k_lag) */
  /* the BFGS pairs on the kept factor (csfRomNewtonOptions.bfgs): s, y (CSF_ROM_BFGS_MAX x n),
   * 1 / (y . s), their count; the residual at the step's start (n); the two-loop's alphas */
  double* bf_s, *bf_y, *bf_rho, *bf_r0, *bf_a;
  int bf_k;
} csfRomData;

csfRomData* csf_romDataCreate(const csfRom* r, csError* err);
void csf_romDataDestroy(csfRomData* d);

/* The unloaded state: q = 0, theta = 1, the fibres' stress at zero strain. */
void csf_romDataReset(const csfRom* r, csfRomData* d);

/* Evaluate r(q) (and K(q) when want_k) at d->q under `load` into d->r, d->K (the residual does
 * not depend on the states; the tangent's geometric terms do, see csfRomData.sync). Returns 0,
 * > 0 when an element inverts (recoverable: cut the step), < 0 on bad arguments. */
int csf_romEvaluate(const csfRom* r, csfRomData* d, const csfRomLoad* load, int want_k);

/* The reduced force of every element of `set` in the FE model (weight 1, whatever the rom's
 * weights) at d->q under `load`: row e of G (nel x n, N) is V_e^T f_e, with f_e the element's
 * internal force (tets, fibres) or its pressure load with the sign of R (faces: -f_ext). Their
 * column sums are the unreduced model's parts of r; ECSW fits element weights to them
 * (tools/rom_ecsw.py).
 * Mixed rom (m > 0), Tet10 set: rows of n + m (csf_romElementForcesWidth): V_e^T f_e with the
 * element's pressure p_e = P_e . p^ of the unreduced model (p^ = A^-1 b with A and b over every
 * Tet10 at weight 1), then the element's constraint share P_e (v_e - V_e) (mm^3 per unit p^):
 * the column sums are the unreduced r's Tet10 part and b, so weights fitted to both keep the
 * reduced pressures as well as the forces.
 * Mixed fibres (mf > 0), fibre set: rows of n + 4 mf: each fibre's reduced force at the
 * unreduced S*, then its shares W_f Q_f E_f and W_f Q_f S(Ebar_f) of the projections and of
 * G's action on E^ and s^ (fem_rom_fibre.h derives the weighted model and why these rows).
 * Returns 0, > 0 if an element inverts, < 0 on bad arguments or out of memory. */
int csf_romElementForces(const csfRom* r, csfRomData* d, const csfRomLoad* load, csfRomSet set,
                         double* G);

/* The row width of csf_romElementForces for `set`: n, n + m for a mixed rom's Tet10s, n + 4 mf
 * for the fibres of a rom with a fibre strain basis. */
int csf_romElementForcesWidth(const csfRom* r, csfRomSet set);

/* Newton options of the reduced statics. */
typedef struct csfRomNewtonOptions_ {
  int max_iter;  /* iterations per load level */
  double rtol;   /* |r| <= rtol (|V^T f_int| + |V^T f_ext|) */
  double atol;   /* ... or |r| <= atol, N */
  int max_ls;    /* line-search halvings */
  /* 0: Newton (K formed and factored at every iterate). > 0: a lagged tangent (chord or
   * modified Newton, Dennis and Schnabel 1983 ch. 5; the FE codes' "modified Newton"): the
   * factor of the last tangent is kept, also from one call to the next (d->lu_valid), and the
   * iterates evaluate the residual alone, which is O(n) per element against the tangent's O(n^2);
   * K is formed and factored again at the current iterate when a step reduces |r| by less
   * than this factor (or not at all: the step is then taken back and redone as a Newton step
   * with its line search). Same solution (the residual decides); more, cheaper iterations. */
  double k_lag;
  /* With k_lag > 0: the number of secant pairs (s, y) = (dq, dr) of the steps taken since the
   * factor was formed that correct it, 0 .. CSF_ROM_BFGS_MAX (0: the plain chord). The step on
   * a kept factor is then -H r with H the BFGS inverse update of K0^-1 by those pairs (the
   * two-loop recursion of L-BFGS with K0^-1 as its initial matrix; Nocedal and Wright 2006,
   * alg. 7.4): H y_k = s_k for the last pair, so the iterates contract superlinearly where the
   * chord contracts linearly, at O(pairs n) per step against the tangent's O(n^2) per element.
   * r is the gradient of the reduced energy (conservative loads: fem_rom.h), so BFGS's
   * symmetric positive update fits; a pair with y . s <= 0 is not stored. The pairs are dropped
   * with every new factor and at every call (the load changes r). */
  int bfgs;
  /* 1: the secant pairs of the last call are kept into this one while its factor is (a sweep's
   * next load: the energy's curvature changes little from one row to the next, and the pairs of
   * the last row's steps correct the kept factor from the first step on); 0: dropped at every
   * call. The residual decides the solution either way. */
  int bfgs_keep;
} csfRomNewtonOptions;

#define CSF_ROM_BFGS_MAX 16 /* the most secant pairs csfRomNewtonOptions.bfgs may keep */

csfRomNewtonOptions csf_romNewtonDefault(void);

/* Solve r(q) = 0 from d->q by the FE's Newton (fem_newton.c): the three-field state update, a
 * lenient first line search (|r| may grow 1e4-fold) and a watchdog that returns to the best
 * iterate after 3 steps without improving on it and continues with strict backtracking; with
 * o->k_lag > 0 a lagged tangent (see there). On failure d->q and the states are restored, the
 * kept factor dropped and CS_ERR_DIVERGED returned. `iters` (may be NULL) gets the iterations. */
csStatus csf_romNewton(const csfRom* r, csfRomData* d, const csfRomLoad* load,
                       const csfRomNewtonOptions* o, int* iters, csError* err);

/* The quasi-Newton pieces of csf_romNewton (csfRomNewtonOptions.bfgs), callable for tests:
 * csf_romFactorTangent factors d->K (an evaluation with the tangent first) into the kept
 * factor and drops the pairs (CS_ERR_SOLVER when singular); csf_romQuasiNewtonPush stores the
 * secant pair (s, y) (n each) when y . s > 0, the oldest leaving past cap (<= CSF_ROM_BFGS_MAX),
 * and returns 1 if stored; csf_romQuasiNewtonApply overwrites x (n) with H x, H the BFGS update
 * of the factor's inverse by the stored pairs (H y = s for the last pair stored). */
csStatus csf_romFactorTangent(const csfRom* r, csfRomData* d, csError* err);
int csf_romQuasiNewtonPush(const csfRom* r, csfRomData* d, const double* s, const double* y,
                           int cap);
void csf_romQuasiNewtonApply(const csfRom* r, csfRomData* d, double* x);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ROM_H */

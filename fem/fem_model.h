/* fem_model.h: the full FE model of one actuator: Yeoh Tet10 elements with a mixed P2/P0
 * (mean-dilatation) incompressibility treatment, follower pressure on tagged faces, embedded
 * tension-only fibres, Dirichlet data, the sparse pattern and the assembly of residual and
 * consistent tangent; plus Newton's method with line search on top of a sparse direct solver.
 *
 * Model/data split (STYLE.md 4): csfModel holds the mesh, material, loads and the sparse pattern
 * and is const once csf_modelFinalize returned; csfData holds the displacement state, residual,
 * tangent values, solver factors, timers. Units: mm, MPa, N, t/mm^3, s.
 * Sign convention: residual R(u) = f_int(u) - f_ext(u, load); tangent K = dR/du. */
#ifndef CS_FEM_MODEL_H
#define CS_FEM_MODEL_H

#include "core_status.h"
#include "fem_linsolve.h"
#include "fem_mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Incompressibility treatment. */
typedef enum csfFormulation_ {
  CSF_FORM_MIXED_P0 = 0,     /* P2 displacement / P0 pressure+dilatation per element, condensed */
  CSF_FORM_DISPLACEMENT = 1, /* plain P2 displacement with pointwise U(J): locks when kappa >> mu */
} csfFormulation;

/* Ratio of bulk to initial shear modulus, kappa / mu0 with mu0 = 2 C10 (MPa/MPa). 2000 gives an
 * initial Poisson ratio 0.49975; results change by < 0.1 % between 1000 and 10000 (see tests). */
#define CSF_KAPPA_RATIO 2000.0

typedef struct csfMaterial_ {
  double C10, C20;     /* Yeoh constants of W = C10 (I1b - 3) + C20 (I1b - 3)^2, MPa */
  double kappa;        /* bulk modulus of U(J) = kappa/2 (J - 1)^2, MPa */
  double kappa_pt;     /* mixed form only: extra pointwise bulk term kappa_pt/2 (J - 1)^2, MPa */
  double rho;          /* density, t/mm^3 (gravity only) */
  csfFormulation form; /* incompressibility treatment */
} csfMaterial;

/* Material with kappa = CSF_KAPPA_RATIO * 2 C10 and the mixed formulation. */
csfMaterial csf_materialDefault(double C10, double C20, double rho);

/* Deviatoric Yeoh energy of a deformation gradient F (3x3 row-major): W (MPa), first
 * Piola-Kirchhoff stress P (9, MPa) and tangent A = dP/dF (81, index (3i+J)*9 + 3k+L), either
 * output may be NULL. Returns J = det F; J <= 0 leaves P and A untouched. */
double csf_yeohDev(double C10, double C20, const double F[9], double* W, double P[9],
                   double A[81]);

typedef struct csfModel_ {
  const csfMesh* mesh; /* not owned; must outlive the model */
  csfMaterial mat;
  int ndof;            /* 3 nnode */
  /* quadrature of every element: 4 points (degree 2) */
  double* dNdX;        /* (ntet x 4 x 10 x 3) shape gradients in the reference frame, 1/mm */
  double* wq;          /* (ntet x 4) weight x reference Jacobian, mm^3 */
  double* vol;         /* (ntet) reference volume, mm^3 */
  /* loads, scaled by the load factor unless stated */
  double* face_p;      /* (nface) pressure per unit load factor on each boundary face (MPa) */
  double gravity[3];   /* body acceleration, mm/s^2, applied at full value at every load */
  unsigned char* fixed; /* (ndof) 1 = Dirichlet dof */
  double* u_fix;       /* (ndof) prescribed displacement per unit load factor, mm */
  /* embedded fibres: 2-node truss elements whose ends live inside host tetrahedra */
  int nfib;
  int* fib_node;       /* (nfib x 20) host nodes of end 1 (10) then end 2 (10) */
  double* fib_coef;    /* (nfib x 20) -N_a(end 1), +N_a(end 2): d = x2 - x1 = sum coef x */
  double* fib_L0;      /* (nfib) reference length, mm */
  double* fib_EA;      /* (nfib) axial stiffness E A, N */
  int fib_tension_only; /* 1 (default): smoothed tension-only law; 0: linear both ways */
  int fib_geo_tension;  /* 1: the tangent keeps the fibre's geometric stiffness only in tension,
                         * EA/L0 max(S, 0) I (residual unchanged, exact); 0: EA/L0 S I */
  csfSolverKind solver; /* sparse direct solver used by csf_dataCreate (default MUMPS) */
  /* sparse pattern (3x3 node blocks, scalar CSR), built by csf_modelFinalize */
  int finalized;
  int* adj_ptr;        /* (nnode + 1) */
  int* adj;            /* (nadj) neighbour nodes, sorted per row */
  int* row_ptr;        /* (ndof + 1) */
  int* col;            /* (nnz) */
  int nnz;
  int* tet_map;        /* (ntet x 100) block slot of node pair (a, b) in row of node a */
  int* fib_map;        /* (nfib x 400) same for fibre node pairs */
  int* face_local;     /* (nface x 6) local node index of each face node in its tet */
} csfModel;

/* Create a model on `mesh` (not copied). No loads, nothing fixed. */
csfModel* csf_modelCreate(const csfMesh* mesh, const csfMaterial* mat, csError* err);

/* Free; NULL-safe. */
void csf_modelDestroy(csfModel* m);

/* Apply a pressure of `p_unit` MPa per unit load factor to every face with tag `tag` (adds to
 * earlier calls). Returns the number of faces, or a negative csStatus. */
int csf_modelAddPressure(csfModel* m, int tag, double p_unit);

/* Add fibres along polylines given in reference coordinates. `pts` (npts x 3, mm) is one
 * polyline; each segment becomes a truss element tied to the tetrahedra containing its end
 * points (located with a tolerance; a point outside the body is an error). E (MPa), radius
 * (mm). Must be called before csf_modelFinalize. */
csStatus csf_modelAddFibre(csfModel* m, int npts, const double* pts, double E, double radius,
                           csError* err);

/* Build the sparse pattern. Loads and Dirichlet values may still change afterwards. */
csStatus csf_modelFinalize(csfModel* m, csError* err);

/* Timers and counters, accumulated over the life of a csfData (s, counts). */
typedef struct csfStats_ {
  double t_assemble, t_factor, t_solve; /* wall seconds */
  long n_assemble, n_factor, n_newton;  /* counts */
} csfStats;

typedef struct csfData_ {
  int ndof;
  double* u;      /* (ndof) displacement, mm */
  double* r;      /* (ndof) residual f_int - f_ext, N (0 on fixed dofs) */
  double* du;     /* (ndof) Newton step */
  double* u_save; /* (ndof) scratch: last accepted state */
  double* kval;   /* (nnz) tangent values in the model's CSR pattern */
  double* theta;  /* (ntet) element dilatation state theta_e of the three-field form (mixed) */
  double* pel;    /* (ntet) element pressure state kappa (theta_e - 1), MPa (mixed form) */
  double* vratio; /* (ntet) element volume ratio v/V at the last assembly */
  double* gel;    /* (ntet x 30) g_e = int cof(F) : G dV at the last assembly, mm^2 */
  double* theta_save; /* (ntet) scratch: theta at Newton entry */
  double* vr0;    /* (ntet) scratch: v/V at the current Newton iterate */
  double* g0;     /* (ntet x 30) scratch: g_e at the current Newton iterate */
  double* fib_S;  /* (nfib) fibre stress state S (strain units, x EA = force) of the tangent */
  double* fib_E;  /* (nfib) fibre Green strain at the last assembly */
  double* fib_d;  /* (nfib x 3) fibre chord x2 - x1 at the last assembly, mm */
  double* fib_S_save, *fib_E0, *fib_d0; /* scratch (Newton entry / current iterate) */
  double* fext1;  /* (ndof) pressure load per unit load factor at the last assembly, N: the
                   * gradient dVw/du of the weighted chamber volume (0 on fixed dofs) */
  double* du2;    /* (ndof) scratch: second solve of the volume-controlled Newton */
  double vol_w;   /* weighted chamber volume sum_f face_p[f] V_f at the last assembly, MPa mm^3:
                   * V_f = 1/3 int x . n_chamber da over the pressurised faces (closed chambers,
                   * or open ones bounded by symmetry planes through the origin) */
  unsigned char* fib_zone; /* (nfib) law zone at the last iterate: 0 slack, 1 smoothing, 2 taut */
  double rnorm;   /* ||R|| on free dofs after the last assembly, N */
  double fnorm;   /* force scale for convergence: ||f_int|| over all dofs + ||f_ext||, N */
  double jmin;    /* smallest pointwise J at quadrature points after the last assembly */
  double load;    /* load factor of the last assembly */
  csfLinSolver* ls;
  csfStats stats;
} csfData;

csfData* csf_dataCreate(const csfModel* m, csError* err);
void csf_dataDestroy(csfData* d);

/* Wall-clock seconds (for the timers of csfStats and the sweeps). */
double csf_wallTime(void);

/* The state a Newton solve starts from, as one vector (like MuJoCo's mj_getState): u (ndof),
 * theta (ntet), pel (ntet), fib_S (nfib), load (1). Copying u alone is not enough: the
 * three-field element dilatation and the fibre stress state enter the first residual and
 * tangent. csf_stateSize gives the length in doubles; the caller owns the buffer. */
size_t csf_stateSize(const csfModel* m);
void csf_stateGet(const csfModel* m, const csfData* d, double* state);
void csf_stateSet(const csfModel* m, csfData* d, const double* state);

/* Set the dilatation state to the current displacement (theta_e = v_e/V_e); after this the
 * assembled K is the exact derivative of R (used by tangent checks). */
void csf_dataSyncVolume(const csfModel* m, csfData* d);

/* Assemble R (and K when want_k) at the current d->u and load factor. Returns 0, > 0 when the
 * state is not physical (an inverted element: recoverable, cut the step), < 0 on fatal errors. */
int csf_assemble(const csfModel* m, csfData* d, double load, int want_k);

/* Newton options (STYLE.md 17). */
/* Line search of csf_newtonSolve. */
typedef enum csfLineSearch_ {
  CSF_LS_RESIDUAL = 0, /* backtracking on ||R|| (halving while ||R|| grows, see fem_model.c) */
  CSF_LS_ENERGY = 1,   /* root of the energy slope g(s) = R(u + s du) . du on the free dofs
                        * (conservative loads: closed chambers), Illinois regula falsi */
} csfLineSearch;

/* One Newton iteration, reported to csfNewtonOptions.monitor. */
typedef struct csfNewtonIter_ {
  double load;      /* load factor */
  int iter;         /* 1-based iteration */
  double alpha;     /* accepted step length */
  int n_eval;       /* residual evaluations in the line search */
  double g0, g1;    /* energy slope R.du at s = 0 and at the accepted s, N mm */
  double rnorm;     /* ||R|| after the step, N */
  double fnorm;     /* force scale, N */
  int fib_switch;   /* fibres whose law zone (slack / smoothing / taut) changed in this step */
  int fib_smooth;   /* fibres inside the smoothing zone |E| < delta after the step */
  int fib_taut;     /* fibres with E >= delta after the step */
} csfNewtonIter;

/* Newton options (STYLE.md 17). */
typedef struct csfNewtonOptions_ {
  int max_iter;   /* Newton iterations per load level */
  double rtol;    /* ||R|| <= rtol * fnorm (dimensionless) */
  double atol;    /* ... or ||R|| <= atol, N */
  int max_ls;     /* line-search halvings / regula falsi evaluations */
  csfLineSearch line_search; /* default CSF_LS_RESIDUAL */
  double ls_eta;  /* energy line search: accept s when |g(s)| <= ls_eta |g(0)| (dimensionless) */
  int threads;    /* OpenMP threads for assembly, 0 = library default */
  void (*monitor)(void* user, const csfNewtonIter* it); /* optional, per iteration */
  void* monitor_user;
} csfNewtonOptions;

csfNewtonOptions csf_newtonDefault(void);

/* Solve R(u, load) = 0 by Newton's method with backtracking line search, starting from d->u
 * (Dirichlet dofs move to load * u_fix within the first Newton step, through the linearised lift). On failure d->u is restored and
 * CS_ERR_DIVERGED is returned (recoverable: the caller cuts the load step); `iters` (may be
 * NULL) receives the number of iterations. */
csStatus csf_newtonSolve(const csfModel* m, csfData* d, double load, const csfNewtonOptions* opt,
                         int* iters, csError* err);

/* Volume control (passes pressure limit points): solve R(u, load) = 0 together with
 * d->vol_w(u) = vol_target, the load factor being an unknown (bordered Newton: two solves with
 * one factorisation per iteration, Crisfield 1991 Sec. 9.4 with the chamber volume as the
 * constraint). Starts from d->u and d->load; on success d->load holds the load factor. Converged
 * when ||R|| <= rtol fnorm (or atol) and |vol_w - vol_target| <= rtol |vol_target|. On failure the
 * state is restored and CS_ERR_DIVERGED returned. */
csStatus csf_newtonSolveVolume(const csfModel* m, csfData* d, double vol_target,
                               const csfNewtonOptions* opt, int* iters, csError* err);

/* Adaptive ramp of the load factor from d->load to load_end, starting with nstep equal steps;
 * a step that fails is halved (down to 1e-4 of the range), easy steps (<= 5 iterations) grow
 * by 1.5. `iters` (may be NULL) receives the total Newton iterations. */
csStatus csf_loadRamp(const csfModel* m, csfData* d, double load_end, int nstep,
                      const csfNewtonOptions* opt, int* iters, csError* err);

/* Cauchy stress averaged over the quadrature points of tetrahedron e (6: xx yy zz xy yz zx, MPa)
 * at the current d->u (d->pel must be current: call after csf_assemble). */
void csf_tetCauchy(const csfModel* m, const csfData* d, int e, double sigma[6]);

/* Reaction/internal force sum over dofs with fixed[] set and a given direction (0..2), N. */
double csf_reactionSum(const csfModel* m, const csfData* d, int dir);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_MODEL_H */

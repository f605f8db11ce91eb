/* fem_model.h: the full FE model of one actuator: model and data (MuJoCo's mjModel/mjData).
 *
 * Owns: csfModel (mesh, material, loads, Dirichlet data, embedded fibres, the sparse pattern and
 * the solver options; constant once csf_modelFinalize returned, except load values) and csfData
 * (the Newton state: displacement, element dilatations, fibre stresses, residual, tangent
 * values, solver factors, scratch and timers), their create/destroy pairs, the loads, and the
 * state vector get/set. The layers on top: element kernels (fem_element.h, on fem_material.h),
 * assembly of residual and tangent (fem_assembly.h), Newton, load stepping and volume control
 * (fem_newton.h), continuation past limit points (fem_path.h), the actuator's pressure sweep
 * (fem_bend.h). Units: mm, MPa, N, t/mm^3, s.
 * Sign convention: residual R(u) = f_int(u) - f_ext(u, load); tangent K = dR/du. */
#ifndef CS_FEM_MODEL_H
#define CS_FEM_MODEL_H

#include <stddef.h>

#include "core_status.h"
#include "fem_linsolve.h"
#include "fem_material.h"
#include "fem_mesh.h"

#ifdef __cplusplus
extern "C" {
#endif

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
  double* f_dead;      /* (ndof) dead nodal loads (e.g. a tip force), N, applied at full value at
                        * every load, not scaled by the load factor (0 = none) */
  unsigned char* fixed; /* (ndof) 1 = Dirichlet dof */
  double* u_fix;       /* (ndof) prescribed displacement per unit load factor, mm */
  /* embedded fibres: 2-node truss elements whose ends live inside host tetrahedra */
  int nfib;
  int* fib_node;       /* (nfib x 20) host nodes of end 1 (10) then end 2 (10) */
  double* fib_coef;    /* (nfib x 20) -N_a(end 1), +N_a(end 2): d = x2 - x1 = sum coef x */
  double* fib_L0;      /* (nfib) reference length, mm */
  double* fib_EA;      /* (nfib) axial stiffness E A, N */
  int fib_tension_only; /* 1 (default): smoothed tension-only law; 0: linear both ways */
  int fib_projected;    /* fibre points that lay just outside the faceted mesh surface and were
                         * projected onto it (csf_modelAddFibre) */
  int fib_split;        /* 1 (default): a fibre segment whose chord crosses element faces is
                         * split there (csf_modelAddFibre), so every fibre element lies in one
                         * tetrahedron and adds no fill to the factorisation; 0: one element per
                         * segment tied to both end hosts (couples 20 nodes) */
  int fib_geo_tension;  /* 1: the tangent keeps the fibre's geometric stiffness only in tension,
                         * EA/L0 max(S, 0) I (residual unchanged, exact); 0: EA/L0 S I */
  csfLinSolverOptions solver; /* sparse direct solver used by csf_dataCreate (default MUMPS);
                               * solver.symmetric: -1 (default) = LDL^T exactly when
                               * csf_modelSymmetric holds at csf_dataCreate, 0 = always LU,
                               * 1 = always LDL^T */
  /* sparse pattern (3x3 node blocks, scalar CSR), built by csf_modelFinalize (fem_assembly.h) */
  int finalized;
  int* adj_ptr;        /* (nnode + 1) */
  int* adj;            /* (nadj) neighbour nodes, sorted per row */
  int* row_ptr;        /* (ndof + 1) */
  int* col;            /* (nnz) */
  int nnz;
  int* tet_map;        /* (ntet x 100) block slot of node pair (a, b) in row of node a */
  int* fib_map;        /* (nfib x 400) same for fibre node pairs */
  unsigned char* fib_single; /* (nfib) 1: both ends in one host (10-node chord) */
  int* face_local;     /* (nface x 6) local node index of each face node in its tet */
} csfModel;

/* Create a model on `mesh` (not copied): reference geometry of every element; no loads,
 * nothing fixed. NULL and err on failure (an inverted element names its index). */
csfModel* csf_modelCreate(const csfMesh* mesh, const csfMaterial* mat, csError* err);

/* Free; NULL-safe. */
void csf_modelDestroy(csfModel* m);

/* Apply a pressure of `p_unit` MPa per unit load factor to every face with tag `tag` (adds to
 * earlier calls). Returns the number of faces, or a negative csStatus. */
int csf_modelAddPressure(csfModel* m, int tag, double p_unit);

/* Add fibres along polylines given in reference coordinates (fem_fibre.c). `pts` (npts x 3, mm)
 * is one polyline; each segment becomes truss elements tied to the tetrahedra containing its
 * end points (split at element faces with fib_split). A point just outside the faceted mesh
 * surface (within 0.2 of the nearest element's size) is projected onto it (counted in
 * fib_projected); a point farther out is an error naming it and its distance. E (MPa),
 * radius (mm). Must be called before csf_modelFinalize. */
csStatus csf_modelAddFibre(csfModel* m, int npts, const double* pts, double E, double radius,
                           csError* err);

/* 1 when the consistent tangent is symmetric: every pressurised face set is a closed surface
 * (each face edge shared by exactly two faces of the same pressure). The follower pressure on a
 * closed chamber is conservative (the gradient of p V) and its load stiffness, non-symmetric
 * face by face, is symmetric in sum; the Yeoh law, the condensed mixed fields, the fibres,
 * gravity and dead loads are conservative too. 0 for open pressurised surfaces (a pressurised
 * patch, a tube bore cut by symmetry planes): their boundary terms make the load stiffness
 * non-symmetric, and the LU path is used. */
int csf_modelSymmetric(const csfModel* m);

/* Timers and counters, accumulated over the life of a csfData (s, counts). */
typedef struct csfStats_ {
  double t_assemble, t_factor, t_solve; /* wall seconds (t_solve includes GMRES) */
  long n_assemble, n_factor, n_newton;  /* counts */
  long n_krylov;      /* linear solves done by GMRES on an older factorisation (fem_newton.h) */
  long n_krylov_iter; /* GMRES iterations in those solves */
  long n_restore;     /* returns of the line search's watchdog to the best iterate */
  long n_repeat;      /* Newton iterates whose |R| repeated an earlier one of the same solve to
                       * 1e-12 (a cycle of the iteration; fem_newton.c) */
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
  double* jel;    /* (ntet) element's smallest pointwise J at its quadrature points (last
                   * assembly) */
  double* gel;    /* (ntet x 30) g_e = int cof(F) : G dV at the last assembly, mm^2 */
  double* theta_save; /* (ntet) scratch: theta at Newton entry */
  double* u_best, *theta_best, *fib_S_best; /* (ndof, ntet, nfib) scratch: the best Newton
                                             * iterate so far (the line search's watchdog) */
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
  double* kry_b;  /* (ndof) scratch: right-hand side of a GMRES solve */
  double* kry_work; /* (csf_gmresWorkSize(ndof, CSF_KRYLOV_RESTART)) GMRES workspace */
  int have_factor;   /* 1: d->ls holds a factorisation of some earlier tangent (a preconditioner) */
  int refactor_next; /* 1: the last GMRES solve was slow: factor the next tangent afresh */
  double rnorm;   /* ||R|| on free dofs after the last assembly, N */
  double fnorm;   /* force scale for convergence: ||f_int|| over all dofs + ||f_ext||, N */
  double jmin;    /* smallest pointwise J at quadrature points after the last assembly */
  double load;    /* load factor of the last assembly */
  csfLinSolver* ls;
  csfStats stats;
} csfData;

/* GMRES restart length of the Newton solves (fem_newton.c) */
#define CSF_KRYLOV_RESTART 40

/* Allocate the data of a finalised model, all in one place (nothing is allocated by the
 * assembly or Newton afterwards), and analyse the pattern with the sparse solver: LDL^T when
 * the tangent is symmetric (csf_modelSymmetric, unless solver.symmetric forces a mode). */
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

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_MODEL_H */

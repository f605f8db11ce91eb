/* fem_rom_act.h: the reduced-order FE model of one actuator, from its files (issue 34).
 *
 * Owns: csfRomActuator: the actuator's FE model on the snapshots' mesh (meshed again from the
 * same parameters and checked against the basis file's mesh signature), the reduced model on
 * the basis of tools/rom_basis.py (fem_rom.h) with the element weights of a hyper-reduction
 * file when given and the twelve chambers' pressure loads in closed form
 * (csf_romChamberTensors: exact, so the chamber faces are never hyper-reduced), the chamber-pressure and tip-force maps, and the reduced statics of a load
 * (chamber pressures per segment, gravity, tip force) reached by an adaptive ramp from the last
 * solved load; the displacement and the measurements (fem_measure.h) of the solved state.
 * Basis file (format "crawlsim-rom-basis 1"): V [ndof, n], attributes n, fe_mesh_size_mm,
 *   mesh_nnode, mesh_ntet, mesh_x_sum, mesh_x_sq (the mesh signature: sum and sum of squares of
 *   the reference coordinates, mm, mm^2).
 * Weights file (format "crawlsim-rom-weights 1"): tet_id, tet_w, fibre_id, fibre_w, face_id,
 *   face_w (element indices of the FE model and their weights; a set that is absent keeps every
 *   element at weight 1).
 * Units: mm, MPa, N, s. */
#ifndef CS_FEM_ROM_ACT_H
#define CS_FEM_ROM_ACT_H

#include "core_status.h"
#include "fem_actuator.h"
#include "fem_rom.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* csfRomActuator.k_lag's and .bfgs's defaults: a tangent kept while the steps on it contract
 * |r| by 0.9 at least, corrected by BFGS with 8 secant pairs. The plain chord (bfgs 0) did not
 * pay on the bend sweep (session romfast: the three-field Newton contracts only linearly, a
 * step on a kept tangent less, and the residual alone costs a quarter of the tangent's
 * evaluation); with the BFGS pairs it forms a third of Newton's tangents and costs less than
 * Newton (measured: docs/notes/rom.md, session romacc). k_lag 0: Newton. */
#define CSF_ROM_ACT_K_LAG 0.9
#define CSF_ROM_ACT_BFGS 8
/* csfRomActuator.rtol's default: the FE sweep's residual test (fem_bend.c
 * CSF_BEND_NEWTON_RTOL), |r| <= rtol (|V^T f_int| + |V^T f_ext|) */
#define CSF_ROM_ACT_RTOL 1e-6

typedef struct csfRomActuator_ {
  csfActuatorFE fe;    /* the FE model the reduced forces come from (no solver data) */
  csfRom* rom;
  csfRomData* d;
  double* face_p;      /* (nface) current face pressures, MPa */
  double* Ftip;        /* (n x 3) reduced tip force per unit force along e1, e2, e3 */
  double* f_dead;      /* (n) current reduced dead load */
  double* u;           /* (ndof) displacement of the solved state, mm */
  double p[CSR_NSEG][CSR_NCHAMBER], gravity[3], tip_force[3]; /* the solved load */
  double p0[CSR_NSEG][CSR_NCHAMBER], g0[3], F0[3]; /* ramp scratch: the ramp's start */
  double* q_conv;      /* (n) last converged q */
  /* the predictor (csf_romActuatorSolve): the converged state before q_conv and both loads (the
   * 12 chamber pressures in MPa, gravity in 1e4 mm/s^2, the tip force in N), nhist of them valid */
  double* q_prev;      /* (n) */
  double L_prev[18], L_conv[18];
  int nhist;
  double k_lag;        /* the reduced Newton's lagged tangent (fem_rom.h csfRomNewtonOptions) */
  int bfgs;            /* its BFGS pairs on the kept factor (csfRomNewtonOptions.bfgs; 0: chord) */
  double rtol;         /* its relative residual test (csfRomNewtonOptions.rtol) */
  int bfgs_keep;       /* the pairs kept from one load step to the next (csfRomNewtonOptions) */
  long n_newton;       /* reduced Newton iterations so far */
  int n_steps, n_cutbacks; /* ramp steps so far */
  char basis_path[512];
} csfRomActuator;

/* Build the reduced actuator: mesh `act` with spec (its mesh_size must be the basis file's, the
 * mesh symmetric), read the basis, check the mesh signature, read the weights (weights_path may
 * be NULL). CS_OK or an error naming the file and the cause. */
csStatus csf_romActuatorCreate(const csrActuator* act, const csfActuatorSpec* spec,
                               const char* basis_path, const char* weights_path,
                               csfRomActuator* ra, csError* err);
void csf_romActuatorDestroy(csfRomActuator* ra);

/* Replace the kept elements and weights of every set the weights file holds (the others stay
 * as they are): a leg file's every-element model hyper-reduced by another fit without its
 * set-up (`crawlsim rom check --leg-file`). An error names the file and the cause. */
csStatus csf_romActuatorSetWeights(csfRomActuator* ra, const char* weights_path, csError* err);

/* The same from a reduced model built elsewhere, without gmsh (a leg file,
 * robot/rom/robot_rom_file.h): ra takes the mesh, the finalised FE model and the rom on it (its
 * weights, pressure basis and the twelve chambers' forms set); csf_romActuatorDestroy frees them,
 * also on failure. spec->ratio sets the bending axis of the measurements (fem_actuator.h
 * csf_actuatorFEFromModel); source names the file in messages. */
csStatus csf_romActuatorFromModel(const csrActuator* act, const csfActuatorSpec* spec,
                                  csfMesh* mesh, csfModel* model, csfRom* rom,
                                  const char* source, csfRomActuator* ra, csError* err);

/* The mesh size (l_soft, mm) a basis file was made on (NAN and err when unreadable). */
double csf_romBasisMeshSize(const char* basis_path, csError* err);

/* Reduced statics at chamber pressures p (MPa, segment s chamber j at 4 s + j), gravity g
 * (mm/s^2) and tip force F (N), ramped
 * from the last solved load in adaptive steps (halved on failure down to 1e-4 of the range,
 * grown by 1.5 after easy ones). Each step starts from the secant predictor of the last two
 * solved states when its load continues theirs along the same line (a sweep), else from the
 * last solved state; the reduced Newton keeps its tangent while it contracts by ra->k_lag
 * (csfRomNewtonOptions.k_lag; 0: Newton). No load at all gives the reference state (q = 0), as the FE's
 * p = 0 row. On failure the last solved state is kept and CS_ERR_DIVERGED returned. ra->u holds
 * the displacement afterwards. */
csStatus csf_romActuatorSolve(csfRomActuator* ra, const double* p,
                              const double g[3], const double F[3], csError* err);

/* The load (p: MPa, segment s chamber j at 4 s + j; g: mm/s^2; F: N) as the rom's csfRomLoad
 * (its face pressures and reduced dead load live in ra; valid until the next call or solve). */
void csf_romActuatorLoad(csfRomActuator* ra, const double* p, const double g[3],
                         const double F[3], csfRomLoad* ld);

/* The training snapshots a basis file carries (tools/rom_basis.py): *ns of them, q (ns x n),
 * p (ns x 12, MPa), g (ns x 3), F (ns x 3); the caller frees the four arrays. */
csStatus csf_romBasisReadTraining(const char* basis_path, int n, int* ns, double** q, double** p,
                                  double** g, double** F, csError* err);

/* A csfData view of the solved displacement for fem_measure.h (only u is set; valid until
 * the next solve). */
csfData csf_romActuatorView(const csfRomActuator* ra);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_ROM_ACT_H */

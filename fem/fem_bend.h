/* fem_bend.h: `crawlsim bend --model fe`: pressure sweep of the full FE actuator model.
 *
 * Owns: csfBendOptions (chambers, pressure range, --until-angle, mesh size, fibres, gravity,
 * output paths), csf_bend (mesh -> model -> adaptive load stepping -> per-segment bending angles
 * from the deformed end-face frames -> csrBendCurve), and the measurement of those angles.
 * Units: MPa, mm, degrees, seconds. Frame: the actuator's base frame (e1, e2, e3), z = e3 along
 * the undeformed axis from the clamped base (z = 0). */
#ifndef CS_FEM_BEND_H
#define CS_FEM_BEND_H

#include "core_status.h"
#include "fem_newton.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Per-step report for progress output and benchmarks (the library itself never prints). */
typedef struct csfBendStep_ {
  double p;            /* pressure of the converged step, MPa */
  double dp;           /* its increment, MPa */
  int newton_iters;    /* Newton iterations of this step */
  int cutbacks;        /* failed attempts before it converged */
  double wall;         /* wall time of the step including failed attempts, s */
  double angle_total;  /* total bending angle, deg */
  double angle_deg[3]; /* per segment, deg */
  int volume_control;  /* 1: a step of the volume-controlled path past a limit point (dp may be
                        * negative there), 0: a pressure-controlled step */
  double volume;       /* weighted chamber volume sum_f p_unit V_f of the state, mm^3 */
} csfBendStep;

typedef void (*csfBendProgress)(void* user, const csfBendStep* step);

/* Summary of a run (filled when csfBendOptions.info is not NULL). */
typedef struct csfBendInfo_ {
  int ntet, nnode, nfibre, ndof;
  int n_steps, n_cutbacks;
  int n_gravity_steps; /* converged steps of the gravity ramp before the pressure sweep */
  long n_newton;
  double t_mesh, t_setup, t_total;         /* wall s: gmsh + reading, model + fibres, all */
  double t_assemble, t_factor, t_solve;    /* wall s, accumulated */
  double factor_nnz;                       /* entries of the sparse factors */
  long n_factor;       /* numeric factorisations of the tangent */
  long n_krylov, n_krylov_iter; /* linear solves by GMRES on an older factorisation, iterations */
  char solver[32];     /* sparse solver and mode used ("mumps-ldlt", ...) */
  double p_limit;  /* MPa: pressure limit point of the path (the largest pressure reached
                    * under volume control after the pressure-controlled step collapsed; with
                    * continuation off, the last converged pressure), NAN when none was met */
  double p_resume; /* MPa: where the path was stable again above p_limit and the sweep resumed
                    * (NAN: not resumed); a pressure-controlled load snaps across */
  double angle_limit, angle_resume; /* total angle at p_limit and at p_resume, deg */
  int n_volume_steps; /* converged steps under chamber-volume control */
  char limit_note[200]; /* why the path past the limit ended without resuming ("" = n/a) */
  double max_j_dev; /* max |theta - 1| over elements at the last state (volume preservation) */
  int n_until_trials, n_until_failed; /* --until-angle refinement: equilibrium trials, failures */
  char until_note[200]; /* the last failed trial's pressure and Newton message ("" = none) */
} csfBendInfo;

typedef struct csfBendOptions_ {
  unsigned chambers[CSR_NSEG]; /* per segment, bit j-1 set = chamber Omega_j pressurised */
  double p_max;        /* MPa, end of the sweep */
  double p_step;       /* MPa, output spacing and largest load step */
  double until_angle;  /* deg, stop when the total angle reaches it (NAN = off) */
  double angle_tol;    /* deg, accuracy of p_until_angle's angle */
  double mesh_size;    /* l_soft, mm */
  double fibre_size;   /* l_fibre, mm (0: 0.4 l_soft - 0.1, the paper's Table 1 pairing) */
  int fibres;          /* 1 = embed the double-helix fibres (n turns per segment) */
  int fibre_compression; /* 1 (default): linear in tension and compression (Green strain, St.
                          * Venant); 0: smoothed tension-only (Newton cycles on the baseline) */
  int fibre_geo_tension; /* 0 (default): consistent fibre tangent; 1: geometric stiffness only
                          * in tension (csfModel.fib_geo_tension; the residual is unchanged) */
  csfFormulation form; /* element formulation (default CSF_FORM_MIXED_P0; CSF_FORM_DISPLACEMENT
                        * is plain P2 = CalculiX's C3D10, for cross-checks) */
  csfLineSearch line_search; /* Newton line search (default CSF_LS_RESIDUAL) */
  int continuation;    /* 1 (default): past a limit point, follow the path by chamber-volume
                        * control and resume pressure control where it is stable again; 0: stop
                        * at the limit (p_limit = last converged pressure) */
  void (*newton_monitor)(void* user, const csfNewtonIter* it); /* optional, per Newton iteration */
  double gravity[3];   /* mm/s^2 in the base frame, e.g. {0, 0, -9810}; zeros = off */
  const char* work_stem; /* path prefix for the .geo/.msh files (default "crawlsim_fe") */
  const char* vtu_path;  /* deformed mesh at the last state (ParaView .vtu), NULL = none */
  const char* inp_path;  /* same model as a CalculiX/ABAQUS .inp deck, NULL = none */
  int threads;           /* OpenMP threads for assembly (0 = default) */
  int krylov;            /* 1: Newton reuses the last factorisation as a GMRES preconditioner
                          * (csfNewtonOptions.krylov); 0 (default): factor every iteration */
  int fibre_split;       /* 1 (default): fibre elements split at element faces (csfModel.fib_split) */
  csfBendProgress progress; /* called after each converged step (NULL = none) */
  void* progress_user;
  csfBendInfo* info;     /* optional summary output */
} csfBendOptions;

/* Defaults: chambers Omega1 & Omega2 of all segments, p_max 0.4, p_step 0.05, until_angle off,
 * angle_tol 0.1 deg, mesh_size 4, fibres on (tension and compression, consistent tangent),
 * gravity off. */
csfBendOptions csf_bendDefault(void);

/* Parse a chamber list "1,2" (applied to every segment) into opts->chambers. */
csStatus csf_bendSetChambers(csfBendOptions* opts, const char* list, csError* err);

/* Run the sweep. `out` must be initialised (csr_bendCurveInit); rows are appended at each
 * multiple of p_step up to p_max, and at p_until_angle when it is found. At a pressure limit
 * point the path is followed by chamber-volume control (info->p_limit); where it is stable again
 * above the limit the sweep resumes (info->p_resume; the rows skip the snap-through), else it
 * ends there. Returns CS_OK also when a limit point stops the sweep early (info->p_resume and
 * out->p_until_angle = NAN tell). */
csStatus csf_bend(const csrActuator* act, const csfBendOptions* opts, csrBendCurve* out,
                  csError* err);

/* Angles of the actuator at the current state d->u: per segment and total (deg), and the tip
 * centroid (mm). Planes are the segments' end faces z = start(s), start(s) + S_s and the base/tip
 * faces. Each angle is the rotation between two fitted face frames about the reference bending
 * axis `axis` (unit, base frame; csf_bendAxisAngle) and unwrapped against `prev` (previous
 * values: 3 segments then total; may be NULL), so bends beyond 180 and 360 deg are followed
 * continuously. */
void csf_bendMeasure(const csrActuator* act, const csfModel* m, const csfData* d,
                     const double axis[3], const double prev[4], double angle_deg[3],
                     double* total_deg, double tip[3]);

/* Angle (rad) of the relative rotation Ra^T Rb (row-major frames) about the unit `axis`: the
 * twist of its swing-twist decomposition, smooth through full turns, unwrapped to within pi of
 * `prev` (rad). axis NULL: the full rotation angle. */
double csf_bendAxisAngle(const double Ra[9], const double Rb[9], const double axis[3],
                         double prev);

/* Rigid rotation R (row-major 3x3) best fitting the deformed positions of the nodes of a plane
 * z = const (reference X, deformed x, n nodes): least-squares fit of the in-plane directions,
 * polar-orthonormalised; R e3 is the deformed face normal. Returns 0, or -1 if degenerate. */
int csf_fitPlaneFrame(int n, const double* X, const double* x, double R[9], double centroid[3]);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_BEND_H */

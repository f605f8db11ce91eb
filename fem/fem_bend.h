/* fem_bend.h: `crawlsim bend --model fe`: pressure sweep of the full FE actuator model.
 *
 * Owns: csfBendOptions (the actuator's discretisation and loads as a csfActuatorSpec, the
 * pressure range, --until-angle, continuation, stiffness probes, outputs), csfBendRecord (the
 * full per-segment kinematics of every output row, for the calibration), and csf_bend: the
 * sweep as named stages (set-up, dead-load ramp, pressure steps with cut-backs and a secant
 * predictor, limit points by volume control, refinement of --until-angle, output rows with
 * optional stiffness probes, finish).
 * Units: MPa, mm, degrees, seconds. Frame: the actuator's base frame (e1, e2, e3), z = e3 along
 * the undeformed axis from the clamped base (z = 0). */
#ifndef CS_FEM_BEND_H
#define CS_FEM_BEND_H

#include <signal.h>

#include "core_status.h"
#include "fem_actuator.h"
#include "fem_measure.h"
#include "fem_newton.h"
#include "fem_wall.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The free surfaces of the actuator at a converged state (fem_wall.h: crease onset and the
 * closing of chambers, which a model without self-contact cannot pass). */
typedef struct csfBendWall_ {
  csfWallStretch vented; /* the inner surfaces of the vented chambers (ratio 0): npoint 0 when
                          * every chamber is pressurised */
  csfWallStretch skin;   /* the outer lateral surface (the untagged boundary faces) */
  csfWallGap gap;        /* the smallest gap between opposite walls (CSF_WALL_COS_OPPOSITE) of
                          * any vented chamber */
  int gap_tag;           /* that chamber's face tag (CSF_TAG_CHAMBER; -1: none) */
  double gap0;           /* the same node's smallest such gap in the reference state, mm */
} csfBendWall;

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
  int neg_pivots;      /* negative pivots of the step's last tangent factorisation (LDL^T:
                        * negative eigenvalues of K, csf_linSolverNegativePivots; 0 = stable
                        * under pressure control); -1 with LU (no inertia) */
  int branch;          /* 0: the path as it came; 1: on a branch switched to at a bifurcation;
                        * 2: the first state of that branch (note says what broke) */
  double asym;         /* largest twin-chamber asymmetry |V_j - V_k| / (V_j + V_k) of the
                        * state on a volume-controlled stretch (csf_bendChamberAsymmetry), NAN
                        * when not measured */
  const char* note;    /* with branch 2: the bifurcation's report line (csfBendInfo's
                        * bifurcation_note); else NULL */
  double lam_vented;   /* smallest plane-strain-equivalent stretch of the vented chambers' walls
                        * (csfWallStretch.lam_eq; INFINITY: none vented) */
  double lam_skin;     /* the same on the outer surface */
  double gap;          /* smallest gap between opposite walls of a vented chamber, mm */
  double jmin;         /* smallest pointwise J of the state (csf_worstElement) */
} csfBendStep;

typedef void (*csfBendProgress)(void* user, const csfBendStep* step);

/* Summary of a run (filled when csfBendOptions.info is not NULL). */
typedef struct csfBendInfo_ {
  int ntet, nnode, nfibre, ndof;
  int nfibre_projected; /* fibre points projected onto the faceted surface (csf_modelAddFibre) */
  int n_steps, n_cutbacks;
  int n_gravity_steps; /* converged steps of the dead-load ramp (gravity, tip force) before the
                        * pressure sweep */
  long n_newton;
  double t_mesh, t_setup, t_total;         /* wall s: gmsh + reading, model + fibres, all */
  double t_assemble, t_factor, t_solve;    /* wall s, accumulated */
  double factor_nnz;                       /* entries of the sparse factors */
  long n_factor;       /* numeric factorisations of the tangent */
  int n_repivot;       /* of them, unpivoted LDL^T redone with pivoting (fem_linsolve.h) */
  long n_krylov, n_krylov_iter; /* linear solves by GMRES on an older factorisation, iterations */
  long n_restore, n_repeat;     /* Newton's watchdog returns and repeated iterates (csfStats) */
  char solver[32];     /* sparse solver and mode used ("mumps-ldlt", ...) */
  int factor_threads;  /* threads of the factorisations and solves (csf_linSolverThreads) */
  double factor_flops; /* flops of one factorisation, the analysis' estimate (0: KLU) */
  int mpi_ranks;       /* MPI ranks of the factorisations (csfActuatorSpec.mpi_ranks; 1: this
                        * process alone) */
  double factor_mem_rank_mb, factor_mem_total_mb; /* memory of the last factorisation, MB: the
                                                   * most on one rank, the sum (MUMPS INFOG(21),
                                                   * (22)) */
  double p_limit;  /* MPa: pressure limit point of the path (the largest pressure reached
                    * under volume control after the pressure-controlled step collapsed; with
                    * continuation off, the last converged pressure), NAN when none was met */
  double p_resume; /* MPa: where the path was stable again above p_limit and the sweep resumed
                    * (NAN: not resumed); a pressure-controlled load snaps across */
  double angle_limit, angle_resume; /* total angle at p_limit and at p_resume, deg */
  int n_volume_steps; /* converged steps under chamber-volume control */
  int limit_shown;    /* 1: the pressure fell past p_limit under volume control (a limit point);
                       * 0: the path ended at p_limit before it fell (both controls failed
                       * there, limit_note says how) or continuation is off */
  int n_hard_passed;  /* hard stretches of the path (pressure control failed, the pressure kept
                       * rising under volume control: no limit point) followed by volume */
  int n_rows_skipped; /* output pressures passed on a volume-controlled stretch without a row */
  double p_definite;   /* MPa: last converged state (pressure- or volume-controlled) before the
                        * first one whose tangent had negative pivots (NAN: every tangent
                        * positive definite, or LU) */
  double p_indefinite; /* MPa: that first state with negative pivots (NAN: none): between the
                        * two the path crossed a critical point (limit or bifurcation) */
  int neg_pivots_max;  /* most negative pivots met on the path (-1: LU, no inertia) */
  char limit_note[200]; /* why the path past the limit ended without resuming ("" = n/a) */
  int n_bifurcation;    /* bifurcations met (a negative pivot more while the pressure rose) */
  int branch_switched;  /* 1: the sweep left the path there along the critical mode */
  double p_bifurcation, angle_bifurcation; /* MPa, deg: the first state past the first one */
  char bifurcation_note[1024]; /* its report (csf_bendBifurcationNote; "" = none) */
  double max_j_dev; /* max |theta - 1| over elements at the last state (volume preservation) */
  double j_min;     /* smallest pointwise J (det F at quadrature points) at the last state: the
                     * most distorted element (csf_worstElement) */
  double j_min_X[3]; /* its reference centroid, mm */
  csfBendWall wall;  /* the free surfaces at the last state */
  double j_min_wall_dist; /* reference distance from that element's centroid to the point of
                           * wall.vented.lam_eq, mm (NAN: no vented chamber) */
  double p_crease, angle_crease; /* MPa, deg: the first converged state whose vented chambers'
                                  * walls were compressed past the crease onset (lam_eq <
                                  * CSF_CREASE_STRETCH), NAN: none */
  double p_crease_skin;          /* MPa: the same for the outer surface, NAN: none */
  int n_until_trials, n_until_failed; /* --until-angle refinement: equilibrium trials, failures */
  long n_probe_newton; /* Newton iterations spent in stiffness probes (included in n_newton) */
  char until_note[200]; /* the last failed trial's pressure and Newton message ("" = none) */
} csfBendInfo;

/* One output row of a sweep with everything the calibration needs (csfBendOptions.record). */
typedef struct csfBendRow_ {
  double p;                     /* load factor (MPa: the pressure of a ratio-1 chamber) */
  csfSegmentState seg[CSR_NSEG];
  double tip[3], Rtip[9];       /* tip-face centroid (mm) and frame, base frame */
  double angle_total;           /* base-to-tip angle about the reference axis, deg */
  int nprobe;                   /* stiffness probes at this row (0 or 3) */
  int probe_ok[3];              /* 1: the probed state converged */
  double probe_force[3][3];     /* tip force of each probe, N (base frame), on top of tip_force */
  csfSegmentState probe_seg[3][CSR_NSEG]; /* kinematics under each probe */
  double probe_tip[3][3];       /* tip centroid under each probe, mm */
} csfBendRow;

/* Caller-owned list of rows (capacity cap; csf_bend stops recording when full). */
typedef struct csfBendRecord_ {
  size_t m, cap;
  csfBendRow* row;
} csfBendRecord;

typedef struct csfBendOptions_ {
  csfActuatorSpec spec; /* discretisation, chamber pressure ratios, gravity, tip force */
  double p_max;        /* MPa, end of the sweep (load factor) */
  double p_step;       /* MPa, output spacing and largest load step */
  double p_first;      /* MPa, first load step from the unloaded state (0: p_step / 4; the
                        * linearised step from u = 0 overshoots: measured on the baseline, 0.05
                        * and 0.025 MPa failed after 3 iterations each, 0.0125 converged) */
  double until_angle;  /* deg, stop when the total angle reaches it (NAN = off) */
  double angle_tol;    /* deg, accuracy of p_until_angle's angle */
  csfLineSearch line_search; /* Newton line search (default CSF_LS_RESIDUAL) */
  double newton_rtol;        /* Newton's |R| <= rtol (|f_int| + |f_ext|) (default
                              * CSF_BEND_NEWTON_RTOL, fem_bend.c says why) */
  int continuation;    /* 1 (default): past a limit point, follow the path by chamber-volume
                        * control and resume pressure control where it is stable again; 0: stop
                        * at the limit (p_limit = last converged pressure) */
  int branch_switch;   /* 1: at a bifurcation (a converged state with more negative pivots than
                        * the one before while the pressure rises) try to leave the path along
                        * the critical mode (csfLimitOptions.branch_switch); 0 (default): stay.
                        * Either way the first bifurcation on a volume-controlled stretch is
                        * reported with its critical mode (bifurcation_note). Off by default:
                        * on the thin-walled actuator it found no branch and cost ~4 min
                        * (fem/README.md "Branch switching") */
  double branch_amp;   /* mm, the perturbation's largest nodal displacement (0: fem_path.c's
                        * default, 0.05 mm) */
  double volume_from;  /* MPa: from the first converged pressure at or above it, follow the path
                        * by chamber volume, as past a limit point, until the pressure has risen
                        * steadily (csf_passLimit), then resume pressure control; every output
                        * pressure passed gets its row. 0 (default): volume control only where
                        * pressure control fails. Needs continuation; checks the volume path
                        * against pressure control (test_fem_bend) */
  void (*newton_monitor)(void* user, const csfNewtonIter* it); /* optional, per Newton iteration */
  const char* vtu_path;  /* deformed mesh at the last state (ParaView .vtu), NULL = none */
  const char* inp_path;  /* same model as a CalculiX/ABAQUS .inp deck, NULL = none */
  int threads;           /* OpenMP threads of the assembly, and the factorisation's count above
                          * CSF_MT_MIN_FLOPS (fem_linsolve.h); 0 = OpenMP's default. The
                          * commands pass the thread plan's count (fem_threads.h) */
  int krylov;            /* 1: Newton reuses the last factorisation as a GMRES preconditioner
                          * (csfNewtonOptions.krylov); 0 (default): factor every iteration */
  int symmetric;         /* -1 (default): LDL^T exactly where the tangent is symmetric; 0: LU;
                          * 1: LDL^T (csfModel.solver.symmetric) */
  /* stiffness probes: at output rows whose pressure is within 1e-9 p_step of one of
   * probe_p[0..nprobe_p), three extra equilibria with a tip force probe_force[k] e_k added
   * (k = 0, 1, 2: e1, e2, e3 of the base frame), each from the row's converged state */
  int nprobe_p;
  double probe_p[16];    /* MPa */
  double probe_force[3]; /* N per direction (0: that probe is skipped) */
  csfBendRecord* record; /* optional: the full kinematics of every output row */
  csfBendProgress progress; /* called after each converged step (NULL = none) */
  void* progress_user;
  csfBendInfo* info;     /* optional summary output */
  const volatile sig_atomic_t* cancel; /* NULL, or a flag the caller sets (a signal handler):
                          * the sweep then ends after the load step in progress and returns
                          * CS_ERR_INTERRUPTED naming the pressure; `out` keeps its rows */
} csfBendOptions;

/* Defaults: csf_actuatorSpecDefault (Omega1 & Omega2 of all segments, l_soft 4, fibres), p_max
 * 0.4, p_step 0.05, until_angle off, angle_tol 0.1 deg, no probes, no record. */
csfBendOptions csf_bendDefault(void);

/* Parse a chamber list "1,2" (applied to every segment at ratio 1) into opts->spec.ratio. */
csStatus csf_bendSetChambers(csfBendOptions* opts, const char* list, csError* err);

/* Run the sweep. `out` must be initialised (csr_bendCurveInit); rows are appended at each
 * multiple of p_step up to p_max, and at p_until_angle when it is found. At a pressure limit
 * point the path is followed by chamber-volume control (info->p_limit); where it is stable again
 * above the limit the sweep resumes (info->p_resume; the rows skip the snap-through), else it
 * ends there. Returns CS_OK also when a limit point stops the sweep early (info->p_resume and
 * out->p_until_angle = NAN tell). */
csStatus csf_bend(const csrActuator* act, const csfBendOptions* opts, csrBendCurve* out,
                  csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_BEND_H */

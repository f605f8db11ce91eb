/* fem_calibration.h: the FE calibration of a leg's chamber modes and stiffness (calibration
 * layer: writes the table that robot/calibration/robot_calibration.h reads; docs/design.md "Data flow").
 *
 * Owns: the calibration cases (chamber pressure ratios per segment with their sweep range:
 * the modes the legs' model is fitted to, the combinations held out of the fit to measure its
 * error, the symmetry check, the stiffness probes, the leg under its own weight), running one
 * case as an FE pressure sweep with the full per-segment kinematics (fem_bend.h), writing it as
 * one HDF5 file (each case its own file, so a calibration of several hours resumes case by
 * case), and merging the case files into one table.
 *
 * Table layout (HDF5; every case file has the same layout with one case):
 *   root attributes: format "crawlsim-fe-calibration 1", every actuator parameter under its
 *     paper name, fe_mesh_size_mm, fe_fibre_size_mm, fe_fibre_split, fe_fibre_law, fe_formulation,
 *     fe_kappa_ratio, fe_solver, version;
 *   /cases/<name>/ attributes kind ("mode", "holdout", "symmetry", "gravity"), ratio (4: the
 *     chamber pressures of every segment per unit pressure p, MPa/MPa), p_step, p_max (asked),
 *     p_end (reached), p_limit (NAN if none), status ("complete" or why it ended), gravity (3,
 *     mm/s^2), wall_time_s, newton_iterations;
 *   /cases/<name>/pressure [M] (MPa, the load factor p: chamber j is at ratio[j] p),
 *     bend [M,3,2] (rad, each segment's bend vector in its base-face frame, csrBendMap's
 *     convention), twist [M,3] (rad), stretch [M,3] (-), radial [M,3] (-), radial_max [M,3]
 *     (mm), tip [M,3] (mm, base frame), angle_total_deg [M];
 *   with stiffness probes: probe_pressure [K] (MPa), probe_force [K,3] (N along e1, e2, e3:
 *     the force each probe used, 0 where it failed),
 *     probe_bend [K,3,3,2] (probe k, segment, component: the bend vector under the probe),
 *     probe_stretch [K,3,3], probe_tip [K,3,3] (mm), and the reduced stiffness EI [K,3,2]
 *     (N mm^2: bending stiffness of each segment from the e1 and e2 probes, about the axis of the
 *     moment at the segment's centre) and EA [K,3] (N, axial stiffness from the e3 probe).
 * Units: mm, MPa, N, rad. */
#ifndef CS_FEM_CALIBRATION_H
#define CS_FEM_CALIBRATION_H

#include "core_status.h"
#include "fem_bend.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

#define CSF_CAL_FORMAT "crawlsim-fe-calibration 1"
#define CSF_CAL_MAX_CASES 64 /* the case list and the files a merge takes (cmd_calibrate.c) */

typedef enum csfCalKind_ {
  CSF_CAL_MODE = 0,     /* fitted: the model must return these points */
  CSF_CAL_HOLDOUT = 1,  /* not fitted: the model's error is measured on them */
  CSF_CAL_SYMMETRY = 2, /* a mode the symmetry of the section predicts from another one */
  CSF_CAL_GRAVITY = 3,  /* the leg under its own weight (p = 0) */
} csfCalKind;

/* One calibration case. */
typedef struct csfCalCase_ {
  const char* name;    /* file stem and group name, e.g. "O12" */
  csfCalKind kind;
  double ratio[CSR_NCHAMBER]; /* chamber j of every segment at ratio[j] p */
  double p_max;        /* MPa: end of the sweep (the sweep ends earlier at a limit point) */
  int probes;          /* 1: stiffness probes at CSF_CAL_PROBE_P */
  double gravity[3];   /* mm/s^2, base frame (gravity cases) */
  const char* about;   /* one line for listings and the README */
} csfCalCase;

/* The cases of the calibration, in running order (fitted modes first). *n gets the count. */
const csfCalCase* csf_calibrationCases(int* n);

/* Find a case by name; NULL if none. */
const csfCalCase* csf_calibrationCaseFind(const char* name);

/* FE settings of a calibration run (shared by every case: the table records them). */
typedef struct csfCalSettings_ {
  double mesh_size;    /* l_soft, mm (4: the paper's choice, within 2.3 % of l_soft 1.5) */
  double fibre_size;   /* l_fibre, mm (default 0.5; 0: the actuator spec's default l_soft / 8) */
  int fibre_split;     /* fibre elements split at element faces */
  int mesh_symmetric;  /* 1: the mesh with the section's symmetry
                        * (csfActuatorSpec.mesh_symmetric). Root attribute fe_mesh_symmetric
                        * (absent = 0: tables written before the setting existed); resume and
                        * merge require the same */
  int fibre_turn;      /* quarter turns of the helices' start (csfActuatorSpec.fibre_turn; 0 for a
                        * table: a symmetry check only). Root attribute fe_fibre_turn_deg
                        * (absent = 0); resume and merge require the same */
  int fibre_tension_only; /* 1: the fibres' smoothed tension-only law (a thread buckles instead
                           * of carrying compression); 0: linear both ways. Root attribute
                           * fe_fibre_law "tension-only" / "linear" (absent = linear: tables
                           * written before the setting existed) */
  double p_step;       /* MPa, output rows */
  double newton_rtol;  /* the sweep's Newton test |R| <= rtol (|f_int| + |f_ext|) (default the FE's
                        * sweep default, 1e-6; root attribute fe_newton_rtol, absent = 1e-8: tables
                        * written before the setting existed ran at 1e-8). Cases of one table share
                        * it: the merge refuses a mix */
  double p_cap;        /* MPa: every case ends at min(its p_max, p_cap) (0 = no cap; small
                        * tables for tests) */
  double probe_force[3]; /* N per probe direction */
  int threads;           /* the FE's threads (csfBendOptions.threads; 0 = OpenMP's default);
                          * root attribute fe_threads, with fe_factor_threads (what the
                          * factorisation used) */
  int mpi_ranks, mpi_ranks_local; /* the factorisation over MPI ranks (csfActuatorSpec; 0 or 1:
                                   * this process alone) */
  const char* threads_why; /* how they were chosen (csfThreadPlan.why): attribute
                            * fe_threads_why; NULL = none */
  const char* work_stem; /* scratch path prefix for gmsh files */
  const char* vtu_path;  /* the deformed leg at the case's last state (ParaView), NULL = none */
  csfBendProgress progress; /* per converged step (NULL = none) */
  void* progress_user;
  const volatile sig_atomic_t* cancel; /* NULL, or a signal flag: the case's sweep ends after
                                          the load step in progress (csfBendOptions.cancel) and
                                          no case file is written */
} csfCalSettings;

csfCalSettings csf_calibrationDefault(void);

/* The stiffness of every segment from a row's probes (the reduction in fem_calibration.c's
 * header): EI[s][k] (N mm^2) from the probe along e1 (k = 0) and e2 (k = 1), EA[s] (N) from the
 * probe along e3; NaN where the probe failed or loads the segment mostly in another mode. The
 * calibration model further uses a probe only where its segment is nearly straight
 * (robot_calibration_build.c): the tables store EI and EA, not the frames this needs. */
void csf_calibrationReduceProbes(const csrActuator* act, const csfBendRow* row, double EI[3][2],
                                 double EA[3]);

/* Run one case on the actuator `act` and write its file `path` (truncated first). The file is
 * complete only when this returns CS_OK (its status attribute says "complete" or names the
 * limit point where the sweep ended). */
csStatus csf_calibrationRunCase(const csrActuator* act, const csfCalCase* c,
                                const csfCalSettings* s, const char* path, csError* err);

/* 1 when `path` is a finished case file of `c` for `act` with the settings `s` (so a resumed
 * calibration skips it), 0 otherwise (missing, unfinished, another actuator or settings). */
int csf_calibrationCaseDone(const char* path, const csrActuator* act, const csfCalCase* c,
                            const csfCalSettings* s);

/* Merge case files into one table at `out`: the root attributes of the first, then every case
 * group. Refuses files of another actuator, other FE settings, or unfinished cases. */
csStatus csf_calibrationMerge(const char* const* paths, int n, const char* out, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_FEM_CALIBRATION_H */

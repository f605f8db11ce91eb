/* robot_bend_io.h: the HDF5 file of `crawlsim bend` (docs/design.md "Output contract", bend).
 *
 * Owns: writing a csrBendCurve and its metadata to an open csH5File, for every model level
 * (analytic, fe, rod, rom), so that all of them produce the same layout:
 *   /pressure [M] MPa; /angle_deg [M,3] per segment; /angle_total_deg [M]; /tip_position [M,3]
 *   mm (base frame e1, e2, e3); root attributes: model, actuator, chambers, every actuator
 *   parameter under its paper name (S1 ... C20, rho, Ef, nuf, rhof, rf), mesh_size_mm,
 *   n_elements_soft, n_elements_fibre, wall_time_s, until_angle_deg and p_until_angle_MPa
 *   (only when an --until-angle target was given), version, units. */
#ifndef CS_ROBOT_BEND_IO_H
#define CS_ROBOT_BEND_IO_H

#include "core_h5.h"
#include "core_status.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Version string written to output files; keep equal to project(VERSION) in CMakeLists.txt. */
#define CSR_OUTPUT_VERSION "0.1.0"

/* The FE fibre law's name in the root attribute fe_fibre_law of bend files and calibration
 * tables: "tension-only" (tension_only 1) or "linear" (0, also what a file without the attribute
 * was written with). */
const char* csr_fibreLawName(int tension_only);

/* The inverse: 1 for "tension-only", 0 for "linear", -1 for anything else. */
int csr_fibreLawParse(const char* name);

/* What the bend file records besides the curve itself. */
typedef struct csrBendMeta_ {
  const char* model;      /* "analytic", "fe", ... */
  const char* chambers;   /* inflated chambers, e.g. "1,2" */
  double mesh_size;       /* FE mesh boundary size (mm); NAN for mesh-free models */
  double n_elements_soft; /* element counts (0 for mesh-free models) */
  double n_elements_fibre;
  double wall_time;       /* s */
  double until_angle_deg; /* --until-angle target (deg), NAN when not given; the result is
                             the curve's p_until_angle (MPa, NAN when not reached) */
  double p_limit;         /* pressure limit point met by the sweep (MPa); 0 or NAN = none */
  double p_resume;        /* pressure where the path was stable again (MPa); 0 or NAN = none */
  double fibre_size;      /* FE fibre element length l_fibre (mm); 0 = not written (no FE) */
  int fibre_split;        /* FE fibres split at element faces (1) or 20-node ties (0); written
                             with fibre_size */
  int fibre_tension_only; /* FE fibre law: 1 tension-only, 0 linear; written with fibre_size */
  double p_indefinite;    /* FE: first converged pressure whose tangent had negative pivots
                             (MPa), NAN = none; written when neg_pivots_max >= 0 */
  int neg_pivots_max;     /* FE: most negative pivots on the path (-1: not written: no inertia
                             (LU) or not an FE run) */
  double p_stalled;       /* FE: the sweep ended here with pressure and volume control both
                             failing while the pressure had not fallen: no limit point (MPa);
                             0 or NAN = none */
  int mesh_symmetric;     /* FE: 1 the mesh with the section's symmetry, 0 the whole-body mesh;
                             written as fe_mesh_symmetric for model "fe" */
} csrBendMeta;

/* Write the rows so far (the four datasets, replacing earlier ones, and the root attribute
 * `samples` = m) and flush the file to disk: a sweep that calls this after each converged step
 * leaves, whatever stops it, a file holding every row up to the last call. */
csStatus csr_bendCurveFlushH5(csH5File* f, const csrBendCurve* bc, csError* err);

/* Write the bend datasets and root attributes into `f` (created by cs_h5Create). */
csStatus csr_bendCurveWriteH5(csH5File* f, const csrActuator* act, const csrBendCurve* bc,
                              const csrBendMeta* meta, csError* err);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_BEND_IO_H */

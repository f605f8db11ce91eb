/* robot_calibration_table.h: reading and validating an FE calibration table of chamber modes
 * (the HDF5 file `crawlsim calibrate` writes, fem/fem_calibration.h) into memory, as data: robot/
 * never calls fem/ (docs/design.md "Data flow").
 *
 * Owns: csrCalTable (the table's root description and its cases with every dataset), the
 * reader csr_calTableRead, which checks the file before anything uses it, and the lookup of a
 * case by its chamber pattern.
 *
 * Layout read (fem_calibration.h is the authority; written by the lead's calibration writer):
 *   root attributes: format "crawlsim-fe-calibration 1", every actuator parameter under its paper
 *     name (must equal the leg's), the FE settings fe_mesh_size_mm, fe_fibre_size_mm,
 *     fe_fibre_split, fe_p_step_MPa, fe_p_cap_MPa, fe_solver, and version; optionally
 *     fe_fibre_law ("linear", the default, or "tension-only") and fe_mesh_symmetric (0 or 1,
 *     default 0);
 *   /cases/<name>/ attributes kind ("mode", "holdout", "symmetry", "gravity"), ratio1..ratio4
 *     (chamber j of every segment at ratio_j p), status ("complete", or "ended at ..." when the
 *     sweep stopped early, e.g. at a limit point), p_end (MPa, last row), p_limit (MPa, NAN if
 *     none); datasets pressure [M] (MPa, 0 first, increasing), bend [M,3,2] (rad), twist [M,3]
 *     (rad), stretch [M,3] (-), radial [M,3] (-), radial_max [M,3] (mm), tip [M,3] (mm, base
 *     frame), angle_total_deg [M]; optionally the stiffness probes probe_pressure [K] (MPa),
 *     probe_force [K,3] (N: the force each probe used along e1, e2, e3, a quarter of the
 *     asked one where the FE's Newton needed it), probe_bend [K,3,3,2], probe_stretch [K,3,3], probe_tip [K,3,3], EI
 *     [K,3,2] (N mm^2) and EA [K,3] (N).
 *
 * Checks (each failure is one line "<file>: <cause>", status CS_ERR_PARSE for a malformed file,
 * CS_ERR_RANGE for values outside their domain): the format; the actuator's parameters; the FE
 * settings present; every case with a known kind, ratios in [0, 1] (max 1, except the gravity
 * case), a status that says the case finished, every dataset present with M rows (a shorter one
 * is a truncated table), pressures starting at 0 and increasing by 1e-9 MPa at least, p_end
 * equal to the last row, every kinematic value finite and within +-1e6 (beyond, the model's
 * interpolation overflows). Probe stiffnesses may be NaN (the writer marks a probe whose
 * equilibrium failed that way; the model skips it) but not <= 0 or above 1e12.
 *
 * Bends past 180 deg: the FE writes a segment's bend as a rotation vector (angle <= pi); the
 * reader continues each segment's bend along the sweep (csrCalCase.bend holds angles beyond pi).
 *
 * Units: mm, MPa, N, rad. Arrays are row-major with the shapes above. */
#ifndef CS_ROBOT_CALIBRATION_TABLE_H
#define CS_ROBOT_CALIBRATION_TABLE_H

#include <hdf5.h>

#include "core_status.h"
#include "robot_actuator.h"

#ifdef __cplusplus
extern "C" {
#endif

/* the format attribute of a mode table (fem_calibration.h's CSF_CAL_FORMAT) */
#define CSR_CAL_FORMAT "crawlsim-fe-calibration 1"
/* the prefix every version of the format starts with */
#define CSR_CAL_FORMAT_PREFIX "crawlsim-fe-calibration "

typedef enum csrCalKind_ {
  CSR_CAL_MODE = 0,     /* fitted: the model returns these points */
  CSR_CAL_HOLDOUT = 1,  /* never fitted: the model's error is measured on them */
  CSR_CAL_SYMMETRY = 2, /* a chamber set the section's symmetry predicts from a fitted one */
  CSR_CAL_GRAVITY = 3,  /* the leg under its own weight */
} csrCalKind;

/* One case: an FE pressure sweep of one chamber pattern applied to every segment. */
typedef struct csrCalCase_ {
  char name[64];
  csrCalKind kind;
  double ratio[CSR_NCHAMBER]; /* chamber j at ratio[j] p (MPa/MPa) */
  char status[256];
  int complete;      /* 1: status "complete"; 0: "ended at ..." (ended before p_max) */
  double p_end;      /* MPa: last row */
  double p_limit;    /* MPa: pressure limit point of the sweep, NAN if none */
  double wall_time;  /* s: the FE run's wall time (attribute wall_time_s; NAN if absent) */
  int m;             /* rows */
  double* pressure;  /* (m) MPa */
  double* bend;      /* (m x 3 x 2) rad, each segment's bend vector in its base-face frame,
                        continued past pi along the sweep */
  double* twist;     /* (m x 3) rad */
  double* stretch;   /* (m x 3) centreline arc length / S */
  double* radial;    /* (m x 3) mean relative growth of the outer surface's distance */
  double* radial_max; /* (m x 3) mm, largest outward growth of the outer surface */
  double* tip;       /* (m x 3) mm, tip-face centre in the base frame */
  double* angle_total; /* (m) deg */
  int k;             /* stiffness probe rows (0: none) */
  double* probe_pressure; /* (k) MPa */
  double* probe_force;    /* (k x 3) N along e1, e2, e3, per probe row */
  double* EI;        /* (k x 3 x 2) N mm^2: each segment from the e1 and e2 probes; NAN = failed */
  double* EA;        /* (k x 3) N; NAN = failed probe */
} csrCalCase;

/* A whole table. */
typedef struct csrCalTable_ {
  char path[512];
  char fe_solver[64];
  char version[32];
  double fe_mesh_size;  /* mm (l_soft) */
  double fe_fibre_size; /* mm (0: the actuator spec's default pairing) */
  char fe_fibre_law[16]; /* "linear" or "tension-only" (fe_fibre_law; absent = "linear") */
  double fe_p_step;     /* MPa, output rows */
  double fe_p_cap;      /* MPa (0: none) */
  int fe_mesh_symmetric; /* 1: the mesh with the section's symmetries (fe_mesh_symmetric;
                          * absent = 0, the whole-body mesh) */
  int ncase;
  csrCalCase* cases;    /* (ncase), owned */
} csrCalTable;

/* Read and check the table at `path` for the leg actuator `leg`. Fills *t (caller-owned
 * struct; free with csr_calTableFree, also after a failure). */
csStatus csr_calTableRead(const char* path, const csrActuator* leg, csrCalTable* t, csError* err);

/* Free what csr_calTableRead allocated (NULL-safe, idempotent). */
void csr_calTableFree(csrCalTable* t);

/* The case of kind `kind` whose ratios equal `ratio` (to 1e-12), or NULL. */
const csrCalCase* csr_calTableFind(const csrCalTable* t, csrCalKind kind,
                                   const double ratio[CSR_NCHAMBER]);

/* Name of a kind as the file spells it. */
const char* csr_calKindName(csrCalKind kind);

/* 1 when `path` starts with the 8-byte HDF5 signature (the project's files have no user
 * block). */
int csr_calIsHdf5(const char* path);

/* The root attributes of the HDF5 file `path` hold every parameter of `leg` (csr_actuatorVisit
 * names) with its value (to 1e-9 relative): else "<file>: calibrated for another actuator: S1 =
 * 40 in the table, 50 in the leg" or "<file>: calibration table has no attribute 'S1' ...".
 * Shared by the mode and pair-mode readers. */
csStatus csr_calCheckActuator(const char* path, const csrActuator* leg, csError* err);

/* 1 when `path` is HDF5 with a root attribute "format" that starts with CSR_CAL_FORMAT_PREFIX
 * (a mode table, of any version); 0 otherwise. */
int csr_calTableIsModeTable(const char* path);

/* A string attribute `name` of object `obj` (e.g. "/") of the open HDF5 file f into buf (size
 * bytes, NUL-terminated): 1, or 0 when absent, not one string (fixed or variable length), or
 * not shorter than size. Shared by the mode and pair-mode readers. */
int csr_calAttrString(hid_t f, const char* obj, const char* name, char* buf, size_t size);

#ifdef __cplusplus
}
#endif
#endif /* CS_ROBOT_CALIBRATION_TABLE_H */

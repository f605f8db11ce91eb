/* cs_bend.h: INTERNAL: one actuator's pressure -> bend point by the mesh-free models, the one
 * implementation behind the public cs_bend (crawlsim.h) and `crawlsim bend --model
 * analytic|rod|strain` (tools/cmd_bend.c, which adds its file, table, --pressures and
 * --until-angle).
 *
 * Owns: csBendSolver (the actuator, the chamber ratios, and for the rod and the strain leg
 * their calibration, model and data), its open/point/close, and the sweep's pressure grid. The FE models (fe, rom) are
 * not here: libcrawlsim does not link fem/; they stay in the command (tools/cmd_bend_fe.c).
 * Units: mm, MPa, deg, N. Messages name the `crawlsim bend` options the fields mirror. */
#ifndef CS_CORE_CS_BEND_H
#define CS_CORE_CS_BEND_H

#include <stddef.h>

#include "core_status.h"
#include "robot_actuator.h"
#include "robot_calibration.h"
#include "robot_rod.h"
#include "robot_strain.h"
#include "sim_scene.h" /* CS_MISSION_*: the rod's default table, rule and actuator */

#ifdef __cplusplus
extern "C" {
#endif

/* the nodal rod (robot_rod.h) and the strain-coordinate leg (robot_strain.h, the level of
 * `crawlsim run --legs strain`) share the calibration's options */
typedef enum { CS_BEND_ANALYTIC, CS_BEND_ROD, CS_BEND_STRAIN } csBendKind;

/* what opens a solver: everything parsed and checked by the caller */
typedef struct {
  csBendKind kind;
  csrActuator act;
  double ratio[CSR_NCHAMBER]; /* chamber j at ratio[j] x p in all three segments */
  double tip_load[3];         /* rod, strain: N, base frame */
  double p_max;               /* MPa: the sweep's top (checked against the calibration) */
  const char* calibration;    /* rod: a table or "analytic"; NULL: default_path */
  const char* default_path;   /* rod: CS_MISSION_CALIBRATION resolved by the caller */
  int cal_rule;               /* rod: csrCalRule, -1: the default table's CS_MISSION_CAL_RULE, a
                                 given table's own */
  unsigned cal_drop;          /* rod: CSR_CAL_DROP_* */
  double mesh_size;           /* rod: element length in mm, NaN: the rod's default */
  int links;                  /* strain: bending modes per segment, 0: the strain level's default
                                 (its setting `links`, robot_strain_leg.c) */
} csBendSpec;

typedef struct {
  csBendSpec spec;
  csrActuator map_act;        /* the analytic map's actuator (rod with calibration analytic) */
  csrCalibration* cal;        /* an FE table, or NULL */
  csrBendMap map;
  csrRodCalibration rodcal;   /* a mode table's strains and probed section stiffness */
  int has_rodcal;
  csrRodModel* m;
  csrRodData* d;
  csrStrainModel* sm;         /* the strain leg (kind CS_BEND_STRAIN) */
  csrStrainData* sd;
  double seg_X[CSR_NSEG][2];  /* strain: rest arc length (mm) where segment s starts and ends */
  int links;                  /* strain: bending modes per segment used */
  int n_dofs;                 /* strain: its unknowns */
  double mesh_size;           /* what the model uses: mm (NaN for the analytic and strain models) */
  int n_elements;             /* rod elements (0: analytic, strain) */
  double p_ceiling;           /* MPa: the calibration's top over the largest ratio (NaN: none) */
} csBendSolver;

/* Build the solver of spec into *s (zeroed first; the caller owns *s): CS_OK or a status with
 * err; on failure call cs_bendSolverClose all the same. */
csStatus cs_bendSolverOpen(csBendSolver* s, const csBendSpec* spec, csError* err);
/* Per-segment angles angle_deg[3] (deg) and the tip in the base frame tip[3] (mm) at p (MPa);
 * the rod and the strain leg continue from their last point. A segment's angle is |the sum of
 * the relative rotation vectors along it| (exact for plane bending, where it may pass π): the
 * rod's over its elements (csr_rodSegmentAngles), the strain leg's over 64 equal steps of
 * rest arc length. */
csStatus cs_bendSolverPoint(csBendSolver* s, double p, double angle_deg[CSR_NSEG],
                            double tip[3], csError* err);
/* Free what open built (NULL-safe, idempotent). */
void cs_bendSolverClose(csBendSolver* s);
/* the rod's or strain leg's rule name ("none" without a table) and section stiffness
 * ("probed" | "default") */
const char* cs_bendSolverRuleName(const csBendSolver* s);
int cs_bendSolverProbedStiffness(const csBendSolver* s);

/* The sweep p = 0, p_step, ... with p_max itself always the last row: its number of rows, the
 * number of whole steps (nstep, the rows before a last off-grid p_max are nstep + 1) and row
 * i's pressure. */
size_t cs_bendSweepSteps(double p_max, double p_step);
size_t cs_bendSweepRows(double p_max, double p_step);
double cs_bendSweepPressure(double p_max, double p_step, size_t i);

#ifdef __cplusplus
}
#endif
#endif /* CS_CORE_CS_BEND_H */

/* robot_calibration.h: the pressure -> segment-bend maps (calibrations) the dynamic legs use.
 *
 * Owns: three kinds of calibration behind one csrBendMap, opened by csr_calibrationOpen, which
 * tells them apart by the file's signature:
 *  - the FE MODE TABLE (`crawlsim calibrate`, format "crawlsim-fe-calibration 1"): every chamber
 *    mode, held-out combinations and stiffness probes of the full FE model, read by
 *    robot_calibration_table.h and turned into the calibration model of
 *    robot_calibration_model.h (bend, stretch, radial growth and stiffness from all four
 *    chamber pressures); it also gives the rod level its richer csrRodCalibration;
 *  - the FE PAIR-MODE table (the bend layout of `crawlsim bend`; section below), kept readable
 *    for the tables written before the mode tables, and
 *  - the PROVISIONAL calibration used before the FE table existed: the analytic model
 * (robot_analytic.h) with its bend angles multiplied by one factor chosen so
 * that a reference actuator reaches a reference total angle at a reference pressure. The
 * reference comes from a small data file (robot/calibration_provisional.txt), not from code:
 *   # comment
 *   actuator baseline          preset of the reference actuator
 *   chambers 1,2               chambers inflated in all three segments
 *   pressure_MPa 0.403         reference pressure
 *   total_angle_deg 360        total bending angle reached at that pressure
 * Why scale the angle and not the stiffness: the analytic model under-predicts the bend of
 * the real (FE) actuator because it ignores the ballooning of the thin chamber walls, which
 * adds actuation, not compliance; scaling the actuation keeps the leg's bending stiffness
 * under external loads (its weight, ground reactions) at the section's E'I. */
#ifndef CS_ROBOT_CALIBRATION_H
#define CS_ROBOT_CALIBRATION_H

#include "core_status.h"
#include "robot_actuator.h"
#include "robot_calibration_model.h"
#include "robot_calibration_table.h"
#include "robot_leg.h"
#include "robot_rod.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct csrProvisionalMap_ csrProvisionalMap;

/* Read the reference from `path`, compute the factor with the analytic model, and bind the map
 * to the leg actuator `leg`. NULL with err ("<file>:<line>: cause") on failure. */
csrProvisionalMap* csr_provisionalMapCreate(const char* path, const csrActuator* leg,
                                            csError* err);
void csr_provisionalMapDestroy(csrProvisionalMap* pm);

/* The map to put in csrRobotModel.map; valid while pm lives. */
csrBendMap csr_provisionalMapGet(const csrProvisionalMap* pm);

/* The factor on the analytic bend angle (-). */
double csr_provisionalMapScale(const csrProvisionalMap* pm);

/* Evaluate the map directly: bend[2] (rad) and stretch for segment seg of the bound leg. */
int csr_provisionalMapEval(const csrProvisionalMap* pm, int seg, const double p[4],
                           double bend[2], double* stretch);

/* ---- FE calibration table ------------------------------------------------------------------
 * An HDF5 file in the `crawlsim bend` layout (robot_bend_io.h), written by `crawlsim calibrate`
 * (or `crawlsim bend --model fe --actuator leg --chambers 1,2`): the pair mode Ω1&Ω2 of every
 * segment swept in pressure, /pressure [M] (MPa, 0 first, increasing) and /angle_deg [M,3].
 * The map keeps the analytic model's dependence on which chambers are inflated (direction and
 * chamber combinations) and takes the magnitude from the table: for a segment whose largest
 * chamber pressure is p, bend = analytic bend x r_s(p), r_s(p) = θ_FE,s(p) / θ_analytic,pair(p),
 * interpolated linearly in p between the table's rows (r_s(p) = r_s(p_1) below the first
 * non-zero row). The pair mode is exact for the flat-road gait (Ω1&Ω2 and, by symmetry,
 * Ω3&Ω4); other chamber sets assume the same ratio at the same pressure (not yet calibrated).
 * Stretch is the analytic model's. The file's actuator parameters must equal the leg's: a table
 * of another actuator is refused. Pressures above the table's last row are outside the
 * calibration: csrBendMap.p_max says where it ends and eval returns CSR_MAP_OUT_OF_RANGE. */
typedef struct csrFeCalibration_ csrFeCalibration;

csrFeCalibration* csr_feCalibrationCreate(const char* path, const csrActuator* leg,
                                          csError* err);
void csr_feCalibrationDestroy(csrFeCalibration* fc);
csrBendMap csr_feCalibrationGet(const csrFeCalibration* fc);
int csr_feCalibrationEval(const csrFeCalibration* fc, int seg, const double p[4],
                          double bend[2], double* stretch);

/* ---- any kind, by file type ----------------------------------------------------------------
 * An HDF5 file whose root attribute "format" starts with "crawlsim-fe-calibration " is a mode
 * table (refused unless its version is the one this build reads), another HDF5 file a pair-mode
 * table, anything else the provisional text file. */
typedef struct csrCalibration_ csrCalibration;

csrCalibration* csr_calibrationOpen(const char* path, const csrActuator* leg, csError* err);
/* The same with the mode table's model options (rule; robot_calibration_model.h). opt NULL =
 * csr_calibrationOpen (the defaults, any kind). opt given: the file must be an FE mode table,
 * else NULL and err "<file>: a calibration rule applies only to an FE mode table (this is a
 * pair-mode table | the provisional calibration)". */
csrCalibration* csr_calibrationOpenWith(const char* path, const csrActuator* leg,
                                        const csrCalOptions* opt, csError* err);
/* The user-facing names of the mode table's rules: "prism" (CSR_CAL_RULE_SUPERPOSITION, the
 * default), "rbf" (CSR_CAL_RULE_RBF), "rbf-pair" (CSR_CAL_RULE_RBF_PAIR). Parse: 1 and *rule
 * set, or 0 for another name. */
int csr_calRuleParse(const char* name, csrCalRule* rule);
const char* csr_calRuleName(csrCalRule rule); /* "?" for a rule without a user-facing name */
/* The parts of a calibration a rod leg leaves out (its setting cal_drop), as a user writes them:
 * "stretch", "stiffness" or both, comma-separated, or "none". Parse: 1 and *drop set, or 0
 * (*drop untouched) for anything else; format: "none" or the words joined by commas. */
int csr_calDropParse(const char* text, unsigned* drop);
void csr_calDropFormat(unsigned drop, char* buf, size_t size);
/* The rule of an open calibration: its name for an FE mode table, "none" for the other kinds. */
const char* csr_calibrationRuleName(const csrCalibration* c);
void csr_calibrationClose(csrCalibration* c);
csrBendMap csr_calibrationMap(const csrCalibration* c);

/* The mode table's model and the table itself (valid while c lives); NULL for the other kinds. */
const csrCalModel* csr_calibrationModel(const csrCalibration* c);
const csrCalTable* csr_calibrationTable(const csrCalibration* c);

/* The rod level's actuation from a mode table: intrinsic curvature and stretch from the bend
 * map's model and, where the table has stiffness probes, the segment's section with EI (both
 * axes) and EA from the probes (GA and GJ stay the rod's defaults, csr_rodLegPieces: the FE
 * did not probe shear or torsion). Fills *out and returns 1 for a mode table; returns 0 (out
 * untouched) for the other kinds, whose csrBendMap the rod adapts itself (robot_rod.h).
 * Valid while c lives. */
int csr_calibrationRod(const csrCalibration* c, csrRodCalibration* out);

/* The same from a csrBendMap that csr_calibrationMap made of a mode table (a leg level gets
 * only the map through csrLegSpec): 1 and *out filled, or 0 for any other map. */
int csr_calibrationRodFromMap(const csrBendMap* map, csrRodCalibration* out);

#ifdef __cplusplus
}
#endif
#endif

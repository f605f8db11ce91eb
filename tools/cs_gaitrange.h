/* cs_gaitrange.h: does a gait stay inside a calibration's pressure range?
 *
 * Owns: csx_gaitRangeCheck, the check `crawlsim gait check` makes against the same calibration
 * (and rule) that `crawlsim run` loads by default, so that a gait it accepts is not stopped by
 * run with "above the calibrated range" (issue 36). The pneumatic model only ramps and lags
 * between the table's rows (core/sim_driver.c cs_schedule, a first-order lag), so no chamber
 * ever exceeds the table's largest value times --pressure-scale: checking the rows is exact. */
#ifndef CS_TOOLS_GAITRANGE_H
#define CS_TOOLS_GAITRANGE_H

#include "core_status.h"
#include "gaits_csv.h"
#include "robot_calibration.h"

/* Every chamber of every row of g, times `scale`, at most the calibration's p_max (MPa,
 * csrBendMap.p_max) and, when `stiffness` and the calibration is an FE mode table with
 * stiffness probes (what rod legs read unless --cal-drop stiffness), every segment's mean
 * chamber pressure at most the probes' range (csr_calModelStiffnessPMax). CS_ERR_RANGE naming
 * `gait_path`, the row's time, the chamber or segment, its pressure and the range. */
csStatus csx_gaitRangeCheck(const csgGait* g, const char* gait_path, double scale,
                            const csrCalibration* cal, int stiffness, csError* err);

#endif

/* fuzz_calib_map.h: the check both calibration harnesses make of an accepted calibration (test
 * code, not a unit): its bend map evaluates. */
#ifndef CS_FUZZ_CALIB_MAP_H
#define CS_FUZZ_CALIB_MAP_H

#include "robot_leg.h"
#include "robot_rod.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The map of an accepted calibration: a name, p_max > 0, and at pressures from 0 to p_max on a
 * few chamber patterns and every segment eval returns 0 with a finite bend and a finite stretch
 * > 0, or > 0 (recoverable); above p_max it returns CSR_MAP_OUT_OF_RANGE (a map never
 * extrapolates). `points` (1..) is how many pressure levels are tried (each costs one eval per
 * segment and pattern: the provisional map runs the analytic model's Newton solve, ~0.1 ms).
 * Aborts with csz_fail otherwise. */
void csz_checkBendMap(const csrBendMap* map, int points);

/* The rod level's actuation of an accepted mode table (csr_calibrationRod) at the same points:
 * 0 with finite strains and, when it gives a section, finite stiffnesses > 0, or > 0; never < 0
 * below p_max, except CSR_MAP_OUT_OF_RANGE where the mean chamber pressure is above k_pmax (the
 * stiffness probes' range, csr_calModelStiffnessPMax; NAN: no stiffness). */
void csz_checkRodCalibration(const csrRodCalibration* rod, double p_max, double k_pmax,
                             int points);

#ifdef __cplusplus
}
#endif
#endif

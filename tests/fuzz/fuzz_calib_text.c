/* fuzz_calib_text.c: fuzz harness of the provisional calibration file (robot_calibration.h:
 * `actuator`, `chambers`, `pressure_MPa`, `total_angle_deg`), read the way the legs open any
 * calibration: csr_calibrationOpen for the `leg` actuator.
 *
 * Inputs that start with the HDF5 signature are skipped: csr_calibrationOpen hands those to
 * HDF5's own parser, which is not ours and not built to survive garbage bytes
 * (fuzz_calib_h5.c fuzzes the HDF5 tables structure-aware instead). Per input: the error
 * contract (fuzz_common.h); an accepted calibration must give a bend map that evaluates
 * (fuzz_calib_map.h). */
#include <string.h>

#include "fuzz_calib_map.h"
#include "fuzz_common.h"
#include "robot_calibration.h"

static csrActuator g_leg; /* the leg the calibration is bound to (read-only after init) */


int csz_harnessInit(void) {
  csError err;
  if (csr_actuatorPreset(&g_leg, "leg", &err) != CS_OK) {
    return 1;
  }
  return csz_tempPath(0, ".txt") ? 0 : 1;
}


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  static const unsigned char kHdf5[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  if (size >= sizeof kHdf5 && !memcmp(data, kHdf5, sizeof kHdf5)) {
    return cs_errorSet(err, CS_OK, "skipped");
  }
  const char* path = csz_tempPath(0, ".txt");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  csrCalibration* c = csr_calibrationOpen(path, &g_leg, err);
  csStatus st = c ? CS_OK : err->status;
  csz_checkError(st, c != NULL, err, path, data, size, CSZ_TEXT);
  if (c) {
    csrBendMap map = csr_calibrationMap(c);
    csz_checkBendMap(&map, 0);
    csr_calibrationClose(c);
  }
  return st;
}

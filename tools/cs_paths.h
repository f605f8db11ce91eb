/* cs_paths.h: where the `crawlsim` command finds its shipped data (gaits, terrains,
 * calibration). Order: $CRAWLSIM_DATA_DIR, then the source tree the binary was built from
 * (CS_SOURCE_DIR, set by CMake). Header-only: used by the command files only. */
#ifndef CS_TOOLS_PATHS_H
#define CS_TOOLS_PATHS_H

#include <stdio.h>
#include <stdlib.h>

#ifndef CS_SOURCE_DIR
#define CS_SOURCE_DIR "."
#endif

/* The actuator of the mission's calibration (core/sim_scene.h CS_MISSION_*, whose header the
 * study-file reader, also built alone into its fuzz harness, does not see). */
#define CSX_MISSION_ACTUATOR "leg"

static inline const char* csx_dataPath(const char* rel, char* buf, size_t size) {
  const char* dir = getenv("CRAWLSIM_DATA_DIR");
  snprintf(buf, size, "%s/%s", dir && dir[0] ? dir : CS_SOURCE_DIR, rel);
  return buf;
}

#endif

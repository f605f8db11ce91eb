/* fuzz_scenefile.c: fuzz harness of the scene-file reader (terrains_scenefile.h,
 * cst_sceneFileLoad).
 *
 * Per input: load it and check the error contract (fuzz_common.h); a scene file the reader
 * accepts must hold what the header promises: NUL-terminated strings, conditions empty,
 * "earth" or "paper", finite numbers within their limits where given (start +-1e6 mm, heading
 * +-360 deg, slope +-45 deg, 0 < t-end <= 1e5 s). */
#include <math.h>
#include <string.h>

#include "fuzz_common.h"
#include "terrains_scenefile.h"


int csz_harnessInit(void) { return csz_tempPath(0, ".scene") ? 0 : 1; }


static void checkScene(const cstSceneFile* s) {
  if (!memchr(s->scene, '\0', sizeof s->scene) || !memchr(s->terrain, '\0', sizeof s->terrain) ||
      !memchr(s->gait, '\0', sizeof s->gait)) {
    csz_fail("accepted scene file: a string is not terminated");
  }
  if (s->conditions[0] && strcmp(s->conditions, "earth") && strcmp(s->conditions, "paper")) {
    csz_fail("accepted scene file: conditions '%s'", s->conditions);
  }
  if (s->has_start && !(fabs(s->start[0]) <= 1e6 && fabs(s->start[1]) <= 1e6)) {
    csz_fail("accepted scene file: start (%g, %g)", s->start[0], s->start[1]);
  }
  if (s->has_heading && !(fabs(s->heading_deg) <= 360)) {
    csz_fail("accepted scene file: heading %g", s->heading_deg);
  }
  if (s->has_slope && !(fabs(s->slope_deg) <= 45)) {
    csz_fail("accepted scene file: slope %g", s->slope_deg);
  }
  if (s->has_t_end && !(s->t_end > 0 && s->t_end <= 1e5)) {
    csz_fail("accepted scene file: t-end %g", s->t_end);
  }
}


csStatus csz_harnessRun(const uint8_t* data, size_t size, csError* err) {
  const char* path = csz_tempPath(0, ".scene");
  if (csz_writeFile(path, data, size) != 0) {
    csz_fail("cannot write %s", path);
  }
  static cstSceneFile s; /* ~1.5 KB */
  csStatus st = cst_sceneFileLoad(&s, path, err);
  csz_checkError(st, st == CS_OK, err, path, data, size, CSZ_TEXT);
  if (st == CS_OK) {
    checkScene(&s);
  }
  return st;
}

/* test_scenefile.c: terrains/terrains_scenefile.c: a scene file's statements are read as
 * written (paths relative to the file's folder), the shipped example loads, and every bad
 * input is refused with the right status and one line "<file>:<line>: <cause>". */
#include "terrains_scenefile.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cs_test.h"


static void expectBad(const char* text, int line, csStatus want, const char* cause) {
  const char* path = "scenefile_bad.scene";
  cs_testWriteText(path, text);
  static cstSceneFile s;
  csError err;
  cs_errorClear(&err);
  csStatus st = cst_sceneFileLoad(&s, path, &err);
  char where[64];
  snprintf(where, sizeof where, "%s:%d: ", path, line);
  CS_EXPECT(st == want);
  CS_EXPECT(strstr(err.msg, where) == err.msg);
  CS_EXPECT(strstr(err.msg, cause) != NULL);
  CS_EXPECT(strchr(err.msg, '\n') == NULL);
  if (st != want || strstr(err.msg, where) != err.msg || !strstr(err.msg, cause)) {
    fprintf(stderr, "  status %s, message '%s' (wanted '%s...%s')\n", cs_statusString(st),
            err.msg, where, cause);
  }
  remove(path);
}


static void test_goodSceneFile(void) {
  cs_testWriteText("scenefile_good.scene", "# a scene\nscene obstacle\n"
                                    "terrain t/road.terrain   # relative\n"
                                    "gait /abs/g.csv\nconditions earth\nstart 150 117.5\n"
                                    "heading -90\nslope 7.5\nt-end 3\n");
  static cstSceneFile s;
  csError err;
  CS_EXPECT(cst_sceneFileLoad(&s, "scenefile_good.scene", &err) == CS_OK);
  CS_EXPECT(!strcmp(s.scene, "obstacle"));
  CS_EXPECT(!strcmp(s.terrain, "t/road.terrain")); /* the file has no folder part */
  CS_EXPECT(!strcmp(s.gait, "/abs/g.csv"));
  CS_EXPECT(!strcmp(s.conditions, "earth"));
  /* numbers exact in binary: compare exactly */
  CS_EXPECT(s.has_start && s.start[0] == 150 && s.start[1] == 117.5);
  CS_EXPECT(s.has_heading && s.heading_deg == -90);
  CS_EXPECT(s.has_slope && s.slope_deg == 7.5);
  CS_EXPECT(s.has_t_end && s.t_end == 3);
  remove("scenefile_good.scene");
  /* the shipped example: paths relative to terrains/ */
  const char* src = getenv("CS_SOURCE_DIR");
  char path[512], want[600];
  snprintf(path, sizeof path, "%s/terrains/slope_earth.scene", src ? src : ".");
  CS_EXPECT(cst_sceneFileLoad(&s, path, &err) == CS_OK);
  snprintf(want, sizeof want, "%s/terrains/slope.terrain", src ? src : ".");
  CS_EXPECT(!strcmp(s.terrain, want));
  snprintf(want, sizeof want, "%s/terrains/../gaits/flat_road_rod.csv", src ? src : ".");
  CS_EXPECT(!strcmp(s.gait, want));
  CS_EXPECT(s.has_slope && !s.has_start && !strcmp(s.conditions, "earth"));
}


static void test_badSceneFiles(void) {
  static cstSceneFile s;
  csError err;
  remove("scenefile_missing.scene");
  CS_EXPECT(cst_sceneFileLoad(&s, "scenefile_missing.scene", &err) == CS_ERR_IO);
  CS_EXPECT(strstr(err.msg, "scenefile_missing.scene: cannot open scene file: ") == err.msg);
  expectBad("scene slope\nterain x\n", 2, CS_ERR_PARSE, "unknown statement 'terain'");
  expectBad("start 1\n", 1, CS_ERR_PARSE, "'start' needs 2 values, got 1");
  expectBad("gait a b\n", 1, CS_ERR_PARSE, "'gait' needs 1 value, got 2");
  expectBad("conditions moon\n", 1, CS_ERR_PARSE, "conditions 'moon'");
  expectBad("slope 46\n", 1, CS_ERR_RANGE, "'slope' value 46 must be");
  expectBad("t-end 0\n", 1, CS_ERR_RANGE, "'t-end' value 0 must be");
  expectBad("t-end nan\n", 1, CS_ERR_RANGE, "'t-end' value nan");
  expectBad("heading 1x\n", 1, CS_ERR_PARSE, "'heading' value '1x' is not a number");
  expectBad("# a\nslope 1\n\nslope 2\n", 4, CS_ERR_PARSE, "second 'slope' (the first is on line 2)");
  char text[1200];
  memset(text, 'a', sizeof text);
  memcpy(text, "gait ", 5);
  text[600] = '\n';
  text[601] = '\0';
  expectBad(text, 1, CS_ERR_RANGE, "path longer than 511 bytes");
}


int main(int argc, char** argv) {
  cs_testInit(argc, argv);
  CS_RUN(test_goodSceneFile);
  CS_RUN(test_badSceneFiles);
  return cs_testSummary();
}

/* sim_scene.c: conditions and the built-in scenes (see sim_scene.h). */
#include "sim_scene.h"

#include <string.h>

/* The paper's two scenes (Sec. 5.1 and 5.2): their tables were computed without self-weight,
 * so they default to `paper` (docs/reference.md "Scene conditions"). */
static const csScene kScenes[] = {
    /* every scene runs the mission's surrogate by default, the strain-coordinate level at its
     * adaptive step, on the 23-mode FE table of the symmetric mesh under `rbf-pair`, the
     * calibration that meets every held-out FE case (docs/notes/calibration.md); rod_links is
     * the rod's elements per segment used when --legs rod is asked */
    /* the flat road's gait was designed on that model and its parameters searched by
     * simulating the strain level (gaits/flat_road_rod.gait, tools/gait_search.py --legs
     * strain; docs/notes/gait_search.md); gaits/flat_road.csv, the design of the pair-mode
     * table and the retired prb legs, stays shipped */
    /* under `earth` the four S-bent stance legs of that gait fold (tilt past 10 deg at 1.23 s);
     * a wave on six straighter stance legs walks (tools/earth_gait.py, docs/studies/earth_gait.md) */
    {"flat-road", "terrains/flat_road.terrain", "gaits/flat_road_rod.csv",
     "gaits/flat_road_earth.csv", CS_CONDITIONS_PAPER,
     CS_MISSION_CALIBRATION, CS_MISSION_CAL_RULE, "strain", 8,
     "paper Sec. 5.1: 600 x 300 mm flat road, 8 strides of 39 mm in 9 s (Table 2)", NULL},
    /* the obstacle's gait (a wave: six legs stand while a pair steps) was designed on the same
     * table (tools/obstacle_gait.py, docs/studies/obstacle.md); its rule 17 (the second pair's
     * first landing past the up edge's corner) was measured on the strain level, on which the
     * table meets Table 3 (docs/notes/obstacle.md "branch obst10"). The rod at 4 elements
     * (--legs rod) falls on it in the climb: C, G's landing on the corner */
    {"obstacle", "terrains/obstacle.terrain", "gaits/obstacle.csv", NULL, CS_CONDITIONS_PAPER,
     CS_MISSION_CALIBRATION, CS_MISSION_CAL_RULE, "strain", 4,
     "paper Sec. 5.2: L-shaped road with a 40 mm step up and down, then a turn (Table 3)",
     /* the landing gate: waits only when the valves are slower than the design's (the set's
      * ramp 0.1 s and lag x2), docs/studies/obstacle.md "sixth session" */
     "gaits/obstacle.gate"},
    /* the flat road's designed gait on an inclined road (terrains/slope.terrain): how steep a
     * slope it climbs (docs/studies/slope.md); the flat road's model and conditions */
    {"slope", "terrains/slope.terrain", "gaits/flat_road_rod.csv", NULL, CS_CONDITIONS_PAPER,
     CS_MISSION_CALIBRATION, CS_MISSION_CAL_RULE, "strain", 8,
     "the flat road inclined by 10 deg (+x uphill; a scene file's `slope A` sets another)", NULL},
};
enum { NSCENE = sizeof kScenes / sizeof kScenes[0] };


const char* cs_conditionsName(csConditions c) {
  return c == CS_CONDITIONS_PAPER ? "paper" : "earth";
}


const char* cs_conditionsWhat(csConditions c) {
  return c == CS_CONDITIONS_PAPER
             ? "the paper's assumption: legs keep mass and inertia, gravity on the support only"
             : "gravity on every body";
}


csStatus cs_conditionsParse(const char* s, csConditions* c, csError* err) {
  if (s && !strcmp(s, "earth")) {
    *c = CS_CONDITIONS_EARTH;
    return CS_OK;
  }
  if (s && !strcmp(s, "paper")) {
    *c = CS_CONDITIONS_PAPER;
    return CS_OK;
  }
  return cs_errorSet(err, CS_ERR_ARG, "unknown conditions '%.60s' (expected earth or paper)",
                     s ? s : "");
}


const csScene* cs_sceneFind(const char* name) {
  for (int i = 0; name && i < NSCENE; i++) {
    if (!strcmp(kScenes[i].name, name)) {
      return &kScenes[i];
    }
  }
  return NULL;
}


int cs_sceneCount(void) { return NSCENE; }


const csScene* cs_sceneAt(int i) { return i >= 0 && i < NSCENE ? &kScenes[i] : NULL; }


csConditions cs_sceneConditions(const csScene* s, int requested, int user_files,
                                csConditionsSource* source) {
  csConditionsSource src = CS_CONDITIONS_FROM_OPTION;
  csConditions c = CS_CONDITIONS_EARTH;
  if (requested >= 0) {
    c = requested == CS_CONDITIONS_PAPER ? CS_CONDITIONS_PAPER : CS_CONDITIONS_EARTH;
  } else if (s && !user_files) {
    c = s->conditions;
    src = CS_CONDITIONS_FROM_SCENE;
  } else {
    /* a user's terrain or gait: nothing says its author neglected self-weight */
    src = CS_CONDITIONS_FROM_USER;
  }
  if (source) {
    *source = src;
  }
  return c;
}


const char* cs_conditionsSourceName(csConditionsSource src) {
  switch (src) {
    case CS_CONDITIONS_FROM_SCENE:
      return "scene default";
    case CS_CONDITIONS_FROM_USER:
      return "default for user files";
    case CS_CONDITIONS_FROM_OPTION:
      return "--conditions";
  }
  return "unknown";
}

/* sim_scene.h: scene descriptions and their physical conditions.
 *
 * Owns: csConditions (`earth` | `paper`, docs/reference.md "Scene conditions") with their names and
 * what each does to the model, and the table of built-in scenes (csScene): a scene is a terrain
 * file (which holds the start pose and heading), a default gait and default conditions
 * (docs/design.md "Scenes"). The paper's two scenes, `flat-road` and `obstacle`, default to `paper`;
 * a run on a user's terrain or gait defaults to `earth` (cs_sceneConditions). Everything is
 * overridable from the command line and recorded in the run's output (root attribute
 * `conditions`, sim_run.c).
 *
 * Conditions:
 *  - earth: gravity acts on every body (support and legs).
 *  - paper: the paper's own assumption (its Sec. 3.1 neglects self-weight): the legs keep their
 *    mass and inertia but gravity does not act on them; the support's weight still presses
 *    the feet on the ground. */
#ifndef CS_CORE_SIM_SCENE_H
#define CS_CORE_SIM_SCENE_H

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

/* The mission's calibration: the 23-mode FE table of the symmetric mesh under the `rbf-pair`
 * rule, the table and rule that meet every held-out FE case (docs/notes/calibration.md). The
 * default of the scenes' rod legs (sim_scene.c) and of the rod's bend (cs_bend.c, `crawlsim
 * bend --model rod`); its actuator is `leg` and it holds 0..0.4 MPa. */
#define CS_MISSION_CALIBRATION "robot/calibration_fe_leg_modes_sym.h5"
#define CS_MISSION_CAL_RULE "rbf-pair"
#define CS_MISSION_ACTUATOR "leg"

typedef enum csConditions_ {
  CS_CONDITIONS_EARTH = 0, /* gravity on every body */
  CS_CONDITIONS_PAPER = 1  /* gravity on the support only; legs keep mass and inertia */
} csConditions;

/* "earth" or "paper" (static string). */
const char* cs_conditionsName(csConditions c);

/* One line saying what the conditions mean (static string, for banners). */
const char* cs_conditionsWhat(csConditions c);

/* Parse "earth" | "paper"; CS_ERR_ARG with a message naming the bad word otherwise. */
csStatus cs_conditionsParse(const char* s, csConditions* c, csError* err);

/* A built-in scene. Paths are relative to the data directory (tools/cs_paths.h). */
typedef struct csScene_ {
  const char* name;        /* as --scene spells it */
  const char* terrain;     /* terrain description file (start pose, heading) */
  const char* gait;        /* default gait table */
  const char* gait_earth;  /* default gait table under `earth` (NULL: `gait`): a gait
                              designed without self-weight may not carry the robot */
  csConditions conditions; /* default conditions of the scene's own terrain and gait */
  const char* calibration; /* default calibration (the one the scene's gait was designed on) */
  const char* cal_rule;    /* the default calibration's rule (`--cal-rule` word), used when
                              neither --calibration nor --cal-rule is given */
  const char* legs;        /* default leg level (`--legs` word) */
  int rod_links;           /* rod legs' elements per segment when --links is not given: the
                              count converged on the default calibration (docs/notes/
                              rod_legs.md, "Elements on the mission's table") */
  const char* what;        /* one line: what the scene is */
  const char* gate;        /* the landing gate of its own gait (gaits_gate.h; NULL: none, the
                              table plays open loop) */
} csScene;

/* The built-in scene called `name`, or NULL. */
const csScene* cs_sceneFind(const char* name);
/* Number of built-in scenes and the i-th (NULL outside 0..count-1). */
int cs_sceneCount(void);
const csScene* cs_sceneAt(int i);

/* Where a run's conditions come from (for the banner). */
typedef enum csConditionsSource_ {
  CS_CONDITIONS_FROM_SCENE = 0,   /* the scene's own terrain and gait: the scene's default */
  CS_CONDITIONS_FROM_USER = 1,    /* a user's terrain or gait: `earth` */
  CS_CONDITIONS_FROM_OPTION = 2   /* --conditions */
} csConditionsSource;

/* The conditions of a run: `requested` if given (>= 0), else the scene's default when both
 * the terrain and the gait are the scene's own (user_files = 0), else `earth`. */
csConditions cs_sceneConditions(const csScene* s, int requested, int user_files,
                                csConditionsSource* source);

/* "scene default", "user files", "--conditions" (static string). */
const char* cs_conditionsSourceName(csConditionsSource src);

#ifdef __cplusplus
}
#endif
#endif

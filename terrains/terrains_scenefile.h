/* terrains_scenefile.h: scene files, the one file that names what a run simulates.
 *
 * Owns: cstSceneFile (what the file sets; everything it leaves out stays the built-in scene's
 * or the command line's) and its reader with line-numbered errors. `crawlsim run --scene-file
 * FILE` applies it (tools/cmd_run.c); options given on the command line win over the file.
 *
 * File format (text, one statement per line, '#' starts a comment; each at most once):
 *   scene <name>         the built-in scene whose defaults apply (calibration, legs, elements
 *                        per segment; core/sim_scene.c); default flat-road
 *   terrain <path>       terrain file (terrains_terrain.h); a relative path is relative to the
 *                        scene file's folder
 *   gait <path>          gait table (gaits/); relative as terrain
 *   conditions <word>    earth | paper (core/sim_scene.h)
 *   start <x> <z>        mm: the support centre's start, instead of the terrain's
 *   heading <deg>        crawl direction about +y, instead of the terrain's (|deg| <= 360)
 *   slope <deg>          the terrain's inclination about +z, instead of its own (|deg| <= 45)
 *   t-end <s>            simulated time, s (0 < t <= 1e5)
 * A line holds at most 1023 bytes; a path at most 511. Errors: "<file>: cannot open scene
 * file: <reason>" (CS_ERR_IO), else "<file>:<line>: <cause>" (CS_ERR_PARSE or CS_ERR_RANGE). */
#ifndef CS_TERRAINS_SCENEFILE_H
#define CS_TERRAINS_SCENEFILE_H

#include "core_status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct cstSceneFile_ {
  char scene[64];     /* built-in scene ("" = not given) */
  char terrain[512];  /* resolved path ("" = not given) */
  char gait[512];     /* resolved path ("" = not given) */
  char conditions[8]; /* "earth" | "paper" ("" = not given) */
  int has_start, has_heading, has_slope, has_t_end;
  double start[2];    /* mm */
  double heading_deg; /* deg */
  double slope_deg;   /* deg */
  double t_end;       /* s */
  char source[256];   /* the file read */
} cstSceneFile;

/* Read a scene file into *s (zeroed first). */
csStatus cst_sceneFileLoad(cstSceneFile* s, const char* path, csError* err);

#ifdef __cplusplus
}
#endif
#endif

/* cs_rundef.h: INTERNAL to core/cs_*.c: from a run definition (crawlsim.h csRunDef) to a
 * loaded model (sim_model.h csModel): the scene's defaults, the leg level (`auto` from the
 * measured table, robot_levels.h), every range check (cs_runDefValidate), the files read.
 *
 * Owns: csRunPlan (what the definition resolved to, for the log lines and the result) and
 * cs_runDefBuild. The public side is crawlsim.h; cs_api.c uses this. */
#ifndef CS_CORE_RUNDEF_H
#define CS_CORE_RUNDEF_H

#include "crawlsim.h"
#include "sim_model.h"

#ifdef __cplusplus
extern "C" {
#endif

/* what a definition resolved to */
typedef struct csRunPlan_ {
  const csScene* scene;           /* the built-in scene that gave the defaults */
  csConditionsSource cond_src;    /* where the conditions came from */
  char terrain[512], gait[512];   /* the files read ("" gait: none) */
  char foothold[512];             /* the gait's .foothold file read ("": none) */
  char gate[512];                 /* the gait's .gate file read ("": none, open loop) */
  char calibration[512];
} csRunPlan;

/* Resolve def into the initialised model m (cs_modelInit) and load its files: the scene file,
 * the scene's defaults, the conditions, the leg level (auto: the measured table), the
 * options, the terrain, gait and calibration, and the checks that need them (pressure scale
 * against the gait, the number of steps). On failure m holds what was loaded so far (free it
 * with cs_modelDestroy) and err the cause, naming the field or file. */
csStatus cs_runDefBuild(const csRunDef* def, csModel* m, csRunPlan* plan, csError* err);

/* The measured track error of the configuration m runs (issue 33 item 1: the default's
 * discretisation error beside every track): the row of the level table (def->levels, else the
 * shipped robot/levels.csv) with m's scene, level, links, macro steps, step, rod tolerance,
 * step order and step kind (fixed, or adaptive at m's tolerance with m's step its longest), as
 * one sentence in out, and its error in *error_mm (NaN when none; error_mm may be NULL).
 * Returns 1 when a row matched, 0 otherwise (out then says that the configuration was not
 * measured, or why the table could not be read). cs_runDefBuild stores both in m
 * (csModel.track_error, track_error_mm) for the banner and the run file. */
int cs_runDefTrackError(const csRunDef* def, const csModel* m, char* out, size_t size,
                        double* error_mm);

/* What the run is, for a checkpoint (resumable runs, sim_checkpoint.c): every field of def
 * that changes the run, as lines "name value" (numbers to the last bit, NaN and NULL
 * "default"), the files it read by the FNV-1a hash of their contents (the same file by another
 * path is the same run; an edited file is another), and the leg level they resolved to. Not
 * in it: t_end (a resumed run may go further), out, checkpoint, resume and the callbacks.
 * Returns 0, or -1 when out (CS_CHECKPOINT_IDENTITY) is too small. A new field of csRunDef that
 * changes the run belongs here. */
int cs_runDefIdentity(const csRunDef* def, const csModel* m, const csRunPlan* plan, char* out,
                      size_t size);

/* A shipped file's path: rel under def->data_dir, $CRAWLSIM_DATA_DIR, share/crawlsim beside
 * the installed library (found with dladdr), the source tree the library was built from (if it
 * holds the data), else the configured prefix's share/crawlsim. */
const char* cs_runDataPath(const csRunDef* def, const char* rel, char* buf, size_t size);

#ifdef __cplusplus
}
#endif
#endif

/* cmd_rom_common.h: what the subcommands of `crawlsim rom` share (cmd_rom_common.c: the shared
 * helpers; cmd_rom_ckpt.c: check's checkpoints) and their entry points, which the subcommand
 * table (cmd_rom.c) calls: cmd_rom_snapshots.c: snapshots; cmd_rom_check.c: check;
 * cmd_rom_ecsw.c: ecsw-matrix; cmd_rom_legfile.c: leg-file; cmd_rom_modes.c: modes;
 * cmd_rom_sway.c: sway. Private to tools/: nothing below includes it. */
#ifndef CS_TOOLS_CMD_ROM_COMMON_H
#define CS_TOOLS_CMD_ROM_COMMON_H

#include "cs_opts.h"
#include "fem_rom_act.h"
#include "robot_actuator.h"

enum { CSX_ROM_MAX_SETS = 32 };

/* the options every subcommand builds the actuator from (as crawlsim bend) */
#define ROM_OPT_ACTUATOR                                                                        \
  {"--actuator", "leg|baseline|fig1", "leg",                                                    \
   "the actuator preset (robot/robot_actuator.h) the FE model is built from"}
#define ROM_OPT_SET                                                                             \
  {"--set", "NAME=VALUE", "none",                                                               \
   "change one actuator parameter after the preset (repeatable, at most 32; the names of "      \
   "crawlsim bend --set)"}

/* the preset `name` with the --set values applied (validated when `validate`); 1 after one
 * error line */
int csx_romActuator(const char* name, const char* const* sets, int nset, int validate,
                    csrActuator* act);

/* one more repeatable value (--set, --ray) into list[*n]; 1 after one error line when full */
int csx_romPushValue(const char* what, const char* v, const char** list, int* n, int max);

/* is `name` one of the built-in rays (fem_rom_snap.h csf_romRays)? 1, or 0 after one error
 * line */
int csx_romKnownRay(const char* name);

/* an operand where a subcommand takes none: one error line, returns 1 */
int csx_romUnexpected(const csxOptTable* t, const char* a);

/* a number in [lo, hi] from option `flag`'s value; 1 after one error line */
int csx_romParseNumber(const char* flag, const char* v, double lo, double hi, double* out);

/* the reduced actuator on the snapshots' FE model (every chamber tagged, the symmetric mesh of
 * the basis' l_soft; gmsh's files under work/stem_name), the element weights when given; 1
 * after one error line */
int csx_romOpen(const char* actname, const char* const* sets, int nset, const char* basis,
                const char* weights, const char* work, const char* stem_name, csrActuator* act,
                csfRomActuator* ra);

/* the reduced actuator of a leg file (crawlsim rom leg-file; robot/rom/robot_rom_file.h): no
 * gmsh, no chamber forms to compute; `weights` (may be NULL) replace the sets the weights file
 * holds; *l_soft (may be NULL) the mesh size it was built on; 1 after one error line */
int csx_romOpenLegFile(const char* actname, const char* const* sets, int nset, const char* path,
                       const char* weights, csrActuator* act, csfRomActuator* ra,
                       double* l_soft);

/* a ray's progress in `crawlsim rom check --checkpoint DIR` (cmd_rom_ckpt.c): k states solved,
 * the worst errors so far (deg, fraction, mm, fraction), the reduced solves' wall and CPU
 * seconds and Newton iterations, the printed state lines (lines, lines_cap bytes: the caller's) */
typedef struct csxRomCkpt_ {
  int k, ok;
  double bend_deg, bend_rel, tip_mm, vol_rel, wall, cpu;
  long newton;
  char* lines;
  size_t lines_cap;
} csxRomCkpt;

/* write DIR/RAY.K.ckpt (K = c->k) from the reduced actuator's last solved state; 1 after one
 * error line */
int csx_romCkptWrite(const char* dir, const char* ray, const char* basis,
                     const csfRomActuator* ra, const csxRomCkpt* c);

/* the ray's checkpoint of the most states (at most m) in DIR into ra (its state after
 * csf_romDataReset: q, the predictor's history, the solved load, the element states) and c:
 * 1 when one was read, 0 when there is none, -1 after one error line (another basis or ray,
 * other sizes, a damaged file: file and line named) */
int csx_romCkptRead(const char* dir, const char* ray, const char* basis, int m,
                    csfRomActuator* ra, csxRomCkpt* c);

/* `crawlsim rom snapshots` (cmd_rom_snapshots.c) */
int csx_cmdRomSnapshots(int argc, char** argv);

/* `crawlsim rom check` (cmd_rom_check.c) */
int csx_cmdRomCheck(int argc, char** argv);

/* `crawlsim rom ecsw-matrix` (cmd_rom_ecsw.c) */
int csx_cmdRomEcswMatrix(int argc, char** argv);

/* `crawlsim rom leg-file` (cmd_rom_legfile.c) */
int csx_cmdRomLegFile(int argc, char** argv);

/* `crawlsim rom modes` (cmd_rom_modes.c) */
int csx_cmdRomModes(int argc, char** argv);

/* `crawlsim rom sway` (cmd_rom_sway.c) */
int csx_cmdRomSway(int argc, char** argv);

#endif /* CS_TOOLS_CMD_ROM_COMMON_H */

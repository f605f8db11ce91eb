/* cmd_rom.h: what the subcommands of `crawlsim rom` share (cmd_rom.c: snapshots, check,
 * ecsw-matrix; cmd_rom_modes.c: modes). Private to tools/: nothing below includes it. */
#ifndef CS_TOOLS_CMD_ROM_H
#define CS_TOOLS_CMD_ROM_H

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

/* `crawlsim rom leg-file` (cmd_rom_legfile.c) */
int csx_cmdRomLegFile(int argc, char** argv);

/* `crawlsim rom modes` (cmd_rom_modes.c) */
int csx_cmdRomModes(int argc, char** argv);

/* `crawlsim rom sway` (cmd_rom_sway.c) */
int csx_cmdRomSway(int argc, char** argv);

#endif /* CS_TOOLS_CMD_ROM_H */

/* cmd_rom.c: `crawlsim rom`: the reduced-order FE leg's offline stages (issue 34): the
 * subcommand table (csx_cmdRom) and its --help. Each subcommand is parsed from its own option
 * table that also prints its --help (cs_opts.h) and lives in its own file: snapshots
 * cmd_rom_snapshots.c, check cmd_rom_check.c (its checkpoints cmd_rom_ckpt.c), ecsw-matrix
 * cmd_rom_ecsw.c, leg-file cmd_rom_legfile.c, modes cmd_rom_modes.c, sway cmd_rom_sway.c; what
 * they share is cmd_rom_common.c (cmd_rom_common.h). This file only dispatches, so that the
 * subcommands stand above what they share and below the table. */
#include <stdio.h>
#include <string.h>

#include "cmd_rom_common.h"
#include "cs_commands.h"

/* `crawlsim rom` and `crawlsim rom --help`: the subcommands (each has its own --help) */
static const char kUsage[] =
    "usage: crawlsim rom <subcommand> [options]\n"
    "  snapshots    full-FE statics along the built-in load rays (the basis' training data)\n"
    "  check        the reduced model along the rays of a snapshot directory against the FE\n"
    "  ecsw-matrix  every element's reduced force at the basis' training snapshots (for\n"
    "               tools/rom_ecsw.py)\n"
    "  leg-file     one file with the reduced leg of a basis, for `crawlsim run --legs rom`\n"
    "  modes        the tangents of the FE and of the reduced model at a pressure (for\n"
    "               tools/rom_modes.py: the first eigenfrequencies)\n"
    "  sway         the foot's guided (sway) stiffness of the rod, the reduced model and the FE\n"
    "               under an axial load: the Earth stance's sway-buckling load\n"
    "Run 'crawlsim rom <subcommand> --help' for its options.\n";


int csx_cmdRom(int argc, char** argv) {
  if (argc < 2) {
    fprintf(stderr, "crawlsim rom: missing subcommand (snapshots, check, ecsw-matrix or modes; see "
            "crawlsim rom --help)\n");
    return 1;
  }
  if (!strcmp(argv[1], "--help") || !strcmp(argv[1], "-h")) {
    fputs(kUsage, stdout);
    return 0;
  }
  if (!strcmp(argv[1], "snapshots")) {
    return csx_cmdRomSnapshots(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "check")) {
    return csx_cmdRomCheck(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "ecsw-matrix")) {
    return csx_cmdRomEcswMatrix(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "modes")) {
    return csx_cmdRomModes(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "leg-file")) {
    return csx_cmdRomLegFile(argc - 1, argv + 1);
  }
  if (!strcmp(argv[1], "sway")) {
    return csx_cmdRomSway(argc - 1, argv + 1);
  }
  fprintf(stderr, "crawlsim rom: unknown stage '%.64s' (expected snapshots, check, ecsw-matrix, "
          "modes, leg-file or sway; "
          "see crawlsim rom --help)\n", argv[1]);
  return 1;
}

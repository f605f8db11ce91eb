# second step of the tools/cmd_rom.c split (after split_cmd.py): the shared helpers leave
# cmd_rom.c for cmd_rom_common.c, cmd_rom.h is renamed cmd_rom_common.h (`git mv` first), so
# that cmd_rom.c only dispatches. Run from the worktree's root, once.
import re
src = open('tools/cmd_rom.c').read().split('\n')
assert src[45].startswith('/* one more repeatable value') and src[189].startswith('int csx_cmdRom(')
helpers = '\n'.join(src[45:187]).strip('\n')
usage = '\n'.join(src[31:44]).strip('\n')
disp = '\n'.join(src[189:]).strip('\n')
main = open('tools/cmd_rom.c').read()  # header and includes written by hand: see the commit
# (the script as run wrote the new head of cmd_rom.c and cmd_rom_common.c, then replaced
# '#include "cmd_rom.h"' by '#include "cmd_rom_common.h"' in cmd_rom_{ckpt,modes,check,sway,
# snapshots,ecsw,legfile}.c and the include guard CS_TOOLS_CMD_ROM_H by
# CS_TOOLS_CMD_ROM_COMMON_H; the texts are those of the committed files)
for f in ['tools/cmd_rom_ckpt.c', 'tools/cmd_rom_modes.c', 'tools/cmd_rom_check.c',
          'tools/cmd_rom_sway.c', 'tools/cmd_rom_snapshots.c', 'tools/cmd_rom_ecsw.c',
          'tools/cmd_rom_legfile.c']:
    t = open(f).read()
    assert t.count('#include "cmd_rom.h"') == 1, f
    open(f, 'w').write(t.replace('#include "cmd_rom.h"', '#include "cmd_rom_common.h"'))

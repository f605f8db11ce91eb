# pure-move split of tools/cmd_rom.c by subcommand (snapshots, check, ecsw-matrix)
import re
src = open('tools/cmd_rom.c').read().split('\n')
L = lambda a, b: '\n'.join(src[a-1:b]).strip('\n')
assert src[9] == '#include <errno.h>' and src[31] == '#include "robot_rom_file.h"'
assert src[47].startswith('static const csxOpt kSnapOpts[]')
assert src[73].startswith('static const csxOpt kCheckOpts[]')
assert src[105].startswith('static const csxOpt kEcswOpts[]')
assert src[134].strip() == 'kEcswOpts, CSX_NOPT(kEcswOpts), NULL};'
assert src[236].startswith('static void snapProgress(')
assert src[402].startswith('/* one ray of the reduced model')
assert src[569].startswith('/* the reduced actuator from a leg file')
assert src[613].startswith('static int cmdCheck(')
assert src[759].startswith('/* a constant matrix')
assert src[1026].startswith('int csx_cmdRom(')
includes = L(10, 32)
usage = L(34, 46)
snap_opts, check_opts, ecsw_opts = L(48, 72), L(74, 104), L(106, 135)
shared1, snap, check1, shared2, check2, ecsw, disp = (
    L(138, 234), L(237, 400), L(403, 568), L(570, 612), L(614, 757), L(760, 1024), L(1027, len(src)))
for blk in (shared1, snap, check1, shared2, check2, ecsw, disp):
    pass
def ren(t):
    t = t.replace('static int knownRay(', 'int csx_romKnownRay(')
    t = re.sub(r'(?<![A-Za-z_])knownRay\(', 'csx_romKnownRay(', t)
    t = t.replace('static int cmdSnapshots(', 'int csx_cmdRomSnapshots(')
    t = t.replace('static int cmdCheck(', 'int csx_cmdRomCheck(')
    t = t.replace('static int cmdEcswMatrix(', 'int csx_cmdRomEcswMatrix(')
    t = re.sub(r'(?<![A-Za-z_])cmdSnapshots\(', 'csx_cmdRomSnapshots(', t)
    t = re.sub(r'(?<![A-Za-z_])cmdCheck\(', 'csx_cmdRomCheck(', t)
    t = re.sub(r'(?<![A-Za-z_])cmdEcswMatrix\(', 'csx_cmdRomEcswMatrix(', t)
    return t
head_main = '''/* cmd_rom.c: `crawlsim rom`: the reduced-order FE leg's offline stages (issue 34): the
 * subcommand table (csx_cmdRom, its --help) and what the subcommands share (cmd_rom.h: the
 * actuator from --actuator/--set, the reduced actuator from a basis or a leg file, option
 * parsing). Each subcommand is parsed from its own option table that also prints its --help
 * (cs_opts.h) and lives in its own file: snapshots cmd_rom_snapshots.c, check cmd_rom_check.c
 * (its checkpoints cmd_rom_ckpt.c), ecsw-matrix cmd_rom_ecsw.c, leg-file cmd_rom_legfile.c,
 * modes cmd_rom_modes.c, sway cmd_rom_sway.c. */'''
head_snap = '''/* cmd_rom_snapshots.c: `crawlsim rom snapshots` (cmd_rom.c holds the subcommand table).
 *
 * snapshots: full-FE static solves on the symmetric mesh along the built-in load rays
 * (fem/fem_rom_snap.h: chamber modes, per-segment patterns, random rays, gravity, tip forces,
 * pressure with loads; training and held-out rays), one HDF5 file per ray in DIR (a finished
 * ray is skipped, so a stopped production resumes ray by ray) and DIR/mesh.h5 (what the offline
 * basis, tools/rom_basis.py, reads). */'''
head_check = '''/* cmd_rom_check.c: `crawlsim rom check` (cmd_rom.c holds the subcommand table): the reduced
 * model along the rays of a snapshot directory against the full FE's states, with its
 * checkpoints (cmd_rom_ckpt.c) and the reduced states (--states). */'''
head_ecsw = '''/* cmd_rom_ecsw.c: `crawlsim rom ecsw-matrix` (cmd_rom.c holds the subcommand table): every
 * element's reduced force at the basis' training snapshots, the matrices of tools/rom_ecsw.py's
 * NNLS. */'''
def write(p, head, parts):
    open(p, 'w').write(head + '\n' + includes + '\n\n' + '\n\n\n'.join(ren(x) for x in parts) + '\n')
# option tables stay with their subcommand: each is followed by its code
write('tools/cmd_rom.c', head_main, [usage + '\n\n' + shared1, shared2, disp])
write('tools/cmd_rom_snapshots.c', head_snap, [snap_opts + '\n\n' + snap])
write('tools/cmd_rom_check.c', head_check, [check_opts + '\n\n' + check1, check2])
write('tools/cmd_rom_ecsw.c', head_ecsw, [ecsw_opts + '\n\n' + ecsw])

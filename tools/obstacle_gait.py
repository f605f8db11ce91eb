#!/usr/bin/python3
"""Write gaits/obstacle.gait, the obstacle road's gait description (docs/studies/obstacle.md).

The description is long (one move line per leg group and phase) but follows from a few rules
and the terrain's two edges; this script is those rules. It plans, slot by slot, where each
foot lands, from the hips' expected positions (the measured support advance per cycle, D) and
the edges of terrains/obstacle.terrain, and writes the moves; `crawlsim gait design` then turns
the description into gaits/obstacle.csv with pressures from the calibrated leg model:

  /usr/bin/python3 tools/obstacle_gait.py -o gaits/obstacle.gait --gate-out gaits/obstacle.gate
  crawlsim gait design gaits/obstacle.gait --stretch --out gaits/obstacle.csv \\
      --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4

Options set the measured constants and the design's few parameters (defaults: the values the
shipped file was made with). The defaults became rule 14's open-loop table k3 on 2026-12-06
(fourth session: --Tp 0.6 --xslots 4 --x2 500 --settle 0.4 --clear 10 --scatter=-44,16 --rmin 0
--Tcross 0.52); options written before then in docs/ are relative to the earlier defaults
--Tp 0.55 --xslots 3 --x2 540 --settle 0 --clear 0 --scatter=-10,16 --rmin 5 --Tcross 0.
Since branch ship11 (2026-12-07, eleventh session) --crawl-max 12 is the default: the lateral
crawl has 12 slots and the gate (--gate-out) ends it on the measured support (its `crawl`
statement); --crawl-max 0 writes the 8-slot table shipped before."""
import argparse
import sys

ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
ap.add_argument('-o', '--out', default='-', help='output file (default stdout)')
ap.add_argument('--D', type=float, default=59.0,
                help='support advance per walk cycle, mm (measured): places the hips for the '
                'landings and, with --xdrift, sets the number of walk slots (rule 7)')
ap.add_argument('--xdrift', type=float, default=14.0,
                help='how far the turn and the lateral crawl carry the support back along x, mm '
                '(measured): the walk turns this far past xturn (rule 7)')
ap.add_argument('--Dz', type=float, default=70.4,
                help='support advance per lateral cycle, mm (measured): the number of lateral '
                'slots is zend / (Dz / 4)')
ap.add_argument('--over', type=float, default=10.0,
                help='landing overshoot ahead of the planned foot, mm (measured)')
ap.add_argument('--over-step', type=float, default=None,
                help='rule 16: landing overshoot of a landing on the step (the vented stance), mm '
                '(measured: the nominal\'s step landings fell 3 mm short of their offset on average '
                'where the road\'s fall --over beyond it; docs/studies/obstacle.md, sixth session); '
                'default --over (rule 16 off)')
ap.add_argument('--up-short', type=float, default=30.0,
                help='rule 17: how far a wave landing onto the step from the road (the leg\'s stance on '
                'the road, its landing planned on the step) falls short of rule 6\'s plan, mm '
                '(measured on k3\'s nominal, the same on rod and strain legs: B 233.4 for 264 planned, '
                'C 224-228 for 258; docs/notes/obstacle.md "Rule 17"); default 30, the measured value '
                '(on since 2026-12-07, branch obst10: the shipped table bf50); negative: off (k3, the '
                'table shipped until then)')
ap.add_argument('--up-band', default='-10,5',
                help='rule 17: the corner\'s band about the up edge, mm short and past it: a landing '
                'expected there (plan less --up-short) takes the shortest longer offset, in 5 mm steps '
                'up to --up-reach, expected past the band (the foot block caught the corner at 233.4 '
                'and hung clear of it at 224-228)')
ap.add_argument('--up-reach', type=float, default=55.0,
                help='rule 17: the longest offset ahead of the hip, mm (rule 16\'s 55)')
ap.add_argument('--push', type=int, default=0,
                help='rule 18: slots in which no pair steps and every stance foot moves on, before the '
                'rear pair\'s step toward the up edge (rule 13\'s slot): the support advances D/4 a slot '
                'over the plateau\'s first feet before the rear pair leaves the road (default 0: off)')
ap.add_argument('--down-lead', type=float, default=0.0,
                help='rule 19: how far the front pair\'s first step from the plateau down to the road '
                'carries the support past the plan, mm (measured with rule 18: 55-64 on rod and strain '
                'legs); the later landings are planned with the hips that far ahead and the wave ends '
                'where that passes --x2 (default 0: off)')
ap.add_argument('--Dcross', type=float, default=None,
                help='rule 16b: support advance per cycle from the climb\'s end (planned x past --xclimb) '
                'to --xcross, mm; places the hips for the landings of these slots, and the later '
                'landings keep the lag it adds (default --D, rule 16 off)')
ap.add_argument('--reach', type=float, default=None,
                help='rule 16: a landing on the step that falls within 25 mm of the up edge '
                '(rule 6\'s margin, where it lands by --over-step), takes the shortest longer offset, '
                'in 5 mm steps up to REACH mm ahead of the hip, that keeps the margin (REACH if none '
                'does); default off')
ap.add_argument('--reach-road', action='store_true',
                help='rule 16 also for the landings on the road within 25 mm before the riser '
                '(default: only those on the step)')
ap.add_argument('--Tp', type=float, default=0.6,
                help='the walk\'s slot: the time one pair takes to step, s (the cycle is 4 slots)')
ap.add_argument('--Tclimb', type=float, default=0.8,
                help='the walk\'s slot while the support climbs (planned x below --xclimb), s')
ap.add_argument('--xclimb', type=float, default=130.0,
                help='support x (mm) from which the walk takes the --Tp slot: the rear hips\' '
                'feet then land on the step (its edge at 240, the rear hips at 75, a landing '
                '25 + 10 mm ahead of them: 240 - 75 - 35)')
ap.add_argument('--Tcross', type=float, default=0.52,
                help='rule 14: the walk\'s slot while the support crosses the plateau (planned x from '
                '--xclimb to --xcross), s (0: --Tp, rule 14 off)')
ap.add_argument('--xcross', type=float, default=235.0,
                help='rule 14: support x (mm) from which the walk takes the --Tp slot again: the front '
                'hips then stand past the down edge (460 - 150 - 75)')
ap.add_argument('--t-place', type=float, default=1.8,
                help='when the front pair steps ahead, s (the walk starts one --Tstart later)')
ap.add_argument('--Tpz', type=float, default=0.55, help='the lateral crawl\'s slot, s')
ap.add_argument('--Tstart', type=float, default=0.8,
                help='slot of the steps into the walk and into the lateral stance (the support '
                'standing), s')
ap.add_argument('--Tturn', type=float, default=0.55,
                help='slot of the steps into and out of the lateral stance (the support '
                'standing), s')
ap.add_argument('--rise', type=float, default=40.0,
                help='stretch of a road leg in the walk, mm (the step is 40 mm: rule 2)')
ap.add_argument('--rise-z', type=float, default=15.0,
                help='stretch of the legs in the lateral crawl, mm')
ap.add_argument('--rise-low', type=float, default=15.0,
                help='stretch of a road leg once every foot stands on the road past the step, '
                'mm (rule 10; --rise keeps the walk up)')
ap.add_argument('--nlow', type=int, default=4,
                help='slots over which the walk comes down from --rise to --rise-low (rule 10)')
ap.add_argument('--SHZ', type=float, default=25.0,
                help='stance stroke of the lateral crawl, mm (the feet move this far sideways '
                'over three slots)')
ap.add_argument('--fracz', default='0.15,0.5,0.15,0.2',
                help='a lateral slot: lift, swing, hold, land (fractions of --Tpz)')
ap.add_argument('--frac', default='0.25,0.4,0.1,0.25',
                help='a step of the wave: lift, swing, hold, land (fractions of its slot); '
                'if they add up to less than 1 the rest ends the slot with all eight legs '
                'standing (the landing settles before the next pair lifts)')
ap.add_argument('--fract', default='0.15,0.5,0.15,0.2',
                help='a step of the turn and of the release: lift, swing, hold, land (fractions '
                'of --Tturn)')
ap.add_argument('--zoverlap', type=float, default=0.0,
                help='rule 20: with --zgroups 2, both groups stand this long (s) at each hand-over of '
                'the lateral crawl, half of it either side of the slot\'s boundary: a stance lasts '
                '--Tpz plus it (its stroke longer at the same foot speed, --SHZ per --Tpz), a swing '
                '--Tpz less it (the first swing, after the two-group walk, half of it less); default 0 '
                '(off): the landing group touched down 0.04 s after the standing group lifted and '
                'the support bounced off the road, aloft 0.08 s of each slot with a 50 g support, 0.24 s with 25 g '
                '(docs/notes/obstacle.md "Rule 20")')
ap.add_argument('--zgroups', type=int, default=2, choices=(2, 4),
                help='the lateral crawl: 4, the wave of the diagonal pairs AH, DE, BG, CF (six '
                'legs stand, --SHZ over three slots); 2, two groups of four, ACFH and BDEG, as '
                'the flat road walks (four legs stand, --SHZ in their one slot of stance, the '
                'turn one slot of ACFH stepping aside)')
ap.add_argument('--Tvent', type=float, default=0.5,
                help='the last vent of every chamber, s (the run ends one --Tvent after it)')
ap.add_argument('--xslots', type=int, default=4,
                help='with --zgroups 2: slots of the walk in two groups after the wave (rule 11)')
ap.add_argument('--SX', type=float, default=14.0,
                help='stance stroke of the walk in two groups, mm per slot (rule 11)')
ap.add_argument('--x2', type=float, default=500.0,
                help='the wave ends at the first slot whose planned support x is past this, mm '
                '(rule 11; 0: rule 7 sets the walk\'s slots)')
ap.add_argument('--walk-slots', type=int, default=None,
                help='number of walk slots (default: rule 7); 0 tests the turn and the lateral '
                'crawl alone')
ap.add_argument('--xturn', type=float, default=646.0, help='x of the turn, mm (Table 3)')
ap.add_argument('--zend', type=float, default=270.0, help='lateral travel, mm (Table 3)')
ap.add_argument('--Dclimb', type=float, default=None,
                help='rule 13 (trial): support advance per cycle while the support climbs (planned x '
                'below --xclimb), mm (measured); places the hips for the climb\'s landings only '
                '(default --D)')
ap.add_argument('--settle', type=float, default=0.4,
                help='rule 13: all eight legs stand this long before the rear pair\'s slot '
                'whose landings can reach within 25 mm of the up edge, s (0: off)')
ap.add_argument('--clear', type=float, default=10.0,
                help='rule 12: wanted clearance of a landing\'s scatter band from an edge, mm '
                '(0: off, rule 6 alone)')
ap.add_argument('--scatter', default='-44,16',
                help='rule 12: where a landing falls against its plan, mm, short and long '
                '(measured: the support stood -44..+33 mm from its plan at the rear pair\'s '
                'climb across the set, docs/studies/obstacle.md "n0"; D and H landed 11, 16 mm '
                'long with a 25 g, 75 g support, Robustness)')
ap.add_argument('--clear-down', action='store_true',
                help='rule 12 also for the first pair landing near the down edge (more than 25 mm '
                'past the up edge; the pair that steps down first): its scatter band keeps --clear from '
                'the down edge (default: only the road landings before the riser)')
ap.add_argument('--rmin', type=float, default=0.0,
                help='rule 12: the shortest landing offset ahead of the hip (below 5 the stance '
                'ends more than 35 mm behind the hip, past rule 4), mm')
ap.add_argument('--rmax', type=float, default=45.0,
                help='rule 12: the longest landing offset ahead of the hip when no offset of '
                'rule 6 keeps --clear, mm')
ap.add_argument('--foothold', action='append', default=[], metavar='LEGS:CYCLE:OFFSETS[:MARGIN]',
                help='rule 15: the step of the pair LEGS (DH, CG, BF, AE) in walk cycle CYCLE (0-based) '
                'is a foothold: its landing is chosen during the run among OFFSETS (mm ahead of the '
                'hip, comma-separated; the plan\'s own offset is added) from the measured support, '
                'keeping MARGIN mm (default 10) from the edges (a `foothold` line in the description; '
                'gaits/gaits_foothold.h)')
ap.add_argument('--force', action='append', default=None, metavar='LEGS:CYCLE:OFFSET',
                help='the step of LEGS in walk cycle CYCLE lands OFFSET mm ahead of the hip whatever '
                'rules 6 and 12 say (--foothold-out writes each candidate with it); default BF:4:35 '
                '(the shipped table since branch ramp11: B, F\'s step down lands clear of the '
                'corner under slow valves); `--force none` forces nothing')
ap.add_argument('--foothold-out', default=None, metavar='NAME',
                help='with --foothold: design -o\'s description into NAME.csv and every candidate '
                'into NAME.foothold.d/, and write the companion NAME.foothold (needs -o FILE; '
                '--crawlsim names the binary)')
ap.add_argument('--decide', choices=('lift', 'swing'), default='lift',
                help='rule 15: when a foothold reads the support: at its step\'s lift, or at the '
                'swing\'s start (the first row any candidate changes; the plan\'s x there '
                'interpolated within the slot), nearer where the foot lands')
ap.add_argument('--crawlsim', default='build/tools/crawlsim', help='the binary for --foothold-out')
ap.add_argument('--low-slot', type=int, default=None, metavar='S',
                help='rule 10 starts at walk slot S whatever the landings (--foothold-out gives each '
                'candidate the nominal plan\'s slot: a foothold changes its own legs only)')
ap.add_argument('--foothold-reuse', action='store_true',
                help='with --foothold-out: a foothold whose candidate tables are all in '
                'NAME.foothold.d already keeps them (not designed again)')
ap.add_argument('--design-cache', default=None, metavar='DIR',
                help='with --foothold-out: keep each designed candidate table in DIR and reuse it '
                'for the same statements (a rerun with other footholds designs only what is new)')
ap.add_argument('--gate-out', default=None, metavar='FILE',
                help='write the landing gate of the description (-o\'s, or --gate-from\'s) to FILE: '
                'every lift of a pair in the wave waits for the last other pair that lifted '
                '(gaits/gaits_gate.h; `crawlsim run --gate FILE`)')
ap.add_argument('--gate-from', default=None, metavar='GAIT',
                help='with --gate-out: take the lifts from the description GAIT (any table\'s '
                '.gait) and write nothing else')
ap.add_argument('--gate-ramp', type=float, default=0.05,
                help='the gate\'s design actuation time, s: the table\'s @ramp (its rows\' spacing)')
ap.add_argument('--gate-lag', type=float, default=0.02,
                help='the gate\'s design pneumatic lag, s (crawlsim run\'s default --tau)')
ap.add_argument('--gate-ptol', type=float, default=0.005,
                help='the gate\'s tolerance, MPa (a pressure sensor\'s accuracy: about 1 %% of the '
                'table\'s 0.4 MPa range)')
ap.add_argument('--gate-maxwait', type=float, default=None,
                help='the longest wait of a gate, s (default --Tp: one walk slot)')
ap.add_argument('--gate-land', default='13.3:19', metavar='T0:T1',
                help='with --gate-out: also gate each wave set-down of a pair (its first move from a '
                'swing pose A* or U0 to a stance pose) lifting at table times T0..T1 s on the pair '
                'itself: the foot is lowered only once its chambers are as near the swing pose as '
                'designed (issue 33, docs/notes/obstacle.md "ramp11"); default 13.3:19 (the shipped '
                'table since ramp11), `none` off')
ap.add_argument('--gate-swing', default='5:24.1', metavar='T0:T1',
                help='with --gate-out: also gate each swing of a pair lifting at table times '
                'T0..T1 s (its move from the lift pose on to the next swing pose) on the pair '
                'itself: the foot swings forward only once it is lifted as designed (issue 33, '
                'docs/notes/obstacle.md "ramp11"); default 5:24.1 (the shipped table since '
                'ramp11), `none` off')
ap.add_argument('--gate-x', default=None, metavar='MM:T0:T1',
                help='with --gate-out: each gate at table times T0..T1 s (lifts, and set-downs of '
                '--gate-land) also waits until the measured support stands at most MM behind the '
                'plan\'s x at its time (`gate T LEGS x XMIN`, gaits/gaits_gate.h); off by default')
ap.add_argument('--crawl-max', type=int, default=12, metavar='N',
                help='the lateral crawl ended on the measured support (issue 33, '
                'docs/notes/obstacle.md "crawl10"): write N lateral slots (instead of zend / '
                '(Dz / 2)) and, with --gate-out, the gate\'s `crawl` statement, so the player '
                'ends the crawl at the first boundary of the release\'s phase where the measured '
                'support z is near enough zend (gaits/gaits_gate.h); default 12 (the shipped '
                'files, issue 33, docs/notes/obstacle.md "ship11"); 0: off, zend / (Dz / 2) '
                'slots and no statement (the files shipped before ship11)')
ap.add_argument('--crawl-carry', type=float, default=23.0,
                help='with --crawl-max: the release\'s own advance along z, mm (the 50 g nominal\'s '
                'measured 23 mm: docs/bench/obst10_2026-12-07c/nominal.txt, `rel8`)')
ap.add_argument('--walk-extra', type=int, default=1, metavar='K',
                help='the walk in two groups ended on the measured support (rule 21, issue 33, '
                'docs/notes/obstacle.md "obst13"): write K more cycles of two slots after '
                '--xslots and, with --gate-out, the gate\'s `walk` statement, so the player ends '
                'the walk at the first boundary of its end\'s phase where the measured support x '
                'is near enough --walk-xend (gaits/gaits_gate.h); default 1 (the shipped files '
                'since obst13; off with --gate-from or --zgroups 4 unless given); 0: off, the '
                'files shipped before')
ap.add_argument('--walk-xend', type=float, default=646.0,
                help='with --walk-extra: the end point\'s x, mm (Table 3\'s end, paper Sec. 5.2)')
ap.add_argument('--walk-carry', type=float, default=65.0,
                help='with --walk-extra: what the walk\'s end (the turn) and the lateral crawl add '
                'along x, mm (the 50 g nominal\'s measured 64.8: the shipped default\'s x from the '
                'turn\'s start, 586.2 mm at 26.84 s, to its end, 651.0; docs/notes/obstacle.md '
                '"obst13")')
a = ap.parse_args()
WALK_GIVEN = any(x == '--walk-extra' or x.startswith('--walk-extra=') for x in sys.argv[1:])
if (a.gate_from or a.zgroups != 2) and not WALK_GIVEN:
    a.walk_extra = 0  # off: the default's walk needs a table written here, two groups
if a.walk_extra < 0 or (a.walk_extra and (a.zgroups != 2 or a.xslots < 2 or a.gate_from)):
    sys.exit('obstacle_gait.py: --walk-extra takes K >= 0, with the walk in two groups '
             '(--zgroups 2, --xslots >= 2) and a table written here (not --gate-from)')
XSLOTS = a.xslots + 2 * a.walk_extra  # the walk's slots written (rule 21)
WALK = None  # (first slot's table time s, slot s, slots before the turn) once written
CRAWL_GIVEN = any(x == '--crawl-max' or x.startswith('--crawl-max=') for x in sys.argv[1:])
if a.crawl_max == 0 or (a.gate_from and not CRAWL_GIVEN) or (a.zgroups != 2 and not CRAWL_GIVEN):
    a.crawl_max = None  # off: the default's crawl needs a table written here, two groups
if a.crawl_max is not None and (a.crawl_max < 3 or a.zgroups != 2 or a.gate_from):
    sys.exit('obstacle_gait.py: --crawl-max takes N >= 3, with the two-group crawl '
             '(--zgroups 2) and a table written here (not --gate-from)')
CRAWL = None  # (first slot's table time s, slot s, slots) once the crawl is written
if a.force is None:
    a.force = ['BF:4:35']  # the shipped table's (ramp11)
a.force = [f for f in a.force if f != 'none']
if a.gate_land == 'none':
    a.gate_land = None
if a.gate_swing == 'none':
    a.gate_swing = None
try:
    LAND = tuple(float(v) for v in a.gate_land.split(':')) if a.gate_land else None
    assert LAND is None or len(LAND) == 2
except (ValueError, AssertionError):
    sys.exit('obstacle_gait.py: --gate-land takes T0:T1 (s)')
try:
    SWING = tuple(float(v) for v in a.gate_swing.split(':')) if a.gate_swing else None
    assert SWING is None or len(SWING) == 2
except (ValueError, AssertionError):
    sys.exit('obstacle_gait.py: --gate-swing takes T0:T1 (s)')
try:
    GX = tuple(float(v) for v in a.gate_x.split(':')) if a.gate_x else None
    assert GX is None or (len(GX) == 3 and not a.gate_from)
except (ValueError, AssertionError):
    sys.exit('obstacle_gait.py: --gate-x takes MM:T0:T1 (mm, s), with a table written here')
DC = a.D if a.Dclimb is None else a.Dclimb


def gate_text(lines, source):
    """the landing gate of a description (gaits/gaits_gate.h): its wave lifts (the first `move`
    of a pair into a step: to a swing pose A* or U0 from a stance; the foot's stance offset
    names the lift pose, AM behind the hip, AP ahead of it, as rule 17's B, F lift at 7.4 s),
    each after the first waiting for the last other pair that lifted (the rule of
    docs/bench/obst_2026-12-06e/gatelib.py Gates)"""
    lifts, swinging, lands, lifted = [], {}, [], {}
    for line in sorted((ln for ln in lines if ln.startswith('move ')),
                       key=lambda ln: float(ln.split()[1])):
        p = line.split()
        if len(p) < 5 or len(p[3]) != 2:
            continue
        air = p[4].startswith('AM') or p[4].startswith('AP') or p[4] == 'U0'
        if air and not swinging.get(p[3]):
            lifts.append((float(p[1]), p[3]))
            lifted[p[3]] = float(p[1])
        if not air and swinging.get(p[3]) and LAND and LAND[0] <= lifted[p[3]] <= LAND[1]:
            # --gate-land: the set-down waits for the pair itself (its swing pose arrived)
            lands.append((float(p[1]), p[3], 'set-down'))
        if air and swinging.get(p[3]) and lifted[p[3]] < float(p[1]) and SWING and \
                SWING[0] <= lifted[p[3]] <= SWING[1]:
            # --gate-swing: the move on from the lift pose waits for the pair itself (lifted)
            lands.append((float(p[1]), p[3], 'swing'))
        swinging[p[3]] = air
    lifts.sort()
    out = ['# the landing gate of %s (gaits/gaits_gate.h), written by\n#   %s\n'
           '# each lift of a pair in the wave waits until the pair that lifted before it is down\n'
           % (source, ' '.join(['tools/obstacle_gait.py'] + sys.argv[1:])),
           'design ramp %g lag %g ptol %g maxwait %g\n'
           % (a.gate_ramp, a.gate_lag, a.gate_ptol, a.Tp if a.gate_maxwait is None else a.gate_maxwait)]
    def xmin(t):
        # --gate-x: the plan's support x at t (XP at the slots' starts, linear between: rule 3)
        if not GX or not GX[1] <= t <= GX[2]:
            return ''
        return ' x %.3f' % (next(XP[i] + (t - T0[i]) / (T0[i + 1] - T0[i]) * (XP[i + 1] - XP[i])
                                 for i in range(len(T0) - 1) if T0[i] <= t < T0[i + 1]) - GX[0])
    gates = []
    for i in range(1, len(lifts)):
        prev = [q for _, q in lifts[:i] if q != lifts[i][1]]
        if prev:
            gates.append((lifts[i][0], 0, 'gate %.4f %s%s  # lift of %s\n'
                          % (lifts[i][0], prev[-1], xmin(lifts[i][0]), lifts[i][1])))
    gates += [(t, 1, 'gate %.4f %s%s  # %s of %s\n' % (t, q, xmin(t), k, q)) for t, q, k in lands]
    out += [g for _, _, g in sorted(gates)]
    if len(out) == 2:
        sys.exit('obstacle_gait.py: %s has no wave lifts to gate' % source)
    if a.walk_extra and WALK:
        out.append('# the walk ends on the measured support: first slot, slot, slots written '
                   'before the turn, XEND and CARRY along the walk (mm)\n'
                   'walk %.4f %g %d %g %g\n' % (WALK + (a.walk_xend, a.walk_carry)))
    if a.crawl_max is not None and CRAWL:
        out.append('# the lateral crawl ends on the measured support: first slot, slot, slots '
                   'written, end z (mm), the release\'s carry (mm)\n'
                   'crawl %.4f %g %d %g %g\n' % (CRAWL + (a.zend, a.crawl_carry)))
    return ''.join(out)


if a.gate_from:
    if not a.gate_out:
        sys.exit('obstacle_gait.py: --gate-from needs --gate-out FILE')
    with open(a.gate_out, 'w') as f:
        f.write(gate_text(open(a.gate_from).read().splitlines(), a.gate_from))
    sys.exit(0)


def fh_spec(text, opt, nparts):
    """LEGS:CYCLE:VALUES[:MARGIN] of --foothold / --force"""
    p = text.split(':')
    try:
        if len(p) not in nparts or p[0] not in ('DH', 'CG', 'BF', 'AE') or int(p[1]) < 0:
            raise ValueError
        vals = tuple(float(v) for v in p[2].split(','))
        margin = float(p[3]) if len(p) > 3 else 10.0
    except (ValueError, IndexError):
        sys.exit('obstacle_gait.py: %s %s: LEGS (DH, CG, BF or AE):CYCLE:OFFSETS%s' %
                 (opt, text, '[:MARGIN]' if 4 in nparts else ''))
    return (p[0], int(p[1])), vals, margin


FH = {}           # (pair, cycle) -> (offsets, margin): rule 15's footholds
for text in a.foothold:
    key, vals, margin = fh_spec(text, '--foothold', (3, 4))
    FH[key] = (vals, margin)
FORCE = {}        # (pair, cycle) -> offset
for text in a.force:
    key, vals, _ = fh_spec(text, '--force', (3,))
    FORCE[key] = vals[0]
FHINFO = []       # per foothold: dict(t, legs, xplan, margin, plan r, offsets, lands)
if a.foothold_out and (not FH or a.out == '-'):
    sys.exit('obstacle_gait.py: --foothold-out needs --foothold and -o FILE')
if a.push < 0 or a.down_lead < 0:
    sys.exit('obstacle_gait.py: --push takes a number of slots >= 0, --down-lead a distance >= 0 (mm)')
if DC <= 0 or a.settle < 0:
    sys.exit('obstacle_gait.py: --Dclimb takes a positive advance (mm), --settle a time >= 0 (s)')
try:
    SCAT = tuple(float(v) for v in a.scatter.split(','))
except ValueError:
    SCAT = ()
if len(SCAT) != 2 or SCAT[0] > 0 or SCAT[1] < 0:
    sys.exit('obstacle_gait.py: --scatter takes two numbers, short (<= 0) and long (>= 0)')
try:
    UPB = tuple(float(v) for v in a.up_band.split(','))
except ValueError:
    UPB = ()
if len(UPB) != 2 or UPB[0] > 0 or UPB[1] < 0:
    sys.exit('obstacle_gait.py: --up-band takes two numbers, short (<= 0) and past (>= 0)')

SH, SHZ = 40.0, a.SHZ         # stance stroke of one stance (3 slots): along x, along z (mm)
RS = (5, 15, 25, 35)          # landing offsets ahead of the hip (mm); stance ends at r - SH
PREF = (25, 15, 35, 5)        # in this order of preference
MARGIN = 25.0                 # wanted distance of a landing from an edge (mm)
BAND = 20.0                   # within this of an edge a landing takes the step's length
EDGES = (240.0, 460.0)        # terrains/obstacle.terrain: the step from x = 240 to 460
START = 150.0                 # the support's start x in the terrain
OFF = {'A': 75, 'E': 75, 'B': 25, 'F': 25, 'C': -25, 'G': -25, 'D': -75, 'H': -75}
PAIRS = ('DH', 'CG', 'BF', 'AE')
# the lateral crawl's pairs: one leg ahead of the centre and one behind, on opposite sides, so
# that their sideways reactions cancel in yaw moment (pairs abreast turned the support 56 deg
# in six lateral cycles: measured on the earlier design)
ZPAIRS = ('AH', 'DE', 'BG', 'CF')


def fractions(text, opt, below=False):
    """a step's four phases (lift, swing, hold, land) as fractions of its slot (below: their
    sum may be less than 1, the rest a stand at the slot's end)"""
    f = tuple(float(v) for v in text.split(','))
    if len(f) != 4 or min(f) <= 0 or (sum(f) > 1 + 1e-9 if below else abs(sum(f) - 1) > 1e-9):
        sys.exit('obstacle_gait.py: %s takes four positive fractions that add up to %s' %
                 (opt, 'at most 1' if below else '1'))
    return f


FRAC = fractions(a.frac, '--frac', below=True)  # a wave's slot: lift, swing, hold, land
FRACZ = fractions(a.fracz, '--fracz')
FRACT = fractions(a.fract, '--fract')
RZ = SHZ / 2
STEP = SH / 3                 # a stance foot's travel per slot relative to its hip (mm)
STEPZ = SHZ / 3

RULE7 = {4: """\
#  7. The walk has round((646 + xdrift) / (D / 4)) slots: it turns where the support, at D per
#     cycle, is xdrift past Table 3's x = 646 mm; the lateral crawl has round(270 / (Dz / 4))
#     slots.""", 2: """\
#  7. The wave ends at the first slot whose planned support x passes x2 (rule 11); the lateral
#     crawl has round(270 / (Dz / 2)) slots, Dz its measured advance per cycle of two slots
#     (the release included)."""}
RULE9 = {4: """\
#  9. The turn: the support stands while the pairs step into a staggered sideways stance
#     ({turnh}), then the lateral wave along
#     +z: the diagonal pairs AH, DE, BG, CF in turn (a pair's sideways reactions cancel in yaw),
#     stance feet {SHZ:g} mm sideways over three slots ({Tpz:g} s each). At the end every pair
#     steps back under its hips and every chamber vents (a release with the feet aside rolled
#     the support over the +z row: measured on the earlier design).""", 2: """\
#  9. The end of the walk and the lateral crawl: rule 11. At the end each group steps back
#     under its hips and every chamber vents (a release with the feet aside rolled the support
#     over the +z row: measured on the earlier design)."""}
RULE11 = """
# 11. The end in two groups of four, ACFH and BDEG, as the flat road walks (a group's sideways
#     reactions cancel in yaw: A, C, F, H stand at x +75, -25, +25, -75 mm). From the slot of
#     rule 7 the wave gives way to one slot in which ACFH step {HX:g} mm ahead of their hips
#     (the support standing on BDEG), then {xslots} slots in which the groups alternate, the
#     standing group stroking {SX:g} mm along x in its one slot of stance; the swinging group
#     of the last of them lands aside ({RZ:g} mm along +z) and the lateral crawl starts in the
#     next slot, the group standing aside pushing {SHZ:g} mm along +z while the other swings
#     ({Tpz:g} s slots): no turn of its own. A stance of one slot moves the support more per
#     second than the wave's stance of three: measured 37-41 mm per slot along x at SX 17-20
#     and 33-41 mm along z at SHZ 22-32 (the legs' sway and the landing overshoot add to the
#     stroke; docs/bench/obstacle_pace_2026-12-06)."""

RULE21 = """
# 21. The walk in two groups ends on the measured support (the gate's `walk` statement): the
#     table has {K} more cycle(s) of it ({N} slots, the last the turn); at each slot boundary
#     from which the table can jump to the turn (the walk is periodic in two slots) the
#     player reads the support's x and its advance over the last two slots, and ends the walk
#     there when stopping lands nearer the end point's x than one more cycle would, counting
#     what the turn and the lateral crawl add (rule 7's crawl statement on x)."""


RULE16 = ''
if a.over_step is not None or a.reach is not None:
    RULE16 += ('\n# 16. Where a foot lands on the step (measured): %g mm beyond its offset (the road\'s %g)%s.'
               % (a.over if a.over_step is None else a.over_step, a.over,
                  '' if a.reach is None else
                  ';\n#     a landing on the step within 25 mm of the up edge takes the shortest longer '
                  'offset,\n#     up to %g mm, that keeps 25 mm (the first B, F landings of the '
                  'earlier table hung on\n#     the edge\'s corner, unloaded)' % a.reach))
    if a.reach_road:
        RULE16 += '\n#     Also the road landings within 25 mm before the riser.'
if a.Dcross is not None:
    RULE16 += ('\n# 16b. From the climb\'s end to support x = %g mm the hips advance %g mm per cycle '
               '(measured),\n#     then %g again with the lag kept.' % (a.xcross, a.Dcross, a.D))
if a.up_short >= 0:
    RULE16 += ('\n# 17. A wave landing onto the step from the road lands %g mm behind its plan (measured:\n'
               '#     the support moves on while the foot comes down); one expected within %g..+%g mm of\n'
               '#     the up edge (the foot block on its corner) takes the shortest longer offset, in 5 mm\n'
               '#     steps up to %g mm, expected past that band.' % (a.up_short, UPB[0], UPB[1], a.up_reach))
if a.push > 0:
    RULE16 += ('\n# 18. Before the rear pair\'s step toward the up edge (rule 13\'s slot) %d slot(s) in which no\n'
               '#     pair steps and every stance foot moves on: the support advances D/4 a slot past the\n'
               '#     plateau\'s first feet before the rear pair leaves the road (with C, G landed past the\n'
               '#     corner the support tipped back over them when D, H lifted: docs/notes/obstacle.md)'
               % a.push)
if a.down_lead > 0:
    RULE16 += ('\n# 19. The front pair\'s first step from the plateau down to the road carries the support %g mm\n'
               '#     past the plan (measured); the later landings are planned with the hips that far ahead,\n'
               '#     and the wave ends where the support so planned passes x2.' % a.down_lead)
if a.zoverlap > 0:
    RULE16 += ('\n# 20. The lateral crawl\'s hand-over: both groups stand %g s, half of it either side of the\n'
               '#     slot\'s boundary (the landing group set down after the standing group lifted and the\n'
               '#     support bounced off the road, aloft 0.08 s a slot with a 50 g support, 0.24 s with 25 g:\n'
               '#     the stroke went by in the air); a stance lasts %g s (%.1f mm, the same foot speed),\n'
               '#     a swing %g s. At the end the group that stood last steps under its hips first.'
               % (a.zoverlap, a.Tpz + a.zoverlap,
                                       SHZ * (a.Tpz + a.zoverlap) / a.Tpz, a.Tpz - a.zoverlap))
if a.clear_down:
    RULE16 += ('\n# 12b. The first pair landing near the down edge: rule 12\'s band keeps %g mm from '
               'that edge.' % a.clear)
TURNH = ('still %g mm up, all legs then come down to a %g mm stretch' % (a.rise, a.rise_z)
           if a.rise_low is None or abs(a.rise_low - a.rise) < 1e-6 else
           'at the walk\'s %g mm stretch' % a.rise_low)
HEADER = """\
# gaits/obstacle.gait: the obstacle road's gait (paper Sec. 5.2, Fig. 13/14, Table 3), written
# by tools/obstacle_gait.py (run it again rather than edit this file) with
{args}
# and turned into gaits/obstacle.csv on the mission's calibration by
#   crawlsim gait design gaits/obstacle.gait --stretch --out gaits/obstacle.csv
#     --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4
# (--stretch: the legs' elongation counts: all four chambers stretch a leg 40 mm at 0.26 MPa).
# docs/studies/obstacle.md has the track and the runs behind each rule.
#
# Rules (rod legs, `paper`):
#  1. A wave: six legs stand while one pair steps, the pairs DH, CG, BF, AE in turn, one slot
#     ({Tp:g} s) each; a cycle is four slots. Four-leg stances tipped over on the edges (one
#     foot not quite down leaves a triangle with the support's centre on its edge).
#  2. The support stays level, {rise:g} mm above the road on the walk: a leg on the road stands
#     stretched by all four chambers of its segments (pose R), a leg on the step stands vented,
#     so their feet differ by the step's height (G* poses against S*). The paper's sequence
#     (BCFG raised, ADEH reaching onto the step, BCFG vented) tilted the support over the edge.
#  3. The stance legs carry the support at constant speed: every standing foot moves back
#     relative to its hip by {step:.2f} mm per slot (`linear`), {SH:g} mm over its three
#     slots of stance, so no standing foot slides against another; the support advances
#     4/3 x {SH:g} mm per cycle where the earlier design (all legs still while a pair stepped,
#     then one shift) made {SH:g}, at no more stroke.
#  4. A road leg bends by raising one pair of chambers above the stretch's pressure (GP/GM):
#     the rod level takes its stiffness from FE probes up to a mean segment pressure of
#     0.3 MPa, so the stroke stays within 35 mm of the hip.
#  5. A step goes up, over and down: from the stance to the `plus` foot pose AM (12 mm above
#     the vented leg), over to AP on the same branch (the solver's own choice changes branch
#     where the leg passes straight and the foot drops 12 mm), a short hold, straight down.
#  6. Where a foot lands: r in 5..35 mm ahead of the hip, at least 25 mm from both edges
#     where it can be (landings missed their plan by up to 23 mm), the hips placed by D per
#     cycle. A landing within 20 mm of an edge takes the step's leg length (over the road the
#     foot hangs 40 mm up, carrying nothing until its next step).
{rule7}
#  8. The start: the legs stretch (1 s), the front pair steps ahead (the support standing),
#     then the wave starts with the pairs behind it still under their hips: each stance foot
#     moves at the wave's rate from wherever it stands, so the first cycle is a ramp, not a
#     jolt.
{rule9}{rule10}{rule11}{rule12}{rule13}{rule14}{rule16}
""".format(args='#   D %g, xdrift %g, Dz %g, over %g mm; xclimb %g, rise %g, rise-z %g mm;\n'
           '#   Tclimb %g, Tp %g, Tpz %g, Tstart %g, Tturn %g, t-place %g s'
           % (a.D, a.xdrift, a.Dz, a.over, a.xclimb, a.rise, a.rise_z, a.Tclimb, a.Tp, a.Tpz,
              a.Tstart, a.Tturn, a.t_place) +
           ('' if a.zgroups == 4 else
            ';\n#   zgroups 2, xslots %d, x2 %s, SX %g, SHZ %g mm, Tvent %g s'
            % (a.xslots, a.x2, a.SX, a.SHZ, a.Tvent) +
            ('' if not a.walk_extra else
             ';\n#   walk-extra %d, walk-xend %g, walk-carry %g mm'
             % (a.walk_extra, a.walk_xend, a.walk_carry))) +
           ('' if abs(sum(FRAC) - 1) < 1e-9 and FRAC == (0.25, 0.4, 0.1, 0.25) else
            ';\n#   frac %s (wave step: lift, swing, hold, land; the rest: all legs stand)'
            % a.frac),
           rule7=RULE7[a.zgroups],
           rule9=RULE9[a.zgroups].format(turnh=TURNH, SHZ=SHZ, Tpz=a.Tpz),
           rule11='' if a.zgroups == 4 else
           RULE11.format(HX=a.SX / 2, xslots=a.xslots, SX=a.SX, RZ=SHZ / 2, SHZ=SHZ, Tpz=a.Tpz) +
           ('' if not a.walk_extra else RULE21.format(K=a.walk_extra, N=XSLOTS)),
           rule10='' if a.rise_low is None else
           '\n# 10. Past the step the walk comes down: from the first slot in which every foot '
           'stands on\n#     the road, the road legs\' stretch falls linearly from %g to %g mm '
           'over %d slots\n#     (each stance move ends at the stretch of its slot\'s end, each '
           'landing takes the\n#     stretch of its landing time), as Table 3\'s support comes '
           'down from 40 mm at 14 s to\n#     13 mm at 24 s and 0 at 29 s; the turn then needs '
           'no descent of its own.' % (a.rise, a.rise_low, a.nlow),
           rule13='' if a.Dclimb is None and a.settle <= 0 else
           '\n# 13. The climb: its landings placed by the climb\'s own measured advance, '
           'Dclimb %g mm\n#     per cycle; all eight legs stand %g s before the rear pair\'s slot '
           'whose landings can\n#     reach within 25 mm of the up edge (the support settles).'
           % (DC, a.settle),
           rule14='' if not a.Tcross else
           '\n# 14. The crossing: the walk\'s slot is %g s while the support is planned between x = %g\n'
           '#     and %g mm (the front hips then past the down edge), to win back time on the plateau.'
           % (a.Tcross, a.xclimb, a.xcross),
           rule16=RULE16,
           rule12='' if a.clear <= 0 else
           '\n# 12. A landing on the road before the riser whose band, its planned x plus '
           '%g..%g mm\n#     (where such landings fell against the plan, measured), comes within '
           '%g mm of an edge\n#     takes the offset in %g..%g mm whose band keeps furthest away.'
           % (SCAT[0], SCAT[1], a.clear, a.rmin, a.rmax),
           Tp=a.Tp, rise=a.rise, step=STEP, SH=SH, risez=a.rise_z, SHZ=SHZ, Tpz=a.Tpz)

out = [HEADER]
w = out.append
w('name obstacle\nsample 0.05\n')
w('# R: all four chambers of every segment, the straight leg %g mm longer (a leg on the road)\n'
  % a.rise)
w('pose R II1:1,2,3,4 II2:1,2,3,4 II3:1,2,3,4 rise %g\n' % a.rise)
w('# R15: the same, %g mm (the lateral crawl\'s stance on the road)\n' % a.rise_z)
w('pose R15 II1:1,2,3,4 II2:1,2,3,4 II3:1,2,3,4 rise %g\n' % a.rise_z)
w('# U0: a lift-off from under the hip\n')
w('pose U0 foot 0 12 plus\n')

POSES = []        # (kind, offset) in order of first use, written before the moves


def tag(v):
    """a pose name's number: 13.333 -> 13q33"""
    s = ('%.2f' % abs(v)).rstrip('0').rstrip('.')
    return s.replace('.', 'q')


BASES = []        # stretches between --rise and --rise-z the lowering uses (rule 10)


def base_pose(h):
    """the name of the straight stretched pose of stretch h mm"""
    if abs(h - a.rise) < 1e-6:
        return 'R'
    if abs(h - a.rise_z) < 1e-6:
        return 'R15'
    h = round(h, 2)
    if h not in BASES:
        BASES.append(h)
    return 'RH' + tag(h)


def gkind(h):
    """the road stance kind at stretch h: G at --rise, L15-based G15 at --rise-z, else Gh"""
    if abs(h - a.rise) < 1e-6:
        return 'G'
    return 'G@%g' % round(h, 2)


def need(kind, v):
    if abs(v) < 1e-9 and kind in ('G', 'S', 'A', 'V', 'L15', 'L40'):
        return {'G': 'R', 'S': 'straight', 'A': 'U0', 'V': 'straight', 'L15': 'R15',
                'L40': 'R'}[kind]
    if abs(v) < 1e-9 and kind.startswith('G@'):
        return base_pose(float(kind[2:]))
    key = (kind, round(v, 2))
    if key not in POSES:
        POSES.append(key)
    if kind.startswith('G@'):
        return '%s%s%s' % (base_pose(float(kind[2:])).replace('R', 'G', 1), 'P' if v > 0 else 'M',
                           tag(v))
    return '%s%s%s' % ({'A': 'A', 'V': 'VL'}.get(kind, kind), 'P' if v > 0 else 'M', tag(v))


def pose_lines(kind, v):
    n = need(kind, v)
    r = abs(v)
    sgn = '' if v > 0 else '-'
    # the bend pair that moves the foot to +e1: II1 on 3,4 and II2 on 1,2 (an S-shape)
    fwd, back = ('II1:3,4 II2:1,2', 'II1:1,2 II2:3,4') if v > 0 else \
        ('II1:1,2 II2:3,4', 'II1:3,4 II2:1,2')
    side, oside = ('II1:2,3 II2:1,4', 'II1:1,4 II2:2,3') if v > 0 else \
        ('II1:1,4 II2:2,3', 'II1:2,3 II2:1,4')
    if kind == 'G' or kind.startswith('G@'):
        b = 'R' if kind == 'G' else base_pose(float(kind[2:]))
        return ['pose %s %s II3:1,2,3,4 pressure-of %s\n' % (n, back, b),
                'pose %s %s stroke %s%g\n' % (n, fwd, sgn, r)]
    if kind == 'S':
        return ['pose %s %s stroke %s%g\n' % (n, fwd, sgn, r)]
    if kind == 'A':
        return ['pose %s foot %s%g 12 plus\n' % (n, sgn, r)]
    if kind in ('L15', 'L40'):
        base = 'R15' if kind == 'L15' else 'R'
        return ['pose %s %s II3:1,2,3,4 pressure-of %s\n' % (n, oside, base),
                'pose %s %s side %s%g\n' % (n, side, sgn, r)]
    if kind == 'V':
        return ['pose %s %s side %s%g\n' % (n, side, sgn, r)]
    raise ValueError(kind)


moves = []        # (t0, dur, legs, pose, linear)


def emit(t0, dur, mv, linear=False):
    """move lines at t0 for {leg: pose}, legs with the same pose in one line"""
    g = {}
    for l, pose in mv.items():
        g.setdefault(pose, []).append(l)
    for pose, ls in sorted(g.items(), key=lambda kv: ''.join(sorted(kv[1]))):
        moves.append((t0, dur, ''.join(sorted(ls)), pose, linear))


def comment(s):
    moves.append((None, s))


def band_clear(x, edges=EDGES):
    """rule 12: distance of the band [x + short, x + long] from the nearest edge (0 across one)"""
    lo, hi = x + SCAT[0], x + SCAT[1]
    return min(0.0 if lo <= e <= hi else min(abs(lo - e), abs(hi - e)) for e in edges)


DOWN = [None]     # --clear-down: the first pair whose landing rule 12 moved off the down edge


def pair_of(l):
    """l's pair in the wave"""
    return next(p for p in PAIRS if l in p)


def lx(hipx, r):
    """where a landing of offset r ahead of a hip at hipx falls: --over beyond its plan; with
    rule 16 a landing on the step (rule 6's step length) --over-step beyond it"""
    x = hipx + r + a.over
    if a.over_step is not None and EDGES[0] < x < EDGES[1] + BAND:
        return hipx + r + a.over_step
    return x


def plan(l, hipx, force=None, climb=False):
    """landing offset r and stance kind (G road / S step length) for a foot of hip x (terrain);
    force: the offset (--force), the kind then follows from its landing as rule 6 says; climb:
    a wave landing of a leg standing on the road (rule 17)"""
    best, bestm = None, -1.0
    for r in (PREF if force is None else ()):
        m = min(abs(lx(hipx, r) - e) for e in EDGES)
        if m >= MARGIN:
            best, bestm = r, m
            break
        if m > bestm:
            best, bestm = r, m
    if force is not None:
        best = force
        bestm = min(abs(lx(hipx, best) - e) for e in EDGES)
    elif a.reach is not None and abs(lx(hipx, best) - EDGES[0]) < MARGIN and \
            (a.reach_road or lx(hipx, best) > EDGES[0]):
        # rule 16: a climbing foot that would stand within MARGIN of the up edge (the nominal's
        # first B, F and C, G landings hung on its corner, unloaded, and slid off it when the
        # pair behind lifted under a 0.5 s actuation time) reaches further onto the step
        r16 = next((r for r in range(int(best) + 5, int(a.reach) + 1, 5)
                    if lx(hipx, r) >= EDGES[0] + MARGIN), a.reach)
        comment('#  %s: rule 16: landing %.0f is %.0f mm from the up edge; offset %g lands %.0f'
                % (l, lx(hipx, best), lx(hipx, best) - EDGES[0], r16, lx(hipx, r16)))
        best = r16
        bestm = min(abs(lx(hipx, best) - e) for e in EDGES)
    elif a.clear > 0 and a.clear_down and lx(hipx, best) > EDGES[0] + MARGIN and \
            band_clear(lx(hipx, best), EDGES[1:]) < a.clear and DOWN[0] in (None, pair_of(l)):
        # rule 12 at the down edge (--clear-down): a landing past the riser whose band comes
        # within --clear of the down edge (A landed on its corner with the support 37-42 mm
        # behind the plan: 25 g open loop, and the 0.5 s actuation time under the gate, on
        # the table of rule 16) takes the offset whose band keeps furthest from that edge
        cands = list(PREF) + [r for r in (-15, -10, -5, 0, 40, 45, 50) if a.rmin <= r <= a.rmax]
        r12 = max(cands, key=lambda r: (band_clear(lx(hipx, r), EDGES[1:]), -abs(r - best)))
        comment('#  %s: rule 12: landing %.0f keeps %.0f mm of its band from the down edge; '
                'offset %g keeps %.0f' % (l, lx(hipx, best), band_clear(lx(hipx, best), EDGES[1:]),
                                          r12, band_clear(lx(hipx, r12), EDGES[1:])))
        best = r12
        bestm = min(abs(lx(hipx, best) - e) for e in EDGES)
        DOWN[0] = pair_of(l)
    elif a.clear > 0 and lx(hipx, best) < EDGES[0] and \
            band_clear(lx(hipx, best)) < a.clear:
        # rule 12: a landing on the road before the riser (the failures of the 25 g and 75 g
        # runs) whose scatter band comes within --clear of an edge: take, among rule 6's
        # offsets and the shorter and longer ones in --rmin..--rmax, the one whose band keeps
        # furthest away
        cands = list(PREF) + [r for r in (-15, -10, -5, 0, 40, 45, 50) if a.rmin <= r <= a.rmax]
        r12 = max(cands, key=lambda r: (band_clear(lx(hipx, r)), -abs(r - best)))
        comment('#  %s: rule 12: landing %.0f keeps %.0f mm of its band from an edge; offset %g '
                'keeps %.0f' % (l, lx(hipx, best), band_clear(lx(hipx, best)), r12,
                                band_clear(lx(hipx, r12))))
        best = r12
        bestm = min(abs(lx(hipx, best) - e) for e in EDGES)
    if force is None and climb and a.up_short >= 0 and \
            EDGES[0] < lx(hipx, best) < EDGES[1] and \
            EDGES[0] + UPB[0] < lx(hipx, best) - a.up_short < EDGES[0] + UPB[1]:
        # rule 17: a wave landing onto the step from the road falls --up-short behind its plan
        # (the support moves on while the foot comes down): expected on the edge's corner, it
        # takes the shortest longer offset expected past the corner's band (k3's B, F landed on
        # the corner at 233.4 mm and held on rod legs and adaptive strain, slid off it at 232.0
        # on fixed 0.5 ms strain: a margin of ~1.5 mm, less than the levels differ by)
        e0 = lx(hipx, best) - a.up_short
        r17 = next((r for r in range(int(best) + 5, int(a.up_reach) + 1, 5)
                    if lx(hipx, r) - a.up_short >= EDGES[0] + UPB[1]), a.up_reach)
        comment('#  %s: rule 17: landing %.0f expected at %.0f, on the corner; offset %g expected at %.0f'
                % (l, lx(hipx, best), e0, r17, lx(hipx, r17) - a.up_short))
        best = r17
        bestm = min(abs(lx(hipx, best) - e) for e in EDGES)
    landx = lx(hipx, best)
    # rule 6: on the step the vented length; on the road the road's, also next to a riser (a
    # rear foot hanging over the road with the step's length left the centre of mass behind
    # the standing feet while the pair ahead stepped: the support tipped backwards off the
    # step, measured); just past the down edge the step's length, hanging (a road leg landing
    # on the step's corner lifts the support 40 mm)
    b = 'S' if EDGES[0] < landx < EDGES[1] + BAND else 'G'
    where = 'step' if EDGES[0] < landx < EDGES[1] else 'road'
    comment('#  %s: hip at %.0f, foot to %.0f (%s, %.0f mm from an edge)%s'
            % (l, hipx, landx, where, bestm, ', step length' if b == 'S' and where == 'road'
               else ''))
    return best, b


def step(t0, slot, legs, lift_pose, air_pose, land_pose, frac=FRAC):
    fl, fs, fh, fd = frac
    emit(t0, fl * slot, {l: lift_pose[l] for l in legs})
    emit(t0 + fl * slot, fs * slot, {l: air_pose[l] for l in legs})
    emit(t0 + (fl + fs + fh) * slot, fd * slot, {l: land_pose[l] for l in legs})


comment('# 0..1 s: raise: every leg stretches %g mm' % a.rise)
emit(0, 1, {l: 'R' for l in OFF})
# state per leg: (kind G/S, offset mm, time the stance began or None if standing still)
state = {l: ['G', 0.0] for l in OFF}
t = a.t_place
# rule 8: the front pair steps ahead, the support standing
comment('# %.2f s: the front pair steps ahead (the support stands)' % t)
land = {}
for l in PAIRS[3]:
    r, b = plan(l, START + OFF[l])
    state[l] = [b, float(r)]
    land[l] = need(b, r)
step(t, a.Tstart, PAIRS[3], {l: 'U0' for l in PAIRS[3]}, {l: need('A', state[l][1])
                                                              for l in PAIRS[3]}, land)
t += a.Tstart
tw = t
NS = int(round((a.xturn + a.xdrift) / (a.D / 4))) if a.walk_slots is None else a.walk_slots
if a.x2 is not None and a.x2 > 0:
    # rule 19: the support then stands --down-lead ahead of the slots' plan: the wave ends where
    # that passes x2
    NS = next(k for k in range(1000) if k * a.D / 4 + a.down_lead > a.x2)
# slot start times: the climb's slots until the support is planned past xclimb (rule 8)
T0, XP = [tw], [0.0]          # slot starts, planned support x there
DUR = []                      # slot lengths (a slot ends at T0[s] + DUR[s])
XL = [0.0]                    # planned support x for the landings (rule 13: --Dclimb)
SETTLE = None                 # rule 13: the slot before which all eight stand --settle s
WAVE = []                     # per slot: the index of the wave's step (its pair PAIRS[k % 4]) or
k = 0                         # None, a push slot (rule 18)
npush = 0
for s in range(NS):
    tp = a.Tclimb if XP[-1] < a.xclimb else a.Tp if XP[-1] >= a.xcross or not a.Tcross \
        else a.Tcross
    climbing = XP[-1] < a.xclimb
    XP.append(XP[-1] + a.D / 4)
    # rule 13: the climb's landings placed by the climb's measured advance; past the climb the
    # plan's own x again (the later rows as rule 6 has them)
    if climbing:
        XL.append(XL[-1] + DC / 4)
    elif a.Dcross is not None:
        # rule 16: past the climb the landings follow the crossing's own advance to --xcross,
        # then --D again from where that leaves them (the support keeps the lag it took)
        XL.append(XL[-1] + (a.Dcross if XP[-2] < a.xcross else a.D) / 4)
    else:
        XL.append(XP[-1])
    # rule 18: before the rear pair's step toward the up edge (rule 13's slot) --push slots in
    # which no pair steps and every stance foot moves on (the support advances D/4 a slot)
    push = npush < a.push and k % 4 == 0 and \
        START + OFF['D'] + XL[-1] + max(RS) + a.over >= EDGES[0] - MARGIN
    WAVE.append(None if push else k)
    npush, k = (npush + 1, k) if push else (npush, k + 1)
    gap = 0.0
    if a.settle > 0 and SETTLE is None and not push and WAVE[s] % 4 == 0 and \
            START + OFF['D'] + XL[-1] + max(RS) + a.over >= EDGES[0] - MARGIN:
        SETTLE, gap = s, a.settle
    T0[-1] += gap
    DUR.append(tp)
    T0.append(T0[-1] + tp)


LEAD = [0.0]      # rule 19: how far the support stands ahead of the plan (mm), once the front pair steps down
LOW = [None]      # rule 10: the slot boundary from which the walk comes down (None: not yet)


def height(k):
    """a road leg's stretch at slot boundary k (rule 10), mm"""
    if a.rise_low is None or LOW[0] is None or k <= LOW[0]:
        return a.rise
    f = min(1.0, (k - LOW[0]) / float(a.nlow))
    return a.rise + f * (a.rise_low - a.rise)


def skind(b, k):
    """the stance kind of a foot of kind b (G road / S step) at slot boundary k"""
    return gkind(height(k)) if b == 'G' else b


def stance(l, b, r0, s0, s1):
    """the stance moves of leg l from slot s0 to s1 (its foot from r0 back STEP per slot), one
    linear move per run of equal slots and equal stretch, so that every standing foot moves at
    the same speed (and, while the walk comes down, at the same stretch)"""
    k = s0
    while k < s1:
        m = k
        while m + 1 < s1 and abs(DUR[m + 1] - DUR[k]) < 1e-9 and \
                abs(T0[m + 1] - T0[m] - DUR[m]) < 1e-9 and \
                abs(height(m + 2) - height(k + 1)) < 1e-9 and \
                abs(height(k + 1) - height(k)) < 1e-9:
            m += 1
        emit(T0[k], T0[m] + DUR[m] - T0[k], {l: need(skind(b, m + 1), r0 - STEP * (m + 1 - s0))},
             linear=True)
        k = m + 1


comment('# the walk: %d slots from %.2f s (%g s while the support climbs, then %g s;\n'
        '# support planned at D = %g mm per cycle)' % (NS, tw, a.Tclimb, a.Tp, a.D))
pending = {}      # leg -> slot index its current stance began
for l in OFF:
    pending[l] = 0
for s in range(NS):
    t0 = T0[s]
    if WAVE[s] is None:
        comment('# rule 18: %.2f..%.2f s no pair steps, every stance foot moves on (support planned '
                'at x + %.0f mm)' % (t0, t0 + DUR[s], XP[s]))
        continue
    k = WAVE[s]
    pair = PAIRS[k % 4]
    if a.rise_low is not None and LOW[0] is None and (
            s == a.low_slot if a.low_slot is not None else
            all(state[l][0] == 'G' for l in OFF) and XP[s] > EDGES[1] - START):
        # rule 10: every foot stands on the road past the step: come down from here
        LOW[0] = s
        comment('# from %.2f s every foot stands on the road: the walk comes down from %g to '
                '%g mm over %d slots' % (t0, a.rise, a.rise_low, a.nlow))
    if k % 4 == 0:
        comment('# cycle %d from %.2f s: support planned at x + %.0f mm' % (k // 4, t0, XP[s]))
    lift, air, lnd = {}, {}, {}
    for l in pair:
        s0 = pending.pop(l)
        b, r0 = state[l]
        off = r0 - STEP * (s - s0)
        stance(l, b, r0, s0, s)
        lift[l] = need('A', off)
        key = (pair, k // 4)
        r, b2 = plan(l, START + OFF[l] + XL[s + 1] + LEAD[0], FORCE.get(key), climb=b == 'G')
        if key in FH and l == pair[0]:
            # rule 15: a foothold: the plan's offset is the nominal candidate; each candidate's
            # landing with the hips where the plan puts them (the player shifts it by how far
            # the measured support stands from XP[s] at the lift)
            offs, margin = FH[key]
            offs = sorted(set(offs) | {float(r)})
            FHINFO.append(dict(t=T0[s], legs=pair, cycle=k // 4, xplan=XP[s], margin=margin, r=r,
                               dur=DUR[s], dx=XP[s + 1] - XP[s],
                               offsets=offs, lands=[lx(START + OFF[l] + XL[s + 1], o)
                                                    for o in offs]))
            comment('foothold %.4f %s %s margin %g' % (T0[s], pair, ','.join('%g' % o for o in offs),
                                                      margin))
        air[l] = need('A', r)
        lnd[l] = need(skind(b2, s + 1), r)
        state[l] = [b2, float(r)]
        pending[l] = s + 1
    if a.down_lead > 0 and not LEAD[0] and pair == PAIRS[3] and b == 'S' and b2 == 'G':
        # rule 19: the front pair's first step from the plateau down to the road carries the
        # support on past the plan; the later landings are planned with the hips that far ahead
        LEAD[0] = a.down_lead
        comment('# rule 19: from this step down the support stands %g mm ahead of the plan' % a.down_lead)
    if s == SETTLE:
        comment('# rule 13: all eight stand %.2f..%.2f s' % (t0 - a.settle, t0))
    step(t0, DUR[s], pair, lift, air, lnd)
t = T0[NS]
for l in OFF:
    s0 = pending.pop(l)
    b, r0 = state[l]
    off = r0 - STEP * (NS - s0)
    stance(l, b, r0, s0, NS)
    state[l] = [b, off]
xend = XP[NS]

hN = height(NS)
if abs(hN - a.rise_z) > 1e-6 and abs(hN - a.rise) > 1e-6:
    sys.exit('obstacle_gait.py: the walk ends at a %g mm stretch: the turn takes --rise or '
             '--rise-z' % hN)
lturn = 'L15' if abs(hN - a.rise_z) < 1e-6 else 'L40'
if a.zgroups == 4:
    # rule 9: the turn into a staggered sideways stance; pair ZPAIRS[j] lifts first in lateral slot
    # j, having pushed j slots: it stands at RZ - SHZ + j STEPZ (pair 0 under its hips)
    comment('# the turn from %.2f s (support planned at x + %.0f mm): the pairs step into a\n'
            '# staggered sideways stance' % (t, xend))
    side0 = {}
    for j, pair in enumerate(ZPAIRS):
        sz = RZ - SHZ + j * STEPZ if j > 0 else 0.0
        for l in pair:
            side0[l] = sz
        step(t, a.Tturn, pair, {l: need('A', state[l][1]) for l in pair},
             {l: need('V', side0[l]) for l in pair}, {l: need(lturn, side0[l]) for l in pair},
             FRACT)
        t += a.Tturn
    if lturn == 'L40':
        comment('# all legs down to the %g mm stretch' % a.rise_z)
        emit(t, 1.0, {l: need('L15', side0[l]) for l in OFF})
        t += 1.0
    tz = t
    NZS = int(round(a.zend / (a.Dz / 4)))
    comment('# the lateral wave: %d slots of %g s from %.2f s' % (NZS, a.Tpz, tz))
    zs = {l: side0[l] for l in OFF}
    pending = {l: tz for l in OFF}
    for s in range(NZS):
        t0 = tz + s * a.Tpz
        pair = ZPAIRS[s % 4]
        lift, air, lnd = {}, {}, {}
        for l in pair:
            ts = pending.pop(l)
            off = zs[l] - STEPZ * round((t0 - ts) / a.Tpz)
            if t0 > ts + 1e-9:
                emit(ts, t0 - ts, {l: need('L15', off)}, linear=True)
            lift[l] = need('V', off)
            air[l] = need('V', RZ)
            lnd[l] = need('L15', RZ)
            zs[l] = RZ
            pending[l] = t0 + a.Tpz
        step(t0, a.Tpz, pair, lift, air, lnd, FRACZ)
    t = tz + NZS * a.Tpz
    for l in OFF:
        ts = pending.pop(l)
        off = zs[l] - STEPZ * round((t - ts) / a.Tpz)
        if t > ts + 1e-9:
            emit(ts, t - ts, {l: need('L15', off)}, linear=True)
        zs[l] = off
    comment('# the feet back under the hips, pair by pair, then every chamber vented\n'
            '# (the paper\'s "release all pressure")')
    for pair in ZPAIRS:
        step(t, a.Tturn, pair, {l: need('V', zs[l]) for l in pair}, {l: 'straight' for l in pair},
             {l: 'R15' for l in pair}, FRACT)
        t += a.Tturn
else:
    # rule 9 with two groups: the turn is one slot in which ACFH step aside to +RZ (the
    # support standing on BDEG); then the groups alternate, BDEG first: the group that stands
    # pushes its feet from +RZ to -RZ (SHZ) in its one slot, the other swings from where it
    # stands (BDEG: the walk's last stance) to +RZ
    if lturn != 'L15':
        sys.exit('obstacle_gait.py: --zgroups 2 needs the walk to end at --rise-z (rule 10)')
    GZ = ('ACFH', 'BDEG')
    HX = a.SX / 2
    gk = skind('G', NS)
    if a.xslots > 0:
        # rule 11: the walk's end in two groups (--SX per slot of stance): a slot in which ACFH
        # step to +SX/2 (the support standing on BDEG), then the groups alternate, BDEG first;
        # in the last of these slots the swinging group lands aside (+RZ), the lateral stance:
        # the crawl along +z starts in the next slot without a turn of its own
        comment('# from %.2f s (support planned at x + %.0f mm): two groups, ACFH step to %g mm'
                % (t, xend, HX))
        step(t, a.Tpz, GZ[0], {l: need('A', state[l][1]) for l in GZ[0]},
             {l: need('A', HX) for l in GZ[0]}, {l: need(gk, HX) for l in GZ[0]}, FRACZ)
        t += a.Tpz
        xs = {l: state[l][1] for l in OFF}
        for l in GZ[0]:
            xs[l] = HX
        WALK = (t, a.Tpz, XSLOTS - 1)
        for k in range(XSLOTS):
            st, sw = GZ[k % 2], GZ[(k + 1) % 2]
            last = k == XSLOTS - 1
            emit(t, a.Tpz, {l: need(gk, -HX) for l in st}, linear=True)
            step(t, a.Tpz, sw, {l: need('A', xs[l]) for l in sw},
                 {l: need('V', RZ) if last else need('A', HX) for l in sw},
                 {l: need('L15', RZ) if last else need(gk, HX) for l in sw}, FRACZ)
            for l in st:
                xs[l] = -HX
            for l in sw:
                xs[l] = HX
            t += a.Tpz
        g0 = XSLOTS % 2          # the group that stands aside: it pushes first
        for l in OFF:
            state[l] = ['G', xs[l]]
    else:
        comment('# the turn from %.2f s (support planned at x + %.0f mm): ACFH step aside, %g mm'
                % (t, xend, RZ))
        step(t, a.Tpz, GZ[0], {l: need('A', state[l][1]) for l in GZ[0]},
             {l: need('V', RZ) for l in GZ[0]}, {l: need('L15', RZ) for l in GZ[0]}, FRACZ)
        t += a.Tpz
        g0 = 0
    tz = t
    NZS = int(round(a.zend / (a.Dz / 2))) if a.crawl_max is None else a.crawl_max
    CRAWL = (tz, a.Tpz, NZS)
    comment('# the lateral crawl: %d slots of %g s from %.2f s, groups ACFH / BDEG' % (NZS, a.Tpz, tz))
    # rule 20 (--zoverlap O): every stance foot moves at SHZ / Tpz relative to its hip; a group
    # lands at +RZO O/2 before a slot's boundary and lifts O/2 after the next one (at -RZO), so
    # both groups stand O at each hand-over; O = 0 is rule 11's crawl, move for move
    O = a.zoverlap
    if O < 0 or O >= a.Tpz:
        sys.exit('obstacle_gait.py: --zoverlap takes a time in 0..--Tpz (s)')
    VZ = SHZ / a.Tpz
    RZO = RZ + VZ * O / 2
    zs = {l: RZ for l in GZ[g0]}
    since = {l: tz for l in GZ[g0]}   # when the stance of each standing foot began (at zs)
    first = True
    for s in range(NZS):
        t0 = tz + s * a.Tpz
        st, sw = GZ[(g0 + s) % 2], GZ[(g0 + s + 1) % 2]
        te = t0 + a.Tpz + (O / 2 if s < NZS - 1 else 0.0)
        for l in st:
            zs[l] -= VZ * (te - since[l])
        emit(since[st[0]], te - since[st[0]], {l: need('L15', zs[l]) for l in st}, linear=True)
        for l in st:
            since[l] = te
        tl = t0 if first else t0 + O / 2
        lift = {l: need('A', state[l][1]) if first else need('V', zs[l]) for l in sw}
        step(tl, t0 + a.Tpz - O / 2 - tl, sw, lift, {l: need('V', RZO) for l in sw},
             {l: need('L15', RZO) for l in sw}, FRACZ)
        for l in sw:
            zs[l], since[l] = RZO, t0 + a.Tpz - O / 2
        first = False
    t = tz + NZS * a.Tpz
    if O > 0:
        # the last swing's group stands the last O / 2 of the crawl, stroking
        sw = GZ[(g0 + NZS) % 2]
        for l in sw:
            zs[l] -= VZ * (t - since[l])
        emit(since[sw[0]], t - since[sw[0]], {l: need('L15', zs[l]) for l in sw}, linear=True)
    comment('# the feet back under the hips, group by group, then every chamber vented\n'
            '# (the paper\'s "release all pressure")')
    # rule 20: the group that stood in the last slot (its feet at -RZO) steps first, the other
    # (just landed) standing: after 8 slots ACFH first (just landed) threw the support 61 mm
    # along +z, after 7 the group that stood last first moved it 6 mm (strain legs, 50 g)
    order = GZ if O <= 0 else (GZ[(g0 + NZS - 1) % 2], GZ[(g0 + NZS) % 2])
    for g in order:
        step(t, a.Tturn, g, {l: need('V', zs[l]) for l in g}, {l: 'straight' for l in g},
             {l: 'R15' for l in g}, FRACT)
        t += a.Tturn
emit(t, a.Tvent, {l: 'straight' for l in OFF})
t += a.Tvent

w('# per offset r (mm ahead of the hip, negative behind): road stance G (stretched S-shape),\n'
  '# step stance S (vented S-shape), swing top A (12 mm above the vented leg, branch plus);\n'
  '# sideways: L40 / L15 (stretched, foot aside along e2), VL (vented, aside)\n')
# every x offset a stance uses gets both stance lengths, road G and step S (their feet differ by
# the step's height: tests/core/test_obstacle.c)
for kind, val in list(POSES):
    if kind in ('G', 'S'):
        need('S' if kind == 'G' else 'G', val)
lines = [ln for kind, val in POSES for ln in pose_lines(kind, val)]
if BASES:
    w('# RH: the straight leg stretched between %g and %g mm (the walk coming down: rule 10)\n'
      % (a.rise, a.rise_z))
for h in BASES:
    w('pose %s II1:1,2,3,4 II2:1,2,3,4 II3:1,2,3,4 rise %g\n' % (base_pose(h), h))
for line in lines:
    w(line)
for m in moves:
    if m[0] is None:
        w(m[1] + '\n')
    else:
        t0, dur, legs, pose, lin = m
        # the end written as the rounded start plus a rounded duration equal to the rounded end,
        # so that a leg's consecutive moves meet exactly
        ts, te = round(t0, 4), round(t0 + dur, 4)
        w('move %.4f %.4f %s %s%s\n' % (ts, te - ts, legs, pose, ' linear' if lin else ''))
w('end %.2f\n' % (t + a.Tvent))
text = ''.join(out)
if a.out == '-':
    sys.stdout.write(text)
else:
    with open(a.out, 'w') as f:
        f.write(text)
if a.gate_out:
    with open(a.gate_out, 'w') as f:
        f.write(gate_text(text.splitlines(), a.out if a.out != '-' else 'the description'))

missing = set(FH) - {(f['legs'], f['cycle']) for f in FHINFO}
if missing:
    sys.exit('obstacle_gait.py: --foothold %s: no such step in the walk' %
             ', '.join('%s:%d' % k for k in sorted(missing)))


def design(gait, csv, cache=None):
    """crawlsim gait design on the mission's table (as the shipped gait is designed); cache: a
    folder of tables already designed, keyed by the description's statements (its comments
    and `foothold` lines, which change no row, left out)"""
    import hashlib
    import os
    import shutil
    import subprocess
    key = None
    if cache:
        body = ''.join(ln for ln in open(gait) if not ln.startswith('#') and
                       not ln.startswith('foothold '))
        key = os.path.join(cache, hashlib.sha1(body.encode()).hexdigest() + '.csv')
        if os.path.exists(key):
            shutil.copyfile(key, csv)
            return
    cmd = [a.crawlsim, 'gait', 'design', gait, '--stretch', '--calibration',
           'robot/calibration_fe_leg_modes_sym.h5', '--cal-rule', 'rbf-pair', '--p-max', '0.4',
           '--out', csv]
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    if r.returncode != 0:
        sys.exit('obstacle_gait.py: %s failed: %s' % (' '.join(cmd), r.stdout.strip()[-300:]))
    if key:
        os.makedirs(cache, exist_ok=True)
        shutil.copyfile(csv, key)


def read_csv(path):
    """(header, rows as (time text, fields)) of a gait CSV, comments dropped"""
    lines = [ln.rstrip('\n') for ln in open(path) if ln.strip() and not ln.startswith('#')]
    head = lines[0].split(',')
    rows = [ln.split(',') for ln in lines[1:]]
    return head, rows


if a.foothold_out:
    # rule 15's companion: every candidate designed as a whole gait with its offset forced,
    # compared with the nominal table: its legs' columns over the rows where any candidate
    # differs (one row before, two after: the schedule's ramp at a row reads the row before it
    # and the time of the row after, gaits_schedule.h) into NAME.foothold.d/, and the index
    import os
    import subprocess
    name = a.foothold_out
    folder = name + '.foothold.d'
    os.makedirs(folder, exist_ok=True)
    if not (a.foothold_reuse and os.path.exists(name + '.csv')):
        design(a.out, name + '.csv')
    head, nom = read_csv(name + '.csv')
    argv = []
    skip = False
    for x in sys.argv[1:]:
        if skip:
            skip = False
            continue
        # the candidates' own runs write no gate: the gate is the nominal description's
        # (before margin18 each candidate's run overwrote it, the last candidate's winning)
        if x in ('-o', '--out', '--foothold-out', '--gate-out'):
            skip = True
            continue
        if x.startswith(('--out=', '--foothold-out=', '--gate-out=')):
            continue
        argv.append(x)
    index = ['# %s.foothold: the landings of %s.csv chosen during the run from the measured '
             'support\n# (gaits/gaits_foothold.h), written by tools/obstacle_gait.py rule 15 with\n'
             '#   %s\n' % (os.path.basename(name), os.path.basename(name), ' '.join(argv))]
    def decide(f, w0):
        """rule 15's decision time and the plan's support x then: the lift, or (--decide swing)
        the window's start, the plan's x moving D/4 per slot (rule 3)"""
        if a.decide == 'lift':
            return f['t'], f['xplan']
        return w0, f['xplan'] + f['dx'] * min(1.0, (w0 - f['t']) / f['dur'])

    for k, f in enumerate(FHINFO):
        cols = [i for i, h in enumerate(head) if h[:1] in f['legs']]
        tables = {}
        names = ['f%d_%s_%g.csv' % (k + 1, f['legs'], o) for o in f['offsets']]
        if a.foothold_reuse and all(os.path.exists(os.path.join(folder, n)) for n in names):
            # --foothold-reuse: this foothold's candidates are in the folder (a rerun that adds
            # footholds after it): its window from them (the rows kept: one before the window,
            # then to its end)
            rows = [ln.split(',') for ln in open(os.path.join(folder, names[0]))
                    if ln.strip() and not ln.startswith('#')][1:]
            td, xd = decide(f, float(rows[1][0]))
            index.append('# %s in cycle %d: the plan\'s offset %g mm (nominal)\n'
                         'foothold %.4f %s xplan %.3f margin %g window %s %s\n'
                         % (f['legs'], f['cycle'], f['r'], td, f['legs'], xd,
                            f['margin'], rows[1][0], rows[-1][0]))
            for o, land, fn in zip(f['offsets'], f['lands'], names):
                lo, hi = ((EDGES[0], EDGES[1] + BAND) if EDGES[0] < land < EDGES[1] + BAND else
                          (-1e6, EDGES[0]) if land <= EDGES[0] else (EDGES[1] + BAND, 1e6))
                index.append('candidate %g land %.3f fits %g %g %s/%s%s\n'
                             % (o, land, lo, hi, os.path.basename(folder), fn,
                                ' nominal' if abs(o - f['r']) < 1e-9 else ''))
            continue
        for o in f['offsets']:
            if abs(o - f['r']) < 1e-9:
                tables[o] = nom
                continue
            var = os.path.join(folder, 'var.gait')
            spec = '%s:%d:%g' % (f['legs'], f['cycle'], o)
            low = [] if LOW[0] is None else ['--low-slot', str(LOW[0])]
            # the forces in effect (the default BF:4:35 too: a run given --force has no
            # default, so before margin18 a candidate of a table without --force lost it)
            forced = [x for f0 in a.force for x in ('--force', f0)]
            subprocess.run([sys.executable, sys.argv[0]] + argv + low + forced +
                           ['--force', spec, '-o', var],
                           check=True)
            design(var, os.path.join(folder, 'var.csv'), a.design_cache)
            h2, rows = read_csv(os.path.join(folder, 'var.csv'))
            if h2 != head or [r[0] for r in rows] != [r[0] for r in nom]:
                sys.exit('obstacle_gait.py: candidate %s: its rows are not at the nominal '
                         'table\'s times' % spec)
            for i, (r1, r0) in enumerate(zip(rows, nom)):
                if any(r1[c] != r0[c] for c in range(1, len(head)) if c not in cols):
                    sys.exit('obstacle_gait.py: candidate %s changes other legs (row %d)' % (spec, i))
            tables[o] = rows
            os.remove(var)
            os.remove(os.path.join(folder, 'var.csv'))
        diff = [i for i in range(len(nom)) if any(tables[o][i][c] != nom[i][c]
                                                  for o in tables for c in cols)]
        if not diff:
            sys.exit('obstacle_gait.py: the candidates of foothold %s:%d do not differ'
                     % (f['legs'], f['cycle']))
        i0, i1 = max(0, diff[0] - 1), min(len(nom) - 1, diff[-1] + 2)
        w0, w1 = float(nom[diff[0]][0]), float(nom[i1][0])
        if w0 < f['t']:
            sys.exit('obstacle_gait.py: foothold %s:%d differs before its lift' % (f['legs'], f['cycle']))
        td, xd = decide(f, w0)
        index.append('# %s in cycle %d: the plan\'s offset %g mm (nominal)\n'
                     'foothold %.4f %s xplan %.3f margin %g window %s %s\n'
                     % (f['legs'], f['cycle'], f['r'], td, f['legs'], xd, f['margin'],
                        nom[diff[0]][0], nom[i1][0]))
        for o, land in zip(f['offsets'], f['lands']):
            fn = 'f%d_%s_%g.csv' % (k + 1, f['legs'], o)
            with open(os.path.join(folder, fn), 'w') as out_f:
                out_f.write('# candidate %g mm of foothold %d (%s, lift %.4f s): its legs\' rows '
                            'over %g..%g s\n' % (o, k + 1, f['legs'], f['t'], w0, w1))
                out_f.write(','.join(head[c] for c in [0] + cols) + '\n')
                for i in range(i0, i1 + 1):
                    out_f.write(','.join(tables[o][i][c] for c in [0] + cols) + '\n')
            # the landings its stance length suits (rule 6): the step's length from the riser
            # to BAND past the down edge, the road's on either side
            lo, hi = ((EDGES[0], EDGES[1] + BAND) if EDGES[0] < land < EDGES[1] + BAND else
                      (-1e6, EDGES[0]) if land <= EDGES[0] else (EDGES[1] + BAND, 1e6))
            index.append('candidate %g land %.3f fits %g %g %s/%s%s\n'
                         % (o, land, lo, hi, os.path.basename(folder), fn,
                            ' nominal' if abs(o - f['r']) < 1e-9 else ''))
    with open(name + '.foothold', 'w') as out_f:
        out_f.write(''.join(index))

#!/usr/bin/python3
"""Write gaits/obstacle.gait, the obstacle road's gait description (README "Obstacle road").

The description is long (one move line per leg group and phase) but follows from a few rules
and the terrain's two edges; this script is those rules. It plans, cycle by cycle, where each
foot lands, from the hips' expected positions (the measured hip advance per shift, D) and the
edges of terrains/obstacle.terrain, and writes the moves; `crawlsim gait design` then turns the
description into gaits/obstacle.csv with pressures from the calibrated leg model.

  /usr/bin/python3 tools/obstacle_gait.py -o gaits/obstacle.gait
  crawlsim gait design gaits/obstacle.gait --stretch \\
      --calibration robot/calibration_fe_leg_modes.h5 --p-max 0.4

Options set the measured constants (defaults: the values the shipped file was made with)."""
import argparse
import sys

ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
ap.add_argument('-o', '--out', default='-', help='output file (default stdout)')
ap.add_argument('--D', type=float, default=43.0,
                help='hip advance per x cycle near the edges, mm (measured)')
ap.add_argument('--xmean', type=float, default=40.2,
                help='mean support advance per x cycle over the whole walk, mm (measured): with '
                '--xdrift it sets the number of x cycles (rule 7)')
ap.add_argument('--xdrift', type=float, default=19.7,
                help='how far the lateral crawl carries the support back along x, mm (measured): '
                'the walk turns this far past xturn (rule 7)')
ap.add_argument('--Dz', type=float, default=55.6,
                help='mean support advance per lateral cycle, mm (measured, the release included):'
                ' the number of lateral cycles is zend / Dz')
ap.add_argument('--over', type=float, default=10.0,
                help='landing overshoot ahead of the planned foot, mm (measured)')
ap.add_argument('--xturn', type=float, default=646.0, help='x of the turn, mm (Table 3)')
ap.add_argument('--zend', type=float, default=270.0, help='lateral travel, mm (Table 3)')
a = ap.parse_args()

SH, SHZ = 40, 50              # stance stroke of one shift: along x, along z (mm)
RS = (5, 15, 25, 35)          # landing offsets ahead of the hip (mm); stance ends at r - SH
PREF = (25, 15, 35, 5)        # in this order of preference
MARGIN = 25.0                 # wanted distance of a landing from an edge (mm)
BAND = 20.0                   # within this of an edge a landing takes the step's length
NEAR = 60.0                   # a cycle with a hip this near an edge uses the slow timing
SLOW = (0.2, 0.4, 0.1, 0.2, 1.0, 0.3)    # lift, swing, hold, land, shift, settle (s)
FAST = (0.15, 0.3, 0.1, 0.15, 0.8, 0.2)
EDGES = (240.0, 460.0)        # terrains/obstacle.terrain: the step from x = 240 to 460
START = 150.0                 # the support's start x in the terrain
OFF = {'A': 75, 'E': 75, 'B': 25, 'F': 25, 'C': -25, 'G': -25, 'D': -75, 'H': -75}
PAIRS = ('DH', 'CG', 'BF', 'AE')
# the lateral crawl's pairs: one leg ahead of the centre and one behind, on opposite sides, so
# that their sideways reactions cancel in yaw moment (pairs abreast turned the support 56 deg
# in six lateral cycles: measured)
ZPAIRS = ('AH', 'DE', 'BG', 'CF')
RZ = SHZ // 2

HEADER = """\
# gaits/obstacle.gait: the obstacle road's gait (paper Sec. 5.2, Fig. 13/14, Table 3), written
# by tools/obstacle_gait.py (D {D:g}, xmean {xmean:g}, xdrift {xdrift:g}, Dz {Dz:g}, over {over:g}
# mm; run it again rather than edit this file) and turned into gaits/obstacle.csv by
#   crawlsim gait design obstacle.gait --stretch --calibration robot/calibration_fe_leg_modes.h5
#            --p-max 0.4
# (--stretch: the legs' elongation counts; the FE mode table: its all-four mode stretches a leg
# 40 mm at 0.26 MPa, where the pair-mode table's analytic stretch gives 13.8 mm at its 0.3 MPa
# end). README "Obstacle road" has the track and the runs behind each rule.
#
# Rules (each found by simulation, rod legs, `paper`):
#  1. Six legs stand while two swing: the pairs DH, CG, BF, AE step in turn, rear to front.
#     Four-leg stances (groups ACFH / BDEG) tipped over at 3 s: one foot not quite down leaves
#     a triangle with the support's centre on its edge.
#  2. The support stays level, 40 mm above the road (the paper raises it 50 mm, Table 3): a leg
#     on the road stands stretched 40 mm by all four chambers of its segments (pose R,
#     0.26 MPa), a leg on the step stands vented, so their feet differ by the step's height
#     (G* poses against S*). The paper's sequence (BCFG raised, ADEH reaching onto the step,
#     BCFG vented) tilts the support over the edge; on these legs it tipped backwards and left
#     the road at 4.5 s.
#  3. The support moves only in a shift, all eight legs carrying: every foot goes from r ahead
#     of its hip to r - {SH} mm, together, so no foot slides; the stance is centred on the hip
#     (r - {SH} .. r within -35 .. 35 mm).
#  4. A road leg bends by raising one pair of chambers above the stretch's 0.26 MPa (GP/GM):
#     the rod level takes its stiffness from FE probes up to a mean segment pressure of
#     0.3 MPa, so the pair gets at most 0.08 MPa more: 35 mm of stroke.
#  5. A swing goes up, over and down: from the stance to the `plus` foot pose AM (foot behind
#     the hip, 12 mm above the vented leg: 52 mm above the road for a road leg; the `plus`
#     branch keeps II1 on chambers 3,4 behind the hip), over to AP on the same branch (the
#     solver's own choice changes branch at the hip, where the leg passes straight and the
#     foot drops 12 mm: measured, it dropped onto the step's corner and threw the support
#     27 mm up), a hold of 0.1 s (without it the landing feet overshot by 10-20 mm), then
#     straight down onto the stance pose.
#  6. Where a foot lands: r in 5..35 mm ahead of the hip, chosen at least 25 mm from both
#     edges where it can be (a foot's contact radius is 7.5-11 mm; measured landings missed
#     their plan by up to 23 mm), the hips placed by the advance per cycle measured on the
#     climb, D. A
#     landing within 20 mm of an edge, on either side, takes the step's leg length: if the
#     foot is over the road it hangs 40 mm up, carrying nothing until its next step; a leg of
#     the road's length landing on the step lifts the support 40 mm (measured: it tipped).
#  7. The walk has round((646 + xdrift) / xmean) cycles, xmean the mean advance measured over
#     the whole walk (683.5 mm at the turn after 17 cycles), xdrift how far the lateral crawl
#     then carries the support back along x (17.5 and 21.9 mm in two runs with rule 11), so that
#     the crawl ends at Table 3's x = 646 mm; the lateral crawl has round(270 / Dz) cycles. A
#     cycle's ~40 mm quantise where the walk turns: 16 cycles ended 27.8 mm from Table 3's end
#     point, 17 cycles 17.0 mm (2026-12-03).
#  8. The cycles near an edge are slow (0.9 s a pair, a 1 s shift, 0.3 s to settle); on the
#     flat road 0.7 s, 0.8 s and 0.2 s.
#  9. The turn: each pair steps to the lateral stance (L40, still 40 mm up), all legs come
#     down to a 15 mm stretch (L15), then lateral cycles along +z: pairs swing sideways
#     (vented: the foot rises 15 mm), all shift {SHZ} mm; at the end every leg vents. The
#     lateral pairs are diagonal (AH, DE, BG, CF): a pair's sideways reactions then cancel in
#     yaw; with the pairs abreast (DH, CG, BF, AE) the support turned 10 deg per lateral cycle
#     (56 deg at the end, measured) and crabbed 90 mm along +x, off the road's end. Before the
#     release every pair steps back under its hips (see there).
# 10. The lateral cycles use the slow timing (0.9 s a pair, a 1 s shift): with the flat road's
#     0.7 s pairs the support slid back 20-40 mm along z while a pair swung (the swinging legs'
#     inertia against the stance feet's friction, which only the 50 g support's weight loads
#     under `paper`) and turned to 13.5 deg of yaw: 34.7 mm per cycle; slow, 55.6 mm per cycle,
#     yaw back within 2 deg after the turn and 3 mm of drift along x per cycle (rod legs,
#     2026-12-03; README "Obstacle road").
# 11. The lateral pairs step in alternating order, AH DE BG CF in one cycle and CF BG DE AH in
#     the next, so that no pair always steps first: with the same order every cycle the crawl's
#     drift back along x depended on where the walk turned (12.2 mm from a turn at x = 679, 29.2
#     mm from one at 642: the same gait with 17 and 16 x cycles), alternating it 17.5 and 21.9
#     mm (rod legs, 2026-12-03; docs/bench/obstacle_stroke_2026-12-03/lateral_order.txt).
""".format(D=a.D, xmean=a.xmean, xdrift=a.xdrift, Dz=a.Dz, over=a.over, SH=SH, SHZ=SHZ)

out = [HEADER]
w = out.append
w('name obstacle\nsample 0.05\n')
w('# R: all four chambers of every segment, the straight leg 40 mm longer (a leg on the road)\n')
w('pose R II1:1,2,3,4 II2:1,2,3,4 II3:1,2,3,4 rise 40\n')
w('# R15: the same, 15 mm (the lateral crawl\'s stance on the road)\n')
w('pose R15 II1:1,2,3,4 II2:1,2,3,4 II3:1,2,3,4 rise 15\n')
w('# U0: the first lift-off, from under the hip\n')
w('pose U0 foot 0 12 plus\n')
w('# per stroke r: road stance (stretched, S-shape ahead GP / behind GM), step stance (vented\n'
  '# S-shape SP / SM), swing tops AP / AM (12 mm above the vented leg, branch plus)\n')
allr = sorted(set(RS) | set(abs(r - SH) for r in RS))
for r in allr:
    w('pose GP%d II1:1,2 II2:3,4 II3:1,2,3,4 pressure-of R\n' % r)
    w('pose GP%d II1:3,4 II2:1,2 stroke %d\n' % (r, r))
    w('pose GM%d II1:3,4 II2:1,2 II3:1,2,3,4 pressure-of R\n' % r)
    w('pose GM%d II1:1,2 II2:3,4 stroke -%d\n' % (r, r))
    w('pose SP%d II1:3,4 II2:1,2 stroke %d\n' % (r, r))
    w('pose SM%d II1:1,2 II2:3,4 stroke -%d\n' % (r, r))
    w('pose AP%d foot %d 12 plus\n' % (r, r))
    w('pose AM%d foot -%d 12 plus\n' % (r, r))
w('# the lateral crawl: sideways S-shapes (chambers 2,3 on II1 move the foot to +z) over a\n'
  '# stretch of 40 mm (L40, the turn) or 15 mm (L15); VL: vented, in the air\n')
for r in sorted({RZ, abs(RZ - SHZ)}):
    for base, b0 in (('L40', 'R'), ('L15', 'R15')):
        w('pose %sP%d II1:1,4 II2:2,3 II3:1,2,3,4 pressure-of %s\n' % (base, r, b0))
        w('pose %sP%d II1:2,3 II2:1,4 side %d\n' % (base, r, r))
        w('pose %sM%d II1:2,3 II2:1,4 II3:1,2,3,4 pressure-of %s\n' % (base, r, b0))
        w('pose %sM%d II1:1,4 II2:2,3 side -%d\n' % (base, r, r))
    w('pose VLP%d II1:2,3 II2:1,4 side %d\n' % (r, r))
    w('pose VLM%d II1:1,4 II2:2,3 side -%d\n' % (r, r))


def air(s):
    if s == 0:
        return 'U0'
    return ('AP%d' % s) if s > 0 else ('AM%d' % -s)


def stance(b, s):
    if s == 0:
        return 'R' if b == 'G' else 'straight'
    return '%s%s%d' % (b, 'P' if s > 0 else 'M', abs(s))


def emit(t0, dur, moves):
    """move lines at t0 for {leg: pose}, legs with the same pose in one line"""
    g = {}
    for l, pose in moves.items():
        g.setdefault(pose, []).append(l)
    for pose, ls in sorted(g.items(), key=lambda kv: ''.join(sorted(kv[1]))):
        w('move %.2f %.2f %s %s\n' % (t0, dur, ''.join(sorted(ls)), pose))


w('# 0..1 s: raise: every leg stretches 40 mm (the paper: BCFG raise the support 50 mm)\n')
w('move 0 1 ABCDEFGH R\n')
state = {k: ('G', 0) for k in OFF}
t, x = 1.0, 0.0
NX = int(round((a.xturn + a.xdrift) / a.xmean))
NZ = int(round(a.zend / a.Dz))
for k in range(NX):
    near = any(abs(START + OFF[l] + x + dx - e) < NEAR for l in OFF for e in EDGES
               for dx in (0, a.D))
    tl, ts, th, td, tsh, tset = SLOW if near else FAST
    w('# cycle %d from %.2f s: hips planned at x + %.0f mm (%s)\n'
      % (k, t, x, 'near an edge: slow' if near else 'flat road'))
    for pair in PAIRS:
        lift, swing, land = {}, {}, {}
        for l in pair:
            hip = START + OFF[l] + x
            best, bestm = None, -1.0
            for r in PREF:
                m = min(abs(hip + r + a.over - e) for e in EDGES)
                if m >= MARGIN:
                    best, bestm = r, m
                    break
                if m > bestm:
                    best, bestm = r, m
            r = best
            landx = hip + r + a.over
            b = 'S' if EDGES[0] - BAND < landx < EDGES[1] + BAND else 'G'
            where = 'step' if EDGES[0] < landx < EDGES[1] else 'road'
            w('#  %s: hip at %.0f, foot to %.0f (%s, %.0f mm from an edge)%s\n'
              % (l, hip, landx, where, bestm,
                 ', step length' if b == 'S' and where == 'road' else ''))
            lift[l] = air(state[l][1])
            swing[l] = air(r)
            land[l] = stance(b, r)
            state[l] = (b, r)
        emit(t, tl, lift)
        emit(t + tl, ts, swing)
        emit(t + tl + ts + th, td, land)
        t += tl + ts + th + td
    shift = {}
    for l in OFF:
        b, s = state[l]
        shift[l] = stance(b, s - SH)
        state[l] = (b, s - SH)
    w('#  shift: the support %d mm along +x\n' % SH)
    emit(t, tsh, shift)
    t += tsh + tset
    x += a.D
tl, ts, th, td, tsh, tset = SLOW
w('# the turn from %.2f s (hips planned at x + %.0f mm): each pair to the lateral stance\n'
  % (t, x))
for pair in ZPAIRS:
    emit(t, tl, {l: air(state[l][1]) for l in pair})
    emit(t + tl, ts, {l: 'VLP%d' % RZ for l in pair})
    emit(t + tl + ts + th, td, {l: 'L40P%d' % RZ for l in pair})
    t += tl + ts + th + td
w('# all legs down to the 15 mm stretch\n')
emit(t, 1.0, {l: 'L15P%d' % RZ for l in OFF})
t += 1.2
tl, ts, th, td, tsh, tset = SLOW
for kz in range(NZ):
    w('# lateral cycle %d from %.2f s\n' % (kz, t))
    if kz > 0:
        for pair in (ZPAIRS if kz % 2 == 0 else ZPAIRS[::-1]):  # rule 11
            emit(t, tl, {l: 'VLM%d' % abs(RZ - SHZ) for l in pair})
            emit(t + tl, ts, {l: 'VLP%d' % RZ for l in pair})
            emit(t + tl + ts + th, td, {l: 'L15P%d' % RZ for l in pair})
            t += tl + ts + th + td
    emit(t, tsh, {l: 'L15M%d' % abs(RZ - SHZ) for l in OFF})
    t += tsh + tset
w('# the feet back under the hips, pair by pair (a release with every foot %d mm aside of its\n'
  '# hip rolled the support over the +z row: measured), then every chamber vented (the\n'
  '# paper\'s "release all pressure")\n' % abs(RZ - SHZ))
for pair in ZPAIRS:
    emit(t, tl, {l: 'VLM%d' % abs(RZ - SHZ) for l in pair})
    emit(t + tl, ts, {l: 'straight' for l in pair})
    emit(t + tl + ts + th, td, {l: 'R15' for l in pair})
    t += tl + ts + th + td
emit(t, 1.0, {l: 'straight' for l in OFF})
t += 1.0
w('end %.2f\n' % (t + 1.0))
text = ''.join(out)
if a.out == '-':
    sys.stdout.write(text)
else:
    with open(a.out, 'w') as f:
        f.write(text)

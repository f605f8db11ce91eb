#!/usr/bin/python3
"""Write a flat-road wave gait for `earth` (issue 33 item 4; docs/studies/earth_gait.md).

Under `earth` the paper's robot stands at 80 % of its legs' sway-buckling load when half of them
stand (the stance check of `crawlsim run`), and the searched two-group gait
(gaits/flat_road_rod.gait) folds its four S-bent stance legs within 1.3 s. This script writes the
other structure the issue names: a wave (the obstacle's, tools/obstacle_gait.py), six legs
standing while one pair steps, so that each standing leg carries 4/6 of the two-group load, on
stance legs as straight as the stroke allows. The rules:

  1. Pairs abreast step in turn, DH, CG, BF, AE (back to front), one slot T each; a cycle is
     four slots. Each standing foot moves back relative to its hip by SH / 3 per slot (`linear`),
     SH over its three slots of stance, so no standing foot slides against another; the support
     advances SH / 3 per slot, 4/3 SH per cycle (speed SH / (3 T)).
  2. Stance: a level sole, the foot r ahead of the hip by an S of the two upper segments (II1 on
     one pair of chambers, II2 on the opposite pair, one common pressure: `stroke r`), II3
     vented and straight: the straightest leg that carries a foot offset with a level sole.
     With --rise R > 0 every segment also takes all four chambers at the pressure that
     stretches the straight leg R mm (the obstacle's road stance).
  3. A step: lift (the `plus` foot pose U above the vented straight leg's foot, at the stance
     offset), swing forward to the landing offset on the same branch, hold, land; fractions of
     the slot --frac.
  4. The start: every leg vented and straight (the settled robot); the front pair AE steps to
     +SH/2 first (the support standing, one slot), then the wave starts with the pairs behind
     it still under their hips: each stance foot moves at the wave's rate from wherever it
     stands, so the first cycle is a ramp (the obstacle's rule 8).
  5. The end: the walk stops at --t-walk; the legs hold (no venting: a vented leg with its foot
     aside drags it).

  /usr/bin/python3 tools/earth_gait.py --T 0.35 --SH 36 -o gaits/flat_road_earth.gait
  crawlsim gait design gaits/flat_road_earth.gait --stretch --out gaits/flat_road_earth.csv \\
      --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4
"""
import argparse
import sys

ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
ap.add_argument('-o', '--out', default='-', help='output file (default stdout)')
ap.add_argument('--T', type=float, default=0.4, help='slot: the time one pair takes to step, s')
ap.add_argument('--SH', type=float, default=36.0,
                help='stance stroke relative to the hip over the three slots of a stance, mm')
ap.add_argument('--bias', type=float, default=0.0,
                help='the stance stroke\'s centre ahead of the hip, mm (0: centred)')
ap.add_argument('--U', type=float, default=12.0,
                help='swing lift above the vented straight leg\'s foot, mm')
ap.add_argument('--rise', type=float, default=0.0,
                help='stance stretch by all four chambers, mm (0: vented stance)')
ap.add_argument('--frac', default='0.25,0.4,0.1,0.25',
                help='a slot\'s lift, swing, hold, land as fractions (sum 1)')
ap.add_argument('--order', default='DH,CG,BF,AE', help='the pairs in stepping order')
ap.add_argument('--t-start', type=float, default=0.2,
                help='when the first pair steps ahead, s (the robot stands until then)')
ap.add_argument('--t-walk', type=float, default=9.5, help='the walk ends by this time, s')
a = ap.parse_args()

FRAC = [float(v) for v in a.frac.split(',')]
PAIRS = a.order.split(',')
if len(FRAC) != 4 or abs(sum(FRAC) - 1) > 1e-9 or min(FRAC) < 0:
    sys.exit('earth_gait.py: --frac needs four fractions >= 0 that sum to 1')
if sorted(''.join(PAIRS)) != list('ABCDEFGH'):
    sys.exit('earth_gait.py: --order must name every leg A..H once')
N = len(PAIRS)
STEP = a.SH / (N - 1)          # a stance foot's travel per slot relative to its hip (mm)
R0 = a.bias + a.SH / 2         # landing offset (mm ahead of the hip)

poses = {}                     # name -> lines


def tag(v):
    s = ('%.2f' % abs(v)).rstrip('0').rstrip('.')
    return ('P' if v > 0 else 'M') + s.replace('.', 'q')


def stance_pose(r):
    r = round(r, 2)
    if abs(r) < 1e-9:
        return 'R' if a.rise > 0 else 'straight'
    n = 'G' + tag(r)
    if n not in poses:
        fwd, back = ('II1:3,4 II2:1,2', 'II1:1,2 II2:3,4') if r > 0 else \
            ('II1:1,2 II2:3,4', 'II1:3,4 II2:1,2')
        if a.rise > 0:
            poses[n] = ['pose %s %s II3:1,2,3,4 pressure-of R\n' % (n, back),
                        'pose %s %s stroke %g\n' % (n, fwd, r)]
        else:
            poses[n] = ['pose %s %s stroke %g\n' % (n, fwd, r)]
    return n


def air_pose(r):
    r = round(r, 2)
    n = 'A0' if abs(r) < 1e-9 else 'A' + tag(r)
    if n not in poses:
        poses[n] = ['pose %s foot %g %g plus\n' % (n, r, a.U)]
    return n


moves = []                     # (t0, dur, legs, pose, linear) or (None, comment)


def emit(t0, dur, legs, pose, linear=False):
    moves.append((t0, dur, legs, pose, linear))


def step(t0, slot, legs, r_from, r_to):
    fl, fs, fh, fd = FRAC
    emit(t0, fl * slot, legs, air_pose(r_from))
    emit(t0 + fl * slot, fs * slot, legs, air_pose(r_to))
    emit(t0 + (fl + fs + fh) * slot, fd * slot, legs, stance_pose(r_to))


t = 0.0
if a.rise > 0:
    moves.append((None, '# 0..1 s: every leg stretches %g mm' % a.rise))
    emit(0.0, 1.0, 'ABCDEFGH', 'R')
    t = 1.0
t = max(t, a.t_start)
front = PAIRS[-1]
moves.append((None, '# %.2f s: the front pair %s steps to +%g mm (the support stands)'
              % (t, front, R0)))
step(t, a.T, front, 0.0, R0)
t += a.T
tw = t
NS = int((a.t_walk - tw) / a.T + 1e-9)
moves.append((None, '# the wave: %d slots of %g s from %.2f s, pairs %s' % (NS, a.T, tw,
                                                                        ' '.join(PAIRS))))
# per pair: offset at the start of its current stance and the slot it began in
state = {p: [0.0, 0] for p in PAIRS}
state[front] = [R0, 0]
for s in range(NS):
    t0 = tw + s * a.T
    p = PAIRS[s % N]
    r0, s0 = state[p]
    r_now = r0 - STEP * (s - s0)
    if s > s0:
        emit(tw + s0 * a.T, (s - s0) * a.T, p, stance_pose(r_now), linear=True)
    step(t0, a.T, p, r_now, R0)
    state[p] = [R0, s + 1]
t = tw + NS * a.T
for p in PAIRS:
    r0, s0 = state[p]
    if NS > s0:
        emit(tw + s0 * a.T, (NS - s0) * a.T, p, stance_pose(r0 - STEP * (NS - s0)), linear=True)

head = ("# flat-road wave gait for `earth`, written by tools/earth_gait.py (run it again rather\n"
        "# than edit this file) with\n"
        "#   T %g s, SH %g mm, bias %g mm, U %g mm, rise %g mm, frac %s, order %s,\n"
        "#   t-start %g s, t-walk %g s\n"
        "# and turned into a table on the mission's calibration by\n"
        "#   crawlsim gait design THIS.gait --stretch --out THIS.csv\n"
        "#     --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4\n"
        "# The rules: tools/earth_gait.py; the runs behind them: docs/studies/earth_gait.md.\n"
        % (a.T, a.SH, a.bias, a.U, a.rise, a.frac, a.order, a.t_start, a.t_walk))
out = [head, 'name flat-road-earth\nsample 0.05\n']
if a.rise > 0:
    out.append('# R: all four chambers of every segment, the straight leg %g mm longer\n' % a.rise)
    out.append('pose R II1:1,2,3,4 II2:1,2,3,4 II3:1,2,3,4 rise %g\n' % a.rise)
out.append('# G*: stance (level sole, S of II1 and II2); A*: swing top (%g mm up, branch plus)\n'
           % a.U)
for n in poses:
    out.extend(poses[n])
for m in moves:
    if m[0] is None:
        out.append(m[1] + '\n')
        continue
    t0, dur, legs, pose, lin = m
    ts, te = round(t0, 4), round(t0 + dur, 4)
    out.append('move %.4f %.4f %s %s%s\n' % (ts, te - ts, legs, pose, ' linear' if lin else ''))
out.append('end %.2f\n' % (t + 0.1))
text = ''.join(out)
if a.out == '-':
    sys.stdout.write(text)
else:
    with open(a.out, 'w') as f:
        f.write(text)

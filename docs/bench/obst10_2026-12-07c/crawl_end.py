#!/usr/bin/python3
"""A lateral crawl that ends on the measured support (issue 33, the 25 g support's shortfall):
a prototype controller through the Python API (reporting data, not used by any code).

The table (GAIT.csv, written by tools/obstacle_gait.py with more lateral slots than any support
needs: --Dz 45 gives 12) plays as the scene plays it, under its landing gate, until the crawl's
decision points; from then a controller plays the same table with its clock moved on (the sim's
own gait command at t + offset, crawlsim.h cs_simGaitCommand): at the boundary after lateral
slot j, j of the last slot's phase (NMAX - 1 - j even: the table's release follows a slot of
that phase, so the rows at the jump's two ends are the same pose), the support's measured z
(cs_simSupportPose) and its advance over the last two slots, a, decide: the crawl ends there
(offset (NMAX - 1 - j) Tpz: the release follows at once) when z + CARRY >= ZEND - a / 2, i.e.
when stopping ends nearer the end point than one more cycle of the measured pace. CARRY is the
release's own advance along z (measured on the nominal, --carry). Nothing moves the support but
the legs; the decision reads the measured state only, as the landing gate does. With the
controller on, the gate neither tests nor holds (crawlsim.h): every gate is released by 24 s of
table time, before the first decision; the hold so far (the state's gate part) is read at each
decision and kept in the controller's clock (table time = run time - hold + the skip).

usage: crawl_end.py GAIT.csv GATE.gate [--support-mass KG] [--t-end S] [--carry MM]
       [--zend MM] [--fixed N] [--set FIELD=VALUE]...   (--fixed N: end after N slots whatever
       is measured, a check; --set friction=0.6, tau=0.04, ramp=0.1, step_tol=1.25e-4: the
       set's runs)
Prints Table 3's nodes, the end's distance from (646, 270), tilt, the decision and CPU s."""
import argparse
import re
import resource

import numpy as np

import crawlsim

T = [4, 5, 7, 11, 12, 14, 24, 29, 32]
X = [26, 26, 52, 130, 170, 230, 492, 646, 646]
H = [22, 48, 20, 50, 40, 40, 13, 0, 0]
Z = [0, 0, 0, 0, 0, 0, 0, 90, 270]

ap = argparse.ArgumentParser()
ap.add_argument('gait')
ap.add_argument('gate')
ap.add_argument('--support-mass', type=float, default=None)
ap.add_argument('--t-end', type=float, default=36.0)
ap.add_argument('--carry', type=float, default=23.0)
ap.add_argument('--zend', type=float, default=270.0)
ap.add_argument('--fixed', type=int, default=None)
ap.add_argument('--set', action='append', default=[], metavar='FIELD=VALUE',
                help='a csRunDef number (friction, tau, step_tol, ...): the set\'s other runs')
a = ap.parse_args()

desc = open(a.gait.replace('.csv', '.gait')).read()
m = re.search(r'# the lateral crawl: (\d+) slots of ([0-9.]+) s from ([0-9.]+) s', desc)
NMAX, TPZ, TZ = int(m.group(1)), float(m.group(2)), float(m.group(3))

kw = dict(scene='obstacle', gait=a.gait, gate=a.gate, conditions='paper', t_end=a.t_end)
if a.support_mass is not None:
    kw['support_mass_kg'] = a.support_mass
for fv in a.set:
    kw[fv.split('=')[0]] = float(fv.split('=')[1])
sim = crawlsim.Sim(**kw)
offset = [0.0]


def play(s, t, p):
    s.gait_command(t + offset[0], out=p)


track, tilt, zb, decided = {}, 0.0, {}, None
cands = [j for j in range(1, NMAX) if (NMAX - 1 - j) % 2 == 0]
# the gate's hold (s): the table's clock is the run's less it; the state's gate part is its last
# 3 + n values, the hold the second (core/sim_state.c)
NG = sum(1 for ln in open(a.gate) if ln.startswith('gate '))


def hold_now():
    return float(sim.get_state()[-(3 + NG) + 1])


bounds = [TZ + (j + 1) * TPZ for j in range(NMAX)]   # table times of the slots' ends
grid = [round(0.05 * i, 10) for i in range(1, int(round(a.t_end / 0.05)) + 1)]
j, gi, HOLD = 0, 0, 0.0
while gi < len(grid):
    HOLD = hold_now() if decided is None else HOLD
    tb = bounds[j] + HOLD if decided is None and j < NMAX else float('inf')
    tm = min(grid[gi], tb)
    sim.run_until(tm)
    pos, q = sim.support_pose()
    if abs(tm - grid[gi]) < 1e-9:
        gi += 1
        tilt = max(tilt, np.degrees(np.arccos(np.clip(1 - 2 * (q[1] ** 2 + q[3] ** 2), -1, 1))))
        for tn in T:
            if abs(tm - tn) < 1e-9:
                track[tn] = pos.copy()
    if abs(tm - tb) < 1e-9:
        zb[j] = pos[2]
        if j in cands and j >= 2:
            adv = zb[j] - zb[j - 2]
            stop = (j + 1 == a.fixed) if a.fixed else pos[2] + a.carry >= a.zend - adv / 2
            if stop or j == NMAX - 1:
                decided = (j + 1, tm, pos[2], adv)
                if j < NMAX - 1:
                    offset[0] = (NMAX - 1 - j) * TPZ - HOLD
                    sim.set_controller(play)
        j += 1
end = sim.support_pose()[0]
worst, where = 0.0, ''
row = []
for k, tn in enumerate(T):
    if tn not in track:
        row.append('%d:-' % tn)
        continue
    x, h, z = track[tn]
    row.append('%d:%.0f/%.0f/%.0f' % (tn, x, h, z))
    e = max(abs(x - X[k]), abs(h - H[k]), abs(z - Z[k]))
    if e > worst:
        worst, where = e, '%d s' % tn
print('%s%s%s: %d lateral slots written from %.2f s (%.2f s each)'
      % (a.gait, '' if a.support_mass is None else ' support %g kg' % a.support_mass,
         ''.join(' ' + v for v in a.set), NMAX, TZ, TPZ))
print('  ' + ' '.join(row))
if decided:
    print('  crawl ended after %d slots at %.2f s: z %.1f mm, last cycle %.1f mm (carry %g; the '
          'gate held %.3f s before)' % (decided + (a.carry, HOLD)))
print('  worst node from 4 s %.1f mm (%s); end (%.1f, %.1f, %.1f) %.1f mm off; tilt max %.1f deg;'
      ' %.1f CPU s' % (worst, where, end[0], end[1], end[2], np.hypot(end[0] - 646, end[2] - 270),
                       tilt, resource.getrusage(resource.RUSAGE_SELF).ru_utime))

#!/usr/bin/python3
"""The set's table from this folder's run files (reporting data, not used by any code): per
case its end's distance from Table 3's end point, the worst node from 4 s, tilt, leg depth, the
fall time (the run's status when it stopped early), the gate's hold, CPU (user) and wall
seconds and the load before the run.

usage: /usr/bin/python3 table.py [CASE...]  (default: every CASE.txt here, the set's order)"""
import os
import re
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
ORDER = ['nominal', 'ramp0.1', 'ramp0.5', 'mu0.6', 'mu1.0', 'm25g', 'm75g', 'tau0.5x', 'tau2x',
         'dt_half', 'rod']
cases = sys.argv[1:] or [c for c in ORDER if os.path.exists(os.path.join(HERE, c + '.txt'))] + \
    sorted(f[:-4] for f in os.listdir(HERE) if f.endswith('.txt') and f[:-4] not in ORDER and
           not f.startswith('ce_'))
print('| run | end (x, z), off (mm) | worst node from 4 s (mm) | tilt (deg) | depth (mm) | fall '
      '| gate held (s) | CPU s, wall s | load before |')
print('|---|---|---|---|---|---|---|---|---|')
for c in cases:
    txt = open(os.path.join(HERE, c + '.txt')).read()
    log = open(os.path.join(HERE, c + '.log')).read()
    m = re.search(r'worst node from 4 s ([0-9.]+) mm \(([^)]*)\); end \(([-0-9.]+), [-0-9.]+, '
                  r'([-0-9.]+)\) ([0-9.]+) mm off; tilt max ([0-9.]+) deg.*leg depth max ([0-9.]+)',
                  txt)
    st = re.search(r'run to ([0-9.]+) s, status ([^;]*);', txt)
    held = re.search(r'held ([0-9.]+) s', txt)
    cpu = re.search(r'([0-9.]+) s user, ([0-9.]+) s wall', log)
    load = re.search(r'load average: ([0-9.]+)', log)
    fell = st and st.group(2) != 'ok'
    fall = re.search(r't = ([0-9.]+) s', st.group(2)).group(1) + ' s' if fell else '-'
    print('| %s | %s | %s | %s | %s | %s | %s | %s | %s |' % (
        c, '(%s, %s), %s' % (m.group(3), m.group(4), m.group(5)) if not fell else 'falls',
        '%s (%s)' % (m.group(1), m.group(2)) if not fell else '-', m.group(6), m.group(7), fall,
        held.group(1) if held else '-', '%s, %s' % cpu.groups() if cpu else '-',
        load.group(1) if load else '-'))

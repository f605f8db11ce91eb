#!/usr/bin/python3
"""Test the end of an obstacle gait from a saved state (reporting tool, not used by any code).

  restart.py save GAIT.csv T STATE.npz       run GAIT.csv (the obstacle scene, rod legs, paper,
                                             the mission's table) to T s; keep the whole state
                                             and the support's track so far
  restart.py run GAIT.csv STATE.npz OUT.npz  restore the state, run GAIT.csv on from there to
                                             its end, keep the track (the saved part before)
  restart.py score OUT.npz                   Table 3's nodes as table3.py prints them

The restart is exact only if GAIT.csv equals the saved run's gait up to T (the generator's
moves up to T unchanged: tools/obstacle_gait.py with the same walk options). Track arrays: t [N]
s, pos [N, 3] mm (support displacement), quat [N, 4]. Needs CRAWLSIM_LIBRARY or the build's
library (tools/python/crawlsim)."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), '../../../tools/python'))
import crawlsim  # noqa: E402

DT_OUT = 0.01
T = [0, 1, 2, 3, 4, 5, 7, 11, 12, 14, 24, 29, 32]
X = [0, 0, 0, 0, 26, 26, 52, 130, 170, 230, 492, 646, 646]
H = [0, 50, 50, 13, 22, 48, 20, 50, 40, 40, 13, 0, 0]
Z = [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 90, 270]


def sim_of(gait, t_end=0.0):
    return crawlsim.Sim(scene='obstacle', gait=gait, conditions='paper', legs='rod',
                        calibration='robot/calibration_fe_leg_modes_sym.h5', cal_rule='rbf-pair',
                        t_end=t_end)


def track(s, t1, ts, ps, qs):
    while s.t < t1 - 1e-9:
        try:
            s.run_until(min(t1, s.t + DT_OUT))
        except crawlsim.Error as e:
            print('run failed at %.3f s: %s' % (s.t, e))
            return False
        p, q = s.support_pose()
        ts.append(s.t)
        ps.append(p.copy())
        qs.append(q.copy())
    return True


def gait_end(path):
    last = None
    with open(path) as f:
        for ln in f:
            if ln[:1].isdigit():
                last = ln
    return float(last.split(',')[0])


def rows(path, t1):
    with open(path) as f:
        return [ln for ln in f if ln[:1].isdigit() and float(ln.split(",")[0]) <= t1 + 1e-9]


def prefix_equal(a, b, t1):
    """True if the gait tables a and b agree on every row up to t1 (the command at t depends
    on the rows up to t only), else the time
    of the first row that differs"""
    ra, rb = rows(a, t1), rows(b, t1)
    for x, y in zip(ra, rb):
        if x != y:
            return x.split(',')[0]
    return True if len(ra) == len(rb) else 'end'


def score(path):
    d = np.load(path)
    t, pos, q = d['t'], d['pos'], d['quat']
    uy = 1 - 2 * (q[:, 1] ** 2 + q[:, 3] ** 2)
    tilt = np.degrees(np.arccos(np.clip(uy, -1, 1)))
    row, worst, where = [], 0.0, ''
    for k, tn in enumerate(T):
        if tn > t[-1] + 1e-9:
            row.append('%d:-' % tn)
            continue
        i = int(np.argmin(abs(t - tn)))
        x, h, z = pos[i]
        row.append('%d:%.0f/%.0f/%.0f' % (tn, x, h, z))
        if tn >= 4:
            e = max(abs(x - X[k]), abs(h - H[k]), abs(z - Z[k]))
            if e > worst:
                worst, where = e, '%d s' % tn
    end = pos[-1]
    print('%s: %.2f s' % (path, t[-1]))
    print('  ' + ' '.join(row))
    print('  worst node from 4 s %.1f mm (%s); end (%.1f, %.1f, %.1f) %.1f mm off; tilt max %.1f'
          ' deg (last 1 s %.1f)' % (worst, where, end[0], end[1], end[2],
                                    np.hypot(end[0] - 646, end[2] - 270), tilt.max(),
                                    tilt[t > t[-1] - 1].max()))
    for zz in (90, 200, 270):
        i = np.nonzero(pos[:, 2] >= zz)[0]
        print('  z = %d mm at %s' % (zz, '%.2f s' % t[i[0]] if len(i) else '-'), end='')
    i = np.nonzero(pos[:, 0] >= 646)[0]
    print('; x = 646 at %s' % ('%.2f s' % t[i[0]] if len(i) else '-'))


def main(argv):
    if len(argv) == 4 and argv[0] == 'save':
        gait, t1, out = argv[1], float(argv[2]), argv[3]
        ts, ps, qs = [0.0], [np.zeros(3)], [np.array([1.0, 0, 0, 0])]
        with sim_of(gait) as s:
            track(s, t1, ts, ps, qs)
            np.savez(out, state=s.get_state(), t=ts, pos=ps, quat=qs, gait=gait, t1=t1)
    elif len(argv) == 4 and argv[0] == 'run':
        gait, st, out = argv[1], np.load(argv[2]), argv[3]
        same = prefix_equal(str(st['gait']), gait, float(st['t1']))
        if same is not True:
            sys.exit('restart.py: %s differs from the saved run\'s %s before %g s (row at %s s)'
                     % (gait, st['gait'], float(st['t1']), same))
        ts, ps, qs = list(st['t']), list(st['pos']), list(st['quat'])
        with sim_of(gait) as s:
            s.set_state(st['state'])
            track(s, gait_end(gait), ts, ps, qs)
        np.savez(out, t=ts, pos=ps, quat=qs)
        score(out)
    elif len(argv) == 2 and argv[0] == 'score':
        score(argv[1])
    else:
        sys.exit(__doc__)


main(sys.argv[1:])

#!/usr/bin/python3
"""The design-referenced landing gate (a prototype sensing controller, not in the library).

usage (from the source root, after the build): /usr/bin/python3 gate2.py RUN [T_END [PTOL]]
RUN: a run of issue 33's robustness set (nominal, ramp0.5, tau2x, ...). Writes RUN_gate2.txt
here (Table 3's nodes as table3.py prints them, the waits, the end) and runs/RUN_gate2.npz
(RUN_gate2_pPTOL.* for a PTOL other than the default). GATE_EVERY=1: a gate waits for every
chamber of the eight legs (RUN_gate2_every.*). GATE_GAIT=NAME: NAME.csv with the gates of
NAME.gait (RUN_gate2_BASENAME.*).

As docs/bench/obstacle_2026-12-06d/gate.py with GATE_SENSOR=pressure (every lift of a pair in
the wave waits for the last other pair that lifted, the table's clock held meanwhile, at most
one slot), but a pair is down when its chambers are as near their valves' command as the
design has them at that table time, within PTOL (default 0.005 MPa, a pressure sensor's
accuracy: about 1 % of the table's 0.4 MPa range), rather than within PTOL of the command
itself: gatelib.py. The gate waits only when the valves are slower than designed; a run whose
gates never wait plays the library's own table (sim.gait_command at t, bit for bit the
open-loop run, cs_api.c) until the first wait.
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, 'tools/python')
sys.path.insert(0, HERE)
import crawlsim  # noqa: E402
from gatelib import R0, Design, Gates, Table  # noqa: E402

RUNS = {'nominal': {}, 'ramp0.1': {'ramp': 0.1}, 'ramp0.5': {'ramp': 0.5},
        'mu0.6': {'friction': 0.6}, 'mu1.0': {'friction': 1.0},
        'm25g': {'support_mass_kg': 0.025}, 'm75g': {'support_mass_kg': 0.075},
        'tau0.5x': {'tau': 0.01}, 'tau2x': {'tau': 0.04}, 'dt_half': {'dt': 0.0005},
        # a diagnosis, not a set run: does ramp 0.5's slide on the plateau stop with more grip?
        'ramp0.5_mu1.0': {'ramp': 0.5, 'friction': 1.0}}
T3 = [0, 1, 2, 3, 4, 5, 7, 11, 12, 14, 24, 29, 32]
X3 = [0, 0, 0, 0, 26, 26, 52, 130, 170, 230, 492, 646, 646]
H3 = [0, 50, 50, 13, 22, 48, 20, 50, 40, 40, 13, 0, 0]
Z3 = [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 90, 270]


def main():
    run = sys.argv[1]
    t_end = float(sys.argv[2]) if len(sys.argv) > 2 else 36.0
    ptol = float(sys.argv[3]) if len(sys.argv) > 3 else 0.005
    gait = os.environ.get('GATE_GAIT', 'gaits/obstacle')  # NAME: NAME.gait and NAME.csv
    tab = Table(gait + '.csv')
    G = Gates(gait + '.gait', every=os.environ.get('GATE_EVERY') == '1')
    design = Design(tab)
    tab.reset()
    opts = dict(RUNS[run])
    R = opts.pop('ramp', R0)  # applied by the controller in the run's time (gatelib.Table)
    if gait != 'gaits/obstacle':  # a gait of one's own defaults to earth: the scene's conditions
        opts.update(gait=gait + '.csv', conditions='paper')
    sim = crawlsim.Sim(scene='obstacle', data_dir='.', **opts)
    H = sim.macro_step
    lib = np.empty(96)

    def ctl(s, t, p):
        if tab.hold == 0.0 and not tab.holding and R == R0:
            p[:] = s.gait_command(t, out=lib)  # no wait yet: the library's table itself
        else:
            p[:] = tab.command(t, R)

    sim.set_controller(ctl)
    cl = np.empty((2, 3))
    pbuf = np.empty(96)
    gi, waited, waits = 0, 0.0, []
    rec, feet = [], []
    while sim.t < t_end - 1e-9:
        t = sim.t
        tab.advance(t)
        tab.holding = False
        pnow = sim.pressures(out=pbuf)
        while gi < len(G.g) and tab.tau(t) >= G.g[gi][0]:
            down = G.down(gi, pnow, tab.valve(), design, tab.tau(t), ptol)
            if down or waited >= G.maxwait - 1e-9:
                waits.append((G.g[gi][0], G.g[gi][1], waited, down))
                gi, waited = gi + 1, 0.0
            else:
                tab.holding = True
                break
        try:
            sim.step()
        except crawlsim.Error as e:
            print('%s: %s' % (run, e))
            break
        if tab.holding:
            tab.hold += H
            waited += H
        if abs(sim.t * 100 - round(sim.t * 100)) < 1e-6:
            pos, q = sim.support_pose()
            rec.append((sim.t, pos[0], pos[1], pos[2], q[0], q[1], q[2], q[3]))
            feet.append([sim.centerline(i, 2, out=cl)[1].copy() for i in range(8)])
        if rec and rec[-1][2] < -19:
            print('%s: fell at %.2f s' % (run, sim.t))
            break
    r = np.array(rec)
    t = r[:, 0]
    x, z = r[:, 5], r[:, 7]  # the quaternion's x, z (w, x, y, z in 4..7)
    tilt = np.degrees(np.arccos(np.clip(1 - 2 * (x * x + z * z), -1, 1)))
    row, worst, where = [], 0.0, ''
    for i, tn in enumerate(T3):
        if tn > t[-1] + 1e-9:
            row.append('%d:-' % tn)
            continue
        j = int(np.argmin(abs(t - tn)))
        row.append('%d:%.0f/%.0f/%.0f' % (tn, r[j, 1], r[j, 2], r[j, 3]))
        if tn >= 4:
            e = max(abs(r[j, 1] - X3[i]), abs(r[j, 2] - H3[i]), abs(r[j, 3] - Z3[i]))
            if e > worst:
                worst, where = e, '%d s' % tn
    d = np.hypot(r[-1, 1] - 646, r[-1, 3] - 270)
    nw = [w for w in waits if w[2] > 0]
    out = ['gate2%s %s (t_end %g s, PTOL %g MPa, MAXWAIT %g s): run to %.2f s, table time %.2f s,'
           ' held %.2f s over %d gates' % (' every chamber' if G.every else '', run, t_end, ptol, G.maxwait, t[-1],
                                           t[-1] - tab.hold, tab.hold, len(nw)),
           '  ' + ' '.join(row),
           '  worst node from 4 s %.1f mm (%s); end (%.1f, %.1f, %.1f) %.1f mm off; tilt max %.1f'
           ' deg' % (worst, where, r[-1, 1], r[-1, 2], r[-1, 3], d, tilt.max()),
           '  waits (table time, legs waited for, s, down): ' +
           '; '.join('%.2f %s %.3f%s' % (a, b, c, '' if dn else ' timeout')
                     for a, b, c, dn in nw)]
    tag = ('' if ptol == 0.005 else '_p%g' % ptol) + ('_every' if G.every else '') + (
        '' if gait == 'gaits/obstacle' else '_' + os.path.basename(gait))  # default untagged
    open(os.path.join(HERE, '%s_gate2%s.txt' % (run, tag)), 'w').write('\n'.join(out) + '\n')
    os.makedirs('runs', exist_ok=True)
    np.savez_compressed('runs/%s_gate2%s.npz' % (run, tag), rec=r, feet=np.array(feet),
                        hold=tab.hold)
    print('\n'.join(out))


main()

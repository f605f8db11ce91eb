#!/usr/bin/python3
"""One obstacle run with the feet's forces recorded (a diagnosis, not a score).

usage (source root, after the build): diag.py RUN T_END MODE [GAIT]
RUN: a set run (gate2.py's names: nominal, ramp0.5, m25g, ...); MODE: open (the library's table)
or gate (docs/bench/obst_2026-12-06e/gatelib.py's design-referenced gate, PTOL 0.005 MPa);
GAIT: NAME for NAME.csv / NAME.gait (default gaits/obstacle). Writes
/work/rom_data/obstfall/diag_RUN_MODE[_GAIT].npz: t, table time, support position (mm) and
quaternion, the feet (centrelines' ends, mm) and the terrain's force on each leg (N), every 0.01 s.
"""
import os
import sys

import numpy as np

ROOT = os.getcwd()
sys.path.insert(0, 'tools/python')
sys.path.insert(0, os.path.join(ROOT, 'docs/bench/obst_2026-12-06e'))
import crawlsim  # noqa: E402
from gatelib import R0, Design, Gates, Table  # noqa: E402

RUNS = {'nominal': {}, 'ramp0.1': {'ramp': 0.1}, 'ramp0.5': {'ramp': 0.5},
        'mu0.6': {'friction': 0.6}, 'mu1.0': {'friction': 1.0},
        'm25g': {'support_mass_kg': 0.025}, 'm75g': {'support_mass_kg': 0.075},
        'tau0.5x': {'tau': 0.01}, 'tau2x': {'tau': 0.04}, 'dt_half': {'dt': 0.0005}}


def main():
    run, t_end, mode = sys.argv[1], float(sys.argv[2]), sys.argv[3]
    gait = sys.argv[4] if len(sys.argv) > 4 else 'gaits/obstacle'
    opts = dict(RUNS[run])
    R = opts.pop('ramp', R0)
    if mode == 'open' and R != R0:
        opts['ramp'] = R
    if gait != 'gaits/obstacle':
        opts.update(gait=gait + '.csv', conditions='paper')
    sim = crawlsim.Sim(scene='obstacle', data_dir='.', **opts)
    tab = G = design = None
    if mode == 'gate':
        tab = Table(gait + '.csv')
        G = Gates(gait + '.gait')
        design = Design(tab)
        tab.reset()
        lib = np.empty(96)

        def ctl(s, t, p):
            if tab.hold == 0.0 and not tab.holding and R == R0:
                p[:] = s.gait_command(t, out=lib)
            else:
                p[:] = tab.command(t, R)
        sim.set_controller(ctl)
    H = sim.macro_step
    cl = np.empty((2, 3))
    fb = np.empty((8, 3))
    pbuf = np.empty(96)
    gi, waited = 0, 0.0
    rec, feet, frc = [], [], []
    while sim.t < t_end - 1e-9:
        t = sim.t
        if tab is not None:
            tab.advance(t)
            tab.holding = False
            pnow = sim.pressures(out=pbuf)
            while gi < len(G.g) and tab.tau(t) >= G.g[gi][0]:
                if G.down(gi, pnow, tab.valve(), design, tab.tau(t), 0.005) or \
                        waited >= G.maxwait - 1e-9:
                    gi, waited = gi + 1, 0.0
                else:
                    tab.holding = True
                    break
        try:
            sim.step()
        except crawlsim.Error as e:
            print('%s: %s' % (run, e))
            break
        if tab is not None and tab.holding:
            tab.hold += H
            waited += H
        if abs(sim.t * 100 - round(sim.t * 100)) < 1e-6:
            pos, q = sim.support_pose()
            rec.append((sim.t, sim.t - (tab.hold if tab else 0.0), pos[0], pos[1], pos[2],
                        q[0], q[1], q[2], q[3]))
            feet.append([sim.centerline(i, 2, out=cl)[1].copy() for i in range(8)])
            frc.append(sim.foot_forces(out=fb).copy())
        if rec and rec[-1][3] < -19:
            print('%s: fell at %.2f s' % (run, sim.t))
            break
    tag = '' if gait == 'gaits/obstacle' else '_' + os.path.basename(gait)
    out = '/work/rom_data/obstfall/diag_%s_%s%s.npz' % (run, mode, tag)
    np.savez_compressed(out, rec=np.array(rec), feet=np.array(feet), frc=np.array(frc))
    print(out, 'to %.2f s' % rec[-1][0])


main()

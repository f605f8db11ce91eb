#!/usr/bin/python3
"""The design-referenced pressure gate's waits from the pneumatics alone (no mechanics).

usage (from the source root): /usr/bin/python3 pneu.py [PTOL_MPa ...]
The chambers follow dp/dt = (p_cmd - p)/tau (core/sim_model.h) whatever the legs do, so the
gate's waits (gate.py with GATE_SENSOR=design) depend on the run's actuation time R and lag tau
only. For each of the set's actuation conditions this integrates the gated schedule (the
table's clock held while a gate waits, the chambers filling on) and prints the number of gates
that wait and the total hold. A run whose gates never wait plays the table unchanged.
"""
import os
import sys

import numpy as np

sys.path.insert(0, 'docs/bench/obst_2026-12-06e')
from gatelib import Design, Gates, Table  # noqa: E402

H = 1e-3  # s: the macro step (the gate reads between steps)
CONDS = {'nominal': (0.05, 0.02), 'ramp0.1': (0.1, 0.02), 'ramp0.5': (0.5, 0.02),
         'tau0.5x': (0.05, 0.01), 'tau2x': (0.05, 0.04), 'dt_half': (0.05, 0.02)}


def run(tab, gates, design, R, tau, ptol, t_end=36.0, h=H):
    tab.reset()
    p = np.zeros(96)
    a = np.exp(-h / tau)
    t, waits = 0.0, []
    gi, waited = 0, 0.0
    c0 = tab.command(0.0, R)
    while t < t_end - 1e-9:
        tab.advance(t)
        holding = False
        while gi < len(gates.g) and tab.tau(t) >= gates.g[gi][0]:
            down = gates.down(gi, p, tab.valve(), design, tab.tau(t), ptol)
            if down or waited >= gates.maxwait - 1e-9:
                if waited > 0:
                    waits.append((gates.g[gi][0], gates.g[gi][1], waited, down))
                gi, waited = gi + 1, 0.0
            else:
                holding = True
                break
        tab.holding = holding
        c1 = tab.command(t + h, R)
        s = (c1 - c0) / h
        p = c1 + (p - c0) * a - s * tau * (1 - a)
        c0 = c1
        t += h
        if holding:
            tab.hold += h
            waited += h
    return waits


def main():
    ptols = [float(v) for v in sys.argv[1:]] or [0.005]
    tab = Table('gaits/obstacle.csv')
    gates = Gates('gaits/obstacle.gait', every=os.environ.get('GATE_EVERY') == '1')
    design = Design(tab)
    for ptol in ptols:
        for name, (R, tau) in CONDS.items():
            h = 5e-4 if name == 'dt_half' else H
            w = run(tab, gates, design, R, tau, ptol, h=h)
            print('%sPTOL %.3f %-8s R %.2f tau %.2f: %2d gates wait, held %.3f s%s' % (
                'every chamber, ' if gates.every else '', ptol, name, R, tau, len(w), sum(x[2] for x in w),
                ('; max %.3f s, %d timeouts' % (max(x[2] for x in w),
                                               sum(1 for x in w if not x[3]))) if w else ''))


if __name__ == '__main__':
    main()

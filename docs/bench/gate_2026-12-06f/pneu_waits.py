#!/usr/bin/python3
"""The landing gate's waits under the pneumatic lag x2 from the prototype's model alone
(docs/bench/obst_2026-12-06e/pneu.py: the gated schedule integrated without the mechanics,
gatelib.py's gates and design), as the table test_gate reads (tests/core/data/gate_tau2x_waits.txt):

  /usr/bin/python3 docs/bench/gate_2026-12-06f/pneu_waits.py > tests/core/data/gate_tau2x_waits.txt

One line per gate that waits before T_END (default 4.3 s): table time, legs waited for, wait (s).
The library's gate (core/sim_gate.c) is a second implementation of the same rule in C; the
test compares its waits with these."""
import sys

sys.path.insert(0, 'docs/bench/obst_2026-12-06e')
from gatelib import Design, Gates, Table  # noqa: E402
from pneu import run  # noqa: E402

t_end = float(sys.argv[1]) if len(sys.argv) > 1 else 4.3
tab = Table('gaits/obstacle.csv')
gates = Gates('gaits/obstacle.gait')
design = Design(tab)
w = run(tab, gates, design, 0.05, 0.04, 0.005, t_end=t_end)
print('# the landing gate\'s waits, obstacle scene, lag 0.04 s (x2), ramp 0.05 s, PTOL 0.005 MPa,')
print('# to %g s, from docs/bench/obst_2026-12-06e/pneu.py\'s model (written by' % t_end)
print('# docs/bench/gate_2026-12-06f/pneu_waits.py): table time (s), legs waited for, wait (s)')
for T, legs, wait, down in w:
    print('%.4f %s %.4f' % (T, legs, wait))

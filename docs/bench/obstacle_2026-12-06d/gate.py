#!/usr/bin/python3
"""A prototype, not shipped: the wave's next pair lifts only once the previous pair's feet are
down (a sensing controller over the shipped table, through the library's controller API).

usage (from the source root, after the build): /usr/bin/python3 gate.py RUN [T_END]
RUN: a robustness run of issue 33's set (nominal, ramp0.5, m25g, ...). Writes RUN_gate.txt
here: Table 3's nodes as table3.py prints them, the waits, the end. GATE_GAIT=NAME plays
NAME.csv with the gates of NAME.gait (default gaits/obstacle) into RUN_gate_BASENAME.txt.
GATE_SENSOR=pressure: down is instead every chamber of the pair within PTOL of its valve's
command (the table's last issued row), a pressure sensor's reading (RUN_gate_pressure.txt).

The gates: every lift of a pair in the wave (a `move` of two legs to an AM* or U0 pose in
gaits/obstacle.gait) waits until both feet of the last other pair that lifted before it are
down, at most MAXWAIT s. Down: the foot (the centreline's end) within 2.5 mm of a terrain level
(0 or 40 mm) and moving up or down at less than 20 mm/s over the last 10 ms, read between
steps. While a gate holds, the table's clock stops (the command of the whole table holds: the
stance legs stop pushing), so the run lasts longer by the waits. The controller plays
gaits/obstacle.csv itself: each row's change is issued when the table's clock (t minus the
holds so far) reaches it and takes the actuation time R to arrive (gaits_schedule.h's sum,
smoothstep; R the run's --ramp, else the gait's 0.05 s), so a hold stops the valves' new
commands but not the chambers' filling; the library is created without --ramp. `gate.py RUN 3
check` compares the command with the library's table at R (7.6e-15 MPa at 0.05 s, 2.2e-16 at
0.5 s). The clock's state changes only between steps, so a retried step sees the same command.
Not the library's player: no restore of the gates' state, no HDF5; the track is sampled every
0.01 s from the read-outs."""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, 'tools/python')
import crawlsim  # noqa: E402

MAXWAIT = 0.6  # s: one walk slot (Tp)
SENSOR = os.environ.get('GATE_SENSOR', 'feet')  # feet | pressure
PTOL = 0.02    # MPa: with GATE_SENSOR=pressure, a chamber has arrived within this of its command
RUNS = {'nominal': {}, 'ramp0.1': {'ramp': 0.1}, 'ramp0.5': {'ramp': 0.5},
        'mu0.6': {'friction': 0.6}, 'mu1.0': {'friction': 1.0},
        'm25g': {'support_mass_kg': 0.025}, 'm75g': {'support_mass_kg': 0.075},
        'tau0.5x': {'tau': 0.01}, 'tau2x': {'tau': 0.04}, 'dt_half': {'dt': 0.0005}}
T3 = [0, 1, 2, 3, 4, 5, 7, 11, 12, 14, 24, 29, 32]
X3 = [0, 0, 0, 0, 26, 26, 52, 130, 170, 230, 492, 646, 646]
H3 = [0, 50, 50, 13, 22, 48, 20, 50, 40, 40, 13, 0, 0]
Z3 = [0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 90, 270]


def gates(gait):
    lifts = []
    for line in open(gait):
        p = line.split()
        if len(p) >= 5 and p[0] == 'move' and len(p[3]) == 2 and (p[4].startswith('AM') or
                                                                   p[4] == 'U0'):
            lifts.append((float(p[1]), p[3]))
    lifts.sort()
    out = []
    for i in range(1, len(lifts)):
        prev = [q for _, q in lifts[:i] if q != lifts[i][1]]
        if prev:  # the last pair other than the lifting one (its own earlier move is no gate)
            out.append((lifts[i][0], prev[-1]))
    return out


def smooth(u):
    u = np.clip(u, 0.0, 1.0)
    return u * u * (3 - 2 * u)


def main():
    run = sys.argv[1]
    t_end = float(sys.argv[2]) if len(sys.argv) > 2 else 45.0
    GAIT = os.environ.get('GATE_GAIT', 'gaits/obstacle')  # NAME: NAME.gait and NAME.csv
    tag = '' if GAIT == 'gaits/obstacle' else '_' + os.path.basename(GAIT)
    tag += '' if SENSOR == 'feet' else '_' + SENSOR
    G = gates(GAIT + '.gait')
    # the table's rows; the actuation time R is applied here, in the run's time, so that a
    # held clock holds the valves' commands but not the chambers' filling (the library's
    # schedule applies its ramp in the table's time: a controller that warped that would
    # freeze the filling too)
    lines = [ln for ln in open(GAIT + '.csv') if ln.strip() and not ln.startswith('#')]
    rows = np.array([[float(v) for v in ln.split(',')] for ln in lines[1:]])
    trow, P = rows[:, 0], rows[:, 1:]
    dP = np.diff(np.vstack([np.zeros(96), P]), axis=0)
    opts = dict(RUNS[run])
    R = opts.pop('ramp', 0.05)  # the gait's own @ramp by default
    if GAIT != 'gaits/obstacle':  # a gait of one's own defaults to earth: the scene's conditions
        opts.update(gait=GAIT + '.csv', conditions='paper')
    sim = crawlsim.Sim(scene='obstacle', data_dir='.', **opts)
    H = sim.macro_step
    off = np.full(len(trow), np.nan)  # each row's issue time minus its table time (the hold then)
    st = {'tn': 0.0, 'hold': 0.0, 'holding': False, 'issued': 0}

    def command(t):
        # rows issued by t: those recorded, and (the clock running) those whose table time
        # t - hold has passed; p = the last arrived row plus the running changes through the
        # ramp (gaits_schedule.h's sum, rows issued in order, each after the one before)
        hold = st['hold']
        k = st['issued']
        if not st['holding']:
            k = max(k, int(np.searchsorted(trow, t - hold + 1e-12, 'right')))
        lo = max(0, int(np.searchsorted(trow, t - R - hold, 'right')) - 1)
        o = off[lo:k].copy()
        o[np.isnan(o)] = hold
        sdue = trow[lo:k] + o
        j = lo + int(np.searchsorted(sdue, t - R, 'right')) - 1  # rows <= j have arrived
        base = P[j] if j >= 0 else np.zeros(96)
        if j + 1 >= k:
            return base
        u = (t - sdue[j + 1 - lo:]) / R
        return np.clip(base + smooth(u) @ dP[j + 1:k], 0.0, 1.0)  # round-off: -6e-17

    def ctl(s, t, p):
        p[:] = command(t)

    if len(sys.argv) > 3 and sys.argv[3] == 'check':
        # the controller's command against the library's table at the gait's own ramp
        ref = crawlsim.Sim(scene='obstacle', data_dir='.', ramp=R) if R != 0.05 else sim
        worst = max(np.abs(command(t) - ref.gait_command(t)).max()
                    for t in np.arange(0, 34, 0.0137))
        print('command vs the library table (ramp %g): max |dp| %.3g MPa' % (R, worst))
        return

    sim.set_controller(ctl)
    legs = 'ABCDEFGH'
    cl = np.empty((2, 3))
    pbuf = np.empty(96)
    NV = int(round(0.01 / H))  # the feet's speed over the last 10 ms (a step's is contact noise)
    ring = np.zeros((NV, 8))
    k, waited, waits = 0, 0.0, []
    rec, feet = [], []
    n = 0
    while sim.t < t_end - 1e-9:
        t = sim.t
        y = np.array([sim.centerline(i, 2, out=cl)[1, 1] for i in range(8)])
        vy = (y - ring[n % NV]) / (NV * H) if n >= NV else np.full(8, np.inf)
        ring[n % NV] = y
        n += 1
        tau = t - st['hold']
        k_new = int(np.searchsorted(trow, tau + 1e-12, 'right'))
        off[st['issued']:k_new] = st['hold']
        st['issued'] = max(st['issued'], k_new)
        st['tn'], st['holding'] = t, False
        if SENSOR == 'pressure':
            pnow = sim.pressures(out=pbuf)
            valve = P[st['issued'] - 1] if st['issued'] else np.zeros(96)
        while k < len(G) and tau >= G[k][0]:
            if SENSOR == 'pressure':  # every chamber of the pair within PTOL of its valve's command
                down = all(np.abs(pnow[12 * legs.index(c):12 * legs.index(c) + 12] -
                                  valve[12 * legs.index(c):12 * legs.index(c) + 12]).max() < PTOL
                           for c in G[k][1])
            else:
                down = all((abs(y[legs.index(c)]) < 2.5 or abs(y[legs.index(c)] - 40) < 2.5) and
                           abs(vy[legs.index(c)]) < 20 for c in G[k][1])
            if down or waited >= MAXWAIT - 1e-9:
                waits.append((G[k][0], G[k][1], waited, down))
                k, waited = k + 1, 0.0
            else:
                st['holding'] = True
                break
        try:
            sim.step()
        except crawlsim.Error as e:
            print('%s: %s' % (run, e))
            break
        if st['holding']:
            st['hold'] += H
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
    # the end: the run's last sample (t_end, or the fall)
    out = ['gate%s %s (t_end %g s, MAXWAIT %g s): run to %.2f s, table time %.2f s, held %.2f s'
           % (tag, run, t_end, MAXWAIT, t[-1], t[-1] - st['hold'], st['hold']),
           '  ' + ' '.join(row),
           '  worst node from 4 s %.1f mm (%s); end (%.1f, %.1f, %.1f) %.1f mm off; tilt max %.1f'
           ' deg' % (worst, where, r[-1, 1], r[-1, 2], r[-1, 3], d, tilt.max()),
           '  waits (table time, legs waited for, s, down): ' +
           '; '.join('%.2f %s %.2f%s' % (a, b, c, '' if dn else ' timeout')
                     for a, b, c, dn in waits if c > 0)]  # the waits above zero
    open(os.path.join(HERE, '%s_gate%s.txt' % (run, tag)), 'w').write('\n'.join(out) + '\n')
    # the track and the feet every 0.01 s, for a look at a fall (runs/ is not kept)
    os.makedirs('runs', exist_ok=True)
    np.savez_compressed('runs/%s_gate%s.npz' % (run, tag), rec=r, feet=np.array(feet),
                        hold=st['hold'])
    print('\n'.join(out))


main()

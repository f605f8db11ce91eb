"""The landing gate's parts, shared by gate2.py (the run) and pneu.py (the pneumatics alone).

Table: the gait table played with a clock that a gate can hold (each row issued when the
table's clock, t minus the holds so far, reaches it; each row's change arrives through the
actuation time R as gaits_schedule.h's smoothstep sum, in the run's time, so a hold stops the
valves' new commands but not the chambers' filling). This is gate.py's command() of
docs/bench/obstacle_2026-12-06d, copied here as a class (that record is left as it was).
Gates: every lift of a pair in the wave waits for the last other pair that lifted (gate.py).
Design: the chamber pressures the design assumes, the table played on time through the gait's
own actuation time (its @ramp, 0.05 s) and the nominal lag (0.02 s), dp/dt = (p_cmd - p)/tau.
The design gate: a pair is down when every chamber of it is at least as near its valve's
command as the design has it at that table time, within PTOL (the pressure sensor's accuracy):
|v - p| <= |v - p_design(tau)| + PTOL. It waits only when the valves are slower than designed.
Gates(every=True): the same test over every chamber of the eight legs (the stance legs' strokes
too), GATE_EVERY=1 in gate2.py and pneu.py.
"""
import numpy as np

R0, TAU0 = 0.05, 0.02  # s: the design's actuation time (the table's @ramp) and pneumatic lag
LEGS = 'ABCDEFGH'


def smooth(u):
    u = np.clip(u, 0.0, 1.0)
    return u * u * (3 - 2 * u)


class Table:
    def __init__(self, csv):
        lines = [ln for ln in open(csv) if ln.strip() and not ln.startswith('#')]
        rows = np.array([[float(v) for v in ln.split(',')] for ln in lines[1:]])
        self.trow, self.P = rows[:, 0], rows[:, 1:]
        self.dP = np.diff(np.vstack([np.zeros(self.P.shape[1]), self.P]), axis=0)
        self.reset()

    def reset(self):
        self.hold, self.holding, self.issued = 0.0, False, 0
        self.off = np.full(len(self.trow), np.nan)  # each row's issue time minus its table time

    def tau(self, t):
        return t - self.hold

    def advance(self, t):
        """Between steps: the rows whose table time has come are issued at the hold so far."""
        k = int(np.searchsorted(self.trow, t - self.hold + 1e-12, 'right'))
        self.off[self.issued:k] = self.hold
        self.issued = max(self.issued, k)

    def valve(self):
        return self.P[self.issued - 1] if self.issued else np.zeros(self.P.shape[1])

    def command(self, t, R):
        hold, k = self.hold, self.issued
        if not self.holding:
            k = max(k, int(np.searchsorted(self.trow, t - hold + 1e-12, 'right')))
        lo = max(0, int(np.searchsorted(self.trow, t - R - hold, 'right')) - 1)
        o = self.off[lo:k].copy()
        o[np.isnan(o)] = hold
        sdue = self.trow[lo:k] + o
        j = lo + int(np.searchsorted(sdue, t - R, 'right')) - 1  # rows <= j have arrived
        base = self.P[j] if j >= 0 else np.zeros(self.P.shape[1])
        if j + 1 >= k:
            return base
        u = (t - sdue[j + 1 - lo:]) / R
        return np.clip(base + smooth(u) @ self.dP[j + 1:k], 0.0, 1.0)


class Gates:
    maxwait = 0.6  # s: one walk slot (Tp)

    def __init__(self, gait, every=False):
        self.every = every  # True: a gate waits for every chamber (all eight legs), not the pair's
        lifts = []
        for line in open(gait):
            p = line.split()
            if len(p) >= 5 and p[0] == 'move' and len(p[3]) == 2 and (
                    p[4].startswith('AM') or p[4] == 'U0'):
                lifts.append((float(p[1]), p[3]))
        lifts.sort()
        self.g = []
        for i in range(1, len(lifts)):
            prev = [q for _, q in lifts[:i] if q != lifts[i][1]]
            if prev:
                self.g.append((lifts[i][0], prev[-1]))

    def down(self, gi, p, valve, design, tau, ptol):
        pd = design.at(tau)
        for c in (LEGS if self.every else self.g[gi][1]):
            s = slice(12 * LEGS.index(c), 12 * LEGS.index(c) + 12)
            if np.any(np.abs(valve[s] - p[s]) > np.abs(valve[s] - pd[s]) + ptol):
                return False
        return True


class Design:
    """p_design(tau) on a 0.5 ms grid: the table on time, R0 and TAU0, exact for a command
    linear over each sub-step."""

    def __init__(self, tab, t_end=40.0, h=5e-4):
        tab.reset()
        n = int(round(t_end / h))
        self.h = h
        self.p = np.zeros((n + 1, tab.P.shape[1]))
        a = np.exp(-h / TAU0)
        c0 = tab.command(0.0, R0)
        p = np.zeros(tab.P.shape[1])
        for i in range(n):
            c1 = tab.command((i + 1) * h, R0)
            p = c1 + (p - c0) * a - (c1 - c0) / h * TAU0 * (1 - a)
            c0 = c1
            self.p[i + 1] = p

    def at(self, tau):
        x = tau / self.h
        i = min(int(x), len(self.p) - 2)
        f = x - i
        return self.p[i] * (1 - f) + self.p[i + 1] * f

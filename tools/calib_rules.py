#!/usr/bin/python3
"""Prototype base rules of the calibration model (robot/calibration/robot_calibration_model.c) and score them
as `crawlsim calibrate --report` does.

For each rule it prints: per held-out case (H1-H7 of the shipped table and H8 of
docs/bench/calibration_cases_2026-12-02b) the worst bend error (deg, per segment, over the whole
sweep), the worst tip error (mm, constant-curvature kinematics of the model's segments against
the FE tip; for a mirror-symmetric pattern also against the FE's symmetric part), the target
scores and the pressure up to which every row meets the target (bend within 5 % or 1 deg, tip
within 2 % of the 166 mm leg); then the refining modes left out of the fit one at a time (each
predicted by the model built without it: bend deg / tip mm), exactly as csr_calModelCompare and
csr_calReportPrint define them.

Rules (each a base plus the fitted modes' residuals over it; the residual is interpolated
along p by each mode's monotone cubic, so every rule returns every fitted row):
  sup         the shipped default: single-chamber superposition + residuals over the canonical
              shape prism with hierarchical hats (CSR_CAL_RULE_SUPERPOSITION; reproduces
              `crawlsim calibrate --report` to the printed digits)
  interp      no base, the modes' values over the prism (CSR_CAL_RULE_INTERPOLATION)
  moment      pressure-moment base: bend along -m̂ with magnitude a(|m|, p̄) and stretch
              d(|m|, p̄) piecewise linear over the modes' rows, + prism hats
  rbf         superposition + residuals by a Gaussian RBF (width RBF_WIDTH in x = p / P) over
              the symmetric images of the modes' shapes (CSR_CAL_RULE_RBF)
  rbf-r3      the same with the cubic kernel r^3 and a linear polynomial part
  rbf-interp  the Gaussian RBF without a base
  rbf-moment  the Gaussian RBF over the pressure-moment base
  rbf-pair    the Gaussian RBF over the superposition with a factor per opposite chamber pair,
              exp(k0 n + k1 l + k2 n^2 + k3 l^2) (n the other pair's pressure sum, l the pair's
              lower pressure) fitted to the bending modes (CSR_CAL_RULE_RBF_PAIR)
(the superposition scaled by a mean-pressure factor is CSR_CAL_RULE_SCALED: its numbers are in
`crawlsim calibrate --report`'s "rules compared")
--extra adds case files to the table: by default H8; add
docs/bench/calibration_cases_2026-12-02/*.h5 for the 12-mode table.

Usage: /usr/bin/python3 tools/calib_rules.py [--table T.h5] [--extra F.h5 ...] [--rules a,b]
Reads only HDF5 files; runs no FE.
"""
import argparse
import math
import sys

import h5py
import numpy as np
from scipy.interpolate import PchipInterpolator

RSQ2 = math.sqrt(0.5)
DEG = math.pi / 180


# ---- table --------------------------------------------------------------------------------------

class Case:
    pass


def unwrap(bend):
    """csr table reader's unwrapBends: continue a bend past pi along the sweep"""
    b = bend.copy()
    for s in range(3):
        prev = b[0, s].copy()
        for i in range(1, b.shape[0]):
            v = b[i, s].copy()
            r = math.hypot(*v)
            best, dbest = v.copy(), math.hypot(*(v - prev))
            for k in range(-2, 3):
                if r <= 0:
                    break
                f = 1 + 2 * math.pi * k / r
                d = math.hypot(*(f * v - prev))
                if d < dbest:
                    dbest, best = d, f * v
            b[i, s] = best
            prev = best
    return b


def load(paths):
    cases, leg = {}, None
    for path in paths:
        with h5py.File(path, "r") as f:
            if leg is None:
                a = f.attrs
                leg = dict(S=[a["S1"], a["S2"], a["S3"]], LS=[a["LS12"], a["LS23"]])
            for name, g in f["cases"].items():
                c = Case()
                c.name = name
                c.kind = g.attrs["kind"].decode() if isinstance(g.attrs["kind"], bytes) else g.attrs["kind"]
                c.ratio = np.array([g.attrs["ratio%d" % k] for k in range(1, 5)], float)
                c.p = g["pressure"][()]
                c.bend = unwrap(g["bend"][()])
                c.stretch = g["stretch"][()]
                c.radial = g["radial"][()]
                c.tip = g["tip"][()]
                cases[name] = c
    return cases, leg


# ---- kinematics (csr_ccForwardKinematics) --------------------------------------------------------

def arc_pose(s, lam, kap):
    w1, w2 = s * kap[1], -s * kap[0]
    al = math.hypot(w1, w2)
    if al < 1e-4:
        a2 = al * al
        A = 1 - a2 / 6 + a2 * a2 / 120
        B = 0.5 - a2 / 24 + a2 * a2 / 720
    else:
        sh = math.sin(0.5 * al) / al
        A, B = math.sin(al) / al, 2 * sh * sh
    L = lam * s
    pos = np.array([-L * s * B * kap[0], -L * s * B * kap[1], L * A])
    R = np.array([[1 - B * w2 * w2, B * w1 * w2, A * w2],
                  [B * w1 * w2, 1 - B * w1 * w1, -A * w1],
                  [-A * w2, A * w1, 1 - B * (w1 * w1 + w2 * w2)]])
    return pos, R


def tip_of(leg, bends, stretches):
    """bends (3,2) rad, stretches (3,): the tip (mm) with kappa = -bend / S"""
    pos, R = np.zeros(3), np.eye(3)
    for i in range(3):
        S = leg["S"][i]
        pl, Rl = arc_pose(S, stretches[i], -np.asarray(bends[i]) / S)
        pos = pos + R @ pl
        R = R @ Rl
        if i < 2:
            pos = pos + R[:, 2] * leg["LS"][i]
    return pos


# ---- the model (robot_calibration_model.c / _build.c) -------------------------------------------

ROLES = {  # role name -> chamber ratios (fem_calibration.c's case list)
    "O1": (1, 0, 0, 0), "O13": (1, 0, 1, 0), "O12": (1, 1, 0, 0), "O124": (1, 1, 0, 1),
    "O1234": (1, 1, 1, 1), "O12r05": (1, .5, 0, 0), "O12O34r3": (1, 1, 1 / 3, 1 / 3),
    "O1O234r05": (1, .5, .5, .5), "O1O234r075": (1, .75, .75, .75), "O124O3r05": (1, 1, .5, 1),
    "O1O23r05O4r025": (1, .5, .5, .25), "O1O3r05": (1, 0, .5, 0),
    # the remaining edge midpoints of the prism (2026-12-03; the RBF rules' nodes only)
    "O12O4r05": (1, 1, 0, .5), "O1O24r05": (1, .5, 0, .5), "O13O2r05": (1, .5, 1, 0),
    # and its face centres
    "O1O2r067O4r033": (1, 2 / 3, 0, 1 / 3), "O13O2r067O4r033": (1, 2 / 3, 1, 1 / 3),
    "O1O23r05": (1, .5, .5, 0), "O12O34r05": (1, 1, .5, .5)}
CORNERS = ["O1", "O13", "O12", "O124", "O1234"]
REFINING = ["O12r05", "O12O34r3", "O1O234r05", "O1O234r075", "O124O3r05", "O1O23r05O4r025",
            "O1O3r05"]
# vertices coarse to fine: (name, role, mirror)
VERTS = [("O1", "O1", 0), ("O13", "O13", 0), ("O12", "O12", 0), ("O124", "O124", 0),
         ("O124M", "O124", 1), ("O1234", "O1234", 0), ("R05", "O12r05", 0),
         ("E13", "O1O3r05", 0), ("E124", "O124O3r05", 0), ("E124M", "O124O3r05", 1),
         ("R3", "O12O34r3", 0), ("F05", "O1O234r05", 0), ("F075", "O1O234r075", 0),
         ("C", "O1O23r05O4r025", 0)]


def moment(p):
    return np.array([(p[0] + p[1]) - (p[2] + p[3]), (p[0] + p[3]) - (p[1] + p[2])])


def mirror_sym(r):
    return (r[0] == r[1] and r[2] == r[3]) or (r[0] == r[3] and r[1] == r[2]) or r[1] == r[3] \
        or r[0] == r[2]


def canonical(p):
    j = int(np.argmax(p))
    pc = np.array([p[(i + j) % 4] for i in range(4)], float)
    mir = pc[1] < pc[3]
    if mir:
        pc[1], pc[3] = pc[3], pc[1]
    return pc, j, mir


def from_canonical(bc, k, mir):
    x, y = (bc[1], bc[0]) if mir else (bc[0], bc[1])
    for _ in range(k):
        x, y = y, -x
    return np.array([x, y])


def find_case(cases, ratio, kind="mode"):
    for c in cases.values():
        if c.kind == kind and np.all(np.abs(c.ratio - np.array(ratio)) < 1e-12):
            return c
    return None


class Curve:
    """monotone cubic (Fritsch-Carlson, scipy's PCHIP as the C curves) of y (m x ...) over p,
    clamped to the rows"""

    def __init__(self, p, y):
        self.p0, self.p1 = p[0], p[-1]
        self.f = PchipInterpolator(p, y, axis=0)

    def __call__(self, p):
        return self.f(min(max(p, self.p0), self.p1))


def hat(x, c):
    return x / c if x <= c else (1 - x) / (1 - c)


def hat_on(x, lo, c):
    return 0.0 if x <= lo else (x - lo) / (c - lo) if x <= c else (1 - x) / (1 - c)


class Model:
    """base (a class: base(modes, leg) with .bend(s, pc) -> canonical bend (2,) rad and
    .stretch(s, pc) -> change of stretch) + the modes' residuals over the prism"""

    def __init__(self, cases, leg, base, exclude=()):
        self.leg = leg
        self.modes = {r: find_case(cases, ROLES[r]) for r in ROLES}
        for r in list(self.modes):
            if self.modes[r] is None or (r in exclude and r not in CORNERS):
                del self.modes[r]
        self.p_max = min(c.p[-1] for c in self.modes.values())
        self.base = base(self.modes, leg)
        self.use, self.coord, self.field = {}, {}, {}
        for vname, role, mir in VERTS:
            c = self.modes.get(role)
            self.use[vname] = c is not None
            if c is None:
                continue
            r = c.ratio.copy()
            if mir:
                r = np.array([r[1], r[0], r[3], r[2]])
            self.coord[vname] = (r[1], r[3] / r[1] if r[1] > 0 else 0.0, r[2])
            self.field[vname] = self._build_field(vname, c, mir, r)

    def weights(self, x2, w, x3):
        W = {"O1": (1 - x2) * (1 - x3), "O13": (1 - x2) * x3, "O12": x2 * (1 - w) * (1 - x3),
             "O124": x2 * w * (1 - x3), "O124M": x2 * (1 - w) * x3, "O1234": x2 * w * x3}
        u = {v[0]: self.use.get(v[0], False) for v in VERTS}
        c = self.coord
        W["R05"] = hat(x2, c["R05"][0]) * (1 - w) * (1 - x3) if u["R05"] else 0
        W["E13"] = (1 - x2) * hat(x3, c["E13"][2]) if u["E13"] else 0
        W["E124"] = x2 * w * hat(x3, c["E124"][2]) if u["E124"] else 0
        W["E124M"] = x2 * hat(w, c["E124M"][1]) * x3 if u["E124M"] else 0
        W["R3"] = x2 * hat(w, c["R3"][1]) * hat(x3, c["R3"][2]) if u["R3"] else 0
        W["F05"] = hat(x2, c["F05"][0]) * w * hat(x3, c["F05"][2]) if u["F05"] else 0
        lo = c["F05"][0] if u["F05"] else 0
        W["F075"] = hat_on(x2, lo, c["F075"][0]) * w * hat_on(x3, lo, c["F075"][2]) \
            if u["F075"] else 0
        W["C"] = hat(x2, c["C"][0]) * hat(w, c["C"][1]) * hat(x3, c["C"][2]) if u["C"] else 0
        return W

    def _build_field(self, vname, c, mir, r):
        n = 1
        while n < len(c.p) and c.p[n - 1] < self.p_max - 1e-12:
            n += 1
        mv = moment(r)
        mn = math.hypot(*mv)
        u = mv / mn if mn > 0 else np.zeros(2)
        sym = mirror_sym(r)
        W = self.weights(*self.coord[vname])
        order = [v[0] for v in VERTS]
        lower = order[:order.index(vname)] if order.index(vname) >= 6 else []
        y = np.zeros((n, 3, 3))  # a, b, dstretch
        for i in range(n):
            p = c.p[i]
            for s in range(3):
                b = c.bend[i, s] - c.bend[0, s]
                if mir:
                    b = np.array([b[0], -b[1]])
                a_ = -(b @ u)
                b_ = 0.0 if sym else -b[0] * u[1] + b[1] * u[0]
                if mn == 0:
                    a_ = b_ = 0.0
                st = c.stretch[i, s] - c.stretch[0, s]
                if p > 0:
                    pc = r * p
                    bb = self.base.bend(s, pc)
                    if mn > 0:
                        a_ -= -(bb @ u)
                        if not sym:
                            b_ -= -bb[0] * u[1] + bb[1] * u[0]
                    st -= self.base.stretch(s, pc)
                yv = np.array([a_, b_, st])
                for uu in lower:
                    if W[uu] != 0 and self.use[uu]:
                        yv = yv - W[uu] * self.field[uu](p)[s]
                y[i, s] = yv
        return Curve(c.p[:n], y)

    def eval(self, s, p):
        """bend (2,) rad and stretch of segment s at chamber pressures p"""
        p = np.maximum(np.asarray(p, float), 0)
        if p.max() == 0:
            return np.zeros(2), 1.0
        pc, k, mir = canonical(p)
        pc[0] = min(pc[0], self.p_max)
        P = pc[0]
        x2, x3, x4 = pc[1] / P, pc[2] / P, pc[3] / P
        w = x4 / x2 if x2 > 0 else 0.0
        W = self.weights(x2, w, x3)
        f = np.zeros(3)
        for v, wv in W.items():
            if wv != 0 and self.use[v]:
                f += wv * self.field[v](P)[s]
        bend = np.array(self.base.bend(s, pc), float)
        st = 1 + f[2] + self.base.stretch(s, pc)
        mv = moment(pc)
        mn = math.hypot(*mv)
        if mn > 0:
            u0, u1 = mv / mn
            bend = bend + np.array([-f[0] * u0 - f[1] * u1, -f[0] * u1 + f[1] * u0])
        return from_canonical(bend, k, mir), st


# ---- comparison (csr_calModelCompare) -----------------------------------------------------------

def compare(model, c, leg):
    L = sum(leg["S"]) + sum(leg["LS"])
    mirror = mirror_sym(c.ratio)
    mv = moment(c.ratio)
    mn = math.hypot(*mv)
    u = mv / mn if mn > 0 else np.zeros(2)
    out = dict(bend=0.0, tip=0.0, tip_sym=0.0, bscore=0.0, tscore=0.0, p_meets=0.0, p_last=0.0,
               mirror=mirror, bend_at=0.0, rows=[])
    meets = True
    for i in range(len(c.p)):
        p = c.p[i]
        if p > model.p_max + 1e-12:
            break
        rb = rbs = 0.0
        bm, sm, bs_, sf = [], [], [], []
        for s in range(3):
            b, st = model.eval(s, c.ratio * p)
            bf = c.bend[i, s]
            d = math.hypot(*(b - bf))
            sc = d / max(0.05 * math.hypot(*bf), DEG)
            if d / DEG > out["bend"]:
                out["bend"], out["bend_at"] = d / DEG, p
            out["bscore"] = max(out["bscore"], sc)
            rb = max(rb, sc)
            along = bf @ u
            bsym = along * u if mirror else bf
            rbs = max(rbs, math.hypot(*(b - bsym)) / max(0.05 * math.hypot(*bsym), DEG))
            bm.append(b), sm.append(st), bs_.append(bsym), sf.append(c.stretch[i, s])
        tm = tip_of(leg, bm, sm)
        tf = tip_of(leg, [c.bend[i, s] for s in range(3)], sf)
        ts = tip_of(leg, bs_, sf)
        dt = tm - c.tip[i]
        dsym = dt - (ts - tf)
        e, es = np.linalg.norm(dt), np.linalg.norm(dsym)
        out["tip"] = max(out["tip"], e)
        out["tip_sym"] = max(out["tip_sym"], es)
        out["tscore"] = max(out["tscore"], e / (0.02 * L))
        rt, rs = e / (0.02 * L), es / (0.02 * L)
        meets = meets and ((rb <= 1 and rt <= 1) or (mirror and rbs <= 1 and rs <= 1))
        if meets:
            out["p_meets"] = p
        out["p_last"] = p
        out["rows"].append((p, rb, rt, e))
    return out


# ---- bases ------------------------------------------------------------------------------------

class SingleChamber:
    """Ω1 alone: theta1(p) along -ĉ1 (rad) and its change of stretch, per segment"""

    def __init__(self, c):
        b = c.bend - c.bend[0]
        th = -RSQ2 * (b[:, :, 0] + b[:, :, 1])  # (m, 3)
        ds = c.stretch - c.stretch[0]
        self.f = Curve(c.p, np.stack([th, ds], axis=2))

    def __call__(self, p, s):
        return self.f(p)[s] if p > 0 else np.zeros(2)


def superpose(t):
    """-Σ t_j ĉ_j, grouped by diagonals (exactly 0 when t1 = t3 and t2 = t4)"""
    g1, g2 = t[0] - t[2], t[1] - t[3]
    return np.array([-RSQ2 * (g1 + g2), -RSQ2 * (g1 - g2)])


class BaseSup:
    """the shipped default: single-chamber superposition"""

    def __init__(self, modes, leg):
        self.one = SingleChamber(modes["O1"])

    def bend(self, s, pc):
        return superpose([self.one(q, s)[0] for q in pc])

    def stretch(self, s, pc):
        return sum(self.one(q, s)[1] for q in pc)


class BaseZero:
    """interpolation of the modes' values"""

    def __init__(self, modes, leg):
        pass

    def bend(self, s, pc):
        return np.zeros(2)

    def stretch(self, s, pc):
        return 0.0


# ---- the RBF rule: residuals over the base interpolated over the modes' symmetric images -------

# Gaussian width in the shape space x = p / P (4-D): chosen by the left-out errors of the
# refining modes (0.25: 25 mm, 0.35: 21, 0.5: 11.7, 0.7: 11.6, 1.0: 12.6, 1.5: 15.6 mm worst
# tip), not by the held-out cases
RBF_WIDTH = 0.5


def image(pc, bc, k, mir):
    q = pc.copy()
    if mir: q[1], q[3] = q[3], q[1]
    p = np.zeros(4)
    for i in range(4): p[(i + k) % 4] = q[i]
    return p, from_canonical(bc, k, mir)

class RBFModel:
    """residual over a base, interpolated by an RBF over the symmetric images of the modes'
    shapes x = p / P (4-D), cardinal weights combine the images' curves along P"""
    kernel = staticmethod(lambda r: np.exp(-(r / RBF_WIDTH) ** 2))
    poly = 0
    def __init__(self, cases, leg, base, exclude=()):
        self.leg = leg
        self.modes = {r: find_case(cases, ROLES[r]) for r in ROLES}
        for r in list(self.modes):
            if self.modes[r] is None or (r in exclude and r not in CORNERS):
                del self.modes[r]
        self.p_max = min(c.p[-1] for c in self.modes.values())
        self.base = base(self.modes, leg)
        X, Y = [], []
        for role, c in self.modes.items():
            r = c.ratio
            n = np.searchsorted(c.p, self.p_max - 1e-12) + 1
            mv = moment(r); mn = math.hypot(*mv); u = mv / mn if mn > 0 else np.zeros(2)
            sym = mirror_sym(r)
            y = np.zeros((n, 3, 3))
            for i in range(n):
                p = c.p[i]
                for s in range(3):
                    b = c.bend[i, s] - c.bend[0, s]
                    if mn == 0: b = np.zeros(2)
                    elif sym: b = (b @ u) * u
                    st = c.stretch[i, s] - c.stretch[0, s]
                    if p > 0:
                        b = b - self.base.bend(s, r * p)
                        st -= self.base.stretch(s, r * p)
                    y[i, s] = [b[0], b[1], st]
            for k in range(4):
                for mir in (0, 1):
                    q, _ = image(r.astype(float), np.zeros(2), k, mir)
                    if any(np.allclose(q, x) for x in X): continue
                    yy = y.copy()
                    for i in range(n):
                        for s in range(3):
                            _, bb = image(r, y[i, s, :2], k, mir)
                            yy[i, s, :2] = bb
                    X.append(q); Y.append(Curve(c.p[:n], yy))
        self.X = np.array(X); self.Y = Y
        N = len(X)
        A = self.kernel(np.linalg.norm(self.X[:, None] - self.X[None], axis=2))
        if self.poly:
            Pm = np.hstack([np.ones((N, 1)), self.X])
            M = np.zeros((N + 5, N + 5)); M[:N, :N] = A; M[:N, N:] = Pm; M[N:, :N] = Pm.T
        else:
            M = A
        self.Minv = np.linalg.inv(M); self.N = N
        self.cond = np.linalg.cond(M)
    def weights(self, x):
        phi = self.kernel(np.linalg.norm(self.X - x, axis=1))
        if self.poly: phi = np.concatenate([phi, [1], x])
        return (self.Minv @ phi)[:self.N]  # symmetric M: cardinal weights
    def eval(self, s, p):
        p = np.maximum(np.asarray(p, float), 0)
        if p.max() == 0: return np.zeros(2), 1.0
        P = min(p.max(), self.p_max); x = p / p.max(); pp = x * P
        w = self.weights(x)
        f = np.zeros(3)
        for wk, Yk in zip(w, self.Y):
            if wk != 0: f += wk * Yk(P)[s]
        pc, k, mir = canonical(pp)
        bb = from_canonical(self.base.bend(s, pc), k, mir)
        return bb + f[:2], 1 + f[2] + self.base.stretch(s, pc)


class RBFCubic(RBFModel):
    kernel = staticmethod(lambda r: r ** 3)
    poly = 1


class BaseMoment:
    """pressure-moment base: the bend along -m̂ with magnitude a(|m|, p̄) and the change of
    stretch d(|m|, p̄), each piecewise linear over a Delaunay triangulation of the fitted modes'
    rows in (|m|, p̄) (the elongation modes give a = 0 at |m| = 0; outside the hull the nearest
    row's value)"""

    def __init__(self, modes, leg):
        from scipy.interpolate import LinearNDInterpolator, NearestNDInterpolator
        pts, va, vs = [], [[] for _ in range(3)], [[] for _ in range(3)]
        for c in modes.values():
            mv = moment(c.ratio)
            mn = math.hypot(*mv)
            for i in range(len(c.p)):
                x = (mn * c.p[i], c.ratio.mean() * c.p[i])
                if any(abs(x[0] - q[0]) + abs(x[1] - q[1]) < 1e-12 for q in pts):
                    continue  # the rest row of every mode
                pts.append(x)
                for s in range(3):
                    b = c.bend[i, s] - c.bend[0, s]
                    va[s].append(-(b @ mv) / mn if mn > 0 else 0.0)
                    vs[s].append(c.stretch[i, s] - c.stretch[0, s])
        pts = np.array(pts)
        self.fa = [(LinearNDInterpolator(pts, va[s]), NearestNDInterpolator(pts, va[s]))
                   for s in range(3)]
        self.fs = [(LinearNDInterpolator(pts, vs[s]), NearestNDInterpolator(pts, vs[s]))
                   for s in range(3)]

    @staticmethod
    def _at(f, x):
        v = float(f[0](*x))
        return v if np.isfinite(v) else float(f[1](*x))

    def bend(self, s, pc):
        mv = moment(pc)
        mn = math.hypot(*mv)
        if mn == 0:
            return np.zeros(2)
        return -self._at(self.fa[s], (mn, np.mean(pc))) * mv / mn

    def stretch(self, s, pc):
        return self._at(self.fs[s], (math.hypot(*moment(pc)), np.mean(pc)))


class BasePair(BaseSup):
    """the superposition with a factor per opposite chamber pair (robot_calibration_pair.c):
    along each diagonal (θ1(p_hi) - θ1(p_lo)) exp(k0 n + k1 l + k2 n² + k3 l²), n the other
    pair's pressure sum, l this pair's lower pressure; k per segment, the least-squares fit of
    the bend vectors of every row of the bending modes used (all but O1, O13, O1234)"""

    def __init__(self, modes, leg):
        from scipy.optimize import least_squares
        super().__init__(modes, leg)
        self.k = np.zeros((3, 4))
        bending = [c for r, c in modes.items() if r not in ("O1", "O13", "O1234")]
        for s in range(3):
            rows = [(c.ratio * c.p[i], c.bend[i, s] - c.bend[0, s])
                    for c in bending for i in range(1, len(c.p))]

            def res(k):
                return np.concatenate([self._bend(s, pc, k) - bf for pc, bf in rows])
            self.k[s] = least_squares(res, np.zeros(4)).x

    def _bend(self, s, pc, k):
        t = [self.one(q, s)[0] for q in pc]
        K = [math.exp(k[0] * n + k[1] * l + k[2] * n * n + k[3] * l * l)
             for n, l in ((pc[1] + pc[3], min(pc[0], pc[2])), (pc[0] + pc[2], min(pc[1], pc[3])))]
        g1, g2 = (t[0] - t[2]) * K[0], (t[1] - t[3]) * K[1]
        return np.array([-RSQ2 * (g1 + g2), -RSQ2 * (g1 - g2)])

    def bend(self, s, pc):
        return self._bend(s, pc, self.k[s])


# ---- driver --------------------------------------------------------------------------------------

HELD = ["H1", "H2", "H3", "H4", "H5", "H6", "H7", "H8"]
LOO = ["O12r05", "O12O34r3", "O1O234r05", "O1O234r075", "O124O3r05", "O1O23r05O4r025", "O1O3r05",
       "O12O4r05", "O1O24r05", "O13O2r05", "O1O2r067O4r033", "O13O2r067O4r033", "O1O23r05",
       "O12O34r05"]


def score(cases, leg, base, verbose=True, label=""):
    M = MODELS.get(label, Model)
    m = M(cases, leg, base)
    res = {"held": {}, "loo": {}, "fit": {}}
    for r in m.modes:
        res["fit"][r] = compare(m, m.modes[r], leg)
    for h in HELD + ["O2"]:
        if h in cases:
            res["held"][h] = compare(m, cases[h], leg)
    for r in LOO:
        if r in m.modes:
            ml = M(cases, leg, base, exclude=(r,))
            res["loo"][r] = compare(ml, m.modes[r], leg)
    if verbose:
        print("== %s" % label)
        print("  fitted (max bend deg / tip mm): " + "  ".join(
            "%s %.2f/%.2f" % (k, v["bend"], v["tip"]) for k, v in res["fit"].items()))
        for h, e in res["held"].items():
            sym = " sym %.2f" % e["tip_sym"] if e["mirror"] else ""
            print("  %-4s bend %6.3f deg (%.2f) tip %7.3f mm (%.2f)%s  meets to %.3g of %.3g" % (
                h, e["bend"], e["bscore"], e["tip"], e["tscore"], sym, e["p_meets"], e["p_last"]))
        for r, e in res["loo"].items():
            print("  left out %-14s bend %6.3f deg  tip %7.3f mm" % (r, e["bend"], e["tip"]))
        hb = max(e["bend"] for h, e in res["held"].items() if h != "O2")
        ht = max(e["tip"] for h, e in res["held"].items() if h != "O2")
        pm = min([e["p_meets"] for h, e in res["held"].items()
                  if h != "O2" and e["p_meets"] < e["p_last"]] or [float("inf")])
        lb = max([e["bend"] for e in res["loo"].values()] or [0])
        lt = max([e["tip"] for e in res["loo"].values()] or [0])
        print("  WORST held out %.3f deg / %.3f mm, all meet to %.3g MPa; left out %.3f deg / "
              "%.3f mm" % (hb, ht, pm, lb, lt))
    return res


RULES = {"sup": BaseSup, "interp": BaseZero, "rbf": BaseSup, "rbf-interp": BaseZero,
         "rbf-r3": BaseSup, "moment": BaseMoment, "rbf-moment": BaseMoment, "rbf-pair": BasePair}
MODELS = {"rbf": RBFModel, "rbf-interp": RBFModel, "rbf-r3": RBFCubic, "rbf-moment": RBFModel,
          "rbf-pair": RBFModel}


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--table", default="robot/calibration_fe_leg_modes.h5")
    ap.add_argument("--extra", nargs="*", default=["docs/bench/calibration_cases_2026-12-02b/H8.h5"])
    ap.add_argument("--rules", default=None)
    a = ap.parse_args()
    cases, leg = load([a.table] + a.extra)
    for name in (a.rules.split(",") if a.rules else RULES):
        score(cases, leg, RULES[name], label=name)
    return cases, leg


if __name__ == "__main__":
    main()

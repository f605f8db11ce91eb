"""crawlsim.bend: one actuator bent, as `crawlsim bend --model analytic|rod|strain` does it
(core/crawlsim.h cs_bend; the FE models stay in the command: libcrawlsim does not link the FE).

Owns `bend(...)` and `BendResult`: the definition is built field by field from keyword
arguments (csBendDef), checked by the C library (cs_bendDefValidate, whose message a bad value
raises as crawlsim.Error), and the sweep is written by cs_bend straight into numpy arrays.
"""

import ctypes
import os

from . import _lib
from .errors import Error

_STR = ("model", "actuator", "chambers", "calibration", "cal_rule", "cal_drop", "data_dir")


class BendResult:
    """The sweep's rows: pressure [n] (MPa), angle_deg [n, 3] (segments II1..II3, deg),
    angle_total [n] (their sum, the paper's Eq. 11, deg) and tip [n, 3] (mm, the actuator's
    base frame); model and actuator as asked."""

    def __init__(self, pressure, angle_deg, tip, model, actuator):
        self.pressure = pressure
        self.angle_deg = angle_deg
        self.angle_total = angle_deg.sum(axis=1)
        self.tip = tip
        self.model = model
        self.actuator = actuator

    def __len__(self):
        return len(self.pressure)

    def __repr__(self):
        return (f"BendResult({self.model}, {len(self)} rows up to {self.pressure[-1]:.4g} MPa: "
                f"total {self.angle_total[-1]:.2f} deg)")


def _text(name, v):
    if v is None:
        return None
    if name == "chambers" and isinstance(v, (list, tuple)):
        v = ",".join(str(int(c)) for c in v)
    if not isinstance(v, (str, os.PathLike)):
        raise Error(f"bend: {name} takes a string, not {type(v).__name__}")
    s = os.fspath(v)
    if "\0" in s:
        raise Error(f"bend: a NUL character in {name} {s!r}")
    return s.encode()


def bend(model="analytic", actuator=None, chambers=None, p_max=None, p_step=None, set=None,
         tip_load=None, calibration=None, cal_rule=None, cal_drop=None, mesh_size=None,
         data_dir=None, links=None):
    """Inflate the listed chambers of all three segments of one actuator at equal pressure
    p = 0, p_step, ... up to p_max (p_max always the last row) and return a BendResult.

    model "analytic" | "rod" | "strain" (the leg of `run --legs strain`); actuator "fig1" |
    "baseline" | "leg" (None: baseline, the rod's and strain leg's leg); chambers "1,2" or
    [1, 2]; p_max, p_step in MPa (None: 0.4, 0.05); set a list of "NAME=VALUE" strings or a
    dict (`bend --set`); rod and strain only: tip_load (3 numbers, N), calibration (a table or
    "analytic"; None: the mission's table), cal_rule, cal_drop; rod only: mesh_size (mm);
    strain only: links (bending modes per segment). Bad input raises crawlsim.Error with the library's message."""
    L = _lib.lib()
    c = L.cs_defaultBendDef()
    args = dict(model=model, actuator=actuator, chambers=chambers, calibration=calibration,
                cal_rule=cal_rule, cal_drop=cal_drop, data_dir=data_dir)
    keep = []
    for name in _STR:
        b = _text(name, args[name])
        keep.append(b)
        setattr(c, name, b)
    for name, v in (("p_max", p_max), ("p_step", p_step), ("mesh_size", mesh_size),
                    ("links", links)):
        if v is None:
            continue
        if isinstance(v, bool) or not isinstance(v, (int, float)) and not hasattr(v, "__float__"):
            raise Error(f"bend: {name} takes a number, not {type(v).__name__}")
        setattr(c, name, float(v))
    if tip_load is not None:
        t = [float(x) for x in tip_load]
        if len(t) != 3:
            raise Error(f"bend: tip_load takes 3 numbers (N), not {len(t)}")
        c.tip_load[:] = t
    if set:
        items = [f"{k}={v}" for k, v in set.items()] if isinstance(set, dict) else list(set)
        arr = (ctypes.c_char_p * len(items))(*[_text("set", s) for s in items])
        keep.append(arr)
        c.actuator_set = ctypes.cast(arr, ctypes.POINTER(ctypes.c_char_p))
        c.n_actuator_set = len(items)
    import numpy as np

    err = _lib.csError()
    rows = L.cs_bendRowCount(ctypes.byref(c), ctypes.byref(err))
    if rows < 0:
        raise _lib.error(err.status, err)
    pressure = np.zeros(rows)
    angle = np.zeros((rows, 3))
    tip = np.zeros((rows, 3))
    n = ctypes.c_int(0)
    ptr = lambda a: a.ctypes.data_as(_lib.c_double_p)  # noqa: E731
    st = L.cs_bend(ctypes.byref(c), rows, ptr(pressure), ptr(angle), ptr(tip), ctypes.byref(n),
                   ctypes.byref(err))
    _lib.check(st, err)
    del keep
    return BendResult(pressure[:n.value], angle[:n.value], tip[:n.value], model,
                      actuator if actuator is not None else ("leg" if model in ("rod", "strain")
                                                             else "baseline"))


__all__ = ["bend", "BendResult"]

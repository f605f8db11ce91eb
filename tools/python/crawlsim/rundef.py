"""crawlsim.rundef: the run definition in Python (core/crawlsim.h csRunDef).

Owns `RunDef`: one attribute per field of csRunDef, starting at the C library's own defaults
(cs_defaultRunDef: strings None, numbers NaN = "the scene's or the driver's default"), set by
keyword arguments or attribute assignment; `validate()` calls cs_runDefValidate, the one place
every range check lives. A keyword that is not a field raises crawlsim.Error naming the nearest
field. Values are converted to C when a run or a simulation is made (`to_c`), and the Python
object keeps the encoded strings alive for as long as the C struct is used.
"""

import ctypes
import difflib
import math
import os

from . import _lib
from .errors import Error

# the fields a user sets, with the kind of value each takes (_lib.RUNDEF_FIELDS)
_KIND = {n: k for n, _, k in _lib.RUNDEF_FIELDS if k != "raw"}


class RunDef:
    """Everything `crawlsim run` takes (docs/reference/commands.md), as keyword arguments
    named as csRunDef's fields (the option with '-' as '_': friction, t_end, legs, ...):

        RunDef(scene="flat-road", legs="rod", conditions="paper", t_end=2.0)

    Strings (scene, gait, terrain, legs, conditions, calibration, out, ...) take str or a path;
    None is the default. Numbers take float; None or NaN is the default. actuator_set takes a
    list of "NAME=VALUE" strings or a dict {NAME: VALUE}. no_gait=True runs without a gait
    table (the pressures are zero until set_pressures or a controller commands them).
    `log` may be a callable that receives each line describing what the run is (scene,
    conditions, calibration, legs, stance check) before it settles; `progress` a callable
    progress(t, x, wall_s) that run() calls once per simulated second with the time (s), the
    support's displacement from t = 0 (a tuple of 3, mm) and the wall time so far (s). The
    library itself prints nothing."""

    __slots__ = ("_values", "log", "progress")

    def __init__(self, **kw):
        object.__setattr__(self, "_values", {})
        object.__setattr__(self, "log", None)
        object.__setattr__(self, "progress", None)
        d = _lib.lib().cs_defaultRunDef()
        for name, kind in _KIND.items():
            if kind == "strlist":
                self._values[name] = []
            elif kind == "str":
                v = getattr(d, name)
                self._values[name] = v.decode() if v is not None else None
            elif kind == "num":
                v = getattr(d, name)
                self._values[name] = None if math.isnan(v) else v
            else:
                self._values[name] = getattr(d, name)
        for k, v in kw.items():
            setattr(self, k, v)

    def __getattr__(self, name):
        try:
            return self._values[name]
        except KeyError:
            raise AttributeError(_unknown(name)) from None

    def __setattr__(self, name, value):
        if name == "log":
            if value is not None and not callable(value):
                raise Error("RunDef.log must be a callable taking one line of text, or None")
            object.__setattr__(self, "log", value)
            return
        if name == "progress":
            if value is not None and not callable(value):
                raise Error("RunDef.progress must be a callable progress(t, x, wall_s), or None")
            object.__setattr__(self, "progress", value)
            return
        kind = _KIND.get(name)
        if kind is None:
            raise Error(_unknown(name))
        self._values[name] = _convert(name, kind, value)

    def fields(self):
        """{field: value} of every settable field (None: the default)."""
        return dict(self._values)

    def __repr__(self):
        set_ = {k: v for k, v in self._values.items() if v not in (None, [], 0) or k == "scene"}
        return "RunDef(" + ", ".join(f"{k}={v!r}" for k, v in set_.items()) + ")"

    def to_c(self):
        """(csRunDef, keep): the C struct and the Python objects it points into (keep them
        alive while the struct is used)."""
        c = _lib.lib().cs_defaultRunDef()
        keep = []
        for name, kind in _KIND.items():
            v = self._values[name]
            if kind == "str":
                b = None if v is None else v.encode()
                keep.append(b)
                setattr(c, name, b)
            elif kind == "num":
                setattr(c, name, math.nan if v is None else v)
            elif kind == "int":
                setattr(c, name, int(v))
            elif kind == "strlist":
                arr = (ctypes.c_char_p * max(1, len(v)))(*[s.encode() for s in v])
                keep.append(arr)
                c.actuator_set = ctypes.cast(arr, ctypes.POINTER(ctypes.c_char_p)) if v else None
                c.n_actuator_set = len(v)
        if self.log is not None:
            user_log = self.log

            def trampoline(_user, line):
                try:
                    user_log(line.decode("utf-8", "replace"))
                except Exception:  # noqa: BLE001: a logger must not unwind through C
                    pass

            fn = _lib.LOGFN(trampoline)
            keep.append(fn)
            c.log = fn
        if self.progress is not None:
            user_progress = self.progress

            def progress_trampoline(_user, t, x, wall_s):
                try:
                    user_progress(t, (x[0], x[1], x[2]), wall_s)
                except Exception:  # noqa: BLE001: a callback must not unwind through C
                    pass

            pfn = _lib.PROGRESSFN(progress_trampoline)
            keep.append(pfn)
            c.progress = pfn
        return c, keep

    def validate(self):
        """cs_runDefValidate: every check that needs no file. Raises crawlsim.Error with the
        C message ("--friction -1 must be >= 0") when a value is out of range."""
        c, _keep = self.to_c()
        err = _lib.csError()
        _lib.check(_lib.lib().cs_runDefValidate(ctypes.byref(c), ctypes.byref(err)), err)
        return self


def from_args(rundef, kw, who):
    """The RunDef a call was given: `rundef` itself, or RunDef(**kw) when it is None (both at
    once, or something else, raise naming the caller `who`)."""
    if rundef is None:
        return RunDef(**kw)
    if kw:
        raise Error(f"{who}: give a RunDef or keyword arguments, not both")
    if not isinstance(rundef, RunDef):
        raise Error(f"{who}: expected a RunDef, not {type(rundef).__name__}")
    return rundef


def _unknown(name):
    near = difflib.get_close_matches(name, list(_KIND) + ["log", "progress"], n=1)
    hint = f" (did you mean {near[0]}?)" if near else ""
    return f"RunDef has no field '{name}'{hint}; fields: {', '.join(_KIND)}, log, progress"


def _convert(name, kind, v):
    """Check a value's type here (the C library checks its range) and normalise it."""
    if kind == "str":
        if v is None:
            return None
        if isinstance(v, (str, os.PathLike)):
            s = os.fspath(v)
            if "\0" in s:
                raise Error(f"RunDef.{name}: a NUL character in {s!r}")
            return s
        raise Error(f"RunDef.{name} takes a string or a path, not {type(v).__name__}")
    if kind == "num":
        if v is None:
            return None
        if isinstance(v, bool) or not isinstance(v, (int, float)) and not hasattr(v, "__float__"):
            raise Error(f"RunDef.{name} takes a number, not {type(v).__name__}")
        f = float(v)
        return None if math.isnan(f) else f
    if kind == "int":
        if not isinstance(v, (bool, int)):
            raise Error(f"RunDef.{name} takes True/False or an integer, not {type(v).__name__}")
        if not -2**31 <= int(v) < 2**31:
            raise Error(f"RunDef.{name} = {v} does not fit a C int")
        return int(v)
    # strlist: actuator_set
    if v is None:
        return []
    if isinstance(v, dict):
        v = [f"{k}={val}" for k, val in v.items()]
    if isinstance(v, str) or not all(isinstance(s, str) for s in v):
        raise Error(f"RunDef.{name} takes a list of 'NAME=VALUE' strings or a dict")
    if any("\0" in s for s in v):
        raise Error(f"RunDef.{name}: a NUL character in {v!r}")
    return list(v)

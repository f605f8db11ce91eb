"""crawlsim.run: a whole run, as `crawlsim run` does it (core/crawlsim.h cs_run).

Owns `run(...)` and `RunResult`: the C result struct (verdict, end time and pose, timings,
steps, the level and calibration that ran) as Python values, plus the run's tracks read back
from its HDF5 file as numpy arrays (results.RunFile).
"""

import ctypes
import os
import shutil
import tempfile

from . import _lib
from .errors import Error
from .results import RunFile
from .rundef import from_args


def _s(b):
    return b.value.decode("utf-8", "replace") if hasattr(b, "value") else b.decode("utf-8", "replace")


class RunResult:
    """What cs_run returned (csRunResult): status and status_name, verdict ("crawls",
    "stands", "tips over", "falls", "stops"), message ("" on success), t_end (s), position [3]
    mm, quat [4], tilt_deg, wall_s, real_time_factor, robot_mass_g, steps, rejected_steps,
    gain_projections, timers {stage: s}, scene, conditions, legs, links, macro_steps, dt,
    calibration, calibration_rule, legs_auto_choice, interrupted; and `tracks`, the run file
    read back (RunFile: t, position, orientation, pressure, centerline, foot_force, stance,
    attrs), or None when it could not be written. `ok` is True when the run completed."""

    def __init__(self, c, tracks, out):
        import numpy as np

        self.status = c.status
        self.status_name = _lib.STATUS_NAMES.get(c.status, str(c.status))
        self.verdict = _s(c.verdict)
        self.message = _s(c.message)
        for name in ("t_end", "tilt_deg", "wall_s", "real_time_factor", "robot_mass_g", "dt"):
            setattr(self, name, float(getattr(c, name)))
        for name in ("steps", "rejected_steps", "gain_projections", "links", "macro_steps"):
            setattr(self, name, int(getattr(c, name)))
        self.position = np.array(c.position[:])
        self.quat = np.array(c.quat[:])
        self.timers = {_s(c.timer_name[k]): float(c.timer_s[k]) for k in range(c.ntimer)}
        for name in ("scene", "conditions", "legs", "calibration", "calibration_rule",
                     "legs_auto_choice"):
            setattr(self, name, _s(getattr(c, name)))
        self.interrupted = bool(c.interrupted)
        self.tracks = tracks
        self.out = out

    @property
    def ok(self):
        return self.status == 0

    def __repr__(self):
        x, _, z = self.position
        return (f"RunResult({self.verdict or self.status_name}: x = {x:.1f} mm, z = {z:.1f} mm at "
                f"t = {self.t_end:.3g} s, legs {self.legs}, conditions {self.conditions}"
                + (f", {self.message!r}" if self.message else "") + ")")


def run(rundef=None, check=True, **kw):
    """Run a scene from t = 0 to t_end as `crawlsim run` does and return a RunResult with the
    tracks. Takes a RunDef or its fields as keywords (run(scene="obstacle", t_end=3)). With
    out=None the HDF5 file goes to a temporary directory, is read back and removed; with
    out="FILE.h5" it stays (with FILE.xdmf). Bad input raises crawlsim.Error before anything
    is built. A run that fails part way raises crawlsim.Error too unless check=False, which
    returns the RunResult (its tracks up to the failure, its message)."""
    rundef = from_args(rundef, kw, "run")
    tmp = None
    out = rundef.out
    c, keep = rundef.to_c()
    if out is None:
        tmp = tempfile.mkdtemp(prefix="crawlsim-run-")
        path = os.path.join(tmp, "run.h5")
        b = path.encode()
        keep.append(b)
        c.out = b
    else:
        path = out
    try:
        res = _lib.csRunResult()
        err = _lib.csError()
        st = _lib.lib().cs_run(ctypes.byref(c), ctypes.byref(res), ctypes.byref(err))
        tracks = None
        if os.path.isfile(path):
            try:
                tracks = RunFile(path)
            except Error:
                tracks = None  # a run refused before its file got its series
        result = RunResult(res, tracks, out)
        if st != 0 and check:
            raise _lib.error(st, err)
        return result
    finally:
        del keep
        if tmp:
            shutil.rmtree(tmp, ignore_errors=True)

"""crawlsim.sim: a simulation stepped from Python (core/crawlsim.h csSim).

Owns `Sim`: create (load, build, settle) from a RunDef or keyword arguments, step, run_until,
reset, the whole state, the read-outs (support pose and twist, foot forces, pressures, leg
centrelines), the chamber commands (set_pressures) and a controller callback.

Arrays: every read-out is written by the C library straight into a numpy array (no copy in
between); pass `out=` to reuse one array across steps (no allocation in the loop). Shapes and
units as core/crawlsim.h: positions mm (world: x crawl, y up, z lateral), quaternions
(w, x, y, z), forces N, pressures MPa in chamber-label order (label L is index L - 1), legs
0..7 = A..H.

The controller (set_controller(f)): f(sim, t, p_cmd) fills the numpy view p_cmd [96] (MPa) of
the library's own buffer for time t (s). The library asks it wherever the gait table would be
asked: at the end of every step and at the pneumatic integrator's inner times within the step,
so it must be a function of t and of the state at the step's start (the read-outs return that
during the step). sim.gait_command(t) is the gait table's command, for a controller that
replays or modulates it. An exception in f fails the step (nothing changes) and is raised again
from step()/run_until(), with the C message as its context.
"""

import ctypes

import numpy as np

from . import _lib
from .errors import Error
from .results import heading_deg
from .rundef import from_args

_D = ctypes.c_double


def _ptr(a):
    return a.ctypes.data_as(_lib.c_double_p)


def _buffer(out, shape, what):
    """`out` checked (float64, C-contiguous, writeable, of `shape`), or a new array."""
    if out is None:
        return np.empty(shape)
    if (not isinstance(out, np.ndarray) or out.dtype != np.float64 or out.shape != shape
            or not out.flags.c_contiguous or not out.flags.writeable):
        raise Error(f"{what}: out must be a writeable C-contiguous float64 array of shape {shape}")
    return out


def _doubles(x, n, what):
    """x as a C-contiguous float64 array of n values (a copy only if x is not one already)."""
    try:
        a = np.ascontiguousarray(x, dtype=np.float64)
    except (TypeError, ValueError):
        raise Error(f"{what}: expected {n} numbers") from None
    if a.shape != (n,):
        raise Error(f"{what}: expected {n} numbers, got shape {a.shape}")
    return a


class Sim:
    """A simulation at t = 0 after settling: Sim(RunDef(...)) or Sim(scene="flat-road", ...).
    Close it with close() or use it in a `with` block (the C object is also freed when the
    Sim is garbage-collected)."""

    def __init__(self, rundef=None, **kw):
        rundef = from_args(rundef, kw, "Sim")
        self._L = _lib.lib()
        self._s = None
        self._controller = None  # the Python callable
        self._cfunc = None       # its ctypes trampoline (kept alive while registered)
        self._exc = None         # an exception the controller raised during the last step
        self._views = {}         # address -> numpy view of a p_cmd buffer
        self.rundef = rundef
        c, keep = rundef.to_c()
        self._err = _lib.csError()
        s = self._L.cs_simCreate(ctypes.byref(c), ctypes.byref(self._err))
        del keep
        if not s:
            raise _lib.error(self._err.status or -1, self._err)
        self._s = ctypes.c_void_p(s)
        self.nchamber = self._L.cs_simChamberCount(self._s)
        self.nleg = self._L.cs_simLegCount(self._s)
        self.macro_step = self._L.cs_simMacroStep(self._s)
        # reused by the read-outs without out=
        self._pos, self._quat = np.empty(3), np.empty(4)

    # ---- life ------------------------------------------------------------------------------
    def close(self):
        """Free the C simulation (idempotent); the Sim cannot be used afterwards."""
        if getattr(self, "_s", None) is not None:
            self._L.cs_simDestroy(self._s)
            self._s = None
            self._cfunc = None

    def __del__(self):
        self.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    def _h(self):
        if self._s is None:
            raise Error("Sim: used after close()")
        return self._s

    def _check(self, status):
        if status != 0:
            exc, self._exc = self._exc, None
            cerr = _lib.error(status, self._err)
            if exc is not None:
                raise exc from cerr
            raise cerr

    # ---- stepping --------------------------------------------------------------------------
    def step(self, n=1):
        """Advance by n macro steps (each macro_step s). A failed step changes nothing and
        raises crawlsim.Error with the time and the cause; further steps then raise until
        reset() or a state is set."""
        s, f, e = self._h(), self._L.cs_simStep, ctypes.byref(self._err)
        for _ in range(n):
            st = f(s, e)
            if st:
                self._check(st)

    def run_until(self, t):
        """Step until the time reaches t (s; within half a step)."""
        self._check(self._L.cs_simRunUntil(self._h(), float(t), ctypes.byref(self._err)))

    def reset(self):
        """Back to the settled state at t = 0; the pressure source (gait, command or
        controller) stays."""
        self._check(self._L.cs_simReset(self._h(), ctypes.byref(self._err)))

    @property
    def t(self):
        """Simulated time (s)."""
        return self._L.cs_simTime(self._h())

    @property
    def steps(self):
        """Accepted macro steps since creation."""
        return self._L.cs_simStepCount(self._h())

    # ---- state -----------------------------------------------------------------------------
    @property
    def state_size(self):
        return self._L.cs_simStateSize(self._h())

    def get_state(self, out=None):
        """The whole state (time, seed, pressures, support, legs) as a flat float64 array."""
        a = _buffer(out, (self.state_size,), "get_state")
        self._L.cs_simStateGet(self._h(), _ptr(a))
        return a

    def set_state(self, x):
        """Restore a state from get_state (of this simulation); clears a failure."""
        a = _doubles(x, self.state_size, "set_state")
        self._check(self._L.cs_simStateSet(self._h(), _ptr(a), ctypes.byref(self._err)))

    state = property(get_state, set_state)

    # ---- read-outs -------------------------------------------------------------------------
    def support_pose(self, out_pos=None, out_quat=None):
        """(position [3] mm: the support centre's displacement from t = 0, world;
        quaternion [4] (w, x, y, z))."""
        p = _buffer(out_pos, (3,), "support_pose")
        q = _buffer(out_quat, (4,), "support_pose")
        self._L.cs_simSupportPose(self._h(), _ptr(p), _ptr(q))
        return p, q

    def support_twist(self, out_v=None, out_w=None):
        """(velocity [3] mm/s, angular velocity [3] rad/s), world frame."""
        v = _buffer(out_v, (3,), "support_twist")
        w = _buffer(out_w, (3,), "support_twist")
        self._L.cs_simSupportTwist(self._h(), _ptr(v), _ptr(w))
        return v, w

    @property
    def heading(self):
        """The support's heading (deg): its x axis on the ground from world +x, positive
        towards -z (counter-clockwise seen from above; results.heading_deg)."""
        self._L.cs_simSupportPose(self._h(), _ptr(self._pos), _ptr(self._quat))
        return float(heading_deg(self._quat))

    def foot_forces(self, out=None):
        """[8, 3] N: the terrain's force on each leg A..H, world frame."""
        f = _buffer(out, (self.nleg, 3), "foot_forces")
        self._L.cs_simFootForces(self._h(), _ptr(f))
        return f

    def pressures(self, out=None):
        """[96] MPa: the chamber pressures now (label order)."""
        p = _buffer(out, (self.nchamber,), "pressures")
        self._L.cs_simPressures(self._h(), _ptr(p))
        return p

    def centerline(self, leg, npts=25, out=None):
        """[npts, 3] mm: leg `leg`'s centreline (0..7 or "A".."H"), hip to foot, world."""
        k = _leg_index(leg)
        c = _buffer(out, (int(npts), 3), "centerline")
        if self._L.cs_simLegCenterline(self._h(), k, int(npts), _ptr(c)) != 0:
            raise Error(f"centerline: leg {leg!r} or npts {npts} out of range (legs 0..7, "
                        "npts 2..201)")
        return c

    def centerlines(self, npts=25, out=None):
        """[8, npts, 3] mm: every leg's centreline, written in place into one array."""
        c = _buffer(out, (self.nleg, int(npts), 3), "centerlines")
        s = self._h()
        for k in range(self.nleg):
            row = c[k]
            if self._L.cs_simLegCenterline(s, k, int(npts), _ptr(row)) != 0:
                raise Error(f"centerlines: npts {npts} out of range (2..201)")
        return c

    def gait_command(self, t, out=None):
        """[96] MPa: the gait table's command at time t (zero without a table or before 0)."""
        p = _buffer(out, (self.nchamber,), "gait_command")
        self._L.cs_simGaitCommand(self._h(), float(t), _ptr(p))
        return p

    # ---- pressures -------------------------------------------------------------------------
    def set_pressures(self, p_cmd):
        """Hold the 96 chamber commands (MPa, label order, each in [0, 1]) from now until
        changed; they replace the gait and any controller."""
        a = _doubles(p_cmd, self.nchamber, "set_pressures")
        self._check(self._L.cs_simSetPressureCommand(self._h(), _ptr(a), ctypes.byref(self._err)))
        self._controller = None
        self._cfunc = None

    @property
    def controller(self):
        return self._controller

    def set_controller(self, f):
        """Register f(sim, t, p_cmd) (see the module's text); None: back to the gait table."""
        if f is not None and not callable(f):
            raise Error("set_controller: expected a callable f(sim, t, p_cmd) or None")
        cfunc = _lib.CONTROLLER(self._trampoline) if f is not None else _lib.CONTROLLER()
        self._check(self._L.cs_simSetController(self._h(), cfunc, None, ctypes.byref(self._err)))
        self._controller = f
        self._cfunc = cfunc if f is not None else None

    def _trampoline(self, _s, t, addr, _user):
        # addr: the library's [96] buffer (the integrator's, on its stack): one numpy view per
        # address, made once (a few addresses recur), no copy either way
        if addr is None or self._controller is None:
            return 1
        view = self._views.get(addr)
        if view is None:
            view = np.ctypeslib.as_array((_D * self.nchamber).from_address(addr))
            if len(self._views) < 64:
                self._views[addr] = view
        try:
            self._controller(self, t, view)
            return 0
        except BaseException as e:  # noqa: BLE001: unwinding through C is undefined
            self._exc = e
            return 1


def _leg_index(leg):
    if isinstance(leg, str) and len(leg) == 1 and leg.upper() in "ABCDEFGH":
        return "ABCDEFGH".index(leg.upper())
    if isinstance(leg, (int, np.integer)) and not isinstance(leg, bool):
        return int(leg)
    raise Error(f"leg {leg!r}: expected 0..7 or 'A'..'H'")

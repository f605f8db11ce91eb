"""crawlsim._lib: INTERNAL: libcrawlsim found and loaded with ctypes, its types and prototypes.

Owns: the ctypes mirror of core/crawlsim.h (csRunDef, csRunResult, csBendDef, csError, the csController
type and every function's argtypes/restype), where the library is looked for, and `check`,
which turns a failed status into crawlsim.Error with the C message.

Why ctypes: it is in the standard library (no build step, nothing more from Debian), and a
call costs about a microsecond, small against a macro step (docs/reference/python.md
"Cost of a Python loop"). The structs are mirrored by hand; tests/python/test_layout.py
compiles a C program against the installed header and compares every field's offset and every
struct's size with this mirror, so a change of the header that is not made here fails a test.

Where the library is looked for, in order:
  1. $CRAWLSIM_LIBRARY (a path to libcrawlsim.so);
  2. the install: _paths.py, which `cmake --install` writes beside this file, holds the
     library's directory relative to the package's (the prefix can be moved as a whole);
  3. the dynamic linker's own search (ctypes.util.find_library: ldconfig, LD_LIBRARY_PATH).
"""

import ctypes
import ctypes.util
import os

from .errors import Error

c_double_p = ctypes.POINTER(ctypes.c_double)

CS_ERROR_MSG_SIZE = 512  # core/core_status.h
CS_RUN_MAX_TIMERS = 16  # core/crawlsim.h
CS_RUN_TEXT = 256
NCHAMBER = 96  # 8 legs x 3 segments x 4 chambers (docs/reference.md "The robot")
NLEG = 8

# core/core_status.h CS_STATUS_LIST: value -> name (the messages come from cs_statusString)
STATUS_NAMES = {0: "CS_OK", -1: "CS_ERR_ARG", -2: "CS_ERR_IO", -3: "CS_ERR_PARSE",
                -4: "CS_ERR_RANGE", -5: "CS_ERR_MEMORY", -6: "CS_ERR_DIVERGED",
                -7: "CS_ERR_SOLVER", -8: "CS_ERR_EXTERNAL", -9: "CS_ERR_REJECTED",
                -10: "CS_ERR_INTERRUPTED"}


class csError(ctypes.Structure):
    _fields_ = [("status", ctypes.c_int), ("msg", ctypes.c_char * CS_ERROR_MSG_SIZE)]


LOGFN = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_char_p)
# void (*progress)(void* user, double t, const double x[3], double wall_s)
PROGRESSFN = ctypes.CFUNCTYPE(None, ctypes.c_void_p, ctypes.c_double, c_double_p,
                              ctypes.c_double)

# csRunDef, field by field in the header's order: (name, ctypes type, kind) where kind says how
# the Python RunDef converts a value: "str" (NULL = default), "num" (NaN = default), "int",
# "strlist" (actuator_set + n_actuator_set), "raw" (not settable from Python)
RUNDEF_FIELDS = [
    ("scene", ctypes.c_char_p, "str"),
    ("scene_file", ctypes.c_char_p, "str"),
    ("terrain", ctypes.c_char_p, "str"),
    ("gait", ctypes.c_char_p, "str"),
    ("no_gait", ctypes.c_int, "int"),
    ("foothold", ctypes.c_char_p, "str"),
    ("gate", ctypes.c_char_p, "str"),
    ("conditions", ctypes.c_char_p, "str"),
    ("legs", ctypes.c_char_p, "str"),
    ("rom_file", ctypes.c_char_p, "str"),
    ("legs_tol_mm", ctypes.c_double, "num"),
    ("levels", ctypes.c_char_p, "str"),
    ("calibration", ctypes.c_char_p, "str"),
    ("cal_rule", ctypes.c_char_p, "str"),
    ("cal_drop", ctypes.c_char_p, "str"),
    ("actuator_set", ctypes.POINTER(ctypes.c_char_p), "strlist"),
    ("n_actuator_set", ctypes.c_int, "raw"),
    ("friction", ctypes.c_double, "num"),
    ("pressure_scale", ctypes.c_double, "num"),
    ("t_end", ctypes.c_double, "num"),
    ("dt", ctypes.c_double, "num"),
    ("output_dt", ctypes.c_double, "num"),
    ("ramp", ctypes.c_double, "num"),
    ("tau", ctypes.c_double, "num"),
    ("gravity", ctypes.c_double, "num"),
    ("support_mass_kg", ctypes.c_double, "num"),
    ("slope_deg", ctypes.c_double, "num"),
    ("links", ctypes.c_double, "num"),
    ("iterations", ctypes.c_double, "num"),
    ("macro_steps", ctypes.c_double, "num"),
    ("coupling", ctypes.c_char_p, "str"),
    ("contact_scale", ctypes.c_double, "num"),
    ("rod_tol", ctypes.c_double, "num"),
    ("step_order", ctypes.c_double, "num"),
    ("strain_step", ctypes.c_char_p, "str"),
    ("step_tol", ctypes.c_double, "num"),
    ("strain_sub", ctypes.c_double, "num"),
    ("out", ctypes.c_char_p, "str"),
    ("checkpoint", ctypes.c_char_p, "str"),
    ("checkpoint_every", ctypes.c_double, "num"),
    ("resume", ctypes.c_char_p, "str"),
    ("progress", PROGRESSFN, "raw"),
    ("progress_user", ctypes.c_void_p, "raw"),
    ("cancel", ctypes.c_void_p, "raw"),
    ("data_dir", ctypes.c_char_p, "str"),
    ("log", LOGFN, "raw"),
    ("log_user", ctypes.c_void_p, "raw"),
]


class csRunDef(ctypes.Structure):
    _fields_ = [(n, t) for n, t, _ in RUNDEF_FIELDS]


class csRunResult(ctypes.Structure):
    _fields_ = [
        ("status", ctypes.c_int),
        ("verdict", ctypes.c_char * 16),
        ("message", ctypes.c_char * CS_ERROR_MSG_SIZE),
        ("t_end", ctypes.c_double),
        ("position", ctypes.c_double * 3),
        ("quat", ctypes.c_double * 4),
        ("tilt_deg", ctypes.c_double),
        ("wall_s", ctypes.c_double),
        ("real_time_factor", ctypes.c_double),
        ("robot_mass_g", ctypes.c_double),
        ("steps", ctypes.c_long),
        ("rejected_steps", ctypes.c_long),
        ("gain_projections", ctypes.c_long),
        ("ntimer", ctypes.c_int),
        ("timer_name", (ctypes.c_char * 16) * CS_RUN_MAX_TIMERS),
        ("timer_s", ctypes.c_double * CS_RUN_MAX_TIMERS),
        ("scene", ctypes.c_char * 32),
        ("conditions", ctypes.c_char * 16),
        ("legs", ctypes.c_char * 16),
        ("links", ctypes.c_int),
        ("macro_steps", ctypes.c_int),
        ("dt", ctypes.c_double),
        ("calibration", ctypes.c_char * CS_RUN_TEXT),
        ("calibration_rule", ctypes.c_char * 16),
        ("legs_auto_choice", ctypes.c_char * 1024),
        ("interrupted", ctypes.c_int),
    ]


class csBendDef(ctypes.Structure):
    """core/crawlsim.h csBendDef (one actuator bent by the analytic model, the rod or the
    strain leg)."""
    _fields_ = [
        ("model", ctypes.c_char_p),
        ("actuator", ctypes.c_char_p),
        ("actuator_set", ctypes.POINTER(ctypes.c_char_p)),
        ("n_actuator_set", ctypes.c_int),
        ("chambers", ctypes.c_char_p),
        ("p_max", ctypes.c_double),
        ("p_step", ctypes.c_double),
        ("tip_load", ctypes.c_double * 3),
        ("calibration", ctypes.c_char_p),
        ("cal_rule", ctypes.c_char_p),
        ("cal_drop", ctypes.c_char_p),
        ("mesh_size", ctypes.c_double),
        ("data_dir", ctypes.c_char_p),
        ("links", ctypes.c_double),
    ]


# int (*csController)(csSim* s, double t, double* p_cmd, void* user); p_cmd as an address
# (an int in Python: the controller's trampoline keeps one numpy view per address)
CONTROLLER = ctypes.CFUNCTYPE(ctypes.c_int, ctypes.c_void_p, ctypes.c_double, ctypes.c_void_p,
                              ctypes.c_void_p)

_P = ctypes.c_void_p  # csSim*
_E = ctypes.POINTER(csError)
_I, _D, _L = ctypes.c_int, ctypes.c_double, ctypes.c_long
# name -> (restype, argtypes)
PROTOTYPES = {
    "cs_defaultRunDef": (csRunDef, []),
    "cs_runDefValidate": (_I, [ctypes.POINTER(csRunDef), _E]),
    "cs_run": (_I, [ctypes.POINTER(csRunDef), ctypes.POINTER(csRunResult), _E]),
    "cs_simCreate": (_P, [ctypes.POINTER(csRunDef), _E]),
    "cs_simDestroy": (None, [_P]),
    "cs_simStep": (_I, [_P, _E]),
    "cs_simRunUntil": (_I, [_P, _D, _E]),
    "cs_simReset": (_I, [_P, _E]),
    "cs_simTime": (_D, [_P]),
    "cs_simMacroStep": (_D, [_P]),
    "cs_simChamberCount": (_I, [_P]),
    "cs_simLegCount": (_I, [_P]),
    "cs_simStepCount": (_L, [_P]),
    "cs_simSetPressureCommand": (_I, [_P, c_double_p, _E]),
    "cs_simSetController": (_I, [_P, CONTROLLER, ctypes.c_void_p, _E]),
    "cs_simGaitCommand": (None, [_P, _D, c_double_p]),
    "cs_simSupportPose": (None, [_P, c_double_p, c_double_p]),
    "cs_simSupportTwist": (None, [_P, c_double_p, c_double_p]),
    "cs_simFootForces": (None, [_P, c_double_p]),
    "cs_simPressures": (None, [_P, c_double_p]),
    "cs_simLegCenterline": (_I, [_P, _I, _I, c_double_p]),
    "cs_simStateSize": (_I, [_P]),
    "cs_simStateGet": (None, [_P, c_double_p]),
    "cs_simStateSet": (_I, [_P, c_double_p, _E]),
    "cs_defaultBendDef": (csBendDef, []),
    "cs_bendDefValidate": (_I, [ctypes.POINTER(csBendDef), _E]),
    "cs_bendRowCount": (_I, [ctypes.POINTER(csBendDef), _E]),
    "cs_bend": (_I, [ctypes.POINTER(csBendDef), _I, c_double_p, c_double_p, c_double_p,
                     ctypes.POINTER(_I), _E]),
    "cs_version": (ctypes.c_char_p, []),
    "cs_statusString": (ctypes.c_char_p, [_I]),
}

_lib = None


def _candidates():
    env = os.environ.get("CRAWLSIM_LIBRARY")
    if env:
        yield env, "$CRAWLSIM_LIBRARY"
        return
    here = os.path.dirname(os.path.abspath(__file__))
    try:
        from . import _paths  # written by cmake --install (tools/python/CMakeLists.txt)

        yield os.path.normpath(os.path.join(here, _paths.LIBDIR_FROM_PACKAGE, _paths.LIBNAME)), \
            "the install (crawlsim/_paths.py)"
    except ImportError:
        pass
    found = ctypes.util.find_library("crawlsim")
    if found:
        yield found, "the dynamic linker's search"


def lib():
    """The loaded library with its prototypes set (loaded on the first call)."""
    global _lib
    if _lib is not None:
        return _lib
    tried = []
    for path, where in _candidates():
        try:
            handle = ctypes.CDLL(path)
        except OSError as e:
            tried.append(f"{path} ({where}): {str(e).splitlines()[0]}")
            continue
        for name, (res, args) in PROTOTYPES.items():
            try:
                fn = getattr(handle, name)
            except AttributeError:
                raise Error(f"{path}: libcrawlsim lacks {name}: the package and the library "
                            "are from different versions (reinstall both: cmake --install)") from None
            fn.restype = res
            fn.argtypes = args
        _lib = handle
        return _lib
    raise Error("libcrawlsim not found: " + ("; ".join(tried) if tried else
                "no $CRAWLSIM_LIBRARY, no install record (crawlsim/_paths.py) and nothing on "
                "the linker's path; install with `cmake --install build --prefix ~/.local` "
                "(docs/reference/python.md)"))


def check(status, err):
    """Raise crawlsim.Error carrying the C message unless status is CS_OK (0)."""
    if status != 0:
        raise error(status, err)


def error(status, err):
    """crawlsim.Error for a failed status: the message the library wrote in err, or the
    status's own text when it wrote none."""
    msg = err.msg.decode("utf-8", "replace") if err is not None else ""
    if not msg:
        msg = lib().cs_statusString(status).decode()
    return Error(msg, status, STATUS_NAMES.get(status, f"status {status}"))

"""crawlsim: the soft crawling robot's co-simulator from Python (issue 35).

A thin package over the shared library libcrawlsim (core/crawlsim.h) with ctypes and numpy:

    import crawlsim
    r = crawlsim.run(scene="flat-road", t_end=2.0)      # a whole run, its tracks as arrays
    r.verdict, r.position, r.tracks.t, r.tracks.position

    with crawlsim.Sim(scene="flat-road") as sim:          # stepped from Python
        sim.set_controller(lambda s, t, p: s.gait_command(t, out=p))
        sim.run_until(1.0)
        pos, quat = sim.support_pose()

    f = crawlsim.read_run("run.h5")                       # any run file, as arrays

    b = crawlsim.bend(model="rod", actuator="leg", chambers="1,2", p_max=0.4, p_step=0.05)
    b.pressure, b.angle_deg, b.angle_total, b.tip        # one actuator bent, as arrays

Errors (bad input, a failed step, a step after a failure) raise crawlsim.Error carrying the
C library's one-line message. Manual: docs/reference/python.md.
"""

from .bend import BendResult, bend
from .errors import Error
from .results import LEGS, RunFile, heading_deg, read_run, tilt_deg
from .rundef import RunDef
from .run import RunResult, run
from .sim import Sim

NCHAMBER = 96
NLEG = 8


def version():
    """The library's version string (what every output file records)."""
    from . import _lib

    return _lib.lib().cs_version().decode()


def library_path():
    """The path of the libcrawlsim that was loaded."""
    from . import _lib

    return _lib.lib()._name


__all__ = ["BendResult", "bend", "Error", "RunDef", "RunFile", "RunResult", "Sim", "read_run", "run", "heading_deg",
           "tilt_deg", "version", "library_path", "LEGS", "NCHAMBER", "NLEG"]

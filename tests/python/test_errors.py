"""Bad input through the package raises crawlsim.Error with the C library's one-line message
and never crashes the interpreter; a failed step changes nothing; a step after a failure is
refused until reset() or a state is set; an exception in a controller comes back out of step()."""

import math

import numpy as np
import pytest

import crawlsim
from conftest import FAST


@pytest.fixture(scope="module")
def sim():
    s = crawlsim.Sim(**FAST)
    yield s
    s.close()


@pytest.mark.parametrize("field,value,words", [
    ("friction", -0.5, "friction"), ("t_end", -1.0, "t-end"), ("dt", 1.0, "dt"),
    ("links", 2.5, "links"), ("iterations", 0, "iterations"), ("legs", "wings", "wings"),
    ("scene", "moon", "moon"), ("coupling", "glue", "glue"), ("tau", -1.0, "tau"),
    ("contact_scale", 1e9, "contact"), ("conditions", "mars", "mars")])
def test_out_of_range_definition_raises_naming_the_field(field, value, words):
    d = crawlsim.RunDef(**{field: value})
    with pytest.raises(crawlsim.Error, match=words) as e:
        d.validate()
    assert e.value.status < 0 and e.value.status_name.startswith("CS_ERR_")
    with pytest.raises(crawlsim.Error, match=words):
        crawlsim.Sim(d)


NUMBERS = ["friction", "pressure_scale", "t_end", "dt", "output_dt", "ramp", "tau", "gravity",
           "support_mass_kg", "slope_deg", "links", "iterations", "macro_steps", "contact_scale",
           "rod_tol", "legs_tol_mm"]


@pytest.mark.parametrize("field", NUMBERS)
def test_infinite_numbers_never_crash(field):
    """+-inf in any number: refused with an Error or run (tau = inf is a chamber that never
    fills), never a crash. NaN is the default, so it is not bad input."""
    for v in (math.inf, -math.inf):
        try:
            with crawlsim.Sim(**{**FAST, field: v}) as s:
                s.step(3)
        except crawlsim.Error as e:
            assert str(e) and e.status < 0


def test_missing_files_are_named(tmp_path):
    missing = tmp_path / "no_such_gait.csv"
    with pytest.raises(crawlsim.Error, match="no_such_gait.csv"):
        crawlsim.Sim(gait=missing, **FAST)
    bad = tmp_path / "bad.csv"
    bad.write_text("time,1\n0,zero\n")
    with pytest.raises(crawlsim.Error, match="bad.csv"):
        crawlsim.run(gait=bad, t_end=0.1, **FAST)


def test_bad_pressure_commands_raise_and_change_nothing(sim):
    x0 = sim.get_state()
    for p, words in [(np.zeros(95), "96"), (np.full(96, 2.0), ""), ([math.nan] * 96, ""),
                     ("no", "96"), (np.full(96, -0.1), "")]:
        with pytest.raises(crawlsim.Error, match=words):
            sim.set_pressures(p)
    assert np.array_equal(sim.get_state(), x0)


def test_bad_read_out_arguments_raise(sim):
    with pytest.raises(crawlsim.Error):
        sim.centerline(8)
    with pytest.raises(crawlsim.Error):
        sim.centerline("Z")
    with pytest.raises(crawlsim.Error):
        sim.centerline(0, npts=1)
    with pytest.raises(crawlsim.Error):
        sim.foot_forces(out=np.zeros((8, 3), dtype=np.float32))
    with pytest.raises(crawlsim.Error):
        sim.set_state(np.zeros(3))
    with pytest.raises(crawlsim.Error):
        sim.set_controller(42)


def test_failed_step_changes_nothing_and_blocks_the_next_until_reset(sim):
    sim.reset()
    sim.step(5)
    x0 = sim.get_state()

    def broken(s, t, p):
        raise ValueError("controller broke")

    sim.set_controller(broken)
    with pytest.raises(ValueError, match="controller broke") as e:
        sim.step()
    assert isinstance(e.value.__cause__, crawlsim.Error)  # the C message travels along
    assert np.array_equal(sim.get_state(), x0)
    sim.set_controller(None)
    with pytest.raises(crawlsim.Error, match="fail"):
        sim.step()  # a step after a failed step
    sim.set_state(x0)  # clears the failure
    sim.step()
    assert sim.t > x0[0]


def test_controller_commanding_out_of_range_fails_the_step(sim):
    sim.reset()

    def too_high(s, t, p):
        p[:] = 3.0  # MPa, above the 1 MPa of any gait

    sim.set_controller(too_high)
    with pytest.raises(crawlsim.Error):
        sim.step()
    assert sim.t == 0.0
    sim.set_controller(None)
    sim.reset()
    sim.step()


def test_closed_sim_raises():
    s = crawlsim.Sim(**FAST)
    s.close()
    s.close()
    with pytest.raises(crawlsim.Error, match="close"):
        s.step()


def test_unreadable_run_file_raises(tmp_path):
    p = tmp_path / "not.h5"
    p.write_text("not HDF5")
    with pytest.raises(crawlsim.Error, match="not.h5"):
        crawlsim.read_run(p)
    with pytest.raises(crawlsim.Error, match="no such file"):
        crawlsim.read_run(tmp_path / "absent.h5")

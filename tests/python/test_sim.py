"""Stepping from Python: time and step counts, the state round trip (bit for bit), reset, the
read-outs' shapes and that they are written in place, and a robot commanded to zero pressure
staying where it settled, carried by its feet."""

import numpy as np
import pytest

import crawlsim
from conftest import FAST


@pytest.fixture(scope="module")
def sim():
    s = crawlsim.Sim(**FAST)
    yield s
    s.close()


def test_step_advances_by_the_macro_step(sim):
    sim.reset()
    n0 = sim.steps
    sim.step(10)
    assert sim.steps - n0 == 10
    assert sim.t == pytest.approx(10 * sim.macro_step, rel=1e-12)
    sim.run_until(0.05)
    assert abs(sim.t - 0.05) <= 0.5 * sim.macro_step


def test_state_round_trip_repeats_steps_bit_for_bit():
    """Steps after set_state repeat bit for bit (core/sim_model.h: the integrators restart from
    the state), on rod legs at the scene's own elements (their integrators restart from the
    state; tests/core/test_state.c checks the same in C)."""
    with crawlsim.Sim(scene="flat-road", legs="rod") as sim:
        sim.step(20)
        x = sim.get_state()
        sim.step(30)
        ends = []
        for _ in range(2):
            sim.state = x
            assert np.array_equal(sim.get_state(), x)
            sim.step(30)
            ends.append((sim.get_state(), sim.support_pose()[0].copy()))
        assert np.array_equal(ends[0][0], ends[1][0])
        assert np.array_equal(ends[0][1], ends[1][1])
        assert not np.array_equal(ends[0][0], x)  # the steps did something


def test_reset_returns_to_the_settled_state(sim):
    sim.reset()
    x0 = sim.get_state()
    sim.step(15)
    assert not np.array_equal(sim.get_state(), x0)
    sim.reset()
    assert sim.t == 0.0
    assert np.array_equal(sim.get_state(), x0)


def test_read_outs_have_their_shapes_and_fill_the_given_arrays(sim):
    sim.reset()
    sim.step(5)
    pos, quat = sim.support_pose()
    assert pos.shape == (3,) and quat.shape == (4,)
    assert np.linalg.norm(quat) == pytest.approx(1.0, abs=1e-9)
    v, w = sim.support_twist()
    assert v.shape == (3,) and w.shape == (3,)
    cl = np.zeros((8, 25, 3))
    ptr = cl.ctypes.data
    got = sim.centerlines(25, out=cl)
    assert got is cl and cl.ctypes.data == ptr  # written in place, no copy
    assert np.all(np.isfinite(cl)) and np.any(cl != 0)
    # each leg hangs below the support's hip: the foot is lower than the hip
    assert np.all(cl[:, -1, 1] < cl[:, 0, 1])
    assert np.array_equal(sim.centerline("C", 25), cl[2])
    ff = sim.foot_forces()
    assert ff.shape == (8, 3) and np.all(np.isfinite(ff))
    p = sim.pressures()
    assert p.shape == (96,) and np.all(p >= -1e-12)
    g = sim.gait_command(1.0)
    assert g.shape == (96,) and g.max() > 0  # the flat road's gait inflates chambers by 1 s
    assert sim.gait_command(-1.0).max() == 0.0


def test_zero_pressure_command_stands_on_its_feet():
    """Vented chambers (no gait): the robot stays where it settled, and its feet carry the
    support's weight. Under `paper` (the scene's conditions) gravity acts on the support alone,
    m g = 0.05 kg x 9.81 m/s^2 = 0.4905 N; tolerance 5 %, as tests/tools/test_output_units.py
    for the feet's mean (what is left is the support's vertical momentum change)."""
    with crawlsim.Sim(**FAST) as s:
        s.set_pressures(np.zeros(96))
        s.run_until(0.5)
        pos, _ = s.support_pose()
        fy = []
        for _ in range(100):
            s.step()
            fy.append(s.foot_forces()[:, 1].sum())
        pos2, _ = s.support_pose()
    # 1 mm: well below the 39 mm stride of one gait phase; a standing robot creeps by the
    # soft contact's relaxation only
    assert np.all(np.abs(pos2[[0, 2]]) < 1.0), pos2
    assert np.mean(fy) == pytest.approx(0.05 * 9.81, rel=0.05)

"""A controller in Python replaying the gait table gives the C track bit for bit (issue 35):
the same states step by step as the table itself in a second simulation, and the same samples
as a whole run of crawlsim.run (cs_run) writes. A controller that modulates the table does
change the track (the callback is not ignored)."""

import numpy as np

import crawlsim
from conftest import FAST

T_END = 1.2  # s: the first row's ramp and plateau and the start of the second (the feet move)


def replay(sim, t, p):
    sim.gait_command(t, out=p)


def test_replaying_controller_steps_as_the_gait_bit_for_bit():
    with crawlsim.Sim(**FAST) as a, crawlsim.Sim(**FAST) as b:
        b.set_controller(replay)
        assert np.array_equal(a.get_state(), b.get_state())
        n = int(round(T_END / a.macro_step))
        for k in range(n):
            a.step()
            b.step()
            if k % 50 == 49 or k == n - 1:
                assert np.array_equal(a.get_state(), b.get_state()), f"differs at t = {a.t}"
        assert abs(a.support_pose()[0][0]) > 0.1  # it did move (mm)


def test_replaying_controller_gives_the_whole_runs_samples(tmp_path):
    out = tmp_path / "c.h5"
    r = crawlsim.run(t_end=T_END, out=out, **FAST)
    assert r.ok and r.tracks is not None and out.is_file()
    trk = r.tracks
    with crawlsim.Sim(**FAST) as s:
        s.set_controller(replay)
        pos = np.empty((len(trk.t), 3))
        quat = np.empty((len(trk.t), 4))
        for i, t in enumerate(trk.t):
            s.run_until(t)
            s.support_pose(out_pos=pos[i], out_quat=quat[i])
    assert np.array_equal(pos, trk.position)
    assert np.array_equal(quat, trk.orientation)
    assert np.array_equal(r.position, trk.position[-1])


def test_modulated_controller_changes_the_track():
    def half_right(sim, t, p):
        sim.gait_command(t, out=p)
        p[48:] *= 0.5  # legs E..H (labels 49..96)

    with crawlsim.Sim(**FAST) as a, crawlsim.Sim(**FAST) as b:
        b.set_controller(half_right)
        a.run_until(T_END)
        b.run_until(T_END)
        assert not np.array_equal(a.get_state(), b.get_state())
        pa, pb = a.pressures(), b.pressures()
        right = np.where(pa[48:] > 0.01)[0] + 48
        assert len(right) > 0
        # the lag is linear in the command; 1e-3: CVODE's tolerances on the pressures
        assert np.allclose(pb[right], 0.5 * pa[right], rtol=1e-3)
        assert np.allclose(pb[:48], pa[:48], rtol=1e-3, atol=1e-9)

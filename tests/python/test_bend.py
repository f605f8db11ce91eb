"""crawlsim.bend (core/crawlsim.h cs_bend) against `crawlsim bend`: the library's sweep and the
command's file hold the same rows (the command runs the same solver, core/cs_bend.c, so they
must be equal to the last bit, whatever the model computes), and bad input raises
crawlsim.Error with the library's message. The reference numbers are the command's own, read
from the file it writes, never typed in here."""

import os
import subprocess

import h5py
import numpy as np
import pytest

import crawlsim


def cli_bend(tmp_path, *args):
    exe = os.environ.get("CS_CRAWLSIM_EXE")
    if not exe or not os.path.exists(exe):
        pytest.fail("CS_CRAWLSIM_EXE (the built crawlsim, tests/python/CMakeLists.txt) is not set")
    out = tmp_path / "bend.h5"
    subprocess.run([exe, "bend", *args, "--out", str(out)], check=True, capture_output=True,
                   env=dict(os.environ, CRAWLSIM_DATA_DIR=os.environ["CS_SOURCE_DIR"]))
    with h5py.File(out, "r") as f:
        return {k: f[k][()] for k in ("pressure", "angle_deg", "angle_total_deg", "tip_position")}


def same_rows(b, ref):
    assert b.pressure.shape == ref["pressure"].shape
    np.testing.assert_array_equal(b.pressure, ref["pressure"])
    np.testing.assert_array_equal(b.angle_deg, ref["angle_deg"])
    np.testing.assert_array_equal(b.tip, ref["tip_position"])
    np.testing.assert_allclose(b.angle_total, ref["angle_total_deg"], rtol=0, atol=1e-12)


@pytest.mark.parametrize("chambers,p_max,p_step,actuator", [
    ("1,2", 0.4, 0.05, "baseline"), ("1", 0.33, 0.05, "fig1"), ("2,3,4", 0.2, 0.07, "leg")])
def test_analytic_bend_equals_the_commands_rows(tmp_path, chambers, p_max, p_step, actuator):
    ref = cli_bend(tmp_path, "--model", "analytic", "--actuator", actuator, "--chambers",
                   chambers, "--p-max", str(p_max), "--p-step", str(p_step), "--set", "S1=40")
    b = crawlsim.bend(model="analytic", actuator=actuator, chambers=chambers, p_max=p_max,
                      p_step=p_step, set={"S1": 40})
    same_rows(b, ref)
    assert b.pressure[-1] == p_max and b.angle_total[-1] > 0  # it bends, up to p_max


def test_rod_bend_equals_the_commands_rows(tmp_path):
    """The rod on the analytic calibration with a tip load (the mission's table is what
    `bend --model rod` takes by default; the command's own test covers it)."""
    ref = cli_bend(tmp_path, "--model", "rod", "--calibration", "analytic", "--chambers", "1",
                   "--p-max", "0.2", "--p-step", "0.05", "--tip-load", "0,0.01,0")
    b = crawlsim.bend(model="rod", calibration="analytic", chambers=[1], p_max=0.2,
                      p_step=0.05, tip_load=(0, 0.01, 0),
                      data_dir=os.environ["CS_SOURCE_DIR"])
    same_rows(b, ref)


def test_rod_bend_on_the_mission_table_equals_the_command(tmp_path):
    ref = cli_bend(tmp_path, "--model", "rod", "--p-max", "0.1", "--p-step", "0.05")
    b = crawlsim.bend(model="rod", actuator="leg", chambers="1,2", p_max=0.1, p_step=0.05,
                      data_dir=os.environ["CS_SOURCE_DIR"])
    same_rows(b, ref)


def test_strain_bend_equals_the_commands_rows(tmp_path):
    """The strain leg (the flat road's leg) with a tip load and a richer basis: the library's
    sweep and the command's file hold the same rows."""
    ref = cli_bend(tmp_path, "--model", "strain", "--links", "3", "--p-max", "0.2",
                   "--p-step", "0.1", "--tip-load", "0.02,0,0")
    b = crawlsim.bend(model="strain", links=3, p_max=0.2, p_step=0.1, tip_load=(0.02, 0, 0),
                      data_dir=os.environ["CS_SOURCE_DIR"])
    same_rows(b, ref)
    assert b.actuator == "leg" and b.angle_total[-1] > 0


@pytest.mark.parametrize("kw,words", [
    (dict(model="fe"), "fe"), (dict(actuator="wing"), "wing"), (dict(chambers="5"), "chambers"),
    (dict(p_max=-0.1), "p-max"), (dict(p_step=0.0), "p-step"),
    (dict(p_max=float("inf")), "p-max"), (dict(set=["S1=-3"]), "S1"),
    (dict(set=["nonsense"]), "nonsense"), (dict(tip_load=(0, 1, 0)), "tip-load"),
    (dict(model="rod", cal_rule="glue"), "glue"), (dict(model="rod", cal_drop="all"), "all"),
    (dict(model="rod", p_max=0.5), "calibration's range"),
    (dict(model="rod", calibration="/nonexistent.h5"), "nonexistent"),
    (dict(model="strain", links=9), "links"), (dict(model="rod", links=2), "links"),
    (dict(model="strain", mesh_size=2), "mesh-size")])
def test_bad_input_raises_with_the_message(kw, words):
    with pytest.raises(crawlsim.Error, match=words) as e:
        crawlsim.bend(**kw)
    assert e.value.status < 0

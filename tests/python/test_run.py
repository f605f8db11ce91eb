"""crawlsim.run: a whole run returns its result and its tracks as arrays (the file kept with
out=, read back and removed without), the result's end pose is the last sample's, the plotting
example reads the file, and what a run has to say reaches the caller's callbacks (log,
progress) while the library writes nothing to stdout or stderr."""

import os
import subprocess
import sys

import numpy as np
import pytest

import crawlsim
from conftest import FAST, SOURCE_DIR


@pytest.fixture(scope="module")
def kept(tmp_path_factory):
    out = tmp_path_factory.mktemp("run") / "r.h5"
    return crawlsim.run(t_end=0.5, out=out, **FAST), out


def test_run_returns_result_and_tracks(kept):
    r, out = kept
    assert r.ok and r.status_name == "CS_OK" and r.message == ""
    assert r.verdict in ("crawls", "stands", "tips over")
    assert r.legs == "rod" and r.links == 2 and r.scene == "flat-road"
    assert r.t_end == pytest.approx(0.5, abs=1e-9)
    t = r.tracks
    assert t.t[0] == 0.0 and t.t[-1] == pytest.approx(0.5, abs=1e-9)
    n = len(t.t)
    assert t.position.shape == (n, 3) and t.orientation.shape == (n, 4)
    assert t.pressure.shape == (n, 96) and t.centerline.shape[:2] == (8, n)
    assert t.foot_force.shape == (n, 8, 3) and t.stance.shape == (n, 8)
    assert np.array_equal(r.position, t.position[-1])
    assert t.attrs["version"] == crawlsim.version()
    assert out.is_file() and out.with_suffix(".xdmf").is_file()
    assert r.steps > 0 and "legs" in r.timers


def test_run_without_out_leaves_no_file(tmp_path, monkeypatch):
    monkeypatch.setenv("TMPDIR", str(tmp_path))
    import tempfile

    monkeypatch.setattr(tempfile, "tempdir", None)
    r = crawlsim.run(t_end=0.1, **FAST)
    assert r.ok and r.tracks is not None and len(r.tracks.t) > 5
    assert r.out is None
    assert os.listdir(tmp_path) == []


def test_read_run_gives_the_same_arrays(kept):
    r, out = kept
    f = crawlsim.read_run(out)
    assert np.array_equal(f.position, r.tracks.position)
    assert f.heading.shape == f.t.shape
    assert abs(f.heading[0]) < 1.0  # deg: the flat road starts heading along +x


def test_plot_example_reads_a_run(kept, tmp_path):
    _, out = kept
    png = tmp_path / "r.png"
    ex = os.path.join(SOURCE_DIR, "tools", "python", "examples", "plot_run.py")
    p = subprocess.run([sys.executable, ex, str(out), "-o", str(png)], capture_output=True,
                       text=True)
    assert p.returncode == 0, p.stderr
    assert png.stat().st_size > 10000
    bad = subprocess.run([sys.executable, ex, str(tmp_path / "absent.h5")], capture_output=True,
                         text=True)
    assert bad.returncode == 1 and bad.stderr.count("\n") == 1 and "absent.h5" in bad.stderr


def test_heading_of_a_quaternion_about_y():
    for deg in (-170.0, -30.0, 0.0, 12.5, 90.0):
        a = np.radians(deg) / 2
        q = np.array([np.cos(a), 0.0, np.sin(a), 0.0])  # a turn about world +y (up)
        assert crawlsim.heading_deg(q) == pytest.approx(deg, abs=1e-9)
    assert crawlsim.tilt_deg([1, 0, 0, 0]) == 0.0


def test_callbacks_get_the_lines_and_nothing_is_printed(capfd):
    lines, calls = [], []
    r = crawlsim.run(t_end=1.0, log=lines.append,
                     progress=lambda t, x, wall: calls.append((t, x, wall)),
                     legs="rod", links=2, rod_tol=20)  # the cheapest rod of the chart
    out, err = capfd.readouterr()  # file descriptors 1 and 2, C's writes included
    assert r.ok
    assert out == "" and err == ""
    assert len(lines) >= 4 and all("\n" not in line for line in lines)
    assert any(line.startswith("stance check") for line in lines)
    # once per simulated second: at t = 1 s (1000 steps of 1 ms), where the run ended
    assert len(calls) == 1
    t, x, wall = calls[0]
    assert t == pytest.approx(1.0, abs=1e-9) and wall > 0
    assert x == pytest.approx(tuple(r.position), abs=1e-12)  # the same state read twice


def test_progress_must_be_callable():
    with pytest.raises(crawlsim.Error, match="progress"):
        crawlsim.RunDef(progress=3)


def test_run_ends_when_the_crawl_table_is_over(tmp_path):
    """a gate with a crawl statement and no t_end: the run ends when the table's clock
    (t - hold + skip) reaches the table's end (cs_runOverAt, as `crawlsim run`): a crawl that
    skips 0.1 s ends the run 0.1 s before the same table with a crawl that never ends, and the
    file says why"""
    gait = tmp_path / "g.csv"
    gait.write_text("time,A_II1_O1\n0,0\n0.5,0.05\n")
    head = "design ramp 0.05 lag 0.02 ptol 0.005 maxwait 0.6\ngate 0.05 AE\n"
    ends = {}
    for name, zend in (("skip", "-1e6"), ("full", "1e6")):
        gate = tmp_path / (name + ".gate")
        gate.write_text(head + "crawl 0.05 0.05 5 %s 0\n" % zend)
        r = crawlsim.run(gait=str(gait), gate=str(gate), **FAST)
        skip = float(r.tracks.attrs["crawl_skip_s"])
        held = float(r.tracks.attrs["gate_held_s"])
        reason = r.tracks.attrs["end_reason"]
        reason = reason.decode() if isinstance(reason, bytes) else reason
        ends[name] = (r.t_end, skip, held, reason)
        assert r.tracks.t[-1] == pytest.approx(r.t_end, abs=1e-9)
    t_full, skip_full, _, why_full = ends["full"]
    t_skip, skip, held, why = ends["skip"]
    assert skip_full == 0 and skip > 0 and "the table's end" in why_full
    assert "the gait is over" in why and t_skip < t_full - 0.05
    assert abs(t_skip - held + skip - t_full) <= 0.01 + 1e-9  # to the output row

"""The heading-control example (tools/python/examples/heading_control.py) turns the robot to a
commanded heading on the flat road through contact and friction only: within 5 deg of -20 deg
after 9 s, where the gait alone (kp 0) keeps its heading near 0. On the cheapest rod legs
(2 elements per segment, CVODE tolerances x 20: a few CPU seconds); the scene's own legs are
measured in docs/reference/python.md."""

import os
import re
import subprocess
import sys

from conftest import SOURCE_DIR

EXAMPLE = os.path.join(SOURCE_DIR, "tools", "python", "examples", "heading_control.py")
CHEAP = ["--links", "2", "--rod-tol", "20", "--heading", "-20"]


def final_heading(args, tmp_path):
    p = subprocess.run([sys.executable, EXAMPLE, *CHEAP, *args, "-o", str(tmp_path / "h.png"),
                        "--csv", str(tmp_path / "h.csv")], capture_output=True, text=True)
    m = re.search(r"final heading (\S+) deg", p.stdout)
    assert m, p.stdout + p.stderr
    assert (tmp_path / "h.png").stat().st_size > 10000
    return p.returncode, float(m.group(1))


def test_controller_reaches_the_commanded_heading(tmp_path):
    rc, psi = final_heading([], tmp_path)
    assert rc == 0 and abs(psi + 20) <= 5, psi


def test_without_feedback_the_heading_stays(tmp_path):
    rc, psi = final_heading(["--kp", "0"], tmp_path)
    assert rc == 2 and abs(psi) < 5, psi

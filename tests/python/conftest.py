"""Shared settings of the Python package's tests (tests/python/CMakeLists.txt runs each file
against the package installed in a temporary prefix, run_pytest.sh)."""

import os

import pytest

# The cheapest honest configuration of the flat road for tests that check plumbing (shapes,
# errors, determinism), not physics: rod legs, 2 elements per segment, CVODE tolerances x 20
# (robot/levels.csv: 0.17 CPU s per simulated second, 26 mm from the reference over 9 s).
FAST = dict(scene="flat-road", legs="rod", links=2, rod_tol=20)

SOURCE_DIR = os.environ.get("CS_SOURCE_DIR", os.path.abspath(
    os.path.join(os.path.dirname(__file__), "..", "..")))


@pytest.fixture(scope="module")
def crawlsim():
    import crawlsim as cs

    return cs

#!/usr/bin/env bash
# run_pytest.sh PREFIX TEST.py: one pytest file against the package installed in PREFIX
# (install_prefix.sh): only that site directory on the path (no user site, no source tree), no
# LD_LIBRARY_PATH, from a scratch working directory.
set -euo pipefail
prefix=$1 test=$2
site=$(cat "$prefix/pythonpath.txt")
export PYTHONPATH=$site PYTHONNOUSERSITE=1 CRAWLSIM_TEST_PREFIX=$prefix
# no __pycache__ left in the source tree (tests/python)
export PYTHONDONTWRITEBYTECODE=1
unset LD_LIBRARY_PATH CRAWLSIM_LIBRARY
work=$(mktemp -d "${TMPDIR:-/tmp}/crawlsim-pytest.XXXXXX")
trap 'rm -rf "$work"' EXIT
cd "$work"
/usr/bin/python3 -m pytest -q -p no:cacheprovider --rootdir "$(dirname "$test")" "$test"

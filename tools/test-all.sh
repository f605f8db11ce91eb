#!/usr/bin/env bash
# Run the whole crawlsim test suite: installs what is missing, then
#   1. a RelWithDebInfo build with warnings as errors, every ctest test;
#   2. an ASan+UBSan build, every test not labelled `slow`;
#   3. a bounded fuzz run (tools/fuzz-long.sh --ci: each libFuzzer harness of tests/fuzz for
#      FUZZ_SECONDS, default 12 s, about 1.5 min in all). Fuzzers that do not build are a
#      failure, not a skip: install-deps.sh installs all they need (clang-14, its sanitizer
#      runtimes, libomp-14-dev), so a machine where they do not build is a broken check.
# Exit status 0 only if all pass. Used by .ci/run. Build trees: build-test/, build-asan/,
# build-fuzz/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install-deps.sh
JOBS=${JOBS:-2}

echo "== release build (warnings are errors) =="
cmake -S . -B build-test -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCS_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build build-test -j"$JOBS"
ctest --test-dir build-test --output-on-failure -j"$JOBS"

echo "== sanitizer build (ASan + UBSan) =="
cmake -S . -B build-asan -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCS_ENABLE_SANITIZERS=ON \
  -DCS_WARNINGS_AS_ERRORS=ON >/dev/null
cmake --build build-asan -j"$JOBS"
ASAN_OPTIONS=detect_leaks=1:abort_on_error=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --test-dir build-asan --output-on-failure -LE slow -j"$JOBS"

echo "== bounded fuzz run (libFuzzer + ASan + UBSan, tests/fuzz) =="
fuzz_rc=0
JOBS=$JOBS bash tools/fuzz-long.sh --ci "${FUZZ_SECONDS:-12}" || fuzz_rc=$?
if [ "$fuzz_rc" -eq 3 ]; then
  echo "== FAILED: the fuzzers do not build here (see above); tools/install-deps.sh should have" \
       "installed everything they need: a check that cannot run is a failed check ==" >&2
  exit 3
elif [ "$fuzz_rc" -ne 0 ]; then
  exit "$fuzz_rc"
fi
echo "== all checks passed (release, sanitizers, fuzz) =="

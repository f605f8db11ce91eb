#!/usr/bin/env bash
# Run the whole crawlsim test suite: installs what is missing, then
#   1. a RelWithDebInfo build with warnings as errors, every ctest test;
#   2. an ASan+UBSan build, every test not labelled `slow`.
# Exit status 0 only if both pass. Used by .ci/run. Build trees: build-test/, build-asan/.
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

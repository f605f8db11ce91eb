#!/usr/bin/env bash
# test_install.sh BUILD_DIR SOURCE_DIR CC [CFLAGS...]: `cmake --install` of the build into a
# temporary prefix, then the C example (tools/examples/crawl_controller.c) built against the
# installed library twice, through pkg-config and through find_package(crawlsim), and run on
# the flat road with rod legs for 0.3 s. Checks that the library exports the cs_ API alone and
# that the installed data is there. Exit 0 on success.
set -euo pipefail
B=$1; S=$2; CC=$3; shift 3
EXTRA=("$@")
T=$(mktemp -d); trap 'rm -rf "$T"' EXIT
fail() { echo "test_install: $*" >&2; exit 1; }

cmake --install "$B" --prefix "$T/prefix" > "$T/install.log" || fail "cmake --install failed"
pc=$(find "$T/prefix" -name crawlsim.pc | head -1)
[ -n "$pc" ] || fail "no crawlsim.pc installed"
export PKG_CONFIG_PATH=$(dirname "$pc")
libdir=$(pkg-config --variable=libdir crawlsim)
[ -f "$libdir/libcrawlsim.so" ] || fail "pkg-config's libdir $libdir has no libcrawlsim.so"
[ -f "$T/prefix/include/crawlsim/crawlsim.h" ] || fail "no header include/crawlsim/crawlsim.h"
[ -f "$T/prefix/share/crawlsim/terrains/flat_road.terrain" ] || fail "no installed terrains"
[ -f "$T/prefix/share/crawlsim/robot/calibration_fe_leg_modes_sym.h5" ] || fail "no calibration"

# the library exports the public API alone (-fvisibility=hidden, --exclude-libs)
others=$(nm -D --defined-only "$libdir/libcrawlsim.so" | awk '$2 ~ /[TDBR]/ {print $3}' |
         grep -v '^cs_' | grep -v '^_' || true)
[ -z "$others" ] || fail "exports more than cs_*: $(echo $others | head -c 300)"
nm -D --defined-only "$libdir/libcrawlsim.so" | grep -q ' T cs_simStep$' || fail "no cs_simStep"

# the example through pkg-config (warnings are errors: the header must be clean C17)
"$CC" -std=c17 -Wall -Wextra -Wpedantic -Werror "${EXTRA[@]}" "$S/tools/examples/crawl_controller.c" \
  $(pkg-config --cflags --libs crawlsim) -lm -Wl,-rpath,"$libdir" -o "$T/ex_pc" ||
  fail "the example does not build with pkg-config"
# and through the CMake package
mkdir -p "$T/cm"
cat > "$T/cm/CMakeLists.txt" <<CM
cmake_minimum_required(VERSION 3.20)
project(example C)
find_package(crawlsim REQUIRED)
add_executable(ex_cmake $S/tools/examples/crawl_controller.c)
target_compile_options(ex_cmake PRIVATE ${EXTRA[*]:-})
target_link_options(ex_cmake PRIVATE ${EXTRA[*]:-})
target_link_libraries(ex_cmake PRIVATE crawlsim::crawlsim m)
CM
cmake -S "$T/cm" -B "$T/cm/build" -DCMAKE_C_COMPILER="$CC" -DCMAKE_PREFIX_PATH="$T/prefix" \
  > "$T/cm.log" 2>&1 || { cat "$T/cm.log"; fail "find_package(crawlsim) failed"; }
cmake --build "$T/cm/build" > "$T/cmb.log" 2>&1 || { cat "$T/cmb.log"; fail "CMake build failed"; }

# run it from elsewhere (no source tree on the way; the library finds its data beside itself)
unset CRAWLSIM_DATA_DIR
cd "$T"
"$T/ex_pc" rod 0.3 > "$T/out.txt" 2> "$T/err.txt" || { cat "$T/err.txt"; fail "the example failed"; }
cat "$T/out.txt"
grep -q '^0.300 ' "$T/out.txt" || fail "the track does not reach t = 0.3 s"
grep -q 'the controller was asked' "$T/out.txt" || fail "no summary line"
"$T/cm/build/ex_cmake" rod 0.1 > /dev/null 2>&1 || fail "the CMake-built example failed"
echo "test_install: ok"

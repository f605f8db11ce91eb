#!/usr/bin/env bash
# Fuzz the readers of user files with libFuzzer (README "Fuzzing", tests/fuzz/).
#
#   bash tools/fuzz-long.sh [--runs N] [--hours H] [--only NAME[,NAME...]] [--update-corpus]
#                           [--coverage | --coverage-only]
#       the long campaign: each harness in turn (one at a time, nice -n 15) until N executions
#       (default 10^7; gait_design_build, the whole `crawlsim gait design`, 10^5) or H hours
#       (default 4) per harness. Work files in build-fuzz/fuzz-long/<harness>/ (corpus,
#       crashes, log); a summary table in build-fuzz/fuzz-long/summary.md. --update-corpus
#       minimises each grown corpus into tests/fuzz/corpus/<harness>/ (to commit); --coverage
#       builds build-fuzz-cov/ (clang source coverage) and reports the readers' line and
#       branch coverage of the final corpus (needs llvm-14); --coverage-only does only that, on
#       the corpora an earlier campaign left. Each harness's row of the summary is replaced when
#       it runs again (--only), the others stay.
#   bash tools/fuzz-long.sh --ci [SECONDS]
#       the bounded run of tools/test-all.sh: every harness SECONDS (default 12) from the seeds
#       and the committed corpus, nothing written into the source tree. Exit 1 if a harness
#       found a crash, a leak, a sanitizer report, a broken contract or a hang; 3 if the
#       fuzzers do not build (no clang-14, or a compile error).
#
# Build: build-fuzz/ or $FUZZ_BUILD (clang-14, CS_BUILD_FUZZERS=ON, ASan + UBSan, LeakSanitizer
# on), -j1 ($JOBS). Each crash artifact is printed with how to make it a regression test: copy it to
# tests/fuzz/regressions/<harness>/<name> with a <name>.expect (tests/fuzz/fuzz_replay.c), and
# ctest replays it in every build.
set -euo pipefail
cd "$(dirname "$0")/.."
ROOT=$(pwd)

MODE=long
CI_SECONDS=12
RUNS=10000000
HOURS=4
ONLY=""
UPDATE=0
COVERAGE=0
while [ $# -gt 0 ]; do
  case "$1" in
    --ci) MODE=ci; if [ $# -gt 1 ] && [[ "$2" =~ ^[0-9]+$ ]]; then CI_SECONDS=$2; shift; fi ;;
    --runs) RUNS=$2; shift ;;
    --hours) HOURS=$2; shift ;;
    --only) ONLY=$2; shift ;;
    --update-corpus) UPDATE=1 ;;
    --coverage) COVERAGE=1 ;;
    --coverage-only) COVERAGE=2 ;;
    -h|--help) sed -n '2,25p' "$0"; exit 0 ;;
    *) echo "fuzz-long: unknown argument '$1' (see --help)" >&2; exit 2 ;;
  esac
  shift
done

CC_FUZZ=${CC_FUZZ:-clang-14}
BUILD=${FUZZ_BUILD:-build-fuzz} # another tree keeps a long campaign's programs apart
FUZZ=$BUILD/tests/fuzz
T=tests/fuzz

# harness | shipped seed files (globs) | dictionary | -max_len | -timeout (s) | long-run executions
# | more libFuzzer options. calib_h5's inputs are edit scripts (4-6 bytes an edit): all lengths
# up to 96 bytes from the start (-len_control=0), not grown from the 1-byte seeds.
HARNESSES=(
  "gait_csv|gaits/*.csv|gait_csv|8192|30|$RUNS|"
  "gait_design|gaits/*.gait|gait_design|4096|30|$RUNS|"
  "gait_design_build|gaits/flat_road_paper.gait|gait_design|2048|120|100000|"
  "terrain|terrains/*.terrain|terrain|4096|30|$RUNS|"
  "scenefile|terrains/*.scene|scenefile|2048|30|$RUNS|"
  "calib_text|robot/calibration_provisional.txt|calib_text|2048|30|$RUNS|"
  "calib_h5||-|96|60|$RUNS|-len_control=0"
  "study||study|8192|30|$RUNS|"
  "levels|robot/levels.csv|-|2048|30|$RUNS|"
  "rundef||rundef|2048|30|1000000|"
)

# exit 3 when the fuzzers do not build (tools/test-all.sh then fails)
build() {
  echo "== fuzz build ($BUILD: $CC_FUZZ, libFuzzer + ASan + UBSan) =="
  if ! CC=$CC_FUZZ cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCS_BUILD_TESTS=OFF \
         -DCS_BUILD_FUZZERS=ON -DCS_ENABLE_SANITIZERS=ON -DCS_WITH_MPI=OFF >/dev/null ||
     ! nice -n 10 cmake --build "$BUILD" --target fuzzers -j"${JOBS:-1}"; then
    echo "fuzz-long: the fuzzers do not build" >&2
    exit 3
  fi
}

# run one harness; sets LAST_RUNS, LAST_COV, LAST_FT, LAST_SECONDS, LAST_CRASHES, LAST_SLOW
run_one() {
  local name=$1 seeds=$2 dict=$3 maxlen=$4 timeout=$5 runs=$6 seconds=$7 work=$8 extra=$9
  mkdir -p "$work/corpus" "$work/artifacts"
  local dirs=("$work/corpus")
  [ -d "$T/corpus/$name" ] && dirs+=("$T/corpus/$name")
  [ -d "$T/seeds/$name" ] && dirs+=("$T/seeds/$name")
  # shipped files: copied in, so that the read-only seed folders hold only files of this kind
  local seedcopy="$work/shipped"
  mkdir -p "$seedcopy"
  if [ -n "$seeds" ]; then
    for f in $seeds; do [ -f "$f" ] && cp "$f" "$seedcopy/"; done
    dirs+=("$seedcopy")
  fi
  local opts=(-max_len="$maxlen" -timeout="$timeout" -rss_limit_mb=2560 -malloc_limit_mb=2048
              -artifact_prefix="$work/artifacts/" -print_final_stats=1 -detect_leaks=1)
  [ "$dict" != "-" ] && opts+=(-dict="$T/dict/$dict.dict")
  [ -n "$extra" ] && opts+=($extra)
  if [ "$MODE" = ci ]; then
    opts+=(-max_total_time="$seconds")
  else
    opts+=(-runs="$runs" -max_total_time="$seconds" -reload=0)
  fi
  local start=$SECONDS rc=0
  ASAN_OPTIONS=${ASAN_OPTIONS:-abort_on_error=1:detect_leaks=1} \
  UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1} \
    nice -n 15 "$FUZZ/fuzz_$name" "${opts[@]}" "${dirs[@]}" >"$work/log" 2>&1 || rc=$?
  LAST_SECONDS=$((SECONDS - start))
  LAST_RUNS=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$work/log" | tail -1 | awk '{print $2}')
  LAST_COV=$(grep -oE 'cov: [0-9]+' "$work/log" | tail -1 | awk '{print $2}')
  LAST_FT=$(grep -oE 'ft: [0-9]+' "$work/log" | tail -1 | awk '{print $2}')
  # libFuzzer's slow-unit-* files are inputs that took over -report_slow_units (10 s) once; a
  # hang is a timeout-* (over -timeout). They are reported, not counted as problems: under a
  # shared machine's load and nice 15 a sanitized `gait design` of a few strides can take 10 s
  LAST_CRASHES=$(find "$work/artifacts" -type f ! -name 'slow-unit-*' | wc -l)
  LAST_SLOW=$(find "$work/artifacts" -type f -name 'slow-unit-*' | wc -l)
  if [ "$rc" -ne 0 ] && [ "$LAST_CRASHES" -eq 0 ]; then
    LAST_CRASHES=1 # a failure without an artifact (e.g. the harness's initialisation)
  fi
  if [ "$LAST_CRASHES" -ne 0 ]; then
    echo "fuzz $name: FOUND A PROBLEM (exit $rc). Log: $work/log" >&2
    grep -E 'ERROR|SUMMARY|harness contract|runtime error' "$work/log" | head -5 >&2 || true
    find "$work/artifacts" -type f | head -5 | while read -r a; do
      echo "  artifact $a: reproduce with $FUZZ/fuzz_$name $a; keep it as a regression:" \
           "cp $a $T/regressions/$name/<name> and write <name>.expect" >&2
    done
  fi
  if [ "$LAST_SLOW" -ne 0 ]; then
    echo "fuzz $name: $LAST_SLOW slow input(s) (over 10 s once; not problems), in $work/artifacts:" \
         "time one with $FUZZ/fuzz_$name FILE" >&2
  fi
  return 0
}

selected() {
  [ -z "$ONLY" ] && return 0
  [[ ",$ONLY," == *",$1,"* ]]
}

if ! command -v "$CC_FUZZ" >/dev/null; then
  echo "fuzz-long: $CC_FUZZ not found (tools/install-deps.sh installs clang-14)" >&2
  exit 3
fi
[ "$COVERAGE" = 2 ] || build

OUT=$BUILD/fuzz-long
[ "$MODE" = ci ] && OUT=$BUILD/fuzz-ci
mkdir -p "$OUT"
found=0
for h in "${HARNESSES[@]}"; do
  IFS='|' read -r name seeds dict maxlen timeout runs extra <<<"$h"
  selected "$name" || continue
  [ "$COVERAGE" = 2 ] && continue
  seconds=$CI_SECONDS
  [ "$MODE" = long ] && seconds=$(awk -v h="$HOURS" 'BEGIN{printf "%d", h*3600}')
  echo "== fuzz $name ($MODE: $([ "$MODE" = ci ] && echo "${seconds} s" || echo "$runs runs or ${seconds} s")) =="
  rm -rf "${OUT:?}/$name"
  run_one "$name" "$seeds" "$dict" "$maxlen" "$timeout" "$runs" "$seconds" "$OUT/$name" "$extra"
  rate=$(awk -v r="${LAST_RUNS:-0}" -v s="$LAST_SECONDS" 'BEGIN{printf "%d", (s > 0 ? r / s : r)}')
  echo "| $name | ${LAST_RUNS:-0} | $LAST_SECONDS | $rate | ${LAST_COV:-?} | ${LAST_FT:-?} | $LAST_CRASHES | $(date -u +%Y-%m-%d) |" \
    >"$OUT/$name/summary.line"
  echo "fuzz $name: ${LAST_RUNS:-0} executions in ${LAST_SECONDS} s, cov ${LAST_COV:-?}, ft ${LAST_FT:-?}, problems $LAST_CRASHES"
  [ "$LAST_CRASHES" -ne 0 ] && found=1
  if [ "$MODE" = long ] && [ "$UPDATE" = 1 ] && [ "$LAST_CRASHES" -eq 0 ]; then
    # the grown corpus, minimised (libFuzzer -merge keeps one input per new feature)
    new=$OUT/$name/minimised
    mkdir -p "$new"
    prev=()
    [ -d "$T/corpus/$name" ] && prev+=("$T/corpus/$name")
    nice -n 15 "$FUZZ/fuzz_$name" -merge=1 -max_len="$maxlen" -timeout="$timeout" \
      -rss_limit_mb=2560 "$new" "${prev[@]}" "$OUT/$name/corpus" >"$OUT/$name/merge.log" 2>&1
    rm -rf "$T/corpus/$name"
    mkdir -p "$T/corpus/$name"
    cp "$new"/* "$T/corpus/$name/" 2>/dev/null || true
    echo "fuzz $name: corpus minimised into $T/corpus/$name ($(ls "$T/corpus/$name" | wc -l) files)"
  fi
done
# the table of every harness run so far into this tree (each run replaces its own row)
{
  echo "| harness | executions | time (s) | exec/s | edges (cov) | features (ft) | problems | date |"
  echo "|---|---|---|---|---|---|---|---|"
  for h in "${HARNESSES[@]}"; do
    IFS='|' read -r name _ <<<"$h"
    [ -f "$OUT/$name/summary.line" ] && cat "$OUT/$name/summary.line"
  done
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), load $(cut -d' ' -f1-3 /proc/loadavg) at the end"
} >"$OUT/summary.md"
cat "$OUT/summary.md"

if [ "$MODE" = long ] && [ "$COVERAGE" != 0 ]; then
  if ! command -v llvm-profdata-14 >/dev/null; then
    echo "fuzz-long: --coverage needs llvm-profdata-14 and llvm-cov-14 (package llvm-14)" >&2
  else
    echo "== source coverage of the readers (build-fuzz-cov) =="
    COV=build-fuzz-cov
    CC=$CC_FUZZ cmake -S . -B "$COV" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCS_BUILD_TESTS=ON \
      -DCMAKE_C_FLAGS="-fprofile-instr-generate -fcoverage-mapping" \
      -DCMAKE_EXE_LINKER_FLAGS="-fprofile-instr-generate" >/dev/null
    rm -rf "$COV/profiles"
    mkdir -p "$COV/profiles"
    objects=()
    for h in "${HARNESSES[@]}"; do
      IFS='|' read -r name seeds dict maxlen timeout runs extra <<<"$h"
      selected "$name" || continue
      [ "$name" = gait_design_build ] && continue # same reader as gait_design
      nice -n 10 cmake --build "$COV" --target "fuzz_${name}_replay" -j1 >/dev/null
      inputs=()
      for d in "$OUT/$name/corpus" "$T/corpus/$name" "$T/seeds/$name" "$OUT/$name/shipped"; do
        [ -d "$d" ] && inputs+=("$d")
      done
      LLVM_PROFILE_FILE="$COV/profiles/$name.profraw" nice -n 15 \
        "$COV/tests/fuzz/fuzz_${name}_replay" "${inputs[@]}" >/dev/null 2>&1 || true
      objects+=(-object "$COV/tests/fuzz/fuzz_${name}_replay")
    done
    llvm-profdata-14 merge -o "$COV/profiles/all.profdata" "$COV"/profiles/*.profraw
    readers=()
    for f in gaits/gaits_csv.c gaits/gaits_design.c terrains/terrains_terrain.c base/core_text.c \
             robot/calibration/robot_calibration.c robot/calibration/robot_calibration_table.c \
             robot/calibration/robot_calibration_build.c tools/study_file.c robot/robot_levels.c; do
      [ -f "$f" ] && readers+=("$ROOT/$f")
    done
    llvm-cov-14 report -instr-profile="$COV/profiles/all.profdata" "${objects[@]:1}" \
      "${readers[@]}" \
      2>/dev/null | tee "$OUT/coverage.txt" || true
  fi
fi
exit $found

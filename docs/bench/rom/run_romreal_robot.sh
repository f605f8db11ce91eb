#!/usr/bin/env bash
# Session romreal (docs/notes/rom.md, "The real leg's rom"): the robot on the real leg's rom
# legs. From the repository root after a Release build. Arguments: LEG (a leg file of
# run_romreal.sh's legfile stage), OUT (a directory), then the stages, in order:
#   stand     test_run_rom on the real leg (S = 50 mm)  -> OUT/stand.log
#   settle    bench_rom_settle, SETTLE_STEPS macro steps -> OUT/settle.log
#   flat      crawlsim run --scene flat-road --legs rom --t-end T_END -> OUT/rom_flat.{h5,log}
#   rodflat   the same with --legs rod                  -> OUT/rod_flat.{h5,log}
# Environment: T_END (default 2 s), SETTLE_STEPS (default 400).
set -euo pipefail
LEG=$1
OUT=$2
shift 2
B=$PWD/build
T_END=${T_END:-2}
SETTLE_STEPS=${SETTLE_STEPS:-400}
mkdir -p "$OUT"
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 CS_SOURCE_DIR=$PWD
T=(/usr/bin/time -f '%e s wall, %U s user, %M kB resident')
for stage in "$@"; do
  uptime
  case $stage in
    stand)
      CRAWLSIM_ROM_LEG_FILE=$LEG CRAWLSIM_ROM_LEG_S=50 "${T[@]}" stdbuf -oL \
        "$B/tests/core/test_run_rom" > "$OUT/stand.log" 2>&1 || true ;;
    settle)
      CRAWLSIM_ROM_LEG_FILE=$LEG CRAWLSIM_ROM_LEG_S=50 "${T[@]}" stdbuf -oL \
        "$B/tests/core/bench_rom_settle" "$LEG" "$SETTLE_STEPS" > "$OUT/settle.log" 2>&1 || true ;;
    flat)
      "${T[@]}" stdbuf -oL "$B/tools/crawlsim" run --scene flat-road --legs rom --rom-file "$LEG" \
        --t-end "$T_END" --out "$OUT/rom_flat.h5" > "$OUT/rom_flat.log" 2>&1 || true ;;
    rodflat)
      "${T[@]}" stdbuf -oL "$B/tools/crawlsim" run --scene flat-road --legs rod \
        --t-end "$T_END" --out "$OUT/rod_flat.h5" > "$OUT/rod_flat.log" 2>&1 || true ;;
    *) echo "run_romreal_robot.sh: unknown stage $stage" >&2; exit 2 ;;
  esac
done
uptime

#!/usr/bin/env bash
# Session romflat2 (2026-12-06/07, seventh; romflat's script): the flat road on the real leg's rom legs, in resumable
# pieces (docs/notes/rom.md "The flat road on rom legs in resumable pieces"). From the
# repository root after a Release build:
#   bash docs/bench/romflat2_2026-12-06g/run_romflat.sh [LEG] [DIR]
# The first call copies build/tools/crawlsim to DIR/bin (a checkpoint is resumed only by the
# program version that wrote it) and starts the run; every later call resumes it from
# DIR/rom_flat.ck, appending to DIR/rom_flat.h5, until --t-end. Stop a piece with SIGTERM
# (kill PID of crawlsim): it writes a checkpoint where it stopped and exits.
# LEG: romcontact's b10 leg file of the real leg (n = 96, m = 48, ECSW 1e-2; regenerable by
# the commands of docs/notes/rom.md "The rom leg's contact steps", ~5 min of CPU).
# Environment: T_END (default 2 s), EVERY (checkpoint interval, default 0.02 s), LOG.
set -euo pipefail
LEG=${1:-/work/rom_data/romcontact/b10/leg_tol1e-2.h5}
DIR=${2:-/work/rom_data/romflat2/run}
T_END=${T_END:-2}
EVERY=${EVERY:-0.02}
LOG=${LOG:-$PWD/docs/bench/romflat2_2026-12-06g/rom_flat.log}
mkdir -p "$DIR/bin"
[ -x "$DIR/bin/crawlsim" ] || cp build/tools/crawlsim "$DIR/bin/crawlsim"
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1 CRAWLSIM_DATA_DIR=$PWD
ARGS=(run --scene flat-road --legs rom --rom-file "$LEG" --t-end "$T_END"
      --out "$DIR/rom_flat.h5" --checkpoint "$DIR/rom_flat.ck" --checkpoint-every "$EVERY")
if [ -f "$DIR/rom_flat.ck" ]; then
  ARGS+=(--resume "$DIR/rom_flat.ck")
fi
{ echo "== piece started $(date -u +%FT%TZ); $(uptime)"; "$DIR/bin/crawlsim" --version | head -1
  echo "crawlsim ${ARGS[*]}"; } >> "$LOG"
/usr/bin/time -f '%e s wall, %U s user, %M kB resident' -a -o "$LOG" \
  nice -n 10 stdbuf -oL "$DIR/bin/crawlsim" "${ARGS[@]}" >> "$LOG" 2>&1 || true
echo "== piece ended $(date -u +%FT%TZ); $(uptime)" >> "$LOG"

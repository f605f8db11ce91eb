#!/usr/bin/env bash
# Session romfast (docs/notes/rom.md, goal 1): the 0-0.4 MPa bend sweep of the short leg
# (Omega1 & Omega2 in every segment, rows every 0.05 MPa), the full FE and the reduced model one
# after the other in one run, each under /usr/bin/time (the command's CPU seconds), the load
# (uptime) between them. The FE once more up to 0.001 MPa (one small step: its set-up's CPU, to
# take from the sweep's); the rom's bend prints its sweep's own CPU time; then
# tests/fem/bench_rom_sweep: the rom sweep per Newton setting (k_lag, predictor) after one set-up.
# From the repository root after a Release build; arguments OUT, BASIS, WEIGHTS ("none": every
# element). CS and BENCH (environment): the crawlsim and bench_rom_sweep binaries; BENCH_ARGS
# (environment): bench_rom_sweep's settings after the segment length (default its own list).
set -euo pipefail
OUT=$1
BASIS=$2
W=$3
CS=${CS:-$PWD/build/tools/crawlsim}
BENCH=${BENCH:-$PWD/build/tests/fem/bench_rom_sweep}
LEG=(--actuator leg --set S1=15 --set S2=15 --set S3=15 --chambers 1,2)
EX=("${LEG[@]}" --p-max 0.4 --p-step 0.05)
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$OUT"
RW=()
[ "$W" != none ] && RW=(--rom-weights "$W")
echo "== load before the FE: $(uptime)"
/usr/bin/time -f '== fe: %e s wall, %U s user, %S s system, %M kB' "$CS" bend --model fe \
  --mesh-symmetric 1 --mesh-size 8 --threads 1 "${EX[@]}" --out "$OUT/bend_fe.h5" 2>&1
echo "== load after the FE: $(uptime)"
/usr/bin/time -f '== fe set-up (to 0.001 MPa): %e s wall, %U s user, %S s system' "$CS" bend \
  --model fe --mesh-symmetric 1 --mesh-size 8 --threads 1 "${LEG[@]}" --p-max 0.001 \
  --p-step 0.001 --out "$OUT/bend_fe_setup.h5" 2>&1
echo "== load after the FE set-up: $(uptime)"
/usr/bin/time -f "== rom: %e s wall, %U s user, %S s system, %M kB" "$CS" bend \
  --model rom --rom-basis "$BASIS" "${RW[@]}" "${EX[@]}" --out "$OUT/bend_rom.h5" 2>&1
echo "== load after the rom: $(uptime)"
read -r -a BA <<< "${BENCH_ARGS:-}"
(cd "$OUT" && /usr/bin/time -f "== bench_rom_sweep: %e s wall, %U s user" "$BENCH" "$BASIS" "$W" 15 \
  "${BA[@]}")
echo "== load at the end: $(uptime)"

#!/usr/bin/env bash
# Session romacc (docs/notes/rom.md): the 0-0.4 MPa bend sweep of the short leg (Omega1 & Omega2
# in every segment, rows every 0.05 MPa), the full FE and the reduced model one after the other
# in one run, each under /usr/bin/time, the load (uptime) between them; the FE once more to
# 0.001 MPa (its set-up's upper bound); `bend --model rom` with the default reduced Newton (a
# kept tangent with BFGS pairs, fem_rom_act.h); then bench_rom_sweep with Newton and BFGS after
# one set-up. From the repository root after a Release build; arguments OUT, BASIS, WEIGHTS
# ("none": every element). CS and BENCH (environment): the crawlsim and bench_rom_sweep binaries.
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
/usr/bin/time -f '== rom: %e s wall, %U s user, %S s system, %M kB' "$CS" bend \
  --model rom --rom-basis "$BASIS" "${RW[@]}" "${EX[@]}" --out "$OUT/bend_rom.h5" 2>&1
echo "== load after the rom: $(uptime)"
/usr/bin/time -f '== fe set-up (to 0.001 MPa): %e s wall, %U s user, %S s system' "$CS" bend \
  --model fe --mesh-symmetric 1 --mesh-size 8 --threads 1 "${LEG[@]}" --p-max 0.001 \
  --p-step 0.001 --out "$OUT/bend_fe_setup.h5" 2>&1
echo "== load after the FE set-up: $(uptime)"
(cd "$OUT" && /usr/bin/time -f "== bench_rom_sweep: %e s wall, %U s user" "$BENCH" "$BASIS" \
  "$W" 15 0 0.9b8 0.9b4 0.99b16)
echo "== load at the end: $(uptime)"

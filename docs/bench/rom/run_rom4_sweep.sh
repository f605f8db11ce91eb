#!/usr/bin/env bash
# Session rom4 (docs/notes/rom.md, goal 2): the 0-0.4 MPa bend sweep of the short leg (Omega1 &
# Omega2 in every segment, rows every 0.05 MPa), the full FE and the hyper-reduced model one
# after the other in one run, each under /usr/bin/time (CPU seconds), the load (uptime) printed
# before and after each. From the repository root; arguments OUT (a directory), BASIS, WEIGHTS
# (rom_ecsw.py's file; "none" keeps every element). CS (environment) is the crawlsim binary.
# The rom is run twice: its first run meshes the leg with gmsh and builds the chambers' forms
# (the set-up; the bend file's rom_sweep_s attribute is the sweep alone).
set -euo pipefail
OUT=$1
BASIS=$2
W=$3
CS=${CS:-$PWD/build/tools/crawlsim}
EX=(--actuator leg --set S1=15 --set S2=15 --set S3=15 --chambers 1,2 --p-max 0.4 --p-step 0.05)
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$OUT"
RW=()
[ "$W" != none ] && RW=(--rom-weights "$W")
echo "== load before the FE: $(uptime)"
/usr/bin/time -f '== fe: %e s wall, %U s user, %S s system, %M kB' "$CS" bend --model fe \
  --mesh-symmetric 1 --mesh-size 8 --threads 1 "${EX[@]}" --out "$OUT/bend_fe.h5" 2>&1
echo "== load after the FE: $(uptime)"
for k in 1 2; do
  /usr/bin/time -f "== rom (run $k): %e s wall, %U s user, %S s system, %M kB" "$CS" bend \
    --model rom --rom-basis "$BASIS" "${RW[@]}" "${EX[@]}" --out "$OUT/bend_rom$k.h5" 2>&1
  echo "== load after rom run $k: $(uptime)"
done

#!/usr/bin/env bash
# Session romfast (docs/notes/rom.md): the rom bend sweep with main's code and this branch's, back
# to back under /usr/bin/time. Arguments: OUT, BASIS, WEIGHTS, then the crawlsim binaries to compare.
set -euo pipefail
OUT=$1
B=$2
W=$3
shift 3
export OMP_WAIT_POLICY=PASSIVE OMP_NUM_THREADS=1 OPENBLAS_NUM_THREADS=1
mkdir -p "$OUT"
k=0
for bin in "$@"; do
  k=$((k + 1))
  echo "== $bin: $(uptime)"
  /usr/bin/time -f "== $bin: %e s wall, %U s user" "$bin" bend --model rom --rom-basis "$B" \
    --rom-weights "$W" --actuator leg --set S1=15 --set S2=15 --set S3=15 --chambers 1,2 \
    --p-max 0.4 --p-step 0.05 --out "$OUT/ba_$k.h5" 2>&1 | grep -v "^ "
done
echo "== end: $(uptime)"

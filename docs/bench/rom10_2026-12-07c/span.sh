#!/bin/bash
# the span of OUT/snap's training (goal 1 of task rom10; romrs's step2.sh): for each N, the
# basis (N POD + 48 supremizers, m = 48 split, every fibre mode), its first 104 fibre modes,
# the chamber walls' best fit (romacc_volume_diag.py) and the M-projection (rom_project.py) of
# the five held-out rays; one job at a time, nice 5. Usage: span.sh OUT N... (OUT/legf the
# 4-mode leg file of run_romreal4.sh's stage legfile)
set -euo pipefail
cd "$(dirname "$0")/../../.."
OUT=$(readlink -f "$1"); shift
RAYS="--ray T_H4 --ray T_S2 --ray T_H7 --ray T_O12GF --ray T_R"
for n in "$@"; do
  N=$n bash docs/bench/rom/run_romreal4.sh "$OUT" basis trunc-f104
  [ -s "$OUT/b${n}_f104_volume_diag.log" ] ||
    /usr/bin/time -f '%e s wall, %U s user' nice -n 5 /usr/bin/python3 docs/bench/rom/romacc_volume_diag.py \
      "$OUT/snap" "$OUT/b${n}_f104.h5" $RAYS > "$OUT/b${n}_f104_volume_diag.log" 2>&1
  [ -s "$OUT/b${n}_f104_projection.log" ] ||
    /usr/bin/time -f '%e s wall, %U s user' nice -n 5 /usr/bin/python3 tools/rom_project.py \
      "$OUT/snap" "$OUT/b${n}_f104.h5" > "$OUT/b${n}_f104_projection.log" 2>&1
done
echo "span.sh done $(date -u +%H:%M:%S)"

#!/bin/bash
# step 2 of task romrs: the 25 training rays + the finished RS rays, N=128 then N=96: basis,
# trunc-f104, the span's wall fit and the M-projection's tip (one job at a time, nice 5)
set -euo pipefail
cd /work/wt-romrs
OUT=/work/rom_data/romrs/$1   # rs3: a folder of its own (its basis names carry no ray count)
RAYS="--ray T_H4 --ray T_S2 --ray T_H7 --ray T_O12GF --ray T_R"
for n in 128 96; do
  N=$n bash docs/bench/rom/run_romreal4.sh $OUT basis trunc-f104
  /usr/bin/time -f '%e s wall, %U s user' nice -n 5 /usr/bin/python3 docs/bench/rom/romacc_volume_diag.py \
    $OUT/snap $OUT/b${n}_f104.h5 $RAYS > $OUT/b${n}_f104_volume_diag.log 2>&1
  /usr/bin/time -f '%e s wall, %U s user' nice -n 5 /usr/bin/python3 tools/rom_project.py \
    $OUT/snap $OUT/b${n}_f104.h5 > $OUT/b${n}_f104_projection.log 2>&1
done
echo step2 done $(date -u +%H:%M:%S)

#!/bin/bash
set -euo pipefail
cd /work/wt-romrs
OUT=/work/rom_data/romrs/$1
N=128 bash docs/bench/rom/run_romreal4.sh $OUT basis trunc-f104
/usr/bin/time -f '%e s wall, %U s user' nice -n 5 /usr/bin/python3 docs/bench/rom/romacc_volume_diag.py \
  $OUT/snap $OUT/b128_f104.h5 --ray T_H4 --ray T_S2 --ray T_H7 --ray T_O12GF --ray T_R > $OUT/b128_f104_volume_diag.log 2>&1
/usr/bin/time -f '%e s wall, %U s user' nice -n 5 /usr/bin/python3 tools/rom_project.py \
  $OUT/snap $OUT/b128_f104.h5 > $OUT/b128_f104_projection.log 2>&1
echo step2 done $(date -u +%H:%M:%S)

#!/bin/sh
# dumps.sh BINDIR TAG: the final states (STRAIN_DUMP) of one leg, 300 steps at 5 ms with and
# without the foot in contact (bench_strain_step 2 C 300), and of the harness's eight legs over
# 0-1 s at 5 ms (bench_strain_robot gaits/flat_road.csv 0.8 0.005 1 2 16 1e-7), into
# build/ss/dump_TAG/; compare two builds with docs/bench/kernel2_2026-12-06/cmpdump.py.
cd "$(dirname "$0")/../../.." || exit 1
export CS_SOURCE_DIR=$PWD
bin=$(cd "$1" && pwd); out=build/ss/dump_$2; mkdir -p $out
for c in 0 1; do
  STRAIN_DUMP=$out/step_$c.bin $bin/bench_strain_step 2 $c 300 > $out/step_$c.txt 2>&1
done
STRAIN_DUMP=$out/robot.bin $bin/bench_strain_robot gaits/flat_road.csv 0.8 0.005 1 2 16 1e-7 > $out/robot.txt 2>&1
grep -h "steps taken" $out/robot.txt

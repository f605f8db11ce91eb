#!/bin/sh
# obstacle.sh BENCH_STRAIN_DRIVER TAG: the obstacle scene's first 4 s at 1 ms through the driver
# (CS_BENCH_SCENE=obstacle bench_strain_driver 4 strain:3:0.001:1), its run file kept in
# build/ss/obs_TAG/; compare with docs/bench/kernel_2026-12-06/tracks.py REF.h5 RUN.h5.
cd "$(dirname "$0")/../../.." || exit 1
root=$PWD; export CS_SOURCE_DIR=$root
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
out=$root/build/ss/obs_$2; mkdir -p $out
cd build/tests/core || exit 1
CS_BENCH_SCENE=obstacle CS_BENCH_KEEP=$out $bin 4 strain:3:0.001:1 > $out/bench.txt 2>&1
grep -h "x(end)\|Newton passes" $out/bench.txt

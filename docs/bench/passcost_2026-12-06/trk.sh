#!/bin/sh
# trk.sh BENCH_STRAIN_DRIVER TAG DT: the 9 s flat road at step DT (s) through the driver
# (bench_strain_driver 9 strain:3:DT:1, the scene's defaults), its run file kept in
# build/ss/trk_TAG/ (CS_BENCH_KEEP) and the bench's lines in build/ss/trk_TAG/bench_DT.txt.
# Compare two runs with docs/bench/kernel_2026-12-06/tracks.py REF.h5 RUN.h5.
cd "$(dirname "$0")/../../.." || exit 1
root=$PWD; export CS_SOURCE_DIR=$root
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
out=$root/build/ss/trk_$2; mkdir -p $out
cd build/tests/core || exit 1
CS_BENCH_KEEP=$out $bin 9 strain:3:$3:1 > $out/bench_$3.txt 2>&1
tail -3 $out/bench_$3.txt

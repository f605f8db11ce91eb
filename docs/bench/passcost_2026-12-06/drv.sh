#!/bin/sh
# drv.sh BENCH_STRAIN_DRIVER TAG: callgrind of the driver's flat road 0-1 s at 5 ms, the run and
# its output (--toggle-collect=cs_runWrite: settling and setup excluded), as branch `kernel`
# measured it; prints the total, keeps the bench's lines and the inclusive profile in
# build/ss/drv_TAG/.
cd "$(dirname "$0")/../../.." || exit 1
root=$PWD; export CS_SOURCE_DIR=$root
bin=$(cd "$(dirname "$1")" && pwd)/$(basename "$1")
out=$root/build/ss/drv_$2; mkdir -p $out
cd build/tests/core || exit 1
valgrind --tool=callgrind --toggle-collect=cs_runWrite --callgrind-out-file=$out/drv.cg \
  $bin 1 strain:3:0.005:1 > $out/bench.txt 2> $out/vg.txt
callgrind_annotate --inclusive=yes $out/drv.cg > $out/inclusive.txt 2>/dev/null
grep -m1 "^summary:" $out/drv.cg

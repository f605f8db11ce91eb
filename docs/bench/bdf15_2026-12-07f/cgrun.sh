#!/bin/sh
# cgrun.sh BIN PREFIX: callgrind of bench_strain_driver (BIN, an absolute path) in the window
# [1, 2] s (../speed_2026-12-07/cg.sh's settings: --instr-atstart=no, --toggle-collect=
# cs_runWrite), BDF2 adaptive 5e-4 mm (`strain:2:0:2`) and backward Euler's default 2.5e-4
# (`strain:2`), on the flat road and the obstacle (CS_BENCH_SCENE); profiles, logs, uptimes in
# /tmp/bdf15/cg ($BDF_SCRATCH/cg if set; resumable: a profile that exists is skipped), "TAG Ir"
# lines appended to its ir_results.txt
OUT=${BDF_SCRATCH:-/tmp/bdf15}/cg
SRC=$(cd "$(dirname "$0")/../../.." && pwd)
mkdir -p $OUT
cd $OUT || exit 1
run() { # TAG SCENE SPEC TOL
  f=$OUT/$1
  [ -f $f.cg ] && return
  uptime > $f.uptime
  CS_SOURCE_DIR=$SRC CS_BENCH_SCENE=$2 CS_BENCH_WINDOWS=1 CS_BENCH_ADAPTIVE=$4 CS_BENCH_FROM=1 \
    nice -n 5 valgrind --tool=callgrind --instr-atstart=no --toggle-collect=cs_runWrite \
    --callgrind-out-file=$f.cg.tmp "$BIN" 1 "$3" > $f.log 2>&1
  uptime >> $f.uptime
  mv $f.cg.tmp $f.cg
  echo "$1 $2 $3 tol=$4 Ir=$(grep -E "^(summary|totals):" $f.cg | head -1 | awk '{print $2}')" >> $OUT/ir_results.txt
}
BIN=$1
for s in flat-road obstacle; do
  run $2.$s.o2 $s strain:2:0:2 5e-4
  run $2.$s.o1 $s strain:2 2.5e-4
done

#!/bin/bash
# bench.sh TAG PASSES CARRY TOL [DT] [EXTRA LEVEL FIELDS]: bench_strain_driver, BDF2 adaptive
# (strain:2:DT:2, CS_BENCH_ADAPTIVE=TOL, longest step DT, default 5 ms), the flat road 9.5 s and
# the obstacle's first 4 s, PASSES tree passes (1: one linearised pass per try), CS_BENCH_CARRY
# CARRY. Run files in $R/TAG/, logs in logs/bench_TAG_{flat,obst}.log. ORDER=1 runs backward Euler.
TAG=$1; PASSES=$2; CARRY=$3; TOL=$4; DT=${5:-0}; ORD=${ORDER:-2}
W=${W:-/work/wt-rosen19}; R=${R:-/tmp/rosen19/runs}; L=$(cd $(dirname "$0") && pwd)/logs
B=${B:-$W/build/tests/core/bench_strain_driver}
export CS_SOURCE_DIR=$W
mkdir -p $R/$TAG $L
run() { local scene=$1 t=$2 out=$3
  { uptime; CS_BENCH_SCENE=$scene CS_BENCH_KEEP=$R/$TAG CS_BENCH_PASSES=$PASSES CS_BENCH_CARRY=$CARRY \
      CS_BENCH_ADAPTIVE=$TOL nice -n 5 $B $t strain:2:$DT:$ORD; echo "rc $?"; uptime; } > $L/bench_${TAG}_$out.log 2>&1; }
run flat-road 9.5 flat &
run obstacle 4 obst
wait

#!/bin/bash
# cg.sh (event17's, CARRY=1 sets CS_BENCH_CARRY) BIN TAG SCENE [PASSES]: callgrind of bench_strain_driver (the default: strain:2, adaptive
# 2.5e-4 mm) in the window 1-2 s (CS_BENCH_FROM=1: the settling and 0-1 s uninstrumented;
# --toggle-collect=cs_runWrite: the run alone), as ../speed_2026-12-07/cg.sh. PASSES > 0 sets
# tree_iterations (CS_BENCH_PASSES; 1: no Newton, one linearisation per try). Out: $OUT/TAG.*
BIN=$1; TAG=$2; SCENE=${3:-flat-road}; PASSES=${4:-0}
OUT=${CG_OUT:-/tmp/carry18/cg}
export CS_SOURCE_DIR=${CS_SOURCE_DIR:-/work/wt-carry18}
f=$OUT/$TAG
uptime > $f.uptime
CS_BENCH_SCENE=$SCENE CS_BENCH_PASSES=$PASSES CS_BENCH_CARRY=${CARRY:-0} CS_BENCH_WINDOWS=1 CS_BENCH_ADAPTIVE=2.5e-4 CS_BENCH_FROM=1 \
  nice -n 5 valgrind --tool=callgrind --instr-atstart=no --toggle-collect=cs_runWrite \
  --callgrind-out-file=$f.cg "$BIN" 1 strain:2 > $f.log 2>&1
uptime >> $f.uptime
ir=$(grep -E "^(summary|totals):" $f.cg | head -1 | awk '{print $2}')
echo "$TAG $SCENE passes=$PASSES Ir=$ir" >> $OUT/ir_results.txt

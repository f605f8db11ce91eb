#!/bin/bash
# cg.sh TAG SCENE PASSES TOL [LEVEL]: callgrind of bench_strain_driver in the window 1-2 s
# (CS_BENCH_FROM=1, --toggle-collect=cs_runWrite), as ../event17_2026-12-07g/cg.sh, with the
# adaptive step at TOL mm and LEVEL (default strain:2:0:2, BDF2). PASSES > 0 sets tree_iterations.
# Out: $OUT/TAG.*, a line in $OUT/ir_results.txt.
TAG=$1; SCENE=${2:-flat-road}; PASSES=${3:-0}; TOL=${4:-5e-4}; LEVEL=${5:-strain:2:0:2}
W=${W:-/work/wt-rosen19}; OUT=${CG_OUT:-$(cd $(dirname "$0") && pwd)/logs}
export CS_SOURCE_DIR=$W
f=$OUT/$TAG
uptime > $f.uptime
CS_BENCH_SCENE=$SCENE CS_BENCH_PASSES=$PASSES CS_BENCH_WINDOWS=1 CS_BENCH_ADAPTIVE=$TOL CS_BENCH_FROM=1 \
  nice -n 5 valgrind --tool=callgrind --instr-atstart=no --toggle-collect=cs_runWrite \
  --callgrind-out-file=/tmp/rosen19/$TAG.cg ${B:-$W/build/tests/core/bench_strain_driver} 1 $LEVEL > $f.log 2>&1
uptime >> $f.uptime
ir=$(grep -E "^(summary|totals):" /tmp/rosen19/$TAG.cg | head -1 | awk '{print $2}')
echo "$TAG $SCENE $LEVEL tol=$TOL passes=$PASSES Ir=$ir" >> $OUT/ir_results.txt

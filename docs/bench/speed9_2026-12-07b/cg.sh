#!/bin/bash
# cg.sh BIN TAG T NWIN SPEC [TOL [FROM]]: callgrind of bench_strain_driver's flat road (its scene
# defaults) in NWIN consecutive windows of T simulated seconds after the settling
# (CS_BENCH_WINDOWS; --instr-atstart=no: the settling runs uninstrumented; --toggle-collect=
# cs_runWrite: the run alone), one profile per window (OUT/TAG.cg.1 .. : callgrind's dump
# parts; the last window in OUT/TAG.cg); TOL > 0: the adaptive step at that step_tol (mm,
# CS_BENCH_ADAPTIVE); FROM > 0: the windows start at FROM s (the steps before it uninstrumented,
# CS_BENCH_FROM). BIN an absolute path to a copy of the bench (build/tests/core). Keeps
# OUT/TAG.{log,uptime}; appends "TAG SPEC TOL window Ir" lines to OUT/ir_results.txt (OUT:
# $CG_OUT, default /work/rom_data/speed9/cg). Split by stage and per leg pass: stages.py.
BIN=$1; TAG=$2; T=$3; NW=$4; SPEC=$5; TOL=${6:-0}; FROM=${7:-0}
OUT=${CG_OUT:-/work/rom_data/speed9/cg}
cd "$(dirname "$0")/../../../build/tests/core" || exit 1
export CS_SOURCE_DIR=$(cd ../../.. && pwd)
f=$OUT/$TAG
uptime > $f.uptime
CS_BENCH_WINDOWS=$NW CS_BENCH_ADAPTIVE=$TOL CS_BENCH_FROM=$FROM nice -n 5 valgrind --tool=callgrind --instr-atstart=no \
  --toggle-collect=cs_runWrite --callgrind-out-file=$f.cg "$BIN" "$T" "$SPEC" > $f.log 2>&1
uptime >> $f.uptime
for g in $f.cg*; do
  ir=$(grep -E "^(summary|totals):" $g | head -1 | awk '{print $2}')
  echo "$TAG $SPEC tol=$TOL from=$FROM T=$T $(basename $g) Ir=$ir" >> $OUT/ir_results.txt
done

#!/bin/bash
# cg.sh BIN TAG T SPEC...: callgrind of bench_strain_driver's scene (CS_BENCH_SCENE, default the
# flat road) for T simulated seconds, the run alone (--toggle-collect=cs_runWrite: settling and
# setup excluded), one run per SPEC one after the other; BIN an absolute path to a copy of the
# bench. Keeps OUT/TAG.SPEC.TT.{cg,log,uptime} (OUT: $CG_OUT, default /work/rom_data/legkin/cg)
# and appends "TAG SPEC T=T Ir=N" to OUT/ir_results.txt. Stages: stages.py. (As
# ../strainspeed_2026-12-06f/cg.sh with the output folder moved.)
BIN=$1; TAG=$2; T=$3; shift 3
OUT=${CG_OUT:-/work/rom_data/legkin/cg}
mkdir -p "$OUT"
cd "$(dirname "$0")/../../../build/tests/core" || exit 1
export CS_SOURCE_DIR=$(cd ../../.. && pwd)
for SPEC in "$@"; do
  f=$OUT/$TAG.${SPEC//:/_}.T$T
  uptime > $f.uptime
  nice -n 5 valgrind --tool=callgrind --toggle-collect=cs_runWrite --callgrind-out-file=$f.cg "$BIN" "$T" "$SPEC" > $f.log 2>&1
  ir=$(grep -E "^(summary|totals):" $f.cg | head -1 | awk '{print $2}')
  echo "$TAG $SPEC T=$T Ir=$ir" >> $OUT/ir_results.txt
done

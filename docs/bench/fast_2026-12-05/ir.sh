#!/bin/bash
# ir.sh BIN TAG T SPEC: the instructions of one bench_strain_driver run under callgrind, the
# run itself only (--toggle-collect=cs_runWrite: settling and setup excluded), appended to
# build/fastbench/ir_results.txt as TAG SPEC T Ir Ir/s. From the repository root; BIN an
# absolute path to a bench_strain_driver binary (a copy, so that rebuilding does not change
# it mid-run), SPEC as bench_strain_driver's LEVEL:LINKS:DT:ORDER[:TREE_TOL].
BIN=$1; TAG=$2; T=$3; SPEC=$4
root=$(pwd)
mkdir -p build/fastbench
out=$root/build/fastbench/cg.$TAG.$SPEC.out
cd build/tests/core || exit 1
nice -n 10 valgrind --tool=callgrind --toggle-collect=cs_runWrite --callgrind-out-file="$out" \
  "$BIN" "$T" "$SPEC" > "$root/build/fastbench/log.$TAG.$SPEC.txt" 2>&1
ir=$(grep -E "^(summary|totals):" "$out" | head -1 | awk '{print $2}')
echo "$TAG $SPEC T=$T Ir=$ir Ir/s=$(/usr/bin/python3 -c "print('%.4g' % ($ir / $T))")" \
  >> "$root/build/fastbench/ir_results.txt"

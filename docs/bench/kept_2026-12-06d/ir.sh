#!/bin/bash
# ir.sh BIN OUTDIR T SPEC...: the instructions of bench_strain_driver runs under callgrind, the
# run itself only (--toggle-collect=cs_runWrite: settling and setup excluded), one run per SPEC
# one after the other, appended to OUTDIR/ir_results.txt as SPEC T Ir Ir/s, with the call counts
# of the legs' inertia assembly, factorisations and matrix-free products. From the worktree's
# root with CS_SOURCE_DIR set; BIN an absolute path to a copy of bench_strain_driver.
BIN=$1; OUT=$2; T=$3; shift 3
mkdir -p "$OUT"
cd build/tests/core || exit 1
for SPEC in "$@"; do
  cg=$OUT/cg.$SPEC.T$T.out
  nice -n 5 valgrind --tool=callgrind --toggle-collect=cs_runWrite --callgrind-out-file="$cg" \
    "$BIN" "$T" "$SPEC" > "$OUT/log.$SPEC.T$T.txt" 2>&1
  ir=$(grep -E "^(summary|totals):" "$cg" | head -1 | awk '{print $2}')
  echo "$SPEC T=$T Ir=$ir Ir/s=$(python3 -c "print('%.4g' % ($ir / $T))")" >> "$OUT/ir_results.txt"
done

#!/bin/sh
# cgrun.sh BIN TAG: callgrind of bench_strain_driver BIN (an absolute path), the default
# (backward Euler, adaptive 2.5e-4 mm, `strain:2`), window [1, 2] s, on the flat road and the
# obstacle, by ../event17_2026-12-07g/cg.sh (its settings: --instr-atstart=no,
# --toggle-collect=cs_runWrite). Profiles and logs /tmp/legpass19/cg/TAG.SCENE.o1.*, their
# totals appended to /tmp/legpass19/cg/ir_results.txt; a profile that exists is skipped
SRC=$(cd "$(dirname "$0")/../../.." && pwd)
mkdir -p /tmp/legpass19/cg && cd /tmp/legpass19/cg || exit 1 # the bench writes its run file here
for s in flat-road obstacle; do
  [ -f /tmp/legpass19/cg/$2.$s.o1.cg ] && continue
  CG_OUT=/tmp/legpass19/cg CS_SOURCE_DIR=$SRC sh "$SRC/docs/bench/event17_2026-12-07g/cg.sh" "$1" "$2.$s.o1" $s
done

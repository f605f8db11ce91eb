#!/bin/sh
# cg_all.sh [ORDER:TOL...]: callgrind of bench_strain_driver's flat road, window [1, 2] s (as
# ../speed10_2026-12-07c's bin1.ada), by ../speed_2026-12-07/cg.sh, for each formula ORDER at
# each tolerance TOL (default: backward Euler at 2.5e-4, BDF2 at 1e-3 and 5e-4). Binary
# /tmp/bdf13/bin/bench_strain_driver (this branch's build); profiles, logs and ir_results.txt
# in $CG_OUT (default /tmp/bdf13/cg); a profile already there is skipped (resumable).
export CG_OUT=${CG_OUT:-/tmp/bdf13/cg}
mkdir -p "$CG_OUT"
for s in ${*:-1:2.5e-4 2:1e-3 2:5e-4}; do
  O=${s%%:*}; T=${s#*:}
  [ -f "$CG_OUT/o$O.$T.cg" ] && continue
  "$(dirname "$0")/../speed_2026-12-07/cg.sh" /tmp/bdf13/bin/bench_strain_driver "o$O.$T" 1 1 \
    "strain:2:0:$O" "$T" 1
done

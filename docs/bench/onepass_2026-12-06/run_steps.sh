#!/bin/sh
# run_steps.sh OUTDIR: the 9 s flat road at 2.5 and 1 ms, backward Euler converged (one_pass 0),
# one_pass 1 and 2, and the bare one pass (CS_BENCH_PASSES=1) at 5, 2.5 and 1 ms; run from
# build/tests/core with CS_SOURCE_DIR the worktree. Tracks kept in $CS_BENCH_KEEP (h5).
D=$(dirname "$0")
uptime
for H in 0.0025 0.001; do
  nice -n 5 ./bench_strain_driver 9 strain:3:$H:1 strain:3:$H:1:0:-1:-1:-1:1 strain:3:$H:1:0:-1:-1:-1:2
done
uptime

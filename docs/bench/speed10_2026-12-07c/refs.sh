#!/bin/sh
# refs.sh: the rod references at 32 elements per segment (the converged nodal rod), one at a
# time: the designed gait (scene default, 9.5 s) at 0.25 ms, the paper's table at 0.25 and
# 0.125 ms, `earth` with the paper's table at 0.25 ms. From the worktree; resumable.
C=$(dirname "$0")/../levels9_2026-12-07b/crun.sh
export D=/tmp/speed10/runs CRAWLSIM=${CRAWLSIM:-/tmp/speed10/crawlsim_base} LOGS=$(dirname "$0")/logs
P=gaits/flat_road_paper.csv
R="--legs rod --links 32 --macro-steps 1"
$C rod32_flat --scene flat-road $R --dt 0.00025
$C rod32_earth --scene flat-road $R --dt 0.00025 --conditions earth --gait $P --t-end 1.5
$C rod32_paper --scene flat-road $R --dt 0.00025 --gait $P --conditions paper --t-end 9
$C rod32_paper_0125 --scene flat-road $R --dt 0.000125 --gait $P --conditions paper --t-end 9

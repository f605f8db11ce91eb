#!/bin/sh
# refs.sh: the rod references at 32 elements per segment that this branch regenerates (the
# designed gait's 9.5 s and the obstacle's first 4 s are copied from the lead's
# /work/lead/lv11a/W/track-{flat-road,obstacle}-rod-l32-m1-dt0.00025*.h5 into $D as rod32_flat.h5
# and rod32_obst4.h5): `earth` with the paper's table, the paper's table at 0.25 and 0.125 ms
# (../speed10_2026-12-07c/refs.sh's commands). From the worktree; resumable.
C=$(dirname "$0")/crun.sh
P=gaits/flat_road_paper.csv
R="--legs rod --links 32 --macro-steps 1"
$C rod32_earth --scene flat-road $R --dt 0.00025 --conditions earth --gait $P --t-end 1.5
$C rod32_paper --scene flat-road $R --dt 0.00025 --gait $P --conditions paper --t-end 9
$C rod32_paper_0125 --scene flat-road $R --dt 0.000125 --gait $P --conditions paper --t-end 9

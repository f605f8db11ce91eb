#!/bin/sh
# same.sh: this branch's build (copied to /tmp/speed11/crawlsim_new) against main's (the -O3
# kernels of branch speed10, its runs /tmp/speed10/runs/new_*.h5 made by
# /tmp/speed10/crawlsim_new, main 8b47012's strain code) on the default's runs: the flat road
# (designed gait, 9.5 s), the paper's table (9 s), `earth` with it (1.5 s), the obstacle's
# first 4 s on strain legs, a fixed 5 ms flat road; every float dataset compared
# (../speed9_2026-12-07b/h5diff.py) into same.txt. From the worktree; resumable (crun.sh).
# D, CRAWLSIM, LOGS, OUT override the runs' directory, the binary, the logs and the summary.
H=$(dirname "$0")
C=$H/../levels9_2026-12-07b/crun.sh
export D=${D:-/tmp/speed11/runs} CRAWLSIM=${CRAWLSIM:-/tmp/speed11/crawlsim_new} LOGS=${LOGS:-$H/logs}
OUT=${OUT:-$H/same.txt}
P=gaits/flat_road_paper.csv
$C new_flat --scene flat-road
$C new_obst4 --scene obstacle --legs strain --t-end 4
$C new_paper --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
$C new_earth --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5
$C new_f5_flat --scene flat-road --legs strain --dt 0.005
: > $OUT
for t in new_flat new_obst4 new_paper new_earth new_f5_flat; do
  echo "main $t vs speed11 $t: $(/usr/bin/python3 $H/../speed9_2026-12-07b/h5diff.py /tmp/speed10/runs/$t.h5 $D/$t.h5 | tr '\n' ' ')" >> $OUT
done

#!/bin/sh
# same.sh: main's crawlsim (9210253, copied to /tmp/speed12/base/crawlsim) and this branch's
# (/tmp/speed12/final4/crawlsim or CRAWLSIM_FINAL, artic 2 the default) on the default's runs: the flat road
# (designed gait, 9.5 s), the obstacle's first 4 s on strain legs, the paper's table (9 s),
# `earth` with it (1.5 s), a fixed 5 ms flat road, the obstacle to 8 s on strain legs; every float dataset compared
# (../speed9_2026-12-07b/h5diff.py) into $OUT. From the worktree; resumable (crun.sh).
# DB, DF: the runs' directories; LOGS: the logs (base_*, final_*); OUT the summary.
H=$(dirname "$0")
C=$H/../levels9_2026-12-07b/crun.sh
DB=${DB:-/tmp/speed12/runs_base} DF=${DF:-/tmp/speed12/runs_final}
export LOGS=${LOGS:-$H/logs}
OUT=${OUT:-$H/same.txt}
P=gaits/flat_road_paper.csv
for side in base final; do
  if [ $side = base ]; then export D=$DB CRAWLSIM=/tmp/speed12/base/crawlsim
  else export D=$DF CRAWLSIM=${CRAWLSIM_FINAL:-/tmp/speed12/final4/crawlsim}; fi
  $C ${side}_flat --scene flat-road
  $C ${side}_obst4 --scene obstacle --legs strain --t-end 4
  $C ${side}_paper --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
  $C ${side}_earth --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5
  $C ${side}_f5_flat --scene flat-road --legs strain --dt 0.005
  $C ${side}_obst8 --scene obstacle --legs strain --t-end 8
done
: > $OUT
for t in flat obst4 paper earth f5_flat obst8; do
  echo "main $t vs speed12 $t: $(/usr/bin/python3 $H/../speed9_2026-12-07b/h5diff.py $DB/base_$t.h5 $DF/final_$t.h5 | tr '\n' ' ')" >> $OUT
done

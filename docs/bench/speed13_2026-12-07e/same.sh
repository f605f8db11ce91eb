#!/bin/sh
# same.sh [base|final|both]: main's crawlsim (061d733, copied to /tmp/speed13/base/crawlsim) and
# this branch's (CRAWLSIM_FINAL, default /tmp/speed13/final/crawlsim) on the default's runs: the
# flat road (designed gait, 9.5 s), the obstacle's first 4 s on strain legs, the paper's table
# (9 s), `earth` with it (1.5 s, falls), a fixed 5 ms flat road; every float dataset compared
# (../speed9_2026-12-07b/h5diff.py) into $OUT. From the worktree; resumable (crun.sh): a run
# whose log has its rc line is skipped. As ../speed12_2026-12-07d/same.sh without the 8 s obstacle.
H=$(dirname "$0")
C=$H/../levels9_2026-12-07b/crun.sh
DB=${DB:-/tmp/speed13/runs_base} DF=${DF:-/tmp/speed13/runs_final}
export LOGS=${LOGS:-$H/logs}
OUT=${OUT:-$H/same.txt}
P=gaits/flat_road_paper.csv
SIDES=${1:-both}
[ "$SIDES" = both ] && SIDES="base final"
for side in $SIDES; do
  if [ $side = base ]; then export D=$DB CRAWLSIM=/tmp/speed13/base/crawlsim
  else export D=$DF CRAWLSIM=${CRAWLSIM_FINAL:-/tmp/speed13/final/crawlsim}; fi
  $C ${side}_flat --scene flat-road
  $C ${side}_obst4 --scene obstacle --legs strain --t-end 4
  $C ${side}_paper --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
  $C ${side}_earth --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5
  $C ${side}_f5_flat --scene flat-road --legs strain --dt 0.005
done
[ -f $DF/final_flat.h5 ] || exit 0
: > $OUT
for t in flat obst4 paper earth f5_flat; do
  echo "main $t vs speed13 $t: $(/usr/bin/python3 $H/../speed9_2026-12-07b/h5diff.py $DB/base_$t.h5 $DF/final_$t.h5 | tr '\n' ' ')" >> $OUT
done

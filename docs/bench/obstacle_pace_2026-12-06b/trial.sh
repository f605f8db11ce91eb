#!/bin/sh
# usage: trial.sh GAIT_NAME T_END RUN... : run runs/GAIT_NAME.csv (designed from GAIT_NAME.gait
# here by gen.sh) on the obstacle scene with each robustness option in turn (docs/bench/obstacle_pace_2026-12-06/opts.sh),
# to T_END, one after the other (nice 10; CRAWLSIM: the binary, default build/tools/crawlsim);
# a run whose score file exists is skipped (resumable); logs and Table 3 scores here, lines in
# trials.txt
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_pace_2026-12-06b
g=$1; te=$2; shift 2
. docs/bench/obstacle_pace_2026-12-06/opts.sh
for n in "$@"; do
  [ -s $B/${g}_$n.table3.txt ] && continue
  nice -n 10 ${CRAWLSIM:-build/tools/crawlsim} run --scene obstacle --gait runs/$g.csv --conditions paper --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair $(opt $n) --t-end $te --out runs/${g}_$n.h5 > $B/${g}_$n.log 2>&1
  /usr/bin/python3 docs/bench/obstacle_road_2026-12-05/table3.py runs/${g}_$n.h5 > $B/${g}_$n.table3.txt 2>&1
  echo "${g} $n $(opt $n): $(sed -n 2p $B/${g}_$n.table3.txt) | $(tail -n 1 $B/${g}_$n.table3.txt)" >> $B/trials.txt
done

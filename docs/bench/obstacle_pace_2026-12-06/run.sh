#!/bin/sh
# usage: run.sh NAME T_END [obstacle_gait.py options]: write NAME.gait/.csv, run the obstacle scene
# on the mission's table (rod legs, paper), score against Table 3. RUNARGS: more `crawlsim run`
# options (a terrain of one's own, the robustness set's); the run file goes to runs/NAME.h5
# (not kept: large); CRAWLSIM: the binary (default build/tools/crawlsim)
set -e
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_pace_2026-12-06
CS=${CRAWLSIM:-build/tools/crawlsim}
n=$1; te=$2; shift 2
mkdir -p runs
/usr/bin/python3 tools/obstacle_gait.py -o $B/$n.gait "$@"
nice -n 10 $CS gait design $B/$n.gait --stretch --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4 --out runs/$n.csv > $B/$n.design.log 2>&1
nice -n 10 $CS run --scene obstacle --gait runs/$n.csv --conditions paper --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --t-end $te --out runs/$n.h5 $RUNARGS > $B/$n.log 2>&1 || true
tail -1 $B/$n.log
/usr/bin/python3 docs/bench/obstacle_road_2026-12-05/table3.py runs/$n.h5 | tee $B/$n.table3.txt

#!/bin/sh
# usage: try.sh NAME STATE.npz [obstacle_gait.py options]: write NAME.gait, design it on the
# mission's table into runs/NAME.csv, run it from the saved state (restart.py run; the gait must
# equal the saved run's up to the state's time) and score it: NAME.score.txt
set -e
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_pace_2026-12-06
export CRAWLSIM_LIBRARY=${CRAWLSIM_LIBRARY:-$PWD/build/core/libcrawlsim.so}
n=$1; st=$2; shift 2
mkdir -p runs
/usr/bin/python3 tools/obstacle_gait.py -o $B/$n.gait "$@"
nice -n 10 build/tools/crawlsim gait design $B/$n.gait --stretch --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4 --out runs/$n.csv > $B/$n.design.log 2>&1
nice -n 10 /usr/bin/python3 $B/restart.py run runs/$n.csv $st runs/$n.npz > $B/$n.score.txt 2>&1 || true
cat $B/$n.score.txt

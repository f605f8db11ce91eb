#!/bin/sh
# usage: gen.sh NAME [obstacle_gait.py options]: write NAME.gait here and design it into
# runs/NAME.csv on the mission's table (as run.sh does, without the run), for trial.sh;
# CRAWLSIM: the binary (default build/tools/crawlsim); OUTDIR: the folder of NAME.gait (default this one)
set -e
cd "$(dirname "$0")/../../.."
B=${OUTDIR:-docs/bench/obstacle_pace_2026-12-06}
CS=${CRAWLSIM:-build/tools/crawlsim}
n=$1; shift
mkdir -p runs
/usr/bin/python3 tools/obstacle_gait.py -o $B/$n.gait "$@"
nice -n 10 $CS gait design $B/$n.gait --stretch --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4 --out runs/$n.csv > $B/$n.design.log 2>&1
tail -n 1 $B/$n.design.log

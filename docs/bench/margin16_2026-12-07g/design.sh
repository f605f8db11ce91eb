#!/bin/sh
# usage: design.sh NAME [obstacle_gait.py OPTIONS...]: writes $D/NAME.gait, .gate and .csv as
# gaits/obstacle.* are made (tools/obstacle_gait.py, then `crawlsim gait design --stretch` on the
# mission's table under rbf-pair, p-max 0.4: the header of gaits/obstacle.gait). D default
# /tmp/margin16/g; BIN the crawlsim binary (default build/tools/crawlsim).
cd "$(dirname "$0")/../../.."
D=${D:-/tmp/margin16/g}; BIN=${BIN:-build/tools/crawlsim}
n=$1; shift
mkdir -p "$D"
/usr/bin/python3 tools/obstacle_gait.py "$@" -o "$D/$n.gait" --gate-out "$D/$n.gate" || exit 1
$BIN gait design "$D/$n.gait" --stretch --out "$D/$n.csv" \
  --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4 > /dev/null

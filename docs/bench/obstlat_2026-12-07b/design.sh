#!/bin/sh
# usage: design.sh NAME [obstacle_gait.py OPTIONS...]  writes $D/NAME.gait, its landing gate
# $D/NAME.gate (none for a description without a wave: the lateral probe) and its table
# $D/NAME.csv, designed as gaits/obstacle.csv is (the mission's table under rbf-pair, --stretch,
# p-max 0.4; tools/obstacle_gait.py's header). D default /work/rom_data/obstlat (not kept: each
# file is regenerated in seconds by its line in README.md).
cd "$(dirname "$0")/../../.."
D=${D:-/work/rom_data/obstlat}
n=$1; shift
mkdir -p "$D"
/usr/bin/python3 tools/obstacle_gait.py "$@" -o "$D/$n.gait" --gate-out "$D/$n.gate" 2>/dev/null ||
  { rm -f "$D/$n.gate"; /usr/bin/python3 tools/obstacle_gait.py "$@" -o "$D/$n.gait" || exit 1; }
build/tools/crawlsim gait design "$D/$n.gait" --stretch --out "$D/$n.csv" \
  --calibration robot/calibration_fe_leg_modes_sym.h5 --cal-rule rbf-pair --p-max 0.4 > /dev/null

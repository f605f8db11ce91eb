#!/bin/sh
# usage: design.sh NAME [obstacle_gait.py OPTIONS...]  writes $D/NAME.gait, .gate and .csv as
# docs/bench/obststrain_2026-12-07/design.sh does, into D (default /work/rom_data/obst).
D=${D:-/work/rom_data/obst} exec "$(dirname "$0")/../obststrain_2026-12-07/design.sh" "$@"

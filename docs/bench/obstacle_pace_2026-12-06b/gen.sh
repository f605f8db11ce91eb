#!/bin/sh
# usage: gen.sh NAME [obstacle_gait.py options]: docs/bench/obstacle_pace_2026-12-06/gen.sh
# writing NAME.gait here (and runs/NAME.csv); CRAWLSIM: the binary
exec env OUTDIR=docs/bench/obstacle_pace_2026-12-06b "$(dirname "$0")/../obstacle_pace_2026-12-06/gen.sh" "$@"

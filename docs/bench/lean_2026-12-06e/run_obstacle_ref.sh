#!/bin/sh
# run_obstacle_ref.sh CRAWLSIM OUT.h5: the obstacle's first 4 s on the nodal rod at 16 elements
# per segment and 0.25 ms (the reference of robot/levels.csv, tools/bench_levels.py --ref-*), on
# the scene's current defaults (its k3 table since the fourth session).
uptime
/usr/bin/time -f "%U s user %e s wall" nice -n 5 "$1" run --scene obstacle --legs rod --links 16 \
  --dt 0.00025 --t-end 4 --out "$2"
uptime

#!/bin/sh
# run_part1.sh CRAWLSIM OUTDIR TAG: the 9 s flat road and the obstacle's first 4 s on the rod
# (the scenes' default legs) and on strain legs (--legs strain, its defaults), one run at a
# time, each run's summary and verdict kept in OUTDIR/TAG_*.log and its track in
# OUTDIR/TAG_*.h5 (compare with tracks.py). Run with CRAWLSIM a build's tools/crawlsim, from
# the worktree's root (the data paths are the scenes' defaults, relative to the binary).
C=$1; O=$2; T=$3
mkdir -p "$O"
uptime
for legs in strain rod; do
  /usr/bin/time -f "%U s user %e s wall" nice -n 5 "$C" run --scene flat-road --legs $legs --t-end 9 \
    --out "$O/${T}_flat_$legs.h5" > "$O/${T}_flat_$legs.log" 2>&1
  /usr/bin/time -f "%U s user %e s wall" nice -n 5 "$C" run --scene obstacle --legs $legs --t-end 4 \
    --out "$O/${T}_obst_$legs.h5" > "$O/${T}_obst_$legs.log" 2>&1
  uptime
done

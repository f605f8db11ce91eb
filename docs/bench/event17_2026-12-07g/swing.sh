#!/bin/bash
# swing.sh BIN OUT F...: the default with the swing feet's positions watched at F times the step
# tolerance (scratch: EV17_SWING=F in trace.patch's sim_adaptive.c watched(); a foot whose leg's
# contactDepth is 0 at the step's end), flat road 9.5 s and the obstacle's first 4 s, run files in
# OUT/swF (tracks against OUT/def: tracks.py)
BIN=$1; OUT=$2; shift 2
export CS_SOURCE_DIR=${CS_SOURCE_DIR:-/tmp/event17/src}
for F in "$@"; do
  d=$OUT/sw$F; mkdir -p $d; uptime
  EV17_SWING=$F CS_BENCH_KEEP=$d CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $BIN 9.5 strain:2 2>&1 | grep -E "x\(end\)|window"
  EV17_SWING=$F CS_BENCH_SCENE=obstacle CS_BENCH_KEEP=$d CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $BIN 4 strain:2 2>&1 | grep -E "x\(end\)|window"
done
uptime

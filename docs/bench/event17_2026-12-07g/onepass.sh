#!/bin/bash
# onepass.sh BIN OUT: the default (strain:2, adaptive 2.5e-4 mm) and the same with one tree pass
# per try (CS_BENCH_PASSES=1: every leg linearised and condensed once, at the step's start; no
# Newton), flat road 9.5 s and the obstacle's first 4 s, run files kept in OUT/{def,one}
BIN=$1; OUT=$2
export CS_SOURCE_DIR=${CS_SOURCE_DIR:-/tmp/event17/src}
for tag in def:0 one:1; do
  d=$OUT/${tag%%:*}; p=${tag##*:}; mkdir -p $d; uptime
  CS_BENCH_KEEP=$d CS_BENCH_PASSES=$p CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $BIN 9.5 strain:2 2>&1 | grep -E "x\(end\)|window|tree"
  CS_BENCH_SCENE=obstacle CS_BENCH_KEEP=$d CS_BENCH_PASSES=$p CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $BIN 4 strain:2 2>&1 | grep -E "x\(end\)|window|tree"
done
uptime

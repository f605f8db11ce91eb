#!/bin/bash
# branch.sh: the branch's build (tree_carry in the library): its default against the scratch
# build's (trace off: main's code), and CS_BENCH_PASSES=1 CS_BENCH_CARRY=1 against the scratch
# EV17_CARRY=2 runs; flat road 9.5 s and the obstacle's first 4 s. Files in R/br_def, R/br_carry.
W=${W:-/work/wt-event17}; R=${R:-/tmp/event17/runs}
export CS_SOURCE_DIR=$W
B=$W/build/tests/core/bench_strain_driver
uptime
for tag in def:0 carry:1; do
  d=$R/br_${tag%%:*}; c=${tag##*:}; mkdir -p $d
  if [ $c = 1 ]; then P=1; else P=0; fi
  CS_BENCH_KEEP=$d CS_BENCH_PASSES=$P CS_BENCH_CARRY=$c CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $B 9.5 strain:2 2>&1 | grep -E "x\(end\)|window"
  CS_BENCH_SCENE=obstacle CS_BENCH_KEEP=$d CS_BENCH_PASSES=$P CS_BENCH_CARRY=$c CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $B 4 strain:2 2>&1 | grep -E "x\(end\)|window"
done
uptime

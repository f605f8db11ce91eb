#!/bin/sh
# usage: robust.sh [NAME...]: the robustness set of issue 33 on the shipped obstacle gait
# (`crawlsim run --scene obstacle` plus one option each), one run after the other (nice 10);
# logs and Table 3 scores here, run files in runs/ (not kept)
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_pace_2026-12-06
mkdir -p runs
. $B/opts.sh
names=${*:-"nominal ramp0.1 ramp0.5 mu0.6 mu1.0 m25g m75g tau0.5x tau2x dt_half"}
for n in $names; do
  nice -n 10 build/tools/crawlsim run --scene obstacle $(opt $n) --out runs/r_$n.h5 > $B/r_$n.log 2>&1
  /usr/bin/python3 docs/bench/obstacle_road_2026-12-05/table3.py runs/r_$n.h5 > $B/r_$n.table3.txt 2>&1
  echo "$n $(opt $n): $(tail -n 1 $B/r_$n.table3.txt)"
done

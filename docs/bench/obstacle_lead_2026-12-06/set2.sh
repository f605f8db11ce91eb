#!/bin/sh
# usage: set2.sh GAIT RUN: one robustness run (issue 33's set) of runs/GAIT.csv (no footholds) on the
# obstacle scene to 35 s under `paper`, scored against Table 3; run two at a time with xargs -P2:
#   for g in shipped k3; do for n in nominal ramp0.1 ...; do echo $g $n; done; done | xargs -P2 -n2 sh set2.sh
# (runs/shipped.csv is gaits/obstacle.csv; runs/k3.csv from docs/bench/obstacle_2026-12-06c/README.md).
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_lead_2026-12-06
g=$1; n=$2
. docs/bench/obstacle_pace_2026-12-06/opts.sh
[ -s $B/${g}_$n.table3.txt ] && exit 0
nice -n 5 ${CRAWLSIM:-build/tools/crawlsim} run --scene obstacle --gait runs/$g.csv --conditions paper $(opt $n) --t-end 35 --out runs/${g}_$n.h5 > $B/${g}_$n.log 2>&1
/usr/bin/python3 docs/bench/obstacle_road_2026-12-05/table3.py runs/${g}_$n.h5 > $B/${g}_$n.table3.txt 2>&1
echo "${g} $n $(opt $n): $(sed -n 2p $B/${g}_$n.table3.txt) | $(tail -n 1 $B/${g}_$n.table3.txt)" >> $B/set.txt

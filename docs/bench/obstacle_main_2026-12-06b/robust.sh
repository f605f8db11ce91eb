#!/bin/sh
# usage: robust.sh [NAME...]: issue 33's robustness set on the shipped obstacle gait at the
# current main (`crawlsim run --scene obstacle` plus one option each; the options in
# ../obstacle_pace_2026-12-06/opts.sh), plus ramps 0.49 and 0.51 (how sharp the ramp's edge is);
# logs and Table 3 scores here, run files in runs/ (not kept). Resumable: a name whose score
# exists is skipped.
cd "$(dirname "$0")/../../.."
B=docs/bench/obstacle_main_2026-12-06b
mkdir -p runs
. docs/bench/obstacle_pace_2026-12-06/opts.sh
o() { case $1 in ramp0.49) echo "--ramp 0.49" ;; ramp0.51) echo "--ramp 0.51" ;; *) opt $1 ;; esac; }
names=${*:-"nominal ramp0.1 ramp0.5 mu0.6 mu1.0 m25g m75g tau0.5x tau2x dt_half ramp0.49 ramp0.51"}
for n in $names; do
  [ -s $B/r_$n.table3.txt ] && continue
  nice -n 10 build/tools/crawlsim run --scene obstacle $(o $n) --out runs/m_$n.h5 > $B/r_$n.log 2>&1
  /usr/bin/python3 docs/bench/obstacle_road_2026-12-05/table3.py runs/m_$n.h5 > $B/r_$n.table3.txt 2>&1
  echo "$n $(o $n): $(tail -n 1 $B/r_$n.table3.txt)" >> $B/robust.txt
done

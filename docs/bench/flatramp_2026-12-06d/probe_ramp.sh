#!/bin/sh
# usage: probe_ramp.sh [DIR/]KEY RAMP...: the search's design KEY (DIR/cases/dKEY/gait.csv, DIR
# search/ unless given, solved by tools/gait_search.py) run on the default model with each
# actuation time RAMP (s); log per run in probe/r_[DIR_]KEY_rRAMP.log (resumable: a log ending
# in a verdict is skipped), nice'd, one at a time; summary:
# /usr/bin/python3 docs/bench/ramp_2026-12-06/summarise.py docs/bench/flatramp_2026-12-06d/probe
cd "$(dirname "$0")/../../.."
B=docs/bench/flatramp_2026-12-06d
k=${1:?usage: probe_ramp.sh [DIR/]KEY RAMP...}
shift
case $k in
  */*) d=${k%/*}; k=${k#*/}; tag=${d}_$k ;;
  *) d=search; tag=$k ;;
esac
mkdir -p $B/probe runs
for r in "$@"; do
  n=${tag}_r$r
  grep -q '^verdict' $B/probe/r_$n.log 2>/dev/null && continue
  nice -n 5 build/tools/crawlsim run --scene flat-road --conditions paper --gait $B/$d/cases/d$k/gait.csv \
    --ramp $r --out runs/flatramp_$n.h5 > $B/probe/r_$n.log 2>&1
  echo "$n: --conditions paper --gait $d/cases/d$k/gait.csv --ramp $r" > $B/probe/o_$n.txt
done

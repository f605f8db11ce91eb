#!/bin/sh
# runs.sh WHO [long]: crawlsim (/tmp/bdf15/bin/crawlsim_WHO) on the flat road and the obstacle,
# 2 s, BDF2 adaptive 5e-4 mm (o2) and backward Euler's default (o1); with `long`: BDF2 5e-4 on
# the flat road's whole gait (9.5 s) and the obstacle's first 4 s; with `paper`: BDF2 5e-4 on
# the flat road with the paper's table (9 s) and under `earth` (1.5 s: it falls). h5 and logs in
# /tmp/bdf15/runs (or $BDF_SCRATCH/runs; resumable: a run whose h5 exists is skipped)
S=${BDF_SCRATCH:-/tmp/bdf15}
W=$1; B=$S/bin/crawlsim_$1
cd "$(dirname "$0")/../../.." || exit 1
mkdir -p $S/runs
one() { # FILE ARGS...
  f=$1; shift
  [ -f $f.h5 ] && return
  (uptime; /usr/bin/time -f "cpu %U s" nice -n 5 $B run "$@" --out $f.h5.tmp; uptime) > $f.log 2>&1
  mv $f.h5.tmp $f.h5
}
P=gaits/flat_road_paper.csv
O2="--legs strain --strain-step adaptive --step-order 2 --step-tol 5e-4"
if [ "$2" = paper ]; then
  one $S/runs/$W.paper.flat-road --scene flat-road $O2 --gait $P --conditions paper --t-end 9
  one $S/runs/$W.earth.flat-road --scene flat-road $O2 --gait $P --conditions earth --t-end 1.5
  exit 0
fi
if [ "$2" = long ]; then
  one $S/runs/$W.long.flat-road --scene flat-road --legs strain --strain-step adaptive --step-order 2 --step-tol 5e-4
  one $S/runs/$W.long.obstacle --scene obstacle --legs strain --strain-step adaptive --step-order 2 --step-tol 5e-4 --t-end 4
  exit 0
fi
for s in flat-road obstacle; do
  one $S/runs/$W.o2.$s --scene $s --legs strain --strain-step adaptive --step-order 2 --step-tol 5e-4 --t-end 2
  one $S/runs/$W.o1.$s --scene $s --legs strain --t-end 2
done
# (extra, run by hand) BDF2 at fixed steps, flat road 2 s: main against the final
#   crawlsim_WHO run --scene flat-road --legs strain --step-order 2 [--dt 0.005] --t-end 2
#   -> /tmp/bdf15/runs/WHO.f2[_5ms].flat-road.h5; compared by compare_fixed.py

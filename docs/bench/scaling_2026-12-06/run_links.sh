#!/bin/sh
# usage: run_links.sh DT LINKS...: the 9 s flat road (scene defaults) on strain legs at each
# number of bending modes per segment (--links, bend order LINKS - 1); resumable (a finished
# run leaves a .done). Compare with ../strain_driver_2026-12-05/compare.py REF.h5 RUN.h5 ...
cd "$(dirname "$0")/../../.." && mkdir -p build/sc
dt=$1; shift
for l in "$@"; do
  n=build/sc/flat_${dt}_l$l
  [ -f $n.done ] && continue
  /usr/bin/time -f "cpu %U s wall %e s" nice -n 10 build/tools/crawlsim run --scene flat-road \
    --legs strain --dt $dt --links $l --out $n.h5 > $n.log 2>&1 && touch $n.done
done

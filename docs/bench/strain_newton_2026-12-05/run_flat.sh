#!/bin/sh
# usage: run.sh DT...
cd "$(dirname "$0")/../../.." && mkdir -p build/sn
for dt in "$@"; do
  n=build/sn/flat_$dt
  [ -f $n.done ] && continue
  /usr/bin/time -f "cpu %U s wall %e s" nice -n 10 build/tools/crawlsim run --scene flat-road --legs strain --dt $dt --out $n.h5 > $n.log 2>&1 && touch $n.done
done

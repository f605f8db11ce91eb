#!/bin/sh
cd "$(dirname "$0")/../../.." && mkdir -p build/sn
for dt in "$@"; do
  n=build/sn/ob_$dt
  [ -f $n.done ] && continue
  /usr/bin/time -f "cpu %U s wall %e s" nice -n 10 build/tools/crawlsim run --scene obstacle --legs strain --dt $dt --t-end 4 --out $n.h5 > $n.log 2>&1 && touch $n.done
done

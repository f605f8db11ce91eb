#!/bin/sh
# usage: run_flat.sh TAG BINARY DT...   (9 s flat road, the scene's defaults, strain legs;
# logs into build/ss/TAG_DT.log; the support's x at whole seconds is in the log)
cd "$(dirname "$0")/../../.." && mkdir -p build/ss
tag=$1; bin=$2; shift 2
for dt in "$@"; do
  n=build/ss/${tag}_$dt
  [ -f $n.done ] && continue
  uptime > $n.log
  /usr/bin/time -f "cpu %U s wall %e s" nice -n 10 $bin run --scene flat-road --legs strain --dt $dt --out $n.h5 >> $n.log 2>&1 && touch $n.done
done

#!/bin/bash
# interleaved CPU: main (with this bench) against the branch, the flat road's first 3 s at 5 ms and 1 ms
cd /work/wt-kernel/build/tests/core
K=/work/wt-kernel/build/kb
for rep in 1 2; do
  for spec in strain:3:0.005:1 strain:3:0.001:1; do
    /tmp/kbase/bench_mainscene 3 $spec 2>&1 | head -1 | sed "s/^/main rep$rep: /" >> $K/ab_final.txt
    /tmp/kbase/bench_new5 3 $spec 2>&1 | head -1 | sed "s/^/kernel rep$rep: /" >> $K/ab_final.txt
  done
done
uptime >> $K/ab_final.txt

#!/bin/sh
# elements per segment of the rod legs on the mission's table (flat road, shipped gait)
B=build/tools/crawlsim  # from the repository root
for n in 4 8 12 16; do
  [ -f links_$n.h5 ] && continue
  /usr/bin/time -f "cpu %U s wall %e s" $B run --scene flat-road --legs rod --links $n --out links_$n.tmp.h5 > links_$n.log 2>&1 && mv links_$n.tmp.h5 links_$n.h5
done

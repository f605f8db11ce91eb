#!/bin/bash
# rod.sh: the references, the nodal rod at 32 elements per segment and 0.25 ms (as
# ../levels9_2026-12-07b/queue.sh): the flat road's designed gait 9.5 s, the obstacle's first
# 4 s (both in parallel), then the paper's table 9 s; the branch's crawlsim. Files in R.
W=${W:-/work/wt-event17}; R=${R:-/tmp/event17/runs}; L=$(cd $(dirname "$0") && pwd)/logs
C=$W/build/tools/crawlsim
cd $W
run() { local tag=$1; shift
  { uptime; echo "crawlsim run $* --quiet --out $R/$tag.h5"
    /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 $C run "$@" --quiet --out $R/$tag.h5
    echo "rc $?"; uptime; } > $L/$tag.log 2>&1; echo "$tag $(grep '^rc ' $L/$tag.log)"; }
run rod32_flat --scene flat-road --legs rod --links 32 --macro-steps 1 --dt 0.00025 &
run rod32_obst4 --scene obstacle --legs rod --links 32 --macro-steps 1 --dt 0.00025 --t-end 4 &
wait
run rod32_paper --scene flat-road --legs rod --links 32 --macro-steps 1 --dt 0.00025 --gait gaits/flat_road_paper.csv --conditions paper --t-end 9

#!/bin/sh
# crawlsim run: the flat road (9 s, scene defaults) and the obstacle's first 4 s with the
# strain legs' BDF2 step (--step-order 2; linearly implicit, the level's step_refresh 0 from
# branch `fast`) at 5 / 2.5 ms. From the repository root; run files under build/fast, logs
# beside this script. Usage: [CRAWLSIM=binary] run_driver.sh [TAG [EXTRA CRAWLSIM ARGS...]]
out=$(dirname "$0")
tag=${1:-o2}; [ $# -gt 0 ] && shift
mkdir -p build/fast
run() { # name args...
  n=$1; shift
  [ -f build/fast/$n.done ] && return
  /usr/bin/time -f "cpu %U s wall %e s" nice -n 10 ${CRAWLSIM:-build/tools/crawlsim} run "$@" --out build/fast/$n.h5 > "$out/$n.log" 2>&1 && touch build/fast/$n.done
}
for dt in 5e-3 2.5e-3; do run flat_${tag}_$dt --scene flat-road --legs strain --dt $dt --step-order 2 "$@"; done
for dt in 5e-3 2.5e-3; do run ob_${tag}_$dt --scene obstacle --legs strain --dt $dt --step-order 2 --t-end 4 "$@"; done

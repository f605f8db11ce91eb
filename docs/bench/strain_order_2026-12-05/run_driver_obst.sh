#!/bin/sh
# crawlsim run, the obstacle's first 4 s (scene defaults) with BDF2 at 5 / 2.5 ms, then the
# flat road with BDF2 at 1.25 ms. From the repository root; logs beside this script.
out=$(dirname "$0")
run() { # name args...
  n=$1; shift
  [ -f build/so/$n.done ] && return
  /usr/bin/time -f "cpu %U s wall %e s" nice -n 10 build/tools/crawlsim run "$@" --out build/so/$n.h5 > "$out/$n.log" 2>&1 && touch build/so/$n.done
}
for dt in 5e-3 2.5e-3; do run ob_o2_$dt --scene obstacle --legs strain --dt $dt --step-order 2 --t-end 4; done
run flat_o2_1.25e-3 --scene flat-road --legs strain --dt 1.25e-3 --step-order 2

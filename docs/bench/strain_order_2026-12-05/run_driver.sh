#!/bin/sh
# crawlsim run on the flat road (9 s) and the obstacle (first 4 s), strain legs at their scene
# defaults, after the drift fix: backward Euler at several steps, then BDF2 (--step-order 2).
# Run from the repository root; run files under build/so, logs beside this script.
out=$(dirname "$0")
mkdir -p build/so
uptime > "$out/uptime_driver.txt"
run() { # name args...
  n=$1; shift
  [ -f build/so/$n.done ] && return
  /usr/bin/time -f "cpu %U s wall %e s" nice -n 10 build/tools/crawlsim run "$@" --out build/so/$n.h5 > "$out/$n.log" 2>&1 && touch build/so/$n.done
}
for dt in 5e-3 2.5e-3 1.25e-3 1e-3 5e-4; do run flat_o1_$dt --scene flat-road --legs strain --dt $dt --step-order 1; done
for dt in 2e-3 1e-3 5e-4; do run ob_o1_$dt --scene obstacle --legs strain --dt $dt --step-order 1 --t-end 4; done
for dt in 1e-3 5e-4; do run flat_o2_$dt --scene flat-road --legs strain --dt $dt --step-order 2; done
uptime >> "$out/uptime_driver.txt"

#!/bin/sh
# The tree harness without ODE (tests/robot/strain_test_robot.h), flat road, mu 0.8, 8 s,
# Newton to 1e-7, bend order 2: backward Euler (1) and BDF2 (2) at 5 / 2.5 / 1.25 / 0.625 ms.
# Run from the repository root after building bench_strain_robot; outputs beside this script.
set -e
out=$(dirname "$0")
export CS_SOURCE_DIR=$PWD
uptime > "$out/uptime_harness.txt"
for so in ${ORDERS:-2 1}; do
  for h in ${STEPS:-5e-3 2.5e-3 1.25e-3 6.25e-4}; do
    f="$out/harness_o${so}_h${h}.txt"
    [ -s "$f" ] && grep -q "^wall" "$f" && continue
    nice -n 10 build/tests/robot/bench_strain_robot gaits/flat_road.csv 0.8 "$h" "${T_END:-8}" 2 16 1e-7 "$so" > "$f" 2>&1 || true
  done
done
uptime >> "$out/uptime_harness.txt"

#!/bin/bash
# carry.sh MODE: one linearised tree pass per try (EV17_PASSES=1 / CS_BENCH_PASSES=1) with the
# legs' momentum residual carried into the next step's support solve, scratch build
# (trace.patch), against the default of the same binary (the env unset). Files in R.
#   MODE 1 (EV17_CARRY=1, the law evaluated at the step's end): the flat road 9.5 s and the
#     obstacle's first 4 s (bench_strain_driver, R/onec), the paper's table 9 s and `earth` with
#     it 1.5 s (crawlsim run: def_*, onec_*, and one_paper without the carry)
#   MODE 2 (EV17_CARRY=2, the step's linear model's contact force, as the branch's tree_carry):
#     the paper's table, `earth`, the whole obstacle climb, and the default's climb (def_obst);
#     its bench runs (R/onec2) were run by hand with the same variables (README)
# BT the scratch build dir, R the runs dir.
MODE=${1:-1}
BT=${BT:-/tmp/event17/bt}; R=${R:-/tmp/event17/runs}
export CS_SOURCE_DIR=${CS_SOURCE_DIR:-/tmp/event17/src}
L=$(cd $(dirname "$0") && pwd)/logs
B=$BT/tests/core/bench_strain_driver; C=$BT/tools/crawlsim
P=$CS_SOURCE_DIR/gaits/flat_road_paper.csv
run() { # TAG ENV... -- ARGS
  local tag=$1; shift; local env=(); while [ "$1" != "--" ]; do env+=("$1"); shift; done; shift
  { uptime; echo "${env[*]} crawlsim run $* --quiet --out $R/$tag.h5"
    env "${env[@]}" /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 $C run "$@" --quiet --out $R/$tag.h5
    echo "rc $?"; uptime; } > $L/$tag.log 2>&1
  echo "$tag $(grep '^rc ' $L/$tag.log)"
}
uptime
if [ "$MODE" = 1 ]; then
  mkdir -p $R/onec
  EV17_CARRY=1 CS_BENCH_KEEP=$R/onec CS_BENCH_PASSES=1 CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $B 9.5 strain:2 2>&1 | grep -E "x\(end\)|window"
  EV17_CARRY=1 CS_BENCH_SCENE=obstacle CS_BENCH_KEEP=$R/onec CS_BENCH_PASSES=1 CS_BENCH_ADAPTIVE=2.5e-4 nice -n 5 $B 4 strain:2 2>&1 | grep -E "x\(end\)|window"
  cd $CS_SOURCE_DIR
  run def_paper X=0 -- --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
  run onec_paper EV17_PASSES=1 EV17_CARRY=1 -- --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
  run def_earth X=0 -- --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5
  run onec_earth EV17_PASSES=1 EV17_CARRY=1 -- --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5
  run one_paper EV17_PASSES=1 -- --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
else
  cd $CS_SOURCE_DIR
  run onec2_paper EV17_PASSES=1 EV17_CARRY=2 -- --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
  run onec2_earth EV17_PASSES=1 EV17_CARRY=2 -- --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5
  run onec2_obst EV17_PASSES=1 EV17_CARRY=2 -- --scene obstacle --legs strain
  run def_obst X=0 -- --scene obstacle --legs strain
fi
uptime

#!/bin/sh
# strain.sh [STEP...]: the flat road on strain legs at fixed backward-Euler steps (default 0.005)
# against every rule the step touches, plus the old default (adaptive 2.5e-4 mm) for the
# comparison. Tags: fSTEP_* (fixed STEP s), hSTEP_* (its half step), def_* (the base default).
# From the worktree; resumable. CRAWLSIM picks the binary (crun.sh).
C=$(dirname "$0")/../levels9_2026-12-07b/crun.sh
export D=/tmp/speed10/runs CRAWLSIM=${CRAWLSIM:-/tmp/speed10/crawlsim_base} LOGS=$(dirname "$0")/logs
P=gaits/flat_road_paper.csv
for H in ${*:-0.005}; do
  HH=$(/usr/bin/python3 -c "print($H/2)")
  S="--scene flat-road --legs strain --dt $H"
  $C f${H}_flat $S
  $C h${H}_flat --scene flat-road --legs strain --dt $HH
  $C f${H}_paper $S --gait $P --conditions paper --t-end 9
  $C h${H}_paper --scene flat-road --legs strain --dt $HH --gait $P --conditions paper --t-end 9
  $C f${H}_earth $S --conditions earth --gait $P --t-end 1.5
  for r in "ramp0.1 --ramp 0.1" "ramp0.5 --ramp 0.5" "mu0.6 --friction 0.6" "mu1.0 --friction 1.0" \
           "m25g --support-mass 0.025" "m75g --support-mass 0.075" "tau0.5x --tau 0.01" \
           "tau2x --tau 0.04" "mu0 --friction 0"; do
    set -- $r; n=$1; shift
    $C f${H}_$n $S "$@"
  done
done
$C def_flat --scene flat-road
$C def_paper --scene flat-road --legs strain --gait $P --conditions paper --t-end 9
$C def_earth --scene flat-road --legs strain --conditions earth --gait $P --t-end 1.5

#!/bin/sh
# batch.sh: dflt15's whole batch, one pair (pair.sh) after the other: two runs at a time.
# Cases (issue 32's brief for dflt15): the paper's table (9 s, against the rod at 0.125 ms) and
# its half tolerance; the obstacle's whole climb (nominal, no --t-end: the gated run ends with
# its table) and its half tolerance; the flat road's nominal and half tolerance; `earth` on both
# scenes (the scene's gait) and with the paper's table (1.5 s, against the rod); the two
# robustness sets (issue33_status.md: flat_set.sh's and obst13's run.sh's options); friction 0.
# From the worktree; resumable (pair.sh skips finished runs). Usage: sh batch.sh [CASE...]
H=$(dirname "$0")
P=gaits/flat_road_paper.csv
B=5e-4; BH=2.5e-4; DH=1.25e-4
cases="paper|--scene flat-road --gait $P --conditions paper --t-end 9|-|$B
paper_half|--scene flat-road --gait $P --conditions paper --t-end 9|$DH|$BH
o_nominal|--scene obstacle|-|$B
o_half|--scene obstacle|$DH|$BH
f_nominal|--scene flat-road|-|$B
f_half|--scene flat-road|$DH|$BH
f_earth|--scene flat-road --conditions earth|-|$B
o_earth|--scene obstacle --conditions earth|-|$B
p_earth|--scene flat-road --conditions earth --gait $P --t-end 1.5|-|$B
f_ramp0.1|--scene flat-road --ramp 0.1|-|$B
f_ramp0.5|--scene flat-road --ramp 0.5|-|$B
f_mu0.6|--scene flat-road --friction 0.6|-|$B
f_mu1.0|--scene flat-road --friction 1.0|-|$B
f_m25g|--scene flat-road --support-mass 0.025|-|$B
f_m75g|--scene flat-road --support-mass 0.075|-|$B
f_tau0.5x|--scene flat-road --tau 0.01|-|$B
f_tau2x|--scene flat-road --tau 0.04|-|$B
f_mu0|--scene flat-road --friction 0|-|$B
o_ramp0.1|--scene obstacle --ramp 0.1|-|$B
o_ramp0.5|--scene obstacle --ramp 0.5|-|$B
o_mu0.6|--scene obstacle --friction 0.6|-|$B
o_mu1.0|--scene obstacle --friction 1.0|-|$B
o_m25g|--scene obstacle --support-mass 0.025|-|$B
o_m75g|--scene obstacle --support-mass 0.075|-|$B
o_tau0.5x|--scene obstacle --tau 0.01|-|$B
o_tau2x|--scene obstacle --tau 0.04|-|$B"
printf '%s\n' "$cases" | while IFS='|' read -r n a dt bt; do
  if [ $# -gt 0 ]; then
    w=0; for c in "$@"; do [ "$c" = "$n" ] && w=1; done; [ $w = 1 ] || continue
  fi
  sh "$H/pair.sh" "$n" "$a" "$dt" "$bt"
done

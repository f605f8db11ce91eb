#!/bin/sh
# usage: robust.sh [NAME...]: issue 33's flat-road robustness set at the current main
# (`crawlsim run --scene flat-road` plus one option each); x at 9 s per run into robust.txt.
# Resumable: a run whose log ends in a verdict is skipped.
cd "$(dirname "$0")/../../.."
B=docs/bench/flat_main_2026-12-06b
mkdir -p runs
o() {
  case $1 in
    nominal) echo "" ;; ramp0.1) echo "--ramp 0.1" ;; ramp0.5) echo "--ramp 0.5" ;;
    mu0.6) echo "--friction 0.6" ;; mu1.0) echo "--friction 1.0" ;; mu0) echo "--friction 0" ;;
    m25g) echo "--support-mass 0.025" ;; m75g) echo "--support-mass 0.075" ;;
    tau0.5x) echo "--tau 0.01" ;; tau2x) echo "--tau 0.04" ;; dt_half) echo "--dt 0.0005" ;;
  esac
}
names=${*:-"nominal ramp0.1 ramp0.5 mu0.6 mu1.0 m25g m75g tau0.5x tau2x dt_half mu0"}
for n in $names; do
  grep -q '^verdict' $B/r_$n.log 2>/dev/null && continue
  nice -n 10 build/tools/crawlsim run --scene flat-road $(o $n) --out runs/f_$n.h5 > $B/r_$n.log 2>&1
  echo "$n $(o $n): $(grep '^  t =  9.00' $B/r_$n.log) | $(grep '^verdict' $B/r_$n.log)" >> $B/robust.txt
done

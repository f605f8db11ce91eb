#!/bin/sh
# usage: robust.sh LEGS [NAME...]: issue 33's flat-road robustness set with the ramp as an
# actuation time (gaits/gaits_schedule.h, 2026-12-06): `crawlsim run --scene flat-road` on
# LEGS plus one option each. LEGS: rod (the default, 8 elements), strain1 (--legs strain, its
# 1 ms backward Euler step), strain5 (--legs strain --dt 0.005 --step-order 2: BDF2 at 5 ms).
# Each run's log goes to LEGS/r_NAME.log; a line per run (x at every whole second from 2 s
# against Table 2, x at 9 s against 312 mm, max |z|, tilt) into LEGS/robust.txt (by
# summarise.py). Resumable: a run whose log ends in a verdict is skipped.
# Runs are nice'd; one at a time (a rod run is ~10 CPU s, a strain run ~5-7).
cd "$(dirname "$0")/../../.."
B=docs/bench/ramp_2026-12-06
L=${1:?usage: robust.sh rod|strain1|strain5 [NAME...]}
shift
case $L in
  rod) base="" ; half="--dt 0.0005" ;;
  strain1) base="--legs strain" ; half="--dt 0.0005" ;;
  strain5) base="--legs strain --dt 0.005 --step-order 2" ; half="--legs strain --dt 0.0025 --step-order 2" ;;
  *) echo "unknown LEGS $L" >&2; exit 2 ;;
esac
o() {
  case $1 in
    nominal) echo "$base" ;; ramp0.1) echo "$base --ramp 0.1" ;; ramp0.5) echo "$base --ramp 0.5" ;;
    ramp0.2) echo "$base --ramp 0.2" ;; ramp0.3) echo "$base --ramp 0.3" ;;
    mu0.6) echo "$base --friction 0.6" ;; mu1.0) echo "$base --friction 1.0" ;; mu0) echo "$base --friction 0" ;;
    m25g) echo "$base --support-mass 0.025" ;; m75g) echo "$base --support-mass 0.075" ;;
    tau0.5x) echo "$base --tau 0.01" ;; tau2x) echo "$base --tau 0.04" ;;
    dt_half) if [ $L = strain5 ]; then echo "$half"; else echo "$base $half"; fi ;;
  esac
}
mkdir -p $B/$L runs
names=${*:-"nominal ramp0.1 ramp0.5 mu0.6 mu1.0 m25g m75g tau0.5x tau2x dt_half mu0"}
for n in $names; do
  grep -q '^verdict' $B/$L/r_$n.log 2>/dev/null && continue
  nice -n 5 build/tools/crawlsim run --scene flat-road $(o $n) --out runs/ramp_${L}_$n.h5 \
    > $B/$L/r_$n.log 2>&1
  echo "$n: $(o $n)" > $B/$L/o_$n.txt
done
/usr/bin/python3 $B/summarise.py $B/$L > $B/$L/robust.txt

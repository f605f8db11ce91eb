#!/bin/sh
# usage: crawl_end.sh CASE...  crawl_end.py on the table z12 (tools/obstacle_gait.py --Dz 45: the
# shipped bf50 with 12 lateral slots, written into $D by docs/bench/obst_2026-12-07b/design.sh
# z12 --Dz 45), one run after the other, nice 5, resumable (ce_CASE.txt here skips the case).
# CASE: nominal m25g m75g (the support's mass 50 / 25 / 75 g), mu0.6 mu1.0 tau0.5x tau2x ramp0.1
# dt_half (the set's other runs); fixed8 (nominal, the crawl ended
# after 8 slots whatever is measured: the shipped table's crawl through the controller, a check
# of the jump against nominal.txt).
cd "$(dirname "$0")/../../.."
B=docs/bench/obst10_2026-12-07c
D=${D:-/work/rom_data/obst10}
export CRAWLSIM_LIBRARY=$PWD/build/core/libcrawlsim.so PYTHONPATH=$PWD/tools/python
for n in "$@"; do
  case $n in
    nominal) a= ;;
    m25g) a="--support-mass 0.025" ;;
    m75g) a="--support-mass 0.075" ;;
    fixed8) a="--fixed 8" ;;
    mu0.6) a="--set friction=0.6" ;;
    mu1.0) a="--set friction=1.0" ;;
    tau0.5x) a="--set tau=0.01" ;;
    tau2x) a="--set tau=0.04" ;;
    ramp0.1) a="--set ramp=0.1" ;;
    dt_half) a="--set step_tol=1.25e-4" ;;
    *) echo "crawl_end.sh: unknown case $n" >&2; exit 2 ;;
  esac
  [ -s $B/ce_$n.txt ] && continue
  { uptime; echo "crawl_end.py $D/z12.csv $D/z12.gate $a"; } > $B/ce_$n.log
  # shellcheck disable=SC2086
  nice -n 5 /usr/bin/python3 $B/crawl_end.py $D/z12.csv $D/z12.gate $a > $B/ce_$n.tmp 2>> $B/ce_$n.log &&
    mv $B/ce_$n.tmp $B/ce_$n.txt
  uptime >> $B/ce_$n.log
done

#!/bin/sh
# usage: set.sh GAIT LEVEL CASE: one run of issue 33's obstacle robustness set
# (a companion $G/GAIT.foothold is passed with --foothold when it exists)
# (docs/bench/obst13_2026-12-07e/run.sh's cases: nominal ramp0.1 ramp0.5 mu0.6 mu1.0 m25g m75g
# tau0.5x tau2x dt_half) on the designed table $G/GAIT.{csv,gate} (GAIT `shipped`: gaits/obstacle.*)
# at LEVEL d (the default step) or b (the adaptive BDF2 at 5e-4 mm; its dt_half is 2.5e-4 mm).
# Whole gated run (no --t-end). Run file $R/GAIT_LEVEL_CASE.h5, log logs/<same>.log with nodes.py's
# and margin.py's lines appended. Resumable (a log with its rc line is skipped).
cd "$(dirname "$0")/../../.."
H=docs/bench/margin16_2026-12-07g; G=${G:-/tmp/margin16/g}; R=${R:-/tmp/margin16/runs}
BIN=${BIN:-build/tools/crawlsim}
g=$1; l=$2; c=$3; tag=${g}_${l}_$c
mkdir -p "$R" "$H/logs"
if [ -f "$H/logs/$tag.log" ] && grep -q '^rc ' "$H/logs/$tag.log"; then exit 0; fi
case $l in
  d) a=; half="--step-tol 1.25e-4" ;;
  b) a="--strain-step adaptive --step-order 2 --step-tol 5e-4"; half="--strain-step adaptive --step-order 2 --step-tol 2.5e-4" ;;
  *) echo "set.sh: unknown level $l" >&2; exit 2 ;;
esac
case $c in
  nominal) x= ;; ramp0.1) x="--ramp 0.1" ;; ramp0.5) x="--ramp 0.5" ;;
  mu0.6) x="--friction 0.6" ;; mu1.0) x="--friction 1.0" ;;
  m25g) x="--support-mass 0.025" ;; m75g) x="--support-mass 0.075" ;;
  tau0.5x) x="--tau 0.01" ;; tau2x) x="--tau 0.04" ;;
  dt_half) a=$half; x= ;;
  *) echo "set.sh: unknown case $c" >&2; exit 2 ;;
esac
if [ "$g" = shipped ]; then gg=; else gg="--gait $G/$g.csv --gate $G/$g.gate --conditions paper"; [ -f $G/$g.foothold ] && gg="$gg --foothold $G/$g.foothold"; fi
{ uptime; echo "crawlsim run --scene obstacle $gg $a $x --out $R/$tag.h5"
  # shellcheck disable=SC2086
  /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 $BIN run --scene obstacle $gg $a $x \
    --out "$R/$tag.h5"
  echo "rc $?"; uptime
  /usr/bin/python3 $H/nodes.py "$R/$tag.h5"; /usr/bin/python3 $H/margin.py "$R/$tag.h5"; } > "$H/logs/$tag.log.tmp" 2>&1
mv "$H/logs/$tag.log.tmp" "$H/logs/$tag.log"
rm -f "$R/$tag.xdmf"

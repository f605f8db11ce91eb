#!/bin/sh
# usage: one.sh GAIT LEVEL [TEND]: `crawlsim run --scene obstacle` on the designed table
# $G/GAIT.{csv,gate} (design.sh; GAIT `shipped`: gaits/obstacle.*) at one step level, nice 5,
# to TEND s (none: the whole gated run). LEVEL: d the default (backward Euler, adaptive 2.5e-4 mm),
# b the adaptive BDF2 at 5e-4 mm, e backward Euler at 3.125e-5 mm, r the rod at 32 elements
# (0.25 ms). Run file $R/GAIT_LEVEL[_tTEND].h5; log logs/<same>.log (uptime before and after,
# the command, banner and summary, CPU, rc). Resumable: a tag whose log has its rc line is skipped.
cd "$(dirname "$0")/../../.."
H=docs/bench/margin16_2026-12-07g; G=${G:-/tmp/margin16/g}; R=${R:-/tmp/margin16/runs}
BIN=${BIN:-build/tools/crawlsim}
g=$1; l=$2; te=$3
tag=${g}_$l${te:+_t$te}
mkdir -p "$R" "$H/logs"
if [ -f "$H/logs/$tag.log" ] && grep -q '^rc ' "$H/logs/$tag.log"; then exit 0; fi
case $l in
  d) a= ;;
  b) a="--strain-step adaptive --step-order 2 --step-tol 5e-4" ;;
  e) a="--strain-step adaptive --step-tol 3.125e-5" ;;
  r) a="--legs rod --links 32 --macro-steps 1 --dt 0.00025" ;;
  *) echo "one.sh: unknown level $l" >&2; exit 2 ;;
esac
if [ "$g" = shipped ]; then gg=; else gg="--gait $G/$g.csv --gate $G/$g.gate --conditions paper"; [ -f $G/$g.foothold ] && gg="$gg --foothold $G/$g.foothold"; fi
{ uptime; echo "crawlsim run --scene obstacle $gg $a ${te:+--t-end $te} --out $R/$tag.h5"
  # shellcheck disable=SC2086
  /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 $BIN run --scene obstacle $gg $a \
    ${te:+--t-end $te} --out "$R/$tag.h5"
  echo "rc $?"; uptime; } > "$H/logs/$tag.log" 2>&1
rm -f "$R/$tag.xdmf"

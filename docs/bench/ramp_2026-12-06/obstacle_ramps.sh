#!/bin/sh
# usage: obstacle_ramps.sh [RAMP...]: `crawlsim run --scene obstacle --ramp R` with the ramp as an
# actuation time (default 0.1 0.5: the robustness set's two ramp runs), logs into
# obstacle/r_rampR.log. Resumable: a run whose log ends in a verdict is skipped.
cd "$(dirname "$0")/../../.."
B=docs/bench/ramp_2026-12-06/obstacle
mkdir -p $B runs
for r in ${*:-0.1 0.5}; do
  grep -q '^verdict' $B/r_ramp$r.log 2>/dev/null && continue
  nice -n 5 build/tools/crawlsim run --scene obstacle --ramp $r --out runs/ramp_obstacle_$r.h5 \
    > $B/r_ramp$r.log 2>&1
done

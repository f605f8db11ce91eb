#!/usr/bin/env bash
# The flat road's robustness set at the merged default (strain legs, adaptive step 2.5e-4 mm,
# sub-intervals by the basis), each run `crawlsim run --scene flat-road OPTION`; scored by
# docs/bench/flat16_2026-12-06e/xs.py. Usage: bash flat_set.sh BUILD_DIR WORK_DIR (resumable:
# a case whose .h5 exists is skipped).
set -u
B=${1:-build}; W=${2:-/tmp/flatset}; mkdir -p "$W"
here=$(cd "$(dirname "$0")" && pwd); root=$(cd "$here/../../.." && pwd)
cases=("nominal:" "ramp0.1:--ramp 0.1" "ramp0.5:--ramp 0.5" "mu0.6:--friction 0.6" "mu1.0:--friction 1.0"
       "m25g:--support-mass 0.025" "m75g:--support-mass 0.075" "tau0.5x:--tau 0.01" "tau2x:--tau 0.04"
       "tol_half:--step-tol 1.25e-4" "mu0:--friction 0")
for c in "${cases[@]}"; do
  name=${c%%:*}; opt=${c#*:}
  [ -f "$W/$name.h5" ] && continue
  nice -n 5 "$root/$B/tools/crawlsim" run --scene flat-road $opt --quiet --out "$W/$name.tmp.h5" >/dev/null 2>"$W/$name.err" \
    && mv "$W/$name.tmp.h5" "$W/$name.h5"
  echo "$name ($opt): $(/usr/bin/python3 "$root/docs/bench/flat16_2026-12-06e/xs.py" "$W/$name.h5" 2>&1 | tail -1)"
done
# under `earth` (the scene's Earth gait), nominal
if [ ! -f "$W/earth.h5" ]; then
  nice -n 5 "$root/$B/tools/crawlsim" run --scene flat-road --conditions earth --quiet --out "$W/earth.tmp.h5" >/dev/null 2>"$W/earth.err" \
    && mv "$W/earth.tmp.h5" "$W/earth.h5"
fi
echo "earth (--conditions earth): $(/usr/bin/python3 "$root/docs/bench/flat16_2026-12-06e/xs.py" "$W/earth.h5" 2>&1 | tail -1)"

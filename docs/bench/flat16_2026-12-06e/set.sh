#!/bin/sh
# The flat road's set (issue 33) with the shipped default gait at N rod elements per segment:
# `crawlsim run --scene flat-road` plus one option each, resumable (a run whose file exists is
# skipped). usage: set.sh N OUTDIR   (run from the repository root; then xs.py OUTDIR/*.h5)
set -e
N=${1:?elements per segment}; OUT=${2:?output directory}
mkdir -p "$OUT"
CS=${CRAWLSIM:-build/tools/crawlsim}
while read -r name opts; do
  f="$OUT/${name}_el$N.h5"
  [ -f "$f" ] && continue
  # shellcheck disable=SC2086
  nice -n 5 "$CS" run --scene flat-road --links "$N" $opts --quiet --out "$f.tmp.h5" \
    > "$OUT/${name}_el$N.log" 2>&1
  mv "$f.tmp.h5" "$f"; rm -f "$f.tmp.xdmf"
done <<LIST
nominal
ramp0.1 --ramp 0.1
ramp0.5 --ramp 0.5
mu0.6 --friction 0.6
mu1.0 --friction 1.0
m25g --support-mass 0.025
m75g --support-mass 0.075
tau0.5x --tau 0.01
tau2x --tau 0.04
dt_half --dt 0.0005
mu0 --friction 0
LIST

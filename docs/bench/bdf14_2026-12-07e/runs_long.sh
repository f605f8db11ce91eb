#!/bin/sh
# runs_long.sh WHO: crawlsim_WHO, BDF2 adaptive 5e-4 mm: the flat road's whole gait (9.5 s) and
# the obstacle's first 4 s, into /tmp/bdf14/runs/WHO.long.{flat-road,obstacle} (resumable)
W=$1; B=/tmp/bdf14/bin/crawlsim_$W
cd /work/wt-bdf14
for s in "flat-road 0" "obstacle 4"; do
  set -- $s
  f=/tmp/bdf14/runs/$W.long.$1
  [ -f $f.h5 ] && continue
  TE=""; [ "$2" != 0 ] && TE="--t-end $2"
  (uptime; nice -n 5 $B run --scene $1 --legs strain --strain-step adaptive --step-order 2 \
    --step-tol 5e-4 $TE --out $f.h5; uptime) > $f.log 2>&1
done

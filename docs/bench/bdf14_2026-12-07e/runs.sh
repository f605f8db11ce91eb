#!/bin/sh
# runs.sh WHO: crawlsim (/tmp/bdf14/bin/crawlsim_WHO) on the flat road and the obstacle, 2 s,
# BDF2 adaptive 5e-4 and backward Euler's default; h5 and logs in /tmp/bdf14/runs (resumable)
W=$1; B=/tmp/bdf14/bin/crawlsim_$1
cd /work/wt-bdf14
for c in "o2 --strain-step adaptive --step-order 2 --step-tol 5e-4" "o1 "; do
  set -- $c; t=$1; shift
  for s in flat-road obstacle; do
    f=/tmp/bdf14/runs/$W.$t.$s
    [ -f $f.h5 ] && continue
    (uptime; /usr/bin/time -f "cpu %U s" nice -n 5 $B run --scene $s --legs strain "$@" --t-end 2 --out $f.h5; uptime) > $f.log 2>&1
  done
done

#!/bin/sh
# diag.sh [PID]: where BDF2 leaves the default on the obstacle (tags bdt{DT}_o10): the adaptive
# BDF2 at 5e-4 mm with a shorter longest step (--dt DT: 2.5 ms and 1 ms instead of 5), to 10.5 s
# (past legs C and G's landing at ~9.05 s), one after the other beside rod.sh's run (two runs at
# a time), after the batch (PID) ends. Logs logs/TAG.log, run files $D/TAG.h5; resumable.
[ -n "$1" ] && while kill -0 "$1" 2>/dev/null; do sleep 20; done
H=$(dirname "$0"); D=${D:-/tmp/dflt15/runs}; C=${CRAWLSIM:-/tmp/dflt15/crawlsim}
for dt in 0.0025 0.001; do
  tag=bdt${dt}_o10
  if [ -f "$H/logs/$tag.log" ] && grep -q '^rc ' "$H/logs/$tag.log"; then continue; fi
  a="--scene obstacle --strain-step adaptive --step-order 2 --step-tol 5e-4 --dt $dt --t-end 10.5"
  { uptime; echo "crawlsim run $a --out $D/$tag.h5"
    # shellcheck disable=SC2086
    /usr/bin/time -f "%U user %S sys %e wall" nice -n 5 "$C" run $a --out "$D/$tag.h5"
    echo "rc $?"; uptime; } > "$H/logs/$tag.log" 2>&1
  rm -f "$D/$tag.xdmf"
done

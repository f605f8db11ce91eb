#!/bin/sh
# noise.sh [PID...]: the obstacle's noise floor past 4 s for both steps (tags n{d,b}_{220,180}):
# the longest step 1/220 s and 1/180 s (-9 / +11 % of 5 ms; --output-dt 0.01, a multiple of
# neither, as strdef's noise.sh: whole seconds are samples) for the default (backward Euler
# 2.5e-4) and the adaptive BDF2 at 5e-4, to 12 s (past the landing of C and G at ~9.05 s and
# the slide back that BDF2's nominal makes there). Pairs at once (two runs at a time), after
# every PID given ends. Logs logs/TAG.log, run files $D/TAG.h5; resumable.
for p in "$@"; do while kill -0 "$p" 2>/dev/null; do sleep 20; done; done
H=$(dirname "$0"); D=${D:-/tmp/dflt15/runs}; C=${CRAWLSIM:-/tmp/dflt15/crawlsim}
. "$H/one.sh"
for n in 220 180; do
  dt=$(/usr/bin/python3 -c "print(1 / $n)")
  one nd_$n --scene obstacle --strain-step adaptive --dt "$dt" --output-dt 0.01 --t-end 12 &
  one nb_$n --scene obstacle --strain-step adaptive --step-order 2 --step-tol 5e-4 --dt "$dt" \
    --output-dt 0.01 --t-end 12 &
  wait
done
